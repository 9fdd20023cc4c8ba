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

use super::orbit::{cost, pow, Copy, Orbit, Shapes};
use super::{Suggestions, HAND_TO_PLACEMENT, TOLERANCE};
use crate::rng::Rng;
use crate::vector::chain::ring_steps;
use crate::vector::classify::median;
use crate::vector::similarity::{self, centroid, mul, samples, Similarity};
use crate::vector::stroke::Stroke;
use kurbo::{Point, Rect, Vec2};
use std::f64::consts::TAU;
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
/// The hand's prior scatter of a copy's place, as a share of the step.
const MIN_ERROR: f64 = 0.02;
/// Copies further back join the run when their step's `a` is within this share of the
/// latest steps'...
const FOLLOW_TURN: f64 = 0.2;
/// ...and the run holds at most this many hand-drawn copies (a curve that bends the
/// other way, an S, is followed by its latest copies).
const MAX_RUN: usize = 8;
/// Weight of an accepted copy in the orbit's fit (a hand-drawn one's is 1).
const ACCEPTED_WEIGHT: f64 = 0.05;
/// The prior error of one pair's turn (`|a|` units, about 1.1 degrees), counted as this
/// many pairs.
const TURN_ERROR: f64 = 0.02;
const PRIOR_PAIRS: f64 = 2.0;
/// A ring's turn is snapped unless the copies' mean square miss then grows past this
/// many times the free fit's.
const SNAP_WORSE: f64 = 2.5;
/// A ring's count is taken when it is this many times likelier than the next best.
const SNAP_SURE: f64 = 20.0;

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
    seed: Option<u64>,
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
    // The run: copies of this shape back from the latest, each a step before the next
    // (a second ring, begun after the first closed, is a run of its own).
    let mean = (one.a + two.a) * 0.5;
    let mut run = vec![*chain.last()?];
    for &p in chain.iter().rev().skip(1) {
        let cur = *run.last()?;
        let d = centre(p).distance(centre(cur));
        let linked = same(p, cur).is_some_and(|(t, _)| (t.a - mean).hypot() <= FOLLOW_TURN * mean.hypot());
        if !linked || !(0.5 * step..=2.0 * step).contains(&d) || run.iter().filter(|&&i| is_hand(i)).count() >= MAX_RUN
        {
            break;
        }
        run.push(p);
    }
    run.reverse();
    let z = |i: usize| centroid(sampled[i].as_ref().expect("recent strokes are sampled"));
    let copies: Vec<Copy> = run
        .iter()
        .enumerate()
        .map(|(t, &i)| Copy {
            t: t as i64,
            z: z(i),
            weight: if is_hand(i) { 1.0 } else { ACCEPTED_WEIGHT },
            hand: is_hand(i),
        })
        .collect();
    // What the shapes say of the step: each consecutive pair drawn by hand (an accepted
    // copy is turned by the step it was proposed with, and says nothing of it).
    let hand_pairs: Vec<(usize, Vec2)> = run
        .windows(2)
        .enumerate()
        .filter(|(_, w)| is_hand(w[0]) && is_hand(w[1]))
        .filter_map(|(k, w)| Some((k, same(w[0], w[1])?.0.a)))
        .collect();
    let pairs: Vec<Vec2> =
        if hand_pairs.is_empty() { vec![one.a, two.a] } else { hand_pairs.iter().map(|p| p.1).collect() };
    let np = pairs.len() as f64;
    // Consecutive pairs share a copy, whose own turn adds to one pair's and takes from
    // the next's: over a run of pairs the turns sum to the last copy's against the
    // first's, so their mean errs by one pair's error over the count, not its root.
    let segments = 1 + hand_pairs.windows(2).filter(|w| w[1].0 != w[0].0 + 1).count();
    // The hand's scatter before the copies' places show it: as loose as its strokes'
    // shapes wobble (the residual between consecutive hand-drawn copies, each point's
    // share half its square; `HAND_TO_PLACEMENT` as for lattices), and no less than
    // `MIN_ERROR` of the step.
    let mut wobble: Vec<f64> = run
        .windows(2)
        .filter(|w| is_hand(w[0]) && is_hand(w[1]))
        .filter_map(|w| Some((same(w[0], w[1])?.1 * size(w[0])).powi(2) / 2.0))
        .collect();
    let wobble = if wobble.is_empty() { 0.0 } else { median(&mut wobble) };
    let prior = (MIN_ERROR * step).powi(2).max(HAND_TO_PLACEMENT * wobble);
    // A hand that misplaces a copy by `e` turns it by about `e` over its radius: the
    // prior error of a pair's turn, no less than `TURN_ERROR`.
    let radius = 0.5 * run.iter().map(|&i| size(i)).sum::<f64>() / run.len() as f64;
    let turn_prior = TURN_ERROR.powi(2).max(prior / radius.powi(2));
    let shape_mean = pairs.iter().fold(Vec2::ZERO, |s, &a| s + a) / np;
    let spread = pairs.iter().map(|&a| (a - shape_mean).hypot2()).sum::<f64>();
    let shapes = Shapes {
        mean: shape_mean,
        var: (spread + PRIOR_PAIRS * turn_prior) / (np - 1.0 + PRIOR_PAIRS),
        pairs: np * np / segments as f64,
    };
    let mut orbit = Orbit::fit(&copies, shapes, prior)?;
    // A ring closes when its turn is about a whole fraction of a turn (see
    // `chain::ring_steps`): snapped to that whole number of copies or one either side,
    // whichever the copies' places and shapes bear out best (`orbit::cost`: the free
    // turn from three petals of eight at 5% may read nine), unless the places then fit
    // much worse than with the free turn.
    let mut closes = None;
    if let Some(c) = orbit.centre() {
        let radius = copies.iter().map(|k| k.z.distance(c)).sum::<f64>() / copies.len() as f64;
        let size = run.iter().map(|&i| size(i)).sum::<f64>() / run.len() as f64;
        let turned = Similarity { a: orbit.a, b: Vec2::ZERO };
        if let Some(k) = ring_steps(&turned, radius, size, run.len()) {
            let sign = turned.turn().signum();
            let mut fits: Vec<(usize, Orbit, f64)> = (k.saturating_sub(1).max(3)..=k + 1)
                .filter_map(|k| {
                    let th = TAU / k as f64 * sign;
                    let a = Vec2::new(th.cos(), th.sin());
                    Some((k, orbit.snapped(&copies, a, prior)?, cost(&copies, &shapes, a, orbit.scatter)))
                })
                .collect();
            fits.sort_by(|x, y| x.2.total_cmp(&y.2));
            // (The costs are minus log-likelihoods: the best count is taken once it is
            // `SNAP_SURE` times likelier than the next; till then the turn stays free,
            // with its error.)
            let sure = fits.get(1).is_none_or(|second| second.2 - fits[0].2 >= SNAP_SURE.ln());
            if let Some((k, snapped, _)) =
                fits.into_iter().next().filter(|b| sure && b.1.scatter <= SNAP_WORSE * orbit.scatter)
            {
                orbit = snapped;
                closes = Some(k as i64);
            }
        }
    }
    let reach = super::certainty::reach(orbit.copies);
    let mut out = Suggestions::default();
    let end = run.len() as i64 - 1;
    let hands: Vec<usize> = (0..run.len()).filter(|&t| is_hand(run[t])).collect();
    let mut rng = seed.map(Rng::new);
    let mut why = "The sequence is complete here: its next copy would fall on a drawn one or off the canvas.";
    for k in 1..=count as i64 {
        let t = end + k;
        if closes.is_some_and(|c| t >= c) {
            break;
        }
        let site = orbit.at(t);
        let here = site.distance(orbit.at(t - 1));
        if reach * orbit.miss(t) > TOLERANCE * here {
            why = "The copies drawn so far leave the next ones too uncertain: draw one more.";
            break;
        }
        // A drawn copy carried to the site, turned and scaled by the steps between: the
        // latest hand-drawn one, or with variation a random one.
        let from = match &mut rng {
            Some(r) => hands[r.below(hands.len())],
            None => *hands.last()?,
        };
        let turn = pow(orbit.a, t - from as i64);
        let src = run[from];
        let ghost = Similarity { a: turn, b: site.to_vec2() - mul(turn, z(src).to_vec2()) }.carry(&strokes[src]);
        let c = ghost.reference_point();
        // Off the canvas, or onto a stroke already drawn (a ring closing): the end.
        if region.is_some_and(|r| !r.contains(c))
            || strokes.iter().any(|s| s.reference_point().distance(c) < 0.5 * here)
        {
            break;
        }
        out.strokes.push(ghost);
        out.confidence.push(super::FALLOFF.powi(k as i32));
        out.sources.push((src + offset) as u32);
        out.cells.push([k, 0]);
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
        let s = propose(&drawn, &[], 8, None, 0, None).expect("a ring of petals continues");
        assert!(s.strokes.len() >= 3, "{} proposed", s.strokes.len());
        for (k, g) in s.strokes.iter().enumerate() {
            let want = petal(c, (3 + k) as f64 * step, 60.0).reference_point();
            assert!(g.reference_point().distance(want) < 1.0, "petal {k}: {:?} vs {want:?}", g.reference_point());
        }
        // Seven drawn: only the eighth is left.
        let seven: Vec<Stroke> = (0..7).map(|k| petal(c, k as f64 * step, 60.0)).collect();
        let s = propose(&seven, &[], 8, None, 0, None).expect("the last petal");
        assert_eq!(s.strokes.len(), 1);
        let eight: Vec<Stroke> = (0..8).map(|k| petal(c, k as f64 * step, 60.0)).collect();
        let s = propose(&eight, &[], 8, None, 0, None).expect("a ring, complete");
        assert!(s.strokes.is_empty() && s.reason.as_deref().is_some_and(|r| r.contains("complete")), "{s:?}");
    }

    #[test]
    fn unrelated_strokes_make_no_sequence() {
        let line = |p: [f64; 2], q: [f64; 2]| Stroke::new(vec![p, q], 2.0, None);
        // Three dashes at random places and turns.
        let dashes =
            vec![line([10.0, 10.0], [30.0, 14.0]), line([80.0, 40.0], [84.0, 70.0]), line([20.0, 90.0], [45.0, 80.0])];
        assert!(propose(&dashes, &[], 3, None, 0, None).is_none());
        // Three different shapes.
        let c = Point::new(100.0, 100.0);
        let mixed = vec![petal(c, 0.0, 40.0), line([0.0, 0.0], [30.0, 0.0]), petal(c, 1.0, 80.0)];
        assert!(propose(&mixed, &[], 3, None, 0, None).is_none());
    }
}
