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
//!
//! Flat addresses outside their area (E2001) are reported once per area: the first, with a note
//! counting the others and naming the size that would hold them all ([`Gen::fold_outside_area`]);
//! a program written for a larger process image (OpenPLC's `%QW0..%QW1023`) is one diagnostic per
//! area, not one per variable.

use super::Gen;
use crate::profile::{address_text, area_field, area_name, Located};
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
            let located = self.profile.locate(addr, access_bytes);
            if let Err(d) = &located {
                if d.code == code::E2001 {
                    let end = self.profile.needed_bytes(addr, access_bytes).unwrap_or(0);
                    self.outside_area.entry(d.span).or_insert((
                        area_index(addr.area),
                        end,
                        address_text(addr),
                    ));
                }
            }
            return located;
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

    /// Keeps the first E2001 of each area in source order (flat addresses outside the profile's
    /// area) and drops the others, noting on the first how many more there were, the farthest of
    /// them and the area size that holds them all. Runs once the program is generated, over every
    /// diagnostic reported.
    pub(super) fn fold_outside_area(&mut self) {
        if self.outside_area.is_empty() {
            return;
        }
        let list = std::mem::take(&mut *self.diags).into_vec();
        let area_of = |d: &Diagnostic| {
            (d.code == code::E2001)
                .then(|| self.outside_area.get(&d.span))
                .flatten()
        };
        let key = |d: &Diagnostic| d.span.map(|s| (s.file.0, s.start, s.end));
        // per area: how many, the first in source order (its index), the farthest (bytes, text)
        let mut count = [0u32; 3];
        let mut first: [Option<usize>; 3] = [None; 3];
        let mut farthest: [(u64, String); 3] = Default::default();
        for (i, d) in list.iter().enumerate() {
            let Some((a, end, text)) = area_of(d) else {
                continue;
            };
            count[*a] += 1;
            if first[*a].is_none_or(|f| key(d) < key(&list[f])) {
                first[*a] = Some(i);
            }
            if *end > farthest[*a].0 {
                farthest[*a] = (*end, text.clone());
            }
        }
        let mut kept = Vec::with_capacity(list.len());
        for (i, mut d) in list.into_iter().enumerate() {
            let Some(a) = area_of(&d).map(|(a, ..)| *a) else {
                kept.push(d);
                continue;
            };
            if first[a] != Some(i) {
                continue;
            }
            if count[a] > 1 {
                let area = [Area::Input, Area::Output, Area::Memory][a];
                let (end, text) = &farthest[a];
                let (area, field) = (area_name(area), area_field(area));
                d = d.with_note(match count[a] - 1 {
                    1 => format!(
                        "1 more address outside the {area} area is not reported: `{text}`, which needs a target profile whose `{field}` is at least {end}"
                    ),
                    n => format!(
                        "{n} more addresses outside the {area} area are not reported; the farthest, `{text}`, needs a target profile whose `{field}` is at least {end}"
                    ),
                });
            }
            kept.push(d);
        }
        self.diags.extend(kept);
    }
}
