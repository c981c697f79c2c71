//! Initial values: C statements that give a zeroed variable its IEC initial value.
//!
//! Input: a C lvalue (already zeroed by `memset` or static storage), its type, the declared initial value.
//! Output: assignments for the non-zero parts only (element-wise for arrays, field-wise for structs, the
//! INIT function plus parameter values for FB instances; a run of equal array values is one loop). Invariants:
//! output size is proportional to the distinct runs of the declared initialisers (a repeat `[n(v)]` costs
//! one loop, not n assignments) and the number of FB/struct elements needing non-zero defaults.

use super::Gen;
use crate::{ctypes, mangle};
use diagnostics::Span;
use il_frontend::sema::{AddressStep, ConstValue, FbType, Type, UserTypeDef};
use std::fmt::Write as _;

/// A run of at least this many equal initial values in an array is written as one loop.
const INIT_LOOP_RUN: usize = 8;

/// At least this many initial values in a row, of an array of an elementary type, that are not in a run
/// are written as one `static const` table and one copy loop. C compilers are superlinear in the length
/// of one function: 100,000 assignments in an INIT function did not compile in a minute; a table
/// compiles in linear time.
const INIT_TABLE_MIN: usize = 64;

impl Gen<'_> {
    /// Whether a zeroed value of `ty` differs from its IEC default.
    pub fn needs_default_init(&self, ty: &Type) -> bool {
        match ty {
            Type::Array { element, .. } => self.needs_default_init(element),
            Type::Struct(id) => match &self.model.user_type(*id).def {
                UserTypeDef::Struct { fields } => fields
                    .iter()
                    .any(|f| f.init.is_some() || self.needs_default_init(&f.ty)),
                _ => false,
            },
            Type::Enum(id) => match &self.model.user_type(*id).def {
                UserTypeDef::Enum { values, default } => {
                    values.get(*default).is_some_and(|v| v.1 != 0)
                }
                _ => false,
            },
            Type::Subrange { lower, upper, .. } => **lower > 0 || **upper < 0,
            Type::Fb(FbType::User(_)) => true,
            // NULL need not be all zero bits in C
            Type::Ref(_) => true,
            _ => false,
        }
    }

    pub fn init_value(
        &mut self,
        out: &mut String,
        indent: usize,
        lv: &str,
        ty: &Type,
        init: Option<&ConstValue>,
        span: Span,
    ) {
        let pad = "    ".repeat(indent);
        match (ty, init) {
            // `p : POINTER TO INT := ADR(a);`: `a` is a variable of the same POU, so its C lvalue
            // is the reference's own with the last name replaced (sema: `address_init`)
            (Type::Ref(_), Some(ConstValue::Address(a))) => {
                // of an instance's input (`fbM : FB_M := (pLamp := ADR(lamp))`): the lvalue ends
                // with the instance's name and the fields to the reference
                let mut own = mangle::var(&a.of_var);
                for f in &a.within {
                    if f.starts_with('[') {
                        // an array's element, its zero-based subscripts (`[1]`)
                        own.push_str(f);
                    } else {
                        let _ = write!(own, ".{}", mangle::var(f));
                    }
                }
                // of a global variable: its own C name (`ADR(GVL.lamp)`)
                let mut target = match a.global {
                    Some(g) => self.global_name(g),
                    None => {
                        let Some(prefix) = lv.strip_suffix(own.as_str()) else {
                            self.unsupported(span, "this address as an initial value");
                            let _ = writeln!(out, "{pad}{lv} = ladderc_ref(NULL, 0);");
                            return;
                        };
                        cfmt!("{prefix}{}", mangle::var(&a.base))
                    }
                };
                // the array of the last index, which a reference to an element is made from (as
                // `ADR(a[i])` in a body: refs.rs)
                let mut whole = None;
                for step in &a.steps {
                    match step {
                        AddressStep::Field(f) => {
                            let _ = write!(target, ".{}", mangle::var(f));
                        }
                        AddressStep::Index(offsets) => {
                            whole = Some(target.clone());
                            for o in offsets {
                                let _ = write!(target, "[{o}]");
                            }
                        }
                    }
                }
                let _ = match whole {
                    Some(w) => writeln!(
                        out,
                        "{pad}{lv} = ladderc_ref_in((void *)&{w}, sizeof {w}, (const void *)&{target});"
                    ),
                    None => writeln!(
                        out,
                        "{pad}{lv} = ladderc_ref((void *)&{target}, sizeof {target});"
                    ),
                };
            }
            (Type::Ref(_), _) => {
                let _ = writeln!(out, "{pad}{lv} = ladderc_ref(NULL, 0);");
            }
            (Type::Fb(fb), init) => {
                match fb {
                    FbType::Standard(f) => {
                        let _ = writeln!(out, "{pad}{}_init(&{lv});", ctypes::std_fb(*f).0);
                    }
                    FbType::User(id) => {
                        let _ = writeln!(
                            out,
                            "{pad}{}_INIT(&{lv});",
                            mangle::fb(&self.model.pou(*id).name)
                        );
                    }
                }
                if let Some(ConstValue::Struct(params)) = init {
                    for (name, v) in params {
                        let (field, fty) = match fb {
                            FbType::Standard(f) => {
                                match ctypes::std_fb(*f)
                                    .1
                                    .iter()
                                    .find(|p| p.0.eq_ignore_ascii_case(name))
                                {
                                    Some(p) => (format!("{lv}.{}", p.0), Type::Elementary(p.1)),
                                    None => continue,
                                }
                            }
                            FbType::User(id) => match self.pou_var(*id, name) {
                                Some(var) => {
                                    (format!("{lv}.{}", mangle::var(&var.name)), var.ty.clone())
                                }
                                None => continue,
                            },
                        };
                        self.init_value(out, indent, &field, &fty, Some(v), span);
                    }
                }
            }
            (Type::Struct(id), init) => {
                let UserTypeDef::Struct { fields } = self.model.user_type(*id).def.clone() else {
                    return;
                };
                let given: &[(String, ConstValue)] = match init {
                    Some(ConstValue::Struct(v)) => v,
                    _ => &[],
                };
                for f in &fields {
                    let v = given
                        .iter()
                        .find(|(n, _)| n.eq_ignore_ascii_case(&f.name))
                        .map(|x| &x.1)
                        .or(f.init.as_ref());
                    if v.is_none() && !self.needs_default_init(&f.ty) {
                        continue;
                    }
                    let field = format!("{lv}.{}", mangle::var(&f.name));
                    self.init_value(out, indent, &field, &f.ty, v, span);
                }
            }
            (Type::Array { dims, element }, init) => {
                let lens: Vec<u128> = dims.iter().map(|d| d.len().max(1)).collect();
                if self.needs_default_init(element) {
                    // a loop nest giving every element its default
                    let mut e = lv.to_string();
                    let _ = writeln!(out, "{pad}{{");
                    for d in 0..lens.len() {
                        let _ = writeln!(out, "{pad}    size_t i_{indent}_{d};");
                        let _ = write!(e, "[i_{indent}_{d}]");
                    }
                    for (d, len) in lens.iter().enumerate() {
                        let _ = writeln!(
                            out,
                            "{pad}    for (i_{indent}_{d} = 0; i_{indent}_{d} < {len}u; i_{indent}_{d}++)"
                        );
                    }
                    let mut inner = String::new();
                    self.init_value(&mut inner, indent + 2, &e, element, None, span);
                    let _ = writeln!(out, "{pad}    {{\n{inner}{pad}    }}");
                    let _ = writeln!(out, "{pad}}}");
                }
                if let Some(ConstValue::Array(elems)) = init {
                    let total: u128 = lens.iter().product();
                    let elems = &elems[..elems
                        .len()
                        .min(usize::try_from(total).unwrap_or(usize::MAX))];
                    // Equal values in a row (`[2000000(7)]`) become one loop over their row-major
                    // positions, so that the C stays proportional to the distinct runs, not to the
                    // array's length.
                    // row-major index expression of position `r` (a C expression) in the array
                    let element_at = |r: &str| row_major_element(lv, r, &lens);
                    // values not in a run, waiting to be written: from position `single_from`
                    let mut single_from = 0;
                    let mut k = 0;
                    while k <= elems.len() {
                        let run = elems
                            .get(k)
                            .map_or(0, |v| elems[k..].iter().take_while(|x| *x == v).count());
                        if run >= INIT_LOOP_RUN || k == elems.len() {
                            self.init_singles(
                                out,
                                indent,
                                lv,
                                &lens,
                                element,
                                single_from,
                                &elems[single_from..k],
                                span,
                            );
                        }
                        if k == elems.len() {
                            break;
                        }
                        if run >= INIT_LOOP_RUN {
                            let v = &elems[k];
                            let r = format!("r_{indent}");
                            let el = element_at(&r);
                            let _ = writeln!(out, "{pad}{{");
                            let _ = writeln!(out, "{pad}    size_t {r};");
                            let _ = writeln!(
                                out,
                                "{pad}    for ({r} = {k}u; {r} < {}u; {r}++)",
                                k + run
                            );
                            let mut inner = String::new();
                            self.init_value(&mut inner, indent + 2, &el, element, Some(v), span);
                            let _ = writeln!(out, "{pad}    {{\n{inner}{pad}    }}");
                            let _ = writeln!(out, "{pad}}}");
                            single_from = k + run;
                        }
                        k += run;
                    }
                }
            }
            (Type::String { wide: false, .. }, Some(ConstValue::String { value, .. })) => {
                let bytes = ctypes::single_bytes(value);
                let _ = writeln!(
                    out,
                    "{pad}ladderc_string_set(&{lv}, {}, {}, {});",
                    mangle::c_string(&bytes),
                    bytes.len(),
                    ctypes::string_cap(ty)
                );
            }
            (Type::String { wide: true, .. }, Some(ConstValue::String { value, .. })) => {
                let (array, len) = ctypes::utf16_array(value);
                let _ = writeln!(
                    out,
                    "{pad}ladderc_wstring_set(&{lv}, {array}, {len}, {});",
                    ctypes::string_cap(ty)
                );
            }
            (Type::String { .. }, _) => {}
            (Type::Enum(id), v) => {
                let value = match v {
                    Some(ConstValue::Enum { ty, index }) => {
                        ctypes::enum_value(self.model, *ty, *index)
                    }
                    Some(ConstValue::Int(i)) => Some(*i),
                    _ => match &self.model.user_type(*id).def {
                        UserTypeDef::Enum { values, default } => values.get(*default).map(|x| x.1),
                        _ => None,
                    },
                };
                if let Some(v) = value.filter(|v| *v != 0) {
                    let _ = writeln!(
                        out,
                        "{pad}{lv} = {};",
                        ctypes::int_literal(il_frontend::sema::Elementary::Dint, v)
                    );
                }
            }
            (t, v) => {
                let Some(e) = t.elementary() else { return };
                let v = match (v, t) {
                    (Some(v), _) => ctypes::const_elementary(self.model, e, v),
                    (None, Type::Subrange { lower, upper, .. }) if **lower > 0 || **upper < 0 => {
                        Some(ctypes::int_literal(e, **lower))
                    }
                    _ => None,
                };
                match v {
                    Some(v) => {
                        let _ = writeln!(out, "{pad}{lv} = {v};");
                    }
                    None if init.is_some() => {
                        self.unsupported(span, "this initial value");
                    }
                    None => {}
                }
            }
        }
    }
}

