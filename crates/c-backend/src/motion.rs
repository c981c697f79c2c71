//! The motion runtime of a generated program that uses PLCopen motion blocks.
//!
//! Input: a [`MotionRuntime`] (engine cycle time, buffer depth, axes with their limits, groups) and the text
//! of the motion library's C header (`motion_lib.h`, supplied by the caller, which depends on motion-lib).
//! Output: `ladderc_motion.c` (one global engine created by `ladderc_motion_init`, returned by
//! `struct McEngine *ladderc_motion_engine(void)` to the block bodies, stepped once per scan cycle by
//! `ladderc_motion_step` after every program ran, destroyed at exit), `motion_lib.h`, and the watchable
//! trace columns `axis.<name>.position|velocity|acceleration` (set values after the cycle's engine step),
//! `axis.<name>.stop_decel_requested|stop_decel_reached|stop_jerk_requested|stop_jerk_reached` (non-zero
//! only in the first cycle of an MC_Stop whose Deceleration or Jerk the axis limits capped)
//! and `group.<name>.junction_requested|junction_reached` (non-zero only in the cycle the path passes a
//! junction whose speed the axis limits lowered).
//! Invariants: axis `i` of the configuration is engine axis `i` (the `AxisNo` of its `AXIS_REF`), group
//! `j` is engine group `j`; the engine's cycle time is the scan cycle time (the caller checks that they
//! agree); a configuration the engine refuses stops the program at init with exit status 3 and a message.

use crate::mangle;
use std::fmt::Write as _;

/// One configured axis (user units).
#[derive(Debug, Clone, PartialEq)]
pub struct MotionAxis {
    /// The global `AXIS_REF` variable's name.
    pub name: String,
    /// Velocity limit (units/s).
    pub velocity_limit: f64,
    /// Acceleration limit (units/s²).
    pub acceleration_limit: f64,
    /// Deceleration limit (units/s²).
    pub deceleration_limit: f64,
    /// 0: no jerk limit.
    pub jerk_limit: f64,
    /// Software limits (`None`: not checked).
    pub sw_limits: Option<(f64, f64)>,
    /// 0: a linear axis.
    pub modulo_period: f64,
    /// 0: not checked.
    pub following_error_limit: f64,
}

/// One configured axes group: its members as `(axis index, identity in group 0=X 1=Y 2=Z ...)`.
#[derive(Debug, Clone, PartialEq)]
pub struct MotionGroup {
    /// The global `AXES_GROUP_REF` variable's name.
    pub name: String,
    /// `(axis index, identity in group)` per member.
    pub members: Vec<(u32, u32)>,
}

/// Everything the generated program needs to create and step its motion engine.
#[derive(Debug, Clone, PartialEq)]
pub struct MotionRuntime {
    /// The engine cycle in seconds (equal to the scan cycle).
    pub cycle_seconds: f64,
    /// Buffered commands per axis and group.
    pub queue_depth: u32,
    /// The axes, in configuration order (engine index).
    pub axes: Vec<MotionAxis>,
    /// The axes groups.
    pub groups: Vec<MotionGroup>,
    /// `motion_lib.h` (the motion library's C ABI).
    pub header: String,
}

/// The trace columns of one axis: `(suffix, C array)`.
const SIGNALS: [(&str, &str); 3] = [
    ("position", "ladderc_axis_position"),
    ("velocity", "ladderc_axis_velocity"),
    ("acceleration", "ladderc_axis_acceleration"),
];

/// The trace columns of one axis about a capped MC_Stop: `(suffix, C array, motion-lib reader)`.
/// All 0 except in the first cycle of an MC_Stop whose Deceleration or Jerk the axis limits capped.
const STOP_SIGNALS: [(&str, &str, &str); 4] = [
    (
        "stop_decel_requested",
        "ladderc_axis_stop_decel_requested",
        "mc_axis_stop_decel_requested",
    ),
    (
        "stop_decel_reached",
        "ladderc_axis_stop_decel_reached",
        "mc_axis_stop_decel_reached",
    ),
    (
        "stop_jerk_requested",
        "ladderc_axis_stop_jerk_requested",
        "mc_axis_stop_jerk_requested",
    ),
    (
        "stop_jerk_reached",
        "ladderc_axis_stop_jerk_reached",
        "mc_axis_stop_jerk_reached",
    ),
];

/// The trace columns of one group: `(suffix, C array, motion-lib reader)`. Both are 0 except
/// in the cycle the path passes a junction whose speed the limits lowered.
const GROUP_SIGNALS: [(&str, &str, &str); 2] = [
    (
        "junction_requested",
        "ladderc_group_junction_requested",
        "mc_group_junction_requested",
    ),
    (
        "junction_reached",
        "ladderc_group_junction_reached",
        "mc_group_junction_reached",
    ),
];

/// A finite `f64` as a C `double` literal (non-finite values become 0: the configuration loader refuses
/// them before this point).
fn c_double(v: f64) -> String {
    if v.is_finite() {
        format!("{v:?}")
    } else {
        "0.0".into()
    }
}

