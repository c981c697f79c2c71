//! JSON-lines front end (`ladderc motion plan FILE.jsonl`).
//!
//! Input: one JSON object per line in the oracle's format (`kind` rest, blend or abort
//! with p0, v0, a0, p1, v1, vmax, amax, dmax, jmax; `kind` line3 with start, end and
//! per-axis vmax, amax, jmax arrays). Output: the same objects, one per line, with
//! `duration` recomputed and `phases: [[duration, jerk], ...]` of the planned profile
//! (for line3, the phases of the path-length profile). Blank lines are skipped.
//! Invariant: an input line that is not a valid problem is an error naming its line number.

use super::line::Line;
use super::{Limits, Profile, State};
use serde_json::{json, Map, Value};

fn num(obj: &Map<String, Value>, key: &str) -> Result<f64, String> {
    obj.get(key)
        .and_then(Value::as_f64)
        .ok_or_else(|| format!("missing or non-numeric field `{key}`"))
}

fn nums(obj: &Map<String, Value>, key: &str) -> Result<Vec<f64>, String> {
    obj.get(key)
        .and_then(Value::as_array)
        .ok_or_else(|| format!("missing array field `{key}`"))?
        .iter()
        .map(|v| {
            v.as_f64()
                .ok_or_else(|| format!("non-numeric entry in `{key}`"))
        })
        .collect()
}

fn plan_one(obj: &mut Map<String, Value>) -> Result<(), String> {
    let kind = obj
        .get("kind")
        .and_then(Value::as_str)
        .unwrap_or("rest")
        .to_string();
    let profile = if kind == "line3" || obj.get("start").is_some_and(Value::is_array) {
        let start = nums(obj, "start")?;
        let end = nums(obj, "end")?;
        let (vmax, amax, jmax) = (nums(obj, "vmax")?, nums(obj, "amax")?, nums(obj, "jmax")?);
        let dmax = if obj.contains_key("dmax") {
            nums(obj, "dmax")?
        } else {
            amax.clone()
        };
        if [amax.len(), dmax.len(), jmax.len()]
            .iter()
            .any(|&n| n != vmax.len())
        {
            return Err("limit arrays of different lengths".into());
        }
        let axes: Vec<Limits> = (0..vmax.len())
            .map(|i| Limits {
                vmax: vmax[i],
                amax: amax[i],
                dmax: dmax[i],
                jmax: jmax[i],
            })
            .collect();
        *Line::plan(&start, &end, &axes)
            .map_err(|e| e.to_string())?
            .profile()
    } else {
        let start = State {
            p: num(obj, "p0")?,
            v: obj.get("v0").and_then(Value::as_f64).unwrap_or(0.0),
            a: obj.get("a0").and_then(Value::as_f64).unwrap_or(0.0),
        };
        let amax = num(obj, "amax")?;
        let lim = Limits {
            vmax: num(obj, "vmax")?,
            amax,
            dmax: obj.get("dmax").and_then(Value::as_f64).unwrap_or(amax),
            jmax: num(obj, "jmax")?,
        };
        let v1 = obj.get("v1").and_then(Value::as_f64).unwrap_or(0.0);
        Profile::position(start, num(obj, "p1")?, v1, &lim).map_err(|e| e.to_string())?
    };
    obj.insert("duration".into(), json!(profile.duration()));
    let phases: Vec<Value> = profile
        .phases()
        .iter()
        .map(|ph| json!([ph.duration, ph.jerk]))
        .collect();
    obj.insert("phases".into(), Value::Array(phases));
    Ok(())
}

/// Plans every problem of a JSON-lines text; see the module documentation.
pub fn plan_jsonl(input: &str) -> Result<String, String> {
    let mut out = String::new();
    for (n, line) in input.lines().enumerate() {
        if line.trim().is_empty() {
            continue;
        }
        let mut value: Value =
            serde_json::from_str(line).map_err(|e| format!("line {}: {e}", n + 1))?;
        let obj = value
            .as_object_mut()
            .ok_or_else(|| format!("line {}: not a JSON object", n + 1))?;
        plan_one(obj).map_err(|e| format!("line {}: {e}", n + 1))?;
        out.push_str(&value.to_string());
        out.push('\n');
    }
    Ok(out)
}
