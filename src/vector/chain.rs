//! Repetition along a similarity step, where the drawing holds no lattice (issue 27):
//! petals round a centre, leaves along a curved stem, hatching that turns, a spiral.
//! Each copy is the one before under one step `z -> a z + b` (`similarity`); the step
//! turns (a ring, or an arc: a turn about a far centre) or scales (a spiral).
//!
//! Finding it: strokes of one shape up to rotation and scale are related pairwise; each
//! relation between two of them is a candidate step, and the step kept is the one that
//! carries the most strokes onto another of their shape (the shortest such, so that a
//! double step is not taken for the step). Strokes carried beside the chain's copies,
//! drawn with them, are their motif's other strokes (`Chain::companions`). Following it from a copy no other copy steps onto gives the
//! chain; it must hold at least three copies and two thirds of its shape's strokes (the
//! petals of one flower among several are a flower's, not the drawing's, repetition).
//! The step is then fitted by least squares over every consecutive pair, and where its
//! turn is close to a whole fraction of a turn (and it does not scale) the ring closes:
//! the turn is snapped to it.
//!
//! Continuing it: copies further along, both ways, each a drawn copy carried by the step
//! as many times as it lies from it (with variation, a random drawn copy, so the hand's
//! own differences recur; without, the nearest end), until a copy would leave the area,
//! land on one placed already (a circle closing), or shrink or grow past sense.
//!
//! Departs from the seed paper (which repeats by translation only, comparing shapes up
//! to translation); follows Xing et al. 2014's local similarity, read globally from all
//! the drawn copies since synthesis sees the whole drawing at once.

use super::frechet::closed_loop;
use super::similarity::{centroid, mul, relate, samples, Similarity};
use super::stroke::Stroke;
use crate::rng::Rng;
use kurbo::{Point, Rect, Vec2};
use serde::Serialize;
use std::f64::consts::TAU;

/// Which structure a synthesis repeated the drawing on.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Structure {
    /// Translations (rows and grids; an exact tile).
    Lattice,
    /// Copies turned round a centre, closing after a whole number of steps.
    Ring,
    /// Copies along an arc (a turn about a far centre that does not close in view).
    Curve,
    /// Copies each turned and scaled from the last (a spiral, hatching that widens).
    Sequence,
    /// No repetition: a mosaic of the drawing's own windows, or a mesh joined afresh.
    Irregular,
}

/// Drawings with more strokes than this are not searched for a chain (each pair of
/// strokes of one shape is related; hand-drawn rings and curves are small).
pub const MAX_STROKES: usize = 160;
/// Same shape: the best similarity leaves an rms residual of at most this share of
/// the stroke's size, and scales by at most `MAX_SCALE` either way.
const SHAPE: f64 = 0.15;
const MAX_SCALE: f64 = 1.3;
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
/// The most steps a chain is followed either way.
const MAX_STEPS: i64 = 400;
/// The most copies round a ring.
const MAX_RING: usize = 72;
/// A completed copy's stroke lies on a drawn one when their centres, and the paths
/// themselves (`apart`), are at most this share of its size apart. (Paired sample by
/// sample from their starts only, a petal drawn as a loop begun elsewhere on its
/// outline than the copy carried onto it was not on it: five petals drawn whole with a
/// shaky pointer, the fifth left out of the chain, synthesized as rosettes of six with
/// that petal doubled.)
const ON: f64 = 0.1;

/// The drawn copies in order along the step, and the step.
#[derive(Clone, Debug)]
pub struct Chain {
    /// Strokes of the drawn copies, in order: `step` carries each onto the next.
    pub members: Vec<usize>,
    /// Each drawn copy's other strokes, of a motif of several (a petal drawn as two
    /// arcs, a leaf and its vein): each carried by the step onto the next copy's, drawn
    /// as near its member in the drawing's order in every copy; empty for a motif of one
    /// stroke, and for a copy short of some.
    pub companions: Vec<Vec<usize>>,
    pub step: Similarity,
    /// Copies round the whole ring, when it closes (a rosette: petals round a centre
    /// within `ROSETTE` copy sizes).
    pub closes: Option<usize>,
}

