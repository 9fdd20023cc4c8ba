//! Carrying a chain's drawn copies by its step: the copies missing round a ring, and
//! the copies further along a curve, a sequence or a large ring.

use super::Chain;
use crate::rng::Rng;
use crate::vector::frechet::closed_loop;
use crate::vector::similarity::{centroid, samples};
use crate::vector::stroke::Stroke;
use kurbo::{Point, Rect};
use std::f64::consts::TAU;

/// The most steps a chain is followed either way.
const MAX_STEPS: i64 = 400;
/// A completed copy's stroke lies on a drawn one when their centres, and the paths
/// themselves (`apart`), are at most this share of its size apart. (Paired sample by
/// sample from their starts only, a petal drawn as a loop begun elsewhere on its
/// outline than the copy carried onto it was not on it: five petals drawn whole with a
/// shaky pointer, the fifth left out of the chain, synthesized as rosettes of six with
/// that petal doubled.)
const ON: f64 = 0.1;
/// Where the ring's copies stand well apart, a petal placed before the copy (drawn, or
/// completed earlier) nearer the copy's than this share of the step between them (and than `ON_MOST` of its size) is on it as well: a
/// shaky hand turns a petal 5 degrees off its place, and its centre lay 0.102 of its
/// size from the copy carried there, which was drawn over it.
const ON_STEP: f64 = 0.3;
const ON_MOST: f64 = 0.2;

impl Chain {
    /// The copy `t` steps from the first drawn one (the drawn copies are 0 to
    /// `members - 1`), carried from drawn copy `from`: its member, then its other
    /// strokes, each with the stroke it was carried from.
    fn copy(&self, strokes: &[Stroke], t: i64, from: usize) -> Option<Vec<(Stroke, usize)>> {
        let step = self.step.power(t - from as i64)?;
        let parts = std::iter::once(self.members[from]).chain(self.companions.get(from).into_iter().flatten().copied());
        if self.upright {
            // (The copy moved whole to where the step carries its member's place.)
            let c = strokes[self.members[from]].reference_point();
            let v = step.apply(c) - c;
            return Some(parts.map(|k| (strokes[k].translated(v.x, v.y), k)).collect());
        }
        Some(parts.map(|k| (step.carry(&strokes[k]), k)).collect())
    }

    /// The drawn copy to carry to position `t`: a random one with variation (`rng`),
    /// else the nearest end; of a motif of several strokes, one that holds them all.
    fn source(&self, t: i64, rng: &mut Option<Rng>) -> usize {
        let most = self.companions.iter().map(Vec::len).max().unwrap_or(0);
        let whole: Vec<usize> =
            (0..self.members.len()).filter(|&i| self.companions.get(i).map_or(0, Vec::len) == most).collect();
        match rng {
            Some(r) => whole[r.below(whole.len())],
            None => *whole.iter().min_by_key(|&&i| (i as i64 - t).abs()).expect("a whole copy"),
        }
    }

    /// The copies missing round a closed ring (none for an open chain), each stroke with
    /// the drawn one it was carried from.
    ///
    /// A stroke that lies on one of the drawing (or on one completed before it) is left
    /// out: bars through one centre (an asterisk's) read as a ring of twice as many
    /// steps, each bar its own copy half a turn on; a petal whose second arc is not yet
    /// drawn gets that arc.
    pub fn complete(&self, strokes: &[Stroke], seed: Option<u64>) -> Vec<(Stroke, usize)> {
        let Some(k) = self.closes else { return Vec::new() };
        let mut rng = seed.map(Rng::new);
        // Each stroke placed: its centre, samples, size and whether it is a dot.
        let mut placed: Vec<(Point, Vec<Point>, f64, bool)> = strokes
            .iter()
            .map(|s| {
                let p = samples(s);
                (centroid(&p), p, s.bounds().size().to_vec2().hypot(), s.is_dot())
            })
            .collect();
        let mut out = Vec::new();
        // (From the first copy short of a stroke: a motif's copy being drawn.)
        let most = self.companions.iter().map(Vec::len).max().unwrap_or(0);
        let first = (0..self.members.len()).find(|&i| self.companions.get(i).map_or(0, Vec::len) < most);
        for t in first.unwrap_or(self.members.len())..k {
            let from = self.source(t as i64, &mut rng);
            let Some(copy) = self.copy(strokes, t as i64, from) else { continue };
            let before = placed.len();
            // (A drawn copy short of a stroke gets that stroke only: its member is drawn.)
            let drawn = usize::from(t < self.members.len());
            for (stroke, source) in copy.into_iter().skip(drawn) {
                let s = samples(&stroke);
                let size = stroke.bounds().size().to_vec2().hypot();
                let c = centroid(&s);
                let dot = stroke.is_dot();
                let on = |q: &(Point, Vec<Point>, f64, bool), within: f64| {
                    q.0.distance(c) < within && apart(&s, &q.1) < within
                };
                // Where the copies stand apart, a stroke is on a drawn one of about its
                // size within `ON_STEP` of the step, and a dot on a drawn dot (a few
                // pixels across, its own size says nothing); never on a stroke of its own
                // copy, nor a vein on its petal.
                let step = ON_STEP * self.step.apply(c).distance(c);
                let wide = if dot { step } else { (ON_MOST * size).min(step) };
                let alike = |q: &(Point, Vec<Point>, f64, bool)| {
                    let ratio = q.2 / size.max(1e-9);
                    if dot || q.3 {
                        (0.5..=2.0).contains(&ratio)
                    } else {
                        (0.8..=1.25).contains(&ratio)
                    }
                };
                if placed.iter().any(|q| on(q, ON * size)) || placed[..before].iter().any(|q| alike(q) && on(q, wide)) {
                    continue;
                }
                placed.push((c, s, size, dot));
                out.push((stroke, source));
            }
        }
        out
    }

