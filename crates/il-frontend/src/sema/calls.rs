//! Calls inside a body: standard functions (generic instantiation), conversions, user functions, FB calls
//! (`CAL`), FB input operators (`S1`, `PT`, `IN` ... and `S`/`R` with an instance operand).
//!
//! Input: the call instructions and the current result. Output: the callee and argument bindings in the
//! instruction's record, the new current result, diagnostics. Invariants: in the IL operator form the
//! current result is the first input; a formal call (or `CAL` of a function) does not read it and
//! replaces it with the result; all generic inputs of one call share one type (the common type they
//! widen to); an unknown callee is reported once and its arguments are still name-checked.

use super::body::{Body, Rec, State, Ty};
use super::model::*;
use super::places::{conversion_hint, fb_param_list, ParamDir};
use super::stdlib::{self, bcd_of_width, Class, ConvTarget, ParamTy, Ret, StdFunction};
use super::typing::common_type;
use crate::ast::{self, ArgDir, CallArgs, Condition, Operand, PouKind, VarKind, VarRef};
use crate::Span;
use diagnostics::code;

/// The smallest real an integer of type `t` converts to implicitly (IEC 61131-3 ed. 3, Figure 11:
/// SINT, INT, USINT, UINT to REAL; DINT, UDINT to LREAL); `None` for LINT, ULINT and non-integers.
fn implicit_real(t: &Type) -> Option<Type> {
    let e = t.elementary().filter(|e| e.is_integer())?;
    [Elementary::Real, Elementary::Lreal]
        .into_iter()
        .find(|r| super::typing::widens(e, *r))
        .map(Type::Elementary)
}

/// A generic instantiation: the overload's name, the generic type, the result type.
pub(super) struct Inst {
    pub(super) name: &'static str,
    pub(super) t: Ty,
    pub(super) result: Ty,
}

impl Body<'_, '_> {
    /// Instantiates a standard function for its inputs `args` (type and where it comes from).
    pub(super) fn instantiate(&mut self, f: &StdFunction, args: &[(Ty, Span)], at: Span) -> Inst {
        let fixed_result = |t: Ty| match f.result {
            Ret::T => t,
            Ret::Fixed(e) => Ty::Known(Type::Elementary(e)),
        };
        // Time and date arithmetic.
        if f.time_arith {
            if let Some(Ty::Known(first)) = args.first().map(|a| self.norm(&a.0)) {
                if let Some(e) = first
                    .elementary()
                    .filter(|e| e.is_duration() || e.is_date())
                {
                    return self.time_arith(f, e, args, at);
                }
            }
        }
        if let Some(inst) = self.pointer_step(f, args) {
            return inst;
        }
        let mut known: Vec<(Type, Span)> = Vec::new();
        // the bit strings counted as unsigned integers: (index in `known`, the bit string, where)
        let mut counted: Vec<(usize, Elementary, Span)> = Vec::new();
        let mut lit_args: Vec<(usize, Span)> = Vec::new();
        let mut error = false;
        let mut class = Class::Any;
        // a comparison of a bit string with a number (`udint = word`): the bit string counts as
        // its unsigned integer, as in arithmetic and in a store (W1436); between bit strings only
        // (`w1 = w2`, `d = w`) it stays a bit string
        let compares_number = super::bit_arith::is_comparison(f.name)
            && args.iter().any(|(ty, _)| match self.norm(ty) {
                Ty::Known(t) => t.is_numeric(),
                Ty::Lit(_) => false,
            });
        for (i, (ty, span)) in args.iter().enumerate() {
            match f.param_ty(i) {
                Some(ParamTy::T(c)) => {
                    class = c;
                    match self.norm(ty) {
                        Ty::Known(Type::Error) => error = true,
                        // CODESYS, TwinCAT: a bit string in arithmetic counts as its unsigned
                        // integer (W1436)
                        Ty::Known(Type::Elementary(e))
                            if (super::bit_arith::is_arithmetic(c) || compares_number)
                                && super::bit_arith::counted_as(e).is_some() =>
                        {
                            let u = super::bit_arith::counted_as(e).unwrap_or(e);
                            counted.push((known.len(), e, *span));
                            known.push((Type::Elementary(u), *span))
                        }
                        // IEC 61131-3 (ed. 3, Figure 11): an integer given to an ANY_REAL input
                        // converts implicitly to the real it widens to (`SQRT(n)` of an INT)
                        Ty::Known(t) if c == Class::AnyReal => {
                            known.push((implicit_real(&t).unwrap_or(t), *span))
                        }
                        // IEC 61131-3 (ed. 3, 6.4.4.2): a subrange value takes part in an
                        // operation as its base type, so a literal beside it (`n * 5` of a
                        // UINT(1..4)) is a UINT, not a value of the subrange; MOVE, SEL and MUX
                        // (ANY) keep the subrange
                        Ty::Known(Type::Subrange { base, .. }) if c != Class::Any => {
                            known.push((Type::Elementary(base), *span))
                        }
                        Ty::Known(t) => known.push((t, *span)),
                        Ty::Lit(v) => lit_args.push((v, *span)),
                    }
                }
                Some(ParamTy::Own(c)) => {
                    let n = self.norm(ty);
                    let ok = match &n {
                        Ty::Known(t) => super::refs::class_admits(f.name, c, t),
                        Ty::Lit(v) => {
                            if self.lits.is_real(*v) {
                                c.accepts_real_literal()
                            } else {
                                c.accepts_int_literal()
                            }
                        }
                    };
                    if !ok {
                        let d = self.describe(&n);
                        self.a
                            .error(
                                code::E1004,
                                *span,
                                format!(
                                    "input {} of {} must be {}, not {d}",
                                    f.param_name(i),
                                    f.name,
                                    c.name()
                                ),
                            )
                            .label(format!("this is {d}"))
                            .hint(format!("pass a value of class {}", c.name()));
                    }
                }
                Some(ParamTy::Fixed(e)) => {
                    let pname = f.param_name(i);
                    let want = Type::Elementary(e);
                    self.coerce(ty, &want, *span, |b, from, to| {
                        b.a.error(
                            code::E1012,
                            *span,
                            format!("input {pname} of {} must be {to}, not {from}", f.name),
                        )
                        .label(format!("this is {from}"))
                        .hint(conversion_hint(from, to));
                    });
                }
                None => {}
            }
        }
        if error {
            return Inst {
                name: f.name,
                t: Ty::ERROR,
                result: fixed_result(Ty::ERROR),
            };
        }
        // CODESYS, TwinCAT: an enumeration without {attribute 'strict'} beside an integer (or an
        // integer literal) counts as its number: an INT, CODESYS's base type, or a DINT where a
        // value does not fit INT (W1439)
        // (beside a bit string, as that bit string: `nFlags AND E_State.eA`, `d = eFlags` of a
        // DWORD `d`)
        // (beside another integer or a real, as that type when it holds every value: `u = E.a`
        // of a UINT `u`, `r = E.a` of an LREAL `r`; a bit string first, then a real, then the
        // widest integer)
        let beside = known
            .iter()
            .filter_map(|k| k.0.elementary())
            .filter(|e| (e.is_bit() && *e != Elementary::Bool) || e.is_integer() || e.is_real())
            .max_by_key(|e| {
                let rank = if e.is_bit() {
                    2
                } else {
                    u32::from(e.is_real())
                };
                (rank, e.size_bytes())
            });
        // (a strict enumeration only compared with a number that holds its values: `strict`
        // forbids arithmetic and storing into the enumeration, not comparing, Infosys
        // "Attribute 'strict'")
        let compared = super::bit_arith::is_comparison(f.name);
        let counts_as_number = |t: &Type| {
            super::loose_enum::is_loose(&self.a.model, t)
                || (compared
                    && beside.is_some_and(|b| {
                        super::loose_enum::type_beside(&self.a.model, t, b, true).is_some()
                    }))
        };
        if matches!(
            class,
            Class::Any | Class::AnyElementary | Class::AnyNum | Class::AnyInt | Class::AnyBit
        ) && known.iter().any(|k| counts_as_number(&k.0))
            && (known.iter().any(|k| k.0.is_integer())
                || beside.is_some()
                || lit_args.iter().any(|(v, _)| !self.lits.is_real(*v)))
        {
            let mut first = None;
            for (t, span) in known.iter_mut() {
                let beside_type = beside
                    .and_then(|b| super::loose_enum::type_beside(&self.a.model, t, b, compared));
                if let Some(b) = beside_type {
                    first.get_or_insert((t.clone(), *span));
                    *t = b;
                } else if super::loose_enum::is_loose(&self.a.model, t) {
                    first.get_or_insert((t.clone(), *span));
                    *t = super::loose_enum::number_type(&self.a.model, t);
                }
            }
            if let Some((t, span)) = first {
                self.enum_as_integer(&t, span);
            }
        }
        // W1436 when counting the bit strings as unsigned integers gives the inputs a common
        // type; otherwise they are reported as written
        if !counted.is_empty() {
            let types: Vec<Type> = known.iter().map(|k| k.0.clone()).collect();
            if common_type(&types).is_some() {
                for (_, e, span) in &counted {
                    self.bit_string_counted(*e, *span);
                }
            } else {
                for (k, e, _) in &counted {
                    known[*k].0 = Type::Elementary(*e);
                }
            }
        }
        if class == Class::AnyBit {
            super::bit_arith::bits_beside_integer(&mut known);
        }
        let t = if !known.is_empty() {
            // all of one type (the usual case): that is the common type, without a list of copies
            let same = known.iter().all(|k| k.0 == known[0].0);
            let common = if same {
                common_type(std::slice::from_ref(&known[0].0))
            } else {
                let types: Vec<Type> = known.iter().map(|k| k.0.clone()).collect();
                common_type(&types)
            };
            match common {
                Some(t) => {
                    // CODESYS, TwinCAT: AND, OR, XOR, NOT and the shifts of an integer work on its
                    // bit pattern (W1438)
                    let int_bits = class == Class::AnyBit
                        && t.elementary().and_then(super::bit_arith::bits_of).is_some();
                    if int_bits {
                        if let Some(e) = t.elementary() {
                            let span = known.first().map_or(at, |k| k.1);
                            self.integer_as_bits(f.name, e, span);
                        }
                    }
                    if !int_bits && !super::refs::class_admits(f.name, class, &t) {
                        let tn = self.a.type_name(&t);
                        let span = known
                            .iter()
                            .find(|k| !super::refs::class_admits(f.name, class, &k.0))
                            .map_or(at, |k| k.1);
                        if matches!(t, Type::Ref(_)) {
                            self.pointer_arithmetic(f.name, &tn, span);
                            return Inst {
                                name: f.name,
                                t: Ty::ERROR,
                                result: fixed_result(Ty::ERROR),
                            };
                        }
                        self.a
                            .error(
                                code::E1004,
                                span,
                                format!("{} is not defined for {tn}", f.name),
                            )
                            .label(format!("this is {tn}"))
                            .hint(format!(
                                "{} needs {}; convert the value first",
                                f.name,
                                class.name()
                            ));
                        return Inst {
                            name: f.name,
                            t: Ty::ERROR,
                            result: fixed_result(Ty::ERROR),
                        };
                    }
                    let t = string_generic(f, t, &known);
                    // IEC 61131-3 (3rd edition, implicit conversions): an integer operand beside a
                    // real literal widens to the smallest real type it converts to implicitly (INT
                    // to REAL, DINT to LREAL), as it does beside a real variable (`1.0 / n`)
                    let t = if t.is_integer()
                        && class.accepts_real_literal()
                        && lit_args.iter().any(|(v, _)| self.lits.is_real(*v))
                    {
                        [Type::REAL, Type::LREAL]
                            .into_iter()
                            .find(|r| common_type(&[t.clone(), r.clone()]).as_ref() == Some(r))
                            .unwrap_or(t)
                    } else {
                        t
                    };
                    for (v, span) in &lit_args {
                        let name = f.name;
                        self.coerce(&Ty::Lit(*v), &t, *span, |b, from, to| {
                            b.a.error(code::E1005, *span, format!("{name} of {to} with {from}"))
                                .label(format!("this is {from}"))
                                .hint(format!("use a {to} value"));
                        });
                    }
                    Ty::Known(t)
                }
                None => {
                    let (a, sa) = known[0].clone();
                    let (b, sb) = known
                        .iter()
                        .find(|k| common_type(&[a.clone(), k.0.clone()]).is_none())
                        .cloned()
                        .unwrap_or_else(|| known[known.len() - 1].clone());
                    let (an, bn) = (self.a.type_name(&a), self.a.type_name(&b));
                    // an operator's operands: IL's current result (`LD u` / `EQ w`) is the
                    // left operand of ST's `u = w`, the words of both languages
                    let (first, second, first_label) = if sa == at {
                        (
                            "the left one",
                            "the right operand",
                            "the left operand (IL: the current result)",
                        )
                    } else {
                        ("the first input", "this input", "the first input")
                    };
                    self.a
                        .error(
                            code::E1005,
                            sb,
                            format!(
                                "{} of {an} and {bn}: {second} does not match {first}",
                                f.name
                            ),
                        )
                        .label(format!("this is {bn}"))
                        .also(sa, format!("{first_label} is {an}"))
                        .hint(match holding_both(&a, &b) {
                            // `i < u` of an INT and a UDINT: UDINT_TO_INT would change the outcome
                            // of a large u, INT_TO_UDINT that of a negative i
                            Some(c) => format!(
                                "convert both to {c}, which holds every value of each ({an}_TO_{c}, {bn}_TO_{c})"
                            ),
                            None => format!(
                                "convert one side explicitly ({})",
                                conversion_hint(&bn, &an)
                                    .trim_start_matches("convert explicitly with ")
                            ),
                        });
                    return Inst {
                        name: f.name,
                        t: Ty::ERROR,
                        result: fixed_result(Ty::ERROR),
                    };
                }
            }
        } else if let Some((first, span)) = lit_args.first().cloned() {
            let mut root = first;
            for (v, _) in &lit_args[1..] {
                root = self.lits.unify(root, *v);
            }
            let real = self.lits.is_real(root);
            if let Some(t) = self.typed_generic.clone() {
                // a typed name: typed_call binds the literals to its type (or reports E1410/E1017)
                let _ = t;
                Ty::Lit(root)
            } else if class == Class::AnyReal && !real {
                // an integer literal is no ANY_REAL value: read leniently as LREAL (`SQRT(2)`);
                // a real literal stays untyped, so the context types it (`r := SQRT(2.0)` with
                // `r : REAL` computes in REAL), LREAL where nothing does
                let _ = self.lits.bind(root, &Type::LREAL);
                Ty::Known(Type::LREAL)
            } else if real && !class.accepts_real_literal() {
                self.a
                    .error(
                        code::E1004,
                        span,
                        format!("{} is not defined for real numbers", f.name),
                    )
                    .label("a real literal")
                    .hint(format!("{} needs {}", f.name, class.name()));
                Ty::ERROR
            } else {
                Ty::Lit(root)
            }
        } else {
            Ty::ERROR
        };
        Inst {
            name: f.name,
            t: t.clone(),
            result: fixed_result(t),
        }
    }

