//! Lattice estimation for near-regular examples (beyond the paper).
//!
//! A hand-drawn example repeats with jitter. Growth copies the example's own relative
//! offsets, so the mean step between copies carries the jitter's bias (about
//! sigma / sqrt(n) per step); over many steps that drifts, and where two growth fronts
//! meet the mismatch leaves seams. Here the two period vectors are estimated from the
//! whole example by least squares, each element is assigned to a motif position (the
//! elements reached from one another by whole periods) and snapped to
//! `centre + u a + v b`. Growth runs on the snapped positions, so it cannot drift; each
//! output element then gets its source's own deviation back, so the hand-drawn feel
//! stays.
//!
//! The fit is used only when it explains the example: enough elements reached by the
//! periods, and small residuals. Otherwise (irregular input, a single copy) the
//! positions are left as drawn.

use super::element::Element;
use super::period::Periods;
use super::spatial::Grid;
use kurbo::{Point, Vec2};

/// The fitted lattice: period vectors and each element's snapped position.
#[derive(Clone, Debug)]
pub struct LatticeFit {
    pub a: Vec2,
    pub b: Option<Vec2>,
    pub snapped: Vec<Point>,
    /// Motif position of each element (its component under the periods).
    pub component: Vec<u32>,
    /// Each element's cell in its component (an element no period reaches is a
    /// component of its own, in its cell (0, 0)).
    pub cell: Vec<(i32, i32)>,
}

impl LatticeFit {
    /// The fit of `elems` as periods (one motif position per component, at its centre),
    /// when it is a lattice (not a row).
    pub fn periods(&self, elems: &[Element]) -> Option<Periods> {
        let b = self.b?;
        let cell = self.cell.clone();
        let positions = self.component.iter().map(|&c| c as usize + 1).max().unwrap_or(0);
        let mut motifs = vec![(0, Point::ZERO); positions];
        for (i, &c) in self.component.iter().enumerate() {
            let (u, w) = cell[i];
            motifs[c as usize] = (elems[i].class, self.snapped[i] - self.a * u as f64 - b * w as f64);
        }
        Some(Periods { a: self.a, b, motif: self.component.clone(), cell, motifs })
    }
}

/// A period must map at least this fraction of the elements onto same-class elements.
const MIN_SUPPORT: f64 = 0.6;
/// Sampled elements used to find and score candidate periods.
const SAMPLE: usize = 256;

