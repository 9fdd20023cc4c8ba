//! Hand-drawn repetitions that are not lattices (test support, issue 27): rings of
//! petals, spirals, leaves along an arc, along S-shaped, wavy and curly stems, along
//! Bézier curves, an inward spiral and a row that turns a corner, hatching along a
//! turning and a straight contour, each copy a similarity transform of the one before
//! (along the stems, of the one before only locally), drawn copy by copy with a wobble
//! (each copy's place off by `wobble` of the step, its points by a fifth of that).

use super::replay::{replay_each, Replay};
use super::stroke::Stroke;
use crate::rng::Rng;
use kurbo::{Point, Vec2};
use std::f64::consts::TAU;

/// A drawn sequence: its strokes in drawing order, the step between copies, and the
/// canvas: the copies' centres and half a step round them (a sequence drawn to the
/// canvas's edge, as a lattice is in the lattice replay: a ghost past the last copy
/// is one the person would not take).
pub struct Sequence {
    pub name: String,
    pub strokes: Vec<Stroke>,
    pub step: f64,
    /// The step at each copy (a spiral's grows along it; the others' is `step`).
    pub steps: Vec<f64>,
    /// The copies the hand would draw next, past the drawing's end (an open sequence's
    /// next `BEYOND`, drawn alike; none past a closed ring): a proposal there is right,
    /// though not among the strokes to draw. Each with its step.
    pub beyond: Vec<(Stroke, f64)>,
    pub canvas: kurbo::Rect,
    /// Each stroke's part of its motif (0 for a motif of one stroke): a ghost is right
    /// only where it is the part it repeats.
    pub classes: Vec<u32>,
    /// Strokes in each copy.
    pub parts: usize,
    /// Strokes drawn before the first copy (a stem the copies go along).
    pub lead: usize,
}

impl Sequence {
    /// `strokes` (the sequence's own, or them drawn otherwise, one class) replayed
    /// through autocomplete stroke by stroke (`replay::replay_each`): a ghost is right
    /// within 0.3 of the step at its copy, or at a copy past the end.
    pub fn replay(&self, strokes: &[Stroke]) -> Replay {
        let tol: Vec<f64> = self.steps.iter().map(|s| 0.3 * s).collect();
        let past: Vec<_> = self.beyond.iter().map(|(b, step)| (b.clone(), 0.3 * step)).collect();
        replay_each(strokes, &self.classes, self.canvas, &tol, &past)
    }

    /// The copies drawn larger and smaller out from `centre` (a ring's), each by a factor
    /// `1 + spread N(0, 1)` (at least 0.1), as a person's petals drawn from the centre
    /// vary in length; strokes before the first copy (`lead`) as they were. `step`,
    /// `steps`, `beyond` and `canvas` stay the drawing's as it was meant.
    pub fn sized_about(mut self, centre: Point, spread: f64, seed: u64) -> Sequence {
        let mut rng = Rng::new(seed * 7 + 1);
        for copy in self.strokes[self.lead..].chunks_mut(self.parts) {
            let k = (1.0 + spread * rng.normal()).max(0.1);
            for p in copy.iter_mut().flat_map(|s| s.points.iter_mut()) {
                *p = [centre.x + (p[0] - centre.x) * k, centre.y + (p[1] - centre.y) * k];
            }
        }
        self
    }

    /// A family of single strokes `step` apart (its steps, classes and canvas set by
    /// `finish`).
    fn of_strokes(name: &str, strokes: Vec<Stroke>, step: f64) -> Sequence {
        Sequence::of_copies(name, strokes.into_iter().map(|s| vec![s]).collect(), step)
    }

    /// A family of motifs of several strokes, `copies` in drawing order (its steps,
    /// classes and canvas set by `finish`).
    fn of_copies(name: &str, copies: Vec<Vec<Stroke>>, step: f64) -> Sequence {
        let parts = copies[0].len();
        Sequence {
            name: name.into(),
            strokes: copies.into_iter().flatten().collect(),
            step,
            steps: Vec::new(),
            beyond: Vec::new(),
            canvas: kurbo::Rect::ZERO,
            classes: Vec::new(),
            parts,
            lead: 0,
        }
    }

    /// How far a ghost centred at `c`, proposed after the first `n` strokes were drawn,
    /// lies from the nearest stroke still to draw (or past the end): over 0.3 of the
    /// step, it is wrong.
    pub fn miss(&self, n: usize, c: Point) -> f64 {
        self.strokes[n..]
            .iter()
            .chain(self.beyond.iter().map(|b| &b.0))
            .map(|t| t.reference_point().distance(c))
            .fold(f64::INFINITY, f64::min)
    }

    /// Share of the strokes accepted after the first three copies were drawn.
    pub fn accepted_after_three(&self, r: &Replay) -> f64 {
        r.accepted_after(self.lead + 3 * self.parts)
    }
}

/// Copies generated past the end of an open sequence (see `Sequence::beyond`).
const BEYOND: usize = 3;

