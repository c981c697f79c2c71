//! PVT segments from a trajectory, their text, and streaming into a rotary buffer.
//!
//! Input: a [`TrajectorySource`] (a sampled [`crate::Trajectory`] or any function of time), the coordinate
//! system, [`PvtOptions`] (segment time, default 10 ms; the controller's velocity time unit Isx90, default
//! 1000 ms) and, for streaming, a [`Transport`].
//! Output: [`PvtSegment`]s (end position and end velocity of every axis, sampled exactly at each segment end),
//! the buffer text (`ABS`, `PVT10`, `X1.5:20 Y0:0` ...; velocities in user units per Isx90 ms), and a
//! [`StreamReport`] after streaming with flow control.
//! Invariants: segment ends are `k * T` from the start, and the last segment ends exactly at the trajectory's
//! end (a shorter last segment gets its own `PVTn` line); for a sampled trajectory `T` must be a whole multiple
//! of the sample cycle (E7003) so that every segment end is a sample. The PMAC interpolates each segment with
//! the cubic Hermite polynomial of its two end points, which is what [`crate::verify::reconstruct_pvt`] does.
//! Streaming never lets more unexecuted lines into the buffer than the transport's capacity, and stops on the
//! first error reply (closing the buffer and aborting the coordinate system).

use crate::error::PmacError;
use crate::model::{CoordSystem, Dialect, TrajectorySource};
use crate::numfmt::num;
use crate::program::axis_definitions;
use crate::transport::Transport;

/// How PVT text is written.
#[derive(Debug, Clone, PartialEq)]
pub struct PvtOptions {
    /// Turbo or Power PMAC.
    pub dialect: Dialect,
    /// Segment time in ms (the `10` of `PVT10`).
    pub segment_ms: f64,
    /// The controller's velocity time unit in ms (Turbo Isx90, Power `Coord[x].FeedTime`); 1000 means per second.
    pub velocity_time_ms: f64,
    /// Decimals for positions and velocities.
    pub decimals: usize,
}

impl Default for PvtOptions {
    fn default() -> Self {
        PvtOptions {
            dialect: Dialect::Turbo,
            segment_ms: 10.0,
            velocity_time_ms: 1000.0,
            decimals: 6,
        }
    }
}

/// One PVT segment: its duration and every axis's end (position, velocity in units per second).
#[derive(Debug, Clone, PartialEq)]
pub struct PvtSegment {
    /// The segment time in seconds.
    pub duration_s: f64,
    /// (position, velocity) of every axis at the segment's end.
    pub end: Vec<(f64, f64)>,
}

/// Cuts `src` into segments of `segment_s` seconds (the last one shorter if needed).
pub fn segments<S: TrajectorySource + ?Sized>(
    src: &S,
    segment_s: f64,
) -> Result<Vec<PvtSegment>, PmacError> {
    src.check()?;
    if !(segment_s.is_finite() && segment_s > 0.0) {
        return Err(PmacError::trajectory(format!(
            "segment time must be positive, got {segment_s} s"
        )));
    }
    if let Some(cycle) = src.sample_period() {
        let ratio = segment_s / cycle;
        if (ratio - ratio.round()).abs() > 1e-6 || ratio.round() < 1.0 {
            return Err(PmacError::trajectory(format!(
                "segment time {} ms is not a whole multiple of the sample cycle {} ms",
                segment_s * 1000.0,
                cycle * 1000.0
            )));
        }
    }
    let total = src.duration();
    let full = ((total / segment_s) + 1e-9).floor() as usize;
    let mut out = Vec::with_capacity(full + 1);
    let mut prev_t = 0.0;
    for k in 1..=full {
        let t = k as f64 * segment_s;
        out.push(PvtSegment {
            duration_s: t - prev_t,
            end: src.state(t),
        });
        prev_t = t;
    }
    if total - prev_t > 1e-9 {
        out.push(PvtSegment {
            duration_s: total - prev_t,
            end: src.state(total),
        });
    }
    // Segment durations are exact multiples; normalise the rounding of k * T - (k-1) * T.
    for s in out.iter_mut().take(full) {
        s.duration_s = segment_s;
    }
    for s in &out {
        if s.end.len() != src.axis_count()
            || s.end.iter().any(|(p, v)| !(p.is_finite() && v.is_finite()))
        {
            return Err(PmacError::trajectory(
                "the trajectory gave a state that is not finite or has the wrong number of axes",
            ));
        }
    }
    Ok(out)
}

