//! The data-size check: every variable, every POU's data and the program's static data against the
//! target profile's memory budget (`data_bytes`), before any C is generated.
//!
//! Input: the sema model and the profile. Output: E2100 diagnostics (located at the variable or POU
//! declaration), `false` when any was reported. Invariants: sizes are computed in `u64` with checked
//! arithmetic (an overflow is reported as too large, never wraps); nested types (structs in structs,
//! FB instances in FBs) are sized once each with an explicit stack, so nesting depth costs no stack.
//! Sizes are those of the generated C up to padding: BOOL 1 byte, STRING[n] n + 1 bytes (WSTRING
//! 2n + 2), enums 4, an IN_OUT a pointer (8), a standard FB its inputs, outputs and 32 bytes of state.

use crate::profile::TargetProfile;
use diagnostics::{code, Diagnostic, Diagnostics, Span};
use il_frontend::ast::{PouKind, VarKind};
use il_frontend::sema::{FbType, Model, Type, UserTypeDef, Variable};
use std::collections::{HashMap, HashSet};

/// A struct type or a user FB whose size depends on its members.
#[derive(Clone, Copy, PartialEq, Eq, Hash)]
enum Key {
    Struct(usize),
    Fb(usize),
}

/// `None`: the size does not fit in `u64`.
type Size = Option<u64>;

struct Sizer<'m> {
    model: &'m Model,
    memo: HashMap<Key, Size>,
}

impl Sizer<'_> {
    /// The size of `ty`, or `Err(key)` when it needs `key`, not sized yet.
    fn try_size(&self, ty: &Type) -> Result<Size, Key> {
        Ok(match ty {
            Type::Elementary(e) => Some(u64::from(e.size_bytes())),
            Type::Ref(_) => Some(16),
            Type::String { wide, len } => {
                let unit = if *wide { 2 } else { 1 };
                u64::from(*len)
                    .checked_add(1)
                    .and_then(|n| n.checked_mul(unit))
            }
            Type::Array { dims, element } => {
                let mut n = self.try_size(element)?;
                for d in dims {
                    n = n.and_then(|n| u64::try_from(d.len()).ok()?.checked_mul(n));
                }
                n
            }
            Type::Struct(id) => self.known(Key::Struct(id.0 as usize))?,
            Type::Enum(_) => Some(4),
            Type::Subrange { base, .. } => Some(u64::from(base.size_bytes())),
            Type::Fb(FbType::Standard(fb)) => {
                let params = il_frontend::sema::stdlib::fb_params(*fb);
                Some(
                    params
                        .iter()
                        .map(|p| u64::from(p.ty.size_bytes()))
                        .sum::<u64>()
                        + 32,
                )
            }
            Type::Fb(FbType::User(id)) => self.known(Key::Fb(id.0 as usize))?,
            Type::Error => Some(0),
        })
    }

    fn known(&self, k: Key) -> Result<Size, Key> {
        self.memo.get(&k).copied().ok_or(k)
    }

    /// The members of a struct or FB instance (a FB's temporaries and externals take no room).
    fn members(&self, k: Key) -> Vec<&Variable> {
        match k {
            Key::Struct(i) => match self.model.types.get(i).map(|t| &t.def) {
                Some(UserTypeDef::Struct { fields }) => fields.iter().collect(),
                _ => Vec::new(),
            },
            Key::Fb(i) => self.model.pous.get(i).map_or(Vec::new(), |p| {
                p.vars
                    .iter()
                    .filter(|v| !matches!(v.kind, VarKind::Temp | VarKind::External))
                    .collect()
            }),
        }
    }

    fn var_size(&self, v: &Variable) -> Result<Size, Key> {
        if v.kind == VarKind::InOut {
            return Ok(Some(8));
        }
        self.try_size(&v.ty)
    }

    /// Sizes `ty`, first sizing every struct and FB it depends on (an explicit stack; a key met
    /// again while still open is a recursive type, which sema reports: it counts 0 here).
    fn size(&mut self, ty: &Type) -> Size {
        let mut stack: Vec<Key> = Vec::new();
        // The keys on `stack`, for a constant-time cycle test (a chain of nested types is as long as
        // the program makes it: a linear search of the stack was quadratic in its length).
        let mut open: HashSet<Key> = HashSet::new();
        loop {
            let needed = match stack.last() {
                None => match self.try_size(ty) {
                    Ok(s) => return s,
                    Err(k) => k,
                },
                Some(&top) => {
                    let mut total: Size = Some(0);
                    let mut missing = None;
                    for v in self.members(top) {
                        match self.var_size(v) {
                            Ok(s) => total = total.and_then(|t| t.checked_add(s?)),
                            Err(k) => {
                                missing = Some(k);
                                break;
                            }
                        }
                    }
                    match missing {
                        None => {
                            self.memo.insert(top, total);
                            stack.pop();
                            open.remove(&top);
                            continue;
                        }
                        Some(k) => k,
                    }
                }
            };
            if open.contains(&needed) {
                self.memo.insert(needed, Some(0));
            } else {
                open.insert(needed);
                stack.push(needed);
            }
        }
    }
}