    fn time_arith(
        &mut self,
        f: &StdFunction,
        e: Elementary,
        args: &[(Ty, Span)],
        at: Span,
    ) -> Inst {
        let second = args.get(1).cloned();
        let overloads: Vec<_> = stdlib::time_overloads(f.name, e).cloned().collect();
        let err = Inst {
            name: f.name,
            t: Ty::ERROR,
            result: Ty::ERROR,
        };
        if overloads.is_empty() {
            self.a
                .error(code::E1004, at, format!("{} is not defined for {}", f.name, e.name()))
                .label(format!("this is {}", e.name()))
                .hint("time arithmetic: ADD/SUB of durations, TOD/DT +- TIME, SUB of two dates, MUL/DIV of a duration by a number");
            return err;
        }
        let Some((ty2, span2)) = second else {
            return err;
        };
        let n2 = self.norm(&ty2);
        if n2.is_error() {
            return err;
        }
        for (name, _, _, in2, out) in &overloads {
            let fits = match (in2, &n2) {
                (Some(t2), Ty::Known(k)) => k.elementary() == Some(*t2),
                (Some(_), Ty::Lit(_)) => false,
                (None, Ty::Known(k)) => k.is_numeric(),
                (None, Ty::Lit(_)) => true,
            };
            if fits {
                return Inst {
                    name,
                    t: Ty::Known(Type::Elementary(e)),
                    result: Ty::Known(Type::Elementary(*out)),
                };
            }
        }
        let d = self.describe(&n2);
        let allowed: Vec<String> = overloads
            .iter()
            .map(|o| o.3.map_or("a number".to_string(), |t| t.name().to_string()))
            .collect();
        self.a
            .error(
                code::E1005,
                span2,
                format!("{} of {} with {d}", f.name, e.name()),
            )
            .label(format!("this is {d}"))
            .also(at, format!("the current result is {}", e.name()))
            .hint(format!(
                "{} of {} takes {}",
                f.name,
                e.name(),
                allowed.join(" or ")
            ));
        err
    }

