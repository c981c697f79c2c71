//! Verification: rebuild the motion a PMAC would run from emitted text and compare it with the plan.
//!
//! Input: LINEAR motion-program text (either dialect, case-insensitive, as written by [`crate::program`] or by
//! hand in the same subset) or PVT text (as written by [`crate::pvt`]), and the start position.
//! Output: per-move times of a program ([`program_move_times`]) following the PMAC's rules, the program's
//! commanded motion as a [`Trajectory`] ([`reconstruct_program`]), the PVT text's motion as a [`PvtCurve`]
//! ([`reconstruct_pvt`]), and the largest deviation between two motions ([`max_deviation`]).
//! Invariants (PMAC rules used): a move lasts `TM = distance / F` over the `FRAX` axes; `TM` is at least the
//! acceleration time; `TA < 2 TS` means `2 TS`; a blend is centred on the corner and lasts the next move's `TA`
//! (capped at `2 (TM - TA/2)` of the previous move); the stop before `DWELL` uses the `TA`/`TS` in force there
//! (Power: the move's `td`); a single move lasts `TM + (TA + TD) / 2`. The commanded speed is the sum of S
//! ramps (each move's velocity vector switched on and off by a ramp centred on its corners).

use crate::error::PmacError;
use crate::model::{Sample, Trajectory, TrajectorySource};
use crate::scurve::{s_ramp, s_ramp_acc};

/// One move of a parsed program.
#[derive(Debug, Clone, PartialEq)]
struct ProgMove {
    start: Vec<f64>,
    end: Vec<f64>,
    /// Move time (s) after the TM >= TA rule.
    tm: f64,
    /// Ramp into the move: (time, ts) in seconds.
    ramp_in: (f64, f64),
}

/// A chain of blended moves ending in a stop.
#[derive(Debug, Clone, PartialEq)]
struct Chain {
    start_time: f64,
    moves: Vec<ProgMove>,
    ramp_out: (f64, f64),
}

impl Chain {
    /// Corner times: centre of the first ramp, then each move's end (blend centres).
    fn corners(&self) -> Vec<f64> {
        let mut c = vec![self.start_time + self.moves[0].ramp_in.0 / 2.0];
        for m in &self.moves {
            let last = *c.last().expect("non-empty");
            c.push(last + m.tm);
        }
        c
    }
    fn end_time(&self) -> f64 {
        self.corners().last().copied().unwrap_or(self.start_time) + self.ramp_out.0 / 2.0
    }
}

/// Parsed program: axis names and chains.
#[derive(Debug, Clone, PartialEq)]
pub struct ProgramTimeline {
    /// The axis names, in the program's order.
    pub axes: Vec<char>,
    chains: Vec<Chain>,
}

impl ProgramTimeline {
    /// (start, end) time of every move in seconds from the program start.
    pub fn move_spans(&self) -> Vec<(f64, f64)> {
        let mut out = Vec::new();
        for ch in &self.chains {
            let c = ch.corners();
            let n = ch.moves.len();
            for i in 0..n {
                let start = if i == 0 { ch.start_time } else { c[i] };
                let end = if i + 1 == n { ch.end_time() } else { c[i + 1] };
                out.push((start, end));
            }
        }
        out
    }
    /// The commanded vector speed (over all axes) where each move meets the next: `None` after an exact stop,
    /// `|V_i + V_(i+1)| / 2` in a blend (the blend's S ramp is half way at the corner). This is what the PMAC
    /// does instead of a PLCopen junction velocity; compare the two to see how far LINEAR blending is from
    /// the plan.
    pub fn corner_speeds(&self) -> Vec<Option<f64>> {
        let mut out = Vec::new();
        for ch in &self.chains {
            let vel = |m: &ProgMove| -> Vec<f64> {
                m.end
                    .iter()
                    .zip(&m.start)
                    .map(|(e, s)| (e - s) / m.tm)
                    .collect()
            };
            for w in ch.moves.windows(2) {
                let (a, b) = (vel(&w[0]), vel(&w[1]));
                let speed = a
                    .iter()
                    .zip(&b)
                    .map(|(x, y)| ((x + y) / 2.0).powi(2))
                    .sum::<f64>()
                    .sqrt();
                out.push(Some(speed));
            }
            out.push(None);
        }
        out
    }
    /// Total duration of the program's motion.
    pub fn duration(&self) -> f64 {
        self.chains.last().map_or(0.0, Chain::end_time)
    }
}

