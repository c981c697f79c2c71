//! The symbolic names of a CODESYS V2.3 PLC configuration (the `PLC_CONFIGURATION` ... `PLC_END`
//! section of a `.EXP` export), read as global variables at their I/O addresses.
//!
//! CODESYS V2.3 declares the symbolic name given to a channel or to a bit of a channel in the PLC
//! configuration as a global variable at that channel's or bit's address (CoDeSys V2.3 user manual,
//! "PLC Configuration", symbolic names; CODESYS-based Automation Builder: "the corresponding
//! variable declarations are automatically created"): the code uses them and declares them nowhere
//! else. The export writes them in two forms, which are all this module reads:
//!
//! ```text
//! _CHANNEL                               _CHANNEL
//! _SYMBOLIC_NAME: 'Lamp'                 _SYMBOLIC_NAME: ''
//! _IECADR: %QX0.0                        _IECADR: %IB1.0
//! _END_CHANNEL                           _BIT 0: %IX1.0.0 'Start_Btn' 'comment'
//!                                        _END_CHANNEL
//! ```
//!
//! A channel's `_SYMBOLIC_NAME` (`''`: none) names the channel's `_IECADR`; a `_BIT n:` line names
//! the bit address it gives (its first quoted text; `''`: none). The export does not write the
//! channel's type (the target's configuration file holds it): it follows from the address's size
//! letter, X BOOL, B BYTE, W WORD, D DWORD, L LWORD. Modules, parameters and comments are not read.
//!
//! Input: the section's lines (byte offset in the file, text). Output: one `VAR_GLOBAL` block whose
//! declarations are located at the names in the section (the name's span is the name inside its
//! quotes, the address's span the address), and one E0006 per named address that is no IEC direct
//! address (`%IR3.0`, an OWEN target's REAL area: that name is not declared) and one E1086 per
//! name that is no IEC identifier (`'Motor 1'`, `'Мотор'`: not declared). Invariant: every
//! name of the section is declared or reported, none twice by this module (two channels with one
//! name are the sema's E1002, as two declarations would be).

use diagnostics::{code, Diagnostic, FileId, Span};
use il_frontend::ast::{AddressSize, DirectAddress, Ident, TypeRef, VarBlock, VarDecl, VarKind};

/// One symbolic name of the configuration: the name and its address, with their byte ranges.
struct Named<'a> {
    name: &'a str,
    name_at: usize,
    address: &'a str,
    address_at: usize,
}

/// The global variables the symbolic names of a PLC configuration section declare (`None` when it
/// names nothing), and E0006 for a named address that is no direct address.
pub fn symbolic_names(
    file: FileId,
    lines: &[(usize, &str)],
    diags: &mut Vec<Diagnostic>,
) -> Option<VarBlock> {
    let mut vars = Vec::new();
    for n in named(lines) {
        let address_span = Span::new(file, n.address_at, n.address_at + n.address.len());
        let name_span = Span::new(file, n.name_at, n.name_at + n.name.len());
        if !is_identifier(n.name) {
            diags.push(
                Diagnostic::error(
                    code::E1086,
                    format!(
                        "the PLC configuration's symbolic name `{}` is no IEC 61131-3 identifier: not declared",
                        n.name
                    ),
                )
                .at(name_span)
                .with_primary_label("ASCII letters, digits and `_` only, not a digit first")
                .with_hint("rename the channel or bit in the PLC configuration (e.g. `Motor_1` for `Motor 1`), then export again"),
            );
            continue;
        }
        let (area, size, path) = match il_frontend::lexer::direct_address(n.address) {
            Ok(a) if !a.2.is_empty() => a,
            Ok(_) | Err(_) => {
                let why = match il_frontend::lexer::direct_address(n.address) {
                    Err(il_frontend::lexer::LexError::BadAddress(why)) => why,
                    _ => format!("`{}` gives no location", n.address),
                };
                diags.push(
                    Diagnostic::error(
                        code::E0006,
                        format!(
                            "invalid direct address of the PLC configuration's symbolic name `{}`: {why}",
                            n.name
                        ),
                    )
                    .at(address_span)
                    .with_primary_label("no IEC 61131-3 direct address")
                    .with_hint(format!(
                        "`{}` is not declared: declare it in a global variable list at an address \
                         %I, %Q or %M with size X, B, W, D or L (e.g. `{} AT %ID3.0 : REAL;`)",
                        n.name, n.name
                    )),
                );
                continue;
            }
        };
        let ty = match size {
            AddressSize::Bit => "BOOL",
            AddressSize::Byte => "BYTE",
            AddressSize::Word => "WORD",
            AddressSize::DWord => "DWORD",
            AddressSize::LWord => "LWORD",
        };
        let location = DirectAddress {
            area,
            size,
            path,
            span: address_span,
        };
        vars.push(
            VarDecl::new(
                Ident::new(n.name, name_span),
                TypeRef::Named(Ident::new(ty, address_span)),
                name_span,
            )
            .with_location(location),
        );
    }
    let (first, last) = (vars.first()?.span, vars.last()?.span);
    Some(VarBlock {
        name: None,
        kind: VarKind::Global,
        constant: false,
        retain: false,
        span: Span::new(
            file,
            first.start.min(last.start) as usize,
            first.end.max(last.end) as usize,
        ),
        vars,
        access: None,
    })
}

