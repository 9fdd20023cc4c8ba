//! Finding a chain: the shortest step that carries about the most copies onto another
//! of their shape, the run it makes, the strokes drawn beside each copy, whether it
//! closes; and the drawing's other rings.

use super::{Chain, MAX_STROKES};
use crate::vector::similarity::{centroid, mul, relations, samples, Similarity};
use crate::vector::stroke::Stroke;
use kurbo::{Point, Vec2};
use std::f64::consts::TAU;

/// Same shape: the best similarity leaves an rms residual of at most this share of
/// the stroke's size, and scales by at most `MAX_SCALE` either way.
pub(super) const SHAPE: f64 = 0.15;
pub(super) const MAX_SCALE: f64 = 1.3;
/// Two relations are the same step when their `a` differ by at most this share of `|a|`
/// (about 17 degrees: a person's hand turns each copy by about 2.5 degrees at random,
/// and three petals of five read pair turns of 65.2 and 77.7 degrees; at 11 degrees, 6
/// of 50 rings begun with three petals at 1% of the step made no chain, now 3).
const TURN: f64 = 0.3;
/// A step carries a copy onto another when it puts its centre within this share of the
/// step's length.
const PLACE: f64 = 0.3;
/// A step turns or scales by at least this much (`|a - 1|`, about 1°): one that does
/// not is a row's, which the lattice reads.
const MIN_TURN: f64 = 0.02;
/// A ring's step turns by at most this much (135 degrees): a ring of three turns 120,
/// and a half turn is its own inverse, which carries copies in pairs and makes no
/// chain. Two flowers of six alike petals, the second begun with four, are carried
/// onto each other by the half turn about the point between them: it carried 8 copies
/// to the ring's 6, and the drawing came back as it was. (`find` still weighs every
/// turn: plus signs touching on a lattice, without their half turns, read a ring of
/// their bars that held most of the drawing, and grew as rosettes.)
const MAX_TURN: f64 = 0.75 * std::f64::consts::PI;
/// No limit (a turn is at most a half turn): `find`'s search. A closed ring's step
/// turns at most 120 degrees and a little, so a ring it reads is one `find_ring` could.
const HALF_TURN: f64 = std::f64::consts::PI + 0.01;
/// Once the step is chosen, the chain follows it from copy to copy within this share
/// of its length (a hand's copy may stray further than the candidates are held to:
/// one line of sixteen hatching lines off by a third of their spacing).
const FOLLOW: f64 = 0.5;
/// Candidate steps relate each copy to this many of its nearest of the same shape.
const NEAREST: usize = 4;
/// A rosette closes when its steps round a whole turn are within this of a whole number
/// (or a tenth of it).
const CLOSE: f64 = 0.3;
/// Copies whose centre of turn is within this many of their sizes are a rosette.
const ROSETTE: f64 = 1.5;
/// The most copies round a ring.
pub(super) const MAX_RING: usize = 72;

/// The chain of `strokes`, if they repeat along a similarity step.
pub fn find(strokes: &[Stroke]) -> Option<Chain> {
    search(strokes, HALF_TURN).filter(|f| f.whole).map(|f| f.chain)
}

/// A ring among `strokes`, though other strokes of its shape lie outside it: one of two
/// flowers drawn with alike petals (`find` takes no chain that holds under two thirds
/// of its shape's strokes). It must hold two thirds of them about its own centre.
pub fn find_ring(strokes: &[Stroke]) -> Option<Chain> {
    search(strokes, MAX_TURN).filter(|f| f.ring).map(|f| f.chain)
}

/// `find`'s chain, or else `find_ring`'s, or else `find_upright`'s: with whether it is
/// `find`'s (or, upright, holds the drawing whole).
pub fn find_or_ring(strokes: &[Stroke]) -> Option<(Chain, bool)> {
    match search(strokes, HALF_TURN) {
        Some(f) if f.whole => Some((f.chain, true)),
        Some(f) if f.ring => Some((f.chain, false)),
        _ => find_ring(strokes).map(|c| (c, false)).or_else(|| find_upright(strokes).map(|c| (c, true))),
    }
}

