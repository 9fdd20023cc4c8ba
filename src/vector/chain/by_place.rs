//! A ring read from its copies' places alone: circles or pen-tap dots evenly round a
//! centre (beads, a clock's marks). Their shapes show no turn (a circle fits its
//! neighbour turned any way, a dot has no shape), so `search`, which reads its steps
//! from pairs of shapes, read such rings as a lattice, a scatter or a sequence (helper-55's
//! trial: 15 of 36 complete rings of five to twelve circles, none of 36 of dots).
//!
//! Read globally, as a whole ring is (Xing et al. predict locally; a complete drawing
//! is seen at once): the places fit one circle (Kåsa's least squares,
//! `bend::circle_through`), their angles about it a whole fraction of a turn apart
//! (the median gap gives the count, `k`), each within `PLACE` of a step of its site and
//! no two on one site, the sites drawn one run (a ring drawn part way round is
//! completed from its ends), at least half round, their fitted turn a site within
//! `CLOSE` of a `k`-th. The step is the turn of a `k`-th about the centre, the way the
//! hand went; the copies are carried unturned. One ring is read so, of one kind (dots
//! or circles, not both), with a centre of its own size allowed; two rings of circles
//! side by side are left to `search`.

use super::bend::circle_through;
// (`find`'s bounds: a round copy's shape fits itself turned within `SHAPE` of its size,
// copies of one ring are within `MAX_SCALE` of their median size, at most `MAX_RING`.)
use super::find::{MAX_RING, MAX_SCALE, SHAPE};
use super::{Chain, MAX_STROKES};
use crate::vector::classify::median;
use crate::vector::similarity::{centroid, looks_round, mul, samples, Similarity};
use crate::vector::stroke::Stroke;
use kurbo::{Point, Vec2};
use std::f64::consts::{PI, TAU};

/// Fewer copies round a centre are as much a lattice's (four circles are a square).
const MIN_COPIES: usize = 5;
/// Each copy lies within this share of the step of its site along the ring, and all of
/// them within `ACROSS` of it across (rms: a scatter of circles fits some circle, loosely).
const PLACE: f64 = 0.3;
const ACROSS: f64 = 0.15;
/// The copies' turn a site, fitted to them all, is within this share of a `k`-th of a
/// turn (the median gap gives `k`, each copy's site is within `PLACE` of a step, and a
/// ring of six drawn 2π/6.5 apart passes both, its last gap 1.4 steps).
const CLOSE: f64 = 0.05;
/// A copy nearer the ring's centre than this share of its mean radius is drawn at the
/// centre, not round it.
const CENTRE: f64 = 0.5;

