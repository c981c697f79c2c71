//! IL bodies to C statements.
//!
//! Input: a POU's IL statements, its [`Scope`], the sema model's per-instruction info (current-result
//! types, callees, argument bindings). Output: C statements appended to one buffer, plus the set of
//! current-result locals and labels they use. Invariants: the current result lives in one C local per
//! C type (`cr_INT`, `cr_BOOL` ...), typed statically from the model; a deferred operator `AND(` saves the
//! outer result in a block-scoped local `d<depth>`, evaluates the nested list, then combines; jumps are
//! `goto L_<label>`; only labels that are jumped to are emitted; work is linear in the body's size.

use super::scope::{convert, convert_elementary, real_to_int, Place, Scope};
use super::Gen;
use crate::ctypes;
use crate::mangle;
use diagnostics::{code, Diagnostic, Span};
use il_frontend::ast::{
    ArgDir, CallArgs, Condition, FbInputOp, IlStmt, InstrKind, Instruction, Op, Operand, VarKind,
    VarRef,
};
use il_frontend::sema::{
    ArgBinding, ArgSource, Callee, ConversionKind, Elementary, FbType, InstrInfo, PouId, Type,
};
use std::collections::{BTreeMap, HashSet};

use Elementary as E;

/// The state of one body being translated.
pub struct Body<'s, 'm> {
    pub scope: &'s Scope<'m>,
    pub out: String,
    indent: usize,
    /// Current-result locals: name -> C declaration.
    pub crs: BTreeMap<String, String>,
    /// Labels that some jump targets (keys).
    pub targets: HashSet<String>,
    depth: usize,
    temps: usize,
    /// For a FUNCTION: the C expression returned by RET.
    pub ret: String,
}

impl<'s, 'm> Body<'s, 'm> {
    pub fn new(scope: &'s Scope<'m>, indent: usize, ret: String) -> Self {
        Body {
            scope,
            out: String::new(),
            indent,
            crs: BTreeMap::new(),
            targets: HashSet::new(),
            depth: 0,
            temps: 0,
            ret,
        }
    }
    pub fn line(&mut self, text: &str) {
        for _ in 0..self.indent {
            self.out.push_str("    ");
        }
        self.out.push_str(text);
        self.out.push('\n');
    }
    fn temp(&mut self) -> String {
        self.temps += 1;
        format!("t_{}", self.temps)
    }
}

/// Collects the labels targeted by jumps (nested lists included).
pub fn jump_targets(stmts: &[IlStmt], into: &mut HashSet<String>) {
    for s in stmts {
        if let IlStmt::Instr(i) = s {
            match &i.kind {
                InstrKind::Jump { label, .. } => {
                    into.insert(label.key());
                }
                InstrKind::Deferred { body, .. } => jump_targets(body, into),
                _ => {}
            }
        }
    }
}

