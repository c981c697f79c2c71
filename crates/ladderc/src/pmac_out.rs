//! `--pmac out.pmc`: a Delta Tau PMAC motion program for the constant moves of a program.
//!
//! Input: the user's units before block lowering, the axis configuration. Output: the program text from
//! crates/pmac-backend (`program::write`): one coordinate system `&1` with every configured axis (motor
//! `i+1`, letters X Y Z A B C U V W in configuration order, or the axis's identity in the first group that
//! holds it; counts per unit from the configuration), and one LINEAR ABS move per `CAL` in source order of
//! - `MC_MoveAbsolute` / `MC_MoveRelative` (one axis moves, the others keep their last target) whose
//!   Position/Distance, Velocity, Acceleration and Deceleration are constants; a jerk of 0 (none) uses the
//!   axis's configured jerk limit, else an effectively unlimited one (`TS` ~ 0);
//! - `MC_MoveLinearAbsolute` / `MC_MoveLinearRelative` on a configured group (`AxesGroup := G1`) whose
//!   Position/Distance is an array variable with a constant initializer (element k = identity k: X, Y, Z,
//!   ...) and whose Velocity, Acceleration, Deceleration, Jerk are constants. These are PATH limits (PLCopen
//!   Part 4); as in the motion library, each is first capped by the group axes' configured limits projected
//!   onto the line (`min_k limit_k / |u_k|`), then handed to the backend as the per-axis value that projects
//!   back to it (`axis_limit_for_path`), so the PMAC's S-curve is the library's jerk-limited path profile.
//!
//! A move's BufferMode says how it joins the move BEFORE it: the previous move ends in an exact stop
//! (`DWELL0`) when this one is `mcAborting`/`mcBuffered`, and blends into it for the blending modes, with the
//! junction speed of the mode (Low = min, Previous, Next, High = max of the two path speeds) written as a
//! comment (LINEAR blending cannot impose it, see crates/pmac-backend/README.md). The last move stops.
//! Calls with non-constant parameters are skipped with a W5050 warning (this is a static view of the
//! program, not a record of the run). Invariant: a move is only emitted for a configured axis or group.

use crate::axes::AxisConfig;
use diagnostics::{code, Diagnostic, Diagnostics};
use il_frontend::ast::*;
use pmac_backend::model::{AxisDef, CoordSystem, Dialect, LinearMove, MoveMode, Transition};
use std::collections::HashMap;

/// Jerk used when neither the call nor the axis limits it.
const UNLIMITED_JERK: f64 = 1e9;
const LETTERS: [char; 9] = ['X', 'Y', 'Z', 'A', 'B', 'C', 'U', 'V', 'W'];

/// The coordinate system of all configured axes.
pub fn coord_system(axes: &AxisConfig) -> CoordSystem {
    let mut letters: Vec<Option<char>> = vec![None; axes.axes.len()];
    for g in &axes.groups {
        for &(axis, ident) in &g.members {
            if let Some(l) = letters.get_mut(axis as usize) {
                if l.is_none() {
                    *l = LETTERS.get(ident as usize).copied();
                }
            }
        }
    }
    let mut free = LETTERS.iter().filter(|c| !letters.contains(&Some(**c)));
    let names: Vec<char> = letters
        .iter()
        .map(|l| l.or_else(|| free.next().copied()).unwrap_or('W'))
        .collect();
    CoordSystem {
        number: 1,
        axes: axes
            .axes
            .iter()
            .zip(names)
            .enumerate()
            .map(|(i, (a, name))| AxisDef {
                motor: i as u32 + 1,
                name,
                counts_per_unit: a.counts_per_unit,
            })
            .collect(),
    }
}

fn constant(op: &Operand) -> Option<f64> {
    match op {
        Operand::Literal(l) => match l.kind {
            LiteralKind::Real(v) => Some(v),
            LiteralKind::Int(v) => Some(v as f64),
            _ => None,
        },
        _ => None,
    }
}

