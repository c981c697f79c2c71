//! A compact index of names kept in a list, found ignoring ASCII case (IEC 61131-3 names).
//!
//! Input: names with their positions in the caller's list (a POU's variables, a body's declared
//! names); the caller keeps the names and lends them back on each call (`name_at`). Output: the
//! position of a name, whatever its case. Invariants: only positions are stored (8 bytes a slot: the
//! position and 32 bits of the name's hash), so the table of a POU with 32,500 variables is 512 KiB
//! and stays in the processor's cache where a map of owned upper-cased keys (`HashMap<String, usize>`,
//! 32 bytes a bucket plus a string each) missed it on every lookup; no upper-cased copy of a name is
//! made; names equal ignoring ASCII case (`str::eq_ignore_ascii_case`) are one name.

/// Positions of names in a list, by name ignoring ASCII case (see the module documentation).
#[derive(Debug, Clone, Default, PartialEq, Eq)]
pub struct NameIndex {
    /// Open addressing with linear probing: `(position + 1, hash tag)`, `(0, _)` when free. The
    /// length is a power of two, at least twice the number of names (or zero).
    slots: Vec<(u32, u32)>,
    /// How many names are indexed.
    len: usize,
}

/// A hash of `name` with ASCII letters upper-cased: names equal ignoring ASCII case hash alike.
pub fn hash_ignoring_case(name: &str) -> u64 {
    let bytes = name.as_bytes();
    let mut h = bytes.len() as u64;
    for chunk in bytes.chunks(8) {
        h = hash_step(h, upper_word(load_word(chunk)));
    }
    hash_finish(h)
}

/// One step of [`hash_ignoring_case`]: eight upper-cased bytes into the state.
#[inline]
fn hash_step(h: u64, word: u64) -> u64 {
    const K: u64 = 0x517c_c1b7_2722_0a95;
    (h.rotate_left(5) ^ word).wrapping_mul(K)
}

/// The end of [`hash_ignoring_case`]: the high bits spread down (the slot comes from the low bits).
#[inline]
fn hash_finish(h: u64) -> u64 {
    h ^ (h >> 29) ^ (h >> 41)
}

/// Whether `a` and `b` are equal ignoring ASCII case ([`str::eq_ignore_ascii_case`]); `b_upper`:
/// `b`'s bytes as one upper-cased word ([`upper_word`] of [`load_word`]) when it has at most eight.
#[inline]
fn eq_ignoring_case(a: &str, b: &str, b_upper: Option<u64>) -> bool {
    a.len() == b.len()
        && match b_upper {
            Some(word) => upper_word(load_word(a.as_bytes())) == word,
            None => a.eq_ignore_ascii_case(b),
        }
}

/// Up to eight bytes as a little-endian word, zero-padded: read as one or two overlapping words, or
/// three bytes (a name's few bytes without a loop or a call to copy them).
#[inline]
fn load_word(chunk: &[u8]) -> u64 {
    let n = chunk.len();
    let u32_at = |at: usize| {
        u64::from(u32::from_le_bytes([
            chunk[at],
            chunk[at + 1],
            chunk[at + 2],
            chunk[at + 3],
        ]))
    };
    match n {
        0 => 0,
        1..=3 => {
            u64::from(chunk[0])
                | u64::from(chunk[n / 2]) << (8 * (n / 2))
                | u64::from(chunk[n - 1]) << (8 * (n - 1))
        }
        4..=7 => u32_at(0) | u32_at(n - 4) << (8 * (n - 4)),
        _ => u32_at(0) | u32_at(4) << 32,
    }
}

/// `word` with each byte that is an ASCII lower-case letter upper-cased, all eight at once: a byte
/// is one when its low seven bits are `a`..=`z` and its high bit is clear (no carry crosses a byte:
/// seven bits plus at most 0x1f stay below 0x100).
fn upper_word(word: u64) -> u64 {
    const ONES: u64 = 0x0101_0101_0101_0101;
    let low = word & (ONES * 0x7f);
    let from_a = low + ONES * (0x80 - u64::from(b'a'));
    let past_z = low + ONES * (0x80 - u64::from(b'z') - 1);
    let lower = from_a & !past_z & !word & (ONES * 0x80);
    word ^ (lower >> 2)
}

