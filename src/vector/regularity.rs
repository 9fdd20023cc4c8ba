//! How close a synthesized pattern is to the ideal periodic extension of its example:
//! coverage of ideal sites, strays, stacked duplicates and residual distance, all
//! relative to the lattice spacing. Used by the tests and the benchmark.
//!
//! A jittered example defines its period only up to its jitter: the mean step between
//! its copies differs from the generator's by about sigma / sqrt(n). Growth repeats that
//! step, so a large output is regular with a period off by a fraction of a percent; read
//! against the generator's lattice, that shows as a drift growing with the distance from
//! the centre. `measure` therefore fits the lattice (origin and both period vectors) to
//! the output, centre outward, and reads residuals against the fit; `period_error` says
//! how far the fitted period is from the generator's, and exact examples (real tiles)
//! must show none.

use super::exemplar::Lattice;
use kurbo::{Point, Rect, Vec2};
use serde::Serialize;

#[derive(Clone, Debug, Serialize)]
pub struct Regularity {
    /// Ideal sites inside the area (a small margin in from its edges).
    pub sites: usize,
    /// Fraction of those with an output element of their class nearby.
    pub coverage: f64,
    /// Output elements near no ideal site of their class.
    pub stray: usize,
    /// Output elements beyond the first at one ideal site.
    pub stacked: usize,
    /// Median distance from an output element to its site, over the spacing.
    pub median_residual: f64,
    /// 95th percentile of the same.
    pub p95_residual: f64,
    /// Largest relative difference between the fitted and the generator's period vectors.
    pub period_error: f64,
}

/// Measures `output` (position, generator class) against `lattice` moved by `shift`
/// (where synthesis placed the example), over `area`. Elements count as on a site
/// within 0.3 spacings.
pub fn measure(lattice: &Lattice, shift: Vec2, output: &[(Point, u32)], area: Rect) -> Regularity {
    measure_at(lattice, lattice.spacing(), shift, output, area)
}

/// `measure` on the scale `spacing` instead of the lattice's smallest distance between
/// sites: for motifs whose parts lie close together (the walls and door of a house), the
/// period is the scale a person sees, and parts are told apart by class.
pub fn measure_at(lattice: &Lattice, spacing: f64, shift: Vec2, output: &[(Point, u32)], area: Rect) -> Regularity {
    let mut lat = lattice.clone();
    lat.origin += shift;
    let centre = area.center();
    // Fit centre outward, so that a slightly different period is followed, not lost.
    for reach in [6.0, 12.0, 24.0, 48.0, 96.0, f64::INFINITY] {
        let near: Vec<(Point, u32)> =
            output.iter().copied().filter(|(p, _)| p.distance(centre) <= reach * spacing).collect();
        let (_, matches) = assign(&lat, spacing, &near, area);
        if let Some(fit) = fit(&lat, &matches) {
            lat = fit;
        }
    }
    let (r, _) = assign(&lat, spacing, output, area);
    let rel = |v: Vec2, w: Vec2| (v - w).hypot() / w.hypot();
    let period_error = rel(lat.a, lattice.a).max(match (lat.b, lattice.b) {
        (Some(v), Some(w)) => rel(v, w),
        _ => 0.0,
    });
    Regularity { period_error, ..r }
}

/// Solves the least-squares fit of origin and period vectors to matched elements
/// (position, cell i, cell j, motif offset).
fn fit(lat: &Lattice, matches: &[(Point, i64, i64, Vec2)]) -> Option<Lattice> {
    let two_d = lat.b.is_some();
    let n = if two_d { 3 } else { 2 };
    if matches.len() < 2 * n {
        return None;
    }
    // Normal equations, shared by x and y: rows [1, i, j].
    let mut m = [[0.0f64; 3]; 3];
    let (mut rx, mut ry) = ([0.0f64; 3], [0.0f64; 3]);
    for &(p, i, j, off) in matches {
        let row = [1.0, i as f64, j as f64];
        for u in 0..n {
            for v in 0..n {
                m[u][v] += row[u] * row[v];
            }
            rx[u] += row[u] * (p.x - off.x);
            ry[u] += row[u] * (p.y - off.y);
        }
    }
    let sx = solve(&m, &rx, n)?;
    let sy = solve(&m, &ry, n)?;
    Some(Lattice {
        origin: Point::new(sx[0], sy[0]),
        a: Vec2::new(sx[1], sy[1]),
        b: two_d.then(|| Vec2::new(sx[2], sy[2])),
        motif: lat.motif.clone(),
    })
}

