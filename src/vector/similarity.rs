//! Similarity transforms between copies of a stroke: `z -> a z + b` on the plane read
//! as complex numbers (`a`: the turn and the scale; `b`: the shift). A petal turned
//! round a centre, a leaf further along a curved stem, a hatching line the next along a
//! turning contour: each copy is the one before under one such step.
//!
//! Shapes are compared here up to rotation and scale (the seed paper compares them up
//! to translation only): each stroke is resampled to a fixed count of points by arc
//! length, and the least-squares similarity between two such samplings (either way
//! round) is the relation between the copies, its residual how far they differ.

use super::frechet::{closed_loop, resample_count};
use super::stroke::Stroke;
use kurbo::{Point, Vec2};

/// Points per stroke for a similarity fit.
pub const SAMPLES: usize = 24;

/// The complex product `a z`.
pub fn mul(a: Vec2, z: Vec2) -> Vec2 {
    Vec2::new(a.x * z.x - a.y * z.y, a.x * z.y + a.y * z.x)
}

/// `z -> a z + b`, with `a` a complex number (`x` real, `y` imaginary).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Similarity {
    pub a: Vec2,
    pub b: Vec2,
}

impl Similarity {
    pub const IDENTITY: Similarity = Similarity { a: Vec2::new(1.0, 0.0), b: Vec2::ZERO };

    pub fn apply(&self, p: Point) -> Point {
        (mul(self.a, p.to_vec2()) + self.b).to_point()
    }

    /// `self` after `other`: `z -> self(other(z))`.
    pub fn then_after(&self, other: &Similarity) -> Similarity {
        Similarity { a: mul(self.a, other.a), b: mul(self.a, other.b) + self.b }
    }

    /// The inverse step (`None` for a degenerate `a = 0`).
    pub fn inverse(&self) -> Option<Similarity> {
        let d = self.a.hypot2();
        (d > 1e-24).then(|| {
            let inv = Vec2::new(self.a.x / d, -self.a.y / d);
            Similarity { a: inv, b: -mul(inv, self.b) }
        })
    }

    /// The step `k` times (`k` < 0: the inverse's); `None` if not invertible.
    pub fn power(&self, k: i64) -> Option<Similarity> {
        let base = if k < 0 { self.inverse()? } else { *self };
        Some((0..k.unsigned_abs()).fold(Similarity::IDENTITY, |t, _| base.then_after(&t)))
    }

    /// The scale factor `|a|` and the turn `arg a` (radians, in (-pi, pi]).
    pub fn scale(&self) -> f64 {
        self.a.hypot()
    }

    pub fn turn(&self) -> f64 {
        self.a.y.atan2(self.a.x)
    }

    /// The point the step keeps where it is, `b / (1 - a)` (`None` for a translation).
    pub fn fixed_point(&self) -> Option<Point> {
        let one_minus = Vec2::new(1.0 - self.a.x, -self.a.y);
        let d = one_minus.hypot2();
        (d > 1e-12).then(|| mul(Vec2::new(one_minus.x / d, -one_minus.y / d), self.b).to_point())
    }

    /// A stroke carried by the step: its points, and its width scaled.
    pub fn carry(&self, s: &Stroke) -> Stroke {
        let mut out = s.clone();
        out.points = s.points.iter().map(|&[x, y]| self.apply(Point::new(x, y))).map(|p| [p.x, p.y]).collect();
        out.width *= self.scale();
        out
    }

