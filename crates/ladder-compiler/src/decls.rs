//! Declarations: `<dataType>`, `<type>`, `<variable>`, `<initialValue>` and the interface variable lists
//! of a POU, turned into [`il_frontend::ast::TypeDecl`], [`il_frontend::ast::TypeRef`], [`il_frontend::ast::VarDecl`] and
//! [`il_frontend::ast::VarBlock`].
//!
//! Input: elements of the `types` and `interface` parts (tc6_0201, tc6_0200 and v1.0 spell them alike).
//! Output: syntax-tree declarations whose spans point at the `<variable>`/`<dataType>` start tags and
//! whose names point at the `name` attribute. Invariants: a declaration that cannot be read is reported
//! (E3011/E3012/E3013) and left out; the rest of the list is still returned.

use crate::context::Ctx;
use crate::values;
use crate::xml::Element;
use diagnostics::{code, Diagnostic};
use il_frontend::ast::{
    ArrayDim, ArrayInitElement, EnumValue, Ident, Initializer, TypeDecl, TypeDef, TypeRef,
    VarBlock, VarDecl, VarKind,
};
use std::collections::HashMap;

/// Elementary type element names of the schema and the IEC name they stand for.
fn elementary(name: &str) -> Option<&'static str> {
    Some(match name {
        "BOOL" => "BOOL",
        "BYTE" => "BYTE",
        "WORD" => "WORD",
        "DWORD" => "DWORD",
        "LWORD" => "LWORD",
        "SINT" => "SINT",
        "INT" => "INT",
        "DINT" => "DINT",
        "LINT" => "LINT",
        "USINT" => "USINT",
        "UINT" => "UINT",
        "UDINT" => "UDINT",
        "ULINT" => "ULINT",
        "REAL" => "REAL",
        "LREAL" => "LREAL",
        "TIME" => "TIME",
        "LTIME" => "LTIME",
        "DATE" => "DATE",
        "DT" => "DT",
        "TOD" => "TOD",
        "LDATE" => "LDATE",
        "LDT" => "LDT",
        "LTOD" => "LTOD",
        "CHAR" => "CHAR",
        "WCHAR" => "WCHAR",
        _ => return None,
    })
}

/// Reads the single type element inside `<type>`, `<baseType>` or `<returnType>`.
pub fn type_ref(ctx: &mut Ctx, holder: &Element) -> Option<TypeRef> {
    let Some(t) = holder.children.first() else {
        ctx.error(
            code::E3013,
            ctx.tag(holder),
            format!("<{}> has no type inside", holder.name()),
        );
        return None;
    };
    type_element(ctx, t)
}

