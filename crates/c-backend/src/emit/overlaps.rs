//! W1400: located variables whose output bits overlap (`a AT %QX0.3` and `w AT %QW0`).
//!
//! Input: every located declaration of the model (POU variables other than VAR_EXTERNAL, free
//! globals, configuration and resource globals) placed by the target profile. Output: one warning per
//! overlapping pair, at the later declaration's address with a label at the earlier one. Invariants:
//! addresses the profile rejects are skipped here (their errors come from code generation); the
//! comparison is bit by bit within the bytes each access touches. A pair of different sizes (`%QX`
//! and `%QW`) is apart where the project comes from (OpenPLC and matiec keep one image per size):
//! its hint names the built-in profile that models that (`--profile openplc`, `profiles/openplc.json`).

use super::values::located_bytes;
use super::Gen;
use diagnostics::{code, Diagnostic, Span, XmlContext};
use il_frontend::ast::{AddressSize, Area, DirectAddress, VarKind};
use il_frontend::sema::Variable;
use std::collections::BTreeMap;

impl Gen<'_> {
    pub(super) fn check_output_overlaps(&mut self) {
        let m = self.model;
        // (qualified name, declaring POU, declaration) of each located output: only they can
        // overlap, so the names of the others (every variable of a large program) are never made.
        let mut decls: Vec<(String, Option<&str>, &Variable)> = Vec::new();
        for p in &m.pous {
            for v in p
                .vars
                .iter()
                .filter(|v| v.kind != VarKind::External && located_output(v))
            {
                decls.push((format!("{}.{}", p.name, v.name), Some(&p.name), v));
            }
        }
        let globals = m
            .globals
            .iter()
            .chain(m.configurations.iter().flat_map(|c| {
                c.globals
                    .iter()
                    .chain(c.resources.iter().flat_map(|r| r.globals.iter()))
            }));
        decls.extend(
            globals
                .filter(|v| located_output(v))
                .map(|v| (v.name.clone(), None, v)),
        );
        // in source order, so that the warning lands on the later declaration (a stable sort: the
        // declarations left out above never changed the order of the ones kept)
        decls.sort_by_key(|(_, _, v)| (v.span.file.0, v.span.start));
        // byte -> (declaration, bit mask) of each located output touching it
        let mut bytes: BTreeMap<u32, Vec<(usize, u8)>> = BTreeMap::new();
        let mut placed: Vec<(String, Span, String, Option<&str>, AddressSize)> = Vec::new();
        for (name, pou, v) in &decls {
            let Some(loc) = &v.location else { continue };
            if loc.area != Area::Output {
                continue;
            }
            let Some(size) = located_bytes(&v.ty, loc.size) else {
                continue;
            };
            let span = self
                .address_spans
                .get(&(v.span, loc.path.is_empty()))
                .copied()
                .unwrap_or(v.span);
            let addr = DirectAddress {
                area: loc.area,
                size: loc.size,
                path: loc.path.clone(),
                span,
            };
            let bytes_arg = if v.ty.is_bool() { None } else { Some(size) };
            let Ok(l) = self.locate(&addr, bytes_arg) else {
                continue;
            };
            let k = placed.len();
            placed.push((name.clone(), span, address_text(loc), *pou, loc.size));
            match l.bit {
                Some(b) => bytes.entry(l.offset).or_default().push((k, 1u8 << b)),
                None => {
                    for o in l.offset..l.offset + l.bytes.max(1) {
                        bytes.entry(o).or_default().push((k, 0xFF));
                    }
                }
            }
        }
        let mut pairs: BTreeMap<(usize, usize), ()> = BTreeMap::new();
        for list in bytes.values() {
            for (i, &(a, ma)) in list.iter().enumerate() {
                for &(b, mb) in &list[i + 1..] {
                    if a != b && ma & mb != 0 {
                        pairs.insert((a.min(b), a.max(b)), ());
                    }
                }
            }
        }
        for (a, b) in pairs.into_keys() {
            let (an, asp, aa, _, asize) = &placed[a];
            let (bn, bsp, ba, bpou, bsize) = &placed[b];
            let hint = if asize == bsize {
                "give each output its own address; writing one changes the other"
            } else {
                "give each output its own address; writing one changes the other (OpenPLC and matiec keep one image per size, where they are apart: `--profile openplc`)"
            };
            let xml = XmlContext {
                pou: bpou.map(str::to_string),
                ..Default::default()
            };
            self.report_once(
                Diagnostic::warning(
                    code::W1400,
                    format!("`{bn}` at {ba} shares output bits with `{an}` at {aa}"),
                )
                .at(*bsp)
                .with_primary_label("overlaps")
                .with_label(*asp, "this output")
                .with_hint(hint)
                .with_xml(xml),
            );
        }
    }
}

/// Whether `v` is located in the output area (`AT %Q...`): the declarations this check compares.
fn located_output(v: &Variable) -> bool {
    v.location.as_ref().is_some_and(|l| l.area == Area::Output)
}

fn address_text(loc: &il_frontend::sema::Location) -> String {
    use AddressSize as S;
    let size = match loc.size {
        S::Bit => "X",
        S::Byte => "B",
        S::Word => "W",
        S::DWord => "D",
        S::LWord => "L",
    };
    let path: Vec<String> = loc.path.iter().map(u32::to_string).collect();
    format!("%Q{size}{}", path.join("."))
}
