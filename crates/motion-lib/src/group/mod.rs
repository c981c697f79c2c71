//! Axes groups (PLCopen Part 4): membership, the group state machine, the group command
//! buffer and path interpolation.
//!
//! Input: group commands (enable, motion, stop, ...) and [`Engine::step`]. Output: each
//! cycle the set points of the group's axes along the path. Invariants: a group has at
//! most [`MAX_AXES`] axes, one per identity; while the group moves its axes are in
//! SynchronizedMotion and only the group writes their set points; an axis error puts
//! the group into GroupErrorStop, fails every buffered group command and clears the queue.

use crate::buffer::{BufferMode, Queue, TransitionMode};
use crate::cmd::{CmdId, CmdStatus};
use crate::engine::{standing, Active, Engine, Kind};
use crate::error::ErrorId;
use crate::fsm::{check_group, AxisState, GroupCmd, GroupState};
use crate::path::{CircMode, Geometry, Vecn, MAX_AXES};
use crate::profile::line::path_limits;
use crate::profile::{Limits, Profile, State};

mod activate;
mod cycle;
mod link;
mod plan;

/// A group motion command.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum GroupMotion {
    /// MC_MoveLinearAbsolute (positions per identity; entries of absent identities ignored).
    LinearAbsolute {
        /// End point per identity, u.
        position: Vecn,
    },
    /// MC_MoveLinearRelative.
    LinearRelative {
        /// Distance per identity, u, from the group's last commanded point.
        distance: Vecn,
    },
    /// MC_MoveCircularAbsolute / Relative (relative: aux and end relative to the start).
    Circular {
        /// How `aux` defines the circle (BORDER, CENTER, RADIUS).
        mode: CircMode,
        /// AuxPoint per identity (a point on the arc, the centre, or the plane normal with the
        /// radius as length).
        aux: Vecn,
        /// EndPoint per identity, u.
        end: Vecn,
        /// PathChoice: TRUE counter-clockwise (CENTER and RADIUS).
        ccw: bool,
        /// TRUE for MC_MoveCircularRelative: `aux` (except RADIUS) and `end` are relative to the
        /// start point.
        relative: bool,
    },
    /// MC_MoveDirectAbsolute: each axis to its target on its own profile.
    DirectAbsolute {
        /// End point per identity, u.
        position: Vecn,
    },
    /// MC_GroupHalt.
    Halt,
    /// MC_GroupStop.
    Stop,
}

/// Path dynamics and blending inputs of a group move.
#[derive(Clone, Copy, Debug, PartialEq, Default)]
pub struct PathInputs {
    /// Largest path speed, u/s (further limited by the axes' limits projected onto the path).
    pub velocity: f64,
    /// Path acceleration, u/s² (further limited by the axes' limits).
    pub acceleration: f64,
    /// Path deceleration, u/s² (further limited by the axes' limits).
    pub deceleration: f64,
    /// 0 = the axes' jerk limits.
    pub jerk: f64,
    /// BufferMode of the group command.
    pub buffer: BufferMode,
    /// TransitionMode towards the predecessor (with a blending BufferMode).
    pub transition: TransitionMode,
    /// TMCornerDistance: the corner distance; TMMaxCornerDeviation: the largest
    /// distance of the blend from the corner.
    pub transition_parameter: f64,
}

/// Why a junction speed was lowered (see the README, "Junction speeds").
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ReductionReason {
    /// TMNone at a corner (the direction changes): passed at rest.
    Corner,
    /// A junction with a circular move (the curvature steps): passed at rest.
    Arc,
    /// The corner blend's curvature or its change: the highest speed the axes allow on it.
    Blend,
    /// The corner is too sharp for a blend (a reversal) or the blend has no room: at rest.
    NoBlend,
    /// The junction speed is above an axis's velocity limit projected onto a line.
    Velocity,
    /// The predecessor's line is too short to reach the junction speed.
    Distance,
    /// An arc's path speed: its curvature and the axes' acceleration and jerk limits
    /// allow less than the block's Velocity (README, "Arc speed").
    ArcSpeed,
}

impl ReductionReason {
    /// Short name (trace and run summary).
    pub fn name(self) -> &'static str {
        match self {
            ReductionReason::Corner => "TMNone corner",
            ReductionReason::Arc => "circle junction",
            ReductionReason::Blend => "blend curvature",
            ReductionReason::NoBlend => "no room for a blend",
            ReductionReason::Velocity => "axis velocity limit",
            ReductionReason::Distance => "line too short",
            ReductionReason::ArcSpeed => "arc curvature",
        }
    }
}

