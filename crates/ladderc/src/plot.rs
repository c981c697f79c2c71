//! `ladderc run --plot out.svg`: position and velocity of every axis over time, from the run's trace.
//!
//! Input: the trace CSV (`cycle,time_ms,...` with `axis.<name>.position` / `.velocity` columns, and
//! optionally block outputs ending in `.busy` / `.done`). Output: an SVG with two charts (position,
//! velocity) sharing the time axis, one line per axis; a rising `Busy` (block start) is marked by a
//! green vertical line, a rising `Done` (block end) by a red one. Invariant: only the trace is read.

use plotters::prelude::*;
use std::path::Path;

struct Trace {
    time_s: Vec<f64>,
    columns: Vec<(String, Vec<f64>)>,
}

fn parse(csv: &str) -> Result<Trace, String> {
    let mut lines = csv.lines();
    let header: Vec<String> = lines
        .next()
        .ok_or("the trace is empty")?
        .split(',')
        .map(str::to_string)
        .collect();
    if header.get(1).map(String::as_str) != Some("time_ms") {
        return Err("the trace has no time_ms column".into());
    }
    let mut cols: Vec<Vec<f64>> = vec![Vec::new(); header.len()];
    for l in lines {
        for (i, v) in l.split(',').enumerate().take(header.len()) {
            cols[i].push(v.parse::<f64>().unwrap_or(f64::NAN));
        }
    }
    let time_s = cols[1].iter().map(|t| t / 1000.0).collect();
    Ok(Trace {
        time_s,
        columns: header.into_iter().zip(cols).skip(2).collect(),
    })
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

/// Draws the plot of `csv` into the SVG file `out`.
pub fn svg(csv: &str, out: &Path) -> Result<(), String> {
    let t = parse(csv)?;
    let e = |e: &dyn std::fmt::Display| e.to_string();
    let root = SVGBackend::new(out, (1000, 700)).into_drawing_area();
    root.fill(&WHITE).map_err(|x| e(&x))?;
    let areas = root.split_evenly((2, 1));
    let (t0, t1) = range(t.time_s.iter().copied());
    let starts: Vec<usize> = t
        .columns
        .iter()
        .filter(|(n, _)| n.to_ascii_lowercase().ends_with(".busy"))
        .flat_map(|(_, v)| rises(v))
        .collect();
    let ends: Vec<usize> = t
        .columns
        .iter()
        .filter(|(n, _)| n.to_ascii_lowercase().ends_with(".done"))
        .flat_map(|(_, v)| rises(v))
        .collect();
    for (area, signal, unit) in [
        (&areas[0], "position", "position"),
        (&areas[1], "velocity", "velocity /s"),
    ] {
        let series: Vec<(&String, &Vec<f64>)> = t
            .columns
            .iter()
            .filter(|(n, _)| n.starts_with("axis.") && n.ends_with(&format!(".{signal}")))
            .map(|(n, v)| (n, v))
            .collect();
        if series.is_empty() {
            return Err(format!("the trace has no axis.<name>.{signal} column"));
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
            .y_desc(unit)
            .draw()
            .map_err(|x| e(&x))?;
        for (k, (name, v)) in series.iter().enumerate() {
            let color = Palette99::pick(k).to_rgba();
            chart
                .draw_series(std::iter::once(PathElement::new(
                    t.time_s
                        .iter()
                        .copied()
                        .zip(v.iter().copied())
                        .filter(|p| p.1.is_finite())
                        .collect::<Vec<_>>(),
                    color.stroke_width(2),
                )))
                .map_err(|x| e(&x))?
                .label(name.trim_start_matches("axis."))
                .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], color));
        }
        for (rows, color) in [(&starts, GREEN), (&ends, RED)] {
            for &k in rows.iter() {
                let x = t.time_s[k];
                chart
                    .draw_series(std::iter::once(PathElement::new(
                        vec![(x, y0), (x, y1)],
                        color.stroke_width(1),
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
        svg(csv, &out).unwrap();
        let text = std::fs::read_to_string(&out).unwrap();
        assert!(text.starts_with("<svg"), "{}", &text[..50.min(text.len())]);
        assert!(text.contains("axis position") && text.contains("axis velocity"));
        assert!(text.contains("X1.position") && text.contains("X1.velocity"));
        assert_eq!(rises(&[1.0, 1.0, 0.0, 1.0]), vec![0, 3]);
    }

    #[test]
    fn a_trace_without_axes_is_an_error() {
        let dir = tempfile::tempdir().unwrap();
        let err = svg("cycle,time_ms,x\n0,0,1\n", &dir.path().join("p.svg")).unwrap_err();
        assert!(err.contains("axis.<name>.position"), "{err}");
    }
}
