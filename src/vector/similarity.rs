//! Similarity transforms between copies of a stroke: `z -> a z + b` on the plane read
//! as complex numbers (`a`: the turn and the scale; `b`: the shift). A petal turned
//! round a centre, a leaf further along a curved stem, a hatching line the next along a
//! turning contour: each copy is the one before under one such step.
//!
//! Shapes are compared here up to rotation and scale (the seed paper compares them up
//! to translation only): each stroke is resampled to a fixed count of points by arc
//! length, and the least-squares similarity between two such samplings (either way
//! round) is the relation between the copies, its residual how far they differ.

use super::classify::median;
use super::frechet::{closed_loop, resample_count};
use super::stroke::Stroke;
use kurbo::{Point, Rect, Vec2};

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

/// A stroke's path at `SAMPLES` points, steadied first where its points shake (see
/// `steadied`).
pub fn samples(s: &Stroke) -> Vec<Point> {
    let pts: Vec<Point> = steadied(s.points.clone()).into_iter().map(|[x, y]| Point::new(x, y)).collect();
    resample_count(&pts, SAMPLES)
}

/// A path shakes when its points' jitter (a standard deviation, see `jitter`) passes
/// this share of the median distance between them: a finger or a shaky mouse, whose
/// points each stray on their own. A pen's or a steady mouse's dense points stay well
/// under (their second differences are the curve's), as does a circle of 16 points or
/// more drawn exactly (0.1 at 24).
const JAGGED: f64 = 0.3;
/// Paths of fewer points are never steadied: their second differences are mostly their
/// own turns (a loop of 8 to 14 points, a flower's centre or petal)...
const STEADIED_POINTS: usize = 16;
/// ...nor paths whose points stray by less than this share of their size, however
/// close the points lie: a pen's dense points, a few tenths of a pixel off, read as
/// shaking against their spacing of a pixel or two (a cross's bars at 5% wobble, 1.1%
/// of their length: averaged, they put 3 more ghosts wrong of 89). A finger's or a
/// shaky mouse's points stray by 2-3% (petals 90 long shaken by 2.7, hatching 80 long
/// by 1.6).
const SHAKEN: f64 = 0.015;

/// `points` averaged `[1, 2, 1] / 4` along the path (round a closed loop across its
/// closing, an open path's ends kept), up to twice, while they shake (`JAGGED`).
///
/// Resampled by arc length as they were drawn, the jitter's zigzag lengthens the path
/// unevenly, so two copies' samples no longer pair like points, and the best
/// similarity turns to make up for it: petals 90 long, each point shaken by 2.7, read
/// steps of 76 and 57 degrees round a ring of six, and no ring was found; once averaged,
/// 58 and 56 (rings of 6, 8 and 9 from four such petals: 40 of 60 found with their
/// count, against 26). A path that does not shake is left as drawn: an average rounds a motif's
/// tips and corners, and moved hand-drawn rings' ghosts (wrong ghosts 38 to 46 of 870
/// for a person's hand at 1% when every path was averaged).
pub fn steadied(mut points: Vec<[f64; 2]>) -> Vec<[f64; 2]> {
    for _ in 0..2 {
        let n = points.len();
        if n < STEADIED_POINTS {
            break;
        }
        let point = |p: &[f64; 2]| Point::new(p[0], p[1]);
        let mut gaps: Vec<f64> = points.windows(2).map(|w| point(&w[0]).distance(point(&w[1]))).collect();
        let spacing = median(&mut gaps);
        let shake = jitter(&points).sqrt();
        let bounds =
            points.iter().fold(Rect::from_points(point(&points[0]), point(&points[0])), |r, p| r.union_pt(point(p)));
        let size = bounds.size().to_vec2().hypot();
        if shake <= JAGGED * spacing || shake <= SHAKEN * size {
            break;
        }
        let closed = closed_loop(&points.iter().map(point).collect::<Vec<_>>());
        // (A closed loop's last point repeats its first.)
        let m = if closed { n - 1 } else { n };
        let at = |k: i64, c: usize| points[k.rem_euclid(m as i64) as usize][c];
        points = (0..n)
            .map(|i| {
                if !closed && (i == 0 || i == n - 1) {
                    return points[i];
                }
                let i = if closed && i == n - 1 { 0 } else { i as i64 };
                let avg = |c: usize| (at(i - 1, c) + 2.0 * at(i, c) + at(i + 1, c)) * 0.25;
                [avg(0), avg(1)]
            })
            .collect();
    }
    points
}

/// The variance of each point's own jitter about a smooth path, per coordinate: a
/// smooth path's second differences `p[i-1] - 2 p[i] + p[i+1]` are about zero where its
/// points lie close, and jitter of variance `s^2` gives them `6 s^2` per coordinate, so
/// their squared length is `6 s^2` times a chi-square of two degrees, whose median is
/// `2 ln 2`. The median leaves out corners (a house's, a zigzag's), where the path
/// itself turns; a loop of few points turns all along, and reads its turning as jitter
/// (see `STEADIED_POINTS`). (Third differences leave more of a loop's turning out, but
/// read a hand's wobble otherwise, and moved the replays' tables: a house drawn at 3%
/// took 49 strokes by hand where it took 24.)
pub(crate) fn jitter(points: &[[f64; 2]]) -> f64 {
    if points.len() < 5 {
        return 0.0;
    }
    let mut d2: Vec<f64> = points
        .windows(3)
        .map(|w| {
            let (x, y) = (w[0][0] - 2.0 * w[1][0] + w[2][0], w[0][1] - 2.0 * w[1][1] + w[2][1]);
            x * x + y * y
        })
        .collect();
    median(&mut d2) / (12.0 * std::f64::consts::LN_2)
}

