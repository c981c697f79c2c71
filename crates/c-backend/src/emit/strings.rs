//! The standard character string functions (LEN, LEFT, RIGHT, MID, CONCAT, INSERT, DELETE, REPLACE,
//! FIND, and MAX, MIN, LIMIT on strings) as calls of the runtime's `ladderc_str_*` (STRING) and `ladderc_wstr_*` (WSTRING) functions.
//!
//! Input: the function's name, its generic string type and the already-evaluated C arguments with their
//! IEC types. Output: one side-effect-free C expression (a string value, or `IEC_INT` for LEN and FIND).
//! Invariants: lengths and positions are passed as `int64_t` (so every integer type keeps its value up
//! to LINT range, negative values included: the runtime flags them); CONCAT, MAX and MIN of n inputs
//! fold left over the binary runtime function; results are at most the 254-unit capacity and are truncated to the
//! declared length only where they are stored (the common store path).

use super::Gen;
use diagnostics::Span;
use il_frontend::sema::{Elementary, Type};

/// `STRING_TO_DATE`, `STRING_TO_TOD`, `STRING_TO_DT` (and their long forms `STRING_TO_LDT` ...) of
/// the C string value `v` (`t` is the target).
pub fn string_to_datetime(v: &str, t: Elementary) -> String {
    let f = match t {
        Elementary::Date => "date",
        Elementary::Tod => "tod",
        Elementary::Ldate => "ldate",
        Elementary::Ltod => "ltod",
        Elementary::Ldt => "ldt",
        _ => "dt",
    };
    format!("ladderc_str_to_{f}({v})")
}

/// Whether this module emits `name` for generic type `ty`: the string functions, and MAX, MIN, LIMIT
/// on strings.
pub fn is_string_function(name: &str, ty: &Type) -> bool {
    matches!(
        name,
        "LEN" | "LEFT" | "RIGHT" | "MID" | "CONCAT" | "INSERT" | "DELETE" | "REPLACE" | "FIND"
    ) || (ty.is_string() && matches!(name, "MAX" | "MIN" | "LIMIT"))
}

impl Gen<'_> {
    /// A string function call on evaluated arguments `vals` of types `tys`; `ty` is the generic type.
    pub(super) fn string_call(
        &mut self,
        span: Span,
        name: &str,
        ty: &Type,
        vals: &[String],
        tys: &[Type],
    ) -> Option<String> {
        let string_ty = if ty.is_string() {
            ty
        } else {
            tys.iter().find(|t| t.is_string())?
        };
        let prefix = match string_ty {
            Type::String { wide: true, .. } => "ladderc_wstr",
            _ => "ladderc_str",
        };
        let arity = match name {
            "LEN" => 1,
            "LEFT" | "RIGHT" | "FIND" | "CONCAT" | "MAX" | "MIN" => 2,
            "MID" | "DELETE" | "INSERT" | "LIMIT" => 3,
            _ => 4,
        };
        let extensible = matches!(name, "CONCAT" | "MAX" | "MIN");
        if vals.len() < arity || (!extensible && vals.len() != arity) {
            self.unsupported(span, format!("{name} with {} inputs", vals.len()));
            return None;
        }
        let f = name.to_ascii_lowercase();
        // Which arguments are integers (lengths, positions).
        let int_args: &[usize] = match name {
            "LEFT" | "RIGHT" => &[1],
            "MID" | "DELETE" => &[1, 2],
            "INSERT" => &[2],
            "REPLACE" => &[2, 3],
            _ => &[],
        };
        let args: Vec<String> = vals
            .iter()
            .enumerate()
            .map(|(i, v)| {
                if int_args.contains(&i) {
                    format!("(int64_t)({v})")
                } else {
                    v.clone()
                }
            })
            .collect();
        if extensible {
            let mut acc = args[0].clone();
            for a in &args[1..] {
                acc = format!("{prefix}_{f}({acc}, {a})");
            }
            return Some(acc);
        }
        Some(format!("{prefix}_{f}({})", args.join(", ")))
    }
}
