//! Kernel profile: seven phase durations of a candidate profile and its validity check.
//!
//! Input: candidate phase durations `t[0..7]` with the boundary states. Output: whether
//! the candidate is valid (non-negative durations, limits respected, target reached to
//! 1e-8), with the states at the phase boundaries filled in.
//! Invariant: a candidate is accepted only when all of the above hold; the boundary arrays
//! are the phases integrated from the start state, so they are consistent with `t` and `j`.
//! Adapted from ruckig's `profile.hpp` via rsruckig 3.0.1 (MIT); see `kernel/mod.rs`.

static V_EPS: f64 = 1e-12;
static A_EPS: f64 = 1e-12;

static P_PRECISION: f64 = 1e-8;
static V_PRECISION: f64 = 1e-8;
static A_PRECISION: f64 = 1e-10;

static T_MAX: f64 = 1e12;

#[derive(Debug, Default, PartialEq, Clone, Copy)]
pub enum ReachedLimits {
    Acc0Acc1Vel,
    Vel,
    Acc0,
    Acc1,
    Acc0Acc1,
    Acc0Vel,
    Acc1Vel,
    #[default]
    None,
}

#[derive(Debug, Default, PartialEq, Clone, Copy)]
pub enum Direction {
    #[default]
    UP,
    DOWN,
}

#[derive(Debug, Default, PartialEq, Clone, Copy)]
pub enum ControlSigns {
    #[default]
    UDDU,
    UDUD,
}

/// The state profile for position, velocity, acceleration and jerk for a single DoF
///
/// This structure holds the complete kinematic profile for a single degree of freedom.
/// It includes:
/// - Time intervals for each trajectory segment
/// - Jerk, acceleration, velocity, and position profiles
/// - Target kinematic state
/// - Information about which limits were reached
///
/// The profile consists of up to 7 phases, each with constant jerk, following
/// a time-optimal bang-bang approach for trajectory generation.
///
/// This is a low-level representation used internally by the algorithm, but
/// exposed for advanced use cases.
#[derive(Debug, Clone, Copy, Default)]
pub struct Profile {
    /// Duration of each phase (up to 7 phases)
    pub t: [f64; 7],

    /// Cumulative time at the end of each phase
    pub t_sum: [f64; 7],

    /// Jerk value for each phase
    pub j: [f64; 7],

    /// Acceleration at the start/end of each phase
    pub a: [f64; 8],

    /// Velocity at the start/end of each phase
    pub v: [f64; 8],

    /// Position at the start/end of each phase
    pub p: [f64; 8],

    /// Target final position
    pub pf: f64,

    /// Target final velocity
    pub vf: f64,

    /// Target final acceleration
    pub af: f64,

    /// Relative tolerance of the final position (0: ruckig's absolute 1e-8 only). Set for a
    /// problem solved relative to its start (`Profile::position_relative`): the end position
    /// is a sum of terms as large as the largest |p| and |v t| along the profile, each
    /// rounded, so beyond a scale of about 1e6 an absolute 1e-8 can only pass when the
    /// rounding happens to land on the target. The tolerance is then
    /// max(1e-8, `p_tol` x that scale).
    pub p_tol: f64,

    /// Information about which kinematic limits were reached
    pub limits: ReachedLimits,

    /// Direction of motion
    pub direction: Direction,

    /// Control sign configuration
    pub control_signs: ControlSigns,
}

impl Profile {
    /// Tolerance of the final position: ruckig's 1e-8, or with `p_tol` > 0 that factor of
    /// the largest |p| and |v t| term of the integration when coarser (see [`Profile::p_tol`]).
    #[inline(always)]
    fn p_precision(&self) -> f64 {
        if self.p_tol > 0.0 {
            let mut scale = self.p[0].abs();
            for i in 0..7 {
                scale = scale
                    .max(self.p[i + 1].abs())
                    .max((self.v[i] * self.t[i]).abs());
            }
            P_PRECISION.max(self.p_tol * scale)
        } else {
            P_PRECISION
        }
    }

    // For second-order velocity interface

