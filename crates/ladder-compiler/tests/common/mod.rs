//! Test helpers: compile a file, render short diagnostics.
#![allow(dead_code)]

use diagnostics::{render_short, Diagnostics, SourceMap};
use ladder_compiler::ast::CompilationUnit;

/// The shared corpus: `../../../shared/corpus` from the crate (the repository's sibling `shared/`), or
/// the nearest ancestor's `shared/corpus` (worktrees live deeper than the main checkout).
pub fn corpus_dir() -> std::path::PathBuf {
    let here = std::path::Path::new(env!("CARGO_MANIFEST_DIR"));
    here.ancestors()
        .map(|a| a.join("shared/corpus"))
        .find(|p| p.is_dir())
        .unwrap_or_else(|| here.join("../../../shared/corpus"))
}

pub fn corpus(name: &str) -> String {
    let path = corpus_dir().join(name);
    std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()))
}

pub fn fixture(name: &str) -> String {
    let path = format!("{}/tests/fixtures/{name}", env!("CARGO_MANIFEST_DIR"));
    std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{path}: {e}"))
}

/// Compiles `xml` named `name`; returns the unit and the short diagnostics, one per line.
pub fn compile(name: &str, xml: &str) -> (CompilationUnit, String) {
    let mut map = SourceMap::new();
    let file = map.add(name, xml);
    let mut diags = Diagnostics::new();
    let unit = ladder_compiler::compile_xml(file, xml, &mut diags);
    let text: String = diags
        .into_sorted()
        .iter()
        .map(|d| render_short(&map, d) + "\n")
        .collect();
    (unit, text)
}

/// A compact debug rendering of a body (test-only; the real printer is `il_frontend::print`).
pub fn dump_body(stmts: &[ladder_compiler::ast::IlStmt], indent: usize, out: &mut String) {
    use ladder_compiler::ast::*;
    let pad = "  ".repeat(indent);
    for s in stmts {
        match s {
            IlStmt::Label(l) => out.push_str(&format!("{pad}{}:\n", l.name)),
            IlStmt::Instr(i) => match &i.kind {
                InstrKind::Simple {
                    op,
                    negate,
                    operand,
                } => out.push_str(&format!(
                    "{pad}{:?}{} {}\n",
                    op,
                    if *negate { "N" } else { "" },
                    operand.as_ref().map(opnd).unwrap_or_default()
                )),
                InstrKind::Deferred {
                    op,
                    negate,
                    operand,
                    body,
                    ..
                } => {
                    out.push_str(&format!(
                        "{pad}{:?}{}( {}\n",
                        op,
                        if *negate { "N" } else { "" },
                        operand.as_ref().map(opnd).unwrap_or_default()
                    ));
                    dump_body(body, indent + 1, out);
                    out.push_str(&format!("{pad})\n"));
                }
                InstrKind::Jump { cond, label } => {
                    out.push_str(&format!("{pad}JMP{cond:?} {}\n", label.name))
                }
                InstrKind::Return { cond } => out.push_str(&format!("{pad}RET{cond:?}\n")),
                InstrKind::Call {
                    cond,
                    instance,
                    args,
                } => out.push_str(&format!(
                    "{pad}CAL{cond:?} {}({})\n",
                    opnd(&Operand::Var(instance.clone())),
                    args_text(args)
                )),
                InstrKind::FunctionCall { name, args } => {
                    out.push_str(&format!("{pad}{} {}\n", name.name, args_text(args)))
                }
                other => out.push_str(&format!("{pad}{other:?}\n")),
            },
        }
    }
}

fn args_text(a: &ladder_compiler::ast::CallArgs) -> String {
    use ladder_compiler::ast::*;
    match a {
        CallArgs::None => String::new(),
        CallArgs::NonFormal(v) => v.iter().map(opnd).collect::<Vec<_>>().join(", "),
        CallArgs::Formal(v) => v
            .iter()
            .map(|f| format!("{} := {}", f.name.name, opnd(&f.value)))
            .collect::<Vec<_>>()
            .join(", "),
    }
}

pub fn opnd(o: &ladder_compiler::ast::Operand) -> String {
    use ladder_compiler::ast::*;
    match o {
        Operand::Literal(l) => format!("{:?}", l.kind),
        Operand::Var(v) => {
            let mut s = v.base.name.clone();
            for a in &v.accessors {
                match a {
                    Accessor::Field(f) => s += &format!(".{}", f.name),
                    Accessor::Index(i) => {
                        s += &format!("[{}]", i.iter().map(opnd).collect::<Vec<_>>().join(","))
                    }
                }
            }
            s
        }
        Operand::Address(a) => format!("%{:?}{:?}{:?}", a.area, a.size, a.path),
        Operand::EnumValue {
            type_name, value, ..
        } => format!("{}#{}", type_name.name, value.name),
    }
}

pub fn dump_unit(u: &CompilationUnit) -> String {
    use ladder_compiler::ast::*;
    let mut out = String::new();
    for it in &u.items {
        if let LibraryElement::Pou(p) = it {
            out.push_str(&format!("POU {} {:?}\n", p.name.name, p.kind));
            for b in &p.var_blocks {
                for v in &b.vars {
                    if v.name.name.starts_with("__") {
                        out.push_str(&format!(
                            "  var {} : {:?}\n",
                            v.name.name,
                            match &v.ty {
                                TypeRef::Named(n) => n.name.clone(),
                                t => format!("{t:?}"),
                            }
                        ));
                    }
                }
            }
            dump_body(&p.body, 1, &mut out);
        }
    }
    out
}