impl MotionRuntime {
    fn array_len(&self) -> usize {
        self.axes.len().max(1)
    }

    fn group_len(&self) -> usize {
        self.groups.len().max(1)
    }

    /// The files of the runtime, with their relative paths in the generated project.
    pub fn files(&self) -> Vec<(String, String)> {
        vec![
            ("ladderc_motion.c".into(), self.runtime_c()),
            ("motion_lib.h".into(), self.header.clone()),
        ]
    }

    /// The line `ladderc_config.h` gets: the harness's default scan cycle is the engine cycle, so that a
    /// built program run without `--cycle-ms` moves its axes at the planned speed.
    pub fn config_define(&self) -> String {
        let ns = (self.cycle_seconds * 1e9).round();
        let ns = if ns.is_finite() && ns >= 1.0 {
            ns as i64
        } else {
            10_000_000
        };
        format!("#define LADDERC_DEFAULT_CYCLE_NS {ns}\n")
    }

    /// Declarations `program.c` needs (the hooks and the trace arrays).
    pub fn declarations(&self) -> String {
        let mut s = String::from(
            "/* Motion runtime (ladderc_motion.c) */\nvoid ladderc_motion_init(void);\nvoid ladderc_motion_step(void);\n",
        );
        for (_, arr) in SIGNALS {
            let _ = writeln!(s, "extern IEC_LREAL {arr}[{}];", self.array_len());
        }
        for (_, arr, _) in STOP_SIGNALS {
            let _ = writeln!(s, "extern IEC_LREAL {arr}[{}];", self.array_len());
        }
        for (_, arr, _) in GROUP_SIGNALS {
            let _ = writeln!(s, "extern IEC_LREAL {arr}[{}];", self.group_len());
        }
        s
    }

    /// Entries of the watchable-variable table (`ladderc_vars`), one per axis and signal.
    pub fn watch_entries(&self) -> Vec<String> {
        let mut out = Vec::new();
        for (i, a) in self.axes.iter().enumerate() {
            let stop = STOP_SIGNALS.iter().map(|(s, a, _)| (*s, *a));
            for (suffix, arr) in SIGNALS.into_iter().chain(stop) {
                let name = format!("axis.{}.{suffix}", a.name);
                out.push(format!(
                    "{{ {}, LADDERC_T_LREAL, (void *)&{arr}[{i}], NULL, 0, 0 }}",
                    mangle::c_string(name.as_bytes())
                ));
            }
        }
        for (j, g) in self.groups.iter().enumerate() {
            for (suffix, arr, _) in GROUP_SIGNALS {
                let name = format!("group.{}.{suffix}", g.name);
                out.push(format!(
                    "{{ {}, LADDERC_T_LREAL, (void *)&{arr}[{j}], NULL, 0, 0 }}",
                    mangle::c_string(name.as_bytes())
                ));
            }
        }
        out
    }

