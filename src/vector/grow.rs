//! Reference/target growth (SPEC 1.2-1.3): the heart of the vector engine.
//!
//! The reference pattern is a set of point elements (class, position). The target starts
//! as one copy of the reference at the centre of the output area and grows outward: at
//! each growing point `g`, every same-class reference element `r` proposes the
//! translation `t = g - r`; under `t` the reference is paired with the target, `t` is
//! refined by least squares (the mean pair offset), and the best-supported candidate that
//! adds something is stamped.
//!
//! Two departures from a literal reading keep the cost near-linear in the number of
//! output elements:
//! - a candidate is judged on a *window* of the reference (its neighbours within a
//!   few spacings of `r`), found through precomputed neighbour lists and a uniform grid
//!   over the target, and only that window is stamped;
//! - growth runs along the frontier: a target element whose source is interior to the
//!   reference and whose reference neighbourhood is already present is passed over
//!   without evaluating candidates (it would add nothing).

use super::classify::median;
pub use super::element::{Element, Placed};
use super::lattice;
use super::period;
use super::spatial::Grid;
use crate::error::{invalid, Error, Result};
use crate::progress::Throttle;
use kurbo::{Point, Rect, Vec2};
use std::cmp::Reverse;
use std::collections::BinaryHeap;

#[derive(Clone, Debug)]
pub struct GrowOptions {
    pub width: f64,
    pub height: f64,
    /// A candidate is eligible when its pair count is at least this fraction of the
    /// largest pair count at the growing point (SPEC 1.3 Choice: 0.6).
    pub support: f64,
    /// Pairing radius as a fraction of the median same-class nearest-neighbour distance.
    pub pair_radius: f64,
    /// Refuse outputs estimated to hold more elements than this.
    pub max_elements: usize,
    /// Pass over growing points whose neighbourhood is already full.
    pub frontier_first: bool,
    /// Grow on the example's fitted lattice (no drift), then give each element its
    /// source's own deviation back (see `lattice`).
    pub regularize: bool,
    /// Half the size of each element's drawing around its position (empty: points).
    /// A periodic extension places every element whose drawing reaches into the area,
    /// so the output is covered to its edges.
    pub extents: Vec<Vec2>,
}

impl Default for GrowOptions {
    fn default() -> Self {
        GrowOptions {
            width: 1000.0,
            height: 1000.0,
            support: 0.6,
            pair_radius: 0.5,
            max_elements: 500_000,
            frontier_first: true,
            regularize: true,
            extents: Vec::new(),
        }
    }
}

/// Counters that tell how growth went (reported to the page and the benchmark).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct GrowStats {
    pub growing_points: usize,
    pub skipped_full: usize,
    pub passed_over: usize,
    pub candidates: usize,
}

/// Neighbours of a reference element within some radius: index and offset.
type Neighbourhood = Vec<(u32, Vec2)>;

/// Everything about the reference that growth reads, computed once.
struct Reference<'a> {
    elems: &'a [Element],
    by_class: Vec<Vec<u32>>,
    /// Pairing radius per class.
    pair_radius: Vec<f64>,
    /// Radius within which an element of another class blocks stamping.
    cross_radius: f64,
    /// Window neighbours of each element (itself included), nearest first.
    window: Vec<Neighbourhood>,
    /// Radius of the disc whose population tells whether a neighbourhood is full.
    near_radius: f64,
    /// Per class: elements of any class within `near_radius` of a deep-interior reference
    /// element of that class (median); `None` when the reference has no deep interior.
    full_count: Vec<Option<usize>>,
    /// Median distance between neighbouring elements (any class).
    spacing: f64,
    /// Radius of the windows.
    window_radius: f64,
    /// The reference elements, indexed by position.
    grid: Grid,
    /// Bounding box of the element positions.
    bounds: Rect,
    /// Elements with neighbours in every direction within the conflict radius and a
    /// spacing: their neighbourhood in the example is complete.
    surrounded: Vec<bool>,
}

fn nearest_distances(elems: &[Element], same_class: bool, skip_coincident: bool, grid: &Grid, scale: f64) -> Vec<f64> {
    let eps = scale * 1e-9;
    elems
        .iter()
        .enumerate()
        .map(|(i, e)| {
            let mut radius = scale;
            loop {
                let mut best = f64::INFINITY;
                grid.for_each_near(e.pos, radius, |j| {
                    let o = &elems[j as usize];
                    if j as usize == i || (same_class && o.class != e.class) {
                        return;
                    }
                    let d = o.pos.distance(e.pos);
                    if (!skip_coincident || d > eps) && d < best {
                        best = d;
                    }
                });
                if best <= radius || radius > scale * 1e6 {
                    return best;
                }
                radius *= 4.0;
            }
        })
        .collect()
}

