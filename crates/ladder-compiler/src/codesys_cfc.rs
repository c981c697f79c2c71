//! CODESYS V3 CFC bodies in a PLCopen XML export: reported, not dropped.
//!
//! TC6 XML has no CFC body. CODESYS V3 ("Export PLCopenXML") writes a POU, action, method or
//! transition drawn in the Continuous Function Chart editor as an empty `<ST>` body followed by the
//! chart in vendor data: `<body><ST><xhtml/></ST><addData><data
//! name="http://www.3s-software.com/plcopenxml/cfc"><CFC>...</CFC></data></addData></body>`. TC6 XML
//! 2.01 lets a reader skip unknown `addData` (`handleUnknown`), but then the body is empty and the
//! program silently does something else than the chart (issue #13: nothing dropped silently).
//! ladderc does not read this chart (its elements reference unnamed `<connector>` wire points and
//! run in `executionOrderId` order; TwinCAT's CFC is another format, an `XmlArchive`, read by
//! `twincat_cfc`).
//!
//! Input: the root element of a PLCopen project. Output: one E0321 per chart, at its `<CFC>` element
//! (or its `<data>` when the chart element is missing), naming the POU, action, method or
//! transition whose body it is; and the `<data>` elements so reported, which the project's W3002
//! (vendor data ignored) leaves out. Invariants: never panics; the walk is iterative and visits
//! each element once.

use crate::context::Ctx;
use crate::xml::Element;
use diagnostics::{code, Diagnostic, XmlContext};
use std::collections::HashSet;

/// The `name` of the vendor data that holds a CODESYS CFC chart.
const CFC_DATA: &str = "http://www.3s-software.com/plcopenxml/cfc";

/// What owns a body: its kind (`POU`, `action`, ...) and its name.
type Owner<'a> = (&'static str, &'a str);

/// Reports every CODESYS CFC chart of the project (E0321) and returns the tag starts of their
/// `<data>` elements.
pub(crate) fn unread_charts(ctx: &mut Ctx, root: &Element) -> HashSet<usize> {
    let mut reported = HashSet::new();
    // (element, what owns the bodies below it: kind and name; the POU it is in)
    let mut stack: Vec<(&Element, Option<Owner>, Option<&str>)> = vec![(root, None, None)];
    while let Some((e, owner, pou)) = stack.pop() {
        let owner = match (owner_kind(e.name()), e.attr("name")) {
            (Some(kind), Some(name)) => Some((kind, name.trim())),
            _ => owner,
        };
        let pou = match (e.name(), e.attr("name")) {
            ("pou", Some(name)) => Some(name.trim()),
            _ => pou,
        };
        if e.name() == "body" {
            for data in e
                .children_named("addData")
                .flat_map(|a| a.children_named("data"))
                .filter(|d| d.attr("name").map(str::trim) == Some(CFC_DATA))
            {
                reported.insert(data.tag_start());
                let at = data.child("CFC").unwrap_or(data);
                let (kind, name) = owner.unwrap_or(("POU", "?"));
                ctx.report(
                    Diagnostic::error(
                        code::E0321,
                        format!(
                            "the body of {kind} `{name}` is a CODESYS CFC chart, which ladderc does not read: it is not compiled"
                        ),
                    )
                    .at(ctx.tag(at))
                    .with_primary_label("CODESYS's CFC chart (vendor data; the <ST> body beside it is empty)")
                    .with_xml(XmlContext {
                        pou: Some(pou.unwrap_or(name).to_string()),
                        ..Default::default()
                    })
                    .with_hint("draw the body in FBD or LD, or write it in ST or IL, in CODESYS and export PLCopen XML again: ladderc reads those"),
                );
            }
        }
        stack.extend(e.children.iter().rev().map(|c| (c, owner, pou)));
    }
    reported
}

/// The words a diagnostic names an element with a body by (`pou`, `action`, `transition`, and a
/// CODESYS method or property accessor's `Method` / `Property`), or `None`.
fn owner_kind(element: &str) -> Option<&'static str> {
    match element {
        "pou" => Some("POU"),
        "action" => Some("action"),
        "transition" => Some("transition"),
        "Method" => Some("method"),
        "Property" => Some("property"),
        _ => None,
    }
}