    /// The least-squares similarity carrying `from` onto `to` (paired points) and its
    /// rms residual.
    pub fn fit(from: &[Point], to: &[Point]) -> (Similarity, f64) {
        let n = from.len() as f64;
        let zc = from.iter().fold(Vec2::ZERO, |s, p| s + p.to_vec2()) / n;
        let wc = to.iter().fold(Vec2::ZERO, |s, p| s + p.to_vec2()) / n;
        let (mut num, mut den) = (Vec2::ZERO, 0.0);
        for (z, w) in from.iter().zip(to) {
            let (z, w) = (z.to_vec2() - zc, w.to_vec2() - wc);
            // conj(z) w
            num += Vec2::new(z.x * w.x + z.y * w.y, z.x * w.y - z.y * w.x);
            den += z.hypot2();
        }
        let a = if den > 0.0 { num / den } else { Vec2::new(1.0, 0.0) };
        let t = Similarity { a, b: wc - mul(a, zc) };
        let rms = (from.iter().zip(to).map(|(z, w)| t.apply(*z).distance_squared(*w)).sum::<f64>() / n).sqrt();
        (t, rms)
    }
}

/// A stroke's path at `SAMPLES` points.
pub fn samples(s: &Stroke) -> Vec<Point> {
    let pts: Vec<Point> = s.points.iter().map(|&[x, y]| Point::new(x, y)).collect();
    resample_count(&pts, SAMPLES)
}

/// The mean of sampled points (a copy's centre for similarity steps).
pub fn centroid(s: &[Point]) -> Point {
    (s.iter().fold(Vec2::ZERO, |m, p| m + p.to_vec2()) / s.len().max(1) as f64).to_point()
}

