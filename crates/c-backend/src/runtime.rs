//! The runtime and harness C sources shipped with every generated program.
//!
//! Input: none (the files under `runtime/` are embedded at compile time). Output: `(path, contents)` pairs.
//! Invariants: the runtime compiles with `-std=c99 -Wall -Wextra -Werror -pedantic` against any
//! `ladderc_config.h` the generator writes.

/// `ladderc_rt.h`: types, inline helpers, standard FB declarations, the harness contract.
pub const RT_H: &str = include_str!("../runtime/ladderc_rt.h");
/// `ladderc_rt.c`: standard FBs, strings, value parsing and formatting.
pub const RT_C: &str = include_str!("../runtime/ladderc_rt.c");
/// `ladderc_strings.c`: the standard string functions (LEN, LEFT ... FIND) on STRING and WSTRING.
pub const STRINGS_C: &str = include_str!("../runtime/ladderc_strings.c");
/// `ladderc_main.c`: the scan harness (`main`).
pub const MAIN_C: &str = include_str!("../runtime/ladderc_main.c");

/// The runtime files, with their relative paths in a generated project.
pub fn files() -> Vec<(String, String)> {
    vec![
        ("ladderc_rt.h".into(), RT_H.into()),
        ("ladderc_rt.c".into(), RT_C.into()),
        ("ladderc_strings.c".into(), STRINGS_C.into()),
        ("ladderc_main.c".into(), MAIN_C.into()),
    ]
}