fn parse_num(s: &str, line: usize) -> Result<f64, PmacError> {
    s.trim_start_matches('(')
        .trim_end_matches(')')
        .parse::<f64>()
        .ok()
        .filter(|x| x.is_finite())
        .ok_or_else(|| PmacError::unreadable(line, format!("`{s}` is not a number")))
}

/// Parses a LINEAR program; `start` is the axis position when it begins (default 0).
pub fn parse_program(text: &str, start: Option<&[f64]>) -> Result<ProgramTimeline, PmacError> {
    // Axis names from the definition line (`#1->1000X`); FRAX defaults to all of them.
    let mut axes: Vec<char> = Vec::new();
    for tok in text.split_whitespace() {
        if let Some((_, rhs)) = tok.split_once("->") {
            if let Some(c) = rhs.chars().last().filter(char::is_ascii_alphabetic) {
                axes.push(c.to_ascii_uppercase());
            }
        }
    }
    if axes.is_empty() {
        axes = vec!['X', 'Y', 'Z'];
    }
    let n = axes.len();
    let mut pos = start.map_or_else(|| vec![0.0; n], <[f64]>::to_vec);
    if pos.len() != n {
        return Err(PmacError::coord_system(format!(
            "start position has {} coordinates, the program has {n} axes",
            pos.len()
        )));
    }
    // Turbo PMAC rounds TA and TS to whole milliseconds when it executes them (Software Reference,
    // `TA{data}`, `TS{data}`); Turbo text is the upper-case dialect.
    let turbo = text.contains("OPEN PROG");
    let exec_ms = |x: f64| if turbo { x.round() } else { x };
    let mut frax: Vec<bool> = vec![true; n];
    let (mut ta, mut ts, mut td, mut f, mut tm) = (0.0, 0.0, None::<f64>, 0.0, None::<f64>);
    let mut inc = false;
    let mut in_prog = false;
    let mut chains: Vec<Chain> = Vec::new();
    let mut cur: Vec<ProgMove> = Vec::new();
    let mut cur_td = 0.0;
    let mut time = 0.0;
    let close_chain =
        |cur: &mut Vec<ProgMove>, chains: &mut Vec<Chain>, time: &mut f64, ramp_out: (f64, f64)| {
            if cur.is_empty() {
                return;
            }
            let ch = Chain {
                start_time: *time,
                moves: std::mem::take(cur),
                ramp_out,
            };
            *time = ch.end_time();
            chains.push(ch);
        };
    for (lineno, raw) in text.lines().enumerate() {
        let lineno = lineno + 1;
        let code = raw.split(';').next().unwrap_or("");
        let code = code.split("//").next().unwrap_or("").to_ascii_uppercase();
        let code = code.replace("FRAX (", "FRAX(");
        let mut target: Vec<Option<f64>> = vec![None; n];
        let mut has_move = false;
        let words = code.split_whitespace();
        let flush_move = |target: &mut Vec<Option<f64>>,
                          pos: &mut Vec<f64>,
                          cur: &mut Vec<ProgMove>,
                          frax: &[bool],
                          ta: f64,
                          ts: f64,
                          f: f64,
                          tm: Option<f64>,
                          inc: bool|
         -> Result<(), PmacError> {
            let end: Vec<f64> = (0..n)
                .map(|k| match target[k] {
                    Some(x) if inc => pos[k] + x,
                    Some(x) => x,
                    None => pos[k],
                })
                .collect();
            let dist = (0..n)
                .filter(|&k| frax[k])
                .map(|k| (end[k] - pos[k]).powi(2))
                .sum::<f64>()
                .sqrt();
            let ta_eff = ta.max(2.0 * ts);
            let mut t = match tm {
                Some(t) => t,
                None if f > 0.0 => dist / f,
                None => return Err(PmacError::unreadable(lineno, "move without a feedrate")),
            };
            t = t.max(ta_eff);
            let mut ramp_in = (ta_eff, ts);
            if let Some(prev) = cur.last() {
                let cap = 2.0 * (prev.tm - prev.ramp_in.0 / 2.0);
                if ramp_in.0 > cap {
                    ramp_in.0 = cap.max(0.0);
                    ramp_in.1 = ramp_in.1.min(ramp_in.0 / 2.0);
                }
            }
            cur.push(ProgMove {
                start: pos.clone(),
                end: end.clone(),
                tm: t,
                ramp_in,
            });
            *pos = end;
            *target = vec![None; n];
            Ok(())
        };
        for w in words {
            if !in_prog {
                if w == "OPEN" {
                    in_prog = true;
                }
                continue;
            }
            let split = w
                .find(|c: char| !c.is_ascii_alphabetic())
                .unwrap_or(w.len());
            let (key, val) = w.split_at(split);
            match key {
                "CLOSE" => {
                    in_prog = false;
                }
                "PROG" | "CLEAR" | "LINEAR" | "" => {}
                "ABS" | "INC" => {
                    if has_move {
                        flush_move(&mut target, &mut pos, &mut cur, &frax, ta, ts, f, tm, inc)?;
                        has_move = false;
                    }
                    inc = key == "INC";
                }
                "FRAX" => {
                    let list = val.trim_start_matches('(').trim_end_matches(')');
                    frax = axes
                        .iter()
                        .map(|a| list.split(',').any(|x| x.trim().starts_with(*a)))
                        .collect();
                }
                "TA" | "TS" | "TD" | "F" | "TM" | "DWELL" => {
                    if has_move {
                        flush_move(&mut target, &mut pos, &mut cur, &frax, ta, ts, f, tm, inc)?;
                        has_move = false;
                        cur_td = td.unwrap_or(ta);
                    }
                    let x = parse_num(val, lineno)?;
                    match key {
                        "TA" => ta = exec_ms(x) / 1000.0,
                        "TS" => ts = exec_ms(x) / 1000.0,
                        "TD" => td = Some(x / 1000.0),
                        "F" => {
                            f = x;
                            tm = None;
                        }
                        "TM" => tm = Some(x / 1000.0),
                        _ => {
                            // DWELL: stop, using the TA/TS in force (Turbo) or the last move's td (Power).
                            let out_time = match td {
                                Some(_) => cur_td,
                                None => ta,
                            };
                            let out = (out_time.max(2.0 * ts), ts);
                            close_chain(&mut cur, &mut chains, &mut time, out);
                            time += x / 1000.0;
                        }
                    }
                }
                _ if key.len() == 1 && axes.contains(&key.chars().next().unwrap_or(' ')) => {
                    let k = axes.iter().position(|a| key.starts_with(*a)).unwrap_or(0);
                    target[k] = Some(parse_num(val, lineno)?);
                    has_move = true;
                }
                _ => {
                    return Err(PmacError::unreadable(
                        lineno,
                        format!("`{w}` is not in the LINEAR subset this checker reads"),
                    ))
                }
            }
        }
        if has_move {
            flush_move(&mut target, &mut pos, &mut cur, &frax, ta, ts, f, tm, inc)?;
            cur_td = td.unwrap_or(ta);
        }
    }
    let out_time = td.map_or(ta, |_| cur_td);
    close_chain(
        &mut cur,
        &mut chains,
        &mut time,
        (out_time.max(2.0 * ts), ts),
    );
    Ok(ProgramTimeline { axes, chains })
}

