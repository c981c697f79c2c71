//! CODESYS's encoding of a variable-length array parameter in its PLCopen XML export.
//!
//! CODESYS V3 declares `VAR_IN_OUT x : ARRAY[*] OF T; END_VAR` (IEC 61131-3 ed. 3, 6.5.3,
//! "variable-length arrays"; CODESYS online help "Data Type: ARRAY", "Variable length arrays": only
//! as a VAR_IN_OUT of a function, function block or method), and its "Export PLCopenXML" writes the
//! parameter as an input `<pointer>` to the element type, the real declaration kept in the variable's
//! vendor attributes (`addData/data[.../plcopenxml/attributes]/Attributes/Attribute`):
//! `variable_length_array` = `ARRAY[*] OF T`, `variable_length_array_original_scope` = `Inout`,
//! `Dimensions` = the number of `*`.
//!
//! Input: a `<variable>` element and the type its `<type>` gives; an input list read as a block.
//! Output: the parameter as it was declared, `ARRAY[*, ...] OF T` ([`ArrayDim::VARIABLE`] bounds),
//! and the input block split so that it is a VAR_IN_OUT block in the same place among the parameters
//! (positional calls keep their order), in a POU's interface and in a METHOD's of the vendor data.
//! [`crate::project`] then splits it into its hidden address
//! and bound inputs as the ST front end does in text (`il_frontend::st::varlen`), and the ST bodies'
//! calls and uses (`LOWER_BOUND`, `UPPER_BOUND`, indexing with the caller's bounds) are rewritten
//! when they are lowered.
//! Invariants: only a `<pointer>` with both attributes, original scope `Inout`, is changed; every
//! other variable is read as written.

use crate::xml::Element;
use il_frontend::ast::{ArrayDim, TypeRef, VarBlock, VarKind};

/// The vendor attribute `name` of variable `v` (CODESYS's `<Attribute Name=".." Value=".."/>`).
fn vendor_attribute<'a>(v: &Element<'a>, name: &str) -> Option<&'a str> {
    v.children_named("addData")
        .flat_map(|a| a.children_named("data"))
        .filter(|d| d.attr("name").is_some_and(|n| n.ends_with("/attributes")))
        .flat_map(|d| d.children_named("Attributes"))
        .flat_map(|a| a.children_named("Attribute"))
        .find(|a| a.attr("Name").is_some_and(|n| n.trim() == name))
        .and_then(|a| a.attr("Value"))
}

/// The vendor attributes [`declared_type`] reads.
const READ: [&str; 3] = [
    "variable_length_array",
    "variable_length_array_original_scope",
    "Dimensions",
];

/// Whether the vendor data block `data` is a variable's attributes holding only what
/// [`declared_type`] reads (the W3002 of ignored vendor data leaves it out).
pub fn only_its_attributes(data: &Element) -> bool {
    if !data
        .attr("name")
        .is_some_and(|n| n.ends_with("/attributes"))
    {
        return false;
    }
    let names = || {
        data.children_named("Attributes")
            .flat_map(|a| a.children.iter())
            .map(|x| (x.name() == "Attribute").then(|| x.attr("Name").map(str::trim)))
    };
    names().any(|n| n == Some(Some(READ[0])))
        && names().all(|n| n.flatten().is_some_and(|n| READ.contains(&n)))
}

/// Whether `v` is CODESYS's export of a variable-length in-out (see the module documentation).
fn is_exported_in_out(v: &Element) -> bool {
    vendor_attribute(v, "variable_length_array").is_some()
        && vendor_attribute(v, "variable_length_array_original_scope")
            .is_some_and(|s| s.trim().eq_ignore_ascii_case("inout"))
}

/// The declared type of `v` when it is CODESYS's export of a variable-length in-out whose `<type>`
/// gave `ty` (a pointer to the element type): `ARRAY[*] OF T`, one `*` per dimension (the
/// `Dimensions` attribute, else the `*`s of the declaration's text, 1 to 8).
pub fn declared_type(v: &Element, ty: &TypeRef) -> Option<TypeRef> {
    if !is_exported_in_out(v) {
        return None;
    }
    let TypeRef::Ref {
        kind: il_frontend::ast::RefKind::Pointer,
        target,
        span,
    } = ty
    else {
        return None;
    };
    let text = vendor_attribute(v, "variable_length_array").unwrap_or("");
    let rank = vendor_attribute(v, "Dimensions")
        .and_then(|d| d.trim().parse::<usize>().ok())
        .unwrap_or_else(|| text.split(" OF").next().unwrap_or("").matches('*').count())
        .clamp(1, 8);
    let dim = ArrayDim {
        lower: ArrayDim::VARIABLE,
        upper: ArrayDim::VARIABLE,
        span: *span,
    };
    Some(TypeRef::Array {
        dims: vec![dim; rank],
        element: target.clone(),
        span: *span,
    })
}

/// Whether `ty` is an array whose every dimension is `*`.
fn is_variable_length(ty: &TypeRef) -> bool {
    matches!(ty, TypeRef::Array { dims, .. } if dims.iter().all(ArrayDim::is_variable))
}

/// An input block as the blocks it was declared as: its variable-length arrays (read by
/// [`declared_type`]) are VAR_IN_OUTs, each in its own block between the inputs before and after
/// it. Any other block is returned as it is.
pub fn split_inputs(block: VarBlock) -> Vec<VarBlock> {
    if block.kind != VarKind::Input || !block.vars.iter().any(|v| is_variable_length(&v.ty)) {
        return vec![block];
    }
    let mut out: Vec<VarBlock> = Vec::new();
    let template = VarBlock {
        vars: Vec::new(),
        ..block.clone()
    };
    for v in block.vars {
        let kind = if is_variable_length(&v.ty) {
            VarKind::InOut
        } else {
            VarKind::Input
        };
        match out.last_mut() {
            Some(b) if b.kind == kind => b.vars.push(v),
            _ => out.push(VarBlock {
                kind,
                vars: vec![v],
                ..template.clone()
            }),
        }
    }
    out
}
