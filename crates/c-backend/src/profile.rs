//! The target profile: the memory model of the controller the C program is built for.
//!
//! Input: JSON (the embedded default `profiles/default.json`, or a user file). Output: a validated
//! [`TargetProfile`] and, per direct address, its [`Located`] byte offset and bit in the %I/%Q/%M areas.
//! Invariants: a validated profile has non-empty areas, the TM window inside %M, a power-of-two alignment;
//! [`TargetProfile::locate`] only returns locations whose bytes lie inside their area (inside the
//! image of their size with `"address_unit": "per_size"`, whose %I and %Q hold one image per size,
//! and with `"memory_per_size": true`, whose %M does too but for its TM window, one flat window in
//! the first image).

use diagnostics::{code, Diagnostic, Diagnostics};
use il_frontend::ast::{AddressSize, Area, DirectAddress};
use serde::{Deserialize, Serialize};
use std::path::Path;

/// The default profile as shipped (documented in the crate README).
pub const DEFAULT_PROFILE_JSON: &str = include_str!("../profiles/default.json");
/// The OpenPLC profile: one image per size (`%QX0.0` and `%QW0` apart), OpenPLC's area sizes.
pub const OPENPLC_PROFILE_JSON: &str = include_str!("../profiles/openplc.json");

/// The profiles built into the compiler, by the name `--profile` takes (`--profile openplc`), with
/// their JSON.
pub const BUILT_IN_PROFILES: &[(&str, &str)] = &[
    ("default", DEFAULT_PROFILE_JSON),
    ("openplc", OPENPLC_PROFILE_JSON),
];

/// Byte order of multi-byte addresses.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum ByteOrder {
    /// Least significant byte first.
    Little,
    /// Most significant byte first.
    Big,
}

/// Which bit of a byte `%IX3.0` names.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum BitNumbering {
    /// Bit 0 is the least significant bit (IEC common practice).
    Lsb0,
    /// Bit 0 is the most significant bit.
    Msb0,
}

/// What the number of `%IW2` counts.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum AddressUnit {
    /// `%IW2` is the third word: bytes 4..6 (CODESYS style; %IB, %IW, %ID, %IL overlap).
    Element,
    /// `%IW2` starts at byte 2 (Siemens style).
    Byte,
    /// `%IW2` is the third word of the words' own image: %I and %Q have one image per size (X and B,
    /// W, D, L), each of `input_bytes` / `output_bytes`, so `%QX0.0` (a digital output) and `%QW0`
    /// (an analog one) never share bits, as OpenPLC and matiec keep them; %M counts elements as
    /// [`AddressUnit::Element`] does (the TM window of parameter passing lies there), in one image
    /// unless the profile's `memory_per_size` is set.
    #[serde(rename = "per_size")]
    PerSize,
}

/// What one unit of a number converted to or from TIME (or LTIME) is: `REAL_TO_TIME(1.5)`,
/// `DINT_TO_TIME(15)`, `TIME_TO_REAL(t)`. IEC 61131-3 leaves it to the implementation (ed. 2
/// 2.5.1.5.1, ed. 3 6.6.2.5.6 give no unit for these conversions), and vendors differ: milliseconds
/// in CODESYS and TwinCAT, seconds in matiec, 10 ms in Panasonic's FPWIN Pro (its `TIME_TO_DWORD`
/// help: "The time 10ms corresponds to the value 1").
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize)]
pub enum TimeNumberUnit {
    /// A millisecond: CODESYS and TwinCAT (`TIME_TO_DWORD` counts ms), OSCAT; ladderc's default.
    #[default]
    #[serde(rename = "ms")]
    Milliseconds,
    /// A second: matiec's `__real_to_time`/`__int_to_time`/`__time_to_real` (its
    /// `lib/C/iec_std_lib.h`), which Beremiz and OpenPLC compile with (`--profile openplc`).
    #[serde(rename = "s")]
    Seconds,
}

