//! Copies on the orbit of one similarity step, fitted to all of them at once: the
//! `t`-th copy's centre is `z_t = z_0 + v g_t(a)`, where `g_t(a) = (a^t - 1) / (a - 1)`
//! is the geometric sum of the step's turns (`t` itself for a translation, where the
//! orbit is a row). A ring is `a` a whole fraction of a turn; an arc, `a` a small turn;
//! a spiral, `a` a turn and a scale.
//!
//! Predicting from the last two copies alone (`z_{t+1} = z_t + a (z_t - z_{t-1})`, the
//! seed paper's local similarity) carries the latest copy's misplacement, and the last
//! step's, into every copy after it: from three petals of twelve at 3% of the step the
//! fourth is off by about `sqrt(6)` hand scatters and the sixth by twice that. Fitted
//! to every drawn copy, the orbit's error is the least-squares one, and shrinks as the
//! hand adds copies.
//!
//! The step `a` is read from both what the copies say: their shapes (each consecutive
//! pair's turn and scale, averaged, with their scatter) and their places (how well the
//! orbit through them fits, given `a`). It minimises
//! `SSR(a) / sigma^2 + n |a - mean_a|^2 / v`: the placement residual over the hand's
//! scatter, and the shapes' mean over its variance. Where the shapes say the step does
//! not scale (within 4%), `a` is held to a pure turn.
//!
//! Given `a`, `z_0` and `v` are linear least squares (a 2 x 2 complex system), so the
//! search for `a` is over one or two real numbers, and the site's error at any `t` has
//! the closed form of a regression's prediction (plus what the error of `a` adds).

use crate::vector::similarity::mul;
use kurbo::{Point, Vec2};

/// One copy on the orbit: its index along the step, its centre, and its weight in the
/// fit (an accepted proposal sits where an earlier fit put it and weighs little).
#[derive(Clone, Copy, Debug)]
pub(super) struct Placed {
    pub t: i64,
    pub z: Point,
    pub weight: f64,
    /// Drawn by hand: its miss counts towards the hand's scatter.
    pub hand: bool,
}

/// A fitted orbit.
#[derive(Clone, Debug)]
pub(super) struct Orbit {
    pub a: Vec2,
    /// How much each step turns on from the one before (`Shapes::bend`).
    pub bend: f64,
    z0: Vec2,
    v: Vec2,
    /// Mean square miss of a hand-drawn copy off its site (`E |e|^2`, both coordinates).
    pub scatter: f64,
    /// How many copies `scatter` is read from (prior ones counted): see `certainty::reach`.
    pub copies: f64,
    /// `det` and the sums of the normal equations, for the sites' error.
    sums: Sums,
    /// Variance of `a` (both components together), from shapes and places; zero once a
    /// ring's turn is snapped to a whole fraction.
    pub var_a: f64,
    /// Variance of the step's scale over what `var_a` holds, where the shapes leave it
    /// open whether the copies scale at all (`sequence::model`'s `PERSON_SIZE`): the
    /// sites further on may lie on the ring as well as on the spiral.
    pub var_scale: f64,
    /// `a` is held to a pure turn (its error is then along the turn only).
    unit: bool,
    members: Vec<Placed>,
}

#[derive(Clone, Copy, Debug, Default)]
struct Sums {
    s0: f64,
    s1: Vec2,
    s2: f64,
    det: f64,
}

fn conj(z: Vec2) -> Vec2 {
    Vec2::new(z.x, -z.y)
}

/// `a^t` for an integer `t` (negative: of the inverse), by polar form.
fn pow(a: Vec2, t: i64) -> Vec2 {
    let (r, th) = (a.hypot(), a.y.atan2(a.x));
    let (m, ang) = (r.powi(t as i32), th * t as f64);
    Vec2::new(m * ang.cos(), m * ang.sin())
}

/// The turn (and scale) from copy `from` to copy `to`: the product of the steps' `a`,
/// each turned on by `bend` from the one before (step `j` turns by `a e^(i bend j)`).
pub(super) fn turn_between(a: Vec2, bend: f64, from: i64, to: i64) -> Vec2 {
    let quad = |t: i64| bend * (t * (t - 1)) as f64 / 2.0;
    let extra = quad(to) - quad(from);
    mul(pow(a, to - from), Vec2::new(extra.cos(), extra.sin()))
}

