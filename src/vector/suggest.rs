//! Autocomplete while drawing (SPEC 1.7, after Xing et al., "Autocomplete Painting
//! Repetitions", 2014): the drawing so far is the example; once it shows a repetition,
//! the next copies of the motif near the latest strokes are proposed as ghost strokes.
//!
//! A repetition is a lattice `origin_m + u a + w b` of motif positions `m` (a row when
//! there is no `b`). Its periods are offsets between same-class strokes that recur
//! (found at least twice among the latest strokes), tried shortest first; a candidate is
//! kept only when it explains the drawing:
//! - most strokes (70%) sit at a motif position drawn at least twice;
//! - no motif position is drawn twice in one cell, and none stops short of a stroke of
//!   its class further along its line (a period that skips drawn copies is a sub-period,
//!   such as the gap inside a pair);
//! - the strokes lie near their lattice sites (median residual at most 20% of the
//!   spacing).
//!
//! Of the lattices built on the first few periods that fit as a row, the one that
//! leaves fewest cells out inside its lines and then needs fewest motif positions
//! wins: the finest lattice the drawing bears out.
//!
//! Predictions then complete the cells already begun (the copy being drawn) and add the
//! next `count` cells along the rhythm of the latest cells. Nothing is proposed on a
//! first stroke, on irregular input, or when the latest stroke does not repeat anything
//! (a stroke that contradicts the prediction dismisses it). Each proposed copy is a
//! random drawn copy of its motif (so accepted copies keep the hand-drawn character)
//! placed at its site: the least-squares site is the best guess of where the hand
//! would put it, and a drawn copy's own deviation would only add to the miss.
//!
//! A proposal is shown only where it is likely right: where the hand's copy falls
//! within the matching tolerance of it with probability 0.98, given its expected miss
//! (the site's standard error, grown with each period away from the hand-drawn copies,
//! and the hand's own scatter) and how few copies that scatter is estimated from (an
//! F quantile, not a Gaussian one). The scatter is estimated with its degrees of
//! freedom (two copies fit a row exactly and say nothing of it) and a prior read from
//! the hand's wobble; accepted copies, which sit where an earlier fit put them, count
//! neither as evidence of the periods' error nor as whole copies of the hand (a copy
//! finished by hand weighs by its hand-drawn share).

use super::element::Element;
use super::reference::Spread;
use super::stroke::Stroke;
use super::synthesize::classify_drawing;
use crate::error::{invalid, Result};
use crate::rng::Rng;
use kurbo::{Point, Rect, Vec2};
use serde::{Deserialize, Serialize};
use std::f64::consts::SQRT_2;

/// Options of `suggest_strokes`.
#[derive(Clone, Debug, Deserialize)]
#[serde(rename_all = "camelCase", default, deny_unknown_fields)]
pub struct SuggestOptions {
    /// The area suggestions must fall in, `[x, y, width, height]` (the canvas); none:
    /// anywhere.
    pub region: Option<[f64; 4]>,
    /// How many copies of the motif to propose beyond those already begun.
    pub count: usize,
    /// Propose every copy in the region instead (the region is then required).
    pub fill: bool,
    pub path_tolerance: Option<f64>,
    pub width_tolerance: Option<f64>,
    pub color_tolerance: Option<f64>,
    /// Each proposal takes a random member of its class (else the stroke at its place).
    pub variation: bool,
    pub seed: u64,
    /// Indices of the strokes that are accepted proposals. They count for little in the
    /// periods' fit: they repeat the periods they were proposed with, so without this a
    /// period misjudged from the first copies drifts on through every accepted copy and
    /// the next hand-drawn stroke cannot correct it.
    pub suggested: Vec<u32>,
}

impl Default for SuggestOptions {
    fn default() -> Self {
        SuggestOptions {
            region: None,
            count: 3,
            fill: false,
            path_tolerance: None,
            width_tolerance: None,
            color_tolerance: None,
            variation: true,
            seed: 1,
            suggested: Vec::new(),
        }
    }
}

