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
//! A motif of several strokes (a petal drawn as two arcs, a leaf and its stalk) is
//! followed by one of its strokes, its largest, and its latest copy's other strokes are
//! carried on with it (`copies`), each turned as its own copies turn: with the orbit, or
//! not at all (a fence's rail turns with the arc, its post stays upright).
//!
//! Copies that keep their pose while their places bend (fence posts along an arc,
//! upright; `upright` in `follow`) step by a translation, which carries nothing round
//! the bend: their step's turn is read from their places (each move against the one
//! before, `model::place_relations`), and they are carried to the orbit's sites
//! unturned.
//!
//! Departs from the lattice model and from the seed paper: shapes are compared up to
//! rotation and scale here (a petal turned is the same petal).

mod copies;
mod model;

use self::copies::{begin, companions, part_turns, trailing, Begun, MAX_STRIDE};
use self::model::{backtest, bend_change, model, Model};
use super::drift::{drift, looks_round};
use super::{Suggestions, TOLERANCE};
use crate::rng::Rng;
use crate::vector::similarity::{self, centroid, mul, samples, Similarity};
use crate::vector::stroke::{Stroke, DOT};
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
/// A step turns or scales by at least this much (`|a - 1|`, about 1°)...
const MIN_TURN: f64 = 0.02;
/// ...and scales by at most this factor either way (a spiral, not a zoom).
const MAX_SCALE: f64 = 1.3;
/// Copies further back join the run when their step's `a` is within this share of the
/// latest steps'...
const FOLLOW_TURN: f64 = 0.2;
/// ...and the run holds at most this many hand-drawn copies (a curve that bends the
/// other way, an S, is followed by its latest copies).
const MAX_RUN: usize = 8;
/// A bend of more than this (radians a step, per step: 0.7 degree) is carried one
/// copy past the last hand-drawn one only (leaves over the top of a Bézier S: the turn
/// read growing from 7 to 15 degrees a step fell to 14 and 10, and the ghost two copies
/// on missed by 17-27 at a step of 44; a bend of 0.013, read where the places say it,
/// put one 15.6 off at a step of 41; an arc's noise reads up to 0.003).
const CLEAR_BEND: f64 = 0.012;
/// Copies keep their pose as the run bends (`upright`) where each of the run's shape
/// steps turns by less than this (radians, about 11 degrees: the difference of two
/// copies a hand tilted a few degrees each, at random) and on average by less than
/// `UPRIGHT` of the places' turn, while their places bend steadily
/// (`chain::bend::steady_bend`); the latest two together too. (At 6 degrees a step,
/// posts tilted 3 degrees each and 7% off in length got the next post at 8 of 40
/// calls: one step in a run past it was enough to lose the bend.)
const UPRIGHT_TURN: f64 = 0.2;
pub(super) const UPRIGHT: f64 = 0.4;
/// Why nothing (more) is proposed while the sequence goes on.
use super::UNCERTAIN;
pub(super) const RING_COMPLETE: &str = "The ring is complete: draw the next one.";
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
/// A ring snapped to its count whose three hand-drawn copies do not pass the local test
/// (a person's hand turns each petal about 2.5 degrees off, and two steps of three
/// petals then disagree by about 6) is taken from them all the same, each within
/// `RUN_PLACE` of its site on the ring, and its ghosts' expected miss widened this many
/// times: the scatter of three places about a ring fitted to them reads low. The replay
/// (`examples/replay_suggest`, `HAND_TURN=2.5`, wobble 5%, seeds 1-3): the issue's
/// families' share accepted after three copies 59.0% -> 64.0%, wrong ghosts 0.8% ->
/// 0.7% (rings of five 50% -> 100%); at 1, 1.5 and 2 times, 66.2% / 60.7% / 60.7%, the
/// first with 2.2% wrong (a ring of six's far ghosts from three petals).
const RING_FROM_THREE: f64 = 1.2;
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

