//! The lattice a drawing of rings repeats on, once each ring is completed (issue 27):
//! rosettes side by side over the output.
//!
//! A ring with all else drawn close round it (a flower with its stem, or rings round
//! one centre) is one rosette: it repeats on a hexagonal lattice its diameter and a
//! tenth apart. Rings drawn apart from one another, or from other strokes (a second
//! flower, a sprig), repeat together: the drawing's box, in rows each offset by half a
//! box, the boxes as far apart as the drawn rings are from the rest (two flowers drawn
//! a flower apart stay so, rather than pair off). A ring large beside the output (its
//! diameter over half the output's short side), or a drawing larger than the output,
//! is no rosette: it is continued across the output as a curve.

use super::chain::Chain;
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
    if 4.0 * radius <= short {
        let s = 2.2 * radius;
        return Some([[s, 0.0], [0.5 * s, 0.5 * 3f64.sqrt() * s]]);
    }
    let radii: Vec<f64> = rings
        .iter()
        .enumerate()
        .map(|(i, ring)| ring.centre().map_or(f64::INFINITY, |c| reach(c, &|k| ring_of[k] == Some(i))))
        .collect();
    let pen = 0.5 * out.iter().map(|s| s.width).fold(0.0, f64::max);
    let bounds = out.iter().skip(1).fold(out.first()?.bounds(), |r, s| r.union(s.bounds())).inflate(pen, pen);
    if radii.iter().any(|&r| 4.0 * r > short) || bounds.width() > area.width() || bounds.height() > area.height() {
        return None;
    }
    let mut boxes: Vec<Option<Rect>> = vec![None; rings.len()];
    for (s, ring) in out.iter().zip(ring_of) {
        if let Some(i) = *ring {
            boxes[i] = Some(boxes[i].map_or(s.bounds(), |b| b.union(s.bounds())));
        }
    }
    let boxes: Vec<Rect> = boxes.into_iter().flatten().collect();
    let loose: Vec<Rect> = out.iter().zip(ring_of).filter(|(_, r)| r.is_none()).map(|(s, _)| s.bounds()).collect();
    let drawn_gap = boxes
        .iter()
        .enumerate()
        .flat_map(|(i, &a)| boxes[i + 1..].iter().chain(&loose).map(move |&b| apart(a, b)))
        .fold(f64::INFINITY, f64::min);
    let gap = (0.2 * radii.iter().copied().fold(0.0, f64::max)).max(drawn_gap.min(short));
    let (w, h) = (bounds.width() + gap, bounds.height() + gap);
    Some([[w, 0.0], [0.5 * w, h]])
}

/// The distance between two boxes (0 where they meet).
fn apart(a: Rect, b: Rect) -> f64 {
    let dx = (a.x0 - b.x1).max(b.x0 - a.x1).max(0.0);
    let dy = (a.y0 - b.y1).max(b.y0 - a.y1).max(0.0);
    dx.hypot(dy)
}