    /// A function call instruction (`SEL x, y`, `LIMIT(MN := 0, ...)`, or `CAL` of a function).
    pub(super) fn function_call(
        &mut self,
        span: Span,
        name: &ast::Ident,
        args: &CallArgs,
        via_cal: bool,
        st: &mut State,
        rec: &mut Rec,
    ) {
        self.duplicate_formals(args);
        let formal = via_cal || matches!(args, CallArgs::Formal(_));
        let user_fn = self
            .a
            .pou_names
            .get(&name.key())
            .copied()
            .filter(|id| self.a.model.pous[id.0 as usize].kind == PouKind::Function);
        if let Some(f) = stdlib::split(&name.name).filter(|_| user_fn.is_none()) {
            // a function with outputs and no result: nothing is left for the current result
            self.split_call(span, f, args, rec);
            if formal {
                self.load(st, Ty::Known(Type::Error), span);
            }
            st.cr.ty = None;
            st.cr.fresh = None;
            return;
        }
        let result = if let Some(conv) = stdlib::conversion(&name.name) {
            self.conversion_call(span, name, conv, args, formal, st, rec)
        } else if let Some(f) = stdlib::function(&name.name).filter(|f| {
            user_fn.is_none()
                || (f.name.eq_ignore_ascii_case(&name.name) && !stdlib::edition3_only(f.name))
        }) {
            // a user FUNCTION named like a typed name (`MAX_REAL`) or `MULTIME` is the user's, and
            // so is one named like a function edition 3 added (OSCAT's `DAY_OF_WEEK(IDATE :
            // UDINT)`, written for edition 2, as matiec reads it); one named like an edition 2
            // function (`LIMIT`) is the standard one, as matiec calls it
            self.typed_generic = stdlib::typed_name(&name.name).map(|(_, t)| t);
            let result = self.std_call(span, f, args, formal, st, rec);
            self.typed_generic = None;
            match stdlib::typed_name(&name.name) {
                Some((_, t)) => self.typed_call(span, name, t, rec, result),
                _ => result,
            }
        } else if let Some(id) = user_fn {
            let result = self.user_call(span, id, args, formal, st, rec);
            if self.a.model.pous[id.0 as usize].return_type.is_none() {
                // a FUNCTION without result type leaves no value: a read of the current result
                // after it is E1007, nothing is left unused (W1001)
                if formal {
                    self.load(st, result, span);
                }
                st.cr.ty = None;
                st.cr.fresh = None;
                return;
            }
            result
        } else {
            let is_fb = self.a.pou_names.contains_key(&name.key())
                || self.pou().var(&name.name).is_some_and(|v| v.ty.is_fb());
            if is_fb {
                self.a
                    .error(
                        code::E1018,
                        name.span,
                        format!("`{}` is not a function", name.name),
                    )
                    .label("a function block, program or FB instance")
                    .hint("call FB instances with CAL inst(...)");
            } else if name.is("SIZEOF") {
                // CODESYS/TwinCAT: sizes in bytes; ST reads `SIZEOF(x)` (`Operand::SizeOf`), IL's
                // `LD x` + `SIZEOF` is folded into `LD SIZEOF(x)` by `crate::il_sizeof`; any other
                // IL call of it (after a value, not a loaded variable) is refused
                self.a
                    .error(code::E1019, name.span, "`SIZEOF` in IL must follow `LD` of a variable")
                    .label("a CODESYS/TwinCAT operator on a variable")
                    .hint("load the variable right before it: `LD arr1` then `SIZEOF` (the bytes of a value are not defined)");
                st.cr.fresh = None;
                st.cr.ty = Some(Ty::ERROR);
                return;
            } else if name.is("__NEW") || name.is("__DELETE") {
                // CODESYS/TwinCAT dynamic memory (an IL call; ST's are E0351 once per file,
                // `st::lower::dynamic_memory`): one error, the argument (a type name for `__NEW`)
                // not looked up as a variable
                self.a
                    .error(
                        code::E0351,
                        name.span,
                        format!(
                            "`{}`: ladderc has no dynamic memory (no heap) to create or free variables at run time",
                            name.name
                        ),
                    )
                    .label("a CODESYS/TwinCAT operator")
                    .hint("declare the variable (or an array of them) instead: every variable of a ladderc program exists before the first scan");
                st.cr.fresh = None;
                st.cr.ty = Some(Ty::ERROR);
                return;
            } else if let Some(Type::Fb(_)) = self.a.model.type_named(&name.name) {
                // `TON T1, T#5s` (a simulator's IL): a block type called as a function
                self.a
                    .error(
                        code::E1019,
                        name.span,
                        format!("`{}` is a function block type, not a function", name.name),
                    )
                    .label("called as a function")
                    .hint(format!(
                        "declare an instance (`T1 : {};`) and call it with its inputs: `CAL T1(...)` in IL, `T1(...);` in ST",
                        name.name
                    ));
            } else if self.a.silent
                || self.a.internal_accessed.insert((
                    self.pou.0,
                    format!("unknown function {}", name.key()),
                    String::new(),
                )) && self.a.internal_accessed.insert((
                    self.pou.0,
                    format!("undeclared {}", name.key()),
                    String::new(),
                ))
            {
                // one E1019 per POU and name, at its first call (as an undeclared name's E1001):
                // a missing library function called 100 times is one cause. A name already
                // reported undeclared in this POU (`fbAxis.Enable := TRUE;` then `fbAxis();`: an
                // instance whose declaration is missing) is not reported again as a function, and
                // after this error its other uses (`fbAxis.Done`) are not reported as undeclared
                self.a
                    .error(code::E1019, name.span, format!("unknown function `{}`", name.name))
                    .label("no such function")
                    .hint("use an IEC standard function, a conversion X_TO_Y, or declare the FUNCTION (its other calls in this POU are not reported)");
            }
            self.args_unchecked(args);
            st.cr.fresh = None;
            Ty::ERROR
        };
        if formal {
            self.load(st, result, span);
        } else {
            st.cr.ty = Some(result);
            st.cr.fresh = Some(span);
        }
    }

    /// `SPLIT_DT(IN := dt, YEAR => y, ...)` (edition 3, Table 36): `IN` and EN like a function's
    /// inputs, ENO like its output; each part goes to an ANY_INT variable wide enough for every value
    /// of the part (E1012 otherwise); only a formal call gives outputs (E1062).
    fn split_call(
        &mut self,
        span: Span,
        f: &'static stdlib::Split,
        args: &CallArgs,
        rec: &mut Rec,
    ) {
        rec.callee = Some(Callee::Std {
            name: f.name,
            ty: Type::Elementary(f.input),
            result: Type::Error,
        });
        let CallArgs::Formal(fargs) = args else {
            self.a
                .error(
                    code::E1062,
                    span,
                    format!(
                        "{} gives its parts as outputs: it needs a formal call",
                        f.name
                    ),
                )
                .label("no formal outputs")
                .hint(format!(
                    "write {}(IN := value, {} => variable, ...)",
                    f.name, f.outputs[0]
                ));
            self.args_unchecked(args);
            return;
        };
        let mut params: Vec<(String, ParamDir, Type)> =
            vec![("IN".into(), ParamDir::Input, Type::Elementary(f.input))];
        params.extend(
            f.outputs
                .iter()
                .map(|o| (o.to_string(), ParamDir::Output, Type::Error)),
        );
        let mut given_in = false;
        for (k, fa) in fargs.iter().enumerate() {
            let part = f.outputs.iter().find(|o| fa.name.is(o));
            let (Some(part), ArgDir::Output { negated }) = (part, fa.dir) else {
                given_in |= fa.name.is("IN");
                self.formal_arg(k, fa, f.name, &params, rec);
                continue;
            };
            let target = self.write_place(&fa.value, "=>");
            let (_, lo, hi) = stdlib::SPLIT_PARTS
                .iter()
                .find(|p| p.0 == *part)
                .copied()
                .unwrap_or(("", 0, 0));
            let fits = match &target {
                Type::Elementary(e) => e
                    .int_range()
                    .is_some_and(|(l, h)| e.is_integer() && l <= lo && hi <= h),
                t => t.is_error(),
            };
            if negated || !fits {
                let to = self.a.type_name(&target);
                let why = if negated {
                    format!("NOT {part}: {part} of {} is not BOOL", f.name)
                } else {
                    format!(
                        "output {part} of {} ({lo}..{hi}) cannot be stored into {to}",
                        f.name
                    )
                };
                self.a
                    .error(code::E1012, fa.value.span(), why)
                    .label(format!("this is {to}"))
                    .hint("receive each part in an integer variable (ANY_INT) that holds its range: INT, UINT or wider for YEAR and MILLISECOND, any for the others");
                continue;
            }
            rec.args.push((
                ArgBinding {
                    param: part.to_string(),
                    output: true,
                    ty: Type::Error,
                    source: ArgSource::Written(k),
                },
                Ty::Known(target),
            ));
        }
        if !given_in {
            self.a
                .error(
                    code::E1062,
                    span,
                    format!("{} without its input IN", f.name),
                )
                .label("no IN := value")
                .hint(format!("write {}(IN := value, ...)", f.name));
        }
    }

    /// The inputs of a call: (type, span, source), `None` where a formal call leaves a gap.
    fn collect_inputs(
        &mut self,
        span: Span,
        args: &CallArgs,
        formal: bool,
        st: &mut State,
        what: &str,
    ) -> Vec<(Ty, Span, ArgSource)> {
        let mut out = Vec::new();
        if !formal {
            out.push((self.use_cr(st, span, what), span, ArgSource::CurrentResult));
        }
        if let CallArgs::NonFormal(ops) = args {
            for (k, o) in ops.iter().enumerate() {
                out.push((self.read_operand(o), o.span(), ArgSource::Written(k)));
            }
        }
        out
    }