/// Copies of one stroke that keep their pose while their places bend (fence posts along
/// an arc, upright): every stroke of the drawing one shape, each a translation of the
/// others (turned by at most `UPRIGHT_TURN`, scaled by at most `UPRIGHT_SCALE`), their
/// places in order along the row each a move on from the last (within `UPRIGHT_MOVE`
/// either way of the median), bending steadily (`bend::steady_bend`). The step is the
/// turn that carries each place onto the next, fitted to all of them; the chain
/// carries its copies by it unturned. (`search` takes no step that only translates:
/// those are the lattice's, and a row that bends is none.)
pub fn find_upright(strokes: &[Stroke]) -> Option<Chain> {
    let n = strokes.len();
    if !(4..=MAX_STROKES).contains(&n) || strokes.iter().any(Stroke::is_dot) {
        return None;
    }
    let sampled: Vec<Vec<Point>> = strokes.iter().map(samples).collect();
    let size = |k: usize| strokes[k].bounds().size().to_vec2().hypot();
    let alike = |i: usize, j: usize| {
        relations(&sampled[i], &sampled[j], size(i), SHAPE, MAX_SCALE)
            .iter()
            .any(|(t, _, _)| t.turn().abs() <= UPRIGHT_TURN && (t.scale() - 1.0).abs() <= UPRIGHT_SCALE)
    };
    if !(1..n).all(|j| alike(0, j)) {
        return None;
    }
    // In order along the row: by their places along its chord's direction (the row's
    // principal axis; an arc bending less than a half turn keeps that order).
    let centre: Vec<Point> = sampled.iter().map(|s| centroid(s)).collect();
    let (_, axis) = super::bend::principal_axis(&centre);
    let mut order: Vec<usize> = (0..n).collect();
    order.sort_by(|&x, &y| centre[x].to_vec2().dot(axis).total_cmp(&centre[y].to_vec2().dot(axis)));
    let places: Vec<Point> = order.iter().map(|&k| centre[k]).collect();
    let lengths: Vec<f64> = places.windows(2).map(|w| w[0].distance(w[1])).collect();
    let median = crate::vector::classify::median(&mut lengths.clone());
    if median <= 0.0 || lengths.iter().any(|&l| l > UPRIGHT_MOVE * median || l < median / UPRIGHT_MOVE) {
        return None;
    }
    super::bend::steady_bend(&super::bend::move_turns(&places))?;
    // The turn about the circle through the places (least squares), by their mean angle
    // a step: a pure turn, since copies that keep their pose keep their size (a scale
    // read from four places is their scatter's, and made a spiral of posts), and read
    // from the circle rather than from each place onto the next, whose scatter in both
    // carried the posts a quarter of a step off the arc round its far side.
    let c = super::bend::circle_through(&places)?;
    let turn = super::bend::turn_about(c, &places);
    let a = Vec2::new(turn.cos(), turn.sin());
    let step = Similarity { a, b: c.to_vec2() - mul(a, c.to_vec2()) };
    if places.windows(2).any(|w| step.apply(w[0]).distance(w[1]) > PLACE * median) {
        return None;
    }
    Some(Chain { members: order, companions: vec![Vec::new(); n], step, upright: true, closes: None })
}

/// An upright chain's copies turn by at most this (radians, about 9 degrees: a hand's
/// own), scale by at most this share, and lie a move apart within this factor of the
/// median move either way.
const UPRIGHT_TURN: f64 = 0.15;
const UPRIGHT_SCALE: f64 = 0.25;
const UPRIGHT_MOVE: f64 = 1.5;

/// The chain the search reads, and which share of its shape's strokes it holds.
struct Found {
    chain: Chain,
    /// Two thirds of its shape's strokes in the drawing (`find`).
    whole: bool,
    /// It closes, and holds two thirds of its shape's strokes about its centre
    /// (`find_ring`).
    ring: bool,
}