/// The ring of round copies (circles, or dots) among `strokes`, where they hold two
/// thirds of the drawing, a stroke at the centre aside (the rest goes with each ring).
pub fn ring(strokes: &[Stroke]) -> Option<Chain> {
    let n = strokes.len();
    if !(MIN_COPIES..=MAX_STROKES).contains(&n) {
        return None;
    }
    let sampled: Vec<Vec<Point>> = strokes.iter().map(samples).collect();
    let size: Vec<f64> = strokes.iter().map(|s| s.bounds().size().to_vec2().hypot()).collect();
    // The larger of the dots and the round strokes of about their median size.
    let dots: Vec<usize> = (0..n).filter(|&k| strokes[k].is_dot()).collect();
    let round: Vec<usize> =
        (0..n).filter(|&k| !strokes[k].is_dot() && looks_round(&sampled[k], size[k], SHAPE)).collect();
    let round: Vec<usize> = {
        let mut sizes: Vec<f64> = round.iter().map(|&k| size[k]).collect();
        let median = median(&mut sizes);
        round.into_iter().filter(|&k| (median / MAX_SCALE..=median * MAX_SCALE).contains(&size[k])).collect()
    };
    let group = if dots.len() > round.len() { dots } else { round };
    let m = group.len();
    if m < MIN_COPIES || 3 * m < 2 * n {
        return None;
    }
    // (A bead drawn at the centre, of the ring's size, is no copy round it: the rest goes
    // with each ring.)
    let centre: Vec<Point> = sampled.iter().map(|s| centroid(s)).collect();
    let c = circle_through(&group.iter().map(|&k| centre[k]).collect::<Vec<_>>())?;
    let mean = group.iter().map(|&k| centre[k].distance(c)).sum::<f64>() / m as f64;
    let group: Vec<usize> = group.into_iter().filter(|&k| centre[k].distance(c) >= CENTRE * mean).collect();
    let centred = m - group.len();
    let m = group.len();
    if m < MIN_COPIES || centred > 1 || 3 * m < 2 * (n - centred) {
        return None;
    }
    let places: Vec<Point> = group.iter().map(|&k| centre[k]).collect();
    let c = circle_through(&places)?;
    let radius = places.iter().map(|p| p.distance(c)).sum::<f64>() / m as f64;
    let angle = |p: Point| (p.y - c.y).atan2(p.x - c.x);
    let mut sorted: Vec<f64> = places.iter().map(|&p| angle(p)).collect();
    sorted.sort_by(f64::total_cmp);
    let mut gaps: Vec<f64> = sorted.windows(2).map(|w| w[1] - w[0]).collect();
    gaps.push(sorted[0] + TAU - sorted[m - 1]);
    let gap = median(&mut gaps);
    if gap <= 0.0 {
        return None;
    }
    let k = (TAU / gap).round();
    if !(MIN_COPIES as f64..=MAX_RING as f64).contains(&k) {
        return None;
    }
    let k = k as usize;
    let alpha = TAU / k as f64;
    let step = 2.0 * radius * (PI / k as f64).sin();
    // On one circle: the rms distance across it within `ACROSS` of the step.
    let across = (places.iter().map(|p| (p.distance(c) - radius).powi(2)).sum::<f64>() / m as f64).sqrt();
    if across > ACROSS * step {
        return None;
    }
    // Each copy's site: the phase fitted to them all (the mean of `k` times each angle).
    let phase = places.iter().fold(Vec2::ZERO, |s, &p| {
        let t = k as f64 * angle(p);
        s + Vec2::new(t.cos(), t.sin())
    });
    let phase = phase.y.atan2(phase.x) / k as f64;
    let mut site = vec![usize::MAX; m];
    let mut taken = vec![None; k];
    for (i, &p) in places.iter().enumerate() {
        let at = (angle(p) - phase) / alpha;
        let s = at.round();
        if (at - s).abs() > PLACE {
            return None;
        }
        let s = (s as i64).rem_euclid(k as i64) as usize;
        if taken[s].is_some() {
            return None;
        }
        taken[s] = Some(i);
        site[i] = s;
    }
    // The sites drawn make one run round the ring; it begins after the sites left empty
    // (a whole ring: at its first-drawn copy).
    let empty: Vec<usize> = (0..k).filter(|&s| taken[s].is_none()).collect();
    let start = if empty.is_empty() {
        site[0]
    } else {
        let after: Vec<usize> = empty.iter().map(|&s| (s + 1) % k).filter(|&s| taken[s].is_some()).collect();
        if after.len() != 1 {
            return None;
        }
        after[0]
    };
    // The copies a `k`-th of a turn apart (`CLOSE`), on sites at least half round: the
    // turn a site, fitted to their angles unwrapped from the run's start (each past
    // the last by the sites between: six circles 2π/6.5 apart were a ring of six with a
    // gap of 1.4 steps, five 2π/8.5 apart, 169 degrees round, half a ring of eight).
    let unwrapped: Vec<(f64, f64)> = (0..m)
        .map(|i| {
            let t = ((site[i] + k - start) % k) as f64;
            let a = angle(places[i]) - angle(places[taken[start].expect("a drawn site")]);
            (t, a - TAU * ((a - t * alpha) / TAU).round())
        })
        .collect();
    let (st, sa) = unwrapped.iter().fold((0.0, 0.0), |s, u| (s.0 + u.0, s.1 + u.1));
    let (mt, ma) = (st / m as f64, sa / m as f64);
    let (num, den) =
        unwrapped.iter().fold((0.0, 0.0), |s, u| (s.0 + (u.0 - mt) * (u.1 - ma), s.1 + (u.0 - mt).powi(2)));
    let turn = if den > 0.0 { num / den } else { 0.0 };
    if (turn / alpha - 1.0).abs() > CLOSE || ((m - 1) as f64 * alpha) < PI - 1e-9 {
        return None;
    }
    // The way the hand went: consecutive copies in the drawing's order mostly one site on
    // or one back (a whole ring either way; else forward).
    let on = |i: usize, j: usize, d: usize| (site[i] + d) % k == site[j];
    let forward = (1..m).filter(|&j| on(j - 1, j, 1)).count();
    let backward = (1..m).filter(|&j| on(j, j - 1, 1)).count();
    let sense = if backward > forward { -1.0 } else { 1.0 };
    // (Backwards, the run begins where it ended going forward.)
    let start = if sense < 0.0 && !empty.is_empty() { (start + m - 1) % k } else { start };
    let members: Vec<usize> = (0..m)
        .map(|t| {
            let s = (start as i64 + sense as i64 * t as i64).rem_euclid(k as i64) as usize;
            taken[s].map(|i| group[i])
        })
        .collect::<Option<Vec<usize>>>()?;
    let a = Vec2::new((sense * alpha).cos(), (sense * alpha).sin());
    let step = Similarity { a, b: c.to_vec2() - mul(a, c.to_vec2()) };
    Some(Chain { members, companions: vec![Vec::new(); m], step, upright: true, closes: Some(k) })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::rng::Rng;
    use crate::vector::sequences::{circle, circle_ring};

    /// Rings of five to twelve circles, whole, each 3% of the step off: read whole, their
    /// count the drawn one, their step carrying each copy onto the next; so too with a
    /// bead drawn at their centre.
    #[test]
    fn whole_rings_of_circles_are_read_by_place() {
        for n in [5, 6, 8, 12] {
            for seed in 1..=3 {
                let (strokes, _) = circle_ring(n, 90.0, 10.0, 0.03, seed);
                let chain = ring(&strokes).unwrap_or_else(|| panic!("{n} circles, seed {seed}: no ring"));
                // (With a bead at the centre too, the same ring.)
                let mut centred = strokes.clone();
                centred.push(circle(Point::new(300.0, 300.0), 10.0, 0.0, 1.0, &mut Rng::new(seed), 0.3));
                assert_eq!(ring(&centred).map(|c| c.members), Some(chain.members.clone()), "{n}, centred");
                assert_eq!(chain.closes, Some(n));
                assert_eq!(chain.members.len(), n);
                let step = 2.0 * 90.0 * (PI / n as f64).sin();
                for w in chain.members.windows(2) {
                    let (p, q) = (strokes[w[0]].reference_point(), strokes[w[1]].reference_point());
                    assert!(chain.step.apply(p).distance(q) < 0.2 * step, "{n}, seed {seed}");
                }
            }
        }
    }

    /// Scattered circles, a row and a spiral of circles are no ring; a ring drawn under
    /// half round is left to the search (an arc).
    #[test]
    fn scatters_rows_spirals_and_arcs_are_no_ring() {
        let mut rng = Rng::new(9);
        for _ in 0..20 {
            let scatter: Vec<Stroke> = (0..8)
                .map(|_| {
                    let at = Point::new(60.0 + 480.0 * rng.next_f64(), 60.0 + 480.0 * rng.next_f64());
                    circle(at, 10.0, 0.0, 1.0, &mut rng, 0.5)
                })
                .collect();
            assert!(ring(&scatter).is_none());
        }
        let row: Vec<Stroke> =
            (0..6).map(|i| circle(Point::new(80.0 + 70.0 * i as f64, 300.0), 12.0, 0.0, 1.0, &mut rng, 0.5)).collect();
        assert!(ring(&row).is_none());
        let spiral: Vec<Stroke> = (0..10)
            .map(|i| {
                let (r, t) = (50.0 * 1.12f64.powi(i), 0.7 * i as f64);
                circle(Point::new(300.0 + r * t.cos(), 300.0 + r * t.sin()), 8.0, 0.0, 1.0, &mut rng, 0.5)
            })
            .collect();
        assert!(ring(&spiral).is_none());
        // (Unevenly: six 2π/6.5 apart, five 2π/8.5 apart, 169 degrees round.)
        let spaced = |n: usize, per: f64, rng: &mut Rng| -> Vec<Stroke> {
            (0..n)
                .map(|i| {
                    let t = TAU / per * i as f64;
                    circle(Point::new(300.0 + 90.0 * t.cos(), 300.0 + 90.0 * t.sin()), 10.0, 0.0, 1.0, rng, 0.3)
                })
                .collect()
        };
        assert!(ring(&spaced(6, 6.5, &mut rng)).is_none());
        assert!(ring(&spaced(5, 8.5, &mut rng)).is_none());
        assert!(ring(&spaced(6, 6.0, &mut rng)).is_some());
        let (whole, _) = circle_ring(12, 90.0, 10.0, 0.01, 4);
        assert!(ring(&whole[..5]).is_none());
        // (Seven of twelve, over half round: completed from its ends.)
        let part = ring(&whole[..7]).expect("seven of twelve");
        assert_eq!((part.closes, part.members.len()), (Some(12), 7));
    }
}
