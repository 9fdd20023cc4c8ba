//! Similarity transforms between copies of a stroke: `z -> a z + b` on the plane read
//! as complex numbers (`a`: the turn and the scale; `b`: the shift). A petal turned
//! round a centre, a leaf further along a curved stem, a hatching line the next along a
//! turning contour: each copy is the one before under one such step.
//!
//! Shapes are compared here up to rotation and scale (the seed paper compares them up
//! to translation only): each stroke is resampled to a fixed count of points by arc
//! length, and the least-squares similarity between two such samplings (either way
//! round) is the relation between the copies, its residual how far they differ.

use super::frechet::resample_count;
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

/// The similarity carrying `from` onto `to` (either way round along `to`), with its
/// residual as a share of `size`, when they are the same shape: the residual at most
/// `shape` of `size` and the scale within `1 / max_scale ..= max_scale`. A shape that
/// looks the same either way round (a line, an ellipse) fits both: the smaller turn is
/// the step (a line's next copy is not the line turned half round). The flag says
/// whether `to` was read backwards.
pub fn relate(from: &[Point], to: &[Point], size: f64, shape: f64, max_scale: f64) -> Option<(Similarity, f64, bool)> {
    if from.len() != to.len() || from.len() < 2 || size <= 0.0 {
        return None;
    }
    let reversed: Vec<Point> = to.iter().rev().copied().collect();
    let (f, r) = (Similarity::fit(from, to), Similarity::fit(from, &reversed));
    let fits = [(f.0, f.1, false), (r.0, r.1, true)];
    let best = f.1.min(r.1);
    let turn = |t: &Similarity| (t.a - Vec2::new(1.0, 0.0)).hypot();
    let (t, rms, back) = fits
        .into_iter()
        .filter(|f| f.1 <= (1.5 * best).max(0.02 * size))
        .min_by(|x, y| turn(&x.0).total_cmp(&turn(&y.0)))?;
    let scale = t.scale();
    (rms <= shape * size && (1.0 / max_scale..=max_scale).contains(&scale)).then_some((t, rms / size, back))
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
