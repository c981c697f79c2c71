//! The time and date functions called by their typed names: `ADD_TIME`, `SUB_DT_DT`, `MUL_TIME` ...
//! (the `TIME_ARITH` overloads of ADD/SUB/MUL/DIV), `CONCAT_DATE_TOD` and `CONCAT_LDATE_LTOD`.
//!
//! Input: the function's name and its evaluated arguments with their IEC types. Output: one
//! side-effect-free C expression of the result type. Invariants: a named overload computes exactly what
//! the generic operator computes on the same types (it goes through the same `std_binary`), so
//! `ADD_TIME(a, b)` and `LD a ADD b` never differ; every time and date is int64 nanoseconds, so
//! `CONCAT_DATE_TOD` is the sum of the day's midnight and the time of day.

use super::Gen;
use diagnostics::Span;
use il_frontend::sema::{stdlib, Type};

/// Whether `name` is a typed time/date function this module emits.
pub fn is_datetime_function(name: &str) -> bool {
    name == "CONCAT_DATE_TOD"
        || name == "CONCAT_LDATE_LTOD"
        || stdlib::TIME_ARITH.iter().any(|t| t.0 == name)
}

impl Gen<'_> {
    pub(super) fn datetime_call(
        &mut self,
        span: Span,
        name: &str,
        vals: &[String],
        tys: &[Type],
        result: &Type,
    ) -> Option<String> {
        let ([a, b], [at, bt]) = (vals, tys) else {
            self.unsupported(span, format!("{name} with {} inputs", vals.len()));
            return None;
        };
        if name == "CONCAT_DATE_TOD" || name == "CONCAT_LDATE_LTOD" {
            return Some(format!(
                "((IEC_DT)(uint64_t)((uint64_t)({a}) + (uint64_t)({b})))"
            ));
        }
        let op = stdlib::TIME_ARITH.iter().find(|t| t.0 == name)?.1;
        self.std_binary(span, op, a, at, b, bt, result)
    }
}
