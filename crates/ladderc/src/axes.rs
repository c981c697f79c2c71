//! The axis configuration of a project (`--axes FILE`, default `<first input stem>.axes.json`).
//!
//! Input: JSON text (schema below, documented in crates/ladderc/AXES.md). Output: an [`AxisConfig`] with
//! the engine's cycle time and queue depth, the axes (limits in user units) and the groups, or E505x
//! diagnostics pointing into the file (JSON errors at serde's line and column). Invariants: axis and
//! group names are IEC identifiers, unique (case-insensitively) among axes and groups; every limit is
//! finite; axis `i` becomes the global `AXIS_REF` named like it with `AxisNo := i`, group `j` the global
//! `AXES_GROUP_REF` with `GroupNo := j` ([`AxisConfig::globals_il`]).
//!
//! ```json
//! { "cycle_ms": 1.0, "queue_depth": 16,
//!   "axes": [ { "name": "X1", "unit": "mm", "counts_per_unit": 1000,
//!               "velocity": 100, "acceleration": 1000, "deceleration": 1000, "jerk": 0,
//!               "software_limits": { "negative": -500, "positive": 500 },
//!               "modulo_period": 0, "following_error_limit": 0 } ],
//!   "groups": [ { "name": "G1", "axes": [ { "axis": "X1", "identity": "X" } ] } ] }
//! ```

use diagnostics::{code, Diagnostic, Diagnostics, FileId, SourceMap, Span};
use serde::Deserialize;
use std::fmt::Write as _;

fn default_queue_depth() -> u32 {
    16
}
fn default_counts() -> f64 {
    1.0
}

#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
struct FileRepr {
    #[serde(default)]
    cycle_ms: Option<f64>,
    #[serde(default = "default_queue_depth")]
    queue_depth: u32,
    #[serde(default)]
    axes: Vec<AxisRepr>,
    #[serde(default)]
    groups: Vec<GroupRepr>,
}

#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
struct AxisRepr {
    name: String,
    #[serde(default)]
    unit: Option<String>,
    #[serde(default = "default_counts")]
    counts_per_unit: f64,
    velocity: f64,
    acceleration: f64,
    deceleration: f64,
    #[serde(default)]
    jerk: f64,
    #[serde(default)]
    software_limits: Option<SwLimits>,
    #[serde(default)]
    modulo_period: f64,
    #[serde(default)]
    following_error_limit: f64,
    /// The program's `AXIS_REF` this axis drives (`GVL_Axes.Axis1`, `MAIN.fbStation.Axis`).
    #[serde(default)]
    link: Option<String>,
    /// Tc2_MC2 MC_Jog's "low velocity for manual functions" (default 10 % of `velocity`).
    #[serde(default)]
    jog_velocity_slow: Option<f64>,
    /// Tc2_MC2 MC_Jog's "high velocity for manual functions" (default 50 % of `velocity`).
    #[serde(default)]
    jog_velocity_fast: Option<f64>,
}

#[derive(Debug, Clone, Copy, Deserialize)]
#[serde(deny_unknown_fields)]
struct SwLimits {
    negative: f64,
    positive: f64,
}

#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
struct GroupRepr {
    name: String,
    axes: Vec<MemberRepr>,
}

#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
struct MemberRepr {
    axis: String,
    identity: String,
}

