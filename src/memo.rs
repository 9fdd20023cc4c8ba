//! Results of pure functions of two point sets, remembered by the sets' digests.
//!
//! Autocomplete reads the whole drawing again after every stroke; most of what it
//! measures between two strokes (their Fréchet distance, the gap between them) was
//! measured the stroke before. A `PairMemo` keeps those figures per thread (each worker
//! keeps its own) and is emptied when it holds its capacity, so it never grows without
//! bound. A key is a pair of digests, either way round: only for functions symmetric
//! in their two arguments.

use std::cell::RefCell;
use std::collections::HashMap;
use std::hash::{BuildHasherDefault, Hasher};

/// A digest of a point set and of `extra` words (a stroke's width): the standard
/// library's hasher, whose keys are fixed within a build, over the coordinates' bits.
/// (FNV-1a over whole 64-bit words, used before, kept a sign bit in the top bit alone:
/// a stroke and its mirror image, such as a cross's two bars, had one digest.)
pub(crate) fn digest(points: impl IntoIterator<Item = (f64, f64)>, extra: &[f64]) -> u64 {
    let mut h = std::collections::hash_map::DefaultHasher::new();
    for (x, y) in points {
        h.write_u64(x.to_bits());
        h.write_u64(y.to_bits());
    }
    extra.iter().for_each(|e| h.write_u64(e.to_bits()));
    h.finish()
}

/// The memo's hasher, and that of maps keyed by a few small integers (a class and a
/// cell): a multiply and a rotation per word, as rustc's FxHasher does. Its keys are
/// digests already, or cells of a drawing, not chosen by an adversary; SipHash, the
/// standard map's, was a tenth of a warm autocomplete call.
#[derive(Default)]
pub(crate) struct Spread(u64);

/// A hash map hashed by `Spread`.
pub(crate) type SpreadMap<K, V> = HashMap<K, V, BuildHasherDefault<Spread>>;

impl Hasher for Spread {
    fn write(&mut self, bytes: &[u8]) {
        bytes.iter().for_each(|&b| self.write_u64(u64::from(b)));
    }

    fn write_u32(&mut self, word: u32) {
        self.write_u64(u64::from(word));
    }

    fn write_usize(&mut self, word: usize) {
        self.write_u64(word as u64);
    }

    fn write_u64(&mut self, word: u64) {
        self.0 = (self.0.rotate_left(5) ^ word).wrapping_mul(0x51_7c_c1_b7_27_22_0a_95);
    }

    fn finish(&self) -> u64 {
        self.0
    }
}

/// Figures by pairs of digests, up to a capacity.
pub(crate) struct PairMemo {
    map: RefCell<SpreadMap<(u64, u64), f64>>,
    capacity: usize,
}

impl PairMemo {
    pub(crate) fn new(capacity: usize) -> PairMemo {
        PairMemo { map: RefCell::default(), capacity }
    }

    fn key(a: u64, b: u64) -> (u64, u64) {
        (a.min(b), a.max(b))
    }

    /// The figure for `a` and `b`, if remembered.
    pub(crate) fn get(&self, a: u64, b: u64) -> Option<f64> {
        self.map.borrow().get(&Self::key(a, b)).copied()
    }

    /// Remembers `value` for `a` and `b` (emptying the memo first when full).
    pub(crate) fn insert(&self, a: u64, b: u64, value: f64) {
        let mut m = self.map.borrow_mut();
        if m.len() >= self.capacity {
            m.clear();
        }
        m.insert(Self::key(a, b), value);
    }

    /// The figure for `a` and `b`, measured by `measure` unless remembered.
    pub(crate) fn get_or(&self, a: u64, b: u64, measure: impl FnOnce() -> f64) -> f64 {
        if let Some(v) = self.get(a, b) {
            return v;
        }
        let v = measure();
        self.insert(a, b, v);
        v
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_pair_is_remembered_either_way_round_and_the_memo_empties_when_full() {
        let m = PairMemo::new(2);
        let (a, b, c) = (digest([(0.0, 1.0)], &[]), digest([(1.0, 0.0)], &[]), digest([(0.0, 1.0)], &[2.0]));
        assert!(a != b && a != c, "a point and its mirror image, or another width, have digests of their own");
        assert_eq!(m.get_or(a, b, || 3.0), 3.0);
        assert_eq!(m.get_or(b, a, || 4.0), 3.0);
        m.insert(a, c, 5.0);
        assert_eq!(m.get(c, a), Some(5.0));
        // (Full at two: the third empties it.)
        m.insert(b, c, 6.0);
        assert_eq!((m.get(a, b), m.get(b, c)), (None, Some(6.0)));
    }
}
