//! The NC axes of a TwinCAT solution (`_Config/NC`), read as the axis configuration when no axes
//! file is given.
//!
//! Input: the command line's paths (a `.plcproj`, or a folder holding one); the solution's
//! `.tsproj` found beside the PLC project or up to three folders above it (or below a folder
//! given), the NC configuration it holds (`<NC>` with its `<Axis>` elements) or names
//! (`<NC File="NC.xti"/>` -> `_Config/NC/NC.xti`, `<Axis File="Axis 1.xti"/>` ->
//! `_Config/NC/Axes/Axis 1.xti`), and the `<Mappings>` that link each axis to a PLC `AXIS_REF`
//! ("Link To PLC": `<Link VarA="PlcTask Inputs^MAIN.Axis.NcToPlc" VarB="Outputs^ToPlc"/>` under
//! the axis `TINC^NC-Task 1 SAF^Axes^Axis 1`). Output: an [`AxisConfig`] with one axis per NC
//! axis, in the NC's order, its `link` the `AXIS_REF`'s instance path ([`crate::axis_links`]),
//! its limits from the axis parameters. Invariants: never panics; a solution without NC axes
//! gives `None` (the empty configuration, as before); every value used is finite and positive
//! (limits) or finite (positions); a parameter the files do not give, or give in a form ladderc
//! cannot read, gets [`DEFAULTS`]'s value and one located W1428 per axis that names it; a file
//! the NC configuration names that cannot be read or is not XML is one located E1047.
//!
//! The parameters read (TwinCAT writes only those that differ from its defaults):
//!
//! | XTI element, attribute | ladderc |
//! |---|---|
//! | `Velo Maximum` | velocity limit |
//! | `Dynamic AccelerationMaximum`, `DecelerationMaximum` | acceleration / deceleration limits |
//! | `Dynamic Acceleration`, `Deceleration` | Tc2_MC2's standard dynamics (a block's 0 or omitted input); also the limits when no maximum is given |
//! | `Dynamic Jerk` | jerk limit |
//! | `Velo FastManual`, `SlowManual` | MC_Jog's manual velocities |
//! | `EncPara SoftEndMinControl`/`SoftEndMaxControl` (`Enable`, `Range`) | software limits |
//! | `EncPara ModuloFactor` | the period MC_MoveModulo positions in (the axis itself stays linear, as in TwinCAT) |
//! | `PosDiffControl` (`Enable`, `Range`) | following error limit |
//! | `EncPara ScaleFactorNumerator`, `ScaleFactorDenominator` | counts per unit (PMAC output) |
//! | `General UnitName` | the unit (plots) |

use crate::axes::{Axis, AxisConfig};
use crate::pipeline::Session;
use diagnostics::{code, Diagnostic, Severity, Span};
use ladder_compiler::xml::{Arena, Element};
use std::path::{Path, PathBuf};

/// A parameter's default: (what, TwinCAT's element and attribute, value).
pub const DEFAULTS: &[(&str, &str, f64)] = &[
    ("maximum velocity", "Velo Maximum", 2000.0),
    ("acceleration", "Dynamic Acceleration", 15000.0),
    ("deceleration", "Dynamic Deceleration", 15000.0),
    ("jerk", "Dynamic Jerk", 2_250_000.0),
    ("manual velocity (fast)", "Velo FastManual", 600.0),
    ("manual velocity (slow)", "Velo SlowManual", 100.0),
    ("position lag limit", "PosDiffControl Range", 5.0),
    ("modulo factor", "EncPara ModuloFactor", 360.0),
];

fn default(what: &str) -> f64 {
    DEFAULTS
        .iter()
        .find(|(w, _, _)| *w == what)
        .map_or(0.0, |d| d.2)
}