/// The buffer text: the mode, `PVTn` whenever the segment time changes, and one line per segment.
pub fn to_lines(
    cs: &CoordSystem,
    segs: &[PvtSegment],
    opts: &PvtOptions,
) -> Result<Vec<String>, PmacError> {
    cs.validate()?;
    if !(opts.velocity_time_ms.is_finite() && opts.velocity_time_ms > 0.0) {
        return Err(PmacError::trajectory("velocity time unit must be positive"));
    }
    let names = cs.axis_names();
    let (abs, pvt) = match opts.dialect {
        Dialect::Turbo => ("ABS", "PVT"),
        Dialect::Power => ("abs", "pvt"),
    };
    let mut lines = vec![abs.to_string()];
    let mut cur_ms = String::new();
    let vscale = opts.velocity_time_ms / 1000.0;
    for s in segs {
        if s.end.len() != names.len() {
            return Err(PmacError::trajectory(format!(
                "a segment has {} axes, &{} has {}",
                s.end.len(),
                cs.number,
                names.len()
            )));
        }
        let ms = num(s.duration_s * 1000.0, 3);
        if ms != cur_ms {
            lines.push(format!("{pvt}{ms}"));
            cur_ms = ms;
        }
        let words: Vec<String> = names
            .iter()
            .zip(&s.end)
            .map(|(n, (p, v))| {
                format!(
                    "{n}{}:{}",
                    num(*p, opts.decimals),
                    num(v * vscale, opts.decimals)
                )
            })
            .collect();
        lines.push(words.join(" "));
    }
    Ok(lines)
}

/// Largest position error of a cubic Hermite segment of `segment_s` seconds over a motion whose jerk jumps by
/// `jerk_step` once inside the segment (the motion is cubic on each side of the jump): `jerk_step * T^3 / 192`
/// (worst case: the jump in the middle). Segments without a jump are exact; errors of several jumps add up.
pub fn hermite_error_bound(jerk_step: f64, segment_s: f64) -> f64 {
    jerk_step.abs() * segment_s.powi(3) / 192.0
}

/// How streaming starts and ends.
#[derive(Debug, Clone, PartialEq)]
pub struct StreamOptions {
    /// Rotary buffer size for `DEFINE ROT` (Turbo: words; Power: `define rotary`, bytes); `None` = do not define.
    pub define_size: Option<u32>,
    /// Start the program once the buffer holds its look-ahead (or all lines, if fewer).
    pub start: bool,
    /// Lines in the buffer before the program starts; `None`: what the defined buffer holds
    /// ([`rotary_capacity_lines`]), capped by a live transport's capacity, or [`DEFAULT_LOOKAHEAD_LINES`]
    /// when no buffer is defined here.
    pub lookahead_lines: Option<usize>,
    /// Polls without progress while the buffer is full before giving up (E7005).
    pub max_full_polls: u32,
    /// After `CLOSE`, poll until the buffer is empty (bounded by `max_full_polls`).
    pub wait_until_done: bool,
}

/// Look-ahead when the rotary buffer is defined elsewhere and no look-ahead is given.
pub const DEFAULT_LOOKAHEAD_LINES: usize = 100;

impl Default for StreamOptions {
    fn default() -> Self {
        StreamOptions {
            define_size: Some(2048),
            start: true,
            lookahead_lines: None,
            max_full_polls: 1000,
            wait_until_done: false,
        }
    }
}

/// What happened while streaming.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct StreamReport {
    /// Buffer lines sent (PVT text), not counting set-up and control lines.
    pub lines_sent: usize,
    /// Lines-remaining queries made.
    pub polls: usize,
    /// Polls that found the buffer still full (the host waited).
    pub full_waits: usize,
    /// Largest number of unexecuted lines the host allowed in the buffer.
    pub peak_fill: usize,
    /// Buffer lines sent before the program was started (`None`: not started).
    pub started_after: Option<usize>,
}

/// Memory words (Turbo) a buffer line takes: one per value (`X1.5:20` is two), at least one.
/// Turbo PMAC User Manual, "Rotary Motion Program Buffers / Defining a Rotary Buffer": "each value in a
/// program (e.g. X1250) takes one word of memory".
pub fn line_words(line: &str) -> usize {
    let mut values = 0;
    let mut in_number = false;
    for c in line.chars() {
        let digit = c.is_ascii_digit() || c == '.';
        if digit && !in_number {
            values += 1;
        }
        in_number = digit;
    }
    values.max(1)
}

/// Bytes a Power PMAC buffer line is counted as (an estimate: 16 bytes per value, at least 16), for
/// `define rotary` sizes, which are in bytes.
fn line_bytes(line: &str) -> usize {
    16 * line_words(line)
}

/// How many of `lines` a rotary buffer of `size` (Turbo words, Power bytes) holds, counting every line as the
/// largest of them.
pub fn rotary_capacity_lines(size: u32, dialect: Dialect, lines: &[String]) -> usize {
    let per_line = lines
        .iter()
        .map(|l| match dialect {
            Dialect::Turbo => line_words(l),
            Dialect::Power => line_bytes(l),
        })
        .max()
        .unwrap_or(1);
    (size as usize / per_line).max(1)
}

