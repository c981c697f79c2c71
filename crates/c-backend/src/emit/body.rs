//! IL bodies to C statements (calls are in `calls`).
//!
//! Input: a POU's IL statements, its [`Scope`], the sema model's per-instruction info (current-result
//! types, callees, argument bindings). Output: C statements appended to one buffer, plus the set of
//! current-result locals and labels they use. Invariants: the current result lives in one C local per
//! C type (`cr_INT`, `cr_BOOL` ...), typed statically from the model; a deferred operator `AND(` saves the
//! outer result in a block-scoped local `d<depth>`, evaluates the nested list, then combines; jumps are
//! `goto L_<label>`; only labels that are jumped to are emitted; work is linear in the body's size (indentation stops growing at `MAX_INDENT` levels).

use super::scope::{Place, Scope};
use super::values::{convert, convert_cow, convert_owned};
use super::Gen;
use crate::ctypes;
use crate::mangle;
use diagnostics::{code, Diagnostic, Span};
use il_frontend::ast::{Condition, FbInputOp, IlStmt, InstrKind, Instruction, Op, Operand};
use il_frontend::sema::{Callee, Elementary, InstrFacts, InstrId, Type};
use std::collections::{BTreeMap, HashSet};
use std::rc::Rc;

use Elementary as E;

/// The deepest indentation of generated C, in levels of four spaces.
pub const MAX_INDENT: usize = 16;

/// The state of one body being translated.
pub struct Body<'s, 'm> {
    pub scope: &'s Scope<'m>,
    pub out: String,
    pub(super) indent: usize,
    /// Current-result locals: name -> C declaration.
    pub crs: BTreeMap<String, String>,
    /// Labels that some jump targets (keys).
    pub targets: HashSet<String>,
    /// Labels already passed (keys): a jump to one of them goes back, it closes a loop.
    placed: HashSet<String>,
    depth: usize,
    temps: usize,
    /// The current-result locals already declared, by IEC type (a short list: one per C type used).
    cr_names: Vec<(Type, Rc<str>)>,
    /// For a FUNCTION: the C expression returned by RET.
    pub ret: String,
    /// In a part of a split body (see `split`): its index and the labels entered from another part.
    pub part: Option<(usize, &'s super::split::PartLabels)>,
    /// Set when a jump leaves the part (`next_ = <label>; goto exit_;`).
    pub exits: bool,
}

impl<'s, 'm> Body<'s, 'm> {
    pub fn new(scope: &'s Scope<'m>, indent: usize, ret: String) -> Self {
        Body {
            scope,
            out: String::new(),
            indent,
            crs: BTreeMap::new(),
            targets: HashSet::new(),
            placed: HashSet::new(),
            depth: 0,
            temps: 0,
            cr_names: Vec::new(),
            ret,
            part: None,
            exits: false,
        }
    }
    /// Appends one line of C, indented by the nesting level up to [`MAX_INDENT`] levels (deeper
    /// blocks stay at that column, so the C grows linearly with the IL however deep `ADD(` nests).
    pub fn line(&mut self, text: &str) {
        self.begin_line();
        self.out.push_str(text);
        self.out.push('\n');
    }
    /// Starts a line: its indentation (see [`Body::line`]).
    pub fn begin_line(&mut self) {
        for _ in 0..self.indent.min(MAX_INDENT) {
            self.out.push_str("    ");
        }
    }
    /// [`Body::line`] for formatted text, written straight into the body (no `String` per line).
    pub fn line_fmt(&mut self, args: std::fmt::Arguments) {
        use std::fmt::Write as _;
        self.push_indent();
        let _ = self.out.write_fmt(args);
        self.out.push('\n');
    }
    /// [`Body::line`] for a line made of `parts`, written straight into the body without a format
    /// template (the per-instruction lines: `cr = value;`).
    pub fn line_parts(&mut self, parts: &[&str]) {
        self.push_indent();
        for p in parts {
            self.out.push_str(p);
        }
        self.out.push('\n');
    }
    fn push_indent(&mut self) {
        for _ in 0..self.indent.min(MAX_INDENT) {
            self.out.push_str("    ");
        }
    }
    pub(super) fn temp(&mut self) -> String {
        self.temps += 1;
        cfmt!("t_{}", self.temps)
    }
}

/// An open deferred operator, waiting for its nested list.
struct Deferred {
    span: Span,
    info: InstrFacts,
    op: Op,
    negate: bool,
    /// The outer current result's type (`None` for `LD(`).
    outer: Option<Type>,
    /// The block-scoped local holding the outer result.
    saved: String,
}

/// Collects the labels targeted by jumps (nested lists included).
pub fn jump_targets(stmts: &[IlStmt], into: &mut HashSet<String>) {
    let mut lists = vec![stmts];
    while let Some(list) = lists.pop() {
        for s in list {
            if let IlStmt::Instr(i) = s {
                match &i.kind {
                    InstrKind::Jump { label, .. } => {
                        into.insert(label.key());
                    }
                    InstrKind::Deferred { body, .. } => lists.push(body),
                    _ => {}
                }
            }
        }
    }
}

impl<'a> Gen<'a> {
    /// The current-result local for values of `ty` (declared on first use).
    /// The name is shared (`Rc`): most instructions ask for it, and only format it.
    pub(super) fn cr(&mut self, b: &mut Body, ty: &Type, span: Span) -> Option<Rc<str>> {
        if let Some((_, name)) = b.cr_names.iter().find(|(t, _)| t == ty) {
            return Some(name.clone());
        }
        if let Type::Array { .. } = ty {
            // a whole array (`b := a`, `LD a` / `ST b`): a C array local, copied with memcpy
            let name = format!("cr_array_{}", b.crs.len());
            let Some(decl) = ctypes::declare(self.model, ty, &name) else {
                self.unsupported(span, "an array of unknown type as the current result");
                return None;
            };
            b.crs.insert(name.clone(), format!("{decl} = {{0}};"));
            let name: Rc<str> = name.into();
            b.cr_names.push((ty.clone(), name.clone()));
            return Some(name);
        }
        let Some(base) = ctypes::base(self.model, ty) else {
            self.unsupported(span, "a current result of unknown type");
            return None;
        };
        let name = cfmt!("cr_{}", base.strip_prefix("IEC_").unwrap_or(&base));
        if !b.crs.contains_key(&name) {
            let init = if ty.elementary().is_some() || matches!(ty, Type::Enum(_)) {
                "0"
            } else {
                "{0}"
            };
            b.crs.insert(name.clone(), cfmt!("{base} {name} = {init};"));
        }
        let name: Rc<str> = name.into();
        if b.cr_names.len() < 16 {
            b.cr_names.push((ty.clone(), name.clone()));
        }
        Some(name)
    }

