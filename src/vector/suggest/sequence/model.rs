//! What a run of copies says: the orbit they lie on, its bend and how far off that may
//! be, a ring's count (`model`); how much further off than expected the run's own latest
//! copies were, predicted from those before them (`backtest`); and how far a bend that
//! may change drifts the copies past the hand-drawn ones (`bend_change`).

use super::super::orbit::{bend_from_places, cost, Orbit, Placed, Shapes};
use super::super::turning::{turning, Relation};
use super::super::HAND_TO_PLACEMENT;
use super::Drawing;
use crate::vector::chain::ring_steps;
use crate::vector::classify::median;
use crate::vector::similarity::Similarity;
use kurbo::{Point, Vec2};
use std::f64::consts::TAU;

/// The hand's prior scatter of a copy's place, as a share of the step.
const MIN_ERROR: f64 = 0.02;
/// Weight of an accepted copy in the orbit's fit (a hand-drawn one's is 1).
const ACCEPTED_WEIGHT: f64 = 0.05;
/// The prior error of one pair's turn (`|a|` units, about 1.1 degrees), counted as this
/// many pairs.
const TURN_ERROR: f64 = 0.02;
const PRIOR_PAIRS: f64 = 2.0;
/// A ring's turn is snapped unless the copies' mean square miss then grows past this
/// many times the free fit's.
const SNAP_WORSE: f64 = 2.5;
/// A ring's count is taken when it is this many times likelier than the next best...
const SNAP_SURE: f64 = 20.0;
/// ...judged as though each copy may be turned this much at random (a standard
/// deviation, radians: 2.5 degrees), as a person's hand turns them, however alike the
/// few copies drawn happen to turn: the pair turns of three petals of eight read 47.9
/// and 50.3 degrees (their places 49.0), and a ring of seven was taken, 27 times
/// likelier than eight, its ghosts two and three copies on 0.9 and 1.05 of the step
/// off. A turned copy's centre moves with it, by about half its size times the turn.
const PERSON_TURN: f64 = 0.0436;
/// A person draws copies of one shape at sizes that vary by about this share at random (a
/// standard deviation): the shapes' mean scale over `s` steps, their sizes' last against
/// first, then varies by `sqrt(2)` times it over `s`. A spiral read within `SPIRAL_SURE`
/// of that may be a ring of petals drawn longer and shorter (a ring's petals each 10%
/// longer or shorter at random, `examples/ring_ghosts` with `SIZE=0.1`, were read from
/// three as spirals of 6-9% a step about the ring's centre, their second and third
/// ghosts off the ring). Past three or four copies the bound falls below the 4% at which
/// an orbit is held to a pure turn anyway, and a spiral read is taken as read. (The
/// wider miss makes `backtest` more lenient with such a run too.)
const PERSON_SIZE: f64 = 0.05;
const SPIRAL_SURE: f64 = 2.0;
/// ...and no more than this much less likely than the free turn (minus log-likelihood):
/// leaves of a ring of nine followed every other one turn 78 degrees a step, no whole
/// fraction, and were snapped to a ring of five all the same, the best of four, five
/// and six (ten ghosts wrong at each of two strokes).
const SNAP_FREE: f64 = 8.0;
/// A bend that has held its sign over `L` steps (the run and its lead-in) is a stretch
/// of a stem whose turn may reverse: a sine turn that has kept its sign half a period
/// changes its bend by up to `bend π / L` a step. A line through the turns misses that
/// change quadratically ahead of the hand-drawn copies; this share of it is counted in
/// the next copies' expected miss (leaves over a wavy stem's crest: the bend read on its
/// rising side carried the ghosts past the crest, 22 off at a step of 40).
const BEND_CHANGE: f64 = 0.25;
/// A bend is taken where it passes this many of its standard errors (else a run turns
/// alike at every step)...
const BEND_SURE: f64 = 3.0;
/// ...and otherwise is held to none, a run of copies mostly turning alike at every step
/// (a ring, an arc, a spiral: Xing's local similarity), with a prior standard
/// deviation of this much (radians a step, per step) for what it may hide.
const BEND_PRIOR: f64 = 0.02;
/// The prior where only the places read the bend (not the shapes: see `model`). At 1%
/// of the step, a steady hand: 0.02 took the spiral's acceptance from 86% to 57%, 0.01
/// to 71%; leaves of three strokes along an S then got 0 wrong ghosts of 53 and 12 of
/// 64 (30 of 82 with the bend held to exactly none).
const UNREAD_BEND_PRIOR: f64 = 0.01;

