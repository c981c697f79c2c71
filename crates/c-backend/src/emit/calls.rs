//! Calls: `CAL` of FB instances, the FB input operators, and function calls (standard functions inline,
//! conversions, user FUNCTIONs).
//!
//! Input: a call instruction with the sema model's callee and argument bindings. Output: C statements in
//! the body buffer. Invariants: FB inputs are assigned before the instance body runs and `=>` outputs are
//! copied after it; FUNCTION outputs go through block-scoped temporaries; IN_OUT parameters are passed by
//! address; every standard function on already-evaluated arguments is a side-effect-free C expression.

use super::body::{negated, Body};
use super::scope::Place;
use super::values::{convert, convert_elementary, real_to_int};
use super::Gen;
use crate::ctypes;
use crate::mangle;
use diagnostics::Span;
use il_frontend::ast::{ArgDir, CallArgs, Condition, Instruction, Operand, VarKind, VarRef};
use il_frontend::sema::{
    ArgBinding, ArgSource, Callee, ConversionKind, Elementary, FbType, InstrFacts, PouId, Type,
};

use Elementary as E;

impl Gen<'_> {
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
        info: &InstrFacts,
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
    pub(super) fn cal(
        &mut self,
        b: &mut Body,
        i: &Instruction,
        info: &InstrFacts,
        cond: Condition,
        instance: &VarRef,
        args: &CallArgs,
    ) {
        // `CAL LIMIT(...)`, `CAL Twice(v := n)` (IEC draft Annex F): sema resolved a function call
        // (a conditional one is sema's E1018).
        if cond == Condition::Always
            && matches!(
                info.callee,
                Some(Callee::Std { .. } | Callee::Conversion { .. } | Callee::UserFunction(_))
            )
        {
            return self.function_call(b, i, info, args);
        }
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
                    cr.to_string()
                } else {
                    cfmt!("!{cr}")
                })
            }
        };
        // EN := e / ENO => v (IEC 61131-3: with EN FALSE the instance is not called and its ENO
        // is FALSE; ladderc skips the whole call, inputs and `=>` copies included, as a ladder
        // rung's CALC does)
        let (mut en, mut eno_target) = self.en_eno(b, args);
        // EN/ENO the block declares itself (IEC 61131-3 ed.3 6.6.1.6, as matiec's
        // add_en_eno_param_decl reads them): they are its enable input and output, kept in the
        // instance: the call stores EN, the body runs only while it is TRUE (and reads it), and
        // the declared ENO is TRUE when the body starts, FALSE when it does not run
        let declared = |name: &str| match fb {
            FbType::User(id) => self.pou_var(id, name).map(|v| v.kind),
            FbType::Standard(_) => None,
        };
        let declared_en = declared("EN") == Some(VarKind::Input);
        let declared_eno = declared("ENO") == Some(VarKind::Output);
        if declared_eno {
            eno_target = None;
        }
        let en_given = en.take();
        if !declared_en {
            en = en_given.clone();
        }
        let user_eno = matches!(fb, FbType::User(_)) && self.model.fb_eno_read;
        if eno_target.is_some() && matches!(fb, FbType::User(_)) && !user_eno {
            self.unsupported(
                instance.span,
                "`ENO =>` of a user function block instance (its body's ENO is not kept)",
            );
            return;
        }
        let stores_eno =
            matches!(fb, FbType::Standard(_)) && (en.is_some() || self.model.fb_eno_read);
        match guard {
            Some(g) => b.line_fmt(format_args!("if ({g}) {{")),
            None => b.line("{"),
        }
        b.indent += 1;
        if declared_en {
            let field = self.fb_param_lvalue(&lv, fb, "EN");
            if let Some(e) = &en_given {
                b.line(&format!("{field} = (IEC_BOOL)({e});"));
            }
            en = Some(field);
        }
        if let Some(e) = &en {
            b.line(&format!("IEC_BOOL ladderc_en = (IEC_BOOL)({e});"));
            b.line("if (ladderc_en) {");
            b.indent += 1;
        }
        let mut outputs = Vec::new();
        let mut after_call = Vec::new();
        let mut eno_output = Vec::new();
        for binding in &info.args {
            if declared_eno && binding.output && binding.param.eq_ignore_ascii_case("ENO") {
                eno_output.push(binding.clone());
                continue;
            }
            if binding.param.eq_ignore_ascii_case("EN") || binding.param.eq_ignore_ascii_case("ENO")
            {
                continue;
            }
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
                    Some(place @ Place::Mem { .. }) => {
                        let raw = self.fb_param_raw(&lv, fb, &binding.param);
                        if let Place::Mem { lv: target, .. } = &place {
                            b.line_fmt(format_args!("{raw} = &{target};"));
                        }
                        let param = match fb {
                            FbType::User(id) => self.pou_var(id, &binding.param).map(|v| &v.ty),
                            FbType::Standard(_) => None,
                        };
                        if let Some(cut) = param.and_then(|p| self.shorter_string_in_out(&place, p))
                        {
                            after_call.push(cut);
                        }
                    }
                    // a located variable of an elementary type (`lamp AT %QX4.3 : BOOL`,
                    // `count AT %MW10 : INT`), or a bit of one: a variable (IEC 61131-3 ed. 3,
                    // 6.5.5) a VAR_IN_OUT takes (6.6.1.2.2). The process image has no C address
                    // of the variable's type (a bit, a byte-aligned word), so the instance is
                    // given the address of a copy kept for this call site (a C static: the
                    // instance keeps it between calls, as it keeps any in-out's address), the
                    // value copied in before the call and the block's writes copied back into
                    // the process image when it returns (a FUNCTION's likewise, round 32;
                    // before round 33: E2005)
                    Some(place @ (Place::Loc { .. } | Place::Part { .. }))
                        if place.ty().elementary().is_some() =>
                    {
                        let param = match fb {
                            FbType::User(id) => self
                                .pou_var(id, &binding.param)
                                .map(|v| v.ty.clone())
                                .filter(|t| t.elementary().is_some()),
                            FbType::Standard(_) => None,
                        };
                        let t = b.temp();
                        let Some((param, decl)) = param.and_then(|p| {
                            let decl = ctypes::declare(self.model, &p, &t)?;
                            Some((p, decl))
                        }) else {
                            self.unsupported(o.span(), "this argument for an IN_OUT parameter");
                            continue;
                        };
                        let raw = self.fb_param_raw(&lv, fb, &binding.param);
                        let value = self.read_owned(place.clone(), &param);
                        b.line_fmt(format_args!("static {decl};"));
                        b.line_fmt(format_args!("{t} = {value};"));
                        b.line_fmt(format_args!("{raw} = &{t};"));
                        let back = convert(&t, &param, place.ty());
                        after_call.push(self.store(&place, &back));
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
            self.store_line(b, &place, &v);
        }
        if user_eno {
            // TRUE unless the body sets it FALSE (IEC 61131-3: ENO of a block that ran)
            b.line(&format!("{lv}.ENO = 1;"));
        }
        if declared_eno {
            let field = self.fb_param_lvalue(&lv, fb, "ENO");
            b.line(&format!("{field} = 1;"));
        }
        b.line(&invoke(self, &lv, fb));
        for cut in after_call {
            b.line(&cut);
        }
        self.store_outputs(b, &lv, fb, &outputs, args);
        if en.is_some() {
            b.indent -= 1;
            b.line("}");
        }
        let eno = if en.is_some() { "ladderc_en" } else { "1" };
        if stores_eno {
            b.line(&format!("{lv}.ENO = {eno};"));
        }
        let user_eno_value = format!("{lv}.ENO");
        if user_eno && en.is_some() {
            // not called: ENO is FALSE
            b.line(&format!("if (!ladderc_en) {lv}.ENO = 0;"));
        }
        if declared_eno {
            if en.is_some() {
                let field = self.fb_param_lvalue(&lv, fb, "ENO");
                b.line(&format!("if (!ladderc_en) {field} = 0;"));
            }
            self.store_outputs(b, &lv, fb, &eno_output, args);
        }
        if let Some(p) = eno_target {
            self.store_line(b, &p, if user_eno { &user_eno_value } else { eno });
        }
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
            self.store_line(b, &target, &v);
        }
    }

    /// A STRING[n] variable given to an in-out of a longer string type (`VAR_IN_OUT s : STRING`):
    /// CODESYS and TwinCAT accept it (their manuals: the lengths "should" be the same), the callee
    /// writes up to its in-out's length. Every string is stored with the runtime's whole capacity,
    /// so no byte is written past the variable; this statement, run after the call, cuts the
    /// variable back to its own length so that it never holds more than it declares.
    fn shorter_string_in_out(&self, place: &Place, param: &Type) -> Option<String> {
        match (place, param) {
            (
                Place::Mem {
                    lv,
                    ty: Type::String { wide, len },
                },
                Type::String {
                    wide: pw,
                    len: plen,
                },
            ) if wide == pw && len < plen => Some(self.store(place, lv)),
            _ => None,
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
                cfmt!("{lv}.{n}")
            }
            FbType::User(_) => cfmt!("{lv}.{}", mangle::var(param)),
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
            cfmt!("(*{raw})")
        } else {
            raw
        }
    }

    /// `IN tmr`, `CU ctr` ...: stores the current result into the input and invokes the instance.
    pub(super) fn fb_input(
        &mut self,
        b: &mut Body,
        i: &Instruction,
        info: &InstrFacts,
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

    pub(super) fn fb_input_named(
        &mut self,
        b: &mut Body,
        i: &Instruction,
        info: &InstrFacts,
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
            self.unsupported(instance.span, cfmt!("the FB input `{input}`"));
            return;
        };
        let field = self.fb_param_lvalue(&lv, fb, input);
        let v = convert(&cr, &before, &pty);
        self.store_line(b, &Place::Mem { lv: field, ty: pty }, &v);
        if matches!(fb, FbType::User(_)) && self.model.fb_eno_read {
            b.line(&format!("{lv}.ENO = 1;"));
        }
        b.line(&invoke(self, &lv, fb));
        if matches!(fb, FbType::Standard(_)) && self.model.fb_eno_read {
            b.line(&format!("{lv}.ENO = 1;"));
        }
    }

    /// A function called as an operator (standard, conversion or user function).
    pub(super) fn function_call(
        &mut self,
        b: &mut Body,
        i: &Instruction,
        info: &InstrFacts,
        args: &CallArgs,
    ) {
        let span = i.span;
        match info.callee.clone() {
            Some(Callee::Std { name, .. }) if name.starts_with("SPLIT_") => {
                self.split_call(b, info, args, span)
            }
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
                let (en, eno) = self.en_eno(b, args);
                let res = self.gated(en.as_deref(), convert(&res, &result, &after), &after, span);
                if let Some(cr) = self.cr(b, &after, span) {
                    b.line_fmt(format_args!("{cr} = {res};"));
                }
                self.store_eno(b, en.as_deref(), eno);
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
                let (en, eno) = self.en_eno(b, args);
                let res = self.gated(en.as_deref(), convert(&res, &to, &after), &after, span);
                if let Some(cr) = self.cr(b, &after, span) {
                    b.line_fmt(format_args!("{cr} = {res};"));
                }
                self.store_eno(b, en.as_deref(), eno);
            }
            Some(Callee::UserFunction(id)) => self.user_function_call(b, i, info, id, args),
            _ => self.unsupported(span, "this function call"),
        }
    }

    /// Edition 3's `SPLIT_DT(IN := v, YEAR => y, ...)` ...: the parts into a block-scoped array
    /// (`ladderc_split`), each stored into its variable (sema checked that it holds the part's range).
    /// With EN FALSE the function does not run: its outputs are not written.
    fn split_call(&mut self, b: &mut Body, info: &InstrFacts, args: &CallArgs, span: Span) {
        let Some(input) = info
            .args
            .iter()
            .find(|a| !a.output && a.param == "IN")
            .cloned()
        else {
            return;
        };
        let Some(v) = self.arg_value(b, info, args, &input, span) else {
            return;
        };
        let (en, eno) = self.en_eno(b, args);
        b.line("{");
        b.indent += 1;
        if let Some(e) = &en {
            b.line_fmt(format_args!("if ({e}) {{"));
            b.indent += 1;
        }
        let parts = b.temp();
        b.line_fmt(format_args!("IEC_LINT {parts}[7];"));
        b.line_fmt(format_args!("ladderc_split((int64_t)({v}), {parts});"));
        for out in info.args.iter().filter(|a| a.output) {
            let Some(k) = il_frontend::sema::stdlib::SPLIT_PARTS
                .iter()
                .position(|p| p.0 == out.param)
            else {
                continue;
            };
            let ArgSource::Written(w) = out.source else {
                continue;
            };
            let Some((o, _)) = Self::written_arg(args, w) else {
                continue;
            };
            if let Some(target) = self.operand_place(b.scope, o) {
                let val = convert(
                    &cfmt!("{parts}[{k}]"),
                    &Type::Elementary(Elementary::Lint),
                    target.ty(),
                );
                let line = self.store(&target, &val);
                b.line(&line);
            }
        }
        if en.is_some() {
            b.indent -= 1;
            b.line("}");
        }
        b.indent -= 1;
        b.line("}");
        self.store_eno(b, en.as_deref(), eno);
    }

    /// `EN := e` and `ENO => v` of a formal call of a function or conversion: the value of EN
    /// (None: not given, the function runs) and the place of ENO.
    fn en_eno(&mut self, b: &Body, args: &CallArgs) -> (Option<String>, Option<Place>) {
        let CallArgs::Formal(fargs) = args else {
            return (None, None);
        };
        let mut en = None;
        let mut eno = None;
        for fa in fargs {
            match (&fa.dir, &fa.value) {
                (ArgDir::Input, o) if fa.name.is("EN") => {
                    en = self.value(b.scope, o, &Type::BOOL);
                }
                (ArgDir::Output { .. }, Operand::Var(r)) if fa.name.is("ENO") => {
                    eno = self.place(b.scope, r);
                }
                _ => {}
            }
        }
        (en, eno)
    }

    /// IEC 61131-3: a function whose EN is FALSE is not executed and gives its type's initial value
    /// (as matiec does); the standard functions have no side effects, so only the result is chosen.
    fn gated(&mut self, en: Option<&str>, res: String, ty: &Type, span: Span) -> String {
        match en {
            Some(e) => {
                let d = self.default_value(ty, None, span);
                cfmt!("(({e}) ? ({res}) : ({d}))")
            }
            None => res,
        }
    }

    /// ENO is EN (TRUE without EN): a standard function or conversion that runs always completes.
    fn store_eno(&mut self, b: &mut Body, en: Option<&str>, eno: Option<Place>) {
        if let Some(p) = eno {
            self.store_line(b, &p, &cfmt!("((IEC_BOOL)({}))", en.unwrap_or("1")));
        }
    }

    fn user_function_call(
        &mut self,
        b: &mut Body,
        i: &Instruction,
        info: &InstrFacts,
        id: PouId,
        args: &CallArgs,
    ) {
        let span = i.span;
        let pou = self.model.pou(id).clone();
        b.line("{");
        b.indent += 1;
        let mut call_args = Vec::new();
        let mut after_call = Vec::new();
        // EN/ENO the function declares itself (IEC 61131-3 ed.3 6.6.1.6; matiec's
        // add_en_eno_param_decl): its EN input is the enable (the body runs only while it is
        // TRUE, and reads it), its ENO output starts TRUE and is FALSE when the body does not run
        let mut declared_en = None;
        let mut declared_eno = None;
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
                    if v.name.eq_ignore_ascii_case("EN") && v.ty == Type::BOOL {
                        let t = b.temp();
                        b.line_fmt(format_args!("IEC_BOOL {t} = (IEC_BOOL)({val});"));
                        declared_en = Some(t.clone());
                        call_args.push(t);
                        continue;
                    }
                    call_args.push(val);
                }
                VarKind::Output => {
                    let t = b.temp();
                    let Some(decl) = ctypes::declare(self.model, &v.ty, &t) else {
                        continue;
                    };
                    let is_eno = v.name.eq_ignore_ascii_case("ENO") && v.ty == Type::BOOL;
                    let init = if is_eno {
                        "1"
                    } else if v.ty.elementary().is_some() {
                        "0"
                    } else {
                        "{0}"
                    };
                    if is_eno {
                        declared_eno = Some(None);
                    }
                    b.line_fmt(format_args!("{decl} = {init};"));
                    call_args.push(cfmt!("&{t}"));
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
                                    if is_eno {
                                        let off = convert("0", &v.ty, target.ty());
                                        declared_eno = Some(Some(self.store(&target, &off)));
                                    }
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
                        Some(place @ Place::Mem { .. }) => {
                            if let Place::Mem { lv, .. } = &place {
                                call_args.push(cfmt!("&{lv}"));
                            }
                            if let Some(cut) = self.shorter_string_in_out(&place, &v.ty) {
                                after_call.push(cut);
                            }
                        }
                        // a located variable of an elementary type (`counter AT %QW0 : UINT`),
                        // or a bit of one (`x.3`): a variable (IEC 61131-3 ed. 3, 6.5.5) a
                        // VAR_IN_OUT takes (6.6.1.2.2); its value copied in, the function's
                        // writes copied back after the call (the process image has no C
                        // address of the variable's type; before round 32: E2005)
                        Some(place @ (Place::Loc { .. } | Place::Part { .. }))
                            if v.ty.elementary().is_some() && place.ty().elementary().is_some() =>
                        {
                            let t = b.temp();
                            let Some(decl) = ctypes::declare(self.model, &v.ty, &t) else {
                                continue;
                            };
                            let value = self.read_owned(place.clone(), &v.ty);
                            b.line_fmt(format_args!("{decl} = {value};"));
                            call_args.push(cfmt!("&{t}"));
                            let back = convert(&t, &v.ty, place.ty());
                            after_call.push(self.store(&place, &back));
                        }
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
        // EN/ENO (IEC 61131-3 Table 18): with EN FALSE the function is not executed, its result
        // is its type's initial value, its outputs are not written and ENO is FALSE; else ENO is
        // TRUE unless the body resets it
        let (mut en, mut eno_target) = self.en_eno(b, args);
        if declared_en.is_some() {
            en = declared_en;
        }
        if declared_eno.is_some() {
            eno_target = None;
        }
        let eno = b.temp();
        b.line_fmt(format_args!("IEC_BOOL {eno} = 1;"));
        call_args.push(cfmt!("&{eno}"));
        let call = cfmt!("{}({})", mangle::function(&pou.name), call_args.join(", "));
        if let Some(e) = &en {
            b.line_fmt(format_args!("if ({e}) {{"));
            b.indent += 1;
        }
        let mut result = None;
        match (&pou.return_type, info.cr_after.clone()) {
            // an array result: its struct (`F_RET`) copied into the current result's array
            (Some(Type::Array { .. }), Some(after)) => {
                if let Some(cr) = self.cr(b, &after, span) {
                    let t = b.temp();
                    b.line_fmt(format_args!(
                        "{{ {}_RET {t} = {call}; memcpy(&{cr}, &{t}.a, sizeof {cr} < sizeof {t}.a ? sizeof {cr} : sizeof {t}.a); }}",
                        mangle::function(&pou.name)
                    ));
                    result = Some((cr, after));
                }
            }
            (Some(rt), Some(after)) => {
                if let Some(cr) = self.cr(b, &after, span) {
                    let v = convert(&call, rt, &after);
                    b.line_fmt(format_args!("{cr} = {v};"));
                    result = Some((cr, after));
                }
            }
            _ => b.line_fmt(format_args!("{call};")),
        }
        for s in after_call {
            b.line(&s);
        }
        if en.is_some() {
            b.indent -= 1;
            b.line("} else {");
            b.indent += 1;
            if let Some((cr, after)) = result {
                if matches!(after, Type::Array { .. }) {
                    b.line_fmt(format_args!("memset(&{cr}, 0, sizeof {cr});"));
                } else {
                    let d = self.default_value(&after, None, span);
                    b.line_fmt(format_args!("{cr} = {d};"));
                }
            }
            b.line_fmt(format_args!("{eno} = 0;"));
            if let Some(Some(off)) = &declared_eno {
                b.line(off);
            }
            b.indent -= 1;
            b.line("}");
        }
        if let Some(p) = eno_target {
            self.store_line(b, &p, &eno);
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
        if let (
            Type::String { wide, .. },
            Some(il_frontend::sema::ConstValue::String { value, .. }),
        ) = (ty, init)
        {
            return if *wide {
                ctypes::wstring_value(value)
            } else {
                ctypes::string_value(value)
            };
        }
        match ty {
            Type::Elementary(_) | Type::Subrange { .. } | Type::Enum(_) => {
                let base = ctypes::base(self.model, ty).unwrap_or_default();
                cfmt!("(({base})0)")
            }
            Type::String { wide: false, .. } => ctypes::string_value(""),
            Type::String { wide: true, .. } => ctypes::wstring_value(""),
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
            n if super::strings::is_string_function(n, &ty) => {
                self.string_call(span, n, &ty, vals, tys)
            }
            n if super::datetime::is_datetime_function(n) => {
                self.datetime_call(span, n, vals, tys, result)
            }
            "CONCAT_DATE" | "CONCAT_TOD" | "CONCAT_DT" | "CONCAT_LTOD" | "CONCAT_LDT"
            | "DAY_OF_WEEK" => {
                // the long forms count nanoseconds as the short ones do here
                let (n, c) = match name {
                    "CONCAT_DATE" => (3, "concat_date"),
                    "CONCAT_TOD" | "CONCAT_LTOD" => (4, "concat_tod"),
                    "CONCAT_DT" | "CONCAT_LDT" => (7, "concat_dt"),
                    _ => (1, "day_of_week"),
                };
                if vals.len() != n {
                    return None;
                }
                let args: Vec<String> = vals.iter().map(|v| cfmt!("(int64_t)({v})")).collect();
                Some(cfmt!("ladderc_{c}({})", args.join(", ")))
            }
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
                Some(cfmt!("((IEC_BOOL)({}))", parts.join(" & ")))
            }
            "TIME" | "LTIME" if vals.is_empty() => Some("ladderc_now".to_string()),
            "NOT" => Some(negated(vals.first()?, &ty)),
            "MOVE" => vals.first().cloned(),
            "SEL" => {
                if !need(3) {
                    return None;
                }
                Some(cfmt!("(({}) ? ({}) : ({}))", vals[0], vals[2], vals[1]))
            }
            "MUX" => {
                if !need(2) {
                    return None;
                }
                let k = &vals[0];
                // K out of range (an error in IEC 61131-3) selects IN0 and sets the runtime flag
                let mut expr = cfmt!("(ladderc_errors |= LADDERC_ERR_MUX, ({}))", vals[1]);
                for (n, v) in vals.iter().enumerate().skip(1).rev() {
                    expr = cfmt!("(({k}) == {} ? ({v}) : {expr})", n - 1);
                }
                Some(expr)
            }
            "MAX" | "MIN" => {
                let e = e?;
                let h = ctypes::ordered_helper_type(e);
                let ct = ctypes::elementary(e);
                let f = name.to_ascii_lowercase();
                let mut acc = cfmt!("(({h})({}))", vals.first()?);
                for v in &vals[1..] {
                    acc = cfmt!("ladderc_{f}_{h}({acc}, ({h})({v}))");
                }
                Some(cfmt!("(({ct}){acc})"))
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
                Some(cfmt!(
                    "(({ct})ladderc_limit_{h}(({h})({}), ({h})({}), ({h})({})))",
                    vals[0],
                    vals[1],
                    vals[2]
                ))
            }
            "TO_BIG_ENDIAN" | "TO_LITTLE_ENDIAN" | "FROM_BIG_ENDIAN" | "FROM_LITTLE_ENDIAN" => {
                let e = e?;
                let v = vals.first()?;
                let n = e.size_bytes();
                if e == E::Bool || n <= 1 {
                    return Some(v.clone());
                }
                let f = if name.starts_with("TO_") {
                    "to"
                } else {
                    "from"
                };
                let big = u8::from(name.contains("BIG"));
                let ct = ctypes::elementary(e);
                Some(match e {
                    E::Real => cfmt!(
                        "ladderc_bits_to_real((uint32_t)ladderc_{f}_endian(ladderc_real_to_bits({v}), 4, {big}))"
                    ),
                    E::Lreal => cfmt!(
                        "ladderc_bits_to_lreal(ladderc_{f}_endian(ladderc_lreal_to_bits({v}), 8, {big}))"
                    ),
                    _ => cfmt!("(({ct})ladderc_{f}_endian((uint64_t)({v}), {n}, {big}))"),
                })
            }
            "ABS" => {
                let e = e?;
                let v = vals.first()?;
                Some(match e {
                    E::Real => cfmt!("((IEC_REAL)fabsf({v}))"),
                    E::Lreal => cfmt!("((IEC_LREAL)fabs({v}))"),
                    _ if e.is_signed_integer() => {
                        let ct = ctypes::elementary(e);
                        cfmt!("ladderc_abs_{ct}({v})")
                    }
                    _ => v.clone(),
                })
            }
            // edition 3
            "IS_VALID" => Some(cfmt!("((IEC_BOOL)(isfinite({}) != 0))", vals.first()?)),
            "IS_VALID_BCD" => Some(cfmt!("ladderc_is_valid_bcd((uint64_t)({}))", vals.first()?)),
            "SQRT" | "LN" | "LOG" | "EXP" | "SIN" | "COS" | "TAN" | "ASIN" | "ACOS" | "ATAN" => {
                let e = e?;
                let f = match name {
                    "LN" => "log",
                    "LOG" => "log10",
                    n => &n.to_ascii_lowercase(),
                };
                let v = vals.first()?;
                // REAL: the double function rounded once to REAL, the correctly rounded result for
                // practically every argument (the float functions, sinf ..., may be 1 ulp off)
                Some(if e == E::Real {
                    cfmt!("((IEC_REAL){f}((double)({v})))")
                } else {
                    cfmt!("((IEC_LREAL){f}({v}))")
                })
            }
            "EXPT" => {
                if !need(2) {
                    return None;
                }
                let ct = ctypes::base(self.model, result)?;
                Some(cfmt!(
                    "(({ct})pow((double)({}), (double)({})))",
                    vals[0],
                    vals[1]
                ))
            }
            "SHL" | "SHR" | "ROL" | "ROR" => {
                if !need(2) {
                    return None;
                }
                let e = e?;
                // a BOOL, the bit string of one bit (IEC 61131-3 ed. 3 Table 24: IN is ANY_BIT,
                // BOOL among them, 6.4.2): a rotation by any N gives IN back; a shift by N >= 1
                // moves the bit out, FALSE; N <= 0 leaves IN, as for the wider strings (the
                // runtime's shifts; before round 32: E2005)
                if e == E::Bool {
                    let (v, n) = (&vals[0], &vals[1]);
                    return Some(if matches!(name, "ROL" | "ROR") {
                        cfmt!("((IEC_BOOL)((void)({n}), ({v})))")
                    } else {
                        cfmt!("((IEC_BOOL)((int64_t)({n}) >= 1 ? 0 : ({v})))")
                    });
                }
                // an integer (CODESYS, TwinCAT; W1438) shifts its bit pattern of the same width,
                // zero fill: a signed value goes through its unsigned bits (no C shift of a
                // negative value) and back (two's complement)
                let h = match e {
                    E::Byte | E::Usint | E::Sint => "IEC_BYTE",
                    E::Word | E::Uint | E::Int => "IEC_WORD",
                    E::Dword | E::Udint | E::Dint => "IEC_DWORD",
                    E::Lword | E::Ulint | E::Lint => "IEC_LWORD",
                    _ => {
                        self.unsupported(span, cfmt!("{name} on this type"));
                        return None;
                    }
                };
                let ct = ctypes::elementary(e);
                let f = name.to_ascii_lowercase();
                Some(cfmt!(
                    "(({ct})ladderc_{f}_{h}(({h})({}), (int64_t)({})))",
                    vals[0],
                    vals[1]
                ))
            }
            other => {
                self.unsupported(span, cfmt!("the standard function {other}"));
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
        // WSTRING goes through STRING (UTF-8 text; runtime `ladderc_wstr_of_str`/`ladderc_str_of_wstr`).
        let narrow = |v: &str| cfmt!("ladderc_str_of_wstr({v})");
        let widen = |v: String| cfmt!("ladderc_wstr_of_str({v})");
        let (f, t) = match (from.elementary(), to.elementary()) {
            (Some(f), Some(t)) => (f, t),
            // an enumerated value (CODESYS/TwinCAT `TO_INT(eState)`, `TO_STRING(eState)`): its
            // number, held as a DINT; its name for `TO_STRING` under `{attribute 'to_string'}`
            (None, _) if matches!(from, Type::Enum(_)) => {
                let Type::Enum(id) = from else { return None };
                if let Some(t) = to.elementary() {
                    return Some(convert_elementary(v, E::Dint, t));
                }
                let ut = self.model.user_type(*id);
                let text = match &ut.def {
                    il_frontend::sema::model::UserTypeDef::Enum { values, .. } if ut.to_string => {
                        // a value outside the enumeration (written through a pointer or a
                        // located variable) gives its number, as a non-attributed one would
                        let mut e = cfmt!(
                            "ladderc_str_of({}, &({}){{(int32_t)({v})}})",
                            ctypes::type_tag(E::Dint),
                            ctypes::elementary(E::Dint)
                        );
                        for (name, n) in values.iter().rev() {
                            e = cfmt!("(({v}) == {n} ? {} : {e})", ctypes::string_value(name));
                        }
                        e
                    }
                    _ => cfmt!(
                        "ladderc_str_of({}, &({}){{(int32_t)({v})}})",
                        ctypes::type_tag(E::Dint),
                        ctypes::elementary(E::Dint)
                    ),
                };
                return Some(if matches!(to, Type::String { wide: true, .. }) {
                    widen(text)
                } else {
                    text
                });
            }
            // edition 3: a character to the one-character string; WCHAR to WSTRING keeps its
            // code (not through STRING)
            (Some(f @ (E::Char | E::Wchar)), None) if to.is_string() && !to.is_error() => {
                let wide_to = matches!(to, Type::String { wide: true, .. });
                return Some(match (f, wide_to) {
                    (E::Char, false) => cfmt!("ladderc_char_to_str({v})"),
                    (E::Char, true) => cfmt!("ladderc_wchar_to_wstr((IEC_WCHAR)({v}))"),
                    (_, false) => cfmt!("ladderc_char_to_str(ladderc_wchar_to_char({v}))"),
                    (_, true) => cfmt!("ladderc_wchar_to_wstr({v})"),
                });
            }
            // edition 3: a string to its first character (NUL of an empty string)
            (None, Some(t @ (E::Char | E::Wchar))) if from.is_string() && !from.is_error() => {
                let wide_from = matches!(from, Type::String { wide: true, .. });
                return Some(match (wide_from, t) {
                    (false, E::Char) => cfmt!("ladderc_str_first({v})"),
                    (false, _) => cfmt!("((IEC_WCHAR)ladderc_str_first({v}))"),
                    (true, E::Char) => cfmt!("ladderc_wchar_to_char(ladderc_wstr_first({v}))"),
                    (true, _) => cfmt!("ladderc_wstr_first({v})"),
                });
            }
            (Some(f), None) if to.is_string() && !to.is_error() => {
                let ct = ctypes::elementary(f);
                let text = cfmt!("ladderc_str_of({}, &({ct}){{{v}}})", ctypes::type_tag(f));
                return Some(if matches!(to, Type::String { wide: true, .. }) {
                    widen(text)
                } else {
                    text
                });
            }
            (None, Some(t)) if from.is_string() && !from.is_error() => {
                let s = if matches!(from, Type::String { wide: true, .. }) {
                    narrow(v)
                } else {
                    v.to_string()
                };
                let v = s.as_str();
                return Some(match t {
                    E::Bool => cfmt!("ladderc_str_to_bool({v})"),
                    E::Real | E::Lreal => {
                        cfmt!("(({})ladderc_str_to_real({v}))", ctypes::elementary(t))
                    }
                    E::Time | E::Ltime => cfmt!("ladderc_str_to_time({v})"),
                    _ if t.is_signed_integer() => {
                        convert_elementary(&cfmt!("ladderc_str_to_int({v})"), E::Lint, t)
                    }
                    _ if t.is_integer() || t.is_bit() => {
                        convert_elementary(&cfmt!("ladderc_str_to_uint({v})"), E::Ulint, t)
                    }
                    _ if t.is_date() => super::strings::string_to_datetime(v, t),
                    _ => {
                        self.unsupported(span, "converting a STRING to a date or time of day");
                        return None;
                    }
                });
            }
            (None, None) if from.is_string() && to.is_string() && !to.is_error() => {
                let fw = matches!(from, Type::String { wide: true, .. });
                let tw = matches!(to, Type::String { wide: true, .. });
                return Some(match (fw, tw) {
                    (false, true) => widen(v.to_string()),
                    (true, false) => narrow(v),
                    _ => convert(v, from, to),
                });
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
                    real_to_int(&cfmt!("trunc((double)({v}))"), t)
                } else {
                    convert_elementary(v, f, t)
                }
            }
            ConversionKind::FromBcd => {
                convert_elementary(&cfmt!("ladderc_bcd_to_uint((uint64_t)({v}))"), E::Ulint, t)
            }
            ConversionKind::ToBcd => {
                let src = if f.is_signed_integer() {
                    cfmt!("(({v}) < 0 ? (ladderc_errors |= LADDERC_ERR_RANGE, (uint64_t)0) : (uint64_t)({v}))")
                } else {
                    cfmt!("(uint64_t)({v})")
                };
                convert_elementary(
                    &cfmt!("ladderc_uint_to_bcd({src}, {})", t.bit_width()),
                    E::Ulint,
                    t,
                )
            }
        })
    }
}

/// The call of an FB instance's body.
fn invoke(g: &Gen, lv: &str, fb: FbType) -> String {
    match fb {
        FbType::Standard(f) => cfmt!("{}_body(&{lv});", ctypes::std_fb(f).0),
        FbType::User(id) => {
            let p = g.model.pou(id);
            let s = if p.kind == il_frontend::ast::PouKind::Program {
                mangle::program(&p.name)
            } else {
                mangle::fb(&p.name)
            };
            cfmt!("{s}_BODY(&{lv});")
        }
    }
}