/// A lowered junction speed: between the group's motion commands `block - 1` and `block`
/// (numbered from 1 in the order they were given to the group).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Reduction {
    /// Sequence number of the successor (the block that starts at the junction).
    pub block: u32,
    /// The successor's command handle.
    pub cmd: CmdId,
    /// The corner as commanded (raw axis coordinates by identity).
    pub corner: Vecn,
    /// Junction speed the BufferMode asked for.
    pub requested: f64,
    /// Junction speed planned and reached.
    pub reached: f64,
    /// Which rule lowered the speed.
    pub reason: ReductionReason,
}

/// Reductions kept per group (the count goes on; older entries are kept, later ones only counted).
pub const REDUCTIONS_KEPT: usize = 256;

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum GKind {
    Home,
    Path,
    Direct,
    Halt,
    Stop,
    Brake,
}

#[derive(Clone, Copy, Debug)]
pub(crate) struct GPending {
    id: CmdId,
    kind: GKind,
    motion: GroupMotion,
    /// Absolute raw end point.
    target: Vecn,
    inputs: PathInputs,
    speed: f64,
    end_v: f64,
    /// Corner blend run before this move (geometry, constant path speed).
    prefix: Option<(Geometry, f64)>,
    /// Path speed at the start when the predecessor ended at a blending junction.
    start_v: Option<f64>,
    /// The corner this move starts from as commanded (before any corner blend).
    start_corner: Vecn,
    /// Sequence number among the group's motion commands (from 1).
    seq: u32,
    /// The junction before this move was lowered: (requested, reached).
    reduced: Option<(f64, f64)>,
    /// Direction the predecessor arrives with, as the junction was planned (zero: no
    /// junction speed). A predecessor that starts elsewhere (its own predecessor failed)
    /// and so arrives otherwise ends at rest instead.
    pred_dir: Vecn,
}

#[derive(Clone, Debug)]
pub(crate) struct GActive {
    kind: GKind,
    id: Option<CmdId>,
    geom: Geometry,
    prof: Profile,
    t: f64,
    prefix: Option<(Geometry, f64)>,
    prefix_end: f64,
    target: Vecn,
    speed: f64,
    lim: Limits,
    end_v: f64,
    direct: Option<Box<[Profile; MAX_AXES]>>,
    /// Velocity-change tail after `prof` (see `engine::plan_to`).
    tail: Option<Profile>,
}

/// Runtime of one group.
#[derive(Clone, Debug)]
pub(crate) struct GroupRt {
    pub state: GroupState,
    pub axes: [Option<u32>; MAX_AXES],
    queue: Queue<GPending>,
    active: Option<GActive>,
    stop_owner: Option<CmdId>,
    pub error: ErrorId,
    scratch: (Vecn, Vecn, Vecn),
    /// Motion commands given so far (numbers the blocks of [`Reduction`]).
    seq: u32,
    /// Lowered junctions (the first [`REDUCTIONS_KEPT`]) and their total count.
    reductions: Vec<Reduction>,
    reduction_count: usize,
    /// (requested, reached) of a lowered junction passed in the last cycle, else (0, 0).
    junction_now: (f64, f64),
    /// (requested, reached) path speed of an arc that started since the last cycle and
    /// whose speed its curvature lowered (shown as `junction_now` unless a lowered
    /// junction takes that cycle).
    arc_now: Option<(f64, f64)>,
    /// The running move could not be planned to its junction (or failed): the next one
    /// starts from rest, without its corner blend.
    drop_junction: bool,
}

impl GroupRt {
    fn n(&self) -> usize {
        self.axes
            .iter()
            .rposition(|a| a.is_some())
            .map_or(0, |i| i + 1)
    }
}

const ZERO: Vecn = [0.0; MAX_AXES];

impl Engine {
    /// Adds an empty group; returns its index.
    pub fn add_group(&mut self) -> usize {
        self.groups.push(GroupRt {
            state: GroupState::GroupDisabled,
            axes: [None; MAX_AXES],
            queue: Queue::new(self.cfg.queue_depth),
            active: None,
            stop_owner: None,
            error: ErrorId::None,
            scratch: (ZERO, ZERO, ZERO),
            seq: 0,
            reductions: Vec::with_capacity(16),
            reduction_count: 0,
            junction_now: (0.0, 0.0),
            arc_now: None,
            drop_junction: false,
        });
        self.groups.len() - 1
    }

    fn grp(&self, g: usize) -> Result<&GroupRt, ErrorId> {
        self.groups.get(g).ok_or(ErrorId::InvalidGroup)
    }

    /// Group state.
    pub fn group_state(&self, g: usize) -> Result<GroupState, ErrorId> {
        Ok(self.grp(g)?.state)
    }

    /// The axis with identity `ident` in the group.
    pub fn group_axis(&self, g: usize, ident: usize) -> Result<Option<usize>, ErrorId> {
        Ok(self
            .grp(g)?
            .axes
            .get(ident)
            .copied()
            .flatten()
            .map(|a| a as usize))
    }