/// The PLCopen value of an enumeration operand (`mcBuffered`, `TMCornerDistance`) or an integer
/// constant; `None` for anything else. A missing operand is 0 (mcAborting, TMNone).
fn enum_value(op: Option<&Operand>, prefix: &str) -> Option<u8> {
    match op {
        None => Some(0),
        Some(Operand::Var(v)) if v.accessors.is_empty() => param_passing::prelude::ENUM_CONSTANTS
            .iter()
            .find(|(n, _)| v.base.is(n) && n.starts_with(prefix))
            .map(|(_, x)| *x),
        Some(o) => constant(o)
            .filter(|x| (0.0..=255.0).contains(x))
            .map(|x| x as u8),
    }
}

/// The motion library's buffer mode of a BufferMode operand.
fn buffer_mode(op: Option<&Operand>) -> Option<motion_lib::buffer::BufferMode> {
    motion_lib::buffer::BufferMode::from_u8(enum_value(op, "mc")?).ok()
}

fn calls<'a>(body: &'a [IlStmt], out: &mut Vec<&'a Instruction>) {
    for s in body {
        if let IlStmt::Instr(i) = s {
            match &i.kind {
                InstrKind::Call { .. } => out.push(i),
                InstrKind::Deferred { body, .. } => calls(body, out),
                _ => {}
            }
        }
    }
}

/// The constant elements of an array initializer, in order (repeats expanded); `None` if one is not a
/// constant.
fn array_constants(init: &Initializer) -> Option<Vec<f64>> {
    let Initializer::Array(elems, _) = init else {
        return None;
    };
    let mut out = Vec::new();
    for e in elems {
        let Initializer::Value(op) = &e.value else {
            return None;
        };
        let v = constant(op)?;
        for _ in 0..e.repeat.unwrap_or(1).min(64) {
            out.push(v);
        }
    }
    Some(out)
}

/// A move as read from the program, before the transitions are known.
struct Read {
    /// Per configured axis: the target (absolute), `None` = keep.
    target: Vec<Option<f64>>,
    /// Limits: per axis for single-axis moves, path limits for group moves.
    velocity: f64,
    acceleration: f64,
    deceleration: f64,
    jerk: f64,
    group: bool,
    buffer: motion_lib::buffer::BufferMode,
}

/// What a block call's named input is, and the types of the POU's and the globals' variables.
struct Scope<'a> {
    types: HashMap<String, String>,
    arrays: HashMap<String, &'a Initializer>,
}

fn scope<'a>(units: &'a [CompilationUnit], pou: &'a Pou) -> Scope<'a> {
    let mut s = Scope {
        types: HashMap::new(),
        arrays: HashMap::new(),
    };
    let mut add = |b: &'a VarBlock| {
        for v in &b.vars {
            if let TypeRef::Named(t) = &v.ty {
                s.types.insert(v.name.key(), t.name.to_ascii_uppercase());
            }
            if let Some(init @ Initializer::Array(..)) = &v.init {
                s.arrays.insert(v.name.key(), init);
            }
        }
    };
    for u in units {
        for item in &u.items {
            match item {
                LibraryElement::GlobalVars(b) => add(b),
                LibraryElement::Configuration(c) => {
                    for b in c
                        .globals
                        .iter()
                        .chain(c.resources.iter().flat_map(|r| r.globals.iter()))
                    {
                        add(b)
                    }
                }
                _ => {}
            }
        }
    }
    for b in &pou.var_blocks {
        add(b);
    }
    s
}

