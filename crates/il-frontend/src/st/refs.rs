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
//! FUNCTION's result); an initial value `ADR(path)` / `REF(path)` (a name with fields and constant
//! subscripts) is kept for the declaration (`sema::address_init` checks it), any other but `NULL`
//! is one E0305.

use super::file::{blank, is_var_keyword, word};
use super::lexer::{Tok, Token};
use crate::ast::{
    Accessor, CompilationUnit, Ident, LibraryElement, RefKind, TypeDef, TypeRef, VarBlock, VarDecl,
    VarRef,
};
use crate::{FileId, Span};
use diagnostics::{code, Diagnostic, Diagnostics};
use std::collections::HashMap;
use std::ops::Range;

/// `__ISVALIDREF(r)` (CODESYS): whether reference `r` refers to a variable (is not NULL).
pub const IS_VALID_REF: &str = "__ISVALIDREF";

/// The callee name `r REF= x` is parsed into (`r := REF=(x)`; no identifier can be written so).
pub const REF_ASSIGN: &str = "REF=";

/// The callee name `r ACCESS e` is parsed into when `e` is not `ADR(x)` (B&R Automation Studio's
/// dynamic variables: `pt ACCESS (ADR(pt) + 1)`): the reference takes the address `e` computes, as a
/// pointer would (`ADR(x)` is read as `r REF= x`).
pub const ACCESS_ASSIGN: &str = "ACCESS=";

/// `REF=` binding a `REFERENCE TO` input of the block's own method for one call (`CalculateBlock(block)`
/// inside a method of the block): the reference is call-scoped ([`crate::ast::RefOperand::call_scoped`]),
/// so it may refer to a VAR_IN_OUT or a temporary of the caller, and the input is reset to NULL when
/// the call returns; sema refuses a reference kept through such an input (E0305).
pub const REF_ASSIGN_CALL: &str = "REF=CALL";

/// Whether `name` is `REF` (edition 3) or `ADR` (CODESYS, TwinCAT): the address of its argument.
pub fn is_address_of(name: &crate::ast::Ident) -> bool {
    name.is("REF") || name.is("ADR") || name.is(super::varlen::CALL_ADDRESS)
}

/// Whether type `t` is or holds (as an array element, or referred to) a `REFERENCE TO`.
pub fn holds_reference_to(t: &TypeRef) -> bool {
    let mut t = t;
    loop {
        match t {
            TypeRef::Ref {
                kind: RefKind::Reference,
                ..
            } => return true,
            TypeRef::Ref { target, .. } => t = target,
            TypeRef::Array { element, .. } => t = element,
            _ => return false,
        }
    }
}

