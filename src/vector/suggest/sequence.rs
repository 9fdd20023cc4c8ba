//! Repetition by similarity, where the drawing holds no lattice (after Xing et al.,
//! "Autocomplete Painting Repetitions", 2014, which predicts from the last strokes
//! rather than a global structure): petals around a centre (each a turn of the last),
//! leaves along an arc, hatching that turns, a spiral. Each step is a similarity
//! transform `z -> a z + b` (complex `a`: the turn and the scale; `b`: the shift).
//!
//! Found as the seed paper finds it, locally: the latest stroke and the two before it
//! of the same shape up to a similarity (among the last `LOOK_BACK`) make a sequence
//! when the step from the first to the second also carries the second onto the third:
//! the same turn and scale (within `TURN`), and the third where that step puts it
//! (within `PLACE` of the step).
//!
//! Predicted globally, from every copy of the run that ends with the latest (the
//! copies back from it each a step before the next, at most `MAX_RUN` drawn by hand):
//! they are fitted as the orbit of one step (`orbit`), whose turn is snapped to a whole
//! fraction when the run is a ring and the likelihood says which. The next copies are
//! the sites further along, while each is likely within the matching tolerance of the
//! hand's copy (the orbit's own expected miss, inflated where the run's own copies
//! were missed by more when predicted from those before them: a stem that bends the
//! other way, an S), and never onto a drawn stroke (a ring stops where it closes).
//!
//! Departs from the lattice model and from the seed paper: shapes are compared up to
//! rotation and scale here (a petal turned is the same petal), and only motifs of one
//! stroke are carried on.

use super::drift::drift;
use super::orbit::{bend_from_places, cost, Orbit, Placed, Shapes};
use super::turning::{turning, Relation};
use super::{Suggestions, HAND_TO_PLACEMENT, TOLERANCE};
use crate::rng::Rng;
use crate::vector::chain::ring_steps;
use crate::vector::classify::median;
use crate::vector::similarity::{self, centroid, mul, samples, Similarity};
use crate::vector::stroke::Stroke;
use kurbo::{Point, Rect, Vec2};
use std::f64::consts::TAU;

/// Strokes looked back over for the two copies before the latest...
const LOOK_BACK: usize = 16;
/// ...and copies of its shape, as far back as this many strokes (a motif of three
/// strokes drawn sixteen strokes back is five copies: too few to read an S-curve's
/// bend from, and ghosts went on round its first bend, 16-40 off at a step of 41).
const LOOK_BACK_COPIES: usize = 32;
/// A copy is the same shape when the best similarity leaves an rms residual of at most
/// this share of its size.
pub(super) const SHAPE: f64 = 0.12;
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
/// A bend that has held its sign over `L` steps (the run and its lead-in) is a stretch
/// of a stem whose turn may reverse: a sine turn that has kept its sign half a period
/// changes its bend by up to `bend π / L` a step. A line through the turns misses that
/// change quadratically ahead of the hand-drawn copies; this share of it is counted in
/// the next copies' expected miss (leaves over a wavy stem's crest: the bend read on its
/// rising side carried the ghosts past the crest, 22 off at a step of 40).
const BEND_CHANGE: f64 = 0.25;
/// A bend of more than this (radians a step, per step: 0.7 degree) is carried one
/// copy past the last hand-drawn one only (leaves over the top of a Bézier S: the turn
/// read growing from 7 to 15 degrees a step fell to 14 and 10, and the ghost two copies
/// on missed by 17-27 at a step of 44; a bend of 0.013, read where the places say it,
/// put one 15.6 off at a step of 41; an arc's noise reads up to 0.003).
const CLEAR_BEND: f64 = 0.012;
/// A bend is taken where it passes this many of its standard errors (else a run turns
/// alike at every step)...
const BEND_SURE: f64 = 3.0;
/// ...and otherwise is held to none, a run of copies mostly turning alike at every step
/// (a ring, an arc, a spiral: Xing's local similarity), with a prior standard
/// deviation of this much (radians a step, per step) for what it may hide.
const BEND_PRIOR: f64 = 0.02;
/// Why nothing (more) is proposed while the sequence goes on.
const UNCERTAIN: &str = "The copies drawn so far leave the next ones too uncertain: draw one more.";
/// Why nothing is proposed where copies repeat but do not yet show the next step.
pub(super) const UNFOLLOWED: &str = "The copies drawn so far do not yet show where the next one goes: draw one more.";
/// ...the latest four each a step apart within this factor either way (a leaf's
/// centre swings round its base as the stem turns: leaves 40 apart along a sine 50 high
/// and 250 long lay 25 to 60 apart)...
const UNFOLLOWED_SPACING: f64 = 0.6;
/// ...and the path through them turns by at most this much a step (leaves along that
/// sine turn by up to 1.3 radians; dashes dropped at random, none of 288 prefixes
/// passed).
const UNFOLLOWED_TURN: f64 = 1.6;
/// A run that does not pass the local test holds at least four hand-drawn copies, its
/// lead-in counted (a stem that bends on, past ghosts accepted from its earlier turn),
/// each within this share of the step of its site on the run's orbit.
const RUN_PLACE: f64 = 0.15;
/// A run's own copies, predicted from those before them, may miss by up to this many
/// expected misses before the model is taken to be off (a Rayleigh miss passes it
/// 98% of the time).
const BACKTEST: f64 = 2.0;

