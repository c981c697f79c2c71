//! `ladderc run --plot out.svg`: position and velocity of every axis over time, from the run's trace.
//!
//! Input: the trace CSV (`cycle,time_ms,...` with `axis.<name>.position` / `.velocity` columns, and
//! optionally block outputs ending in `.busy` / `.active` / `.done` / `.commandaborted`). Output: an SVG
//! with two charts (position, velocity) sharing the time axis, one line per axis (and the path speed
//! `|v|` when there are several axes), and the blocks' events marked the way paper B's Fig. 8 marks them
//! ([`events`]): a block's start (rising `Active`, or rising `Busy` when the block has no `Active`
//! column) as a green vertical line, a junction (one block ends, by `Done` or `CommandAborted`, in the
//! cycle another starts, or the next cycle) as a blue one, a block's end that no other block continues as a red one
//! (with only `Done` columns, as in the README's command: each block's Done is the junction to the
//! next block's, the first block starts with the first axis motion); each
//! line is labelled with the block and, for a junction, the path speed there. A junction whose speed the
//! axis limits lowered (the trace's `group.<name>.junction_requested` column is non-zero there) is drawn
//! in magenta and labelled "(lowered from `<requested>`)". Block outputs of a row were computed in the scan
//! before that cycle's engine step, so an event seen in row k is drawn at row k-1's time and speed (the
//! axis state the block reacted to). Axis labels carry the axes file's unit; labels stay inside the
//! frame (right-aligned in the right half); colours are a fixed high-contrast (colour-blind safe) set.
//! Invariant: only the trace is read.

use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};
use std::path::Path;

struct Trace {
    time_s: Vec<f64>,
    columns: Vec<(String, Vec<f64>)>,
}

/// The fields of one CSV line: `"..."` quoted fields (a 2-D array element's name `main.g[0,1]`, a STRING
/// value) keep their commas, `""` is a quote.
fn csv_fields(line: &str) -> Vec<String> {
    let mut out = Vec::new();
    let mut cur = String::new();
    let mut quoted = false;
    let mut chars = line.chars().peekable();
    while let Some(c) = chars.next() {
        match c {
            '"' if quoted && chars.peek() == Some(&'"') => {
                cur.push('"');
                chars.next();
            }
            '"' => quoted = !quoted,
            ',' if !quoted => out.push(std::mem::take(&mut cur)),
            _ => cur.push(c),
        }
    }
    out.push(cur);
    out
}

fn parse(csv: &str) -> Result<Trace, String> {
    let mut lines = csv.lines();
    let header = lines.next().ok_or("the trace is empty")?;
    let header = csv_fields(header);
    if header.get(1).map(String::as_str) != Some("time_ms") {
        return Err("the trace has no time_ms column".into());
    }
    let mut cols: Vec<Vec<f64>> = vec![Vec::new(); header.len()];
    for l in lines {
        let mut push = |i: usize, v: &str| {
            if let Some(col) = cols.get_mut(i) {
                col.push(v.parse::<f64>().unwrap_or(f64::NAN));
            }
        };
        if l.contains('"') {
            for (i, v) in csv_fields(l).iter().enumerate() {
                push(i, v);
            }
        } else {
            // the common row (no quoted field): no allocation per field
            for (i, v) in l.split(',').enumerate() {
                push(i, v);
            }
        }
    }
    let time_s = cols[1].iter().map(|t| t / 1000.0).collect();
    Ok(Trace {
        time_s,
        columns: header.into_iter().zip(cols).skip(2).collect(),
    })
}

/// What happened to a block at a row of the trace.
#[derive(Debug, Clone, PartialEq)]
pub enum Event {
    /// The block started (and no other block ended there).
    Start {
        /// The trace row.
        row: usize,
        /// The block (its column prefix).
        block: String,
    },
    /// `from` ended (Done or CommandAborted) and `to` started in the same cycle (or the next one).
    Junction {
        /// The trace row.
        row: usize,
        /// The block that ended.
        from: String,
        /// The block that started.
        to: String,
    },
    /// The block ended and no other block started there.
    End {
        /// The trace row.
        row: usize,
        /// The block (its column prefix).
        block: String,
    },
}