/// The variable that fixes the velocity time unit (`F` and PVT velocities are user units per this many ms):
/// Turbo `Isx90` (`I5190` for coordinate system 1; Turbo PMAC Software Reference, coordinate-system
/// I-variables Isx90 "Feedrate Time Units"), Power `Coord[x].FeedTime`.
pub fn feed_time_setting(cs: u32, dialect: Dialect, velocity_time_ms: f64) -> String {
    let ms = num(velocity_time_ms, 3);
    match dialect {
        Dialect::Turbo => format!("I{}={ms}", 5000 + 100 * cs + 90),
        Dialect::Power => format!("Coord[{cs}].FeedTime={ms}"),
    }
}

/// Control lines around the buffer text, per dialect.
///
/// No on-line command is ever sent while the rotary buffer is open: the Turbo manual (Software Reference,
/// `OPEN ROTARY` and `B{constant}`) says that `B0` sent to an open buffer is entered as a B-axis move, and
/// `A` (abort) would be an A-axis move. So `B0` is sent before `OPEN ROT`, and the program is started by
/// `CLOSE`, `&n R`, `OPEN ROT` (the rotary buffer keeps its contents and entry point when closed). The data
/// gathering buffer is deleted before `DEFINE ROT` (User Manual, "Required Buffer State for Defining").
struct Control {
    setup: Vec<String>,
    start: Vec<String>,
    close: String,
    abort: String,
}

fn control(
    cs: &CoordSystem,
    dialect: Dialect,
    define: Option<u32>,
    velocity_time_ms: f64,
) -> Control {
    let n = cs.number;
    let units = feed_time_setting(n, dialect, velocity_time_ms);
    match dialect {
        Dialect::Turbo => {
            let mut setup = vec!["CLOSE".to_string()];
            if let Some(size) = define {
                setup.push("DELETE GATHER".to_string());
                setup.push(units);
                setup.push(axis_definitions(cs));
                setup.push(format!("&{n} DEFINE ROT {size}"));
            } else {
                setup.push(units);
                setup.push(axis_definitions(cs));
            }
            setup.push(format!("&{n} B0"));
            setup.push("OPEN ROT".to_string());
            Control {
                setup,
                start: vec!["CLOSE".into(), format!("&{n} R"), "OPEN ROT".into()],
                close: "CLOSE".to_string(),
                abort: format!("&{n} A"),
            }
        }
        Dialect::Power => {
            let mut setup = vec!["close".to_string(), units, axis_definitions(cs)];
            if let Some(size) = define {
                setup.push(format!("&{n} define rotary {size}"));
            }
            setup.push(format!("&{n} b0"));
            setup.push("open rotary".to_string());
            Control {
                setup,
                start: vec!["close".into(), format!("&{n} r"), "open rotary".into()],
                close: "close".to_string(),
                abort: format!("&{n} a"),
            }
        }
    }
}

/// Streams the segments' text into the coordinate system's rotary buffer through `transport`: set-up lines,
/// then the buffer lines with flow control (never more unexecuted lines than the transport's capacity; when
/// full, poll the lines remaining and wait), the run command once the buffer is primed, `CLOSE`, and a final
/// poll that surfaces any error reply. On an error reply: stop sending, `CLOSE`, abort (`&n A`), return E7004.
pub fn stream(
    cs: &CoordSystem,
    segs: &[PvtSegment],
    opts: &PvtOptions,
    stream_opts: &StreamOptions,
    transport: &mut dyn Transport,
) -> Result<StreamReport, PmacError> {
    let lines = to_lines(cs, segs, opts)?;
    stream_lines_with_units(
        cs,
        &lines,
        opts.dialect,
        opts.velocity_time_ms,
        stream_opts,
        transport,
    )
}

/// [`stream`] for ready buffer lines (e.g. a LINEAR program's move lines), velocities per second.
pub fn stream_lines(
    cs: &CoordSystem,
    lines: &[String],
    dialect: Dialect,
    stream_opts: &StreamOptions,
    transport: &mut dyn Transport,
) -> Result<StreamReport, PmacError> {
    stream_lines_with_units(cs, lines, dialect, 1000.0, stream_opts, transport)
}

/// [`stream_lines`] with the velocity time unit (ms) that the set-up declares.
pub fn stream_lines_with_units(
    cs: &CoordSystem,
    lines: &[String],
    dialect: Dialect,
    velocity_time_ms: f64,
    stream_opts: &StreamOptions,
    transport: &mut dyn Transport,
) -> Result<StreamReport, PmacError> {
    let ctl = control(cs, dialect, stream_opts.define_size, velocity_time_ms);
    let lookahead = stream_opts
        .lookahead_lines
        .or_else(|| {
            stream_opts
                .define_size
                .map(|size| rotary_capacity_lines(size, dialect, lines))
        })
        .unwrap_or(DEFAULT_LOOKAHEAD_LINES)
        .min(transport.capacity().unwrap_or(usize::MAX))
        .max(1);
    let result = run_stream(&ctl, lines, lookahead, stream_opts, transport);
    if let Err(e) = &result {
        if e.code() == "E7004" {
            // Best effort: the buffer must not stay open and the axes must not run on.
            let _ = transport.send(&ctl.close);
            let _ = transport.send(&ctl.abort);
            let _ = transport.flush();
        }
    }
    result
}