/// Duration (s) of every move of a LINEAR program, by the PMAC's rules (module header). Start at the origin.
pub fn program_move_times(text: &str) -> Result<Vec<f64>, PmacError> {
    Ok(parse_program(text, None)?
        .move_spans()
        .into_iter()
        .map(|(a, b)| b - a)
        .collect())
}

/// The commanded motion of a LINEAR program, sampled every `cycle_s` from `start` (default origin).
pub fn reconstruct_program(
    text: &str,
    start: Option<&[f64]>,
    cycle_s: f64,
) -> Result<Trajectory, PmacError> {
    if !(cycle_s.is_finite() && cycle_s > 0.0) {
        return Err(PmacError::trajectory("sample cycle must be positive"));
    }
    let tl = parse_program(text, start)?;
    let n = tl.axes.len();
    let total = tl.duration();
    let steps = (total / cycle_s).ceil() as usize;
    let origin = start.map_or_else(|| vec![0.0; n], <[f64]>::to_vec);
    let mut axes = vec![Vec::with_capacity(steps + 1); n];
    for i in 0..=steps {
        let t = (i as f64 * cycle_s).min(total);
        let st = program_state(&tl, &origin, t);
        for (k, s) in st.into_iter().enumerate() {
            axes[k].push(s);
        }
    }
    Ok(Trajectory { cycle_s, axes })
}