/// Proposed strokes (empty when the drawing shows no repetition yet).
#[derive(Clone, Debug, Default, Serialize)]
#[serde(rename_all = "camelCase")]
pub struct Suggestions {
    pub strokes: Vec<Stroke>,
    /// Of each proposed stroke, in (0, 1]: how well the lattice explains the drawing,
    /// lower for copies further from the drawn ones.
    pub confidence: Vec<f64>,
    /// The drawn stroke whose place (and deviation) each proposal repeats.
    pub sources: Vec<u32>,
    /// Lattice cell `[u, w]` of each proposal; proposals of one copy share it.
    pub cells: Vec<[i64; 2]>,
    /// The repetition's period vectors (one for a row, two for a lattice; none found).
    pub periods: Vec<[f64; 2]>,
    /// Why nothing is proposed, when nothing is.
    pub reason: Option<String>,
}

/// The most strokes a suggestion reads; beyond, only the latest ones (the repetition
/// is near them and the answer must come within a pen-up's patience).
pub const MAX_STROKES: usize = 400;
/// The most copies `fill` proposes, and the most points all its strokes may hold.
pub const MAX_FILL_CELLS: usize = 5_000;
pub const MAX_FILL_POINTS: usize = 2_000_000;
/// Candidate periods start at the latest strokes.
const RECENT: usize = 32;
/// Candidate periods evaluated in full, shortest first.
const MAX_TRIED: usize = 48;
/// Periods that fit as a row on which a lattice is tried.
const ROW_CHOICES: usize = 3;
/// Share of the strokes that must sit at a motif position drawn at least twice.
const EXPLAINED: f64 = 0.7;
/// Matching tolerance, as a fraction of the spacing.
const TOLERANCE: f64 = 0.3;
/// Median distance of strokes from their lattice sites, as a fraction of the spacing.
const MAX_RESIDUAL: f64 = 0.2;
/// Confidence lost per period of distance from the nearest drawn copy.
const FALLOFF: f64 = 0.85;
/// A proposal is shown only where the hand's copy is this likely to fall within the
/// matching tolerance of it (see `Certainty::reach`).
const SURE: f64 = 0.98;
/// A site nearer the region's edge than this many of its standard errors (in either
/// coordinate) may be outside it.
const EDGE: f64 = 2.0;
/// The least scatter of a copy about its site assumed before the drawing shows its
/// own, as a fraction of the spacing (a hand's own is read from its strokes' shapes:
/// see `hand_scatter`).
const MIN_SCATTER: f64 = 0.04;
/// A hand places its copies more loosely than it shapes them: the prior scatter of a
/// copy's place is this multiple of the mean square wobble of its strokes' ends.
const HAND_TO_PLACEMENT: f64 = 8.0;
/// The prior scatter counts as this many copies: it is read from every pair of a
/// hand's strokes of one class, not guessed.
const PRIOR_COPIES: f64 = 3.0;
/// Weight of an accepted proposal in the periods' fit (a hand-drawn stroke's is 1).
const SUGGESTED_WEIGHT: f64 = 0.05;

fn nothing(reason: &str) -> Suggestions {
    Suggestions { reason: Some(reason.into()), ..Suggestions::default() }
}