    /// Commands waiting in the group's buffer.
    pub fn group_queued(&self, g: usize) -> Result<usize, ErrorId> {
        Ok(self.grp(g)?.queue.len())
    }

    /// The group's lowered junction speeds (the first [`REDUCTIONS_KEPT`]) and how many
    /// there were in all.
    pub fn group_reductions(&self, g: usize) -> Result<(&[Reduction], usize), ErrorId> {
        let gr = self.grp(g)?;
        Ok((&gr.reductions, gr.reduction_count))
    }

    /// (requested, reached) junction speed of a lowered junction the path passed in the
    /// last cycle; (0, 0) in every other cycle.
    pub fn group_junction_now(&self, g: usize) -> Result<(f64, f64), ErrorId> {
        Ok(self.grp(g)?.junction_now)
    }

    /// MC_AddAxisToGroup.
    pub fn add_axis_to_group(
        &mut self,
        g: usize,
        axis: usize,
        ident: usize,
    ) -> Result<(), ErrorId> {
        let gr = self.grp(g)?;
        check_group(gr.state, GroupCmd::Configure)?;
        let ax = self.axis(axis)?;
        if ident >= MAX_AXES || gr.axes[ident].is_some() {
            return Err(ErrorId::InvalidIdentInGroup);
        }
        if ax.group.is_some() {
            return Err(ErrorId::AxisAlreadyInGroup);
        }
        self.groups[g].axes[ident] = Some(axis as u32);
        self.axes[axis].group = Some(g as u16);
        Ok(())
    }

    /// MC_RemoveAxisFromGroup (by identity).
    pub fn remove_axis_from_group(&mut self, g: usize, ident: usize) -> Result<(), ErrorId> {
        let gr = self.grp(g)?;
        check_group(gr.state, GroupCmd::Configure)?;
        let a = gr
            .axes
            .get(ident)
            .copied()
            .flatten()
            .ok_or(ErrorId::AxisNotInGroup)?;
        self.groups[g].axes[ident] = None;
        self.axes[a as usize].group = None;
        Ok(())
    }

    /// MC_UngroupAllAxes: removes every axis; the group is GroupDisabled.
    pub fn ungroup_all(&mut self, g: usize) -> Result<(), ErrorId> {
        let gr = self.grp(g)?;
        let st = check_group(gr.state, GroupCmd::Ungroup)?;
        for i in 0..MAX_AXES {
            if let Some(a) = self.groups[g].axes[i].take() {
                self.axes[a as usize].group = None;
            }
        }
        self.groups[g].state = st;
        Ok(())
    }

    /// MC_GroupEnable: every axis powered and in Standstill.
    pub fn group_enable(&mut self, g: usize) -> Result<(), ErrorId> {
        let gr = self.grp(g)?;
        let st = check_group(gr.state, GroupCmd::Enable)?;
        let members: Vec<u32> = gr.axes.iter().flatten().copied().collect();
        if members.is_empty()
            || members.iter().any(|&a| {
                !self.axes[a as usize].powered
                    || self.axes[a as usize].state != AxisState::Standstill
            })
        {
            return Err(ErrorId::GroupAxesNotReady);
        }
        self.groups[g].state = st;
        Ok(())
    }

    /// MC_GroupDisable.
    pub fn group_disable(&mut self, g: usize) -> Result<(), ErrorId> {
        let gr = self.grp(g)?;
        let st = check_group(gr.state, GroupCmd::Disable)?;
        self.groups[g].state = st;
        Ok(())
    }

    /// MC_GroupReset: GroupErrorStop -> GroupStandby, resetting the axes' errors.
    pub fn group_reset(&mut self, g: usize) -> Result<(), ErrorId> {
        let gr = self.grp(g)?;
        if gr.state != GroupState::GroupErrorStop {
            return Ok(());
        }
        if gr.active.is_some() {
            return Err(ErrorId::AxisStillMoving);
        }
        let members: Vec<u32> = gr.axes.iter().flatten().copied().collect();
        for a in members {
            self.reset(a as usize)?;
        }
        let st = check_group(GroupState::GroupErrorStop, GroupCmd::Reset)?;
        self.groups[g].state = st;
        self.groups[g].error = ErrorId::None;
        Ok(())
    }

    /// The group's error (GroupErrorStop reason).
    pub fn group_error(&self, g: usize) -> Result<ErrorId, ErrorId> {
        Ok(self.grp(g)?.error)
    }

