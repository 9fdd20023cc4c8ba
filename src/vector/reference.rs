//! What growth reads about the example, computed once: where its elements are and how
//! far apart (`Spread`), and per element and class the neighbourhoods, radii and
//! closest approaches that pairing, stamping and the frontier test use (`Reference`).

use super::classify::median;
use super::element::Element;
use super::spatial::Grid;
use crate::error::{invalid, Result};
use kurbo::{Point, Rect, Vec2};

/// Radius, in spacings, within which a new element's neighbours must agree with the example.
pub(super) const CONFLICT_RADIUS: f64 = 1.25;

/// Neighbours of a reference element within some radius: index and offset.
pub(super) type Neighbourhood = Vec<(u32, Vec2)>;

/// Everything about the reference that growth reads, computed once.
pub(super) struct Reference<'a> {
    pub(super) elems: &'a [Element],
    /// Each class's members, in a fixed random order from which large classes offer a
    /// rotating sample of candidates (see `CANDIDATES`).
    pub(super) members: Vec<Vec<u32>>,
    /// Pairing radius per class.
    pub(super) pair_radius: Vec<f64>,
    /// Radius within which an element of another class blocks stamping.
    pub(super) cross_radius: f64,
    /// Closest approach per pair of classes.
    pub(super) apart: Apart,
    /// Window neighbours of each element (itself included), nearest first.
    pub(super) window: Vec<Neighbourhood>,
    /// Radius of the disc whose population tells whether a neighbourhood is full.
    pub(super) near_radius: f64,
    /// Per class: elements of any class within `near_radius` of a deep-interior reference
    /// element of that class (median); `None` when the reference has no deep interior.
    pub(super) full_count: Vec<Option<usize>>,
    /// Median distance between neighbouring elements (any class).
    pub(super) spacing: f64,
    /// Radius of the windows.
    pub(super) window_radius: f64,
    /// The reference elements, indexed by position.
    pub(super) grid: Grid,
    /// Bounding box of the element positions.
    pub(super) bounds: Rect,
    /// Elements with neighbours in every direction within the conflict radius and a
    /// spacing: their neighbourhood in the example is complete.
    pub(super) surrounded: Vec<bool>,
}