/// Proposes the next strokes of the repetition in `strokes` (in drawing order).
pub fn suggest_strokes(strokes: &[Stroke], opts: &SuggestOptions) -> Result<Suggestions> {
    if opts.count > 64 {
        return invalid("count can be at most 64 copies; use fill to propose the whole region.");
    }
    let region = match opts.region {
        Some([x, y, w, h]) => {
            if ![x, y, w, h].iter().all(|v| v.is_finite()) || w <= 0.0 || h <= 0.0 {
                return invalid("region must be [x, y, width, height] with finite numbers and a positive size.");
            }
            Some(Rect::new(x, y, x + w, y + h))
        }
        None if opts.fill => return invalid("fill needs a region: the canvas to fill."),
        None => None,
    };
    if let Some(&i) = opts.suggested.iter().find(|&&i| i as usize >= strokes.len()) {
        return invalid(format!("suggested lists stroke {i}, but there are {} strokes.", strokes.len()));
    }
    if strokes.len() < 3 {
        return Ok(nothing("Draw a motif two or three times and the next copies are proposed."));
    }
    let skip = strokes.len().saturating_sub(MAX_STROKES);
    let mut weight = vec![1.0; strokes.len() - skip];
    for &i in &opts.suggested {
        if let Some(w) = (i as usize).checked_sub(skip).and_then(|k| weight.get_mut(k)) {
            *w = SUGGESTED_WEIGHT;
        }
    }
    let (earlier, strokes) = strokes.split_at(skip);
    let accepted: Vec<bool> = weight.iter().map(|&w| w < 1.0).collect();
    let classification =
        classify_drawing(strokes, opts.path_tolerance, opts.width_tolerance, opts.color_tolerance, &accepted)?;
    // The repetition is one of motifs: a copy of a motif of several strokes is one
    // element, proposed whole (an accepted copy is one whose strokes all were).
    let motifs = &classification.motifs;
    let elems = classification.elements();
    let parts: Vec<usize> = motifs.instances.iter().map(Vec::len).collect();
    // A copy with fewer strokes than its kind's most is still being drawn (or was left
    // so): its centre is only estimated from the parts drawn, so it weighs little.
    let mut most = vec![0usize; motifs.kind.iter().map(|&k| k as usize + 1).max().unwrap_or(0)];
    for (&p, &k) in parts.iter().zip(&motifs.kind) {
        most[k as usize] = most[k as usize].max(p);
    }
    let whole = |x: usize| parts[x] >= most[motifs.kind[x] as usize];
    let weight: Vec<f64> = motifs
        .instances
        .iter()
        .enumerate()
        .map(|(x, g)| {
            // A copy of accepted strokes sits where the lattice put it and says nothing
            // new about it; one finished by hand is placed by its hand-drawn strokes only.
            let hand = g.iter().filter(|&&s| weight[s as usize] >= 1.0).count() as f64 / g.len() as f64;
            if whole(x) {
                hand.max(SUGGESTED_WEIGHT)
            } else {
                SUGGESTED_WEIGHT
            }
        })
        .collect();
    let Ok(mut spread) = Spread::new(&elems) else {
        return Ok(nothing("The strokes have no spacing to repeat."));
    };
    spread.spacing = spread.apart(&elems);
    let Some(mut fit) = Fit::find(&elems, &weight, &parts, &spread) else {
        return Ok(nothing("The drawing shows no repetition yet."));
    };
    let prior = (HAND_TO_PLACEMENT * hand_scatter(strokes, &classification.classes, &accepted))
        .max((MIN_SCATTER * spread.spacing).powi(2));
    fit.certainty = fit.certainty(&elems, &weight, prior);
    let latest = motifs.instance_of()[strokes.len() - 1] as usize;
    if !whole(latest) {
        return Ok(nothing("The copy being drawn is not finished: the next copies are proposed once it is."));
    }
    if fit.motif[fit.cell[latest].0].members.len() < 2 {
        return Ok(nothing("The latest stroke does not repeat the pattern."));
    }
    let points = strokes.iter().map(|s| s.points.len().max(1)).sum::<usize>();
    let per_copy = points.div_ceil(elems.len()) * fit.motif.len();
    let extents = motifs.extents(strokes);
    let wanted = fit.wanted(&elems, region, opts, (MAX_FILL_POINTS / per_copy.max(1)).clamp(1, MAX_FILL_CELLS));
    let mut out = Suggestions {
        periods: std::iter::once(fit.a).chain(fit.b).map(|v| [v.x, v.y]).collect(),
        ..Suggestions::default()
    };
    // A copy drawn where the lattice (fitted to hand-drawn copies) no longer puts it is
    // still drawn: nothing is proposed on a stroke of its class.
    let tol = TOLERANCE * spread.spacing;
    let drawn_at = |class: u32, p: Point, size: f64| {
        let mut hit = false;
        spread.grid.for_each_near(p, tol, |j| {
            let o = &elems[j as usize];
            hit |= o.class == class && o.pos.distance(p) < tol;
        });
        hit || earlier.iter().any(|e| {
            e.reference_point().distance(p) < tol && (e.bounds().size().to_vec2().hypot() - size).abs() <= 0.25 * size
        })
    };
    let mut uncertain = 0;
    for (m, cell, steps) in wanted {
        // Not so far ahead of the hand-drawn copies that the site is likely off by more
        // than the tolerance (fill is asked for explicitly and goes everywhere).
        if !opts.fill && fit.certainty.reach() * fit.miss_at(m, cell) > tol {
            uncertain += 1;
            continue;
        }
        let motif = &fit.motif[m];
        // Seeded by the place, so a copy keeps its look from one pen-up to the next.
        let mut rng = Rng::new(
            opts.seed
                ^ (m as u64).wrapping_mul(0x9E37_79B9_7F4A_7C15)
                ^ (cell.0 as u64).wrapping_mul(0xC2B2_AE3D)
                ^ (cell.1 as u64).wrapping_mul(0x1656_67B1),
        );
        // Variation among the drawn copies of this motif position only.
        let source = motif.members[rng.below(motif.members.len())];
        // A whole drawn copy (not one still being drawn) when varying.
        let copies: Vec<usize> = motif.members.iter().copied().filter(|&x| whole(x)).collect();
        let pick = if opts.variation && !copies.is_empty() { copies[rng.below(copies.len())] } else { source };
        let target = fit.site(m, cell);
        if drawn_at(elems[source].class, target, extents[pick].hypot() * 2.0) {
            continue;
        }
        let shift = target - motifs.centre[pick];
        for &s in &motifs.instances[pick] {
            let part = motifs.part[s as usize];
            let named = motifs.instances[source].iter().copied().find(|&t| motifs.part[t as usize] == part);
            out.strokes.push(strokes[s as usize].translated(shift.x, shift.y));
            out.confidence.push(fit.quality * FALLOFF.powi(steps as i32));
            out.sources.push(named.unwrap_or(s) + skip as u32);
            out.cells.push([cell.0, cell.1]);
        }
    }
    if out.strokes.is_empty() {
        out.reason = Some(if uncertain > 0 {
            "The copies drawn so far leave the next ones too uncertain: draw one more.".into()
        } else {
            "Every copy of the repetition in the region is drawn.".into()
        });
    }
    Ok(out)
}

