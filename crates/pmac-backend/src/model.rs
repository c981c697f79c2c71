//! The backend's input model, independent of the motion library.
//!
//! Input: built by the caller (the integrator adapts motion-lib output to these types).
//! Output: validated coordinate systems, moves and trajectories for `program`, `pvt` and `verify`.
//! Invariants: `CoordSystem::validate` and `LinearMove` checks reject everything that would give invalid PMAC
//! text (E7001/E7002); a `Trajectory` is exact at its samples and a quintic Hermite curve between them.

use crate::error::PmacError;

/// Which controller family the text is for.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Dialect {
    /// Turbo PMAC / PMAC2: upper-case keywords, one `TA` for acceleration and deceleration.
    #[default]
    Turbo,
    /// Power PMAC: lower-case keywords, separate `td` deceleration time, `define rotary` buffers.
    Power,
}

impl std::str::FromStr for Dialect {
    type Err = String;
    /// `turbo` (also `pmac`, `turbo-pmac`) or `power` (also `power-pmac`, `ppmac`), any case.
    fn from_str(s: &str) -> Result<Self, Self::Err> {
        match s.trim().to_ascii_lowercase().as_str() {
            "turbo" | "pmac" | "turbo-pmac" => Ok(Dialect::Turbo),
            "power" | "power-pmac" | "ppmac" => Ok(Dialect::Power),
            other => Err(format!(
                "unknown PMAC dialect `{other}` (expected `turbo` or `power`)"
            )),
        }
    }
}

/// One axis of a coordinate system: `#motor->counts_per_unit name`.
#[derive(Debug, Clone, PartialEq)]
pub struct AxisDef {
    /// The motor number (the `1` of `#1->1000X`).
    pub motor: u32,
    /// `X`, `Y`, `Z`, `A`, `B`, `C`, `U`, `V` or `W`.
    pub name: char,
    /// Motor counts per user unit (the `1000` of `#1->1000X`).
    pub counts_per_unit: f64,
}

/// A PMAC coordinate system (`&number`) and its axes, in the order used by move targets and trajectories.
#[derive(Debug, Clone, PartialEq)]
pub struct CoordSystem {
    /// The coordinate system number (the `1` of `&1`).
    pub number: u32,
    /// Its axes, in move-target order.
    pub axes: Vec<AxisDef>,
}

impl CoordSystem {
    /// Checks the definition (E7001).
    pub fn validate(&self) -> Result<(), PmacError> {
        if self.number == 0 {
            return Err(PmacError::coord_system(
                "coordinate system number must be 1 or more",
            ));
        }
        if self.axes.is_empty() {
            return Err(PmacError::coord_system(format!(
                "coordinate system &{} has no axes",
                self.number
            )));
        }
        for (i, a) in self.axes.iter().enumerate() {
            if !"XYZABCUVW".contains(a.name.to_ascii_uppercase()) {
                return Err(PmacError::coord_system(format!(
                    "axis name `{}` is not a PMAC axis (A B C U V W X Y Z)",
                    a.name
                )));
            }
            if a.motor == 0 {
                return Err(PmacError::coord_system(format!(
                    "axis {}: motor number must be 1 or more",
                    a.name
                )));
            }
            if !(a.counts_per_unit.is_finite() && a.counts_per_unit > 0.0) {
                return Err(PmacError::coord_system(format!(
                    "axis {}: counts per unit must be positive and finite, got {}",
                    a.name, a.counts_per_unit
                )));
            }
            for b in &self.axes[..i] {
                if b.motor == a.motor {
                    return Err(PmacError::coord_system(format!(
                        "motor #{} is assigned to two axes ({} and {})",
                        a.motor, b.name, a.name
                    )));
                }
                if b.name.eq_ignore_ascii_case(&a.name) {
                    return Err(PmacError::coord_system(format!(
                        "axis {} is defined twice",
                        a.name
                    )));
                }
            }
        }
        Ok(())
    }

    /// Upper-case axis letters in order.
    pub fn axis_names(&self) -> Vec<char> {
        self.axes
            .iter()
            .map(|a| a.name.to_ascii_uppercase())
            .collect()
    }
}

/// `ABS` (targets are positions) or `INC` (targets are distances).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum MoveMode {
    /// `ABS`: targets are positions.
    #[default]
    Abs,
    /// `INC`: targets are distances from where the move starts.
    Inc,
}

