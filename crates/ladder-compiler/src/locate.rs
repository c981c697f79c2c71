//! Where a byte offset of a PLCopen XML project lies, in the engineer's terms: the POU, the network (rung)
//! and the graphical element's `localId`.
//!
//! Input: the XML text and a byte offset (the start of a diagnostic's span). Output: an [`XmlContext`], or
//! `None` when the offset is outside every POU. Used to annotate diagnostics of later stages (semantic
//! checks of the lowered IL) whose spans point into the XML file, so that they carry the same context as
//! the ladder compiler's own diagnostics.
//! Invariants: networks are numbered as the lowering numbers them (1-based, in evaluation order, from the
//! same [`graph::read`]); the offset is clamped to the text; bad XML gives `None`, never a panic.

use crate::context::Ctx;
use crate::graph;
use crate::xml::{self, Element};
use diagnostics::{Diagnostics, FileId, XmlContext};
use std::collections::HashMap;

/// The context of every POU and of every element with a `localId`, by byte range: built once per file,
/// then asked for many offsets.
#[derive(Debug, Default)]
pub struct Locator {
    /// (start, end, context); a POU's whole element, then its elements with a localId.
    entries: Vec<(usize, usize, XmlContext)>,
}

impl Locator {
    /// Reads the project's POUs (bad XML gives an empty locator).
    pub fn new(xml_text: &str) -> Self {
        let mut entries = Vec::new();
        let arena = xml::Arena::new();
        if let (Some(root), _) = xml::parse(xml_text, &arena) {
            let mut pous = Vec::new();
            collect_pous(&root, &mut pous);
            for pou in pous {
                add_pou(xml_text, pou, &mut entries);
            }
        }
        Locator { entries }
    }

    /// The innermost context around `offset`: an element's (POU, network for LD/FBD, localId), else
    /// its POU's; `None` outside every POU.
    pub fn at(&self, offset: usize) -> Option<&XmlContext> {
        self.entries
            .iter()
            .filter(|(s, e, _)| *s <= offset && offset < *e)
            .min_by_key(|(s, e, _)| e - s)
            .map(|(_, _, c)| c)
    }
}

/// The POU, network and localId around `offset` (one lookup; use a [`Locator`] for many).
pub fn context_at(xml_text: &str, offset: usize) -> Option<XmlContext> {
    Locator::new(xml_text).at(offset).cloned()
}

fn range(e: &Element) -> (usize, usize) {
    (e.tag_start(), e.end().max(e.tag_end()))
}

fn collect_pous<'a, 'b>(e: &'b Element<'a>, out: &mut Vec<&'b Element<'a>>) {
    if e.name() == "pou" {
        out.push(e);
        return;
    }
    for c in e.children.iter() {
        collect_pous(c, out);
    }
}

fn add_pou(xml_text: &str, pou: &Element, entries: &mut Vec<(usize, usize, XmlContext)>) {
    // PLCopen names a POU by its attribute; a CODESYS V2.3 object file by its `<name>` child
    let name = match pou.attr("name") {
        Some(n) => n.to_string(),
        None => pou
            .child("name")
            .map(|n| n.text_ref().trim().to_string())
            .unwrap_or_default(),
    };
    let (s, e) = range(pou);
    entries.push((
        s,
        e,
        XmlContext {
            pou: Some(name.clone()),
            ..Default::default()
        },
    ));
    let Some(lang) = pou.child("body").and_then(|b| {
        b.children
            .iter()
            .find(|c| !matches!(c.name(), "documentation" | "addData"))
    }) else {
        return;
    };
    // Networks as the lowering numbers them (LD/FBD only).
    let mut network_of: HashMap<String, usize> = HashMap::new();
    if matches!(lang.name(), "LD" | "FBD") {
        let mut scratch = Diagnostics::new();
        let mut ctx = Ctx::new(FileId(0), xml_text, &mut scratch);
        let g = graph::read(&mut ctx, lang, &name);
        for (n, net) in g.networks.iter().enumerate() {
            for &i in net {
                network_of.insert(g.nodes[i].id.to_string(), n + 1);
            }
        }
    }
    let mut stack: Vec<&Element> = lang.children.iter().collect();
    while let Some(el) = stack.pop() {
        if let Some(id) = el.attr("localId") {
            let (s, e) = range(el);
            entries.push((
                s,
                e,
                XmlContext {
                    pou: Some(name.clone()),
                    local_id: Some(id.to_string()),
                    network: network_of.get(id).map(|n| n.to_string()),
                },
            ));
        }
        stack.extend(el.children.iter());
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const LD: &str = r#"<project><types><pous>
<pou name="main" pouType="program"><interface><localVars><variable name="a"><type><BOOL/></type></variable></localVars></interface>
<body><LD>
<leftPowerRail localId="1"/>
<contact localId="2"><connectionPointIn><connection refLocalId="1"/></connectionPointIn><variable>a</variable></contact>
<coil localId="3"><connectionPointIn><connection refLocalId="2"/></connectionPointIn><variable>b</variable></coil>
</LD></body></pou>
<pou name="other" pouType="program"><body><ST><xhtml:p>x := 1;</xhtml:p></ST></body></pou>
</pous></types></project>"#;

    #[test]
    fn a_coil_variable_names_its_pou_network_and_local_id() {
        let at = LD.find("<variable>b").unwrap() + 10;
        let c = context_at(LD, at).unwrap();
        assert_eq!(c.pou.as_deref(), Some("main"));
        assert_eq!(c.network.as_deref(), Some("1"));
        assert_eq!(c.local_id.as_deref(), Some("3"));
    }

    #[test]
    fn a_textual_body_names_its_pou_only_and_outside_every_pou_is_none() {
        let c = context_at(LD, LD.find("x := 1").unwrap()).unwrap();
        assert_eq!(c.pou.as_deref(), Some("other"));
        assert_eq!((c.network, c.local_id), (None, None));
        assert!(context_at(LD, 3).is_none());
        assert!(context_at("<not xml", 2).is_none());
    }
}