impl<'a> Drawing<'a> {
    /// The drawing with its latest `LOOK_BACK_COPIES + 1` strokes sampled.
    fn new(strokes: &'a [Stroke], accepted: &'a [bool]) -> Self {
        let lookback = strokes.len().saturating_sub(LOOK_BACK_COPIES + 1);
        let sampled = (0..strokes.len()).map(|i| (i >= lookback).then(|| samples(&strokes[i]))).collect();
        Drawing { strokes, accepted, sampled }
    }

    fn hand(&self, i: usize) -> bool {
        !self.accepted.get(i).copied().unwrap_or(false)
    }

    fn size(&self, i: usize) -> f64 {
        self.strokes[i].bounds().size().to_vec2().hypot()
    }

    /// The steps from copy `i` to copy `j` with their shape residual, when they are one
    /// shape (more than one where the shape looks the same turned: an ellipse half round).
    /// A dot has no shape to carry (a pen tap's few points are noise): none.
    fn steps(&self, i: usize, j: usize) -> Vec<(Similarity, f64)> {
        if self.strokes[i].is_dot() || self.strokes[j].is_dot() {
            return Vec::new();
        }
        match (&self.sampled[i], &self.sampled[j]) {
            (Some(a), Some(b)) => relations(a, b, self.size(i)),
            _ => Vec::new(),
        }
    }