/// The `.tsproj` of the solution the inputs belong to, if there is exactly one where it is looked
/// for (see the module header).
pub fn solution(session: &Session, inputs: &[PathBuf]) -> Option<PathBuf> {
    if !session.disk {
        return None;
    }
    let first = inputs.first()?;
    let has_ext = |p: &Path, e: &str| {
        p.extension()
            .and_then(|x| x.to_str())
            .is_some_and(|x| x.eq_ignore_ascii_case(e))
    };
    let in_dir = |d: &Path| -> Vec<PathBuf> {
        let mut v: Vec<PathBuf> = std::fs::read_dir(d)
            .map(|r| {
                r.flatten()
                    .map(|e| e.path())
                    .filter(|p| p.is_file() && has_ext(p, "tsproj"))
                    .collect()
            })
            .unwrap_or_default();
        v.sort();
        v
    };
    let one = |v: Vec<PathBuf>| {
        if v.len() == 1 {
            v.into_iter().next()
        } else {
            None
        }
    };
    if has_ext(first, "plcproj") {
        // (`Cell/Cell.plcproj` given relative to the working folder: its folder, then `.`, then
        // `..`; before, the search ended at the first empty parent and found no .tsproj)
        let mut dir = match first.parent() {
            Some(d) if !d.as_os_str().is_empty() => d.to_path_buf(),
            _ => PathBuf::from("."),
        };
        for _ in 0..4 {
            let found = in_dir(&dir);
            if !found.is_empty() {
                return one(found);
            }
            dir = folder_above(&dir);
        }
        return None;
    }
    if first.is_dir() {
        // the folder, then up to three levels below it (a .sln folder holds the .tsproj's)
        let mut level = vec![first.clone()];
        for _ in 0..4 {
            let found: Vec<PathBuf> = level.iter().flat_map(|d| in_dir(d)).collect();
            if !found.is_empty() {
                return one(found);
            }
            let mut next = Vec::new();
            for d in &level {
                if let Ok(r) = std::fs::read_dir(d) {
                    next.extend(r.flatten().map(|e| e.path()).filter(|p| p.is_dir()));
                }
            }
            next.sort();
            level = next;
        }
    }
    None
}

/// The folder above `dir`, also of a relative one: `Cell` -> `.`, `.` -> `..`, `..` -> `../..`
/// (a root stays itself).
fn folder_above(dir: &Path) -> PathBuf {
    use std::path::Component;
    match (dir.components().next_back(), dir.parent()) {
        (Some(Component::Normal(_)), Some(p)) if !p.as_os_str().is_empty() => p.to_path_buf(),
        (Some(Component::Normal(_)), _) => PathBuf::from("."),
        (Some(Component::RootDir | Component::Prefix(_)), _) => dir.to_path_buf(),
        _ => dir.join(".."),
    }
}

/// The PLC project the inputs name (a `.plcproj`, or a folder, `.sln` or `.tsproj` whose folder
/// holds exactly one), whose instance's links are the ones to read.
pub fn plc_project(session: &Session, inputs: &[PathBuf]) -> Option<PathBuf> {
    if !session.disk {
        return None;
    }
    let first = inputs.first()?;
    if crate::twincat::has_extension(first, "plcproj") {
        return Some(first.clone());
    }
    let dir = if crate::twincat::has_extension(first, "sln")
        || crate::twincat::has_extension(first, "tsproj")
    {
        match first.parent() {
            Some(d) if !d.as_os_str().is_empty() => d.to_path_buf(),
            _ => PathBuf::from("."),
        }
    } else {
        first.clone()
    };
    if !dir.is_dir() {
        return None;
    }
    let mut found = Vec::new();
    crate::twincat::find_projects(&dir, 0, &mut found);
    (found.len() == 1).then(|| found.pop()).flatten()
}