impl TimeNumberUnit {
    /// Nanoseconds per unit.
    pub fn nanoseconds(self) -> i64 {
        match self {
            TimeNumberUnit::Milliseconds => 1_000_000,
            TimeNumberUnit::Seconds => 1_000_000_000,
        }
    }
    /// Whether a real number converted to TIME (`REAL_TO_TIME`, `LREAL_TO_TIME`) is rounded to a
    /// whole number of units (to the nearest, halves to even, as every REAL to integer conversion):
    /// under milliseconds, since TIME is a 32-bit count of milliseconds in CODESYS and TwinCAT and
    /// their `REAL_TO_<type>` rounds to the nearest integer (Beckhoff infosys, `"REAL/LREAL_TO_<type>"`:
    /// the exceptions are only STRING, BOOL, REAL and LREAL), so `REAL_TO_TIME(1.5)` is `T#2ms`;
    /// not under seconds, where matiec's `__real_to_time` keeps the fraction (`T#1.5s`). LTIME (a
    /// count of nanoseconds in CODESYS and TwinCAT) keeps its nanoseconds under either unit.
    pub fn rounds_real_to_time(self) -> bool {
        self == TimeNumberUnit::Milliseconds
    }
    /// The unit's name as the profile writes it (`ms`, `s`).
    pub fn name(self) -> &'static str {
        match self {
            TimeNumberUnit::Milliseconds => "ms",
            TimeNumberUnit::Seconds => "s",
        }
    }
}

/// How a sequential function chart's actions are controlled.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum SfcActionControl {
    /// IEC 61131-3 (ed. 2 2.6.4.5, ed. 3 6.7.4.6, the ACTION_CONTROL block): an action's body runs
    /// once more in the scan its `Q` falls (the final scan), and an initial step's P action runs in
    /// the first scan (the step becomes active then). ladderc's default.
    #[default]
    Iec,
    /// Beremiz and OpenPLC (matiec's generated SFC code): an action runs only while its `Q` is TRUE
    /// (no final scan), and an initial step counts as active before the first scan, so its P action
    /// runs only on a later activation (`--profile openplc`).
    Beremiz,
}

/// Sizes and layout of the process image and the TM area.
#[derive(Debug, Clone, PartialEq, Eq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct TargetProfile {
    /// The profile's name (shown in the generated header).
    pub name: String,
    /// Size of the %I area in bytes.
    pub input_bytes: u32,
    /// Size of the %Q area in bytes.
    pub output_bytes: u32,
    /// Size of the %M area in bytes (the TM window included).
    pub memory_bytes: u32,
    /// Byte order of multi-byte addresses (%IW, %QD, %ML ...).
    pub byte_order: ByteOrder,
    /// Which bit of a byte `%IX3.0` names.
    pub bit_numbering: BitNumbering,
    /// What the number of `%IW2` counts.
    pub address_unit: AddressUnit,
    /// The TM (temporary) area for parameter passing: bytes `tm_offset..tm_offset + tm_bytes` of %M.
    pub tm_offset: u32,
    /// The TM area's size in bytes.
    pub tm_bytes: u32,
    /// A multi-byte address must start at a multiple of `min(alignment, its size)` bytes (1: no rule).
    pub alignment: u32,
    /// The memory budget for variables, in bytes: no variable, no POU's data and not all static data
    /// together (globals and program instances) may need more (E2100, checked before C is generated).
    /// Optional in a profile file; the default is 16 MiB.
    #[serde(default = "default_data_bytes")]
    pub data_bytes: u64,
    /// The unit of a number converted to or from TIME (`"ms"` or `"s"`). Optional in a profile
    /// file; the default is milliseconds (`--profile openplc`: seconds, as matiec).
    #[serde(default)]
    pub time_number_unit: TimeNumberUnit,
    /// How SFC actions are controlled (`"iec"` or `"beremiz"`). Optional in a profile file; the
    /// default is IEC's final scan (`--profile openplc`: Beremiz's, none).
    #[serde(default)]
    pub sfc_action_control: SfcActionControl,
    /// The length in characters of a `STRING` or `WSTRING` declared without one (IEC 61131-3 ed. 3
    /// leaves it to the implementation). Optional in a profile file; the default is 80, as CODESYS
    /// and TwinCAT ("If no size is specified, 80 bytes are reserved by default", TwinCAT 3 manual,
    /// STRING); `--profile openplc`: 126, matiec's `STR_MAX_LEN`. At most 254, the capacity of every
    /// `IEC_STRING`.
    #[serde(default = "default_string_length")]
    pub default_string_length: u32,
    /// Whether %M has one image per size, as %I and %Q have with [`AddressUnit::PerSize`]: `%MX0.1`
    /// and `%MB0` in the first, `%MW0` in the second, `%MD0` in the third, `%ML0` in the fourth, each
    /// `memory_bytes` long and counted in elements, so `%MX0.1`, `%MW0`, `%MD0` and `%ML0` never share
    /// bits. OpenPLC keeps its %M memory so (`int_memory`, `dint_memory`, `lint_memory`: one buffer
    /// per size, and matiec gives every located variable storage of its own); `--profile openplc`
    /// sets it. The TM window of parameter passing stays one flat window (its bytes in the first
    /// image, whatever the size of the address that reaches them), as the static library reads it.
    /// Optional in a profile file; the default is `false` (one image: `%MX0.1` is bit 1 of `%MW0`);
    /// it needs element addressing (`address_unit` `"element"` or `"per_size"`).
    #[serde(default, skip_serializing_if = "std::ops::Not::not")]
    pub memory_per_size: bool,
}