/// One configured axis.
#[derive(Debug, Clone, PartialEq)]
pub struct Axis {
    /// The global `AXIS_REF` variable the axis becomes (`X1`).
    pub name: String,
    /// The user unit (`mm`, `deg`), shown in plots and the run summary.
    pub unit: Option<String>,
    /// Encoder counts per user unit (for drives and the PMAC backend; the engine works in user units).
    pub counts_per_unit: f64,
    /// The axis limits and settings the motion runtime gets.
    pub limits: c_backend::motion::MotionAxis,
    /// `"link"`: the instance path of the program's `AXIS_REF` this axis drives, and where the
    /// path is written in the axes file ([`crate::axis_links`]).
    pub link: Option<(String, Span)>,
    /// The program declares the global `AXIS_REF` of this name itself (a TwinCAT GVL): the axes
    /// file then declares none ([`AxisConfig::globals_il`]).
    pub declared_by_program: bool,
    /// MC_Jog's slow and fast manual velocities ([`crate::tc2_blocks`]).
    pub jog_velocities: (f64, f64),
    /// Tc2_MC2's standard acceleration and deceleration (a block's `Acceleration` /
    /// `Deceleration` left out or 0), when they differ from the limits (a TwinCAT NC axis's
    /// `Dynamic Acceleration` below its `AccelerationMaximum`, [`crate::nc_axes`]).
    pub standard_dynamics: Option<(f64, f64)>,
    /// The period MC_MoveModulo positions in when it is not the engine's modulo period (a TwinCAT
    /// NC axis's modulo factor: the axis itself stays linear, [`crate::nc_axes`]).
    pub modulo_factor: Option<f64>,
    /// The NC axis's `Id` (Tc2_MC2's `NcToPlc.AxisId`), for an axis read from a TwinCAT solution.
    pub nc_id: Option<u32>,
}

/// The axis configuration of a project.
#[derive(Debug, Clone, PartialEq)]
pub struct AxisConfig {
    /// The engine (= scan) cycle; `None`: the scan cycle of `run` (`--cycle-ms`, default 10 ms).
    pub cycle_ms: Option<f64>,
    /// The motion queue depth per axis and group (buffered blocks).
    pub queue_depth: u32,
    /// The axes, in file order.
    pub axes: Vec<Axis>,
    /// The axes groups (Part 4), each a global `AXES_GROUP_REF`.
    pub groups: Vec<c_backend::motion::MotionGroup>,
    /// The program uses a block ladderc builds ([`crate::tc2_blocks`]): the globals include the
    /// per-axis tables it reads (modulo period, acceleration and deceleration limits by `AxisNo`).
    pub tc2_tables: bool,
    /// The axes are a TwinCAT solution's NC axes: its `.tsproj` ([`crate::nc_axes`]).
    pub nc_solution: Option<String>,
}

impl Default for AxisConfig {
    fn default() -> Self {
        AxisConfig {
            cycle_ms: None,
            queue_depth: default_queue_depth(),
            axes: Vec::new(),
            groups: Vec::new(),
            tc2_tables: false,
            nc_solution: None,
        }
    }
}

/// Group identities: `X` is 0, `Y` 1, `Z` 2, then `A`, `B`, `C` (PLCopen IdentInGroup).
const IDENTITIES: [&str; 6] = ["X", "Y", "Z", "A", "B", "C"];

fn is_identifier(s: &str) -> bool {
    let mut c = s.chars();
    matches!(c.next(), Some(ch) if ch.is_ascii_alphabetic() || ch == '_')
        && c.all(|ch| ch.is_ascii_alphanumeric() || ch == '_')
        && !s.contains("__")
}

/// `v` as an IEC real literal (`360.0`, `1.5e-3`); `v` is finite (checked when the file is read).
fn real(v: f64) -> String {
    let t = format!("{v:e}");
    match t.split_once('e') {
        Some((m, e)) if !m.contains('.') => format!("{m}.0e{e}"),
        _ => t,
    }
}

/// The span of the first `"text"` string in the file after byte `from` (the whole file when absent).
fn string_span(file: FileId, src: &str, text: &str, from: usize) -> Span {
    let needle = format!("\"{text}\"");
    match src[from.min(src.len())..].find(&needle) {
        Some(i) => Span::new(file, from + i, from + i + needle.len()),
        None => Span::new(file, 0, 0),
    }
}