/// Whether each element has another within `radius` in each of eight 45-degree sectors.
fn surrounded(elems: &[Element], grid: &Grid, radius: f64) -> Vec<bool> {
    elems
        .iter()
        .map(|e| {
            let mut sectors = 0u8;
            grid.for_each_near(e.pos, radius, |j| {
                let o = elems[j as usize].pos - e.pos;
                let d2 = o.hypot2();
                if d2 > 0.0 && d2 <= radius * radius {
                    let k = ((o.y.atan2(o.x) + std::f64::consts::PI) / std::f64::consts::FRAC_PI_4) as u32 % 8;
                    sectors |= 1 << k;
                }
            });
            sectors == 0xFF
        })
        .collect()
}

/// Moves `radius` into the widest gap of the neighbour distances between 0.8x and 1.6x
/// of it, so that jitter does not move elements in and out of discs of that radius.
fn between_shells(elems: &[Element], grid: &Grid, radius: f64) -> f64 {
    let (lo, hi) = (0.8 * radius, 1.6 * radius);
    let mut d = vec![lo, hi];
    for e in elems {
        grid.for_each_near(e.pos, hi, |j| {
            let x = elems[j as usize].pos.distance(e.pos);
            if x > lo && x < hi {
                d.push(x);
            }
        });
    }
    crate::order::floats(&mut d);
    let (a, b) =
        d.windows(2).map(|w| (w[0], w[1])).max_by(|x, y| (x.1 - x.0).total_cmp(&(y.1 - y.0))).unwrap_or((lo, hi));
    0.5 * (a + b)
}

/// Where the example's elements are: their box, a grid indexing them and their spacing
/// (the median distance between neighbours). The period search needs only this; growth
/// builds its `Reference` on it.
struct Spread {
    bounds: Rect,
    grid: Grid,
    /// The grid's cell size, the scale of neighbour searches.
    rough: f64,
    spacing: f64,
}

impl Spread {
    fn new(elems: &[Element]) -> Result<Self> {
        let n = elems.len();
        if n < 2 {
            return invalid("Draw at least two strokes: a pattern needs a spacing to repeat.");
        }
        let bounds = elems.iter().fold(Rect::from_points(elems[0].pos, elems[0].pos), |r, e| r.union_pt(e.pos));
        let extent = bounds.width().max(bounds.height());
        if extent <= 0.0 {
            return invalid("All strokes are centred on the same point: there is no spacing to repeat.");
        }
        let rough = extent / (n as f64).sqrt().max(1.0);
        let mut grid = Grid::new(bounds, rough, 4 * n + 16);
        for (i, e) in elems.iter().enumerate() {
            grid.insert(i as u32, e.pos);
        }
        let mut any = nearest_distances(elems, false, true, &grid, rough);
        let spacing = median(&mut any);
        if !spacing.is_finite() || spacing <= 0.0 {
            return invalid("All strokes are centred on the same point: there is no spacing to repeat.");
        }
        Ok(Spread { bounds, grid, rough, spacing })
    }
}

impl<'a> Reference<'a> {
    fn new(elems: &'a [Element]) -> Result<Self> {
        Reference::on(elems, Spread::new(elems)?)
    }