/// Reads one call; `Ok(None)`: not a move block, `Err(())`: a move block that cannot be read statically.
fn read_call(
    c: &Instruction,
    sc: &Scope,
    axes: &AxisConfig,
    pos: &[f64],
) -> Result<Option<Read>, ()> {
    let InstrKind::Call {
        instance,
        args: CallArgs::Formal(args),
        ..
    } = &c.kind
    else {
        return Ok(None);
    };
    let (group, relative) = match sc.types.get(&instance.base.key()).map(String::as_str) {
        Some("MC_MOVEABSOLUTE") => (false, false),
        Some("MC_MOVERELATIVE") => (false, true),
        Some("MC_MOVELINEARABSOLUTE") => (true, false),
        Some("MC_MOVELINEARRELATIVE") => (true, true),
        _ => return Ok(None),
    };
    let arg = |n: &str| {
        args.iter()
            .find(|a| a.name.is(n) && a.dir == ArgDir::Input)
            .map(|a| &a.value)
    };
    let num = |n: &str| arg(n).and_then(constant).ok_or(());
    let name = |n: &str| match arg(n) {
        Some(Operand::Var(v)) if v.accessors.is_empty() => Some(v.base.clone()),
        _ => None,
    };
    let jerk = match arg("Jerk") {
        None => 0.0,
        Some(o) => constant(o).ok_or(())?,
    };
    let buffer = buffer_mode(arg("BufferMode")).ok_or(())?;
    let (v, a, d) = (num("Velocity")?, num("Acceleration")?, num("Deceleration")?);
    let mut target = vec![None; axes.axes.len()];
    if !group {
        let axis = name("Axis")
            .and_then(|n| axes.axes.iter().position(|a| n.is(&a.name)))
            .ok_or(())?;
        let t = num(if relative { "Distance" } else { "Position" })?;
        target[axis] = Some(if relative { pos[axis] + t } else { t });
        let limit = axes.axes[axis].limits.jerk_limit;
        let jerk = if jerk > 0.0 {
            jerk
        } else if limit > 0.0 {
            limit
        } else {
            UNLIMITED_JERK
        };
        return Ok(Some(Read {
            target,
            velocity: v,
            acceleration: a,
            deceleration: d,
            jerk,
            group: false,
            buffer,
        }));
    }
    let g = name("AxesGroup")
        .and_then(|n| axes.groups.iter().find(|g| n.is(&g.name)))
        .ok_or(())?;
    let values = name(if relative { "Distance" } else { "Position" })
        .and_then(|n| sc.arrays.get(&n.key()).copied())
        .and_then(array_constants)
        .ok_or(())?;
    for &(axis, ident) in &g.members {
        let (axis, ident) = (axis as usize, ident as usize);
        let t = *values.get(ident).ok_or(())?;
        *target.get_mut(axis).ok_or(())? = Some(if relative { pos[axis] + t } else { t });
    }
    Ok(Some(Read {
        target,
        velocity: v,
        acceleration: a,
        deceleration: d,
        jerk,
        group: true,
        buffer,
    }))
}

/// The path limits of a group move from `from` to `to` as the motion library plans them: the block's
/// limits (jerk 0 = none) capped by every moving axis's limit projected onto the line.
fn path_limits(r: &Read, from: &[f64], to: &[f64], axes: &AxisConfig) -> (f64, f64, f64, f64) {
    let len = from
        .iter()
        .zip(to)
        .map(|(a, b)| (b - a) * (b - a))
        .sum::<f64>()
        .sqrt();
    let mut lim = (
        r.velocity,
        r.acceleration,
        r.deceleration,
        if r.jerk > 0.0 { r.jerk } else { f64::INFINITY },
    );
    if len > 0.0 {
        for (k, ax) in axes.axes.iter().enumerate() {
            let u = (to[k] - from[k]).abs() / len;
            if u > 0.0 {
                let l = &ax.limits;
                lim.0 = lim.0.min(l.velocity_limit / u);
                lim.1 = lim.1.min(l.acceleration_limit / u);
                lim.2 = lim.2.min(l.deceleration_limit / u);
                if l.jerk_limit > 0.0 {
                    lim.3 = lim.3.min(l.jerk_limit / u);
                }
            }
        }
    }
    if !lim.3.is_finite() {
        lim.3 = UNLIMITED_JERK;
    }
    lim
}