/// The similarities carrying `from` onto `to` (either way round along `to`), with their
/// residual as a share of `size`, when they are the same shape: the residual at most
/// `shape` of `size` and the scale within `1 / max_scale ..= max_scale`. A shape that
/// looks the same either way round (a line, an ellipse) fits more than one way: the
/// fits as good as the best (within half again its residual) come first, the smallest
/// turn first (a line's next copy is not the line turned half round), then any other
/// that passes; where the copies' places say which, the caller picks. The flag says
/// whether `to` was read backwards.
///
/// Two closed loops (petals, leaves, rings) are compared from every start along `to`:
/// a hand starts each copy of a loop where it happens to put the pen, and samplings
/// begun at different places pair the wrong points (a petal begun a tenth of the way
/// round read as no copy at all). The residual of each start is the cyclic correlation
/// of the centred loops: `|w|^2 - |sum conj(z) w_k|^2 / |z|^2`. (A loop symmetric under
/// a half turn fits turned either way: both are given.)
pub fn relations(from: &[Point], to: &[Point], size: f64, shape: f64, max_scale: f64) -> Vec<(Similarity, f64, bool)> {
    if from.len() != to.len() || from.len() < 2 || size <= 0.0 {
        return Vec::new();
    }
    let reversed: Vec<Point> = to.iter().rev().copied().collect();
    let mut fits = vec![(Similarity::fit(from, to), false), (Similarity::fit(from, &reversed), true)];
    if closed_loop(from) && closed_loop(to) {
        let m = from.len() - 1;
        let centred = |s: &[Point]| -> Vec<Vec2> {
            let c = s[..m].iter().fold(Vec2::ZERO, |a, p| a + p.to_vec2()) / m as f64;
            s[..m].iter().map(|p| p.to_vec2() - c).collect()
        };
        let z = centred(from);
        let den: f64 = z.iter().map(|v| v.hypot2()).sum();
        for (back, path) in [(false, to), (true, &reversed[..])] {
            let w = centred(path);
            let ww: f64 = w.iter().map(|v| v.hypot2()).sum();
            let residual: Vec<f64> = (0..m)
                .map(|k| {
                    let num = z.iter().enumerate().fold(Vec2::ZERO, |a, (i, zi)| {
                        let wi = w[(i + k) % m];
                        a + Vec2::new(zi.x * wi.x + zi.y * wi.y, zi.x * wi.y - zi.y * wi.x)
                    });
                    ww - num.hypot2() / den.max(1e-300)
                })
                .collect();
            // Every start that fits better than its neighbours (a loop symmetric under a
            // half turn, an ellipse, fits begun at either end: the turn rule below picks
            // among those as good as the best), each moved between samples to the vertex
            // of the parabola through its neighbours (a start half a sample off turns the
            // fit by a few degrees, and makes the other end of an ellipse fit worse).
            for k in 0..m {
                let (before, here, after) = (residual[(k + m - 1) % m], residual[k], residual[(k + 1) % m]);
                // (Begun where `to` begins: the plain fits above, unmoved.)
                if k == 0 || here > before || here > after {
                    continue;
                }
                let curve = before - 2.0 * here + after;
                let shift = if curve > 0.0 { (0.5 * (before - after) / curve).clamp(-0.5, 0.5) } else { 0.0 };
                let cycle = &path[..m];
                let mut started: Vec<Point> = (0..m)
                    .map(|i| {
                        let at = (i + k + m) as f64 + shift;
                        let (j, f) = (at.floor() as usize, at - at.floor());
                        cycle[j % m].lerp(cycle[(j + 1) % m], f)
                    })
                    .collect();
                started.push(started[0]);
                fits.push((Similarity::fit(from, &started), back));
            }
        }
    }
    let best = fits.iter().map(|f| f.0 .1).fold(f64::INFINITY, f64::min);
    let plain = fits[0].0 .1.min(fits[1].0 .1);
    let turn = |t: &Similarity| (t.a - Vec2::new(1.0, 0.0)).hypot();
    // The rank of a fit: begun as drawn and as good as the better of those (the fits of
    // copies begun alike, as before loops were begun anywhere: a loop symmetric under a
    // half turn, an ellipse, also fits begun half round, and a hand's wobble can make
    // that one fit a little better), then begun anywhere and as good as the best, then
    // the others that still pass for the same shape.
    // (Begun alike: the better of those within a few times the best of all; a loop begun
    // elsewhere fits as drawn many times worse, or not at all.)
    let alike = plain <= (3.0 * best).max(0.02 * size);
    let rank = |k: usize, rms: f64| {
        if alike && k < 2 && rms <= (1.5 * plain).max(0.02 * size) {
            0
        } else if rms <= (1.5 * best).max(0.02 * size) {
            1
        } else {
            2
        }
    };
    let mut out: Vec<(Similarity, f64, bool, u8)> = fits
        .into_iter()
        .enumerate()
        .filter(|(_, ((t, rms), _))| *rms <= shape * size && (1.0 / max_scale..=max_scale).contains(&t.scale()))
        .map(|(k, ((t, rms), back))| (t, rms / size, back, rank(k, rms)))
        .collect();
    // (The smallest turn first within a rank, the closest first among the others.)
    out.sort_by(|x, y| {
        x.3.cmp(&y.3).then_with(|| if x.3 < 2 { turn(&x.0).total_cmp(&turn(&y.0)) } else { x.1.total_cmp(&y.1) })
    });
    out.into_iter().map(|(t, r, back, _)| (t, r, back)).collect()
}

/// The relation `relations` ranks first: the smallest turn among the fits as good as
/// the best.
pub fn relate(from: &[Point], to: &[Point], size: f64, shape: f64, max_scale: f64) -> Option<(Similarity, f64, bool)> {
    relations(from, to, size, shape, max_scale).into_iter().next()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn powers_and_fixed_points() {
        // A turn of a quarter about (10, 0).
        let c = Vec2::new(10.0, 0.0);
        let a = Vec2::new(0.0, 1.0);
        let t = Similarity { a, b: c - mul(a, c) };
        assert!(t.fixed_point().unwrap().distance(c.to_point()) < 1e-9);
        let p = Point::new(20.0, 0.0);
        assert!(t.power(4).unwrap().apply(p).distance(p) < 1e-9);
        assert!(t.power(-1).unwrap().apply(t.apply(p)).distance(p) < 1e-9);
        assert!(t.power(2).unwrap().apply(p).distance(Point::new(0.0, 0.0)) < 1e-9);
        assert!(Similarity { a: Vec2::new(1.0, 0.0), b: Vec2::new(3.0, 0.0) }.fixed_point().is_none());
    }
}