/// The name the solution gives the PLC project `plc` (`<Plc><Project Name="A"
/// PrjFilePath="A\A.plcproj">`, or the same in the `.xti` a `<Project File=...>` names): the
/// second part of its instance's owner name in `<Mappings>` (`TIPC^A^A Instance`).
fn plc_project_name(
    root: &Element,
    dir: &Path,
    plc: &Path,
    xti: &[(String, PathBuf)],
) -> Option<String> {
    let Ok(plc) = plc.canonicalize() else {
        return None;
    };
    // relative to the .tsproj's folder (or to `_Config/PLC`, where an .xti lies)
    let same = |rel: &str| {
        let rel: PathBuf = rel.split(['\\', '/']).collect();
        [dir.join(&rel), dir.join("_Config").join("PLC").join(&rel)]
            .iter()
            .any(|p| p.canonicalize().is_ok_and(|p| p == plc))
    };
    for plc_el in root.walk().filter(|e| e.name() == "Plc") {
        for project in plc_el.children_named("Project") {
            if let (Some(name), Some(path)) = (project.attr("Name"), project.attr("PrjFilePath")) {
                if same(path) {
                    return Some(name.to_string());
                }
            }
        }
    }
    xti.iter().find_map(|(name, path)| {
        let rel = path.to_string_lossy();
        same(&rel).then(|| name.clone())
    })
}

/// An NC axis linked to a PLC `AXIS_REF`: the axis's name, the instance path, where the link is.
type Link = (String, String, Span);

/// One NC axis as read: its name, where it is declared, its parameters.
struct NcAxis {
    name: String,
    id: Option<u32>,
    at: Span,
    values: Values,
    missing: Vec<&'static str>,
}

#[derive(Default)]
struct Values {
    velocity: Option<f64>,
    acc: Option<f64>,
    dec: Option<f64>,
    acc_max: Option<f64>,
    dec_max: Option<f64>,
    jerk: Option<f64>,
    fast: Option<f64>,
    slow: Option<f64>,
    soft_min: Option<f64>,
    soft_max: Option<f64>,
    modulo: Option<f64>,
    lag: Option<Option<f64>>,
    numerator: Option<f64>,
    denominator: Option<f64>,
    unit: Option<String>,
}