/// The sum of the steps' turns up to copy `t`: `g_t = (a^t - 1) / (a - 1)` for a
/// constant step (`t` for `a = 1`); with a `bend`, the sum over the steps `j` from 0 to
/// `t` (less those from `t` to 0 for a negative `t`) of `turn_between(0, j)` turned on
/// by `bend j / 2`: the chord from copy `j` to the next runs along the curve's tangent
/// half way between them, turned from the first chord by the turns before `j` and half
/// of `j`'s own less half the first's (without it, a stem bending on at 0.05 a step put
/// the third copy ahead 0.4 of a step off).
fn geometric(a: Vec2, bend: f64, t: i64) -> Vec2 {
    if bend != 0.0 {
        let chord = |j: i64| {
            let half = 0.5 * bend * j as f64;
            mul(turn_between(a, bend, 0, j), Vec2::new(half.cos(), half.sin()))
        };
        let sum = |range: std::ops::Range<i64>| range.fold(Vec2::ZERO, |s, j| s + chord(j));
        return if t >= 0 { sum(0..t) } else { -sum(t..0) };
    }
    let d = a - Vec2::new(1.0, 0.0);
    if d.hypot2() < 1e-18 {
        return Vec2::new(t as f64, 0.0);
    }
    let num = pow(a, t) - Vec2::new(1.0, 0.0);
    mul(num, conj(d)) / d.hypot2()
}

/// Given `a`: `z_0`, `v`, the normal equations' sums, and the hand-drawn copies' sum of
/// square misses and the weighted one (`None` when the copies do not fix the orbit).
fn solve(copies: &[Placed], a: Vec2, bend: f64) -> Option<(Vec2, Vec2, Sums, f64, f64)> {
    let mut s = Sums::default();
    let (mut r0, mut r1) = (Vec2::ZERO, Vec2::ZERO);
    for c in copies {
        let p = geometric(a, bend, c.t);
        let z = c.z.to_vec2();
        s.s0 += c.weight;
        s.s1 += p * c.weight;
        s.s2 += c.weight * p.hypot2();
        r0 += z * c.weight;
        r1 += mul(conj(p), z) * c.weight;
    }
    s.det = s.s0 * s.s2 - s.s1.hypot2();
    if s.det <= 1e-9 * (s.s0 * s.s2).max(1e-300) {
        return None;
    }
    let z0 = (r0 * s.s2 - mul(s.s1, r1)) / s.det;
    let v = (r1 * s.s0 - mul(conj(s.s1), r0)) / s.det;
    let (mut hand, mut weighted) = (0.0, 0.0);
    for c in copies {
        let e = (c.z.to_vec2() - z0 - mul(v, geometric(a, bend, c.t))).hypot2();
        weighted += c.weight * e;
        if c.hand {
            hand += e;
        }
    }
    Some((z0, v, s, hand, weighted))
}

/// The minimum of `f` over `centre ± radius`, by a grid narrowed three times.
fn argmin_1d(f: &dyn Fn(f64) -> f64, centre: f64, radius: f64) -> f64 {
    let (mut c, mut r) = (centre, radius);
    for _ in 0..4 {
        let best = (-10..=10)
            .map(|k| c + r * k as f64 / 10.0)
            .map(|x| (x, f(x)))
            .min_by(|p, q| p.1.total_cmp(&q.1))
            .map_or(c, |p| p.0);
        c = best;
        r *= 0.2;
    }
    c
}

/// The same over a square.
fn argmin_2d(f: &dyn Fn(Vec2) -> f64, centre: Vec2, radius: f64) -> Vec2 {
    let (mut c, mut r) = (centre, radius);
    for _ in 0..4 {
        let mut best = (c, f(c));
        for i in -6..=6 {
            for j in -6..=6 {
                let x = c + Vec2::new(i as f64, j as f64) * (r / 6.0);
                let y = f(x);
                if y < best.1 {
                    best = (x, y);
                }
            }
        }
        c = best.0;
        r *= 0.3;
    }
    c
}

/// What the copies' shapes say of the step: the mean of the consecutive pairs' `a`,
/// the variance of one pair's `a` about it, and how many independent pairs that mean
/// is worth (its variance is `var / pairs`).
#[derive(Clone, Copy, Debug)]
pub(super) struct Shapes {
    pub mean: Vec2,
    pub var: f64,
    pub pairs: f64,
    /// How much each step turns on from the one before (radians; 0 but for a stem that
    /// bends on): `mean` is then the first step's.
    pub bend: f64,
}

