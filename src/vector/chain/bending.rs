//! Copies along a curve whose turn changes: leaves drawn along a wave or an S with no
//! stem drawn. No one step carries them (a chain's step turns alike at every copy, and
//! here the turn grows, falls and changes sign), yet each copy is the one before under
//! a similarity: a step on along the curve, turned as the curve turns there, its pose
//! in the curve's frame kept. Xing et al.'s local similarity, read at each end: the
//! curve goes on past its ends as its last copies step (`Bending::ends`), a few copies
//! and at most 60 degrees past an end's tangent (a constant step carried far curls the
//! curve into a circle).
//!
//! Departs from `find`, which asks one step of the whole drawing: a chain fitted to
//! leaves over a wave's crest went on round a circle (a new user's S came back as a U),
//! and leaves along its rising side, whose turn changes too much for one step, were
//! grown as a scatter.

use super::Chain;
use crate::vector::similarity::{centroid, mul, relations, samples, Similarity};
use crate::vector::stroke::Stroke;
use kurbo::{Point, Vec2};
use std::f64::consts::PI;

/// Same shape as `find` asks: the best similarity's rms residual as a share of the
/// size, and its scale either way.
const SHAPE: f64 = 0.15;
const MAX_SCALE: f64 = 1.3;
/// Each move from a copy to the next is within this factor of the median either way (a
/// leaf's centre lies off the curve it is drawn along, on the outside of one bend of an
/// S and the inside of the next: a new user's leaves of an S lay 43 and 70 apart)...
const MOVE: f64 = 1.8;
/// ...and turns from the one before by at most this (radians, about 69 degrees: a
/// strong wave turned its leaves' places by 47 degrees a step, a tight crest by 65; a
/// path that doubles back is no curve)...
const MOVE_TURN: f64 = 1.2;
/// ...and the copies' poses in the curve's frame agree within this (radians, about 20
/// degrees: a person's hand turns each copy by a few degrees, and the tangent at a copy
/// is read from the places either side of it).
const POSE: f64 = 0.35;
/// A copy's centre lies off the curve (a leaf's, half its length out from its base):
/// the places' tangent then leans off the curve's by about `d κ` (the offset times the
/// curvature), one way on one bend of an S and the other way on the next. Where the
/// curvature read from the places differs from the second copy's, the poses may differ
/// by that lean's change too (`d` half a copy's size), up to this much more (radians,
/// about 20 degrees: leaves along an S of two arcs of radius 72, 32 apart, read poses
/// 23 degrees apart across its inflection).
const LEAN: f64 = 0.35;
/// Some copy is turned from the first by at least this much (radians, about 17
/// degrees): copies that keep their pose are a row's, the lattice's. (Not the turn from
/// the first copy to the last: an S turns back by as much as it turned.)
const LEAST_TURN: f64 = 0.3;
/// The copies' steps change their turn where their turns spread over at least this
/// (radians, about 17 degrees): a person's hand turns each copy about 2.5 degrees at random, so that the
/// steps of eight leaves along an arc, alike but for it, spread over about 10 degrees.
const CHANGE: f64 = 0.3;
/// ...or turn one way past this and the other way past it (radians, about 3 degrees: a
/// gentle wave's inflection, 13 degrees a step one way and 4 the other);
const INFLECTS: f64 = 0.05;
/// Each step's turn changes from the one before by at most this (radians, about 46
/// degrees: a tight S reversed from 24 degrees a step to -9 in one), but where the turn
/// changes sign between two steps whose neighbours change smoothly (an S of two arcs
/// joined, whose steps turn 25 degrees one way and then 25 the other)...
const SMOOTH: f64 = 0.8;
/// ...and not one way, the other and back by more than this each (radians, 20
/// degrees: two mirrored arcs drawn for each petal of a ring turn by 80 degrees one way
/// and 30 the other, by turns; a strong wave's crest turned 28, 48 and 19 degrees a
/// step, one change back; a person's hand, turning each leaf a few degrees at random,
/// changes a wave's steps by about 6 degrees either way).
const ZIGZAG: f64 = 0.35;
/// Past each end, the curve goes on by at most this share of its drawn copies' count
/// (a guess, and further out a worse one: a wave's leaves three steps past six drawn
/// were 1.1-1.5 steps off the wave's own)...
const ON: f64 = 1.0 / 3.0;
/// ...and while it turns by at most this much past the end's tangent (radians, 60
/// degrees).
const ON_TURN: f64 = PI / 3.0;
/// The step past an end scales by at most this either way.
const SCALE: f64 = 1.05;