/// How far a hand turns each copy off the turn it means, whatever its placement wobble
/// (a standard deviation, in radians). A steady hand turns its copies no more than its
/// wobble does; a person's turns theirs by a few degrees (`HandTurn::PERSON`): a long
/// hatching line drawn 2.5 degrees off moves its ends by a tenth of its hatching's step.
#[derive(Clone, Copy, Debug)]
pub struct HandTurn(pub f64);

impl HandTurn {
    pub const STEADY: HandTurn = HandTurn(0.0);
    /// 2.5 degrees.
    pub const PERSON: HandTurn = HandTurn(0.043_633_231_299_858_24);

    /// A copy's turn off the one meant (nothing drawn from `rng` for a steady hand, so
    /// its drawings stay what they were).
    fn draw(self, rng: &mut Rng) -> f64 {
        if self.0 > 0.0 {
            rng.normal() * self.0
        } else {
            0.0
        }
    }
}

/// `strokes` with every dot tapped with the pen instead: three to six points within two
/// pixels of one another, as a stylus or a mouse leaves them (a shape of noise).
pub fn pen_taps(strokes: &[Stroke], seed: u64) -> Vec<Stroke> {
    let mut rng = Rng::new(seed);
    strokes
        .iter()
        .map(|s| {
            if !s.is_dot() {
                return s.clone();
            }
            let c = s.reference_point();
            let mut tap = s.clone();
            tap.points = (0..3 + rng.below(4))
                .map(|_| [c.x + 2.0 * rng.next_f64() - 1.0, c.y + 2.0 * rng.next_f64() - 1.0])
                .collect();
            tap
        })
        .collect()
}

/// `strokes` with every point moved at random by `by` (a standard deviation, each
/// coordinate): a mouse's jaggies, a tremor.
pub fn shaken(strokes: &[Stroke], by: f64, seed: u64) -> Vec<Stroke> {
    let mut rng = Rng::new(seed);
    strokes
        .iter()
        .map(|s| {
            let mut t = s.clone();
            for p in &mut t.points {
                p[0] += rng.normal() * by;
                p[1] += rng.normal() * by;
            }
            t
        })
        .collect()
}

/// A loop `len` long and `len / 3` wide, from `at` along `theta` (a petal, a leaf), each
/// point off by `noise` (a standard deviation).
pub fn leaf(at: Point, theta: f64, len: f64, rng: &mut Rng, noise: f64) -> Stroke {
    let (c, s) = (theta.cos(), theta.sin());
    let pts = (0..=24)
        .map(|k| {
            let t = k as f64 / 24.0 * TAU;
            let (along, across) = (0.5 * len * (1.0 - t.cos()), len / 6.0 * t.sin());
            let (dx, dy) = (rng.normal() * noise, rng.normal() * noise);
            [at.x + along * c - across * s + dx, at.y + along * s + across * c + dy]
        })
        .collect();
    Stroke::new(pts, 2.0, None)
}

/// A straight line `len` long through `at` along `theta`.
fn line(at: Point, theta: f64, len: f64, rng: &mut Rng, noise: f64) -> Stroke {
    let d = Vec2::new(theta.cos(), theta.sin()) * (0.5 * len);
    let pts = (0..=12)
        .map(|k| {
            let p = at - d + d * (2.0 * k as f64 / 12.0);
            [p.x + rng.normal() * noise, p.y + rng.normal() * noise]
        })
        .collect();
    Stroke::new(pts, 2.0, None)
}

/// A closed loop begun `k` points further round (its closing point moved with it), and
/// read backwards when asked: the same loop, begun wherever the pen landed.
pub fn begun_at(s: &Stroke, k: usize, backwards: bool) -> Stroke {
    let cycle = &s.points[..s.points.len() - 1];
    let k = k % cycle.len().max(1);
    let mut points: Vec<[f64; 2]> = cycle[k..].iter().chain(&cycle[..k]).copied().collect();
    if backwards {
        points.reverse();
    }
    points.push(points[0]);
    Stroke { points, ..s.clone() }
}

/// A circle of radius `r` round `at`, begun at angle `start` and drawn either way round
/// (`dir` 1 or -1): 24 points and its first again, each off by `noise`.
pub fn circle(at: Point, r: f64, start: f64, dir: f64, rng: &mut Rng, noise: f64) -> Stroke {
    let mut pts: Vec<[f64; 2]> = (0..24)
        .map(|k| {
            let t = start + dir * k as f64 / 24.0 * TAU;
            [at.x + r * t.cos() + rng.normal() * noise, at.y + r * t.sin() + rng.normal() * noise]
        })
        .collect();
    pts.push(pts[0]);
    Stroke::new(pts, 2.0, None)
}

