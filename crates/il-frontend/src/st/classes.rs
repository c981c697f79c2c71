//! IEC 61131-3 edition 3 classes (6.6.5): `CLASS [FINAL | ABSTRACT] Name [EXTENDS Base]
//! [IMPLEMENTS I1, I2] ... END_CLASS`.
//!
//! A class is read as a function block without a body ([`super::file`]'s scan and the IL parser's
//! layout take `CLASS` / `END_CLASS` for `FUNCTION_BLOCK` / `END_FUNCTION_BLOCK`): its variables,
//! METHODs, EXTENDS, IMPLEMENTS, FINAL and ABSTRACT are compiled as a block's. [`set_access`] marks
//! the parsed POU a class (sema refuses a call of its instances, E1018), gives its variable blocks
//! their access specifiers (`VAR PUBLIC`, `VAR PRIVATE`, ...; a class's VAR without one is
//! PROTECTED, as 6.6.5 gives it; sema refuses `inst.x` of a PRIVATE or PROTECTED one from another
//! POU, E1021), and reports what a class cannot hold (E1076): statements of its own (a class has
//! no body) and VAR_INPUT, VAR_OUTPUT or VAR_IN_OUT blocks (only its methods have them).

use super::file::PouText;
use super::lexer::{lex, Tok};
use crate::ast::{Access, CompilationUnit, LibraryElement, VarKind};
use crate::{FileId, Span};
use diagnostics::{code, Diagnostic, Diagnostics};

/// Sets the access specifiers `kept` (the offset of each block's `VAR` keyword, and its
/// specifier) on the blocks of the file's function blocks and classes, marks each class
/// (`pous[..].class`) and reports what a class may not hold (see the module documentation).
pub(super) fn set_access(
    unit: &mut CompilationUnit,
    file: FileId,
    src: &str,
    pous: &[PouText],
    kept: &[(usize, Access)],
    diags: &mut Diagnostics,
) {
    for item in &mut unit.items {
        let LibraryElement::Pou(p) = item else {
            continue;
        };
        if p.name.span.file != file {
            continue;
        }
        let text = pous.iter().find(|t| {
            t.actions.is_none()
                && t.interface.is_none()
                && t.name_range.start == p.name.span.start as usize
        });
        for b in &mut p.var_blocks {
            if let Some((_, a)) = kept.iter().find(|(at, _)| *at == b.span.start as usize) {
                b.access = Some(*a);
            }
        }
        let Some(t) = text.filter(|t| t.class.is_some()) else {
            continue;
        };
        p.class = true;
        for b in &mut p.var_blocks {
            match b.kind {
                // IEC 61131-3 ed. 3, 6.6.5: PROTECTED unless said otherwise
                VarKind::Local if b.access.is_none() => b.access = Some(Access::Protected),
                VarKind::Input | VarKind::Output | VarKind::InOut => {
                    let kw = match b.kind {
                        VarKind::Input => "VAR_INPUT",
                        VarKind::Output => "VAR_OUTPUT",
                        _ => "VAR_IN_OUT",
                    };
                    let at = b.span.start as usize;
                    diags.push(
                        Diagnostic::error(
                            code::E1076,
                            format!("the CLASS `{}` declares a {kw} block: a class has no inputs, outputs or in-outs of its own", p.name.name),
                        )
                        .at(Span::new(file, at, at + kw.len()))
                        .with_primary_label("not in a CLASS")
                        .with_hint(format!("IEC 61131-3 (6.6.5) gives a class's methods their {kw} blocks: move the variables into the METHOD that uses them, declare them `VAR PUBLIC`, or declare `{}` a FUNCTION_BLOCK", p.name.name)),
                    );
                }
                _ => {}
            }
        }
        // statements outside its methods and properties: a class has no body
        let body = src.get(t.body.clone()).unwrap_or("");
        let stray = lex(body).0.into_iter().find(|k| {
            let at = t.body.start + k.range.start;
            !matches!(k.tok, Tok::Eof | Tok::Semi)
                && !t.methods.iter().any(|m| m.whole.contains(&at))
                && !t.properties.iter().any(|q| q.whole.contains(&at))
        });
        if let Some(k) = stray {
            let at = t.body.start + k.range.start;
            diags.push(
                Diagnostic::error(
                    code::E1076,
                    format!(
                        "the CLASS `{}` has statements of its own: a class has no body",
                        p.name.name
                    ),
                )
                .at(Span::new(file, at, t.body.start + k.range.end))
                .with_primary_label("outside any METHOD")
                .with_hint(format!("IEC 61131-3 (6.6.5) runs a class's code in its methods only: move the statements into a METHOD and call it (`inst.M();`), or declare `{}` a FUNCTION_BLOCK", p.name.name)),
            );
        }
    }
}