impl NameIndex {
    /// An empty index with room for `n` names before it grows.
    pub fn with_capacity(n: usize) -> Self {
        let mut index = NameIndex::default();
        if n > 0 {
            index.slots = vec![(0, 0); (n * 2).next_power_of_two()];
        }
        index
    }

    /// How many names are indexed.
    pub fn len(&self) -> usize {
        self.len
    }

    /// Whether no name is indexed.
    pub fn is_empty(&self) -> bool {
        self.len == 0
    }

    /// The position of `name` (any case); `name_at(p)` is the name at position `p` of the caller's
    /// list.
    pub fn find<'n>(&self, name: &str, name_at: impl Fn(usize) -> &'n str) -> Option<usize> {
        if self.slots.is_empty() {
            return None;
        }
        self.probe(name, &name_at).ok().map(|(_, p)| p)
    }

    /// Walks the slots from `name`'s hash: `Ok((slot, position))` where the name (any case) is indexed,
    /// `Err((slot, tag))` the free slot where it would go, with its hash tag. The table is not empty and
    /// never full (at most half its slots are used), so the walk ends.
    fn probe<'n>(
        &self,
        name: &str,
        name_at: &impl Fn(usize) -> &'n str,
    ) -> Result<(usize, usize), (usize, u32)> {
        // most names have at most eight bytes: hashed and compared as one upper-cased word (the hash
        // is `hash_ignoring_case`'s)
        let (h, upper) = match name.len() {
            n @ 1..=8 => {
                let word = upper_word(load_word(name.as_bytes()));
                (hash_finish(hash_step(n as u64, word)), Some(word))
            }
            _ => (hash_ignoring_case(name), None),
        };
        let tag = (h >> 32) as u32;
        let mask = self.slots.len() - 1;
        let mut k = h as usize & mask;
        loop {
            let (slot, slot_tag) = self.slots[k];
            if slot == 0 {
                return Err((k, tag));
            }
            let p = slot as usize - 1;
            if slot_tag == tag && eq_ignoring_case(name_at(p), name, upper) {
                return Ok((k, p));
            }
            k = (k + 1) & mask;
        }
    }

    /// Indexes `name` at position `pos`. When the name (any case) is indexed already, its position is
    /// replaced by `pos` and the old one returned. A position past `u32::MAX - 1` is not indexed
    /// (`None`, and [`NameIndex::len`] does not count it: callers that compare it with their list's
    /// length then search the list).
    pub fn insert<'n>(
        &mut self,
        name: &str,
        pos: usize,
        name_at: impl Fn(usize) -> &'n str,
    ) -> Option<usize> {
        let stored = u32::try_from(pos).ok().and_then(|p| p.checked_add(1))?;
        if (self.len + 1) * 2 > self.slots.len() {
            self.grow(&name_at);
        }
        match self.probe(name, &name_at) {
            Err((k, tag)) => {
                self.slots[k] = (stored, tag);
                self.len += 1;
                None
            }
            Ok((k, p)) => {
                self.slots[k].0 = stored;
                Some(p)
            }
        }
    }

    /// Doubles the table (at least 16 slots) and places every name again.
    fn grow<'n>(&mut self, name_at: &impl Fn(usize) -> &'n str) {
        let size = (self.slots.len() * 2).max(16);
        let old = std::mem::replace(&mut self.slots, vec![(0, 0); size]);
        let mask = size - 1;
        for (slot, tag) in old.into_iter().filter(|s| s.0 != 0) {
            let mut k = hash_ignoring_case(name_at(slot as usize - 1)) as usize & mask;
            while self.slots[k].0 != 0 {
                k = (k + 1) & mask;
            }
            self.slots[k] = (slot, tag);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::collections::HashMap;

    #[test]
    fn finds_names_ignoring_ascii_case_like_a_map_of_upper_cased_keys() {
        let names: Vec<String> = (0..5000)
            .map(|i| match i % 4 {
                0 => format!("a{i}"),
                1 => format!("Motor_{i}_Speed"),
                2 => format!("a_very_long_variable_name_past_eight_bytes_{i}"),
                _ => format!("Grün{i}"),
            })
            .collect();
        let mut index = NameIndex::default();
        let mut map = HashMap::new();
        for (i, n) in names.iter().enumerate() {
            assert_eq!(index.insert(n, i, |p| names[p].as_str()), None);
            map.insert(n.to_ascii_uppercase(), i);
        }
        assert_eq!(index.len(), names.len());
        for n in &names {
            for probe in [n.clone(), n.to_ascii_uppercase(), n.to_ascii_lowercase()] {
                assert_eq!(
                    index.find(&probe, |p| names[p].as_str()),
                    map.get(&probe.to_ascii_uppercase()).copied(),
                    "{probe}"
                );
            }
        }
        for absent in ["", "a", "a5000", "b1", "grün3", "GRüN3x"] {
            assert_eq!(
                index.find(absent, |p| names[p].as_str()),
                map.get(&absent.to_ascii_uppercase()).copied(),
                "{absent}"
            );
        }
        // `ü` is not ASCII: only its ASCII letters fold
        assert_eq!(index.find("GRüN3", |p| names[p].as_str()), Some(3));
        assert_eq!(index.find("GRÜN3", |p| names[p].as_str()), None);
    }

    #[test]
    fn a_name_indexed_again_takes_the_new_position() {
        let names = ["x", "Y", "X"];
        let mut index = NameIndex::with_capacity(2);
        assert_eq!(index.insert(names[0], 0, |p| names[p]), None);
        assert_eq!(index.insert(names[1], 1, |p| names[p]), None);
        assert_eq!(index.insert(names[2], 2, |p| names[p]), Some(0));
        assert_eq!(index.len(), 2);
        assert_eq!(index.find("x", |p| names[p]), Some(2));
        assert_eq!(index.find("y", |p| names[p]), Some(1));
        assert!(NameIndex::default().find("x", |p| names[p]).is_none());
    }

    /// Eight bytes upper-cased at once are the bytes upper-cased one by one, whatever the byte in
    /// whatever position (non-ASCII bytes stay); the comparison built on it is
    /// `str::eq_ignore_ascii_case`.
    #[test]
    fn words_upper_case_as_their_bytes_do() {
        for b in 0..=255u8 {
            for pos in 0..8 {
                let mut bytes = *b"aZ_9~{`@";
                bytes[pos] = b;
                let one_by_one = bytes.map(|c| c.to_ascii_uppercase());
                assert_eq!(
                    upper_word(u64::from_le_bytes(bytes)),
                    u64::from_le_bytes(one_by_one),
                    "{b:#x} at {pos}"
                );
                // the first `pos + 1` bytes (1 to 8, the changed one last), zero-padded
                assert_eq!(load_word(&bytes[..=pos]), {
                    let mut padded = [0u8; 8];
                    padded[..=pos].copy_from_slice(&bytes[..=pos]);
                    u64::from_le_bytes(padded)
                });
            }
        }
        assert_eq!(load_word(&[]), 0);
        let names = [
            "",
            "a",
            "A",
            "ab",
            "aB",
            "abc",
            "motor_speed",
            "MOTOR_SPEED",
            "Motor_Speeds",
            "grün",
            "GRüN",
            "GRÜN",
            "a_name_past_sixteen_bytes",
            "A_NAME_PAST_SIXTEEN_BYTES",
            "x{",
            "X[",
        ];
        for a in names {
            for b in names {
                let upper = (b.len() <= 8).then(|| upper_word(load_word(b.as_bytes())));
                for b_upper in [upper, None] {
                    assert_eq!(
                        eq_ignoring_case(a, b, b_upper),
                        a.eq_ignore_ascii_case(b),
                        "{a} {b}"
                    );
                }
            }
        }
    }

    #[test]
    fn names_equal_ignoring_case_hash_alike() {
        assert_eq!(
            hash_ignoring_case("Motor_Speed_Setpoint"),
            hash_ignoring_case("MOTOR_speed_setPOINT")
        );
        assert_ne!(hash_ignoring_case("A"), hash_ignoring_case("A\0"));
        // the probe's one-word hash of a short name is the same hash
        let names = [
            "a", "Ab", "abc", "abcd", "ABCDE", "abcdef", "AbCdEfG", "abcdefgh",
        ];
        for n in names {
            let word = upper_word(load_word(n.as_bytes()));
            assert_eq!(
                hash_finish(hash_step(n.len() as u64, word)),
                hash_ignoring_case(n)
            );
        }
    }
}
