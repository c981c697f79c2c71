//! Boolean actions written elsewhere in their chart, for [`super`]: warning W1461.
//!
//! IEC 61131-3 ed. 2 2.6.4.5 a) (ed. 3 6.7.4.6): when an action is a BOOL variable, the variable is
//! the `Q` output of the action's ACTION_CONTROL, which ladderc computes in every scan of the chart
//! (step 5 of [`super`]). Any other write of that variable in the chart's action bodies (`lamp :=
//! TRUE;`, an S or R coil, an FB output `=> lamp`) is overwritten in the next scan: at most one scan
//! sees it. ladderc keeps the standard's behaviour and says so at each such write; Beremiz (matiec)
//! writes the variable only while a step that drives it is active, so a program written for it may
//! behave otherwise (`tests/tests/fbd_r32_run.rs`).
//!
//! Input: the chart's actions and the IL of one action body. Output: one W1461 per write of a Boolean
//! action's variable in that body, naming the action and the rule. Invariants: reads nothing but the
//! statements given (no recursion: an explicit stack over nested deferred operators); changes no
//! statement.

use super::actions::{Action, Target};
use crate::context::Ctx;
use diagnostics::{code, Diagnostic, XmlContext};
use il_frontend::ast::{ArgDir, CallArgs, IlStmt, InstrKind, Op, Operand};
use il_frontend::Span;

/// The name a write stores into, when `op` is a plain variable (no field, no index).
fn plain_name(op: &Operand) -> Option<&str> {
    match op {
        Operand::Var(v) if v.accessors.is_empty() => Some(&v.base.name),
        _ => None,
    }
}

/// The variables `code` writes, each with the span of the writing instruction.
fn writes(code: &[IlStmt]) -> Vec<(&str, Span)> {
    let mut out = Vec::new();
    let mut stack: Vec<&[IlStmt]> = vec![code];
    while let Some(stmts) = stack.pop() {
        for s in stmts {
            let IlStmt::Instr(i) = s else { continue };
            match &i.kind {
                InstrKind::Simple {
                    op: Op::St | Op::S | Op::R,
                    operand: Some(op),
                    ..
                } => out.extend(plain_name(op).map(|n| (n, i.span))),
                InstrKind::Deferred { body, .. } => stack.push(body),
                InstrKind::Call {
                    args: CallArgs::Formal(args),
                    ..
                } => out.extend(
                    args.iter()
                        .filter(|a| a.dir != ArgDir::Input)
                        .filter_map(|a| plain_name(&a.value).map(|n| (n, a.span))),
                ),
                _ => {}
            }
        }
    }
    out
}

/// W1461 at every write, in `code` (the body of `display`), of a variable that is a Boolean action of
/// the chart.
pub fn warn_overwritten(ctx: &mut Ctx, acts: &[Action], code: &[IlStmt], display: &str, pou: &str) {
    let vars: Vec<(&str, &str)> = acts
        .iter()
        .filter_map(|a| match &a.target {
            Target::Variable(op) => plain_name(op).map(|n| (n, a.display.as_str())),
            _ => None,
        })
        .collect();
    if vars.is_empty() {
        return;
    }
    for (name, span) in writes(code) {
        let Some((var, _)) = vars.iter().find(|(v, _)| v.eq_ignore_ascii_case(name)) else {
            continue;
        };
        ctx.report(
            Diagnostic::warning(
                code::W1461,
                format!(
                    "`{var}` is written here, in {display}, but it is a Boolean action of the \
                     chart: its action control sets it every scan, so this write lasts one scan \
                     at most"
                ),
            )
            .at(span)
            .with_primary_label("overwritten by the action control")
            .with_hint(format!(
                "IEC 61131-3 (ed. 2 2.6.4.5): a BOOL action is its action control's Q; drive \
                 `{var}` only through the steps' qualifiers (S, R, N, P ...), or use another \
                 variable here"
            ))
            .with_xml(XmlContext {
                pou: Some(pou.to_string()),
                local_id: None,
                network: None,
            }),
        );
    }
}