/// A grid of 6 x 4 circles of radius 18, 60 apart from (40, 40), drawn row by row, each
/// off its site by `wobble` of the spacing (its points by a fifth of that); begun at
/// angle 0 and drawn one way, or `anywhere`: at a random point, either way round. With
/// the canvas the grid's sites and half a spacing round them.
pub fn circle_grid(wobble: f64, seed: u64, anywhere: bool) -> (Vec<Stroke>, kurbo::Rect) {
    let spacing = 60.0;
    let mut rng = Rng::new(seed);
    let mut strokes = Vec::new();
    for j in 0..4 {
        for i in 0..6 {
            let site = Point::new(40.0 + spacing * i as f64, 40.0 + spacing * j as f64);
            let jitter = Vec2::new(rng.normal(), rng.normal()) * (wobble * spacing);
            let (start, dir) = if anywhere {
                (rng.below(360) as f64 / 360.0 * TAU, if rng.below(2) == 0 { 1.0 } else { -1.0 })
            } else {
                (0.0, 1.0)
            };
            strokes.push(circle(site + jitter, 18.0, start, dir, &mut rng, 0.2 * wobble * spacing));
        }
    }
    (strokes, kurbo::Rect::new(10.0, 10.0, 40.0 + spacing * 5.5, 40.0 + spacing * 3.5))
}

/// A ring of `n` circles of radius `size` round (300, 300) at `radius`, drawn in order
/// round it, each off its site by `wobble` of the step between neighbours (its points by
/// a fifth of that), begun at a random point and drawn either way round; with the canvas.
pub fn circle_ring(n: usize, radius: f64, size: f64, wobble: f64, seed: u64) -> (Vec<Stroke>, kurbo::Rect) {
    let mut rng = Rng::new(seed);
    let step = 2.0 * radius * (std::f64::consts::PI / n as f64).sin();
    let strokes = (0..n)
        .map(|k| {
            let theta = k as f64 * TAU / n as f64;
            let site = Point::new(300.0 + radius * theta.cos(), 300.0 + radius * theta.sin());
            let jitter = Vec2::new(rng.normal(), rng.normal()) * (wobble * step);
            let (start, dir) = (rng.below(360) as f64 / 360.0 * TAU, if rng.below(2) == 0 { 1.0 } else { -1.0 });
            circle(site + jitter, size, start, dir, &mut rng, 0.2 * wobble * step)
        })
        .collect();
    (strokes, kurbo::Rect::new(0.0, 0.0, 600.0, 600.0))
}

/// Leaves one every 40 along the sine `y = 300 + amplitude sin((x - 300) / scale)` from
/// `x0`, each turned with it: `n` drawn and `BEYOND` more.
fn stem(name: &str, amplitude: f64, scale: f64, x0: f64, n: usize, hand: (f64, HandTurn), seed: u64) -> Sequence {
    let path = |x: f64| Point::new(x, 300.0 + amplitude * ((x - 300.0) / scale).sin());
    leaves_along(name, path, (x0, 0.5), n, (hand.0, 0.0, hand.1), seed)
}

/// Leaves one every 40 (of arc length) along `path(t)` from `t = from.0` on in steps of
/// `from.1`, each turned with the path: `n` drawn and `BEYOND` more. Each leaf is off
/// its place by `wobble.0` of the step (its points by a fifth of that) and turned off
/// the path's direction by `wobble.1` radian (the angle a hand gets wrong too) and as
/// the hand `wobble.2` turns its copies.
fn leaves_along(
    name: &str,
    path: impl Fn(f64) -> Point,
    from: (f64, f64),
    n: usize,
    wobble: (f64, f64, HandTurn),
    seed: u64,
) -> Sequence {
    let turn = wobble.2;
    let mut rng = Rng::new(seed);
    let step = 40.0;
    let sites: Vec<(Point, f64)> =
        sites(&path, from, step, n + BEYOND).into_iter().map(|(p, phi, _)| (p, phi)).collect();
    let strokes = sites
        .iter()
        .map(|&(p, phi)| {
            let jitter = Vec2::new(rng.normal(), rng.normal()) * (wobble.0 * step);
            let off = if wobble.1 > 0.0 { rng.normal() * wobble.1 } else { 0.0 } + turn.draw(&mut rng);
            leaf(p + jitter, phi - 0.6 + off, 36.0, &mut rng, 0.2 * wobble.0 * step)
        })
        .collect();
    Sequence::of_strokes(name, strokes, step)
}

/// Sites `step` apart (of arc length) along `path(t)` from `t = from.0` on in steps of
/// `from.1`: each one's place, the path's direction there and its `t`.
fn sites(path: &impl Fn(f64) -> Point, from: (f64, f64), step: f64, count: usize) -> Vec<(Point, f64, f64)> {
    let (mut sites, mut along, mut t) = (Vec::new(), 0.0, from.0);
    while sites.len() < count {
        let (p, q) = (path(t), path(t + from.1));
        along += p.distance(q);
        if along >= step || sites.is_empty() {
            along = 0.0;
            sites.push((p, (q.y - p.y).atan2(q.x - p.x), t));
        }
        t += from.1;
    }
    sites
}