impl AxisConfig {
    /// Parses and checks a configuration registered as `file` in `map`. `None`: errors were reported.
    pub fn parse(map: &SourceMap, file: FileId, diags: &mut Diagnostics) -> Option<AxisConfig> {
        let sf = map.get(file);
        let src = sf.text.as_str();
        let repr: FileRepr = match serde_json::from_str(src) {
            Ok(r) => r,
            Err(e) => {
                let at = if e.line() == 0 {
                    0
                } else {
                    sf.offset_of(e.line(), e.column().max(1))
                };
                let msg = e.to_string();
                let msg = msg.split(" at line ").next().unwrap_or(&msg).to_string();
                diags.push(
                    Diagnostic::error(code::E5050, format!("invalid axis configuration: {msg}"))
                        .at(Span::new(file, at, (at + 1).min(src.len())))
                        .with_hint("see `ladderc explain E5050` for the file's fields"),
                );
                return None;
            }
        };
        let before = diags.error_count();
        if !repr.cycle_ms.is_none_or(|c| c.is_finite() && c > 0.0) || repr.queue_depth == 0 {
            diags.push(
                Diagnostic::error(
                    code::E5051,
                    "the cycle time must be a positive number of milliseconds and the queue depth at least 1",
                )
                .at(string_span(file, src, "cycle_ms", 0))
                .with_hint("e.g. \"cycle_ms\": 1.0, \"queue_depth\": 16"),
            );
        }
        let mut names: Vec<String> = Vec::new();
        let mut axes = Vec::new();
        let mut cursor = 0;
        for a in &repr.axes {
            let span = string_span(file, src, &a.name, cursor);
            cursor = span.range().end;
            let bad = |what: &str| {
                Diagnostic::error(code::E5051, format!("axis `{}`: {what}", a.name)).at(span)
            };
            if !is_identifier(&a.name) {
                diags.push(bad("the name is not an IEC identifier").with_hint(
                    "programs name the axis (`Axis := X1`): use letters, digits and single underscores",
                ));
            } else if names.iter().any(|n| n.eq_ignore_ascii_case(&a.name)) {
                diags.push(bad("the name is used twice"));
            }
            names.push(a.name.clone());
            let positive = |v: f64| v.is_finite() && v > 0.0;
            if !positive(a.velocity) || !positive(a.acceleration) || !positive(a.deceleration) {
                diags.push(bad("velocity, acceleration and deceleration limits must be finite and greater than 0")
                    .with_hint("give the axis's limits in user units per second (and per second squared)"));
            }
            if !(a.jerk.is_finite() && a.jerk >= 0.0) {
                diags.push(bad("the jerk limit must be 0 (none) or positive"));
            }
            let non_negative = |v: f64| v.is_finite() && v >= 0.0;
            if !non_negative(a.modulo_period)
                || !non_negative(a.following_error_limit)
                || !positive(a.counts_per_unit)
            {
                diags.push(bad("modulo_period and following_error_limit must be 0 or positive, counts_per_unit positive"));
            }
            if let Some(l) = a.software_limits {
                if !(l.negative.is_finite() && l.positive.is_finite() && l.negative < l.positive) {
                    diags.push(bad(
                        "software limits need finite values with negative < positive",
                    ));
                }
            }
            let link = a.link.as_ref().map(|l| {
                let at = string_span(file, src, l, span.range().start);
                (l.clone(), at)
            });
            let jog = (
                a.jog_velocity_slow.unwrap_or(0.1 * a.velocity),
                a.jog_velocity_fast.unwrap_or(0.5 * a.velocity),
            );
            let given = [a.jog_velocity_slow, a.jog_velocity_fast];
            if given.iter().flatten().any(|&v| !positive(v)) {
                diags.push(bad(
                    "jog_velocity_slow and jog_velocity_fast must be finite and greater than 0",
                ));
            }
            axes.push(Axis {
                link,
                declared_by_program: false,
                jog_velocities: jog,
                standard_dynamics: None,
                modulo_factor: None,
                nc_id: None,
                name: a.name.clone(),
                unit: a.unit.clone(),
                counts_per_unit: a.counts_per_unit,
                limits: c_backend::motion::MotionAxis {
                    name: a.name.clone(),
                    velocity_limit: a.velocity,
                    acceleration_limit: a.acceleration,
                    deceleration_limit: a.deceleration,
                    jerk_limit: a.jerk,
                    sw_limits: a.software_limits.map(|l| (l.positive, l.negative)),
                    modulo_period: a.modulo_period,
                    following_error_limit: a.following_error_limit,
                },
            });
        }
        let mut groups = Vec::new();
        for g in &repr.groups {
            let span = string_span(file, src, &g.name, cursor);
            cursor = span.range().end;
            if !is_identifier(&g.name) || names.iter().any(|n| n.eq_ignore_ascii_case(&g.name)) {
                diags.push(
                    Diagnostic::error(
                        code::E5052,
                        format!(
                            "group `{}`: the name is not an IEC identifier or is already used",
                            g.name
                        ),
                    )
                    .at(span),
                );
            }
            names.push(g.name.clone());
            let mut members = Vec::new();
            for m in &g.axes {
                let mspan = string_span(file, src, &m.axis, span.range().start);
                let axis = axes
                    .iter()
                    .position(|a: &Axis| a.name.eq_ignore_ascii_case(&m.axis));
                let ident = IDENTITIES
                    .iter()
                    .position(|i| i.eq_ignore_ascii_case(&m.identity));
                match (axis, ident) {
                    (Some(a), Some(i))
                        if !members.iter().any(|&(x, y)| x == a as u32 || y == i as u32) =>
                    {
                        members.push((a as u32, i as u32))
                    }
                    (None, _) => diags.push(
                        Diagnostic::error(
                            code::E5052,
                            format!("group `{}`: no axis named `{}`", g.name, m.axis),
                        )
                        .at(mspan)
                        .with_hint("list the axis under \"axes\" first"),
                    ),
                    (_, None) => diags.push(
                        Diagnostic::error(
                            code::E5052,
                            format!(
                                "group `{}`: identity `{}` is not one of X, Y, Z, A, B, C",
                                g.name, m.identity
                            ),
                        )
                        .at(mspan),
                    ),
                    _ => diags.push(
                        Diagnostic::error(
                            code::E5052,
                            format!(
                                "group `{}`: axis `{}` or identity `{}` appears twice",
                                g.name, m.axis, m.identity
                            ),
                        )
                        .at(mspan),
                    ),
                }
            }
            groups.push(c_backend::motion::MotionGroup {
                name: g.name.clone(),
                members,
            });
        }
        if diags.error_count() > before {
            return None;
        }
        Some(AxisConfig {
            cycle_ms: repr.cycle_ms,
            queue_depth: repr.queue_depth,
            axes,
            groups,
            tc2_tables: false,
            nc_solution: None,
        })
    }