fn type_element(ctx: &mut Ctx, t: &Element) -> Option<TypeRef> {
    let span = ctx.tag(t);
    if let Some(n) = elementary(t.name()) {
        return Some(TypeRef::Named(Ident::new(n, span)));
    }
    match t.name() {
        "string" | "wstring" => Some(TypeRef::String {
            wide: t.name() == "wstring",
            length: t.attr("length").and_then(|l| l.trim().parse().ok()),
            span,
        }),
        "derived" => match t.attr("name") {
            // CODESYS's one-bit type `BIT` (CODESYS online help, "Data Type: BIT": only for the
            // members of a structure or function block), which its export writes as
            // `<derived name="BIT"/>`: read as BOOL, as the ST front end reads it in text
            // (`il_frontend::parser`'s `named_type`)
            Some(n) if n.trim().eq_ignore_ascii_case("BIT") => {
                Some(TypeRef::Named(Ident::new("BOOL", ctx.attr_span(t, "name"))))
            }
            Some(n) if values::is_ident(n.trim()) => Some(TypeRef::Named(Ident::new(
                n.trim(),
                ctx.attr_span(t, "name"),
            ))),
            // a library-qualified name (CODESYS `MQTT.MQTTClient`, `OSCAT_BASIC.GEN_PULSE`): kept
            // whole, so that the missing type is reported by the name the file uses (E3009)
            // `Standard.TON` (CODESYS) and `Tc2_Standard.TON` (TwinCAT) are the IEC standard blocks
            Some(n) if n.trim().split('.').all(values::is_ident) => {
                let n = n.trim();
                let name = match n.split_once('.') {
                    Some((lib, fb))
                        if ["STANDARD", "TC2_STANDARD"]
                            .contains(&lib.to_ascii_uppercase().as_str())
                            && il_frontend::sema::StdFb::from_name(fb).is_some() =>
                    {
                        fb
                    }
                    _ => n,
                };
                Some(TypeRef::Named(Ident::new(name, ctx.attr_span(t, "name"))))
            }
            Some(n) if is_reference(n).is_some() => {
                // `REFERENCE TO X` / `POINTER TO X` (CODESYS, TwinCAT)
                let span = ctx.attr_span(t, "name");
                let n = n.trim();
                let kind = is_reference(n)?;
                let base = n.split_whitespace().nth(2).unwrap_or("");
                let base = elementary(&base.to_ascii_uppercase()).unwrap_or(base);
                // a library-qualified target (CODESYS `REFERENCE TO SM3_Robotics.AXIS_GROUP_REF_SM3`)
                // is one type too: kept whole, so that a missing one is reported by its name (E3009)
                if n.split_whitespace().count() != 3 || !base.split('.').all(values::is_ident) {
                    let msg = format!("type `{n}` is not supported here: a reference or pointer names one type (`POINTER TO INT`, `REFERENCE TO Motor`)");
                    ctx.error(code::E3012, span, msg);
                    return None;
                }
                Some(TypeRef::Ref {
                    kind,
                    target: Box::new(TypeRef::Named(Ident::new(base, span))),
                    span,
                })
            }
            // a type written out as the name (`ARRAY[1..N] OF T`, `STRING[20]`), as a script may
            // generate it for Beremiz, which copies the text into its ST: named in the message
            Some(n)
                if !n.trim().is_empty()
                    && n.trim().chars().count() <= 80
                    && !n.chars().any(char::is_control) =>
            {
                // `ARRAY [0..4999] OF INT`, as OpenPLC Editor v4 writes an array variable of an
                // ST POU into its build's plc.xml (its own compiler, matiec, reads the text as ST)
                if let Some(array) = array_text(ctx, n, ctx.attr_span(t, "name")) {
                    return Some(array);
                }
                let n = n.trim();
                let msg = format!("<derived> type name `{n}` is not a type name");
                let hint = if n.to_ascii_uppercase().starts_with("ARRAY") {
                    "PLCopen XML writes an array type as <array> with <dimension lower=.. upper=..> and <baseType>, or names a declared <dataType>"
                } else {
                    "name a declared <dataType> or a block, or write an elementary type as its element (<INT/>, <string length=..>)"
                };
                ctx.report(
                    Diagnostic::error(code::E3013, msg)
                        .at(ctx.attr_span(t, "name"))
                        .with_hint(hint),
                );
                None
            }
            _ => {
                ctx.error(code::E3013, span, "<derived> type without a valid `name`");
                None
            }
        },
        "array" => {
            let mut dims = Vec::new();
            for d in t.children_named("dimension") {
                let lo = bound(ctx, d, "lower");
                let hi = bound(ctx, d, "upper");
                match (lo, hi) {
                    (Ok(lower), Ok(upper)) => dims.push(ArrayDim {
                        lower,
                        upper,
                        span: ctx.tag(d),
                    }),
                    (Err(e), _) | (_, Err(e)) => {
                        ctx.report(*e);
                        return None;
                    }
                }
            }
            let element = type_ref(ctx, t.child("baseType")?)?;
            Some(TypeRef::Array {
                dims,
                element: Box::new(element),
                span,
            })
        }
        "enum" => {
            let values = t
                .child("values")
                .map(|v| {
                    v.children_named("value")
                        .filter_map(|e| {
                            e.attr("name").map(|n| EnumValue {
                                name: Ident::new(n, ctx.attr_span(e, "name")),
                                // TC6 XML: `<value name="run" value="10"/>`, a fixed value
                                value: e.attr("value").and_then(|v| v.trim().parse().ok()),
                            })
                        })
                        .collect()
                })
                .unwrap_or_default();
            Some(TypeRef::Enum { values, span })
        }
        "subrangeSigned" | "subrangeUnsigned" => {
            let range = t.child("range");
            let lo = range
                .and_then(|r| r.attr("lower"))
                .and_then(|v| v.trim().parse().ok());
            let hi = range
                .and_then(|r| r.attr("upper"))
                .and_then(|v| v.trim().parse().ok());
            let base = t.child("baseType").and_then(|b| b.children.first());
            let base = base.and_then(|b| elementary(b.name()).map(|n| Ident::new(n, ctx.tag(b))));
            match (lo, hi, base) {
                (Some(lower), Some(upper), Some(base)) => Some(TypeRef::Subrange {
                    base,
                    lower,
                    upper,
                    span,
                }),
                _ => {
                    ctx.error(
                        code::E3011,
                        span,
                        "subrange needs integer bounds and an elementary base type",
                    );
                    None
                }
            }
        }
        "pointer" => {
            // `<pointer><baseType>X</baseType></pointer>` (PLCopen TC6 XML 2.01)
            let base = t.child("baseType").and_then(|b| b.children.first())?;
            let target = type_element(ctx, base)?;
            Some(TypeRef::Ref {
                kind: il_frontend::ast::RefKind::Pointer,
                target: Box::new(target),
                span,
            })
        }
        other => {
            ctx.error(
                code::E3012,
                span,
                format!("type <{other}> is not supported here"),
            );
            None
        }
    }
}

