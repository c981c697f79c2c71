//! The block library: the built-in templates (`templates/*.xml` of the repository, compiled in) plus a user
//! directory (`--templates DIR`), whose files replace built-ins of the same block name.
//!
//! Input: template files. Output: a [`Library`] of validated templates, looked up case-insensitively by block
//! name; every problem is a diagnostic in the template file. Invariant: block names are unique in a library.

use crate::cbody::{self, Scope};
use crate::template::{self, Template};
use diagnostics::{code, Diagnostic, Diagnostics, SourceMap};
use std::collections::BTreeSet;
use std::path::Path;

/// The built-in templates: (file name, text).
pub const BUILTIN: &[(&str, &str)] = &[
    (
        "MC_AddAxisToGroup.xml",
        include_str!("../../../templates/MC_AddAxisToGroup.xml"),
    ),
    (
        "MC_GearIn.xml",
        include_str!("../../../templates/MC_GearIn.xml"),
    ),
    (
        "MC_GroupDisable.xml",
        include_str!("../../../templates/MC_GroupDisable.xml"),
    ),
    (
        "MC_GroupEnable.xml",
        include_str!("../../../templates/MC_GroupEnable.xml"),
    ),
    (
        "MC_GroupHalt.xml",
        include_str!("../../../templates/MC_GroupHalt.xml"),
    ),
    (
        "MC_GroupHome.xml",
        include_str!("../../../templates/MC_GroupHome.xml"),
    ),
    (
        "MC_GroupReadActualPosition.xml",
        include_str!("../../../templates/MC_GroupReadActualPosition.xml"),
    ),
    (
        "MC_GroupReadActualVelocity.xml",
        include_str!("../../../templates/MC_GroupReadActualVelocity.xml"),
    ),
    (
        "MC_GroupReadStatus.xml",
        include_str!("../../../templates/MC_GroupReadStatus.xml"),
    ),
    (
        "MC_GroupReset.xml",
        include_str!("../../../templates/MC_GroupReset.xml"),
    ),
    (
        "MC_GroupStop.xml",
        include_str!("../../../templates/MC_GroupStop.xml"),
    ),
    (
        "MC_Halt.xml",
        include_str!("../../../templates/MC_Halt.xml"),
    ),
    (
        "MC_Home.xml",
        include_str!("../../../templates/MC_Home.xml"),
    ),
    (
        "MC_MoveAbsolute.xml",
        include_str!("../../../templates/MC_MoveAbsolute.xml"),
    ),
    (
        "MC_MoveAdditive.xml",
        include_str!("../../../templates/MC_MoveAdditive.xml"),
    ),
    (
        "MC_MoveCircularAbsolute.xml",
        include_str!("../../../templates/MC_MoveCircularAbsolute.xml"),
    ),
    (
        "MC_MoveCircularRelative.xml",
        include_str!("../../../templates/MC_MoveCircularRelative.xml"),
    ),
    (
        "MC_MoveDirectAbsolute.xml",
        include_str!("../../../templates/MC_MoveDirectAbsolute.xml"),
    ),
    (
        "MC_MoveLinearAbsolute.xml",
        include_str!("../../../templates/MC_MoveLinearAbsolute.xml"),
    ),
    (
        "MC_MoveLinearRelative.xml",
        include_str!("../../../templates/MC_MoveLinearRelative.xml"),
    ),
    (
        "MC_MoveRelative.xml",
        include_str!("../../../templates/MC_MoveRelative.xml"),
    ),
    (
        "MC_MoveVelocity.xml",
        include_str!("../../../templates/MC_MoveVelocity.xml"),
    ),
    (
        "MC_Power.xml",
        include_str!("../../../templates/MC_Power.xml"),
    ),
    (
        "MC_ReadActualPosition.xml",
        include_str!("../../../templates/MC_ReadActualPosition.xml"),
    ),
    (
        "MC_ReadActualVelocity.xml",
        include_str!("../../../templates/MC_ReadActualVelocity.xml"),
    ),
    (
        "MC_ReadAxisError.xml",
        include_str!("../../../templates/MC_ReadAxisError.xml"),
    ),
    (
        "MC_ReadStatus.xml",
        include_str!("../../../templates/MC_ReadStatus.xml"),
    ),
    (
        "MC_RemoveAxisFromGroup.xml",
        include_str!("../../../templates/MC_RemoveAxisFromGroup.xml"),
    ),
    (
        "MC_Reset.xml",
        include_str!("../../../templates/MC_Reset.xml"),
    ),
    (
        "MC_SetOverride.xml",
        include_str!("../../../templates/MC_SetOverride.xml"),
    ),
    (
        "MC_SetPosition.xml",
        include_str!("../../../templates/MC_SetPosition.xml"),
    ),
    (
        "MC_Stop.xml",
        include_str!("../../../templates/MC_Stop.xml"),
    ),
    (
        "MC_UngroupAllAxes.xml",
        include_str!("../../../templates/MC_UngroupAllAxes.xml"),
    ),
];

