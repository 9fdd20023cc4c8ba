//! Places that bend steadily: copies each a move on from the last, every move turned
//! from the one before by about the same angle (fence posts along an arc). Read where
//! the copies keep their pose and their shapes say nothing of the bend.

use kurbo::{Point, Vec2};

/// Places bend steadily where their moves' mean turn passes this many of its standard
/// errors...
const STEADY: f64 = 3.0;
/// ...the turns' scatter pooled with a hand's (radians: a copy placed 1% of the step
/// off turns the moves either side of it by about 0.03), counted as this many turns...
const HAND_BEND: f64 = 0.03;
const PRIOR_TURNS: f64 = 2.0;
/// ...and the mean is at least this (radians a step, about 1 degree) and at most this
/// (about 30 degrees: an arc, not a grid drawn row by row).
const LEAST_BEND: f64 = 0.02;
const MOST_BEND: f64 = 0.5;

/// The turn a step of places that bend steadily (fence posts along an arc), given the
/// turn of each move from the one before, when there are two or more: their mean, where
/// it is clear of none (`STEADY`) and within `LEAST_BEND` and `MOST_BEND`.
pub fn steady_bend(turns: &[f64]) -> Option<f64> {
    if turns.len() < 2 {
        return None;
    }
    let n = turns.len() as f64;
    let mean = turns.iter().sum::<f64>() / n;
    let ss = turns.iter().map(|t| (t - mean).powi(2)).sum::<f64>();
    let var = (ss + PRIOR_TURNS * HAND_BEND * HAND_BEND) / (n - 1.0 + PRIOR_TURNS);
    (mean.abs() > STEADY * (var / n).sqrt() && (LEAST_BEND..=MOST_BEND).contains(&mean.abs())).then_some(mean)
}

/// The turn of each move between consecutive `places` from the one before.
pub fn move_turns(places: &[Point]) -> Vec<f64> {
    let moves: Vec<Vec2> = places.windows(2).map(|w| w[1] - w[0]).collect();
    moves.windows(2).map(|m| m[0].cross(m[1]).atan2(m[0].dot(m[1]))).collect()
}

/// The mean turn a step about `c` from each of `places` to the next (each step taken
/// the short way round).
pub fn turn_about(c: Point, places: &[Point]) -> f64 {
    let angle = |p: Point| (p.y - c.y).atan2(p.x - c.x);
    let pi = std::f64::consts::PI;
    let sum: f64 = places.windows(2).map(|w| (angle(w[1]) - angle(w[0]) + 3.0 * pi).rem_euclid(2.0 * pi) - pi).sum();
    sum / (places.len().max(2) - 1) as f64
}

/// The mean turn a step about the circle through `places` (`circle_through`, then
/// `turn_about`), or none where they lie on a line: copies whose shapes show no turn of
/// their own (circles) or keep their pose (fence posts) turn so.
pub fn turn_through(places: &[Point]) -> f64 {
    circle_through(places).map_or(0.0, |c| turn_about(c, places))
}

/// The mean of `places` and the unit direction they spread along most (the principal
/// axis: half the angle of the covariance's `(2 sxy, sxx - syy)`).
pub fn principal_axis(places: &[Point]) -> (Vec2, Vec2) {
    let mean = places.iter().fold(Vec2::ZERO, |s, p| s + p.to_vec2()) / places.len().max(1) as f64;
    let (sxx, sxy, syy) = places.iter().fold((0.0, 0.0, 0.0), |(a, b, c), p| {
        let d = p.to_vec2() - mean;
        (a + d.x * d.x, b + d.x * d.y, c + d.y * d.y)
    });
    let theta = 0.5 * (2.0 * sxy).atan2(sxx - syy);
    (mean, Vec2::new(theta.cos(), theta.sin()))
}

/// The centre of the circle through `places` nearest them all (Kåsa's least squares:
/// `x^2 + y^2 + D x + E y + F` minimised over the places), or `None` where they lie on
/// a line.
pub fn circle_through(places: &[Point]) -> Option<Point> {
    // Normal equations of [x y 1] (D E F)^T = -(x^2 + y^2), about the places' mean for
    // conditioning.
    let n = places.len() as f64;
    let m = places.iter().fold(Vec2::ZERO, |s, p| s + p.to_vec2()) / n;
    let (mut sxx, mut sxy, mut syy, mut sxz, mut syz) = (0.0, 0.0, 0.0, 0.0, 0.0);
    for p in places {
        let (x, y) = (p.x - m.x, p.y - m.y);
        let z = x * x + y * y;
        sxx += x * x;
        sxy += x * y;
        syy += y * y;
        sxz += x * z;
        syz += y * z;
    }
    // (About the mean, F decouples: D and E solve the 2 x 2 system.)
    let det = sxx * syy - sxy * sxy;
    if det.abs() <= 1e-9 * (sxx + syy).powi(2) {
        return None;
    }
    let d = -(sxz * syy - syz * sxy) / det;
    let e = -(sxx * syz - sxy * sxz) / det;
    Some(Point::new(m.x - 0.5 * d, m.y - 0.5 * e))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_circle_through_points_on_an_arc_is_found() {
        let c = Point::new(120.0, -40.0);
        let arc: Vec<Point> =
            (0..6).map(|k| c + Vec2::new((0.3 * k as f64).cos(), (0.3 * k as f64).sin()) * 200.0).collect();
        assert!(circle_through(&arc).unwrap().distance(c) < 1e-6);
        let line: Vec<Point> = (0..6).map(|k| Point::new(k as f64 * 10.0, 5.0)).collect();
        assert!(circle_through(&line).is_none());
        // Turns alike a step bend steadily; alternating ones do not.
        assert!(steady_bend(&move_turns(&arc)).is_some_and(|t| (t - 0.3).abs() < 1e-9));
        assert!(steady_bend(&[0.2, -0.2, 0.2, -0.2]).is_none());
        assert!((turn_about(c, &arc) - 0.3).abs() < 1e-9);
        assert!(principal_axis(&line).1.cross(Vec2::new(1.0, 0.0)).abs() < 1e-9);
    }
}