impl Event {
    /// The trace row of the event.
    pub fn row(&self) -> usize {
        match self {
            Event::Start { row, .. } | Event::Junction { row, .. } | Event::End { row, .. } => *row,
        }
    }
}

/// The block events of a trace, ordered by row. A block is the prefix of its output columns
/// (`prog.move_a` of `prog.move_a.Done`); outputs are matched without regard to case.
pub fn events(columns: &[(String, Vec<f64>)]) -> Vec<Event> {
    let mut blocks: Vec<String> = Vec::new();
    let find = |block: &str, out: &str| {
        columns
            .iter()
            .find(|(n, _)| n.eq_ignore_ascii_case(&format!("{block}.{out}")))
            .map(|(_, v)| v)
    };
    for (n, _) in columns {
        if let Some((b, out)) = n.rsplit_once('.') {
            let out = out.to_ascii_lowercase();
            if ["busy", "active", "done", "commandaborted"].contains(&out.as_str())
                && !n.starts_with("axis.")
                && !blocks.iter().any(|x| x.eq_ignore_ascii_case(b))
            {
                blocks.push(b.to_string());
            }
        }
    }
    let mut starts: Vec<(usize, String)> = Vec::new();
    let mut ends: Vec<(usize, String)> = Vec::new();
    for b in &blocks {
        if let Some(v) = find(b, "active").or_else(|| find(b, "busy")) {
            starts.extend(rises(v).into_iter().map(|r| (r, b.clone())));
        }
        for out in ["done", "commandaborted"] {
            if let Some(v) = find(b, out) {
                ends.extend(rises(v).into_iter().map(|r| (r, b.clone())));
            }
        }
    }
    let mut out = Vec::new();
    if starts.is_empty() && !ends.is_empty() {
        // Only Done / CommandAborted watched (the README's command): a block ending while a later one
        // ends afterwards hands over to it; the first starts with the first motion of an axis.
        ends.sort();
        let moving = columns
            .iter()
            .filter(|(n, _)| n.starts_with("axis.") && n.ends_with(".velocity"))
            .filter_map(|(_, v)| v.iter().position(|x| *x != 0.0))
            .min();
        if let Some(first) = moving {
            out.push(Event::Start {
                row: first + 1,
                block: ends[0].1.clone(),
            });
        }
        for (k, (row, from)) in ends.iter().enumerate() {
            out.push(match ends.get(k + 1) {
                Some((_, to)) if to != from => Event::Junction {
                    row: *row,
                    from: from.clone(),
                    to: to.clone(),
                },
                _ => Event::End {
                    row: *row,
                    block: from.clone(),
                },
            });
        }
        out.sort_by_key(Event::row);
        return out;
    }
    let mut used = vec![false; starts.len()];
    for (row, from) in ends {
        match starts
            .iter()
            .enumerate()
            .find(|(k, (r, b))| !used[*k] && r.abs_diff(row) <= 1 && *b != from)
        {
            Some((k, (_, to))) => {
                used[k] = true;
                out.push(Event::Junction {
                    row,
                    from,
                    to: to.clone(),
                });
            }
            None => out.push(Event::End { row, block: from }),
        }
    }
    for (k, (row, block)) in starts.into_iter().enumerate() {
        if !used[k] {
            out.push(Event::Start { row, block });
        }
    }
    out.sort_by_key(Event::row);
    out
}

/// The last name part of a block path (`move_a` of `prog.move_a`).
fn short(block: &str) -> &str {
    block.rsplit('.').next().unwrap_or(block)
}

/// The rows where a 0/1 column rises.
fn rises(v: &[f64]) -> Vec<usize> {
    (0..v.len())
        .filter(|&k| v[k] == 1.0 && (k == 0 || v[k - 1] != 1.0))
        .collect()
}