/// The default `default_string_length`: 80 characters, as CODESYS and TwinCAT.
pub const DEFAULT_STRING_LENGTH: u32 = 80;

fn default_string_length() -> u32 {
    DEFAULT_STRING_LENGTH
}

/// The default `data_bytes`: 16 MiB.
pub const DEFAULT_DATA_BYTES: u64 = 16 * 1024 * 1024;

fn default_data_bytes() -> u64 {
    DEFAULT_DATA_BYTES
}

/// Why a profile was refused.
#[derive(Debug, thiserror::Error)]
pub enum ProfileError {
    /// The file could not be read.
    #[error("cannot read the target profile `{path}`: {message}")]
    Io {
        /// The file.
        path: String,
        /// The I/O error.
        message: String,
    },
    /// The text is not a profile's JSON.
    #[error("the target profile is not valid JSON for a profile: {0}")]
    Json(String),
    /// The values contradict each other or are out of range.
    #[error("the target profile is inconsistent: {0}")]
    Invalid(String),
}

impl Default for TargetProfile {
    fn default() -> Self {
        // The embedded file is ours and covered by a test; fall back to the same values if it ever breaks.
        TargetProfile::from_json(DEFAULT_PROFILE_JSON).unwrap_or(TargetProfile {
            name: "default".into(),
            input_bytes: 256,
            output_bytes: 256,
            memory_bytes: 4096,
            byte_order: ByteOrder::Little,
            bit_numbering: BitNumbering::Lsb0,
            address_unit: AddressUnit::Element,
            tm_offset: 3840,
            tm_bytes: 256,
            alignment: 1,
            data_bytes: DEFAULT_DATA_BYTES,
            time_number_unit: TimeNumberUnit::Milliseconds,
            sfc_action_control: SfcActionControl::Iec,
            default_string_length: DEFAULT_STRING_LENGTH,
            memory_per_size: false,
        })
    }
}

/// Where a direct address (or an AT-located variable) lives.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Located {
    /// The area (`%I`, `%Q`, `%M`).
    pub area: Area,
    /// Byte offset in the area.
    pub offset: u32,
    /// The bit (0..=7) for `X` addresses.
    pub bit: Option<u8>,
    /// Bytes accessed (1 for bits).
    pub bytes: u32,
}

/// Largest area the profile accepts (the C arrays are static; 64 MiB keeps `offset + size` in `u32`).
const MAX_AREA: u32 = 64 * 1024 * 1024;

impl TargetProfile {
    /// A profile from its JSON text, validated.
    pub fn from_json(text: &str) -> Result<Self, ProfileError> {
        let p: TargetProfile =
            serde_json::from_str(text).map_err(|e| ProfileError::Json(e.to_string()))?;
        p.validate()?;
        Ok(p)
    }

    /// The built-in profile called `name` (`default`, `openplc`; see [`BUILT_IN_PROFILES`]), when
    /// `name` is a bare name: no folder, no extension.
    pub fn built_in(name: &Path) -> Option<Self> {
        if name.components().count() != 1 || name.extension().is_some() {
            return None;
        }
        let name = name.to_str()?;
        BUILT_IN_PROFILES
            .iter()
            .find(|(n, _)| n.eq_ignore_ascii_case(name))
            .and_then(|(_, json)| Self::from_json(json).ok())
    }

    /// A profile from a JSON file, validated.
    pub fn load(path: &Path) -> Result<Self, ProfileError> {
        let text = std::fs::read_to_string(path).map_err(|e| ProfileError::Io {
            path: path.display().to_string(),
            message: e.to_string(),
        })?;
        Self::from_json(&text)
    }