/// Leaves along a stem the hand draws first (issue 27: "a stem and three leaves"): the
/// stem from half a step before the first leaf to half a step past the `n`-th (round,
/// for a closed path, `Some(past)`: closed exactly where `past` is 0, else begun half
/// way round and drawn `past` of `t` on beyond its start, or short of it where `past`
/// is negative, as a hand's circle seldom meets itself), its points off by a fifth of `wobble` of the step and
/// swaying by `wobble` of it; then the leaves, as `leaves_along` draws them (every
/// other one on the stem's other side, where they `alternate`).
fn stem_drawn(
    name: &str,
    path: impl Fn(f64) -> Point,
    from: (f64, f64),
    n: usize,
    (round, alternate): (Option<f64>, bool),
    wobble: (f64, HandTurn),
    seed: u64,
) -> Sequence {
    let step = 40.0;
    let mut leaves = leaves_along(name, &path, from, n, (wobble.0, 0.0, wobble.1), seed);
    // (Every other leaf on the stem's other side: mirrored across its tangent.)
    if alternate {
        for (leaf, (p, phi, _)) in
            leaves.strokes.iter_mut().zip(sites(&path, from, step, n + BEYOND)).skip(1).step_by(2)
        {
            let d = Vec2::new(phi.cos(), phi.sin());
            for q in &mut leaf.points {
                let v = Vec2::new(q[0] - p.x, q[1] - p.y);
                let m = d * (2.0 * v.dot(d)) - v;
                (q[0], q[1]) = (p.x + m.x, p.y + m.y);
            }
        }
    }
    let mut rng = Rng::new(seed ^ 0x5EED);
    let at = sites(&path, from, step, n + 1);
    let closed = round.is_some();
    let (t0, t1) = match round {
        Some(0.0) => (from.0, at[n].2),
        // (Begun half way round: a periodic path, a circle, is drawn from anywhere.)
        Some(past) => (0.5 * (from.0 + at[n].2), 1.5 * at[n].2 - 0.5 * from.0 + past),
        None => (from.0 - 0.5 * (at[1].2 - at[0].2), 0.5 * (at[n - 1].2 + at[n].2)),
    };
    let phase = rng.next_f64() * TAU;
    // (A point every 4 of the step's 40 or so, as a pen's coalesced events give.)
    let count = ((t1 - t0) / from.1 / 8.0).ceil().max(8.0) as usize;
    let noise = 0.2 * wobble.0 * step;
    let mut points: Vec<[f64; 2]> = (0..=count)
        .map(|k| {
            let t = t0 + (t1 - t0) * k as f64 / count as f64;
            let (p, q) = (path(t), path(t + from.1));
            let normal = Vec2::new(p.y - q.y, q.x - p.x).normalize();
            let sway = wobble.0 * step * (k as f64 / count as f64 * TAU + phase).sin();
            let p = p + normal * sway;
            [p.x + rng.normal() * noise, p.y + rng.normal() * noise]
        })
        .collect();
    if round == Some(0.0) {
        points.push(points[0]);
    }
    leaves.strokes.insert(0, Stroke::new(points, 2.0, None));
    leaves.classes = std::iter::once(1).chain(std::iter::repeat_n(0, leaves.strokes.len() - 1)).collect();
    leaves.lead = 1;
    if closed {
        leaves.strokes.truncate(1 + n);
        leaves.classes.truncate(1 + n);
    }
    leaves
}

/// Leaves along stems drawn first, each leaf turned with its stem, at `wobble` (share
/// of the step) and turned off as `turn` says: an S-curve, wavy, curly and tight sines
/// (and the wavy one with its leaves on alternate sides), a Bézier S and arch, and twelve
/// round a drawn circle.
pub fn along_drawn(wobble: f64, turn: HandTurn, seed: u64) -> Vec<Sequence> {
    let sine =
        |amplitude: f64, scale: f64| move |x: f64| Point::new(x, 300.0 + amplitude * ((x - 300.0) / scale).sin());
    let hand = (wobble, turn);
    let k = seed * 131;
    let open = (None, false);
    let mut out = vec![
        stem_drawn("leaves on a drawn S-curve", sine(70.0, 110.0), (70.0, 0.5), 12, open, hand, k + 13),
        stem_drawn("leaves on a drawn wavy stem", sine(40.0, 400.0 / TAU), (50.0, 0.5), 16, open, hand, k + 19),
        stem_drawn("leaves on a drawn curly stem", sine(60.0, 300.0 / TAU), (50.0, 0.5), 16, open, hand, k + 23),
        stem_drawn("leaves on a drawn tight stem", sine(50.0, 250.0 / TAU), (40.0, 0.5), 16, open, hand, k + 37),
        stem_drawn(
            "leaves alternating on a drawn wavy stem",
            sine(40.0, 400.0 / TAU),
            (50.0, 0.5),
            16,
            (None, true),
            hand,
            k + 43,
        ),
    ];
    let arch = bezier([(60.0, 500.0), (250.0, 50.0), (650.0, 50.0), (840.0, 500.0)]);
    let s = bezier([(60.0, 150.0), (700.0, -50.0), (200.0, 750.0), (840.0, 450.0)]);
    out.push(stem_drawn("leaves on a drawn Bézier arch", arch, (0.0, 1.0 / 8000.0), 16, open, hand, k + 29));
    out.push(stem_drawn("leaves on a drawn Bézier S", s, (0.0, 1.0 / 8000.0), 16, open, hand, k + 30));
    let r = 12.0 * 40.0 / TAU;
    let circle = move |t: f64| Point::new(300.0 + r * t.cos(), 300.0 + r * t.sin());
    out.push(stem_drawn(
        "ring of 12 leaves round a drawn circle",
        circle,
        (0.0, TAU / 4000.0),
        12,
        (Some(0.0), false),
        hand,
        k + 41,
    ));
    // (The circle's end a fifth of a gap short of its start, or up to half a gap past.)
    let past = (Rng::new(k + 47).next_f64() * 0.7 - 0.2) * TAU / 12.0;
    out.push(stem_drawn(
        "ring of 12 leaves round a circle drawn open",
        circle,
        (0.0, TAU / 4000.0),
        12,
        (Some(past), false),
        hand,
        k + 47,
    ));
    finish(&mut out);
    out
}

