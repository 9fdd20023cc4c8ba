//! Reference/target growth (SPEC 1.2-1.3): the heart of the vector engine.
//!
//! `grow` takes the example by the first route that fits it:
//! - a periodic example (a tile repeated, a hand-drawn grid) is extended exactly along
//!   its periods (`period`);
//! - a near-regular one grows by the paper's rule on its fitted lattice (`lattice`), each
//!   element then taking its source's deviation back;
//! - an irregular one (no period, no lattice) becomes a mosaic of its own windows
//!   (`mosaic`);
//! - with `regularize: false`, every example grows by the paper's rule on its drawn
//!   positions, and holes left by it are filled (`fill`).
//!
//! The paper's rule: the reference pattern is a set of point elements (class,
//! position). The target starts as one copy of the reference at the centre of the
//! output area and grows outward: at each growing point `g`, same-class reference
//! elements `r` propose the translation `t = g - r`; under `t` the reference is paired
//! with the target, `t` is refined by least squares (the mean pair offset), and the
//! best-supported candidate that adds something is stamped.
//!
//! Three departures from a literal reading keep the cost near-linear in the number of
//! output elements:
//! - a candidate is judged on a *window* of the reference (its neighbours within a
//!   few spacings of `r`), found through precomputed neighbour lists and a uniform grid
//!   over the target, and only that window is stamped;
//! - a growing point tries a rotating sample of at most `CANDIDATES` members of its
//!   class, so its cost does not grow with the example;
//! - growth runs along the frontier: a target element whose source is interior to the
//!   reference and whose reference neighbourhood is already present is passed over
//!   without evaluating candidates (it would add nothing).

pub use super::element::{Element, Placed};
use super::lattice;
use super::mosaic;
use super::period;
use super::reference::{Reference, Spread, CANDIDATES, CONFLICT_RADIUS};
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
    /// Seeds the windows free growth cuts from an irregular example (see `mosaic`).
    pub seed: u64,
    /// Periods a designer set: the example is extended on them, whatever it shows.
    pub periods: Option<(Vec2, Vec2)>,
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
            seed: 1,
            periods: None,
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

mod fill;

