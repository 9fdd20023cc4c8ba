//! The order of generation (SPEC 3.1): midpoint displacement on a torus of side `n`
//! (a power of two).
//!
//! The four corners are one point of the torus; it is set with the centre. Then, with
//! `s` the side of the smallest squares of known points (starting at `n`), a diamond
//! step sets the points midway along their sides (`i s/2, j s/2` with `i + j` odd; the
//! vertices, `s/2` away along the axes, are read through the torus), and a square step
//! at half the side sets the centres of the new smaller squares; until every pixel is
//! set. Each point is decided from four known vertices, the offsets from which to it
//! are those of its `Step`.

/// Where a point sits in the generation.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Kind {
    /// The corner and the centre together (SPEC 3.3 step 1).
    First,
    /// The first diamond step: the pairwise rule (step 2).
    FirstDiamond,
    /// A square step: vertices at `(+-h, +-h)`.
    Square,
    /// A diamond step: vertices at `(0, +-h)` and `(+-h, 0)`.
    Diamond,
}

/// One point to decide: its position, how, and the vertices' offsets from it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Step {
    pub x: usize,
    pub y: usize,
    pub kind: Kind,
    /// Half the side of the square (or diamond) it is the centre of.
    pub h: usize,
}

impl Step {
    /// Offsets from the point to its four vertices, in order around it (consecutive
    /// ones share a side): bottom-left first as in the paper, then anticlockwise on
    /// screen.
    pub fn vertices(&self) -> [(isize, isize); 4] {
        let h = self.h as isize;
        match self.kind {
            Kind::Square | Kind::First => [(-h, h), (h, h), (h, -h), (-h, -h)],
            Kind::Diamond | Kind::FirstDiamond => [(0, h), (h, 0), (0, -h), (-h, 0)],
        }
    }
}

/// Every point of an `n x n` torus in generation order (the corner and the centre are
/// the first step, reported once at the centre).
pub fn order(n: usize) -> Vec<Step> {
    debug_assert!(n.is_power_of_two() && n >= 2);
    let mut steps = vec![Step { x: n / 2, y: n / 2, kind: Kind::First, h: n / 2 }];
    let mut s = n;
    while s >= 2 {
        let h = s / 2;
        // Diamond: midpoints of the sides of the s-squares.
        let kind = if s == n { Kind::FirstDiamond } else { Kind::Diamond };
        for j in 0..n / h {
            for i in 0..n / h {
                if (i + j) % 2 == 1 {
                    steps.push(Step { x: i * h, y: j * h, kind, h });
                }
            }
        }
        // Square: centres of the h-squares, once there are any.
        if h >= 2 {
            let q = h / 2;
            for j in 0..n / h {
                for i in 0..n / h {
                    steps.push(Step { x: i * h + q, y: j * h + q, kind: Kind::Square, h: q });
                }
            }
        }
        s = h;
    }
    steps
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_pixel_once_and_every_vertex_known_before() {
        for n in [2usize, 4, 8, 32] {
            let steps = order(n);
            let mut set = vec![false; n * n];
            set[0] = true; // the corner, set with the first step
            assert_eq!(steps.len() + 1, n * n, "n = {n}");
            for st in &steps {
                if st.kind != Kind::First {
                    for (dx, dy) in st.vertices() {
                        let (vx, vy) =
                            ((st.x as isize + dx).rem_euclid(n as isize), (st.y as isize + dy).rem_euclid(n as isize));
                        assert!(set[vy as usize * n + vx as usize], "n {n}: vertex of {st:?} not set");
                    }
                }
                assert!(!set[st.y * n + st.x], "n {n}: {st:?} set twice");
                set[st.y * n + st.x] = true;
            }
            assert!(set.iter().all(|&b| b));
        }
    }
}