/// Estimates the lattice of `elems` (with `grid` indexing them, `pair_radius` per class
/// and the median neighbour `spacing`); `None` when the example is not periodic enough.
pub fn fit(elems: &[Element], grid: &Grid, pair_radius: &[f64], spacing: f64, reach: f64) -> Option<LatticeFit> {
    let n = elems.len();
    if n < 4 {
        return None;
    }
    let partner = |i: usize, v: Vec2| partner(elems, grid, pair_radius, i, v);
    let step = n.div_ceil(SAMPLE).max(1);
    let sample: Vec<usize> = (0..n).step_by(step).collect();
    let support = |v: Vec2| sample.iter().filter(|&&i| partner(i, v).is_some()).count() as f64 / sample.len() as f64;

    // Candidate periods: offsets from a few central elements to their same-class
    // neighbours, in one half-plane, shortest first.
    let centre = elems.iter().fold(Vec2::ZERO, |s, e| s + e.pos.to_vec2()) / n as f64;
    let mut by_centre: Vec<usize> = (0..n).collect();
    by_centre.sort_by(|&i, &j| {
        (elems[i].pos.to_vec2() - centre).hypot2().total_cmp(&(elems[j].pos.to_vec2() - centre).hypot2())
    });
    let mut candidates: Vec<Vec2> = Vec::new();
    for &i in by_centre.iter().take(12) {
        let e = &elems[i];
        grid.for_each_near(e.pos, reach, |j| {
            let o = &elems[j as usize];
            let v = o.pos - e.pos;
            if o.class == e.class
                && v.hypot() > 0.5 * spacing
                && v.hypot() <= reach
                && (v.x > 1e-9 || (v.x.abs() <= 1e-9 && v.y > 0.0))
            {
                candidates.push(v);
            }
        });
    }
    let mut candidates = crate::order::sorted(&candidates, |v| v.hypot2());
    candidates.dedup_by(|a, b| (*a - *b).hypot() < 0.25 * spacing);

    let a = *candidates.iter().find(|&&v| support(v) >= MIN_SUPPORT)?;
    let b = candidates
        .iter()
        .copied()
        .filter(|v| a.cross(*v).abs() > 0.3 * a.hypot() * v.hypot())
        .find(|&v| support(v) >= MIN_SUPPORT);

    // Refine each period as the mean of all its observed instances.
    let refine = |v: Vec2| -> Vec2 {
        let (mut sum, mut count) = (Vec2::ZERO, 0usize);
        for i in 0..n {
            if let Some(j) = partner(i, v) {
                sum += elems[j].pos - elems[i].pos;
                count += 1;
            }
        }
        if count > 0 {
            sum / count as f64
        } else {
            v
        }
    };
    let (a, b) = (refine(a), b.map(refine));

    let (coord, reached, snapped) = assign(n, &partner, a, b, elems);
    if (reached as f64) < 0.8 * n as f64 {
        return None;
    }
    // Accept only a fit that explains the drawing: residuals small against the periods.
    let mut residuals: Vec<f64> = snapped.iter().zip(elems).map(|(s, e)| s.distance(e.pos)).collect();
    crate::order::floats(&mut residuals);
    // (On the scale of the periods: a motif of small parts, a cat's eyes and mouth, has
    // its strokes' spacing far below its copies'.)
    let shorter = b.map_or(a.hypot(), |b| a.hypot().min(b.hypot()));
    if residuals[residuals.len() / 2] > 0.15 * shorter {
        return None;
    }
    Some(lattice_fit(a, b, snapped, &coord))
}

fn lattice_fit(a: Vec2, b: Option<Vec2>, snapped: Vec<Point>, coord: &[(usize, i64, i64)]) -> LatticeFit {
    let component = coord.iter().map(|c| c.0 as u32).collect();
    let cell = coord.iter().map(|&(_, u, w)| (u as i32, w as i32)).collect();
    LatticeFit { a, b, snapped, component, cell }
}

/// Motif positions: the connected components of the elements under `+-a`, `+-b`
/// (`partner`), each element's component and lattice coordinates, how many elements
/// lie in components of several, and each element snapped to its component's centre
/// (the mean of its members' positions less their steps) plus its steps.
fn assign(
    n: usize,
    partner: &dyn Fn(usize, Vec2) -> Option<usize>,
    a: Vec2,
    b: Option<Vec2>,
    elems: &[Element],
) -> (Vec<(usize, i64, i64)>, usize, Vec<Point>) {
    let mut coord: Vec<Option<(usize, i64, i64)>> = vec![None; n];
    let steps: Vec<(Vec2, i64, i64)> =
        [(a, 1, 0), (-a, -1, 0)].into_iter().chain(b.into_iter().flat_map(|b| [(b, 0, 1), (-b, 0, -1)])).collect();
    let mut components = 0usize;
    let mut reached = 0usize;
    for root in 0..n {
        if coord[root].is_some() {
            continue;
        }
        coord[root] = Some((components, 0, 0));
        let mut stack = vec![root];
        let mut size = 0;
        while let Some(i) = stack.pop() {
            size += 1;
            let (c, u, w) = coord[i].expect("set before pushed");
            for &(v, du, dw) in &steps {
                if let Some(j) = partner(i, v) {
                    if coord[j].is_none() {
                        coord[j] = Some((c, u + du, w + dw));
                        stack.push(j);
                    }
                }
            }
        }
        if size > 1 {
            reached += size;
        }
        components += 1;
    }
    let coord: Vec<(usize, i64, i64)> = coord.into_iter().map(|c| c.expect("every element is reached")).collect();
    let b0 = b.unwrap_or(Vec2::ZERO);
    let mut sums = vec![(Vec2::ZERO, 0usize); components];
    for (i, &(k, u, w)) in coord.iter().enumerate() {
        sums[k].0 += elems[i].pos.to_vec2() - a * u as f64 - b0 * w as f64;
        sums[k].1 += 1;
    }
    let snapped = coord
        .iter()
        .map(|&(k, u, w)| (sums[k].0 / sums[k].1 as f64 + a * u as f64 + b0 * w as f64).to_point())
        .collect();
    (coord, reached, snapped)
}