/// The axes of the solution `tsproj`: `None` when it has none (or errors were reported: then
/// `session.diags` holds them).
/// `plc`: the PLC project compiled; when the solution names it, only its instance's links are read
/// (a solution's other PLC projects link their own `AXIS_REF`s).
pub fn import(session: &mut Session, tsproj: &Path, plc: Option<&Path>) -> Option<AxisConfig> {
    let text = session.read_file(tsproj).ok()?;
    let text = text.strip_prefix('\u{feff}').unwrap_or(&text).to_string();
    let dir = tsproj.parent().unwrap_or(Path::new("")).to_path_buf();
    let file = session.map.add(tsproj.display().to_string(), text.clone());
    let arena = Arena::new();
    let (root, _) = ladder_compiler::xml::parse(&text, &arena);
    let root = root?;
    let nc_dir = dir.join("_Config").join("NC");
    let mut axes: Vec<NcAxis> = Vec::new();
    let mut failed = false;
    // the NC element: in the .tsproj, or in the file it names
    let nc = root.walk().find(|e| e.name() == "NC")?;
    let nc_file;
    let nc_arena = Arena::new();
    let nc_el: Element = match nc.attr_and_range("File") {
        Some((name, (s, e))) => {
            let path = nc_dir.join(name);
            let (f, src) = read_xml(session, &path, Span::new(file, s, e))?;
            nc_file = f;
            let src = nc_arena.str(&src);
            match ladder_compiler::xml::parse(src, &nc_arena) {
                (Some(r), None) => match r.walk().find(|e| e.name() == "NC") {
                    Some(n) => *n,
                    None => return None,
                },
                _ => {
                    not_xml(session, &path, Span::new(file, s, e));
                    return None;
                }
            }
        }
        None => {
            nc_file = file;
            *nc
        }
    };
    for a in nc_el.walk().filter(|e| e.name() == "Axis") {
        match a.attr_and_range("File") {
            Some((name, (s, e))) => {
                let rel: PathBuf = name.split(['\\', '/']).collect();
                let path = nc_dir.join("Axes").join(&rel);
                let stem = rel
                    .file_stem()
                    .and_then(|x| x.to_str())
                    .unwrap_or("Axis")
                    .to_string();
                let Some((f, src)) = read_xml(session, &path, Span::new(nc_file, s, e)) else {
                    failed = true;
                    continue;
                };
                let ax_arena = Arena::new();
                let src = ax_arena.str(&src);
                match ladder_compiler::xml::parse(src, &ax_arena) {
                    (Some(r), None) => {
                        if let Some(el) = r.walk().find(|e| e.name() == "Axis") {
                            axes.push(read_axis(session, el, f, &stem));
                        }
                    }
                    _ => {
                        not_xml(session, &path, Span::new(nc_file, s, e));
                        failed = true;
                    }
                }
            }
            None => axes.push(read_axis(session, a, nc_file, "Axis")),
        }
    }
    if failed {
        return None;
    }
    if axes.is_empty() {
        return None;
    }
    // TwinCAT 3.1 with independent project files keeps a PLC instance's links (its
    // `<Mappings>`) in `_Config/PLC/<plc>.xti`, which `<Plc><Project File="PLC1.xti"/>` names:
    // each such file's project (name and path, to tell which is `plc`) and its links
    let mut xti_projects: Vec<(String, PathBuf)> = Vec::new();
    let mut xti_links: Vec<(Option<String>, Vec<Link>)> = Vec::new();
    for plc_el in root.walk().filter(|e| e.name() == "Plc") {
        for project in plc_el.children_named("Project") {
            let Some((name, (s, e))) = project.attr_and_range("File") else {
                continue;
            };
            let rel: PathBuf = name.split(['\\', '/']).collect();
            let path = dir.join("_Config").join("PLC").join(rel);
            let Some((f, src)) = read_xml(session, &path, Span::new(file, s, e)) else {
                continue;
            };
            let plc_arena = Arena::new();
            let src = plc_arena.str(&src);
            match ladder_compiler::xml::parse(src, &plc_arena) {
                (Some(r), None) => {
                    let own = r.walk().find(|e| e.name() == "Project").and_then(|p| {
                        let name = p.attr("Name")?.to_string();
                        if let Some(path) = p.attr("PrjFilePath") {
                            xti_projects.push((name.clone(), PathBuf::from(path)));
                        }
                        Some(name)
                    });
                    xti_links.push((own, mappings(&r, f, None)));
                }
                _ => not_xml(session, &path, Span::new(file, s, e)),
            }
        }
    }
    let own = plc.and_then(|p| plc_project_name(&root, &dir, p, &xti_projects));
    let mut links = mappings(&root, file, own.as_deref());
    for (project, found) in xti_links {
        if let (Some(own), Some(project)) = (&own, &project) {
            if !own.eq_ignore_ascii_case(project) {
                continue;
            }
        }
        for l in found {
            if !links
                .iter()
                .any(|(a, i, _)| *a == l.0 && i.eq_ignore_ascii_case(&l.1))
            {
                links.push(l);
            }
        }
    }
    let mut config = config(session, axes, &links);
    config.nc_solution = Some(tsproj.display().to_string());
    Some(config)
}

/// The text of an NC file named at `at`, registered in the source map; E1047 when it cannot be read.
fn read_xml(session: &mut Session, path: &Path, at: Span) -> Option<(diagnostics::FileId, String)> {
    match session.read_file(path) {
        Ok(t) => {
            let t = t.strip_prefix('\u{feff}').unwrap_or(&t).to_string();
            let f = session.map.add(path.display().to_string(), t.clone());
            Some((f, t))
        }
        Err(e) => {
            session.diags.push(
                Diagnostic::error(
                    code::E1047,
                    format!(
                        "the NC configuration names {}, which cannot be read: {e}",
                        path.display()
                    ),
                )
                .at(at)
                .with_hint(
                    "give the solution's whole `_Config/NC` folder, or an axes file (--axes FILE.json)",
                ),
            );
            None
        }
    }
}

fn not_xml(session: &mut Session, path: &Path, at: Span) {
    session.diags.push(
        Diagnostic::error(
            code::E1047,
            format!(
                "{} is not a well-formed NC configuration file",
                path.display()
            ),
        )
        .at(at)
        .with_hint("TwinCAT writes it as XML: restore it, or give an axes file (--axes FILE.json)"),
    );
}