fn range(vals: impl Iterator<Item = f64>) -> (f64, f64) {
    let (lo, hi) = vals
        .filter(|v| v.is_finite())
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), v| {
            (a.min(v), b.max(v))
        });
    if !lo.is_finite() {
        return (0.0, 1.0);
    }
    let pad = ((hi - lo) * 0.05).max(1e-9);
    (lo - pad, hi + pad)
}

fn series_of(columns: &[(String, Vec<f64>)], signal: &str) -> Vec<(String, Vec<f64>)> {
    columns
        .iter()
        .filter(|(n, _)| n.starts_with("axis.") && n.ends_with(&format!(".{signal}")))
        .cloned()
        .collect()
}

/// At most about [`MAX_POINTS`] points of a series: per bucket of rows its first, smallest and largest
/// value (in time order), so that steps and peaks stay visible; non-finite values are left out.
fn thin(time: &[f64], v: &[f64]) -> Vec<(f64, f64)> {
    let n = time.len().min(v.len());
    let bucket = n.div_ceil(MAX_POINTS / 3).max(1);
    let mut out = Vec::new();
    let mut start = 0;
    while start < n {
        let end = (start + bucket).min(n);
        let mut rows: Vec<usize> = (start..end).filter(|&k| v[k].is_finite()).collect();
        if let (Some(&first), Some(&lo), Some(&hi)) = (
            rows.first(),
            rows.iter().min_by(|a, b| v[**a].total_cmp(&v[**b])),
            rows.iter().max_by(|a, b| v[**a].total_cmp(&v[**b])),
        ) {
            rows = vec![first, lo, hi, end - 1];
            rows.retain(|k| v[*k].is_finite());
            rows.sort_unstable();
            rows.dedup();
            out.extend(rows.into_iter().map(|k| (time[k], v[k])));
        }
        start = end;
    }
    out
}

/// Points per series drawn at most (about).
const MAX_POINTS: usize = 6000;

/// `|v|` per row over the axes' velocity columns.
fn path_speed(velocities: &[(String, Vec<f64>)]) -> Vec<f64> {
    let rows = velocities.first().map_or(0, |(_, v)| v.len());
    (0..rows)
        .map(|k| {
            velocities
                .iter()
                .map(|(_, v)| v.get(k).copied().unwrap_or(f64::NAN).powi(2))
                .sum::<f64>()
                .sqrt()
        })
        .collect()
}

/// Line colours (Okabe-Ito, colour-blind safe, high contrast on white); the path speed is black.
const LINES: [RGBColor; 6] = [
    RGBColor(0, 114, 178),
    RGBColor(213, 94, 0),
    RGBColor(0, 158, 115),
    RGBColor(204, 121, 167),
    RGBColor(230, 159, 0),
    RGBColor(86, 180, 233),
];
const START: RGBColor = RGBColor(0, 128, 0);
const JUNCTION: RGBColor = RGBColor(0, 0, 205);
const LOWERED: RGBColor = RGBColor(200, 0, 160);
const END: RGBColor = RGBColor(200, 0, 0);

/// The requested junction speed of a lowered junction near `row` (the trace's
/// `group.<name>.junction_requested` columns, the row itself or the one before or after).
fn lowered_at(columns: &[(String, Vec<f64>)], row: usize) -> Option<f64> {
    columns
        .iter()
        .filter(|(n, _)| n.starts_with("group.") && n.ends_with(".junction_requested"))
        .flat_map(|(_, v)| (row.saturating_sub(1)..=row + 1).filter_map(|k| v.get(k).copied()))
        .find(|x| *x > 0.0)
}