    fn on(elems: &'a [Element], spread: Spread) -> Result<Self> {
        let Spread { bounds, grid, rough, spacing } = spread;
        let (n, extent) = (elems.len(), bounds.width().max(bounds.height()));
        let mut with_coincident = nearest_distances(elems, false, false, &grid, rough);
        let cross_radius = 0.5 * median(&mut with_coincident);

        let classes = elems.iter().map(|e| e.class as usize + 1).max().unwrap_or(0);
        let mut by_class = vec![Vec::new(); classes];
        for (i, e) in elems.iter().enumerate() {
            by_class[e.class as usize].push(i as u32);
        }
        let same = nearest_distances(elems, true, true, &grid, rough);
        let pair_radius = (0..classes)
            .map(|c| {
                let mut d: Vec<f64> = by_class[c].iter().map(|&i| same[i as usize]).filter(|d| d.is_finite()).collect();
                let m = median(&mut d);
                0.5 * if m > 0.0 { m } else { spacing }
            })
            .collect();

        let k_window = (n - 1).min(48);
        let k_near = (n - 1).min(8);
        // The k-th neighbour distance at quantile `q` over the elements.
        let kth = |k: usize, q: f64| {
            let mut radius = spacing * 2.0;
            let mut d: Vec<f64> = elems
                .iter()
                .enumerate()
                .map(|(i, e)| loop {
                    let mut ds = Vec::new();
                    grid.for_each_near(e.pos, radius, |j| {
                        if j as usize != i {
                            ds.push(elems[j as usize].pos.distance(e.pos));
                        }
                    });
                    ds.retain(|&x| x <= radius);
                    if ds.len() >= k || radius > extent * 4.0 {
                        crate::order::floats(&mut ds);
                        return ds.get(k - 1).copied().unwrap_or(radius);
                    }
                    radius *= 2.0;
                })
                .collect();
            crate::order::floats(&mut d);
            d[((d.len() - 1) as f64 * q) as usize]
        };
        let window_radius = (3.0 * spacing).max(kth(k_window, 0.5)) * 1.05;
        // A low quantile: the interior elements' radius, not the border's.
        let near_radius = between_shells(elems, &grid, kth(k_near, 0.1));
        let neighbourhood = |radius: f64| -> Vec<Neighbourhood> {
            elems
                .iter()
                .map(|e| {
                    let mut nb = Vec::new();
                    grid.for_each_near(e.pos, radius, |j| {
                        let off = elems[j as usize].pos - e.pos;
                        if off.hypot() <= radius {
                            nb.push((j, off));
                        }
                    });
                    nb.sort_by(|a, b| a.1.hypot2().total_cmp(&b.1.hypot2()).then(a.0.cmp(&b.0)));
                    nb
                })
                .collect()
        };
        let window = neighbourhood(window_radius);
        let near = neighbourhood(near_radius);
        // Deep interior: the near disc lies inside the reference's extent along every axis
        // the reference spans (a row spans one).
        let deep = |p: Point| {
            let fits = |lo: f64, hi: f64, v: f64| {
                hi - lo < 2.0 * near_radius || (v - lo >= near_radius && hi - v >= near_radius)
            };
            fits(bounds.x0, bounds.x1, p.x) && fits(bounds.y0, bounds.y1, p.y)
        };
        let full_count = by_class
            .iter()
            .map(|members| {
                let counts: Vec<f64> = members
                    .iter()
                    .filter(|&&i| deep(elems[i as usize].pos))
                    .map(|&i| near[i as usize].len() as f64)
                    .collect();
                counts
                    .iter()
                    .copied()
                    .fold(None, |m: Option<f64>, c| Some(m.map_or(c, |m| m.max(c))))
                    .map(|c| c as usize)
            })
            .collect();
        Ok(Reference {
            elems,
            by_class,
            pair_radius,
            cross_radius,
            window,
            near_radius,
            full_count,
            spacing,
            window_radius,
            surrounded: surrounded(elems, &grid, CONFLICT_RADIUS * spacing + spacing),
            grid,
            bounds,
        })
    }

    /// Whether the example is one row of elements (no extent across it): a row grows
    /// only along itself, so the area beside it is no hole to fill.
    fn is_row(&self) -> bool {
        let b = self.bounds;
        b.width().min(b.height()) < self.spacing
    }

    /// Whether an element of `class` lies within its pairing radius of `p`.
    fn has(&self, p: Point, class: u32) -> bool {
        let d = self.pair_radius[class as usize];
        let mut hit = false;
        self.grid.for_each_near(p, d, |j| {
            let e = &self.elems[j as usize];
            hit |= e.class == class && (e.pos - p).hypot2() < d * d;
        });
        hit
    }

    fn density(&self) -> f64 {
        let b = self.bounds;
        let area = (b.width() + self.spacing) * (b.height() + self.spacing);
        self.elems.len() as f64 / area.max(1e-12)
    }
}

/// One evaluated candidate translation.
#[derive(Clone, Copy, Debug)]
struct Candidate {
    source: u32,
    delta: Vec2,
    pairs: usize,
    error: f64,
    adds: usize,
}

