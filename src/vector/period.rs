//! The translational periods of a whole example, and its exact periodic extension.
//!
//! A tile repeated 3x3 may hold dozens of unlike elements per period, so the period is
//! far longer than any neighbour's offset. Here candidate periods are the displacements
//! between members of the rarest classes (a true period maps every class onto itself,
//! so it is among them), shortest first; a candidate is a period when it maps (almost)
//! every element whose image lies inside the example's convex hull onto a same-class
//! element. The
//! shortest such vector and the shortest one not parallel to it, reduced (Lagrange-
//! Gauss), are verified against all elements.
//!
//! The extension then places every *motif position* (the elements reached from one
//! another by whole periods) at every lattice translate inside the output: no growth,
//! so no drift, no stalled bands and no strays. Each output element copies the example
//! element at the same place in the example's block of periods, with that element's
//! own deviation from the lattice, so hand-drawn jitter is kept as drawn.

use super::element::{Element, Placed};
use super::spatial::Grid;
use crate::error::{Error, Result};
use crate::order;
use crate::progress::Throttle;
use kurbo::{Point, Rect, Vec2};
use std::collections::{HashMap, HashSet};

/// The share of elements (whose image lies inside the example) a period must map onto
/// same-class elements: all but a few hand-drawn outliers.
const FULL_SUPPORT: f64 = 0.97;
/// Members of each rare class whose displacements to the others are candidates.
const ANCHORS: usize = 6;
/// Elements a candidate is screened on before it is verified on all of them...
const SAMPLE: usize = 400;
/// ...and, first, these few (a curve of 200 hatching lines has no second period: each
/// of 1,200 candidates was followed over every line whose image falls off the curve,
/// 17 ms of an autocomplete call).
const PROBE: usize = 48;
/// The most candidate displacements tried as periods.
const MAX_CANDIDATES: usize = 8_192;
/// Matching radius as a fraction of the median nearest-neighbour distance.
const TOLERANCE: f64 = 0.2;

/// An example's lattice: its reduced periods and, per element, the motif position it
/// belongs to and its cell `(k, l)` (its offset from the motif's origin in periods).
#[derive(Clone, Debug)]
pub struct Periods {
    pub a: Vec2,
    pub b: Vec2,
    pub motif: Vec<u32>,
    pub cell: Vec<(i32, i32)>,
    /// Per motif position: class and origin (the least-squares position of cell (0, 0)).
    pub motifs: Vec<(u32, Point)>,
}

struct Index<'a> {
    elems: &'a [Element],
    grid: &'a Grid,
    /// The example's convex hull, counter-clockwise (y down: clockwise on screen).
    hull: Vec<Point>,
    tolerance: f64,
    reach: f64,
}

impl Index<'_> {
    /// The same-class element nearest `p`, within the tolerance.
    fn partner(&self, i: usize, v: Vec2) -> Option<usize> {
        let e = &self.elems[i];
        let p = e.pos + v;
        let mut best: Option<(usize, f64)> = None;
        let t2 = self.tolerance * self.tolerance;
        self.grid.for_each_near(p, self.tolerance, |j| {
            let o = &self.elems[j as usize];
            let d2 = (o.pos - p).hypot2();
            if o.class == e.class && d2 <= t2 && best.is_none_or(|b| d2 < b.1) {
                best = Some((j as usize, d2));
            }
        });
        best.map(|b| b.0)
    }

    /// Where `p` lies: `None` outside the example, `Some(true)` inside it (within its
    /// hull by the tolerance and near some element), `Some(false)` on its edge (within
    /// the tolerance of the hull's outline).
    fn inside(&self, p: Point) -> Option<bool> {
        let hull = &self.hull;
        let mut clear = true;
        for k in 0..hull.len() {
            let (p0, p1) = (hull[k], hull[(k + 1) % hull.len()]);
            let e = p1 - p0;
            let d = e.cross(p - p0);
            if d < -self.tolerance * e.hypot() {
                return None;
            }
            clear &= d >= self.tolerance * e.hypot();
        }
        let mut near = false;
        let r2 = self.reach * self.reach;
        self.grid.for_each_near(p, self.reach, |j| near |= (self.elems[j as usize].pos - p).hypot2() <= r2);
        near.then_some(clear)
    }

    /// Whether `v` maps the elements `set` onto same-class elements, all but a few of
    /// those whose image is inside; stops at the first few misses. `overlap`: the image
    /// must also cover a quarter of the example (a search candidate, not a check).
    fn supports(&self, v: Vec2, set: &[usize], overlap: bool) -> bool {
        let (mut inside, mut misses) = (0usize, 0usize);
        for &i in set {
            let Some(clear) = self.inside(self.elems[i].pos + v) else { continue };
            let hit = self.partner(i, v).is_some();
            // An image on the example's edge counts only when it lands on something: a
            // tile cut at its edge has pieces there (the left half of a shape whose right
            // half is on the far side) whose images one period on have nothing to meet.
            if !clear && !hit {
                continue;
            }
            inside += 1;
            if !hit {
                misses += 1;
                if misses as f64 > 2.0 + (1.0 - FULL_SUPPORT) * set.len() as f64 {
                    return false;
                }
            }
        }
        // The image must overlap a fair part of the example, not a corner of it.
        (if overlap { inside * 4 >= set.len() } else { inside > 0 })
            && (misses as f64) <= (1.0 - FULL_SUPPORT) * inside as f64 + 1.0
    }
}