    /// Loads a profile file, reporting a problem as E2003.
    pub fn load_or_report(path: &Path, diags: &mut Diagnostics) -> Option<Self> {
        match Self::load(path) {
            Ok(p) => Some(p),
            // A file that cannot be read is an I/O error (E9001, exit 2), not a bad profile.
            Err(e @ ProfileError::Io { .. }) => {
                diags.push(
                    Diagnostic::error(code::E9001, e.to_string())
                        .with_hint("check the --profile path and its permissions, or name a built-in profile: `default`, `openplc`"),
                );
                None
            }
            Err(e) => {
                diags.push(
                    Diagnostic::error(code::E2003, e.to_string())
                        .with_hint("see the memory model section of the c-backend README"),
                );
                None
            }
        }
    }

    /// The profile as pretty JSON.
    pub fn to_json(&self) -> String {
        serde_json::to_string_pretty(self).unwrap_or_default()
    }

    /// Checks the sizes, the TM window, the alignment and the name.
    pub fn validate(&self) -> Result<(), ProfileError> {
        let bad = |m: String| Err(ProfileError::Invalid(m));
        for (name, size) in [
            ("input_bytes", self.input_bytes),
            ("output_bytes", self.output_bytes),
            ("memory_bytes", self.memory_bytes),
        ] {
            let images = if name == "memory_bytes" {
                self.images(Area::Memory)
            } else if self.address_unit == AddressUnit::PerSize {
                4
            } else {
                1
            };
            if size == 0 || size > MAX_AREA / images {
                return bad(format!(
                    "{name} must be between 1 and {}, got {size}",
                    MAX_AREA / images
                ));
            }
        }
        if self.tm_bytes == 0 {
            return bad("tm_bytes must be at least 1".into());
        }
        if u64::from(self.tm_offset) + u64::from(self.tm_bytes) > u64::from(self.memory_bytes) {
            return bad(format!(
                "the TM area (tm_offset {} + tm_bytes {}) does not fit in memory_bytes {}",
                self.tm_offset, self.tm_bytes, self.memory_bytes
            ));
        }
        if self.alignment == 0 || !self.alignment.is_power_of_two() || self.alignment > 8 {
            return bad(format!(
                "alignment must be 1, 2, 4 or 8, got {}",
                self.alignment
            ));
        }
        if self.memory_per_size && self.address_unit == AddressUnit::Byte {
            return bad(
                "memory_per_size needs element addressing (address_unit \"element\" or \"per_size\"), got address_unit \"byte\""
                    .into(),
            );
        }
        if self.data_bytes == 0 {
            return bad("data_bytes must be at least 1".into());
        }
        if !(1..=254).contains(&self.default_string_length) {
            return bad(format!(
                "default_string_length must be between 1 and 254 (the capacity of every STRING), got {}",
                self.default_string_length
            ));
        }
        if self.name.is_empty() {
            return bad("name must not be empty".into());
        }
        Ok(())
    }

    /// The size of `area`'s C array in bytes: its images together (see [`Self::images`]).
    pub fn area_size(&self, area: Area) -> u32 {
        self.image_size(area) * self.images(area)
    }

    /// The size in bytes of one image of `area`: the profile's `input_bytes`, `output_bytes` or
    /// `memory_bytes`.
    pub fn image_size(&self, area: Area) -> u32 {
        match area {
            Area::Input => self.input_bytes,
            Area::Output => self.output_bytes,
            Area::Memory => self.memory_bytes,
        }
    }

    /// How many images `area` has: 4 for %I and %Q with [`AddressUnit::PerSize`] and for %M with
    /// `memory_per_size` (X and B, W, D, L, in that order in the area's C array), else 1.
    pub fn images(&self, area: Area) -> u32 {
        let per_size = match area {
            Area::Memory => self.memory_per_size,
            Area::Input | Area::Output => self.address_unit == AddressUnit::PerSize,
        };
        if per_size {
            4
        } else {
            1
        }
    }

    /// Whether bytes `offset..offset + bytes` of %M lie in the TM window of parameter passing.
    fn in_tm_window(&self, offset: u64, bytes: u32) -> bool {
        offset >= u64::from(self.tm_offset)
            && offset + u64::from(bytes) <= u64::from(self.tm_offset) + u64::from(self.tm_bytes)
    }