/// The cubic Bézier curve through `p[0]` and `p[3]` with control points `p[1]`, `p[2]`.
fn bezier(p: [(f64, f64); 4]) -> impl Fn(f64) -> Point {
    move |t| {
        let u = 1.0 - t;
        let w = [u * u * u, 3.0 * u * u * t, 3.0 * u * t * t, t * t * t];
        let (x, y) = p.iter().zip(w).fold((0.0, 0.0), |(x, y), (q, w)| (x + w * q.0, y + w * q.1));
        Point::new(x, y)
    }
}

/// A straight row from (60, 300), 400 long, that turns by `angle` and goes on as far.
fn kinked(angle: f64) -> impl Fn(f64) -> Point {
    move |t| {
        let d = 800.0 * t;
        if d <= 400.0 {
            Point::new(60.0 + d, 300.0)
        } else {
            Point::new(460.0, 300.0) + Vec2::new(angle.cos(), angle.sin()) * (d - 400.0)
        }
    }
}

/// Every family at `wobble` (share of the step), seeded.
pub fn sequences(wobble: f64, seed: u64) -> Vec<Sequence> {
    drawn_by(wobble, HandTurn::STEADY, seed)
}

/// Every family at `wobble` (share of the step), each copy turned off as `turn` says,
/// seeded.
pub fn drawn_by(wobble: f64, turn: HandTurn, seed: u64) -> Vec<Sequence> {
    let mut out = Vec::new();
    let centre = Point::new(300.0, 300.0);
    // Rings of n petals around a centre: the step is the distance between neighbours'
    // centres.
    for n in [5usize, 6, 8, 10, 12] {
        let mut rng = Rng::new(seed * 131 + n as u64);
        let len = 90.0;
        let step = 2.0 * (0.5 * len) * (std::f64::consts::PI / n as f64).sin();
        let strokes = (0..n)
            .map(|k| {
                let theta =
                    k as f64 * TAU / n as f64 + rng.normal() * wobble * step / (0.5 * len) + turn.draw(&mut rng);
                let at = centre + Vec2::new(rng.normal(), rng.normal()) * (wobble * step);
                leaf(at, theta, len, &mut rng, 0.2 * wobble * step)
            })
            .collect();
        out.push(Sequence::of_strokes(&format!("ring of {n}"), strokes, step));
    }
    // A spiral: petals turning by 30° and growing by 6% a step, out from the centre.
    {
        let mut rng = Rng::new(seed * 131 + 99);
        let strokes: Vec<Stroke> = (0..10 + BEYOND as i32)
            .map(|k| {
                let r = 120.0 * 1.06f64.powi(k);
                let theta = k as f64 * TAU / 12.0;
                let at = centre + Vec2::new(theta.cos(), theta.sin()) * r;
                let jitter = Vec2::new(rng.normal(), rng.normal()) * (wobble * 0.5 * r * (TAU / 12.0));
                leaf(
                    at + jitter,
                    theta + 1.2 + turn.draw(&mut rng),
                    0.35 * r,
                    &mut rng,
                    0.2 * wobble * 0.5 * r * (TAU / 12.0),
                )
            })
            .collect();
        // (The step grows: `step` is the one at the middle of the spiral.)
        let steps = (0..10 + BEYOND as i32).map(|k| 120.0 * 1.06f64.powi(k) * TAU / 12.0).collect();
        out.push(Sequence { steps, ..Sequence::of_strokes("spiral", strokes, 120.0 * 1.06f64.powi(5) * TAU / 12.0) });
    }
    // Leaves along an arc of radius 260, one every 14°, each turned with the arc.
    {
        let mut rng = Rng::new(seed * 131 + 7);
        let (r, d) = (260.0, 14f64.to_radians());
        let step = r * d;
        let strokes: Vec<Stroke> = (0..10 + BEYOND)
            .map(|k| {
                let phi = -1.2 + k as f64 * d;
                let at = Point::new(300.0, 560.0) + Vec2::new(phi.sin(), -phi.cos()) * r;
                let jitter = Vec2::new(rng.normal(), rng.normal()) * (wobble * step);
                leaf(at + jitter, phi - 0.6 + turn.draw(&mut rng), 45.0, &mut rng, 0.2 * wobble * step)
            })
            .collect();
        out.push(Sequence::of_strokes("leaves on an arc", strokes, step));
    }
    // Hatching across a contour that turns: lines 70 long, 7.2 apart along an arc of
    // radius 240, each across the arc.
    {
        let mut rng = Rng::new(seed * 131 + 11);
        let (r, step) = (240.0, 7.2);
        let strokes: Vec<Stroke> = (0..16 + BEYOND)
            .map(|k| {
                let phi = -0.25 + k as f64 * step / r;
                let at = Point::new(300.0, 480.0) + Vec2::new(phi.sin(), -phi.cos()) * r;
                let jitter = Vec2::new(rng.normal(), rng.normal()) * (wobble * step);
                line(
                    at + jitter,
                    phi + std::f64::consts::FRAC_PI_2 + rng.normal() * wobble * 0.1 + turn.draw(&mut rng),
                    70.0,
                    &mut rng,
                    0.2 * wobble * step,
                )
            })
            .collect();
        out.push(Sequence::of_strokes("turning hatching", strokes, step));
    }
    // Leaves along an S: a stem that bends one way and then the other (no one similarity
    // carries every leaf onto the next), one leaf every 40 along it, each turned with it;
    // and along wavier stems, whose turn (up to 0.4 and 1 radian a step) changes sign
    // every few leaves.
    out.push(stem("leaves on an S-curve", 70.0, 110.0, 70.0, 12, (wobble, turn), seed * 131 + 13));
    out.push(stem("leaves on a wavy stem", 40.0, 400.0 / TAU, 50.0, 16, (wobble, turn), seed * 131 + 19));
    out.push(stem("leaves on a curly stem", 60.0, 300.0 / TAU, 50.0, 16, (wobble, turn), seed * 131 + 23));
    // (A new user's tighter sine, 50 high and 250 long: up to 1.3 radians a leaf.)
    out.push(stem("leaves on a tight stem", 50.0, 250.0 / TAU, 40.0, 16, (wobble, turn), seed * 131 + 37));
    // A new user's curves (a helper's trial): leaves along a Bézier arch and a Bézier S,
    // and along a row that turns by 60 and by 30 degrees half way, each leaf turned off
    // the path by the wobble too.
    let arch = bezier([(60.0, 500.0), (250.0, 50.0), (650.0, 50.0), (840.0, 500.0)]);
    let s = bezier([(60.0, 150.0), (700.0, -50.0), (200.0, 750.0), (840.0, 450.0)]);
    let along = |k: u64, name: &str, path: &dyn Fn(f64) -> Point| {
        leaves_along(name, path, (0.0, 1.0 / 8000.0), 16, (wobble, wobble, turn), seed * 131 + 29 + k)
    };
    out.push(along(0, "leaves on a Bézier arch", &arch));
    out.push(along(1, "leaves on a Bézier S", &s));
    out.push(along(2, "leaves on a row turning 60°", &kinked(60f64.to_radians())));
    out.push(along(3, "leaves on a row turning 30°", &kinked(30f64.to_radians())));
    // And a spiral drawn inwards, its turn growing as it closes in.
    let inwards = |t: f64| {
        let theta = 5.0 * std::f64::consts::PI * (1.0 - t);
        Point::new(450.0, 450.0) + Vec2::new(theta.cos(), theta.sin()) * (40.0 + 28.0 * theta)
    };
    out.push(along(4, "leaves on an inward spiral", &inwards));
    // Hatching along a straight contour: a row, the lattice's (lines 70 long, 9 apart, at
    // 60 degrees).
    {
        let mut rng = Rng::new(seed * 131 + 17);
        let step = 9.0;
        let strokes = (0..14 + BEYOND)
            .map(|k| {
                let at = Point::new(200.0 + k as f64 * step, 300.0)
                    + Vec2::new(rng.normal(), rng.normal()) * (wobble * step);
                line(
                    at,
                    60f64.to_radians() + rng.normal() * wobble * 0.1 + turn.draw(&mut rng),
                    70.0,
                    &mut rng,
                    0.2 * wobble * step,
                )
            })
            .collect();
        out.push(Sequence::of_strokes("straight hatching", strokes, step));
    }
    finish(&mut out);
    out
}

