//! Discrete Fréchet distance between stroke shapes (SPEC 1.1).
//!
//! A shape is a stroke's path translated so that its reference point (bounding-box
//! centre) is the origin, then resampled by arc length to a common spacing. Translation
//! is thus ignored; rotation and scale are not. Drawing direction is ignored too
//! (a line drawn right-to-left is the same line), by taking the smaller of the two
//! directions. The discrete distance over-estimates the continuous one by at most the
//! sample spacing, which is chosen small against the tolerances in use.

use crate::memo::{digest, PairMemo};
use kurbo::{Point, Vec2};

/// A stroke's path centred on its reference point and resampled.
#[derive(Clone, Debug)]
pub struct Shape {
    pub points: Vec<Point>,
    /// Half the bounding-box extents (loops are filed by them to be classified).
    pub half_extent: Vec2,
    /// The least and greatest coordinates of `points`, and for a loop how far its last
    /// point lies from its first: a lower bound on the distance comes from them.
    low: Vec2,
    high: Vec2,
    slack: f64,
    /// A digest of `points`, under which distances are remembered (see `MEMO`).
    key: u64,
    /// A closed loop (its ends within two sample steps): compared from its best start
    /// too (see `Shape::starts`).
    pub closed: bool,
}

/// Distances already measured, by the two shapes' digests (see `crate::memo`).
/// Autocomplete classifies the whole drawing again after every stroke, and its
/// tolerances come from the distances between up to 120 strokes: about 7,000 of them, a
/// quarter of a second in wasm for a hand's 200 strokes, all but a hundred measured the
/// stroke before.
const MEMO_ENTRIES: usize = 1 << 18;
thread_local! {
    static MEMO: PairMemo = PairMemo::new(MEMO_ENTRIES);
}

/// Whether a path resampled at equal steps closes on itself: its ends within two steps
/// of each other (a loop, begun wherever the pen landed), with six samples or more.
pub(crate) fn closed_loop(points: &[Point]) -> bool {
    let n = points.len();
    if n < 6 {
        return false;
    }
    let len: f64 = points.windows(2).map(|w| w[0].distance(w[1])).sum();
    points[0].distance(points[n - 1]) <= 2.0 * len / (n - 1) as f64
}

/// At most this many samples per shape: keeps one comparison at a few thousand steps.
pub const MAX_SAMPLES: usize = 64;

impl Shape {
    /// Centres `points` on their bounding-box centre and resamples every `spacing`
    /// of arc length (coarser for long paths, so at most `MAX_SAMPLES`).
    pub fn new(points: &[[f64; 2]], spacing: f64) -> Shape {
        let pts: Vec<Point> = points.iter().map(|&[x, y]| Point::new(x, y)).collect();
        let (lo, hi) =
            pts.iter().fold((Point::new(f64::MAX, f64::MAX), Point::new(f64::MIN, f64::MIN)), |(lo, hi), p| {
                (Point::new(lo.x.min(p.x), lo.y.min(p.y)), Point::new(hi.x.max(p.x), hi.y.max(p.y)))
            });
        let centre = lo.midpoint(hi);
        let rel: Vec<Point> = pts.iter().map(|p| (*p - centre).to_point()).collect();
        let points = resample(&rel, spacing, MAX_SAMPLES);
        let (low, high) = points.iter().fold(
            (Vec2::new(f64::INFINITY, f64::INFINITY), Vec2::new(f64::NEG_INFINITY, f64::NEG_INFINITY)),
            |(l, h), p| (Vec2::new(l.x.min(p.x), l.y.min(p.y)), Vec2::new(h.x.max(p.x), h.y.max(p.y))),
        );
        let closed = closed_loop(&points);
        let slack = if closed { points[0].distance(points[points.len() - 1]) } else { 0.0 };
        Shape {
            key: digest(points.iter().map(|p| (p.x, p.y)), &[]),
            closed,
            points,
            half_extent: (hi - lo) * 0.5,
            low,
            high,
            slack,
        }
    }