/// How badly step `a` explains the copies, given the hand's mean square `scatter`:
/// the placement residual over the scatter, plus the shapes' mean's distance over its
/// variance (minus the log-likelihood of both, up to a constant).
pub(super) fn cost(copies: &[Placed], shapes: &Shapes, a: Vec2, scatter: f64) -> f64 {
    let ssr = solve(copies, a, shapes.bend).map_or(f64::INFINITY, |s| s.4);
    ssr / scatter + shapes.pairs * (a - shapes.mean).hypot2() / shapes.var
}

/// Prior copies of the hand's scatter (see `certainty::reach`).
const PRIOR_COPIES: f64 = 3.0;

/// The step that explains the copies best (`cost`), given the hand's scatter: searched
/// about the shapes' mean within four of their standard deviations, along the turn only
/// at a given `scale`.
fn best_a(copies: &[Placed], shapes: &Shapes, scatter: f64, scale: Option<f64>) -> Vec2 {
    let objective = |a: Vec2| cost(copies, shapes, a, scatter);
    let polar = |th: f64| Vec2::new(th.cos(), th.sin());
    let spread = 4.0 * shapes.var.sqrt();
    if let Some(scale) = scale {
        let turn = shapes.mean.y.atan2(shapes.mean.x);
        polar(argmin_1d(&|th| objective(polar(th) * scale), turn, spread.min(0.5))) * scale
    } else {
        argmin_2d(&objective, shapes.mean, spread.min(0.3))
    }
}

/// What the copies' places say of the bend (how much each step turns on from the one
/// before), near `bend`: the bend they fit best and their information on it (the
/// inverse of its variance), from the curvature of the likelihood's profile, the step
/// refitted (along its turn) at each bend; `shapes_at` gives what the shapes say of the
/// step at a bend. `None` where the profile does not curve up there.
///
/// A hand turns each copy by a few degrees at random: the bend read from four leaves'
/// shapes may be off by 0.1 radian a step per step, while their places, a few percent
/// of the step off their curve, hold it to a tenth of that.
pub(super) fn bend_from_places(
    copies: &[Placed],
    shapes_at: &dyn Fn(f64) -> Shapes,
    prior: f64,
    bend: f64,
) -> Option<(f64, f64)> {
    let fit = Orbit::fit(copies, shapes_at(bend), prior)?;
    let profile = |b: f64| {
        let shapes = shapes_at(b);
        cost(copies, &shapes, best_a(copies, &shapes, fit.scatter, Some(fit.a.hypot())), fit.scatter)
    };
    let h = BEND_PROBE;
    let (lo, mid, hi) = (profile(bend - h), profile(bend), profile(bend + h));
    let curvature = (lo + hi - 2.0 * mid) / (h * h);
    (curvature.is_finite() && curvature > 0.0).then(|| (bend - (hi - lo) / (2.0 * h) / curvature, curvature))
}

/// The bend's step in `bend_from_places` (radians a step, per step).
const BEND_PROBE: f64 = 0.01;

impl Orbit {
    /// The orbit through `copies` (their indices along the step), with the step read
    /// from the shapes and the places; `prior` is the hand's mean square scatter assumed
    /// before the copies show their own.
    pub fn fit(copies: &[Placed], shapes: Shapes, prior: f64) -> Option<Orbit> {
        let hand = copies.iter().filter(|c| c.hand).count() as f64;
        // `z_0`, `v` and `a` take three copies' worth of the hand-drawn ones.
        let free = (hand - 3.0).max(0.0);
        let scatter_at = |ssr: f64| (ssr + PRIOR_COPIES * prior) / (free + PRIOR_COPIES);
        let unit = (shapes.mean.hypot() - 1.0).abs() < 0.04;
        let bend = shapes.bend;
        let mut scatter = scatter_at(solve(copies, shapes.mean, bend)?.3);
        let objective = |a: Vec2, scatter: f64| cost(copies, &shapes, a, scatter);
        let polar = |th: f64| Vec2::new(th.cos(), th.sin());
        let mut a = shapes.mean;
        for _ in 0..2 {
            a = best_a(copies, &shapes, scatter, unit.then_some(1.0));
            scatter = scatter_at(solve(copies, a, bend)?.3);
        }
        // The error of `a`: the objective's curvature (along the turn only, for a pure
        // turn).
        let var_a = if unit {
            let th = a.y.atan2(a.x);
            let h = 1e-4;
            let f = |x: f64| objective(polar(x), scatter);
            let curv = (f(th + h) + f(th - h) - 2.0 * f(th)) / (h * h);
            if curv > 0.0 {
                1.0 / curv
            } else {
                shapes.var / shapes.pairs
            }
        } else {
            let h = 1e-4;
            let f = |x: Vec2| objective(x, scatter);
            let c = f(a);
            let cx = (f(a + Vec2::new(h, 0.0)) + f(a - Vec2::new(h, 0.0)) - 2.0 * c) / (h * h);
            let cy = (f(a + Vec2::new(0.0, h)) + f(a - Vec2::new(0.0, h)) - 2.0 * c) / (h * h);
            if cx > 0.0 && cy > 0.0 {
                1.0 / cx + 1.0 / cy
            } else {
                shapes.var / shapes.pairs
            }
        };
        Orbit::with(copies, a, bend, scatter_at, var_a, unit)
    }