    #[allow(clippy::too_many_arguments)]
    fn conversion_call(
        &mut self,
        span: Span,
        name: &ast::Ident,
        conv: stdlib::Conversion,
        args: &CallArgs,
        formal: bool,
        st: &mut State,
        rec: &mut Rec,
    ) -> Ty {
        let cname = name.name.to_ascii_uppercase();
        let (input, ispan, source) = match args {
            CallArgs::Formal(fargs) => {
                let mut input = None;
                for (k, fa) in fargs.iter().enumerate() {
                    // EN/ENO, as every function has (Beremiz writes them for LD networks)
                    if fa.name.is("ENO") && matches!(fa.dir, ArgDir::Output { .. }) {
                        let t = self.write_place(&fa.value, "=>");
                        self.coerce_store(&Ty::Known(Type::BOOL), &t, fa.value.span(), fa.span);
                        continue;
                    }
                    if fa.name.is("EN") && fa.dir == ArgDir::Input {
                        let t = self.read_operand(&fa.value);
                        self.check_bool(&t, fa.value.span(), "EN");
                        continue;
                    }
                    if fa.dir == ArgDir::Input && fa.name.is("IN") {
                        input = Some((
                            self.read_operand(&fa.value),
                            fa.value.span(),
                            ArgSource::Written(k),
                        ));
                    } else {
                        self.unknown_param(&fa.name, &cname, &["IN".to_string()]);
                    }
                }
                match input {
                    Some(i) => i,
                    None => {
                        self.a
                            .error(code::E1020, span, format!("{cname} needs its input IN"))
                            .label("missing IN := value")
                            .hint(format!("write {cname}(IN := value)"));
                        return Ty::ERROR;
                    }
                }
            }
            _ => {
                let ins = self.collect_inputs(span, args, formal, st, &cname);
                if ins.len() != 1 {
                    // ST's `F(a, b)` is lowered to IL's `LD a` `F b`: the count includes the
                    // current result, and the hint names both languages' forms
                    let hint = if formal {
                        format!("write {cname}(value) with one input")
                    } else {
                        format!(
                            "write {cname}(value) in ST, or LD value then {cname} with no operand in IL"
                        )
                    };
                    self.a
                        .error(
                            code::E1020,
                            span,
                            format!("{cname} takes one input, {} given", ins.len()),
                        )
                        .label("wrong number of inputs")
                        .hint(hint);
                    return Ty::ERROR;
                }
                ins.into_iter()
                    .next()
                    .unwrap_or((Ty::ERROR, span, ArgSource::CurrentResult))
            }
        };
        let from = match &conv.from {
            Some(t) => {
                let ok = self.coerce(&input, t, ispan, |b, f, t| {
                    b.a.error(
                        code::E1012,
                        ispan,
                        format!("{cname} converts from {t}, not {f}"),
                    )
                    .label(format!("this is {f}"))
                    .hint(format!("use {f}_TO_... for a {f} value"));
                });
                if ok {
                    Ty::Known(t.clone())
                } else {
                    Ty::ERROR
                }
            }
            None => match self.norm(&input) {
                Ty::Known(t) if conv.from_class == Class::Any => {
                    // TO_INT ...: the input's type, as X_TO_Y would take it
                    let ok = match &conv.to {
                        ConvTarget::Fixed(to) => {
                            stdlib::conversion_allowed(&t, to)
                                || stdlib::enum_conversion_allowed(&t, to, conv.kind)
                        }
                        ConvTarget::BcdOfWidth => false,
                    };
                    if ok || t.is_error() {
                        Ty::Known(t)
                    } else {
                        let tn = self.a.type_name(&t);
                        self.a
                            .error(code::E1004, ispan, format!("{cname} cannot convert {tn}"))
                            .label(format!("this is {tn}"))
                            .hint("IEC 61131-3 defines no such conversion");
                        Ty::ERROR
                    }
                }
                Ty::Known(t) if conv.from_class.contains(&t) => Ty::Known(t),
                // IEC 61131-3 (ed. 3, 6.4.2, Figure 11): an integer converts implicitly to the
                // real it widens to (`TRUNC(n / 2)` of an INT `n` takes REAL, of a DINT LREAL)
                Ty::Known(t)
                    if conv.from_class == Class::AnyReal && implicit_real(&t).is_some() =>
                {
                    Ty::Known(implicit_real(&t).unwrap_or(t))
                }
                Ty::Lit(v) => {
                    let t = if conv.from_class == Class::AnyReal
                        || (conv.from_class == Class::Any && self.lits.is_real(v))
                    {
                        Type::LREAL
                    } else if conv.from_class == Class::Any {
                        Type::Elementary(Elementary::Lint)
                    } else {
                        Type::Elementary(Elementary::Dword)
                    };
                    if self.lits.bind(v, &t).is_ok() {
                        Ty::Known(t)
                    } else {
                        Ty::ERROR
                    }
                }
                Ty::Known(t) => {
                    let tn = self.a.type_name(&t);
                    self.a
                        .error(
                            code::E1004,
                            ispan,
                            format!("{cname} is not defined for {tn}"),
                        )
                        .label(format!("this is {tn}"))
                        .hint(if t.is_integer() {
                            format!(
                                "{cname} needs {}; {tn} converts implicitly to no real (convert it explicitly)",
                                conv.from_class.name()
                            )
                        } else {
                            format!("{cname} needs {}", conv.from_class.name())
                        });
                    Ty::ERROR
                }
            },
        };
        let to = match (&conv.to, self.norm(&from)) {
            (_, Ty::Known(Type::Error)) => Ty::ERROR,
            (ConvTarget::Fixed(t), _) => Ty::Known(t.clone()),
            (ConvTarget::BcdOfWidth, Ty::Known(t)) => Ty::Known(Type::Elementary(bcd_of_width(
                t.elementary().unwrap_or(Elementary::Int),
            ))),
            (ConvTarget::BcdOfWidth, Ty::Lit(_)) => Ty::Known(Type::Elementary(Elementary::Word)),
        };
        rec.callee = Some(Callee::Conversion {
            name: cname,
            kind: conv.kind,
            from: Type::Error,
            to: Type::Error,
        });
        rec.callee_tys = Some((from.clone(), to.clone()));
        rec.args.push((
            ArgBinding {
                param: "IN".into(),
                output: false,
                ty: Type::Error,
                source,
            },
            from,
        ));
        to
    }

    fn std_call(
        &mut self,
        span: Span,
        f: &'static StdFunction,
        args: &CallArgs,
        formal: bool,
        st: &mut State,
        rec: &mut Rec,
    ) -> Ty {
        let inputs: Vec<(Ty, Span, ArgSource)> = match args {
            CallArgs::Formal(fargs) => {
                let mut slots: Vec<Option<(Ty, Span, ArgSource)>> = Vec::new();
                for (k, fa) in fargs.iter().enumerate() {
                    if fa.name.is("ENO") && matches!(fa.dir, ArgDir::Output { .. }) {
                        let t = self.write_place(&fa.value, "=>");
                        self.coerce_store(&Ty::Known(Type::BOOL), &t, fa.value.span(), fa.span);
                        continue;
                    }
                    if fa.name.is("EN") && fa.dir == ArgDir::Input {
                        let t = self.read_operand(&fa.value);
                        self.check_bool(&t, fa.value.span(), "EN");
                        continue;
                    }
                    let Some(idx) = f.param_index(&fa.name.name) else {
                        let names: Vec<String> =
                            (0..f.params.len()).map(|i| f.param_name(i)).collect();
                        self.unknown_param(&fa.name, f.name, &names);
                        self.arg_unchecked(fa);
                        continue;
                    };
                    if let ArgDir::Output { .. } = fa.dir {
                        self.a
                            .error(
                                code::E1013,
                                fa.span,
                                format!("`{}` is an input of {}", fa.name.name, f.name),
                            )
                            .label("=> receives outputs")
                            .hint(format!("write {} := value", fa.name.name));
                        continue;
                    }
                    let t = self.read_operand(&fa.value);
                    if slots.len() <= idx {
                        slots.resize(idx + 1, None);
                    }
                    slots[idx] = Some((t, fa.value.span(), ArgSource::Written(k)));
                }
                let needed = f.params.len().max(slots.len());
                let missing: Vec<String> = (0..needed)
                    .filter(|&i| slots.get(i).is_none_or(|s| s.is_none()))
                    .map(|i| f.param_name(i))
                    .collect();
                if !missing.is_empty() {
                    self.a
                        .error(
                            code::E1020,
                            span,
                            format!("{} needs input(s) {}", f.name, missing.join(", ")),
                        )
                        .label("missing inputs")
                        .hint(format!(
                            "give every input: {}",
                            (0..needed)
                                .map(|i| format!("{} := ...", f.param_name(i)))
                                .collect::<Vec<_>>()
                                .join(", ")
                        ));
                    return Ty::ERROR;
                }
                slots.into_iter().flatten().collect()
            }
            _ => {
                let ins = self.collect_inputs(span, args, formal, st, f.name);
                let n = f.params.len();
                if f.extensible && ins.len() > stdlib::MAX_EXTENSIBLE_INPUTS {
                    self.a
                        .error(
                            code::E1020,
                            span,
                            format!(
                                "{} takes at most {} inputs, {} given",
                                f.name,
                                stdlib::MAX_EXTENSIBLE_INPUTS,
                                ins.len()
                            ),
                        )
                        .label("too many inputs")
                        .hint("split the list: compute part of it, store it, and go on from there");
                    return Ty::ERROR;
                }
                let bad = if f.extensible {
                    ins.len() < n
                } else {
                    ins.len() != n
                };
                if bad {
                    let cr_note = if formal || n == 0 {
                        ""
                    } else {
                        " (the current result is the first)"
                    };
                    let hint = if n == 0 {
                        format!("call it without inputs: `{}()`", f.name)
                    } else {
                        format!(
                            "inputs: {}",
                            (0..n)
                                .map(|i| f.param_name(i))
                                .collect::<Vec<_>>()
                                .join(", ")
                        )
                    };
                    self.a
                        .error(
                            code::E1020,
                            span,
                            format!(
                                "{} takes {}{n} inputs{cr_note}, {} given",
                                f.name,
                                if f.extensible { "at least " } else { "" },
                                ins.len()
                            ),
                        )
                        .label("wrong number of inputs")
                        .hint(hint);
                    return Ty::ERROR;
                }
                ins
            }
        };
        let mut typed: Vec<(Ty, Span)> = inputs.iter().map(|(t, s, _)| (t.clone(), *s)).collect();
        if f.name == "CONCAT" {
            // edition 3 (Table 29: CONCAT of ANY_CHARS): a CHAR (WCHAR) joins as the
            // one-character STRING (WSTRING)
            for (t, _) in &mut typed {
                if let Ty::Known(Type::Elementary(e)) = t {
                    if e.is_char() {
                        let wide = *e == Elementary::Wchar;
                        *t = Ty::Known(Type::String { wide, len: 1 });
                    }
                }
            }
        }
        let inst = self.instantiate(f, &typed, span);
        for (i, (t, _, source)) in inputs.into_iter().enumerate() {
            let pty = match f.param_ty(i) {
                Some(ParamTy::T(_)) => inst.t.clone(),
                Some(ParamTy::Fixed(e)) => Ty::Known(Type::Elementary(e)),
                _ => t,
            };
            rec.args.push((
                ArgBinding {
                    param: f.param_name(i),
                    output: false,
                    ty: Type::Error,
                    source,
                },
                pty,
            ));
        }
        rec.callee = Some(Callee::Std {
            name: inst.name,
            ty: Type::Error,
            result: Type::Error,
        });
        rec.callee_tys = Some((inst.t.clone(), inst.result.clone()));
        inst.result
    }