/// Finds the two periods of `elems` (indexed by `grid`, `spacing` apart: the median
/// distance between neighbours), or `None` when the example is not periodic in two
/// directions (a single copy, a row, irregular or too jittery input).
pub fn find(elems: &[Element], grid: &Grid, spacing: f64) -> Option<Periods> {
    let n = elems.len();
    if n < 4 || !(spacing > 0.0 && spacing.is_finite()) {
        return None;
    }
    let bounds = elems.iter().fold(Rect::from_points(elems[0].pos, elems[0].pos), |r, e| r.union_pt(e.pos));
    // (Elements along an arc are all on their hull: 200 hatching lines made a hull of
    // 200 edges, each element's image tested against every one.)
    let hull = simplify(convex_hull(elems.iter().map(|e| e.pos).collect()), 0.25 * TOLERANCE * spacing);
    if hull.len() < 3 {
        return None;
    }
    let index = Index { elems, grid, hull, tolerance: TOLERANCE * spacing, reach: 1.5 * spacing };

    // Candidates: displacements from a few central members of the rarest classes (with
    // at least two members) to all their members, one per half-plane, shortest first.
    // One class would do if classes were exact; three tolerate a misclassified copy.
    let classes = elems.iter().map(|e| e.class).max()? as usize + 1;
    let mut members = vec![Vec::new(); classes];
    for (i, e) in elems.iter().enumerate() {
        members[e.class as usize].push(i);
    }
    let rare: Vec<&Vec<usize>> = members.iter().filter(|m| m.len() >= 2).collect();
    let mut rare = order::sorted(&rare, |m| m.len() as f64);
    rare.truncate(3);
    if rare.is_empty() {
        return None;
    }
    let centre = bounds.center();
    let quantum = index.tolerance.max(1e-12);
    let mut seen = HashSet::new();
    let mut candidates: Vec<Vec2> = Vec::new();
    for class in rare {
        let mut anchors = order::sorted(class, |&i| (elems[i].pos - centre).hypot2());
        anchors.truncate(ANCHORS);
        for &i in &anchors {
            for &j in class {
                let mut v = elems[j].pos - elems[i].pos;
                if v.x < 0.0 || (v.x == 0.0 && v.y < 0.0) {
                    v = -v;
                }
                if v.hypot() <= 2.0 * index.tolerance {
                    continue;
                }
                if seen.insert(((v.x / quantum).round() as i64, (v.y / quantum).round() as i64)) {
                    candidates.push(v);
                }
            }
        }
    }
    let mut candidates = order::sorted(&candidates, |v| v.hypot2());
    // A period is among the shortest displacements of its rarest classes (the test
    // corpora find theirs within the first 1,800); an irregular scatter of 50,000
    // strokes made 300,000 candidates, each tried on 400 elements (4.8 s natively).
    candidates.truncate(MAX_CANDIDATES);

    let step = n.div_ceil(SAMPLE).max(1);
    let sample: Vec<usize> = (0..n).step_by(step).collect();
    let probe: Vec<usize> = (0..n).step_by(n.div_ceil(PROBE).max(1)).collect();
    let all: Vec<usize> = (0..n).collect();
    let is_period = |v: Vec2| {
        (n < 2 * PROBE || index.supports(v, &probe, true))
            && index.supports(v, &sample, true)
            && index.supports(v, &all, true)
    };
    // Each period as the mean of its instances rather than one displacement: with a
    // hand's jitter, one pair is off by up to twice the jitter, and sums of periods
    // (checked below) add the errors.
    let mean = |v: Vec2| {
        let (sum, count) = all.iter().fold((Vec2::ZERO, 0usize), |(s, c), &i| match index.partner(i, v) {
            Some(j) => (s + (elems[j].pos - elems[i].pos), c + 1),
            None => (s, c),
        });
        if count > 0 {
            sum / count as f64
        } else {
            v
        }
    };
    let a = mean(*candidates.iter().find(|&&v| is_period(v))?);
    // The reduced basis must not be shorter than a candidate may be: two periods nearly
    // parallel within the tolerance reduce to a sliver that maps every element onto itself.
    let long = |(a, b): (Vec2, Vec2)| a.hypot().min(b.hypot()) > 2.0 * index.tolerance;
    let b = *candidates
        .iter()
        .find(|&&v| a.cross(v).abs() > 0.1 * a.hypot() * v.hypot() && long(reduce(a, v)) && is_period(v))?;
    let (a, b) = reduce(a, mean(b));
    // The reduced basis and its sums hold wherever the example overlaps its image.
    if ![a, b, a + b, a - b].iter().all(|&v| index.supports(v, &all, false)) {
        return None;
    }
    motifs(&index, a, b)
}