/// A number attribute of `el`: `Some(Ok(v))` when finite, `Some(Err(range))` when given but not
/// a number, `None` when absent.
fn number(el: &Element, attr: &str) -> Option<Result<f64, (usize, usize)>> {
    let (v, range) = el.attr_and_range(attr)?;
    Some(
        v.trim()
            .parse::<f64>()
            .ok()
            .filter(|x| x.is_finite())
            .ok_or(range),
    )
}

/// Reads one `<Axis>` element of `file`; `stem` names it when it says `__FILENAME__` or nothing.
fn read_axis(
    session: &mut Session,
    axis: &Element,
    file: diagnostics::FileId,
    stem: &str,
) -> NcAxis {
    let at = Span::new(file, axis.tag_start(), axis.tag_end());
    let name = match axis.child("Name").map(|n| n.text().trim().to_string()) {
        Some(n) if !n.is_empty() && n != "__FILENAME__" => n,
        _ => stem.to_string(),
    };
    let mut v = Values::default();
    let mut bad: Vec<(String, (usize, usize))> = Vec::new();
    let mut take =
        |el: &Element, attr: &str, slot: &mut Option<f64>, positive: bool| match number(el, attr) {
            Some(Ok(x)) if !positive || x > 0.0 => *slot = Some(x),
            Some(Ok(_)) | Some(Err(_)) => {
                let range = el
                    .attr_range(attr)
                    .unwrap_or((el.tag_start(), el.tag_end()));
                bad.push((format!("{} {attr}", el.name()), range));
            }
            None => {}
        };
    let enabled = |el: &Element| {
        el.attr("Enable")
            .is_none_or(|e| !e.eq_ignore_ascii_case("false"))
    };
    // the parameter elements of the axis itself, not of its process image (`Vars`)
    let mut stack: Vec<&Element> = axis
        .children
        .iter()
        .filter(|c| c.name() != "Vars")
        .collect();
    while let Some(el) = stack.pop() {
        stack.extend(el.children.iter().filter(|c| c.name() != "Vars"));
        match el.name() {
            "Velo" => {
                take(el, "Maximum", &mut v.velocity, true);
                take(el, "FastManual", &mut v.fast, true);
                take(el, "SlowManual", &mut v.slow, true);
            }
            "Dynamic" => {
                take(el, "Acceleration", &mut v.acc, true);
                take(el, "Deceleration", &mut v.dec, true);
                take(el, "AccelerationMaximum", &mut v.acc_max, true);
                take(el, "DecelerationMaximum", &mut v.dec_max, true);
                let mut j = None;
                take(el, "Jerk", &mut j, false);
                if let Some(j) = j {
                    if j >= 0.0 {
                        v.jerk = Some(j);
                    }
                }
            }
            "EncPara" => {
                take(el, "ScaleFactorNumerator", &mut v.numerator, true);
                take(el, "ScaleFactorDenominator", &mut v.denominator, true);
                take(el, "ModuloFactor", &mut v.modulo, true);
            }
            "SoftEndMinControl" if enabled(el) && el.attr("Enable").is_some() => {
                take(el, "Range", &mut v.soft_min, false);
            }
            "SoftEndMaxControl" if enabled(el) && el.attr("Enable").is_some() => {
                take(el, "Range", &mut v.soft_max, false);
            }
            "PosDiffControl" => {
                if enabled(el) {
                    let mut r = None;
                    take(el, "Range", &mut r, true);
                    v.lag = Some(r);
                } else {
                    v.lag = Some(Some(0.0));
                }
            }
            "General" => {
                if let Some(u) = el.attr("UnitName").filter(|u| !u.trim().is_empty()) {
                    v.unit = Some(u.trim().to_string());
                }
            }
            _ => {}
        }
    }
    let reported: Vec<String> = bad.iter().map(|(w, _)| w.clone()).collect();
    for (what, range) in bad {
        session.diags.push(
            Diagnostic::warning(
                code::W1428,
                format!("NC axis `{name}`: `{what}` is not a value ladderc can use; its default is used"),
            )
            .at(Span::new(file, range.0, range.1))
            .with_hint("a limit must be a positive number (`ladderc explain W1428` lists the defaults)"),
        );
    }
    let mut missing = Vec::new();
    if v.velocity.is_none() {
        missing.push("maximum velocity");
    }
    if v.acc.is_none() && v.acc_max.is_none() {
        missing.push("acceleration");
    }
    if v.dec.is_none() && v.dec_max.is_none() {
        missing.push("deceleration");
    }
    if v.jerk.is_none() {
        missing.push("jerk");
    }
    if v.fast.is_none() {
        missing.push("manual velocity (fast)");
    }
    if v.slow.is_none() {
        missing.push("manual velocity (slow)");
    }
    if v.lag.is_none() || v.lag == Some(None) {
        missing.push("position lag limit");
    }
    if v.modulo.is_none() {
        missing.push("modulo factor");
    }
    // a value reported as unreadable is not listed again
    missing.retain(|w| {
        !DEFAULTS
            .iter()
            .any(|(d, attr, _)| d == w && reported.iter().any(|r| r == attr))
    });
    NcAxis {
        name,
        id: axis.attr("Id").and_then(|i| i.trim().parse().ok()),
        at,
        values: v,
        missing,
    }
}