    pub(super) fn info(&mut self, i: &Instruction) -> Option<&'a InstrFacts> {
        let model: &'a il_frontend::sema::Model = self.model;
        match model.instrs.get_near(InstrId::of(i), self.instr_cursor) {
            Some((at, info)) => {
                self.instr_cursor = at + 1;
                Some(info.facts)
            }
            None => {
                self.report_once(
                    Diagnostic::error(
                        code::E2005,
                        "the C backend has no type information for this instruction",
                    )
                    .at(i.span)
                    .with_note("the analysis did not record it; this is a bug in ladderc"),
                );
                None
            }
        }
    }

    /// Translates a statement list. Nested lists of deferred operators are walked with an explicit
    /// stack, so nesting depth is bounded by memory, not by the call stack.
    pub fn stmts(&mut self, b: &mut Body, stmts: &[IlStmt]) {
        enum Work<'a> {
            List(&'a [IlStmt]),
            Close(Option<Box<Deferred>>),
        }
        let mut stack = vec![Work::List(stmts)];
        while let Some(work) = stack.pop() {
            let list = match work {
                Work::Close(Some(d)) => {
                    self.deferred_close(b, *d);
                    continue;
                }
                Work::Close(None) => continue,
                Work::List(list) => list,
            };
            let Some((s, rest)) = list.split_first() else {
                continue;
            };
            stack.push(Work::List(rest));
            match s {
                IlStmt::Label(l) => {
                    b.placed.insert(l.key());
                    if b.targets.contains(&l.key()) {
                        let ind = b.indent;
                        b.indent = ind.saturating_sub(1);
                        b.line_fmt(format_args!("{}:;", mangle::label(&l.name)));
                        b.indent = ind;
                    }
                }
                IlStmt::Instr(i) => {
                    if let InstrKind::Deferred {
                        op,
                        negate,
                        operand,
                        body,
                        ..
                    } = &i.kind
                    {
                        let d = self.deferred_open(b, i, *op, *negate, operand.as_deref(), body);
                        if d.is_some() {
                            stack.push(Work::Close(d.map(Box::new)));
                            stack.push(Work::List(body));
                        }
                    } else {
                        self.instr(b, i);
                    }
                }
            }
        }
    }

