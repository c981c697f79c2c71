//! Mangling of IEC names into C identifiers, and C literals for user data.
//!
//! Input: user identifiers (any text the parser accepted) and literal values. Output: C identifiers and
//! C literal text. Invariants: two IEC names map to the same C identifier iff they are equal ignoring ASCII
//! case; every mangled identifier starts with a generator prefix (`v_`, `FB_`, ...) so it is never a C
//! keyword nor a runtime name (`ladderc_`, `LADDERC_`, `IEC_`); string literals are emitted byte-wise with
//! octal escapes for everything but letters, digits and a few harmless punctuation marks, so no user text can end a C literal or
//! comment; user comments are never copied.

/// The case-insensitive core of an identifier: lower-case letters, digits and `_` for ordinary IEC names;
/// for anything else, `X` followed by the upper-case hex of the upper-cased UTF-8 bytes. Plain cores never
/// contain upper-case letters, so the two forms cannot collide.
pub fn core(name: &str) -> String {
    let mut s = String::new();
    push_core(&mut s, name);
    s
}

/// Appends [`core()`] of `name` to `s`.
pub fn push_core(s: &mut String, name: &str) {
    if !name.is_empty() && name.bytes().all(|b| b.is_ascii_alphanumeric() || b == b'_') {
        // All ASCII: copied whole, then lower-cased in place (no `char` at a time).
        let start = s.len();
        s.push_str(name);
        s[start..].make_ascii_lowercase();
    } else {
        const HEX: &[u8; 16] = b"0123456789ABCDEF";
        s.reserve(1 + 2 * name.len());
        s.push('X');
        for b in name.bytes().map(|b| b.to_ascii_uppercase()) {
            s.push(HEX[usize::from(b >> 4)] as char);
            s.push(HEX[usize::from(b & 15)] as char);
        }
    }
}

/// `prefix` followed by [`core()`] of `name`, in one allocation.
fn prefixed(prefix: &str, name: &str) -> String {
    let mut s = String::with_capacity(prefix.len() + name.len() + 1);
    s.push_str(prefix);
    push_core(&mut s, name);
    s
}

/// A variable, parameter or struct field.
pub fn var(name: &str) -> String {
    prefixed("v_", name)
}
/// A user function block's instance struct (`FB_x`), its init (`FB_x_INIT`) and body (`FB_x_BODY`).
pub fn fb(name: &str) -> String {
    prefixed("FB_", name)
}
/// A program's instance struct.
pub fn program(name: &str) -> String {
    prefixed("P_", name)
}
/// A user function.
pub fn function(name: &str) -> String {
    prefixed("F_", name)
}
/// A user data type.
pub fn user_type(name: &str) -> String {
    prefixed("T_", name)
}
/// A jump label.
pub fn label(name: &str) -> String {
    prefixed("L_", name)
}
/// A global variable: free globals `g_x`, configuration globals `gc<c>_x`, resource globals `gr<c>_<r>_x`.
pub fn global_free(name: &str) -> String {
    prefixed("g_", name)
}
/// A configuration global: `gc<c>_x`.
pub fn global_config(config: usize, name: &str) -> String {
    format!("gc{config}_{}", core(name))
}
/// A resource global: `gr<c>_<r>_x`.
pub fn global_resource(config: usize, resource: usize, name: &str) -> String {
    format!("gr{config}_{resource}_{}", core(name))
}
/// A configured program instance (`pi<c>_<r>_name`) or the implicit instance of a program (`pi_name`).
pub fn program_instance(config: usize, resource: usize, name: &str) -> String {
    format!("pi{config}_{resource}_{}", core(name))
}
/// The implicit instance of a program: `pi_name`.
pub fn implicit_instance(name: &str) -> String {
    prefixed("pi_", name)
}

/// C keywords (C99 and later) and names the generated code or the runtime reserve for themselves.
const C_KEYWORDS: &[&str] = &[
    "auto",
    "break",
    "case",
    "char",
    "const",
    "continue",
    "default",
    "do",
    "double",
    "else",
    "enum",
    "extern",
    "float",
    "for",
    "goto",
    "if",
    "inline",
    "int",
    "long",
    "register",
    "restrict",
    "return",
    "short",
    "signed",
    "sizeof",
    "static",
    "struct",
    "switch",
    "typedef",
    "union",
    "unsigned",
    "void",
    "volatile",
    "while",
    "_Bool",
    "_Complex",
    "_Imaginary",
    "_Alignas",
    "_Alignof",
    "_Atomic",
    "_Generic",
    "_Noreturn",
    "_Static_assert",
    "_Thread_local",
    "main",
    "bool",
    "true",
    "false",
    "self",
];

/// Whether `name` may be used verbatim as the C name of an embedded function.
pub fn is_valid_embedded_name(name: &str) -> bool {
    let mut bytes = name.bytes();
    let Some(first) = bytes.next() else {
        return false;
    };
    if !(first.is_ascii_alphabetic() || first == b'_') {
        return false;
    }
    if !name.bytes().all(|b| b.is_ascii_alphanumeric() || b == b'_') {
        return false;
    }
    if C_KEYWORDS.contains(&name) || name.starts_with("__") {
        return false;
    }
    let reserved = [
        "ladderc_", "LADDERC_", "IEC_", "v_", "FB_", "F_", "P_", "T_", "L_", "g_", "pi_", "cr_",
        "d_", "t_",
    ];
    let numbered = ["pi", "gc", "gr"].iter().any(|p| {
        name.strip_prefix(p)
            .is_some_and(|rest| rest.starts_with(|c: char| c.is_ascii_digit()))
    });
    !numbered && !reserved.iter().any(|p| name.starts_with(p))
}