/// The constant moves of `units`, in source order.
pub fn moves(
    units: &[CompilationUnit],
    axes: &AxisConfig,
    diags: &mut Diagnostics,
) -> Vec<LinearMove> {
    let mut pos = vec![0.0; axes.axes.len()];
    let mut out: Vec<LinearMove> = Vec::new();
    // path speed of the previous move (for the junction speed of a blend)
    let mut prev_speed = 0.0;
    for u in units {
        for item in &u.items {
            let LibraryElement::Pou(pou) = item else {
                continue;
            };
            let sc = scope(units, pou);
            let mut cs = Vec::new();
            calls(&pou.body, &mut cs);
            for c in cs {
                let r = match read_call(c, &sc, axes, &pos) {
                    Ok(Some(r)) => r,
                    Ok(None) => continue,
                    Err(()) => {
                        let name = match &c.kind {
                            InstrKind::Call { instance, .. } => instance.base.name.clone(),
                            _ => String::new(),
                        };
                        diags.push(
                            Diagnostic::warning(
                                code::W5050,
                                format!(
                                    "--pmac: the call of `{name}` is left out of the PMAC program (its axis or group is not configured or a parameter is not a constant)"
                                ),
                            )
                            .at(c.span),
                        );
                        continue;
                    }
                };
                let from = pos.clone();
                for (p, t) in pos.iter_mut().zip(&r.target) {
                    if let Some(t) = t {
                        *p = *t;
                    }
                }
                let (v, a, d, j, speed) = if r.group {
                    let (pv, pa, pd, pj) = path_limits(&r, &from, &pos, axes);
                    let delta: Vec<f64> = from.iter().zip(&pos).map(|(f, t)| t - f).collect();
                    let axis =
                        |l: f64| pmac_backend::scurve::axis_limit_for_path(&delta, l).unwrap_or(l);
                    (axis(pv), axis(pa), axis(pd), axis(pj), pv)
                } else {
                    (
                        r.velocity,
                        r.acceleration,
                        r.deceleration,
                        r.jerk,
                        r.velocity,
                    )
                };
                // this move's buffer mode decides how the previous one ends
                if let Some(last) = out.last_mut() {
                    use motion_lib::buffer::BufferMode::{Aborting, Buffered};
                    last.transition = match r.buffer {
                        Aborting | Buffered => Transition::ExactStop,
                        mode => Transition::Blend {
                            junction_velocity: mode.junction_speed(prev_speed, speed),
                        },
                    };
                }
                prev_speed = speed;
                out.push(LinearMove {
                    target: pos.clone(),
                    velocity: v,
                    acceleration: a,
                    deceleration: d,
                    jerk: j,
                    mode: MoveMode::Abs,
                    transition: Transition::ExactStop,
                });
            }
        }
    }
    out
}