/// The reference keywords blanked in one file: by the offset of the type text they stood before,
/// the kinds outermost first (`REF_TO REF_TO INT` has two) and the span of the first keyword.
#[derive(Debug, Default)]
pub struct RefTypes {
    file: Option<FileId>,
    at: HashMap<usize, (Vec<RefKind>, Span)>,
    /// Errors found while blanking (initial values), reported with the others.
    pending: Vec<Diagnostic>,
    /// `:= ADR(x)` initial values (CODESYS, TwinCAT), by the offset of the type text: set on the
    /// declarations when they are wrapped (sema checks what `x` is).
    addresses: HashMap<usize, VarRef>,
    /// While blanking: inside `METHOD ... END_METHOD`, where a variable's initial value may be an
    /// expression assigned when the method starts (`super::method_inits`).
    in_method: bool,
    /// While blanking: the declaration being read is of one name in a method (`p : T := e`), whose
    /// initial value `method_inits` can assign (`a, b : T := e` it cannot: E0305 stays).
    one_method_var: bool,
    /// The initial values of pointers that `super::pou_inits` may compute at run time (`p :
    /// POINTER TO WORD := ADR(regs[idx]);` in a POU's VAR), left in the text with their E0305:
    /// [`Self::settle_initial_values`]. Only while blanking a whole file ([`Self::blank_keywords`]).
    deferred: Option<Vec<(Range<usize>, Diagnostic)>>,
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
        Self::blank_keywords_deferring(file, src, toks, 0, true)
    }

    /// The E0305 of the pointers' initial values left in the text (held back while the text was read) that are
    /// not among the initial values computed at run time (`computed`, ranges of `:= expr`):
    /// reported, and the values blanked in `text`.
    pub fn settle_initial_values(&mut self, text: &mut String, computed: &[Range<usize>]) {
        for (r, d) in self.deferred.take().unwrap_or_default() {
            if !computed
                .iter()
                .any(|c| c.start <= r.start && r.end <= c.end)
            {
                blank(text, r);
                self.pending.push(d);
            }
        }
    }

    /// [`Self::blank_keywords`] of a text that starts at offset `base` of its file (a declaration
    /// text cut out of an XML element).
    pub fn blank_keywords_at(
        file: FileId,
        src: &str,
        toks: &[Token],
        base: usize,
    ) -> (Option<String>, RefTypes) {
        Self::blank_keywords_deferring(file, src, toks, base, false)
    }

    fn blank_keywords_deferring(
        file: FileId,
        src: &str,
        toks: &[Token],
        base: usize,
        defer: bool,
    ) -> (Option<String>, RefTypes) {
        let mut text: Option<String> = None;
        let mut refs = RefTypes {
            file: Some(file),
            at: HashMap::new(),
            pending: Vec::new(),
            addresses: HashMap::new(),
            in_method: false,
            one_method_var: false,
            deferred: defer.then(Vec::new),
        };
        let mut in_decl = false;
        for (k, t) in toks.iter().enumerate() {
            let w = word(src, t).to_ascii_uppercase();
            if matches!(t.tok, Tok::Kw(_) | Tok::Ident) {
                if w == "METHOD" {
                    refs.in_method = true;
                } else if w == "END_METHOD" {
                    refs.in_method = false;
                }
                // (a METHOD's result type too: `METHOD Take : POINTER TO ST_Node`, and a
                // PROPERTY's: `PROPERTY Child : REFERENCE TO FB_Tree`)
                if is_var_keyword(&w)
                    || matches!(
                        w.as_str(),
                        "STRUCT" | "TYPE" | "FUNCTION" | "METHOD" | "PROPERTY"
                    )
                {
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
                first.get_or_insert(Span::new(file, base + kw.range.start, base + end));
                kinds.push(kind);
                blank(
                    text.get_or_insert_with(|| src.to_string()),
                    kw.range.start..end,
                );
                j = next;
            }
            if let (Some(span), true) = (first, kinds.len() > crate::parser::MAX_TYPE_NESTING) {
                // `REF_TO REF_TO ...` deeper than any type may nest: read as the type (no wrap)
                refs.pending.push(
                    Diagnostic::error(
                        code::E0211,
                        format!(
                            "references to references nested more than {} deep",
                            crate::parser::MAX_TYPE_NESTING
                        ),
                    )
                    .at(span)
                    .with_primary_label("the first of them")
                    .with_hint("refer to a structure holding the next reference instead"),
                );
                continue;
            }
            if let (Some(span), Some(target)) = (first, toks.get(j)) {
                refs.at.insert(base + target.range.start, (kinds, span));
                // a METHOD's, FUNCTION's or PROPERTY's result type has no initial value: the
                // body follows (`METHOD Next : POINTER TO FB_Item` then `Next := pNext;`)
                if !result_type_at(src, toks, k) {
                    refs.one_method_var = refs.in_method
                        && k >= 1
                        && toks[k - 1].tok == Tok::Ident
                        && (k < 2 || toks[k - 2].tok != Tok::Comma);
                    let kind = refs
                        .at
                        .get(&(base + target.range.start))
                        .and_then(|(k, _)| k.first().copied());
                    refs.initial_value(file, src, toks, (j, kind), base, &mut text);
                }
            }
        }
        (text, refs)
    }

    /// The initial value of a reference declared at token `j` (its type), up to the `;`: `:= NULL`
    /// is what every reference starts with (blanked); `:= REF(x)` / `ADR(x)` is one E0305 (a
    /// reference starts as NULL; it is set in the body), blanked too, so that the declaration reads.
    /// `kind`: the outermost keyword; the value of a `POINTER TO` or `REF_TO` (not a `REFERENCE
    /// TO`) `super::pou_inits` may compute at run time (`:= ADR(regs[idx])`): then left for it.
    fn initial_value(
        &mut self,
        file: FileId,
        src: &str,
        toks: &[Token],
        (j, kind): (usize, Option<RefKind>),
        base: usize,
        text: &mut Option<String>,
    ) {
        let mut k = j;
        // `r : REFERENCE TO INT REF= x;` (TwinCAT, CODESYS): the reference starts referring to
        // `x`, as a pointer declared `:= ADR(x)` starts pointing at it
        let mut ref_eq = false;
        while let Some(t) = toks.get(k) {
            match t.tok {
                Tok::Semi => return,
                Tok::Assign => break,
                Tok::Ident
                    if word(src, t).eq_ignore_ascii_case("REF")
                        && toks.get(k + 1).is_some_and(|e| e.tok == Tok::Eq) =>
                {
                    ref_eq = true;
                    break;
                }
                _ if is_var_keyword(&word(src, t).to_ascii_uppercase()) => return,
                _ => k += 1,
            }
        }
        let Some(assign) = toks.get(k) else { return };
        let from = if ref_eq { k + 2 } else { k + 1 };
        let mut end = from;
        while toks.get(end).is_some_and(|t| t.tok != Tok::Semi) {
            end += 1;
        }
        let Some(last) = toks.get(end.wrapping_sub(1)).filter(|_| end > from) else {
            return;
        };
        let first_value = toks.get(from).map_or(assign.range.end, |t| t.range.start);
        let value = src.get(first_value..last.range.end).unwrap_or("").trim();
        let value_span = Span::new(file, base + assign.range.start, base + last.range.end);
        let as_address;
        let value = if ref_eq {
            as_address = format!("ADR({value})");
            as_address.as_str()
        } else {
            value
        };
        if let Some(target) = address_initial_value(
            value,
            Span::new(file, base + first_value, base + last.range.end),
        ) {
            // `p : POINTER TO INT := ADR(a);`: kept for the declaration (see `decls`)
            if let Some(t) = toks.get(j) {
                self.addresses.insert(base + t.range.start, target);
            }
        } else if kind != Some(RefKind::Reference)
            && !ref_eq
            && !self.in_method
            && address_array(value, value_span)
        {
            // `p : ARRAY[0..1] OF POINTER TO INT := [ADR(a), ADR(b)];` (CODESYS, TwinCAT): left
            // for the declaration, each element an address (`sema::address_init`; a method's
            // variables start at each call, `method_inits`: E0305 there)
            return;
        } else if self.one_method_var
            && (super::method_inits::is_run_time_value(&toks[k + 1..end])
                || value.eq_ignore_ascii_case("THIS")
                // `pCopy : POINTER TO INT := pHead;`: another pointer's value, read when the
                // method starts (`method_inits`)
                || (!value.eq_ignore_ascii_case("NULL")
                    && toks[from..end]
                        .iter()
                        .all(|t| matches!(t.tok, Tok::Ident | Tok::Dot))
                    && toks.get(from).is_some_and(|t| t.tok == Tok::Ident)))
        {
            // `pCurrent : POINTER TO T := THIS^.pRoot;` in a method (CODESYS, TwinCAT,
            // fisothemes/TwinCat-Dynamic-Collections), `pSelf : POINTER TO FB_X := THIS;` in its
            // VAR_INST: assigned when the method starts, or at its first call on the instance
            // (`method_inits`), left in the text for it
            return;
        } else if !value.eq_ignore_ascii_case("NULL") && !is_zero_literal(value) {
            let what = if kind == Some(RefKind::Pointer) {
                "a pointer"
            } else {
                "a reference"
            };
            let pointer = matches!(kind, Some(RefKind::Pointer | RefKind::RefTo));
            let d = Diagnostic::error(
                code::E0305,
                format!("{what} cannot have the initial value `{value}`"),
            )
            .at(value_span)
            .with_primary_label("initial value")
            .with_hint(format!("{what} starts as NULL or as `ADR(x)` of a variable; a pointer of a PROGRAM's or block's VAR may start as an address computed at run time (`ADR(a[i])`): else set it in the body (`r := REF(x);`)"));
            if let (Some(deferred), true, false) =
                (self.deferred.as_mut(), pointer, ref_eq || self.in_method)
            {
                // left in the text: `pou_inits` may compute it
                deferred.push((assign.range.start..last.range.end, d));
                return;
            }
            self.pending.push(d);
        }
        blank(
            text.get_or_insert_with(|| src.to_string()),
            assign.range.start..last.range.end,
        );
    }

    /// Wraps the declared types that stood after a reference keyword into [`TypeRef::Ref`], and
    /// reports the refused initial values.
    pub fn apply(mut self, unit: &mut CompilationUnit, diags: &mut Diagnostics) {
        if self.at.is_empty() {
            self.report_left(diags);
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

    /// Reports the initial values refused (E0305). A keyword whose type was not wrapped stood in
    /// text the parser did not read (a POU refused as a whole, a declaration with a syntax error):
    /// that is reported already, and nothing is added.
    pub fn report_left(&mut self, diags: &mut Diagnostics) {
        for d in self.pending.drain(..) {
            diags.push(d);
        }
    }

    fn blocks(&mut self, blocks: &mut [VarBlock]) {
        for b in blocks {
            self.decls(&mut b.vars);
        }
    }

    fn decls(&mut self, decls: &mut [VarDecl]) {
        for d in decls {
            let start = d.ty.span().start as usize;
            if let Some(target) = self.addresses.get(&start) {
                d.init = Some(crate::ast::Initializer::Value(
                    crate::ast::Operand::reference(Some(target.clone()), target.span),
                ));
            }
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
    }
}

/// Whether the `:` at token `colon` starts the result type of a POU header: `METHOD [modifiers]
/// Name :`, `FUNCTION Name :`, `PROPERTY [modifiers] Name :`.
fn result_type_at(src: &str, toks: &[Token], colon: usize) -> bool {
    let Some(mut k) = colon.checked_sub(1) else {
        return false;
    };
    if toks[k].tok != Tok::Ident {
        return false;
    }
    while let Some(before) = k.checked_sub(1) {
        let w = word(src, &toks[before]).to_ascii_uppercase();
        match w.as_str() {
            "METHOD" | "FUNCTION" | "PROPERTY" => return true,
            "PUBLIC" | "PRIVATE" | "PROTECTED" | "INTERNAL" | "FINAL" | "ABSTRACT" | "OVERRIDE" => {
                k = before
            }
            _ => return false,
        }
    }
    false
}

/// `ADR(path)` / `REF(path)` written as an initial value, `path` a name with fields and constant
/// integer subscripts (`ADR(a)`, `ADR(st.f)`, `ADR(buf[2])`), as the variable it names; `None`
/// for anything else (an expression, a variable subscript: E0305 at the value).
fn address_initial_value(value: &str, span: Span) -> Option<VarRef> {
    let up = value.to_ascii_uppercase();
    if !(up.starts_with("ADR") || up.starts_with("REF")) {
        return None;
    }
    let inner = value[3..]
        .trim_start()
        .strip_prefix('(')?
        .strip_suffix(')')?
        .trim();
    let ident = |s: &str| {
        let s = s.trim();
        (!s.is_empty()
            && s.chars().all(|c| c.is_ascii_alphanumeric() || c == '_')
            && !s.starts_with(|c: char| c.is_ascii_digit()))
        .then(|| Ident::new(s, span))
    };
    let mut base: Option<Ident> = None;
    let mut accessors = Vec::new();
    for segment in inner.split('.') {
        let (name, mut rest) = match segment.find('[') {
            Some(i) => (&segment[..i], &segment[i..]),
            None => (segment, ""),
        };
        let name = ident(name)?;
        if base.is_none() {
            base = Some(name);
        } else {
            accessors.push(Accessor::Field(name));
        }
        while let Some(r) = rest.trim().strip_prefix('[') {
            let close = r.find(']')?;
            let mut subscripts = Vec::new();
            for s in r[..close].split(',') {
                let v: i128 = s.trim().parse().ok()?;
                subscripts.push(crate::ast::Operand::literal(crate::ast::Literal {
                    kind: crate::ast::LiteralKind::Int(v),
                    type_prefix: None,
                    span,
                }));
            }
            accessors.push(Accessor::Index(subscripts));
            rest = &r[close + 1..];
        }
        if !rest.trim().is_empty() {
            return None;
        }
    }
    Some(VarRef {
        base: base?,
        accessors: accessors.into(),
        span,
    })
}

/// Whether `value` is an array's initial value `[e, ...]` whose every element is `ADR(path)`,
/// `REF(path)` (at least one) or the null address.
fn address_array(value: &str, span: Span) -> bool {
    let Some(inner) = value.strip_prefix('[').and_then(|v| v.strip_suffix(']')) else {
        return false;
    };
    // the top-level elements (commas inside `[...]` subscripts or `(...)` belong to them)
    let mut depth = 0i32;
    let mut elements = Vec::new();
    let mut from = 0;
    for (k, c) in inner.char_indices() {
        match c {
            '(' | '[' => depth += 1,
            ')' | ']' => depth -= 1,
            ',' if depth == 0 => {
                elements.push(inner[from..k].trim());
                from = k + 1;
            }
            _ => {}
        }
    }
    elements.push(inner[from..].trim());
    let mut any = false;
    for e in elements {
        if address_initial_value(e, span).is_some() {
            any = true;
        } else if !e.eq_ignore_ascii_case("NULL") && !is_zero_literal(e) {
            return false;
        }
    }
    any
}

/// `0`, `16#0`, `2#0000` ...: the null address CODESYS and TwinCAT write for a pointer or
/// reference (`p : POINTER TO INT := 0;`), the same as NULL.
fn is_zero_literal(value: &str) -> bool {
    let digits = ["16#", "8#", "2#"]
        .iter()
        .find_map(|p| value.strip_prefix(p))
        .unwrap_or(value);
    !digits.is_empty() && digits.chars().all(|c| c == '0' || c == '_')
}
