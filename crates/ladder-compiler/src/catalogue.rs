//! What ladderc knows about blocks it did not read from the project: the IEC 61131-3 standard function
//! blocks and functions, the PLCopen motion (MC_*) blocks, and the elementary types.
//!
//! Input: a block or type name (case-insensitive). Output: its kind, pins and pin types, and the rule
//! that gives a function's result type. Invariants: names are compared upper-cased; a motion block
//! accepts any pin (their exact pin lists belong to the motion library), with types for the usual ones.

/// A standard function block: input and output pins with their types.
pub struct StdFb {
    /// The block type name, upper case (`TON`, `CTU_DINT`).
    pub name: &'static str,
    /// `(pin, type)` of each input, in the standard's order (the order of positional arguments).
    pub inputs: &'static [(&'static str, &'static str)],
    /// `(pin, type)` of each output, in the standard's order.
    pub outputs: &'static [(&'static str, &'static str)],
}

const TIMER_IN: &[(&str, &str)] = &[("IN", "BOOL"), ("PT", "TIME")];
const TIMER_OUT: &[(&str, &str)] = &[("Q", "BOOL"), ("ET", "TIME")];
const LTIMER_IN: &[(&str, &str)] = &[("IN", "BOOL"), ("PT", "LTIME")];
const LTIMER_OUT: &[(&str, &str)] = &[("Q", "BOOL"), ("ET", "LTIME")];

/// The IEC 61131-3 standard function blocks (bistables, edge detectors, counters, timers) with their pins.
pub static STD_FBS: &[StdFb] = &[
    StdFb {
        name: "SR",
        inputs: &[("S1", "BOOL"), ("R", "BOOL")],
        outputs: &[("Q1", "BOOL")],
    },
    StdFb {
        name: "RS",
        inputs: &[("S", "BOOL"), ("R1", "BOOL")],
        outputs: &[("Q1", "BOOL")],
    },
    StdFb {
        name: "R_TRIG",
        inputs: &[("CLK", "BOOL")],
        outputs: &[("Q", "BOOL")],
    },
    StdFb {
        name: "F_TRIG",
        inputs: &[("CLK", "BOOL")],
        outputs: &[("Q", "BOOL")],
    },
    StdFb {
        name: "CTU",
        inputs: &[("CU", "BOOL"), ("R", "BOOL"), ("PV", "INT")],
        outputs: &[("Q", "BOOL"), ("CV", "INT")],
    },
    StdFb {
        name: "CTD",
        inputs: &[("CD", "BOOL"), ("LD", "BOOL"), ("PV", "INT")],
        outputs: &[("Q", "BOOL"), ("CV", "INT")],
    },
    StdFb {
        name: "CTUD",
        inputs: &[
            ("CU", "BOOL"),
            ("CD", "BOOL"),
            ("R", "BOOL"),
            ("LD", "BOOL"),
            ("PV", "INT"),
        ],
        outputs: &[("QU", "BOOL"), ("QD", "BOOL"), ("CV", "INT")],
    },
    StdFb {
        name: "CTU_DINT",
        inputs: &[("CU", "BOOL"), ("R", "BOOL"), ("PV", "DINT")],
        outputs: &[("Q", "BOOL"), ("CV", "DINT")],
    },
    StdFb {
        name: "CTD_DINT",
        inputs: &[("CD", "BOOL"), ("LD", "BOOL"), ("PV", "DINT")],
        outputs: &[("Q", "BOOL"), ("CV", "DINT")],
    },
    StdFb {
        name: "CTUD_DINT",
        inputs: &[
            ("CU", "BOOL"),
            ("CD", "BOOL"),
            ("R", "BOOL"),
            ("LD", "BOOL"),
            ("PV", "DINT"),
        ],
        outputs: &[("QU", "BOOL"), ("QD", "BOOL"), ("CV", "DINT")],
    },
    StdFb {
        name: "CTU_LINT",
        inputs: &[("CU", "BOOL"), ("R", "BOOL"), ("PV", "LINT")],
        outputs: &[("Q", "BOOL"), ("CV", "LINT")],
    },
    StdFb {
        name: "CTD_LINT",
        inputs: &[("CD", "BOOL"), ("LD", "BOOL"), ("PV", "LINT")],
        outputs: &[("Q", "BOOL"), ("CV", "LINT")],
    },
    StdFb {
        name: "CTUD_LINT",
        inputs: &[
            ("CU", "BOOL"),
            ("CD", "BOOL"),
            ("R", "BOOL"),
            ("LD", "BOOL"),
            ("PV", "LINT"),
        ],
        outputs: &[("QU", "BOOL"), ("QD", "BOOL"), ("CV", "LINT")],
    },
    StdFb {
        name: "CTU_UDINT",
        inputs: &[("CU", "BOOL"), ("R", "BOOL"), ("PV", "UDINT")],
        outputs: &[("Q", "BOOL"), ("CV", "UDINT")],
    },
    StdFb {
        name: "CTD_UDINT",
        inputs: &[("CD", "BOOL"), ("LD", "BOOL"), ("PV", "UDINT")],
        outputs: &[("Q", "BOOL"), ("CV", "UDINT")],
    },
    StdFb {
        name: "CTUD_UDINT",
        inputs: &[
            ("CU", "BOOL"),
            ("CD", "BOOL"),
            ("R", "BOOL"),
            ("LD", "BOOL"),
            ("PV", "UDINT"),
        ],
        outputs: &[("QU", "BOOL"), ("QD", "BOOL"), ("CV", "UDINT")],
    },
    StdFb {
        name: "CTU_ULINT",
        inputs: &[("CU", "BOOL"), ("R", "BOOL"), ("PV", "ULINT")],
        outputs: &[("Q", "BOOL"), ("CV", "ULINT")],
    },
    StdFb {
        name: "CTD_ULINT",
        inputs: &[("CD", "BOOL"), ("LD", "BOOL"), ("PV", "ULINT")],
        outputs: &[("Q", "BOOL"), ("CV", "ULINT")],
    },
    StdFb {
        name: "CTUD_ULINT",
        inputs: &[
            ("CU", "BOOL"),
            ("CD", "BOOL"),
            ("R", "BOOL"),
            ("LD", "BOOL"),
            ("PV", "ULINT"),
        ],
        outputs: &[("QU", "BOOL"), ("QD", "BOOL"), ("CV", "ULINT")],
    },
    StdFb {
        name: "TP",
        inputs: TIMER_IN,
        outputs: TIMER_OUT,
    },
    StdFb {
        name: "TON",
        inputs: TIMER_IN,
        outputs: TIMER_OUT,
    },
    StdFb {
        name: "TOF",
        inputs: TIMER_IN,
        outputs: TIMER_OUT,
    },
    StdFb {
        name: "TP_LTIME",
        inputs: LTIMER_IN,
        outputs: LTIMER_OUT,
    },
    StdFb {
        name: "TON_LTIME",
        inputs: LTIMER_IN,
        outputs: LTIMER_OUT,
    },
    StdFb {
        name: "TOF_LTIME",
        inputs: LTIMER_IN,
        outputs: LTIMER_OUT,
    },
];