    /// IL declaring one global reference per axis and group (parsed after the block prelude).
    pub fn globals_il(&self) -> String {
        let mut s = String::from("(* axes and groups of the axis configuration *)\n");
        if self.axes.iter().all(|a| a.declared_by_program)
            && self.groups.is_empty()
            && !self.tc2_tables
        {
            return s;
        }
        s.push_str("VAR_GLOBAL\n");
        if self.tc2_tables {
            let n = self.axes.len().max(1);
            let table = |f: &dyn Fn(&Axis) -> f64| -> String {
                let mut v: Vec<String> = self.axes.iter().map(|a| real(f(a))).collect();
                if v.is_empty() {
                    v.push("0.0".into());
                }
                v.join(", ")
            };
            for (name, values) in [
                (
                    "MODULO",
                    table(&|a| a.modulo_factor.unwrap_or(a.limits.modulo_period)),
                ),
                (
                    "ACC",
                    table(&|a| {
                        a.standard_dynamics
                            .map_or(a.limits.acceleration_limit, |d| d.0)
                    }),
                ),
                (
                    "DEC",
                    table(&|a| {
                        a.standard_dynamics
                            .map_or(a.limits.deceleration_limit, |d| d.1)
                    }),
                ),
                ("JOGSLOW", table(&|a| a.jog_velocities.0)),
                ("JOGFAST", table(&|a| a.jog_velocities.1)),
            ] {
                let _ = writeln!(
                    s,
                    "    __TC2_{name} : ARRAY [0..{}] OF LREAL := [{values}];",
                    n - 1
                );
            }
            // Tc2_MC2's `Status.Homed` per axis: not homed at the start (crate::tc2_blocks)
            let _ = writeln!(s, "    __TC2_HOMED : ARRAY [0..{}] OF BOOL;", n - 1);
            // Tc2_MC2's `PlcToNc.Override` per axis (UDINT, 1000000 = 100 %): what the program
            // last wrote into it, 100 % at the start as the NC's override; the last entry,
            // `__TC2_NO_AXIS`, is what an unbound `REFERENCE TO AXIS_REF` reads: 0, never
            // written (crate::tc2_axis_ref)
            let _ = writeln!(
                s,
                "    __TC2_OVERRIDE : ARRAY [0..{n}] OF UDINT := [{}, 0];",
                vec!["1000000"; n].join(", ")
            );
            let _ = writeln!(s, "    __TC2_NO_AXIS : UDINT := {n};");
            // `NcToPlc.AxisId`: the NC axis's Id, else the axis's place in the file from 1
            let mut ids: Vec<String> = (self.axes.iter().enumerate())
                .map(|(i, a)| a.nc_id.unwrap_or(i as u32 + 1).to_string())
                .collect();
            if ids.is_empty() {
                ids.push("0".into());
            }
            let _ = writeln!(
                s,
                "    __TC2_AXISID : ARRAY [0..{}] OF UDINT := [{}];",
                n - 1,
                ids.join(", ")
            );
        }
        for (i, a) in self.axes.iter().enumerate() {
            if a.declared_by_program {
                continue;
            }
            let _ = writeln!(s, "    {} : AXIS_REF := (AxisNo := {i});", a.name);
        }
        for (j, g) in self.groups.iter().enumerate() {
            let _ = writeln!(s, "    {} : AXES_GROUP_REF := (GroupNo := {j});", g.name);
        }
        s.push_str("END_VAR\n");
        s
    }