/// Each element's distance to its nearest other (of its class, with `same_class`)
/// further than `beyond`; pass a negative `beyond` to count coincident elements.
fn nearest_distances(elems: &[Element], same_class: bool, beyond: f64, grid: &Grid, scale: f64) -> Vec<f64> {
    // An element alone in its class has no other: without this, the search widened to
    // the whole drawing for each (20,000 strokes of distinct shapes took 11 s).
    let mut members = vec![0usize; elems.iter().map(|e| e.class as usize + 1).max().unwrap_or(0)];
    elems.iter().for_each(|e| members[e.class as usize] += 1);
    elems
        .iter()
        .enumerate()
        .map(|(i, e)| {
            if (same_class && members[e.class as usize] < 2) || elems.len() < 2 {
                return f64::INFINITY;
            }
            let mut radius = scale;
            loop {
                let mut best = f64::INFINITY;
                grid.for_each_near(e.pos, radius, |j| {
                    let o = &elems[j as usize];
                    if j as usize == i || (same_class && o.class != e.class) {
                        return;
                    }
                    let d = o.pos.distance(e.pos);
                    if d > beyond && d < best {
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

/// Candidates evaluated per growing point: a class with more members offers a
/// rotating sample of this many (besides the growing point's own source), so the cost
/// of a growing point does not grow with the example. In a pattern every interior member
/// proposes the same translations, so a sample finds them; on irregular input no member
/// is much better supported than another.
pub(super) const CANDIDATES: usize = 64;

/// Seed of the candidate sample's order (growth is deterministic).
const SAMPLE_SEED: u64 = 0x5eed;

/// Within this many spacings the closest approach of two classes is measured; classes
/// never that close in the example are kept at least this far apart (less the margin).
const APART_REACH: f64 = 2.0;

/// Fraction of the example's closest approach that a stamped element must keep: the
/// margin for hand-drawn jitter.
const APART_MARGIN: f64 = 0.9;

/// Classes beyond which the closest approach is kept for all classes at once (the
/// table's size is quadratic).
const APART_CLASSES: usize = 256;

/// How near the example ever brings an element of one class to one of another, less a
/// margin: nothing is stamped nearer, so grown output keeps the example's density.
pub(super) struct Apart {
    classes: usize,
    /// Row-major `classes x classes`; empty when there are too many classes.
    table: Vec<f64>,
    /// The closest approach of any two elements (used without a table).
    any: f64,
    /// The largest distance `get` returns: the radius of a query that finds every conflict.
    pub(super) max: f64,
}

impl Apart {
    fn new(elems: &[Element], grid: &Grid, classes: usize, spacing: f64) -> Apart {
        let reach = APART_REACH * spacing;
        let keep = classes <= APART_CLASSES;
        let mut table = vec![reach; if keep { classes * classes } else { 0 }];
        let mut any = reach;
        for (i, e) in elems.iter().enumerate() {
            grid.for_each_near(e.pos, reach, |j| {
                if j as usize != i {
                    let o = &elems[j as usize];
                    let d = o.pos.distance(e.pos);
                    any = any.min(d);
                    if keep {
                        let k = e.class as usize * classes + o.class as usize;
                        table[k] = table[k].min(d);
                    }
                }
            });
        }
        table.iter_mut().for_each(|d| *d *= APART_MARGIN);
        any *= APART_MARGIN;
        let max = table.iter().copied().fold(any, f64::max);
        Apart { classes, table, any, max }
    }

    /// The distance an element of class `a` keeps from one of class `b`.
    #[inline]
    pub(super) fn get(&self, a: u32, b: u32) -> f64 {
        self.table.get(a as usize * self.classes + b as usize).copied().unwrap_or(self.any)
    }
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
pub(super) struct Spread {
    pub(super) bounds: Rect,
    pub(super) grid: Grid,
    /// The grid's cell size, the scale of neighbour searches.
    pub(super) rough: f64,
    pub(super) spacing: f64,
}

impl Spread {
    pub(super) fn new(elems: &[Element]) -> Result<Self> {
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
        let mut any = nearest_distances(elems, false, rough * 1e-9, &grid, rough);
        let spacing = median(&mut any);
        if !spacing.is_finite() || spacing <= 0.0 {
            return invalid("All strokes are centred on the same point: there is no spacing to repeat.");
        }
        Ok(Spread { bounds, grid, rough, spacing })
    }

    /// The spacing without near-coincident neighbours: the median distance to the
    /// nearest element further than a quarter of the median distance between elements
    /// of one class. The parts of a motif drawn on one another (the two strokes of a
    /// hand-drawn cross, a fraction of a unit apart) say nothing of the period.
    pub(super) fn apart(&self, elems: &[Element]) -> f64 {
        let finite = |d: Vec<f64>| -> Vec<f64> { d.into_iter().filter(|d| d.is_finite()).collect() };
        let mut same = finite(nearest_distances(elems, true, self.rough * 1e-9, &self.grid, self.rough));
        let floor = 0.25 * median(&mut same);
        let mut any = finite(nearest_distances(elems, false, floor.max(self.rough * 1e-9), &self.grid, self.rough));
        match median(&mut any) {
            m if m > 0.0 => m,
            _ => self.spacing,
        }
    }
}

impl<'a> Reference<'a> {
    pub(super) fn new(elems: &'a [Element]) -> Result<Self> {
        Reference::on(elems, Spread::new(elems)?)
    }

    pub(super) fn on(elems: &'a [Element], spread: Spread) -> Result<Self> {
        let Spread { bounds, grid, rough, spacing } = spread;
        let (n, extent) = (elems.len(), bounds.width().max(bounds.height()));
        let mut with_coincident = nearest_distances(elems, false, -1.0, &grid, rough);
        let cross_radius = 0.5 * median(&mut with_coincident);

        let classes = elems.iter().map(|e| e.class as usize + 1).max().unwrap_or(0);
        let mut by_class = vec![Vec::new(); classes];
        for (i, e) in elems.iter().enumerate() {
            by_class[e.class as usize].push(i as u32);
        }
        let same = nearest_distances(elems, true, rough * 1e-9, &grid, rough);
        let pair_radius = (0..classes)
            .map(|c| {
                let mut d: Vec<f64> = by_class[c].iter().map(|&i| same[i as usize]).filter(|d| d.is_finite()).collect();
                let m = median(&mut d);
                0.5 * if m > 0.0 { m } else { spacing }
            })
            .collect();

        let mut rng = crate::rng::Rng::new(SAMPLE_SEED);
        let members: Vec<Vec<u32>> = by_class
            .into_iter()
            .map(|mut m| {
                if m.len() > CANDIDATES {
                    for i in (1..m.len()).rev() {
                        m.swap(i, rng.below(i + 1));
                    }
                }
                m
            })
            .collect();
        let apart = Apart::new(elems, &grid, classes, spacing);
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
        let full_count = members
            .iter()
            .map(|class| {
                let counts: Vec<f64> = class
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
            members,
            pair_radius,
            cross_radius,
            apart,
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
    pub(super) fn is_row(&self) -> bool {
        let b = self.bounds;
        b.width().min(b.height()) < self.spacing
    }

    /// Whether an element of `class` lies within its pairing radius of `p`.
    pub(super) fn has(&self, p: Point, class: u32) -> bool {
        let d = self.pair_radius[class as usize];
        let mut hit = false;
        self.grid.for_each_near(p, d, |j| {
            let e = &self.elems[j as usize];
            hit |= e.class == class && (e.pos - p).hypot2() < d * d;
        });
        hit
    }

    pub(super) fn density(&self) -> f64 {
        let b = self.bounds;
        let area = (b.width() + self.spacing) * (b.height() + self.spacing);
        self.elems.len() as f64 / area.max(1e-12)
    }
}