    fn instr(&mut self, b: &mut Body, i: &Instruction) {
        match &i.kind {
            InstrKind::Jump { cond, label } => {
                let far = b.part.and_then(|(k, labels)| {
                    labels
                        .get(&label.key())
                        .filter(|(p, _)| *p != k)
                        .map(|&(p, id)| (p < k, id))
                });
                // a jump back closes a loop: under `ladderc run` it counts against the scan's loop
                // budget (`LADDERC_LOOP_GUARD`, `ladderc_rt.h`), located by the jump's span
                let back = match far {
                    Some((earlier, _)) => earlier,
                    None => b.placed.contains(&label.key()),
                };
                let guard = if back {
                    cfmt!(
                        "LADDERC_LOOP_GUARD({}u, {}u, {}u); ",
                        i.span.file.0,
                        i.span.start,
                        i.span.end
                    )
                } else {
                    String::new()
                };
                let stmt = match far {
                    Some((_, id)) => {
                        b.exits = true;
                        cfmt!("{{ {guard}next_ = {id}; goto exit_; }}")
                    }
                    None if back => cfmt!("{{ {guard}goto {}; }}", mangle::label(&label.name)),
                    None => cfmt!("goto {};", mangle::label(&label.name)),
                };
                self.conditional(b, i, *cond, &stmt);
            }
            InstrKind::Return { cond } => {
                let ret = if b.ret.is_empty() {
                    "return;".to_string()
                } else {
                    cfmt!("return {};", b.ret)
                };
                self.conditional(b, i, *cond, &ret);
            }
            InstrKind::EmbeddedC { name } if self.is_method(name) => {
                let call = self.method_call(name, b.scope.pou.map(|p| p.1));
                if let Some(call) = call.filter(|c| !c.is_empty()) {
                    b.line(&call);
                }
            }
            InstrKind::EmbeddedC { name } => match self.embedded.get(&name.key()) {
                Some(c) => {
                    let c = c.clone();
                    b.line_fmt(format_args!("{c}();"));
                }
                None => self.report_once(
                    Diagnostic::error(
                        code::E2004,
                        cfmt!("no embedded C function `{}` was supplied", name.name),
                    )
                    .at(name.span)
                    .with_primary_label("unknown embedded function")
                    .with_hint("FUNC calls functions provided by the parameter-passing stage"),
                ),
            },
            _ => {
                let Some(info) = self.info(i) else { return };
                match &i.kind {
                    InstrKind::Simple {
                        op,
                        negate,
                        operand,
                    } => self.simple(b, i, info, *op, *negate, operand.as_ref()),
                    InstrKind::Call {
                        cond,
                        instance,
                        args,
                    } => self.cal(b, i, info, *cond, instance, args),
                    InstrKind::FunctionCall { args, .. } => self.function_call(b, i, info, args),
                    InstrKind::FbInput { op, instance } => {
                        self.fb_input(b, i, info, fb_input_name(*op), instance)
                    }
                    _ => {}
                }
            }
        }
    }

    /// Emits `stmt` guarded by the condition (C: CR TRUE, CN: CR FALSE).
    fn conditional(&mut self, b: &mut Body, i: &Instruction, cond: Condition, stmt: &str) {
        if cond == Condition::Always {
            b.line(stmt);
            return;
        }
        let Some(cr) = self.cr(b, &Type::BOOL, i.span) else {
            return;
        };
        let found = self
            .model
            .instrs
            .get_near(InstrId::of(i), self.instr_cursor);
        if let Some((at, _)) = found {
            self.instr_cursor = at + 1;
        }
        let before = found
            .and_then(|(_, x)| x.cr_before.clone())
            .unwrap_or(Type::BOOL);
        let converted;
        let cr: &str = if before.is_bool() {
            &cr
        } else {
            match self.cr(b, &before, i.span) {
                Some(c) => {
                    converted = convert(&c, &before, &Type::BOOL);
                    &converted
                }
                None => return,
            }
        };
        if cond == Condition::IfTrue {
            b.line_parts(&["if (", cr, ") ", stmt]);
        } else {
            b.line_parts(&["if (!", cr, ") ", stmt]);
        }
    }