/// Gaussian elimination on the leading `n x n` block.
#[allow(clippy::needless_range_loop)] // index form mirrors the algebra
fn solve(m: &[[f64; 3]; 3], r: &[f64; 3], n: usize) -> Option<[f64; 3]> {
    let mut a = *m;
    let mut b = *r;
    for c in 0..n {
        let p = (c..n).max_by(|&x, &y| a[x][c].abs().total_cmp(&a[y][c].abs()))?;
        if a[p][c].abs() < 1e-12 {
            return None;
        }
        a.swap(c, p);
        b.swap(c, p);
        for row in 0..n {
            if row != c {
                let f = a[row][c] / a[c][c];
                for k in c..n {
                    a[row][k] -= f * a[c][k];
                }
                b[row] -= f * b[c];
            }
        }
    }
    let mut x = [0.0; 3];
    for c in 0..n {
        x[c] = b[c] / a[c][c];
    }
    Some(x)
}

/// Matches each output element to the nearest same-class site of `lat` and counts.
fn assign(
    lat: &Lattice,
    spacing: f64,
    output: &[(Point, u32)],
    area: Rect,
) -> (Regularity, Vec<(Point, i64, i64, Vec2)>) {
    let tol = 0.3 * spacing;
    let all = lat.sites_in(area.x0 - spacing, area.y0 - spacing, area.x1 + spacing, area.y1 + spacing);
    // Nearest same-class site of each output element, by brute force over a coarse grid.
    let cell = spacing.max(1e-9);
    let cols = ((area.width() + 2.0 * spacing) / cell).ceil() as usize + 1;
    let rows = ((area.height() + 2.0 * spacing) / cell).ceil() as usize + 1;
    let mut grid = vec![Vec::new(); cols * rows];
    let index = |p: Point| {
        let cx = (((p.x - area.x0 + spacing) / cell).floor().max(0.0) as usize).min(cols - 1);
        let cy = (((p.y - area.y0 + spacing) / cell).floor().max(0.0) as usize).min(rows - 1);
        (cx, cy)
    };
    for (k, site) in all.iter().enumerate() {
        let p = site.0;
        let (cx, cy) = index(p);
        grid[cy * cols + cx].push(k);
    }
    let mut hits = vec![0usize; all.len()];
    let mut residuals = Vec::new();
    let mut matches = Vec::new();
    let mut stray = 0;
    for &(p, c) in output {
        let (cx, cy) = index(p);
        let mut best: Option<(usize, f64)> = None;
        for y in cy.saturating_sub(1)..=(cy + 1).min(rows - 1) {
            for x in cx.saturating_sub(1)..=(cx + 1).min(cols - 1) {
                for &k in &grid[y * cols + x] {
                    let d = all[k].0.distance(p);
                    if all[k].1 == c && d < tol && best.is_none_or(|b| d < b.1) {
                        best = Some((k, d));
                    }
                }
            }
        }
        match best {
            Some((k, d)) => {
                hits[k] += 1;
                residuals.push(d / spacing);
                matches.push((p, all[k].2, all[k].3, all[k].4));
            }
            None => stray += 1,
        }
    }
    let margin = 0.1 * spacing;
    let inner = area.inset(-margin);
    let inside: Vec<usize> = (0..all.len()).filter(|&k| inner.contains(all[k].0)).collect();
    let covered = inside.iter().filter(|&&k| hits[k] > 0).count();
    let stacked = hits.iter().map(|&h| h.saturating_sub(1)).sum();
    crate::order::floats(&mut residuals);
    let pct =
        |q: f64| residuals.get(((residuals.len() as f64 - 1.0) * q).round() as usize).copied().unwrap_or(f64::NAN);
    let r = Regularity {
        sites: inside.len(),
        coverage: if inside.is_empty() { 1.0 } else { covered as f64 / inside.len() as f64 },
        stray,
        stacked,
        median_residual: pct(0.5),
        p95_residual: pct(0.95),
        period_error: 0.0,
    };
    (r, matches)
}