fn program_state(tl: &ProgramTimeline, origin: &[f64], t: f64) -> Vec<Sample> {
    let n = origin.len();
    let mut out: Vec<Sample> = origin
        .iter()
        .map(|&p| Sample { p, v: 0.0, a: 0.0 })
        .collect();
    for ch in &tl.chains {
        if t < ch.start_time {
            break;
        }
        let corners = ch.corners();
        // Velocity vectors: 0, V_1 .. V_m, 0; transition i centred on corners[i].
        let mut vel: Vec<Vec<f64>> = vec![vec![0.0; n]];
        for m in &ch.moves {
            vel.push((0..n).map(|k| (m.end[k] - m.start[k]) / m.tm).collect());
        }
        vel.push(vec![0.0; n]);
        let base = &ch.moves[0].start;
        for (k, s) in out.iter_mut().enumerate() {
            s.p = base[k];
            s.v = 0.0;
            s.a = 0.0;
        }
        for (i, &c) in corners.iter().enumerate() {
            let (time, ts) = if i < ch.moves.len() {
                ch.moves[i].ramp_in
            } else {
                ch.ramp_out
            };
            let time_eff = time.max(2.0 * ts);
            let x = t - (c - time_eff / 2.0);
            let (val, integral) = s_ramp(time_eff, ts, x);
            let acc = s_ramp_acc(time_eff, ts, x);
            for (k, s) in out.iter_mut().enumerate() {
                let dv = vel[i + 1][k] - vel[i][k];
                s.p += dv * integral;
                s.v += dv * val;
                s.a += dv * acc;
            }
        }
    }
    out
}

/// (segment start time, duration, start (p, v) per axis, end (p, v) per axis).
type PvtPiece = (f64, f64, Vec<(f64, f64)>, Vec<(f64, f64)>);

/// The motion described by PVT text: cubic Hermite per segment from the previous point.
#[derive(Debug, Clone, PartialEq)]
pub struct PvtCurve {
    /// The axis names, in the text's order.
    pub axes: Vec<char>,
    /// (segment start time, duration, start (p, v) per axis, end (p, v) per axis), v in user units per second.
    segments: Vec<PvtPiece>,
    start: Vec<(f64, f64)>,
}

impl PvtCurve {
    /// How many PVT segments the text has.
    pub fn segment_count(&self) -> usize {
        self.segments.len()
    }
}