    /// The motion runtime of the generated C.
    pub fn runtime(&self, cycle_ms: f64, header: &str) -> c_backend::motion::MotionRuntime {
        c_backend::motion::MotionRuntime {
            cycle_seconds: cycle_ms / 1000.0,
            queue_depth: self.queue_depth,
            axes: self.axes.iter().map(|a| a.limits.clone()).collect(),
            groups: self.groups.clone(),
            header: header.to_string(),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn parse(text: &str) -> (Option<AxisConfig>, String) {
        let mut map = SourceMap::new();
        let f = map.add("m.axes.json", text);
        let mut d = Diagnostics::new();
        let c = AxisConfig::parse(&map, f, &mut d);
        let out = diagnostics::render(&map, &d.into_sorted(), diagnostics::MessageFormat::Short);
        (c, out)
    }

    #[test]
    fn a_full_configuration_parses_with_groups_and_defaults() {
        let (c, out) = parse(
            r#"{ "cycle_ms": 1, "axes": [
                { "name": "X1", "velocity": 100, "acceleration": 1000, "deceleration": 500, "jerk": 10000,
                  "software_limits": { "negative": -5, "positive": 500 } },
                { "name": "Y1", "velocity": 50, "acceleration": 100, "deceleration": 100 } ],
              "groups": [ { "name": "G1", "axes": [ { "axis": "Y1", "identity": "X" }, { "axis": "X1", "identity": "y" } ] } ] }"#,
        );
        let c = c.unwrap_or_else(|| panic!("{out}"));
        assert_eq!(c.queue_depth, 16);
        assert_eq!(c.axes[0].limits.sw_limits, Some((500.0, -5.0)));
        assert_eq!(c.axes[1].limits.jerk_limit, 0.0);
        assert_eq!(c.groups[0].members, vec![(1, 0), (0, 1)]);
        let il = c.globals_il();
        assert!(il.contains("X1 : AXIS_REF := (AxisNo := 0);"), "{il}");
        assert!(il.contains("Y1 : AXIS_REF := (AxisNo := 1);"), "{il}");
        assert!(
            il.contains("G1 : AXES_GROUP_REF := (GroupNo := 0);"),
            "{il}"
        );
        assert_eq!(c.cycle_ms, Some(1.0));
        assert_eq!(c.runtime(1.0, "h").cycle_seconds, 0.001);
    }