fn run_stream(
    ctl: &Control,
    lines: &[String],
    lookahead: usize,
    opts: &StreamOptions,
    t: &mut dyn Transport,
) -> Result<StreamReport, PmacError> {
    let mut report = StreamReport::default();
    for l in &ctl.setup {
        t.send(l)?;
    }
    let capacity = t.capacity();
    let mut in_buffer = 0usize;
    if capacity.is_some() {
        in_buffer = poll(t, &mut report)?;
    }
    let mut started = false;
    let mut start = |t: &mut dyn Transport, report: &mut StreamReport| -> Result<(), PmacError> {
        if opts.start && !started {
            for l in &ctl.start {
                t.send(l)?;
            }
            started = true;
            report.started_after = Some(report.lines_sent);
        }
        Ok(())
    };
    for line in lines {
        if report.lines_sent >= lookahead {
            start(t, &mut report)?;
        }
        if let Some(cap) = capacity {
            let mut stalls = 0u32;
            while in_buffer >= cap.max(1) {
                start(t, &mut report)?;
                let before = in_buffer;
                in_buffer = poll(t, &mut report)?;
                if in_buffer >= before {
                    report.full_waits += 1;
                    stalls += 1;
                    if stalls > opts.max_full_polls {
                        return Err(PmacError::transport(format!(
                            "rotary buffer stayed full ({in_buffer} lines) for {stalls} polls; is the program running?"
                        )));
                    }
                    t.wait();
                }
            }
        }
        t.send(line)?;
        report.lines_sent += 1;
        in_buffer += 1;
        report.peak_fill = report.peak_fill.max(in_buffer);
    }
    if opts.start && !started {
        // Everything fits in the look-ahead: close the buffer, then run what it holds.
        t.send(&ctl.close)?;
        t.send(&ctl.start[1])?;
        report.started_after = Some(report.lines_sent);
    } else {
        t.send(&ctl.close)?;
    }
    if capacity.is_some() {
        in_buffer = poll(t, &mut report)?;
        if opts.wait_until_done {
            let mut stalls = 0u32;
            while in_buffer > 0 {
                let before = in_buffer;
                t.wait();
                in_buffer = poll(t, &mut report)?;
                if in_buffer >= before {
                    stalls += 1;
                    if stalls > opts.max_full_polls {
                        return Err(PmacError::transport(format!(
                            "rotary buffer did not drain ({in_buffer} lines left)"
                        )));
                    }
                }
            }
        }
    }
    t.flush()?;
    Ok(report)
}

/// Writes the whole rotary-buffer script for `src` (set-up, PVT lines, run, close) to the file at `path`:
/// what `ladderc run --pmac-pvt out.pmc` needs.
pub fn write_file<S: TrajectorySource + ?Sized>(
    cs: &CoordSystem,
    src: &S,
    opts: &PvtOptions,
    path: &std::path::Path,
) -> Result<StreamReport, PmacError> {
    let segs = segments(src, opts.segment_ms / 1000.0)?;
    let mut t = crate::transport::FileTransport::create(path)?;
    stream(cs, &segs, opts, &StreamOptions::default(), &mut t)
}

fn poll(t: &mut dyn Transport, report: &mut StreamReport) -> Result<usize, PmacError> {
    report.polls += 1;
    t.lines_remaining()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::verify::hermite;

    #[test]
    fn hermite_bound_is_reached_by_a_jerk_jump_mid_segment() {
        // p(t) = j/6 * (t - T/2)^3 for t > T/2: one jump of the jerk by j in the middle of the segment.
        let (j, h) = (3.0, 0.02);
        let p = |t: f64| j / 6.0 * (t - h / 2.0).max(0.0).powi(3);
        let v = |t: f64| j / 2.0 * (t - h / 2.0).max(0.0).powi(2);
        let worst = (0..=1000)
            .map(|i| {
                let u = i as f64 / 1000.0;
                (hermite(p(0.0), v(0.0), p(h), v(h), h, u).0 - p(u * h)).abs()
            })
            .fold(0.0, f64::max);
        let bound = hermite_error_bound(j, h);
        assert!(
            worst <= bound * (1.0 + 1e-9) && worst > 0.9 * bound,
            "{worst} vs {bound}"
        );
    }
}
