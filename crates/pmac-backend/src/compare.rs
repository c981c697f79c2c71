//! The PMAC's motion, as the backend models it from the emitted text, against the planned motion.
//!
//! Input: a coordinate system, the planned [`LinearMove`]s and the [`ProgramOptions`] the text is written with.
//! Output: a [`Comparison`]: per move the planned and the program's duration, per blended corner the planned
//! (PLCopen junction) and the program's corner speed, and warnings (`W7200`) for every corner whose speed
//! differs by more than [`CORNER_TOLERANCE`] and for every move whose time differs by more than
//! [`TIME_TOLERANCE_S`].
//! Invariants: the program is parsed with the same rules as [`crate::verify`] (Turbo rounds `TA`/`TS` to whole
//! ms at execution); nothing here changes the text.

use crate::error::PmacError;
use crate::model::{CoordSystem, LinearMove, Transition};
use crate::program::{self, ProgramOptions};
use crate::verify;
use diagnostics::{code, Diagnostic};

/// Relative corner-speed difference above which a warning is given.
pub const CORNER_TOLERANCE: f64 = 0.01;
/// Move-time difference above which a warning is given: the whole-ms `TA`/`TS` of Turbo and the rounded-down
/// `F` stay below it (at most 2 ms per ramp, 0.5 ms for `F`).
pub const TIME_TOLERANCE_S: f64 = 4.5e-3;

/// One blended corner.
#[derive(Debug, Clone, PartialEq)]
pub struct Corner {
    /// Index of the move that ends at the corner (0-based).
    pub after_move: usize,
    /// The planned junction velocity (PLCopen BufferMode).
    pub planned: f64,
    /// The speed the PMAC passes the corner at (LINEAR blending: half way between the two moves' velocities).
    pub program: f64,
}

/// The two motions side by side.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Comparison {
    /// (planned, program) duration of every move, in seconds, for moves that start and end at rest.
    pub move_times: Vec<(f64, f64)>,
    /// Every corner between two moves: the planned and the program's speed there.
    pub corners: Vec<Corner>,
}

impl Comparison {
    /// Largest `program - planned` move time (s).
    pub fn worst_time_difference(&self) -> f64 {
        self.move_times
            .iter()
            .map(|(p, q)| (q - p).abs())
            .fold(0.0, f64::max)
    }

    /// A `W7200` warning per difference beyond the tolerances.
    pub fn warnings(&self) -> Vec<Diagnostic> {
        let mut out = Vec::new();
        for c in &self.corners {
            let rel = (c.program - c.planned).abs() / c.planned.abs().max(1e-12);
            if rel > CORNER_TOLERANCE {
                out.push(
                    Diagnostic::warning(
                        code::W7200,
                        format!(
                            "the PMAC program passes the corner after move {} at {:.3} units/s; the plan has {:.3}",
                            c.after_move + 1,
                            c.program,
                            c.planned
                        ),
                    )
                    .with_hint(
                        "LINEAR blending cannot impose a PLCopen junction velocity; stream the run as PVT (--pmac-pvt) to reproduce it",
                    ),
                );
            }
        }
        for (i, (p, q)) in self.move_times.iter().enumerate() {
            if (q - p).abs() > TIME_TOLERANCE_S {
                out.push(Diagnostic::warning(
                    code::W7200,
                    format!(
                        "the PMAC program's move {} takes {:.4} s; the plan takes {:.4} s",
                        i + 1,
                        q,
                        p
                    ),
                ));
            }
        }
        out
    }
}

/// Writes the program for `moves`, models what the PMAC does with it, and compares that with the plan.
pub fn compare(
    cs: &CoordSystem,
    moves: &[LinearMove],
    opts: &ProgramOptions,
) -> Result<Comparison, PmacError> {
    let planned = program::plan(cs, moves, opts.start.as_deref())?;
    let text = program::write_with(cs, moves, opts)?;
    let timeline = verify::parse_program(&text, opts.start.as_deref())?;
    let spans = timeline.move_spans();
    let corner_speeds = timeline.corner_speeds();
    let mut out = Comparison::default();
    // Zero-length moves are not in the program: match planned moves to moves that have length.
    let real: Vec<&LinearMove> = {
        let mut pos = opts
            .start
            .clone()
            .unwrap_or_else(|| vec![0.0; cs.axes.len()]);
        let mut v = Vec::new();
        for m in moves {
            let end: Vec<f64> = match m.mode {
                crate::model::MoveMode::Abs => m.target.clone(),
                crate::model::MoveMode::Inc => {
                    pos.iter().zip(&m.target).map(|(p, d)| p + d).collect()
                }
            };
            if end.iter().zip(&pos).any(|(e, p)| e != p) {
                v.push(m);
            }
            pos = end;
        }
        v
    };
    let mut from_rest = true;
    for (i, p) in planned.iter().enumerate() {
        if from_rest && p.stops {
            let plan_time = p.length / p.speed + (p.accel.time + p.decel.time) / 2.0;
            if let Some((a, b)) = spans.get(i) {
                out.move_times.push((plan_time, b - a));
            }
        }
        if !p.stops {
            if let (Some(Transition::Blend { junction_velocity }), Some(Some(speed))) = (
                real.get(i).map(|m| m.transition),
                corner_speeds.get(i).copied(),
            ) {
                out.corners.push(Corner {
                    after_move: i,
                    planned: junction_velocity,
                    program: speed,
                });
            }
        }
        from_rest = p.stops;
    }
    Ok(out)
}
