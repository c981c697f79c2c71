//! Edge-triggered inputs (`VAR_INPUT x : BOOL R_EDGE;` / `F_EDGE`) of user function blocks.
//!
//! Input: a sema POU whose variables carry `edge` (sema only keeps it on BOOL inputs of function
//! blocks). Output: the hidden struct members (one runtime `ladderc_R_TRIG`/`ladderc_F_TRIG` per
//! qualified input, named `edge_<member>`, which no user name can produce since user members start with
//! `v_`) and the `_BODY` wrapper around the body proper (`_BODY_LEVELS`). Invariants: during one
//! execution the body reads the edge (the trigger's Q: TRUE only in the call in which the input rose, or
//! fell), exactly as an implicit R_TRIG/F_TRIG instance of the standard; the member keeps the value the
//! caller wrote (restored after the body), so a call that does not reassign the input sees it unchanged;
//! the trigger memory is per instance and starts FALSE (zeroed by `_INIT`), so a first call with TRUE is
//! a rising edge (and, as F_TRIG defines it, a first call with FALSE is a falling edge).

use crate::mangle;
use il_frontend::ast::Edge;
use il_frontend::sema::Pou;
use std::fmt::Write as _;

/// The qualified inputs: (C member name, edge).
fn edge_inputs(p: &Pou) -> Vec<(String, Edge)> {
    p.vars
        .iter()
        .filter_map(|v| v.edge.map(|e| (mangle::var(&v.name), e)))
        .collect()
}

fn trigger(e: Edge) -> &'static str {
    match e {
        Edge::Rising => "ladderc_R_TRIG",
        Edge::Falling => "ladderc_F_TRIG",
    }
}

/// The hidden members of the instance struct (empty without edge-triggered inputs).
pub fn hidden_members(p: &Pou) -> Vec<String> {
    edge_inputs(p)
        .into_iter()
        .map(|(m, e)| format!("{} edge_{m};", trigger(e)))
        .collect()
}

/// The C function name (with `static` when it is the inner one) the body proper gets.
pub fn body_signature(sname: &str, p: &Pou) -> String {
    if edge_inputs(p).is_empty() {
        format!("void {sname}_BODY({sname} *self)")
    } else {
        format!("static void {sname}_BODY_LEVELS({sname} *self)")
    }
}

/// The `_BODY` wrapper that turns the qualified inputs into edges around the body proper (empty
/// without edge-triggered inputs).
pub fn wrapper(sname: &str, p: &Pou) -> String {
    let inputs = edge_inputs(p);
    if inputs.is_empty() {
        return String::new();
    }
    let mut c = String::new();
    let _ = writeln!(c, "void {sname}_BODY({sname} *self) {{");
    for (m, _) in &inputs {
        let _ = writeln!(c, "    IEC_BOOL level_{m} = self->{m};");
    }
    for (m, e) in &inputs {
        let _ = writeln!(c, "    self->edge_{m}.CLK = level_{m};");
        let _ = writeln!(c, "    {}_body(&self->edge_{m});", trigger(*e));
        let _ = writeln!(c, "    self->{m} = self->edge_{m}.Q;");
    }
    let _ = writeln!(c, "    {sname}_BODY_LEVELS(self);");
    for (m, _) in &inputs {
        let _ = writeln!(c, "    self->{m} = level_{m};");
    }
    c.push_str("}\n\n");
    c
}