/// A `<derived name>` that writes an array type out (`ARRAY [0..4999] OF INT`, `ARRAY[1..2, 0..N]
/// OF Motor`): bounds that are integer constant expressions, an element that is one elementary or
/// declared type's name. `None` for other text (E3013 then names it).
fn array_text(ctx: &Ctx, n: &str, span: diagnostics::Span) -> Option<TypeRef> {
    let t = n.trim();
    let rest = t.get(..5).filter(|a| a.eq_ignore_ascii_case("ARRAY"))?;
    let rest = t[rest.len()..].trim_start().strip_prefix('[')?;
    let (dims_text, tail) = rest.split_once(']')?;
    let tail = tail.trim_start();
    let of = tail.get(..2).filter(|o| o.eq_ignore_ascii_case("OF"))?;
    let base = tail[of.len()..].trim();
    if !tail[of.len()..].starts_with(char::is_whitespace) || !values::is_ident(base) {
        return None;
    }
    let mut dims = Vec::new();
    for d in dims_text.split(',') {
        let (lo, hi) = d.split_once("..")?;
        let int = |x: &str| values::const_int_expr(x, &|c| ctx.constant(c)).ok();
        dims.push(ArrayDim {
            lower: int(lo)?,
            upper: int(hi)?,
            span,
        });
    }
    let base = elementary(&base.to_ascii_uppercase()).unwrap_or(base);
    Some(TypeRef::Array {
        dims,
        element: Box::new(TypeRef::Named(Ident::new(base, span))),
        span,
    })
}

/// CODESYS/TwinCAT write references and pointers as a derived name (`REFERENCE TO Vehiculo`,
/// `POINTER TO INT`): which of the two, or `None` for another name.
fn is_reference(name: &str) -> Option<il_frontend::ast::RefKind> {
    let up = name.trim().to_ascii_uppercase();
    if up.starts_with("REFERENCE TO ") {
        Some(il_frontend::ast::RefKind::Reference)
    } else if up.starts_with("POINTER TO ") {
        Some(il_frontend::ast::RefKind::Pointer)
    } else {
        None
    }
}

/// The variable of an initial value `ADR(x)` / `REF(x)` (a name, an element or a field; any
/// case, blanks allowed inside the parentheses); `None` for other text.
fn address_of(text: &str, span: diagnostics::Span) -> Option<il_frontend::ast::VarRef> {
    let t = text.trim();
    let (callee, rest) = t.split_at_checked(3)?;
    if !(callee.eq_ignore_ascii_case("ADR") || callee.eq_ignore_ascii_case("REF")) {
        return None;
    }
    let inner = rest.trim_start().strip_prefix('(')?.strip_suffix(')')?;
    if inner.contains(['(', ')', '\'', '"']) {
        return None;
    }
    values::var_ref(inner, span)
}

