//! The lattice a drawing of rings repeats on, once each ring is completed (issue 27):
//! rosettes side by side over the output.
//!
//! Rings round one centre, with all else within half again the largest's reach (a
//! sprig across a petal), are one rosette: it repeats on a hexagonal lattice its
//! diameter and a tenth apart. Rings drawn apart from one another, or from other
//! strokes (a second flower, a sprig, a long stem), repeat together: the drawing's box,
//! in rows each offset by half a box, the boxes as far apart as the drawn rings are
//! from the rest (two flowers drawn a flower apart stay so, rather than pair off; a
//! flower's disc or stem, which meets its ring, is part of it, not a gap of nothing;
//! a drawing all in one cluster, a flower and its long stem, packs as a rosette).
//! A ring large beside the output (its diameter over half the output's short side), or
//! a drawing larger than the output, is no rosette: it is continued across the output
//! as a curve.

use super::chain::Chain;
use super::pack;
use super::stroke::Stroke;
use kurbo::{Point, Rect};

/// The periods `[[ax, ay], [bx, by]]` the completed drawing `out` repeats on in `area`
/// (its rings `rings`, the first turning round `centre`; `ring_of`: the ring each
/// stroke of `out` belongs to), or none where it should not repeat.
pub fn lattice(
    out: &[Stroke],
    ring_of: &[Option<usize>],
    rings: &[Chain],
    centre: Point,
    area: Rect,
) -> Option<[[f64; 2]; 2]> {
    let short = area.width().min(area.height());
    // How far the strokes `of` reach from `p`, with their pen.
    let reach = |p: Point, of: &dyn Fn(usize) -> bool| {
        out.iter()
            .enumerate()
            .filter(|&(k, _)| of(k))
            .flat_map(|(_, s)| s.points.iter().map(move |&[x, y]| p.distance(Point::new(x, y)) + 0.5 * s.width))
            .fold(0.0, f64::max)
    };
    let radius = reach(centre, &|_| true);
    let radii: Vec<f64> = rings
        .iter()
        .enumerate()
        .map(|(i, ring)| ring.centre().map_or(f64::INFINITY, |c| reach(c, &|k| ring_of[k] == Some(i))))
        .collect();
    // (One rosette: the rings round one centre, and all else within half again the
    // largest's reach: a sprig across a petal, not a second flower.)
    let largest = radii.iter().copied().fold(0.0, f64::max);
    let concentric = rings.iter().all(|r| r.centre().is_some_and(|c| c.distance(centre) <= 0.25 * radii[0]));
    if concentric && radius <= 1.5 * largest && 4.0 * radius <= short {
        // (Rosettes a tenth of their diameter apart, and no closer than copies round
        // the outermost ring lie to one another: beads round a ring, a step apart,
        // read as one pattern with the next rosette's a tenth apart.)
        let s = (2.2 * radius).max(2.0 * radius + outer_gap(out, ring_of, rings));
        return Some([[s, 0.0], [0.5 * s, 0.5 * 3f64.sqrt() * s]]);
    }
    let bounds = pack::inked_bounds(out)?;
    if radii.iter().any(|&r| 4.0 * r > short) || bounds.width() > area.width() || bounds.height() > area.height() {
        return None;
    }
    // The drawing in clusters: each ring's box, grown by the other strokes that meet it
    // (a flower's disc or stem, petals the ring's chain left out), and the rest.
    let mut boxes: Vec<Option<Rect>> = vec![None; rings.len()];
    for (s, ring) in out.iter().zip(ring_of) {
        if let Some(i) = *ring {
            boxes[i] = Some(boxes[i].map_or(s.bounds(), |b| b.union(s.bounds())));
        }
    }
    let mut clusters: Vec<Rect> = boxes.into_iter().flatten().collect();
    let rings_held = clusters.len();
    for (s, _) in out.iter().zip(ring_of).filter(|(_, r)| r.is_none()) {
        match clusters[..rings_held].iter_mut().find(|b| box_gap(**b, s.bounds()) == 0.0) {
            Some(b) => *b = b.union(s.bounds()),
            None => clusters.push(s.bounds()),
        }
    }
    let drawn_gap = (0..rings_held)
        .flat_map(|i| clusters.iter().enumerate().filter(move |&(j, _)| j != i).map(move |(_, &b)| (i, b)))
        .map(|(i, b)| box_gap(clusters[i], b))
        .fold(f64::INFINITY, f64::min);
    // (One cluster, a clover and its long stem, has no drawn gap to keep: it packs as a
    // rosette does. Taken as the output's side, it was laid once.)
    let gap = if drawn_gap.is_finite() { (0.2 * largest).max(drawn_gap.min(short)) } else { 0.2 * largest };
    Some(pack::brick(bounds.width() + gap, bounds.height() + gap))
}

/// The gap between neighbouring copies round the outermost ring: their centres' step
/// less a copy's extent (none or less where they touch, as petals do).
fn outer_gap(out: &[Stroke], ring_of: &[Option<usize>], rings: &[Chain]) -> f64 {
    let outermost = rings
        .iter()
        .enumerate()
        .filter_map(|(i, ring)| {
            let (c, k) = (ring.centre()?, ring.closes?);
            let copies: Vec<&Stroke> =
                out.iter().zip(ring_of).filter(|(_, r)| **r == Some(i)).map(|(s, _)| s).collect();
            let n = copies.len().max(1) as f64;
            let r = copies.iter().map(|s| s.reference_point().distance(c)).sum::<f64>() / n;
            let extent = copies.iter().map(|s| s.bounds().width().max(s.bounds().height())).sum::<f64>() / n;
            Some((r, 2.0 * r * (std::f64::consts::PI / k as f64).sin() - extent))
        })
        .max_by(|x, y| x.0.total_cmp(&y.0));
    outermost.map_or(0.0, |(_, gap)| gap)
}

/// The distance between two boxes (0 where they meet).
fn box_gap(a: Rect, b: Rect) -> f64 {
    let dx = (a.x0 - b.x1).max(b.x0 - a.x1).max(0.0);
    let dy = (a.y0 - b.y1).max(b.y0 - a.y1).max(0.0);
    dx.hypot(dy)
}