#[derive(Debug, Default, Clone)]
pub struct Library {
    templates: Vec<Template>,
}

impl Library {
    pub fn new() -> Self {
        Self::default()
    }
    /// Loads the built-in templates.
    pub fn builtin(map: &mut SourceMap, diags: &mut Diagnostics) -> Self {
        let mut lib = Library::new();
        for (name, text) in BUILTIN {
            lib.add_text(map, &format!("templates/{name}"), text, diags);
        }
        lib
    }
    /// Loads every `*.xml` of `dir` (sorted by name); they replace built-ins of the same block name.
    pub fn add_dir(&mut self, dir: &Path, map: &mut SourceMap, diags: &mut Diagnostics) {
        let entries = match std::fs::read_dir(dir) {
            Ok(e) => e,
            Err(e) => {
                diags.push(
                    Diagnostic::error(
                        code::E9001,
                        format!("cannot read the template directory {}: {e}", dir.display()),
                    )
                    .with_hint("pass an existing directory of template files to --templates"),
                );
                return;
            }
        };
        let mut paths: Vec<_> = entries
            .filter_map(|e| e.ok().map(|e| e.path()))
            .filter(|p| p.extension().is_some_and(|x| x.eq_ignore_ascii_case("xml")))
            .collect();
        paths.sort();
        for p in paths {
            match std::fs::read_to_string(&p) {
                Ok(text) => self.add_text(map, &p.display().to_string(), &text, diags),
                Err(e) => diags.push(
                    Diagnostic::error(code::E9001, format!("cannot read {}: {e}", p.display()))
                        .with_hint("template files must be readable UTF-8"),
                ),
            }
        }
    }
    /// Adds one template file's text (replacing a template of the same block name).
    pub fn add_text(
        &mut self,
        map: &mut SourceMap,
        name: &str,
        text: &str,
        diags: &mut Diagnostics,
    ) {
        let file = map.add(name, text);
        if let Some(t) = template::load(file, text, diags) {
            self.templates
                .retain(|old| !old.block.eq_ignore_ascii_case(&t.block));
            self.templates.push(t);
        }
    }
    pub fn get(&self, block: &str) -> Option<&Template> {
        self.templates
            .iter()
            .find(|t| t.block.eq_ignore_ascii_case(block))
    }
    pub fn templates(&self) -> &[Template] {
        &self.templates
    }
    /// Checks every body against its head and the runtime symbols (see [`crate::cbody`]).
    pub fn check_bodies(&self, runtime: &BTreeSet<String>, diags: &mut Diagnostics) -> bool {
        let embedded: BTreeSet<String> = self.templates.iter().map(|t| t.block.clone()).collect();
        let mut clean = true;
        for t in &self.templates {
            let mut declared: BTreeSet<String> = t.params.iter().map(|p| p.abbr.clone()).collect();
            declared.insert("FuncNum".into());
            declared.extend(t.locals.iter().map(|l| l.name.clone()));
            let scope = Scope {
                declared,
                runtime,
                embedded_functions: &embedded,
            };
            clean &= cbody::check(&t.body, &scope, &t.block, diags);
        }
        clean
    }
}

/// The identifiers a C header declares (functions, types, macros): what template bodies may call.
pub fn header_symbols(header: &str) -> BTreeSet<String> {
    let (toks, _) = cbody::tokens(header);
    toks.iter()
        .filter(|t| t.kind == cbody::Tok::Ident)
        .map(|t| header[t.start..t.end].to_string())
        .collect()
}

/// The symbols template bodies may use: the motion library's header and the runtime's engine accessor.
pub fn runtime_symbols() -> BTreeSet<String> {
    let mut s = header_symbols(MOTION_HEADER);
    s.insert("ladderc_motion_engine".into());
    s
}

/// The motion library's C header (generated by cbindgen, committed in crates/motion-lib/include).
pub const MOTION_HEADER: &str = include_str!("../../motion-lib/include/motion_lib.h");