/// Whether an initial value's text is a call of `ADR` or `REF` (of anything).
fn is_address_call(text: &str) -> bool {
    let t = text.trim();
    t.split_at_checked(3).is_some_and(|(callee, rest)| {
        (callee.eq_ignore_ascii_case("ADR") || callee.eq_ignore_ascii_case("REF"))
            && rest.trim_start().starts_with('(')
    })
}

/// `<initialValue>`: simpleValue, arrayValue, structValue.
/// `ty` is the declared type: a string variable's initial value written without its type's quotes (as v1.0
/// exports and Beremiz do: `"1234"` for a STRING) is taken as the string itself.
pub fn initial_value(ctx: &mut Ctx, holder: &Element, ty: Option<&TypeRef>) -> Option<Initializer> {
    let v = holder.children.first()?;
    value_element(ctx, v, ty)
}

fn value_element(ctx: &mut Ctx, v: &Element, ty: Option<&TypeRef>) -> Option<Initializer> {
    match v.name() {
        "simpleValue" => {
            let text = v.attr("value").unwrap_or_default();
            let span = ctx.attr_span(v, "value");
            if let Some(TypeRef::String { wide, .. }) = ty {
                // a literal only in the type's own quotes; other text is the string itself, as
                // Beremiz (OpenPLC Editor) generates it: `"1234"` for a STRING is `'"1234"'`
                if let Some(op) = values::string_as_written(text, *wide, span) {
                    return Some(Initializer::Value(op));
                }
            }
            // `ADR(x)` / `REF(x)` of a variable (CODESYS exports a declaration's `:= ADR(x)` so):
            // the address, as the ST declaration `p : POINTER TO INT := ADR(x);` reads it
            if let Some(of) = address_of(text, span) {
                return Some(Initializer::Value(il_frontend::ast::Operand::Ref(
                    Box::new(il_frontend::ast::RefOperand {
                        of: Some(of),
                        span,
                        call_scoped: false,
                        address_of: false,
                    }),
                )));
            }
            match values::operand(text, span) {
                Some(op) => {
                    if let il_frontend::ast::Operand::Literal(l) = &op {
                        if matches!(
                            l.kind,
                            il_frontend::ast::LiteralKind::TimeOfDay(_)
                                | il_frontend::ast::LiteralKind::DateAndTime(_)
                        ) && il_frontend::literal::lacks_seconds(text)
                        {
                            ctx.report(il_frontend::st::lexer::no_seconds_diagnostic(
                                span,
                                text.trim(),
                            ));
                        }
                    }
                    Some(Initializer::Value(op))
                }
                // an integer constant expression (`(BLOCK * 2)`, `((1024 * 1024) * 30)`: CODESYS
                // writes a declaration's expression so, fully parenthesised), computed now as
                // the ST reader computes `BLOCK * 2`
                None => match values::const_int_expr(text, &|n| ctx.constant(n)) {
                    Ok(n) => Some(Initializer::Value(il_frontend::ast::Operand::literal(
                        il_frontend::ast::Literal {
                            kind: il_frontend::ast::LiteralKind::Int(n),
                            type_prefix: None,
                            span,
                        },
                    ))),
                    Err(_) if is_address_call(text) => {
                        // `ADR('State')` (a literal's address, CODESYS): as the ST declaration
                        ctx.report(
                            Diagnostic::error(
                                code::E0305,
                                format!("a pointer cannot have the initial value `{}`", text.trim()),
                            )
                            .at(span)
                            .with_hint("a pointer starts as NULL or as `ADR(x)` of a variable; else set it in the body (`p := ADR(x);`)"),
                        );
                        None
                    }
                    Err(_) => {
                        ctx.error(
                            code::E3011,
                            span,
                            format!("initial value `{text}` is not a literal, a constant name or an integer constant expression"),
                        );
                        None
                    }
                },
            }
        }
        "arrayValue" => {
            let mut elems = Vec::new();
            for e in v.children_named("value") {
                let repeat = e.attr("repeatCount").and_then(|r| r.trim().parse().ok());
                let inner = e
                    .children
                    .first()
                    .and_then(|c| value_element(ctx, c, None))?;
                elems.push(ArrayInitElement {
                    repeat,
                    value: inner,
                });
            }
            Some(Initializer::Array(elems, ctx.tag(v)))
        }
        "structValue" => {
            let mut fields = Vec::new();
            for e in v.children_named("value") {
                let name = e.attr("member").unwrap_or_default();
                let span = ctx.attr_span(e, "member");
                let inner = e
                    .children
                    .first()
                    .and_then(|c| value_element(ctx, c, None))?;
                fields.push((Ident::new(name, span), inner));
            }
            Some(Initializer::Struct(fields, ctx.tag(v)))
        }
        other => {
            ctx.error(
                code::E3012,
                ctx.tag(v),
                format!("value <{other}> is not supported"),
            );
            None
        }
    }
}

