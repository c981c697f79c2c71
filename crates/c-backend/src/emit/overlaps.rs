//! W1400: located variables whose output bits overlap (`a AT %QX0.3` and `w AT %QW0`); W1460:
//! located variables of different sizes whose input bits overlap (`level AT %IW0` and `button AT
//! %IX1.0`); W1472: located variables of different sizes whose memory bits overlap, one of them
//! written by a body (`level AT %MW0` and `flag AT %MX0.1`); W1473: a CONSTANT located variable
//! whose memory bits a variable the bodies write overlaps (`LIMIT AT %MW0 : INT := 50` in `VAR_GLOBAL
//! CONSTANT` and a written `flag AT %MX0.1`: the constant changes at run time).
//!
//! Input: every located declaration of the model (POU variables other than VAR_EXTERNAL, free
//! globals, configuration and resource globals) placed by the target profile, and the variables the
//! bodies write (`Model::written`). Output: one warning per overlapping pair, at the later
//! declaration's address with a label at the earlier one. Invariants: addresses the profile rejects
//! are skipped here (their errors come from code generation); the comparison is bit by bit within
//! the bytes each access touches. Inputs are compared only between sizes: two variables reading the
//! same input address (or two words of one double word) read the same signal, which is harmless.
//! Memory is compared between sizes when a body writes one of the two (a word and its bits that are
//! only read are a deliberate view), and between any sizes when one is CONSTANT and a body writes
//! the other (IEC 61131-3 ed. 2 2.4.3: a CONSTANT cannot be modified); that pair is W1473 only. A
//! pair of different sizes (`%QX` and `%QW`, `%IX` and `%IW`, `%MX` and `%MW`) is apart where the
//! project comes from (OpenPLC and matiec keep one image per size): its hint names the built-in
//! profile that models that (`--profile openplc`, `profiles/openplc.json`), under which such a pair
//! no longer overlaps and is not reported.

use super::values::located_bytes;
use super::Gen;
use diagnostics::{code, Diagnostic, Span, XmlContext};
use il_frontend::ast::{AddressSize, Area, DirectAddress, VarKind};
use il_frontend::sema::{GlobalRef, PouId, Variable, WrittenVar};
use std::collections::BTreeMap;

impl Gen<'_> {
    /// W1400 for the located outputs, W1460 for the located inputs, W1472 and W1473 for the located
    /// memory (module header).
    pub(super) fn check_address_overlaps(&mut self) {
        self.check_overlaps_in(Area::Output);
        self.check_overlaps_in(Area::Input);
        self.check_overlaps_in(Area::Memory);
    }

    /// The overlapping pairs of the located variables of `area` (`%Q`: every pair; `%I`: pairs of
    /// different sizes; `%M`: pairs of different sizes one of which is written, and a CONSTANT with
    /// a written one), each one warning.
    fn check_overlaps_in(&mut self, area: Area) {
        let m = self.model;
        let located_in = |v: &Variable| v.location.as_ref().is_some_and(|l| l.area == area);
        // (qualified name, declaring POU, declaration, whether a body writes it) of each located
        // variable of the area: only they can overlap, so the names of the others (every variable
        // of a large program) are never made.
        let written = |w: WrittenVar| m.written.contains(&w);
        let mut decls: Vec<(String, Option<&str>, &Variable, bool)> = Vec::new();
        for (p, pou) in m.pous.iter().zip(0u32..) {
            for (index, v) in p.vars.iter().enumerate() {
                if v.kind != VarKind::External && located_in(v) {
                    let w = written(WrittenVar::Pou {
                        pou: PouId(pou),
                        index,
                    });
                    decls.push((format!("{}.{}", p.name, v.name), Some(&p.name), v, w));
                }
            }
        }
        let free = m
            .globals
            .iter()
            .enumerate()
            .map(|(i, v)| (GlobalRef::Free(i), v));
        let of_configurations = m.configurations.iter().enumerate().flat_map(|(config, c)| {
            let own = c
                .globals
                .iter()
                .enumerate()
                .map(move |(index, v)| (GlobalRef::Configuration { config, index }, v));
            let of_resources = c
                .resources
                .iter()
                .enumerate()
                .flat_map(move |(resource, r)| {
                    r.globals.iter().enumerate().map(move |(index, v)| {
                        let g = GlobalRef::Resource {
                            config,
                            resource,
                            index,
                        };
                        (g, v)
                    })
                });
            own.chain(of_resources)
        });
        decls.extend(
            free.chain(of_configurations)
                .filter(|(_, v)| located_in(v))
                .map(|(g, v)| (v.name.clone(), None, v, written(WrittenVar::Global(g)))),
        );
        // in source order, so that the warning lands on the later declaration (a stable sort: the
        // declarations left out above never changed the order of the ones kept)
        decls.sort_by_key(|(_, _, v, _)| (v.span.file.0, v.span.start));
        // byte -> (declaration, bit mask) of each located variable touching it
        let mut bytes: BTreeMap<u32, Vec<(usize, u8)>> = BTreeMap::new();
        let mut placed: Vec<Placed> = Vec::new();
        for (name, pou, v, written) in &decls {
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
            placed.push(Placed {
                name: name.clone(),
                span,
                address: address_text(loc),
                pou: *pou,
                size: loc.size,
                constant: v.constant,
                written: *written,
            });
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
            let (first, second) = (&placed[a], &placed[b]);
            let (an, asp, aa, asize) = (&first.name, first.span, &first.address, first.size);
            let (bn, bsp, ba, bsize) = (&second.name, second.span, &second.address, second.size);
            let xml = XmlContext {
                pou: second.pou.map(str::to_string),
                ..Default::default()
            };
            let d = match area {
                Area::Output => {
                    let hint = if asize == bsize {
                        "give each output its own address; writing one changes the other"
                    } else {
                        "give each output its own address; writing one changes the other (OpenPLC and matiec keep one image per size, where they are apart: `--profile openplc`)"
                    };
                    Diagnostic::warning(
                        code::W1400,
                        format!("`{bn}` at {ba} shares output bits with `{an}` at {aa}"),
                    )
                    .with_label(asp, "this output")
                    .with_hint(hint)
                }
                Area::Input if asize != bsize => Diagnostic::warning(
                    code::W1460,
                    format!("`{bn}` at {ba} shares input bits with `{an}` at {aa}"),
                )
                .with_label(asp, "this input")
                .with_hint("with this target profile one input image holds both, so a value set for one changes the other; OpenPLC and matiec keep one image per size, where they are apart: `--profile openplc`"),
                Area::Input => continue,
                Area::Memory => match memory_overlap(first, second, self.profile.memory_per_size) {
                    Some(d) => d,
                    None => continue,
                },
            };
            self.report_once(d.at(bsp).with_primary_label("overlaps").with_xml(xml));
        }
    }
}

