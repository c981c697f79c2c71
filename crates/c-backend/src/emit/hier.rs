//! Hierarchical direct addresses (`%IX1.0.0`, `%IW0.0`, `%QW0.0.0.0`): a slot of their own.
//!
//! Input: the direct addresses the generator meets (declarations' `AT`, operands). Output: their
//! [`Located`] places, the extension sizes of the three areas (written into `ladderc_config.h`) and
//! the watch-table entries that name each slot by its address text.
//! Invariants: IEC 61131-3 (2013, 6.5.5.2) leaves the meaning of hierarchical addresses to the
//! implementation. ladderc gives each distinct address (area, size letter, numbers) one slot of its
//! own size (X: one byte, bit 0; B 1; W 2; D 4; L 8 bytes), naturally aligned, after the profile's
//! bytes of its area, in the order the generator first meets them. Two variables at the same address
//! share the slot; different addresses never overlap each other or the flat addresses (`%IW0` is not
//! `%IW0.0`, and `%IB0.0` is not `%IW0.0`), as matiec makes each one its own external variable. A
//! variable larger than its address's size is E2002. An area's slots together are at most
//! [`MAX_EXTENSION`] bytes (E2001 beyond).

use super::Gen;
use crate::profile::{address_text, Located};
use diagnostics::{code, Diagnostic};
use il_frontend::ast::{AddressSize, Area, DirectAddress};

/// The most bytes of hierarchical slots an area may have.
pub const MAX_EXTENSION: u32 = 1024 * 1024;

/// Whether `addr` is hierarchical: more than `byte.bit` for a bit, more than one number otherwise.
pub fn is_hierarchical(addr: &DirectAddress) -> bool {
    match addr.size {
        AddressSize::Bit => addr.path.len() > 2,
        _ => addr.path.len() > 1,
    }
}

/// The slots of one generation.
#[derive(Default)]
pub struct Slots {
    /// (area, size letter, numbers) -> byte offset in the area's C array.
    by_address: std::collections::BTreeMap<(u8, u8, Vec<u32>), u32>,
    /// In order of allocation: the address text, its area, offset and size.
    pub list: Vec<(String, Area, u32, AddressSize)>,
    /// Bytes used after the profile's area, per area (I, Q, M).
    pub used: [u32; 3],
}

fn area_index(a: Area) -> usize {
    match a {
        Area::Input => 0,
        Area::Output => 1,
        Area::Memory => 2,
    }
}

fn size_bytes(s: AddressSize) -> u32 {
    match s {
        AddressSize::Bit | AddressSize::Byte => 1,
        AddressSize::Word => 2,
        AddressSize::DWord => 4,
        AddressSize::LWord => 8,
    }
}

impl Gen<'_> {
    /// Where a direct address accessed with `access_bytes` bytes lives: a hierarchical one in its
    /// slot, any other as the profile says ([`crate::TargetProfile::locate`]).
    pub(super) fn locate(
        &mut self,
        addr: &DirectAddress,
        access_bytes: Option<u32>,
    ) -> Result<Located, Box<Diagnostic>> {
        if !is_hierarchical(addr) {
            return self.profile.locate(addr, access_bytes);
        }
        let size = size_bytes(addr.size);
        let text = address_text(addr);
        let wanted = if addr.size == AddressSize::Bit {
            1
        } else {
            access_bytes.unwrap_or(size)
        };
        if wanted > size {
            return Err(Box::new(
                Diagnostic::error(
                    code::E2002,
                    format!(
                        "the hierarchical address `{text}` holds {size} byte(s); the variable needs {wanted}"
                    ),
                )
                .at(addr.span)
                .with_primary_label("this address")
                .with_hint("a hierarchical address is a slot of its own size (X: BOOL, B: 1 byte, W: 2, D: 4, L: 8 bytes): use the size letter of the variable's type"),
            ));
        }
        let a = area_index(addr.area);
        let key = (
            a as u8,
            size as u8 + u8::from(addr.size == AddressSize::Bit) * 16,
            addr.path.clone(),
        );
        let bit = (addr.size == AddressSize::Bit).then_some(0u8);
        if let Some(&offset) = self.hier.by_address.get(&key) {
            return Ok(Located {
                area: addr.area,
                offset,
                bit,
                bytes: wanted,
            });
        }
        let start = self.hier.used[a].div_ceil(size) * size;
        if start + size > MAX_EXTENSION {
            return Err(Box::new(
                Diagnostic::error(
                    code::E2001,
                    format!("too many hierarchical addresses in one area: `{text}` does not fit in {MAX_EXTENSION} bytes"),
                )
                .at(addr.span)
                .with_primary_label("this address")
                .with_hint("use fewer distinct hierarchical addresses, or flat addresses (`%IW4`)"),
            ));
        }
        self.hier.used[a] = start + size;
        let offset = self.profile.area_size(addr.area) + start;
        self.hier.by_address.insert(key, offset);
        self.hier.list.push((text, addr.area, offset, addr.size));
        Ok(Located {
            area: addr.area,
            offset,
            bit,
            bytes: wanted,
        })
    }
}