    fn simple(
        &mut self,
        b: &mut Body,
        i: &Instruction,
        info: &InstrFacts,
        op: Op,
        negate: bool,
        operand: Option<&Operand>,
    ) {
        let span = i.span;
        match op {
            Op::Ld => {
                let (Some(ty), Some(o)) = (info.cr_after.as_ref(), operand) else {
                    return;
                };
                let Some(cr) = self.cr(b, ty, span) else {
                    return;
                };
                let Some(v) = self.value(b.scope, o, ty) else {
                    return;
                };
                if let Type::Array { .. } = ty {
                    b.line(&format!("memcpy({cr}, {v}, sizeof {cr});"));
                    return;
                }
                let v = if negate { negated(&v, ty) } else { v };
                b.line_parts(&[&cr, " = ", &v, ";"]);
            }
            Op::St => {
                let (Some(ty), Some(o)) = (info.cr_before.as_ref(), operand) else {
                    return;
                };
                let Some(cr) = self.cr(b, ty, span) else {
                    return;
                };
                let Some(place) = self.operand_place(b.scope, o) else {
                    return;
                };
                if let (Type::Array { .. }, Place::Loc { .. }) = (&ty, &place) {
                    self.unsupported(span, "storing a whole array at a direct address");
                    return;
                }
                let v = if negate {
                    convert_owned(negated(&cr, ty), ty, place.ty())
                } else {
                    convert(&cr, ty, place.ty())
                };
                let v = into_subrange(v, ty, place.ty());
                self.store_line(b, &place, &v);
            }
            Op::S | Op::R => {
                if let Some(Callee::FbInstance {
                    fb,
                    input: Some(input),
                }) = &info.callee
                {
                    if let Some(Operand::Var(r)) = operand {
                        self.fb_input_named(b, i, info, *fb, input, r);
                    }
                    return;
                }
                let Some(o) = operand else { return };
                let Some(cr) = self.cr(b, &Type::BOOL, span) else {
                    return;
                };
                let Some(place) = self.operand_place(b.scope, o) else {
                    return;
                };
                let one = convert(if op == Op::S { "1" } else { "0" }, &Type::BOOL, place.ty());
                let stmt = self.store(&place, &one);
                b.line_parts(&["if (", &cr, ") { ", &stmt, " }"]);
            }
            Op::Not => {
                let Some(ty) = info.cr_before.as_ref() else {
                    return;
                };
                let Some(cr) = self.cr(b, ty, span) else {
                    return;
                };
                let v = negated(&cr, ty);
                b.line_parts(&[&cr, " = ", &v, ";"]);
            }
            _ => {
                let (Some(before), Some(after), Some(o)) =
                    (info.cr_before.as_ref(), info.cr_after.as_ref(), operand)
                else {
                    return;
                };
                let common = std_common_type(info, before);
                let Some(a) = self.cr(b, before, span) else {
                    return;
                };
                let a = convert(&a, before, common);
                let operand_ty = self.operand_ty_for(info, common, op);
                let Some(v) = self.value(b.scope, o, operand_ty) else {
                    return;
                };
                let v = if negate { negated(&v, operand_ty) } else { v };
                let Some(res) = self.binary(span, op, &a, common, &v, operand_ty, after) else {
                    return;
                };
                let Some(cr) = self.cr(b, after, span) else {
                    return;
                };
                b.line_parts(&[&cr, " = ", &res, ";"]);
            }
        }
    }

    /// The type to read an operator's operand as: the instantiated generic type, except for the
    /// time overloads (`MUL_TIME` by a number) where the operand keeps its own numeric type.
    fn operand_ty_for<'t>(&self, info: &'t InstrFacts, common: &'t Type, op: Op) -> &'t Type {
        if let Some(t) = &info.operand {
            if matches!(op, Op::Mul | Op::Div)
                && common.elementary().is_some_and(|e| e.is_duration())
            {
                return t;
            }
            if common.is_error() {
                return t;
            }
            if matches!(op, Op::Sub | Op::Add) && t.elementary().is_some_and(|e| e.is_duration()) {
                return t;
            }
            // `p + n`: the byte count keeps its integer type
            if matches!(op, Op::Sub | Op::Add) && matches!(common, Type::Ref(_)) {
                return t;
            }
        }
        common
    }

