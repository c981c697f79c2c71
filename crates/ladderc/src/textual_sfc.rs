//! Textual SFC (IEC 61131-3 2.6 written in an ST file, TwinCAT's SFC objects) lowered once every unit's
//! declarations are known, and `SUPER^()` of a block whose base's body is such a chart.
//!
//! Input: the parsed units and the bodies the ST reader left pending ([`PendingBody`] with `sfc` set), the
//! source map. Output: each chart's POU with the chart's IL appended after what its body held before (the
//! run-time initial values), its hidden step and action-control variables declared, its actions' calls
//! inlined; in a derived block each `CAL __SUPER_SFC_<base>` of its body or methods replaced by one scan of
//! the base's chart. Invariants: a chart's diagnostics are reported once (the base's, not again for each
//! derived block); spans of the lowered code point into the chart's file; nothing is copied per chart
//! unless the body is not its file's text.

use il_frontend::ast::CompilationUnit;
use il_frontend::st::file::PendingBody;

/// What a scan of a base's chart reads: the pending bodies, each chart's body by its block's name (upper
/// case), the declarations of every unit, and the sources.
#[derive(Clone, Copy)]
struct Charts<'a> {
    pending: &'a [PendingBody],
    by_name: &'a std::collections::HashMap<String, usize>,
    index: &'a ladder_compiler::project::Index,
    map: &'a diagnostics::SourceMap,
}

/// Lowers the bodies written in textual SFC (IEC 61131-3 2.6 in an ST file) with the SFC lowering of
/// PLCopen XML charts, once every unit's declarations are known.
pub(crate) fn lower_textual_sfc(
    units: &mut [CompilationUnit],
    pending: &[PendingBody],
    map: &diagnostics::SourceMap,
    diags: &mut diagnostics::Diagnostics,
) {
    use il_frontend::ast::{LibraryElement, VarBlock};
    if !pending.iter().any(|pb| pb.sfc) {
        return;
    }
    let index = ladder_compiler::sfc::text::index_of_units(units);
    // each chart's POU by (file, offset of its name): one look-up per chart, not a scan of every POU
    let mut charts: std::collections::HashMap<(diagnostics::FileId, usize), usize> = pending
        .iter()
        .enumerate()
        .filter(|(_, pb)| pb.sfc)
        .map(|(k, pb)| ((pb.file, pb.name_start), k))
        .collect();
    // the actions of each chart's POU (and its methods without inputs, TwinCAT's actions before
    // a method): a chart runs them by `CAL Act`, inlined below as an ST body's own calls are
    let mut own: std::collections::HashMap<String, Vec<&il_frontend::ast::Action>> =
        std::collections::HashMap::new();
    for item in units.iter().flat_map(|u| u.items.iter()) {
        if let LibraryElement::Action(a) = item {
            if a.method_inputs.as_ref().is_none_or(|m| m.is_empty()) {
                own.entry(a.pou.key()).or_default().push(a);
            }
        }
    }
    #[allow(clippy::type_complexity)]
    let own: std::collections::HashMap<
        String,
        (
            std::collections::HashMap<String, Vec<il_frontend::ast::IlStmt>>,
            Vec<diagnostics::Diagnostic>,
        ),
    > = own
        .into_iter()
        .map(|(k, acts)| {
            let map = acts
                .iter()
                .map(|a| (a.name.key(), a.body.clone()))
                .collect();
            let found = acts
                .iter()
                .flat_map(|a| a.diagnostics.iter().cloned())
                .collect();
            (k, (map, found))
        })
        .collect();
    // each chart by its block's name, for the blocks derived from it (`SUPER^()`)
    let by_name: std::collections::HashMap<String, usize> = units
        .iter()
        .flat_map(|u| u.items.iter())
        .filter_map(|item| match item {
            LibraryElement::Pou(p) => charts
                .get(&(p.name.span.file, p.name.span.start as usize))
                .map(|&k| (p.name.key(), k)),
            _ => None,
        })
        .collect();
    let base_charts = Charts {
        pending,
        by_name: &by_name,
        index: &index,
        map,
    };
    for item in units.iter_mut().flat_map(|u| u.items.iter_mut()) {
        let LibraryElement::Pou(p) = item else {
            continue;
        };
        if !by_name.is_empty() {
            let acts = own.get(&p.name.key()).map(|(acts, _)| acts);
            super_charts(p, &base_charts, acts, diags);
        }
        let Some(k) = charts.remove(&(p.name.span.file, p.name.span.start as usize)) else {
            continue;
        };
        let pb = &pending[k];
        // the body in its file's text: spans of the lowered code point into the file, and nothing is
        // copied per chart (a copy padded to the body's offset cost charts x file size)
        let src = map.get(pb.file).text.as_str();
        let body = pb.base..pb.base + pb.text.len();
        let (body, hidden, steps) = if src.get(body.clone()) == Some(pb.text.as_str()) {
            ladder_compiler::sfc::text::lower(pb.file, src, body, p, &index, diags)
        } else {
            // a body that is not its file's text (parse_text never gives one): padded to its offset
            let mut padded = " ".repeat(pb.base);
            padded.push_str(&pb.text);
            ladder_compiler::sfc::text::lower(pb.file, &padded, body, p, &index, diags)
        };
        // what the POU's body holds before its chart (the run-time initial values of its
        // variables, `il_frontend::st::file::compile_pending`) runs first, as in an ST body
        let mut first = std::mem::take(&mut p.body);
        first.extend(body);
        p.body = first;
        if !hidden.is_empty() {
            let span = diagnostics::Span::new(pb.file, pb.base, pb.base);
            p.var_blocks.push(VarBlock::locals(hidden, span));
        }
        if let Some((acts, found)) = own.get(&p.name.key()) {
            let is_var = il_frontend::actions::declares(p);
            let mut next = 0;
            p.body = il_frontend::actions::inline_calls(
                std::mem::take(&mut p.body),
                acts,
                &is_var,
                "__SFCA",
                &mut next,
                diags,
            );
            // `Step.X`, `Step.T` in those actions: the chart's flags (round 31: E1001 before)
            ladder_compiler::sfc::rename_step_flags(&mut p.body, &steps, diags);
            // the actions' own diagnostics, as where an ST body calls them
            for d in found {
                diags.push(d.clone());
            }
        }
    }
    if !by_name.is_empty() {
        method_super_charts(units, &base_charts, &own, diags);
    }
}

