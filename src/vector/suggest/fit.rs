//! The lattice that explains the drawing: its periods tried and kept, its motif
//! positions, and the cells each stroke falls in.

use super::certainty::Certainty;
use super::lattice::{candidates, refine, rows_drawn, shear, square, Lattice, Residues};
use super::TOLERANCE;
use crate::vector::element::Element;
use crate::vector::reference::Spread;
use crate::vector::spatial::Grid;
use kurbo::{Point, Vec2};

/// Candidate periods evaluated in full, shortest first.
const MAX_TRIED: usize = 48;
/// Periods that fit as a row on which a lattice is tried.
const ROW_CHOICES: usize = 3;
/// Share of the strokes that must sit at a motif position drawn at least twice.
const EXPLAINED: f64 = 0.7;
/// Median distance of strokes from their lattice sites, as a fraction of the spacing.
const MAX_RESIDUAL: f64 = 0.2;

/// A motif position: its class, its site in cell (0, 0) and the strokes drawn there.
#[derive(Clone, Debug)]
pub(super) struct MotifPosition {
    class: u32,
    origin: Point,
    pub(super) members: Vec<usize>,
}

/// A lattice that explains the drawing.
#[derive(Clone, Debug)]
pub(super) struct Fit {
    pub(super) a: Vec2,
    pub(super) b: Option<Vec2>,
    pub(super) motif: Vec<MotifPosition>,
    /// Motif position and cell of each stroke.
    pub(super) cell: Vec<(usize, (i64, i64))>,
    /// Share of the strokes explained, less their residual.
    pub(super) quality: f64,
    /// How far off the lattice may be in a cell: see `Fit::error_at`.
    pub(super) certainty: Certainty,
}

impl Fit {
    /// The best lattice of `elems`, or `None` when no candidate explains them.
    ///
    /// A lattice is tried on each of the first few periods that fit as a row, and the
    /// one with the fewest motif positions wins (the finest lattice the drawing does not
    /// contradict): a period that joins one part of a copy to another part of the next
    /// (the diagonal from a pair's left stroke to the right stroke of the pair above)
    /// also fits, but on a coarser lattice that needs twice the positions.
    pub(super) fn find(elems: &[Element], weight: &[f64], parts: &[usize], spread: &Spread) -> Option<Fit> {
        let tol = TOLERANCE * spread.spacing;
        let candidates = candidates(elems, parts, spread, tol);
        let row = candidates
            .iter()
            .take(MAX_TRIED)
            .find_map(|&a| Fit::build(elems, weight, parts, spread, tol, a, None, true));
        // A lattice filled in out of order leaves cells out of its rows, which no row
        // explains: its first periods are then those that fit as a row with a few left out.
        let firsts = candidates
            .iter()
            .take(MAX_TRIED)
            .filter_map(|&a| Fit::build(elems, weight, parts, spread, tol, a, None, false))
            .map(|r| r.a)
            .take(ROW_CHOICES);
        let mut best: Option<Fit> = None;
        for a in firsts {
            let lattice = candidates
                .iter()
                .filter(|v| a.cross(**v).abs() > 0.3 * a.hypot() * v.hypot())
                .take(MAX_TRIED)
                .find_map(|&b| Fit::build(elems, weight, parts, spread, tol, a, Some(b), true));
            if let Some(f) = lattice {
                let rank = |f: &Fit| (f.sparse(), f.motif.len(), -f.quality);
                if best.as_ref().is_none_or(|b| rank(&f) < rank(b)) {
                    best = Some(f);
                }
            }
        }
        best.map(|f| f.along_rows_drawn(elems, tol)).or(row)
    }

    /// The same lattice on the basis whose rows of cells are the rows the hand drew (see
    /// `rows_drawn`), each stroke's cell counted on it.
    fn along_rows_drawn(self, elems: &[Element], tol: f64) -> Fit {
        let Some(b) = self.b else { return self };
        // (How often the hand went from one copy to the next of its kind by `v`, either
        // way: a step from one part of a motif to another is no period.)
        let steps_along = |v: Vec2| {
            let by = |d: Vec2| (d - v).hypot() < tol || (d + v).hypot() < tol;
            elems.windows(2).filter(|w| w[0].class == w[1].class && by(w[1].pos - w[0].pos)).count()
        };
        let Some([[i, j], [k, l]]) = rows_drawn(self.a, b, steps_along) else { return self };
        // `u a + w b = u' a' + w' b'`: `(u', w') = (u, w) M^-1`, `M^-1 = [[l, -j], [-k, i]] / det`.
        let det = i * l - j * k;
        let cell = self.cell.iter().map(|&(m, (u, w))| (m, ((u * l - w * k) * det, (w * i - u * j) * det))).collect();
        let (a, b) = (self.a * i as f64 + b * j as f64, self.a * k as f64 + b * l as f64);
        Fit { a, b: Some(b), cell, ..self }
    }

