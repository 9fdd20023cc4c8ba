//! Which copies of the latest stroke's shape a sequence follows (`begin`): the two
//! before it, or where motifs hold several strokes of that shape (a petal drawn as two
//! mirrored arcs), every `stride`-th; and the latest copy's other strokes, carried on
//! with it (`companions`), drawn before or after the stroke followed (`trailing`).

use super::Drawing;
use crate::vector::similarity::Similarity;
use kurbo::Vec2;

/// The two steps agree when their `a` differ by at most this share of `|a|` (about 5°
/// of turn or 5% of scale)...
const TURN: f64 = 0.09;
/// ...or, round a centre near the copies (petals: both steps turn about one point
/// within `ROSETTE` of the latest copy's size, and within `ROSETTE_CENTRE` of it of
/// each other), within this share (about 8.5 degrees). A person's hand turns each
/// petal about 2.5 degrees off its place, so that two steps of three petals disagree by
/// about 6 degrees (the sum of three turns, the middle twice): at 5 degrees 5 of 6
/// rings of five begun with three petals at 5% of the step got no ghost. The places
/// round the centre bear the ring out where its petals' shapes turn loosely.
const ROSETTE_TURN: f64 = 0.15;
const ROSETTE: f64 = 1.5;
const ROSETTE_CENTRE: f64 = 0.3;
/// ...and the first step puts the third copy within this share of the step.
const PLACE: f64 = 0.2;
/// How the latest copy follows the two before it, taken every `stride`-th of its shape
/// back along `chain` (the strokes of its shape, the latest at `at`).
#[derive(Clone, Copy)]
pub(super) struct Begun {
    pub(super) stride: usize,
    /// The steps from the first copy to the second, and from the second to the latest.
    pub(super) one: Similarity,
    pub(super) two: Similarity,
    /// The distance from the second copy to the latest.
    pub(super) step: f64,
    /// The two steps alike, and the first carrying the second copy onto the latest (the
    /// miss of its centre, where a copy is matched). Where they are not (a stem that
    /// bends on, past copies accepted from its earlier turn), the whole run must bear
    /// the sequence out instead (`RUN_PLACE`).
    pub(super) local: bool,
    /// How far the two steps disagree, as a share of the first's `|a|`.
    pub(super) disagree: f64,
}

/// The steps between copies of a motif of several strokes of one shape turn or scale
/// by at least this much (`|a - 1|`, about 6 degrees: petals round a centre, leaves
/// along a curve).
const STRIDE_TURN: f64 = 0.1;

/// Copies of a motif holding up to this many strokes of one shape are followed.
pub(super) const MAX_STRIDE: usize = 4;