    /// A typed name (`ADD_INT`): the generic type the call was instantiated with must be that type
    /// (an untyped literal takes it), E1410 otherwise.
    fn typed_call(
        &mut self,
        span: Span,
        name: &ast::Ident,
        t: Type,
        rec: &mut Rec,
        result: Ty,
    ) -> Ty {
        let Some((inst, res)) = rec.callee_tys.clone() else {
            return result;
        };
        let inst = self.norm(&inst);
        match &inst {
            Ty::Known(k) if k.is_error() => return result,
            Ty::Known(k) if !same_type(k, &t) => {
                let (got, want) = (self.a.type_name(k), self.a.type_name(&t));
                self.a
                    .error(
                        code::E1410,
                        span,
                        format!("`{}` takes {want} inputs, not {got}", name.name),
                    )
                    .label(format!("the inputs are {got}"))
                    .hint(format!(
                        "convert the inputs to {want}, or call the overloaded function without the type in its name"
                    ));
                return Ty::ERROR;
            }
            Ty::Known(_) => return result,
            Ty::Lit(_) => {}
        }
        // untyped literals only: they become the named type
        let fits = self.coerce(&inst, &t, span, |b, from, to| {
            b.a.error(
                code::E1410,
                span,
                format!("`{}` takes {to} inputs, not {from}", name.name),
            )
            .label(format!("the inputs are {from}"))
            .hint("write literals of the named type");
        });
        if !fits {
            return Ty::ERROR;
        }
        let (inst, res) = (self.norm(&inst), self.norm(&res));
        rec.callee_tys = Some((inst, res.clone()));
        res
    }

    fn user_call(
        &mut self,
        span: Span,
        id: PouId,
        args: &CallArgs,
        formal: bool,
        st: &mut State,
        rec: &mut Rec,
    ) -> Ty {
        let pou = self.a.model.pous[id.0 as usize].clone();
        let inputs: Vec<&Variable> = pou
            .vars
            .iter()
            .filter(|v| matches!(v.kind, VarKind::Input | VarKind::InOut))
            .collect();
        rec.callee = Some(Callee::UserFunction(id));
        let result = Ty::Known(pou.return_type.clone().unwrap_or(Type::Error));
        if self
            .a
            .declared_twice
            .contains(&pou.name.to_ascii_uppercase())
        {
            // an overloaded function (SIMATIC AX): its E1002 is the one cause, the arguments are
            // not checked against the declaration kept
            self.args_unchecked(args);
            return result;
        }
        match args {
            CallArgs::Formal(fargs) => {
                for (k, fa) in fargs.iter().enumerate() {
                    self.formal_arg(k, fa, &pou.name, &fb_like_params(&pou), rec);
                }
            }
            // a function without inputs in operator form (`LD x` then `seven`): no current result to
            // pass, the call replaces it (as matiec does)
            CallArgs::None if !formal && inputs.is_empty() => {}
            _ => {
                let ins = self.collect_inputs(span, args, formal, st, &pou.name);
                if ins.len() != inputs.len() {
                    let cr_note = if formal {
                        ""
                    } else {
                        " (the current result is the first)"
                    };
                    self.a
                        .error(
                            code::E1020,
                            span,
                            format!(
                                "{} takes {} inputs{cr_note}, {} given",
                                pou.name,
                                inputs.len(),
                                ins.len()
                            ),
                        )
                        .label("wrong number of inputs")
                        .also(pou.span, "function declared here")
                        .hint(if inputs.is_empty() {
                            format!("{} has no inputs: call it without operands", pou.name)
                        } else {
                            format!(
                                "inputs: {}",
                                inputs
                                    .iter()
                                    .map(|v| v.name.clone())
                                    .collect::<Vec<_>>()
                                    .join(", ")
                            )
                        });
                    return result;
                }
                for ((t, s, source), p) in ins.into_iter().zip(inputs) {
                    let pname = p.name.clone();
                    let fname = pou.name.clone();
                    if p.kind == VarKind::InOut
                        && self.in_out_type_differs(&t, &p.ty, s, &pname, &fname)
                    {
                        rec.args.push((
                            ArgBinding {
                                param: pname,
                                output: false,
                                ty: Type::Error,
                                source,
                            },
                            Ty::Known(p.ty.clone()),
                        ));
                        continue;
                    }
                    self.a.passing_any_address = crate::st::any_inputs::is_address_input(&pname);
                    self.coerce(&t, &p.ty, s, |b, from, to| {
                        if b.a.passing_any_address {
                            return any_address_refused(b, &t, s, &pname, &fname, from);
                        }
                        b.a.error(
                            code::E1012,
                            s,
                            format!("input {pname} of {fname} is {to}, not {from}"),
                        )
                        .label(format!("this is {from}"))
                        .hint(conversion_hint(from, to));
                    });
                    self.a.passing_any_address = false;
                    rec.args.push((
                        ArgBinding {
                            param: p.name.clone(),
                            output: false,
                            ty: Type::Error,
                            source,
                        },
                        Ty::Known(p.ty.clone()),
                    ));
                }
            }
        }
        result
    }

    /// `CAL inst(...)`, `CALC inst`, and `CAL f(...)` of a function (accepted as in IEC Annex F).
    pub(super) fn cal(
        &mut self,
        span: Span,
        cond: Condition,
        instance: &VarRef,
        args: &CallArgs,
        st: &mut State,
        rec: &mut Rec,
    ) {
        // (an instance keeps what its inputs are given: `ADR` of a VAR_TEMP given to one
        // outlives the call, E0305 in `refs`)
        let outer = std::mem::replace(&mut self.instance_args, true);
        self.cal_checked(span, cond, instance, args, st, rec);
        self.instance_args = outer;
    }