    /// The lattice of periods `a` (and `b`) over `elems`, if it explains them (without
    /// `strict`, a row may leave a third of its cells out).
    #[allow(clippy::too_many_arguments)]
    fn build(
        elems: &[Element],
        weight: &[f64],
        parts: &[usize],
        spread: &Spread,
        tol: f64,
        a: Vec2,
        b: Option<Vec2>,
        strict: bool,
    ) -> Option<Fit> {
        let n = elems.len();
        let partner = |i: usize, v: Vec2| -> Option<usize> {
            let p = elems[i].pos + v;
            let mut best: Option<(usize, f64)> = None;
            spread.grid.for_each_near(p, tol, |j| {
                let o = &elems[j as usize];
                let d2 = (o.pos - p).hypot2();
                if o.class == elems[i].class && d2 < tol * tol && best.is_none_or(|b| d2 < b.1) {
                    best = Some((j as usize, d2));
                }
            });
            best.map(|b| b.0)
        };
        let steps: Vec<(Vec2, i64, i64)> =
            [(a, 1, 0), (-a, -1, 0)].into_iter().chain(b.into_iter().flat_map(|b| [(b, 0, 1), (-b, 0, -1)])).collect();
        // Components reached by whole periods, each with lattice coordinates.
        let mut coord: Vec<Option<(usize, i64, i64)>> = vec![None; n];
        let mut components = 0;
        for root in 0..n {
            if coord[root].is_some() {
                continue;
            }
            coord[root] = Some((components, 0, 0));
            let mut stack = vec![root];
            while let Some(i) = stack.pop() {
                let (c, u, w) = coord[i].expect("set before pushed");
                for &(v, du, dw) in &steps {
                    if let Some(j) = partner(i, v) {
                        match coord[j] {
                            None => {
                                coord[j] = Some((c, u + du, w + dw));
                                stack.push(j);
                            }
                            // Reached again at another cell: the periods do not fit.
                            Some((_, u2, w2)) if (u2, w2) != (u + du, w + dw) => return None,
                            Some(_) => {}
                        }
                    }
                }
            }
            components += 1;
        }
        // Components of one class whose sites differ by whole periods are one motif
        // position (a copy left out between them splits a chain).
        let lattice = Lattice { a, b };
        let origin = elems[0].pos;
        let mut sums = vec![(Vec2::ZERO, 0usize, 0u32); components];
        for (i, c) in coord.iter().enumerate() {
            let (k, u, w) = c.expect("every stroke reached");
            sums[k].0 += elems[i].pos - lattice.step(u, w) - origin;
            sums[k].1 += 1;
            sums[k].2 = elems[i].class;
        }
        let mut motif: Vec<MotifPosition> = Vec::new();
        // Per component: its motif position and the cell shift that aligns it.
        let mut place = vec![(0usize, 0i64, 0i64); components];
        let mut residues = Residues::new(lattice, tol);
        for (k, &(sum, count, class)) in sums.iter().enumerate() {
            let site = origin + sum / count as f64;
            let found = residues.first(class, site.to_vec2(), |m| {
                let (du, dw) = lattice.whole(site - motif[m].origin, tol)?;
                Some((m, du, dw))
            });
            place[k] = match found {
                Some(p) => p,
                None => {
                    motif.push(MotifPosition { class, origin: site, members: Vec::new() });
                    residues.file(class, site.to_vec2(), motif.len() - 1);
                    (motif.len() - 1, 0, 0)
                }
            };
        }
        let cell: Vec<(usize, (i64, i64))> = coord
            .iter()
            .map(|c| {
                let (k, u, w) = c.expect("every stroke reached");
                let (m, du, dw) = place[k];
                (m, (u + du, w + dw))
            })
            .collect();
        for (i, &(m, _)) in cell.iter().enumerate() {
            motif[m].members.push(i);
        }
        // Counted in strokes: two copies of a motif of two strokes repeat as clearly as
        // three copies of one stroke.
        let explained: usize =
            motif.iter().filter(|m| m.members.len() >= 2).flat_map(|m| m.members.iter().map(|&i| parts[i])).sum();
        let total: usize = parts.iter().sum();
        if explained < 3 || (explained as f64) < EXPLAINED * total as f64 {
            return None;
        }
        // Periods by least squares over every stroke (one pair's offset carries its two
        // strokes' jitter), then each site from its members' mean, then the residuals.
        let (a, b) = refine(elems, weight, &motif, &cell, a, b);
        let a = square(a);
        let b = b.map(|b| shear(a, square(b)));
        let lattice = Lattice { a, b };
        for mp in motif.iter_mut() {
            let sum = mp.members.iter().fold(Vec2::ZERO, |s, &i| {
                s + (elems[i].pos - lattice.step(cell[i].1 .0, cell[i].1 .1)).to_vec2() * weight[i]
            });
            mp.origin = (sum / mp.members.iter().map(|&i| weight[i]).sum::<f64>()).to_point();
        }
        let fit = Fit { a, b, motif, cell, quality: 0.0, certainty: Certainty::default() };
        let mut residuals: Vec<f64> =
            (0..n).map(|i| fit.site(fit.cell[i].0, fit.cell[i].1).distance(elems[i].pos)).collect();
        crate::order::floats(&mut residuals);
        let residual = residuals[n / 2];
        if residual > MAX_RESIDUAL * spread.spacing || fit.contradicted(elems, &spread.grid, tol, strict) || fit.apart()
        {
            return None;
        }
        let quality = (explained as f64 / total as f64) * (1.0 - residual / spread.spacing);
        Some(Fit { quality, ..fit })
    }

