//! The path copies follow: a drawn stroke read as a curve by arc length, with its
//! tangent, and where a copy lies in its frame.

use super::super::sequence::smoothed;
use crate::vector::frechet::{closed_loop, resample};
use crate::vector::motif::contact::point_segment;
use crate::vector::similarity::Similarity;
use crate::vector::stroke::Stroke;
use kurbo::{Point, Vec2};

/// About this far apart the path's points lie...
const SPACING: f64 = 2.0;
/// ...at least and at most this many.
const MIN_POINTS: usize = 16;
const MAX_POINTS: usize = 1024;

/// A path whose end comes back within this share of its extent (its box's diagonal)
/// of its start, having turned most of the way round, is closed.
const CLOSE: f64 = 0.15;

/// A drawn path resampled evenly by arc length and smoothed.
pub(super) struct Path {
    pub(super) points: Vec<Point>,
    /// Arc length between consecutive points.
    pub(super) ds: f64,
    pub(super) closed: bool,
    /// Half the window the tangent is read over (arc length).
    window: f64,
}

impl Path {
    pub(super) fn new(stroke: &Stroke, window: f64) -> Option<Path> {
        let raw: Vec<Point> = stroke.points.iter().map(|p| Point::new(p[0], p[1])).collect();
        let (raw, closed) = round(raw);
        let length: f64 = raw.windows(2).map(|w| w[0].distance(w[1])).sum();
        if length <= 0.0 {
            return None;
        }
        // (A hand's jaggies, a mouse's whole pixels, would turn the tangent at random and
        // lengthen the path where its points are dense: it is resampled, averaged over
        // five points and read by the smoothed curve's own arc length.)
        let n = ((length / SPACING).ceil() as usize).clamp(MIN_POINTS, MAX_POINTS);
        let spacing = length / n as f64 * (1.0 + 1e-9);
        let smooth = smoothed(&resample(&raw, spacing, MAX_POINTS + 1));
        let smooth_length: f64 = smooth.windows(2).map(|w| w[0].distance(w[1])).sum();
        let points = resample(&smooth, smooth_length / n as f64 * (1.0 + 1e-9), MAX_POINTS + 1);
        if points.len() < 2 || smooth_length <= 0.0 {
            return None;
        }
        let ds = smooth_length / (points.len() - 1) as f64;
        Some(Path { points, ds, closed, window })
    }

    pub(super) fn length(&self) -> f64 {
        self.ds * (self.points.len() - 1) as f64
    }

    /// `s` brought onto the path (round a closed one), or `None` past an open one's ends.
    pub(super) fn on(&self, s: f64) -> Option<f64> {
        let l = self.length();
        if self.closed {
            Some(s.rem_euclid(l))
        } else {
            (-1e-9..=l + 1e-9).contains(&s).then_some(s.clamp(0.0, l))
        }
    }

    pub(super) fn at(&self, s: f64) -> Point {
        let x = (s / self.ds).clamp(0.0, (self.points.len() - 1) as f64);
        let i = (x.floor() as usize).min(self.points.len() - 2);
        self.points[i].lerp(self.points[i + 1], x - i as f64)
    }

    /// The tangent's direction at `s` (radians), read over `window` either side.
    pub(super) fn heading(&self, s: f64) -> f64 {
        let l = self.length();
        let (a, b) = if self.closed {
            (self.at((s - self.window).rem_euclid(l)), self.at((s + self.window).rem_euclid(l)))
        } else {
            (self.at((s - self.window).max(0.0)), self.at((s + self.window).min(l)))
        };
        (b - a).atan2()
    }

    /// How far the tangent turns along the path (the range of its unwrapped direction).
    pub(super) fn curve(&self) -> f64 {
        let steps = (self.length() / self.window.max(self.ds)).ceil().max(2.0) as usize;
        let (mut lo, mut hi, mut acc, mut prev) = (0.0f64, 0.0f64, 0.0, self.heading(0.0));
        for k in 1..=steps {
            let h = self.heading(self.length() * k as f64 / steps as f64);
            acc += (h - prev + std::f64::consts::PI).rem_euclid(std::f64::consts::TAU) - std::f64::consts::PI;
            prev = h;
            (lo, hi) = (lo.min(acc), hi.max(acc));
        }
        hi - lo
    }

    /// Where `points` come nearest the path: the arc length there and the distance.
    pub(super) fn nearest(&self, points: &[Point]) -> (f64, f64) {
        let mut best = (0.0, f64::INFINITY);
        for (i, w) in self.points.windows(2).enumerate() {
            let d = w[1] - w[0];
            for &p in points {
                let u = ((p - w[0]).dot(d) / d.hypot2().max(1e-12)).clamp(0.0, 1.0);
                let dist = (p - (w[0] + d * u)).hypot();
                if dist < best.1 {
                    best = ((i as f64 + u) * self.ds, dist);
                }
            }
        }
        best
    }

