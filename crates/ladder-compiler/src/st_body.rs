//! ST bodies embedded in the XML: the text of `<ST>` is rebuilt in place (see
//! [`crate::il_body::embedded_text`]), parsed and lowered to IL by `il_frontend::st`.
//!
//! Input: the `<ST>` element, the POU header, the project [`Index`]. Output: the IL body and the
//! `VAR_TEMP` block of the temporaries it needs. Invariants: every diagnostic points into the XML file
//! and names the POU; the POU keeps its interface whatever the body contains.

use crate::context::Ctx;
use crate::project::Index;
use crate::xml::Element;
use diagnostics::{Diagnostics, XmlContext};
use il_frontend::ast::{Ident, IlStmt, Pou, VarBlock};
use il_frontend::st::{Declarations, PouInterface};

/// What the ST lowering needs to know about the project: data types, POU interfaces, globals. Built once
/// per index.
pub fn declarations(index: &Index) -> &Declarations {
    index
        .st_declarations
        .get_or_init(|| build_declarations(index))
}

fn build_declarations(index: &Index) -> Declarations {
    let mut d = Declarations::new();
    d.methods = index.method_sigs.clone();
    for t in index.types.values() {
        d.add_type(t.clone());
    }
    for p in index.pous.values() {
        d.add_pou_interface(PouInterface {
            kind: p.kind,
            name: p.name.clone(),
            vars: p.pins.iter().chain(&p.internals).cloned().collect(),
            ret: p.ret.clone(),
            constant_in_outs: Vec::new(),
        });
    }
    for (name, ty) in &index.globals {
        d.add_global(name, ty.clone());
    }
    for (list, members) in &index.global_lists {
        for (name, ty) in members {
            d.add_list_member(list, name, ty.clone());
        }
    }
    d
}

/// Parses and lowers the ST body of `pou` in place (spans point into the XML file). `actions` are
/// the `<ST>` elements of the POU's actions (CODESYS), with their names: a call statement `Act();`
/// is lowered as the action's statements. `il_actions` are the POU's other actions, already IL
/// (written in IL, LD or FBD): a call statement of one is a copy of its statements.
pub fn lower(
    ctx: &mut Ctx,
    index: &Index,
    e: &Element,
    pou: &Pou,
    actions: &[(Ident, &Element)],
    il_actions: &[(Ident, Vec<IlStmt>)],
) -> (Vec<IlStmt>, Vec<VarBlock>) {
    let mut t = crate::il_body::embedded_text(e);
    join_split_operators(&mut t.text, t.base, ctx.xml);
    // the declaration blocks the body begins with are the POU's (read by `body_declarations`)
    let n = leading_var_blocks(&t.text);
    if n > 0 {
        let blank: String = t.text[..n]
            .chars()
            .map(|c| if matches!(c, '\n' | '\r') { c } else { ' ' })
            .collect();
        t.text.replace_range(..n, &blank);
    }
    let decls = declarations(index);
    let mut local = Diagnostics::new();
    let span = ctx.tag(e);
    let actions: Vec<(Ident, String, usize)> = actions
        .iter()
        .map(|(n, st)| {
            let mut a = crate::il_body::embedded_text(st);
            join_split_operators(&mut a.text, a.base, ctx.xml);
            (n.clone(), a.text, a.base)
        })
        .collect();
    let (body, temps, standalone) = il_frontend::st::compile_body_with_actions(
        ctx.file,
        &t.text,
        t.base,
        decls,
        pou,
        (&actions, &[]),
        il_actions,
        span,
        &mut local,
    );
    let xml = XmlContext {
        pou: Some(pou.name.name.clone()),
        ..Default::default()
    };
    for mut a in standalone {
        for d in &mut a.diagnostics {
            if d.xml.is_none() {
                d.xml = Some(xml.clone());
            }
        }
        ctx.actions.push(a);
    }
    for d in local {
        ctx.report_in_pou(d, &pou.name.name);
    }
    (body, temps)
}

/// The `VAR ... END_VAR` blocks an ST body begins with (Beremiz and OpenPLC Editor accept them:
/// they copy the body after the POU's declarations, and matiec reads the blocks as the POU's own),
/// parsed with their spans in the XML file; diagnostics go to `ctx`.
pub fn body_declarations(ctx: &mut Ctx, e: &Element, pou: &str) -> Vec<VarBlock> {
    let t = crate::il_body::embedded_text(e);
    let n = leading_var_blocks(&t.text);
    if n == 0 {
        return Vec::new();
    }
    let mut local = Diagnostics::new();
    let blocks = il_frontend::parse_var_blocks(ctx.file, &t.text[..n], t.base, &mut local);
    for d in local {
        ctx.report(d.with_xml(XmlContext {
            pou: Some(pou.to_string()),
            ..Default::default()
        }));
    }
    blocks
}

