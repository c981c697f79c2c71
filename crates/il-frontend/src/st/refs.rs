//! References and pointers in `.st` text (IEC 61131-3 edition 3, 6.4.4.10: `REF_TO T`, `REF(x)`,
//! `r^`, `NULL`; CODESYS and TwinCAT: `POINTER TO T` with `ADR(x)` and `p^`, `REFERENCE TO T`
//! with `r REF= x` and `__ISVALIDREF(r)`).
//!
//! Input: a file's text and tokens, before its declarations are parsed. Output: the text with the
//! reference keywords blanked (positions unchanged, so the IL parser reads `r : REF_TO INT` as
//! `r : INT`), a [`RefTypes`] table saying which type texts they stood before, and, after the parse,
//! the declarations' types wrapped back into [`TypeRef::Ref`] ([`RefTypes::apply`]).
//! Invariants: every span stays where the user wrote it; a reference type is wrapped exactly where
//! its keyword stood (a variable, a structure field, an array's element type, a TYPE alias, a
//! FUNCTION's result); a keyword left without a type to wrap is one E0305 at the keyword.

use super::file::{blank, is_var_keyword, word};
use super::lexer::{Tok, Token};
use crate::ast::{CompilationUnit, LibraryElement, RefKind, TypeDef, TypeRef, VarBlock, VarDecl};
use crate::{FileId, Span};
use diagnostics::{code, Diagnostic, Diagnostics};
use std::collections::{HashMap, HashSet};

/// `__ISVALIDREF(r)` (CODESYS): whether reference `r` refers to a variable (is not NULL).
pub const IS_VALID_REF: &str = "__ISVALIDREF";

/// The callee name `r REF= x` is parsed into (`r := REF=(x)`; no identifier can be written so).
pub const REF_ASSIGN: &str = "REF=";

/// Whether `name` is `REF` (edition 3) or `ADR` (CODESYS, TwinCAT): the address of its argument.
pub fn is_address_of(name: &crate::ast::Ident) -> bool {
    name.is("REF") || name.is("ADR")
}

/// The reference keywords blanked in one file: by the offset of the type text they stood before,
/// the kinds outermost first (`REF_TO REF_TO INT` has two) and the span of the first keyword.
#[derive(Debug, Default)]
pub struct RefTypes {
    file: Option<FileId>,
    at: HashMap<usize, (Vec<RefKind>, Span)>,
    /// The offsets whose type was wrapped.
    used: HashSet<usize>,
}

impl RefTypes {
    /// Whether the file declares no reference.
    pub fn is_empty(&self) -> bool {
        self.at.is_empty()
    }

    /// Blanks `REF_TO`, `POINTER TO` and `REFERENCE TO` where a type is declared (after `:` or `OF`
    /// in a VAR, STRUCT or TYPE block, or a FUNCTION's result type) and records them. `None`: the text
    /// has none (nothing blanked).
    pub fn blank_keywords(file: FileId, src: &str, toks: &[Token]) -> (Option<String>, RefTypes) {
        let mut text: Option<String> = None;
        let mut refs = RefTypes {
            file: Some(file),
            at: HashMap::new(),
            used: HashSet::new(),
        };
        let mut in_decl = false;
        for (k, t) in toks.iter().enumerate() {
            let w = word(src, t).to_ascii_uppercase();
            if matches!(t.tok, Tok::Kw(_) | Tok::Ident) {
                if is_var_keyword(&w) || w == "STRUCT" || w == "TYPE" || w == "FUNCTION" {
                    in_decl = true;
                } else if matches!(w.as_str(), "END_VAR" | "END_STRUCT" | "END_TYPE") {
                    in_decl = false;
                }
            }
            let after_colon = t.tok == Tok::Colon || w == "OF";
            if !in_decl || !after_colon {
                continue;
            }
            // the keywords, outermost first: `REF_TO`, `POINTER TO`, `REFERENCE TO`
            let mut j = k + 1;
            let mut kinds = Vec::new();
            let mut first: Option<Span> = None;
            while let Some(kw) = toks.get(j) {
                let (kind, end, next) = match word(src, kw).to_ascii_uppercase().as_str() {
                    "REF_TO" => (RefKind::RefTo, kw.range.end, j + 1),
                    w @ ("POINTER" | "REFERENCE") => match toks.get(j + 1) {
                        Some(to) if word(src, to).eq_ignore_ascii_case("TO") => {
                            let kind = if w == "POINTER" {
                                RefKind::Pointer
                            } else {
                                RefKind::Reference
                            };
                            (kind, to.range.end, j + 2)
                        }
                        _ => break,
                    },
                    _ => break,
                };
                first.get_or_insert(Span::new(file, kw.range.start, end));
                kinds.push(kind);
                blank(
                    text.get_or_insert_with(|| src.to_string()),
                    kw.range.start..end,
                );
                j = next;
            }
            if let (Some(span), Some(target)) = (first, toks.get(j)) {
                refs.at.insert(target.range.start, (kinds, span));
            }
        }
        (text, refs)
    }