/// The search, taking candidate steps that turn by at most `max_turn`.
fn search(strokes: &[Stroke], max_turn: f64) -> Option<Found> {
    let n = strokes.len();
    if !(3..=MAX_STROKES).contains(&n) {
        return None;
    }
    let sampled: Vec<Vec<Point>> = strokes.iter().map(samples).collect();
    let centre: Vec<Point> = sampled.iter().map(|s| centroid(s)).collect();
    let size: Vec<f64> = strokes.iter().map(|s| s.bounds().size().to_vec2().hypot()).collect();
    // Each pair's fits as good as its best, the smallest turn first (`relations`: a
    // petal symmetric under a half turn, an ellipse, fits turned either way, and four
    // ellipses round a centre read turns of 90 and -90 degrees by the hand's noise).
    let mut fits: Vec<Vec<Similarity>> = vec![Vec::new(); n * n];
    // (A dot, a tap of the pen a few widths across, has no shape to relate: three to six
    // points within two pixels are noise. Dots relate to one another by place alone,
    // and to nothing else.)
    let dot = |k: usize| strokes[k].is_dot();
    for i in 0..n {
        for j in 0..n {
            let ratio = size[j] / size[i].max(1e-9);
            if i != j && dot(i) && dot(j) {
                fits[i * n + j] = vec![Similarity { a: Vec2::new(1.0, 0.0), b: centre[j] - centre[i] }];
            } else if i != j && !dot(i) && !dot(j) && (1.0 / MAX_SCALE..=MAX_SCALE).contains(&ratio) {
                let all = relations(&sampled[i], &sampled[j], size[i], SHAPE, MAX_SCALE);
                let best = all.iter().map(|f| f.1).fold(f64::INFINITY, f64::min);
                fits[i * n + j] = all.into_iter().filter(|f| f.1 <= (1.5 * best).max(0.02)).map(|f| f.0).collect();
            }
        }
    }
    // Shape groups: strokes related to one another, directly or through others.
    let mut group: Vec<usize> = (0..n).collect();
    fn root(g: &mut [usize], mut i: usize) -> usize {
        while g[i] != i {
            g[i] = g[g[i]];
            i = g[i];
        }
        i
    }
    for i in 0..n {
        for j in 0..n {
            if !fits[i * n + j].is_empty() {
                let (a, b) = (root(&mut group, i), root(&mut group, j));
                group[a] = b;
            }
        }
    }
    let groups: Vec<usize> = (0..n).map(|i| root(&mut group, i)).collect();
    // Where `t` carries copy `k`: the copy of its shape it lands on, related to it by
    // about the same step.
    // (A dot turns as the pen went: its copies are carried by place alone. A petal's dot
    // at its tip was left off 23 of 58.)
    let onto = |t: &Similarity, k: usize, reach: f64| -> Option<usize> {
        let p = t.apply(centre[k]);
        // (Where it lands first: the cheap test, before the fits.)
        (0..n)
            .map(|m| (m, centre[m].distance(p)))
            .filter(|&(m, d)| d <= reach && m != k && groups[m] == groups[k])
            .filter(|&(m, _)| fits[k * n + m].iter().any(|r| dot(k) || (r.a - t.a).hypot() <= TURN * t.a.hypot()))
            .min_by(|x, y| x.1.total_cmp(&y.1))
            .map(|(m, _)| m)
    };
    // The candidate step that carries the most copies onto another, the shortest first;
    // candidates relate each copy to its nearest few of its shape (a step joins
    // neighbours along the chain).
    // (Within a tenth of the most, or one, the shortest: a double step carries as many
    // round a ring, and its reach, a share of its length, forgives a shaky petal the
    // single step does not. Nine ellipses, each related either way round, were read as
    // a step of two petals, 80 degrees, that closes no ring.)
    let mut candidates: Vec<(usize, f64, Similarity)> = Vec::new();
    for i in 0..n {
        let mut near: Vec<usize> = (0..n).filter(|&j| !fits[i * n + j].is_empty()).collect();
        near.sort_by(|&x, &y| centre[i].distance(centre[x]).total_cmp(&centre[i].distance(centre[y])));
        for (j, &t) in near.iter().take(NEAREST).flat_map(|&j| fits[i * n + j].iter().map(move |t| (j, t))) {
            let d = centre[i].distance(centre[j]);
            if (t.a - Vec2::new(1.0, 0.0)).hypot() < MIN_TURN || t.turn().abs() > max_turn {
                continue;
            }
            // Copies on one centre (an asterisk's bars) step by a turn alone: reach is
            // then read from their size.
            let d = d.max(0.1 * size[i]);
            // (Copies of every shape: the step of a motif of several strokes carries
            // each of them, a petal and its vein.)
            let carried = (0..n).filter(|&k| onto(&t, k, PLACE * d).is_some()).count();
            if carried >= 2 {
                candidates.push((carried, d, t));
            }
        }
    }
    let most = candidates.iter().map(|c| c.0).max()?;
    let enough = most - (most / 10).max(1).min(most - 2);
    let shortest = candidates.iter().filter(|c| c.0 >= enough).map(|c| c.1).fold(f64::INFINITY, f64::min);
    // (Then, of the steps about that long, the one that carries the most: each is one
    // pair's relation, and a shaky pair's leaves a petal's dot behind.)
    let (_, d, t) = candidates.into_iter().filter(|c| c.1 <= 1.25 * shortest).reduce(|b, c| {
        if c.0 > b.0 || (c.0 == b.0 && c.1 < b.1) {
            c
        } else {
            b
        }
    })?;
    let next: Vec<Option<usize>> = (0..n).map(|k| onto(&t, k, FOLLOW * d)).collect();
    // Every run along the step, from a copy no other steps onto (a closed ring: from its
    // first-drawn copy); the longest is the chain.
    let runs = runs(&next);
    // (Of runs as long, the one of the largest strokes: the turn is read from its
    // shapes, and a dot's says nothing.)
    // A run of dots, which link by place alone, never leads one of larger strokes.
    let extent = |r: &Vec<usize>| r.iter().map(|&k| size[k]).sum::<f64>();
    let key = |r: &Vec<usize>| (r.iter().any(|&k| !dot(k)), r.len());
    let chain = runs.iter().max_by(|x, y| key(x).cmp(&key(y)).then(extent(x).total_cmp(&extent(y))))?.clone();
    // Runs beside it, a motif's other strokes (see `Chain::companions`).
    let mut companions = companions(&chain, &runs);
    // (And strokes of one shape in no run that the step carries onto one another in
    // whole numbers of steps: the veins of the first and third petals, the second drawn
    // bare, left four petals of six bare in every rosette.)
    for g in (0..n).filter(|&k| groups[k] == k) {
        let loose: Vec<usize> = (0..n)
            .filter(|&k| groups[k] == g && !chain.contains(&k) && !companions.iter().flatten().any(|&c| c == k))
            .collect();
        if loose.len() < 2 {
            continue;
        }
        let beside = self::companions(&chain, std::slice::from_ref(&loose));
        let placed: Vec<(i64, usize)> =
            beside.iter().enumerate().flat_map(|(i, c)| c.iter().map(move |&k| (i as i64, k))).collect();
        let carried = placed.windows(2).all(|w| {
            let ((i, a), (j, b)) = (w[0], w[1]);
            t.power(j - i).is_some_and(|tk| tk.apply(centre[a]).distance(centre[b]) <= FOLLOW * d)
        });
        if placed.len() == loose.len() && carried {
            for (c, more) in companions.iter_mut().zip(beside) {
                c.extend(more);
                c.sort_unstable();
            }
        }
    }
    let covered = chain.len() + companions.iter().map(Vec::len).sum::<usize>();
    let grouped =
        |k: usize| groups[k] == groups[chain[0]] || companions.iter().flatten().any(|&c| groups[c] == groups[k]);
    let shape_count = (0..n).filter(|&k| grouped(k)).count();
    if chain.len() < 3 {
        return None;
    }
    let whole = 3 * covered >= 2 * shape_count;
    // The step: its turn and scale from the copies' shapes (the mean over consecutive
    // pairs, each fitted on its own, so that where the hand put each copy does not
    // leak into how it turned it), its shift from where the copies are (the mean of
    // what each pair needs, given the turn).
    // (Each consecutive pair's own fit is its relation, read the way round it fits.)
    let pairs: Vec<Similarity> = chain
        .windows(2)
        .map(|w| nearest_fit(&fits[w[0] * n + w[1]], t).expect("consecutive copies are related"))
        .collect();
    let shift_for = |a: Vec2| {
        let b = chain.windows(2).fold(Vec2::ZERO, |s, w| s + centre[w[1]].to_vec2() - mul(a, centre[w[0]].to_vec2()));
        Similarity { a, b: b / pairs.len() as f64 }
    };
    let mut step = shift_for(pairs.iter().fold(Vec2::ZERO, |s, t| s + t.a) / pairs.len() as f64);
    // A turn without scale is read from where the copies are as well: the mean angle
    // each pair of copies makes at the centre, averaged with the shapes' turn (each
    // alone errs about as much: a petal's angle as its place round the centre).
    let off = |c: Point| chain.iter().all(|&k| centre[k].distance(c) > 0.25 * size[k]);
    if let (true, Some(c)) = ((step.scale() - 1.0).abs() < 0.04, step.fixed_point().filter(|&c| off(c))) {
        let placed = super::bend::turn_about(c, &chain.iter().map(|&k| centre[k]).collect::<Vec<_>>());
        let turn = 0.5 * (step.turn() + placed);

        // (Within 4%, a scale is the hand's: a curve's copies stay its size.)
        step = shift_for(Vec2::new(turn.cos(), turn.sin()));
    }
    if (step.a - Vec2::new(1.0, 0.0)).hypot() < MIN_TURN {
        return None;
    }
    // Every consecutive pair within reach of the fitted step.
    let len = (chain.windows(2).map(|w| centre[w[0]].distance(centre[w[1]])).sum::<f64>() / (chain.len() - 1) as f64)
        .max(0.1 * size[chain[0]]);
    if chain.windows(2).any(|w| step.apply(centre[w[0]]).distance(centre[w[1]]) > FOLLOW * len) {
        return None;
    }
    // A ring (`ring_steps`)?
    let radius =
        step.fixed_point().map(|c| chain.iter().map(|&k| centre[k].distance(c)).sum::<f64>() / chain.len() as f64);
    let size = chain.iter().map(|&k| size[k]).sum::<f64>() / chain.len() as f64;
    let closes = radius.and_then(|r| ring_steps(&step, r, size, chain.len()));
    if let Some(k) = closes {
        // The turn snapped, and the shift read again for it.
        let turn = TAU / k as f64 * step.turn().signum();
        step = shift_for(Vec2::new(turn.cos(), turn.sin()));
    }
    // A chain that does not close turns each copy less than a right angle from the last
    // (leaves along a curve, hatching that turns, a spiral): nine open petal loops, each
    // fitting its neighbours either way round, read a step of 157 degrees that left the
    // drawing as it was.
    if closes.is_none() && step.turn().abs() > std::f64::consts::FRAC_PI_2 {
        return None;
    }
    // (A second flower: two thirds of its shape's strokes about its centre, as `find`
    // asks of the whole drawing's; four petals of nine drawn whole read a ring of 11.)
    let ring = match (step.fixed_point(), radius, closes) {
        (Some(c), Some(r), Some(_)) => {
            let about = (0..n).filter(|&k| grouped(k) && centre[k].distance(c) <= r + size).count();
            3 * covered >= 2 * about
        }
        _ => false,
    };
    Some(Found { chain: Chain { members: chain, companions, step, upright: false, closes }, whole, ring })
}