    /// The copies further along the chain, both ways, whose centres lie in `area` (at
    /// most `max`), each with the drawn copy it was carried from. A chain that leaves
    /// the area may come back into it (an arc of a circle larger than the area), so it
    /// is followed on: for a turn, once round; for a spiral, while its copies are
    /// between half the smallest drawn copy and twice the largest (further on, the
    /// step's error read from a few copies outgrows the copies); never onto a
    /// copy placed already (within half a step: a circle closing). With whether a copy
    /// in the area was left out for `max`.
    pub fn extend(
        &self,
        strokes: &[Stroke],
        area: Rect,
        seed: Option<u64>,
        max: usize,
    ) -> (Vec<(Stroke, usize)>, bool) {
        self.extend_by(strokes, area, seed, max, [MAX_STEPS; 2])
    }

    /// `extend`, at most `by[0]` steps past the last drawn copy and `by[1]` before the
    /// first (a curve whose turn changes goes on past each end by its end's step, a
    /// few copies: `Bending`).
    pub fn extend_by(
        &self,
        strokes: &[Stroke],
        area: Rect,
        seed: Option<u64>,
        max: usize,
        by: [i64; 2],
    ) -> (Vec<(Stroke, usize)>, bool) {
        let mut rng = seed.map(Rng::new);
        let l = self.members.len() as i64;
        let size = |s: &Stroke| s.bounds().size().to_vec2().hypot();
        let sizes: Vec<f64> = self.members.iter().map(|&m| size(&strokes[m])).collect();
        let (small, large) = (
            0.5 * sizes.iter().copied().fold(f64::INFINITY, f64::min),
            2.0 * sizes.iter().copied().fold(0.0, f64::max),
        );
        let turning = (self.step.scale() - 1.0).abs() < 0.04;
        let steps = if turning { (TAU / self.step.turn().abs().max(1e-3)).ceil() as i64 } else { MAX_STEPS };
        let mut centres: Vec<Point> = self.members.iter().map(|&m| strokes[m].reference_point()).collect();
        let mut out = Vec::new();
        let mut capped = false;
        // Both ways in turn, so that where the two runs meet (round a circle) each copy
        // comes from the nearer end.
        let mut next = [Some(l), Some(-1)];
        while next.iter().any(Option::is_some) {
            for (d, dir) in [1i64, -1].into_iter().enumerate() {
                let Some(t) = next[d] else { continue };
                next[d] = None;
                if (t - if dir > 0 { l - 1 } else { 0 }).abs() > steps.min(by[d]) {
                    continue;
                }
                let from = self.source(t, &mut rng);
                let Some(copy) = self.copy(strokes, t, from) else { continue };
                let c = copy[0].0.reference_point();
                let s = size(&copy[0].0);
                // The step's length here: the distance to the copy before it.
                let before = self.copy(strokes, t - dir, from).map_or(0.0, |b| b[0].0.reference_point().distance(c));
                if s < small || s > large || centres.iter().any(|p| p.distance(c) < 0.5 * before) {
                    continue;
                }
                if area.contains(c) {
                    let kept: Vec<(Stroke, usize)> =
                        copy.into_iter().filter(|(p, _)| area.contains(p.reference_point())).collect();
                    // (A copy goes whole or not at all: `max` bounds the output's memory.)
                    if out.len() + kept.len() > max {
                        capped |= !kept.is_empty();
                        continue;
                    }
                    centres.push(c);
                    out.extend(kept);
                }
                next[d] = Some(t + dir);
            }
        }
        (out, capped)
    }
}

/// How far apart two paths lie, point for point: the root-mean-square distance between
/// their samples paired in order, either way round, and for two closed loops from the
/// start along the second that pairs them best (a hand begins each loop wherever it
/// puts the pen: a loop begun elsewhere on the same outline is 0 apart). Paired, unlike
/// the nearest points, a vein inside its petal, or a narrow petal 2 beside the next, is
/// not on it.
fn apart(p: &[Point], q: &[Point]) -> f64 {
    let n = p.len().min(q.len());
    if n == 0 {
        return f64::INFINITY;
    }
    let rms =
        |pair: &dyn Fn(usize) -> Point| ((0..n).map(|i| p[i].distance_squared(pair(i))).sum::<f64>() / n as f64).sqrt();
    let mut best = rms(&|i| q[i]).min(rms(&|i| q[n - 1 - i]));
    if n > 2 && closed_loop(p) && closed_loop(q) {
        // (A closed loop's last sample repeats its first.)
        let m = n - 1;
        for k in 1..m {
            best = best.min(rms(&|i| q[(i + k) % m])).min(rms(&|i| q[(m + k - i % m) % m]));
        }
    }
    best
}