/// A motif position: its class, its site in cell (0, 0) and the strokes drawn there.
#[derive(Clone, Debug)]
struct MotifPosition {
    class: u32,
    origin: Point,
    members: Vec<usize>,
}

/// A lattice that explains the drawing.
#[derive(Clone, Debug)]
struct Fit {
    a: Vec2,
    b: Option<Vec2>,
    motif: Vec<MotifPosition>,
    /// Motif position and cell of each stroke.
    cell: Vec<(usize, (i64, i64))>,
    /// Share of the strokes explained, less their residual.
    quality: f64,
    /// How far off the lattice may be in a cell: see `Fit::error_at`.
    certainty: Certainty,
}

/// What the (weighted) drawn copies say about the lattice's error: the variance of a
/// copy about its site, each motif position's weight and mean cell, and the pooled
/// scatter of the cells about those means (`[uu, uw, ww]`).
#[derive(Clone, Debug, Default)]
struct Certainty {
    residual2: f64,
    /// The copies `residual2` is estimated from (the prior counting as `PRIOR_COPIES`).
    copies: f64,
    held: Vec<f64>,
    mean: Vec<(f64, f64)>,
    scatter: [f64; 3],
}

impl Certainty {
    /// How many root-mean-square misses (`Fit::miss_at`) reach the circle that holds
    /// the hand's copy with probability `SURE`. The scatter is estimated from few
    /// copies (each gives two coordinates), so the miss's square over its estimate's
    /// is `2 F(2, 2n)`, whose quantile has a closed form: `F = n (p^(-1/n) - 1)` for
    /// `p = 1 - SURE`. From `sqrt(-ln p)` = 1.98 with many copies it grows to 3.5 with
    /// two and 7 with one: a row of three copies fits its periods almost exactly and
    /// says little of how far the next ones will stray.
    fn reach(&self) -> f64 {
        let n = self.copies.max(1.0);
        (n * ((1.0 - SURE).powf(-1.0 / n) - 1.0)).sqrt()
    }
}