/// The growing target: its elements, a grid over them, and scratch buffers.
struct Target<'r, 'a> {
    reference: &'r Reference<'a>,
    area: Rect,
    placed: Vec<Placed>,
    grid: Grid,
    used: Vec<u32>,
    stamp: u32,
    pairs: Vec<(u32, u32)>,
    previous: Vec<(u32, u32)>,
    /// Element counts on a coarse grid (cells a window across): empty cells are holes.
    cover: Vec<u32>,
    /// Columns, rows, and cell width and height: cells tile the area exactly.
    cover_dims: (usize, usize, f64, f64),
    /// Second phase: stamp only into holes.
    fill_holes: bool,
    /// The growing point's nearest neighbours (offset, class), for the candidate pre-test.
    sig: Vec<(Vec2, u32)>,
    /// Filling holes adds to cells with fewer elements than this (0.9 of the example's
    /// density); an empty cell is a hole that starts the filling.
    hole_below: u32,
}

const MAX_REFINEMENTS: usize = 4;

/// A candidate whose first pairing reaches less than this fraction of the best pair
/// count so far is dropped before refinement: refinement moves `t` by under a pairing
/// radius, which cannot lift it to the support ratio (0.6).
const PRUNE: f64 = 0.45;

/// Radius, in spacings, within which a new element's neighbours must agree with the example.
const CONFLICT_RADIUS: f64 = 1.25;

/// Normalised errors within (this x pairing radius)^2 of each other are ties.
const ERROR_QUANTUM: f64 = 0.02;

/// Nearest neighbours of a growing point that a candidate must reproduce to be evaluated.
const SIGNATURE: usize = 4;

impl<'r, 'a> Target<'r, 'a> {
    fn inside(&self, p: Point) -> bool {
        p.x >= self.area.x0 && p.x <= self.area.x1 && p.y >= self.area.y0 && p.y <= self.area.y1
    }

    fn add(&mut self, pos: Point, source: u32) {
        let class = self.reference.elems[source as usize].class;
        if let Some(c) = self.cover_cell(pos) {
            self.cover[c] += 1;
        }
        self.grid.insert(self.placed.len() as u32, pos);
        self.placed.push(Placed { pos, class, source });
        self.used.push(0);
    }

    /// The nearest target element of `class` within its pairing radius of `p` not
    /// already paired in this pass.
    fn nearest_unpaired(&self, p: Point, class: u32) -> Option<(u32, f64)> {
        let d = self.reference.pair_radius[class as usize];
        let mut best: Option<(u32, f64)> = None;
        let mut best_d2 = d * d;
        self.grid.for_each_near(p, d, |id| {
            let e = &self.placed[id as usize];
            if e.class == class && self.used[id as usize] != self.stamp {
                let d2 = (e.pos - p).hypot2();
                if d2 < best_d2 {
                    best_d2 = d2;
                    best = Some((id, d2));
                }
            }
        });
        best
    }

    /// Whether something already in the target sits where an element of `class` at `p`
    /// would be stacked on it.
    fn occupied(&self, p: Point, class: u32) -> bool {
        let same = self.reference.pair_radius[class as usize];
        let cross = self.reference.cross_radius;
        let mut hit = false;
        self.grid.for_each_near(p, same.max(cross), |id| {
            let e = &self.placed[id as usize];
            let r = if e.class == class { same } else { cross };
            hit |= (e.pos - p).hypot2() < r * r;
        });
        hit
    }

    /// Pairs the window of reference element `r`, placed so that `r` lands at `at`.
    /// Fills `self.pairs` (window index, target id); returns the squared-error sum and
    /// the sum of pair offsets. Stops early (returning `None`) once fewer than `need`
    /// pairs are still possible.
    fn pair(&mut self, r: u32, at: Point, need: usize) -> Option<(f64, Vec2)> {
        self.stamp = self.stamp.wrapping_add(1);
        if self.stamp == 0 {
            self.used.iter_mut().for_each(|u| *u = 0);
            self.stamp = 1;
        }
        self.pairs.clear();
        let (mut err, mut sum) = (0.0, Vec2::ZERO);
        let window = &self.reference.window[r as usize];
        for (k, &(j, off)) in window.iter().enumerate() {
            if self.pairs.len() + (window.len() - k) < need {
                return None;
            }
            let p = at + off;
            let class = self.reference.elems[j as usize].class;
            if let Some((t, d2)) = self.nearest_unpaired(p, class) {
                self.used[t as usize] = self.stamp;
                self.pairs.push((k as u32, t));
                err += d2;
                sum += self.placed[t as usize].pos - p;
            }
        }
        Some((err, sum))
    }

