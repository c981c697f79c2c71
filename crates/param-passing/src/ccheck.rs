//! The load-time C check of a user template (E4210, W4211): the function a call of the block gets is built
//! in a translation unit of its own and compiled with `$CC -std=c99 -Wall -Wextra -Werror -fsyntax-only`
//! against the motion library's header, so that a bad body is reported against the template file, never as
//! a C error of the user's build.
//!
//! Input: a template whose body passed [`crate::cbody::check`] (so it contains no directive and cannot leave
//! the function). Output: diagnostics at the template's line and column for every error or warning of the
//! compiler (at most [`MAX_REPORTED`] per template); W4211 when no compiler can be started.
//! Invariants: the compiler reads the unit from standard input and writes no file; every line of the unit
//! knows the template element it came from (body line, `<local>`, `<param>`, or the template itself).

use crate::library::MOTION_HEADER;
use crate::template::Template;
use diagnostics::{code, Diagnostic, Diagnostics, Span};
use std::fmt::Write as _;
use std::io::Write as _;
use std::process::{Command, Stdio};

/// The most compiler messages reported per template (the first ones; the rest follow from them).
pub const MAX_REPORTED: usize = 8;

/// Where a line of the check unit comes from.
#[derive(Debug, Clone, Copy)]
enum Origin {
    /// Line `k` (0-based) of the body.
    Body(usize),
    /// A declaration generated from an element of the template (a `<param>` or `<local>`).
    Element(Span),
    /// Generated text of the unit (headers, the function's frame).
    Frame,
}

/// The check unit of `t`, the origin of each of its lines (index = line number - 1) and the first body line.
fn build(t: &Template) -> (String, Vec<Origin>, usize) {
    let mut c = String::new();
    let mut origins = Vec::new();
    let line = |c: &mut String, origins: &mut Vec<Origin>, text: &str, o: Origin| {
        for l in text.lines() {
            c.push_str(l);
            c.push('\n');
            origins.push(o);
        }
    };
    let frame = "#include <stdint.h>\n#include <stdbool.h>\n#include <stddef.h>\n#include <string.h>\n#include <math.h>\n";
    line(&mut c, &mut origins, frame, Origin::Frame);
    line(&mut c, &mut origins, MOTION_HEADER, Origin::Frame);
    let mut head = String::new();
    let _ = writeln!(head, "struct McEngine *ladderc_motion_engine(void);");
    let _ = writeln!(head, "void {}(void);", t.block);
    let _ = writeln!(head, "void {}(void) {{", t.block);
    let _ = writeln!(head, "    int FuncNum = {};", t.func_num);
    line(&mut c, &mut origins, &head, Origin::Frame);
    for p in &t.params {
        let decl = match p.array {
            None => format!("    {ty} {} = ({ty})0;", p.abbr, ty = p.c_type()),
            Some(a) => format!("    {} {}[{}] = {{ 0 }};", p.c_type(), p.abbr, a.len),
        };
        line(&mut c, &mut origins, &decl, Origin::Element(p.span));
    }
    for l in &t.locals {
        line(
            &mut c,
            &mut origins,
            &format!("    {} {};", l.c_type, l.name),
            Origin::Element(l.span),
        );
    }
    let body_line = origins.len() + 1;
    // The body verbatim, line by line (LF, CR LF and a lone CR each end a line, as for the compiler).
    let text = t.body.text.as_str();
    let mut k = 0;
    let mut start = 0;
    let b = text.as_bytes();
    let mut i = 0;
    while i <= b.len() {
        let end_here = i == b.len() || b[i] == b'\n' || b[i] == b'\r';
        if end_here {
            c.push_str(&text[start..i]);
            c.push('\n');
            origins.push(Origin::Body(k));
            k += 1;
            if i + 1 < b.len() && b[i] == b'\r' && b[i + 1] == b'\n' {
                i += 1;
            }
            start = i + 1;
        }
        i += 1;
    }
    let mut tail = String::new();
    for p in &t.params {
        let _ = writeln!(tail, "    (void){};", p.abbr);
    }
    tail.push_str("    (void)FuncNum;\n}\n");
    line(&mut c, &mut origins, &tail, Origin::Frame);
    (c, origins, body_line)
}

/// Byte offsets in the body where each line starts (the same line ends as [`build`]).
fn body_line_starts(text: &str) -> Vec<usize> {
    let b = text.as_bytes();
    let mut starts = vec![0];
    let mut i = 0;
    while i < b.len() {
        if b[i] == b'\r' && b.get(i + 1) == Some(&b'\n') {
            i += 1;
        }
        if b[i] == b'\n' || b[i] == b'\r' {
            starts.push(i + 1);
        }
        i += 1;
    }
    starts
}