/// The PLC instance each NC axis is linked to: (axis name, `AXIS_REF` path, where the link is).
/// `own`: the name of the PLC project compiled; links of another PLC project's instance
/// (`TIPC^B^B Instance` while compiling A) are left out.
fn mappings(root: &Element, file: diagnostics::FileId, own: Option<&str>) -> Vec<Link> {
    let mut out = Vec::new();
    let Some(m) = root.walk().find(|e| e.name() == "Mappings") else {
        return out;
    };
    for owner_a in m.children_named("OwnerA") {
        for owner_b in owner_a.children_named("OwnerB") {
            let (a, b) = (
                owner_a.attr("Name").unwrap_or(""),
                owner_b.attr("Name").unwrap_or(""),
            );
            // the PLC side is `TIPC^<project>^<instance>`, on either owner
            let other_plc = [a, b].into_iter().any(|n| {
                let mut parts = n.split('^');
                parts.next() == Some("TIPC")
                    && own.is_some_and(|own| {
                        parts.next().is_some_and(|p| !p.eq_ignore_ascii_case(own))
                    })
            });
            if other_plc {
                continue;
            }
            // the NC side is `TINC^<task>^Axes^[folder^]<axis>`, on either owner
            let axis = [a, b]
                .into_iter()
                .find(|n| n.starts_with("TINC^") && n.contains("^Axes^"))
                .and_then(|n| n.rsplit('^').next());
            let Some(axis) = axis else { continue };
            for link in owner_b.children_named("Link") {
                for var in ["VarA", "VarB"] {
                    let Some((v, (s, e))) = link.attr_and_range(var) else {
                        continue;
                    };
                    let path = v.rsplit('^').next().unwrap_or(v);
                    let upper = path.to_ascii_uppercase();
                    let Some(base) = [".NCTOPLC", ".PLCTONC"]
                        .iter()
                        .find_map(|suf| upper.strip_suffix(suf).map(|b| b.len()))
                    else {
                        continue;
                    };
                    let instance = path[..base].to_string();
                    if !out.iter().any(|(x, p, _): &(String, String, Span)| {
                        x == axis && p.eq_ignore_ascii_case(&instance)
                    }) {
                        out.push((axis.to_string(), instance, Span::new(file, s, e)));
                    }
                }
            }
        }
    }
    out
}

/// `name` as an IEC identifier: each other character `_`, no `__`, a leading `_` before a digit.
fn identifier(name: &str) -> String {
    let mut s = String::new();
    for c in name.chars() {
        let c = if c.is_ascii_alphanumeric() { c } else { '_' };
        if !(c == '_' && s.ends_with('_')) {
            s.push(c);
        }
    }
    if s.is_empty() || s.starts_with(|c: char| c.is_ascii_digit()) {
        s.insert_str(0, "Axis_");
    }
    s
}