/// A standard FB by name, case-insensitively, under every name sema knows it by (`CTU_INT` is `CTU`,
/// `TON_TIME` is `TON`, `LTON` is `TON_LTIME`: `il_frontend::sema::StdFb::from_name`).
pub fn std_fb(name: &str) -> Option<&'static StdFb> {
    let fb = il_frontend::sema::StdFb::from_name(name.trim())?;
    STD_FBS
        .iter()
        .find(|f| f.name.eq_ignore_ascii_case(fb.name()))
}

/// The IEC 61131-3 name of a standard block's input as CODESYS and TwinCAT name it (their standard
/// library's `SR(SET1, RESET)`, `RS(SET, RESET1)`, `CTU(CU, RESET, PV)`, `CTD(CD, LOAD, PV)`,
/// `CTUD(..., RESET, LOAD, PV)`, which their LD/FBD exports write): `None` for any other block or
/// pin (see `il_frontend::sema::stdlib::vendor_param_alias`).
pub fn vendor_pin_alias(block: &str, pin: &str) -> Option<&'static str> {
    let block = block.trim();
    let fb = il_frontend::sema::StdFb::from_name(block)?;
    il_frontend::sema::stdlib::vendor_param_alias(fb, pin)
}

/// PLCopen motion blocks (Part 1 and Part 4 names start with `MC_`).
pub fn is_motion_block(name: &str) -> bool {
    name.len() > 3 && name.get(..3).is_some_and(|p| p.eq_ignore_ascii_case("MC_"))
}