/// Of `fits`, the one whose turn and scale are nearest `t`'s.
fn nearest_fit(fits: &[Similarity], t: Similarity) -> Option<Similarity> {
    fits.iter().copied().min_by(|x, y| (x.a - t.a).hypot().total_cmp(&(y.a - t.a).hypot()))
}

/// Further rings among the strokes `chain` does not hold, each indexed in `strokes`:
/// two flowers drawn side by side are two rings (`find` takes one, and the other's
/// petals are no part of it), and each is completed. A chain among the rest that does
/// not close ends the search.
pub fn rings_beside(strokes: &[Stroke], chain: &Chain) -> Vec<Chain> {
    let mut held = vec![false; strokes.len()];
    let mut out: Vec<Chain> = Vec::new();
    chain.held().for_each(|k| held[k] = true);
    // Each ring's centre, radius and copy size.
    let circle = |c: &Chain| {
        let centre = c.centre()?;
        let placed = c.members.iter().map(|&k| strokes[k].reference_point().distance(centre));
        let size = c.members.iter().map(|&k| strokes[k].bounds().size().to_vec2().hypot());
        let n = c.members.len() as f64;
        Some((centre, placed.sum::<f64>() / n, size.sum::<f64>() / n))
    };
    let mut circles: Vec<(Point, f64, f64)> = circle(chain).into_iter().collect();
    loop {
        let rest: Vec<usize> = (0..strokes.len()).filter(|&k| !held[k]).collect();
        let sub: Vec<Stroke> = rest.iter().map(|&k| strokes[k].clone()).collect();
        let Some(ring) = find_ring(&sub) else { return out };
        let ring = Chain {
            members: ring.members.iter().map(|&k| rest[k]).collect(),
            companions: ring.companions.iter().map(|c| c.iter().map(|&k| rest[k]).collect()).collect(),
            ..ring
        };
        ring.held().for_each(|k| held[k] = true);
        // (Petals of a ring found already, left out of its chain by a shaky hand, are
        // on its circle: its completion takes their places. A ring round the same centre
        // further out is a ring of its own.)
        let Some((c, r, size)) = circle(&ring) else { continue };
        if circles.iter().any(|&(d, q, s)| c.distance(d) < 0.5 * s.max(size) && (r - q).abs() < 0.5 * s.max(size)) {
            continue;
        }
        circles.push((c, r, size));
        out.push(ring);
    }
}