    fn cal_checked(
        &mut self,
        span: Span,
        cond: Condition,
        instance: &VarRef,
        args: &CallArgs,
        st: &mut State,
        rec: &mut Rec,
    ) {
        if cond != Condition::Always {
            let cr = self.use_cr(st, span, "a conditional CAL");
            self.check_bool(&cr, span, "a conditional CAL");
        }
        if instance.accessors.is_empty() && self.pou().var(&instance.base.name).is_none() {
            let n = &instance.base;
            let is_fn =
                stdlib::conversion(&n.name).is_some()
                    || stdlib::function(&n.name).is_some()
                    || stdlib::split(&n.name).is_some()
                    || self.a.pou_names.get(&n.key()).is_some_and(|id| {
                        self.a.model.pous[id.0 as usize].kind == PouKind::Function
                    });
            if is_fn && cond != Condition::Always {
                // a function has no instance whose call could be skipped with its outputs kept:
                // the conditional forms call FB instances only (IEC 61131-3 IL: CALC / CALCN)
                self.a
                    .error(
                        code::E1018,
                        n.span,
                        format!(
                            "`{}` is a function: a conditional CAL (CALC, CALCN) calls a function block instance",
                            n.name
                        ),
                    )
                    .label("a function")
                    .hint(format!(
                        "jump over an unconditional call (`JMPCN skip`, `CAL {}(...)`, `skip:`), or call an FB instance",
                        n.name
                    ));
                self.args_unchecked(args);
                st.cr.ty = Some(Ty::ERROR);
                return;
            }
            if is_fn {
                self.function_call(span, n, args, true, st, rec);
                return;
            }
        }
        // `CAL PLC_PRG(__ACTION_RESET := TRUE)`: an action of a program run on the program's one
        // instance (written `PLC_PRG.Reset();`, linked by `crate::actions::link`)
        let program = match args {
            CallArgs::Formal(list)
                if instance.accessors.is_empty()
                    && self.pou().var(&instance.base.name).is_none()
                    && list
                        .iter()
                        .any(|a| a.name.name.starts_with(crate::actions::FLAG_PREFIX)) =>
            {
                self.a
                    .pou_names
                    .get(&instance.base.key())
                    .copied()
                    .filter(|id| self.a.model.pous[id.0 as usize].kind == PouKind::Program)
            }
            _ => None,
        };
        let place = match (program, self.called_program(instance)) {
            (Some(id), _) => super::places::Place {
                ty: Type::Fb(FbType::User(id)),
                read_only: None,
            },
            // `CAL P(in := x)`, `P(in := x);` (CODESYS, TwinCAT): the program's one instance
            (None, Some(id)) => super::places::Place {
                ty: self.program_call(instance, id).unwrap_or(Type::Error),
                read_only: None,
            },
            (None, None) => self.resolve_var(instance),
        };
        // an instance of a CLASS (IEC 61131-3 ed. 3, 6.6.5) has no body to call: only its
        // methods are called (`inst.M()`, linked to a call with an `__ACTION_` flag)
        if let Type::Fb(FbType::User(id)) = place.ty {
            let method = matches!(args, CallArgs::Formal(list) if list
                .iter()
                .any(|a| a.name.name.starts_with(crate::actions::FLAG_PREFIX)));
            let class = &self.a.model.pous[id.0 as usize];
            if class.class && !method {
                let name = class.name.clone();
                self.a
                    .error(
                        code::E1018,
                        instance.span,
                        format!(
                            "`{}` is an instance of the class {name}: a class is not called, its methods are",
                            instance.base.name
                        ),
                    )
                    .label("an instance of a CLASS")
                    .hint(format!("call one of its methods (`{}.M();`), or declare {name} a FUNCTION_BLOCK to give it a body", instance.base.name));
                self.args_unchecked(args);
                return;
            }
        }
        match place.ty {
            Type::Fb(fb) => {
                rec.callee = Some(Callee::FbInstance { fb, input: None });
                rec.operand = Some(Ty::Known(Type::Fb(fb)));
                self.duplicate_formals(args);
                self.fb_args(fb, args, rec);
                self.in_outs_connected(fb, span, instance, args, rec);
            }
            Type::Error => self.args_unchecked(args),
            other => {
                let t = self.a.type_name(&other);
                self.a
                    .error(
                        code::E1018,
                        instance.span,
                        format!("`{}` is {t}, not an FB instance", instance.base.name),
                    )
                    .label("CAL needs an FB instance")
                    .hint("declare an instance (VAR t : TON; END_VAR) and call it");
                self.args_unchecked(args);
            }
        }
    }

    fn fb_args(&mut self, fb: FbType, args: &CallArgs, rec: &mut Rec) {
        let params = fb_param_list(&self.a.model, fb);
        let tname = self.a.type_name(&Type::Fb(fb));
        match args {
            CallArgs::None => {}
            CallArgs::NonFormal(ops) => {
                let inputs: Vec<_> = params
                    .iter()
                    .filter(|p| matches!(p.1, ParamDir::Input | ParamDir::InOut))
                    .cloned()
                    .collect();
                let visible: Vec<_> = params
                    .iter()
                    .filter(|p| p.1 != ParamDir::Internal)
                    .collect();
                // an output in a positional call of a block (`c(x)` where C has only the output
                // `o`): named in the message (before round 26: "C has 0 inputs, 1 given" alone)
                let first_output = params.iter().find(|p| p.1 == ParamDir::Output);
                if first_output.is_some() && ops.len() == visible.len() {
                    // every parameter listed in declaration order, the outputs receiving
                    // (IEC 61131-3 ed. 2 Table 53's `CAL C10(%IX10, FALSE, A, OUT, B)`, ed. 3
                    // 6.6.1.4.2): bound as the formal call naming each one, an output's
                    // argument the variable it is written to (`Q => OUT`)
                    for (k, (o, p)) in ops.iter().zip(visible).enumerate() {
                        let dir = if p.1 == ParamDir::Output {
                            ArgDir::Output { negated: false }
                        } else {
                            ArgDir::Input
                        };
                        let fa = ast::FormalArg {
                            name: ast::Ident::new(p.0.clone(), o.span()),
                            dir,
                            value: o.clone(),
                            span: o.span(),
                        };
                        self.formal_arg(k, &fa, &tname, &params, rec);
                    }
                    return;
                }
                if let (true, Some(out)) = (ops.len() > inputs.len(), first_output) {
                    self.a
                        .error(
                            code::E1020,
                            ops[inputs.len()].span(),
                            format!(
                                "{tname} has {} inputs, {} given: an output of a block is given by position only in a call that lists all its parameters in order ({} in all)",
                                inputs.len(),
                                ops.len(),
                                visible.len()
                            ),
                        )
                        .label("one argument too many")
                        .hint(format!(
                            "connect the output by name (`{0} => x`), or read it after the call (`inst.{0}`)",
                            out.0
                        ));
                } else if ops.len() > inputs.len() {
                    self.a
                        .error(
                            code::E1020,
                            ops[inputs.len()].span(),
                            format!("{tname} has {} inputs, {} given", inputs.len(), ops.len()),
                        )
                        .label("one argument too many")
                        .hint(format!(
                            "inputs: {}",
                            inputs
                                .iter()
                                .map(|p| p.0.clone())
                                .collect::<Vec<_>>()
                                .join(", ")
                        ));
                }
                for (k, (o, p)) in ops
                    .iter()
                    .zip(inputs.iter().chain(std::iter::repeat(&(
                        String::new(),
                        ParamDir::Internal,
                        Type::Error,
                    ))))
                    .enumerate()
                {
                    let t = self.read_operand(o);
                    let s = o.span();
                    let (pname, tn) = (p.0.clone(), tname.clone());
                    if p.1 == ParamDir::InOut && self.in_out_type_differs(&t, &p.2, s, &pname, &tn)
                    {
                        rec.args.push((
                            ArgBinding {
                                param: p.0.clone(),
                                output: false,
                                ty: Type::Error,
                                source: ArgSource::Written(k),
                            },
                            Ty::Known(p.2.clone()),
                        ));
                        continue;
                    }
                    self.a.passing_any_address = crate::st::any_inputs::is_address_input(&pname);
                    self.coerce(&t, &p.2, s, |b, from, to| {
                        if b.a.passing_any_address {
                            return any_address_refused(b, &t, s, &pname, &tn, from);
                        }
                        b.a.error(
                            code::E1012,
                            s,
                            format!("input {pname} of {tn} is {to}, not {from}"),
                        )
                        .label(format!("this is {from}"))
                        .hint(conversion_hint(from, to));
                    });
                    self.a.passing_any_address = false;
                    if !p.0.is_empty() {
                        rec.args.push((
                            ArgBinding {
                                param: p.0.clone(),
                                output: false,
                                ty: Type::Error,
                                source: ArgSource::Written(k),
                            },
                            Ty::Known(p.2.clone()),
                        ));
                    }
                }
            }
            CallArgs::Formal(fargs) => {
                for (k, fa) in fargs.iter().enumerate() {
                    // `CTU(CU := x, RESET := r)`: the CODESYS/TwinCAT name of an IEC input
                    let alias = match fb {
                        FbType::Standard(s) => super::stdlib::vendor_param_alias(s, &fa.name.name),
                        FbType::User(_) => None,
                    };
                    match alias {
                        Some(iec) => {
                            let mut named = fa.clone();
                            named.name.name = iec.to_string();
                            self.formal_arg(k, &named, &tname, &params, rec);
                        }
                        None => self.formal_arg(k, fa, &tname, &params, rec),
                    }
                }
            }
        }
    }