/// The lowered bodies of a POU's actions, by action name (upper case).
type ActionBodies = std::collections::HashMap<String, Vec<il_frontend::ast::IlStmt>>;

/// `SUPER^()` in a block derived from a block whose body is a chart (`CAL __SUPER_SFC_<base>`,
/// `il_frontend::st::file::SUPER_CHART_CALL`): one scan of the base's chart in the derived
/// block's instance per call (Beckhoff infosys "SUPER": `SUPER^()` calls the base's body). The
/// chart is lowered again with the derived block (its variables are the base's and its own); its
/// steps, step times and action control are hidden variables of the derived block, and
/// `Step.X`/`Step.T` in the derived block's body read them; the chart's calls of the block's
/// actions (`actions`, the base's it inherits) are inlined. A derived block that never calls
/// `SUPER^()` runs no chart. Diagnostics of the chart itself are the base's (already reported).
fn super_charts(
    p: &mut il_frontend::ast::Pou,
    charts: &Charts,
    actions: Option<&ActionBodies>,
    diags: &mut diagnostics::Diagnostics,
) {
    let body = std::mem::take(&mut p.body);
    let mut next = 0;
    let (body, hidden) = chart_scans(
        (p, body),
        (["__SFCS", "__SFCA"], &mut next),
        charts,
        actions,
        diags,
    );
    p.body = body;
    declare_hidden(p, hidden);
}

/// The chart variables `hidden` that `p` does not declare yet, declared (a block whose body and
/// method both run the base's chart has one set).
fn declare_hidden(p: &mut il_frontend::ast::Pou, hidden: Vec<il_frontend::ast::VarDecl>) {
    let declared = |p: &il_frontend::ast::Pou, n: &il_frontend::ast::Ident| {
        p.var_blocks
            .iter()
            .flat_map(|b| b.vars.iter())
            .any(|v| v.name.key() == n.key())
    };
    let new: Vec<_> = hidden
        .into_iter()
        .filter(|v| !declared(p, &v.name))
        .collect();
    if !new.is_empty() {
        let end = p.name.span.end as usize;
        let span = diagnostics::Span::new(p.name.span.file, end, end);
        p.var_blocks
            .push(il_frontend::ast::VarBlock::locals(new, span));
    }
}

/// The lowered actions of each block with their diagnostics, by block name (upper case).
type OwnActions = std::collections::HashMap<String, (ActionBodies, Vec<diagnostics::Diagnostic>)>;

/// `SUPER^()` of a block's method (the body of a middle level of a chain, `SUPER^()` of a base
/// two levels up whose body is a chart, Resi4MPM's `ControlPrimitiveBase`): as in the body
/// ([`super_charts`]), its chart variables the block's. Before round 32: E1019 `__C000`.
fn method_super_charts(
    units: &mut [CompilationUnit],
    charts: &Charts,
    own: &OwnActions,
    diags: &mut diagnostics::Diagnostics,
) {
    use il_frontend::ast::LibraryElement;
    let runs_chart = |a: &il_frontend::ast::Action| {
        a.method_inputs.is_some() && !chart_bases(&a.body).is_empty()
    };
    let owners: std::collections::HashSet<String> = units
        .iter()
        .flat_map(|u| u.items.iter())
        .filter_map(|i| match i {
            LibraryElement::Action(a) if runs_chart(a) => Some(a.pou.key()),
            _ => None,
        })
        .collect();
    if owners.is_empty() {
        return;
    }
    let blocks: std::collections::HashMap<String, il_frontend::ast::Pou> = units
        .iter()
        .flat_map(|u| u.items.iter())
        .filter_map(|i| match i {
            LibraryElement::Pou(p) if owners.contains(&p.name.key()) => {
                Some((p.name.key(), p.clone()))
            }
            _ => None,
        })
        .collect();
    let mut hidden: std::collections::HashMap<String, Vec<il_frontend::ast::VarDecl>> =
        std::collections::HashMap::new();
    let mut labels: std::collections::HashMap<String, usize> = std::collections::HashMap::new();
    for item in units.iter_mut().flat_map(|u| u.items.iter_mut()) {
        let LibraryElement::Action(a) = item else {
            continue;
        };
        if !runs_chart(a) {
            continue;
        }
        let Some(p) = blocks.get(&a.pou.key()) else {
            continue;
        };
        let body = std::mem::take(&mut a.body);
        let acts = own.get(&p.name.key()).map(|(acts, _)| acts);
        // (labels of their own: the method is inlined where the block calls it)
        let next = labels.entry(a.pou.key()).or_insert(0);
        let (body, vars) = chart_scans(
            (p, body),
            (["__SFCM", "__SFCMA"], next),
            charts,
            acts,
            diags,
        );
        a.body = body;
        hidden.entry(a.pou.key()).or_default().extend(vars);
    }
    for item in units.iter_mut().flat_map(|u| u.items.iter_mut()) {
        if let LibraryElement::Pou(p) = item {
            if let Some(vars) = hidden.remove(&p.name.key()) {
                declare_hidden(p, vars);
            }
        }
    }
}

