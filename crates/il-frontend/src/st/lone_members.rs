//! Methods and properties exported one file each: a CODESYS export script (kevin00156's
//! `codesys_export`, greenforge-labs' CODESCRIBE) writes a function block to `Block.st` and each of
//! its methods to a file of its own, `Block.Method.st`, holding `METHOD [modifiers] Method [: T]`, its
//! variable blocks and its statements (often without `END_METHOD`, and with the block's file without
//! `END_FUNCTION_BLOCK`, as the CODESYS editor shows them).
//!
//! Input: the text of such a file from its first `METHOD` / `PROPERTY` keyword (read by
//! [`super::file::parse_text`] when the file holds no POU around it), and later the pending bodies of
//! every file of the project. Output: a [`PendingBody`] with no POU of its own that carries the
//! members ([`LoneMembers`]); [`attach`] moves them to their block's body, so that they are compiled
//! exactly as if their text stood inside the block.
//! Invariants: the owner is the block named by the file name: the part of the file's stem before
//! its last dot (`BaseStateMachine.Raise.st` -> `BaseStateMachine`; the method's name after the dot
//! is not checked against the text, a file may hold several methods); the block must be one of the
//! files given on the same command line (ladderc reads no folder of plain `.st` files by itself). A
//! member whose owner is not found keeps the one E1063 at its header (its hint says where the text
//! belongs); a member whose name its block already has is one E1066 and is not compiled (no
//! silent choice between two texts). Every span still points into the member's own file.

use super::file::{PendingBody, PendingMethod};
use crate::ast::{CompilationUnit, LibraryElement, PouKind};
use diagnostics::{code, Diagnostic, Diagnostics};

/// The members of a file that holds methods or properties without their block.
#[derive(Debug, Clone)]
pub struct LoneMembers {
    /// The E1063 reported when no owner is found (at the first member's header).
    pub unowned: Diagnostic,
    /// The block the file name names (set by the caller, which knows the file's name:
    /// [`LoneMembers::name_owner`]).
    pub owner: Option<String>,
}

impl LoneMembers {
    /// Names the owner from the file's name (a path as given): the stem's part before its last dot,
    /// its last dotted segment (`Block.Method.st` -> `Block`). No dot: no owner.
    pub fn name_owner(&mut self, file_name: &str) {
        let stem = std::path::Path::new(file_name)
            .file_stem()
            .and_then(|s| s.to_str())
            .unwrap_or("");
        self.owner = stem
            .rsplit_once('.')
            .map(|(head, _)| head.rsplit('.').next().unwrap_or(head).trim().to_string())
            .filter(|o| {
                o.chars()
                    .next()
                    .is_some_and(|c| c.is_ascii_alphabetic() || c == '_')
                    && o.chars().all(|c| c.is_ascii_alphanumeric() || c == '_')
            });
    }
}

/// Reads the members of a file from the keyword at `start` (`METHOD` or `PROPERTY`) to the end of
/// `src`: the methods (and properties' accessors, as methods) as the block's own would be read (a
/// method's `VAR_STAT` blocks are those whose keyword is at one of `stat_at`).
/// `END_METHOD` / `END_PROPERTY` may be missing at the end of the file (the export scripts leave it
/// out). `None` when nothing could be read (the caller reports E1063 at once).
pub(super) fn read(
    file: crate::FileId,
    src: &str,
    start: usize,
    stat_at: &[usize],
    refs: &mut super::refs::RefTypes,
    diags: &mut Diagnostics,
) -> Option<Vec<PendingMethod>> {
    let head = src.get(start..)?;
    let (probe, _) = super::lexer::lex(head);
    let has = |w: &str| {
        probe.iter().any(|t| {
            head.get(t.range.clone())
                .is_some_and(|x| x.eq_ignore_ascii_case(w))
        })
    };
    let mut text = src.to_string();
    if has("METHOD") && !has("END_METHOD") {
        text.push_str("\nEND_METHOD\n");
    } else if has("PROPERTY") && !has("END_PROPERTY") {
        text.push_str("\nEND_PROPERTY\n");
    }
    let (toks, _) = super::lexer::lex(&text);
    let from = toks.iter().position(|t| t.range.start >= start)?;
    let members = &toks[from..];
    let mut methods = Vec::new();
    for m in super::file::scan_methods(&text, members) {
        let mut pm = super::file::pending_method(file, &text, &m, diags);
        super::var_stat::name_method_blocks(&mut pm, stat_at);
        refs.apply_to_method(&mut pm.blocks, pm.ret.as_mut());
        methods.push(pm);
    }
    for p in super::property::scan_properties(&text, members) {
        for mut pm in super::property::pending_accessors(file, &text, &p, diags) {
            refs.apply_to_method(&mut pm.blocks, pm.ret.as_mut());
            methods.push(pm);
        }
    }
    (!methods.is_empty()).then_some(methods)
}

/// Moves the members of each file of lone members to the body of the block its file name names
/// (see the module documentation); reports E1063 for those without one. `None` when `pending` has
/// no lone members.
pub fn attach(
    units: &[CompilationUnit],
    pending: &[PendingBody],
    diags: &mut Diagnostics,
) -> Option<Vec<PendingBody>> {
    if pending.iter().all(|pb| pb.lone.is_none()) {
        return None;
    }
    let (lone, mut out): (Vec<PendingBody>, Vec<PendingBody>) =
        pending.iter().cloned().partition(|pb| pb.lone.is_some());
    for pb in lone {
        let Some(l) = pb.lone else { continue };
        let owner = l.owner.as_deref().and_then(|o| {
            units
                .iter()
                .flat_map(|u| u.items.iter())
                .find_map(|i| match i {
                    LibraryElement::Pou(p)
                        if p.name.is(o)
                            && matches!(p.kind, PouKind::FunctionBlock | PouKind::Program) =>
                    {
                        Some(p)
                    }
                    _ => None,
                })
        });
        let Some(p) = owner else {
            diags.push(l.unowned);
            continue;
        };
        let at = (p.name.span.file, p.name.span.start as usize);
        let k = match out
            .iter()
            .position(|b| (b.file, b.name_start) == at && !b.sfc && b.lone.is_none())
        {
            Some(k) => k,
            // a block whose own body is empty (all its code in its methods) is read as IL with no
            // instruction: its ST body is empty
            None if p.body.is_empty() => {
                out.push(PendingBody {
                    base: p.name.span.end as usize,
                    ..PendingBody::empty(p.name.span.file, at.1)
                });
                out.len() - 1
            }
            None => {
                diags.push(l.unowned.with_note(format!(
                    "the file's name names `{}`, whose body is instruction list or SFC: methods are compiled with a block whose body is Structured Text",
                    p.name.name
                )));
                continue;
            }
        };
        // a `Block.Actions.st` file's actions (`ACTION Name : ... END_ACTION` outside any POU)
        out[k].actions.extend(pb.actions);
        for m in pb.methods {
            let block = &mut out[k];
            if let Some(first) = block.methods.iter().find(|x| x.name.key() == m.name.key()) {
                diags.push(
                    Diagnostic::error(
                        code::E1066,
                        format!(
                            "`{}` of `{}` is written twice: in the block and in a file of its own",
                            m.name.name, p.name.name
                        ),
                    )
                    .at(m.name.span)
                    .with_primary_label("this text is not compiled")
                    .with_label(first.name.span, "the text that is compiled")
                    .with_hint("delete one of the two texts (an export script run over a project that already held the method inside its block writes it twice)"),
                );
                continue;
            }
            block.methods.push(m);
        }
    }
    Some(out)
}