    /// The place an operand denotes (variables and direct addresses).
    pub(super) fn operand_place(&mut self, scope: &Scope, o: &Operand) -> Option<Place> {
        match o {
            Operand::Var(r) => self.place(scope, r),
            Operand::Address(a) => {
                let e = il_frontend::sema::Location::of(a).elementary();
                match self.locate(a, None) {
                    Ok(loc) => Some(Place::Loc {
                        loc,
                        ty: Type::Elementary(e),
                        at: None,
                    }),
                    Err(d) => {
                        self.report_once(*d);
                        None
                    }
                }
            }
            _ => {
                self.unsupported(o.span(), "storing into a constant");
                None
            }
        }
    }

    /// `a OP b` for the IL operators (arithmetic, comparison, logic).
    #[allow(clippy::too_many_arguments)]
    fn binary(
        &mut self,
        span: Span,
        op: Op,
        a: &str,
        aty: &Type,
        v: &str,
        vty: &Type,
        result: &Type,
    ) -> Option<String> {
        let name = match op {
            Op::And => "AND",
            Op::Or => "OR",
            Op::Xor => "XOR",
            Op::Add => "ADD",
            Op::Sub => "SUB",
            Op::Mul => "MUL",
            Op::Div => "DIV",
            Op::Mod => "MOD",
            Op::Gt => "GT",
            Op::Ge => "GE",
            Op::Eq => "EQ",
            Op::Ne => "NE",
            Op::Le => "LE",
            Op::Lt => "LT",
            _ => return None,
        };
        self.std_binary(span, name, a, aty, v, vty, result)
    }

