//! `ladderc build --report json`: what each PLCopen block type cost (paper A's comparison).
//!
//! Input: the lowering (per-block method, calls, TM bytes, IL instructions), the library and the generated
//! C project. Output: a JSON document `{ "blocks": [ { "block", "method", "calls", "tm_bytes",
//! "il_instructions", "c_bytes" } ] }`, blocks in name order. `c_bytes` is the size of the C the block
//! contributes: its guarded static-library function (IL method, one per block type) or the definitions of
//! its synthesised functions in `program.c` (template method, one per call).
//! Invariant: the figures are measured on the generated text, never estimated.

use crate::pipeline::Lowered;
use param_passing::lower::Method;

/// The C definition of `static void name(` in `c` (from its signature to the closing brace line).
fn definition_len(c: &str, name: &str) -> usize {
    let sig = format!("static void {name}(");
    let Some(start) = c
        .match_indices(&sig)
        .map(|(i, _)| i)
        .find(|&i| !c[i..].lines().next().unwrap_or("").ends_with(';'))
    else {
        return 0;
    };
    match c[start..].find("\n}\n") {
        Some(end) => end + 3,
        None => c.len() - start,
    }
}

/// The report as JSON text.
pub fn json(lowered: &Lowered, program: &c_backend::CProgram) -> String {
    let program_c = program.file("program.c").unwrap_or("");
    let mut blocks = Vec::new();
    for r in &lowered.lowering.reports {
        let c_bytes = match r.method {
            Method::Il => match (
                lowered.library.get(&r.block),
                lowered.lowering.static_functions.get(&r.block),
            ) {
                (Some(t), Some(layout)) => param_passing::static_lib::function_c(t, layout).len(),
                _ => 0,
            },
            Method::Template => lowered
                .lowering
                .synthesized
                .iter()
                .filter(|s| {
                    s.name
                        .strip_prefix(r.block.as_str())
                        .is_some_and(|rest| rest.starts_with('_'))
                })
                .map(|s| definition_len(program_c, &s.name))
                .sum(),
        };
        blocks.push(serde_json::json!({
            "block": r.block,
            "method": match r.method { Method::Il => "il", Method::Template => "template" },
            "calls": r.calls,
            "tm_bytes": r.tm_bytes,
            "il_instructions": r.il_instructions,
            "c_bytes": c_bytes,
        }));
    }
    let doc = serde_json::json!({ "blocks": blocks });
    serde_json::to_string_pretty(&doc).unwrap_or_default()
}

#[cfg(test)]
mod tests {
    use super::definition_len;

    #[test]
    fn the_definition_not_the_prototype_is_measured() {
        let c =
            "static void F_1(P *self);\nint x;\nstatic void F_1(P *self) {\n    x = 1;\n}\nrest";
        assert_eq!(
            definition_len(c, "F_1"),
            "static void F_1(P *self) {\n    x = 1;\n}\n".len()
        );
        assert_eq!(definition_len(c, "G"), 0);
    }
}