impl Gen<'_> {
    /// The current-result local for values of `ty` (declared on first use).
    fn cr(&mut self, b: &mut Body, ty: &Type, span: Span) -> Option<String> {
        let base = match ty {
            Type::Array { .. } => {
                self.unsupported(span, "an array as the current result");
                return None;
            }
            Type::String { wide: true, .. } => {
                self.unsupported(span, "a WSTRING as the current result");
                return None;
            }
            t => match ctypes::base(self.model, t) {
                Some(b) => b,
                None => {
                    self.unsupported(span, "a current result of unknown type");
                    return None;
                }
            },
        };
        let name = format!("cr_{}", base.strip_prefix("IEC_").unwrap_or(&base));
        if !b.crs.contains_key(&name) {
            let init = if ty.elementary().is_some() || matches!(ty, Type::Enum(_)) {
                "0"
            } else {
                "{0}"
            };
            b.crs
                .insert(name.clone(), format!("{base} {name} = {init};"));
        }
        Some(name)
    }

    fn info(&mut self, i: &Instruction) -> Option<InstrInfo> {
        match self.model.instr(i.span) {
            Some(info) => Some(info.clone()),
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

    pub fn stmts(&mut self, b: &mut Body, stmts: &[IlStmt]) {
        for s in stmts {
            match s {
                IlStmt::Label(l) => {
                    if b.targets.contains(&l.key()) {
                        let ind = b.indent;
                        b.indent = ind.saturating_sub(1);
                        b.line(&format!("{}:;", mangle::label(&l.name)));
                        b.indent = ind;
                    }
                }
                IlStmt::Instr(i) => self.instr(b, i),
            }
        }
    }

    fn instr(&mut self, b: &mut Body, i: &Instruction) {
        match &i.kind {
            InstrKind::Jump { cond, label } => {
                let target = mangle::label(&label.name);
                self.conditional(b, i, *cond, &format!("goto {target};"));
            }
            InstrKind::Return { cond } => {
                let ret = if b.ret.is_empty() {
                    "return;".to_string()
                } else {
                    format!("return {};", b.ret)
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
                    b.line(&format!("{c}();"));
                }
                None => self.report_once(
                    Diagnostic::error(
                        code::E2004,
                        format!("no embedded C function `{}` was supplied", name.name),
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
                    } => self.simple(b, i, &info, *op, *negate, operand.as_ref()),
                    InstrKind::Deferred {
                        op,
                        negate,
                        operand,
                        body,
                        close,
                    } => self.deferred(b, i, &info, *op, *negate, operand.as_ref(), body, *close),
                    InstrKind::Call {
                        cond,
                        instance,
                        args,
                    } => self.cal(b, i, &info, *cond, instance, args),
                    InstrKind::FunctionCall { args, .. } => self.function_call(b, i, &info, args),
                    InstrKind::FbInput { op, instance } => {
                        self.fb_input(b, i, &info, fb_input_name(*op), instance)
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
        let before = self
            .model
            .instr(i.span)
            .and_then(|x| x.cr_before.clone())
            .unwrap_or(Type::BOOL);
        let cr = if before.is_bool() {
            cr
        } else {
            match self.cr(b, &before, i.span) {
                Some(c) => convert(&c, &before, &Type::BOOL),
                None => return,
            }
        };
        let test = if cond == Condition::IfTrue {
            cr
        } else {
            format!("!{cr}")
        };
        b.line(&format!("if ({test}) {stmt}"));
    }

    fn simple(
        &mut self,
        b: &mut Body,
        i: &Instruction,
        info: &InstrInfo,
        op: Op,
        negate: bool,
        operand: Option<&Operand>,
    ) {
        let span = i.span;
        match op {
            Op::Ld => {
                let (Some(ty), Some(o)) = (info.cr_after.clone(), operand) else {
                    return;
                };
                let Some(cr) = self.cr(b, &ty, span) else {
                    return;
                };
                let Some(v) = self.value(b.scope, o, &ty) else {
                    return;
                };
                let v = if negate { negated(&v, &ty) } else { v };
                b.line(&format!("{cr} = {v};"));
            }
            Op::St => {
                let (Some(ty), Some(o)) = (info.cr_before.clone(), operand) else {
                    return;
                };
                let Some(cr) = self.cr(b, &ty, span) else {
                    return;
                };
                let Some(place) = self.operand_place(b.scope, o) else {
                    return;
                };
                let v = if negate { negated(&cr, &ty) } else { cr };
                let v = convert(&v, &ty, place.ty());
                let stmt = self.store(&place, &v);
                b.line(&stmt);
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
                b.line(&format!("if ({cr}) {{ {stmt} }}"));
            }
            Op::Not => {
                let Some(ty) = info.cr_before.clone() else {
                    return;
                };
                let Some(cr) = self.cr(b, &ty, span) else {
                    return;
                };
                let v = negated(&cr, &ty);
                b.line(&format!("{cr} = {v};"));
            }
            _ => {
                let (Some(before), Some(after), Some(o)) =
                    (info.cr_before.clone(), info.cr_after.clone(), operand)
                else {
                    return;
                };
                let common = std_common_type(info, &before);
                let Some(a) = self.cr(b, &before, span) else {
                    return;
                };
                let a = convert(&a, &before, &common);
                let operand_ty = self.operand_ty_for(info, &common, op);
                let Some(v) = self.value(b.scope, o, &operand_ty) else {
                    return;
                };
                let v = if negate { negated(&v, &operand_ty) } else { v };
                let Some(res) = self.binary(span, op, &a, &common, &v, &operand_ty, &after) else {
                    return;
                };
                let Some(cr) = self.cr(b, &after, span) else {
                    return;
                };
                b.line(&format!("{cr} = {res};"));
            }
        }
    }

    /// The type to read an operator's operand as: the instantiated generic type, except for the
    /// time overloads (`MUL_TIME` by a number) where the operand keeps its own numeric type.
    fn operand_ty_for(&self, info: &InstrInfo, common: &Type, op: Op) -> Type {
        if let Some(t) = &info.operand {
            if matches!(op, Op::Mul | Op::Div)
                && common.elementary().is_some_and(|e| e.is_duration())
            {
                return t.clone();
            }
            if common.is_error() {
                return t.clone();
            }
            if matches!(op, Op::Sub | Op::Add) && t.elementary().is_some_and(|e| e.is_duration()) {
                return t.clone();
            }
        }
        common.clone()
    }

    /// The place an operand denotes (variables and direct addresses).
    pub(super) fn operand_place(&mut self, scope: &Scope, o: &Operand) -> Option<Place> {
        match o {
            Operand::Var(r) => self.place(scope, r),
            Operand::Address(a) => {
                let e = il_frontend::sema::Location::of(a).elementary();
                match self.profile.locate(a, None) {
                    Ok(loc) => Some(Place::Loc {
                        loc,
                        ty: Type::Elementary(e),
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
    fn std_binary(
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
                let v = convert(v, vty, result);
                let a = convert(a, aty, result);
                Some(format!("(({ct})(({a}) {c} ({v})))"))
            }
            "GT" | "GE" | "EQ" | "NE" | "LE" | "LT" => {
                let lname = name.to_ascii_lowercase();
                if aty.is_string() {
                    let c = match name {
                        "GT" => ">",
                        "GE" => ">=",
                        "EQ" => "==",
                        "NE" => "!=",
                        "LE" => "<=",
                        _ => "<",
                    };
                    return Some(format!("((IEC_BOOL)(ladderc_str_cmpv({a}, {v}) {c} 0))"));
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
                let v = convert(v, vty, aty);
                Some(format!("ladderc_{lname}_{h}(({h})({a}), ({h})({v}))"))
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
                let lname = name.to_ascii_lowercase();
                let ve = vty.elementary();
                if re.is_real() {
                    let a = convert(a, aty, result);
                    let v = convert(v, vty, result);
                    return Some(match name {
                        "MOD" => format!("(({rt})fmod((double)({a}), (double)({v})))"),
                        _ => {
                            let c = match name {
                                "ADD" => "+",
                                "SUB" => "-",
                                "MUL" => "*",
                                _ => "/",
                            };
                            format!("(({rt})(({a}) {c} ({v})))")
                        }
                    });
                }
                if re.is_duration()
                    && matches!(name, "MUL" | "DIV")
                    && ve.is_some_and(|e| e.is_real())
                {
                    let c = if name == "MUL" { "*" } else { "/" };
                    return Some(format!(
                        "(({rt})ladderc_real_to_int((double)({a}) {c} (double)({v}), INT64_MIN, INT64_MAX))"
                    ));
                }
                let h = ctypes::arith_helper_type(re)?;
                Some(format!(
                    "(({rt})ladderc_{lname}_{h}(({h})({a}), ({h})({v})))"
                ))
            }
            _ => {
                self.unsupported(span, format!("the operator {name}"));
                None
            }
        }
    }

    #[allow(clippy::too_many_arguments)]
    fn deferred(
        &mut self,
        b: &mut Body,
        i: &Instruction,
        info: &InstrInfo,
        op: Op,
        negate: bool,
        operand: Option<&Operand>,
        body: &[IlStmt],
        _close: Span,
    ) {
        let span = i.span;
        b.depth += 1;
        let d = format!("d_{}", b.depth);
        b.line("{");
        b.indent += 1;
        let outer = if op == Op::Ld {
            None
        } else {
            let Some(before) = info.cr_before.clone() else {
                b.indent -= 1;
                b.line("}");
                b.depth -= 1;
                return;
            };
            let Some(cr) = self.cr(b, &before, span) else {
                b.indent -= 1;
                b.line("}");
                b.depth -= 1;
                return;
            };
            let decl = ctypes::declare(self.model, &before, &d).unwrap_or_default();
            b.line(&format!("{decl} = {cr};"));
            Some(before)
        };
        let nested_ty = info.operand.clone();
        if let Some(o) = operand {
            // the implicit LD that starts the nested list, typed as the first instruction expects
            let first = body.iter().find_map(|s| match s {
                IlStmt::Instr(i) => self.model.instr(i.span).and_then(|x| x.cr_before.clone()),
                _ => None,
            });
            let ty = first
                .or_else(|| nested_ty.clone())
                .unwrap_or_else(|| self.operand_type(b.scope, o, None));
            if let (Some(cr), Some(v)) = (self.cr(b, &ty, o.span()), self.value(b.scope, o, &ty)) {
                b.line(&format!("{cr} = {v};"));
            }
        }
        self.stmts(b, body);
        if let (Some(vt), Some(after)) = (nested_ty, info.cr_after.clone()) {
            if let Some(vcr) = self.cr(b, &vt, span) {
                let v = if negate { negated(&vcr, &vt) } else { vcr };
                let res = match &outer {
                    None => Some(convert(&v, &vt, &after)),
                    Some(before) => {
                        let common = std_common_type(info, before);
                        let a = convert(&d, before, &common);
                        let vty = self.operand_ty_for(info, &common, op);
                        let v = convert(&v, &vt, &vty);
                        self.binary(span, op, &a, &common, &v, &vty, &after)
                    }
                };
                if let (Some(res), Some(cr)) = (res, self.cr(b, &after, span)) {
                    b.line(&format!("{cr} = {res};"));
                }
            }
        }
        b.indent -= 1;
        b.line("}");
        b.depth -= 1;
    }

    /// The written operand of argument `i`.
    fn written_arg(args: &CallArgs, i: usize) -> Option<(&Operand, bool)> {
        match args {
            CallArgs::None => None,
            CallArgs::NonFormal(v) => v.get(i).map(|o| (o, false)),
            CallArgs::Formal(v) => v
                .get(i)
                .map(|a| (&a.value, matches!(a.dir, ArgDir::Output { negated: true }))),
        }
    }

    /// The C value of an input binding, of the parameter's type.
    fn arg_value(
        &mut self,
        b: &mut Body,
        info: &InstrInfo,
        args: &CallArgs,
        binding: &ArgBinding,
        span: Span,
    ) -> Option<String> {
        match binding.source {
            ArgSource::CurrentResult => {
                let before = info.cr_before.clone()?;
                let cr = self.cr(b, &before, span)?;
                Some(convert(&cr, &before, &binding.ty))
            }
            ArgSource::Written(i) => {
                let (o, _) = Self::written_arg(args, i)?;
                self.value(b.scope, o, &binding.ty)
            }
        }
    }

    /// `CAL inst(...)`, `CALC inst`, `CALCN inst`.
    fn cal(
        &mut self,
        b: &mut Body,
        i: &Instruction,
        info: &InstrInfo,
        cond: Condition,
        instance: &VarRef,
        args: &CallArgs,
    ) {
        let Some(Place::Mem { lv, ty }) = self.place(b.scope, instance) else {
            self.unsupported(
                instance.span,
                "calling something that is not an FB instance in memory",
            );
            return;
        };
        let Type::Fb(fb) = ty else {
            self.unsupported(
                instance.span,
                "CAL of a variable that is not an FB instance",
            );
            return;
        };
        let guard = match cond {
            Condition::Always => None,
            c => {
                let Some(cr) = self.cr(b, &Type::BOOL, i.span) else {
                    return;
                };
                Some(if c == Condition::IfTrue {
                    cr
                } else {
                    format!("!{cr}")
                })
            }
        };
        match guard {
            Some(g) => b.line(&format!("if ({g}) {{")),
            None => b.line("{"),
        }
        b.indent += 1;
        let mut outputs = Vec::new();
        for binding in &info.args {
            if binding.output {
                outputs.push(binding.clone());
                continue;
            }
            let field = self.fb_param_lvalue(&lv, fb, &binding.param);
            if self.fb_param_is_inout(fb, &binding.param) {
                let ArgSource::Written(k) = binding.source else {
                    continue;
                };
                let Some((o, _)) = Self::written_arg(args, k) else {
                    continue;
                };
                match self.operand_place(b.scope, o) {
                    Some(Place::Mem { lv: target, .. }) => {
                        let raw = self.fb_param_raw(&lv, fb, &binding.param);
                        b.line(&format!("{raw} = &{target};"));
                    }
                    _ => self.unsupported(o.span(), "this argument for an IN_OUT parameter"),
                }
                continue;
            }
            let Some(v) = self.arg_value(b, info, args, binding, i.span) else {
                continue;
            };
            let place = Place::Mem {
                lv: field,
                ty: binding.ty.clone(),
            };
            let stmt = self.store(&place, &v);
            b.line(&stmt);
        }
        b.line(&invoke(self, &lv, fb));
        self.store_outputs(b, &lv, fb, &outputs, args);
        b.indent -= 1;
        b.line("}");
    }

    fn store_outputs(
        &mut self,
        b: &mut Body,
        lv: &str,
        fb: FbType,
        outputs: &[ArgBinding],
        args: &CallArgs,
    ) {
        for binding in outputs {
            let ArgSource::Written(k) = binding.source else {
                continue;
            };
            let Some((o, negate)) = Self::written_arg(args, k) else {
                continue;
            };
            let Some(target) = self.operand_place(b.scope, o) else {
                continue;
            };
            let field = self.fb_param_lvalue(lv, fb, &binding.param);
            let v = if negate {
                negated(&field, &binding.ty)
            } else {
                field
            };
            let v = convert(&v, &binding.ty, target.ty());
            let stmt = self.store(&target, &v);
            b.line(&stmt);
        }
    }

    fn fb_param_raw(&self, lv: &str, fb: FbType, param: &str) -> String {
        match fb {
            FbType::Standard(f) => {
                let (_, params) = ctypes::std_fb(f);
                let n = params
                    .iter()
                    .find(|p| p.0.eq_ignore_ascii_case(param))
                    .map(|p| p.0.to_string())
                    .unwrap_or_else(|| param.to_ascii_uppercase());
                format!("{lv}.{n}")
            }
            FbType::User(_) => format!("{lv}.{}", mangle::var(param)),
        }
    }

    fn fb_param_is_inout(&self, fb: FbType, param: &str) -> bool {
        match fb {
            FbType::Standard(_) => false,
            FbType::User(id) => self
                .pou_var(id, param)
                .is_some_and(|v| v.kind == VarKind::InOut),
        }
    }

    fn fb_param_lvalue(&self, lv: &str, fb: FbType, param: &str) -> String {
        let raw = self.fb_param_raw(lv, fb, param);
        if self.fb_param_is_inout(fb, param) {
            format!("(*{raw})")
        } else {
            raw
        }
    }

    /// `IN tmr`, `CU ctr` ...: stores the current result into the input and invokes the instance.
    fn fb_input(
        &mut self,
        b: &mut Body,
        i: &Instruction,
        info: &InstrInfo,
        input: &str,
        instance: &VarRef,
    ) {
        let fb = match &info.callee {
            Some(Callee::FbInstance { fb, .. }) => *fb,
            _ => match self.place(b.scope, instance).map(|p| p.ty().clone()) {
                Some(Type::Fb(fb)) => fb,
                _ => {
                    self.unsupported(instance.span, "an FB input operator on a non-instance");
                    return;
                }
            },
        };
        self.fb_input_named(b, i, info, fb, input, instance);
    }

    fn fb_input_named(
        &mut self,
        b: &mut Body,
        i: &Instruction,
        info: &InstrInfo,
        fb: FbType,
        input: &str,
        instance: &VarRef,
    ) {
        let Some(Place::Mem { lv, .. }) = self.place(b.scope, instance) else {
            return;
        };
        let Some(before) = info.cr_before.clone() else {
            return;
        };
        let Some(cr) = self.cr(b, &before, i.span) else {
            return;
        };
        let pty = match fb {
            FbType::Standard(f) => ctypes::std_fb(f)
                .1
                .iter()
                .find(|p| p.0.eq_ignore_ascii_case(input))
                .map(|p| Type::Elementary(p.1)),
            FbType::User(id) => self.pou_var(id, input).map(|v| v.ty.clone()),
        };
        let Some(pty) = pty else {
            self.unsupported(instance.span, format!("the FB input `{input}`"));
            return;
        };
        let field = self.fb_param_lvalue(&lv, fb, input);
        let v = convert(&cr, &before, &pty);
        let stmt = self.store(&Place::Mem { lv: field, ty: pty }, &v);
        b.line(&stmt);
        b.line(&invoke(self, &lv, fb));
    }

    /// A function called as an operator (standard, conversion or user function).
    fn function_call(&mut self, b: &mut Body, i: &Instruction, info: &InstrInfo, args: &CallArgs) {
        let span = i.span;
        match info.callee.clone() {
            Some(Callee::Std { name, ty, result }) => {
                let after = info.cr_after.clone().unwrap_or(result.clone());
                let mut vals = Vec::new();
                let mut tys = Vec::new();
                for binding in info.args.iter().filter(|a| !a.output) {
                    let Some(v) = self.arg_value(b, info, args, binding, span) else {
                        return;
                    };
                    vals.push(v);
                    tys.push(binding.ty.clone());
                }
                let Some(res) = self.std_call(span, name, &ty, &vals, &tys, &result) else {
                    return;
                };
                let res = convert(&res, &result, &after);
                if let Some(cr) = self.cr(b, &after, span) {
                    b.line(&format!("{cr} = {res};"));
                }
            }
            Some(Callee::Conversion { kind, from, to, .. }) => {
                let Some(binding) = info.args.iter().find(|a| !a.output) else {
                    return;
                };
                let Some(v) = self.arg_value(b, info, args, &binding.clone(), span) else {
                    return;
                };
                let Some(res) = self.conversion(span, kind, &v, &from, &to) else {
                    return;
                };
                let after = info.cr_after.clone().unwrap_or(to.clone());
                let res = convert(&res, &to, &after);
                if let Some(cr) = self.cr(b, &after, span) {
                    b.line(&format!("{cr} = {res};"));
                }
            }
            Some(Callee::UserFunction(id)) => self.user_function_call(b, i, info, id, args),
            _ => self.unsupported(span, "this function call"),
        }
    }

    fn user_function_call(
        &mut self,
        b: &mut Body,
        i: &Instruction,
        info: &InstrInfo,
        id: PouId,
        args: &CallArgs,
    ) {
        let span = i.span;
        let pou = self.model.pou(id).clone();
        b.line("{");
        b.indent += 1;
        let mut call_args = Vec::new();
        let mut after_call = Vec::new();
        for v in pou
            .vars
            .iter()
            .filter(|v| matches!(v.kind, VarKind::Input | VarKind::Output | VarKind::InOut))
        {
            let binding = info
                .args
                .iter()
                .find(|a| a.param.eq_ignore_ascii_case(&v.name))
                .cloned();
            match v.kind {
                VarKind::Input => {
                    let val = match &binding {
                        Some(bd) => self.arg_value(b, info, args, bd, span),
                        None => Some(self.default_value(&v.ty, v.init.as_ref(), span)),
                    };
                    let Some(val) = val else {
                        b.indent -= 1;
                        b.line("}");
                        return;
                    };
                    call_args.push(val);
                }
                VarKind::Output => {
                    let t = b.temp();
                    let Some(decl) = ctypes::declare(self.model, &v.ty, &t) else {
                        continue;
                    };
                    let init = if v.ty.elementary().is_some() {
                        "0"
                    } else {
                        "{0}"
                    };
                    b.line(&format!("{decl} = {init};"));
                    call_args.push(format!("&{t}"));
                    if let Some(bd) = &binding {
                        if let ArgSource::Written(k) = bd.source {
                            if let Some((o, negate)) = Self::written_arg(args, k) {
                                if let Some(target) = self.operand_place(b.scope, o) {
                                    let val = if negate {
                                        negated(&t, &v.ty)
                                    } else {
                                        t.clone()
                                    };
                                    let val = convert(&val, &v.ty, target.ty());
                                    after_call.push(self.store(&target, &val));
                                }
                            }
                        }
                    }
                }
                _ => {
                    let target = binding.as_ref().and_then(|bd| match bd.source {
                        ArgSource::Written(k) => Self::written_arg(args, k).map(|x| x.0.clone()),
                        ArgSource::CurrentResult => None,
                    });
                    match target.and_then(|o| self.operand_place(b.scope, &o)) {
                        Some(Place::Mem { lv, .. }) => call_args.push(format!("&{lv}")),
                        _ => {
                            self.unsupported(span, "a missing or located IN_OUT argument");
                            b.indent -= 1;
                            b.line("}");
                            return;
                        }
                    }
                }
            }
        }
        let call = format!("{}({})", mangle::function(&pou.name), call_args.join(", "));
        match (&pou.return_type, info.cr_after.clone()) {
            (Some(rt), Some(after)) => {
                if let Some(cr) = self.cr(b, &after, span) {
                    let v = convert(&call, rt, &after);
                    b.line(&format!("{cr} = {v};"));
                }
            }
            _ => b.line(&format!("{call};")),
        }
        for s in after_call {
            b.line(&s);
        }
        b.indent -= 1;
        b.line("}");
    }

    /// The default (initial) value of a parameter not given in a call.
    pub fn default_value(
        &mut self,
        ty: &Type,
        init: Option<&il_frontend::sema::ConstValue>,
        span: Span,
    ) -> String {
        if let (Some(e), Some(v)) = (ty.elementary(), init) {
            if let Some(c) = ctypes::const_elementary(self.model, e, v) {
                return c;
            }
        }
        if let (Type::String { .. }, Some(il_frontend::sema::ConstValue::String { value, .. })) =
            (ty, init)
        {
            return ctypes::string_value(value);
        }
        match ty {
            Type::Elementary(_) | Type::Subrange { .. } | Type::Enum(_) => {
                let base = ctypes::base(self.model, ty).unwrap_or_default();
                format!("(({base})0)")
            }
            Type::String { wide: false, .. } => ctypes::string_value(""),
            _ => {
                self.unsupported(span, "omitting an input of this type in a function call");
                "0".into()
            }
        }
    }

    /// A standard function on already-evaluated arguments.
    fn std_call(
        &mut self,
        span: Span,
        name: &str,
        ty: &Type,
        vals: &[String],
        tys: &[Type],
        result: &Type,
    ) -> Option<String> {
        let ty = if ty.is_error() {
            tys.first().cloned().unwrap_or(Type::Error)
        } else {
            ty.clone()
        };
        let e = ty.elementary();
        let need = |n: usize| vals.len() >= n;
        match name {
            "ADD" | "MUL" | "SUB" | "DIV" | "MOD" | "AND" | "OR" | "XOR" => {
                if !need(2) {
                    return None;
                }
                let mut acc = vals[0].clone();
                let mut acc_ty = tys[0].clone();
                for k in 1..vals.len() {
                    acc = self.std_binary(span, name, &acc, &acc_ty, &vals[k], &tys[k], result)?;
                    acc_ty = result.clone();
                }
                Some(acc)
            }
            "GT" | "GE" | "EQ" | "NE" | "LE" | "LT" => {
                if !need(2) {
                    return None;
                }
                let mut parts = Vec::new();
                for k in 1..vals.len() {
                    parts.push(self.std_binary(
                        span,
                        name,
                        &vals[k - 1],
                        &ty,
                        &vals[k],
                        &tys[k],
                        &Type::BOOL,
                    )?);
                }
                Some(format!("((IEC_BOOL)({}))", parts.join(" & ")))
            }
            "NOT" => Some(negated(vals.first()?, &ty)),
            "MOVE" => vals.first().cloned(),
            "SEL" => {
                if !need(3) {
                    return None;
                }
                Some(format!("(({}) ? ({}) : ({}))", vals[0], vals[2], vals[1]))
            }
            "MUX" => {
                if !need(2) {
                    return None;
                }
                let k = &vals[0];
                let mut expr = vals[1].clone();
                for (n, v) in vals.iter().enumerate().skip(2).rev() {
                    expr = format!("(({k}) == {} ? ({v}) : {expr})", n - 1);
                }
                // K out of range selects IN0
                Some(expr)
            }
            "MAX" | "MIN" => {
                let e = e?;
                let h = ctypes::ordered_helper_type(e);
                let ct = ctypes::elementary(e);
                let f = name.to_ascii_lowercase();
                let mut acc = format!("(({h})({}))", vals.first()?);
                for v in &vals[1..] {
                    acc = format!("ladderc_{f}_{h}({acc}, ({h})({v}))");
                }
                Some(format!("(({ct}){acc})"))
            }
            "LIMIT" => {
                if !need(3) {
                    return None;
                }
                let Some(e) = e else {
                    self.unsupported(span, "LIMIT on this type");
                    return None;
                };
                let h = ctypes::ordered_helper_type(e);
                let ct = ctypes::elementary(e);
                Some(format!(
                    "(({ct})ladderc_limit_{h}(({h})({}), ({h})({}), ({h})({})))",
                    vals[0], vals[1], vals[2]
                ))
            }
            "ABS" => {
                let e = e?;
                let v = vals.first()?;
                Some(match e {
                    E::Real => format!("((IEC_REAL)fabsf({v}))"),
                    E::Lreal => format!("((IEC_LREAL)fabs({v}))"),
                    _ if e.is_signed_integer() => {
                        let ct = ctypes::elementary(e);
                        format!("ladderc_abs_{ct}({v})")
                    }
                    _ => v.clone(),
                })
            }
            "SQRT" | "LN" | "LOG" | "EXP" | "SIN" | "COS" | "TAN" | "ASIN" | "ACOS" | "ATAN" => {
                let e = e?;
                let f = match name {
                    "LN" => "log",
                    "LOG" => "log10",
                    n => &n.to_ascii_lowercase(),
                };
                let v = vals.first()?;
                Some(if e == E::Real {
                    format!("((IEC_REAL){f}f({v}))")
                } else {
                    format!("((IEC_LREAL){f}({v}))")
                })
            }
            "EXPT" => {
                if !need(2) {
                    return None;
                }
                let ct = ctypes::base(self.model, result)?;
                Some(format!(
                    "(({ct})pow((double)({}), (double)({})))",
                    vals[0], vals[1]
                ))
            }
            "SHL" | "SHR" | "ROL" | "ROR" => {
                if !need(2) {
                    return None;
                }
                let e = e?;
                let h = match e {
                    E::Byte | E::Usint => "IEC_BYTE",
                    E::Word | E::Uint => "IEC_WORD",
                    E::Dword | E::Udint => "IEC_DWORD",
                    E::Lword | E::Ulint => "IEC_LWORD",
                    _ => {
                        self.unsupported(span, format!("{name} on this type"));
                        return None;
                    }
                };
                let ct = ctypes::elementary(e);
                let f = name.to_ascii_lowercase();
                Some(format!(
                    "(({ct})ladderc_{f}_{h}(({h})({}), (int64_t)({})))",
                    vals[0], vals[1]
                ))
            }
            other => {
                self.unsupported(span, format!("the standard function {other}"));
                None
            }
        }
    }

    fn conversion(
        &mut self,
        span: Span,
        kind: ConversionKind,
        v: &str,
        from: &Type,
        to: &Type,
    ) -> Option<String> {
        let (f, t) = match (from.elementary(), to.elementary()) {
            (Some(f), Some(t)) => (f, t),
            (Some(f), None) if matches!(to, Type::String { wide: false, .. }) => {
                let ct = ctypes::elementary(f);
                return Some(format!(
                    "ladderc_str_of({}, &({ct}){{{v}}})",
                    ctypes::type_tag(f)
                ));
            }
            (None, Some(t)) if matches!(from, Type::String { wide: false, .. }) => {
                return Some(match t {
                    E::Bool => format!("ladderc_str_to_bool({v})"),
                    E::Real | E::Lreal => {
                        format!("(({})ladderc_str_to_real({v}))", ctypes::elementary(t))
                    }
                    E::Time | E::Ltime => format!("ladderc_str_to_time({v})"),
                    _ if t.is_signed_integer() => {
                        convert_elementary(&format!("ladderc_str_to_int({v})"), E::Lint, t)
                    }
                    _ if t.is_integer() || t.is_bit() => {
                        convert_elementary(&format!("ladderc_str_to_uint({v})"), E::Ulint, t)
                    }
                    _ => {
                        self.unsupported(span, "converting a STRING to a date or time of day");
                        return None;
                    }
                });
            }
            (None, None) if from.is_string() && to.is_string() && !to.is_error() => {
                if matches!(
                    (from, to),
                    (
                        Type::String { wide: false, .. },
                        Type::String { wide: false, .. }
                    )
                ) {
                    return Some(convert(v, from, to));
                }
                self.unsupported(span, "WSTRING conversions");
                return None;
            }
            _ => {
                self.unsupported(span, "this conversion");
                return None;
            }
        };
        Some(match kind {
            ConversionKind::Plain => convert_elementary(v, f, t),
            ConversionKind::Trunc => {
                if f.is_real() && (t.is_integer() || t.is_bit()) {
                    real_to_int(&format!("trunc((double)({v}))"), t)
                } else {
                    convert_elementary(v, f, t)
                }
            }
            ConversionKind::FromBcd => convert_elementary(
                &format!("ladderc_bcd_to_uint((uint64_t)({v}))"),
                E::Ulint,
                t,
            ),
            ConversionKind::ToBcd => {
                let src = if f.is_signed_integer() {
                    format!("(({v}) < 0 ? (ladderc_errors |= LADDERC_ERR_RANGE, (uint64_t)0) : (uint64_t)({v}))")
                } else {
                    format!("(uint64_t)({v})")
                };
                convert_elementary(&format!("ladderc_uint_to_bcd({src})"), E::Ulint, t)
            }
        })
    }
}

/// The call of an FB instance's body.
fn invoke(g: &Gen, lv: &str, fb: FbType) -> String {
    match fb {
        FbType::Standard(f) => format!("{}_body(&{lv});", ctypes::std_fb(f).0),
        FbType::User(id) => format!("{}_BODY(&{lv});", mangle::fb(&g.model.pou(id).name)),
    }
}

fn fb_input_name(op: FbInputOp) -> &'static str {
    op.input_name()
}

/// The instantiated type of an operator from the model (falls back to the CR type).
fn std_common_type(info: &InstrInfo, before: &Type) -> Type {
    match &info.callee {
        Some(Callee::Std { ty, .. }) if !ty.is_error() => ty.clone(),
        _ => before.clone(),
    }
}

/// Boolean NOT for BOOL, bitwise complement for bit strings.
pub fn negated(v: &str, ty: &Type) -> String {
    if ty.is_bool() {
        format!("((IEC_BOOL)!({v}))")
    } else {
        let ct = ty
            .elementary()
            .map(ctypes::elementary)
            .unwrap_or("IEC_DWORD");
        format!("(({ct})~({v}))")
    }
}
