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

/// The basis of the lattice of periods `a` and `b` whose rows of cells are the rows the
/// hand drew, as whole multiples of `a` and `b` (a matrix of determinant 1 or -1, whose
/// rows give the new periods; `None`: `a` and `b` are it already): its first period
/// the one the hand stepped along most often from one copy to the next (`steps_along`),
/// when that is at least twice and more often than along `a` (one step down to begin
/// the next row is no row), the same way as `a`; the second the shortest that completes
/// it, on `b`'s side. The lattice is the same; only its cells are counted otherwise. (A grid
/// read on a diagonal and a column went on along the diagonal: its next row's ghosts
/// fell off the grid.)
pub(super) fn rows_drawn(a: Vec2, b: Vec2, steps_along: impl Fn(Vec2) -> usize) -> Option<[[i64; 2]; 2]> {
    let gcd = |mut x: i64, mut y: i64| {
        (x, y) = (x.abs(), y.abs());
        while y != 0 {
            (x, y) = (y, x % y);
        }
        x
    };
    let at = |(i, j): (i64, i64)| a * i as f64 + b * j as f64;
    let mut best = ((1i64, 0i64), steps_along(a), a.hypot());
    for i in -2i64..=2 {
        for j in -2i64..=2 {
            // (Primitive periods only, one of each pair ±v.)
            if (i, j) <= (0, 0) || gcd(i, j) != 1 {
                continue;
            }
            let v = at((i, j));
            let (steps, len) = (steps_along(v), v.hypot());
            if steps > best.1.max(1) || (steps == best.1 && best.0 != (1, 0) && len < best.2 - 1e-9) {
                best = ((i, j), steps, len);
            }
        }
    }
    let (mut i, mut j) = best.0;
    if (i, j) == (1, 0) {
        return None;
    }
    if at((i, j)).dot(a) < 0.0 {
        (i, j) = (-i, -j);
    }
    // A second period completing the basis: `k a + l b` with `i l - j k = 1`, less the
    // whole multiple of the first that leaves it shortest, on `b`'s side.
    let (mut k, mut l) = (-2i64..=2)
        .flat_map(|k| (-2i64..=2).map(move |l| (k, l)))
        .find(|&(k, l)| i * l - j * k == 1)
        .expect("a primitive pair of small integers has one");
    let r = (at((k, l)).dot(at((i, j))) / at((i, j)).hypot2()).round() as i64;
    (k, l) = (k - r * i, l - r * j);
    if at((i, j)).cross(at((k, l))).signum() != a.cross(b).signum() {
        (k, l) = (-k, -l);
    }
    Some([[i, j], [k, l]])
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

    /// `d` in periods: `(u, w)` with `d = u a + w b` (a row's `w` is 0; its `u`, `d`'s
    /// length along `a`).
    pub(super) fn coords(&self, d: Vec2) -> (f64, f64) {
        match self.b {
            Some(b) => {
                let det = self.a.cross(b);
                (d.cross(b) / det, self.a.cross(d) / det)
            }
            None => (d.dot(self.a) / self.a.hypot2(), 0.0),
        }
    }

    /// The whole periods `(u, w)` that make up `d` (within `tol`), if any.
    pub(super) fn whole(&self, d: Vec2, tol: f64) -> Option<(i64, i64)> {
        let (u, w) = self.coords(d);
        let (u, w) = (u.round() as i64, w.round() as i64);
        ((d - self.step(u, w)).hypot() < tol).then_some((u, w))
    }
}

/// Sites filed by their class and their place modulo the lattice, so that a site finds
/// those a whole number of periods from it (`Lattice::whole`) among a few neighbours
/// instead of all (a lattice tried on 200 hatching lines along an arc makes about 200
/// sites; each tried against every other was half of an autocomplete call).
///
/// A site's coordinates along the periods, modulo one, are cut into cells at least as
/// wide as the tolerance moves them (`tol |b| / |a x b|` along `a`), so two sites
/// within `tol` of a whole number of periods apart lie in the same or adjacent cells
/// (round the wrap); a row cuts its across-coordinate by `tol`, without wrapping.
pub(super) struct Residues {
    lattice: Lattice,
    cells: (i64, i64),
    tol: f64,
    /// (Hashed by `memo::Spread`: SipHash was a twentieth of autocomplete on hatching.)
    filed: crate::memo::SpreadMap<(u32, i64, i64), Vec<usize>>,
}