/// Pin types of motion blocks that are the same in every PLCopen block.
pub fn motion_pin_type(pin: &str) -> Option<&'static str> {
    let p = pin.to_ascii_uppercase();
    Some(match p.as_str() {
        "EXECUTE" | "ENABLE" | "DONE" | "BUSY" | "ACTIVE" | "COMMANDABORTED" | "ERROR"
        | "VALID" | "STATUS" | "INVELOCITY" | "INGEAR" | "INSYNC" | "ENABLEPOSITIVE"
        | "ENABLENEGATIVE" | "CONTINUOUSUPDATE" => "BOOL",
        "ERRORID" => "WORD",
        "POSITION" | "VELOCITY" | "ACCELERATION" | "DECELERATION" | "JERK" | "DISTANCE" => "LREAL",
        "AXIS" | "MASTER" | "SLAVE" => "AXIS_REF",
        _ => return None,
    })
}

/// Types that may appear in declarations without being defined in the project.
pub fn is_library_type(name: &str) -> bool {
    let u = name.to_ascii_uppercase();
    is_elementary(&u)
        || std_fb(&u).is_some()
        || is_motion_block(&u)
        || matches!(
            u.as_str(),
            "AXIS_REF"
                | "AXES_GROUP_REF"
                | "MC_BUFFER_MODE"
                | "MC_DIRECTION"
                | "MC_TRANSITION_MODE"
        )
}

/// Whether `u` (already upper case) names an elementary type, `STRING`/`WSTRING` and long date/time names
/// included.
pub fn is_elementary(u: &str) -> bool {
    matches!(
        u,
        "BOOL"
            | "SINT"
            | "INT"
            | "DINT"
            | "LINT"
            | "USINT"
            | "UINT"
            | "UDINT"
            | "ULINT"
            | "REAL"
            | "LREAL"
            | "TIME"
            | "LTIME"
            | "DATE"
            | "TIME_OF_DAY"
            | "TOD"
            | "DATE_AND_TIME"
            | "DT"
            | "LDATE"
            | "LTOD"
            | "LTIME_OF_DAY"
            | "LDT"
            | "LDATE_AND_TIME"
            | "CHAR"
            | "WCHAR"
            | "STRING"
            | "WSTRING"
            | "BYTE"
            | "WORD"
            | "DWORD"
            | "LWORD"
    )
}

/// How a standard function's result type follows from its inputs.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ResultRule {
    /// The type of the inputs (the first typed one), skipping selector inputs (`G`, `K`).
    SameAsInputs,
    /// A fixed result type (`BOOL` for comparisons, `DINT` for `TRUNC`, the target of `X_TO_Y`).
    Fixed(&'static str),
}

/// IL operators that a two-input block lowers to directly (`LD IN1` / `ADD IN2`).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum OperatorBlock {
    /// `ADD SUB MUL DIV MOD`: the IL arithmetic operator.
    Arith(il_frontend::ast::Op),
    /// `GT GE EQ NE LE LT`: the IL comparison operator (BOOL result).
    Compare(il_frontend::ast::Op),
    /// `AND OR XOR`: the IL logic operator.
    Logic(il_frontend::ast::Op),
    /// `NOT`: one input, inverted.
    Not,
    /// `MOVE`: the input unchanged (`LD IN` / `ST OUT`).
    Move,
}

/// What the lowering needs to know about a standard function block (`<block typeName="ADD">`).
pub struct StdFunction {
    /// How the result type follows from the inputs.
    pub rule: ResultRule,
    /// The IL operator the block lowers to directly, if any; `None` for functions called by name (`LIMIT`,
    /// `SEL`).
    pub operator: Option<OperatorBlock>,
    /// Leading selector inputs that do not take part in the result type.
    pub selectors: usize,
}