    /// The byte range `(offset, bytes)` a flat direct address accessed with `access_bytes` bytes
    /// (`None`: the address's own size) takes in its area, whether or not the area holds it; `Err`
    /// with the reason for a form that has no place in the flat area (a `*` placeholder, a bit
    /// beyond 7, a hierarchical address).
    fn byte_range(
        &self,
        addr: &DirectAddress,
        access_bytes: Option<u32>,
    ) -> Result<(u64, u32, Option<u8>, u32), &'static str> {
        let size_bytes = match addr.size {
            AddressSize::Bit => 1,
            AddressSize::Byte => 1,
            AddressSize::Word => 2,
            AddressSize::DWord => 4,
            AddressSize::LWord => 8,
        };
        let (index, bit) = match (addr.size, addr.path.as_slice()) {
            (_, []) => return Err("a `*` address must be given a location before it can be compiled"),
            (AddressSize::Bit, [byte, bit]) => {
                if *bit > 7 {
                    return Err("the bit number must be 0 to 7");
                }
                (*byte, Some(*bit as u8))
            }
            // `%IX13` (one number, as matiec and some LD editors write): absolute bit 13 = byte 1, bit 5
            (AddressSize::Bit, [n]) => (n / 8, Some((n % 8) as u8)),
            (_, [index]) => (*index, None),
            // hierarchical: `Gen::locate` (emit/hier.rs) gives each a slot after the area
            _ => return Err(
                "a hierarchical address has no place in the flat area (the C generator gives it a slot of its own)",
            ),
        };
        let offset = match self.address_unit {
            AddressUnit::Byte => u64::from(index),
            AddressUnit::Element | AddressUnit::PerSize => u64::from(index) * u64::from(size_bytes),
        };
        let bytes = if bit.is_some() {
            1
        } else {
            access_bytes.unwrap_or(size_bytes).max(1)
        };
        // the TM window is one flat window (module header): its bytes are in the first image
        let tm = addr.area == Area::Memory && self.in_tm_window(offset, bytes);
        let image = if self.images(addr.area) > 1 && !tm {
            match addr.size {
                AddressSize::Bit | AddressSize::Byte => 0,
                AddressSize::Word => 1,
                AddressSize::DWord => 2,
                AddressSize::LWord => 3,
            }
        } else {
            0
        };
        Ok((offset, bytes, bit, image))
    }

    /// The bytes of its image a flat direct address needs (the end of its byte range),
    /// `None` for a form [`Self::locate`] refuses.
    pub fn needed_bytes(&self, addr: &DirectAddress, access_bytes: Option<u32>) -> Option<u64> {
        self.byte_range(addr, access_bytes)
            .ok()
            .map(|(offset, bytes, ..)| offset + u64::from(bytes))
    }

    /// The first built-in profile other than this one (by name) whose area holds `addr`, for
    /// E2001's hint (an OpenPLC program's `%QW200` fits `--profile openplc`).
    fn built_in_holding(
        &self,
        addr: &DirectAddress,
        access_bytes: Option<u32>,
    ) -> Option<&'static str> {
        BUILT_IN_PROFILES.iter().find_map(|&(name, json)| {
            if name.eq_ignore_ascii_case(&self.name) {
                return None;
            }
            let p = Self::from_json(json).ok()?;
            let (offset, bytes, ..) = p.byte_range(addr, access_bytes).ok()?;
            (offset + u64::from(bytes) <= u64::from(p.image_size(addr.area))).then_some(name)
        })
    }

    /// Locates a direct address accessed with `access_bytes` bytes (the located variable's type size;
    /// `None`: the address's own size). Errors: E2002 (form), E2001 (outside the area), E2006 (alignment).
    pub fn locate(
        &self,
        addr: &DirectAddress,
        access_bytes: Option<u32>,
    ) -> Result<Located, Box<Diagnostic>> {
        let text = address_text(addr);
        let (offset, bytes, bit, image) = self.byte_range(addr, access_bytes).map_err(|msg| {
            Box::new(
                Diagnostic::error(code::E2002, format!("unsupported address `{text}`: {msg}"))
                    .at(addr.span)
                    .with_primary_label("this address")
                    .with_hint("write a bit as byte.bit with a bit from 0 to 7 (`%IX1.1`); an `AT %I*` variable needs a VAR_CONFIG entry that places it; `ladderc explain E2002`"),
            )
        })?;
        let area_size = self.image_size(addr.area);
        if offset + u64::from(bytes) > u64::from(area_size) {
            return Err(Box::new(
                Diagnostic::error(
                    code::E2001,
                    format!(
                        "address `{text}` is outside the {} area ({} bytes in target profile `{}`)",
                        area_name(addr.area),
                        area_size,
                        self.name
                    ),
                )
                .at(addr.span)
                .with_primary_label(format!(
                    "needs bytes {}..{}",
                    offset,
                    offset + u64::from(bytes)
                ))
                .with_hint(format!(
                    "use a smaller address, or a target profile (`--profile FILE.json`) whose `{}` is at least {}{}",
                    area_field(addr.area),
                    offset + u64::from(bytes),
                    self.built_in_holding(addr, access_bytes)
                        .map(|n| format!(" (the built-in `--profile {n}` has room for it)"))
                        .unwrap_or_default()
                )),
            ));
        }
        // inside its image, whose size fits in u32 (validated), so this fits too
        let offset = (u64::from(image) * u64::from(area_size) + offset) as u32;
        let align = self.alignment.min(bytes);
        if bit.is_none() && align > 1 && !offset.is_multiple_of(align) {
            return Err(Box::new(
                Diagnostic::error(
                    code::E2006,
                    format!(
                        "address `{text}` starts at byte {offset}, not a multiple of {align} as target profile `{}` requires",
                        self.name
                    ),
                )
                .at(addr.span)
                .with_primary_label("misaligned"),
            ));
        }
        Ok(Located {
            area: addr.area,
            offset,
            bit,
            bytes,
        })
    }
}