impl Fit {
    /// The best lattice of `elems`, or `None` when no candidate explains them.
    ///
    /// A lattice is tried on each of the first few periods that fit as a row, and the
    /// one with the fewest motif positions wins (the finest lattice the drawing does not
    /// contradict): a period that joins one part of a copy to another part of the next
    /// (the diagonal from a pair's left stroke to the right stroke of the pair above)
    /// also fits, but on a coarser lattice that needs twice the positions.
    fn find(elems: &[Element], weight: &[f64], parts: &[usize], spread: &Spread) -> Option<Fit> {
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
        best.or(row)
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
        for (k, &(sum, count, class)) in sums.iter().enumerate() {
            let site = origin + sum / count as f64;
            let found = motif.iter().enumerate().find_map(|(m, mp)| {
                if mp.class != class {
                    return None;
                }
                let (du, dw) = lattice.whole(site - mp.origin, tol)?;
                Some((m, du, dw))
            });
            place[k] = match found {
                Some(p) => p,
                None => {
                    motif.push(MotifPosition { class, origin: site, members: Vec::new() });
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
        if residual > MAX_RESIDUAL * spread.spacing || fit.contradicted(elems, tol, strict) {
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
    fn contradicted(&self, elems: &[Element], tol: f64, strict: bool) -> bool {
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
                    let beyond = elems.iter().any(|o| {
                        if o.class != mp.class {
                            return false;
                        }
                        let d = o.pos - next;
                        let t = d.dot(dir) / len;
                        let off = (d.cross(dir) / len).abs();
                        off < tol && t > tol && t < 3.0 * len
                    });
                    let there = elems.iter().any(|o| o.class == mp.class && o.pos.distance(next) < tol);
                    if beyond && !there {
                        return true;
                    }
                }
            }
        }
        false
    }

    /// The residual is the unbiased one (each motif position's site and each period take
    /// a degree of freedom: two copies fit a row exactly and say nothing of its error),
    /// with `PRIOR_COPIES` prior copies off by `prior` (a mean square), so that a lattice
    /// seen in few copies is not taken as exact.
    fn certainty(&self, elems: &[Element], weight: &[f64], prior: f64) -> Certainty {
        let positions = self.motif.len();
        let mut held = vec![0.0; positions];
        let mut mean = vec![(0.0, 0.0); positions];
        let mut r2 = 0.0;
        // Accepted copies sit where an earlier fit put them: they carry no evidence of
        // its error, and their cells, far out, would make it look well anchored.
        let weight: Vec<f64> = weight.iter().map(|&w| if w > SUGGESTED_WEIGHT { w } else { 0.0 }).collect();
        for (i, &(m, (u, w))) in self.cell.iter().enumerate() {
            held[m] += weight[i];
            mean[m].0 += weight[i] * u as f64;
            mean[m].1 += weight[i] * w as f64;
            r2 += weight[i] * self.site(m, (u, w)).distance_squared(elems[i].pos);
        }
        for (m, h) in mean.iter_mut().zip(&held) {
            *m = if *h > 0.0 { (m.0 / h, m.1 / h) } else { (0.0, 0.0) };
        }
        let mut scatter = [0.0; 3];
        for (i, &(m, (u, w))) in self.cell.iter().enumerate() {
            let (du, dw) = (u as f64 - mean[m].0, w as f64 - mean[m].1);
            scatter[0] += weight[i] * du * du;
            scatter[1] += weight[i] * du * dw;
            scatter[2] += weight[i] * dw * dw;
        }
        let periods = if self.b.is_some() { 2.0 } else { 1.0 };
        let free = (held.iter().map(|&h| (h - 1.0).max(0.0)).sum::<f64>() - periods).max(0.0);
        let copies = free + PRIOR_COPIES;
        Certainty { residual2: (r2 + PRIOR_COPIES * prior) / copies, copies, held, mean, scatter }
    }

    /// The standard error of motif position `m`'s site in cell `(u, w)`, as least
    /// squares gives it: with `d` the cell's offset from the position's (weighted) mean
    /// cell and `S` the cells' scatter, `r^2 (1 / held + d' S^-1 d)`. The periods are
    /// correlated when the copies lie along a diagonal of the cells (the basis then
    /// crosses the rows), which the full `S` takes in.
    fn error_at(&self, m: usize, (u, w): (i64, i64)) -> f64 {
        let c = &self.certainty;
        let (du, dw) = (u as f64 - c.mean[m].0, w as f64 - c.mean[m].1);
        let [suu, suw, sww] = c.scatter;
        let det = suu * sww - suw * suw;
        let far = if self.b.is_none() {
            if suu > 0.0 {
                du * du / suu
            } else {
                f64::INFINITY
            }
        } else if det > 1e-9 * (suu * sww).max(1e-300) {
            (du * du * sww - 2.0 * du * dw * suw + dw * dw * suu) / det
        } else {
            f64::INFINITY
        };
        (c.residual2 * (1.0 / c.held[m].max(1e-9) + far)).sqrt()
    }

    /// The root-mean-square distance between a proposal for motif position `m` in cell
    /// `(u, w)` and the copy the hand would draw there: the site's error and the drawn
    /// copy's own scatter about its site (the proposal itself sits on the site).
    fn miss_at(&self, m: usize, cell: (i64, i64)) -> f64 {
        (self.error_at(m, cell).powi(2) + self.certainty.residual2).sqrt()
    }

    fn lattice(&self) -> Lattice {
        Lattice { a: self.a, b: self.b }
    }

    /// Site of motif position `m` in cell `(u, w)`.
    fn site(&self, m: usize, (u, w): (i64, i64)) -> Point {
        self.motif[m].origin + self.lattice().step(u, w)
    }

    fn at(&self, i: usize) -> (i64, i64) {
        self.cell[i].1
    }

    /// The (motif position, cell, periods from the nearest drawn copy) to propose.
    fn wanted(
        &self,
        elems: &[Element],
        region: Option<Rect>,
        opts: &SuggestOptions,
        max_cells: usize,
    ) -> Vec<(usize, (i64, i64), usize)> {
        // Near the region's edge, a site off by its error may be outside: the copy the
        // hand would draw there may not be on the canvas (fill goes to the edge).
        let margin = |m: usize, c: (i64, i64)| if opts.fill { 0.0 } else { EDGE * self.error_at(m, c) / SQRT_2 };
        let inside = |m: usize, c: (i64, i64)| {
            region.is_none_or(|r| {
                let p = self.site(m, c);
                let d = margin(m, c);
                r.contains(p) && p.x - r.x0 >= d && r.x1 - p.x >= d && p.y - r.y0 >= d && r.y1 - p.y >= d
            })
        };
        let mut drawn = self.cell.clone();
        drawn.sort_unstable();
        let mut occupied: Vec<(i64, i64)> = self.cell.iter().map(|c| c.1).collect();
        occupied.sort_unstable();
        occupied.dedup();
        let neighbours: Vec<(i64, i64)> =
            if self.b.is_some() { vec![(1, 0), (-1, 0), (0, 1), (0, -1)] } else { vec![(1, 0), (-1, 0)] };
        let any_inside = |c: (i64, i64)| (0..self.motif.len()).any(|m| inside(m, c));
        let latest = self.at(elems.len() - 1);
        // The rhythm: from the cell drawn before the latest one to the latest.
        let previous = (0..elems.len()).rev().map(|i| self.at(i)).find(|&c| c != latest);
        let rhythm = previous.map_or((1, 0), |p| (latest.0 - p.0, latest.1 - p.1));

        let mut cells: Vec<((i64, i64), usize)> = occupied.iter().map(|&c| (c, 0)).collect();
        let mut taken = Cells(occupied);
        if opts.fill {
            // Every cell reachable from the drawn ones through cells in the region, in
            // breadth-first order (`cells` is the queue).
            let mut head = 0;
            while let Some(&(c, d)) = cells.get(head) {
                head += 1;
                for &(du, dw) in &neighbours {
                    let n = (c.0 + du, c.1 + dw);
                    if taken.len() < max_cells && !taken.contains(n) && any_inside(n) {
                        taken.insert(n);
                        cells.push((n, d + 1));
                    }
                }
            }
        } else {
            // The next cells along the rhythm, else the free neighbour nearest the latest.
            let mut last = latest;
            for _ in 0..opts.count {
                let along = (last.0 + rhythm.0, last.1 + rhythm.1);
                let next = if !taken.contains(along) && any_inside(along) && taken.adjacent(along, &neighbours) {
                    Some(along)
                } else {
                    let here = self.lattice().step(latest.0, latest.1);
                    taken
                        .0
                        .iter()
                        .flat_map(|&c| neighbours.iter().map(move |&(du, dw)| (c.0 + du, c.1 + dw)))
                        .filter(|&c| !taken.contains(c) && any_inside(c))
                        // The latest copy's line of cells first: a row is finished before the next.
                        .min_by(|p, q| {
                            let dp = (self.lattice().step(p.0, p.1) - here).hypot2();
                            let dq = (self.lattice().step(q.0, q.1) - here).hypot2();
                            (p.1 != latest.1).cmp(&(q.1 != latest.1)).then(dp.total_cmp(&dq)).then(p.cmp(q))
                        })
                };
                let Some(next) = next else { break };
                let steps = neighbours
                    .iter()
                    .filter_map(|&(du, dw)| cells.iter().find(|(c, _)| *c == (next.0 - du, next.1 - dw)).map(|x| x.1))
                    .min()
                    .unwrap_or(0)
                    + 1;
                taken.insert(next);
                cells.push((next, steps));
                last = next;
            }
        }
        let mut out = Vec::new();
        for (c, steps) in cells {
            // Motif positions drawn once are not yet part of the repetition.
            for m in 0..self.motif.len() {
                if self.motif[m].members.len() >= 2 && drawn.binary_search(&(m, c)).is_err() && inside(m, c) {
                    out.push((m, c, steps));
                }
            }
        }
        out
    }
}

/// How far a hand's copy strays from where it means to put it, as the drawing shows it
/// before its repetition does: the mean square difference, between consecutive
/// hand-drawn strokes of one class, of their ends' offsets from their reference
/// points (either way round), halved. Exact copies give 0; a hand that wobbles its
/// strokes' ends by `e` gives about `e^2`, and places its copies about as loosely.
fn hand_scatter(strokes: &[Stroke], classes: &[u32], accepted: &[bool]) -> f64 {
    let ends = |s: &Stroke| {
        let r = s.reference_point().to_vec2();
        let p = |q: &[f64; 2]| Vec2::new(q[0], q[1]) - r;
        (s.points.first().map_or(Vec2::ZERO, p), s.points.last().map_or(Vec2::ZERO, p))
    };
    let mut last: Vec<Option<usize>> = vec![None; classes.iter().map(|&c| c as usize + 1).max().unwrap_or(0)];
    let (mut sum, mut count) = (0.0, 0usize);
    for (i, &c) in classes.iter().enumerate() {
        if accepted[i] {
            continue;
        }
        if let Some(j) = last[c as usize] {
            let ((a0, a1), (b0, b1)) = (ends(&strokes[i]), ends(&strokes[j]));
            let same = (a0 - b0).hypot2() + (a1 - b1).hypot2();
            let reversed = (a0 - b1).hypot2() + (a1 - b0).hypot2();
            sum += same.min(reversed) / 4.0;
            count += 1;
        }
        last[c as usize] = Some(i);
    }
    if count == 0 {
        0.0
    } else {
        sum / count as f64
    }
}

/// The periods that best explain the strokes' positions given their cells: with `d`
/// a stroke's offset from its motif position's (weighted) mean and `(du, dw)` its
/// cell's, the weighted least squares solution of `d = du a + dw b`.
fn refine(
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
fn square(v: Vec2) -> Vec2 {
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
fn shear(a: Vec2, b: Vec2) -> Vec2 {
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

/// A set of lattice cells, kept sorted.
struct Cells(Vec<(i64, i64)>);

impl Cells {
    fn len(&self) -> usize {
        self.0.len()
    }

    fn contains(&self, c: (i64, i64)) -> bool {
        self.0.binary_search(&c).is_ok()
    }

    fn insert(&mut self, c: (i64, i64)) {
        if let Err(at) = self.0.binary_search(&c) {
            self.0.insert(at, c);
        }
    }

    /// Whether a neighbour of `c` is in the set.
    fn adjacent(&self, c: (i64, i64), neighbours: &[(i64, i64)]) -> bool {
        neighbours.iter().any(|&(du, dw)| self.contains((c.0 - du, c.1 - dw)))
    }
}

/// Periods `a` and `b` (a row when there is no `b`).
#[derive(Clone, Copy, Debug)]
struct Lattice {
    a: Vec2,
    b: Option<Vec2>,
}

impl Lattice {
    fn step(&self, u: i64, w: i64) -> Vec2 {
        self.a * u as f64 + self.b.unwrap_or(Vec2::ZERO) * w as f64
    }

    /// The whole periods `(u, w)` that make up `d` (within `tol`), if any.
    fn whole(&self, d: Vec2, tol: f64) -> Option<(i64, i64)> {
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
fn candidates(elems: &[Element], parts: &[usize], spread: &Spread, tol: f64) -> Vec<Vec2> {
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