/// The periods that best explain the drawn positions, given each element's motif and
/// cell: minimises the squared distances of `pos = origin(motif) + k a + l b` (the
/// origins eliminated by centring each motif), so jitter averages out instead of the
/// one displacement the search found setting the period (which would drift).
fn least_squares(elems: &[Element], motif: &[u32], cell: &[(i32, i32)], motifs: usize) -> Option<(Vec2, Vec2)> {
    let mut mean = vec![(0.0, 0.0, Vec2::ZERO, 0.0); motifs];
    for (i, e) in elems.iter().enumerate() {
        let m = &mut mean[motif[i] as usize];
        m.0 += cell[i].0 as f64;
        m.1 += cell[i].1 as f64;
        m.2 += e.pos.to_vec2();
        m.3 += 1.0;
    }
    let (mut uu, mut uv, mut vv, mut uy, mut vy) = (0.0, 0.0, 0.0, Vec2::ZERO, Vec2::ZERO);
    for (i, e) in elems.iter().enumerate() {
        let m = &mean[motif[i] as usize];
        let (u, v) = (cell[i].0 as f64 - m.0 / m.3, cell[i].1 as f64 - m.1 / m.3);
        let y = e.pos.to_vec2() - m.2 / m.3;
        (uu, uv, vv) = (uu + u * u, uv + u * v, vv + v * v);
        uy += y * u;
        vy += y * v;
    }
    let det = uu * vv - uv * uv;
    if det.is_nan() || det.abs() <= 1e-9 * (uu * vv).max(1e-300) {
        return None;
    }
    Some(((uy * vv - vy * uv) / det, (vy * uu - uy * uv) / det))
}

/// The convex hull of `points` (Andrew's monotone chain), with positive turns.
fn convex_hull(points: Vec<Point>) -> Vec<Point> {
    // By x, then y (the sort keeps the order of ties).
    let mut points = order::sorted(&order::sorted(&points, |p| p.y), |p| p.x);
    points.dedup();
    if points.len() < 3 {
        return points;
    }
    let turn = |o: Point, a: Point, b: Point| (a - o).cross(b - o);
    let mut hull: Vec<Point> = Vec::with_capacity(2 * points.len());
    for pass in 0..2 {
        let start = hull.len();
        for k in 0..points.len() {
            let p = if pass == 0 { points[k] } else { points[points.len() - 1 - k] };
            while hull.len() >= start + 2 && turn(hull[hull.len() - 2], hull[hull.len() - 1], p) <= 0.0 {
                hull.pop();
            }
            hull.push(p);
        }
        hull.pop();
    }
    hull
}

/// A convex hull with the vertices dropped that lie within `within` of the chord of
/// their neighbours, the nearest first (down to a triangle): the polygon shrinks by at
/// most `within`, a quarter of the tolerance its edges are tested with.
fn simplify(mut hull: Vec<Point>, within: f64) -> Vec<Point> {
    while hull.len() > 3 {
        let n = hull.len();
        let height = |k: usize| {
            let (a, b, c) = (hull[(k + n - 1) % n], hull[k], hull[(k + 1) % n]);
            let e = c - a;
            e.cross(b - a).abs() / e.hypot().max(1e-12)
        };
        let Some((k, h)) = (0..n).map(|k| (k, height(k))).min_by(|x, y| x.1.total_cmp(&y.1)) else { break };
        if h >= within {
            break;
        }
        hull.remove(k);
    }
    hull
}