/// A C string literal holding exactly `bytes` (letters, digits and ` ._,[]%#:-+=` verbatim, all else
/// `\ooo`: no quote, backslash, `?` (trigraphs), newline or `*/` can appear).
pub fn c_string(bytes: &[u8]) -> String {
    let mut s = String::with_capacity(bytes.len() * 2 + 2);
    s.push('"');
    push_c_string_body(&mut s, bytes);
    s.push('"');
    s
}

/// Appends the inside of [`c_string`] of `bytes` (without the quotes) to `s`: the text of a string
/// literal written in pieces.
pub fn push_c_string_body(s: &mut String, bytes: &[u8]) {
    /// The bytes written as they are.
    static PLAIN: [bool; 256] = {
        let mut t = [false; 256];
        let mut b = 0;
        while b < 256 {
            t[b] = (b as u8).is_ascii_alphanumeric();
            b += 1;
        }
        let extra = b" ._,[]%#:-+=";
        let mut i = 0;
        while i < extra.len() {
            t[extra[i] as usize] = true;
            i += 1;
        }
        t
    };
    // Runs of plain bytes (ASCII) are copied whole; the rest is escaped byte by byte.
    let mut rest = bytes;
    while !rest.is_empty() {
        let n = rest
            .iter()
            .position(|&b| !PLAIN[b as usize])
            .unwrap_or(rest.len());
        if let Ok(run) = std::str::from_utf8(&rest[..n]) {
            s.push_str(run);
        }
        let Some(&b) = rest.get(n) else { break };
        rest = &rest[n + 1..];
        s.push('\\');
        s.push(char::from(b'0' + (b >> 6)));
        s.push(char::from(b'0' + ((b >> 3) & 7)));
        s.push(char::from(b'0' + (b & 7)));
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_fold_case_and_get_prefixes() {
        assert_eq!(var("Count"), "v_count");
        assert_eq!(var("COUNT"), var("count"));
        assert_eq!(var("int"), "v_int");
        assert_eq!(fb("main"), "FB_main");
        assert_eq!(label("end"), "L_end");
    }

    /// The byte-by-byte writers give the text of their `format!` definitions.
    #[test]
    fn direct_writers_equal_their_format_definitions() {
        use std::fmt::Write as _;
        let fmt_core = |name: &str| {
            if !name.is_empty() && name.bytes().all(|b| b.is_ascii_alphanumeric() || b == b'_') {
                name.to_ascii_lowercase()
            } else {
                let mut s = String::from("X");
                for b in name.to_ascii_uppercase().bytes() {
                    let _ = write!(s, "{b:02X}");
                }
                s
            }
        };
        for name in [
            "Count",
            "a_B9",
            "",
            "a-b",
            "Zähler",
            "x y\n",
            "\u{7f}\u{1F600}",
            "_",
        ] {
            assert_eq!(core(name), fmt_core(name), "{name:?}");
            assert_eq!(var(name), format!("v_{}", fmt_core(name)));
            assert_eq!(label(name), format!("L_{}", fmt_core(name)));
            assert_eq!(implicit_instance(name), format!("pi_{}", fmt_core(name)));
        }
        let all: Vec<u8> = (0..=255).collect();
        let mut want = String::from("\"");
        for &b in &all {
            if b.is_ascii_alphanumeric() || b" ._,[]%#:-+=".contains(&b) {
                want.push(b as char);
            } else {
                let _ = write!(want, "\\{b:03o}");
            }
        }
        want.push('"');
        assert_eq!(c_string(&all), want);
        // Written in two pieces, the same text inside the quotes.
        let mut pieces = String::from("\"");
        push_c_string_body(&mut pieces, &all[..100]);
        push_c_string_body(&mut pieces, &all[100..]);
        pieces.push('"');
        assert_eq!(pieces, want);
    }

    #[test]
    fn unusual_names_are_hex_and_cannot_collide_with_plain_ones() {
        assert_eq!(core("a-b"), "X412D42");
        assert_ne!(core("x412d42"), core("a-b"));
        assert!(core("*/ system(\"rm\")").starts_with('X'));
        assert!(core("")
            .bytes()
            .all(|b| b.is_ascii_alphanumeric() || b == b'_'));
    }

    #[test]
    fn string_literals_escape_everything_that_could_end_them() {
        let s = c_string(b"\"*/ system(\"rm -rf /\"); /*\\\n??/");
        assert!(!s[1..s.len() - 1].contains('"'));
        assert!(!s.contains("*/"));
        assert!(!s.contains('\n'));
        assert!(!s.contains("??"));
        assert_eq!(c_string(b"ab 1"), "\"ab 1\"");
        assert_eq!(c_string(b"a\"b"), "\"a\\042b\"");
    }

    #[test]
    fn embedded_names_must_be_plain_and_unreserved() {
        assert!(is_valid_embedded_name("MC_MoveAbsolute"));
        assert!(!is_valid_embedded_name("int"));
        assert!(!is_valid_embedded_name("main"));
        assert!(!is_valid_embedded_name("ladderc_now"));
        assert!(!is_valid_embedded_name("move-abs"));
        assert!(!is_valid_embedded_name("1abc"));
        assert!(!is_valid_embedded_name(""));
        assert!(!is_valid_embedded_name("pi0_1_x"));
        assert!(is_valid_embedded_name("PID_step"));
    }
}