/// What happens at the end of a move.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub enum Transition {
    /// Stop exactly at the target (PLCopen Aborting/Buffered at the end of a queue): `DWELL0`.
    #[default]
    ExactStop,
    /// Blend into the next move (PLCopen Blending*): no dwell, the PMAC blends over the next move's `TA`.
    /// `junction_velocity` is the planner's path speed at the corner; LINEAR mode cannot impose it (see README), so
    /// it is not written into the program (PVT streaming reproduces it).
    Blend {
        /// The planner's path speed at the corner (user units per second).
        junction_velocity: f64,
    },
}

/// A straight move with jerk-limited limits. The limits are per axis (each axis may use up to `velocity`,
/// `acceleration`, ...); the backend projects them onto the line to get the path limits.
#[derive(Debug, Clone, PartialEq)]
pub struct LinearMove {
    /// One value per axis of the coordinate system, in its order.
    pub target: Vec<f64>,
    /// Velocity limit per axis (user units per second).
    pub velocity: f64,
    /// Acceleration limit per axis (units/s²).
    pub acceleration: f64,
    /// Deceleration limit per axis (units/s²).
    pub deceleration: f64,
    /// Jerk limit per axis (units/s³).
    pub jerk: f64,
    /// Absolute or incremental target.
    pub mode: MoveMode,
    /// How the move joins the next one (stop or blend).
    pub transition: Transition,
}

impl LinearMove {
    /// Checks the move against the coordinate system (E7002); `index` is 0-based (reported 1-based).
    pub fn validate(&self, index: usize, cs: &CoordSystem) -> Result<(), PmacError> {
        if self.target.len() != cs.axes.len() {
            return Err(PmacError::invalid_move(
                index,
                format!(
                    "target has {} coordinates but &{} has {} axes",
                    self.target.len(),
                    cs.number,
                    cs.axes.len()
                ),
            ));
        }
        if let Some(x) = self.target.iter().find(|x| !x.is_finite()) {
            return Err(PmacError::invalid_move(
                index,
                format!("target coordinate {x} is not finite"),
            ));
        }
        for (name, x) in [
            ("velocity", self.velocity),
            ("acceleration", self.acceleration),
            ("deceleration", self.deceleration),
            ("jerk", self.jerk),
        ] {
            if !(x.is_finite() && x > 0.0) {
                return Err(PmacError::invalid_move(
                    index,
                    format!("{name} must be positive and finite, got {x}"),
                ));
            }
        }
        if let Transition::Blend { junction_velocity } = self.transition {
            if !(junction_velocity.is_finite() && junction_velocity >= 0.0) {
                return Err(PmacError::invalid_move(
                    index,
                    format!("junction velocity must be 0 or more, got {junction_velocity}"),
                ));
            }
        }
        Ok(())
    }
}

/// One sample of one axis: position, velocity, acceleration (user units, seconds).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Sample {
    /// Position.
    pub p: f64,
    /// Velocity.
    pub v: f64,
    /// Acceleration.
    pub a: f64,
}

/// Anything that can say where each axis is at time `t` (seconds from the start).
pub trait TrajectorySource {
    /// The number of axes.
    fn axis_count(&self) -> usize;
    /// Duration in seconds; the motion is at rest at its end.
    fn duration(&self) -> f64;
    /// (position, velocity) of every axis at `t`, `0 <= t <= duration()`.
    fn state(&self, t: f64) -> Vec<(f64, f64)>;
    /// The sample period if the source is sampled (PVT segment ends must then fall on samples).
    fn sample_period(&self) -> Option<f64> {
        None
    }
    /// Checks the source before use (E7003).
    fn check(&self) -> Result<(), PmacError> {
        Ok(())
    }
}

/// A trajectory given by a function of time, e.g. an adapter around a motion-library profile.
pub struct FnSource<F: Fn(f64) -> Vec<(f64, f64)>> {
    /// The number of axes.
    pub axes: usize,
    /// The duration in seconds.
    pub duration: f64,
    /// (position, velocity) of every axis at a time in seconds.
    pub state: F,
}

