//! What a pipeline command reported and wrote: the counts behind the final summary record, and `run`'s
//! one-line summary.
//!
//! Input: every diagnostic the command prints ([`count`]), every file it writes ([`wrote`]), and `run`'s
//! figures ([`set_run`]). Output: at the end of `check`, `build` and `run`, [`finish`] prints the summary:
//! under `--message-format json` one record (`"kind": "summary"`, schema `ladderc-diagnostic/1`) with errors,
//! warnings, files and the run's figures; otherwise, for `run`, one human line
//! (`ran 195000 cycles: 195 s simulated in 0.26 s (750x real time); wrote ...`).
//! Invariants: the tally is process-wide (one command per process) and is taken once, by [`finish`]; the
//! record is the last line on standard error.

use crate::cli::Format;
use diagnostics::{Diagnostic, RunSummary, Severity, Summary};
use std::path::Path;
use std::sync::Mutex;

static TALLY: Mutex<Option<Summary>> = Mutex::new(None);

fn with<R>(f: impl FnOnce(&mut Summary) -> R) -> R {
    let mut guard = TALLY.lock().unwrap_or_else(|e| e.into_inner());
    f(guard.get_or_insert_with(Summary::default))
}

/// Counts printed diagnostics by severity.
pub fn count(diags: &[Diagnostic]) {
    with(|s| {
        s.errors += diags
            .iter()
            .filter(|d| d.severity == Severity::Error)
            .count();
        s.warnings += diags
            .iter()
            .filter(|d| d.severity == Severity::Warning)
            .count();
    });
}

/// Records a file (or the build directory) written, as named on the command line.
pub fn wrote(path: &Path) {
    with(|s| s.files.push(path.display().to_string()));
}

/// Records what the program's run did.
pub fn set_run(run: RunSummary) {
    with(|s| s.run = Some(run));
}

/// The run's figures: `cycles` of `cycle_ms` in `wall` seconds.
pub fn run_figures(cycles: u64, cycle_ms: f64, wall: std::time::Duration) -> RunSummary {
    let simulated_s = cycles as f64 * cycle_ms / 1000.0;
    let wall_s = wall.as_secs_f64();
    RunSummary {
        cycles,
        simulated_s,
        wall_s,
        real_time_factor: (wall_s > 0.0).then(|| simulated_s / wall_s),
    }
}

/// The human line of a run: cycles, simulated time, wall time and their ratio, the files written.
pub fn run_line(r: &RunSummary, files: &[String]) -> String {
    let ratio = match r.real_time_factor {
        Some(f) if f >= 10.0 => format!(" ({f:.0}x real time)"),
        Some(f) => format!(" ({f:.2}x real time)"),
        None => String::new(),
    };
    let wrote = if files.is_empty() {
        String::new()
    } else {
        format!("; wrote {}", files.join(", "))
    };
    format!(
        "ran {} cycles: {} s simulated in {:.3} s{ratio}{wrote}\n",
        r.cycles,
        seconds(r.simulated_s),
        r.wall_s
    )
}

/// Seconds without trailing zeros (`195`, `0.25`).
fn seconds(s: f64) -> String {
    let t = format!("{s:.6}");
    let t = t.trim_end_matches('0').trim_end_matches('.');
    t.to_string()
}

/// Prints the summary for `format` (see the module header) and clears the tally.
pub fn finish(format: Format) {
    let s = with(std::mem::take);
    match format {
        Format::Json => crate::stdio::err(&(diagnostics::render_summary_json(&s) + "\n")),
        Format::Human | Format::Short => {
            if let Some(r) = &s.run {
                crate::stdio::err(&run_line(r, &s.files));
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_run_line_names_cycles_times_ratio_and_files() {
        let r = run_figures(195_000, 1.0, std::time::Duration::from_millis(260));
        assert_eq!(r.simulated_s, 195.0);
        assert_eq!(
            run_line(&r, &["t.csv".into(), "p.svg".into()]),
            "ran 195000 cycles: 195 s simulated in 0.260 s (750x real time); wrote t.csv, p.svg\n"
        );
        let slow = run_figures(10, 0.5, std::time::Duration::from_secs(2));
        assert_eq!(
            run_line(&slow, &[]),
            "ran 10 cycles: 0.005 s simulated in 2.000 s (0.00x real time)\n"
        );
    }
}