/// The similarities carrying `from` onto `to`, with their residual as a share of
/// `size`, when they are the same shape (`similarity::relations` with this module's
/// bounds), the smallest turn first.
pub(super) fn relations(from: &[Point], to: &[Point], size: f64) -> Vec<(Similarity, f64)> {
    similarity::relations(from, to, size, SHAPE, MAX_SCALE).into_iter().map(|(t, r, _)| (t, r)).collect()
}

/// What is asked of a sequence.
#[derive(Clone, Copy, Debug)]
pub(super) struct Ask {
    /// The most copies to propose, in `region` if any.
    pub count: usize,
    pub region: Option<Rect>,
    /// Added to the source indices (the strokes before the latest `MAX_STROKES`).
    pub offset: usize,
    /// With a seed, each proposal is a random hand-drawn copy carried to its site.
    pub seed: Option<u64>,
    /// Steps that neither turn nor scale are taken too: where the lattice has read no
    /// repetition, or a row too loosely to propose from (hatching along a contour that
    /// bends a little); not within a copy being drawn (the parallel bars of one motif).
    pub rows: bool,
}

/// The drawing as the sequence reads it: its strokes, which were accepted proposals,
/// and the recent ones' samplings.
struct Drawing<'a> {
    strokes: &'a [Stroke],
    accepted: &'a [bool],
    sampled: Vec<Option<Vec<Point>>>,
}

impl Drawing<'_> {
    fn hand(&self, i: usize) -> bool {
        !self.accepted.get(i).copied().unwrap_or(false)
    }

    fn size(&self, i: usize) -> f64 {
        self.strokes[i].bounds().size().to_vec2().hypot()
    }

    /// The steps from copy `i` to copy `j` with their shape residual, when they are one
    /// shape (more than one where the shape looks the same turned: an ellipse half round).
    fn steps(&self, i: usize, j: usize) -> Vec<(Similarity, f64)> {
        match (&self.sampled[i], &self.sampled[j]) {
            (Some(a), Some(b)) => relations(a, b, self.size(i)),
            _ => Vec::new(),
        }
    }

    /// The step from copy `i` to copy `j`, the smallest turn where several fit.
    fn same(&self, i: usize, j: usize) -> Option<(Similarity, f64)> {
        self.steps(i, j).into_iter().next()
    }

    /// The step from copy `i` to copy `j` that turns nearest `turn` (radians).
    fn near(&self, i: usize, j: usize, turn: f64) -> Option<(Similarity, f64)> {
        let off = |t: &Similarity| {
            let d = (t.turn() - turn).rem_euclid(TAU);
            d.min(TAU - d)
        };
        self.steps(i, j).into_iter().min_by(|x, y| off(&x.0).total_cmp(&off(&y.0)))
    }

    /// Where a copy is, for the orbit: the centre of its sampling (a similarity carries
    /// it as it carries the copy).
    fn z(&self, i: usize) -> Point {
        centroid(self.sampled[i].as_ref().expect("recent strokes are sampled"))
    }
}

/// What a run of copies says: the orbit they lie on and, for a ring, its count; and how
/// far off the orbit's bend may be (radians a step, per step).
struct Model {
    orbit: Orbit,
    closes: Option<i64>,
    bend_error: f64,
}