/// Each family's steps, classes, the copies past an open one's end, and its canvas.
fn finish(out: &mut [Sequence]) {
    for q in out {
        if q.steps.is_empty() {
            q.steps = vec![q.step; q.strokes.len()];
        }
        if q.classes.is_empty() {
            q.classes = (0..q.strokes.len()).map(|i| (i % q.parts) as u32).collect();
        }
        if !q.name.starts_with("ring") {
            let at = q.strokes.len() - BEYOND * q.parts;
            q.beyond = q.strokes.split_off(at).into_iter().zip(q.steps.split_off(at)).collect();
            q.classes.truncate(at);
        }
        let c: Vec<Point> = q.strokes.iter().map(Stroke::reference_point).collect();
        q.canvas = c
            .iter()
            .fold(kurbo::Rect::from_points(c[0], c[0]), |r, &p| r.union_pt(p))
            .inflate(0.5 * q.step, 0.5 * q.step);
    }
}

/// An arc from `from` to `to` bulging `bulge` of its chord to the left of the way it
/// goes (right where negative): 16 points, each off by `noise`.
fn arc(from: Point, to: Point, bulge: f64, rng: &mut Rng, noise: f64) -> Stroke {
    let chord = to - from;
    let left = Vec2::new(chord.y, -chord.x);
    let pts = (0..=16)
        .map(|k| {
            let t = k as f64 / 16.0;
            let p = from + chord * t + left * (bulge * 4.0 * t * (1.0 - t));
            [p.x + rng.normal() * noise, p.y + rng.normal() * noise]
        })
        .collect();
    Stroke::new(pts, 2.0, None)
}