    fn runtime_c(&self) -> String {
        let n = self.array_len();
        let mut c = String::from(
            "/* Motion runtime generated by ladderc: one engine for the whole program, created at init from the\n \
             * axis configuration, stepped once per scan cycle after the programs ran (engine cycle = scan cycle). */\n\
             #include \"ladderc_rt.h\"\n#include \"motion_lib.h\"\n#include <stdio.h>\n#include <stdlib.h>\n\n",
        );
        for (_, arr) in SIGNALS {
            let _ = writeln!(c, "IEC_LREAL {arr}[{n}];");
        }
        for (_, arr, _) in STOP_SIGNALS {
            let _ = writeln!(c, "IEC_LREAL {arr}[{n}];");
        }
        for (_, arr, _) in GROUP_SIGNALS {
            let _ = writeln!(c, "IEC_LREAL {arr}[{}];", self.group_len());
        }
        c.push_str(
            "static struct McEngine *ladderc_engine;\n\n\
             struct McEngine *ladderc_motion_engine(void);\nvoid ladderc_motion_init(void);\nvoid ladderc_motion_step(void);\n\n\
             struct McEngine *ladderc_motion_engine(void) { return ladderc_engine; }\n\n\
             static void ladderc_motion_shutdown(void) {\n    mc_engine_destroy(ladderc_engine);\n    ladderc_engine = NULL;\n}\n\n\
             static void ladderc_motion_fail(const char *what) {\n    fprintf(stderr, \"motion: the engine refused %s\\n\", what);\n    ladderc_motion_shutdown();\n    exit(3);\n}\n\n",
        );
        c.push_str("static void ladderc_motion_sample(void) {\n");
        // No loop over zero axes or groups: `i < 0u` fails -Wextra -Werror (-Wtype-limits).
        if !self.axes.is_empty() || !self.groups.is_empty() {
            c.push_str("    uint32_t i;\n");
        }
        if !self.axes.is_empty() {
            let _ = writeln!(c, "    for (i = 0; i < {}u; i++) {{", self.axes.len());
            c.push_str(
                "        ladderc_axis_position[i] = mc_axis_set_position(ladderc_engine, i);\n\
                 \x20       ladderc_axis_velocity[i] = mc_axis_set_velocity(ladderc_engine, i);\n\
                 \x20       ladderc_axis_acceleration[i] = mc_axis_set_acceleration(ladderc_engine, i);\n",
            );
            for (_, arr, reader) in STOP_SIGNALS {
                let _ = writeln!(c, "        {arr}[i] = {reader}(ladderc_engine, i);");
            }
            c.push_str("    }\n");
        }
        if !self.groups.is_empty() {
            let _ = writeln!(c, "    for (i = 0; i < {}u; i++) {{", self.groups.len());
            for (_, arr, reader) in GROUP_SIGNALS {
                let _ = writeln!(c, "        {arr}[i] = {reader}(ladderc_engine, i);");
            }
            c.push_str("    }\n");
        }
        c.push_str("}\n\n");
        c.push_str("void ladderc_motion_init(void) {\n    static int registered;\n    if (ladderc_engine) ladderc_motion_shutdown();\n");
        let _ = writeln!(
            c,
            "    ladderc_engine = mc_engine_create({}, {}u);",
            c_double(self.cycle_seconds),
            self.queue_depth
        );
        c.push_str(
            "    if (mc_abi_version() != MC_ABI_VERSION) ladderc_motion_fail(\"this program: it was compiled against another motion_lib.h\");\n",
        );
        c.push_str(
            "    if (!ladderc_engine) ladderc_motion_fail(\"the cycle time or queue depth\");\n",
        );
        c.push_str("    if (!registered) {\n        registered = 1;\n        atexit(ladderc_motion_shutdown);\n    }\n");
        for (i, a) in self.axes.iter().enumerate() {
            let (pos, neg, on) = match a.sw_limits {
                Some((p, n)) => (p, n, "true"),
                None => (0.0, 0.0, "false"),
            };
            let _ = writeln!(c, "    {{ /* axis {i}: {} */", c_comment(&a.name));
            c.push_str("        MC_AxisConfig_C cfg;\n        McIndex index = 0;\n        memset(&cfg, 0, sizeof cfg);\n");
            for (field, v) in [
                ("VelocityLimit", a.velocity_limit),
                ("AccelerationLimit", a.acceleration_limit),
                ("DecelerationLimit", a.deceleration_limit),
                ("JerkLimit", a.jerk_limit),
                ("SwLimitPositive", pos),
                ("SwLimitNegative", neg),
                ("ModuloPeriod", a.modulo_period),
                ("FollowingErrorLimit", a.following_error_limit),
            ] {
                let _ = writeln!(c, "        cfg.{field} = {};", c_double(v));
            }
            let _ = writeln!(c, "        cfg.SwLimitsEnabled = {on};");
            let _ = writeln!(
                c,
                "        if (mc_engine_add_axis(ladderc_engine, &cfg, &index) != MC_OK || index != {i}u) ladderc_motion_fail({});\n    }}",
                mangle::c_string(format!("the limits of axis {}", a.name).as_bytes())
            );
        }
        for (j, g) in self.groups.iter().enumerate() {
            let _ = writeln!(c, "    {{ /* group {j}: {} */", c_comment(&g.name));
            let _ = writeln!(
                c,
                "        McIndex index = 0;\n        if (mc_engine_add_group(ladderc_engine, &index) != MC_OK || index != {j}u) ladderc_motion_fail({});",
                mangle::c_string(format!("group {}", g.name).as_bytes())
            );
            for (axis, ident) in &g.members {
                let _ = writeln!(
                    c,
                    "        {{\n            MC_AddAxisToGroup_C add;\n            memset(&add, 0, sizeof add);\n            \
                     add.Execute = true;\n            add.Axis = {axis}u;\n            add.IdentInGroup = {ident}u;\n            \
                     mc_add_axis_to_group(ladderc_engine, {j}u, &add);\n            if (!add.Done) ladderc_motion_fail({});\n        }}",
                    mangle::c_string(format!("a member of group {}", g.name).as_bytes())
                );
            }
            c.push_str("    }\n");
        }
        c.push_str("    ladderc_motion_sample();\n}\n\n");
        c.push_str("void ladderc_motion_step(void) {\n    if (mc_engine_step(ladderc_engine) != MC_OK) ladderc_motion_fail(\"a cycle (internal error of the motion library)\");\n    ladderc_motion_sample();\n}\n");
        c
    }
}

/// Text safe inside a C block comment.
fn c_comment(s: &str) -> String {
    s.chars()
        .filter(|c| c.is_ascii_alphanumeric() || *c == '_')
        .collect()
}

/// The linker arguments a program with the motion runtime needs after its sources: the static library
/// and the system libraries a Rust staticlib depends on.
pub fn link_args(staticlib: &str) -> Vec<String> {
    vec![
        staticlib.to_string(),
        "-lpthread".into(),
        "-ldl".into(),
        "-lm".into(),
    ]
}

/// The file name of the motion library inside a generated project.
pub const STATICLIB: &str = "libmotion_lib.a";