/// Lagrange-Gauss reduction: the shortest basis of the lattice `a`, `b` spans.
fn reduce(mut a: Vec2, mut b: Vec2) -> (Vec2, Vec2) {
    if a.hypot2() > b.hypot2() {
        std::mem::swap(&mut a, &mut b);
    }
    for _ in 0..64 {
        let m = (a.dot(b) / a.hypot2()).round();
        if m == 0.0 {
            break;
        }
        b -= a * m;
        if b.hypot2() >= a.hypot2() {
            break;
        }
        std::mem::swap(&mut a, &mut b);
    }
    (a, b)
}

/// Groups elements into motif positions (joined by the periods), gives each element its
/// cell, and each motif its least-squares origin; motifs that land on one another
/// modulo the lattice (a partner missed by jitter) are merged.
fn motifs(index: &Index, a: Vec2, b: Vec2) -> Option<Periods> {
    let elems = index.elems;
    let n = elems.len();
    let steps = [(a, (1, 0)), (-a, (-1, 0)), (b, (0, 1)), (-b, (0, -1))];
    let mut cell: Vec<Option<(i32, i32)>> = vec![None; n];
    let mut motif = vec![u32::MAX; n];
    let mut roots = Vec::new();
    for root in 0..n {
        if cell[root].is_some() {
            continue;
        }
        let m = roots.len() as u32;
        roots.push(root);
        cell[root] = Some((0, 0));
        motif[root] = m;
        let mut stack = vec![root];
        while let Some(i) = stack.pop() {
            let (k, l) = cell[i]?;
            for (v, (dk, dl)) in steps {
                if let Some(j) = index.partner(i, v) {
                    if cell[j].is_none() {
                        cell[j] = Some((k + dk, l + dl));
                        motif[j] = m;
                        stack.push(j);
                    }
                }
            }
        }
    }
    let cell: Vec<(i32, i32)> = cell.into_iter().collect::<Option<_>>()?;
    // The fit refines the found periods by a fraction of the tolerance; a fit far from
    // them means a chain of partners skipped a cell (jitter near the tolerance), and
    // the periods found stand.
    let (a, b) = match least_squares(elems, &motif, &cell, roots.len()) {
        Some((fa, fb)) if (fa - a).hypot() <= index.tolerance && (fb - b).hypot() <= index.tolerance => (fa, fb),
        _ => (a, b),
    };
    let origin_of = |i: usize| elems[i].pos - a * cell[i].0 as f64 - b * cell[i].1 as f64;
    let mut sums = vec![(Vec2::ZERO, 0usize); roots.len()];
    for i in 0..n {
        let s = &mut sums[motif[i] as usize];
        s.0 += origin_of(i).to_vec2();
        s.1 += 1;
    }
    let mut motifs: Vec<(u32, Point)> =
        roots.iter().zip(&sums).map(|(&r, s)| (elems[r].class, (s.0 / s.1 as f64).to_point())).collect();

    // Merge motif positions that coincide modulo the lattice.
    let det = a.cross(b);
    let to_lattice = |v: Vec2| (v.cross(b) / det, a.cross(v) / det);
    let mut merged: Vec<u32> = (0..motifs.len() as u32).collect();
    if motifs.len() <= 4000 {
        for x in 0..motifs.len() {
            if merged[x] != x as u32 {
                continue;
            }
            for y in x + 1..motifs.len() {
                if merged[y] != y as u32 || motifs[x].0 != motifs[y].0 {
                    continue;
                }
                let d = motifs[y].1 - motifs[x].1;
                let (s, t) = to_lattice(d);
                let (ks, kt) = (s.round(), t.round());
                if (d - a * ks - b * kt).hypot() <= index.tolerance {
                    merged[y] = x as u32;
                }
            }
        }
    }
    // Renumber (a merged motif's members join the one it lands on), and recompute each
    // element's cell from its position.
    let mut renumber = vec![u32::MAX; motifs.len()];
    let mut kept = Vec::new();
    for (x, m) in motifs.drain(..).enumerate() {
        if merged[x] == x as u32 {
            renumber[x] = kept.len() as u32;
            kept.push(m);
        }
    }
    let mut cells = cell;
    for i in 0..n {
        let m = renumber[merged[motif[i] as usize] as usize] as usize;
        motif[i] = m as u32;
        let (s, t) = to_lattice(elems[i].pos - kept[m].1);
        cells[i] = (s.round() as i32, t.round() as i32);
    }
    Some(Periods { a, b, motif, cell: cells, motifs: kept })
}

