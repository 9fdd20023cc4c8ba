//! Neighbourhood shapes (Wei-Levoy): the causal L-shape of already synthesized pixels at
//! the current level (rows above, and the pixels to the left on the current row) and a
//! full 3x3 block at the parent (coarser) level; a full square for correction passes.

#[derive(Clone, Debug)]
pub struct Shape {
    /// Offsets at the pixel's own level.
    pub own: Vec<(isize, isize)>,
    /// Offsets at the parent level, around (x / 2, y / 2).
    pub parent: Vec<(isize, isize)>,
    /// Half size: own offsets lie within `[-half, half]`.
    pub half: isize,
}

impl Shape {
    /// The causal neighbourhood of a `(2 half + 1)` square.
    pub fn causal(half: isize) -> Shape {
        let mut own = Vec::new();
        for dy in -half..=0 {
            for dx in -half..=half {
                if dy < 0 || dx < 0 {
                    own.push((dx, dy));
                }
            }
        }
        Shape { own, parent: parent_block(), half }
    }

    /// The whole square but the centre (for passes where every pixel is already set).
    pub fn full(half: isize) -> Shape {
        let mut own = Vec::new();
        for dy in -half..=half {
            for dx in -half..=half {
                if (dx, dy) != (0, 0) {
                    own.push((dx, dy));
                }
            }
        }
        Shape { own, parent: parent_block(), half }
    }

    /// The shape without the own offsets `own` refuses and the parent offsets `parent`
    /// refuses (a neighbourhood cut off by the output's border), or `None` when both keep
    /// every offset.
    pub fn clipped(&self, own: impl Fn(isize, isize) -> bool, parent: impl Fn(isize, isize) -> bool) -> Option<Shape> {
        let keep = |v: &[(isize, isize)], f: &dyn Fn(isize, isize) -> bool| -> Vec<(isize, isize)> {
            v.iter().copied().filter(|&(dx, dy)| f(dx, dy)).collect()
        };
        let (o, p) = (keep(&self.own, &own), keep(&self.parent, &parent));
        (o.len() < self.own.len() || p.len() < self.parent.len()).then_some(Shape {
            own: o,
            parent: p,
            half: self.half,
        })
    }

    /// Feature length (three channels per pixel) with or without the parent level.
    pub fn dim(&self, with_parent: bool) -> usize {
        3 * (self.own.len() + if with_parent { self.parent.len() } else { 0 })
    }
}

fn parent_block() -> Vec<(isize, isize)> {
    let mut v = Vec::new();
    for dy in -1..=1 {
        for dx in -1..=1 {
            v.push((dx, dy));
        }
    }
    v
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn causal_5x5_has_12_pixels_all_before_the_centre() {
        let s = Shape::causal(2);
        assert_eq!(s.own.len(), 12);
        assert!(s.own.iter().all(|&(dx, dy)| dy < 0 || (dy == 0 && dx < 0)));
        assert_eq!(s.dim(true), 3 * 21);
        assert_eq!(Shape::full(2).own.len(), 24);
    }
}