/// The latest copy and the two before it, every `stride`-th copy of its shape back
/// along `chain`, when they are one shape.
pub(super) fn begin(d: &Drawing, chain: &[usize], at: usize, stride: usize) -> Option<Begun> {
    let last = chain[at];
    let second = chain[at.checked_sub(stride)?];
    let centre = |i: usize| d.strokes[i].reference_point();
    let first = if stride == 1 {
        (chain[0]..second).rev().find(|&i| d.same(i, second).is_some())?
    } else {
        // (A copy's strokes of this shape lie on one another, as a petal's two arcs do:
        // those between the second and the latest each lie on one of the two, whose
        // copy it is part of; four leaves along a stem, each a step from the next, are
        // no motif of four.)
        let on = |i: usize, j: usize| centre(i).distance(centre(j)) <= 0.5 * d.size(i).max(d.size(j));
        if !chain[at + 1 - stride..at].iter().all(|&i| on(i, last) || on(i, second)) {
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
    // (A motif of several strokes carried by about a translation is the lattice's: it
    // reads those, whole, with its own certainty. Asterisks in a row, each bar turned a
    // few degrees by the hand, read as an orbit that bent with them, and the finished
    // drawing synthesized less regularly: 95th percentile residual 0.126 of the step.)
    if stride > 1 && (one.a + two.a - Vec2::new(2.0, 0.0)).hypot() < 2.0 * STRIDE_TURN {
        return None;
    }
    let agree = (two.a - one.a).hypot();
    let size = d.size(last);
    let rosette = match (one.fixed_point(), two.fixed_point()) {
        (Some(p), Some(q)) => p.distance(q) <= ROSETTE_CENTRE * size && q.distance(centre(last)) <= ROSETTE * size,
        _ => false,
    };
    let local = agree <= if rosette { ROSETTE_TURN } else { TURN } * one.a.hypot()
        && one.carry(&d.strokes[second]).reference_point().distance(centre(last)) <= PLACE * step;
    Some(Begun { stride, one, two, step, local, disagree: agree / one.a.hypot().max(1e-9) })
}

/// A companion carried on by the step between two copies lands within this share of the
/// step of its copy's (looser than `PLACE`: a part at a petal's tip, a step behind, is
/// carried less closely than the petals the step was read from).
const COMPANION: f64 = 0.3;

/// The strokes of the copy that ends with `run[h]` drawn since the copy before it
/// (`run[h - 1]`) that repeat one of the copy before that, carried on by the step from
/// that copy to this one within `COMPANION` of the step: a motif's other strokes (a
/// petal's second arc, a leaf's midrib, its stalk, its dot), in drawing order. The step
/// is the pair's own (the one turning nearest `a`), the pair's before it, or `a` itself
/// (the orbit's turn from one copy to the next, read from every copy) about the pair's
/// places: a person's hand turns and spaces each petal a few degrees off, and one pair's
/// step carried a pen-tapped dot at a petal's tip off its copy's (three petals of
/// eight, then of seven, were proposed without theirs).
pub(super) fn companions(d: &Drawing, run: &[usize], h: usize, step: f64, a: Vec2) -> Vec<usize> {
    let (Some(&before), Some(&prev)) = (h.checked_sub(2).map(|x| &run[x]), h.checked_sub(1).map(|x| &run[x])) else {
        return Vec::new();
    };
    let last = run[h];
    let orbit = Similarity { a, b: d.z(last).to_vec2() - crate::vector::similarity::mul(a, d.z(prev).to_vec2()) };
    // (A part drawn after its copy, a leaf's dot, belongs to the copy before: the step
    // from the copy before that carries it, where the hand spaced its copies unevenly.)
    let carries: Vec<Similarity> = [d.near(prev, last, a.atan2()), d.near(before, prev, a.atan2())]
        .into_iter()
        .flatten()
        .map(|(t, _)| t)
        .chain([orbit])
        .collect();
    let centre = |i: usize| d.strokes[i].reference_point();
    (prev + 1..last)
        .filter(|&c| {
            (before + 1..prev).any(|o| {
                d.alike(o, c)
                    && carries
                        .iter()
                        .any(|t| t.carry(&d.strokes[o]).reference_point().distance(centre(c)) <= COMPANION * step)
            })
        })
        .collect()
}

/// Whether part `c` of the copy that ends with `run[h]` turns from copy to copy by the
/// orbit's `turn` a step, where the stroke followed does (`frame_turns`) or keeps its
/// pose: the part's own turn from its like in the copy before (the one the step `a`
/// carries nearest it) decides only where it is within `UPRIGHT` of the turn of the
/// other way (none, or `turn`) and the step turns by at least `PART_TURN`; else the part
/// goes as the stroke followed. A fence seen from the side, drawn as a post and a rail:
/// the rail turns with the arc, the post stays upright, and carried with the rail each
/// ghost post leaned by the arc's turn.
pub(super) fn part_turns(
    d: &Drawing,
    run: &[usize],
    h: usize,
    c: usize,
    a: Vec2,
    turn: f64,
    frame_turns: bool,
) -> bool {
    let (Some(&before), Some(&prev)) = (h.checked_sub(2).map(|x| &run[x]), h.checked_sub(1).map(|x| &run[x])) else {
        return frame_turns;
    };
    if turn.abs() < PART_TURN {
        return frame_turns;
    }
    let orbit = Similarity { a, b: d.z(run[h]).to_vec2() - crate::vector::similarity::mul(a, d.z(prev).to_vec2()) };
    let centre = |i: usize| d.strokes[i].reference_point();
    let like = (before + 1..prev).filter(|&o| d.alike(o, c)).min_by(|&x, &y| {
        let off = |o: usize| orbit.carry(&d.strokes[o]).reference_point().distance(centre(c));
        off(x).total_cmp(&off(y))
    });
    let Some((own, _)) = like.and_then(|o| d.near(o, c, turn)) else { return frame_turns };
    let other = if frame_turns { 0.0 } else { turn };
    let otherwise = (own.turn() - other).abs() < super::UPRIGHT * turn.abs();
    frame_turns != otherwise
}

/// Parts are told apart by their turn only where the stroke followed turns by at least
/// this much a step (radians, about 6 degrees: a hand's tilt of a copy either way).
const PART_TURN: f64 = 0.1;

/// Whether the latest copy's `parts` (see `companions`) were drawn after the stroke
/// followed in their copy, and so belong to the copy before (a leaf, then its dot).
/// `turn(t)` is the turn from the latest copy to copy `t` of the `run`. Each part,
/// carried to the run's first copy as the latest copy's (by the step of the stroke
/// followed onto that copy's), lands on no drawn stroke of its shape, and carried as the
/// copy before's, lands on one. (Drawn before the stroke followed, a stalk and then its
/// leaf, it lands on one both ways; so too where the run's first copy is not the first
/// drawn: taken as drawn before, which proposes no part more.) And each part lies nearer
/// the copy before than the latest: a dot at the tip of the leaf before, not a stalk
/// touching the leaf after it, whose first copy was drawn bare (the places alone cannot
/// tell the two apart: a stray stalk was proposed past the last leaf).
pub(super) fn trailing(d: &Drawing, run: &[usize], parts: &[usize], turn: &dyn Fn(i64) -> f64, step: f64) -> bool {
    let (Some(&last), true) = (run.last(), run.len() >= 2) else { return false };
    let lands = |c: usize, t: usize| {
        let Some((carry, _)) = d.near(last, run[t], turn(t as i64)) else { return false };
        let p = carry.carry(&d.strokes[c]).reference_point();
        (0..d.strokes.len())
            .any(|s| s != c && d.strokes[s].reference_point().distance(p) <= PLACE * step && d.alike(s, c))
    };
    let before = run[run.len() - 2];
    let gap = |a: usize, b: usize| match (&d.sampled[a], &d.sampled[b]) {
        (Some(p), Some(q)) => {
            p.iter().flat_map(|u| q.iter().map(move |v| u.distance(*v))).fold(f64::INFINITY, f64::min)
        }
        _ => f64::INFINITY,
    };
    !parts.is_empty() && parts.iter().all(|&c| !lands(c, 0) && lands(c, 1) && gap(c, before) < gap(c, last))
}
