//! How far off the fitted lattice may be: the error of a site, the miss of a proposal
//! there, and the hand's own scatter.

use super::fit::Fit;
use super::SUGGESTED_WEIGHT;
use crate::vector::element::Element;
use crate::vector::frechet::closed_loop;
use crate::vector::similarity::{jitter, samples};
use crate::vector::stroke::Stroke;
use kurbo::Vec2;

/// A proposal is shown only where the hand's copy is this likely to fall within the
/// matching tolerance of it (see `Certainty::reach`).
const SURE: f64 = 0.98;
/// The prior scatter counts as this many copies: it is read from every pair of a
/// hand's strokes of one class, not guessed.
const PRIOR_COPIES: f64 = 3.0;

/// What the (weighted) drawn copies say about the lattice's error: the variance of a
/// copy about its site, each motif position's weight and mean cell, and the pooled
/// scatter of the cells about those means (`[uu, uw, ww]`).
#[derive(Clone, Debug, Default)]
pub(super) struct Certainty {
    residual2: f64,
    /// The copies `residual2` is estimated from (the prior counting as `PRIOR_COPIES`).
    copies: f64,
    held: Vec<f64>,
    mean: Vec<(f64, f64)>,
    scatter: [f64; 3],
}

impl Certainty {
    /// How many root-mean-square misses (`Fit::miss_at`) reach the circle that holds
    /// the hand's copy with probability `SURE`. The scatter is estimated from few
    /// copies (each gives two coordinates), so the miss's square over its estimate's
    /// is `2 F(2, 2n)`, whose quantile has a closed form: `F = n (p^(-1/n) - 1)` for
    /// `p = 1 - SURE`. From `sqrt(-ln p)` = 1.98 with many copies it grows to 3.5 with
    /// two and 7 with one: a row of three copies fits its periods almost exactly and
    /// says little of how far the next ones will stray.
    pub(super) fn reach(&self) -> f64 {
        reach(self.copies)
    }
}

/// `Certainty::reach` for a scatter estimated from `copies` copies (prior ones counted).
pub(super) fn reach(copies: f64) -> f64 {
    let n = copies.max(1.0);
    (n * ((1.0 - SURE).powf(-1.0 / n) - 1.0)).sqrt()
}

impl Fit {
    /// The residual is the unbiased one (each motif position's site and each period take
    /// a degree of freedom: two copies fit a row exactly and say nothing of its error),
    /// with `PRIOR_COPIES` prior copies off by `prior` (a mean square), so that a lattice
    /// seen in few copies is not taken as exact.
    pub(super) fn certainty(&self, elems: &[Element], weight: &[f64], prior: f64) -> Certainty {
        let positions = self.motif.len();
        let mut held = vec![0.0; positions];
        let mut mean = vec![(0.0, 0.0); positions];
        let mut r2 = 0.0;
        // Accepted copies sit where an earlier fit put them: they carry no evidence of
        // its error, and their cells, far out, would make it look well anchored.
        let weight: Vec<f64> = weight.iter().map(|&w| if w > SUGGESTED_WEIGHT { w } else { 0.0 }).collect();
        for (i, &(m, (u, w))) in self.cell.iter().enumerate() {
            held[m] += weight[i];
            mean[m].0 += weight[i] * u as f64;
            mean[m].1 += weight[i] * w as f64;
            r2 += weight[i] * self.site(m, (u, w)).distance_squared(elems[i].pos);
        }
        for (m, h) in mean.iter_mut().zip(&held) {
            *m = if *h > 0.0 { (m.0 / h, m.1 / h) } else { (0.0, 0.0) };
        }
        let mut scatter = [0.0; 3];
        for (i, &(m, (u, w))) in self.cell.iter().enumerate() {
            let (du, dw) = (u as f64 - mean[m].0, w as f64 - mean[m].1);
            scatter[0] += weight[i] * du * du;
            scatter[1] += weight[i] * du * dw;
            scatter[2] += weight[i] * dw * dw;
        }
        let periods = if self.b.is_some() { 2.0 } else { 1.0 };
        let free = (held.iter().map(|&h| (h - 1.0).max(0.0)).sum::<f64>() - periods).max(0.0);
        let copies = free + PRIOR_COPIES;
        Certainty { residual2: (r2 + PRIOR_COPIES * prior) / copies, copies, held, mean, scatter }
    }

