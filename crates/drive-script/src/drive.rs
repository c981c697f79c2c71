//! The drive the interpreter commands: the [`Drive`] trait and [`SimDrive`], a simulated servo drive.
//!
//! Input: commands from the interpreter (moves, settings, outputs) and, for [`SimDrive`], `tick()` calls that
//! advance simulated time by one main-loop cycle. Output: the readings the interpreter snapshots.
//! Invariants: no method panics for any argument (all arithmetic saturates or is done in f64); a command
//! that starts motion makes `motion_state()` non-standstill immediately, so a Motion that starts a move and
//! then waits for `MotionDone` never sees a stale "done" from before the command.
//! Units: position in pulses, velocity in pulses/s, acceleration in pulses/s², current in mA, time in ms.

/// What the drive is doing, as seen by the script (`MotionState`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
#[repr(u8)]
pub enum MotionState {
    #[default]
    /// 0: no motion command runs and the drive stands (`MotionDone` = 1).
    Standstill = 0,
    /// 1: a move, jog or velocity command runs, or the drive still brakes.
    Moving = 1,
    /// 2: a homing command runs.
    Homing = 2,
    /// 3: the drive is in fault (motion-lib axis in ErrorStop); `SimDrive` never reports it.
    Fault = 3,
}

/// The servo-drive interface the interpreter uses. Implemented by [`SimDrive`] (exact trapezoidal
/// simulation) and by [`crate::MotionLibDrive`] (a motion-lib axis driven by PLCopen blocks).
pub trait Drive {
    /// Actual position, pulses (`ActualPosition`).
    fn actual_position(&self) -> i32;
    /// Actual velocity, pulses/s (`ActualVelocity`).
    fn actual_velocity(&self) -> i32;
    /// Motor current, mA (`ActualCurrent`).
    fn actual_current(&self) -> i32;
    /// Bit n = `DI_n`.
    fn digital_inputs(&self) -> u32;
    /// Bit n = `DO_n`.
    fn digital_outputs(&self) -> u32;
    /// Sets `DO_<index>` (the action `DO_n = value`; non-zero value is HIGH); indices from 32 on are ignored.
    fn set_digital_output(&mut self, index: u8, high: bool);
    /// What the drive is doing (`MotionState`; `MotionDone` is `Standstill`). Non-standstill from the call
    /// that starts a motion on.
    fn motion_state(&self) -> MotionState;
    /// True after a successful homing (`Homed`).
    fn homed(&self) -> bool;
    /// A free-running millisecond clock (wraps).
    fn now_ms(&self) -> u32;
    /// Profile velocity of the following moves, pulses/s (`Velocity = value`; magnitude used).
    fn set_velocity(&mut self, v: i32);
    /// Acceleration of the following moves, pulses/s² (`Acceleration = value`; magnitude used).
    fn set_acceleration(&mut self, a: i32);
    /// Deceleration of the following moves, pulses/s² (`Deceleration = value`; magnitude used).
    fn set_deceleration(&mut self, d: i32);
    /// Jog and homing velocity, pulses/s (`JogVelocity = value`; magnitude used).
    fn set_jog_velocity(&mut self, v: i32);
    /// Redefines the actual position without moving.
    fn set_position(&mut self, p: i32);
    /// Runs at the signed velocity `v`, pulses/s, until another command (`VelocityMove = value`).
    fn velocity_move(&mut self, v: i32);
    /// Moves by the signed `distance`, pulses, from the running target if a positioning move is active, else
    /// from the current position (`RelativeTargetPosition`).
    fn relative_move(&mut self, distance: i32);
    /// Moves to position `target`, pulses (`AbsoluteTargetPosition`).
    fn absolute_move(&mut self, target: i32);
    /// >0 positive, <0 negative, 0 stop.
    fn jog(&mut self, direction: i32);
    /// Starts homing (`Homing = method`): 0 = the current position becomes 0; another method runs to the
    /// reference mark at the jog velocity, which becomes position 0.
    fn home(&mut self, method: i32);
    /// Decelerates to standstill with the set deceleration (`Stop`).
    fn stop(&mut self);
}

/// A drive whose time advances one main-loop cycle per [`CycleDrive::tick`] (the simulations the CLI and
/// the debugger run: [`SimDrive`] and [`crate::MotionLibDrive`]).
pub trait CycleDrive: Drive {
    /// Advances by one main-loop cycle.
    fn tick(&mut self);
    /// Sets the digital inputs (bit n = `DI_n`).
    fn set_inputs(&mut self, bits: u32);
    /// Sets one digital input; indices from 32 on are ignored.
    fn set_input_bit(&mut self, index: u8, high: bool) {
        if index < 32 {
            let bits = self.digital_inputs();
            let mask = 1u32 << index;
            self.set_inputs(if high { bits | mask } else { bits & !mask });
        }
    }
}