impl Gen<'_> {
    /// The initial values `values` of array `lv` (dimensions `lens`) from row-major position `from`, none
    /// of them in a run: one assignment each, or for [`INIT_TABLE_MIN`] or more of an elementary type, one
    /// `static const` table and one copy loop.
    #[allow(clippy::too_many_arguments)]
    fn init_singles(
        &mut self,
        out: &mut String,
        indent: usize,
        lv: &str,
        lens: &[u128],
        element: &Type,
        from: usize,
        values: &[ConstValue],
        span: Span,
    ) {
        let pad = "    ".repeat(indent);
        let table: Option<Vec<String>> = match element {
            Type::Elementary(e) if values.len() >= INIT_TABLE_MIN => values
                .iter()
                .map(|v| ctypes::const_elementary(self.model, *e, v))
                .collect(),
            _ => None,
        };
        if let (Some(table), Type::Elementary(e)) = (table, element) {
            let (r, t) = (format!("r_{indent}"), format!("t_{indent}"));
            let el = row_major_element(lv, &r, lens);
            let _ = writeln!(out, "{pad}{{");
            let _ = writeln!(
                out,
                "{pad}    static const {} {t}[{}] = {{",
                ctypes::elementary(*e),
                table.len()
            );
            for chunk in table.chunks(8) {
                let _ = writeln!(out, "{pad}        {},", chunk.join(", "));
            }
            let _ = writeln!(out, "{pad}    }};");
            let _ = writeln!(out, "{pad}    size_t {r};");
            let _ = writeln!(
                out,
                "{pad}    for ({r} = {from}u; {r} < {}u; {r}++)",
                from + table.len()
            );
            let _ = writeln!(out, "{pad}        {el} = {t}[{r} - {from}u];");
            let _ = writeln!(out, "{pad}}}");
            return;
        }
        for (j, v) in values.iter().enumerate() {
            // row-major index decomposition
            let mut rest = (from + j) as u128;
            let mut el = lv.to_string();
            let mut idx = vec![0u128; lens.len()];
            for (d, len) in lens.iter().enumerate().rev() {
                idx[d] = rest % len;
                rest /= len;
            }
            for i in &idx {
                let _ = write!(el, "[{i}]");
            }
            self.init_value(out, indent, &el, element, Some(v), span);
        }
    }
}

/// The element of array `lv` (dimension lengths `lens`) at row-major position `r`, a C expression:
/// `lv[(r / stride) % len]...`, one subscript per dimension.
fn row_major_element(lv: &str, r: &str, lens: &[u128]) -> String {
    let mut el = lv.to_string();
    let mut stride: u128 = 1;
    let mut subs = Vec::new();
    for len in lens.iter().rev() {
        subs.push(format!("[({r} / {stride}u) % {len}u]"));
        stride = stride.saturating_mul(*len);
    }
    for sub in subs.iter().rev() {
        el.push_str(sub);
    }
    el
}