fn too_large(what: String, size: Size, budget: u64, span: Span, label: &str) -> Diagnostic {
    let msg = match size {
        Some(n) => {
            format!("{what} needs {n} bytes, more than the target's data budget of {budget} bytes")
        }
        None => format!("{what} is too large: its size in bytes overflows a 64-bit count"),
    };
    Diagnostic::error(code::E2100, msg)
        .at(span)
        .with_primary_label(label.to_string())
        .with_hint("make the array smaller, or raise `data_bytes` in the target profile (--profile FILE.json)")
}

/// Checks the data sizes; reports E2100 and returns `false` when something does not fit.
pub fn check(model: &Model, profile: &TargetProfile, diags: &mut Diagnostics) -> bool {
    let budget = profile.data_bytes;
    let mut sizer = Sizer {
        model,
        memo: HashMap::new(),
    };
    let start = diags.error_count();
    let check_var = |sizer: &mut Sizer, v: &Variable, diags: &mut Diagnostics| -> Size {
        let s = if v.kind == VarKind::InOut {
            Some(8)
        } else {
            sizer.size(&v.ty)
        };
        if s.is_none_or(|n| n > budget) {
            diags.push(too_large(
                format!("variable `{}`", v.name),
                s,
                budget,
                v.span,
                "declared here",
            ));
        }
        s
    };
    // static data: globals and program instances
    let mut total: Size = Some(0);
    let mut biggest: Option<(u64, Span, String)> = None;
    let mut count = |s: Size, span: Span, name: &str, total: &mut Size| {
        *total = total.and_then(|t| t.checked_add(s?));
        if let Some(n) = s {
            if biggest.as_ref().is_none_or(|b| n > b.0) {
                biggest = Some((n, span, name.to_string()));
            }
        }
    };
    let mut globals: Vec<&Variable> = model.globals.iter().collect();
    for c in &model.configurations {
        globals.extend(&c.globals);
        for r in &c.resources {
            globals.extend(&r.globals);
        }
    }
    for g in globals {
        let s = check_var(&mut sizer, g, diags);
        count(s, g.span, &g.name, &mut total);
    }
    for p in &model.pous {
        let mut own: Size = Some(0);
        let mut reported = false;
        for v in &p.vars {
            if v.kind == VarKind::External {
                continue;
            }
            let before = diags.error_count();
            let s = check_var(&mut sizer, v, diags);
            reported |= diags.error_count() > before;
            own = own.and_then(|o| o.checked_add(s?));
        }
        if !reported && own.is_none_or(|n| n > budget) {
            diags.push(too_large(
                format!("the data of `{}`", p.name),
                own,
                budget,
                p.span,
                "its variables together are too large",
            ));
            reported = true;
        }
        if p.kind == PouKind::Program && !reported {
            count(own, p.span, &p.name, &mut total);
        }
    }
    if diags.error_count() == start && total.is_none_or(|n| n > budget) {
        if let Some((_, span, name)) = biggest {
            diags.push(
                too_large(
                    "the program's static data".to_string(),
                    total,
                    budget,
                    span,
                    "",
                )
                .with_primary_label(format!("the largest part: `{name}`")),
            );
        }
    }
    diags.error_count() == start
}