    fn with(
        copies: &[Placed],
        a: Vec2,
        bend: f64,
        scatter_at: impl Fn(f64) -> f64,
        var_a: f64,
        unit: bool,
    ) -> Option<Orbit> {
        let (z0, v, sums, hand_ssr, _) = solve(copies, a, bend)?;
        let hand = copies.iter().filter(|c| c.hand).count() as f64;
        Some(Orbit {
            a,
            bend,
            z0,
            v,
            scatter: scatter_at(hand_ssr),
            copies: (hand - 3.0).max(0.0) + PRIOR_COPIES,
            sums,
            var_a,
            var_scale: 0.0,
            unit,
            members: copies.to_vec(),
        })
    }

    /// The same copies on the orbit whose step is exactly `a` (a ring's turn snapped to
    /// a whole fraction): `a` is then known, and so is nothing of its error.
    pub fn snapped(&self, copies: &[Placed], a: Vec2, prior: f64) -> Option<Orbit> {
        let hand = copies.iter().filter(|c| c.hand).count() as f64;
        // (With `a` given, `z_0` and `v` take two copies' worth.)
        let free = (hand - 2.0).max(0.0);
        let mut o = Orbit::with(copies, a, 0.0, |ssr| (ssr + PRIOR_COPIES * prior) / (free + PRIOR_COPIES), 0.0, true)?;
        o.copies = free + PRIOR_COPIES;
        Some(o)
    }

    /// Whether the step scales (a spiral), not held to a pure turn.
    pub fn scales(&self) -> bool {
        !self.unit
    }

    /// The turn and scale carrying copy `from` onto copy `to`.
    pub fn turn(&self, from: i64, to: i64) -> Vec2 {
        turn_between(self.a, self.bend, from, to)
    }

    /// The site of copy `t`.
    pub fn at(&self, t: i64) -> Point {
        (self.z0 + mul(self.v, geometric(self.a, self.bend, t))).to_point()
    }

    /// The centre the orbit turns about (`None` for a row).
    pub fn centre(&self) -> Option<Point> {
        let d = Vec2::new(1.0, 0.0) - self.a;
        (d.hypot2() > 1e-12).then(|| (self.z0 + mul(self.v, conj(d)) / d.hypot2()).to_point())
    }