/// Periods given as an option, `[[ax, ay], [bx, by]]`, as vectors, or an error when they
/// span no lattice (not finite, zero or parallel).
pub fn given_periods(periods: Option<[[f64; 2]; 2]>) -> crate::error::Result<Option<(Vec2, Vec2)>> {
    let Some([a, b]) = periods else { return Ok(None) };
    let (a, b) = (Vec2::new(a[0], a[1]), Vec2::new(b[0], b[1]));
    let finite = [a.x, a.y, b.x, b.y].iter().all(|v| v.is_finite());
    if !finite || a.cross(b).abs() <= 1e-6 * a.hypot() * b.hypot() || a.hypot().min(b.hypot()) < 1e-6 {
        return crate::error::invalid(
            "periods must be two vectors [[ax, ay], [bx, by]] of finite numbers that are not parallel (nor zero).",
        );
    }
    Ok(Some((a, b)))
}

/// The elements on periods `a` and `b` a designer set: copies a whole period apart are
/// one motif position (snapped to their centre, as `fit` does); an element no period
/// reaches is a motif position of its own, so one drawn motif repeats at the periods
/// as it is. Unlike `fit`, nothing is refused: the periods are the designer's.
pub fn on_periods(elems: &[Element], a: Vec2, b: Vec2) -> LatticeFit {
    // Partners within a quarter of a period (the drawing may show no spacing at all: one
    // cross drawn once is two bars on one centre).
    let reach = 0.25 * a.hypot().min(b.hypot());
    let first = elems.first().map_or(Point::ZERO, |e| e.pos);
    let area = elems.iter().fold(kurbo::Rect::from_points(first, first), |r, e| r.union_pt(e.pos));
    let mut grid = Grid::new(area, reach, 4 * elems.len() + 16);
    for (i, e) in elems.iter().enumerate() {
        grid.insert(i as u32, e.pos);
    }
    let radius = vec![f64::INFINITY; elems.iter().map(|e| e.class as usize + 1).max().unwrap_or(0)];
    let partner = |i: usize, v: Vec2| partner(elems, &grid, &radius, i, v);
    let (coord, _, snapped) = assign(elems.len(), &partner, a, Some(b), elems);
    lattice_fit(a, Some(b), snapped, &coord)
}

/// The partner of element `i` under offset `v`: a same-class element near `pos + v`,
/// within a quarter of the period (a class's own spacing alone would let an offset
/// between two parts of a copy, a cat's ears, land near another part), never the
/// element itself (an offset shorter than the class's radius would map a lone part of
/// each copy, a cat's face, onto itself).
fn partner(elems: &[Element], grid: &Grid, pair_radius: &[f64], i: usize, v: Vec2) -> Option<usize> {
    let e = &elems[i];
    let p = e.pos + v;
    let d = pair_radius[e.class as usize].min(0.25 * v.hypot());
    let mut best: Option<(usize, f64)> = None;
    grid.for_each_near(p, d, |j| {
        let o = &elems[j as usize];
        let d2 = (o.pos - p).hypot2();
        if j as usize != i && o.class == e.class && d2 < d * d && best.is_none_or(|b| d2 < b.1) {
            best = Some((j as usize, d2));
        }
    });
    best.map(|b| b.0)
}
