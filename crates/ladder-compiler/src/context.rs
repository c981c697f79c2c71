//! The compilation context shared by the readers: file id, XML text, diagnostics sink, and helpers that
//! turn byte offsets and XML elements into spans and engineer-facing locations.
//!
//! Input: the file id, the XML text and the caller's `Diagnostics`. Output: spans ([`Ctx::tag`],
//! [`Ctx::attr_span`], [`Ctx::text_span`]), reported diagnostics, named integer constants for array bounds.
//!
//! Invariants: every span produced here lies inside the XML text; diagnostics about a graphical element
//! carry an [`XmlContext`] naming the POU, the network (rung) and the element's localId.

use crate::xml::Element;
use diagnostics::{Code, Diagnostic, Diagnostics, FileId, Span, XmlContext};
use std::collections::HashMap;

/// The reading context of one PLCopen XML file: where spans point, where diagnostics go, which named
/// constants are known.
pub struct Ctx<'a> {
    /// The XML file's id (every span points into it).
    pub file: FileId,
    /// The whole XML text.
    pub xml: &'a str,
    /// Where every diagnostic of the file goes.
    pub diags: &'a mut Diagnostics,
    /// Integer constants usable as array bounds: global (`VAR_GLOBAL CONSTANT` of configurations,
    /// resources and vendor global variable lists), upper-cased names.
    pub constants: HashMap<String, i128>,
    /// The constants of the POU being read (`VAR CONSTANT`), which shadow the global ones.
    pub local_constants: HashMap<String, i128>,
    /// The actions of the POUs read so far, each lowered on its own (for calls from other POUs:
    /// `il_frontend::actions::link`); the unit gets them at its end.
    pub actions: Vec<il_frontend::ast::Action>,
    /// The `<configVariable>` entries of the configurations read so far (VAR_CONFIG), applied
    /// once every input file is read (`il_frontend::st::file::apply_var_config`).
    pub var_config: Vec<il_frontend::st::file::ConfigEntry>,
    /// The ST bodies left to the ST front end (`crate::xml_oop`: a file with CODESYS's
    /// interfaces or inheritance): compiled with the other files' pending bodies.
    pub pending: Vec<il_frontend::st::file::PendingBody>,
}

impl<'a> Ctx<'a> {
    /// The span of the byte range `start..end`, clamped to the text.
    pub fn span(&self, start: usize, end: usize) -> Span {
        let end = end.min(self.xml.len());
        Span::new(self.file, start.min(end), end)
    }
    /// The span of an element's start tag: what diagnostics and lowered nodes point at.
    pub fn tag(&self, e: &Element) -> Span {
        self.span(e.tag_start(), e.tag_end())
    }
    /// The span of an attribute's value, or of the start tag when the attribute is absent.
    pub fn attr_span(&self, e: &Element, name: &str) -> Span {
        match e.attr_range(name) {
            Some((start, end)) => self.span(start, end),
            None => self.tag(e),
        }
    }
    /// The span of an element's text content (first to last segment), or its start tag when empty.
    pub fn text_span(&self, e: &Element) -> Span {
        match (e.segments().first(), e.segments().last()) {
            (Some(f), Some(l)) => {
                // Trim surrounding whitespace so the excerpt underlines the words.
                let raw = &self.xml[f.start..l.end];
                let lead = raw.len() - raw.trim_start().len();
                let trail = raw.len() - raw.trim_end().len();
                if lead + trail >= raw.len() {
                    self.tag(e)
                } else {
                    self.span(f.start + lead, l.end - trail)
                }
            }
            _ => self.tag(e),
        }
    }
    /// A context with no constants known yet.
    pub fn new(file: FileId, xml: &'a str, diags: &'a mut Diagnostics) -> Ctx<'a> {
        Ctx {
            file,
            xml,
            diags,
            constants: HashMap::new(),
            local_constants: HashMap::new(),
            actions: Vec::new(),
            var_config: Vec::new(),
            pending: Vec::new(),
        }
    }
    /// The value of a named integer constant (the POU's own first).
    pub fn constant(&self, name: &str) -> Option<i128> {
        let key = name.to_ascii_uppercase();
        self.local_constants
            .get(&key)
            .or_else(|| self.constants.get(&key))
            .copied()
    }
    /// Adds a ready diagnostic.
    pub fn report(&mut self, d: Diagnostic) {
        self.diags.push(d);
    }
    /// Reports `d`, placed in POU `pou` when it has no XML context of its own.
    pub fn report_in_pou(&mut self, d: Diagnostic, pou: &str) {
        let d = if d.xml.is_none() {
            d.with_xml(diagnostics::XmlContext {
                pou: Some(pou.to_string()),
                ..Default::default()
            })
        } else {
            d
        };
        self.diags.push(d);
    }
    /// Reports error `code` at `span`.
    pub fn error(&mut self, code: Code, span: Span, msg: impl Into<String>) {
        self.diags.push(Diagnostic::error(code, msg).at(span));
    }
}

/// Where in the project a graphical element sits.
#[derive(Debug, Clone, Default)]
pub struct Where {
    /// The POU's name.
    pub pou: String,
    /// The network (rung) number, 1-based, in execution order ([`crate::graph::Graph::networks`]).
    pub network: Option<usize>,
    /// The element's `localId`.
    pub local_id: Option<String>,
}

impl Where {
    /// The location as the diagnostics' [`XmlContext`] (POU, network, localId).
    pub fn xml(&self) -> XmlContext {
        XmlContext {
            pou: Some(self.pou.clone()),
            local_id: self.local_id.clone(),
            network: self.network.map(|n| n.to_string()),
        }
    }
}