    /// Wraps the declared types that stood after a reference keyword into [`TypeRef::Ref`]; a
    /// keyword whose type was not found (an error the parser reported, or a place no type is
    /// declared) is one E0305.
    pub fn apply(mut self, unit: &mut CompilationUnit, diags: &mut Diagnostics) {
        if self.at.is_empty() {
            return;
        }
        for item in &mut unit.items {
            match item {
                LibraryElement::Pou(p) => {
                    if let Some(r) = &mut p.return_type {
                        self.wrap(r);
                    }
                    self.blocks(&mut p.var_blocks);
                }
                LibraryElement::DataTypes(types) => {
                    for t in types {
                        match &mut t.def {
                            TypeDef::Alias { ty, .. } => self.wrap(ty),
                            TypeDef::Struct { fields } => self.decls(fields),
                            TypeDef::Enum { .. } => {}
                        }
                    }
                }
                LibraryElement::GlobalVars(b) => self.decls(&mut b.vars),
                LibraryElement::Configuration(c) => {
                    self.blocks(&mut c.globals);
                    for r in &mut c.resources {
                        self.blocks(&mut r.globals);
                    }
                }
                LibraryElement::Action(_) => {}
            }
        }
        self.report_left(diags);
    }

    /// Wraps the types of a method's declarations (read apart from the unit).
    pub fn apply_to_method(&mut self, blocks: &mut [VarBlock], ret: Option<&mut VarDecl>) {
        self.blocks(blocks);
        if let Some(r) = ret {
            self.wrap(&mut r.ty);
        }
    }

    /// E0305 for each keyword whose type was not found.
    pub fn report_left(&mut self, diags: &mut Diagnostics) {
        let used = std::mem::take(&mut self.used);
        let mut left: Vec<(Vec<RefKind>, Span)> = self
            .at
            .drain()
            .filter(|(k, _)| !used.contains(k))
            .map(|(_, v)| v)
            .collect();
        left.sort_by_key(|(_, s)| s.start);
        for (kinds, span) in left {
            let kw = kinds.first().map_or("REF_TO", |k| k.keyword());
            diags.push(
                Diagnostic::error(
                    code::E0305,
                    format!("`{kw}` is not supported here"),
                )
                .at(span)
                .with_primary_label("reference type")
                .with_hint("declare references in VAR blocks, STRUCT fields, array elements or TYPE aliases"),
            );
        }
    }

    fn blocks(&mut self, blocks: &mut [VarBlock]) {
        for b in blocks {
            self.decls(&mut b.vars);
        }
    }

    fn decls(&mut self, decls: &mut [VarDecl]) {
        for d in decls {
            self.wrap(&mut d.ty);
        }
    }

    /// Wraps `ty` (and its element types) where a keyword stood before it.
    fn wrap(&mut self, ty: &mut TypeRef) {
        if let TypeRef::Array { element, .. } = ty {
            self.wrap(element);
        }
        let start = ty.span().start as usize;
        let Some(span_file) = self.file else { return };
        if ty.span().file != span_file {
            return;
        }
        // `a, b : REF_TO INT` gives two declarations sharing the type text: each is wrapped
        let Some((kinds, span)) = self.at.get(&start).cloned() else {
            return;
        };
        for kind in kinds.iter().rev() {
            let target = std::mem::replace(ty, TypeRef::Named(crate::ast::Ident::new("", span)));
            let end = target.span().end;
            *ty = TypeRef::Ref {
                kind: *kind,
                target: Box::new(target),
                span: Span::new(span_file, span.start as usize, end as usize),
            };
        }
        self.used.insert(start);
    }
}