impl CycleDrive for SimDrive {
    fn tick(&mut self) {
        SimDrive::tick(self);
    }
    fn set_inputs(&mut self, bits: u32) {
        self.inputs = bits;
    }
}

#[derive(Debug, Clone, Copy, PartialEq)]
enum Mode {
    Idle,
    /// Positioning to an absolute target (pulses, f64 for exact integration).
    Position(f64),
    /// Running at a signed velocity until another command.
    Velocity(f64),
    /// Homing: run to position 0 (the simulated reference), then mark homed.
    Homing,
}

/// A simulated drive: trapezoidal moves integrated once per `tick()` of `cycle_ms` milliseconds.
#[derive(Debug, Clone)]
pub struct SimDrive {
    /// Length of one main-loop cycle, ms (at least 1): the simulated time each `tick` advances.
    pub cycle_ms: u32,
    time_ms: u32,
    position: f64,
    velocity: f64,
    accel_now: f64,
    profile_velocity: f64,
    acceleration: f64,
    deceleration: f64,
    jog_velocity: f64,
    mode: Mode,
    homed: bool,
    /// Bit n = `DI_n`; tests and the debugger write it.
    pub inputs: u32,
    outputs: u32,
    /// mA per pulse/s² of acceleration (the simulated torque constant and inertia together).
    pub current_per_accel: f64,
}

impl Default for SimDrive {
    fn default() -> Self {
        SimDrive::new(1)
    }
}

impl SimDrive {
    /// A drive at position 0, standing, not homed, with the default settings (10,000 pulses/s, 100,000
    /// pulses/s², jog 5,000 pulses/s); `cycle_ms` 0 is taken as 1.
    pub fn new(cycle_ms: u32) -> SimDrive {
        SimDrive {
            cycle_ms: cycle_ms.max(1),
            time_ms: 0,
            position: 0.0,
            velocity: 0.0,
            accel_now: 0.0,
            profile_velocity: 10_000.0,
            acceleration: 100_000.0,
            deceleration: 100_000.0,
            jog_velocity: 5_000.0,
            mode: Mode::Idle,
            homed: false,
            inputs: 0,
            outputs: 0,
            current_per_accel: 0.01,
        }
    }

    /// Sets digital input `DI_<index>` (tests, the debugger); indices from 32 on are ignored.
    pub fn set_input(&mut self, index: u8, high: bool) {
        if index < 32 {
            if high {
                self.inputs |= 1 << index;
            } else {
                self.inputs &= !(1 << index);
            }
        }
    }

    /// Advances simulated time by one cycle.
    pub fn tick(&mut self) {
        let dt = self.cycle_ms as f64 / 1000.0;
        self.time_ms = self.time_ms.wrapping_add(self.cycle_ms);
        let v0 = self.velocity;
        let acc = self.acceleration.max(1.0);
        let dec = self.deceleration.max(1.0);
        match self.mode {
            Mode::Idle => {
                self.velocity = approach(self.velocity, 0.0, dec * dt);
                self.position += (v0 + self.velocity) / 2.0 * dt;
            }
            Mode::Velocity(target) => {
                let rate = if target.abs() > self.velocity.abs() {
                    acc
                } else {
                    dec
                };
                self.velocity = approach(self.velocity, target, rate * dt);
                self.position += (v0 + self.velocity) / 2.0 * dt;
            }
            Mode::Position(_) | Mode::Homing => {
                let target = match self.mode {
                    Mode::Position(t) => t,
                    _ => 0.0,
                };
                let vmax = if self.mode == Mode::Homing {
                    self.jog_velocity.abs().max(1.0)
                } else {
                    self.profile_velocity.abs().max(1.0)
                };
                let remaining = target - self.position;
                // Fastest speed from which we can still stop at the target.
                let brake = (2.0 * dec * remaining.abs()).sqrt();
                let wanted = remaining.signum() * vmax.min(brake);
                self.velocity = approach(self.velocity, wanted, acc.max(dec) * dt);
                let step = (v0 + self.velocity) / 2.0 * dt;
                if remaining.abs() <= step.abs().max(0.5) {
                    self.position = target;
                    self.velocity = 0.0;
                    if self.mode == Mode::Homing {
                        self.homed = true;
                    }
                    self.mode = Mode::Idle;
                } else {
                    self.position += step;
                }
            }
        }
        self.accel_now = (self.velocity - v0) / dt;
    }

    fn pos_i32(&self) -> i32 {
        self.position
            .round()
            .clamp(i32::MIN as f64, i32::MAX as f64) as i32
    }
}

