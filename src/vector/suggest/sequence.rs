//! Repetition by local similarity, where the drawing holds no lattice (after Xing et
//! al., "Autocomplete Painting Repetitions", 2014, which predicts from the last
//! strokes rather than a global structure): the next copy relates to the latest as the
//! latest relates to the one before. Petals around a centre (each a turn of the last),
//! leaves along an arc, hatching that turns: each step is a similarity transform
//! `z -> a z + b` (complex `a`: the turn and the scale; `b`: the shift).
//!
//! The latest stroke and the two before it of the same shape up to a similarity (the
//! most recent ones among the last `LOOK_BACK`) make a sequence when the step from the
//! first to the second also carries the second onto the third: the same turn and scale
//! (within `TURN`), and the third where that step puts it (within `PLACE` of the step).
//! The next copies are the latest carried on by the mean step, as far as their expected
//! miss (the step's own error, growing with each step) stays well within the matching
//! tolerance, and never onto a drawn stroke (a ring stops where it closes).
//!
//! Departs from the lattice model and from the seed paper: shapes are compared up to
//! rotation and scale here (a petal turned is the same petal), and only motifs of one
//! stroke are carried on.

use super::{Suggestions, TOLERANCE};
use crate::vector::similarity::{self, centroid, mul, samples, Similarity};
use crate::vector::stroke::Stroke;
use kurbo::{Point, Rect, Vec2};
/// Strokes looked back over for the two copies before the latest.
const LOOK_BACK: usize = 12;
/// A copy is the same shape when the best similarity leaves an rms residual of at most
/// this share of its size.
const SHAPE: f64 = 0.12;
/// The two steps agree when their `a` differ by at most this share of `|a|` (about 5°
/// of turn or 5% of scale)...
const TURN: f64 = 0.09;
/// ...and the first step puts the third copy within this share of the step.
const PLACE: f64 = 0.2;
/// A step turns or scales by at least this much (`|a - 1|`, about 1°)...
const MIN_TURN: f64 = 0.02;
/// ...and scales by at most this factor either way (a spiral, not a zoom).
const MAX_SCALE: f64 = 1.3;
/// The hand's prior scatter of a copy's place, as a share of the step...
const MIN_ERROR: f64 = 0.02;
/// ...counted as this many observed misses.
const PRIOR_COPIES: f64 = 3.0;

/// The similarity carrying `from` onto `to`, with its residual as a share of `size`,
/// when they are the same shape (`similarity::relate` with this module's bounds).
fn relate(from: &[Point], to: &[Point], size: f64) -> Option<(Similarity, f64)> {
    similarity::relate(from, to, size, SHAPE, MAX_SCALE).map(|(t, r, _)| (t, r))
}

