//! W1400: located variables whose output bits overlap (`a AT %QX0.3` and `w AT %QW0`); W1460:
//! located variables of different sizes whose input bits overlap (`level AT %IW0` and `button AT
//! %IX1.0`).
//!
//! Input: every located declaration of the model (POU variables other than VAR_EXTERNAL, free
//! globals, configuration and resource globals) placed by the target profile. Output: one warning per
//! overlapping pair, at the later declaration's address with a label at the earlier one. Invariants:
//! addresses the profile rejects are skipped here (their errors come from code generation); the
//! comparison is bit by bit within the bytes each access touches. Inputs are compared only between
//! sizes: two variables reading the same input address (or two words of one double word) read the
//! same signal, which is harmless. A pair of different sizes (`%QX` and `%QW`, `%IX` and `%IW`) is
//! apart where the project comes from (OpenPLC and matiec keep one image per size): its hint names
//! the built-in profile that models that (`--profile openplc`, `profiles/openplc.json`), under which
//! such a pair no longer overlaps and is not reported.

use super::values::located_bytes;
use super::Gen;
use diagnostics::{code, Diagnostic, Span, XmlContext};
use il_frontend::ast::{AddressSize, Area, DirectAddress, VarKind};
use il_frontend::sema::Variable;
use std::collections::BTreeMap;

impl Gen<'_> {
    /// W1400 for the located outputs, W1460 for the located inputs (module header).
    pub(super) fn check_address_overlaps(&mut self) {
        self.check_overlaps_in(Area::Output);
        self.check_overlaps_in(Area::Input);
    }

    /// The overlapping pairs of the located variables of `area` (`%Q`: every pair; `%I`: pairs of
    /// different sizes), each one warning.
    fn check_overlaps_in(&mut self, area: Area) {
        let m = self.model;
        let located_in = |v: &Variable| v.location.as_ref().is_some_and(|l| l.area == area);
        // (qualified name, declaring POU, declaration) of each located variable of the area: only
        // they can overlap, so the names of the others (every variable of a large program) are
        // never made.
        let mut decls: Vec<(String, Option<&str>, &Variable)> = Vec::new();
        for p in &m.pous {
            for v in p
                .vars
                .iter()
                .filter(|v| v.kind != VarKind::External && located_in(v))
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
                .filter(|v| located_in(v))
                .map(|v| (v.name.clone(), None, v)),
        );
        // in source order, so that the warning lands on the later declaration (a stable sort: the
        // declarations left out above never changed the order of the ones kept)
        decls.sort_by_key(|(_, _, v)| (v.span.file.0, v.span.start));
        // byte -> (declaration, bit mask) of each located variable touching it
        let mut bytes: BTreeMap<u32, Vec<(usize, u8)>> = BTreeMap::new();
        let mut placed: Vec<(String, Span, String, Option<&str>, AddressSize)> = Vec::new();
        for (name, pou, v) in &decls {
            let Some(loc) = &v.location else { continue };
            if loc.area != area {
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
            let xml = XmlContext {
                pou: bpou.map(str::to_string),
                ..Default::default()
            };
            let d = if area == Area::Output {
                let hint = if asize == bsize {
                    "give each output its own address; writing one changes the other"
                } else {
                    "give each output its own address; writing one changes the other (OpenPLC and matiec keep one image per size, where they are apart: `--profile openplc`)"
                };
                Diagnostic::warning(
                    code::W1400,
                    format!("`{bn}` at {ba} shares output bits with `{an}` at {aa}"),
                )
                .with_label(*asp, "this output")
                .with_hint(hint)
            } else if asize != bsize {
                Diagnostic::warning(
                    code::W1460,
                    format!("`{bn}` at {ba} shares input bits with `{an}` at {aa}"),
                )
                .with_label(*asp, "this input")
                .with_hint("with this target profile one input image holds both, so a value set for one changes the other; OpenPLC and matiec keep one image per size, where they are apart: `--profile openplc`")
            } else {
                continue;
            };
            self.report_once(d.at(*bsp).with_primary_label("overlaps").with_xml(xml));
        }
    }
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
    let area = match loc.area {
        Area::Input => "I",
        Area::Output => "Q",
        Area::Memory => "M",
    };
    format!("%{area}{size}{}", path.join("."))
}