impl Residues {
    pub(super) fn new(lattice: Lattice, tol: f64) -> Self {
        let a = lattice.a;
        let cells = match lattice.b {
            Some(b) => {
                let det = a.cross(b).abs();
                let along = |len: f64| ((det / (tol * len)).floor() as i64).clamp(1, 1 << 20);
                (along(b.hypot()), along(a.hypot()))
            }
            None => (((a.hypot() / tol).floor() as i64).clamp(1, 1 << 20), 0),
        };
        Residues { lattice, cells, tol, filed: Default::default() }
    }

    /// The cell of `p`: each coordinate's fraction cut into `cells` (a row's second
    /// coordinate is its distance across, in tolerances).
    fn cell(&self, p: Vec2) -> (i64, i64) {
        let a = self.lattice.a;
        let cut = |x: f64, k: i64| ((x - x.floor()) * k as f64).floor().clamp(0.0, (k - 1) as f64) as i64;
        match self.lattice.b {
            Some(b) => {
                let det = a.cross(b);
                (cut(p.cross(b) / det, self.cells.0), cut(a.cross(p) / det, self.cells.1))
            }
            None => (cut(p.dot(a) / a.hypot2(), self.cells.0), (p.cross(a) / a.hypot() / self.tol).floor() as i64),
        }
    }

    pub(super) fn file(&mut self, class: u32, p: Vec2, id: usize) {
        let (i, j) = self.cell(p);
        self.filed.entry((class, i, j)).or_default().push(id);
    }

    /// The first (least) `id` filed near `p` for which `matches` says something.
    pub(super) fn first<T>(&self, class: u32, p: Vec2, mut matches: impl FnMut(usize) -> Option<T>) -> Option<T> {
        let (i, j) = self.cell(p);
        let (ki, kj) = self.cells;
        // The cells round `i` (each once, however few there are round the wrap)...
        let around = |x: i64, k: i64| {
            if k >= 3 {
                (x - 1..=x + 1).map(|y| y.rem_euclid(k)).collect()
            } else {
                (0..k).collect::<Vec<i64>>()
            }
        };
        let mut best: Option<(usize, T)> = None;
        for u in around(i, ki) {
            let across: Vec<i64> = match self.lattice.b {
                Some(_) => around(j, kj),
                None => vec![j - 1, j, j + 1],
            };
            for w in across {
                // (Each cell's ids ascend: its first match is its least.)
                let Some(ids) = self.filed.get(&(class, u, w)) else { continue };
                for &id in ids.iter().take_while(|&&id| best.as_ref().is_none_or(|b| id < b.0)) {
                    if let Some(t) = matches(id) {
                        best = Some((id, t));
                        break;
                    }
                }
            }
        }
        best.map(|b| b.1)
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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_grid_read_on_its_diagonal_is_counted_along_the_rows_drawn() {
        // A square grid of period 30 read on the diagonal (30, -30) and the column
        // (0, 30); the hand stepped along (30, 0) six times, down a column once.
        let (a, b) = (Vec2::new(30.0, -30.0), Vec2::new(0.0, 30.0));
        let steps = |v: Vec2| {
            let is = |w: Vec2| (v - w).hypot() < 1.0 || (v + w).hypot() < 1.0;
            if is(Vec2::new(30.0, 0.0)) {
                6
            } else if is(Vec2::new(0.0, 30.0)) {
                1
            } else {
                0
            }
        };
        let [[i, j], [k, l]] = rows_drawn(a, b, steps).expect("another basis");
        assert_eq!((i * l - j * k).abs(), 1, "the same lattice");
        let (first, second) = (a * i as f64 + b * j as f64, a * k as f64 + b * l as f64);
        assert!((first - Vec2::new(30.0, 0.0)).hypot() < 1e-9, "{first:?}");
        assert!((second.hypot() - 30.0).abs() < 1e-9 && second.cross(first).abs() > 1.0, "{second:?}");
        // Already along the rows: unchanged.
        assert!(rows_drawn(Vec2::new(30.0, 0.0), Vec2::new(0.0, 30.0), steps).is_none());
    }
}