/// Proposals continuing the sequence that ends with the latest of `strokes` (none, with
/// the reason, when it is complete or too uncertain to go on), or `None` when the
/// latest strokes make no sequence. The steps are read from hand-drawn copies only
/// (`accepted` marks the proposals taken, which repeat the step they were proposed
/// with and say nothing of its error); copies accepted after the latest hand-drawn one
/// count as steps already taken. `offset` is added to the source indices.
pub(super) fn propose(
    strokes: &[Stroke],
    accepted: &[bool],
    count: usize,
    region: Option<Rect>,
    offset: usize,
) -> Option<Suggestions> {
    let n = strokes.len();
    let is_hand = |i: usize| !accepted.get(i).copied().unwrap_or(false);
    let last = (0..n).rev().find(|&i| is_hand(i))?;
    let taken = n - 1 - last;
    if taken > LOOK_BACK {
        return None;
    }
    let recent: Vec<usize> = (n.saturating_sub(LOOK_BACK + 1)..n).collect();
    let sampled: Vec<Option<Vec<Point>>> = (0..n).map(|i| (i >= recent[0]).then(|| samples(&strokes[i]))).collect();
    let size = |i: usize| strokes[i].bounds().size().to_vec2().hypot();
    let same = |i: usize, j: usize| relate(sampled[i].as_ref()?, sampled[j].as_ref()?, size(i));
    // The copies of the latest hand-drawn stroke's shape (hand-drawn or accepted), and
    // the two before it: the most recent of its shape, then of theirs.
    let chain: Vec<usize> = recent.iter().copied().filter(|&i| i == last || same(i, last).is_some()).collect();
    let at = chain.iter().position(|&i| i == last)?;
    let second = *chain[..at].last()?;
    let first = (chain[0]..second).rev().find(|&i| i >= recent[0] && same(i, second).is_some())?;
    let (one, _) = same(first, second)?;
    let (two, _) = same(second, last)?;
    let centre = |i: usize| strokes[i].reference_point();
    let step = centre(second).distance(centre(last));
    // Copies a step apart, not one drawn over another (hatching lies a tenth of its
    // length apart, or closer).
    if step <= (0.02 * size(last)).max(3.0 * strokes[last].width) {
        return None;
    }
    if (two.a - one.a).hypot() > TURN * one.a.hypot() {
        return None;
    }
    // A step that neither turns nor scales is a row's: the lattice reads those, with
    // its own certainty, from every copy.
    if (one.a + two.a - Vec2::new(2.0, 0.0)).hypot() < 2.0 * MIN_TURN {
        return None;
    }
    // The first step must carry the second copy onto the latest: the miss of its centre
    // (where a copy is matched).
    let carry = |t: &Similarity, i: usize| t.carry(&strokes[i]).reference_point();
    if carry(&one, second).distance(centre(last)) > PLACE * step {
        return None;
    }
    // The hand's scatter from every run of three hand-drawn copies of this shape: each
    // copy placed off by `sigma` makes a one-step prediction miss by about
    // `sigma sqrt(6)` (the two copies it is read from and the one it predicts), with
    // `PRIOR_COPIES` prior misses of `MIN_ERROR` of the step, so that three copies are
    // not taken as exact.
    // (A miss counts where the copy predicted is hand-drawn: an accepted one sits where
    // it was predicted.)
    let misses: Vec<f64> = chain[..=at]
        .windows(3)
        .filter(|w| is_hand(w[2]))
        .filter_map(|w| Some(carry(&same(w[0], w[1])?.0, w[1]).distance_squared(centre(w[2]))))
        .collect();
    let prior = (MIN_ERROR * step).powi(2);
    let copies = misses.len() as f64 + PRIOR_COPIES;
    let sigma2 = (misses.iter().sum::<f64>() / 6.0 + PRIOR_COPIES * prior) / copies;
    // A ghost `K` steps past the last hand-drawn copy misses the hand's copy by its own
    // scatter, the last copy's, and `K` times the step's error (read from `m` steps).
    let m = (chain[..=at].iter().filter(|&&i| is_hand(i)).count().saturating_sub(1)).max(2) as f64;
    let miss_at = |k: usize| (sigma2 * (2.0 + 2.0 * (k * k) as f64 / m)).sqrt();
    let reach = super::certainty::reach(copies);
    // The mean step, placed so that it carries the second copy's centre of mass onto the
    // latest's.
    let a = (one.a + two.a) * 0.5;
    let (s2, s3) = (sampled[second].as_ref()?, sampled[last].as_ref()?);
    let t = Similarity { a, b: centroid(s3).to_vec2() - mul(a, centroid(s2).to_vec2()) };
    let tol = TOLERANCE * step;
    let mut out = Suggestions::default();
    // From the latest stroke (a copy accepted after the last hand-drawn one is the
    // step already taken).
    let latest = n - 1;
    let mut from: Vec<Point> = strokes[latest].points.iter().map(|&[x, y]| Point::new(x, y)).collect();
    let mut scale = 1.0;
    let mut why = "The sequence is complete here: its next copy would fall on a drawn one or off the canvas.";
    for k in 1..=count {
        if reach * miss_at(taken + k) > tol {
            why = "The copies drawn so far leave the next ones too uncertain: draw one more.";
            break;
        }
        from = from.iter().map(|&p| t.apply(p)).collect();
        scale *= a.hypot();
        let mut ghost = strokes[latest].clone();
        ghost.points = from.iter().map(|p| [p.x, p.y]).collect();
        ghost.width *= scale;
        let c = ghost.reference_point();
        // Off the canvas, or onto a stroke already drawn (a ring closing): the end.
        if region.is_some_and(|r| !r.contains(c))
            || strokes.iter().any(|s| s.reference_point().distance(c) < 0.5 * step)
        {
            break;
        }
        out.strokes.push(ghost);
        out.confidence.push(super::FALLOFF.powi(k as i32));
        out.sources.push((latest + offset) as u32);
        out.cells.push([k as i64, 0]);
    }
    // (Found, with nothing to add: said, so the page does not read "no repetition".)
    if out.strokes.is_empty() {
        out.reason = Some(why.into());
    }
    Some(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A petal: a loop from the centre out along angle `theta`.
    fn petal(centre: Point, theta: f64, r: f64) -> Stroke {
        let pts = (0..=20)
            .map(|k| {
                let t = k as f64 / 20.0 * std::f64::consts::TAU;
                let (along, across) = (0.5 * r * (1.0 - t.cos()), 0.18 * r * t.sin());
                let (c, s) = (theta.cos(), theta.sin());
                [centre.x + along * c - across * s, centre.y + along * s + across * c]
            })
            .collect();
        Stroke::new(pts, 2.0, None)
    }

    #[test]
    fn a_ring_is_completed_and_stops_where_it_closes() {
        let c = Point::new(200.0, 200.0);
        let step = std::f64::consts::TAU / 8.0;
        let drawn: Vec<Stroke> = (0..3).map(|k| petal(c, k as f64 * step, 60.0)).collect();
        let s = propose(&drawn, &[], 8, None, 0).expect("a ring of petals continues");
        assert!(s.strokes.len() >= 3, "{} proposed", s.strokes.len());
        for (k, g) in s.strokes.iter().enumerate() {
            let want = petal(c, (3 + k) as f64 * step, 60.0).reference_point();
            assert!(g.reference_point().distance(want) < 1.0, "petal {k}: {:?} vs {want:?}", g.reference_point());
        }
        // Seven drawn: only the eighth is left.
        let seven: Vec<Stroke> = (0..7).map(|k| petal(c, k as f64 * step, 60.0)).collect();
        let s = propose(&seven, &[], 8, None, 0).expect("the last petal");
        assert_eq!(s.strokes.len(), 1);
        let eight: Vec<Stroke> = (0..8).map(|k| petal(c, k as f64 * step, 60.0)).collect();
        let s = propose(&eight, &[], 8, None, 0).expect("a ring, complete");
        assert!(s.strokes.is_empty() && s.reason.as_deref().is_some_and(|r| r.contains("complete")), "{s:?}");
    }

    #[test]
    fn unrelated_strokes_make_no_sequence() {
        let line = |p: [f64; 2], q: [f64; 2]| Stroke::new(vec![p, q], 2.0, None);
        // Three dashes at random places and turns.
        let dashes =
            vec![line([10.0, 10.0], [30.0, 14.0]), line([80.0, 40.0], [84.0, 70.0]), line([20.0, 90.0], [45.0, 80.0])];
        assert!(propose(&dashes, &[], 3, None, 0).is_none());
        // Three different shapes.
        let c = Point::new(100.0, 100.0);
        let mixed = vec![petal(c, 0.0, 40.0), line([0.0, 0.0], [30.0, 0.0]), petal(c, 1.0, 80.0)];
        assert!(propose(&mixed, &[], 3, None, 0).is_none());
    }
}