/// Fence posts along an arc (issue 27: "a row of fence posts along an arc: autocomplete
/// proposes nothing"): posts 40 long, `step` apart along an arc of radius `radius`,
/// each placed `jitter` of the step off at random and turned 2 degrees, upright (a
/// fence seen from the side: the posts keep their pose as the row bends) or turned with
/// the arc. Twelve posts, from four steps before the arc's top; each with its site (the
/// middle of the post where the hand placed it) and pose.
pub fn posts(radius: f64, step: f64, upright: bool, jitter: f64, seed: u64) -> (Vec<Stroke>, Vec<(Point, f64)>) {
    posts_by(radius, step, upright, jitter, PostHand { tilt: 2f64.to_radians(), length: 0.0 }, seed)
}

/// How loosely a hand draws each fence post: turned `tilt` (radians, a standard
/// deviation) off its pose, and `length` (a share) longer or shorter.
#[derive(Clone, Copy, Debug)]
pub struct PostHand {
    pub tilt: f64,
    pub length: f64,
}

/// `posts` drawn by `hand`.
pub fn posts_by(
    radius: f64,
    step: f64,
    upright: bool,
    jitter: f64,
    hand: PostHand,
    seed: u64,
) -> (Vec<Stroke>, Vec<(Point, f64)>) {
    let mut rng = Rng::new(seed * 7919 + radius as u64);
    let centre = Point::new(400.0, 250.0 + radius);
    let mut sites = Vec::new();
    let strokes = (0..12)
        .map(|k| {
            let phi = -std::f64::consts::FRAC_PI_2 + (k as f64 - 4.0) * step / radius;
            let base = centre + Vec2::new(phi.cos(), phi.sin()) * radius;
            let base = base + Vec2::new(rng.normal(), rng.normal()) * (jitter * step);
            let pose = if upright { -std::f64::consts::FRAC_PI_2 } else { phi + std::f64::consts::PI };
            let ang = pose + hand.tilt * rng.normal();
            let len = 40.0;
            sites.push((base + Vec2::new(pose.cos(), pose.sin()) * (len / 2.0), pose));
            // (Drawn from the post's foot: a longer one reaches higher. No draw for an
            // exact length, so that `posts` draws the same posts as before `PostHand`.)
            let len = if hand.length > 0.0 { len * (1.0 + hand.length * rng.normal()) } else { len };
            let pts = (0..=4)
                .map(|i| {
                    let t = len * i as f64 / 4.0;
                    [base.x + t * ang.cos() + 0.5 * rng.normal(), base.y + t * ang.sin() + 0.5 * rng.normal()]
                })
                .collect();
            Stroke::new(pts, 3.0, None)
        })
        .collect();
    (strokes, sites)
}

/// A leaf of three strokes from `at` along `theta`, `len` long: its left and right
/// halves (arcs, mirror images of one another) and its midrib, in that order.
fn three_stroke_leaf(at: Point, theta: f64, len: f64, rng: &mut Rng, noise: f64) -> Vec<Stroke> {
    let tip = at + Vec2::new(theta.cos(), theta.sin()) * len;
    vec![
        arc(at, tip, 0.2, rng, noise),
        arc(at, tip, -0.2, rng, noise),
        line(at.midpoint(tip), theta, 0.8 * len, rng, noise),
    ]
}