/// A standard function by name, or `None`.
pub fn std_function(name: &str) -> Option<StdFunction> {
    use il_frontend::ast::Op;
    let u = name.to_ascii_uppercase();
    let f = |rule, operator, selectors| {
        Some(StdFunction {
            rule,
            operator,
            selectors,
        })
    };
    let same = ResultRule::SameAsInputs;
    match u.as_str() {
        "ADD" => f(same, Some(OperatorBlock::Arith(Op::Add)), 0),
        "SUB" => f(same, Some(OperatorBlock::Arith(Op::Sub)), 0),
        "MUL" => f(same, Some(OperatorBlock::Arith(Op::Mul)), 0),
        "DIV" => f(same, Some(OperatorBlock::Arith(Op::Div)), 0),
        "MOD" => f(same, Some(OperatorBlock::Arith(Op::Mod)), 0),
        "GT" => f(
            ResultRule::Fixed("BOOL"),
            Some(OperatorBlock::Compare(Op::Gt)),
            0,
        ),
        "GE" => f(
            ResultRule::Fixed("BOOL"),
            Some(OperatorBlock::Compare(Op::Ge)),
            0,
        ),
        "EQ" => f(
            ResultRule::Fixed("BOOL"),
            Some(OperatorBlock::Compare(Op::Eq)),
            0,
        ),
        "NE" => f(
            ResultRule::Fixed("BOOL"),
            Some(OperatorBlock::Compare(Op::Ne)),
            0,
        ),
        "LE" => f(
            ResultRule::Fixed("BOOL"),
            Some(OperatorBlock::Compare(Op::Le)),
            0,
        ),
        "LT" => f(
            ResultRule::Fixed("BOOL"),
            Some(OperatorBlock::Compare(Op::Lt)),
            0,
        ),
        "AND" => f(same, Some(OperatorBlock::Logic(Op::And)), 0),
        "OR" => f(same, Some(OperatorBlock::Logic(Op::Or)), 0),
        "XOR" => f(same, Some(OperatorBlock::Logic(Op::Xor)), 0),
        "NOT" => f(same, Some(OperatorBlock::Not), 0),
        "MOVE" => f(same, Some(OperatorBlock::Move), 0),
        "EXPT" | "ABS" | "SQRT" | "LN" | "LOG" | "EXP" | "SIN" | "COS" | "TAN" | "ASIN"
        | "ACOS" | "ATAN" | "MAX" | "MIN" | "SHL" | "SHR" | "ROL" | "ROR" | "LIMIT" => {
            f(same, None, 0)
        }
        "SEL" => f(same, None, 1),
        "MUX" => f(same, None, 1),
        "TRUNC" => f(ResultRule::Fixed("DINT"), None, 0),
        "LEN" | "FIND" => f(ResultRule::Fixed("INT"), None, 0),
        "ADD_TIME" | "SUB_TIME" | "MUL_TIME" | "DIV_TIME" | "SUB_DATE_DATE" | "SUB_TOD_TOD"
        | "SUB_DT_DT" => f(ResultRule::Fixed("TIME"), None, 0),
        "ADD_LTIME" | "SUB_LTIME" | "MUL_LTIME" | "DIV_LTIME" => {
            f(ResultRule::Fixed("LTIME"), None, 0)
        }
        "ADD_TOD_TIME" | "SUB_TOD_TIME" => f(ResultRule::Fixed("TOD"), None, 0),
        "ADD_DT_TIME" | "SUB_DT_TIME" | "CONCAT_DATE_TOD" => f(ResultRule::Fixed("DT"), None, 0),
        "LEFT" | "RIGHT" | "MID" | "CONCAT" | "INSERT" | "DELETE" | "REPLACE" => {
            f(ResultRule::Fixed("STRING"), None, 0)
        }
        _ => {
            // A typed name (`MAX_UDINT`, `ADD_INT`, `MUX_INT_DINT`: IEC 61131-3 edition 2,
            // 2.5.1.4, as ST reads them): the function with its generic type fixed
            if let Some((base, _)) = il_frontend::sema::stdlib::typed_name(&u) {
                let mut typed = std_function(base.name)?;
                if typed.rule == ResultRule::SameAsInputs {
                    let t = u.rsplit('_').next()?;
                    typed.rule = ResultRule::Fixed(static_name(t)?);
                }
                return Some(typed);
            }
            // Conversions: X_TO_Y, and the BCD conversions.
            let (_, target) = u.split_once("_TO_")?;
            let target = target.strip_prefix("BCD_").unwrap_or(target);
            if is_elementary(target) {
                Some(StdFunction {
                    rule: ResultRule::Fixed(static_name(target)?),
                    operator: None,
                    selectors: 0,
                })
            } else {
                None
            }
        }
    }
}

