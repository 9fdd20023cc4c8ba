//! Co-occurrence statistics of a grey exemplar (SPEC 3.2, 3.3).
//!
//! `C(i, j; dx, dy)` counts the exemplar positions `(x, y)` with `V(x, y) = i` and
//! `V(x + dx, y + dy) = j`, both inside the exemplar (not toroidal). Tables are built
//! on first use, one per offset (256 x 256 counts).
//!
//! The multi-distance matrix asks, for one side `(P_a, P_b)` of a square and its apex
//! (the centre), which apex values `k` occur in the exemplar with `(V_a, V_b)` at the
//! side: `E_side(k) > 0`. `Triples` holds, for one side's offsets, the sorted distinct
//! `(V_a, V_b, k)` found in the exemplar, so that the set of `k` for a pair is a binary
//! search away (memory: at most one `u32` per exemplar pixel and side).

/// A grey image, row major.
#[derive(Clone, Debug, PartialEq)]
pub struct Grey {
    pub width: usize,
    pub height: usize,
    pub data: Vec<u8>,
}

impl Grey {
    /// The value at `(x + dx, y + dy)` if inside.
    #[inline]
    fn at(&self, x: usize, y: usize, dx: isize, dy: isize) -> Option<u8> {
        let (xx, yy) = (x as isize + dx, y as isize + dy);
        if xx < 0 || yy < 0 || xx >= self.width as isize || yy >= self.height as isize {
            return None;
        }
        Some(self.data[yy as usize * self.width + xx as usize])
    }

    /// Pixel count per grey level.
    pub fn histogram(&self) -> [u32; 256] {
        let mut h = [0u32; 256];
        for &v in &self.data {
            h[v as usize] += 1;
        }
        h
    }
}

/// Pairwise tables, built per offset on first use (a few dozen offsets at most: a
/// list serves).
pub struct Pairs<'a> {
    img: &'a Grey,
    tables: Vec<((isize, isize), Vec<u32>)>,
}

impl<'a> Pairs<'a> {
    pub fn new(img: &'a Grey) -> Self {
        Pairs { img, tables: Vec::new() }
    }

    /// The table of `C(i, j; dx, dy)`, indexed `i * 256 + j`.
    pub fn table(&mut self, dx: isize, dy: isize) -> &[u32] {
        let img = self.img;
        let i = match self.tables.iter().position(|(o, _)| *o == (dx, dy)) {
            Some(i) => i,
            None => {
                let mut t = vec![0u32; 256 * 256];
                for y in 0..img.height {
                    for x in 0..img.width {
                        if let Some(j) = img.at(x, y, dx, dy) {
                            t[img.data[y * img.width + x] as usize * 256 + j as usize] += 1;
                        }
                    }
                }
                self.tables.push(((dx, dy), t));
                self.tables.len() - 1
            }
        };
        &self.tables[i].1
    }
}

/// The distinct `(V_a, V_b, k)` of one side: vertices at offsets `a` and `b` from the
/// apex. A bit set over all 2^24 triples (2 MB): building is one pass over the image
/// (sorting the triples was a fifth of E-TFMCM's time), and the apex values of a pair of
/// vertex values are four adjacent words.
pub struct Triples {
    bits: Vec<u64>,
    /// The words with a bit set, so that `rebuild` clears only them (a fresh 2 MB set per
    /// side and scale was a third of generation's time, in page faults and clearing).
    set: Vec<u32>,
}

/// Words of the bit set: 2^24 triples, 64 per word.
const WORDS: usize = 1 << 18;

impl Triples {
    pub fn build(img: &Grey, a: (isize, isize), b: (isize, isize)) -> Self {
        let mut t = Triples { bits: vec![0u64; WORDS], set: Vec::new() };
        t.rebuild(img, a, b);
        t
    }

    /// The triples of another side (vertex offsets `a` and `b`), reusing the set.
    pub fn rebuild(&mut self, img: &Grey, a: (isize, isize), b: (isize, isize)) {
        for &w in &self.set {
            self.bits[w as usize] = 0;
        }
        self.set.clear();
        // The apexes whose two vertices both lie in the image, as ranges (no test per pixel).
        let (w, h) = (img.width as isize, img.height as isize);
        let x0 = 0.max(-a.0).max(-b.0);
        let x1 = w.min(w - a.0).min(w - b.0);
        let y0 = 0.max(-a.1).max(-b.1);
        let y1 = h.min(h - a.1).min(h - b.1);
        let (da, db) = (a.1 * w + a.0, b.1 * w + b.0);
        for y in y0..y1 {
            for apex in (y * w + x0)..(y * w + x1).max(y * w + x0) {
                let va = img.data[(apex + da) as usize] as usize;
                let vb = img.data[(apex + db) as usize] as usize;
                let key = va << 16 | vb << 8 | img.data[apex as usize] as usize;
                let word = &mut self.bits[key >> 6];
                if *word == 0 {
                    self.set.push((key >> 6) as u32);
                }
                *word |= 1 << (key & 63);
            }
        }
    }