/// The target profile's field that sizes an area (`input_bytes`, `output_bytes`, `memory_bytes`).
pub fn area_field(area: Area) -> &'static str {
    match area {
        Area::Input => "input_bytes",
        Area::Output => "output_bytes",
        Area::Memory => "memory_bytes",
    }
}

/// The prefix of an area (`%I`, `%Q`, `%M`).
pub fn area_name(area: Area) -> &'static str {
    match area {
        Area::Input => "%I",
        Area::Output => "%Q",
        Area::Memory => "%M",
    }
}

/// The address as IEC text (`%IX0.1`, `%QW3`, `%I*`).
pub fn address_text(addr: &DirectAddress) -> String {
    let size = match addr.size {
        AddressSize::Bit => "X",
        AddressSize::Byte => "B",
        AddressSize::Word => "W",
        AddressSize::DWord => "D",
        AddressSize::LWord => "L",
    };
    let path = if addr.path.is_empty() {
        "*".to_string()
    } else {
        addr.path
            .iter()
            .map(u32::to_string)
            .collect::<Vec<_>>()
            .join(".")
    };
    format!("{}{size}{path}", area_name(addr.area))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn memory(size: AddressSize, path: &[u32]) -> DirectAddress {
        DirectAddress {
            area: Area::Memory,
            size,
            path: path.to_vec(),
            span: Default::default(),
        }
    }

    /// `--profile openplc`: `%MX0.1`, `%MW0`, `%MD0` and `%ML0` each in an image of their own
    /// (`memory_per_size`), while the TM window stays one flat window in the first image, where
    /// the static library of parameter passing reads it.
    #[test]
    fn openplc_memory_is_one_image_per_size_but_for_the_tm_window() {
        let p = TargetProfile::built_in(Path::new("openplc")).expect("built in");
        assert!(p.memory_per_size);
        assert_eq!(p.area_size(Area::Memory), 4 * p.memory_bytes);
        let at = |size, path: &[u32]| p.locate(&memory(size, path), None).map(|l| l.offset).ok();
        assert_eq!(at(AddressSize::Bit, &[0, 1]), Some(0));
        assert_eq!(at(AddressSize::Word, &[0]), Some(p.memory_bytes));
        assert_eq!(at(AddressSize::DWord, &[0]), Some(2 * p.memory_bytes));
        assert_eq!(at(AddressSize::LWord, &[0]), Some(3 * p.memory_bytes));
        // the TM window (bytes 7936..8192): every size reaches the same bytes
        assert_eq!(
            at(AddressSize::DWord, &[p.tm_offset / 4]),
            Some(p.tm_offset)
        );
        assert_eq!(at(AddressSize::Word, &[p.tm_offset / 2]), Some(p.tm_offset));
        let default = TargetProfile::default();
        assert!(!default.memory_per_size);
        assert_eq!(default.images(Area::Memory), 1);
    }

    /// `memory_per_size` counts elements: with byte addressing the profile is refused.
    #[test]
    fn memory_per_size_needs_element_addressing() {
        let json = DEFAULT_PROFILE_JSON.replace(
            "\"address_unit\": \"element\"",
            "\"address_unit\": \"byte\", \"memory_per_size\": true",
        );
        assert_ne!(json, DEFAULT_PROFILE_JSON);
        let err = TargetProfile::from_json(&json).expect_err("refused");
        assert!(err.to_string().contains("memory_per_size"), "{err}");
    }
}