/// Copies along a curve whose turn changes: the drawn copies in order along it, and at
/// each end a chain of its last copies (the first end's read backwards) whose step
/// carries the curve on, with how many copies it goes on by.
#[derive(Clone, Debug)]
pub struct Bending {
    pub members: Vec<usize>,
    pub ends: [(Chain, usize); 2],
    /// The steps' turn changes (by `CHANGE`, or from one way to the other past
    /// `INFLECTS`): no chain's one step carries the copies.
    pub changes: bool,
}

/// The drawing as copies of a motif along a curve whose turn changes (`Bending`): its
/// largest stroke's copies (`motif`; each copy's other strokes carried with it), in
/// order along the curve by their places (each the nearest
/// of those left to the one before, from the copy furthest from their mean), each a
/// move on from the last (`MOVE`, `MOVE_TURN`), lying alike in the curve's frame
/// (`POSE`), some turned from the first by at least `LEAST_TURN`, the steps' turns
/// changing gradually (`SMOOTH`, `ZIGZAG`); whether they change at all (`changes`) is
/// for the caller to weigh against a chain.
pub fn find_bending(strokes: &[Stroke]) -> Option<Bending> {
    if !(4..=super::MAX_STROKES).contains(&strokes.len()) {
        return None;
    }
    let sampled: Vec<Vec<Point>> = strokes.iter().map(samples).collect();
    let size = |k: usize| strokes[k].bounds().size().to_vec2().hypot();
    let places: Vec<Point> = sampled.iter().map(|s| centroid(s)).collect();
    let (copies, companions) = motif(strokes, &sampled, &places)?;
    let n = copies.len();
    let order: Vec<usize> =
        along(&copies.iter().map(|&k| places[k]).collect::<Vec<_>>())?.into_iter().map(|k| copies[k]).collect();
    let at: Vec<Point> = order.iter().map(|&k| places[k]).collect();
    let moves: Vec<Vec2> = at.windows(2).map(|w| w[1] - w[0]).collect();
    let mut lengths: Vec<f64> = moves.iter().map(|m| m.hypot()).collect();
    let median = crate::vector::classify::median(&mut lengths);
    let angle = |v: Vec2| v.y.atan2(v.x);
    let wrap = |x: f64| (x + 3.0 * PI).rem_euclid(2.0 * PI) - PI;
    if median <= 0.0
        || moves.iter().any(|m| m.hypot() > MOVE * median || m.hypot() < median / MOVE)
        || moves.windows(2).any(|w| wrap(angle(w[1]) - angle(w[0])).abs() > MOVE_TURN)
    {
        return None;
    }
    // The tangent at each copy (from the places either side of it) and the turn of each
    // copy's shape from the one before nearest the tangent's: the pose in the curve's
    // frame is the sum of the shapes' turns less the tangent's.
    let tangent: Vec<f64> = (0..n).map(|t| angle(at[(t + 1).min(n - 1)] - at[t.saturating_sub(1)])).collect();
    let mut steps: Vec<Similarity> = Vec::with_capacity(n - 1);
    let mut poses = vec![0.0];
    for t in 1..n {
        let (i, j) = (order[t - 1], order[t]);
        let want = wrap(tangent[t] - tangent[t - 1]);
        let step = relations(&sampled[i], &sampled[j], size(i), SHAPE, MAX_SCALE)
            .into_iter()
            .map(|(s, _, _)| s)
            .min_by(|x, y| wrap(x.turn() - want).abs().total_cmp(&wrap(y.turn() - want).abs()))?;
        poses.push(poses[t - 1] + wrap(step.turn() - want));
        steps.push(step);
    }
    // (Against the second copy's: an end's tangent is read from one move, half a step
    // off the copy, and is off by half the move's turn, which the end is allowed.)
    let turns: Vec<f64> = moves.windows(2).map(|w| wrap(angle(w[1]) - angle(w[0])).abs()).collect();
    // (The curvature at each copy from the move turns either side of it, a step's
    // length apart.)
    let bend = |t: usize| {
        let turn = |m: usize| wrap(angle(moves[m + 1]) - angle(moves[m]));
        turn(t.saturating_sub(1).min(moves.len() - 2)) / median
    };
    let half = 0.5 * order.iter().map(|&k| size(k)).sum::<f64>() / n as f64;
    let allowed = |t: usize| {
        POSE + (half * (bend(t) - bend(1)).abs()).min(LEAN)
            + if t == 0 {
                0.5 * turns[0]
            } else if t == n - 1 {
                0.5 * turns[turns.len() - 1]
            } else {
                0.0
            }
    };
    if (0..n).any(|t| (poses[t] - poses[1]).abs() > allowed(t)) {
        return None;
    }
    // (The copies' own turns, each from the first.)
    let headings: Vec<f64> = steps
        .iter()
        .scan(0.0, |h, s| {
            *h += s.turn();
            Some(*h)
        })
        .collect();
    let spread = headings.iter().fold(0.0f64, |m, h| m.max(h.abs()));
    if spread < LEAST_TURN {
        return None;
    }
    // The turn changes gradually, not by turns one way and the other (mirrored arcs).
    let changes: Vec<f64> = steps.windows(2).map(|w| wrap(w[1].turn() - w[0].turn())).collect();
    let sharp = |t: usize| changes[t].abs() > SMOOTH;
    let flips = |t: usize| {
        steps[t].turn() * steps[t + 1].turn() < 0.0
            && steps[t].turn().abs().max(steps[t + 1].turn().abs()) <= MOVE_TURN
            && !(t > 0 && sharp(t - 1))
            && !(t + 1 < changes.len() && sharp(t + 1))
    };
    if (0..changes.len()).any(|t| sharp(t) && !flips(t))
        || changes.windows(3).any(|c| c[0] * c[1] < 0.0 && c[1] * c[2] < 0.0 && c.iter().all(|c| c.abs() > ZIGZAG))
    {
        return None;
    }
    // (A turn alike at every step is a chain's, an arc read from all its copies, where
    // one is found.)
    let turns = steps.iter().map(Similarity::turn);
    let (low, high) = turns.fold((f64::INFINITY, f64::NEG_INFINITY), |(l, h), t| (l.min(t), h.max(t)));
    let changes = high - low >= CHANGE || (high > INFLECTS && low < -INFLECTS);
    let reversed: Vec<usize> = order.iter().rev().copied().collect();
    let inverse: Vec<Similarity> = steps.iter().rev().map(|s| s.inverse()).collect::<Option<_>>()?;
    let ends = [end(&reversed, &inverse, &places, &companions)?, end(&order, &steps, &places, &companions)?];
    Some(Bending { members: order, ends, changes })
}