/// The length of the declaration blocks (`VAR`, `VAR_TEMP`, ... up to their `END_VAR`, comments
/// between them) at the start of `text`, or 0 when it does not begin with one.
pub fn leading_var_blocks(text: &str) -> usize {
    let b = text.as_bytes();
    let mut i = 0;
    let mut end = 0;
    // skips blanks and (nested) comments from `i`
    let skip = |i: usize| -> usize {
        let mut i = i.min(b.len());
        loop {
            while i < b.len() && b[i].is_ascii_whitespace() {
                i += 1;
            }
            if b[i..].starts_with(b"(*") {
                let mut depth = 0usize;
                while i < b.len() {
                    if b[i..].starts_with(b"(*") {
                        depth += 1;
                        i += 2;
                    } else if b[i..].starts_with(b"*)") {
                        depth -= 1;
                        i += 2;
                        if depth == 0 {
                            break;
                        }
                    } else {
                        i += 1;
                    }
                }
            } else if b[i..].starts_with(b"//") {
                while i < b.len() && b[i] != b'\n' {
                    i += 1;
                }
            } else {
                return i;
            }
        }
    };
    let word = |i: usize| -> &str {
        let i = i.min(b.len());
        let n = b[i..]
            .iter()
            .take_while(|c| c.is_ascii_alphanumeric() || **c == b'_')
            .count();
        &text[i..i + n]
    };
    loop {
        i = skip(i);
        let w = word(i).to_ascii_uppercase();
        if !matches!(
            w.as_str(),
            "VAR" | "VAR_TEMP" | "VAR_INPUT" | "VAR_OUTPUT" | "VAR_IN_OUT" | "VAR_EXTERNAL"
        ) {
            return end;
        }
        // up to the END_VAR word (outside comments and strings)
        i += w.len();
        loop {
            i = skip(i);
            if i >= b.len() {
                return end;
            }
            if b[i] == b'\'' || b[i] == b'"' {
                let q = b[i];
                i += 1;
                while i < b.len() && b[i] != q {
                    i += 1;
                }
                i += 1;
                continue;
            }
            let w = word(i);
            if w.eq_ignore_ascii_case("END_VAR") {
                i += w.len();
                end = i;
                break;
            }
            i += w.len().max(1);
        }
    }
}

/// Joins operators that XML entities split: `&lt;=` is rebuilt as `<` plus padding, which would read
/// as `<` then `=`. An entity-decoded `<`/`>` whose padding is followed by a character that continues
/// the operator (`=`, or `>` after `<`) is moved to the end of its padding: `   <=` instead of `<   =`.
/// Positions stay inside the entity.
pub fn join_split_operators(text: &mut String, base: usize, xml: &str) {
    let bytes = xml.as_bytes();
    let mut t = std::mem::take(text).into_bytes();
    let mut k = 0;
    while k < t.len() {
        let c = t[k];
        if (c == b'<' || c == b'>') && bytes.get(base + k) == Some(&b'&') {
            let pad = t[k + 1..].iter().take_while(|&&b| b == b' ').count();
            let entity_len = xml[base + k..].find(';').map_or(0, |n| n + 1);
            if pad > 0 && pad + 1 == entity_len {
                let next = t.get(k + 1 + pad).copied();
                if next == Some(b'=') || (c == b'<' && next == Some(b'>')) {
                    t[k] = b' ';
                    t[k + pad] = c;
                }
            }
            k += 1 + pad;
            continue;
        }
        k += 1;
    }
    *text = String::from_utf8(t).unwrap_or_default();
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn entities_that_split_operators_are_joined() {
        let xml = "<ST><p>IF a &lt;&gt; b AND c &gt;= d AND e &lt;= f THEN x(Q =&gt; y);</p></ST>";
        let arena = crate::xml::Arena::new();
        let (root, _) = crate::xml::parse(xml, &arena);
        let mut t = crate::il_body::embedded_text(&root.unwrap());
        join_split_operators(&mut t.text, t.base, xml);
        let words: Vec<&str> = t.text.split_whitespace().collect();
        assert_eq!(
            words,
            [
                "IF", "a", "<>", "b", "AND", "c", ">=", "d", "AND", "e", "<=", "f", "THEN", "x(Q",
                "=>", "y);"
            ]
        );
        assert_eq!(t.text.len(), xml.len() - t.base - "</p></ST>".len());
    }
}