/// The chain of `strokes`, if they repeat along a similarity step.
pub fn find(strokes: &[Stroke]) -> Option<Chain> {
    let n = strokes.len();
    if !(3..=MAX_STROKES).contains(&n) {
        return None;
    }
    let sampled: Vec<Vec<Point>> = strokes.iter().map(samples).collect();
    let centre: Vec<Point> = sampled.iter().map(|s| centroid(s)).collect();
    let size: Vec<f64> = strokes.iter().map(|s| s.bounds().size().to_vec2().hypot()).collect();
    let mut rel: Vec<Option<(Similarity, bool)>> = vec![None; n * n];
    // (A dot, a tap of the pen a few widths across, has no shape to relate: three to six
    // points within two pixels are noise. Dots relate to one another by place alone,
    // and to nothing else.)
    let dot = |k: usize| strokes[k].is_dot();
    for i in 0..n {
        for j in 0..n {
            let ratio = size[j] / size[i].max(1e-9);
            if i != j && dot(i) && dot(j) {
                let shift = Similarity { a: Vec2::new(1.0, 0.0), b: centre[j] - centre[i] };
                rel[i * n + j] = Some((shift, false));
            } else if i != j && !dot(i) && !dot(j) && (1.0 / MAX_SCALE..=MAX_SCALE).contains(&ratio) {
                rel[i * n + j] = relate(&sampled[i], &sampled[j], size[i], SHAPE, MAX_SCALE).map(|(t, _, b)| (t, b));
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
            if rel[i * n + j].is_some() {
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
        (0..n)
            .filter(|&m| m != k && groups[m] == groups[k])
            .filter(|&m| rel[k * n + m].is_some_and(|(r, _)| dot(k) || (r.a - t.a).hypot() <= TURN * t.a.hypot()))
            .map(|m| (m, centre[m].distance(p)))
            .filter(|&(_, d)| d <= reach)
            .min_by(|x, y| x.1.total_cmp(&y.1))
            .map(|(m, _)| m)
    };
    // The candidate step that carries the most copies onto another, the shortest first;
    // candidates relate each copy to its nearest few of its shape (a step joins
    // neighbours along the chain).
    let mut best: Option<(usize, f64, Similarity)> = None;
    for i in 0..n {
        let mut near: Vec<usize> = (0..n).filter(|&j| rel[i * n + j].is_some()).collect();
        near.sort_by(|&x, &y| centre[i].distance(centre[x]).total_cmp(&centre[i].distance(centre[y])));
        for &j in near.iter().take(NEAREST) {
            let Some((t, _)) = rel[i * n + j] else { continue };
            let d = centre[i].distance(centre[j]);
            if (t.a - Vec2::new(1.0, 0.0)).hypot() < MIN_TURN {
                continue;
            }
            // Copies on one centre (an asterisk's bars) step by a turn alone: reach is
            // then read from their size.
            let d = d.max(0.1 * size[i]);
            // (Copies of every shape: the step of a motif of several strokes carries
            // each of them, a petal and its vein.)
            let carried = (0..n).filter(|&k| onto(&t, k, PLACE * d).is_some()).count();
            let better = match &best {
                None => carried >= 2,
                Some(b) => carried > b.0 || (carried == b.0 && d < b.1),
            };
            if better {
                best = Some((carried, d, t));
            }
        }
    }
    let (_, d, t) = best?;
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
    if chain.len() < 3 || 3 * covered < 2 * shape_count {
        return None;
    }
    // The step: its turn and scale from the copies' shapes (the mean over consecutive
    // pairs, each fitted on its own, so that where the hand put each copy does not
    // leak into how it turned it), its shift from where the copies are (the mean of
    // what each pair needs, given the turn).
    // (Each consecutive pair's own fit is its relation, read the way round it fits.)
    let pairs: Vec<Similarity> =
        chain.windows(2).map(|w| rel[w[0] * n + w[1]].expect("consecutive copies are related").0).collect();
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
        let angle = |p: Point| (p.y - c.y).atan2(p.x - c.x);
        let placed = chain
            .windows(2)
            .map(|w| {
                (angle(centre[w[1]]) - angle(centre[w[0]]) + 3.0 * std::f64::consts::PI).rem_euclid(TAU)
                    - std::f64::consts::PI
            })
            .sum::<f64>()
            / pairs.len() as f64;
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
    Some(Chain { members: chain, companions, step, closes })
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

impl Chain {
    /// The structure the chain makes.
    pub fn structure(&self) -> Structure {
        if self.closes.is_some() {
            Structure::Ring
        } else if (self.step.scale() - 1.0).abs() < 0.04 {
            Structure::Curve
        } else {
            Structure::Sequence
        }
    }

    /// The chain with its drawing moved by `v`: the step conjugated by the move.
    pub fn moved(&self, v: Vec2) -> Chain {
        let t = self.step;
        Chain { step: Similarity { a: t.a, b: t.b + v - mul(t.a, v) }, ..self.clone() }
    }

    /// The centre a ring turns about.
    pub fn centre(&self) -> Option<Point> {
        self.closes.and(self.step.fixed_point())
    }

    /// The copy `t` steps from the first drawn one (the drawn copies are 0 to
    /// `members - 1`), carried from drawn copy `from`: its member, then its other
    /// strokes, each with the stroke it was carried from.
    fn copy(&self, strokes: &[Stroke], t: i64, from: usize) -> Option<Vec<(Stroke, usize)>> {
        let step = self.step.power(t - from as i64)?;
        let parts = std::iter::once(self.members[from]).chain(self.companions.get(from).into_iter().flatten().copied());
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

    /// How many of the drawing's strokes the chain holds.
    pub fn strokes(&self) -> usize {
        self.members.len() + self.companions.iter().map(Vec::len).sum::<usize>()
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
        let mut placed: Vec<(Point, Vec<Point>)> = strokes
            .iter()
            .map(|s| {
                let s = samples(s);
                (centroid(&s), s)
            })
            .collect();
        let mut out = Vec::new();
        // (From the first copy short of a stroke: a motif's copy being drawn.)
        let most = self.companions.iter().map(Vec::len).max().unwrap_or(0);
        let first = (0..self.members.len()).find(|&i| self.companions.get(i).map_or(0, Vec::len) < most);
        for t in first.unwrap_or(self.members.len())..k {
            let from = self.source(t as i64, &mut rng);
            let Some(copy) = self.copy(strokes, t as i64, from) else { continue };
            // (A drawn copy short of a stroke gets that stroke only: its member is drawn.)
            let drawn = usize::from(t < self.members.len());
            for (stroke, source) in copy.into_iter().skip(drawn) {
                let s = samples(&stroke);
                let size = stroke.bounds().size().to_vec2().hypot();
                let c = centroid(&s);
                if placed.iter().any(|(pc, p)| pc.distance(c) < ON * size && apart(&s, p) < ON * size) {
                    continue;
                }
                placed.push((c, s));
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
                if (t - if dir > 0 { l - 1 } else { 0 }).abs() > steps.min(MAX_STEPS) {
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

#[cfg(test)]
mod tests {
    use super::*;

    /// A petal: a loop `len` long from `at` along `theta`.
    fn petal(at: Point, theta: f64, len: f64) -> Stroke {
        let pts = (0..=20)
            .map(|k| {
                let t = k as f64 / 20.0 * TAU;
                let (along, across) = (0.5 * len * (1.0 - t.cos()), len / 6.0 * t.sin());
                let (c, s) = (theta.cos(), theta.sin());
                [at.x + along * c - across * s, at.y + along * s + across * c]
            })
            .collect();
        Stroke::new(pts, 2.0, None)
    }

    #[test]
    fn three_petals_of_eight_make_a_ring_and_complete_it() {
        let c = Point::new(100.0, 100.0);
        let drawn: Vec<Stroke> = (0..3).map(|k| petal(c, k as f64 * TAU / 8.0, 60.0)).collect();
        let chain = find(&drawn).expect("a ring");
        assert_eq!(chain.closes, Some(8));
        assert_eq!(chain.members, vec![0, 1, 2]);
        assert!(chain.centre().unwrap().distance(c) < 1.0);
        let rest = chain.complete(&drawn, None);
        assert_eq!(rest.len(), 5);
        for (k, (s, _)) in rest.iter().enumerate() {
            let want = petal(c, (3 + k) as f64 * TAU / 8.0, 60.0).reference_point();
            assert!(s.reference_point().distance(want) < 1.0, "petal {}", k + 3);
        }
    }

    #[test]
    fn a_petal_drawn_from_another_start_closes_the_ring() {
        // Five petals of five, the fifth (left out of the chain, as a shaky hand's may
        // be) a loop begun half way round its outline: the ring is whole.
        let c = Point::new(200.0, 200.0);
        let mut drawn: Vec<Stroke> = (0..5).map(|k| petal(c, k as f64 * TAU / 5.0, 60.0)).collect();
        let loop_points = &drawn[4].points;
        let half = loop_points.len() / 2;
        let begun_elsewhere: Vec<[f64; 2]> =
            loop_points[half..].iter().chain(&loop_points[1..=half]).copied().collect();
        drawn[4].points = begun_elsewhere;
        let a = Vec2::new((TAU / 5.0).cos(), (TAU / 5.0).sin());
        let chain = Chain {
            members: vec![0, 1, 2, 3],
            companions: vec![Vec::new(); 4],
            step: Similarity { a, b: c.to_vec2() - mul(a, c.to_vec2()) },
            closes: Some(5),
        };
        assert!(chain.complete(&drawn, None).is_empty());
        // (Without the fifth, it is the one completed.)
        let four = &drawn[..4];
        let rest = chain.complete(four, None);
        assert_eq!(rest.len(), 1);
        assert!(rest[0].0.reference_point().distance(petal(c, 4.0 * TAU / 5.0, 60.0).reference_point()) < 1.0);
    }

    #[test]
    fn a_dense_ring_is_completed_whole() {
        // 48 petals 70 long and 10 wide, 60 from the centre, 20 drawn, each a loop begun
        // elsewhere on its outline: the 28 completed, and their veins, lie beside their
        // neighbours and about each other, never on them.
        let c = Point::new(400.0, 300.0);
        let step = TAU / 48.0;
        let narrow = |k: usize| {
            let (th, start) = (k as f64 * step, (k as f64 * 0.37).fract());
            let pts = (0..=40)
                .map(|i| {
                    let t = TAU * (start + i as f64 / 40.0);
                    let (x, y) = (60.0 + 35.0 * (1.0 - t.cos()), 5.0 * t.sin());
                    [c.x + x * th.cos() - y * th.sin(), c.y + x * th.sin() + y * th.cos()]
                })
                .collect();
            Stroke::new(pts, 2.0, None)
        };
        // (Each with a vein down its middle, drawn after it.)
        let vein = |k: usize| {
            let d = Vec2::new((k as f64 * step).cos(), (k as f64 * step).sin());
            let (p, q) = (c + d * 70.0, c + d * 120.0);
            Stroke::new(vec![[p.x, p.y], [q.x, q.y]], 2.0, None)
        };
        let drawn: Vec<Stroke> = (0..20).flat_map(|k| [narrow(k), vein(k)]).collect();
        let a = Vec2::new(step.cos(), step.sin());
        let chain = Chain {
            members: (0..20).map(|k| 2 * k).collect(),
            companions: (0..20).map(|k| vec![2 * k + 1]).collect(),
            step: Similarity { a, b: c.to_vec2() - mul(a, c.to_vec2()) },
            closes: Some(48),
        };
        assert_eq!(chain.complete(&drawn, None).len(), 56);
    }

    #[test]
    fn a_ring_with_one_vein_missing_keeps_the_others() {
        // Six petals, each drawn with its vein but the third: the veins' run wraps round
        // from the fourth to the second (it lost every vein).
        let c = Point::new(200.0, 200.0);
        let mut drawn = Vec::new();
        for k in 0..6 {
            let th = k as f64 * TAU / 6.0;
            drawn.push(petal(c, th, 60.0));
            if k != 2 {
                let (p, q) = (c + Vec2::new(th.cos(), th.sin()) * 18.0, c + Vec2::new(th.cos(), th.sin()) * 42.0);
                drawn.push(Stroke::new(vec![[p.x, p.y], [q.x, q.y]], 2.0, None));
            }
        }
        let chain = find(&drawn).expect("a ring");
        assert_eq!(chain.closes, Some(6));
        assert_eq!(chain.strokes(), 11, "{:?} {:?}", chain.members, chain.companions);
        let with_vein = chain.companions.iter().filter(|v| v.len() == 1).count();
        assert_eq!(with_vein, 5);
    }

    #[test]
    fn leaves_on_an_arc_continue_along_it() {
        // Leaves every 12° on a circle of radius 300 about (0, 400), continued across
        // an area that holds part of the circle.
        let o = Point::new(0.0, 400.0);
        let leaf = |k: i32| {
            let phi = -0.3 + k as f64 * 12f64.to_radians();
            petal(o + Vec2::new(phi.sin(), -phi.cos()) * 300.0, phi, 30.0)
        };
        let drawn: Vec<Stroke> = (0..3).map(leaf).collect();
        let chain = find(&drawn).expect("an arc");
        // 12° would close after 30, but round a far centre that is a curve's business.
        assert_eq!(chain.structure(), Structure::Curve);
        let (more, _) = chain.extend(&drawn, Rect::new(-400.0, 0.0, 400.0, 400.0), None, 100);
        assert!(more.len() >= 4, "{}", more.len());
        for (s, _) in &more {
            let on = (s.reference_point().distance(o) - leaf(0).reference_point().distance(o)).abs();
            assert!(on < 1.0, "off the arc by {on}");
        }
    }

    #[test]
    fn a_motif_of_two_strokes_goes_on_whole_within_the_limit() {
        // A leaf and its vein every 12° on a circle: no more strokes than asked
        // for, and only whole copies (an odd limit once let a leaf go without its vein).
        let o = Point::new(0.0, 400.0);
        let drawn: Vec<Stroke> = (0..4)
            .flat_map(|k| {
                let phi = -0.3 + k as f64 * 12f64.to_radians();
                let (at, along) = (o + Vec2::new(phi.sin(), -phi.cos()) * 300.0, Vec2::new(phi.cos(), phi.sin()));
                let (p, q) = (at + along * 8.0, at + along * 22.0);
                [petal(at, phi, 30.0), Stroke::new(vec![[p.x, p.y], [q.x, q.y]], 2.0, None)]
            })
            .collect();
        let chain = find(&drawn).expect("an arc");
        assert_eq!(chain.strokes(), 8);
        for max in [5, 6, 7] {
            let (more, capped) = chain.extend(&drawn, Rect::new(-400.0, 0.0, 400.0, 400.0), None, max);
            assert!(more.len() <= max && more.len() % 2 == 0 && more.len() >= max - 1, "{max}: {}", more.len());
            assert!(capped, "{max}: the copies left out are said");
        }
    }

    #[test]
    fn unrelated_strokes_and_rows_make_no_chain() {
        let line = |p: [f64; 2], q: [f64; 2]| Stroke::new(vec![p, q], 2.0, None);
        let dashes =
            vec![line([10.0, 10.0], [30.0, 14.0]), line([80.0, 40.0], [84.0, 70.0]), line([20.0, 90.0], [45.0, 80.0])];
        assert!(find(&dashes).is_none());
        // A straight row: translations, the lattice's.
        let row: Vec<Stroke> = (0..5).map(|k| petal(Point::new(40.0 * k as f64, 0.0), 0.5, 30.0)).collect();
        assert!(find(&row).is_none());
    }
}