/// The orbit through `run` (copies in order along the step, `step` apart), with its
/// step read from the hand-drawn copies' shapes and places; `fallback` is the step to
/// read the shapes' turn from when no two consecutive copies are hand-drawn.
fn model(d: &Drawing, run: &[usize], step: f64, fallback: [Vec2; 2], lead: Option<(usize, usize)>) -> Option<Model> {
    let copies: Vec<Placed> = run
        .iter()
        .enumerate()
        .map(|(t, &i)| Placed {
            t: t as i64,
            z: d.z(i),
            weight: if d.hand(i) { 1.0 } else { ACCEPTED_WEIGHT },
            hand: d.hand(i),
        })
        .collect();
    // What the shapes say of the step: each hand-drawn copy against the next hand-drawn
    // one along the run, however many steps on (an accepted copy is turned by the step
    // it was proposed with, and says nothing of it).
    let hands: Vec<usize> = (0..run.len()).filter(|&k| d.hand(run[k])).collect();
    let expected = ((fallback[0] + fallback[1]) * 0.5).atan2();
    let mut relations: Vec<Relation> = hands
        .windows(2)
        .filter_map(|w| {
            let span = w[1] - w[0];
            let (t, r) = d.near(run[w[0]], run[w[1]], span as f64 * expected)?;
            // (Unwrapped to the whole turns `span` steps of about the expected turn make.)
            let turn = t.turn() + TAU * ((span as f64 * expected - t.turn()) / TAU).round();
            Some(Relation { from: w[0] as i64, span, turn, scale: t.scale(), residual: r * d.size(run[w[0]]) })
        })
        .collect();
    // (The lead-in's turn onto the run's first hand-drawn copy, for the bend only.)
    let lead_in = lead.zip(hands.first()).and_then(|((p, back), &h)| {
        let span = h + back;
        let (t, _) = d.near(p, run[h], span as f64 * expected)?;
        let turn = t.turn() + TAU * ((span as f64 * expected - t.turn()) / TAU).round();
        Some(Relation { from: -(back as i64), span, turn, scale: t.scale(), residual: 0.0 })
    });
    if relations.is_empty() {
        relations = fallback
            .iter()
            .enumerate()
            .map(|(k, a)| Relation { from: k as i64, span: 1, turn: a.atan2(), scale: a.hypot(), residual: 0.0 })
            .collect();
    }
    // The hand's scatter before the copies' places show it: as loose as its strokes'
    // shapes wobble (the residual between hand-drawn copies, each point's share half its
    // square; `HAND_TO_PLACEMENT` as for lattices), and no less than `MIN_ERROR` of the
    // step.
    let mut wobble: Vec<f64> = relations.iter().map(|r| r.residual * r.residual / 2.0).collect();
    let wobble = median(&mut wobble);
    let prior = (MIN_ERROR * step).powi(2).max(HAND_TO_PLACEMENT * wobble);
    // A hand that misplaces a copy by `e` turns it by about `e` over its radius: the
    // prior error of a relation's turn, no less than `TURN_ERROR`.
    let size = run.iter().map(|&i| d.size(i)).sum::<f64>() / run.len() as f64;
    let turn_prior = TURN_ERROR.powi(2).max(prior / (0.5 * size).powi(2));
    let turning = turning(&relations, lead_in);
    let steps = relations.iter().map(|r| r.span).sum::<usize>() as f64;
    let scale = (relations.iter().map(|r| r.scale.ln()).sum::<f64>() / steps).exp();
    let scale_spread = relations.iter().map(|r| (r.scale.ln() - r.span as f64 * scale.ln()).powi(2)).sum::<f64>();
    let var = (turning.spread + scale_spread + PRIOR_PAIRS * turn_prior) / (turning.dof + PRIOR_PAIRS);
    let shapes_at = |bend: f64| {
        let first = turning.first_given(bend);
        Shapes {
            mean: Vec2::new(first.cos(), first.sin()) * scale,
            var,
            // (The turns of consecutive relations share a copy, whose own turn adds to
            // one and takes from the next: their sum is the last copy's against the
            // first's, so the mean errs by one relation's error over the steps, not
            // their root; less well known where a bend is read too.)
            pairs: steps * steps / if bend != 0.0 { 4.0 } else { 1.0 },
            bend,
        }
    };
    // The bend, from the shapes' turns and the places together (see `bend_from_places`):
    // taken where it is clear of its error (`BEND_SURE`), else none, its error then the
    // bend read and its error, both shrunk by the prior (`BEND_PRIOR`).
    let (bend, bend_error) = match turning.slope {
        Some((slope, se)) => match bend_from_places(&copies, &shapes_at, prior, slope) {
            Some((placed, information)) => {
                let precision = 1.0 / (se * se).max(1e-12) + information;
                let both = (slope / (se * se).max(1e-12) + placed * information) / precision;
                let error = precision.sqrt().recip();
                if both.abs() > BEND_SURE * error {
                    (both, error)
                } else {
                    // (Held to no bend, as a run of copies mostly is: what bend it may
                    // still hide, given that prior.)
                    let shrink = BEND_PRIOR.powi(2) / (BEND_PRIOR.powi(2) + error * error);
                    (0.0, both.abs() * shrink + (shrink * error * error).sqrt())
                }
            }
            None => (turning.bend, turning.bend_error),
        },
        None => (turning.bend, turning.bend_error),
    };
    let shapes = shapes_at(bend);
    let mut orbit = Orbit::fit(&copies, shapes, prior)?;
    // A ring closes when its turn is about a whole fraction of a turn (see
    // `chain::ring_steps`): snapped to that whole number of copies or one either side,
    // whichever the copies' places and shapes bear out best (`orbit::cost`: the free
    // turn from three petals of eight at 5% may read nine), unless the places then fit
    // much worse than with the free turn.
    let mut closes = None;
    if let Some(c) = orbit.centre() {
        let radius = copies.iter().map(|k| k.z.distance(c)).sum::<f64>() / copies.len() as f64;
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
    // (A ring closes whole: its turn holds by construction; unless a lead-in shows the
    // turn changing into it, as where four leaves over a wavy stem's crest turn as
    // petals of nine would: the stem turns back after them.)
    let bend_error = if closes.is_some() && lead.is_none() { 0.0 } else { bend_error };
    Some(Model { orbit, closes, bend_error })
}

/// How the latest copy follows the two before it, taken every `stride`-th of its shape
/// back along `chain` (the strokes of its shape, the latest at `at`).
struct Begun {
    stride: usize,
    /// The steps from the first copy to the second, and from the second to the latest.
    one: Similarity,
    two: Similarity,
    /// The distance from the second copy to the latest.
    step: f64,
    /// The two steps alike, and the first carrying the second copy onto the latest (the
    /// miss of its centre, where a copy is matched). Where they are not (a stem that
    /// bends on, past copies accepted from its earlier turn), the whole run must bear
    /// the sequence out instead (`RUN_PLACE`).
    local: bool,
    /// The two steps are unlike outright (`FOLLOW_TURN`): no run of copies one step
    /// apart, but perhaps one of copies `stride` apart in a motif of several.
    apart: bool,
}

/// A proposed stroke is on a drawn one of its shape when its centre lies within this
/// share of the step of it (the matching tolerance).
const DRAWN: f64 = 0.3;

/// Copies of a motif holding up to this many strokes of one shape are followed.
const MAX_STRIDE: usize = 4;

fn begin(d: &Drawing, chain: &[usize], at: usize, stride: usize) -> Option<Begun> {
    let last = chain[at];
    let second = chain[at.checked_sub(stride)?];
    let centre = |i: usize| d.strokes[i].reference_point();
    let first = if stride == 1 {
        (chain[0]..second).rev().find(|&i| d.same(i, second).is_some())?
    } else {
        // (The latest copy's strokes of this shape lie on one another, as a petal's two
        // arcs do, not a step apart: four leaves along a stem are no motif of four.)
        let apart = |i: usize| centre(i).distance(centre(last)) > 0.5 * d.size(i).max(d.size(last));
        if chain[at + 1 - stride..at].iter().any(|&i| apart(i)) {
            return None;
        }
        let first = chain[at.checked_sub(2 * stride)?];
        d.same(first, second)?;
        first
    };
    let step = centre(second).distance(centre(last));
    // Of the steps that fit both pairs (a loop that looks the same turned half round
    // fits either way), the pair that agree and carry the second copy nearest the
    // latest: the places say which way the copies turn.
    let (one, two) = {
        let (ones, twos) = (d.steps(first, second), d.steps(second, last));
        let miss = |o: &Similarity, t: &Similarity| {
            (t.a - o.a).hypot() / o.a.hypot().max(1e-9)
                + o.carry(&d.strokes[second]).reference_point().distance(centre(last)) / step.max(1e-9)
        };
        let pairs = ones.iter().flat_map(|o| twos.iter().map(move |t| (o.0, t.0)));
        pairs.min_by(|x, y| miss(&x.0, &x.1).total_cmp(&miss(&y.0, &y.1)))?
    };
    let agree = (two.a - one.a).hypot();
    let local = agree <= TURN * one.a.hypot()
        && one.carry(&d.strokes[second]).reference_point().distance(centre(last)) <= PLACE * step;
    Some(Begun { stride, one, two, step, local, apart: agree > FOLLOW_TURN * one.a.hypot() })
}

/// The strokes of the copy that ends with `run[h]` drawn since the copy before it
/// (`run[h - 1]`) that repeat one of the copy before that, carried on by the step from
/// that copy to this one (the one turning nearest `turn`) within `PLACE` of the step: a
/// motif's other strokes (a petal's second arc, a leaf's midrib, its stalk), in drawing
/// order.
fn companions(d: &Drawing, run: &[usize], h: usize, step: f64, turn: f64) -> Vec<usize> {
    let (Some(&before), Some(&prev)) = (h.checked_sub(2).map(|x| &run[x]), h.checked_sub(1).map(|x| &run[x])) else {
        return Vec::new();
    };
    let last = run[h];
    let Some((carry, _)) = d.near(prev, last, turn) else { return Vec::new() };
    let centre = |i: usize| d.strokes[i].reference_point();
    (prev + 1..last)
        .filter(|&c| {
            (before + 1..prev).any(|o| {
                d.same(o, c).is_some()
                    && carry.carry(&d.strokes[o]).reference_point().distance(centre(c)) <= PLACE * step
            })
        })
        .collect()
}

/// How many times further off than it expected a model of the run has been: each of
/// the last two hand-drawn copies predicted from the run before it (one and two steps
/// ahead, read with the run's lead-in, which a stem's bend is read from and which counts
/// as one of the three hand-drawn copies a model needs: a bend read from the lead-in
/// and two copies has no degree of freedom left to show it wrong), its miss over
/// the miss the model expected. 1 unless some miss passes
/// `BACKTEST` (a stem that bends the other way is missed by several times that).
fn backtest(d: &Drawing, run: &[usize], step: f64, fallback: [Vec2; 2], lead: Option<(usize, usize)>) -> f64 {
    let hands: Vec<usize> = (0..run.len()).filter(|&k| d.hand(run[k])).collect();
    let mut worst: f64 = 1.0;
    for (target, ahead) in [(1, 1), (1, 2), (2, 1)] {
        let Some(&k) = hands.len().checked_sub(target).and_then(|x| hands.get(x)) else { continue };
        let Some(before) = k.checked_sub(ahead - 1) else { continue };
        let sub = &run[..before];
        if sub.iter().filter(|&&i| d.hand(i)).count() + usize::from(lead.is_some()) < 3 {
            continue;
        }
        let Some(m) = model(d, sub, step, fallback, lead) else { continue };
        let ratio = m.orbit.at(k as i64).distance(d.z(run[k])) / m.orbit.miss(k as i64).max(1e-9);
        if ratio > BACKTEST {
            worst = worst.max(ratio / BACKTEST);
        }
    }
    worst
}

/// How far off the turns' line puts copy `t` (in steps), where the bend `bend` may
/// change (`BEND_CHANGE`): a turn off by `c (h + i)^2 / 2` at step `i` past the last
/// hand-drawn copy (`h` half the hand-drawn copies' span, less the mean square the line
/// absorbs over them), summed over the steps. Counted from the hand-drawn copies: an
/// accepted one repeats the line and says nothing of its change.
fn bend_change(bend: f64, (first_hand, last_hand): (i64, i64), lead: usize, t: i64) -> f64 {
    let span = (last_hand - first_hand) as f64;
    let c = BEND_CHANGE * bend.abs() * std::f64::consts::PI / (span + lead as f64).max(1.0);
    let h = 0.5 * span;
    0.5 * c * (1..=t - last_hand).map(|i| (h + i as f64).powi(2) - h * h / 3.0).sum::<f64>()
}

/// Proposals continuing the sequence that ends with the latest of `strokes` (none, with
/// the reason, when it is complete or too uncertain to go on), or `None` when the
/// latest strokes make no sequence. The steps are read from hand-drawn copies only
/// (`accepted` marks the proposals taken, which repeat the step they were proposed
/// with and say nothing of its error); copies accepted after the latest hand-drawn one
/// count as steps already taken.
pub(super) fn propose(strokes: &[Stroke], accepted: &[bool], ask: &Ask) -> Option<Suggestions> {
    let n = strokes.len();
    let lookback = n.saturating_sub(LOOK_BACK_COPIES + 1);
    let d =
        Drawing { strokes, accepted, sampled: (0..n).map(|i| (i >= lookback).then(|| samples(&strokes[i]))).collect() };
    let last = (0..n).rev().find(|&i| d.hand(i))?;
    if n - 1 - last > LOOK_BACK {
        return None;
    }
    let (found, parts) = follow(&d, ask, last)?;
    // A motif's largest stroke shows its turn best (a stalk a few pixels long reads it
    // loosely, and put ghosts over the top of a Bézier arch 15-25 off at a step of 41,
    // where its leaves showed the turn changing): where the latest copy holds a
    // hand-drawn stroke this much larger than the latest, the copies follow that one's,
    // and where it says nothing goes on yet, nothing is proposed.
    let largest = parts.into_iter().filter(|&i| d.hand(i)).max_by(|&x, &y| d.size(x).total_cmp(&d.size(y)));
    match largest.filter(|&b| d.size(b) > LARGER * d.size(last)).and_then(|b| follow(&d, ask, b)) {
        Some((better, _)) => Some(better),
        None => Some(found),
    }
}

/// A motif's stroke is followed in place of the latest when it is this many times the
/// latest's size.
const LARGER: f64 = 1.5;

/// `propose` carrying on the copies of stroke `last` (hand-drawn, among the latest
/// `LOOK_BACK`), with the other strokes of its latest copy carried along.
fn follow(d: &Drawing, ask: &Ask, last: usize) -> Option<(Suggestions, Vec<usize>)> {
    let Ask { count, region, offset, seed, rows } = *ask;
    let strokes = d.strokes;
    let n = strokes.len();
    let lookback = n.saturating_sub(LOOK_BACK_COPIES + 1);
    // The copies of the latest hand-drawn stroke's shape (hand-drawn or accepted), and
    // the two before it: the most recent of its shape, then of theirs; or, where those
    // steps disagree outright, every `stride`-th copy of its shape (a motif holding that
    // many strokes of one shape: a petal drawn as two mirrored arcs).
    let mut chain: Vec<usize> =
        (lookback..n).rev().filter(|&i| i == last || d.same(i, last).is_some()).take(LOOK_BACK + 1).collect();
    chain.reverse();
    let at = chain.iter().position(|&i| i == last)?;
    let start = {
        let one = begin(d, &chain, at, 1);
        match one {
            Some(b) if b.local || !b.apart => Some(b),
            _ => (2..=MAX_STRIDE).filter_map(|k| begin(d, &chain, at, k)).find(|b| b.local).or(one),
        }
    }?;
    let Begun { stride, one, two, step, local, .. } = start;
    let centre = |i: usize| strokes[i].reference_point();
    // Copies a step apart, not one drawn over another (hatching lies a tenth of its
    // length apart, or closer).
    if step <= (0.02 * d.size(last)).max(3.0 * strokes[last].width) {
        return None;
    }
    // A step that neither turns nor scales is a row's: the lattice reads those, with
    // its own certainty, from every copy.
    if !rows && (one.a + two.a - Vec2::new(2.0, 0.0)).hypot() < 2.0 * MIN_TURN {
        return None;
    }
    // The run: copies of this shape back from the latest, each a step before the next
    // (a second ring, begun after the first closed, is a run of its own).
    let mean = (one.a + two.a) * 0.5;
    // (Of a motif of several strokes of one shape, the copies of the latest's own.)
    let latest = at + (chain.len() - 1 - at) / stride * stride;
    let mut run = vec![chain[latest]];
    let mut cut = None;
    for (k, &p) in chain[..latest].iter().enumerate().rev().filter(|(k, _)| (latest - k) % stride == 0) {
        let cur = *run.last()?;
        let gap = centre(p).distance(centre(cur));
        let near = (0.5 * step..=2.0 * step).contains(&gap);
        let linked =
            d.near(p, cur, mean.atan2()).is_some_and(|(t, _)| (t.a - mean).hypot() <= FOLLOW_TURN * mean.hypot());
        if !linked || !near || run.iter().filter(|&&i| d.hand(i)).count() >= MAX_RUN {
            cut = (near && !linked).then_some(k);
            break;
        }
        run.push(p);
    }
    // Where the run stops at a copy that turns too differently to join it, the nearest
    // hand-drawn copy from there back (a step apart each) is its lead-in, so many steps
    // before the run: it shows how the turn is changing (a stem that bends on).
    let mut lead = None;
    if let Some(k) = cut {
        let mut back = 1;
        let mut at = k;
        loop {
            if d.hand(chain[at]) {
                lead = Some((chain[at], back));
                break;
            }
            let gap = at.checked_sub(stride).map(|b| centre(chain[b]).distance(centre(chain[at])));
            if back >= 4 || !gap.is_some_and(|g| (0.5 * step..=2.0 * step).contains(&g)) {
                break;
            }
            at -= stride;
            back += 1;
        }
    }
    run.reverse();
    // (Accepted copies after the latest hand-drawn one that do not follow from it are
    // no run of its.)
    if !run.contains(&last) {
        return None;
    }
    // Where no step carries the copies on (a stem that bends, mid-way), they may still
    // repeat: the latest four of one shape each about a step on from the one before
    // (`UNFOLLOWED_SPACING`), along a path that turns by less than `UNFOLLOWED_TURN` a
    // step (dashes scattered anywhere seldom are), and the page says so, not "no
    // repetition yet" with seventeen leaves drawn.
    let unfollowed = || {
        let latest: Vec<usize> = (0..4).rev().filter_map(|k| at.checked_sub(k * stride).map(|x| chain[x])).collect();
        let moves: Vec<Vec2> = latest.windows(2).map(|w| centre(w[1]) - centre(w[0])).collect();
        let spaced = moves.len() == 3
            && moves.iter().all(|m| (UNFOLLOWED_SPACING * step..=step / UNFOLLOWED_SPACING).contains(&m.hypot()))
            && moves.windows(2).all(|w| w[0].cross(w[1]).atan2(w[0].dot(w[1])).abs() < UNFOLLOWED_TURN);
        spaced.then(|| Suggestions { reason: Some(UNFOLLOWED.into()), ..Default::default() })
    };
    let Some(Model { orbit, closes, bend_error }) = model(d, &run, step, [one.a, two.a], lead) else {
        return unfollowed().map(|s| (s, Vec::new()));
    };
    // A step turning by more than a ring of two and a half copies would (about half a
    // turn) carries each copy back near the one before the last: nothing goes on by it.
    // (Dashes dropped at random, each about a half turn of the one before, were called
    // a complete ring: 14 of 288 prefixes.)
    if orbit.a.atan2().abs() > TAU / 2.5 {
        return None;
    }
    if !local {
        let hand: Vec<usize> = (0..run.len()).filter(|&t| d.hand(run[t])).collect();
        if hand.len() + usize::from(lead.is_some()) < 4
            || hand.iter().any(|&t| orbit.at(t as i64).distance(d.z(run[t])) > RUN_PLACE * step)
        {
            return unfollowed().map(|s| (s, Vec::new()));
        }
    }
    let inflate = backtest(d, &run, step, [one.a, two.a], lead);
    let reach = super::certainty::reach(orbit.copies);
    let mut out = Suggestions::default();
    let end = run.len() as i64 - 1;
    let hands: Vec<usize> = (0..run.len()).filter(|&t| d.hand(run[t])).collect();
    // The latest copy's other strokes, carried on with it; a ghost is on a drawn stroke
    // within half the step or half the nearest two of the copy's strokes lie apart.
    let h = run.iter().position(|&i| i == last)?;
    let parts = companions(d, &run, h, step, orbit.a.atan2());
    // (A copy's strokes may share a centre, a leaf's two halves and its midrib: a ghost
    // is on a drawn stroke that it carries onto about unturned, unscaled and unmoved.)
    let drawn = |g: &Stroke, here: f64| {
        let p = g.reference_point();
        let mut near = strokes.iter().filter(|s| s.reference_point().distance(p) < 0.5 * here).peekable();
        near.peek().is_some() && {
            let (mine, size) = (samples(g), g.bounds().size().to_vec2().hypot());
            let c = centroid(&mine);
            near.any(|s| {
                relations(&mine, &samples(s), size).iter().any(|(t, _)| {
                    (t.a - Vec2::new(1.0, 0.0)).hypot() < FOLLOW_TURN && t.apply(c).distance(c) < DRAWN * here
                })
            })
        }
    };
    // The latest copy's other strokes carried to copy `t`, where none is drawn yet (the
    // copy that closes a ring may lack one).
    let parts_at = |t: i64, here: f64| -> Vec<(Stroke, usize)> {
        let turn = orbit.turn(h as i64, t);
        let to = Similarity { a: turn, b: orbit.at(t).to_vec2() - mul(turn, d.z(last).to_vec2()) };
        parts
            .iter()
            .map(|&c| (to.carry(&strokes[c]), c))
            .filter(|(g, _)| {
                let p = g.reference_point();
                region.is_none_or(|r| r.contains(p)) && !drawn(g, here)
            })
            .collect()
    };
    let push = |out: &mut Suggestions, ghost: Stroke, src: usize, k: i64| {
        out.strokes.push(ghost);
        out.confidence.push(super::FALLOFF.powi(k as i32));
        out.sources.push((src + offset) as u32);
        out.cells.push([k, 0]);
    };
    let mut rng = seed.map(Rng::new);
    let mut why = "The sequence is complete here: its next copy would fall on a drawn one or off the canvas.";
    for k in 1..=count as i64 {
        let t = end + k;
        let site = orbit.at(t);
        let here = site.distance(orbit.at(t - 1));
        // Where a ring closes (at its count, or round onto the run's own first copies: a
        // ring, whole, even where its count was never sure enough to snap, three petals
        // of six, three accepted), what is left of the copy before its first.
        if closes.is_some_and(|c| t >= c)
            || (orbit.centre().is_some() && run.iter().any(|&i| d.z(i).distance(site) < 0.5 * here))
        {
            for (g, c) in parts_at(t, here) {
                push(&mut out, g, c, k);
            }
            why = "The ring is complete: draw the next one.";
            break;
        }
        // An open curve is not continued further past its last hand-drawn copy than
        // the hand-drawn copies span: a stem may bend the other way past what they
        // show (a ring that closes is known whole).
        let (first_hand, last_hand) = (hands[0] as i64, *hands.last()? as i64);
        // A clear bend, no further than the next copy: when it stops (the top of an S,
        // where the turn that grew falls again) the copies before do not say. (Once
        // that copy is accepted, nothing more is proposed till one is drawn by hand.)
        if closes.is_none()
            && (t - last_hand > (last_hand - first_hand).max(1) || (orbit.bend.abs() > CLEAR_BEND && t - last_hand > 1))
        {
            why = UNCERTAIN;
            break;
        }
        // (A bend off by `bend_error` drifts the copies past the hand-drawn ones: see
        // `drift`; a bend that changes, more still.)
        let drift = drift(here, bend_error, (last_hand - first_hand) as f64, (t - last_hand) as f64);
        let change = bend_change(orbit.bend, (first_hand, last_hand), lead.map_or(0, |l| l.1), t);
        let drift = drift.hypot(here * change);
        if reach * (inflate * inflate * orbit.miss(t).powi(2) + drift * drift).sqrt() > TOLERANCE * here {
            why = UNCERTAIN;
            break;
        }
        // A drawn copy carried to the site, turned and scaled by the steps between: the
        // latest hand-drawn one, or with variation a random one.
        let from = match &mut rng {
            Some(r) => hands[r.below(hands.len())],
            None => *hands.last()?,
        };
        let turn = orbit.turn(from as i64, t);
        let src = run[from];
        let ghost = Similarity { a: turn, b: site.to_vec2() - mul(turn, d.z(src).to_vec2()) }.carry(&strokes[src]);
        let c = ghost.reference_point();
        // Off the canvas: the end. Onto a stroke already drawn (a ring closing): what
        // is left of that copy, and the end.
        if region.is_some_and(|r| !r.contains(c)) {
            break;
        }
        if drawn(&ghost, here) {
            if closes.is_some() {
                why = "The ring is complete: draw the next one.";
                for (g, c) in parts_at(t, here) {
                    push(&mut out, g, c, k);
                }
            }
            break;
        }
        for (g, c) in parts_at(t, here) {
            push(&mut out, g, c, k);
        }
        push(&mut out, ghost, src, k);
    }
    // (Found, with nothing to add: said, so the page does not read "no repetition".)
    if out.strokes.is_empty() {
        out.reason = Some(why.into());
    }
    Some((out, parts))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn ask(count: usize) -> Ask {
        Ask { count, region: None, offset: 0, seed: None, rows: false }
    }

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
        let s = propose(&drawn, &[], &ask(8)).expect("a ring of petals continues");
        assert!(s.strokes.len() >= 3, "{} proposed", s.strokes.len());
        for (k, g) in s.strokes.iter().enumerate() {
            let want = petal(c, (3 + k) as f64 * step, 60.0).reference_point();
            assert!(g.reference_point().distance(want) < 1.0, "petal {k}: {:?} vs {want:?}", g.reference_point());
        }
        // Seven drawn: only the eighth is left.
        let seven: Vec<Stroke> = (0..7).map(|k| petal(c, k as f64 * step, 60.0)).collect();
        let s = propose(&seven, &[], &ask(8)).expect("the last petal");
        assert_eq!(s.strokes.len(), 1);
        let eight: Vec<Stroke> = (0..8).map(|k| petal(c, k as f64 * step, 60.0)).collect();
        let s = propose(&eight, &[], &ask(8)).expect("a ring, complete");
        assert!(s.strokes.is_empty() && s.reason.as_deref().is_some_and(|r| r.contains("complete")), "{s:?}");
    }

    #[test]
    fn unrelated_strokes_make_no_sequence() {
        let line = |p: [f64; 2], q: [f64; 2]| Stroke::new(vec![p, q], 2.0, None);
        // Three dashes at random places and turns.
        let dashes =
            vec![line([10.0, 10.0], [30.0, 14.0]), line([80.0, 40.0], [84.0, 70.0]), line([20.0, 90.0], [45.0, 80.0])];
        assert!(propose(&dashes, &[], &ask(3)).is_none());
        // Three different shapes.
        let c = Point::new(100.0, 100.0);
        let mixed = vec![petal(c, 0.0, 40.0), line([0.0, 0.0], [30.0, 0.0]), petal(c, 1.0, 80.0)];
        assert!(propose(&mixed, &[], &ask(3)).is_none());
    }
}