    /// A two-input standard function (`ADD`, `GT`, `AND` ...).
    #[allow(clippy::too_many_arguments)]
    pub(super) fn std_binary(
        &mut self,
        span: Span,
        name: &str,
        a: &str,
        aty: &Type,
        v: &str,
        vty: &Type,
        result: &Type,
    ) -> Option<String> {
        match name {
            "AND" | "OR" | "XOR" => {
                let c = match name {
                    "AND" => "&",
                    "OR" => "|",
                    _ => "^",
                };
                let ct = ctypes::base(self.model, result)?;
                let v = convert_cow(v, vty, result);
                let a = convert_cow(a, aty, result);
                Some(crate::cat(&[
                    "((", &ct, ")((", &a, ") ", c, " (", &v, ")))",
                ]))
            }
            "GT" | "GE" | "EQ" | "NE" | "LE" | "LT" => {
                let lname = lower_op(name);
                let c = c_comparison(name);
                if aty.is_string() {
                    let f = if matches!(aty, Type::String { wide: true, .. }) {
                        "ladderc_wstr_cmpv"
                    } else {
                        "ladderc_str_cmpv"
                    };
                    return Some(crate::cat(&[
                        "((IEC_BOOL)(",
                        f,
                        "(",
                        a,
                        ", ",
                        v,
                        ") ",
                        c,
                        " 0))",
                    ]));
                }
                if let Type::Ref(_) = aty {
                    // references: the addresses they stand for (NULL is 0), compared as integers
                    // (`ladderc_ref_addr`), so any two references compare without undefined
                    // behaviour; ordering is meaningful between references into one variable
                    return Some(crate::cat(&[
                        "((IEC_BOOL)(ladderc_ref_addr(",
                        a,
                        ") ",
                        c,
                        " ladderc_ref_addr(",
                        v,
                        ")))",
                    ]));
                }
                let e = match aty {
                    Type::Enum(_) => E::Dint,
                    t => match t.elementary() {
                        Some(e) => e,
                        None => {
                            self.unsupported(span, "comparing values of this type");
                            return None;
                        }
                    },
                };
                let h = ctypes::ordered_helper_type(e);
                let v = convert_cow(v, vty, aty);
                Some(crate::cat(&[
                    "ladderc_", &lname, "_", h, "((", h, ")(", a, "), (", h, ")(", &v, "))",
                ]))
            }
            "SUB" if matches!(aty, Type::Ref(_)) && matches!(vty, Type::Ref(_)) => {
                // `p - q`: the distance in bytes of the addresses they stand for
                Some(crate::cat(&[
                    "((IEC_DWORD)(ladderc_ref_addr(",
                    a,
                    ") - ladderc_ref_addr(",
                    v,
                    ")))",
                ]))
            }
            "ADD" | "SUB" if matches!(aty, Type::Ref(_)) => {
                // pointer arithmetic (CODESYS, TwinCAT): `p + n` moves `p` by n bytes; the offset
                // is checked when the pointer is dereferenced (refs.rs)
                let f = if name == "SUB" {
                    "ladderc_ref_sub("
                } else {
                    "ladderc_ref_add("
                };
                Some(crate::cat(&[f, a, ", (int64_t)(", v, "))"]))
            }
            "ADD" | "SUB" | "MUL" | "DIV" | "MOD" => {
                let re = match result {
                    Type::Enum(_) => E::Dint,
                    t => match t.elementary() {
                        Some(e) => e,
                        None => {
                            self.unsupported(span, "arithmetic on values of this type");
                            return None;
                        }
                    },
                };
                let rt = ctypes::elementary(re);
                let lname = lower_op(name);
                let ve = vty.elementary();
                if re.is_real() {
                    let a = convert_cow(a, aty, result);
                    let v = convert_cow(v, vty, result);
                    return Some(match name {
                        "MOD" => crate::cat(&[
                            "((",
                            rt,
                            ")fmod((double)(",
                            &a,
                            "), (double)(",
                            &v,
                            ")))",
                        ]),
                        _ => {
                            let c = match name {
                                "ADD" => "+",
                                "SUB" => "-",
                                "MUL" => "*",
                                _ => "/",
                            };
                            crate::cat(&["((", rt, ")((", &a, ") ", c, " (", &v, ")))"])
                        }
                    });
                }
                if re.is_duration()
                    && matches!(name, "MUL" | "DIV")
                    && ve.is_some_and(|e| e.is_real())
                {
                    let c = if name == "MUL" { "*" } else { "/" };
                    return Some(cfmt!(
                        "(({rt})ladderc_real_to_int((double)({a}) {c} (double)({v}), INT64_MIN, INT64_MAX))"
                    ));
                }
                let h = ctypes::arith_helper_type(re)?;
                Some(crate::cat(&[
                    "((",
                    rt,
                    ")ladderc_",
                    &lname,
                    "_",
                    h,
                    "((",
                    h,
                    ")(",
                    a,
                    "), (",
                    h,
                    ")(",
                    v,
                    ")))",
                ]))
            }
            _ => {
                self.unsupported(span, cfmt!("the operator {name}"));
                None
            }
        }
    }

    /// Opens a deferred operator's block: saves the outer result, loads the implicit operand. Returns
    /// what [`Gen::deferred_close`] needs, or `None` (block already closed) when the outer result is
    /// unusable.
    fn deferred_open(
        &mut self,
        b: &mut Body,
        i: &Instruction,
        op: Op,
        negate: bool,
        operand: Option<&Operand>,
        body: &[IlStmt],
    ) -> Option<Deferred> {
        let span = i.span;
        let info = self.info(i)?;
        b.depth += 1;
        let d = cfmt!("d_{}", b.depth);
        b.line("{");
        b.indent += 1;
        let outer = if op == Op::Ld {
            None
        } else {
            let saved = info
                .cr_before
                .clone()
                .and_then(|before| self.cr(b, &before, span).map(|cr| (before, cr)));
            let Some((before, cr)) = saved else {
                b.indent -= 1;
                b.line("}");
                b.depth -= 1;
                return None;
            };
            let decl = ctypes::declare(self.model, &before, &d).unwrap_or_default();
            b.line_parts(&[&decl, " = ", &cr, ";"]);
            Some(before)
        };
        if let Some(o) = operand {
            // the implicit LD that starts the nested list, typed as the first instruction expects
            let first = body.iter().find_map(|s| match s {
                IlStmt::Instr(i) => self
                    .model
                    .instrs
                    .get_near(InstrId::of(i), self.instr_cursor)
                    .and_then(|(_, x)| x.cr_before.clone()),
                _ => None,
            });
            let ty = first
                .or_else(|| info.operand.clone())
                .unwrap_or_else(|| self.operand_type(b.scope, o, None));
            if let (Some(cr), Some(v)) = (self.cr(b, &ty, o.span()), self.value(b.scope, o, &ty)) {
                b.line_parts(&[&cr, " = ", &v, ";"]);
            }
        }
        Some(Deferred {
            span,
            info: info.clone(),
            op,
            negate,
            outer,
            saved: d,
        })
    }

