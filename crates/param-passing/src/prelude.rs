//! The IL declarations that make PLCopen blocks known to the semantic checks.
//!
//! Input: the library (and which blocks a program uses). Output: IL source text, parsed like a user file:
//! the reference types (`AXIS_REF` ...), the PLCopen enumeration constants (`mcAborting` ... as USINT
//! constants), and for each block either a `FUNCTION_BLOCK` declaration with the block's interface (before
//! lowering: the user's calls are type-checked against it) or a `STRUCT` of the same name (after lowering:
//! the instance keeps its inputs' defaults, its outputs and its state words as plain fields).
//! Invariant: the text only contains names from templates, which the loader validated as identifiers.

use crate::library::Library;
use crate::template::{Direction, Param, Template, TypeClass};
use std::fmt::Write as _;

/// The reference types and the field that holds their index in the motion engine.
pub const REFERENCE_TYPES: &[(&str, &str)] = &[
    ("AXIS_REF", "AxisNo"),
    ("AXES_GROUP_REF", "GroupNo"),
    ("MC_CAM_REF", "CamNo"),
    ("MC_CAM_ID", "CamId"),
];

/// Other names of reference types (`AXIS_GROUP_REF` is a common spelling of PLCopen's `AXES_GROUP_REF`):
/// declared as IEC type aliases, so values of both names are interchangeable.
pub const REFERENCE_ALIASES: &[(&str, &str)] = &[("AXIS_GROUP_REF", "AXES_GROUP_REF")];

/// PLCopen enumeration values, as USINT constants.
pub const ENUM_CONSTANTS: &[(&str, u8)] = &[
    ("mcAborting", 0),
    ("mcBuffered", 1),
    ("mcBlendingLow", 2),
    ("mcBlendingPrevious", 3),
    ("mcBlendingNext", 4),
    ("mcBlendingHigh", 5),
    ("mcPositiveDirection", 0),
    ("mcShortestWay", 1),
    ("mcNegativeDirection", 2),
    ("mcCurrentDirection", 3),
    ("TMNone", 0),
    ("TMStartVelocity", 1),
    ("TMConstantVelocity", 2),
    ("TMCornerDistance", 3),
    ("TMMaxCornerDeviation", 4),
    // Part 4: MC_COORD_SYSTEM, MC_CIRC_MODE, MC_CIRC_PATHCHOICE
    ("mcACS", 0),
    ("mcMCS", 1),
    ("mcPCS", 2),
    ("mcBorder", 0),
    ("mcCenter", 1),
    ("mcRadius", 2),
    ("mcClockwise", 0),
    ("mcCounterClockwise", 1),
    // Beckhoff Tc2_MC2's spellings (Infosys, Tc2_MC2 > Data types > MC_Direction, MC_BufferMode).
    // Tc2_MC2 numbers MC_Direction from 1 (MC_Positive_Direction := 1, MC_Shortest_Way,
    // MC_Negative_Direction, MC_Current_Direction, MC_Undefined_Direction := 128); the order is
    // PLCopen's, so each name is given the PLCopen value the motion library reads. An
    // uninitialised MC_Direction variable is then MC_Positive_Direction (0), as in TwinCAT (an
    // enumeration starts at its first value). MC_Undefined_Direction has no PLCopen value: the
    // blocks refuse it (ErrorID InvalidDirection).
    ("MC_Positive_Direction", 0),
    ("MC_Shortest_Way", 1),
    ("MC_Negative_Direction", 2),
    ("MC_Current_Direction", 3),
    ("MC_Undefined_Direction", 128),
    ("MC_Aborting", 0),
    ("MC_Buffered", 1),
    ("MC_BlendingLow", 2),
    ("MC_BlendingPrevious", 3),
    ("MC_BlendingNext", 4),
    ("MC_BlendingHigh", 5),
];

/// Enumeration types of the vendor motion libraries, declared as USINT (the values are the constants
/// above): Tc2_MC2's `MC_Direction` and `MC_BufferMode`.
pub const ENUM_TYPES: &[&str] = &["MC_Direction", "MC_BufferMode"];