/// One `<variable>` of an interface list, a struct, or a global list.
pub fn variable(ctx: &mut Ctx, v: &Element) -> Option<VarDecl> {
    let span = ctx.tag(v);
    // `name` and `address` in one pass over the start tag
    let [name, address] = v.attrs_and_ranges(["name", "address"]);
    let Some((name, (start, end))) = name
        .map(|(n, r)| (n.trim(), r))
        .filter(|(n, _)| values::is_ident(n))
    else {
        match name.map(|(n, r)| (n.trim(), r)) {
            // a name that is there but not an identifier (`Input/OutputVariable`, written by an
            // editor that does not check it): say which, at the attribute
            Some((bad, (start, end))) if !bad.is_empty() => ctx.error(
                code::E3013,
                ctx.span(start, end),
                format!(
                    "variable name `{bad}` is not an IEC 61131-3 identifier (letters, digits and `_`, not starting with a digit)"
                ),
            ),
            _ => ctx.error(code::E3013, span, "variable without a valid `name`"),
        }
        return None;
    };
    let name = Ident::new(name, ctx.span(start, end));
    let Some(ty_el) = v.child("type") else {
        ctx.error(
            code::E3013,
            span,
            format!("variable `{}` has no <type>", name.name),
        );
        return None;
    };
    let ty = type_ref(ctx, ty_el)?;
    // CODESYS exports a VAR_IN_OUT `ARRAY[*] OF T` as a pointer with vendor attributes
    let ty = crate::codesys_vla::declared_type(v, &ty).unwrap_or(ty);
    let location = match address {
        Some((a, (astart, aend))) => {
            let aspan = ctx.span(astart, aend);
            match values::address(a.trim(), aspan) {
                Some(addr) => Some(addr),
                None => {
                    ctx.error(code::E3011, aspan, format!("`{a}` is not a direct address"));
                    None
                }
            }
        }
        None => None,
    };
    let init = v
        .child("initialValue")
        .and_then(|i| initial_value(ctx, i, Some(&ty)));
    Some(VarDecl {
        name,
        location,
        ty,
        init,
        edge: None,
        span,
    })
}

/// The interface list element names and the variable kind they declare.
pub fn var_kind(list: &str) -> Option<VarKind> {
    Some(match list {
        "inputVars" => VarKind::Input,
        "outputVars" => VarKind::Output,
        "inOutVars" => VarKind::InOut,
        "localVars" => VarKind::Local,
        "tempVars" => VarKind::Temp,
        "externalVars" => VarKind::External,
        "globalVars" => VarKind::Global,
        _ => return None,
    })
}

