//! The static library of the IL-instruction method (paper A, method 1).
//!
//! Input: the templates and their TM layouts. Output: C99 text: one complete function per block,
//! `void MC_Name(void)`, each guarded by `#ifdef LADDERC_USE_MC_NAME` so that only used blocks are compiled;
//! [`library_c`] defines the guards of the blocks a program uses. Invariant: a function reads its parameters
//! from the TM area and writes its outputs and state back there, and touches no other memory of the program
//! (it calls the motion library through the body, like the template method).

use crate::template::{Param, Template, TypeClass};
use crate::tm::TmLayout;
use std::fmt::Write as _;

/// The guard macro of a block (`LADDERC_USE_MC_MOVEABSOLUTE`).
pub fn guard(block: &str) -> String {
    format!("LADDERC_USE_{}", block.to_ascii_uppercase())
}

fn load_expr(p: &Param, offset: u32) -> String {
    let n = p.class.tm_bytes();
    let raw = format!("ladderc_load(LADDERC_TM, {offset}u, {n}u)");
    match (p.class, p.c_type()) {
        (TypeClass::Real, _) => format!("ladderc_tm_f32((uint32_t){raw})"),
        (TypeClass::Lreal, _) => format!("ladderc_tm_f64({raw})"),
        (_, "int8_t") => format!("(int8_t)(uint8_t){raw}"),
        (_, "int16_t") => format!("(int16_t)(uint16_t){raw}"),
        (_, "int32_t") => format!("(int32_t)(uint32_t){raw}"),
        (_, c) => format!("({c}){raw}"),
    }
}

/// The store of `value` (the C local of `p`, or one of its elements) into TM at `offset`.
fn store_stmt(p: &Param, value: &str, offset: u32) -> String {
    let n = p.class.tm_bytes();
    let value = match (p.class, p.c_type()) {
        (TypeClass::Real, _) => format!("(uint64_t)ladderc_tm_f32_bits({value})"),
        (TypeClass::Lreal, _) => format!("ladderc_tm_f64_bits({value})"),
        (TypeClass::Bool, _) => format!("(uint64_t)({value} != 0u)"),
        (_, "int8_t") => format!("(uint64_t)(uint8_t){value}"),
        (_, "int16_t") => format!("(uint64_t)(uint16_t){value}"),
        (_, "int32_t") => format!("(uint64_t)(uint32_t){value}"),
        _ => format!("(uint64_t){value}"),
    };
    format!("ladderc_store(LADDERC_TM, {offset}u, {n}u, {value});")
}

/// The complete, guarded function of one block. An array parameter is a C array local whose elements
/// are loaded from (and, for outputs, stored back to) consecutive TM values.
pub fn function_c(t: &Template, layout: &TmLayout) -> String {
    let mut c = String::new();
    let g = guard(&t.block);
    let _ = writeln!(c, "#ifdef {g}");
    let _ = writeln!(
        c,
        "/* {} (FuncNum {}): IL-instruction method; parameters in TM bytes 0..{} */",
        t.block, t.func_num, layout.total
    );
    let _ = writeln!(c, "void {}(void) {{", t.block);
    let _ = writeln!(c, "    int FuncNum = {};", t.func_num);
    for p in &t.params {
        let slot = layout.slot(&p.name).expect("every parameter has a slot");
        match p.array {
            None => {
                let _ = writeln!(
                    c,
                    "    {} {} = {};",
                    p.c_type(),
                    p.abbr,
                    load_expr(p, slot.offset)
                );
            }
            Some(shape) => {
                let elems: Vec<String> = (0..shape.len)
                    .map(|k| load_expr(p, slot.offset + k * p.class.tm_bytes()))
                    .collect();
                let _ = writeln!(
                    c,
                    "    {} {}[{}] = {{\n        {}\n    }};",
                    p.c_type(),
                    p.abbr,
                    shape.len,
                    elems.join(",\n        ")
                );
            }
        }
    }
    for l in &t.locals {
        let _ = writeln!(c, "    {} {};", l.c_type, l.name);
    }
    c.push_str(&t.body.text);
    if !t.body.text.ends_with('\n') {
        c.push('\n');
    }
    for p in t.carried() {
        let slot = layout.slot(&p.name).expect("every parameter has a slot");
        match p.array {
            None => {
                let _ = writeln!(c, "    {}", store_stmt(p, &p.abbr, slot.offset));
            }
            Some(shape) => {
                for k in 0..shape.len {
                    let value = format!("{}[{k}]", p.abbr);
                    let offset = slot.offset + k * p.class.tm_bytes();
                    let _ = writeln!(c, "    {}", store_stmt(p, &value, offset));
                }
            }
        }
    }
    for p in t.inputs() {
        let _ = writeln!(c, "    (void){};", p.abbr);
    }
    let _ = writeln!(c, "    (void)FuncNum;");
    let _ = writeln!(c, "}}");
    let _ = writeln!(c, "#endif /* {g} */");
    c
}

/// The static library: the float helpers, then every block's guarded function, with the guards of `used`
/// defined first (only those functions are compiled).
pub fn library_c<'a>(
    all: impl IntoIterator<Item = (&'a Template, &'a TmLayout)>,
    used: &[&str],
) -> String {
    let mut c = String::from(
        "/* Static library of the IL-instruction method (generated from templates/). */\n\
         #include \"ladderc_rt.h\"\n#include \"motion_lib.h\"\n\n\
         /* The program's motion engine (ladderc_motion.c). */\n\
         struct McEngine *ladderc_motion_engine(void);\n\n",
    );
    for u in used {
        let _ = writeln!(c, "#define {}", guard(u));
    }
    c.push_str(
        "\nstatic inline float ladderc_tm_f32(uint32_t b) { union { uint32_t u; float f; } v; v.u = b; return v.f; }\n\
         static inline double ladderc_tm_f64(uint64_t b) { union { uint64_t u; double f; } v; v.u = b; return v.f; }\n\
         static inline uint32_t ladderc_tm_f32_bits(float f) { union { uint32_t u; float f; } v; v.f = f; return v.u; }\n\
         static inline uint64_t ladderc_tm_f64_bits(double f) { union { uint64_t u; double f; } v; v.f = f; return v.u; }\n\n",
    );
    for (t, l) in all {
        c.push_str(&function_c(t, l));
        c.push('\n');
    }
    c
}