    /// E1033 for each VAR_IN_OUT of the block that a call of an instance leaves unconnected
    /// (`inst();`, `inst(io := , a := 1)`): IEC 61131-3 ed. 3 (6.6.1.2.2) requires an in-out to be
    /// connected, CODESYS and TwinCAT refuse such a call (C0039: "VAR_IN_OUT must be assigned in
    /// call"), and the block would read through a null reference. A call that runs an action of
    /// the instance (its `__ACTION_` flag) passes no parameters and is not checked.
    fn in_outs_connected(
        &mut self,
        fb: FbType,
        span: Span,
        instance: &VarRef,
        args: &CallArgs,
        rec: &Rec,
    ) {
        if let CallArgs::Formal(list) = args {
            if list
                .iter()
                .any(|a| a.name.name.starts_with(crate::actions::FLAG_PREFIX))
            {
                return;
            }
        }
        let tname = self.a.type_name(&Type::Fb(fb));
        for (name, dir, _) in fb_param_list(&self.a.model, fb) {
            // (a method's in-out, `__M_<M>_X`, is bound by the calls of that method only)
            if dir != ParamDir::InOut
                || name.starts_with(crate::actions::METHOD_PREFIX)
                || rec
                    .args
                    .iter()
                    .any(|(b, _)| !b.output && b.param.eq_ignore_ascii_case(&name))
            {
                continue;
            }
            self.a
                .error(
                    code::E1033,
                    span,
                    format!(
                        "VAR_IN_OUT `{name}` of {tname} is not connected in this call of `{}`",
                        instance.base.name
                    ),
                )
                .label("in-out not connected")
                .hint(format!(
                    "connect it to a variable in every call: `{}({name} := ...)`",
                    instance.base.name
                ));
        }
    }

    /// E1028 for each input given again in one call (`f(a := 1, a := 2)`): which value won was the
    /// generated code's accident. An output may be written to several variables (`Q => a, NOT Q => b`).
    fn duplicate_formals(&mut self, args: &CallArgs) {
        let CallArgs::Formal(fargs) = args else {
            return;
        };
        let mut seen: std::collections::HashMap<String, Span> = std::collections::HashMap::new();
        for fa in fargs.iter().filter(|fa| fa.dir == ArgDir::Input) {
            match seen.entry(fa.name.key()) {
                std::collections::hash_map::Entry::Vacant(v) => {
                    v.insert(fa.name.span);
                }
                std::collections::hash_map::Entry::Occupied(o) => {
                    let first = *o.get();
                    self.a
                        .error(
                            code::E1028,
                            fa.name.span,
                            format!("input `{}` is given twice in one call", fa.name.name),
                        )
                        .label("given again")
                        .also(first, "first given here")
                        .hint("pass each input once");
                }
            }
        }
    }

    /// One `name := value` / `name => var` of a call to an FB or user function.
    fn formal_arg(
        &mut self,
        k: usize,
        fa: &ast::FormalArg,
        callee: &str,
        params: &[(String, ParamDir, Type)],
        rec: &mut Rec,
    ) {
        let found = params
            .iter()
            .find(|p| fa.name.is(&p.0) && p.1 != ParamDir::Internal)
            .cloned()
            .or_else(|| {
                if fa.name.is("EN") {
                    Some(("EN".into(), ParamDir::Input, Type::BOOL))
                } else if fa.name.is("ENO") {
                    // `inst(..., ENO => ok)`: the instance keeps its ENO (user FBs too)
                    self.a.model.fb_eno_read = true;
                    Some(("ENO".into(), ParamDir::Output, Type::BOOL))
                } else {
                    None
                }
            });
        let Some((pname, pdir, pty)) = found else {
            let names: Vec<String> = params
                .iter()
                .filter(|p| p.1 != ParamDir::Internal)
                .map(|p| p.0.clone())
                .collect();
            self.unknown_param(&fa.name, callee, &names);
            self.arg_unchecked(fa);
            return;
        };
        match (fa.dir, pdir) {
            (ArgDir::Input, ParamDir::Input | ParamDir::InOut) => {
                if pdir == ParamDir::InOut && matches!(pty, Type::Ref(_)) {
                    self.in_out_reference(&pname, callee, fa.value.span());
                }
                let t = self.read_operand(&fa.value);
                let s = fa.value.span();
                if pdir == ParamDir::InOut && self.in_out_type_differs(&t, &pty, s, &pname, callee)
                {
                    rec.args.push((
                        ArgBinding {
                            param: pname,
                            output: false,
                            ty: Type::Error,
                            source: ArgSource::Written(k),
                        },
                        Ty::Known(pty),
                    ));
                    return;
                }
                let (pn, cn) = (pname.clone(), callee.to_string());
                self.a.passing_any_address = crate::st::any_inputs::is_address_input(&pname);
                self.coerce(&t, &pty, s, |b, from, to| {
                    if b.a.passing_any_address {
                        return any_address_refused(b, &t, s, &pn, &cn, from);
                    }
                    let hint = match ltime_timer(&cn) {
                        Some(l) if pn == "PT" && from == "LTIME" => format!(
                            "declare the instance {l} (edition 3's timer on LTIME), or convert explicitly with LTIME_TO_TIME"
                        ),
                        _ => conversion_hint(from, to),
                    };
                    b.a.error(code::E1012, s, format!("{pn} of {cn} is {to}, not {from}"))
                        .label(format!("this is {from}"))
                        .hint(hint);
                });
                self.a.passing_any_address = false;
                rec.args.push((
                    ArgBinding {
                        param: pname,
                        output: false,
                        ty: Type::Error,
                        source: ArgSource::Written(k),
                    },
                    Ty::Known(pty),
                ));
            }
            (ArgDir::Output { negated }, ParamDir::Output) => {
                let target = self.write_place(&fa.value, "=>");
                let s = fa.value.span();
                if negated && !pty.is_bool() && !pty.is_error() {
                    self.a
                        .error(
                            code::E1004,
                            fa.span,
                            format!("NOT {pname}: {pname} is not BOOL"),
                        )
                        .label("only BOOL outputs can be negated")
                        .hint(format!("write {pname} => var"));
                }
                // `inst(Q => v)` stores the output into `v` after the call (IEC 61131-3 ed. 3,
                // 6.6.1.4.2, output assignment): the rule of the assignment `v := inst.Q`, with its
                // dialect conversions (a WORD output into a UINT counts as UINT, W1436)
                let (pn, cn) = (pname.clone(), callee.to_string());
                self.coerce(&Ty::Known(pty.clone()), &target, s, |b, from, to| {
                    b.a.error(
                        code::E1012,
                        s,
                        format!("output {pn} of {cn} is {from}, cannot be stored into {to}"),
                    )
                    .label(format!("this is {to}"))
                    .hint(conversion_hint(from, to));
                });
                rec.args.push((
                    ArgBinding {
                        param: pname,
                        output: true,
                        ty: Type::Error,
                        source: ArgSource::Written(k),
                    },
                    Ty::Known(pty),
                ));
            }
            (ArgDir::Input, _) => {
                self.a
                    .error(
                        code::E1013,
                        fa.span,
                        format!("`{pname}` is an output of {callee}"),
                    )
                    .label(":= passes inputs")
                    .hint(format!("write {pname} => variable to receive it"));
                self.arg_unchecked(fa);
            }
            (ArgDir::Output { .. }, _) => {
                self.a
                    .error(
                        code::E1013,
                        fa.span,
                        format!("`{pname}` is an input of {callee}"),
                    )
                    .label("=> receives outputs")
                    .hint(format!("write {pname} := value to pass it"));
                self.arg_unchecked(fa);
            }
        }
    }

    /// An elementary variable given to an in-out of another elementary type (`r := i` for
    /// `VAR_IN_OUT r : REAL` and `i : INT`, a WORD to a DWORD, a BOOL to a BYTE): one E1012, by
    /// name or by position, of a block, function, method or `CAL`. An in-out passes the variable
    /// itself (IEC 61131-3 ed. 3, 6.6.1.2.2: its type is the in-out's; CODESYS and TwinCAT refuse
    /// it), so no conversion (not even a widening one) can stand between them; the C would write a
    /// REAL over a two-byte INT. A subrange counts as its integer type, an enumeration as the DINT
    /// it is stored as (so an enumeration and a DINT in-out pass, W1439 as for values).
    fn in_out_type_differs(
        &mut self,
        given: &Ty,
        param: &Type,
        at: Span,
        pname: &str,
        callee: &str,
    ) -> bool {
        // the C storage of the value: an enumeration is a DINT there
        let elementary = |t: &Type| match t {
            Type::Elementary(e) => Some(*e),
            Type::Subrange { base, .. } => Some(*base),
            Type::Enum(_) => Some(Elementary::Dint),
            _ => None,
        };
        let Ty::Known(g) = given else {
            return false;
        };
        let (Some(a), Some(b)) = (elementary(g), elementary(param)) else {
            return false;
        };
        if a == b {
            return false;
        }
        let (from, to) = (self.a.type_name(g), self.a.type_name(param));
        self.a
            .error(
                code::E1012,
                at,
                format!("in-out {pname} of {callee} is {to}, not {from}"),
            )
            .label(format!("this variable is {from}"))
            .hint(format!(
                "an in-out passes the variable itself, so its type must be {to}: declare it {to}, or copy it through a variable of type {to} before and after the call"
            ));
        true
    }