    /// Combines the saved outer result with the nested list's value and closes the block.
    fn deferred_close(&mut self, b: &mut Body, d: Deferred) {
        let span = d.span;
        if let (Some(vt), Some(after)) = (d.info.operand.clone(), d.info.cr_after.clone()) {
            if let Some(vcr) = self.cr(b, &vt, span) {
                let v = if d.negate {
                    negated(&vcr, &vt)
                } else {
                    vcr.to_string()
                };
                let res = match &d.outer {
                    None => Some(convert(&v, &vt, &after)),
                    Some(before) => {
                        let common = std_common_type(&d.info, before);
                        let a = convert(&d.saved, before, common);
                        let vty = self.operand_ty_for(&d.info, common, d.op);
                        let v = convert(&v, &vt, vty);
                        self.binary(span, d.op, &a, common, &v, vty, &after)
                    }
                };
                if let (Some(res), Some(cr)) = (res, self.cr(b, &after, span)) {
                    b.line_parts(&[&cr, " = ", &res, ";"]);
                }
            }
        }
        b.indent -= 1;
        b.line("}");
        b.depth -= 1;
    }
}

fn fb_input_name(op: FbInputOp) -> &'static str {
    op.input_name()
}

/// The instantiated type of an operator from the model (falls back to the CR type).
fn std_common_type<'t>(info: &'t InstrFacts, before: &'t Type) -> &'t Type {
    match &info.callee {
        Some(Callee::Std { ty, .. }) if !ty.is_error() => ty,
        _ => before,
    }
}

/// Boolean NOT for BOOL, bitwise complement for bit strings.
pub fn negated(v: &str, ty: &Type) -> String {
    if ty.is_bool() {
        cfmt!("((IEC_BOOL)!({v}))")
    } else {
        let ct = ty
            .elementary()
            .map(ctypes::elementary)
            .unwrap_or("IEC_DWORD");
        cfmt!("(({ct})~({v}))")
    }
}

/// The C operator of an IEC comparison (`GT` ... `LT`).
fn c_comparison(name: &str) -> &'static str {
    match name {
        "GT" => ">",
        "GE" => ">=",
        "EQ" => "==",
        "NE" => "!=",
        "LE" => "<=",
        _ => "<",
    }
}

/// An operator's name in lower case, as the runtime's helpers spell it (`ladderc_gt_...`).
fn lower_op(name: &str) -> std::borrow::Cow<'static, str> {
    let known = [
        ("GT", "gt"),
        ("GE", "ge"),
        ("EQ", "eq"),
        ("NE", "ne"),
        ("LE", "le"),
        ("LT", "lt"),
        ("ADD", "add"),
        ("SUB", "sub"),
        ("MUL", "mul"),
        ("DIV", "div"),
        ("MOD", "mod"),
    ];
    match known.iter().find(|(n, _)| *n == name) {
        Some((_, l)) => (*l).into(),
        None => name.to_ascii_lowercase().into(),
    }
}

/// A value of type `from` stored into a place of type `to`: when `to` is a subrange and `from` is
/// not that subrange (`n := n * 5`, a UINT result into a `UINT(1..4)`), the value saturated to the
/// range with the runtime's range flag (IEC 61131-3 makes a value outside a subrange an error); a
/// value of the subrange itself (a literal checked against it, another variable of it) stays.
fn into_subrange(v: String, from: &Type, to: &Type) -> String {
    let Type::Subrange { base, lower, upper } = to else {
        return v;
    };
    if from == to {
        return v;
    }
    let ct = ctypes::elementary(*base);
    if base.is_signed() {
        cfmt!(
            "(({ct})ladderc_subrange_i((int64_t)({v}), INT64_C({}), INT64_C({})))",
            **lower,
            **upper
        )
    } else {
        cfmt!(
            "(({ct})ladderc_subrange_u((uint64_t)({v}), UINT64_C({}), UINT64_C({})))",
            **lower,
            **upper
        )
    }
}