    #[inline(always)]
    pub fn check(
        &mut self,
        control_signs: ControlSigns,
        limits: ReachedLimits,
        set_limits: bool,
        jf: f64,
        v_max: f64,
        v_min: f64,
        a_max: f64,
        a_min: f64,
    ) -> bool {
        if self.t[0] < 0.0 {
            return false;
        }

        self.t_sum[0] = self.t[0];
        for i in 0..6 {
            if self.t[i + 1] < 0.0 {
                return false;
            }
            self.t_sum[i + 1] = self.t_sum[i] + self.t[i + 1];
        }

        if matches!(
            limits,
            ReachedLimits::Acc0Acc1Vel
                | ReachedLimits::Acc0Vel
                | ReachedLimits::Acc1Vel
                | ReachedLimits::Vel
        ) && self.t[3] < f64::EPSILON
        {
            return false;
        }

        if matches!(limits, ReachedLimits::Acc0 | ReachedLimits::Acc0Acc1)
            && self.t[1] < f64::EPSILON
        {
            return false;
        }

        if matches!(limits, ReachedLimits::Acc1 | ReachedLimits::Acc0Acc1)
            && self.t[5] < f64::EPSILON
        {
            return false;
        }

        if self.t_sum[6] > T_MAX {
            return false;
        }

        self.j = if control_signs == ControlSigns::UDDU {
            [
                if self.t[0] > 0.0 { jf } else { 0.0 },
                0.0,
                if self.t[2] > 0.0 { -jf } else { 0.0 },
                0.0,
                if self.t[4] > 0.0 { -jf } else { 0.0 },
                0.0,
                if self.t[6] > 0.0 { jf } else { 0.0 },
            ]
        } else {
            [
                if self.t[0] > 0.0 { jf } else { 0.0 },
                0.0,
                if self.t[2] > 0.0 { -jf } else { 0.0 },
                0.0,
                if self.t[4] > 0.0 { jf } else { 0.0 },
                0.0,
                if self.t[6] > 0.0 { -jf } else { 0.0 },
            ]
        };

        self.direction = if v_max > 0.0 {
            Direction::UP
        } else {
            Direction::DOWN
        };

        let v_upp_lim = if self.direction == Direction::UP {
            v_max
        } else {
            v_min
        } + V_EPS;
        let v_low_lim = if self.direction == Direction::UP {
            v_min
        } else {
            v_max
        } - V_EPS;

        for i in 0..7 {
            self.a[i + 1] = self.a[i] + self.t[i] * self.j[i];
            self.v[i + 1] = self.v[i] + self.t[i] * (self.a[i] + self.t[i] * self.j[i] / 2.0);
            self.p[i + 1] = self.p[i]
                + self.t[i]
                    * (self.v[i] + self.t[i] * (self.a[i] / 2.0 + self.t[i] * self.j[i] / 6.0));

            if matches!(
                limits,
                ReachedLimits::Acc0Acc1Vel
                    | ReachedLimits::Acc0Acc1
                    | ReachedLimits::Acc0Vel
                    | ReachedLimits::Acc1Vel
                    | ReachedLimits::Vel
            ) && i == 2
            {
                self.a[3] = 0.0;
            }

            if set_limits {
                match limits {
                    ReachedLimits::Acc1 if i == 2 => {
                        self.a[3] = a_min;
                    }
                    ReachedLimits::Acc0Acc1 => {
                        if i == 0 {
                            self.a[1] = a_max;
                        }
                        if i == 4 {
                            self.a[5] = a_min;
                        }
                    }
                    _ => {}
                }
            }

            if i > 1 && self.a[i + 1] * self.a[i] < -f64::EPSILON {
                let v_a_zero = self.v[i] - (self.a[i] * self.a[i]) / (2.0 * self.j[i]);
                if v_a_zero > v_upp_lim || v_a_zero < v_low_lim {
                    return false;
                }
            }
        }

        self.control_signs = control_signs;
        self.limits = limits;

        let a_upp_lim = if self.direction == Direction::UP {
            a_max
        } else {
            a_min
        } + A_EPS;
        let a_low_lim = if self.direction == Direction::UP {
            a_min
        } else {
            a_max
        } - A_EPS;

        (self.p[7] - self.pf).abs() < self.p_precision()
            && (self.v[7] - self.vf).abs() < V_PRECISION
            && (self.a[7] - self.af).abs() < A_PRECISION
            && self.a[1] >= a_low_lim
            && self.a[1] <= a_upp_lim
            && self.a[3] >= a_low_lim
            && self.a[3] <= a_upp_lim
            && self.a[5] >= a_low_lim
            && self.a[5] <= a_upp_lim
            && self.v[3] <= v_upp_lim
            && self.v[3] >= v_low_lim
            && self.v[4] <= v_upp_lim
            && self.v[4] >= v_low_lim
            && self.v[5] <= v_upp_lim
            && self.v[5] >= v_low_lim
            && self.v[6] <= v_upp_lim
            && self.v[6] >= v_low_lim
    }