    /// The apex values seen with `(va, vb)` at this side, as a 256-bit set (bit `k` of
    /// word `k / 64`).
    #[inline]
    pub fn apexes(&self, va: u8, vb: u8) -> Levels {
        let first = ((va as usize) << 16 | (vb as usize) << 8) >> 6;
        Levels(self.bits[first..first + 4].try_into().unwrap())
    }
}

/// A set of grey levels: bit `k % 64` of word `k / 64`.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Levels(pub [u64; 4]);

impl Levels {
    /// The levels in `self` and in `other`.
    #[inline]
    pub fn and(self, other: Levels) -> Levels {
        Levels([0, 1, 2, 3].map(|w| self.0[w] & other.0[w]))
    }

    /// The levels in `self` or in `other`.
    #[inline]
    pub fn or(self, other: Levels) -> Levels {
        Levels([0, 1, 2, 3].map(|w| self.0[w] | other.0[w]))
    }

    pub fn is_empty(self) -> bool {
        self.0 == [0; 4]
    }

    pub fn len(self) -> usize {
        self.0.iter().map(|w| w.count_ones() as usize).sum()
    }

    /// The levels, ascending.
    pub fn iter(self) -> impl Iterator<Item = u8> {
        (0..4).flat_map(move |w| {
            let mut word = self.0[w];
            std::iter::from_fn(move || {
                (word != 0).then(|| {
                    let bit = word.trailing_zeros() as usize;
                    word &= word - 1;
                    (w * 64 + bit) as u8
                })
            })
        })
    }

    /// The `i`-th level, ascending (`i < len`).
    pub fn nth(self, mut i: usize) -> u8 {
        for (w, &word) in self.0.iter().enumerate() {
            let n = word.count_ones() as usize;
            if i < n {
                let mut word = word;
                for _ in 0..i {
                    word &= word - 1;
                }
                return (w * 64 + word.trailing_zeros() as usize) as u8;
            }
            i -= n;
        }
        unreachable!("level index out of range")
    }

    /// The levels in at least 4, 3, 2 and 1 of `sets` (four sets): a count per level by
    /// bit logic, instead of counting level by level.
    pub fn at_least(sets: [Levels; 4]) -> [Levels; 4] {
        let [a, b, c, d] = sets;
        let (ab, cd) = (a.and(b), c.and(d));
        let (a_or_b, c_or_d) = (a.or(b), c.or(d));
        let four = ab.and(cd);
        let three = ab.and(c_or_d).or(cd.and(a_or_b));
        let two = ab.or(cd).or(a_or_b.and(c_or_d));
        let one = a_or_b.or(c_or_d);
        [four, three, two, one]
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn counts_pairs_inside_the_image_only() {
        // 0 1
        // 2 3
        let img = Grey { width: 2, height: 2, data: vec![0, 1, 2, 3] };
        let mut p = Pairs::new(&img);
        let t = p.table(1, 0);
        assert_eq!((t[1], t[2 * 256 + 3], t[256]), (1, 1, 0));
        assert_eq!(t.iter().sum::<u32>(), 2);
        let t = p.table(-1, 1);
        assert_eq!((t[256 + 2], t.iter().sum::<u32>()), (1, 1));
    }

    #[test]
    fn triples_list_the_apex_values_of_a_side() {
        // A 3x3 with apex at the centre, vertices left and up.
        let img = Grey { width: 3, height: 3, data: vec![5, 6, 7, 8, 9, 10, 11, 12, 13] };
        let t = Triples::build(&img, (-1, 0), (0, -1));
        assert_eq!(t.apexes(8, 6).iter().collect::<Vec<_>>(), vec![9]);
        assert!(t.apexes(6, 8).is_empty());
    }

    #[test]
    fn levels_count_membership_by_bit_logic() {
        let set = |ks: &[u8]| {
            let mut l = Levels::default();
            ks.iter().for_each(|&k| l.0[k as usize / 64] |= 1 << (k % 64));
            l
        };
        let sets = [set(&[1, 70, 200]), set(&[1, 70]), set(&[1, 130]), set(&[1, 200, 255])];
        let [four, three, two, one] = Levels::at_least(sets);
        assert_eq!(four.iter().collect::<Vec<_>>(), vec![1]);
        assert_eq!(three.iter().collect::<Vec<_>>(), vec![1]);
        assert_eq!(two.iter().collect::<Vec<_>>(), vec![1, 70, 200]);
        assert_eq!(one.iter().collect::<Vec<_>>(), vec![1, 70, 130, 200, 255]);
        assert_eq!((one.len(), one.nth(0), one.nth(3), one.nth(4)), (5, 1, 200, 255));
    }
}