/// Motifs of several strokes, drawn a few times by hand and carried on by turns
/// (issue 27: a ring of petals each drawn as two mirrored arcs got "no repetition";
/// leaves of three strokes along curves 0-10% accepted): petals of two arcs round a
/// centre, petals with a vein, petals with a dot at the tip, leaves of three strokes along an arc and an S-curve, and
/// a stalk and its leaf along a Bézier arch. Each copy's strokes in one order; each
/// copy off its place by `wobble` of the step and turned as `turn` says, each stroke's
/// points off by a fifth of that.
pub fn composite(wobble: f64, turn: HandTurn, seed: u64) -> Vec<Sequence> {
    let mut out = Vec::new();
    let centre = Point::new(300.0, 300.0);
    // A ring of `n` petals, each `len` long, drawn by `petal` (its strokes in order).
    let mut ring =
        |name: &str, n: usize, len: f64, k0: u64, petal: &dyn Fn(Point, f64, &mut Rng, f64) -> Vec<Stroke>| {
            let mut rng = Rng::new(seed * 131 + k0);
            let step = len * (std::f64::consts::PI / n as f64).sin();
            let copies: Vec<Vec<Stroke>> = (0..n)
                .map(|k| {
                    let theta =
                        k as f64 * TAU / n as f64 + rng.normal() * wobble * step / (0.5 * len) + turn.draw(&mut rng);
                    let at = centre + Vec2::new(rng.normal(), rng.normal()) * (wobble * step);
                    petal(at, theta, &mut rng, 0.2 * wobble * step)
                })
                .collect();
            out.push(Sequence::of_copies(name, copies, step));
        };
    ring("ring of 7 two-arc petals", 7, 90.0, 201, &|at, theta, rng, noise| {
        let tip = at + Vec2::new(theta.cos(), theta.sin()) * 90.0;
        vec![arc(at, tip, 0.18, rng, noise), arc(at, tip, -0.18, rng, noise)]
    });
    ring("ring of 6 veined petals", 6, 90.0, 203, &|at, theta, rng, noise| {
        let vein = at + Vec2::new(theta.cos(), theta.sin()) * 45.0;
        vec![leaf(at, theta, 90.0, rng, noise), line(vein, theta, 60.0, rng, noise)]
    });
    ring("ring of 8 petals with a dot", 8, 90.0, 213, &|at, theta, rng, noise| {
        let tip = at + Vec2::new(theta.cos(), theta.sin()) * 98.0;
        let mut dot = circle(tip, 1.5, rng.below(360) as f64 / 360.0 * TAU, 1.0, rng, 0.1 * noise);
        dot.width = 3.0;
        vec![leaf(at, theta, 90.0, rng, noise), dot]
    });
    ring("ring of 9 three-stroke leaves", 9, 80.0, 205, &|at, theta, rng, noise| {
        three_stroke_leaf(at, theta, 80.0, rng, noise)
    });
    // Along curves: each copy's strokes from `motif`, one copy every 40 of arc length.
    let along = |name: &str,
                 path: &dyn Fn(f64) -> Point,
                 dt: f64,
                 n: usize,
                 k0: u64,
                 motif: &dyn Fn(Point, f64, &mut Rng, f64) -> Vec<Stroke>| {
        let mut rng = Rng::new(seed * 131 + k0);
        let step = 40.0;
        let (mut sites, mut run, mut t) = (Vec::new(), 0.0, 0.0);
        while sites.len() < n + BEYOND {
            let (p, q) = (path(t), path(t + dt));
            run += p.distance(q);
            t += dt;
            if run >= step || sites.is_empty() {
                run = 0.0;
                sites.push((p, (q.y - p.y).atan2(q.x - p.x)));
            }
        }
        let copies: Vec<Vec<Stroke>> = sites
            .iter()
            .map(|&(p, phi)| {
                let jitter = Vec2::new(rng.normal(), rng.normal()) * (wobble * step);
                let off = rng.normal() * wobble + turn.draw(&mut rng);
                motif(p + jitter, phi - 0.6 + off, &mut rng, 0.2 * wobble * step)
            })
            .collect();
        Sequence::of_copies(name, copies, step)
    };
    let arc_path = |t: f64| {
        let phi = -1.2 + 2.4 * t;
        Point::new(300.0, 560.0) + Vec2::new(phi.sin(), -phi.cos()) * 260.0
    };
    let s_path = |t: f64| {
        let x = 70.0 + 600.0 * t;
        Point::new(x, 300.0 + 70.0 * ((x - 300.0) / 110.0).sin())
    };
    let leaf3 = |at, theta, rng: &mut Rng, noise| three_stroke_leaf(at, theta, 34.0, rng, noise);
    out.push(along("three-stroke leaves on an arc", &arc_path, 1e-4, 10, 207, &leaf3));
    out.push(along("three-stroke leaves on an S-curve", &s_path, 1e-4, 12, 209, &leaf3));
    // (The leaf first, then its dot: the stroke followed is not the last of its copy.)
    out.push(along("leaves with a dot on an arc", &arc_path, 1e-4, 10, 215, &|at, theta, rng, noise| {
        let tip = at + Vec2::new(theta.cos(), theta.sin()) * 38.0;
        let mut dot = circle(tip, 1.5, rng.below(360) as f64 / 360.0 * TAU, 1.0, rng, 0.1 * noise);
        dot.width = 3.0;
        vec![leaf(at, theta, 32.0, rng, noise), dot]
    }));
    let arch = bezier([(60.0, 500.0), (250.0, 50.0), (650.0, 50.0), (840.0, 500.0)]);
    out.push(along("stalked leaves on a Bézier arch", &arch, 1.0 / 8000.0, 14, 211, &|at, theta, rng, noise| {
        let d = Vec2::new(theta.cos(), theta.sin());
        vec![line(at + d * 6.0, theta, 12.0, rng, noise), leaf(at + d * 12.0, theta, 30.0, rng, noise)]
    }));
    finish(&mut out);
    out
}