    /// Set positions of the group's axes (user units) by identity; absent identities 0.
    pub fn group_position(&self, g: usize) -> Result<Vecn, ErrorId> {
        let gr = self.grp(g)?;
        let mut r = ZERO;
        for (i, a) in gr.axes.iter().enumerate() {
            if let Some(a) = a {
                r[i] = self.set_position_of(*a as usize)?;
            }
        }
        Ok(r)
    }

    /// Set velocities of the group's axes by identity, and the path velocity (norm).
    pub fn group_velocity(&self, g: usize) -> Result<(Vecn, f64), ErrorId> {
        let gr = self.grp(g)?;
        let mut r = ZERO;
        for (i, a) in gr.axes.iter().enumerate() {
            if let Some(a) = a {
                r[i] = self.axes[*a as usize].set.v;
            }
        }
        let n = r.iter().map(|x| x * x).sum::<f64>().sqrt();
        Ok((r, n))
    }

    fn raw_now(&self, g: usize) -> Vecn {
        let mut r = ZERO;
        for (i, a) in self.groups[g].axes.iter().enumerate() {
            if let Some(a) = a {
                r[i] = self.axes[*a as usize].set.p;
            }
        }
        r
    }

    /// End point (raw) the next buffered group move starts from: the last path move's
    /// target in the buffer, else the running move's (a halt's: where its brake ends).
    fn group_last_target(&self, g: usize) -> Vecn {
        let gr = &self.groups[g];
        if let Some(b) = gr
            .queue
            .iter()
            .filter(|b| matches!(b.kind, GKind::Path | GKind::Direct))
            .last()
        {
            return b.target;
        }
        match &gr.active {
            Some(a) if matches!(a.kind, GKind::Path | GKind::Direct) => a.target,
            Some(a) if matches!(a.kind, GKind::Halt | GKind::Stop | GKind::Brake) => {
                let n = gr.n();
                if let Some(profs) = &a.direct {
                    // Each axis brakes on its own profile.
                    let mut r = self.raw_now(g);
                    for (i, ax) in gr.axes.iter().enumerate().take(n) {
                        if ax.is_some() {
                            r[i] = profs[i].end().p;
                        }
                    }
                    return r;
                }
                let mut q = self.raw_now(g);
                let (mut d1, mut d2) = (ZERO, ZERO);
                // (A brake begun on a corner blend has the line after it as geometry.)
                a.geom.eval(a.prof.end().p, n, &mut q, &mut d1, &mut d2);
                let mut r = self.raw_now(g);
                for (i, ax) in gr.axes.iter().enumerate() {
                    if ax.is_some() {
                        r[i] = q[i];
                    }
                }
                r
            }
            _ => self.raw_now(g),
        }
    }
}

/// The junction speed closest to `vj` (towards the start speed) that a jerk-limited
/// velocity change from `start` reaches within `room` (bisection on the distance the
/// change needs).
fn reachable(start: State, room: f64, vj: f64, lim: &Limits) -> f64 {
    let mut l = *lim;
    l.vmax = l.vmax.max(start.v.abs()).max(vj);
    l.amax = l.amax.max(start.a.abs());
    let need =
        |v: f64| -> f64 { Profile::velocity(start, v, &l).map_or(f64::INFINITY, |p| p.end().p) };
    if room <= 0.0 {
        return 0.0;
    }
    if need(vj) <= room {
        return vj;
    }
    // From vj towards the start speed, the distance needed shrinks (when accelerating).
    let (mut ok, mut bad) = (start.v.max(0.0), vj);
    if need(ok) > room {
        return if vj < start.v { vj } else { 0.0 };
    }
    for _ in 0..60 {
        let m = 0.5 * (ok + bad);
        if need(m) <= room {
            ok = m;
        } else {
            bad = m;
        }
    }
    ok
}

fn dist(a: &Vecn, b: &Vecn) -> f64 {
    a.iter()
        .zip(b)
        .map(|(x, y)| (x - y) * (x - y))
        .sum::<f64>()
        .sqrt()
}

/// Corner distance d of the clothoid blend (legs meeting with unit tangents u1, u2,
/// cos = u1.u2). TMCornerDistance gives d itself. The blend's closest point to the corner
/// is its midpoint; TMMaxCornerDeviation e gives the d whose midpoint is e from the corner
/// ([`Geometry::blend_distance_for_deviation`]; a shorter d, as when a leg is short,
/// deviates less).
pub(crate) fn corner_distance(mode: TransitionMode, parameter: f64, cos: f64) -> f64 {
    match mode {
        TransitionMode::None => 0.0,
        TransitionMode::CornerDistance => parameter,
        TransitionMode::MaxCornerDeviation => {
            let alpha = cos.clamp(-1.0, 1.0).acos();
            if alpha > 1e-9 {
                Geometry::blend_distance_for_deviation(parameter, alpha)
            } else {
                0.0
            }
        }
    }
}
