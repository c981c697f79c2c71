//! `--pmac out.pmc`: a Delta Tau PMAC motion program for the constant moves of a program.
//!
//! Input: the user's units before block lowering, the axis configuration. Output: the program text from
//! crates/pmac-backend (`program::write`): one coordinate system `&1` with every configured axis (motor
//! `i+1`, letters X Y Z A B C U V W in configuration order, or the axis's identity in the first group that
//! holds it; counts per unit from the configuration), and one LINEAR ABS move per `CAL` of
//! `MC_MoveAbsolute` / `MC_MoveRelative` in source order whose Position/Distance, Velocity, Acceleration and
//! Deceleration are constants; the other axes keep their last target. A jerk of 0 (none) uses the axis's
//! configured jerk limit, else an effectively unlimited one (`TS` ~ 0). `mcAborting`/`mcBuffered` end in
//! an exact stop, the blending modes in a blend. Calls with non-constant parameters are skipped with a
//! W5050 warning (this is a static view of the program, not a record of the run).
//! Invariant: a move is only emitted for a call whose axis is a configured axis.

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
        Operand::Literal(Literal {
            kind: LiteralKind::Real(v),
            ..
        }) => Some(*v),
        Operand::Literal(Literal {
            kind: LiteralKind::Int(v),
            ..
        }) => Some(*v as f64),
        _ => None,
    }
}

fn buffer_mode(op: Option<&Operand>) -> Option<Transition> {
    let value = match op {
        None => 0,
        Some(Operand::Var(v)) if v.accessors.is_empty() => {
            param_passing::prelude::ENUM_CONSTANTS
                .iter()
                .find(|(n, _)| v.base.is(n) && n.starts_with("mc"))?
                .1
        }
        Some(o) => constant(o)? as u8,
    };
    Some(match value {
        0 | 1 => Transition::ExactStop,
        _ => Transition::Blend {
            junction_velocity: 0.0,
        },
    })
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

/// The constant moves of `units`, in source order.
pub fn moves(
    units: &[CompilationUnit],
    axes: &AxisConfig,
    diags: &mut Diagnostics,
) -> Vec<LinearMove> {
    let mut pos = vec![0.0; axes.axes.len()];
    let mut out = Vec::new();
    for u in units {
        for item in &u.items {
            let LibraryElement::Pou(pou) = item else {
                continue;
            };
            let mut types: HashMap<String, String> = HashMap::new();
            for b in &pou.var_blocks {
                for v in &b.vars {
                    if let TypeRef::Named(t) = &v.ty {
                        types.insert(v.name.key(), t.name.to_ascii_uppercase());
                    }
                }
            }
            let mut cs = Vec::new();
            calls(&pou.body, &mut cs);
            for c in cs {
                let InstrKind::Call {
                    instance,
                    args: CallArgs::Formal(args),
                    ..
                } = &c.kind
                else {
                    continue;
                };
                let relative = match types.get(&instance.base.key()).map(String::as_str) {
                    Some("MC_MOVEABSOLUTE") => false,
                    Some("MC_MOVERELATIVE") => true,
                    _ => continue,
                };
                let arg = |n: &str| {
                    args.iter()
                        .find(|a| a.name.is(n) && a.dir == ArgDir::Input)
                        .map(|a| &a.value)
                };
                let axis = match arg("Axis") {
                    Some(Operand::Var(v)) if v.accessors.is_empty() => {
                        axes.axes.iter().position(|a| v.base.is(&a.name))
                    }
                    _ => None,
                };
                let num = |n: &str| arg(n).and_then(constant);
                let target = num(if relative { "Distance" } else { "Position" });
                let jerk = match arg("Jerk") {
                    None => Some(0.0),
                    Some(o) => constant(o),
                };
                let parts = (
                    axis,
                    target,
                    num("Velocity"),
                    num("Acceleration"),
                    num("Deceleration"),
                    jerk,
                    buffer_mode(arg("BufferMode")),
                );
                let (Some(axis), Some(target), Some(v), Some(a), Some(d), Some(j), Some(tr)) =
                    parts
                else {
                    diags.push(
                        Diagnostic::warning(
                            code::W5050,
                            format!(
                                "--pmac: the call of `{}` is left out of the PMAC program (its axis is not configured or a parameter is not a constant)",
                                instance.base.name
                            ),
                        )
                        .at(c.span),
                    );
                    continue;
                };
                let limit = axes.axes[axis].limits.jerk_limit;
                let jerk = if j > 0.0 {
                    j
                } else if limit > 0.0 {
                    limit
                } else {
                    UNLIMITED_JERK
                };
                pos[axis] = if relative { pos[axis] + target } else { target };
                out.push(LinearMove {
                    target: pos.clone(),
                    velocity: v,
                    acceleration: a,
                    deceleration: d,
                    jerk,
                    mode: MoveMode::Abs,
                    transition: tr,
                });
            }
        }
    }
    // the last move of a program always stops exactly
    if let Some(last) = out.last_mut() {
        last.transition = Transition::ExactStop;
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
    match pmac_backend::program::write(&cs, &ms, dialect) {
        Ok(t) => Some(t),
        Err(e) => {
            diags.push(e.into_diagnostic());
            None
        }
    }
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
                accessors: vec![],
                span: diagnostics::Span::default(),
            })
        };
        assert_eq!(buffer_mode(None), Some(Transition::ExactStop));
        assert_eq!(
            buffer_mode(Some(&var("mcBuffered"))),
            Some(Transition::ExactStop)
        );
        assert!(matches!(
            buffer_mode(Some(&var("mcBlendingHigh"))),
            Some(Transition::Blend { .. })
        ));
        assert_eq!(buffer_mode(Some(&var("someVariable"))), None);
    }
}