/// Growing points by distance from the centre, nearest first.
type Queue = BinaryHeap<Reverse<(u64, u32)>>;

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
        let reference = self.reference;
        let same = reference.pair_radius[class as usize];
        let cross = reference.cross_radius;
        let mut hit = false;
        self.grid.for_each_near(p, same.max(cross).max(reference.apart.max), |id| {
            let e = &self.placed[id as usize];
            let r = if e.class == class { same } else { cross };
            let r = r.max(reference.apart.get(class, e.class));
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

    /// The candidates for growing point `gi`: its own source first (it usually pairs the
    /// most, which lets the weak candidates after it be dropped early), then a rotating
    /// sample of at most `CANDIDATES` members of its class.
    fn candidates(&self, gi: u32) -> impl Iterator<Item = u32> + 'r {
        let g = self.placed[gi as usize];
        let members = &self.reference.members[g.class as usize];
        // Consecutive growing points start the sample at spread-out places.
        let from = (gi as usize).wrapping_mul(0x9E37_79B1) % members.len();
        let others = members.iter().cycle().skip(from).take(members.len().min(CANDIDATES));
        std::iter::once(g.source).chain(others.copied().filter(move |&r| r != g.source))
    }

    /// Stamps `best` and queues what it adds as growing points.
    fn stamp_and_queue(&mut self, best: &Candidate, queue: &mut Queue, max_elements: usize) -> Result<()> {
        let before = self.placed.len();
        self.stamp_candidate(best);
        for i in before..self.placed.len() {
            queue.push(Reverse((self.key(self.placed[i].pos), i as u32)));
        }
        if self.placed.len() > max_elements {
            return Err(Error::TooLarge(format!("Growth passed the limit of {max_elements} elements.")));
        }
        Ok(())
    }

    /// Growing points are taken nearest the centre first.
    fn key(&self, p: Point) -> u64 {
        (p - self.area.center()).hypot2().to_bits()
    }

    fn queue(&self, start: &[u32]) -> Queue {
        start.iter().map(|&i| Reverse((self.key(self.placed[i as usize].pos), i))).collect()
    }

    /// The paper's growth (SPEC 1.3) from the elements `start` and all they add: at each
    /// growing point the eligible candidate (well supported, adding something, no
    /// conflict) with the least error is stamped.
    fn run(
        &mut self,
        start: &[u32],
        opts: &GrowOptions,
        estimate: f64,
        progress: &mut Throttle,
        stats: &mut GrowStats,
    ) -> Result<()> {
        let reference = self.reference;
        let mut queue = self.queue(start);
        let mut candidates: Vec<Candidate> = Vec::new();
        let mut processed = 0usize;
        while let Some(Reverse((_, gi))) = queue.pop() {
            processed += 1;
            progress.tick(processed as f64 / estimate.max(self.placed.len() as f64).max(1.0))?;
            let g = self.placed[gi as usize];
            if opts.frontier_first && self.full(gi as usize) {
                stats.skipped_full += 1;
                continue;
            }
            stats.growing_points += 1;
            candidates.clear();
            let mut most_pairs = 0;
            self.signature(gi);
            for r in self.candidates(gi) {
                stats.candidates += 1;
                // Cheap test first: the growing point's nearest neighbours must be found
                // around `r` too (all but one of them: `r` may sit on the example's edge).
                if !self.matches_signature(r) {
                    continue;
                }
                let need = (PRUNE * most_pairs as f64).ceil() as usize;
                let eligible = (opts.support * most_pairs as f64).ceil() as usize;
                let Some(c) = self.evaluate(g.pos, r, need, eligible) else { continue };
                most_pairs = most_pairs.max(c.pairs);
                if c.adds > 0 {
                    candidates.push(c);
                }
            }
            let need = ((opts.support * most_pairs as f64).ceil() as usize).max(1);
            // Errors closer than this count as equal; among them the candidate that adds the
            // most wins (bigger stamps, fewer growing points), then the best supported.
            let tiny = ((ERROR_QUANTUM * reference.pair_radius[g.class as usize]).powi(2)).max(1e-300);
            let best = candidates.iter().filter(|c| c.pairs >= need).min_by(|a, b| {
                let (ea, eb) = ((a.error / tiny).floor(), (b.error / tiny).floor());
                ea.total_cmp(&eb).then(b.adds.cmp(&a.adds)).then(b.pairs.cmp(&a.pairs))
            });
            let Some(best) = best.copied() else {
                stats.passed_over += 1;
                continue;
            };
            self.stamp_and_queue(&best, &mut queue, opts.max_elements)?;
        }
        Ok(())
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

/// What growth made: the placed elements, how it went, and the orbit of each reference
/// element: the example elements that are copies of one place of the pattern (one motif
/// position under the periods or the fitted lattice; the class where there is neither).
/// Variation dresses a placed element with a copy from its source's orbit, never with
/// another place's element of the same class.
pub struct Grown {
    pub placed: Vec<Placed>,
    pub stats: GrowStats,
    pub orbit: Vec<u32>,
    /// The periods the output repeats on (found, fitted or given; none for free growth).
    pub periods: Option<(Vec2, Vec2)>,
}

/// Grows the reference `elems` over a `width x height` area.
pub fn grow(elems: &[Element], opts: &GrowOptions, progress: &mut Throttle) -> Result<Grown> {
    let raw_elems = elems;
    if !(opts.width.is_finite() && opts.height.is_finite() && opts.width > 0.0 && opts.height > 0.0) {
        return invalid("Output width and height must be positive numbers.");
    }
    if let Some(i) = elems.iter().position(|e| !(e.pos.x.is_finite() && e.pos.y.is_finite())) {
        return invalid(format!("Element {i} has a position that is not a finite number."));
    }
    let area = Rect::new(0.0, 0.0, opts.width, opts.height);
    if let Some((a, b)) = opts.periods {
        let periods = lattice::on_periods(elems, a, b).periods(elems).expect("a lattice of two periods");
        let placed = period::extend(elems, &opts.extents, &periods, area, opts.max_elements, progress)?;
        progress.tick(1.0)?;
        return Ok(Grown { placed, stats: GrowStats::default(), orbit: periods.motif, periods: Some((a, b)) });
    }
    let spread = Spread::new(elems)?;
    // A periodic example (a tile repeated, a hand-drawn grid) needs no growth: its
    // exact periodic extension has every site and no drift (see `period`).
    if opts.regularize {
        if let Some(periods) = period::find(elems, &spread.grid, spread.spacing) {
            let placed = period::extend(elems, &opts.extents, &periods, area, opts.max_elements, progress)?;
            progress.tick(1.0)?;
            let found = Some((periods.a, periods.b));
            return Ok(Grown { placed, stats: GrowStats::default(), orbit: periods.motif, periods: found });
        }
    }
    let drawn = Reference::on(elems, spread)?;
    let fit = if opts.regularize {
        lattice::fit(elems, &drawn.grid, &drawn.pair_radius, drawn.spacing, drawn.window_radius)
    } else {
        None
    };
    // No period and no lattice: an irregular example grows as a mosaic of its own windows.
    if opts.regularize && fit.is_none() && mosaic::applies(&drawn) {
        let placed = mosaic::mosaic(&drawn, &opts.extents, area, opts.seed, opts.max_elements, progress)?;
        progress.tick(1.0)?;
        let orbit = elems.iter().map(|e| e.class).collect();
        return Ok(Grown { placed, stats: GrowStats::default(), orbit, periods: None });
    }
    let snapped: Vec<Element> = match &fit {
        Some(f) => elems.iter().zip(&f.snapped).map(|(e, &pos)| Element { pos, class: e.class }).collect(),
        None => Vec::new(),
    };
    let reference = if fit.is_some() { Reference::new(&snapped)? } else { drawn };
    let elems = reference.elems;
    let estimate = reference.density() * area.area();
    if estimate > opts.max_elements as f64 {
        return Err(Error::TooLarge(format!(
            "This output would hold about {:.0} elements; the limit is {}. Use a smaller output or larger strokes.",
            estimate, opts.max_elements
        )));
    }
    let max_radius =
        reference.pair_radius.iter().copied().fold(reference.cross_radius.max(reference.apart.max), f64::max);
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
    target.run(&all, opts, estimate, progress, &mut stats)?;
    // Irregular input leaves the area partly empty (no candidate is well supported):
    // fill what is left with the candidates that add the most, so the output is
    // still covered, as a person would expect, with the example's local arrangement.
    if !reference.is_row() && target.holes() > 0 {
        target.fill_holes(opts, &mut stats)?;
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
    let periods = fit.as_ref().and_then(|f| Some((f.a, f.b?)));
    let orbit = match fit {
        Some(f) => f.component,
        None => raw_elems.iter().map(|e| e.class).collect(),
    };
    Ok(Grown { placed, stats, orbit, periods })
}