impl TrajectorySource for PvtCurve {
    fn axis_count(&self) -> usize {
        self.axes.len()
    }
    fn duration(&self) -> f64 {
        self.segments.last().map_or(0.0, |s| s.0 + s.1)
    }
    fn state(&self, t: f64) -> Vec<(f64, f64)> {
        let idx = self.segments.partition_point(|s| s.0 + s.1 < t);
        let Some((t0, h, a, b)) = self.segments.get(idx) else {
            return self
                .segments
                .last()
                .map_or_else(|| self.start.clone(), |s| s.3.clone());
        };
        let u = ((t - t0) / h).clamp(0.0, 1.0);
        a.iter()
            .zip(b)
            .map(|(&(p0, v0), &(p1, v1))| hermite(p0, v0, p1, v1, *h, u))
            .collect()
    }
}

/// Cubic Hermite position and velocity at fraction `u` of a segment of `h` seconds.
pub fn hermite(p0: f64, v0: f64, p1: f64, v1: f64, h: f64, u: f64) -> (f64, f64) {
    let (m0, m1) = (v0 * h, v1 * h);
    let u2 = u * u;
    let u3 = u2 * u;
    let p = (2.0 * u3 - 3.0 * u2 + 1.0) * p0
        + (u3 - 2.0 * u2 + u) * m0
        + (-2.0 * u3 + 3.0 * u2) * p1
        + (u3 - u2) * m1;
    let dp = (6.0 * u2 - 6.0 * u) * p0
        + (3.0 * u2 - 4.0 * u + 1.0) * m0
        + (-6.0 * u2 + 6.0 * u) * p1
        + (3.0 * u2 - 2.0 * u) * m1;
    (p, dp / h)
}

/// Rebuilds the motion of PVT text (lines such as `PVT10` and `X1.5:20 Y0:0`). `start` is each axis's position
/// at rest before the first segment; `velocity_time_ms` is Isx90 (velocities are units per that many ms).
pub fn reconstruct_pvt(
    text: &str,
    axes: &[char],
    start: &[f64],
    velocity_time_ms: f64,
) -> Result<PvtCurve, PmacError> {
    if start.len() != axes.len() {
        return Err(PmacError::trajectory(format!(
            "start has {} coordinates for {} axes",
            start.len(),
            axes.len()
        )));
    }
    let vscale = 1000.0 / velocity_time_ms;
    let mut seg_s = None::<f64>;
    let mut t = 0.0;
    let mut prev: Vec<(f64, f64)> = start.iter().map(|&p| (p, 0.0)).collect();
    let first = prev.clone();
    let mut segments = Vec::new();
    let mut inc = false;
    for (i, raw) in text.lines().enumerate() {
        let line = raw
            .split(';')
            .next()
            .unwrap_or("")
            .trim()
            .to_ascii_uppercase();
        let mut end = prev.clone();
        let mut any = false;
        for w in line.split_whitespace() {
            if let Some(ms) = w.strip_prefix("PVT") {
                let ms = parse_num(ms, i + 1)?;
                if ms <= 0.0 {
                    return Err(PmacError::unreadable(i + 1, "PVT time must be positive"));
                }
                seg_s = Some(ms / 1000.0);
                continue;
            }
            match w {
                "ABS" => inc = false,
                "INC" => inc = true,
                _ => {}
            }
            let mut chars = w.chars();
            let Some(c) = chars.next() else { continue };
            let Some(k) = axes.iter().position(|a| a.eq_ignore_ascii_case(&c)) else {
                continue;
            };
            let Some((p, v)) = chars.as_str().split_once(':') else {
                continue;
            };
            let p = parse_num(p, i + 1)?;
            let v = parse_num(v, i + 1)? * vscale;
            end[k] = (if inc { prev[k].0 + p } else { p }, v);
            any = true;
        }
        if any {
            let h = seg_s
                .ok_or_else(|| PmacError::unreadable(i + 1, "PVT line before any PVT time"))?;
            segments.push((t, h, prev.clone(), end.clone()));
            t += h;
            prev = end;
        }
    }
    Ok(PvtCurve {
        axes: axes.to_vec(),
        segments,
        start: first,
    })
}