/// A located variable placed by the target profile, for the overlap warnings.
struct Placed<'m> {
    /// Its name, qualified by its POU.
    name: String,
    /// Its address in the source.
    span: Span,
    /// Its address as IEC text.
    address: String,
    /// The POU declaring it (none: a global).
    pou: Option<&'m str>,
    /// The size of its address.
    size: AddressSize,
    /// Declared CONSTANT.
    constant: bool,
    /// A body writes it (`Model::written`).
    written: bool,
}

/// W1473 when one of two located variables whose memory bits overlap is CONSTANT and a body writes
/// the other; else W1472 when they are of different sizes and a body writes one of them; else
/// nothing (module header). `first` is declared before `second`; `per_size`: the profile keeps %M
/// one image per size (then only addresses in the TM window still overlap, not different sizes).
fn memory_overlap(first: &Placed, second: &Placed, per_size: bool) -> Option<Diagnostic> {
    let (an, asp, aa) = (&first.name, first.span, &first.address);
    let (bn, ba) = (&second.name, &second.address);
    let apart = if per_size {
        "give them addresses apart"
    } else {
        "give them addresses apart; for an OpenPLC or Beremiz project use `--profile openplc`, whose %M keeps one image per size (matiec gives every located variable storage of its own)"
    };
    let constant = [(first, second), (second, first)]
        .into_iter()
        .find(|(c, w)| c.constant && !w.constant && w.written);
    if let Some((c, w)) = constant {
        return Some(
            Diagnostic::warning(
                code::W1473,
                format!(
                    "CONSTANT `{}` at {} shares memory bits with `{}` at {}, which the program writes: the constant changes at run time",
                    c.name, c.address, w.name, w.address
                ),
            )
            .with_label(asp, if first.constant { "this constant" } else { "this variable" })
            .with_hint(format!(
                "IEC 61131-3 (ed. 2 2.4.3) says a CONSTANT cannot be modified; {apart}"
            )),
        );
    }
    if first.size == second.size || !(first.written || second.written) {
        return None;
    }
    let writes: Vec<&str> = [first, second]
        .into_iter()
        .filter(|p| p.written)
        .map(|p| p.name.as_str())
        .collect();
    Some(
        Diagnostic::warning(
            code::W1472,
            format!(
                "`{bn}` at {ba} shares memory bits with `{an}` at {aa}, and the program writes `{}`",
                writes.join("` and `")
            ),
        )
        .with_label(asp, "this variable")
        .with_hint(format!(
            "with this target profile one %M image holds both, so writing one changes the other; {apart}"
        )),
    )
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