    /// The lines of cells along `(du, dw)` that motif position `m` is drawn on: per line,
    /// the lowest and highest place on it, the last cell, and how many cells are drawn.
    fn lines(&self, m: usize, (du, dw): (i64, i64)) -> Vec<(i64, i64, (i64, i64), usize)> {
        let mut places: Vec<(i64, i64, (i64, i64))> = self.motif[m]
            .members
            .iter()
            .map(|&i| {
                let (u, w) = self.cell[i].1;
                (u * dw - w * du, u * du + w * dw, (u, w))
            })
            .collect();
        places.sort_unstable();
        places
            .chunk_by(|p, q| p.0 == q.0)
            .map(|group| (group[0].1, group[group.len() - 1].1, group[group.len() - 1].2, group.len()))
            .collect()
    }

    /// Whether a quarter or more of the cells inside the lines along a period are left
    /// out: a lattice finer than the drawing (a pair's gap taken for a period) leaves a
    /// third or more; one drawn in order but a copy or two, about none.
    fn sparse(&self) -> bool {
        let axes: &[(i64, i64)] = if self.b.is_some() { &[(1, 0), (0, 1)] } else { &[(1, 0)] };
        axes.iter().any(|&axis| {
            let (mut span, mut drawn) = (0, 0);
            for m in 0..self.motif.len() {
                for (low, high, _, count) in self.lines(m, axis) {
                    span += high - low + 1;
                    drawn += count as i64;
                }
            }
            4 * drawn <= 3 * span
        })
    }

    /// Whether a motif position is drawn twice in one cell, leaves cells out inside its
    /// lines (in a row: any when `strict`, else a third of them: a sub-period leaves
    /// half or more), or stops short of a stroke of its class further along a line
    /// (within three periods).
    fn contradicted(&self, elems: &[Element], grid: &Grid, tol: f64, strict: bool) -> bool {
        // Sorted vectors rather than sets throughout: this runs on a few hundred strokes
        // and the module stays smaller without the tree code.
        let mut cells = self.cell.clone();
        cells.sort_unstable();
        if cells.windows(2).any(|p| p[0] == p[1]) {
            return true;
        }
        let lattice = self.lattice();
        // Lines along the periods and, in a lattice, along their diagonals: a lattice
        // too fine for the drawing puts sites between drawn copies on one of them.
        let axes: Vec<(i64, i64)> = if self.b.is_some() {
            vec![(1, 0), (-1, 0), (0, 1), (0, -1), (1, 1), (-1, -1), (1, -1), (-1, 1)]
        } else {
            vec![(1, 0), (-1, 0)]
        };
        for (m, mp) in self.motif.iter().enumerate() {
            for &(du, dw) in &axes {
                let dir = lattice.step(du, dw);
                let len = dir.hypot();
                let lines = self.lines(m, (du, dw));
                // A row with a cell left out inside it: the period skips copies. (Only
                // for a row: in a lattice, copies are often filled in out of order.)
                if self.b.is_none() {
                    let span: i64 = lines.iter().map(|&(low, high, _, _)| high - low + 1).sum();
                    let drawn = mp.members.len() as i64;
                    if (strict && span != drawn) || 3 * drawn < 2 * span {
                        return true;
                    }
                }
                for &(_, _, (u, w), _) in &lines {
                    let next = self.site(m, (u + du, w + dw));
                    // (Looked up in the grid: a lattice tried on 200 hatching lines has
                    // 200 lines along each axis, and scanning every stroke for each was
                    // most of an autocomplete call.)
                    let mut there = false;
                    grid.for_each_near(next, tol, |j| {
                        let o = &elems[j as usize];
                        there |= o.class == mp.class && o.pos.distance(next) < tol;
                    });
                    if there {
                        continue;
                    }
                    let mut beyond = false;
                    grid.for_each_near(next + dir * 1.5, 1.5 * len + tol, |j| {
                        let o = &elems[j as usize];
                        if beyond || o.class != mp.class {
                            return;
                        }
                        let d = o.pos - next;
                        let t = d.dot(dir) / len;
                        let off = (d.cross(dir) / len).abs();
                        beyond = off < tol && t > tol && t < 3.0 * len;
                    });
                    if beyond {
                        return true;
                    }
                }
            }
        }
        false
    }