/// The symbolic names of the section's channels and bits, in order.
fn named<'a>(lines: &[(usize, &'a str)]) -> Vec<Named<'a>> {
    let mut out = Vec::new();
    // the channel's symbolic name, waiting for its `_IECADR`
    let mut channel: Option<(&str, usize)> = None;
    for &(at, line) in lines {
        let indent = line.len() - line.trim_start().len();
        let t = line.trim();
        if t == "_CHANNEL" || t == "_END_CHANNEL" || t.starts_with("_MODULE:") {
            channel = None;
        } else if let Some(rest) = t.strip_prefix("_SYMBOLIC_NAME:") {
            let from = at + indent + (t.len() - rest.len());
            channel = quoted(rest)
                .filter(|(n, _)| !n.is_empty())
                .map(|(n, k)| (n, from + k));
        } else if let Some(rest) = t.strip_prefix("_IECADR:") {
            if let Some((name, name_at)) = channel.take() {
                let a = rest.trim_start();
                let address = a.split_whitespace().next().unwrap_or("");
                if !address.is_empty() {
                    out.push(Named {
                        name,
                        name_at,
                        address,
                        address_at: at + indent + (t.len() - a.len()),
                    });
                }
            }
        } else if let Some(rest) = t.strip_prefix("_BIT") {
            // `_BIT 2: %IX1.0.2 'A1_DI_PDS1' 'comment'`
            let Some((_, after)) = rest.split_once(':') else {
                continue;
            };
            let a = after.trim_start();
            let address = a.split_whitespace().next().unwrap_or("");
            let address_at = at + indent + (t.len() - a.len());
            let tail = &a[address.len()..];
            let tail_at = address_at + address.len();
            if let Some((name, k)) = quoted(tail).filter(|(n, _)| !n.is_empty()) {
                if address.starts_with('%') {
                    out.push(Named {
                        name,
                        name_at: tail_at + k,
                        address,
                        address_at,
                    });
                }
            }
        }
    }
    out
}

/// Whether `s` is an IEC 61131-3 identifier: an ASCII letter or `_`, then letters, digits, `_`.
fn is_identifier(s: &str) -> bool {
    let mut c = s.chars();
    matches!(c.next(), Some(ch) if ch.is_ascii_alphabetic() || ch == '_')
        && c.all(|ch| ch.is_ascii_alphanumeric() || ch == '_')
}

/// The first `'...'` text of `s` and the byte offset of its first character in `s`.
fn quoted(s: &str) -> Option<(&str, usize)> {
    let open = s.find('\'')?;
    let len = s[open + 1..].find('\'')?;
    Some((&s[open + 1..open + 1 + len], open + 1))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::codesys_v23::lines;

    #[test]
    fn channel_and_bit_names_with_their_places() {
        let text = "_CHANNEL\n_SYMBOLIC_NAME: 'Lamp'\n_IECADR: %QW0.0\n_END_CHANNEL\n_CHANNEL\n_SYMBOLIC_NAME: ''\n_IECADR: %IB1.0\n_BIT 0: %IX1.0.0 'Start' 'c'\n_BIT 1: %IX1.0.1 '' 'c'\n_END_CHANNEL\n";
        let ls = lines(text);
        let n = named(&ls);
        assert_eq!(n.len(), 2);
        assert_eq!((n[0].name, n[0].address), ("Lamp", "%QW0.0"));
        assert_eq!(&text[n[0].name_at..n[0].name_at + 4], "Lamp");
        assert_eq!(&text[n[0].address_at..n[0].address_at + 6], "%QW0.0");
        assert_eq!((n[1].name, n[1].address), ("Start", "%IX1.0.0"));
        assert_eq!(&text[n[1].name_at..n[1].name_at + 5], "Start");
        let mut d = Vec::new();
        let b = symbolic_names(FileId(0), &ls, &mut d).expect("two names");
        assert!(d.is_empty());
        assert_eq!(b.vars.len(), 2);
        assert!(matches!(&b.vars[0].ty, TypeRef::Named(t) if t.name == "WORD"));
        assert!(matches!(&b.vars[1].ty, TypeRef::Named(t) if t.name == "BOOL"));
    }

    #[test]
    fn a_name_that_is_no_identifier_is_one_error_at_the_name() {
        let text = "_BIT 0: %IX1.0.0 'Motor 1' 'c'\n_BIT 1: %IX1.0.1 'Motor_2' 'c'\n";
        let mut d = Vec::new();
        let b = symbolic_names(FileId(0), &lines(text), &mut d).expect("one name");
        assert_eq!(b.vars.len(), 1);
        assert_eq!(d.len(), 1);
        assert_eq!(d[0].code, code::E1086);
    }

    #[test]
    fn an_unknown_size_letter_is_one_error_and_no_declaration() {
        let text = "_SYMBOLIC_NAME: 'ai0'\n_IECADR: %IR3.0\n";
        let mut d = Vec::new();
        assert!(symbolic_names(FileId(0), &lines(text), &mut d).is_none());
        assert_eq!(d.len(), 1);
        assert!(d[0].message.contains("size letter `R`"), "{}", d[0].message);
    }
}