fn config(
    session: &mut Session,
    axes: Vec<NcAxis>,
    links: &[(String, String, Span)],
) -> AxisConfig {
    let mut out: Vec<Axis> = Vec::new();
    for a in axes {
        let mut name = identifier(&a.name);
        let mut k = 2;
        while out.iter().any(|o| o.name.eq_ignore_ascii_case(&name)) {
            name = format!("{}_{k}", identifier(&a.name));
            k += 1;
        }
        let v = &a.values;
        let velocity = v.velocity.unwrap_or(default("maximum velocity"));
        let std_acc = v.acc.or(v.acc_max).unwrap_or(default("acceleration"));
        let std_dec = v.dec.or(v.dec_max).unwrap_or(default("deceleration"));
        // a standard value above the maximum is capped: the limit holds
        let acc = v.acc_max.unwrap_or(std_acc).max(f64::MIN_POSITIVE);
        let dec = v.dec_max.unwrap_or(std_dec).max(f64::MIN_POSITIVE);
        let (std_acc, std_dec) = (std_acc.min(acc), std_dec.min(dec));
        let jerk = v.jerk.unwrap_or(default("jerk"));
        let fast = v
            .fast
            .unwrap_or(default("manual velocity (fast)"))
            .min(velocity);
        let slow = v
            .slow
            .unwrap_or(default("manual velocity (slow)"))
            .min(velocity);
        let lag = match v.lag {
            Some(Some(r)) => r,
            _ => default("position lag limit"),
        };
        let sw_limits = match (v.soft_min, v.soft_max) {
            (None, None) => None,
            (min, max) => Some((max.unwrap_or(1e300), min.unwrap_or(-1e300))),
        };
        let sw_limits = sw_limits.filter(|(p, n)| n < p);
        let counts_per_unit = v.denominator.unwrap_or(1.0) / v.numerator.unwrap_or(1.0);
        if !a.missing.is_empty() {
            let list: Vec<String> = a
                .missing
                .iter()
                .map(|w| format!("{w} {}", real_text(default(w))))
                .collect();
            session.diags.push(
                Diagnostic::new(
                    code::W1428,
                    Severity::Note,
                    format!(
                        "NC axis `{}` gives no {}: TwinCAT's defaults are used ({})",
                        a.name,
                        join_words(&a.missing),
                        list.join(", ")
                    ),
                )
                .at(a.at)
                .with_hint(
                    "set them in the axis's parameters, or give an axes file (--axes FILE.json)",
                ),
            );
        }
        let link = links
            .iter()
            .find(|(x, _, _)| *x == a.name)
            .map(|(_, p, s)| (p.clone(), *s));
        out.push(Axis {
            name: name.clone(),
            unit: v.unit.clone().or(Some("mm".into())),
            counts_per_unit: if counts_per_unit.is_finite() && counts_per_unit > 0.0 {
                counts_per_unit
            } else {
                1.0
            },
            limits: c_backend::motion::MotionAxis {
                name,
                velocity_limit: velocity,
                acceleration_limit: acc,
                deceleration_limit: dec,
                jerk_limit: jerk,
                sw_limits,
                modulo_period: 0.0,
                following_error_limit: lag,
            },
            link,
            declared_by_program: false,
            jog_velocities: (slow, fast),
            standard_dynamics: Some((std_acc, std_dec)),
            modulo_factor: Some(v.modulo.unwrap_or(default("modulo factor"))),
            nc_id: a.id,
        });
    }
    AxisConfig {
        axes: out,
        ..AxisConfig::default()
    }
}

fn real_text(v: f64) -> String {
    if v == v.trunc() && v.abs() < 1e15 {
        format!("{}", v as i64)
    } else {
        format!("{v}")
    }
}

fn join_words(w: &[&str]) -> String {
    match w {
        [] => String::new(),
        [one] => (*one).to_string(),
        [rest @ .., last] => format!("{} or {last}", rest.join(", ")),
    }
}

#[cfg(test)]
mod tests {
    use super::identifier;

    #[test]
    fn axis_names_become_identifiers() {
        assert_eq!(identifier("Axis 1"), "Axis_1");
        assert_eq!(identifier("M2_DET_Z"), "M2_DET_Z");
        assert_eq!(identifier("Y²"), "Y_");
        assert_eq!(identifier("1st"), "Axis_1st");
    }
}
