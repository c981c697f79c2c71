//! The IEC operators of TwinCAT 3's graphical bodies (LD, FBD, CFC) under the names TwinCAT saves.
//!
//! An operator box shows what the engineer typed into it: the IEC operator's name (`SUB`, `GT`) or
//! its ST symbol (`-`, `>`); both name the same operator (Beckhoff Infosys, TC3 PLC, "Arithmetic
//! operators" / "Comparison operators": `SUB` is ST's `-`, `GT` is `>`). The LD/FBD archive saves
//! the box's text as `BoxType` and the operator as `CallType`, which differs between versions and
//! spellings: `Sub`, `Gt` (3.1.4024 and later, an IEC-named box), `Minus` beside a `-` box (3.1.4024
//! and 3.1.4026), `Greater`, `Equal` (3.1.4022). A CFC box saves only its text.
//!
//! Input: a box's text (the CFC box's type, the LD/FBD `BoxType`) and, for LD/FBD, its `CallType`.
//! Output: the IEC operator the box computes: [`iec_name`] upper-case (`SUB`), [`call_type`] as the
//! short call type the network reader knows (`Sub`).
//! Invariants: an operator symbol is read as its operator whatever long call type is beside it (a
//! symbol never names a function, function block, method or program: those call types are kept);
//! a long comparison call type is read as its operator only when the box's text names the same
//! operator; anything else is returned unchanged, so that the caller reports it (E0325/E0326).

/// One IEC operator: its name, its ST symbol, the short call type TwinCAT writes for it, and the
/// long call types earlier versions write beside its IEC name.
struct Operator {
    iec: &'static str,
    symbol: Option<&'static str>,
    short: &'static str,
    long: &'static [&'static str],
}

const OPERATORS: &[Operator] = &[
    Operator {
        iec: "ADD",
        symbol: Some("+"),
        short: "Add",
        long: &["Plus"],
    },
    Operator {
        iec: "SUB",
        symbol: Some("-"),
        short: "Sub",
        long: &["Minus"],
    },
    Operator {
        iec: "MUL",
        symbol: Some("*"),
        short: "Mul",
        long: &["Multiply", "Times"],
    },
    Operator {
        iec: "DIV",
        symbol: Some("/"),
        short: "Div",
        long: &["Divide"],
    },
    Operator {
        iec: "MOD",
        symbol: None,
        short: "Mod",
        long: &["Modulo"],
    },
    Operator {
        iec: "GT",
        symbol: Some(">"),
        short: "Gt",
        long: &["Greater"],
    },
    Operator {
        iec: "GE",
        symbol: Some(">="),
        short: "Ge",
        long: &["GreaterEqual", "GreaterOrEqual"],
    },
    Operator {
        iec: "EQ",
        symbol: Some("="),
        short: "Eq",
        long: &["Equal"],
    },
    Operator {
        iec: "NE",
        symbol: Some("<>"),
        short: "Ne",
        long: &["NotEqual", "Unequal"],
    },
    Operator {
        iec: "LE",
        symbol: Some("<="),
        short: "Le",
        long: &["LessEqual", "LessOrEqual"],
    },
    Operator {
        iec: "LT",
        symbol: Some("<"),
        short: "Lt",
        long: &["Less"],
    },
];

/// The call types of boxes that are calls, not operators: a box with one of them is never read
/// as an operator, whatever its text.
const CALLS: &[&str] = &["Function", "FunctionBlock", "Method", "Program", "Action"];

/// The operator a box's text names: its IEC name or its ST symbol.
fn named_by(text: &str) -> Option<&'static Operator> {
    let text = text.trim();
    OPERATORS
        .iter()
        .find(|o| o.symbol == Some(text) || o.iec.eq_ignore_ascii_case(text))
}

/// The IEC operator (upper-case: `SUB`) a CFC box's text names, as its name or its symbol (`-`);
/// `None` when the text is no operator's (a function's name, for one).
pub(crate) fn iec_name(text: &str) -> Option<&'static str> {
    named_by(text).map(|o| o.iec)
}

/// An LD/FBD box's call type read as the short one (`Sub`, `Gt`) when the box is an operator saved
/// under another name: a symbol box (`-` beside `Minus`), or a long comparison name beside the
/// operator's name or symbol (`Greater` beside `>` or `GT`). Otherwise `call` unchanged.
pub(crate) fn call_type(call: &str, box_type: &str) -> String {
    if CALLS.contains(&call) {
        return call.to_string();
    }
    let Some(op) = named_by(box_type) else {
        return call.to_string();
    };
    let symbol_box = op.symbol == Some(box_type.trim());
    if symbol_box || op.long.contains(&call) {
        op.short.to_string()
    } else {
        call.to_string()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn symbol_boxes_are_their_operators() {
        assert_eq!(call_type("Minus", "-"), "Sub");
        assert_eq!(call_type("Plus", "+"), "Add");
        assert_eq!(call_type("Greater", ">"), "Gt");
        assert_eq!(call_type("Greater", "GT"), "Gt");
        assert_eq!(call_type("Sub", "SUB"), "Sub");
        assert_eq!(iec_name("-"), Some("SUB"));
        assert_eq!(iec_name("<>"), Some("NE"));
        assert_eq!(iec_name("LIMIT"), None);
    }

    #[test]
    fn calls_and_mismatches_are_kept() {
        assert_eq!(call_type("Function", "-"), "Function");
        assert_eq!(call_type("Greater", "<"), "Lt");
        assert_eq!(call_type("Minus", "LIMIT"), "Minus");
        assert_eq!(call_type("Equal", "GT"), "Equal");
    }
}