/// Largest |position difference| between two motions over all axes, checked every `step` seconds up to the
/// longer duration (each motion holds its end point after it ends). Infinite if `step` is not positive.
pub fn max_deviation<A, B>(a: &A, b: &B, step: f64) -> f64
where
    A: TrajectorySource + ?Sized,
    B: TrajectorySource + ?Sized,
{
    if !(step.is_finite() && step > 0.0) {
        return f64::INFINITY;
    }
    let end = a.duration().max(b.duration());
    let steps = (end / step).ceil() as usize;
    let mut worst: f64 = 0.0;
    for i in 0..=steps {
        let t = (i as f64 * step).min(end);
        let sa = a.state(t.min(a.duration()));
        let sb = b.state(t.min(b.duration()));
        for (x, y) in sa.iter().zip(&sb) {
            worst = worst.max((x.0 - y.0).abs());
        }
    }
    worst
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn hermite_end_points() {
        assert_eq!(hermite(1.0, 2.0, 3.0, 4.0, 0.5, 0.0), (1.0, 2.0));
        let (p, v) = hermite(1.0, 2.0, 3.0, 4.0, 0.5, 1.0);
        assert!((p - 3.0).abs() < 1e-12 && (v - 4.0).abs() < 1e-12);
    }

    #[test]
    fn manual_rule_tm_at_least_ta() {
        // 1 unit at F100 would take 10 ms, but TA is 200 ms: the move takes TA + TA.
        let prog = "&1 #1->1000X\nOPEN PROG 1 CLEAR\nLINEAR INC TA200 TS0 F100 X1 DWELL0\nCLOSE\n";
        let t = program_move_times(prog).unwrap();
        assert_eq!(t.len(), 1);
        assert!((t[0] - 0.4).abs() < 1e-12, "{t:?}");
    }

    #[test]
    fn blended_moves_share_the_corner() {
        // Two blended 100-unit moves at F10, TA 1 s: 0.5 + 10 + 10 + 0.5 s in total.
        let prog = "&1 #1->1000X\nOPEN PROG 1 CLEAR\nLINEAR ABS TA1000 TS0 F10\nX100\nX200 DWELL0\nCLOSE\n";
        let t = program_move_times(prog).unwrap();
        assert_eq!(t.len(), 2);
        assert!(
            (t[0] - 10.5).abs() < 1e-12 && (t[1] - 10.5).abs() < 1e-12,
            "{t:?}"
        );
        let tr = reconstruct_program(prog, None, 0.01).unwrap();
        let (p, v) = tr.state(10.5)[0];
        assert!((p - 100.0).abs() < 1e-9 && (v - 10.0).abs() < 1e-9);
        let (p, v) = tr.state(tr.duration())[0];
        assert!((p - 200.0).abs() < 1e-9 && v.abs() < 1e-12);
    }

    #[test]
    fn unknown_words_are_reported() {
        let e = program_move_times("OPEN PROG 1\nCIRCLE1 X1\nCLOSE\n").unwrap_err();
        assert_eq!(e.code(), "E7006");
        assert!(e.diagnostic().message.starts_with("line 2:"), "{e}");
        let e = program_move_times("OPEN PROG 1\nX1\nCLOSE\n").unwrap_err();
        assert_eq!(e.code(), "E7006");
        let e = program_move_times("OPEN PROG 1\nF1 X1y\nCLOSE\n").unwrap_err();
        assert_eq!(e.code(), "E7006");
        let e = reconstruct_pvt("X1:2", &['X'], &[0.0], 1000.0).unwrap_err();
        assert_eq!(e.code(), "E7006");
        let e = reconstruct_pvt("PVT0\nX1:2", &['X'], &[0.0], 1000.0).unwrap_err();
        assert_eq!(e.code(), "E7006");
    }
}