    /// Where on the path, within `window` of `near`, `points` lie as `target` lies at
    /// `at` in the path's frame: the arc length from which carrying them to `at` brings
    /// them nearest `target`, and their mean square distance from it there.
    pub(super) fn register(&self, points: &[Point], target: &[Point], at: f64, near: f64, window: f64) -> (f64, f64) {
        let msd = |s: f64| {
            let carry = self.carry(s, at);
            points.iter().map(|&p| to_polyline(carry.apply(p), target)).sum::<f64>() / points.len().max(1) as f64
        };
        let k = (window / self.ds).ceil() as i64;
        let i0 = (near / self.ds).round() as i64;
        let costs: Vec<(f64, f64)> =
            (i0 - k..=i0 + k).filter_map(|i| self.on(i as f64 * self.ds)).map(|s| (s, msd(s))).collect();
        let Some(b) = (0..costs.len()).min_by(|&x, &y| costs[x].1.total_cmp(&costs[y].1)) else {
            return (near, f64::INFINITY);
        };
        // (Between samples: the parabola through the least cost and its neighbours.)
        if b > 0 && b + 1 < costs.len() {
            let (l, m, r) = (costs[b - 1].1, costs[b].1, costs[b + 1].1);
            let curve = l - 2.0 * m + r;
            if curve > 1e-12 {
                let shift = (0.5 * (l - r) / curve).clamp(-0.5, 0.5);
                let s = costs[b].0 + shift * self.ds;
                return (s, msd(s));
            }
        }
        costs[b]
    }

    /// The similarity carrying what lies at arc length `from` to `to`, in the path's
    /// frame (turned as the tangent turns, about the path's point).
    pub(super) fn carry(&self, from: f64, to: f64) -> Similarity {
        let turn = self.heading(to) - self.heading(from);
        let a = Vec2::new(turn.cos(), turn.sin());
        let (p, q) = (self.at(from).to_vec2(), self.at(to).to_vec2());
        Similarity { a, b: q - crate::vector::similarity::mul(a, p) }
    }

    /// The signed arc length from `a` to `b` (the shorter way round a closed path).
    pub(super) fn gap(&self, a: f64, b: f64) -> f64 {
        let d = b - a;
        if self.closed {
            let l = self.length();
            (d + 0.5 * l).rem_euclid(l) - 0.5 * l
        } else {
            d
        }
    }
}

/// The squared distance from `p` to the polyline through `line`.
fn to_polyline(p: Point, line: &[Point]) -> f64 {
    line.windows(2).map(|w| point_segment(p, w[0], w[1]).powi(2)).fold(f64::INFINITY, f64::min)
}

/// `raw` closed where the hand drew it round to where it began: a circle's ends seldom
/// meet, falling short or running on past the start. Its end within `CLOSE` of its
/// extent of its start, after turning at least 1.5 pi (a horseshoe's ends may come as
/// near), it is closed; run on past, the overshoot is cut where it comes nearest the
/// start. (`closed_loop`'s test alone, ends within two steps, is for shapes: a petal.)
fn round(mut raw: Vec<Point>) -> (Vec<Point>, bool) {
    let n = raw.len();
    if closed_loop(&raw) {
        return (raw, true);
    }
    if n < 6 {
        return (raw, false);
    }
    let bounds = raw.iter().fold(kurbo::Rect::from_points(raw[0], raw[0]), |r, &p| r.union_pt(p));
    let reach = CLOSE * bounds.size().to_vec2().hypot();
    // (The end's last stretch, its last quarter: where it comes nearest the start.)
    let Some((k, d)) = (3 * n / 4..n).map(|k| (k, raw[k].distance(raw[0]))).min_by(|a, b| a.1.total_cmp(&b.1)) else {
        return (raw, false);
    };
    let turning: f64 = raw[..=k]
        .windows(3)
        .map(|w| {
            let (u, v) = (w[1] - w[0], w[2] - w[1]);
            u.cross(v).atan2(u.dot(v))
        })
        .sum();
    if d > reach || turning.abs() < 1.5 * std::f64::consts::PI {
        return (raw, false);
    }
    raw.truncate(k + 1);
    raw.push(raw[0]);
    (raw, true)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_circle_whose_ends_miss_is_closed_and_a_horseshoe_is_not() {
        let circle = |turn: f64| -> Vec<Point> {
            (0..=200).map(|k| (Vec2::from_angle(turn * k as f64 / 200.0) * 80.0).to_point()).collect()
        };
        // Short of its start by 12, or on past it by 20 (cut where it comes back).
        for turn in [std::f64::consts::TAU - 0.15, std::f64::consts::TAU + 0.25] {
            let (points, closed) = round(circle(turn));
            assert!(closed, "turn {turn:.2}");
            assert_eq!(points.first(), points.last());
            let length: f64 = points.windows(2).map(|w| w[0].distance(w[1])).sum();
            assert!((length - 160.0 * std::f64::consts::PI).abs() < 15.0, "turn {turn:.2}: {length:.0} long");
        }
        // Half way round: open.
        assert!(!round(circle(std::f64::consts::PI)).1);
        // A narrow U: its ends 20 apart, within reach, but it turns by pi only.
        let u: Vec<Point> = (0..=40)
            .map(|k| Point::new(200.0 - 5.0 * k as f64, -10.0))
            .chain((1..=20).map(|k| {
                Point::new(0.0, 0.0)
                    + Vec2::from_angle(-std::f64::consts::FRAC_PI_2 - std::f64::consts::PI * k as f64 / 20.0) * 10.0
            }))
            .chain((1..=40).map(|k| Point::new(5.0 * k as f64, 10.0)))
            .collect();
        assert!(!round(u).1);
    }
}