/// The periodic extension of the example over `area`: every motif position at every
/// lattice translate whose drawing (`extents`: half sizes per element, or none) reaches
/// into the area, the example block centred as growth centres it. Refuses above
/// `max_elements`; reports progress per motif position.
pub fn extend(
    elems: &[Element],
    extents: &[Vec2],
    p: &Periods,
    area: Rect,
    max_elements: usize,
    progress: &mut Throttle,
) -> Result<Vec<Placed>> {
    let det = p.a.cross(p.b).abs();
    let estimate = p.motifs.len() as f64 * area.area() / det;
    if estimate.is_nan() || estimate > max_elements as f64 {
        return Err(Error::TooLarge(format!(
            "This output would hold about {estimate:.0} elements; the limit is {max_elements}. Use a smaller output or larger strokes."
        )));
    }
    let bounds = elems.iter().fold(Rect::from_points(elems[0].pos, elems[0].pos), |r, e| r.union_pt(e.pos));
    let shift = area.center() - bounds.center();
    let (kmin, kmax) = p.cell.iter().fold((i32::MAX, i32::MIN), |(lo, hi), c| (lo.min(c.0), hi.max(c.0)));
    let (lmin, lmax) = p.cell.iter().fold((i32::MAX, i32::MIN), |(lo, hi), c| (lo.min(c.1), hi.max(c.1)));
    let (kn, ln) = (kmax - kmin + 1, lmax - lmin + 1);
    let mut members = vec![Vec::new(); p.motifs.len()];
    // The member in each cell (the first, as the scan below would take it): most sites
    // find theirs here, not by a scan of every member (50,000 examples x 450,000 sites).
    let mut at_cell: HashMap<(u32, (i32, i32)), usize> = HashMap::with_capacity(p.motif.len());
    for (i, &m) in p.motif.iter().enumerate() {
        members[m as usize].push(i);
        at_cell.entry((m, p.cell[i])).or_insert(i);
    }
    let sdet = p.a.cross(p.b);
    let to_lattice = |v: Vec2| (v.cross(p.b) / sdet, p.a.cross(v) / sdet);
    let half = |i: usize| extents.get(i).copied().unwrap_or(Vec2::ZERO);
    // Lattice ranges over the area grown by the largest drawing.
    let reach = (0..elems.len()).map(half).fold(Vec2::ZERO, |m, h| Vec2::new(m.x.max(h.x), m.y.max(h.y)));
    let wide = area.inset((reach.x, reach.y));
    let corners =
        [wide.origin(), Point::new(wide.x1, wide.y0), Point::new(wide.x0, wide.y1), Point::new(wide.x1, wide.y1)];
    let mut out = Vec::with_capacity(estimate as usize + 16);
    for (m, &(class, origin)) in p.motifs.iter().enumerate() {
        progress.tick(m as f64 / p.motifs.len() as f64)?;
        let o = origin + shift;
        let (mut s0, mut s1, mut t0, mut t1) = (f64::INFINITY, f64::NEG_INFINITY, f64::INFINITY, f64::NEG_INFINITY);
        for c in corners {
            let (s, t) = to_lattice(c - o);
            (s0, s1, t0, t1) = (s0.min(s), s1.max(s), t0.min(t), t1.max(t));
        }
        let (l0, l1) = (t0.floor() as i32, t1.ceil() as i32);
        for l in l0..=l1 {
            // Per row of the lattice too: one motif position may be the whole output.
            progress.tick((m as f64 + (l - l0) as f64 / (l1 - l0 + 1) as f64) / p.motifs.len() as f64)?;
            for k in s0.floor() as i32..=s1.ceil() as i32 {
                let ideal = o + p.a * k as f64 + p.b * l as f64;
                if !wide.contains(ideal) {
                    continue;
                }
                // The example element at the same place in the example's block.
                let want = (kmin + (k - kmin).rem_euclid(kn), lmin + (l - lmin).rem_euclid(ln));
                let source = match at_cell.get(&(m as u32, want)) {
                    Some(&i) => i,
                    None => *members[m]
                        .iter()
                        .min_by_key(|&&i| (p.cell[i].0 - want.0).abs() + (p.cell[i].1 - want.1).abs())
                        .expect("a motif position has members"),
                };
                let c = p.cell[source];
                let deviation = elems[source].pos - (origin + p.a * c.0 as f64 + p.b * c.1 as f64);
                let pos = ideal + deviation;
                let h = half(source);
                if pos.x + h.x < area.x0 || pos.x - h.x > area.x1 || pos.y + h.y < area.y0 || pos.y - h.y > area.y1 {
                    continue;
                }
                out.push(Placed { pos, class, source: source as u32 });
            }
        }
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The periods of `elems` as growth finds them (its grid and spacing).
    fn find(elems: &[Element]) -> Option<Periods> {
        crate::vector::grow::find_periods(elems).unwrap()
    }

    /// A tile of `motif` elements (positions in the unit cell, classes) repeated nx x ny.
    fn repeat(motif: &[(f64, f64, u32)], a: Vec2, b: Vec2, nx: i32, ny: i32) -> Vec<Element> {
        let mut v = Vec::new();
        for j in 0..ny {
            for i in 0..nx {
                for &(x, y, class) in motif {
                    v.push(Element { pos: Point::new(x, y) + a * i as f64 + b * j as f64, class });
                }
            }
        }
        v
    }

    #[test]
    fn finds_long_periods_of_busy_irregular_tiles() {
        // 30 scattered elements of 3 classes in a 100 x 80 tile: neighbours are ~15
        // apart, the period is 100.
        let mut r = crate::rng::Rng::new(5);
        let motif: Vec<(f64, f64, u32)> =
            (0..30).map(|i| (r.next_f64() * 100.0, r.next_f64() * 80.0, (i % 3) as u32)).collect();
        let (a, b) = (Vec2::new(100.0, 0.0), Vec2::new(0.0, 80.0));
        let elems = repeat(&motif, a, b, 3, 3);
        let p = find(&elems).expect("periodic");
        let mut got = [p.a, p.b];
        got.sort_by(|x, y| x.x.abs().total_cmp(&y.x.abs()));
        assert!((got[0].x.abs() < 1e-6 && (got[0].y.abs() - 80.0).abs() < 1e-6), "{got:?}");
        assert!(((got[1].x.abs() - 100.0).abs() < 1e-6 && got[1].y.abs() < 1e-6), "{got:?}");
        assert_eq!(p.motifs.len(), 30);
        let mut silent = crate::Silent;
        let out =
            extend(&elems, &[], &p, Rect::new(0.0, 0.0, 1000.0, 800.0), 1_000_000, &mut Throttle::new(&mut silent))
                .unwrap();
        // 10 x 10 periods of 30 elements, give or take those on the border.
        assert!((out.len() as i64 - 3000).abs() <= 60, "{}", out.len());
        // Every placed element sits on its motif's lattice, one per site.
        let mut sites = HashSet::new();
        for e in &out {
            assert!(sites.insert(((e.pos.x * 1e3).round() as i64, (e.pos.y * 1e3).round() as i64, e.class)), "stacked");
        }
    }

    #[test]
    fn oblique_lattices_reduce_and_rows_are_not_lattices() {
        let (a, b) = (Vec2::new(30.0, 0.0), Vec2::new(15.0, 26.0));
        let elems = repeat(&[(0.0, 0.0, 0), (10.0, 5.0, 1)], a, b, 4, 4);
        let p = find(&elems).expect("periodic");
        assert!((p.a.hypot() - 30.0).abs() < 1e-6 && (p.b.hypot() - 30.0).abs() < 0.1, "{:?} {:?}", p.a, p.b);
        let row = repeat(&[(0.0, 0.0, 0), (10.0, 5.0, 1)], a, Vec2::new(0.0, 1e3), 8, 1);
        assert!(find(&row).is_none());
    }

    #[test]
    fn irregular_input_has_no_periods() {
        let mut r = crate::rng::Rng::new(9);
        let elems: Vec<Element> = (0..200)
            .map(|i| Element { pos: Point::new(r.next_f64() * 500.0, r.next_f64() * 500.0), class: i % 2 })
            .collect();
        assert!(find(&elems).is_none());
    }
}