impl<F: Fn(f64) -> Vec<(f64, f64)>> TrajectorySource for FnSource<F> {
    fn axis_count(&self) -> usize {
        self.axes
    }
    fn duration(&self) -> f64 {
        self.duration
    }
    fn state(&self, t: f64) -> Vec<(f64, f64)> {
        (self.state)(t)
    }
    fn check(&self) -> Result<(), PmacError> {
        if !(self.duration.is_finite() && self.duration > 0.0) || self.axes == 0 {
            return Err(PmacError::trajectory(
                "a trajectory needs at least one axis and a positive duration",
            ));
        }
        Ok(())
    }
}

/// A trajectory sampled every `cycle_s` seconds; `axes[k][i]` is axis k at `i * cycle_s`.
#[derive(Debug, Clone, PartialEq)]
pub struct Trajectory {
    /// The sample period in seconds.
    pub cycle_s: f64,
    /// The samples, per axis.
    pub axes: Vec<Vec<Sample>>,
}

impl Trajectory {
    /// Number of samples per axis (0 if there are no axes).
    pub fn len(&self) -> usize {
        self.axes.first().map_or(0, Vec::len)
    }
    /// Whether there is no sample.
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }
    /// Checks cycle, equal lengths and finite values (E7003).
    pub fn validate(&self) -> Result<(), PmacError> {
        if !(self.cycle_s.is_finite() && self.cycle_s > 0.0) {
            return Err(PmacError::trajectory(format!(
                "sample cycle must be positive, got {} s",
                self.cycle_s
            )));
        }
        if self.axes.is_empty() || self.len() < 2 {
            return Err(PmacError::trajectory(
                "a trajectory needs at least one axis and two samples",
            ));
        }
        for (k, axis) in self.axes.iter().enumerate() {
            if axis.len() != self.len() {
                return Err(PmacError::trajectory(format!(
                    "axis {} has {} samples, axis 1 has {}",
                    k + 1,
                    axis.len(),
                    self.len()
                )));
            }
            if axis
                .iter()
                .any(|s| !(s.p.is_finite() && s.v.is_finite() && s.a.is_finite()))
            {
                return Err(PmacError::trajectory(format!(
                    "axis {} has a sample that is not finite",
                    k + 1
                )));
            }
        }
        Ok(())
    }
}

impl TrajectorySource for Trajectory {
    fn axis_count(&self) -> usize {
        self.axes.len()
    }
    fn duration(&self) -> f64 {
        self.len().saturating_sub(1) as f64 * self.cycle_s
    }
    fn state(&self, t: f64) -> Vec<(f64, f64)> {
        let n = self.len();
        if n == 0 {
            return vec![(0.0, 0.0); self.axes.len()];
        }
        let x = (t / self.cycle_s).max(0.0);
        let nearest = x.round();
        if (x - nearest).abs() < 1e-9 || nearest as usize >= n - 1 && x >= (n - 1) as f64 {
            let i = (nearest as usize).min(n - 1);
            return self.axes.iter().map(|ax| (ax[i].p, ax[i].v)).collect();
        }
        let i = (x.floor() as usize).min(n - 2);
        let u = x - i as f64;
        let h = self.cycle_s;
        self.axes
            .iter()
            .map(|ax| quintic(ax[i], ax[i + 1], h, u))
            .collect()
    }
    fn sample_period(&self) -> Option<f64> {
        Some(self.cycle_s)
    }
    fn check(&self) -> Result<(), PmacError> {
        self.validate()
    }
}

