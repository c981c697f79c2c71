//! The TM (temporary) area layout of the IL-instruction method.
//!
//! Input: a template's parameters and the TM size of the target profile. Output: one slot per parameter,
//! contiguous, in declaration order, sized by class (no padding: the area is byte-addressed and moves into it
//! are byte-wise); an array parameter's slot holds its elements contiguously (element `k` at
//! `offset + k * element bytes`). Invariant: the slots tile `0..total` exactly; a block that does not fit is an error naming the
//! block, the bytes it needs and the bytes available.

use crate::template::{Param, Template};

/// One parameter's place in the TM area.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Slot {
    /// Parameter name as declared in the template.
    pub param: String,
    /// Byte offset in the TM area.
    pub offset: u32,
    /// Bytes it takes.
    pub bytes: u32,
}

/// A block type's TM layout: every parameter's slot.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct TmLayout {
    /// The slots, in parameter order.
    pub slots: Vec<Slot>,
    /// Bytes of the whole layout.
    pub total: u32,
}

impl TmLayout {
    /// The slot of `param` (case-insensitive).
    pub fn slot(&self, param: &str) -> Option<&Slot> {
        self.slots
            .iter()
            .find(|s| s.param.eq_ignore_ascii_case(param))
    }
}

/// Lays out the parameters of `template`. `Err((needed, available))` when the block does not fit.
pub fn layout(template: &Template, tm_size: u32) -> Result<TmLayout, (u32, u32)> {
    layout_params(&template.params, tm_size)
}

/// Lays out `params` in a TM area of `tm_size` bytes; `Err((needed, available))` when they do not fit.
pub fn layout_params(params: &[Param], tm_size: u32) -> Result<TmLayout, (u32, u32)> {
    let mut offset = 0u32;
    let mut slots = Vec::with_capacity(params.len());
    for p in params {
        let bytes = p.tm_bytes();
        slots.push(Slot {
            param: p.name.clone(),
            offset,
            bytes,
        });
        offset += bytes;
    }
    if offset > tm_size {
        return Err((offset, tm_size));
    }
    Ok(TmLayout {
        slots,
        total: offset,
    })
}