    /// The root-mean-square distance from the site of copy `t` to where the hand will
    /// put it: the hand's own scatter, the site's least-squares error, and how far the
    /// error of `a` moves it (with `z_0` and `v` refitted for the changed `a`: near the
    /// copies they make up for most of it).
    pub fn miss(&self, t: i64) -> f64 {
        let Sums { s0, s1, s2, det } = self.sums;
        let p = geometric(self.a, self.bend, t);
        // x^T M^-1 conj(x) for x = [1, p].
        let leverage = ((s2 - 2.0 * (s1.x * p.x + s1.y * p.y) + s0 * p.hypot2()) / det).max(0.0);
        let site =
            |a: Vec2| solve(&self.members, a, self.bend).map(|(z0, v, ..)| z0 + mul(v, geometric(a, self.bend, t)));
        let h = 1e-5;
        let moved = |d: Vec2| match (site(self.a + d * h), site(self.a - d * h)) {
            (Some(p), Some(q)) => ((p - q) / (2.0 * h)).hypot2(),
            _ => 0.0,
        };
        let from_a = if self.unit {
            // (Along the turn: `a i` is the tangent of the unit circle at `a`.)
            moved(mul(self.a, Vec2::new(0.0, 1.0))) * self.var_a
        } else {
            // (And out along `a` itself, its scale, by what `var_scale` adds.)
            let scale = if self.var_scale > 0.0 { moved(self.a / self.a.hypot()) * self.var_scale } else { 0.0 };
            0.5 * (moved(Vec2::new(1.0, 0.0)) + moved(Vec2::new(0.0, 1.0))) * self.var_a + scale
        };
        (self.scatter * (1.0 + leverage) + from_a).sqrt()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn ring(n: usize, drawn: usize, centre: Point, radius: f64) -> Vec<Placed> {
        (0..drawn)
            .map(|k| {
                let th = k as f64 * std::f64::consts::TAU / n as f64;
                Placed { t: k as i64, z: centre + Vec2::new(th.cos(), th.sin()) * radius, weight: 1.0, hand: true }
            })
            .collect()
    }

    #[test]
    fn an_exact_ring_is_fitted_and_continued() {
        let c = Point::new(100.0, 50.0);
        let copies = ring(8, 4, c, 40.0);
        let th = std::f64::consts::TAU / 8.0;
        let a = Vec2::new(th.cos(), th.sin());
        let shapes = Shapes { mean: a, var: 1e-4, pairs: 3.0, bend: 0.0 };
        let o = Orbit::fit(&copies, shapes, 0.01).unwrap();
        assert!(o.centre().unwrap().distance(c) < 1e-3, "{:?}", o.centre());
        let want = ring(8, 8, c, 40.0);
        for w in &want[4..] {
            assert!(o.at(w.t).distance(w.z) < 1e-3);
        }
        // Further along, the site is less certain.
        assert!(o.miss(6) > o.miss(4));
    }

    #[test]
    fn a_row_is_the_orbit_of_a_translation() {
        let copies: Vec<Placed> = (0..4)
            .map(|k| Placed { t: k, z: Point::new(10.0 + 20.0 * k as f64, 5.0), weight: 1.0, hand: true })
            .collect();
        let shapes = Shapes { mean: Vec2::new(1.0, 0.0), var: 1e-4, pairs: 3.0, bend: 0.0 };
        let o = Orbit::fit(&copies, shapes, 0.01).unwrap();
        assert!(o.at(6).distance(Point::new(130.0, 5.0)) < 1e-3, "{:?}", o.at(6));
        assert!(o.centre().is_none() || o.centre().unwrap().to_vec2().hypot() > 1e4);
    }

    #[test]
    fn a_stem_that_bends_on_is_continued_along_its_curve() {
        // Copies every 40 along an Euler spiral (its curvature changing steadily along
        // it, as an S's does between its bends): step `j` turns by 0.2 - 0.05 j.
        let (len, k0, k1): (f64, f64, f64) = (40.0, 0.225 / 40.0, -0.05 / 1600.0);
        let mut copies = Vec::new();
        let (mut p, mut s) = (Vec2::ZERO, 0.0);
        for t in 0..9 {
            if t > 0 {
                // (Integrated finely between copies.)
                for _ in 0..400 {
                    let h = len / 400.0;
                    let th = k0 * (s + h / 2.0) + k1 * (s + h / 2.0).powi(2) / 2.0;
                    p += Vec2::new(th.cos(), th.sin()) * h;
                    s += h;
                }
            }
            copies.push(Placed { t, z: p.to_point(), weight: 1.0, hand: true });
        }
        let th: f64 = 0.2;
        let shapes = Shapes { mean: Vec2::new(th.cos(), th.sin()), var: 1e-6, pairs: 16.0, bend: -0.05 };
        let o = Orbit::fit(&copies[..5], shapes, 1e-4).unwrap();
        for c in &copies[5..] {
            assert!(o.at(c.t).distance(c.z) < 0.02 * len, "copy {}: {:?} vs {:?}", c.t, o.at(c.t), c.z);
        }
    }

    #[test]
    fn places_correct_a_shapes_turn_that_is_off() {
        // Six copies on a ring of twelve, the shapes' turn 10% off and that uncertain:
        // the places put it back.
        let copies = ring(12, 6, Point::new(0.0, 0.0), 100.0);
        let th = 1.1 * std::f64::consts::TAU / 12.0;
        let shapes = Shapes { mean: Vec2::new(th.cos(), th.sin()), var: 0.1f64.powi(2), pairs: 5.0, bend: 0.0 };
        let o = Orbit::fit(&copies, shapes, 0.25).unwrap();
        let turn = o.a.y.atan2(o.a.x);
        assert!((turn - std::f64::consts::TAU / 12.0).abs() < 0.005, "{turn}");
    }
}
