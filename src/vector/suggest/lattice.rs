//! Periods: the candidates, their least-squares refinement and snapping, and the
//! lattice they span.

use super::fit::MotifPosition;
use crate::vector::element::Element;
use crate::vector::reference::Spread;
use kurbo::Vec2;

/// Candidate periods start at the latest strokes.
const RECENT: usize = 32;

/// The periods that best explain the strokes' positions given their cells: with `d`
/// a stroke's offset from its motif position's (weighted) mean and `(du, dw)` its
/// cell's, the weighted least squares solution of `d = du a + dw b`.
pub(super) fn refine(
    elems: &[Element],
    weight: &[f64],
    motif: &[MotifPosition],
    cell: &[(usize, (i64, i64))],
    a: Vec2,
    b: Option<Vec2>,
) -> (Vec2, Option<Vec2>) {
    let (mut suu, mut suw, mut sww) = (0.0, 0.0, 0.0);
    let (mut su, mut sw) = (Vec2::ZERO, Vec2::ZERO);
    for mp in motif.iter().filter(|m| m.members.len() >= 2) {
        let k: f64 = mp.members.iter().map(|&i| weight[i]).sum();
        let mean_p = mp.members.iter().fold(Vec2::ZERO, |s, &i| s + elems[i].pos.to_vec2() * weight[i]) / k;
        let mean_u = mp.members.iter().map(|&i| weight[i] * cell[i].1 .0 as f64).sum::<f64>() / k;
        let mean_w = mp.members.iter().map(|&i| weight[i] * cell[i].1 .1 as f64).sum::<f64>() / k;
        for &i in &mp.members {
            let d = elems[i].pos.to_vec2() - mean_p;
            let (du, dw) = (cell[i].1 .0 as f64 - mean_u, cell[i].1 .1 as f64 - mean_w);
            let wi = weight[i];
            suu += wi * du * du;
            suw += wi * du * dw;
            sww += wi * dw * dw;
            su += d * (wi * du);
            sw += d * (wi * dw);
        }
    }
    match b {
        None if suu > 0.0 => (su / suu, None),
        Some(_) => {
            let det = suu * sww - suw * suw;
            if det.abs() < 1e-9 * (suu * sww).max(1e-300) {
                // Every stroke on one line of cells: `b` is not observed apart from `a`.
                return (a, b);
            }
            ((su * sww - sw * suw) / det, Some((sw * suu - su * suw) / det))
        }
        None => (a, b),
    }
}

/// Periods within this angle of the canvas's axes are taken along them.
const SQUARE_DEGREES: f64 = 2.5;

/// `v` turned onto the nearest canvas axis when it is within `SQUARE_DEGREES` of it: a
/// row drawn by hand is meant level (a few copies leave its slope uncertain by a degree
/// or two, and every copy proposed further along would drift off the row).
pub(super) fn square(v: Vec2) -> Vec2 {
    let len = v.hypot();
    let quarter = std::f64::consts::FRAC_PI_2;
    let angle = v.y.atan2(v.x);
    let axis = (angle / quarter).round() * quarter;
    if (angle - axis).abs() < SQUARE_DEGREES.to_radians() {
        Vec2::new(len * axis.cos(), len * axis.sin())
    } else {
        v
    }
}

/// `b`'s offset along `a` taken as a simple fraction of `a` (whole, halves, thirds,
/// quarters) when it is within this share of `a` of one.
const SHEAR_SNAP: f64 = 0.04;

/// `b` with its offset along `a` snapped to a simple fraction: rows of a lattice drawn
/// by hand sit straight above one another or half a period over (brick, hexagonal),
/// and a few copies leave the offset uncertain by a few percent, which grows row by row.
pub(super) fn shear(a: Vec2, b: Vec2) -> Vec2 {
    let t = b.dot(a) / a.hypot2();
    let nearest = [1.0, 2.0]
        .iter()
        .map(|&q| (t * q).round() / q)
        .min_by(|x, y| (x - t).abs().total_cmp(&(y - t).abs()))
        .unwrap_or(t);
    if (nearest - t).abs() < SHEAR_SNAP {
        b + a * (nearest - t)
    } else {
        b
    }
}

/// Periods `a` and `b` (a row when there is no `b`).
#[derive(Clone, Copy, Debug)]
pub(super) struct Lattice {
    pub(super) a: Vec2,
    pub(super) b: Option<Vec2>,
}

impl Lattice {
    pub(super) fn step(&self, u: i64, w: i64) -> Vec2 {
        self.a * u as f64 + self.b.unwrap_or(Vec2::ZERO) * w as f64
    }

    /// The whole periods `(u, w)` that make up `d` (within `tol`), if any.
    pub(super) fn whole(&self, d: Vec2, tol: f64) -> Option<(i64, i64)> {
        let (u, w) = match self.b {
            Some(b) => {
                let det = self.a.cross(b);
                ((d.cross(b) / det).round() as i64, (self.a.cross(d) / det).round() as i64)
            }
            None => ((d.dot(self.a) / self.a.hypot2()).round() as i64, 0),
        };
        ((d - self.step(u, w)).hypot() < tol).then_some((u, w))
    }
}

/// Offsets between same-class elements that recur (at least twice from the latest
/// elements, an offset between two copies of a motif of `k` strokes counting `k` times:
/// each of its parts shows it), in one half-plane, shortest first.
pub(super) fn candidates(elems: &[Element], parts: &[usize], spread: &Spread, tol: f64) -> Vec<Vec2> {
    let n = elems.len();
    let mut offsets: Vec<(Vec2, usize)> = Vec::new();
    let first = n.saturating_sub(RECENT);
    for i in first..n {
        for (j, o) in elems.iter().enumerate() {
            // Each pair once: a pair of two recent strokes was seen from the earlier.
            if j == i || (j >= first && j < i) || o.class != elems[i].class {
                continue;
            }
            let mut v = o.pos - elems[i].pos;
            if v.hypot() <= 0.5 * spread.spacing {
                continue;
            }
            if v.x < 0.0 || (v.x == 0.0 && v.y < 0.0) {
                v = -v;
            }
            offsets.push((v, parts[i].min(parts[j])));
        }
    }
    let offsets = crate::order::sorted(&offsets, |v| v.0.hypot2());
    // Cluster: each kept offset with the number of offsets within `tol` of it.
    let mut kept: Vec<(Vec2, usize)> = Vec::new();
    for (v, votes) in offsets {
        let len = v.hypot();
        // Offsets near the half-plane's edge may have flipped: compare both signs.
        let near = kept
            .iter_mut()
            .rev()
            .take_while(|(k, _)| len - k.hypot() < tol)
            .find(|(k, _)| (*k - v).hypot() < tol || (*k + v).hypot() < tol);
        match near {
            Some(k) => k.1 += votes,
            None => kept.push((v, votes)),
        }
    }
    kept.into_iter().filter(|&(_, votes)| votes >= 2).map(|(v, _)| v).collect()
}