    #[test]
    fn links_jog_velocities_and_the_tc2_tables() {
        let (c, out) = parse(
            r#"{ "axes": [
                { "name": "A", "velocity": 100, "acceleration": 10, "deceleration": 20,
                  "link": "MAIN.st.Axis", "jog_velocity_slow": 5 },
                { "name": "B", "velocity": 200, "acceleration": 30, "deceleration": 40,
                  "modulo_period": 360 } ] }"#,
        );
        let mut c = c.unwrap_or_else(|| panic!("{out}"));
        assert_eq!(
            c.axes[0].link.as_ref().map(|l| l.0.as_str()),
            Some("MAIN.st.Axis")
        );
        assert_eq!(c.axes[0].jog_velocities, (5.0, 50.0));
        assert_eq!(c.axes[1].jog_velocities, (20.0, 100.0));
        c.tc2_tables = true;
        c.axes[1].declared_by_program = true;
        let il = c.globals_il();
        assert!(il.contains("A : AXIS_REF := (AxisNo := 0);"), "{il}");
        assert!(!il.contains("B : AXIS_REF"), "{il}");
        assert!(
            il.contains("__TC2_MODULO : ARRAY [0..1] OF LREAL := [0.0e0, 3.6e2];"),
            "{il}"
        );
        assert!(
            il.contains("__TC2_DEC : ARRAY [0..1] OF LREAL := [2.0e1, 4.0e1];"),
            "{il}"
        );
        let (c, out) = parse(
            r#"{ "axes": [ { "name": "A", "velocity": 1, "acceleration": 1, "deceleration": 1,
                "jog_velocity_fast": -1 } ] }"#,
        );
        assert!(
            c.is_none() && out.contains("jog_velocity_slow and jog_velocity_fast"),
            "{out}"
        );
    }

    #[test]
    fn json_errors_point_at_serde_line_and_column() {
        let (c, out) = parse(
            "{\n  \"cycle_ms\": 1,\n  \"axes\": [ { \"name\": \"X1\", \"velocity\": 1 } ]\n}",
        );
        assert!(c.is_none());
        insta::assert_snapshot!(out);
        let (_, out) = parse("{ \"cycle_ms\": 1, \"speed\": 3 }");
        assert!(
            out.contains("E5050") && out.contains("unknown field `speed`"),
            "{out}"
        );
    }

    #[test]
    fn bad_values_are_reported_at_the_axis_name() {
        let (c, out) = parse(
            r#"{ "axes": [ { "name": "X1", "velocity": 0, "acceleration": 1, "deceleration": 1 },
                           { "name": "x1", "velocity": 1, "acceleration": 1, "deceleration": 1 },
                           { "name": "bad name", "velocity": 1, "acceleration": 1, "deceleration": 1 } ],
                "groups": [ { "name": "G", "axes": [ { "axis": "Q", "identity": "X" }, { "axis": "X1", "identity": "W" } ] } ],
                "cycle_ms": -1 }"#,
        );
        assert!(c.is_none());
        insta::assert_snapshot!(out);
    }
}