    /// Pairs, refines `t` by least squares until the pairing is stable, and counts what
    /// the candidate would add. `None` when the first pairing already falls short of
    /// `need` pairs (such a candidate could not be well supported).
    fn evaluate(&mut self, g: Point, r: u32, need: usize, eligible: usize) -> Option<Candidate> {
        let origin = self.reference.elems[r as usize].pos;
        let base = g - origin;
        let settle = 0.1 * self.reference.pair_radius[self.reference.elems[r as usize].class as usize];
        let mut delta = Vec2::ZERO;
        let mut error = f64::INFINITY;
        for iteration in 0..MAX_REFINEMENTS {
            let (err, sum) = self.pair(r, origin + base + delta, if iteration == 0 { need } else { 0 })?;
            let n = self.pairs.len();
            if n == 0 || (iteration > 0 && self.pairs == self.previous) {
                break;
            }
            // Least squares: moving by the mean offset lowers the squared sum by n|mean|^2,
            // so the refined error needs no second pass unless the pairing may change.
            let mean = sum / n as f64;
            delta += mean;
            error = (err - n as f64 * mean.hypot2()).max(0.0) / n as f64;
            if mean.hypot() < settle {
                break;
            }
            std::mem::swap(&mut self.pairs, &mut self.previous);
        }
        let pairs = self.pairs.len();
        // A candidate short of the support ratio so far can never be chosen: skip counting.
        let mut adds = 0;
        if pairs >= eligible.max(1) {
            let mut conflicts = 0;
            for (j, p) in self.unpaired(r, origin + base + delta) {
                if !self.fill_holes && self.conflicts(j, p) {
                    conflicts += 1;
                } else {
                    adds += 1;
                }
            }
            // A candidate whose new elements would sit among existing ones that the
            // example does not have there is misaligned: its adds are strays.
            if conflicts > 0 {
                adds = 0;
            }
        }
        Some(Candidate { source: r, delta: base + delta, pairs, error, adds })
    }