    /// Whether the motif positions are not parts of one copy. Each position is moved by
    /// whole periods next to the first (of the shifts that round its origin's offset
    /// down or up, the one whose cells share most with the first's), and positions
    /// that share more than half the cells of the smaller are parts of one group. A
    /// group that shares at most half its cells with the others must then hold most of
    /// theirs (a second part filled in after the first was drawn all along its row).
    /// A motif of several parts drawn in order is one group; a row that turns a corner,
    /// read as a lattice of the periods before and after it (the leaves past the corner
    /// parts ten periods off those before it), is two, sharing one cell at most.
    fn apart(&self) -> bool {
        let positions: Vec<&MotifPosition> = self.motif.iter().filter(|m| m.members.len() >= 2).collect();
        if positions.len() < 2 {
            return false;
        }
        let lattice = self.lattice();
        let cells_of = |mp: &MotifPosition, (du, dw): (i64, i64)| {
            let mut cells: Vec<(i64, i64)> = mp
                .members
                .iter()
                .map(|&i| {
                    let (u, w) = self.cell[i].1;
                    (u + du, w + dw)
                })
                .collect();
            cells.sort_unstable();
            cells.dedup();
            cells
        };
        let shared = |x: &[(i64, i64)], y: &[(i64, i64)]| x.iter().filter(|c| y.binary_search(c).is_ok()).count();
        let first = cells_of(positions[0], (0, 0));
        let mut cells = vec![first.clone()];
        for mp in &positions[1..] {
            let (u, w) = lattice.coords(mp.origin - positions[0].origin);
            let shifts = [(u.floor(), w.floor()), (u.ceil(), w.floor()), (u.floor(), w.ceil()), (u.ceil(), w.ceil())];
            let best = shifts
                .iter()
                .map(|&(du, dw)| cells_of(mp, (du as i64, dw as i64)))
                .max_by_key(|c| shared(c, &first))
                .unwrap_or_default();
            cells.push(best);
        }
        // Groups: each position's group's least member (positions are few, a handful
        // of parts; hatching read on a coarse lattice makes a few dozen at most).
        let mut group: Vec<usize> = (0..cells.len()).collect();
        for k in 1..cells.len() {
            for j in 0..k {
                if 2 * shared(&cells[k], &cells[j]) > cells[k].len().min(cells[j].len()) {
                    let (gk, gj) = (group[k], group[j]);
                    group.iter_mut().filter(|g| **g == gk).for_each(|g| *g = gj.min(gk));
                    group.iter_mut().filter(|g| **g == gj).for_each(|g| *g = gj.min(gk));
                }
            }
        }
        let mut groups: Vec<Vec<(i64, i64)>> = Vec::new();
        for g in 0..cells.len() {
            let mut union: Vec<(i64, i64)> =
                (0..cells.len()).filter(|&k| group[k] == g).flat_map(|k| cells[k].iter().copied()).collect();
            union.sort_unstable();
            union.dedup();
            if !union.is_empty() {
                groups.push(union);
            }
        }
        groups.len() > 1
            && (0..groups.len()).any(|k| {
                let mut others: Vec<(i64, i64)> =
                    (0..groups.len()).filter(|&j| j != k).flat_map(|j| groups[j].iter().copied()).collect();
                others.sort_unstable();
                others.dedup();
                2 * shared(&groups[k], &others) <= groups[k].len() && 2 * shared(&others, &groups[k]) <= others.len()
            })
    }

    pub(super) fn lattice(&self) -> Lattice {
        Lattice { a: self.a, b: self.b }
    }

    /// Site of motif position `m` in cell `(u, w)`.
    pub(super) fn site(&self, m: usize, (u, w): (i64, i64)) -> Point {
        self.motif[m].origin + self.lattice().step(u, w)
    }
}