    /// A lower bound on the discrete Fréchet distance: every point is coupled with one
    /// of the other shape's within it, so the greatest and least coordinates of the two
    /// samplings differ by no more (less each loop's slack: begun elsewhere, a loop's
    /// path leaves out its last point, which lies that far from its first). Read from
    /// the bounding boxes of the points drawn it was not one: resampling cuts a corner
    /// (a zigzag's tips flattened by 0.2 measured 0.18 apart at a spacing of 1.6).
    pub fn extent_bound(&self, other: &Shape) -> f64 {
        if self.points.is_empty() || other.points.is_empty() {
            return 0.0;
        }
        let (l, h) = (self.low - other.low, self.high - other.high);
        (l.x.abs().max(l.y.abs()).max(h.x.abs()).max(h.y.abs()) - self.slack - other.slack).max(0.0)
    }

    /// Whether the discrete Fréchet distance to `other` is below `eps` (either direction).
    pub fn within(&self, other: &Shape, eps: f64) -> bool {
        if self.extent_bound(other) >= eps {
            return false;
        }
        if let Some(d) = self.remembered(other) {
            return d < eps;
        }
        let (p, q) = (&self.points, &other.points);
        let direct = |t: f64| decide(p, q, t, false) || decide(p, q, t, true);
        if direct(eps) {
            return true;
        }
        if !(self.closed && other.closed && near_everywhere(p, q, eps)) {
            return false;
        }
        // Two loops: `other` begun elsewhere, decided rather than measured (a full
        // distance per pair was 45% of a cold call on a hand's 200 petals). A start
        // brings the distance under `eps` only where `measure` would try it: while the
        // least distance so far (direct, and each start tried before) exceeds both its
        // first points' distance and its root mean square over 0.3.
        let starts = self.starts(other);
        let threshold = |(started, rms): &(Vec<Point>, f64)| p[0].distance(started[0]).max(rms / 0.3);
        for k in 0..starts.len() {
            if !decide(p, &starts[k].0, eps, false) {
                continue;
            }
            let mut tried: Vec<bool> = Vec::with_capacity(k + 1);
            for j in 0..=k {
                let t = threshold(&starts[j]);
                let before = (0..j).all(|i| !tried[i] || !decide(p, &starts[i].0, t, false));
                tried.push(before && !direct(t));
            }
            if tried[k] {
                return true;
            }
        }
        false
    }

    /// The distance to `other`, if measured already.
    fn remembered(&self, other: &Shape) -> Option<f64> {
        MEMO.with(|m| m.get(self.key, other.key))
    }

    /// Two closed loops: `other` started where it best matches `self`'s start, each
    /// way round (where that is not where it starts already), with the root mean square
    /// distance of the points so paired. A hand starts each copy
    /// of a loop wherever the pen lands, and the discrete distance pairs the two starts:
    /// a circle begun a quarter of the way round measured a radius and a half off. The
    /// best start minimises the sum of square distances between the loops' points
    /// paired in order (both centred on their bounding boxes).
    fn starts(&self, other: &Shape) -> Vec<(Vec<Point>, f64)> {
        if !(self.closed && other.closed) {
            return Vec::new();
        }
        let (p, n, m) = (&self.points, self.points.len() - 1, other.points.len() - 1);
        let mut out = Vec::new();
        // (Each point of `self` paired with the point as far round `other`.)
        let paired: Vec<usize> = (0..n).map(|i| i * m / n).collect();
        for reversed in [false, true] {
            // (Read backwards from its first point: begun there, it is `other` reversed.)
            let cycle: Vec<Point> = (0..m).map(|j| other.points[if reversed { (m - j) % m } else { j }]).collect();
            // The square distances of the points paired in order from start `k`, on
            // every `stride`-th point (the cycle twice over: no remainder per point).
            let twice: Vec<Point> = cycle.iter().chain(&cycle).copied().collect();
            let cost = |k: usize, stride: usize| -> f64 {
                paired
                    .iter()
                    .step_by(stride)
                    .zip(p.iter().step_by(stride))
                    .map(|(&j, pi)| pi.distance_squared(twice[j + k]))
                    .sum()
            };
            // Every fourth start on every fourth point, then the best's neighbours on all
            // (a loop's cost changes slowly with its start: about a fifth of the time of
            // one distance, where every start on every point took twice that).
            let coarse = (0..m).step_by(4).map(|k| (k, cost(k, 4))).min_by(|x, y| x.1.total_cmp(&y.1));
            let Some((coarse, _)) = coarse else { continue };
            let near = (coarse + m - 3..=coarse + m + 3).map(|k| k % m);
            let Some((k, c)) = near.map(|k| (k, cost(k, 1))).min_by(|x, y| x.1.total_cmp(&y.1)) else { continue };
            // (Begun where `other` begins: measured already.)
            if k != 0 {
                let mut q: Vec<Point> = cycle[k..].iter().chain(&cycle[..k]).copied().collect();
                q.push(q[0]);
                out.push((q, (c / n as f64).sqrt()));
            }
        }
        out
    }