/// The maximal runs of `next` (each stroke's successor along the step): from each copy
/// no other steps onto, and where none starts (a ring closed whole), from the first.
fn runs(next: &[Option<usize>]) -> Vec<Vec<usize>> {
    let follow = |s: usize| {
        let mut run = vec![s];
        while let Some(m) = next[*run.last().expect("a run holds its start")] {
            if run.contains(&m) {
                break;
            }
            run.push(m);
        }
        run
    };
    let mut pointed = vec![false; next.len()];
    for &m in next.iter().flatten() {
        pointed[m] = true;
    }
    let mut out: Vec<Vec<usize>> = (0..next.len()).filter(|&s| next[s].is_some() && !pointed[s]).map(follow).collect();
    for (s, n) in next.iter().enumerate() {
        if n.is_some() && !out.iter().flatten().any(|&k| k == s) {
            out.push(follow(s));
        }
    }
    out
}

/// For each copy of `chain`, the strokes of the other `runs` drawn beside it: a run of
/// two or more whose strokes each lie the same number of strokes from a copy of the
/// chain in the drawing's order (fewer than usually separate two copies). A run may
/// wrap round a ring where one of its strokes is missing (a petal drawn without its
/// vein: the veins after it, round to those before), so its strokes need not come in
/// the chain's order.
fn companions(chain: &[usize], runs: &[Vec<usize>]) -> Vec<Vec<usize>> {
    let mut out = vec![Vec::new(); chain.len()];
    // (The median, not the least: a copy missing a stroke is drawn closer to the next.)
    let mut gaps: Vec<usize> = chain.windows(2).map(|w| w[0].abs_diff(w[1])).collect();
    gaps.sort_unstable();
    let gap = gaps.get(gaps.len() / 2).copied().unwrap_or(0) as u64;
    let place = |k: usize, d: i64| chain.iter().position(|&c| c as i64 + d == k as i64);
    for r in runs.iter().filter(|r| r.len() >= 2 && r.len() <= chain.len() && r.iter().all(|k| !chain.contains(k))) {
        let beside = chain
            .iter()
            .map(|&c| r[0] as i64 - c as i64)
            .find(|&d| d.unsigned_abs() < gap && r.iter().all(|&k| place(k, d).is_some()));
        if let Some(d) = beside {
            for &k in r {
                out[place(k, d).expect("checked above")].push(k);
            }
        }
    }
    for c in &mut out {
        c.sort_unstable();
    }
    out
}