/// Draws the plot of `csv` into the SVG file `out`; `unit` is the axes' position unit (axis labels).
pub fn svg(csv: &str, out: &Path, unit: &str) -> Result<(), String> {
    let t = parse(csv)?;
    let e = |e: &dyn std::fmt::Display| e.to_string();
    let root = SVGBackend::new(out, (1000, 700)).into_drawing_area();
    root.fill(&WHITE).map_err(|x| e(&x))?;
    let areas = root.split_evenly((2, 1));
    let (t0, t1) = range(t.time_s.iter().copied());
    let evs = events(&t.columns);
    let pos_label = format!("position [{unit}]");
    let vel_label = format!("velocity [{unit}/s]");
    for (area, signal, ylabel) in [
        (&areas[0], "position", pos_label.as_str()),
        (&areas[1], "velocity", vel_label.as_str()),
    ] {
        let mut series: Vec<(String, Vec<f64>)> = t
            .columns
            .iter()
            .filter(|(n, _)| n.starts_with("axis.") && n.ends_with(&format!(".{signal}")))
            .cloned()
            .collect();
        if series.is_empty() {
            return Err(format!("the trace has no axis.<name>.{signal} column"));
        }
        if signal == "velocity" && series.len() > 1 {
            let speed = path_speed(&series);
            series.push(("axis.path speed |v|".to_string(), speed));
        }
        let (y0, y1) = range(series.iter().flat_map(|(_, v)| v.iter().copied()));
        let mut chart = ChartBuilder::on(area)
            .caption(format!("axis {signal}"), ("sans-serif", 18))
            .margin(10)
            .x_label_area_size(35)
            .y_label_area_size(60)
            .build_cartesian_2d(t0..t1, y0..y1)
            .map_err(|x| e(&x))?;
        chart
            .configure_mesh()
            .x_desc("time [s]")
            .y_desc(ylabel)
            .axis_desc_style(("sans-serif", 14))
            .label_style(("sans-serif", 12))
            .draw()
            .map_err(|x| e(&x))?;
        for (k, (name, v)) in series.iter().enumerate() {
            let name = name.as_str();
            let color = if name.ends_with("|v|") {
                BLACK
            } else {
                LINES[k % LINES.len()]
            };
            chart
                .draw_series(std::iter::once(PathElement::new(
                    thin(&t.time_s, v),
                    color.stroke_width(2),
                )))
                .map_err(|x| e(&x))?
                .label(name.trim_start_matches("axis."))
                .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], color));
        }
        let speed = path_speed(&series_of(&t.columns, "velocity"));
        for (n, ev) in evs.iter().enumerate() {
            // a row's block outputs were computed by the scan before that cycle's engine step, i.e. from
            // the axis state of the row before: the event happened there
            let k = ev.row().saturating_sub(1);
            let x = t.time_s[k];
            let (color, label) = match ev {
                Event::Start { block, .. } => (START, format!("start {}", short(block))),
                Event::Junction { from, to, row } => {
                    let v = speed.get(k).copied().unwrap_or(f64::NAN);
                    let base = format!("junction {}->{} |v|={v:.3}", short(from), short(to));
                    match lowered_at(&t.columns, k.min(*row)) {
                        Some(req) => (LOWERED, format!("{base} (lowered from {req})")),
                        None => (JUNCTION, base),
                    }
                }
                Event::End { block, .. } => (END, format!("end {}", short(block))),
            };
            chart
                .draw_series(std::iter::once(PathElement::new(
                    vec![(x, y0), (x, y1)],
                    color.stroke_width(2),
                )))
                .map_err(|x| e(&x))?;
            // the junction speed reached, as a point on the path speed
            if signal == "velocity" {
                if let (Event::Junction { .. }, Some(v)) = (ev, speed.get(k)) {
                    chart
                        .draw_series(std::iter::once(Circle::new((x, *v), 4, color.filled())))
                        .map_err(|x| e(&x))?;
                }
            }
            if signal == "position" {
                // labels stacked downwards so neighbouring events stay readable; in the right half
                // they end at their line, so that they stay inside the frame
                let y = y1 - (y1 - y0) * (0.04 + 0.07 * (n % 4) as f64);
                let right = x > t0 + (t1 - t0) * 0.5;
                let pos = if right {
                    Pos::new(HPos::Right, VPos::Top)
                } else {
                    Pos::new(HPos::Left, VPos::Top)
                };
                let dx = (t1 - t0) * 0.004 * if right { -1.0 } else { 1.0 };
                chart
                    .draw_series(std::iter::once(Text::new(
                        label,
                        (x + dx, y),
                        ("sans-serif", 12).into_font().color(&color).pos(pos),
                    )))
                    .map_err(|x| e(&x))?;
            }
        }
        chart
            .configure_series_labels()
            .border_style(BLACK)
            .background_style(WHITE.mix(0.8))
            .draw()
            .map_err(|x| e(&x))?;
    }
    root.present().map_err(|x| e(&x))?;
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn an_svg_with_both_charts_and_markers_is_written() {
        let csv = "cycle,time_ms,m.busy,m.done,axis.X1.position,axis.X1.velocity\n\
                   0,0,1,0,0,0\n1,10,1,0,1,100\n2,20,0,1,2,0\n";
        let dir = tempfile::tempdir().unwrap();
        let out = dir.path().join("p.svg");
        svg(csv, &out, "mm").unwrap();
        let text = std::fs::read_to_string(&out).unwrap();
        assert!(text.starts_with("<svg"), "{}", &text[..50.min(text.len())]);
        assert!(text.contains("axis position") && text.contains("axis velocity"));
        assert!(text.contains("X1.position") && text.contains("X1.velocity"));
        assert!(text.contains("position [mm]") && text.contains("velocity [mm/s]"));
        assert_eq!(rises(&[1.0, 1.0, 0.0, 1.0]), vec![0, 3]);
    }

    #[test]
    fn quoted_names_and_strings_keep_their_columns() {
        let t = parse("cycle,time_ms,\"m.g[0,1]\",m.s,axis.X1.position\n0,0,5,\"a,\"\"b\",7\n")
            .unwrap();
        let names: Vec<&str> = t.columns.iter().map(|c| c.0.as_str()).collect();
        assert_eq!(names, ["m.g[0,1]", "m.s", "axis.X1.position"]);
        assert_eq!((t.columns[0].1[0], t.columns[2].1[0]), (5.0, 7.0));
        assert_eq!(csv_fields("a,\"b,\"\"c\""), ["a", "b,\"c"]);
    }

    #[test]
    fn a_trace_without_axes_is_an_error() {
        let dir = tempfile::tempdir().unwrap();
        let err = svg("cycle,time_ms,x\n0,0,1\n", &dir.path().join("p.svg"), "mm").unwrap_err();
        assert!(err.contains("axis.<name>.position"), "{err}");
    }

    #[test]
    fn paper_b_style_events_start_junctions_end() {
        let col = |n: &str, v: &[u8]| (n.to_string(), v.iter().map(|&x| x as f64).collect());
        let columns = vec![
            col("p.a.Busy", &[1, 1, 1, 0, 0, 0, 0, 0]),
            col("p.a.Active", &[1, 1, 1, 0, 0, 0, 0, 0]),
            col("p.a.Done", &[0, 0, 0, 1, 1, 1, 1, 1]),
            col("p.b.Busy", &[1, 1, 1, 1, 1, 0, 0, 0]),
            col("p.b.Active", &[0, 0, 0, 1, 1, 0, 0, 0]),
            col("p.b.Done", &[0, 0, 0, 0, 0, 1, 1, 1]),
            col("p.c.BUSY", &[1, 1, 1, 1, 1, 1, 1, 0]),
            col("p.c.active", &[0, 0, 0, 0, 0, 0, 1, 0]),
            col("p.c.done", &[0, 0, 0, 0, 0, 0, 0, 1]),
            col("axis.X.position", &[0; 8]),
        ];
        let ev = events(&columns);
        let s = |x: &str| x.to_string();
        assert_eq!(
            ev,
            vec![
                Event::Start {
                    row: 0,
                    block: s("p.a")
                },
                Event::Junction {
                    row: 3,
                    from: s("p.a"),
                    to: s("p.b")
                },
                Event::Junction {
                    row: 5,
                    from: s("p.b"),
                    to: s("p.c")
                },
                Event::End {
                    row: 7,
                    block: s("p.c")
                },
            ]
        );
        // without Active columns a rising Busy is the start; an aborted block ends a junction too
        let columns = vec![
            col("m1.busy", &[1, 1, 0, 0]),
            col("m1.commandaborted", &[0, 0, 1, 0]),
            col("m2.busy", &[0, 0, 1, 0]),
            col("m2.done", &[0, 0, 0, 1]),
        ];
        assert_eq!(
            events(&columns),
            vec![
                Event::Start {
                    row: 0,
                    block: s("m1")
                },
                Event::Junction {
                    row: 2,
                    from: s("m1"),
                    to: s("m2")
                },
                Event::End {
                    row: 3,
                    block: s("m2")
                },
            ]
        );
    }

    #[test]
    fn junction_labels_carry_the_path_speed() {
        let csv = "cycle,time_ms,p.a.active,p.a.done,p.b.active,p.b.done,axis.X.position,axis.X.velocity,axis.Y.position,axis.Y.velocity\n\
                   0,1,1,0,0,0,0,0,0,0\n1,2,1,0,0,0,1,3,1,4\n2,3,0,1,1,0,2,3,2,4\n3,4,0,1,0,1,3,0,3,0\n";
        let dir = tempfile::tempdir().unwrap();
        let out = dir.path().join("p.svg");
        svg(csv, &out, "mm").unwrap();
        let text = std::fs::read_to_string(&out).unwrap();
        assert!(text.contains("start a"), "{text}");
        assert!(
            text.contains("junction a-&gt;b |v|=5.000") || text.contains("junction a->b |v|=5.000"),
            "{text}"
        );
        assert!(text.contains("end b"));
        assert!(text.contains("path speed |v|"));
    }

    #[test]
    fn done_columns_alone_give_start_junctions_and_end() {
        let col = |n: &str, v: &[u8]| (n.to_string(), v.iter().map(|&x| x as f64).collect());
        let columns = vec![
            col("p.a.Done", &[0, 0, 1, 1, 1, 1]),
            col("p.b.Done", &[0, 0, 0, 0, 1, 1]),
            col("axis.X.velocity", &[0, 1, 1, 1, 0, 0]),
        ];
        let s = |x: &str| x.to_string();
        assert_eq!(
            events(&columns),
            vec![
                Event::Start {
                    row: 2,
                    block: s("p.a")
                },
                Event::Junction {
                    row: 2,
                    from: s("p.a"),
                    to: s("p.b")
                },
                Event::End {
                    row: 4,
                    block: s("p.b")
                },
            ]
        );
    }

    #[test]
    fn lowered_junctions_are_flagged() {
        let csv = "cycle,time_ms,p.a.active,p.a.done,p.b.active,p.b.done,axis.X.position,axis.X.velocity,group.G.junction_requested,group.G.junction_reached\n\
                   0,1,1,0,0,0,0,0,0,0\n1,2,1,0,0,0,1,3,40,0\n2,3,0,1,1,0,2,0,0,0\n3,4,0,1,0,1,3,0,0,0\n";
        let dir = tempfile::tempdir().unwrap();
        let out = dir.path().join("p.svg");
        svg(csv, &out, "mm").unwrap();
        let text = std::fs::read_to_string(&out).unwrap();
        assert!(text.contains("(lowered from 40)"), "{text}");
        // drawn in the flag colour
        assert!(text.contains("#C800A0"), "{text}");
    }

    #[test]
    fn long_series_are_thinned_keeping_peaks_and_ends() {
        let n = 200_000;
        let time: Vec<f64> = (0..n).map(|k| k as f64).collect();
        let mut v = vec![0.0; n];
        v[123_457] = 5.0; // a one-row spike
        let pts = thin(&time, &v);
        assert!(pts.len() <= MAX_POINTS * 4 / 3 + 4, "{}", pts.len());
        assert!(pts.contains(&(123_457.0, 5.0)));
        assert_eq!(pts.first(), Some(&(0.0, 0.0)));
        assert_eq!(pts.last(), Some(&((n - 1) as f64, 0.0)));
        assert!(pts.windows(2).all(|w| w[0].0 < w[1].0));
        // short series are drawn whole
        assert_eq!(thin(&time[..10], &v[..10]).len(), 10);
    }
}