    fn unknown_param(&mut self, name: &ast::Ident, callee: &str, params: &[String]) {
        let address = format!("{}{}", name.name, crate::st::varlen::ADDRESS);
        if params.iter().any(|p| p.eq_ignore_ascii_case(&address)) {
            // an `ARRAY [*]` in-out given by a call the ST rewrite did not see (an IL `CAL`)
            self.a
                .error(
                    code::E1071,
                    name.span,
                    format!(
                        "`{}` of {callee} is an `ARRAY [*]` in-out: only calls in Structured Text pass a variable-length array",
                        name.name
                    ),
                )
                .label("variable-length array argument")
                .hint("call it from an ST body (`inst(data := arr);`), which passes the array's address and bounds");
            return;
        }
        let params: Vec<String> = params
            .iter()
            .filter(|p| !is_hidden_varlen(p))
            // nor an action's hidden selector (`__ACTION_M`): no parameter the user may give
            .filter(|p| !p.starts_with("__ACTION_"))
            .cloned()
            .collect();
        self.a
            .error(
                code::E1011,
                name.span,
                format!("{callee} has no parameter `{}`", name.name),
            )
            .label("unknown parameter")
            .hint(format!("parameters of {callee}: {}", params.join(", ")));
    }

    /// Name-checks the operands of arguments that cannot be type-checked.
    fn args_unchecked(&mut self, args: &CallArgs) {
        match args {
            CallArgs::None => {}
            CallArgs::NonFormal(ops) => {
                for o in ops {
                    self.read_operand(o);
                }
            }
            CallArgs::Formal(fargs) => {
                for fa in fargs {
                    self.arg_unchecked(fa);
                }
            }
        }
    }

    fn arg_unchecked(&mut self, fa: &ast::FormalArg) {
        match fa.dir {
            ArgDir::Input => {
                self.read_operand(&fa.value);
            }
            ArgDir::Output { .. } => {
                self.write_place(&fa.value, "=>");
            }
        }
    }

    /// An FB input operator (`PT tmr`, `IN tmr` ...) on a variable reference.
    pub(super) fn fb_input(
        &mut self,
        span: Span,
        input: &str,
        instance: &VarRef,
        cr: Ty,
        rec: &mut Rec,
    ) {
        let place = self.resolve_var(instance);
        match place.ty {
            Type::Fb(fb) => self.fb_input_core(span, input, fb, instance.span, cr, rec),
            Type::Error => {}
            other => {
                let t = self.a.type_name(&other);
                self.a
                    .error(
                        code::E1018,
                        instance.span,
                        format!("`{}` is {t}, not an FB instance", instance.base.name),
                    )
                    .label(format!("{input} needs an FB instance with input {input}"))
                    .hint("declare an FB instance (VAR t : TON; END_VAR)");
            }
        }
    }

    /// `S inst` / `R inst`: the FB input operators S and R.
    pub(super) fn fb_input_resolved(
        &mut self,
        span: Span,
        input: &str,
        fb: FbType,
        o: &Operand,
        cr: Ty,
        rec: &mut Rec,
    ) {
        if let Operand::Var(v) = o {
            let _ = self.resolve_var(v);
        }
        self.fb_input_core(span, input, fb, o.span(), cr, rec);
    }

    fn fb_input_core(
        &mut self,
        span: Span,
        input: &str,
        fb: FbType,
        inst_span: Span,
        cr: Ty,
        rec: &mut Rec,
    ) {
        let params = fb_param_list(&self.a.model, fb);
        let tname = self.a.type_name(&Type::Fb(fb));
        rec.operand = Some(Ty::Known(Type::Fb(fb)));
        let Some((pname, _, pty)) = params
            .iter()
            .find(|p| {
                p.0.eq_ignore_ascii_case(input) && matches!(p.1, ParamDir::Input | ParamDir::InOut)
            })
            .cloned()
        else {
            let names: Vec<String> = params
                .iter()
                .filter(|p| p.1 == ParamDir::Input)
                .map(|p| p.0.clone())
                .collect();
            self.a
                .error(code::E1011, span, format!("{tname} has no input `{input}`"))
                .label(format!("{input} stores into input {input}"))
                .also(inst_span, format!("this is a {tname}"))
                .hint(format!("inputs of {tname}: {}", names.join(", ")));
            return;
        };
        let tn = tname.clone();
        let pn = pname.clone();
        self.coerce(&cr, &pty, span, |b, from, to| {
            b.a.error(
                code::E1012,
                span,
                format!("input {pn} of {tn} is {to}, but the current result is {from}"),
            )
            .label(format!("stores the current result ({from}) into {pn}"))
            .hint(conversion_hint(from, to));
        });
        rec.callee = Some(Callee::FbInstance {
            fb,
            input: Some(pname),
        });
    }
}

/// A user function's parameters in the FB parameter format.
fn fb_like_params(pou: &Pou) -> Vec<(String, ParamDir, Type)> {
    pou.vars
        .iter()
        .map(|v| {
            let d = match v.kind {
                VarKind::Input => ParamDir::Input,
                VarKind::InOut => ParamDir::InOut,
                VarKind::Output => ParamDir::Output,
                _ => ParamDir::Internal,
            };
            (v.name.clone(), d, v.ty.clone())
        })
        .collect()
}

/// The generic type of a string function: as long as the longest input (CONCAT: the sum of their
/// lengths), at most the 254-character capacity, so the result's declared length never truncates it.
fn string_generic(f: &StdFunction, t: Type, known: &[(Type, Span)]) -> Type {
    let Type::String { wide, .. } = t else {
        return t;
    };
    let lens = known.iter().filter_map(|(k, _)| match k {
        Type::String { len, .. } => Some(*len),
        _ => None,
    });
    let len = if f.name == "CONCAT" {
        lens.sum::<u32>()
    } else {
        lens.max().unwrap_or_else(default_string_len)
    };
    Type::String {
        wide,
        len: len.clamp(1, STRING_CAPACITY),
    }
}

/// The type a typed function name denotes: strings of any length are `STRING` (or `WSTRING`).
fn same_type(a: &Type, b: &Type) -> bool {
    match (a, b) {
        (Type::String { wide: x, .. }, Type::String { wide: y, .. }) => x == y,
        _ => a == b,
    }
}

/// Whether `p` is one of the hidden inputs of an `ARRAY [*]` in-out (`st::varlen`), which a
/// parameter list shown to the user leaves out.
fn is_hidden_varlen(p: &str) -> bool {
    let up = p.to_ascii_uppercase();
    up.ends_with(crate::st::varlen::ADDRESS)
        || [crate::st::varlen::LOWER, crate::st::varlen::UPPER]
            .iter()
            .any(|s| {
                up.rfind(s).is_some_and(|k| {
                    k > 0
                        && up[k + s.len()..].chars().all(|c| c.is_ascii_digit())
                        && up.len() > k + s.len()
                })
            })
}

/// E1068 at an ANY input's argument whose bytes `.pValue` may not reach (`pname` is the hidden
/// `In__PVALUE`, `crate::st::any_inputs`): its type holds a reference or a function block instance,
/// which bytes written through a `POINTER TO BYTE` could forge; nothing when `t` holds a type that
/// was not found (its E1003 is the one error).
fn any_address_refused(b: &mut Body, t: &Ty, at: Span, pname: &str, callee: &str, from: &str) {
    // (an argument whose type holds one that was not found: that type's E1003 is the cause)
    if let Ty::Known(t) = t {
        if super::typing::holds_unknown(t, &b.a.model) {
            return;
        }
    }
    let input = &pname[..pname
        .len()
        .saturating_sub(crate::st::any_inputs::VALUE.len())];
    let of = from.strip_prefix("REF_TO ").unwrap_or(from);
    b.a.error(
        code::E1068,
        at,
        format!("`{input}.pValue` of `{callee}` cannot point into a {of}: it holds a reference or a function block instance"),
    )
    .label(format!("this is {of}"))
    .hint("bytes written through `.pValue` could make a reference; pass a variable whose type holds numbers, strings, enumerations, arrays and structures of these");
}

/// The smallest integer or real type that both elementary numbers `a` and `b` widen to implicitly
/// (INT and UDINT: LINT; UINT and INT: DINT), when neither widens to the other; `None` otherwise.
fn holding_both(a: &Type, b: &Type) -> Option<Elementary> {
    let (a, b) = (a.elementary()?, b.elementary()?);
    if !(a.is_numeric() && b.is_numeric()) {
        return None;
    }
    Elementary::ALL
        .into_iter()
        .filter(|&c| {
            c.is_numeric()
                && c != a
                && c != b
                && super::typing::widens(a, c)
                && super::typing::widens(b, c)
        })
        .min_by_key(|c| (c.bit_width(), c.is_real()))
}

/// The LTIME timer of edition 3 (Table 46) in the family of the TIME timer `callee` (`TON` ->
/// `TON_LTIME`), for the hint of an LTIME given to its PT.
fn ltime_timer(callee: &str) -> Option<&'static str> {
    let fb = super::StdFb::from_name(callee)?;
    match fb.timer()? {
        (super::StdFb::Ton, false) => Some("TON_LTIME"),
        (super::StdFb::Tof, false) => Some("TOF_LTIME"),
        (super::StdFb::Tp, false) => Some("TP_LTIME"),
        _ => None,
    }
}