/// The copies round a whole ring, when copies `size` large on the orbit of `step`,
/// `radius` from its centre, `drawn` of them, close into one: a ring round a centre
/// close by (petals: the centre within about a copy's size) or drawn half round it, no
/// scale, and a whole number of steps round, however the hand's wobble has put the
/// turn (three petals of twelve at 3% of the step read the turn 4% off): the nearest
/// whole number within a tenth of it, to which the turn is then snapped. Copies round a
/// far centre (leaves along an arc) are a curve: snapping 25.7 steps round to 26 would
/// put the 8th leaf on from the drawn ones 9% of a step off its arc.
pub fn ring_steps(step: &Similarity, radius: f64, size: f64, drawn: usize) -> Option<usize> {
    let turns = TAU / step.turn().abs();
    let whole = turns.round();
    // (A ring drawn half round or more, sun rays round a disc, closes however far.)
    let rosette =
        radius <= ROSETTE * size || drawn.saturating_sub(1) as f64 * step.turn().abs() >= std::f64::consts::PI;
    (rosette
        && (step.scale() - 1.0).abs() < 0.04
        && (turns - whole).abs() <= CLOSE.max(0.1 * whole)
        && (3.0..=MAX_RING as f64).contains(&whole))
    .then_some(whole as usize)
}
