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

    fn path_lims(&self, g: usize, unit: &Vecn, inp: &PathInputs) -> Result<Limits, ErrorId> {
        let gr = &self.groups[g];
        // Fixed arrays: this runs inside the cycle on an error brake, so no allocation.
        let mut us = [0.0; MAX_AXES];
        let mut ls = [Limits::default(); MAX_AXES];
        let mut k = 0;
        for (i, a) in gr.axes.iter().enumerate() {
            if let Some(a) = a {
                us[k] = unit[i];
                ls[k] = self.axes[*a as usize].cfg.limits;
                k += 1;
            }
        }
        let mut l = path_limits(&us[..k], &ls[..k]).map_err(|_| ErrorId::PlanningFailed)?;
        let pos = |x: f64| x.is_finite() && x > 0.0;
        if !pos(inp.velocity) {
            return Err(ErrorId::InvalidVelocity);
        }
        if !pos(inp.acceleration) {
            return Err(ErrorId::InvalidAcceleration);
        }
        if !pos(inp.deceleration) {
            return Err(ErrorId::InvalidDeceleration);
        }
        if !(inp.jerk.is_finite() && inp.jerk >= 0.0) {
            return Err(ErrorId::InvalidJerk);
        }
        l.vmax = l.vmax.min(inp.velocity);
        l.amax = l.amax.min(inp.acceleration);
        l.dmax = l.dmax.min(inp.deceleration);
        if inp.jerk > 0.0 {
            l.jmax = if l.jmax.is_infinite() || l.jmax == 0.0 {
                inp.jerk
            } else {
                l.jmax.min(inp.jerk)
            };
        }
        if l.jmax.is_infinite() {
            l.jmax = 0.0;
        }
        Ok(l)
    }

    /// The move `p` ends at rest instead of at its junction speed: its successor starts
    /// from rest (reported as a reduction to 0).
    fn note_dropped_junction(&mut self, g: usize, p: &GPending) {
        let gr = &mut self.groups[g];
        gr.drop_junction = true;
        gr.reduction_count += 1;
        if let Some(nx) = gr.queue.front() {
            if gr.reductions.len() < REDUCTIONS_KEPT {
                gr.reductions.push(Reduction {
                    block: nx.seq,
                    cmd: nx.id,
                    corner: p.target,
                    requested: p.end_v,
                    reached: 0.0,
                    reason: ReductionReason::Distance,
                });
            }
        }
    }

    /// A move or brake that starts while the path accelerates: with the block's (lower)
    /// jerk the speed would pass the axes' velocity limit on direction `u` before the
    /// acceleration is gone; the jerk is then raised to the axes' own, projected.
    fn raise_jerk(&self, g: usize, u: &Vecn, s: State, lim: &mut Limits) {
        if lim.jmax <= 0.0 || s.a == 0.0 {
            return;
        }
        let free = PathInputs {
            velocity: f64::MAX,
            acceleration: f64::MAX,
            deceleration: f64::MAX,
            jerk: 0.0,
            ..PathInputs::default()
        };
        let Ok(axes) = self.path_lims(g, u, &free) else {
            return;
        };
        let peak = (s.v + s.a * s.a.abs() / (2.0 * lim.jmax)).abs();
        if peak > axes.vmax && (axes.jmax == 0.0 || axes.jmax > lim.jmax) {
            lim.jmax = axes.jmax;
        }
    }

    /// Arc path limits ("Arc speed" in the README). The tangent turns, so every axis's
    /// limits bound the path. With a = min over the axes of min(amax, dmax) and j the
    /// lowest axis jerk limit, on an arc of curvature k (largest |d2|) and largest |d3| = m:
    /// an axis accelerates at most |a_t| + k v^2 and jerks at most
    /// |j_t| + 3 k v |a_t| + m v^3 (a_t, j_t the path's tangential acceleration and jerk).
    /// The budget is split: the tangential acceleration and the turn get a / 2 each
    /// (v <= sqrt(a / (2 k))); the tangential jerk j / 2, the turn's own jerk j / 4
    /// (v <= cbrt(j / (4 m))), the cross term j / 4 (|a_t| <= j / (12 k v)). Returns the
    /// path speed the arc allows (the lowest of those caps and the axes' velocity limits).
    fn arc_limits(&self, g: usize, geo: &Geometry, lim: &mut Limits) -> f64 {
        let n = self.groups[g].n();
        let mut vmax = f64::INFINITY;
        let mut amin = f64::INFINITY;
        let mut jmin = f64::INFINITY;
        for a in self.groups[g].axes.iter().flatten() {
            let l = self.axes[*a as usize].cfg.limits;
            vmax = vmax.min(l.vmax);
            amin = amin.min(l.amax).min(l.dmax);
            if l.jmax > 0.0 {
                jmin = jmin.min(l.jmax);
            }
        }
        let half = amin.min(lim.amax).min(lim.dmax) / 2.0;
        let k = geo.max_curvature(n);
        let m = geo.max_d3();
        let v_turn = if k > 0.0 {
            (half / k).sqrt()
        } else {
            f64::INFINITY
        };
        let mut v_arc = vmax.min(v_turn);
        lim.amax = lim.amax.min(half);
        lim.dmax = lim.dmax.min(half);
        if jmin.is_finite() {
            if m > 0.0 {
                v_arc = v_arc.min((jmin / (4.0 * m)).cbrt());
            }
            if k > 0.0 && v_arc > 0.0 {
                let a_cross = jmin / (12.0 * k * v_arc);
                lim.amax = lim.amax.min(a_cross);
                lim.dmax = lim.dmax.min(a_cross);
            }
            lim.jmax = if lim.jmax > 0.0 {
                lim.jmax.min(jmin / 2.0)
            } else {
                jmin / 2.0
            };
        }
        lim.vmax = lim.vmax.min(v_arc);
        v_arc
    }

    /// Software limits of the group's axes against a path piece between arc lengths
    /// `s0 <= s1` (the geometry over [0, len] and, at activation, the planned profile's
    /// overshoot): ErrorID 27 when the end point of an axis lies outside its range, 29 when
    /// the path leaves it (an arc's bulge, an overshoot). As for single axes, an axis that
    /// starts beyond a limit may move back, never further out.
    fn group_sw_check(&self, g: usize, geo: &Geometry, s0: f64, s1: f64) -> Result<(), ErrorId> {
        let gr = &self.groups[g];
        let n = gr.n();
        let on = |a: &u32| {
            let c = &self.axes[*a as usize].cfg;
            c.sw_limits_enabled && c.period().is_none()
        };
        if !gr.axes.iter().flatten().any(on) {
            return Ok(());
        }
        let (mut start, mut end, mut d1, mut d2) = (ZERO, ZERO, ZERO, ZERO);
        geo.eval(0.0, n, &mut start, &mut d1, &mut d2);
        geo.eval(geo.len(), n, &mut end, &mut d1, &mut d2);
        let (lo, hi) = geo.axis_range(n, s0.min(0.0), s1.max(geo.len()));
        for (i, a) in gr.axes.iter().enumerate().take(n) {
            let Some(a) = a.filter(on) else {
                continue;
            };
            let ax = &self.axes[a as usize];
            let (o, c) = (ax.origin, &ax.cfg);
            let e = end[i] + o;
            if e > c.sw_limit_pos || e < c.sw_limit_neg {
                return Err(ErrorId::TargetBeyondSoftwareLimit);
            }
            let top = c.sw_limit_pos.max(start[i] + o);
            let bottom = c.sw_limit_neg.min(start[i] + o);
            let eps = 1e-12 * (1.0 + top.abs().max(bottom.abs()));
            if hi[i] + o > top + eps || lo[i] + o < bottom - eps {
                return Err(ErrorId::PathBeyondSoftwareLimit);
            }
        }
        Ok(())
    }

    /// Gives a motion command to a group. Returns its handle or the ErrorID.
    pub fn submit_group(
        &mut self,
        g: usize,
        motion: GroupMotion,
        inputs: PathInputs,
    ) -> Result<CmdId, ErrorId> {
        let gr = self.grp(g)?;
        let class = match motion {
            GroupMotion::Stop => GroupCmd::Stop,
            _ => GroupCmd::Motion,
        };
        check_group(gr.state, class)?;
        if (inputs.buffer.is_blending() || inputs.transition != TransitionMode::None)
            && !(inputs.transition_parameter.is_finite() && inputs.transition_parameter >= 0.0)
        {
            return Err(ErrorId::InvalidTransitionMode);
        }
        let n = gr.n();
        let origin =
            |eng: &Engine, i: usize| gr.axes[i].map_or(0.0, |a| eng.axes[a as usize].origin);
        let mut buffer = inputs.buffer;
        let kind = match motion {
            GroupMotion::Stop => {
                buffer = BufferMode::Aborting;
                GKind::Stop
            }
            GroupMotion::Halt => GKind::Halt,
            GroupMotion::DirectAbsolute { .. } => GKind::Direct,
            _ => GKind::Path,
        };
        let from = if buffer == BufferMode::Aborting {
            self.raw_now(g)
        } else {
            self.group_last_target(g)
        };
        let check = |v: &Vecn| -> Result<(), ErrorId> {
            if v[..n].iter().all(|x| x.is_finite()) {
                Ok(())
            } else {
                Err(ErrorId::InvalidPosition)
            }
        };
        let mut target = from;
        match motion {
            GroupMotion::LinearAbsolute { position } | GroupMotion::DirectAbsolute { position } => {
                check(&position)?;
                for i in 0..n {
                    if gr.axes[i].is_some() {
                        target[i] = position[i] - origin(self, i);
                    }
                }
            }
            GroupMotion::LinearRelative { distance } => {
                check(&distance)?;
                for i in 0..n {
                    if gr.axes[i].is_some() {
                        target[i] = from[i] + distance[i];
                    }
                }
            }
            GroupMotion::Circular {
                end,
                aux,
                relative,
                mode,
                ccw,
            } => {
                check(&end)?;
                check(&aux)?;
                let mut e = from;
                // RADIUS: AuxPoint is the plane's normal vector, taken as given.
                let mut x = if mode == CircMode::Radius { aux } else { from };
                for i in 0..n {
                    if gr.axes[i].is_some() {
                        e[i] = if relative {
                            from[i] + end[i]
                        } else {
                            end[i] - origin(self, i)
                        };
                        x[i] = if mode == CircMode::Radius {
                            aux[i]
                        } else if relative {
                            from[i] + aux[i]
                        } else {
                            aux[i] - origin(self, i)
                        };
                    }
                }
                Geometry::arc(&from, &x, &e, mode, ccw).ok_or(ErrorId::InvalidCircle)?;
                target = e;
            }
            GroupMotion::Halt | GroupMotion::Stop => {}
        }
        // Validate the dynamics against the move's direction.
        let geom = self.geometry_for(g, &from, &target, &motion);
        if kind == GKind::Path {
            // The path (end point, an arc's bulge) within the software limits, before any
            // motion; buffered moves again when they start (from where they really start).
            self.group_sw_check(g, &geom, 0.0, geom.len())?;
        } else if kind == GKind::Direct {
            self.group_sw_check(g, &Geometry::line(&target, &target), 0.0, 0.0)?;
        }
        let (t0, _) = geom.tangents(n);
        let lim = match kind {
            GKind::Halt | GKind::Stop => {
                let mut i2 = inputs;
                i2.velocity = f64::MAX;
                i2.acceleration = inputs.deceleration;
                self.path_lims(g, &t0, &i2)?
            }
            _ => self.path_lims(g, &t0, &inputs)?,
        };
        let _ = lim;
        let gr = &self.groups[g];
        let idle = gr.active.is_none();
        if buffer != BufferMode::Aborting && !idle && gr.queue.len() >= gr.queue.depth() {
            return Err(ErrorId::QueueFull);
        }
        let id = self.cmds.alloc(CmdStatus::Queued);
        let seq = if matches!(kind, GKind::Path | GKind::Direct) {
            self.groups[g].seq = self.groups[g].seq.wrapping_add(1);
            self.groups[g].seq
        } else {
            0
        };
        let p = GPending {
            id,
            kind,
            motion,
            target,
            inputs: PathInputs { buffer, ..inputs },
            speed: inputs.velocity.abs(),
            end_v: 0.0,
            prefix: None,
            start_v: None,
            start_corner: from,
            seq,
            reduced: None,
            pred_dir: ZERO,
        };
        if buffer == BufferMode::Aborting || idle {
            self.group_abort_all(g, CmdStatus::Aborted);
            if kind == GKind::Path && self.group_turns(g, &from, &target, &motion) {
                // The path turns away from the current motion: a velocity or acceleration
                // step would break the axis limits, so the group first brakes along its
                // path (the command is Active meanwhile) and starts from there.
                self.group_brake_then(g, p);
            } else if let Err(e) = self.group_activate(g, p, 0.0) {
                // Refused as it starts (e.g. its overshoot leaves the software limits): the
                // running move, already aborted, brakes along its path.
                if let Some(lim) = self.groups[g].active.as_ref().map(|a| a.lim) {
                    // With the running move's own deceleration: it stops before the end
                    // it was planned to.
                    let halt = GPending {
                        kind: GKind::Halt,
                        motion: GroupMotion::Halt,
                        speed: 0.0,
                        seq: 0,
                        inputs: PathInputs {
                            deceleration: if lim.dmax > 0.0 {
                                lim.dmax
                            } else {
                                p.inputs.deceleration
                            },
                            jerk: lim.jmax,
                            ..p.inputs
                        },
                        ..p
                    };
                    if self.group_activate(g, halt, 0.0).is_ok() {
                        if let Some(a) = self.groups[g].active.as_mut() {
                            a.id = None;
                        }
                    }
                }
                self.cmds.set(id, CmdStatus::Error(e));
            }
        } else {
            let mut p = p;
            self.group_link(g, &mut p);
            if let Err((e, p)) = self.groups[g].queue.push(p) {
                self.cmds.set(p.id, CmdStatus::Error(e));
            }
        }
        Ok(id)
    }

    /// True when the group moves (or accelerates) across the start direction of the new
    /// path from `from` to `target`.
    fn group_turns(&self, g: usize, from: &Vecn, target: &Vecn, motion: &GroupMotion) -> bool {
        if self.groups[g].active.is_none() {
            return false;
        }
        let n = self.groups[g].n();
        let geo = self.geometry_for(g, from, target, motion);
        let (u, _) = geo.tangents(n);
        let mut vel = ZERO;
        let mut acc = ZERO;
        for (i, a) in self.groups[g].axes.iter().enumerate() {
            if let Some(a) = a {
                vel[i] = self.axes[*a as usize].set.v;
                acc[i] = self.axes[*a as usize].set.a;
            }
        }
        let lateral = |x: &Vecn| {
            let along: f64 = (0..n).map(|i| x[i] * u[i]).sum();
            (0..n)
                .map(|i| (x[i] - along * u[i]).powi(2))
                .sum::<f64>()
                .sqrt()
        };
        let moving = vel[..n].iter().chain(&acc[..n]).any(|x| *x != 0.0);
        let arc = matches!(geo, Geometry::Arc { .. });
        moving && (arc || lateral(&vel) > 1e-12 || lateral(&acc) > 1e-12)
    }

    /// Brakes the running path to rest with `p`'s deceleration, then starts `p`.
    fn group_brake_then(&mut self, g: usize, mut p: GPending) {
        let halt = GPending {
            id: p.id,
            kind: GKind::Halt,
            motion: GroupMotion::Halt,
            target: ZERO,
            inputs: p.inputs,
            speed: 0.0,
            end_v: 0.0,
            prefix: None,
            start_v: None,
            start_corner: ZERO,
            seq: 0,
            reduced: None,
            pred_dir: ZERO,
        };
        if let Err(e) = self.group_activate(g, halt, 0.0) {
            self.cmds.set(p.id, CmdStatus::Error(e));
            return;
        }
        let n = self.groups[g].n();
        if let Some(a) = self.groups[g].active.as_mut() {
            a.id = None;
            // The move starts where the brake ends.
            let (mut q, mut d1, mut d2) = (ZERO, ZERO, ZERO);
            a.geom.eval(a.prof.end().p, n, &mut q, &mut d1, &mut d2);
            if let Some(profs) = &a.direct {
                for i in 0..n {
                    q[i] = profs[i].end().p;
                }
            }
            for (i, ax) in self.groups[g].axes.iter().enumerate() {
                if ax.is_some() {
                    p.start_corner[i] = q[i];
                }
            }
        }
        self.cmds.set(p.id, CmdStatus::Active);
        if let Err((e, p)) = self.groups[g].queue.push(p) {
            self.cmds.set(p.id, CmdStatus::Error(e));
        }
    }

    fn geometry_for(&self, g: usize, from: &Vecn, target: &Vecn, motion: &GroupMotion) -> Geometry {
        let n = self.groups[g].n();
        if let GroupMotion::Circular {
            aux,
            relative,
            mode,
            ccw,
            ..
        } = motion
        {
            let mut x = if *mode == CircMode::Radius {
                *aux
            } else {
                *from
            };
            for i in 0..n {
                if let Some(a) = self.groups[g].axes[i] {
                    x[i] = if *mode == CircMode::Radius {
                        aux[i]
                    } else if *relative {
                        from[i] + aux[i]
                    } else {
                        aux[i] - self.axes[a as usize].origin
                    };
                }
            }
            if let Some(geo) = Geometry::arc(from, &x, target, *mode, *ccw) {
                return geo;
            }
        }
        Geometry::line(from, target)
    }

    /// A blending successor joins the group's last move.
    fn group_link(&mut self, g: usize, next: &mut GPending) {
        if !next.inputs.buffer.is_blending() || next.kind != GKind::Path {
            return;
        }
        let n = self.groups[g].n();
        let gr = &self.groups[g];
        // Predecessor: the queue's back, else the active move.
        // Predecessor: the queue's back (its geometry from its original start corner: its
        // own predecessor may since have been shortened by a corner blend), else the
        // active move.
        let (pred_target, pred_speed, pred_kind, pred_is_active, pred_geom, pred_circle) =
            match gr.queue.back() {
                Some(b) => (
                    b.target,
                    b.speed,
                    b.kind,
                    false,
                    self.geometry_for(g, &b.start_corner, &b.target, &b.motion),
                    matches!(b.motion, GroupMotion::Circular { .. }),
                ),
                None => match &gr.active {
                    Some(a) => (
                        a.target,
                        a.speed,
                        a.kind,
                        true,
                        a.geom,
                        matches!(a.geom, Geometry::Arc { .. }),
                    ),
                    None => return,
                },
            };
        if pred_kind != GKind::Path {
            return;
        }
        let gr = &self.groups[g];
        // Where the predecessor's own line really starts (after its corner blend) and at
        // what path state: it has `room` to reach the junction speed.
        let (room_start, room, room_inputs) = match gr.queue.back() {
            Some(b) => {
                let start = match &b.prefix {
                    Some((Geometry::Blend { end, .. }, _)) => *end,
                    _ => b.start_corner,
                };
                let q = &gr.queue;
                let v0 = if q.len() >= 2 {
                    q.iter().nth(q.len() - 2).map_or(0.0, |p| p.end_v)
                } else {
                    gr.active.as_ref().map_or(0.0, |a| a.end_v)
                };
                (
                    State {
                        p: 0.0,
                        v: v0,
                        a: 0.0,
                    },
                    dist(&start, &b.target),
                    b.inputs,
                )
            }
            None => {
                let a = gr.active.as_ref().map(|a| {
                    let s_now = if a.t < a.prefix_end {
                        a.prof.start()
                    } else {
                        a.prof.at(a.t - a.prefix_end)
                    };
                    (s_now, a.geom.len() - s_now.p, a.lim)
                });
                match a {
                    Some((st, room, lim)) => (
                        State { p: 0.0, ..st },
                        room,
                        PathInputs {
                            velocity: lim.vmax,
                            acceleration: lim.amax,
                            deceleration: lim.dmax,
                            jerk: lim.jmax,
                            ..PathInputs::default()
                        },
                    ),
                    None => return,
                }
            }
        };
        let next_geom = self.geometry_for(g, &pred_target, &next.target, &next.motion);
        let (_, u1) = pred_geom.tangents(n);
        let (u2, _) = next_geom.tangents(n);
        let requested = next.inputs.buffer.junction_speed(pred_speed, next.speed);
        let mut vj = requested;
        let mut reason = ReductionReason::Velocity;
        // Corner blend.
        let mut new_pred_target = pred_target;
        let cos = (0..n).map(|i| u1[i] * u2[i]).sum::<f64>();
        // (A circle's geometry is known for sure only from where it starts: a circular
        // move on either side is a circle junction.)
        let lines = matches!(pred_geom, Geometry::Line { .. })
            && matches!(next_geom, Geometry::Line { .. })
            && !pred_circle
            && !matches!(next.motion, GroupMotion::Circular { .. });
        let tangent = cos >= 1.0 - 1e-12;
        if vj > 0.0 && lines {
            // Never above an axis's velocity limit projected onto either line.
            let free = PathInputs {
                velocity: f64::MAX,
                acceleration: f64::MAX,
                deceleration: f64::MAX,
                jerk: 0.0,
                ..PathInputs::default()
            };
            for u in [&u1, &u2] {
                if let Ok(l) = self.path_lims(g, u, &free) {
                    vj = vj.min(l.vmax);
                }
            }
        }
        if vj > 0.0 && !lines {
            vj = 0.0;
            reason = ReductionReason::Arc;
        } else if vj > 0.0 && !tangent {
            if next.inputs.transition == TransitionMode::None
                || next.inputs.transition_parameter <= 0.0
            {
                vj = 0.0;
                reason = ReductionReason::Corner;
            } else {
                let mut d = corner_distance(
                    next.inputs.transition,
                    next.inputs.transition_parameter,
                    cos,
                )
                .min(room / 2.0)
                .min(next_geom.len() / 2.0);
                if pred_is_active {
                    if let Some(a) = &gr.active {
                        let s_now = a.prof.at(a.t - a.prefix_end).p;
                        let remaining = pred_geom.len() - s_now;
                        // Leave room to reach the junction speed before the blend.
                        d = d.min(remaining * 0.5);
                    }
                }
                match Geometry::corner_blend(&pred_target, &u1, &u2, d, n) {
                    Some(blend) if d > 1e-9 => {
                        let vb = self.blend_speed(g, &blend);
                        if vb < vj {
                            vj = vb;
                            reason = ReductionReason::Blend;
                        }
                        if vj > 0.0 {
                            next.prefix = Some((blend, vj));
                            if let Geometry::Blend { start, .. } = blend {
                                new_pred_target = start;
                            }
                        }
                    }
                    _ => {
                        vj = 0.0;
                        reason = ReductionReason::NoBlend;
                    }
                }
            }
        }
        if vj > 0.0 {
            // The predecessor must reach vj on the room it has left (after the blend's cut).
            let cut = dist(&pred_target, &new_pred_target);
            let lim = self.path_lims(g, &u1, &room_inputs).ok();
            if let Some(lim) = lim {
                let r = reachable(room_start, room - cut, vj, &lim);
                if r < vj {
                    vj = r;
                    reason = ReductionReason::Distance;
                    match next.prefix.as_mut() {
                        Some(pre) if vj > 0.0 => pre.1 = vj,
                        _ => {
                            next.prefix = None;
                            new_pred_target = pred_target;
                        }
                    }
                }
            }
        }
        if vj > 0.0 {
            next.pred_dir = u1;
        }
        if vj < requested {
            next.reduced = Some((requested, vj));
            let gr = &mut self.groups[g];
            gr.reduction_count += 1;
            if gr.reductions.len() < REDUCTIONS_KEPT {
                gr.reductions.push(Reduction {
                    block: next.seq,
                    cmd: next.id,
                    corner: pred_target,
                    requested,
                    reached: vj,
                    reason,
                });
            }
        }
        let gr = &mut self.groups[g];
        if pred_is_active {
            if let Some(a) = gr.active.as_mut() {
                // Re-plan the running move to end at the junction (speed vj). While the
                // move still runs its own corner blend, its main part has not started:
                // re-plan that from its start state.
                let in_prefix = a.t < a.prefix_end;
                let s_now = if in_prefix {
                    a.prof.start()
                } else {
                    a.prof.at(a.t - a.prefix_end)
                };
                let new_len = a.geom.len() - dist(&pred_target, &new_pred_target);
                if let Ok((p, tail)) = crate::engine::plan_to(s_now, new_len, vj, &a.lim) {
                    a.prof = p;
                    a.tail = tail;
                    if !in_prefix {
                        a.t = a.prefix_end;
                    }
                    a.end_v = vj;
                    a.target = new_pred_target;
                } else {
                    next.prefix = None;
                }
            }
        } else if let Some(b) = gr.queue.back_mut() {
            b.end_v = vj;
            b.target = new_pred_target;
        }
    }

    /// The highest constant path speed on a corner blend at which every axis keeps its
    /// velocity, acceleration and jerk limits: min over axes of vmax / max|d1|,
    /// sqrt(a / max|d2|), cbrt(j / max|d3|) (derivatives by arc length, bounded in closed
    /// form by [`Geometry::blend_bounds`]). The block's Acceleration and Jerk bound the
    /// path's tangential motion; on the blend the path speed is constant and the axes
    /// carry the turn.
    fn blend_speed(&self, g: usize, blend: &Geometry) -> f64 {
        let n = self.groups[g].n();
        let Some((b1, b2, b3)) = blend.blend_bounds(n) else {
            return 0.0;
        };
        let mut v = f64::INFINITY;
        for (i, a) in self.groups[g].axes.iter().enumerate() {
            let Some(a) = a else { continue };
            let l = self.axes[*a as usize].cfg.limits;
            if b1[i] > 0.0 {
                v = v.min(l.vmax / b1[i]);
            }
            if b2[i] > 0.0 {
                v = v.min((l.amax.min(l.dmax) / b2[i]).sqrt());
            }
            if b3[i] > 0.0 && l.jmax > 0.0 && l.jmax.is_finite() {
                v = v.min((l.jmax / b3[i]).cbrt());
            }
        }
        // Rounding margin: the bounds are met with 1e-9 to spare.
        v * (1.0 - 1e-9)
    }

    fn group_abort_all(&mut self, g: usize, status: CmdStatus) {
        let gr = &mut self.groups[g];
        gr.drop_junction = false;
        if let Some(a) = gr.active.as_mut() {
            if let Some(id) = a.id.take() {
                self.cmds.set(id, status);
            }
        }
        let cmds = &mut self.cmds;
        gr.queue.drain_with(|p| cmds.set(p.id, status));
    }

    /// Current path state of the running group move (s, ds/dt, d2s/dt2) and its geometry.
    fn path_state(a: &GActive) -> (Geometry, State) {
        if a.t < a.prefix_end {
            if let Some((geo, v)) = a.prefix {
                return (
                    geo,
                    State {
                        p: v * a.t,
                        v,
                        a: 0.0,
                    },
                );
            }
        }
        (a.geom, a.prof.at(a.t - a.prefix_end))
    }

    fn group_activate(&mut self, g: usize, p: GPending, t0: f64) -> Result<(), ErrorId> {
        let n = self.groups[g].n();
        let now = self.raw_now(g);
        // Current axis velocities/accelerations by identity.
        let mut vel = ZERO;
        let mut acc = ZERO;
        for (i, a) in self.groups[g].axes.iter().enumerate() {
            if let Some(a) = a {
                vel[i] = self.axes[*a as usize].set.v;
                acc[i] = self.axes[*a as usize].set.a;
            }
        }
        let running = self.groups[g]
            .active
            .as_ref()
            .map(|a| (Self::path_state(a), a.lim));
        let mut tail = None;
        let mut end_v = p.end_v;
        // A brake that starts on a corner blend finishes the blend at its constant speed
        // (its curvature takes the whole acceleration budget) and brakes on the line after it.
        let in_blend = self.groups[g].active.as_ref().and_then(|a| match a.prefix {
            Some((b @ Geometry::Blend { end, u2, .. }, v)) if a.t < a.prefix_end => {
                Some((b, v, a.t, a.prefix_end, end, u2))
            }
            _ => None,
        });
        let mut keep_prefix = None;
        // An arc whose path speed its curvature lowered: (requested, reached, start).
        let mut arc_cut = None;
        let (geom, prof, lim, direct, prefix_end) = match p.kind {
            GKind::Halt | GKind::Stop | GKind::Brake if in_blend.is_some() => {
                let Some((b, v, t, pe, end, u2)) = in_blend else {
                    return Err(ErrorId::PlanningFailed);
                };
                let mut i2 = p.inputs;
                i2.velocity = f64::MAX;
                i2.acceleration = p.inputs.deceleration;
                let mut lim = self.path_lims(g, &u2, &i2)?;
                lim.amax = lim.amax.max(lim.dmax);
                lim.vmax = lim.vmax.max(v);
                let s0 = State { p: 0.0, v, a: 0.0 };
                let prof = Profile::velocity(s0, 0.0, &lim).map_err(|_| ErrorId::PlanningFailed)?;
                let mut far = end;
                let l = prof.end().p.max(1e-9);
                for i in 0..n {
                    far[i] += u2[i] * l;
                }
                keep_prefix = Some(((b, v), t));
                (Geometry::line(&end, &far), prof, lim, None, pe)
            }
            GKind::Halt | GKind::Stop | GKind::Brake
                if self.groups[g]
                    .active
                    .as_ref()
                    .is_some_and(|a| a.direct.is_some()) =>
            {
                // A MoveDirectAbsolute (or its brake) runs: each axis brakes on its own
                // profile with the block's deceleration and jerk capped by its limits.
                let mut profs = Box::new([standing(0.0); MAX_AXES]);
                for i in 0..n {
                    if let Some(a) = self.groups[g].axes[i] {
                        let al = self.axes[a as usize].cfg.limits;
                        let st = State {
                            p: now[i],
                            v: vel[i],
                            a: acc[i],
                        };
                        let mut l = Limits {
                            vmax: al.vmax.max(st.v.abs()),
                            amax: al.amax.max(al.dmax).max(st.a.abs()),
                            dmax: al.dmax.min(p.inputs.deceleration),
                            jmax: if p.inputs.jerk > 0.0 && al.jmax > 0.0 {
                                p.inputs.jerk.min(al.jmax)
                            } else if p.inputs.jerk > 0.0 {
                                p.inputs.jerk
                            } else {
                                al.jmax
                            },
                        };
                        if l.jmax > 0.0 && (al.jmax == 0.0 || al.jmax > l.jmax) {
                            let peak = (st.v + st.a * st.a.abs() / (2.0 * l.jmax)).abs();
                            if peak > al.vmax {
                                l.jmax = al.jmax;
                            }
                        }
                        profs[i] =
                            Profile::velocity(st, 0.0, &l).map_err(|_| ErrorId::PlanningFailed)?;
                    }
                }
                let geo = Geometry::line(&now, &now);
                (geo, standing(0.0), Limits::default(), Some(profs), 0.0)
            }
            GKind::Home | GKind::Halt | GKind::Stop | GKind::Brake => {
                let ((geo, s), _) = running.unwrap_or((
                    (Geometry::line(&now, &now), State::default()),
                    Limits::default(),
                ));
                let mut i2 = p.inputs;
                i2.velocity = f64::MAX;
                i2.acceleration = p.inputs.deceleration;
                let (u, _) = geo.tangents(n);
                let mut lim = self.path_lims(g, &u, &i2)?;
                if let Geometry::Arc { .. } = geo {
                    // Braking on an arc: the arc's limits (the turn keeps its share); the
                    // arc's own jerk when the halt's lower one would carry the speed
                    // past the arc's.
                    let mut arc = lim;
                    arc.jmax = 0.0;
                    let v_arc = self.arc_limits(g, &geo, &mut arc);
                    lim.dmax = lim.dmax.min(arc.dmax);
                    lim.jmax = if lim.jmax > 0.0 && arc.jmax > 0.0 {
                        lim.jmax.min(arc.jmax)
                    } else {
                        arc.jmax
                    };
                    let peak = s.v + s.a * s.a.abs() / (2.0 * lim.jmax.max(1e-300));
                    if lim.jmax > 0.0 && peak > v_arc {
                        lim.jmax = arc.jmax;
                    }
                    lim.amax = lim.dmax.max(s.a.abs());
                    lim.vmax = v_arc.max(s.v.abs());
                } else {
                    lim.amax = lim.amax.max(lim.dmax);
                    lim.vmax = lim.vmax.max(s.v.abs());
                    self.raise_jerk(g, &u, s, &mut lim);
                }
                let prof = Profile::velocity(s, 0.0, &lim).map_err(|_| ErrorId::PlanningFailed)?;
                (geo, prof, lim, None, 0.0)
            }
            GKind::Path => {
                let start = match &p.prefix {
                    Some((geo, _)) => {
                        let (mut q, mut d1, mut d2) = (ZERO, ZERO, ZERO);
                        geo.eval(geo.len(), n, &mut q, &mut d1, &mut d2);
                        q
                    }
                    None => now,
                };
                let geo = self.geometry_for(g, &start, &p.target, &p.motion);
                if matches!(p.motion, GroupMotion::Circular { .. })
                    && !matches!(geo, Geometry::Arc { .. })
                {
                    // A buffered circle whose start (its predecessor's end) does not
                    // define it: refused when it would start, never run as a line.
                    return Err(ErrorId::InvalidCircle);
                }
                let (u, _) = geo.tangents(n);
                let mut lim = self.path_lims(g, &u, &p.inputs)?;
                if let Geometry::Arc { .. } = geo {
                    let requested = lim.vmax;
                    let reached = self.arc_limits(g, &geo, &mut lim);
                    if reached < requested {
                        arc_cut = Some((requested, reached, start));
                    }
                }
                let (v0, a0, pe) = match &p.prefix {
                    Some((b, v)) => (*v, 0.0, if *v > 0.0 { b.len() / v } else { 0.0 }),
                    None if p.start_v.is_some() => (p.start_v.unwrap_or(0.0), 0.0, 0.0),
                    None => {
                        // Aborting: the current axis velocity projected onto the path.
                        let v0: f64 = (0..n).map(|i| vel[i] * u[i]).sum();
                        let a0: f64 = (0..n).map(|i| acc[i] * u[i]).sum();
                        (v0, a0, 0.0)
                    }
                };
                let s0 = State {
                    p: 0.0,
                    v: v0,
                    a: a0,
                };
                self.raise_jerk(g, &u, s0, &mut lim);
                let (_, u_end) = geo.tangents(n);
                let arrives_as_planned = self.groups[g].queue.front().is_none_or(|nx| {
                    let dot: f64 = (0..n).map(|i| nx.pred_dir[i] * u_end[i]).sum();
                    nx.pred_dir == ZERO || dot >= 1.0 - 1e-9
                });
                let mut p = p;
                if p.end_v > 0.0 && !arrives_as_planned {
                    // The junction (and its blend) was planned for another direction.
                    self.note_dropped_junction(g, &p);
                    p.end_v = 0.0;
                    end_v = 0.0;
                }
                let planned = match crate::engine::plan_to(s0, geo.len(), p.end_v, &lim) {
                    Err(_) if p.end_v > 0.0 => {
                        // The junction speed cannot be planned from here: stop at the
                        // junction instead (reported), the successor starts from rest.
                        let r = crate::engine::plan_to(s0, geo.len(), 0.0, &lim);
                        if r.is_ok() {
                            self.note_dropped_junction(g, &p);
                            end_v = 0.0;
                        }
                        r
                    }
                    r => r,
                };
                let (prof, t) = planned.map_err(|_| ErrorId::PlanningFailed)?;
                let (lo, hi) = crate::engine::position_range(&prof, t.as_ref());
                self.group_sw_check(g, &geo, lo, hi)?;
                tail = t;
                (geo, prof, lim, None, pe)
            }
            GKind::Direct => {
                let mut profs = Box::new([standing(0.0); MAX_AXES]);
                let mut longest: f64 = 0.0;
                for i in 0..n {
                    if let Some(a) = self.groups[g].axes[i] {
                        let al = self.axes[a as usize].cfg.limits;
                        // The block's inputs capped by the axis's limits (Jerk 0: the
                        // axis's own), as a single-axis move.
                        let mut l = Limits {
                            vmax: al.vmax.min(p.inputs.velocity),
                            amax: al.amax.min(p.inputs.acceleration),
                            dmax: al.dmax.min(p.inputs.deceleration),
                            jmax: if p.inputs.jerk > 0.0 && al.jmax > 0.0 {
                                p.inputs.jerk.min(al.jmax)
                            } else if p.inputs.jerk > 0.0 {
                                p.inputs.jerk
                            } else {
                                al.jmax
                            },
                        };
                        let st = State {
                            p: now[i],
                            v: vel[i],
                            a: acc[i],
                        };
                        // Started while the axis accelerates: the block's lower jerk would
                        // carry the velocity past the axis's limit; the axis's jerk then.
                        if l.jmax > 0.0 && (al.jmax == 0.0 || al.jmax > l.jmax) {
                            let peak = (st.v + st.a * st.a.abs() / (2.0 * l.jmax)).abs();
                            if peak > al.vmax {
                                l.jmax = al.jmax;
                            }
                        }
                        profs[i] = crate::engine::plan_position(st, p.target[i], 0.0, &l)
                            .map_err(|_| ErrorId::PlanningFailed)?;
                        let ax = &self.axes[a as usize];
                        if ax.cfg.sw_limits_enabled && ax.cfg.period().is_none() {
                            // Each axis's own path (an overshoot) within its range.
                            let (lo, hi) = crate::engine::position_range(&profs[i], None);
                            let (o, c) = (ax.origin, &ax.cfg);
                            let top = c.sw_limit_pos.max(st.p + o);
                            let bottom = c.sw_limit_neg.min(st.p + o);
                            let eps = 1e-12 * (1.0 + top.abs().max(bottom.abs()));
                            if hi + o > top + eps || lo + o < bottom - eps {
                                return Err(ErrorId::PathBeyondSoftwareLimit);
                            }
                        }
                        longest = longest.max(profs[i].duration());
                    }
                }
                let geo = Geometry::line(&now, &p.target);
                let prof = Profile::velocity(
                    State::default(),
                    0.0,
                    &Limits {
                        vmax: 1.0,
                        amax: 1.0,
                        dmax: 1.0,
                        jmax: 0.0,
                    },
                )
                .map_err(|_| ErrorId::PlanningFailed)?;
                let _ = longest;
                (geo, prof, Limits::default(), Some(profs), 0.0)
            }
        };
        let gr = &mut self.groups[g];
        gr.active = Some(GActive {
            kind: p.kind,
            id: Some(p.id),
            geom,
            prof,
            t: keep_prefix.map_or(t0, |k| k.1),
            prefix: keep_prefix.map_or(p.prefix, |k| Some(k.0)),
            prefix_end,
            target: p.target,
            speed: p.speed,
            lim,
            end_v,
            direct,
            tail,
        });
        if let Some((requested, reached, corner)) = arc_cut {
            gr.reduction_count += 1;
            if gr.reductions.len() < REDUCTIONS_KEPT {
                gr.reductions.push(Reduction {
                    block: p.seq,
                    cmd: p.id,
                    corner,
                    requested,
                    reached,
                    reason: ReductionReason::ArcSpeed,
                });
            }
            gr.arc_now = Some((requested, reached));
        }
        gr.state = if p.kind == GKind::Stop {
            gr.stop_owner = Some(p.id);
            GroupState::GroupStopping
        } else if p.kind == GKind::Brake {
            GroupState::GroupErrorStop
        } else {
            GroupState::GroupMoving
        };
        self.cmds.set(p.id, CmdStatus::Active);
        for a in self.groups[g].axes.iter().flatten() {
            let ax = &mut self.axes[*a as usize];
            if ax.state == AxisState::Disabled {
                continue;
            }
            ax.active = Active {
                kind: Kind::Group,
                ..Active::idle(ax.set)
            };
            if ax.state != AxisState::ErrorStop {
                ax.state = AxisState::SynchronizedMotion;
            }
        }
        Ok(())
    }

    /// An axis of the group failed (or lost power): GroupErrorStop, buffered moves fail,
    /// the path brakes.
    pub(crate) fn group_axis_fault(&mut self, g: usize) {
        if self.groups[g].state == GroupState::GroupErrorStop
            || self.groups[g].state == GroupState::GroupDisabled
        {
            return;
        }
        self.group_abort_all(g, CmdStatus::Error(ErrorId::GroupAxisError));
        self.groups[g].error = ErrorId::GroupAxisError;
        self.groups[g].state = GroupState::GroupErrorStop;
        self.groups[g].stop_owner = None;
        if self.groups[g].active.is_some() {
            // Brake along the path with the axes' deceleration.
            let inputs = PathInputs {
                velocity: f64::MAX,
                acceleration: f64::MAX,
                deceleration: f64::MAX,
                jerk: 0.0,
                ..PathInputs::default()
            };
            let id = self.cmds.alloc(CmdStatus::Queued);
            let p = GPending {
                id,
                kind: GKind::Brake,
                motion: GroupMotion::Halt,
                target: ZERO,
                inputs,
                speed: 0.0,
                end_v: 0.0,
                prefix: None,
                start_v: None,
                start_corner: ZERO,
                seq: 0,
                reduced: None,
                pred_dir: ZERO,
            };
            if self.group_activate(g, p, 0.0).is_err() {
                self.finish_group(g);
            }
            if let Some(a) = self.groups[g].active.as_mut() {
                a.id = None;
            }
            self.cmds.set(id, CmdStatus::Done);
            self.cmds.release(id);
        }
    }

    /// MC_GroupHome: homes every axis of the group (simulated drives: on the spot, the
    /// set positions become `position` by identity); GroupStandby -> GroupHoming ->
    /// GroupStandby when every drive reports its homing done.
    pub fn group_home(&mut self, g: usize, position: Vecn) -> Result<CmdId, ErrorId> {
        let gr = self.grp(g)?;
        let st = check_group(gr.state, GroupCmd::Home)?;
        let n = gr.n();
        if position[..n].iter().any(|x| !x.is_finite()) {
            return Err(ErrorId::InvalidPosition);
        }
        let now = self.raw_now(g);
        let id = self.cmds.alloc(CmdStatus::Active);
        let members = self.groups[g].axes;
        for a in members.iter().flatten() {
            let a = *a as usize;
            let ax = &mut self.axes[a];
            ax.active = Active {
                kind: Kind::Group,
                ..Active::idle(ax.set)
            };
            ax.state = AxisState::Homing;
            if let Some(d) = self.drives[a].as_mut() {
                d.start_homing();
            }
        }
        let gr = &mut self.groups[g];
        gr.active = Some(GActive {
            kind: GKind::Home,
            id: Some(id),
            geom: Geometry::line(&now, &now),
            prof: standing(0.0),
            t: 0.0,
            prefix: None,
            prefix_end: 0.0,
            target: position,
            speed: 0.0,
            lim: Limits::default(),
            end_v: 0.0,
            direct: None,
            tail: None,
        });
        gr.state = st;
        Ok(id)
    }

    /// One cycle of a group homing: poll the drives.
    fn step_group_home(&mut self, g: usize, a: GActive) {
        let members = self.groups[g].axes;
        let mut all = true;
        let mut failed = None;
        for ax in members.iter().flatten() {
            let ax = *ax as usize;
            let st = match self.drives[ax].as_mut() {
                Some(d) => d.homing_status(),
                None => crate::axis::HomingStatus::Done,
            };
            match st {
                crate::axis::HomingStatus::Busy => all = false,
                crate::axis::HomingStatus::Failed => failed = Some(ax),
                crate::axis::HomingStatus::Done => {}
            }
        }
        let id = a.id;
        let target = a.target;
        self.groups[g].active = Some(a);
        if let Some(ax) = failed {
            let _ = self.raise_axis_error(ax, ErrorId::HomingFailed);
            return;
        }
        if !all {
            return;
        }
        for (i, ax) in members.iter().enumerate() {
            if let Some(ax) = ax {
                let ax = &mut self.axes[*ax as usize];
                ax.origin = target[i] - ax.set.p;
            }
        }
        if let Some(id) = id {
            self.cmds.set(id, CmdStatus::Done);
        }
        self.finish_group(g);
        self.groups[g].state = GroupState::GroupStandby;
    }

    /// MC_GroupStop's Execute fell after Done: GroupStopping -> GroupStandby.
    pub fn release_group_stop(&mut self, g: usize, id: CmdId) {
        if let Some(gr) = self.groups.get_mut(g) {
            let running = gr.active.as_ref().is_some_and(|a| a.kind == GKind::Stop);
            if gr.stop_owner == Some(id) && !running {
                gr.stop_owner = None;
                if gr.state == GroupState::GroupStopping {
                    gr.state = GroupState::GroupStandby;
                }
            }
        }
    }

    /// The group's motion ended: axes stand still.
    fn finish_group(&mut self, g: usize) {
        self.groups[g].active = None;
        for a in self.groups[g].axes.iter().flatten() {
            let ax = &mut self.axes[*a as usize];
            ax.set.v = 0.0;
            ax.set.a = 0.0;
            ax.active = Active::idle(ax.set);
            if matches!(ax.state, AxisState::SynchronizedMotion | AxisState::Homing) {
                ax.state = AxisState::Standstill;
            }
        }
    }

    /// Writes the set points of the group's axes from the running path move at its time.
    fn write_path_setpoints(&mut self, g: usize) {
        let n = self.groups[g].n();
        let Some(a) = self.groups[g].active.as_ref() else {
            return;
        };
        if a.direct.is_some() {
            return;
        }
        let (geo, s) = Self::path_state(a);
        let (mut pos, mut d1, mut d2) = self.groups[g].scratch;
        geo.eval(s.p, n, &mut pos, &mut d1, &mut d2);
        for i in 0..n {
            if let Some(ax) = self.groups[g].axes[i] {
                if self.axes[ax as usize].active.kind != Kind::Group {
                    continue;
                }
                self.axes[ax as usize].set = State {
                    p: pos[i],
                    v: d1[i] * s.v,
                    a: d1[i] * s.a + d2[i] * s.v * s.v,
                };
            }
        }
        self.groups[g].scratch = (pos, d1, d2);
    }

    /// One cycle of every group with a running move.
    pub(crate) fn step_groups(&mut self, dt: f64) {
        for g in 0..self.groups.len() {
            self.groups[g].junction_now = self.groups[g].arc_now.take().unwrap_or((0.0, 0.0));
            let Some(mut a) = self.groups[g].active.take() else {
                continue;
            };
            if a.kind == GKind::Home {
                self.step_group_home(g, a);
                continue;
            }
            let n = self.groups[g].n();
            a.t += dt;
            let (mut pos, mut d1, mut d2) = self.groups[g].scratch;
            let ended;
            if let Some(profs) = &a.direct {
                let mut done = true;
                for i in 0..n {
                    if let Some(ax) = self.groups[g].axes[i] {
                        if self.axes[ax as usize].active.kind != Kind::Group {
                            continue;
                        }
                        let s = profs[i].at(a.t);
                        self.axes[ax as usize].set = s;
                        done &= a.t >= profs[i].duration();
                    }
                }
                ended = done;
            } else {
                if let Some(tail) = a.tail {
                    if a.t >= a.prefix_end + a.prof.duration() {
                        // Main part done: the velocity-change tail follows at once.
                        a.prefix_end += a.prof.duration();
                        a.prof = tail;
                        a.tail = None;
                    }
                }
                let (geo, s) = Self::path_state(&a);
                geo.eval(s.p, n, &mut pos, &mut d1, &mut d2);
                for i in 0..n {
                    if let Some(ax) = self.groups[g].axes[i] {
                        if self.axes[ax as usize].active.kind != Kind::Group {
                            continue;
                        }
                        self.axes[ax as usize].set = State {
                            p: pos[i],
                            v: d1[i] * s.v,
                            a: d1[i] * s.a + d2[i] * s.v * s.v,
                        };
                    }
                }
                ended = a.t >= a.prefix_end + a.prof.duration() && a.tail.is_none();
            }
            self.groups[g].scratch = (pos, d1, d2);
            let kind = a.kind;
            let id = a.id;
            let leftover = a.t - a.prefix_end - a.prof.duration();
            let end_v = a.end_v;
            self.groups[g].active = Some(a);
            if !ended {
                continue;
            }
            if let Some(id) = id {
                self.cmds.set(id, CmdStatus::Done);
            }
            if matches!(kind, GKind::Path | GKind::Direct) {
                // Land exactly on the commanded end point.
                let target = self.groups[g].active.as_ref().map(|a| a.target);
                if let Some(target) = target {
                    for (i, t) in target.iter().enumerate().take(n) {
                        if let Some(ax) = self.groups[g].axes[i] {
                            if self.axes[ax as usize].active.kind != Kind::Group {
                                continue;
                            }
                            // At a junction (end_v > 0) the successor starts from the
                            // end point, not from the profile extrapolated past it.
                            let s = &mut self.axes[ax as usize].set;
                            s.p = *t;
                            s.v = d1[i] * end_v;
                            s.a = 0.0;
                        }
                    }
                }
            }
            match kind {
                GKind::Stop | GKind::Brake => {
                    self.finish_group(g);
                    if kind == GKind::Brake {
                        self.groups[g].state = GroupState::GroupErrorStop;
                    }
                }
                _ => {
                    // Next buffered move starts from the junction.
                    let mut started = false;
                    while let Some(mut p) = self.groups[g].queue.pop() {
                        if std::mem::take(&mut self.groups[g].drop_junction) {
                            p.prefix = None;
                            p.start_v = None;
                        }
                        let t0 = if end_v > 0.0 { leftover.max(0.0) } else { 0.0 };
                        if end_v > 0.0 {
                            p.start_v = Some(end_v);
                        }
                        match self.group_activate(g, p, t0) {
                            Ok(()) => {
                                let arc = self.groups[g].arc_now.take();
                                if let Some(r) = p.reduced.or(arc) {
                                    self.groups[g].junction_now = r;
                                }
                                if t0 > 0.0 {
                                    // The successor already ran `t0` of this cycle.
                                    self.write_path_setpoints(g);
                                }
                                started = true;
                                break;
                            }
                            Err(e) => {
                                // Its successor cannot join it: it starts from rest.
                                self.groups[g].drop_junction = true;
                                self.cmds.set(p.id, CmdStatus::Error(e));
                            }
                        }
                    }
                    if !started {
                        self.finish_group(g);
                        if self.groups[g].state == GroupState::GroupMoving {
                            self.groups[g].state = GroupState::GroupStandby;
                        }
                    }
                }
            }
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