fn approach(from: f64, to: f64, step: f64) -> f64 {
    if (to - from).abs() <= step {
        to
    } else {
        from + step * (to - from).signum()
    }
}

impl Drive for SimDrive {
    fn actual_position(&self) -> i32 {
        self.pos_i32()
    }
    fn actual_velocity(&self) -> i32 {
        self.velocity
            .round()
            .clamp(i32::MIN as f64, i32::MAX as f64) as i32
    }
    fn actual_current(&self) -> i32 {
        (self.accel_now * self.current_per_accel)
            .round()
            .clamp(i32::MIN as f64, i32::MAX as f64) as i32
    }
    fn digital_inputs(&self) -> u32 {
        self.inputs
    }
    fn digital_outputs(&self) -> u32 {
        self.outputs
    }
    fn set_digital_output(&mut self, index: u8, high: bool) {
        if index < 32 {
            if high {
                self.outputs |= 1 << index;
            } else {
                self.outputs &= !(1 << index);
            }
        }
    }
    fn motion_state(&self) -> MotionState {
        match self.mode {
            Mode::Idle if self.velocity != 0.0 => MotionState::Moving,
            Mode::Idle => MotionState::Standstill,
            Mode::Homing => MotionState::Homing,
            _ => MotionState::Moving,
        }
    }
    fn homed(&self) -> bool {
        self.homed
    }
    fn now_ms(&self) -> u32 {
        self.time_ms
    }
    fn set_velocity(&mut self, v: i32) {
        self.profile_velocity = (v as f64).abs();
    }
    fn set_acceleration(&mut self, a: i32) {
        self.acceleration = (a as f64).abs();
    }
    fn set_deceleration(&mut self, d: i32) {
        self.deceleration = (d as f64).abs();
    }
    fn set_jog_velocity(&mut self, v: i32) {
        self.jog_velocity = (v as f64).abs();
    }
    fn set_position(&mut self, p: i32) {
        let shift = p as f64 - self.position;
        self.position = p as f64;
        if let Mode::Position(t) = self.mode {
            self.mode = Mode::Position(t + shift);
        }
    }
    fn velocity_move(&mut self, v: i32) {
        self.mode = Mode::Velocity(v as f64);
    }
    fn relative_move(&mut self, distance: i32) {
        let base = match self.mode {
            Mode::Position(t) => t,
            _ => self.position.round(),
        };
        self.mode = Mode::Position(base + distance as f64);
    }
    fn absolute_move(&mut self, target: i32) {
        self.mode = Mode::Position(target as f64);
    }
    fn jog(&mut self, direction: i32) {
        self.mode = match direction.signum() {
            0 => Mode::Idle,
            s => Mode::Velocity(s as f64 * self.jog_velocity),
        };
    }
    fn home(&mut self, method: i32) {
        if method == 0 {
            // Method 0: the current position is the reference.
            self.position = 0.0;
            self.velocity = 0.0;
            self.mode = Mode::Idle;
            self.homed = true;
        } else {
            self.homed = false;
            self.mode = Mode::Homing;
        }
    }
    fn stop(&mut self) {
        self.mode = Mode::Idle;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn relative_move_reaches_its_target_and_stops() {
        let mut d = SimDrive::new(1);
        d.set_velocity(100_000);
        d.set_acceleration(1_000_000);
        d.set_deceleration(1_000_000);
        d.relative_move(10_000);
        assert_eq!(d.motion_state(), MotionState::Moving);
        let mut cycles = 0;
        while d.motion_state() != MotionState::Standstill && cycles < 10_000 {
            d.tick();
            cycles += 1;
        }
        assert_eq!(d.actual_position(), 10_000);
        assert_eq!(d.actual_velocity(), 0);
        // 0.1 s at 100000 p/s plus 0.1 s of ramps: about 200 ms.
        assert!((150..300).contains(&cycles), "{cycles}");
    }

    #[test]
    fn homing_method_1_runs_to_zero_and_marks_homed() {
        let mut d = SimDrive::new(1);
        d.set_position(-3000);
        d.home(1);
        assert_eq!(d.motion_state(), MotionState::Homing);
        for _ in 0..5000 {
            d.tick();
        }
        assert!(d.homed());
        assert_eq!(d.actual_position(), 0);
    }

    #[test]
    fn jog_and_velocity_move_run_until_stopped() {
        let mut d = SimDrive::new(1);
        d.set_jog_velocity(2000);
        d.jog(-1);
        for _ in 0..1000 {
            d.tick();
        }
        assert_eq!(d.actual_velocity(), -2000);
        assert!(d.actual_position() < -1000);
        d.stop();
        for _ in 0..1000 {
            d.tick();
        }
        assert_eq!(d.motion_state(), MotionState::Standstill);
    }
}