/// The field of a reference type that carries the engine index (`AXIS_REF` -> `AxisNo`).
pub fn index_field(iec_type: &str) -> &'static str {
    let iec_type = REFERENCE_ALIASES
        .iter()
        .find(|(a, _)| a.eq_ignore_ascii_case(iec_type))
        .map_or(iec_type, |(_, t)| t);
    REFERENCE_TYPES
        .iter()
        .find(|(t, _)| t.eq_ignore_ascii_case(iec_type))
        .map_or("AxisNo", |(_, f)| f)
}

/// The IEC type of a parameter's value (of each element for an array) in the declarations (MC_*
/// enumerations are USINT).
pub fn declared_type(p: &Param) -> String {
    if p.class == TypeClass::Byte && p.iec_type.to_ascii_uppercase().starts_with("MC_") {
        "USINT".into()
    } else {
        p.iec_type.to_ascii_uppercase()
    }
}

/// The full declared type: `LREAL`, or `ARRAY [0..5] OF LREAL` for an array parameter.
fn full_type(p: &Param) -> String {
    p.iec_declared(&declared_type(p))
}

fn init(p: &Param) -> String {
    match (&p.default, p.array) {
        (Some(d), Some(a)) => format!(" := [{}]", vec![d.as_str(); a.len as usize].join(", ")),
        (Some(d), None) => format!(" := {d}"),
        (None, _) => String::new(),
    }
}

fn common(out: &mut String) {
    out.push_str("TYPE\n");
    for (t, f) in REFERENCE_TYPES {
        let _ = writeln!(out, "    {t} : STRUCT {f} : UDINT; END_STRUCT;");
    }
    for (alias, t) in REFERENCE_ALIASES {
        let _ = writeln!(out, "    {alias} : {t};");
    }
    for t in ENUM_TYPES {
        let _ = writeln!(out, "    {t} : USINT;");
    }
    out.push_str("END_TYPE\n\nVAR_GLOBAL CONSTANT\n");
    for (n, v) in ENUM_CONSTANTS {
        let _ = writeln!(out, "    {n} : USINT := {v};");
    }
    out.push_str("END_VAR\n\n");
}

/// The declarations checked against before lowering: one FUNCTION_BLOCK per template.
pub fn before_lowering(lib: &Library) -> String {
    let mut out = String::from(
        "(* PLCopen blocks as the programs see them (generated from the templates) *)\n",
    );
    common(&mut out);
    for t in lib.templates() {
        fb_declaration(t, &mut out);
    }
    out
}

fn fb_declaration(t: &Template, out: &mut String) {
    let _ = writeln!(out, "FUNCTION_BLOCK {}", t.block);
    for (dir, kw) in [
        (Direction::InOut, "VAR_IN_OUT"),
        (Direction::Input, "VAR_INPUT"),
        (Direction::Output, "VAR_OUTPUT"),
    ] {
        let ps: Vec<&Param> = t.params.iter().filter(|p| p.direction == dir).collect();
        if ps.is_empty() {
            continue;
        }
        let _ = writeln!(out, "{kw}");
        for p in ps {
            let _ = writeln!(out, "    {} : {}{};", p.name, full_type(p), init(p));
        }
        out.push_str("END_VAR\n");
    }
    out.push_str("END_FUNCTION_BLOCK\n\n");
}

/// The declarations after lowering: one STRUCT per template (inputs with defaults, outputs, state).
pub fn after_lowering(lib: &Library) -> String {
    let mut out = String::from(
        "(* PLCopen block instances after lowering (generated from the templates) *)\n",
    );
    common(&mut out);
    out.push_str("TYPE\n");
    for t in lib.templates() {
        let _ = writeln!(out, "    {} : STRUCT", t.block);
        for p in t.params.iter().filter(|p| p.direction != Direction::InOut) {
            let _ = writeln!(out, "        {} : {}{};", p.name, full_type(p), init(p));
        }
        out.push_str("    END_STRUCT;\n");
    }
    out.push_str("END_TYPE\n");
    out
}