/// The compiler command: `$CC` (which may carry arguments), else `cc`.
fn compiler() -> Vec<String> {
    let cc = std::env::var("CC").ok().filter(|s| !s.trim().is_empty());
    cc.unwrap_or_else(|| "cc".into())
        .split_whitespace()
        .map(String::from)
        .collect()
}

fn run(cmd: &[String], unit: &str, byte_columns: bool) -> std::io::Result<(bool, String)> {
    let mut c = Command::new(&cmd[0]);
    c.args(&cmd[1..])
        .args(["-std=c99", "-Wall", "-Wextra", "-Werror", "-fsyntax-only"])
        .args(["-fno-diagnostics-show-caret", "-fdiagnostics-color=never"]);
    if byte_columns {
        c.arg("-fdiagnostics-column-unit=byte");
    }
    c.args(["-x", "c", "-"])
        .stdin(Stdio::piped())
        .stdout(Stdio::null())
        .stderr(Stdio::piped());
    let mut child = c.spawn()?;
    if let Some(mut stdin) = child.stdin.take() {
        stdin.write_all(unit.as_bytes())?;
    }
    let out = child.wait_with_output()?;
    Ok((
        out.status.success(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    ))
}

/// Compiles `t`'s function alone; reports the compiler's messages against the template. Returns whether it
/// compiled cleanly (`true` as well when no compiler could be started: W4211 says so).
pub fn compile(t: &Template, diags: &mut Diagnostics) -> bool {
    let (unit, origins, _) = build(t);
    let cmd = compiler();
    let result = match run(&cmd, &unit, true) {
        Ok((false, err)) if err.contains("column-unit") => run(&cmd, &unit, false),
        r => r,
    };
    let (ok, stderr) = match result {
        Ok(r) => r,
        Err(e) => {
            diags.push(
                Diagnostic::warning(
                    code::W4211,
                    format!(
                        "template `{}` was not compiled: cannot start the C compiler `{}`: {e}",
                        t.block,
                        cmd.join(" ")
                    ),
                )
                .at(t.span)
                .with_hint(
                    "install a C compiler or set CC; the lexical checks of the body still hold",
                ),
            );
            return true;
        }
    };
    if ok {
        return true;
    }
    let starts = body_line_starts(&t.body.text);
    let mut reported = 0;
    for l in stderr.lines() {
        let Some(rest) = l.strip_prefix("<stdin>:") else {
            continue;
        };
        let mut parts = rest.splitn(3, ':');
        let (Some(ln), Some(col), Some(msg)) = (parts.next(), parts.next(), parts.next()) else {
            continue;
        };
        let (Ok(ln), Ok(col)) = (ln.trim().parse::<usize>(), col.trim().parse::<usize>()) else {
            continue;
        };
        let msg = msg.trim();
        let Some(msg) = ["fatal error:", "error:", "warning:"]
            .iter()
            .find_map(|p| msg.strip_prefix(p))
        else {
            continue;
        };
        let span = match origins.get(ln.wrapping_sub(1)) {
            Some(Origin::Body(k)) => {
                let line_start = starts.get(*k).copied().unwrap_or(t.body.text.len());
                let line_end = starts
                    .get(k + 1)
                    .map_or(t.body.text.len(), |&s| s.saturating_sub(1));
                let mut at = (line_start + col.saturating_sub(1)).min(line_end.max(line_start));
                while !t.body.text.is_char_boundary(at) {
                    at -= 1;
                }
                let mut end = at + t.body.text[at..].chars().next().map_or(0, char::len_utf8);
                if end > line_end.max(at) {
                    end = at;
                }
                t.body.span_of(at, end)
            }
            Some(Origin::Element(span)) => *span,
            _ => t.span,
        };
        diags.push(
            Diagnostic::error(
                code::E4210,
                format!("the C compiler rejects template `{}`: {}", t.block, msg.trim()),
            )
            .at(span)
            .with_hint("fix the body's C at this place; the template's function is compiled alone with -std=c99 -Wall -Wextra -Werror"),
        );
        reported += 1;
        if reported == MAX_REPORTED {
            break;
        }
    }
    if reported == 0 {
        let first = stderr
            .lines()
            .find(|l| !l.trim().is_empty())
            .unwrap_or("no message");
        diags.push(
            Diagnostic::error(
                code::E4210,
                format!(
                    "the C compiler rejects template `{}`: {}",
                    t.block,
                    first.trim()
                ),
            )
            .at(t.span)
            .with_hint(
                "the template's function is compiled alone with -std=c99 -Wall -Wextra -Werror",
            ),
        );
    }
    false
}