/// A bend read as `read` with standard error `error`: itself where it is clear of that
/// (`BEND_SURE`), else held to none, as a run of copies mostly is, its error then what
/// bend it may still hide given a prior of standard deviation `prior` (both shrunk).
fn held(read: f64, error: f64, prior: f64) -> (f64, f64) {
    if read.abs() > BEND_SURE * error {
        (read, error)
    } else {
        let shrink = prior * prior / (prior * prior + error * error);
        (0.0, read.abs() * shrink + (shrink * error * error).sqrt())
    }
}
/// The weight of the moves' turn, read from the places, against that of turns read
/// from shapes, where the shapes show none (a circle).
const UNSHOWN: f64 = 0.1;
/// A run's own copies, predicted from those before them, may miss by up to this many
/// expected misses before the model is taken to be off (a Rayleigh miss passes it
/// 98% of the time).
const BACKTEST: f64 = 2.0;

/// What a run of copies says: the orbit they lie on and, for a ring, its count; and how
/// far off the orbit's bend may be (radians a step, per step).
pub(super) struct Model {
    pub(super) orbit: Orbit,
    pub(super) closes: Option<i64>,
    pub(super) bend_error: f64,
}

/// What the places of `run` say of its step, for copies that keep their pose as the run
/// bends (`upright`): each step's move against the one before (its turn and scale), where
/// the three copies are hand-drawn.
pub(super) fn place_relations(d: &Drawing, run: &[usize]) -> Vec<Relation> {
    (1..run.len().saturating_sub(1))
        .filter(|&t| (t - 1..=t + 1).all(|k| d.hand(run[k])))
        .filter_map(|t| {
            let (u, v) = (d.z(run[t]) - d.z(run[t - 1]), d.z(run[t + 1]) - d.z(run[t]));
            let r = Similarity::fit(&[u.to_point(), Point::ZERO], &[v.to_point(), Point::ZERO]).0;
            // (Round copies, circles, show their scale
            // by their size, more surely than four places' scatter does: read from the
            // moves, it made spirals of rings of circles.)
            let scale = if d.round(run[t]) { d.size(run[t + 1]) / d.size(run[t]) } else { r.scale() };
            (u.hypot() > 0.0).then(|| Relation { from: t as i64 - 1, span: 1, turn: r.turn(), scale, residual: 0.0 })
        })
        .collect()
}