/// (A loop of `SAMPLES` points, the last its first, is begun "a quarter" round 5 samples
/// on, 78 degrees, and "an eighth" 2 on, 31: the figures below are of that sampling.)
///
/// Whether a closed loop (sampled) fits itself begun a quarter of the way round, within
/// `shape` of `size` (rms): a circle or a square, whose copies' turn its shape shows
/// only up to quarter turns.
pub fn looks_the_same_turned(p: &[Point], size: f64, shape: f64) -> bool {
    self_residual(p, 4).is_some_and(|r| r <= shape * size)
}

/// Whether a closed loop (sampled) is round, a circle, whose copies show no turn at all:
/// it fits itself begun a quarter of the way round and an eighth, and the eighth no
/// worse than the quarter (a square begun an eighth round pairs its corners with its
/// sides' middles: 0.088 of its size off, against 0.043 a quarter round, sampled as
/// here; circles of radius 7 to 30 drawn with a 2% wobble and 0.7 px of jitter fit an
/// eighth round within 0.066, and no worse than a quarter round by much).
pub fn looks_round(p: &[Point], size: f64, shape: f64) -> bool {
    match (self_residual(p, 4), self_residual(p, 8)) {
        (Some(quarter), Some(eighth)) => {
            quarter.max(eighth) <= shape * size && eighth <= (ROUND_EIGHTH * quarter).max(ROUND_FLOOR * size)
        }
        _ => false,
    }
}

/// A round loop's fit begun an eighth round is at most this many times its fit begun a
/// quarter round, or this share of its size.
const ROUND_EIGHTH: f64 = 1.5;
const ROUND_FLOOR: f64 = 0.03;

/// The rms residual of a closed loop fitted to itself begun `1 / part` of the way round
/// (`None` for an open stroke).
fn self_residual(p: &[Point], part: usize) -> Option<f64> {
    if !closed_loop(p) {
        return None;
    }
    let m = p.len() - 1;
    let mut turned: Vec<Point> = (0..m).map(|i| p[(i + m / part) % m]).collect();
    turned.push(turned[0]);
    Some(Similarity::fit(p, &turned).1)
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
    use crate::rng::Rng;

    /// A smooth path reads next to no jitter, a shaken one about its own.
    #[test]
    fn jitter_reads_a_pointers_shake_and_not_a_smooth_curve() {
        let arc: Vec<[f64; 2]> =
            (0..40).map(|k| (k as f64 * 0.05).sin_cos()).map(|(s, c)| [60.0 * c, 60.0 * s]).collect();
        assert!(jitter(&arc) < 0.01, "{}", jitter(&arc));
        let mut rng = Rng::new(3);
        for sd in [0.5, 1.6] {
            let mut reads = Vec::new();
            for _ in 0..50 {
                let line: Vec<[f64; 2]> =
                    (0..20).map(|k| [sd * rng.normal(), 4.0 * k as f64 + sd * rng.normal()]).collect();
                reads.push(jitter(&line) / (sd * sd));
            }
            let mean = reads.iter().sum::<f64>() / reads.len() as f64;
            assert!((0.9..1.4).contains(&mean), "shaken by {sd}: read {mean:.2} of its variance");
        }
    }

    /// A loop 90 long and 50 wide, begun `start` of the way round, turned by `turn`, its
    /// 30 points each shaken by `shake`.
    fn petal(turn: f64, start: f64, shake: f64, rng: &mut Rng) -> Stroke {
        let (c, s) = (turn.cos(), turn.sin());
        let mut pts: Vec<[f64; 2]> = (0..29)
            .map(|k| {
                let t = std::f64::consts::TAU * (start + k as f64 / 29.0);
                let (x, y) = (60.0 + 45.0 * t.cos(), 25.0 * t.sin());
                [x * c - y * s + shake * rng.normal(), x * s + y * c + shake * rng.normal()]
            })
            .collect();
        // (Closed where it began.)
        pts.push(pts[0]);
        Stroke::new(pts, 3.0, None)
    }

    /// Paths that do not shake are left as drawn (a circle of 24 points, a petal whose
    /// points stray by 1% of it); a petal whose points shake by 3.5 is steadied to a
    /// fraction of that.
    #[test]
    fn only_shaking_paths_are_steadied() {
        let circle: Vec<[f64; 2]> = (0..=24)
            .map(|k| (k as f64 * std::f64::consts::TAU / 24.0).sin_cos())
            .map(|(s, c)| [40.0 * c, 40.0 * s])
            .collect();
        assert_eq!(steadied(circle.clone()), circle);
        let mut rng = Rng::new(5);
        let shake = |p: &[[f64; 2]]| jitter(p).sqrt();
        for _ in 0..20 {
            let steady = petal(0.3, rng.next_f64(), 1.0, &mut rng).points;
            assert_eq!(steadied(steady.clone()), steady);
            let shaken = petal(0.3, rng.next_f64(), 3.5, &mut rng).points;
            let after = steadied(shaken.clone());
            assert!(shake(&after) < 0.5 * shake(&shaken), "{:.2} from {:.2}", shake(&after), shake(&shaken));
            // (Closed as drawn.)
            assert_eq!(after[0], after[after.len() - 1]);
        }
    }

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
