//! The loop guard of `ladderc run`: a scan that never ends, reported at its loop.
//!
//! Input: the harness's standard error. `ladderc run` compiles the program with
//! `-DLADDERC_LOOP_LIMIT=`[`LIMIT`]; every jump back of the generated code (the end of a WHILE, REPEAT
//! or FOR pass, an IL jump to an earlier label) counts against that budget within one scan, and past
//! it the harness writes the trace so far and one line `ladderc-loop-guard FILE START END CYCLE N`
//! (the source span of the jump back, `c-backend/runtime/ladderc_main.c`) and exits with status 3.
//! Output: that line taken out of the standard error and turned into one E1061 at the loop.
//! Invariant: a line whose file is not one of the compilation's, or whose offsets are out of the
//! file, gives no diagnostic (the run then fails as any run does, E9201).
//!
//! Why a budget of jumps and not of time: the result is the same on every machine (a test can rely
//! on it), and ten million passes of a loop in one scan are far beyond any PLC task's cycle, so no
//! program that a controller runs is stopped. A controller's watchdog stops such a task too (TwinCAT:
//! the task's cycle-time exceeded, the PLC stops with an exception); IEC 61131-3 leaves it to the
//! implementation.

use diagnostics::{code, Diagnostic, FileId, SourceMap, Span};

/// The jumps back one scan may take before the run is stopped.
pub const LIMIT: u64 = 10_000_000;

/// The C compiler flag that turns the guard on.
pub fn c_flag() -> String {
    format!("-DLADDERC_LOOP_LIMIT={LIMIT}")
}

/// Takes the guard's line out of `stderr` and returns its diagnostic (see the module header).
pub fn take(stderr: &mut String, sources: &SourceMap) -> Option<Diagnostic> {
    let mut found = None;
    let mut rest = String::with_capacity(stderr.len());
    for line in stderr.split_inclusive('\n') {
        match line.trim_end().strip_prefix("ladderc-loop-guard ") {
            Some(fields) if found.is_none() => found = Some(fields.to_string()),
            _ => rest.push_str(line),
        }
    }
    let fields = found?;
    *stderr = rest;
    let n: Vec<u64> = fields
        .split_whitespace()
        .map(|w| w.parse().ok())
        .collect::<Option<_>>()?;
    let [file, start, end, cycle, limit] = n[..] else {
        return None;
    };
    let file = FileId(u32::try_from(file).ok()?);
    let len = sources.files().find(|(id, _)| *id == file)?.1.text.len() as u64;
    if start > end || end > len {
        return None;
    }
    let span = Span::new(file, start as usize, end as usize);
    Some(
        Diagnostic::error(
            code::E1061,
            format!("the scan of cycle {cycle} never ends: this loop went round {limit} times"),
        )
        .at(span)
        .with_primary_label("this loop does not end")
        .with_hint(
            "the loop's condition must change inside the loop; to wait for an input or a timer, \
             test it once per scan (an IF or a CASE step) instead of looping",
        )
        .with_note(
            "a controller's watchdog stops such a task; `ladderc run` stops the run after \
             ten million jumps back in one scan",
        ),
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_guard_line_becomes_one_located_error_and_leaves_the_rest() {
        let mut sources = SourceMap::new();
        sources.add("a.st", "WHILE TRUE DO\n  x := x + 1;\nEND_WHILE\n");
        let mut err =
            "runtime: something\nladderc-loop-guard 0 0 13 4 10000000\nafter\n".to_string();
        let d = take(&mut err, &sources).expect("a diagnostic");
        assert_eq!(err, "runtime: something\nafter\n");
        assert_eq!(d.code, code::E1061);
        assert!(d.message.contains("cycle 4"), "{}", d.message);
    }

    #[test]
    fn a_line_outside_the_files_gives_nothing() {
        let sources = SourceMap::new();
        let mut err = "ladderc-loop-guard 3 0 13 4 10\n".to_string();
        assert!(take(&mut err, &sources).is_none());
        let mut sources = SourceMap::new();
        sources.add("a.st", "x");
        let mut err = "ladderc-loop-guard 0 0 99 4 10\n".to_string();
        assert!(take(&mut err, &sources).is_none());
    }
}