/// The orbit through `run` (copies in order along the step, `step` apart), with its
/// step read from the hand-drawn copies' shapes (or, where they keep their pose as the
/// run bends, `upright`, from their places' moves) and places; `fallback` is the step to
/// read the turn from when no two consecutive copies are hand-drawn.
pub(super) fn model(
    d: &Drawing,
    run: &[usize],
    step: f64,
    fallback: [Vec2; 2],
    lead: Option<(usize, usize)>,
    upright: bool,
) -> Option<Model> {
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
    let mut relations: Vec<Relation> = if upright {
        place_relations(d, run)
    } else {
        hands
            .windows(2)
            .filter_map(|w| {
                let span = w[1] - w[0];
                let (t, _) = d.near(run[w[0]], run[w[1]], span as f64 * expected)?;
                // (Unwrapped to the whole turns `span` steps of about the expected turn make.)
                let turn = t.turn() + TAU * ((span as f64 * expected - t.turn()) / TAU).round();
                let residual = d.shape_wobble(run[w[0]], run[w[1]], &t);
                Some(Relation { from: w[0] as i64, span, turn, scale: t.scale(), residual })
            })
            .collect()
    };
    // (The lead-in's turn onto the run's first hand-drawn copy, for the bend only.)
    let lead_in = lead.filter(|_| !upright).zip(hands.first()).and_then(|((p, back), &h)| {
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
    // step. (The residual leaves out each point's own jitter, `shape_wobble`: points
    // shaken by 3% of the step made leaves on an arc "too uncertain" at 31 of 70 calls,
    // which the copies' places did not bear out.)
    let mut wobble: Vec<f64> = relations.iter().map(|r| r.residual * r.residual / 2.0).collect();
    let wobble = median(&mut wobble);
    let prior = (MIN_ERROR * step).powi(2).max(HAND_TO_PLACEMENT * wobble);
    // A hand that misplaces a copy by `e` turns it by about `e` over its radius: the
    // prior error of a relation's turn, no less than `TURN_ERROR`.
    let size = run.iter().map(|&i| d.size(i)).sum::<f64>() / run.len() as f64;
    let turn_prior = TURN_ERROR.powi(2).max(prior / (0.5 * size).powi(2));
    let turning = turning(&relations, lead_in);
    let steps = relations.iter().map(|r| r.span).sum::<usize>() as f64;
    let read = relations.iter().map(|r| r.scale.ln()).sum::<f64>() / steps;
    let scale = read.exp();
    let scale_spread = relations.iter().map(|r| (r.scale.ln() - r.span as f64 * read).powi(2)).sum::<f64>();
    let var = (turning.spread + scale_spread + PRIOR_PAIRS * turn_prior) / (turning.dof + PRIOR_PAIRS);
    // (Round copies, circles, show their step in their places
    // alone, which the orbit fits already: what the moves say is counted as a weak
    // prior only, not a second reading of the same places.)
    let shown = !(upright && run.last().is_some_and(|&i| d.round(i)));
    let shapes_at = |bend: f64| {
        let first = turning.first_given(bend);
        Shapes {
            mean: Vec2::new(first.cos(), first.sin()) * scale,
            var,
            // (The turns of consecutive relations share a copy, whose own turn adds to
            // one and takes from the next: their sum is the last copy's against the
            // first's, so the mean errs by one relation's error over the steps, not
            // their root; less well known where a bend is read too.)
            pairs: steps * steps / if bend != 0.0 { 4.0 } else { 1.0 } * if shown { 1.0 } else { UNSHOWN },
            bend,
        }
    };
    // The bend, from the shapes' turns and the places together (see `bend_from_places`):
    // taken where it is clear of its error (`BEND_SURE`), else none (see `held`).
    let (bend, bend_error) = match turning.slope {
        Some((slope, se)) => match bend_from_places(&copies, &shapes_at, prior, slope) {
            // (Where the moves' turns are the places' own, they are not counted twice.)
            Some((placed, information)) if !shown && information > 0.0 => {
                held(placed, information.sqrt().recip(), BEND_PRIOR)
            }
            Some((placed, information)) => {
                let precision = 1.0 / (se * se).max(1e-12) + information;
                let both = (slope / (se * se).max(1e-12) + placed * information) / precision;
                held(both, precision.sqrt().recip(), BEND_PRIOR)
            }
            None => (turning.bend, turning.bend_error),
        },
        // (Too few hand-drawn relations to read a bend from the shapes. Where ghosts were
        // accepted between the hand's copies, which then span more steps than they
        // show, what the places say, or none with the prior's error: read as exactly
        // none, ghosts two and three copies on went past the first bend of an S of
        // leaves of three strokes, 13-40 off at a step of 41.)
        None if hands.last().zip(hands.first()).is_some_and(|(l, f)| l - f + 1 > hands.len()) => {
            match bend_from_places(&copies, &shapes_at, prior, 0.0) {
                Some((placed, information)) if information > 0.0 => {
                    held(placed, information.sqrt().recip(), UNREAD_BEND_PRIOR)
                }
                _ => (turning.bend, turning.bend_error.max(UNREAD_BEND_PRIOR)),
            }
        }
        None => (turning.bend, turning.bend_error),
    };
    let shapes = shapes_at(bend);
    let mut orbit = Orbit::fit(&copies, shapes, prior)?;
    // A spiral read from the shapes' scale where a person's copies of varying size would
    // read it as often (see `PERSON_SIZE`) may be a ring: its sites further on are as
    // uncertain as the scale is off one.
    let scale_error = std::f64::consts::SQRT_2 * PERSON_SIZE / steps;
    if !upright && orbit.scales() && read.abs() < SPIRAL_SURE * scale_error {
        orbit.var_scale = orbit.a.hypot().ln().powi(2);
    }
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
            // (Judged as a person's hand may have drawn them: see `PERSON_TURN`.)
            let var = shapes.var.max(2.0 * PERSON_TURN * PERSON_TURN);
            // (A ring turns alike at every step: each count is judged against the run's
            // mean turn, not the first step's of a bend read from a person's few copies.)
            let judged = Shapes { var, ..shapes_at(0.0) };
            let scatter = orbit.scatter + (0.5 * size * PERSON_TURN).powi(2);
            // (The counts either side of the mean turn's too, where that is another.)
            let mean = judged.mean.y.atan2(judged.mean.x).abs();
            let k_mean = if mean > 0.0 { (TAU / mean).round().min(2.0 * k as f64) as usize } else { k };
            let mut fits: Vec<(usize, Orbit, f64)> = (k.min(k_mean).saturating_sub(1).max(3)..=k.max(k_mean) + 1)
                .filter_map(|k| {
                    let th = TAU / k as f64 * sign;
                    let a = Vec2::new(th.cos(), th.sin());
                    Some((k, orbit.snapped(&copies, a, prior)?, cost(&copies, &judged, a, scatter)))
                })
                .collect();
            fits.sort_by(|x, y| x.2.total_cmp(&y.2));
            // (The costs are minus log-likelihoods: the best count is taken once it is
            // `SNAP_SURE` times likelier than the next; till then the turn stays free,
            // with its error.)
            let sure = fits.get(1).is_none_or(|second| second.2 - fits[0].2 >= SNAP_SURE.ln());
            if let Some((k, snapped, _)) = fits.into_iter().next().filter(|b| {
                let free = cost(&copies, &Shapes { var, ..shapes }, orbit.a, scatter);
                sure && b.1.scatter <= SNAP_WORSE * orbit.scatter && b.2 - free <= SNAP_FREE
            }) {
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

/// How many times further off than it expected a model of the run has been: each of
/// the last two hand-drawn copies predicted from the run before it (one and two steps
/// ahead, read with the run's lead-in, which a stem's bend is read from and which counts
/// as one of the three hand-drawn copies a model needs: a bend read from the lead-in
/// and two copies has no degree of freedom left to show it wrong), its miss over
/// the miss the model expected. 1 unless some miss passes
/// `BACKTEST` (a stem that bends the other way is missed by several times that).
pub(super) fn backtest(
    d: &Drawing,
    run: &[usize],
    step: f64,
    fallback: [Vec2; 2],
    lead: Option<(usize, usize)>,
    upright: bool,
) -> f64 {
    let hands: Vec<usize> = (0..run.len()).filter(|&k| d.hand(run[k])).collect();
    let mut worst: f64 = 1.0;
    for (target, ahead) in [(1, 1), (1, 2), (2, 1)] {
        let Some(&k) = hands.len().checked_sub(target).and_then(|x| hands.get(x)) else { continue };
        let Some(before) = k.checked_sub(ahead - 1) else { continue };
        let sub = &run[..before];
        if sub.iter().filter(|&&i| d.hand(i)).count() + usize::from(lead.is_some()) < 3 {
            continue;
        }
        let Some(m) = model(d, sub, step, fallback, lead, upright) else { continue };
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
pub(super) fn bend_change(bend: f64, (first_hand, last_hand): (i64, i64), lead: usize, t: i64) -> f64 {
    let span = (last_hand - first_hand) as f64;
    let c = BEND_CHANGE * bend.abs() * std::f64::consts::PI / (span + lead as f64).max(1.0);
    let h = 0.5 * span;
    0.5 * c * (1..=t - last_hand).map(|i| (h + i as f64).powi(2) - h * h / 3.0).sum::<f64>()
}