/// Quintic Hermite between two (p, v, a) samples `h` apart, at fraction `u`: exact for motion whose position is
/// a polynomial of degree 5 or less over the interval (jerk-limited motion is cubic).
fn quintic(s0: Sample, s1: Sample, h: f64, u: f64) -> (f64, f64) {
    let (p0, v0, a0) = (s0.p, s0.v * h, s0.a * h * h);
    let (p1, v1, a1) = (s1.p, s1.v * h, s1.a * h * h);
    let u2 = u * u;
    let u3 = u2 * u;
    let u4 = u3 * u;
    let u5 = u4 * u;
    let h00 = 1.0 - 10.0 * u3 + 15.0 * u4 - 6.0 * u5;
    let h10 = u - 6.0 * u3 + 8.0 * u4 - 3.0 * u5;
    let h20 = 0.5 * (u2 - 3.0 * u3 + 3.0 * u4 - u5);
    let h01 = 10.0 * u3 - 15.0 * u4 + 6.0 * u5;
    let h11 = -4.0 * u3 + 7.0 * u4 - 3.0 * u5;
    let h21 = 0.5 * (u3 - 2.0 * u4 + u5);
    let d00 = -30.0 * u2 + 60.0 * u3 - 30.0 * u4;
    let d10 = 1.0 - 18.0 * u2 + 32.0 * u3 - 15.0 * u4;
    let d20 = 0.5 * (2.0 * u - 9.0 * u2 + 12.0 * u3 - 5.0 * u4);
    let d01 = 30.0 * u2 - 60.0 * u3 + 30.0 * u4;
    let d11 = -12.0 * u2 + 28.0 * u3 - 15.0 * u4;
    let d21 = 0.5 * (3.0 * u2 - 8.0 * u3 + 5.0 * u4);
    let p = h00 * p0 + h10 * v0 + h20 * a0 + h01 * p1 + h11 * v1 + h21 * a1;
    let v = (d00 * p0 + d10 * v0 + d20 * a0 + d01 * p1 + d11 * v1 + d21 * a1) / h;
    (p, v)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn cs() -> CoordSystem {
        CoordSystem {
            number: 1,
            axes: vec![
                AxisDef {
                    motor: 1,
                    name: 'X',
                    counts_per_unit: 1000.0,
                },
                AxisDef {
                    motor: 2,
                    name: 'Y',
                    counts_per_unit: 1000.0,
                },
            ],
        }
    }

    #[test]
    fn dialect_names() {
        assert_eq!("Turbo".parse::<Dialect>(), Ok(Dialect::Turbo));
        assert_eq!("ppmac".parse::<Dialect>(), Ok(Dialect::Power));
        assert!("umac".parse::<Dialect>().unwrap_err().contains("umac"));
    }

    #[test]
    fn coordinate_system_checks() {
        assert!(cs().validate().is_ok());
        let mut c = cs();
        c.axes[1].motor = 1;
        assert_eq!(c.validate().unwrap_err().code(), "E7001");
        let mut c = cs();
        c.axes[1].name = 'x';
        assert_eq!(c.validate().unwrap_err().code(), "E7001");
        let mut c = cs();
        c.axes[0].name = 'Q';
        assert_eq!(c.validate().unwrap_err().code(), "E7001");
        let mut c = cs();
        c.axes[0].counts_per_unit = f64::NAN;
        assert_eq!(c.validate().unwrap_err().code(), "E7001");
        let mut c = cs();
        c.number = 0;
        assert_eq!(c.validate().unwrap_err().code(), "E7001");
    }

    #[test]
    fn move_checks() {
        let m = LinearMove {
            target: vec![1.0, 2.0],
            velocity: 1.0,
            acceleration: 1.0,
            deceleration: 1.0,
            jerk: 1.0,
            mode: MoveMode::Abs,
            transition: Transition::ExactStop,
        };
        assert!(m.validate(0, &cs()).is_ok());
        let mut bad = m.clone();
        bad.target.push(3.0);
        let e = bad.validate(2, &cs()).unwrap_err();
        assert_eq!(e.code(), "E7002");
        assert!(e.diagnostic().message.starts_with("move 3:"));
        let mut bad = m.clone();
        bad.jerk = 0.0;
        assert_eq!(bad.validate(0, &cs()).unwrap_err().code(), "E7002");
        let mut bad = m;
        bad.target[0] = f64::INFINITY;
        assert_eq!(bad.validate(0, &cs()).unwrap_err().code(), "E7002");
    }

    #[test]
    fn quintic_reproduces_a_cubic() {
        // p(t) = t^3 sampled at 0 and 0.1: exact in between.
        let f = |t: f64| Sample {
            p: t * t * t,
            v: 3.0 * t * t,
            a: 6.0 * t,
        };
        let tr = Trajectory {
            cycle_s: 0.1,
            axes: vec![vec![f(0.0), f(0.1), f(0.2)]],
        };
        let (p, v) = tr.state(0.137)[0];
        assert!((p - 0.137f64.powi(3)).abs() < 1e-12);
        assert!((v - 3.0 * 0.137f64.powi(2)).abs() < 1e-10);
        assert_eq!(tr.state(0.2)[0], (f(0.2).p, f(0.2).v));
        assert!((tr.duration() - 0.2).abs() < 1e-12);
    }
}