/// An array bound: an integer literal, or a constant expression over named integer constants
/// (`ciCount`, `MAX_AXES - 1`), as CODESYS and TwinCAT exports write them.
fn bound(ctx: &Ctx, d: &Element, attr: &str) -> Result<i128, Box<Diagnostic>> {
    let span = ctx.attr_span(d, attr);
    let Some(text) = d.attr(attr) else {
        return Err(Box::new(
            Diagnostic::error(
                code::E3011,
                format!("array dimension without a `{attr}` bound"),
            )
            .at(span),
        ));
    };
    values::const_int_expr(text, &|n| ctx.constant(n)).map_err(|why| {
        let unknown = why.starts_with("unknown");
        let c = if unknown { code::E3401 } else { code::E3011 };
        Box::new(Diagnostic::error(c, format!("array bound `{}`: {why}", text.trim())).at(span)
            .with_hint(if unknown {
                "declare it as an integer constant (VAR_GLOBAL CONSTANT or VAR CONSTANT) with an initial value"
            } else {
                "write an integer, or an expression of integer constants with + - * / and parentheses"
            }))
    })
}

/// The integer constants declared by the `constant="true"` lists under `scope` (a POU's interface,
/// or the whole project for the global ones), evaluated in declaration order; a constant may use the
/// ones before it. Values that are not integer constant expressions are skipped. A named list's
/// constants are found by name and qualified by the list's name (`GVL.N`, upper-case).
pub fn collect_constants(
    scope: &Element,
    deep: bool,
    lookup: &dyn Fn(&str) -> Option<i128>,
) -> HashMap<String, i128> {
    let mut found: HashMap<String, i128> = HashMap::new();
    let mut stack = vec![scope];
    while let Some(e) = stack.pop() {
        for c in e.children.iter().rev() {
            let is_list = c.name().ends_with("Vars") || c.name() == "varList";
            if is_list
                && c.attr("constant")
                    .is_some_and(|v| v.trim() == "true" || v.trim() == "1")
            {
                for v in c.children_named("variable") {
                    let (Some(name), Some(value)) = (
                        v.attr("name"),
                        v.child("initialValue")
                            .and_then(|i| i.child("simpleValue"))
                            .and_then(|s| s.attr("value")),
                    ) else {
                        continue;
                    };
                    let key = name.trim().to_ascii_uppercase();
                    let val = values::const_int_expr(value, &|n| {
                        found
                            .get(&n.to_ascii_uppercase())
                            .copied()
                            .or_else(|| lookup(n))
                    });
                    if let Ok(x) = val {
                        // a CODESYS/TwinCAT list's constant is also reached qualified, `GVL.N`
                        if let Some(list) = c.attr("name").map(str::trim).filter(|l| !l.is_empty())
                        {
                            found.insert(format!("{}.{key}", list.to_ascii_uppercase()), x);
                        }
                        found.insert(key, x);
                    }
                }
                if deep {
                    // CODESYS nests the list's CONSTANT section in the list's own vendor data
                    // (`mixedattrsvarlist`)
                    stack.push(c);
                }
            } else if deep && c.name() != "pou" {
                // a POU's own constants are local to it
                stack.push(c);
            }
        }
    }
    found
}

/// A variable list element (`<localVars constant="true" retain="true">...`) as a [`VarBlock`] of `kind`,
/// one declaration per `<variable>`.
pub fn var_block(ctx: &mut Ctx, list: &Element, kind: VarKind) -> VarBlock {
    let flag = |n: &str| {
        list.attr(n)
            .is_some_and(|v| v.trim() == "true" || v.trim() == "1")
    };
    // Sized once (a 10,000-rung program declares 32,500 variables in one list): no regrowth copies.
    let mut vars = Vec::with_capacity(list.children.len());
    vars.extend(
        list.children_named("variable")
            .filter_map(|v| variable(ctx, v)),
    );
    // a CODESYS/TwinCAT global variable list has a name (`GVL.x` reaches its members)
    let name = if kind == VarKind::Global {
        list.attr("name")
            .map(str::trim)
            .filter(|n| values::is_ident(n))
            .map(|n| Ident::new(n, ctx.attr_span(list, "name")))
    } else {
        None
    };
    VarBlock {
        access: None,
        name,
        kind,
        constant: flag("constant"),
        retain: flag("retain") || flag("persistent"),
        vars,
        span: ctx.tag(list),
    }
}