/// The PMAC program text, or the backend's E7xxx diagnostic.
pub fn program(
    units: &[CompilationUnit],
    axes: &AxisConfig,
    dialect: Dialect,
    diags: &mut Diagnostics,
) -> Option<String> {
    if axes.axes.is_empty() {
        diags.push(
            Diagnostic::error(code::E5054, "--pmac needs configured axes")
                .with_hint("give the axis configuration (--axes FILE)"),
        );
        return None;
    }
    let cs = coord_system(axes);
    let ms = moves(units, axes, diags);
    let opts = pmac_backend::program::ProgramOptions {
        dialect,
        ..Default::default()
    };
    match pmac_backend::program::write_with(&cs, &ms, &opts) {
        Ok(t) => {
            // The controller's motion, as modelled from the text, against the plan: report what differs.
            if let Ok(cmp) = pmac_backend::compare::compare(&cs, &ms, &opts) {
                for w in cmp.warnings() {
                    diags.push(w);
                }
            }
            Some(t)
        }
        Err(e) => {
            diags.push(e.into_diagnostic());
            None
        }
    }
}
/// The run's motion as a sampled trajectory: every configured axis's `axis.<name>.position`, `.velocity`
/// and `.acceleration` columns of the trace CSV, one sample per row, `cycle_ms` apart (row 0 at t = 0).
/// `Err`: a missing column or an unreadable value (E7100).
pub fn trajectory_from_trace(
    csv: &str,
    axes: &AxisConfig,
    cycle_ms: f64,
) -> Result<pmac_backend::model::Trajectory, Box<Diagnostic>> {
    use pmac_backend::model::{Sample, Trajectory};
    let fail = |m: String| {
        Box::new(Diagnostic::error(code::E7100, m).with_hint(
            "the trace needs axis.<name>.position, .velocity and .acceleration of every configured axis",
        ))
    };
    let mut lines = csv.lines();
    let header: Vec<&str> = lines.next().unwrap_or("").split(',').collect();
    let mut cols = Vec::new();
    for a in &axes.axes {
        for sig in ["position", "velocity", "acceleration"] {
            let name = format!("axis.{}.{sig}", a.name);
            let k = header
                .iter()
                .position(|h| h.eq_ignore_ascii_case(&name))
                .ok_or_else(|| fail(format!("the trace has no column `{name}`")))?;
            cols.push(k);
        }
    }
    let mut traj = Trajectory {
        cycle_s: cycle_ms / 1000.0,
        axes: vec![Vec::new(); axes.axes.len()],
    };
    for (row, l) in lines.enumerate() {
        let cells: Vec<&str> = l.split(',').collect();
        let value = |k: usize| -> Result<f64, Box<Diagnostic>> {
            cells
                .get(k)
                .and_then(|c| c.trim().parse::<f64>().ok())
                .filter(|v| v.is_finite())
                .ok_or_else(|| {
                    fail(format!(
                        "trace row {}: column {} is not a number",
                        row + 1,
                        k + 1
                    ))
                })
        };
        for (i, samples) in traj.axes.iter_mut().enumerate() {
            samples.push(Sample {
                p: value(cols[3 * i])?,
                v: value(cols[3 * i + 1])?,
                a: value(cols[3 * i + 2])?,
            });
        }
    }
    Ok(traj)
}