    /// Window elements left unpaired by the last `pair` call that would land inside the
    /// area on free ground: (reference index, position).
    fn unpaired(&self, r: u32, at: Point) -> impl Iterator<Item = (u32, Point)> + '_ {
        // `pairs` is in window order, so one cursor tells which entries were paired.
        let mut paired = self.pairs.iter().map(|&(k, _)| k as usize).peekable();
        self.reference.window[r as usize].iter().enumerate().filter_map(move |(k, &(j, off))| {
            if paired.next_if_eq(&k).is_some() {
                return None;
            }
            let p = at + off;
            let class = self.reference.elems[j as usize].class;
            let free = self.inside(p) && !self.occupied(p, class);
            // Filling holes adds only inside them, never among regular elements.
            let wanted = !self.fill_holes || self.cover_cell(p).is_some_and(|c| self.cover[c] < self.hole_below);
            (free && wanted).then_some((j, p))
        })
    }

    /// Whether placing reference element `j` at `p` contradicts the target: a target
    /// element close to `p` with no counterpart at the same offset from `j` in the
    /// example. Only elements surrounded in the example are judged (elsewhere a missing
    /// counterpart may just lie beyond the example's edge).
    fn conflicts(&self, j: u32, p: Point) -> bool {
        let reference = self.reference;
        if !reference.surrounded[j as usize] {
            return false;
        }
        let rho = CONFLICT_RADIUS * reference.spacing;
        let rj = reference.elems[j as usize].pos;
        let mut conflict = false;
        self.grid.for_each_near(p, rho, |id| {
            if conflict {
                return;
            }
            let q = &self.placed[id as usize];
            let o = q.pos - p;
            let x = rj + o;
            if o.hypot2() < rho * rho && !reference.has(x, q.class) {
                conflict = true;
            }
        });
        conflict
    }

    /// Whether the neighbourhood of target element `e` is already as populated as a
    /// deep-interior neighbourhood of the reference: then it is no frontier point.
    /// Also full: an element whose source is surrounded in the example and whose
    /// source's neighbours (within the conflict radius and a spacing) are all present;
    /// this catches irregular motifs, whose neighbourhood populations vary.
    fn full(&self, e: usize) -> bool {
        let Placed { pos, class, source } = self.placed[e];
        let reference = self.reference;
        if let Some(want) = reference.full_count[class as usize] {
            let r2 = reference.near_radius.powi(2);
            let mut count = 0;
            self.grid.for_each_near(pos, reference.near_radius, |id| {
                count += ((self.placed[id as usize].pos - pos).hypot2() <= r2) as usize;
            });
            if count >= want {
                return true;
            }
        }
        if !reference.surrounded[source as usize] {
            return false;
        }
        let reach = (CONFLICT_RADIUS + 1.0) * reference.spacing;
        reference.window[source as usize].iter().take_while(|(_, off)| off.hypot2() <= reach * reach).all(
            |&(j, off)| {
                let p = pos + off;
                !self.inside(p) || self.occupied(p, reference.elems[j as usize].class)
            },
        )
    }

    /// Grows from the elements `start` (and all they add), nearest the centre first.
    /// `relaxed`: only around holes, taking the candidate that adds the most.
    fn run(
        &mut self,
        start: &[u32],
        opts: &GrowOptions,
        relaxed: bool,
        estimate: f64,
        progress: &mut Throttle,
        stats: &mut GrowStats,
    ) -> Result<()> {
        let reference = self.reference;
        self.fill_holes = relaxed;
        let centre = self.area.center();
        let key = |p: Point| (p - centre).hypot2().to_bits();
        let mut queue: BinaryHeap<Reverse<(u64, u32)>> =
            start.iter().map(|&i| Reverse((key(self.placed[i as usize].pos), i))).collect();
        let mut candidates: Vec<Candidate> = Vec::new();
        let mut processed = 0usize;
        while let Some(Reverse((_, gi))) = queue.pop() {
            processed += 1;
            if !relaxed {
                progress.tick(processed as f64 / estimate.max(self.placed.len() as f64).max(1.0))?;
            }
            let g = self.placed[gi as usize];
            if relaxed && !self.near_hole(g.pos) {
                continue;
            }
            if !relaxed && opts.frontier_first && self.full(gi as usize) {
                stats.skipped_full += 1;
                continue;
            }
            stats.growing_points += 1;
            candidates.clear();
            let mut most_pairs = 0;
            // The growing point's own source first: it usually pairs the most, which lets
            // the weak candidates after it be dropped early.
            let own = std::iter::once(g.source);
            let others = reference.by_class[g.class as usize].iter().copied().filter(|&r| r != g.source);
            if !relaxed {
                self.signature(gi);
            }
            for r in own.chain(others) {
                // Cheap test first: the growing point's nearest neighbours must be found
                // around `r` too (all but one of them: `r` may sit on the example's edge).
                if !relaxed && !self.matches_signature(r) {
                    continue;
                }
                let factor = if relaxed { (0.0, 0.0) } else { (PRUNE, opts.support) };
                let need = (factor.0 * most_pairs as f64).ceil() as usize;
                let eligible = (factor.1 * most_pairs as f64).ceil() as usize;
                let Some(c) = self.evaluate(g.pos, r, need, eligible) else { continue };
                most_pairs = most_pairs.max(c.pairs);
                if c.adds > 0 {
                    candidates.push(c);
                }
            }
            stats.candidates += reference.by_class[g.class as usize].len();
            let need = if relaxed { 1 } else { ((opts.support * most_pairs as f64).ceil() as usize).max(1) };
            // Errors closer than this count as equal; among them the candidate that adds the
            // most wins (bigger stamps, fewer growing points), then the best supported.
            let tiny = ((ERROR_QUANTUM * reference.pair_radius[g.class as usize]).powi(2)).max(1e-300);
            let best = candidates.iter().filter(|c| c.pairs >= need).min_by(|a, b| {
                let (ea, eb) = ((a.error / tiny).floor(), (b.error / tiny).floor());
                if relaxed {
                    b.adds.cmp(&a.adds).then(ea.total_cmp(&eb))
                } else {
                    ea.total_cmp(&eb).then(b.adds.cmp(&a.adds)).then(b.pairs.cmp(&a.pairs))
                }
            });
            let Some(best) = best.copied() else {
                stats.passed_over += 1;
                continue;
            };
            let before = self.placed.len();
            self.stamp_candidate(&best);
            for i in before..self.placed.len() {
                queue.push(Reverse((key(self.placed[i].pos), i as u32)));
            }
            if self.placed.len() > opts.max_elements {
                return Err(Error::TooLarge(format!("Growth passed the limit of {} elements.", opts.max_elements)));
            }
        }
        Ok(())
    }

    fn cover_cell(&self, p: Point) -> Option<usize> {
        let (cols, rows, sx, sy) = self.cover_dims;
        let cx = ((p.x - self.area.x0) / sx).floor().min(cols as f64 - 1.0);
        let cy = ((p.y - self.area.y0) / sy).floor().min(rows as f64 - 1.0);
        (cx >= 0.0 && cy >= 0.0 && (cx as usize) < cols && (cy as usize) < rows)
            .then(|| cy as usize * cols + cx as usize)
    }

    /// Coverage cells (a window across) that hold no element.
    fn holes(&self) -> usize {
        self.cover.iter().filter(|&&c| c == 0).count()
    }

    /// Whether an empty coverage cell touches the window around `p`.
    fn near_hole(&self, p: Point) -> bool {
        let r = self.reference.window_radius;
        let (cols, rows, sx, sy) = self.cover_dims;
        let x0 = ((p.x - r - self.area.x0) / sx).floor().max(0.0) as usize;
        let y0 = ((p.y - r - self.area.y0) / sy).floor().max(0.0) as usize;
        let x1 = (((p.x + r - self.area.x0) / sx).floor().max(0.0) as usize).min(cols - 1);
        let y1 = (((p.y + r - self.area.y0) / sy).floor().max(0.0) as usize).min(rows - 1);
        (y0..=y1).any(|y| (x0..=x1).any(|x| self.cover[y * cols + x] < self.hole_below))
    }

    /// Records the offsets and classes of the few target elements nearest to `gi`.
    fn signature(&mut self, gi: u32) {
        let g = self.placed[gi as usize].pos;
        let radius = 1.5 * self.reference.spacing;
        let mut near: Vec<(f64, Vec2, u32)> = Vec::new();
        self.grid.for_each_near(g, radius, |id| {
            let e = &self.placed[id as usize];
            let d2 = (e.pos - g).hypot2();
            if id != gi && d2 < radius * radius {
                near.push((d2, e.pos - g, e.class));
            }
        });
        near.sort_by(|a, b| a.0.total_cmp(&b.0));
        self.sig.clear();
        self.sig.extend(near.iter().take(SIGNATURE).map(|&(_, o, c)| (o, c)));
    }

    fn matches_signature(&self, r: u32) -> bool {
        let at = self.reference.elems[r as usize].pos;
        let mut missed = 0;
        for &(o, c) in &self.sig {
            if !self.reference.has(at + o, c) {
                missed += 1;
                if missed > 1 {
                    return false;
                }
            }
        }
        true
    }

    /// Applies candidate `c` at growing point `g`: adds every free window element.
    fn stamp_candidate(&mut self, c: &Candidate) -> usize {
        let r = c.source;
        let at = self.reference.elems[r as usize].pos + c.delta;
        self.pair(r, at, 0);
        let adds: Vec<(u32, Point)> = self.unpaired(r, at).collect();
        let mut added = 0;
        for (j, p) in adds {
            // Re-check: two window elements may land on each other.
            let hole = !self.fill_holes || self.cover_cell(p).is_some_and(|c| self.cover[c] < self.hole_below);
            if !self.occupied(p, self.reference.elems[j as usize].class) && (hole || !self.fill_holes) {
                self.add(p, j);
                added += 1;
            }
        }
        added
    }
}