/// The bases whose chart `body` runs (`CAL __SUPER_SFC_<base>`), each once.
fn chart_bases(body: &[il_frontend::ast::IlStmt]) -> Vec<String> {
    use il_frontend::ast::{IlStmt, InstrKind, Instruction};
    use il_frontend::st::file::SUPER_CHART_CALL;
    let mut bases: Vec<String> = Vec::new();
    for s in body {
        if let IlStmt::Instr(Instruction {
            kind: InstrKind::Call { instance, .. },
            ..
        }) = s
        {
            if let Some(base) = instance.base.name.strip_prefix(SUPER_CHART_CALL) {
                if !bases.iter().any(|b| b == base) {
                    bases.push(base.to_string());
                }
            }
        }
    }
    bases
}

/// `body` (of block `p` or of one of its methods) with each `CAL __SUPER_SFC_<base>` replaced by
/// one scan of the base's chart, and the chart variables it needs; `tag`: the label prefixes of
/// the chart's copies and of its actions' copies, numbered by `next`.
fn chart_scans(
    (p, body): (&il_frontend::ast::Pou, Vec<il_frontend::ast::IlStmt>),
    (tag, next): ([&str; 2], &mut usize),
    charts: &Charts,
    actions: Option<&ActionBodies>,
    diags: &mut diagnostics::Diagnostics,
) -> (
    Vec<il_frontend::ast::IlStmt>,
    Vec<il_frontend::ast::VarDecl>,
) {
    use il_frontend::ast::IlStmt;
    use il_frontend::st::file::SUPER_CHART_CALL;
    let Charts {
        pending,
        by_name,
        index,
        map,
    } = *charts;
    let bases = chart_bases(&body);
    if bases.is_empty() {
        return (body, Vec::new());
    }
    let mut calls: std::collections::HashMap<String, Vec<IlStmt>> =
        std::collections::HashMap::new();
    let mut steps: Vec<String> = Vec::new();
    let mut hidden_all: Vec<il_frontend::ast::VarDecl> = Vec::new();
    for base in &bases {
        let Some(pb) = by_name
            .get(&base.to_ascii_uppercase())
            .and_then(|&k| pending.get(k))
        else {
            continue;
        };
        let src = map.get(pb.file).text.as_str();
        let body = pb.base..pb.base + pb.text.len();
        let mut local = diagnostics::Diagnostics::new();
        let (code, hidden, names) = if src.get(body.clone()) == Some(pb.text.as_str()) {
            ladder_compiler::sfc::text::lower(pb.file, src, body, p, index, &mut local)
        } else {
            // (as in `lower_textual_sfc`: a body that is not its file's text, padded)
            let mut padded = " ".repeat(pb.base);
            padded.push_str(&pb.text);
            ladder_compiler::sfc::text::lower(pb.file, &padded, body, p, index, &mut local)
        };
        for d in local.into_vec() {
            if !diags.iter().any(|e| e.code == d.code && e.span == d.span) {
                diags.push(d);
            }
        }
        for v in hidden {
            if !hidden_all.iter().any(|h| h.name.key() == v.name.key()) {
                hidden_all.push(v);
            }
        }
        steps.extend(names);
        calls.insert(
            format!("{SUPER_CHART_CALL}{base}").to_ascii_uppercase(),
            code,
        );
    }
    let mut body =
        il_frontend::actions::inline_calls(body, &calls, &|_| false, tag[0], next, diags);
    // the chart's `CAL Act` of the block's actions (the base's, which it inherits)
    if let Some(acts) = actions {
        let is_var = il_frontend::actions::declares(p);
        body = il_frontend::actions::inline_calls(body, acts, &is_var, tag[1], next, diags);
    }
    ladder_compiler::sfc::rename_step_flags(&mut body, &steps, diags);
    (body, hidden_all)
}