    /// Whether strokes `i` and `j` are copies of one part of a motif: one shape, or both
    /// dots (which go by their place alone).
    fn alike(&self, i: usize, j: usize) -> bool {
        match (self.strokes[i].is_dot(), self.strokes[j].is_dot()) {
            (true, true) => true,
            (false, false) => self.same(i, j).is_some(),
            _ => false,
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

    /// How far copy `j` departs from copy `i` carried on by `t`, the jitter of single
    /// points left out (a mouse's jaggies, a tremor: each point's own, which moves a copy's
    /// centre by a fifth of itself over 24 samples, not as a hand misplaces a copy): the
    /// rms distance of `i`'s samples, smoothed along the path and carried, from `j`'s
    /// smoothed path.
    fn shape_wobble(&self, i: usize, j: usize, t: &Similarity) -> f64 {
        let (Some(a), Some(b)) = (&self.sampled[i], &self.sampled[j]) else { return 0.0 };
        let (a, b) = (smoothed(a), smoothed(b));
        let path: Vec<(Point, Point)> = b.windows(2).map(|w| (w[0], w[1])).collect();
        let far = |p: Point| {
            path.iter()
                .map(|&(u, v)| {
                    let (d, e) = (v - u, p - u);
                    let s = (e.dot(d) / d.hypot2().max(1e-12)).clamp(0.0, 1.0);
                    (e - d * s).hypot2()
                })
                .fold(f64::INFINITY, f64::min)
        };
        (a.iter().map(|&p| far(t.apply(p))).sum::<f64>() / a.len().max(1) as f64).sqrt()
    }

    /// Whether stroke `i` (sampled) is round, a circle: its shape shows no turn (see
    /// `drift::looks_round`).
    pub(super) fn round(&self, i: usize) -> bool {
        self.sampled[i].as_ref().is_some_and(|p| looks_round(p, self.size(i)))
    }

    /// Where a copy is, for the orbit: the centre of its sampling (a similarity carries
    /// it as it carries the copy).
    fn z(&self, i: usize) -> Point {
        centroid(self.sampled[i].as_ref().expect("recent strokes are sampled"))
    }
}

/// A proposed stroke is on a drawn one of its shape when its centre lies within this
/// share of the step of it (the matching tolerance).
const DRAWN: f64 = 0.3;
/// Where a ring closes (snapped to its count, or come round a whole turn), a drawn stroke
/// up to this many times larger or smaller than a ghost is the copy it would be proposed
/// over.
const RESIZED: f64 = 2.0;

/// Proposals continuing the sequence that ends with the latest of `strokes` (none, with
/// the reason, when it is complete or too uncertain to go on), or `None` when the
/// latest strokes make no sequence. The steps are read from hand-drawn copies only
/// (`accepted` marks the proposals taken, which repeat the step they were proposed
/// with and say nothing of its error); copies accepted after the latest hand-drawn one
/// count as steps already taken.
pub(super) fn propose(strokes: &[Stroke], accepted: &[bool], ask: &Ask) -> Option<Suggestions> {
    let n = strokes.len();
    let d = Drawing::new(strokes, accepted);
    let last = (0..n).rev().find(|&i| d.hand(i))?;
    if n - 1 - last > LOOK_BACK {
        return None;
    }
    // (A dot says nothing of how its copies turn, nor does a small circle a few pen
    // widths across, whose hand's wobble is a large share of its size: where it is
    // the latest stroke and carries nothing on, the larger stroke drawn before it in
    // its copy may. Petals each with a small circle drawn in it got no ghost after
    // three or four of them, in a new user's 20 of 20 rings.)
    let own = follow(&d, ask, last);
    let larger = || {
        let before =
            (last.saturating_sub(MAX_STRIDE)..last).rev().find(|&i| d.hand(i) && d.size(i) > LARGER * d.size(last));
        before.and_then(|b| follow(&d, ask, b))
    };
    let (found, parts, _) = match own {
        Some(o) if !o.0.strokes.is_empty() || strokes[last].is_dot() => o,
        // (Where the latest stroke's own copies propose nothing, those of a stroke
        // half again its size drawn just before it in its copy may: a small circle in
        // a petal. A pen tap's own answer stands: its copies go by place, and say when
        // to wait.)
        o => match (o, larger()) {
            (_, Some(l)) if !l.0.strokes.is_empty() => l,
            (Some(o), _) => o,
            (None, l) => l?,
        },
    };
    // A motif's largest stroke shows its turn best (a stalk a few pixels long reads it
    // loosely, and put ghosts over the top of a Bézier arch 15-25 off at a step of 41,
    // where its leaves showed the turn changing): where the latest copy holds a
    // hand-drawn stroke this much larger than the latest, the copies follow that one's,
    // and where it says nothing goes on yet, nothing is proposed.
    let largest = parts.into_iter().filter(|&i| d.hand(i)).max_by(|&x, &y| d.size(x).total_cmp(&d.size(y)));
    match largest.filter(|&b| d.size(b) > LARGER * d.size(last)).and_then(|b| follow(&d, ask, b)) {
        Some((better, _, _)) => Some(better),
        None => Some(found),
    }
}

/// Whether the latest hand-drawn stroke's copies make a ring snapped to its count, of
/// one stroke, that holds every copy of its shape among the latest strokes (not one of
/// several flowers on a lattice, which the lattice places): the lattice the ring's
/// places may also fit (a ring of six lies on a triangular one) does not carry it on.
/// (`chain::find`, which `ring_holds_latest` asks, reads no ring of circles, whose
/// shapes show no turn, and not always one of squares, which show it up to quarter
/// turns: five of a ring of six got ghosts of that lattice, 1.6-1.8 steps off.)
pub(super) fn snapped_ring(strokes: &[Stroke], accepted: &[bool], ask: &Ask) -> bool {
    let d = Drawing::new(strokes, accepted);
    let Some(last) = (0..strokes.len()).rev().find(|&i| d.hand(i)) else { return false };
    follow(&d, ask, last).is_some_and(|f| f.2)
}

/// Whether the latest strokes repeat a shape: the latest hand-drawn one with a shape of
/// its own (not a dot, nor a straight line, which any two lines share), among the latest
/// `MAX_STRIDE` hand-drawn ones (a petal's dot or vein may come after it), has at least
/// `REPEATED` copies before it among the latest `LOOK_BACK_COPIES` strokes, one shape up
/// to a similarity and drawn with the same pen (the same colours, widths within a
/// quarter: fixed here, not the lattice's `width_tolerance` and `color_tolerance`).
/// Where nothing is proposed, the page then says the copies do not yet show where the
/// next goes, not that there is no repetition (three or four petals a person turned read
/// "no repetition yet" at 59 of 180 calls of `examples/ring_ghosts`).
pub(super) fn repeats(strokes: &[Stroke], accepted: &[bool]) -> bool {
    let d = Drawing::new(strokes, accepted);
    let from = strokes.len().saturating_sub(LOOK_BACK_COPIES + 1);
    let shaped = |i: usize| !strokes[i].is_dot() && !super::hatching::straight(&strokes[i]);
    let Some(last) = (from..strokes.len()).rev().filter(|&i| d.hand(i)).take(MAX_STRIDE).find(|&i| shaped(i)) else {
        return false;
    };
    // (Drawn with the same pen: a sketch's wandering curves of any colour and width
    // match one another's shapes now and then.)
    let pen = |i: usize| {
        let (s, t) = (&strokes[i], &strokes[last]);
        s.stroke == t.stroke && s.fill == t.fill && (s.width - t.width).abs() <= 0.25 * t.width
    };
    (from..last).rev().filter(|&i| shaped(i) && pen(i) && d.same(i, last).is_some()).nth(REPEATED - 1).is_some()
}

/// Copies before the latest that make it a repetition for `repeats`.
const REPEATED: usize = 2;

/// Round copies (circles) are followed from this many drawn by hand (their places alone show the step).
const ROUND_COPIES: usize = 4;

/// A stroke under this many pen widths across is small: its shape is mostly the hand's
/// wobble (a circle drawn in a petal).
const SMALL: f64 = 2.0 * DOT;

/// A motif's stroke is followed in place of the latest when it is this many times the
/// latest's size.
const LARGER: f64 = 1.5;

/// `propose` carrying on the copies of stroke `last` (hand-drawn, among the latest
/// `LOOK_BACK`), with the other strokes of its latest copy carried along: the proposals,
/// those strokes, and whether the copies make a ring snapped to its count.
fn follow(d: &Drawing, ask: &Ask, last: usize) -> Option<(Suggestions, Vec<usize>, bool)> {
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
    // (The first stride whose steps agree; where none does, the one whose steps come
    // nearest, a stride of more than one only where the strokes between lie on the
    // copies followed: see `begin`.)
    // (Read stride by stride, stopping at the first that agrees: usually the first.)
    let mut begun: Vec<Begun> = Vec::new();
    for b in (1..=MAX_STRIDE).filter_map(|k| begin(d, &chain, at, k)) {
        let local = b.local;
        begun.push(b);
        if local {
            break;
        }
    }
    let start =
        begun.iter().find(|b| b.local).or_else(|| begun.iter().min_by(|x, y| x.disagree.total_cmp(&y.disagree)))?;
    let Begun { stride, one, two, step, local, .. } = *start;
    let centre = |i: usize| strokes[i].reference_point();
    // A round shape (a circle) shows no turn of its own: its copies' step is read from
    // their places alone, as upright copies' is, and the run must bear it out (rings
    // of five to eight circles read their turn from whichever start of each circle
    // fitted best, and 40 of 75 ghosts were wrong).
    let round = d.round(last);
    let local = local && !round;
    // Copies a step apart, not one drawn over another (hatching lies a tenth of its
    // length apart, or closer).
    if step <= (0.02 * d.size(last)).max(3.0 * strokes[last].width) {
        return None;
    }
    // A step that neither turns nor scales is a row's: the lattice reads those, with
    // its own certainty, from every copy.
    if !rows && !round && (one.a + two.a - Vec2::new(2.0, 0.0)).hypot() < 2.0 * MIN_TURN {
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
        let linked = round
            || d.near(p, cur, mean.atan2()).is_some_and(|(t, _)| (t.a - mean).hypot() <= FOLLOW_TURN * mean.hypot());
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
    // Copies that keep their pose while their places bend (fence posts along an arc,
    // upright): the shapes step by a translation, which carries nothing round the bend,
    // and the places say how the step turns. Their copies are carried on unturned.
    // (The shapes' turn is a hand's few degrees at random; the places' is the bend's,
    // alike at every step. Read only where the latest shape steps barely turn: the
    // places' bend first, the run's every shape step last.)
    // Round copies are carried unturned too, their step's turn read as the turn about
    // the circle through the run's places (a ring's places turn by its whole step,
    // past what a steady bend allows), from `ROUND_COPIES` drawn by hand: three places
    // fit a circle exactly, and say nothing of its error. Where they turn by none, a
    // row's, the lattice reads them.
    let upright = if round {
        if run.iter().filter(|&&i| d.hand(i)).count() < ROUND_COPIES {
            return unfollowed().map(|s| (s, Vec::new(), false));
        }
        let places: Vec<Point> = run.iter().map(|&i| d.z(i)).collect();
        let turn = crate::vector::chain::bend::turn_through(&places);
        if !rows && turn.abs() < MIN_TURN {
            return None;
        }
        Some(Vec2::new(turn.cos(), turn.sin()))
    } else {
        (rows && [one.a, two.a].iter().all(|a| a.atan2().abs() < UPRIGHT_TURN))
            .then(|| place_turn(d, &run))
            .flatten()
            .filter(|a| (one.a + two.a).atan2().abs() < UPRIGHT * a.atan2().abs())
            .filter(|a| {
                let turns: Option<Vec<f64>> =
                    run.windows(2).map(|w| d.near(w[0], w[1], 0.0).map(|(t, _)| t.turn())).collect();
                turns.is_some_and(|t| {
                    let mean = t.iter().sum::<f64>() / t.len() as f64;
                    mean.abs() < UPRIGHT * a.atan2().abs() && t.iter().all(|x| x.abs() < UPRIGHT_TURN)
                })
            })
    };
    let shapes = upright.map_or([one.a, two.a], |a| [a; 2]);
    let upright = upright.is_some();
    let Some(Model { orbit, closes, bend_error }) = model(d, &run, step, shapes, lead, upright) else {
        return unfollowed().map(|s| (s, Vec::new(), false));
    };
    // A step turning by more than a ring of two and a half copies would (about half a
    // turn) carries each copy back near the one before the last: nothing goes on by it.
    // (Dashes dropped at random, each about a half turn of the one before, were called
    // a complete ring: 14 of 288 prefixes.)
    if orbit.a.atan2().abs() > TAU / 2.5 {
        return None;
    }
    // (Round copies' turn is read from their places only: unless their ring snaps to
    // its count, one more than `ROUND_COPIES` is drawn. Four circles round a ring of
    // eight, 3% of the step off, read 40.6 degrees a step, no count sure, and the
    // second ghost fell 0.38 of the step off.)
    if round && closes.is_none() && run.iter().filter(|&&i| d.hand(i)).count() <= ROUND_COPIES {
        return unfollowed().map(|s| (s, Vec::new(), false));
    }
    // A ring snapped to its count (`model`), with no lead-in, of copies of one stroke: its
    // places round the centre are a global fit, which three copies bear out.
    let ring = closes.is_some() && lead.is_none() && stride == 1;
    let mut from_three = false;
    if !local {
        let hand: Vec<usize> = (0..run.len()).filter(|&t| d.hand(run[t])).collect();
        let needed = if ring { 3 } else { 4 };
        if hand.len() + usize::from(lead.is_some()) < needed
            || hand.iter().any(|&t| orbit.at(t as i64).distance(d.z(run[t])) > RUN_PLACE * step)
        {
            return unfollowed().map(|s| (s, Vec::new(), false));
        }
        from_three = ring && hand.len() < 4;
    }
    // (A ring snapped to its count, with no lead-in, closes whole: its turn holds by
    // construction and cannot bend the other way, which is what the backtest looks for,
    // as its bend error is none; a miss of its latest copy is the hand's scatter, which
    // the orbit reads. Eight petals by a steady hand at 5% of the step, snapped to
    // eight after five, were held back as though bending, by 1.8 times: the first
    // ghost's reach 0.37 of the step, against 0.20; six veined petals by a person's hand
    // at 3%, snapped after four, by 2.4 times: 0.46 against 0.19.)
    let inflate = if from_three {
        RING_FROM_THREE
    } else if closes.is_some() && lead.is_none() {
        1.0
    } else {
        backtest(d, &run, step, shapes, lead, upright)
    };
    // The turn a copy takes from copy `from` to copy `to`: the orbit's, or none.
    let turn_of = |from: i64, to: i64| if upright { Vec2::new(1.0, 0.0) } else { orbit.turn(from, to) };
    let reach = super::certainty::reach(orbit.copies);
    let mut out = Suggestions::default();
    let end = run.len() as i64 - 1;
    let hands: Vec<usize> = (0..run.len()).filter(|&t| d.hand(run[t])).collect();
    // The latest copy's other strokes, carried on with it; a ghost is on a drawn stroke
    // within half the step or half the nearest two of the copy's strokes lie apart.
    let h = run.iter().position(|&i| i == last)?;
    let parts = companions(d, &run, h, step, turn_of(h as i64 - 1, h as i64));
    // Each part turns as its own copies do: with the orbit, or not at all (a fence's
    // rail turns with the arc while its post stays upright), whichever way the stroke
    // followed goes.
    let step_turn = orbit.turn(h as i64 - 1, h as i64).atan2();
    let frame_turns = !upright;
    let own_turns: Vec<bool> = parts
        .iter()
        .map(|&c| part_turns(d, &run, h, c, turn_of(h as i64 - 1, h as i64), step_turn, frame_turns))
        .collect();
    // (A copy's strokes may share a centre, a leaf's two halves and its midrib: a ghost
    // is on a drawn stroke that it carries onto about unturned, unscaled and unmoved.)
    // (`resized`: or drawn larger or smaller, up to `RESIZED` times, its centre off by
    // what that moves it; asked where a ring closes only (snapped to its count, or come
    // round a whole turn), whose copies past the run may be drawn: a first petal a person
    // drew a third longer than the rest is still the ring's, and a ghost was proposed
    // over it, the ring's own or, where its petals were read in pairs, the part left of
    // the copy that closes it: 11 of 45 complete rings of five to twelve, at 1-5%.)
    let drawn_as = |g: &Stroke, here: f64, resized: bool| {
        let (p, size) = (g.reference_point(), g.bounds().size().to_vec2().hypot());
        let within = 0.5 * here + if resized { (RESIZED - 1.0) * 0.5 * size } else { 0.0 };
        let mut near = strokes.iter().filter(|s| s.reference_point().distance(p) < within).peekable();
        near.peek().is_some() && {
            let mine = samples(g);
            let c = centroid(&mine);
            // (A dot turns as the pen went, and a circle a few pen widths across as the
            // hand's wobble does: its place alone says it is drawn, the circle's where
            // a small stroke is there. A petal's small circle was proposed again on the
            // one drawn.)
            let small = |s: &Stroke| s.bounds().size().to_vec2().hypot() < SMALL * s.width;
            let (dot, circle) = (g.is_dot(), small(g));
            near.any(|s| {
                if dot || (circle && small(s)) {
                    return s.reference_point().distance(p) < DRAWN * here;
                }
                if resized {
                    // (The residual is in the drawn stroke's units: a share of its size.)
                    let theirs = s.bounds().size().to_vec2().hypot();
                    return similarity::relations(&mine, &samples(s), theirs, SHAPE, RESIZED).iter().any(
                        |(t, _, _)| {
                            let moved = (t.scale() - 1.0).abs() * 0.5 * size;
                            t.turn().abs() < FOLLOW_TURN && t.apply(c).distance(c) < DRAWN * here + moved
                        },
                    );
                }
                relations(&mine, &samples(s), size).iter().any(|(t, _)| {
                    (t.a - Vec2::new(1.0, 0.0)).hypot() < FOLLOW_TURN && t.apply(c).distance(c) < DRAWN * here
                })
            })
        }
    };
    let drawn = |g: &Stroke, here: f64| drawn_as(g, here, false);
    // The latest copy's other strokes carried to copy `t`, where none is drawn yet (the
    // copy that closes a ring may lack one).
    let ring_centre = orbit.centre();
    let parts_at = |t: i64, here: f64, closing: bool| -> Vec<(Stroke, usize)> {
        let turn = turn_of(h as i64, t);
        let to = Similarity { a: turn, b: orbit.at(t).to_vec2() - mul(turn, d.z(last).to_vec2()) };
        // (A part that turns otherwise than the frame goes where the frame carries its
        // place, turned its own way about it.)
        let carry = |c: usize, turns: bool| {
            if turns == frame_turns {
                return to.carry(&strokes[c]);
            }
            let own = if turns { orbit.turn(h as i64, t) } else { Vec2::new(1.0, 0.0) };
            let p = strokes[c].reference_point();
            Similarity { a: own, b: to.apply(p).to_vec2() - mul(own, p.to_vec2()) }.carry(&strokes[c])
        };
        parts
            .iter()
            .zip(&own_turns)
            .map(|(&c, &turns)| (carry(c, turns), c))
            .filter(|(g, _)| {
                let p = g.reference_point();
                // (A part further from a ring's centre than the copy's site, a petal's
                // dot at its tip, steps further, and a hand's turn of its copy moves it
                // further: judged by its own step. Eight petals with a pen-tapped dot at
                // each tip, by a person's hand: a dot carried to the copy drawn last fell
                // 13.6 from the dot drawn there, past 0.3 of the petals' step, and was
                // proposed again beside it.)
                let own = ring_centre.map_or(1.0, |c| {
                    let r = orbit.at(t).distance(c);
                    if r > 0.0 {
                        (p.distance(c) / r).max(1.0)
                    } else {
                        1.0
                    }
                });
                region.is_none_or(|r| r.contains(p)) && !drawn_as(g, own * here, closing)
            })
            .collect()
    };
    let push = |out: &mut Suggestions, ghost: Stroke, src: usize, k: i64| {
        out.strokes.push(ghost);
        out.confidence.push(super::FALLOFF.powi(k as i32));
        out.sources.push((src + offset) as u32);
        out.cells.push([k, 0]);
    };
    let mut proposed = None;
    let mut rng = seed.map(Rng::new);
    let mut why = "The sequence is complete here: its next copy would fall on a drawn one or off the canvas.";
    // (The copies of `chain` that are the followed stroke's: every `stride`-th.)
    let of_run = |x: usize| x.abs_diff(latest) % stride == 0;
    let step_angle = orbit.a.atan2().abs();
    for k in 1..=count as i64 {
        let t = end + k;
        let site = orbit.at(t);
        let here = site.distance(orbit.at(t - 1));
        // Where a ring closes (at its count, or round onto its own first copies: a ring,
        // whole, even where its count was never sure enough to snap, three petals of
        // six, three accepted), what is left of the copy before its first. (Its first
        // copies, not the run's only: a run holds `MAX_RUN` hand-drawn copies, and
        // twelve squares turned with their ring, its count unsnapped, got ghosts on the
        // first three, turned a few degrees off them.)
        if closes.is_some_and(|c| t >= c)
            || (orbit.centre().is_some()
                && chain.iter().enumerate().any(|(x, &i)| of_run(x) && d.z(i).distance(site) < 0.5 * here))
        {
            for (g, c) in parts_at(t, here, true) {
                push(&mut out, g, c, k);
            }
            why = RING_COMPLETE;
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
        let turn = turn_of(from as i64, t);
        let src = run[from];
        let ghost = Similarity { a: turn, b: site.to_vec2() - mul(turn, d.z(src).to_vec2()) }.carry(&strokes[src]);
        let c = ghost.reference_point();
        // Off the canvas: the end. Onto a stroke already drawn (a ring closing): what
        // is left of that copy, and the end.
        if region.is_some_and(|r| !r.contains(c)) {
            break;
        }
        // (An orbit round a centre that has come round a whole turn, but for a step and a
        // half, since the run's first copy is closing as a ring does, though its count
        // was never snapped: a first petal drawn a quarter longer than the rest is no
        // copy of the run, which then closes onto it.)
        let closing = closes.is_some() || (ring_centre.is_some() && t as f64 * step_angle >= TAU - 1.5 * step_angle);
        if drawn(&ghost, here) || (closing && drawn_as(&ghost, here, true)) {
            if closing {
                why = RING_COMPLETE;
                for (g, c) in parts_at(t, here, true) {
                    push(&mut out, g, c, k);
                }
            }
            break;
        }
        for (g, c) in parts_at(t, here, false) {
            push(&mut out, g, c, k);
        }
        push(&mut out, ghost, src, k);
        proposed = Some((t, k));
    }
    // Companions drawn after the stroke followed (a leaf, then its dot) belong to the
    // copy before the latest: each ghost copy carried the one before's, and the last
    // copy proposed gets its own here (not past a ring's closing copy, which got what
    // was left of it).
    // (Where the stroke followed is not the latest, and a part's like was drawn after
    // it, that part of its copy came after it: a petal, then its dot, the latest. The
    // places alone misread it where a person's hand turned the petals, and the last
    // ghost petal of three was proposed bare.)
    let after = (last + 1..n).any(|i| d.hand(i) && parts.iter().any(|&c| d.alike(c, i)));
    let trails = || after || trailing(d, &run[..=h], &parts, &|t| turn_of(h as i64, t).atan2(), step);
    if let Some((t, k)) = proposed.filter(|_| why != RING_COMPLETE && trails()) {
        for (g, c) in parts_at(t + 1, orbit.at(t + 1).distance(orbit.at(t)), false) {
            push(&mut out, g, c, k);
        }
    }
    // (Found, with nothing to add: said, so the page does not read "no repetition".)
    if out.strokes.is_empty() {
        out.reason = Some(why.into());
    }
    // (A ring snapped to its count that holds every copy of its shape drawn lately, of
    // one stroke and with no lead-in: what `snapped_ring` asks.)
    let whole = closes.is_some()
        && lead.is_none()
        && stride == 1
        && chain.iter().enumerate().all(|(x, i)| !of_run(x) || run.contains(i));
    Some((out, parts, whole))
}

/// The step of the run's places where they bend steadily (`chain::bend::steady_bend`, each
/// move against the one before where the three copies are hand-drawn): its turn, and
/// the moves' mean change of length.
fn place_turn(d: &Drawing, run: &[usize]) -> Option<Vec2> {
    let relations = model::place_relations(d, run);
    let turn = crate::vector::chain::bend::steady_bend(&relations.iter().map(|r| r.turn).collect::<Vec<_>>())?;
    // (The moves' change of length is the hand's unless it is clear of its standard
    // error: read from five posts 3% off their places, a scale of 0.81 made a spiral.)
    let logs: Vec<f64> = relations.iter().map(|r| r.scale.ln()).collect();
    let n = logs.len() as f64;
    let mean = logs.iter().sum::<f64>() / n;
    let se = (logs.iter().map(|l| (l - mean).powi(2)).sum::<f64>() / (n - 1.0).max(1.0) / n).sqrt();
    let scale = if n >= 3.0 && mean.abs() > SCALE_SURE * se { mean.exp() } else { 1.0 };
    Some(Vec2::new(turn.cos(), turn.sin()) * scale)
}

/// Upright copies' moves change length by a scale where its mean log passes this many
/// of its standard errors (and is read from at least three moves' changes).
const SCALE_SURE: f64 = 3.0;

/// `points` averaged over five along the path (fewer at an open path's ends; round a
/// closed loop, across its closing).
pub(in crate::vector::suggest) fn smoothed(points: &[Point]) -> Vec<Point> {
    let n = points.len();
    let closed = crate::vector::frechet::closed_loop(points);
    // (A closed loop's last point repeats its first.)
    let m = if closed { n - 1 } else { n };
    (0..n)
        .map(|i| {
            let (mut sum, mut count) = (Vec2::ZERO, 0.0);
            for k in -2i64..=2 {
                let at = i as i64 + k;
                let at = if closed {
                    at.rem_euclid(m as i64)
                } else if (0..n as i64).contains(&at) {
                    at
                } else {
                    continue;
                };
                sum += points[at as usize].to_vec2();
                count += 1.0;
            }
            (sum / count).to_point()
        })
        .collect()
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