    /// The discrete Fréchet distance (smaller of the two directions). The direction
    /// whose ends lie closer is measured first; the other only as far as it could still
    /// come out smaller (its ends, and each row of its recurrence, bound it from below).
    pub fn distance(&self, other: &Shape) -> f64 {
        MEMO.with(|m| m.get_or(self.key, other.key, || self.measure(other)))
    }

    fn measure(&self, other: &Shape) -> f64 {
        let (p, q) = (&self.points, &other.points);
        let (Some(&p0), Some(&pn), Some(&q0), Some(&qm)) = (p.first(), p.last(), q.first(), q.last()) else {
            return value(p, q, false, f64::INFINITY);
        };
        let ends = |reversed: bool| {
            let (a, b) = if reversed { (qm, q0) } else { (q0, qm) };
            p0.distance(a).max(pn.distance(b))
        };
        let first = ends(true) < ends(false);
        let mut best = value(p, q, first, f64::INFINITY);
        if ends(!first) < best {
            best = best.min(value(p, q, !first, best));
        }
        for (started, rms) in self.starts(other) {
            // (Its first points must be paired: no nearer than they are. And a start
            // whose points pair, in order, at a root mean square of 0.3 of the distance
            // from the loops' own starts or more, is not where the same loop was begun:
            // two petals turned apart, which differ anyway.)
            if p[0].distance(started[0]) < best && rms < 0.3 * best {
                best = best.min(value(p, &started, false, best));
            }
        }
        best
    }
}

/// `pts` resampled to `count` points (at least 2) at equal arc-length steps, both ends
/// kept; fewer for a path of no length.
pub(crate) fn resample_count(pts: &[Point], count: usize) -> Vec<Point> {
    let len: f64 = pts.windows(2).map(|w| w[0].distance(w[1])).sum();
    // A hair over the exact step, so rounding never asks for one sample more.
    resample(pts, len / (count.clamp(2, MAX_SAMPLES) - 1) as f64 * (1.0 + 1e-9), MAX_SAMPLES)
}

/// Resamples a polyline at equal arc-length steps of about `spacing` (at most `max`
/// points), keeping both ends.
pub(crate) fn resample(pts: &[Point], spacing: f64, max: usize) -> Vec<Point> {
    if pts.len() < 2 {
        return pts.to_vec();
    }
    let len: f64 = pts.windows(2).map(|w| w[0].distance(w[1])).sum();
    if len <= 0.0 {
        return vec![pts[0]];
    }
    let n = ((len / spacing.max(1e-12)).ceil() as usize).clamp(1, max.max(2) - 1);
    let step = len / n as f64;
    let mut out = Vec::with_capacity(n + 1);
    out.push(pts[0]);
    let (mut seg, mut seg_start, mut next) = (0usize, 0.0f64, step);
    while out.len() < n {
        let seg_len = pts[seg].distance(pts[seg + 1]);
        if seg_start + seg_len >= next {
            let t = if seg_len > 0.0 { (next - seg_start) / seg_len } else { 0.0 };
            out.push(pts[seg].lerp(pts[seg + 1], t));
            next += step;
        } else {
            seg_start += seg_len;
            seg += 1;
            if seg + 1 >= pts.len() {
                break;
            }
        }
    }
    out.push(pts[pts.len() - 1]);
    out
}

#[inline]
fn at(q: &[Point], j: usize, reversed: bool) -> Point {
    if reversed {
        q[q.len() - 1 - j]
    } else {
        q[j]
    }
}

/// Whether every point of `p` lies within `eps` of some point of `q`: so it does
/// wherever the discrete distance is under `eps`, from whichever start (the directed
/// Hausdorff distance is at most the Fréchet distance). Stops at the first that does not.
fn near_everywhere(p: &[Point], q: &[Point], eps: f64) -> bool {
    let e2 = eps * eps;
    p.iter().all(|a| q.iter().any(|b| a.distance_squared(*b) < e2))
}