fn static_name(u: &str) -> Option<&'static str> {
    const NAMES: &[&str] = &[
        "BOOL",
        "SINT",
        "INT",
        "DINT",
        "LINT",
        "USINT",
        "UINT",
        "UDINT",
        "ULINT",
        "REAL",
        "LREAL",
        "TIME",
        "LTIME",
        "DATE",
        "TIME_OF_DAY",
        "TOD",
        "DATE_AND_TIME",
        "DT",
        "LDATE",
        "LTOD",
        "LTIME_OF_DAY",
        "LDT",
        "LDATE_AND_TIME",
        "CHAR",
        "WCHAR",
        "STRING",
        "WSTRING",
        "BYTE",
        "WORD",
        "DWORD",
        "LWORD",
    ];
    NAMES.iter().copied().find(|n| *n == u)
}

/// Broad type families for connection checks.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Family {
    /// BOOL.
    Bool,
    /// ANY_INT: SINT ... ULINT.
    Int,
    /// ANY_REAL: REAL, LREAL.
    Real,
    /// Bit strings: BYTE, WORD, DWORD, LWORD.
    Bits,
    /// Durations: TIME, LTIME.
    Time,
    /// Dates and times of day: DATE, TOD, DT.
    Date,
    /// STRING, WSTRING.
    String,
    /// Edition 3's characters: CHAR, WCHAR.
    Char,
}

/// The family of an elementary type name (case-insensitive); `None` for user and FB types.
pub fn family(type_name: &str) -> Option<Family> {
    // Compared without case instead of upper-casing a copy: called for every contact and coil.
    const FAMILIES: [(&str, Family); 31] = [
        ("BOOL", Family::Bool),
        ("SINT", Family::Int),
        ("INT", Family::Int),
        ("DINT", Family::Int),
        ("LINT", Family::Int),
        ("USINT", Family::Int),
        ("UINT", Family::Int),
        ("UDINT", Family::Int),
        ("ULINT", Family::Int),
        ("REAL", Family::Real),
        ("LREAL", Family::Real),
        ("BYTE", Family::Bits),
        ("WORD", Family::Bits),
        ("DWORD", Family::Bits),
        ("LWORD", Family::Bits),
        ("TIME", Family::Time),
        ("LTIME", Family::Time),
        ("DATE", Family::Date),
        ("TIME_OF_DAY", Family::Date),
        ("TOD", Family::Date),
        ("DATE_AND_TIME", Family::Date),
        ("DT", Family::Date),
        ("LDATE", Family::Date),
        ("LTOD", Family::Date),
        ("LTIME_OF_DAY", Family::Date),
        ("LDT", Family::Date),
        ("LDATE_AND_TIME", Family::Date),
        ("STRING", Family::String),
        ("WSTRING", Family::String),
        ("CHAR", Family::Char),
        ("WCHAR", Family::Char),
    ];
    FAMILIES
        .iter()
        .find(|(n, _)| n.eq_ignore_ascii_case(type_name))
        .map(|(_, f)| *f)
}

/// Whether a value of family `from` may drive an input of family `to` (IEC 61131-3 ed. 3 implicit
/// conversions: integers widen to reals; bit strings and integers mix in practice).
pub fn compatible(from: Family, to: Family) -> bool {
    from == to
        || matches!(
            (from, to),
            (Family::Int, Family::Real) | (Family::Int, Family::Bits) | (Family::Bits, Family::Int)
        )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn knows_standard_blocks() {
        assert_eq!(std_fb("ton").unwrap().outputs[1], ("ET", "TIME"));
        assert!(std_function("GT").unwrap().operator.is_some());
        assert_eq!(
            std_function("UINT_TO_REAL").unwrap().rule,
            ResultRule::Fixed("REAL")
        );
        assert!(std_function("FOO_TO_BAR").is_none());
        assert!(is_motion_block("MC_MoveAbsolute"));
        assert!(!is_library_type("HMI_BOOL"));
        assert!(is_library_type("axis_ref"));
        assert!(!compatible(Family::Bool, Family::Int));
        assert!(compatible(Family::Int, Family::Real));
    }

    #[test]
    fn families_ignore_case_and_know_every_elementary_name() {
        assert_eq!(family("bool"), Some(Family::Bool));
        assert_eq!(family("Udint"), Some(Family::Int));
        assert_eq!(family("lreal"), Some(Family::Real));
        assert_eq!(family("dword"), Some(Family::Bits));
        assert_eq!(family("ltime"), Some(Family::Time));
        assert_eq!(family("time_of_day"), Some(Family::Date));
        assert_eq!(family("wString"), Some(Family::String));
        assert_eq!(family("TON"), None);
        assert_eq!(family(""), None);
        assert_eq!(family("BOOLX"), None);
    }
}