    #[inline]
    pub fn check_with_timing(
        &mut self,
        control_signs: ControlSigns,
        limits: ReachedLimits,
        jf: f64,
        v_max: f64,
        v_min: f64,
        a_max: f64,
        a_min: f64,
    ) -> bool {
        // Time doesn't need to be checked as every profile has a: tf - ... equation
        // Note: Uncomment the next part if t_precision is used later
        // && (self.t_sum.last().unwrap_or(&0.0) - tf).abs() < t_precision
        self.check(control_signs, limits, false, jf, v_max, v_min, a_max, a_min)
    }

    #[inline]
    pub fn set_boundary_from_profile(&mut self, profile: &Profile) {
        self.a[0] = profile.a[0];
        self.v[0] = profile.v[0];
        self.p[0] = profile.p[0];
        self.af = profile.af;
        self.vf = profile.vf;
        self.pf = profile.pf;
        self.p_tol = profile.p_tol;
    }

    #[inline]
    pub fn set_boundary(
        &mut self,
        p0_new: f64,
        v0_new: f64,
        a0_new: f64,
        pf_new: f64,
        vf_new: f64,
        af_new: f64,
    ) {
        self.a[0] = a0_new;
        self.v[0] = v0_new;
        self.p[0] = p0_new;
        self.af = af_new;
        self.vf = vf_new;
        self.pf = pf_new;
    }

    #[inline]
    pub fn check_for_second_order(
        &mut self,
        control_signs: ControlSigns,
        limits: ReachedLimits,
        a_up: f64,
        a_down: f64,
        v_max: f64,
        v_min: f64,
    ) -> bool {
        if self.t[0] < 0.0 {
            return false;
        }

        self.t_sum[0] = self.t[0];
        for i in 0..6 {
            if self.t[i + 1] < 0.0 {
                return false;
            }

            self.t_sum[i + 1] = self.t_sum[i] + self.t[i + 1];
        }

        if self.t_sum[6] > T_MAX {
            return false;
        }

        self.j = [0.0; 7];

        match control_signs {
            ControlSigns::UDDU => {
                self.a = [
                    if self.t[0] > 0.0 { a_up } else { 0.0 },
                    0.0,
                    if self.t[2] > 0.0 { a_down } else { 0.0 },
                    0.0,
                    if self.t[4] > 0.0 { a_down } else { 0.0 },
                    0.0,
                    if self.t[6] > 0.0 { a_up } else { 0.0 },
                    self.af,
                ];
            }
            _ => {
                self.a = [
                    if self.t[0] > 0.0 { a_up } else { 0.0 },
                    0.0,
                    if self.t[2] > 0.0 { a_down } else { 0.0 },
                    0.0,
                    if self.t[4] > 0.0 { a_up } else { 0.0 },
                    0.0,
                    if self.t[6] > 0.0 { a_down } else { 0.0 },
                    self.af,
                ];
            }
        }

        self.direction = if v_max > 0.0 {
            Direction::UP
        } else {
            Direction::DOWN
        };

        let v_upp_lim = if self.direction == Direction::UP {
            v_max + V_EPS
        } else {
            v_min + V_EPS
        };
        let v_low_lim = if self.direction == Direction::UP {
            v_min - V_EPS
        } else {
            v_max - V_EPS
        };

        for i in 0..7 {
            self.v[i + 1] = self.v[i] + self.t[i] * self.a[i];
            self.p[i + 1] = self.p[i] + self.t[i] * (self.v[i] + self.t[i] * self.a[i] / 2.0);
        }

        self.control_signs = control_signs;
        self.limits = limits;

        (self.p[7] - self.pf).abs() < P_PRECISION
            && (self.v[7] - self.vf).abs() < P_PRECISION
            && self.v[2] <= v_upp_lim
            && self.v[2] >= v_low_lim
            && self.v[3] <= v_upp_lim
            && self.v[3] >= v_low_lim
            && self.v[4] <= v_upp_lim
            && self.v[4] >= v_low_lim
            && self.v[5] <= v_upp_lim
            && self.v[5] >= v_low_lim
            && self.v[6] <= v_upp_lim
            && self.v[6] >= v_low_lim
            && self.v[7] <= v_upp_lim
            && self.v[7] >= v_low_lim
    }

    // For first-order position interface
}