/// Decision form: is there a coupling with every pair closer than `eps`? Row by row
/// dynamic programming that stops as soon as a row has no reachable cell.
fn decide(p: &[Point], q: &[Point], eps: f64, reversed: bool) -> bool {
    let (n, m) = (p.len(), q.len());
    if n == 0 || m == 0 {
        return n == m;
    }
    let e2 = eps * eps;
    let close = |i: usize, j: usize| (p[i] - at(q, j, reversed)).hypot2() < e2;
    if !close(0, 0) || !close(n - 1, m - 1) {
        return false;
    }
    let mut prev = vec![false; m];
    let mut cur = vec![false; m];
    for i in 0..n {
        let mut any = false;
        for j in 0..m {
            let reach = if i == 0 && j == 0 {
                true
            } else {
                (i > 0 && prev[j]) || (j > 0 && cur[j - 1]) || (i > 0 && j > 0 && prev[j - 1])
            };
            cur[j] = reach && close(i, j);
            any |= cur[j];
        }
        if !any {
            return false;
        }
        std::mem::swap(&mut prev, &mut cur);
    }
    prev[m - 1]
}

/// The discrete Fréchet distance by the classic O(nm) recurrence (on square
/// distances, whose order is the distances': one square root at the end); abandoned,
/// returning infinity, once a whole row of it passes `bound` (every coupling crosses
/// each row, so the distance is at least the row's least).
///
/// Each cell waits on the one before it in its row, so rows go two at a time, the
/// second a column behind the first: two independent chains of comparisons
/// interleaved (the distances between a hand's 200 strokes are 30 million cells).
fn value(p: &[Point], q: &[Point], reversed: bool, bound: f64) -> f64 {
    let bound = bound * bound;
    let (n, m) = (p.len(), q.len());
    if n == 0 || m == 0 {
        return if n == m { 0.0 } else { f64::INFINITY };
    }
    // (Plain comparisons rather than `f64::max`/`min`, which also handle NaN: the
    // same values, as the distances are never NaN.)
    let max = |a: f64, b: f64| if a > b { a } else { b };
    let min = |a: f64, b: f64| if a < b { a } else { b };
    let q: Vec<Point> = (0..m).map(|j| at(q, j, reversed)).collect();
    if m == 1 {
        let worst = p.iter().map(|pi| pi.distance_squared(q[0])).fold(0.0, max);
        return if worst > bound && n > 1 { f64::INFINITY } else { worst.sqrt() };
    }
    let mut prev = vec![0.0f64; m];
    let mut cur = vec![0.0f64; m];
    let mut next = vec![0.0f64; m];
    // The first row: along `q` from its start.
    prev[0] = p[0].distance_squared(q[0]);
    for j in 1..m {
        prev[j] = max(p[0].distance_squared(q[j]), prev[j - 1]);
    }
    let mut i = 1;
    while i < n {
        let pa = p[i];
        let mut a = max(pa.distance_squared(q[0]), prev[0]);
        cur[0] = a;
        let mut least_a = a;
        if i + 1 == n {
            // The last row alone.
            for ((c, w), qj) in cur[1..].iter_mut().zip(prev.windows(2)).zip(&q[1..]) {
                a = max(pa.distance_squared(*qj), min(a, min(w[0], w[1])));
                *c = a;
                least_a = min(least_a, a);
            }
            if least_a > bound {
                return f64::INFINITY;
            }
            std::mem::swap(&mut prev, &mut cur);
            break;
        }
        let pb = p[i + 1];
        let mut b = max(pb.distance_squared(q[0]), a);
        next[0] = b;
        let mut least_b = b;
        // Row `i` at column 1, then at each column `j` from 2 both row `i` at `j` and
        // row `i + 1` at `j - 1`, whose cells above (row `i` at `j - 2` and `j - 1`)
        // are the two latest of row `i`, kept in registers.
        let mut a_before = a;
        a = max(pa.distance_squared(q[1]), min(a, min(prev[0], prev[1])));
        cur[1] = a;
        least_a = min(least_a, a);
        for ((((c, nb), w), qa), qb) in
            cur[2..].iter_mut().zip(next[1..m - 1].iter_mut()).zip(prev[1..].windows(2)).zip(&q[2..]).zip(&q[1..m - 1])
        {
            b = max(pb.distance_squared(*qb), min(b, min(a_before, a)));
            *nb = b;
            least_b = min(least_b, b);
            a_before = a;
            a = max(pa.distance_squared(*qa), min(a, min(w[0], w[1])));
            *c = a;
            least_a = min(least_a, a);
        }
        b = max(pb.distance_squared(q[m - 1]), min(b, min(a_before, a)));
        next[m - 1] = b;
        least_b = min(least_b, b);
        if least_a > bound || least_b > bound {
            return f64::INFINITY;
        }
        std::mem::swap(&mut prev, &mut next);
        i += 2;
    }
    prev[m - 1].sqrt()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn line(x0: f64, y0: f64, x1: f64, y1: f64) -> Vec<[f64; 2]> {
        vec![[x0, y0], [x1, y1]]
    }

    #[test]
    fn translation_is_ignored() {
        let a = Shape::new(&line(0.0, 0.0, 10.0, 0.0), 0.5);
        let b = Shape::new(&line(100.0, 50.0, 110.0, 50.0), 0.5);
        assert!(a.distance(&b) < 1e-9);
        assert!(a.within(&b, 0.1));
    }

    #[test]
    fn rotation_and_scale_are_not() {
        let a = Shape::new(&line(0.0, 0.0, 10.0, 0.0), 0.5);
        let rotated = Shape::new(&line(0.0, 0.0, 0.0, 10.0), 0.5);
        let longer = Shape::new(&line(0.0, 0.0, 20.0, 0.0), 0.5);
        assert!((a.distance(&rotated) - 50f64.sqrt()).abs() < 1e-6);
        assert!((a.distance(&longer) - 5.0).abs() < 1e-6);
        assert!(!a.within(&rotated, 7.0));
        assert!(a.within(&rotated, 7.1));
    }

    #[test]
    fn direction_is_ignored() {
        let a = Shape::new(&[[0.0, 0.0], [5.0, 3.0], [10.0, 0.0]], 0.5);
        let b = Shape::new(&[[10.0, 0.0], [5.0, 3.0], [0.0, 0.0]], 0.5);
        assert!(a.distance(&b) < 1e-9);
    }

    #[test]
    fn decision_agrees_with_value() {
        let a = Shape::new(&[[0.0, 0.0], [3.0, 4.0], [6.0, 0.0], [9.0, 4.0]], 0.3);
        let b = Shape::new(&[[0.0, 1.0], [3.0, 3.0], [6.0, 1.5], [9.0, 5.0]], 0.3);
        let d = a.distance(&b);
        assert!(d > 0.5);
        assert!(a.within(&b, d + 1e-6));
        assert!(!a.within(&b, d - 1e-6));
    }

    #[test]
    fn loops_decided_as_measured() {
        // Wobbled ellipses begun anywhere, either way round, some turned: the decision
        // on two loops agrees with the measured distance on either side of it.
        let mut rng = crate::rng::Rng::new(11);
        let mut lp = |turn: f64, start: f64, back: bool| -> Shape {
            let pts: Vec<[f64; 2]> = (0..=40)
                .map(|k| {
                    let t = start + if back { -1.0 } else { 1.0 } * k as f64 / 40.0 * std::f64::consts::TAU;
                    let (x, y) = (20.0 * t.cos() + rng.normal() * 0.4, 8.0 * t.sin() + rng.normal() * 0.4);
                    [x * turn.cos() - y * turn.sin(), x * turn.sin() + y * turn.cos()]
                })
                .collect();
            Shape::new(&pts, 0.7)
        };
        let mut checked = 0;
        for case in 0..60 {
            let a = lp(0.0, 0.0, false);
            let b = lp((case % 5) as f64 * 0.15, (case % 7) as f64 * 0.9, case % 2 == 1);
            assert!(a.closed && b.closed);
            let d = a.measure(&b);
            for f in [0.3, 0.8, 0.97, 1.03, 1.3, 3.0] {
                assert_eq!(a.within(&b, d * f), f > 1.0, "case {case}, distance {d}, eps {}", d * f);
                checked += 1;
            }
        }
        assert_eq!(checked, 360);
    }

    #[test]
    fn mirror_images_are_told_apart() {
        // A cross's two bars: one the other mirrored (the memo once took them for one).
        let a = Shape::new(&[[-15.0, -15.0], [0.0, 0.0], [15.0, 15.0]], 2.5);
        let b = Shape::new(&[[15.0, -15.0], [0.0, 0.0], [-15.0, 15.0]], 2.5);
        assert_eq!(a.distance(&a), 0.0);
        assert!(a.distance(&b) > 10.0);
        assert!(!a.within(&b, 10.0));
    }

    #[test]
    fn the_extent_bound_is_a_lower_bound() {
        // A zigzag and the same with its tips flattened a little, sampled coarsely (the
        // tips cut: the drawn points' boxes differ by more than the samples do), and
        // loops begun anywhere: never above the distance.
        let zig = |tip: f64| Shape::new(&[[0.0, 0.0], [5.0, 5.0 - tip], [15.0, -5.0 + tip], [20.0, 0.0]], 1.6);
        let (a, b) = (zig(0.0), zig(0.2));
        assert!(a.extent_bound(&b) <= a.measure(&b), "{} > {}", a.extent_bound(&b), a.measure(&b));
        let mut rng = crate::rng::Rng::new(3);
        for k in 0..40 {
            let lp = |r: f64, start: f64, rng: &mut crate::rng::Rng| -> Shape {
                let pts: Vec<[f64; 2]> = (0..=30)
                    .map(|j| {
                        let t = start + j as f64 / 30.0 * std::f64::consts::TAU;
                        [r * t.cos() + rng.normal(), 0.5 * r * t.sin() + rng.normal()]
                    })
                    .collect();
                Shape::new(&pts, 2.0 + k as f64 * 0.1)
            };
            let (p, q) = (lp(20.0, 0.0, &mut rng), lp(20.0 + (k % 5) as f64, k as f64 * 0.7, &mut rng));
            for (x, y) in [(&p, &q), (&q, &p)] {
                assert!(x.extent_bound(y) <= x.measure(y) + 1e-9, "case {k}");
            }
        }
    }

    #[test]
    fn dot_against_path() {
        let dot = Shape::new(&[[5.0, 5.0]], 0.5);
        let seg = Shape::new(&line(0.0, 0.0, 4.0, 0.0), 0.5);
        assert!((dot.distance(&seg) - 2.0).abs() < 1e-9);
        assert_eq!(dot.points.len(), 1);
    }

    /// The textbook recurrence, cell by cell, for `value` to agree with bit for bit.
    fn reference(p: &[Point], q: &[Point]) -> f64 {
        let (n, m) = (p.len(), q.len());
        let mut c = vec![vec![0.0f64; m]; n];
        for i in 0..n {
            for j in 0..m {
                let d = p[i].distance_squared(q[j]);
                c[i][j] = match (i, j) {
                    (0, 0) => d,
                    (0, _) => d.max(c[0][j - 1]),
                    (_, 0) => d.max(c[i - 1][0]),
                    _ => d.max(c[i - 1][j].min(c[i][j - 1]).min(c[i - 1][j - 1])),
                };
            }
        }
        c[n - 1][m - 1].sqrt()
    }

    #[test]
    fn value_is_the_recurrence_exactly() {
        // Rows two at a time, odd and even counts, a single column or row, both
        // directions, and a bound that abandons nothing within it.
        let mut rng = crate::rng::Rng::new(5);
        let mut pts =
            |k: usize| -> Vec<Point> { (0..k).map(|_| Point::new(rng.normal() * 10.0, rng.normal() * 10.0)).collect() };
        for n in 1..9 {
            for m in 1..9 {
                let (p, q) = (pts(n), pts(m));
                let want = reference(&p, &q);
                assert_eq!(value(&p, &q, false, f64::INFINITY).to_bits(), want.to_bits(), "{n} x {m}");
                let back: Vec<Point> = q.iter().rev().copied().collect();
                assert_eq!(value(&p, &q, true, f64::INFINITY).to_bits(), reference(&p, &back).to_bits());
                assert_eq!(value(&p, &q, false, want * 1.001).to_bits(), want.to_bits());
                // (Below the distance: abandoned, or the distance itself where no row's
                // least passes the bound.)
                let under = value(&p, &q, false, want * 0.999);
                assert!(under.is_infinite() || under.to_bits() == want.to_bits());
            }
        }
    }

    #[test]
    fn resampling_caps_samples() {
        let long = Shape::new(&line(0.0, 0.0, 1e6, 0.0), 0.1);
        assert!(long.points.len() <= MAX_SAMPLES);
    }
}