/// `--pmac-pvt FILE`: the run's trace as a PVT rotary-buffer script (segments of `segment_ms`).
pub fn write_pvt(
    csv: &str,
    axes: &AxisConfig,
    cycle_ms: f64,
    dialect: Dialect,
    segment_ms: f64,
    path: &std::path::Path,
) -> Result<(), Box<Diagnostic>> {
    let traj = trajectory_from_trace(csv, axes, cycle_ms)?;
    let opts = pmac_backend::pvt::PvtOptions {
        dialect,
        segment_ms,
        ..Default::default()
    };
    pmac_backend::pvt::write_file(&coord_system(axes), &traj, &opts, path)
        .map(|_| ())
        .map_err(|e| Box::new(e.into_diagnostic()))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn axis_letters_follow_group_identities_then_the_free_letters() {
        let mut map = diagnostics::SourceMap::new();
        let f = map.add(
            "a.json",
            r#"{ "axes": [
                { "name": "A1", "velocity": 1, "acceleration": 1, "deceleration": 1, "counts_per_unit": 10 },
                { "name": "A2", "velocity": 1, "acceleration": 1, "deceleration": 1 },
                { "name": "A3", "velocity": 1, "acceleration": 1, "deceleration": 1 } ],
              "groups": [ { "name": "G", "axes": [ { "axis": "A2", "identity": "X" }, { "axis": "A3", "identity": "Z" } ] } ] }"#,
        );
        let mut d = Diagnostics::new();
        let axes = AxisConfig::parse(&map, f, &mut d).unwrap();
        let cs = coord_system(&axes);
        assert_eq!(cs.axis_names(), vec!['Y', 'X', 'Z']);
        assert_eq!(cs.axes[0].counts_per_unit, 10.0);
        assert_eq!(cs.axes[2].motor, 3);
    }

    #[test]
    fn buffer_modes_map_to_exact_stops_and_blends() {
        let var = |n: &str| {
            Operand::Var(VarRef {
                base: Ident::new(n, diagnostics::Span::default()),
                accessors: Default::default(),
                span: diagnostics::Span::default(),
            })
        };
        use motion_lib::buffer::BufferMode as B;
        assert_eq!(buffer_mode(None), Some(B::Aborting));
        assert_eq!(buffer_mode(Some(&var("mcBuffered"))), Some(B::Buffered));
        assert_eq!(
            buffer_mode(Some(&var("MCBLENDINGHIGH"))),
            Some(B::BlendingHigh)
        );
        assert_eq!(buffer_mode(Some(&var("TMCornerDistance"))), None);
        assert_eq!(buffer_mode(Some(&var("someVariable"))), None);
    }

    /// The example's program and axes, read as `ladderc` reads them (no checks).
    fn example(stem: &str) -> (Vec<CompilationUnit>, AxisConfig) {
        let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples/paper-b");
        let mut map = diagnostics::SourceMap::new();
        let mut d = Diagnostics::new();
        let src = std::fs::read_to_string(dir.join(format!("{stem}.il"))).unwrap();
        let f = map.add(format!("{stem}.il"), src.clone());
        let unit = il_frontend::parse_named(f, &src, stem, &mut d);
        let json = std::fs::read_to_string(dir.join("paper_b.axes.json")).unwrap();
        let f = map.add("paper_b.axes.json", json);
        let axes = AxisConfig::parse(&map, f, &mut d).unwrap();
        assert!(!d.has_errors());
        (vec![unit], axes)
    }

    /// The motion library's time-optimal rest-to-rest duration along each of paper B's lines, with the
    /// path limits of the program's blocks capped by the projected axis limits (as the group planner does).
    fn library_durations(v: [f64; 3], a: [f64; 3], j: [f64; 3], axes: &AxisConfig) -> Vec<f64> {
        use motion_lib::profile::{Limits, Profile, State};
        let pts = [
            [0.0, 0.0, 0.0],
            [1600.0, 1200.0, 800.0],
            [2200.0, 3800.0, 5000.0],
            [4500.0, 4200.0, 4800.0],
        ];
        (0..3)
            .map(|i| {
                let d: Vec<f64> = (0..3).map(|k| pts[i + 1][k] - pts[i][k]).collect();
                let len = d.iter().map(|x| x * x).sum::<f64>().sqrt();
                let u: Vec<f64> = d.iter().map(|x| x / len).collect();
                let ax: Vec<Limits> = axes
                    .axes
                    .iter()
                    .map(|x| Limits {
                        vmax: x.limits.velocity_limit,
                        amax: x.limits.acceleration_limit,
                        dmax: x.limits.deceleration_limit,
                        jmax: x.limits.jerk_limit,
                    })
                    .collect();
                let p = motion_lib::profile::line::path_limits(&u, &ax).unwrap();
                let lim = Limits {
                    vmax: p.vmax.min(v[i]),
                    amax: p.amax.min(a[i]),
                    dmax: p.dmax.min(a[i]),
                    jmax: p.jmax.min(j[i]),
                };
                Profile::position(State::default(), len, 0.0, &lim)
                    .unwrap()
                    .duration()
            })
            .collect()
    }

    fn program_times(stem: &str, dialect: Dialect) -> (String, Vec<f64>) {
        let (units, axes) = example(stem);
        let mut d = Diagnostics::new();
        let text = program(&units, &axes, dialect, &mut d).unwrap();
        assert!(d.is_empty(), "{:?}", d);
        let times = pmac_backend::verify::program_move_times(&text).unwrap();
        (text, times)
    }

    #[test]
    fn paper_b_exact_stops_take_the_time_optimal_move_times() {
        let (_, axes) = example("paper_b_exact");
        let lib = library_durations([40.0, 55.0, 70.0], [5.0; 3], [2.0; 3], &axes);
        // |line| / v + v / a + a / j along each line (v >= a^2/j = 12.5): see the example's README
        let lens = [
            4_640_000f64.sqrt(),
            24_760_000f64.sqrt(),
            5_490_000f64.sqrt(),
        ];
        for (i, v) in [40.0, 55.0, 70.0].into_iter().enumerate() {
            let closed = lens[i] / v + v / 5.0 + 5.0 / 2.0;
            assert!(
                (lib[i] - closed).abs() < 1e-9,
                "{i}: {} vs {closed}",
                lib[i]
            );
        }
        for dialect in [Dialect::Turbo, Dialect::Power] {
            let (text, times) = program_times("paper_b_exact", dialect);
            assert_eq!(times.len(), 3, "{text}");
            for (t, l) in times.iter().zip(&lib) {
                assert!((t - l).abs() < 1e-3, "{t} vs {l}\n{text}");
            }
            assert_eq!(
                text.to_ascii_uppercase().matches("DWELL0").count(),
                3,
                "{text}"
            );
        }
    }

    #[test]
    fn pmac_md_parameters_give_50_5_76_5_68_0_seconds() {
        let (text, times) = program_times("paper_b_pmac_md", Dialect::Turbo);
        for (t, w) in times.iter().zip([50.5, 76.5, 68.0]) {
            assert!((t - w).abs() < 1e-3, "{t} vs {w}\n{text}");
        }
        // pmac.md's own program: the same feedrates and ramps
        for part in [
            "TS2500 TA10500 F53.851",
            "TA16500 F82.932",
            "TA10500 F40.749",
        ] {
            assert!(text.contains(part), "{part}\n{text}");
        }
    }

    #[test]
    fn paper_b_blends_at_the_modes_junction_speeds() {
        let (units, axes) = example("paper_b");
        let mut d = Diagnostics::new();
        let ms = moves(&units, &axes, &mut d);
        assert!(d.is_empty());
        assert_eq!(ms.len(), 3);
        // A: BlendingLow min(40, 55); B: BlendingHigh max(55, 70); C stops.
        assert_eq!(
            ms[0].transition,
            Transition::Blend {
                junction_velocity: 40.0
            }
        );
        assert_eq!(
            ms[1].transition,
            Transition::Blend {
                junction_velocity: 70.0
            }
        );
        assert_eq!(ms[2].transition, Transition::ExactStop);
        assert_eq!(ms[2].target, vec![4500.0, 4200.0, 4800.0]);
        let text = program(&units, &axes, Dialect::Turbo, &mut d).unwrap();
        assert!(
            !text.contains("DWELL0 \n") && text.matches("DWELL0").count() == 1,
            "{text}"
        );
        let timeline = pmac_backend::verify::parse_program(&text, None).unwrap();
        assert_eq!(timeline.move_spans().len(), 3);
    }

    #[test]
    fn a_group_move_with_a_computed_position_is_left_out_with_a_warning() {
        let mut map = diagnostics::SourceMap::new();
        let mut d = Diagnostics::new();
        let src = "PROGRAM p\nVAR m : MC_MoveLinearAbsolute; q : ARRAY[0..2] OF LREAL; \
                   r : ARRAY[0..2] OF LREAL := [1.0, 2.0, 3.0]; END_VAR\n\
                   CAL m(AxesGroup := G1, Position := q, Velocity := 1.0, Acceleration := 1.0, Deceleration := 1.0)\n\
                   CAL m(AxesGroup := G2, Position := r, Velocity := 1.0, Acceleration := 1.0, Deceleration := 1.0)\n\
                   CAL m(AxesGroup := G1, Position := r, Velocity := 1.0, Acceleration := 1.0, Deceleration := 1.0)\n\
                   END_PROGRAM\n";
        let f = map.add("p.il", src.to_string());
        let unit = il_frontend::parse(f, src, &mut d);
        assert!(!d.has_errors(), "{:?}", d);
        let (_, axes) = example("paper_b");
        let ms = moves(&[unit], &axes, &mut d);
        assert_eq!(ms.len(), 1);
        assert_eq!(ms[0].target, vec![1.0, 2.0, 3.0]);
        assert_eq!(d.len(), 2, "{:?}", d);
    }
}