    /// The standard error of motif position `m`'s site in cell `(u, w)`, as least
    /// squares gives it: with `d` the cell's offset from the position's (weighted) mean
    /// cell and `S` the cells' scatter, `r^2 (1 / held + d' S^-1 d)`. The periods are
    /// correlated when the copies lie along a diagonal of the cells (the basis then
    /// crosses the rows), which the full `S` takes in.
    pub(super) fn error_at(&self, m: usize, (u, w): (i64, i64)) -> f64 {
        let c = &self.certainty;
        let (du, dw) = (u as f64 - c.mean[m].0, w as f64 - c.mean[m].1);
        let [suu, suw, sww] = c.scatter;
        let det = suu * sww - suw * suw;
        let far = if self.b.is_none() {
            if suu > 0.0 {
                du * du / suu
            } else {
                f64::INFINITY
            }
        } else if det > 1e-9 * (suu * sww).max(1e-300) {
            (du * du * sww - 2.0 * du * dw * suw + dw * dw * suu) / det
        } else {
            f64::INFINITY
        };
        (c.residual2 * (1.0 / c.held[m].max(1e-9) + far)).sqrt()
    }

    /// The root-mean-square distance between a proposal for motif position `m` in cell
    /// `(u, w)` and the copy the hand would draw there: the site's error and the drawn
    /// copy's own scatter about its site (the proposal itself sits on the site).
    pub(super) fn miss_at(&self, m: usize, cell: (i64, i64)) -> f64 {
        (self.error_at(m, cell).powi(2) + self.certainty.residual2).sqrt()
    }
}

/// How far a hand's copy strays from where it means to put it, as the drawing shows it
/// before its repetition does: the mean square difference, between consecutive
/// hand-drawn strokes of one class, of their ends' offsets from their reference
/// points (either way round), halved (of loops begun at different places, which end
/// wherever the pen landed, their boxes' corners). Exact copies give 0; a hand that
/// wobbles its strokes' ends by `e` gives about `e^2`, and places its copies about as
/// loosely.
///
/// Each point's own jitter (a shaky pointer, a tremor: see `similarity::jitter`) is taken out: it
/// moves the ends without moving the copy, whose place averages it away. (Hatching 80
/// long, 20 apart, its points shaken by 1.6 at random, read a scatter of 5.4 to 7.4 and
/// got no ghost at four to six strokes, though they lay within 0.4 of a row.)
pub(super) fn hand_scatter(strokes: &[Stroke], classes: &[u32], accepted: &[bool]) -> f64 {
    let ends = |s: &Stroke| {
        let r = s.reference_point().to_vec2();
        let p = |q: &[f64; 2]| Vec2::new(q[0], q[1]) - r;
        (s.points.first().map_or(Vec2::ZERO, p), s.points.last().map_or(Vec2::ZERO, p))
    };
    let mut last: Vec<Option<usize>> = vec![None; classes.iter().map(|&c| c as usize + 1).max().unwrap_or(0)];
    let (mut sum, mut shaken, mut count) = (0.0, 0.0, 0usize);
    for (i, &c) in classes.iter().enumerate() {
        if accepted[i] {
            continue;
        }
        if let Some(j) = last[c as usize] {
            let (a, b) = (&strokes[i], &strokes[j]);
            let ((a0, a1), (b0, b1)) = (ends(a), ends(b));
            let same = (a0 - b0).hypot2() + (a1 - b1).hypot2();
            let reversed = (a0 - b1).hypot2() + (a1 - b0).hypot2();
            let size = a.bounds().size().to_vec2().hypot();
            let closed = |s: &Stroke| closed_loop(&samples(s));
            shaken += jitter(&a.points) + jitter(&b.points);
            sum += if same.min(reversed) > (0.25 * size).powi(2) && closed(a) && closed(b) {
                // (Loops begun at different places: their ends say where the pen landed,
                // their boxes' corners how the hand wobbled.)
                let (ea, eb) = (a.bounds().size().to_vec2(), b.bounds().size().to_vec2());
                2.0 * ((ea - eb) * 0.5).hypot2() / 4.0
            } else {
                same.min(reversed) / 4.0
            };
            count += 1;
        }
        last[c as usize] = Some(i);
    }
    if count == 0 {
        0.0
    } else {
        (sum - JITTER_AT_ENDS * shaken).max(0.0) / count as f64
    }
}

/// What each stroke's jitter of variance `s^2` adds to its pair's share of
/// `hand_scatter`, over `s^2` as `jitter` reads it: a pair of lines of 10 to 40 points
/// gets about `1.5 s^2` (their ends each off by it, their boxes' centres a little),
/// 0.75 per stroke, and `jitter` reads `s^2` 10-30% high from so few points.
const JITTER_AT_ENDS: f64 = 0.65;
