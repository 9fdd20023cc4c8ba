//! How close a synthesized pattern is to the ideal periodic extension of its example:
//! coverage of ideal sites, strays, stacked duplicates and residual distance, all
//! relative to the lattice spacing. Used by the tests and the benchmark.

use super::exemplar::Lattice;
use kurbo::{Point, Rect};
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
}

/// Measures `output` (position, generator class) against `lattice` moved by `shift`
/// (where synthesis placed the example), over `area`. Elements count as on a site
/// within 0.3 spacings.
pub fn measure(lattice: &Lattice, shift: kurbo::Vec2, output: &[(Point, u32)], area: Rect) -> Regularity {
    let spacing = lattice.spacing();
    let tol = 0.3 * spacing;
    let mut lat = lattice.clone();
    lat.origin += shift;
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
    for (k, &(p, _)) in all.iter().enumerate() {
        let (cx, cy) = index(p);
        grid[cy * cols + cx].push(k);
    }
    let mut hits = vec![0usize; all.len()];
    let mut residuals = Vec::new();
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
            }
            None => stray += 1,
        }
    }
    let margin = 0.1 * spacing;
    let inner = area.inset(-margin);
    let inside: Vec<usize> = (0..all.len()).filter(|&k| inner.contains(all[k].0)).collect();
    let covered = inside.iter().filter(|&&k| hits[k] > 0).count();
    let stacked = hits.iter().map(|&h| h.saturating_sub(1)).sum();
    residuals.sort_by(|a, b| a.total_cmp(b));
    let pct =
        |q: f64| residuals.get(((residuals.len() as f64 - 1.0) * q).round() as usize).copied().unwrap_or(f64::NAN);
    Regularity {
        sites: inside.len(),
        coverage: if inside.is_empty() { 1.0 } else { covered as f64 / inside.len() as f64 },
        stray,
        stacked,
        median_residual: pct(0.5),
        p95_residual: pct(0.95),
    }
}