/// A `<globalVars>` list as declaration blocks. CODESYS exports a list that mixes `VAR_GLOBAL`,
/// `VAR_GLOBAL CONSTANT` and `VAR_GLOBAL RETAIN` sections as one list with one set of attributes (often
/// `constant="true"` on them all) and puts the real split into its vendor data
/// (`addData/data[.../mixedattrsvarlist]/MixedAttrsVarList/globalVars`, one list per section, same
/// name): those sections are read instead when present.
pub fn global_lists(ctx: &mut Ctx, list: &Element) -> Vec<VarBlock> {
    let sections: Vec<&Element> = list
        .child("addData")
        .into_iter()
        .flat_map(|a| a.children_named("data"))
        .filter(|d| {
            d.attr("name")
                .is_some_and(|n| n.ends_with("/mixedattrsvarlist"))
        })
        .flat_map(|d| d.children_named("MixedAttrsVarList"))
        .flat_map(|m| m.children_named("globalVars"))
        .collect();
    if sections.is_empty() {
        return vec![var_block(ctx, list, VarKind::Global)];
    }
    sections
        .into_iter()
        .map(|g| var_block(ctx, g, VarKind::Global))
        .collect()
}

/// A CODESYS V3 UNION, exported in vendor data as
/// `<data name=".../plcopenxml/union"><union name="U"><variable .../>...</union>` (TC6 has no
/// union type): the same declaration as `TYPE U : UNION ... END_UNION` in ST.
pub fn union_type(ctx: &mut Ctx, u: &Element) -> Option<TypeDecl> {
    let span = ctx.tag(u);
    let Some(name) = u
        .attr("name")
        .map(str::trim)
        .filter(|n| values::is_ident(n))
    else {
        ctx.error(code::E3013, span, "union without a valid `name`");
        return None;
    };
    let name = Ident::new(name, ctx.attr_span(u, "name"));
    let fields = u
        .children_named("variable")
        .filter_map(|v| variable(ctx, v))
        .collect();
    Some(TypeDecl {
        name,
        def: TypeDef::Struct { fields },
        union: true,
        span,
    })
}

/// `<dataType name="...">` with its `<baseType>` and optional `<initialValue>`.
pub fn data_type(ctx: &mut Ctx, d: &Element) -> Option<TypeDecl> {
    let span = ctx.tag(d);
    let Some(name) = d
        .attr("name")
        .map(str::trim)
        .filter(|n| values::is_ident(n))
    else {
        ctx.error(code::E3013, span, "data type without a valid `name`");
        return None;
    };
    let name = Ident::new(name, ctx.attr_span(d, "name"));
    let Some(base) = d.child("baseType").and_then(|b| b.children.first()) else {
        ctx.error(
            code::E3013,
            span,
            format!("data type `{}` has no <baseType>", name.name),
        );
        return None;
    };
    let init = d
        .child("initialValue")
        .and_then(|i| initial_value(ctx, i, None));
    let def = match base.name() {
        "struct" => TypeDef::Struct {
            fields: base
                .children_named("variable")
                .filter_map(|v| variable(ctx, v))
                .collect(),
        },
        "enum" => {
            let values = base
                .child("values")
                .map(|vs| {
                    vs.children_named("value")
                        .filter_map(|e| {
                            let n = e.attr("name")?;
                            Some(EnumValue {
                                name: Ident::new(n, ctx.attr_span(e, "name")),
                                value: e.attr("value").and_then(|x| x.trim().parse().ok()),
                            })
                        })
                        .collect()
                })
                .unwrap_or_default();
            let init = match init {
                Some(Initializer::Value(il_frontend::ast::Operand::Var(v))) => Some(v.base),
                Some(Initializer::Value(il_frontend::ast::Operand::EnumValue(e))) => Some(e.value),
                _ => None,
            };
            TypeDef::Enum { values, init }
        }
        _ => TypeDef::Alias {
            ty: type_element(ctx, base)?,
            init,
        },
    };
    Some(TypeDecl {
        name,
        def,
        union: false,
        span,
    })
}