/// The lattice fitted to `elems` (see `lattice`), or `None` when they are not periodic
/// enough; an error for input with no spacing at all.
pub fn fit_lattice(elems: &[Element]) -> Result<Option<lattice::LatticeFit>> {
    let r = Reference::new(elems)?;
    Ok(lattice::fit(elems, &r.grid, &r.pair_radius, r.spacing, r.window_radius))
}

/// The translational periods of `elems` (see `period`), or `None` when they are not
/// periodic in two directions; an error for input with no spacing at all.
pub fn find_periods(elems: &[Element]) -> Result<Option<period::Periods>> {
    let spread = Spread::new(elems)?;
    Ok(period::find(elems, &spread.grid, spread.spacing))
}

/// Grows the reference `elems` over a `width x height` area.
pub fn grow(elems: &[Element], opts: &GrowOptions, progress: &mut Throttle) -> Result<(Vec<Placed>, GrowStats)> {
    let raw_elems = elems;
    if !(opts.width.is_finite() && opts.height.is_finite() && opts.width > 0.0 && opts.height > 0.0) {
        return invalid("Output width and height must be positive numbers.");
    }
    if let Some(i) = elems.iter().position(|e| !(e.pos.x.is_finite() && e.pos.y.is_finite())) {
        return invalid(format!("Element {i} has a position that is not a finite number."));
    }
    let spread = Spread::new(elems)?;
    // A periodic example (a tile repeated, a hand-drawn grid) needs no growth: its
    // exact periodic extension has every site and no drift (see `period`).
    if opts.regularize {
        if let Some(periods) = period::find(elems, &spread.grid, spread.spacing) {
            let area = Rect::new(0.0, 0.0, opts.width, opts.height);
            let placed = period::extend(elems, &opts.extents, &periods, area, opts.max_elements, progress)?;
            progress.tick(1.0)?;
            return Ok((placed, GrowStats::default()));
        }
    }
    let drawn = Reference::on(elems, spread)?;
    let fit = if opts.regularize {
        lattice::fit(elems, &drawn.grid, &drawn.pair_radius, drawn.spacing, drawn.window_radius)
    } else {
        None
    };
    let snapped: Vec<Element> = match &fit {
        Some(f) => elems.iter().zip(&f.snapped).map(|(e, &pos)| Element { pos, class: e.class }).collect(),
        None => Vec::new(),
    };
    let reference = if fit.is_some() { Reference::new(&snapped)? } else { drawn };
    let elems = reference.elems;
    let area = Rect::new(0.0, 0.0, opts.width, opts.height);
    let estimate = reference.density() * area.area();
    if estimate > opts.max_elements as f64 {
        return Err(Error::TooLarge(format!(
            "This output would hold about {:.0} elements; the limit is {}. Use a smaller output or larger strokes.",
            estimate, opts.max_elements
        )));
    }
    let max_radius = reference.pair_radius.iter().copied().fold(reference.cross_radius, f64::max);
    // Coverage cells about half a window across (wider than any gap of a regular
    // pattern, so only irregular input leaves holes), tiling the area exactly.
    let cover_size = (0.5 * reference.window_radius).max(3.0 * reference.spacing);
    let cols = (area.width() / cover_size).round().max(1.0);
    let rows = (area.height() / cover_size).round().max(1.0);
    let cover_dims = (cols as usize, rows as usize, area.width() / cols, area.height() / rows);
    if (cover_dims.0 as f64) * (cover_dims.1 as f64) > 4.0 * opts.max_elements as f64 {
        return Err(Error::TooLarge("The output is too large for the spacing of these strokes.".into()));
    }
    let mut target = Target {
        reference: &reference,
        area,
        placed: Vec::new(),
        grid: Grid::new(
            area,
            2.0 * max_radius.max(reference.spacing * 0.5),
            (estimate as usize).saturating_mul(4) + 64,
        ),
        used: Vec::new(),
        stamp: 0,
        pairs: Vec::new(),
        previous: Vec::new(),
        cover: vec![0; cover_dims.0 * cover_dims.1],
        cover_dims,
        fill_holes: false,
        sig: Vec::new(),
        hole_below: (0.9 * reference.density() * cover_dims.2 * cover_dims.3).max(1.0) as u32,
    };
    let bounds = reference.bounds;
    let shift = area.center() - bounds.center();
    for (i, e) in elems.iter().enumerate() {
        let p = e.pos + shift;
        if target.inside(p) && !target.occupied(p, e.class) {
            target.add(p, i as u32);
        }
    }

    let mut stats = GrowStats::default();
    let all: Vec<u32> = (0..target.placed.len() as u32).collect();
    target.run(&all, opts, false, estimate, progress, &mut stats)?;
    // Irregular input leaves the area partly empty (no candidate is well supported):
    // fill what is left with the candidates that add the most, so the output is
    // still covered, as a person would expect, with the example's local arrangement.
    if !reference.is_row() && target.holes() > 0 {
        let all: Vec<u32> = (0..target.placed.len() as u32).collect();
        target.run(&all, opts, true, estimate, progress, &mut stats)?;
    }
    progress.tick(1.0)?;
    let mut placed = target.placed;
    if fit.is_some() {
        // Each element takes its source's deviation from the lattice back.
        for e in &mut placed {
            let s = e.source as usize;
            e.pos += raw_elems[s].pos - snapped[s].pos;
        }
    }
    Ok((placed, stats))
}