/// The copies of the drawing's motif: the strokes of its largest stroke's shape (not a
/// dot), at least four, and each other stroke (a leaf's midrib, its dot) with the copy
/// whose centre is nearest it, within that copy's size, in drawing order (indexed by
/// stroke); `None` unless every copy holds as many (each whole).
fn motif(strokes: &[Stroke], sampled: &[Vec<Point>], places: &[Point]) -> Option<(Vec<usize>, Vec<Vec<usize>>)> {
    let n = strokes.len();
    let size = |k: usize| strokes[k].bounds().size().to_vec2().hypot();
    let big = (0..n).max_by(|&x, &y| size(x).total_cmp(&size(y)))?;
    if strokes[big].is_dot() {
        return None;
    }
    let copies: Vec<usize> = (0..n)
        .filter(|&j| {
            j == big
                || (!strokes[j].is_dot()
                    && size(j) * MAX_SCALE >= size(big)
                    && !relations(&sampled[big], &sampled[j], size(big), SHAPE, MAX_SCALE).is_empty())
        })
        .collect();
    if copies.len() < 4 {
        return None;
    }
    let mut parts = vec![Vec::new(); n];
    for j in (0..n).filter(|j| !copies.contains(j)) {
        let &m =
            copies.iter().min_by(|&&x, &&y| places[x].distance(places[j]).total_cmp(&places[y].distance(places[j])))?;
        if places[m].distance(places[j]) > size(m) {
            return None;
        }
        parts[m].push(j);
    }
    let count = parts[copies[0]].len();
    copies.iter().all(|&m| parts[m].len() == count).then_some((copies, parts))
}

/// The copies in order along the curve through `places`: from the one furthest from
/// their mean, each the nearest of those left to the one before (an order that jumps
/// back over the way come fails the caller's `MOVE` test).
fn along(places: &[Point]) -> Option<Vec<usize>> {
    let n = places.len();
    let mean = (places.iter().fold(Vec2::ZERO, |s, p| s + p.to_vec2()) / n as f64).to_point();
    let far = |p: &Point| p.distance(mean);
    let first = (0..n).max_by(|&x, &y| far(&places[x]).total_cmp(&far(&places[y])))?;
    let mut order = vec![first];
    let mut left: Vec<usize> = (0..n).filter(|&k| k != first).collect();
    while !left.is_empty() {
        let here = places[*order.last()?];
        let (pos, _) = left
            .iter()
            .enumerate()
            .min_by(|x, y| here.distance(places[*x.1]).total_cmp(&here.distance(places[*y.1])))?;
        order.push(left.remove(pos));
    }
    Some(order)
}

/// The chain of the last copy of `order`, with the step that carries the curve on past
/// it: turned by the last of the last three `steps`' turns plus their change a step
/// (half the first's to the last's: leaves over a wave's crest turn less each step, and
/// their mean turn put the next 0.24 of a step off), but never more than the latest two
/// turned, nor the other way (carried on, a growing turn curls the curve into a knot),
/// scaled by their mean scale within `SCALE` (a scale read from three copies, carried a
/// third of the way again, made a spiral), and carrying the one before the last onto
/// the last (the next copy is the last move turned so); and how many copies it goes on
/// by (`ON`, `ON_TURN`). (The last copy alone is carried: with variation, the one
/// before it, carried two steps, turned by twice the extrapolated turn, and the copies
/// past an end alternated in pose.)
fn end(order: &[usize], steps: &[Similarity], places: &[Point], parts: &[Vec<usize>]) -> Option<(Chain, usize)> {
    let k = order.len();
    let drawn = k;
    let last = &steps[steps.len().saturating_sub(3)..];
    let turns: Vec<f64> = last.iter().map(Similarity::turn).collect();
    let turn = match turns[..] {
        [t1, t2, t3] => (t3 + 0.5 * (t3 - t1)).clamp(t2.min(t3).min(0.0), t2.max(t3).max(0.0)),
        _ => turns.iter().sum::<f64>() / turns.len() as f64,
    };
    let scale = (last.iter().map(|s| s.scale().ln()).sum::<f64>() / last.len() as f64).exp().clamp(1.0 / SCALE, SCALE);
    let a = Vec2::new(turn.cos(), turn.sin()) * scale;
    let (before, latest) = (order[k - 2], order[k - 1]);
    let b = places[latest].to_vec2() - mul(a, places[before].to_vec2());
    let members = vec![latest];
    let by = ((ON * drawn as f64).floor() as usize).min((ON_TURN / turn.abs().max(1e-9)).floor() as usize);
    let companions = members.iter().map(|&m| parts[m].clone()).collect();
    Some((Chain { members, companions, step: Similarity { a, b }, upright: false, closes: None }, by))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A leaf 36 long from `at` along `theta` (the replay families' own).
    fn leaf(at: Point, theta: f64) -> Stroke {
        crate::vector::sequences::leaf(at, theta, 36.0, &mut crate::rng::Rng::new(1), 0.0)
    }

    /// Leaves every 40 (of arc length) along `y = 300 + amp sin(x / 64)` from `x0`,
    /// each leaning 0.6 off the curve.
    fn wave(count: usize, x0: f64, amp: f64) -> Vec<Stroke> {
        let f = |x: f64| Point::new(x, 300.0 + amp * (x / 64.0).sin());
        let (mut x, mut along, mut out) = (x0, 0.0, Vec::new());
        let site = |x: f64| leaf(f(x), (f(x + 0.01) - f(x)).atan2() - 0.6);
        out.push(site(x));
        while out.len() < count {
            along += f(x).distance(f(x + 0.05));
            x += 0.05;
            if along >= 40.0 {
                along = 0.0;
                out.push(site(x));
            }
        }
        out
    }

    #[test]
    fn leaves_along_a_wave_go_on_as_its_ends_turn() {
        // Six leaves up a wave's rising side and over its crest (the middle six of
        // eight), drawn out of order.
        let truth = wave(8, -150.0, 40.0);
        let mut drawn = truth[1..7].to_vec();
        drawn.swap(1, 4);
        let b = find_bending(&drawn).expect("leaves along a wave");
        let places: Vec<Point> = b.members.iter().map(|&k| drawn[k].reference_point()).collect();
        assert!(places.windows(2).all(|w| w[0].distance(w[1]) < 50.0), "in order along it");
        // Past each end, the leaf before the first and the one after the last (measured
        // 6.4 and under off, at a step of 40).
        let mut next: Vec<Point> = b
            .ends
            .iter()
            .map(|(end, by)| {
                assert!(*by >= 1);
                centroid(&samples(&end.step.carry(&drawn[*end.members.last().unwrap()])))
            })
            .collect();
        let want = [&truth[0], &truth[7]].map(|s| centroid(&samples(s)));
        if next[0].distance(want[0]) > next[1].distance(want[0]) {
            next.swap(0, 1);
        }
        for (p, want) in next.iter().zip(want) {
            let d = p.distance(want);
            assert!(d < 0.2 * 40.0, "{p:?} is {d:.1} off");
        }
    }

    #[test]
    fn a_leaf_with_its_midrib_goes_on_whole() {
        // Each leaf drawn with its midrib, a line along it from its base.
        let leaves = wave(6, -150.0, 40.0);
        let mut drawn = Vec::new();
        for l in &leaves {
            let (base, tip) = (l.points[0], l.points[12]);
            drawn.push(l.clone());
            drawn.push(Stroke::new(vec![base, [0.5 * (base[0] + tip[0]), 0.5 * (base[1] + tip[1])], tip], 1.0, None));
        }
        let b = find_bending(&drawn).expect("leaves with midribs along a wave");
        assert_eq!(b.members.len(), 6);
        for (end, _) in &b.ends {
            for (m, parts) in end.members.iter().zip(&end.companions) {
                assert_eq!(parts, &vec![m + 1], "a leaf's midrib goes with it");
            }
        }
        // A midrib far from any leaf: no motif of whole copies.
        drawn[3] = drawn[3].translated(200.0, 200.0);
        assert!(find_bending(&drawn).is_none());
    }

    #[test]
    fn a_row_a_scatter_and_mixed_shapes_are_not_a_bending_curve() {
        // Straight: a row's.
        let row: Vec<Stroke> = (0..6).map(|k| leaf(Point::new(40.0 * k as f64, 0.0), -0.6)).collect();
        assert!(find_bending(&row).is_none());
        // Each leaf at random: no pose kept along the curve.
        let turns = [0.0, 2.0, -1.0, 2.5, 0.7, -2.2];
        let scatter: Vec<Stroke> =
            (0..6).map(|k| leaf(Point::new(40.0 * k as f64, 30.0 * (k as f64 * 0.5).sin()), turns[k])).collect();
        assert!(find_bending(&scatter).is_none());
        // A line among the leaves.
        let mut mixed = wave(6, -120.0, 40.0);
        mixed[3] = Stroke::new(vec![[0.0, 0.0], [40.0, 0.0]], 2.0, None);
        assert!(find_bending(&mixed).is_none());
    }
}
