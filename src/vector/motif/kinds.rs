//! Kinds of motif instances, and the parts of each kind, from the drawing's own evidence.
//!
//! Two instances are copies of one motif when their strokes correspond one to one: each
//! stroke of one has a stroke of the other at about the same offset from the instance's
//! centre, with about the same shape (discrete Fréchet distance of the centred paths),
//! width and paint. The cost of a correspondence is its worst pair, over the instances'
//! size; instances join a kind below the largest clear gap of these costs (one kind when
//! there is no clear gap: a hand's copies differ continuously, different motifs by a
//! jump).
//!
//! A part is a stroke's place in its kind: the stroke of the kind's first instance it
//! corresponds to. The strokes of one part are copies of one another by the drawing's own
//! account, so hand variation can never merge two parts of a motif (the paper's global
//! split of pairwise distances does, once the wobble is as large as the difference
//! between parts). Parts of any kinds then share a class when they differ by no more than
//! the spread their own copies show (two identical eyes of a face), or, with an explicit
//! path tolerance, by less than it (the paper's `Match`).

use super::super::classify::{split_at_gap, Tolerances};
use super::super::color::paint_distance;
use super::super::frechet::Shape;
use super::super::stroke::Stroke;
use kurbo::{Point, Vec2};

/// Instances compared to propose the kinds' threshold (pairs grow quadratically).
const SAMPLE: usize = 24;
/// Members of a kind an instance is compared with before it starts a kind of its own.
const REPRESENTATIVES: usize = 4;
/// Candidate partners per stroke, nearest by offset, in a correspondence of a motif of
/// more than `ALL_PARTNERS` strokes (in a smaller one, every stroke is a candidate).
const PARTNERS: usize = 4;
const ALL_PARTNERS: usize = 8;
/// An incomplete copy's strokes must lie within this share of the motif's size of the
/// parts they stand for.
const INCOMPLETE: f64 = 0.25;
/// Part classes beyond which parts are not merged into shared classes (pairs grow
/// quadratically; each part then keeps its own class).
const MERGE_LIMIT: usize = 512;
/// Parts share a class within this multiple of the larger spread of their copies.
const SPREAD_MARGIN: f64 = 1.5;
/// The least spread, as a share of the median stroke size (exact copies spread by none).
const SPREAD_FLOOR: f64 = 0.03;

/// The instances' kinds, each stroke's part and class.
pub struct Kinds {
    /// Kind of each instance, numbered by first appearance.
    pub kind: Vec<u32>,
    /// Part of each stroke: its index in the first instance of its kind.
    pub part: Vec<u32>,
    /// Class of each stroke (parts that look alike share one), by first appearance.
    pub classes: Vec<u32>,
    /// Of each instance that is an incomplete copy: its kind's first instance and the
    /// translation from that to it (where the whole motif's centre would be).
    pub incomplete: Vec<Option<(usize, Vec2)>>,
}

/// One instance as compared: its strokes, their offsets from its centre and its size.
struct Instance {
    strokes: Vec<u32>,
    offsets: Vec<Vec2>,
    size: f64,
    centre: Point,
}

struct Context<'a> {
    strokes: &'a [Stroke],
    shapes: Vec<Shape>,
    tol: Tolerances,
}

impl Context<'_> {
    /// The correspondence of `b`'s strokes to `a`'s (for each stroke of `b`, its partner's
    /// index in `a`), with its cost (worst pair over the size) and each pair's shape
    /// distance; `None` when the counts differ or a stroke has no compatible partner.
    ///
    /// Pairs are matched greedily, cheapest first (a pair's cost: the larger of its
    /// offset and its shape distance, over the size). Each is measured only when it
    /// comes up, ordered until then by a lower bound (its offset, its extents), and
    /// not at all once its strokes are matched: of a rosette of eight petals against
    /// another, eight pairs of 64. With a finite `limit`, `None` too where the cost
    /// would exceed it (the same answer otherwise), and pairs over it are decided
    /// (`Shape::within`), not measured. Measuring every pair was a third of a cold call.
    fn correspond(&self, a: &Instance, b: &Instance, limit: f64) -> Option<(f64, Vec<u32>, Vec<f64>)> {
        let k = a.strokes.len();
        if k != b.strokes.len() {
            return None;
        }
        let scale = a.size.max(b.size).max(1e-9);
        let reach = limit * scale;
        let shape_of = |i: usize, j: usize| (&self.shapes[a.strokes[i] as usize], &self.shapes[b.strokes[j] as usize]);
        // (cost or its lower bound, measured, i, j, shape distance), the cheapest last.
        let mut pairs: Vec<(f64, bool, u32, u32, f64)> = Vec::new();
        for (j, &sb) in b.strokes.iter().enumerate() {
            let mut near: Vec<(f64, usize)> =
                a.offsets.iter().enumerate().map(|(i, o)| ((*o - b.offsets[j]).hypot(), i)).collect();
            near.sort_by(|x, y| x.0.total_cmp(&y.0));
            // Every stroke is a candidate in a small motif: the parts of an asterisk all
            // sit on its centre, and only their shapes tell them apart.
            let partners = if k <= ALL_PARTNERS { k } else { PARTNERS };
            for &(off, i) in near.iter().take(partners) {
                let sa = a.strokes[i];
                let (x, y) = (&self.strokes[sa as usize], &self.strokes[sb as usize]);
                if (x.width - y.width).abs() >= self.tol.width
                    || paint_distance(x.stroke, y.stroke) >= self.tol.color
                    || paint_distance(x.fill, y.fill) >= self.tol.color
                    || off > reach
                {
                    continue;
                }
                let (sx, sy) = shape_of(i, j);
                pairs.push((off.max(sx.extent_bound(sy)) / scale, false, i as u32, j as u32, 0.0));
            }
        }
        // Cheapest first; a bound before a measured cost equal to it (it may measure
        // equal, and then goes by its strokes' order as it would have).
        let order = |x: &(f64, bool, u32, u32, f64), y: &(f64, bool, u32, u32, f64)| {
            y.0.total_cmp(&x.0).then(y.1.cmp(&x.1)).then(y.2.cmp(&x.2)).then(y.3.cmp(&x.3))
        };
        pairs.sort_by(order);
        let (mut of_b, mut taken) = (vec![u32::MAX; k], vec![false; k]);
        let mut shapes = vec![0.0; k];
        let mut worst = 0.0f64;
        let mut left = k;
        while let Some(pair) = pairs.pop() {
            let (cost, measured, i, j, shape) = pair;
            if left == 0 || cost > limit {
                break;
            }
            if of_b[j as usize] != u32::MAX || taken[i as usize] {
                continue;
            }
            if !measured {
                let (sx, sy) = shape_of(i as usize, j as usize);
                if reach.is_finite() && !sx.within(sy, reach) {
                    continue;
                }
                let shape = sx.distance(sy);
                let off = (a.offsets[i as usize] - b.offsets[j as usize]).hypot();
                let measured = (off.max(shape) / scale, true, i, j, shape);
                pairs.insert(pairs.partition_point(|p| order(p, &measured).is_lt()), measured);
                continue;
            }
            of_b[j as usize] = i;
            taken[i as usize] = true;
            shapes[j as usize] = shape;
            worst = worst.max(cost);
            left -= 1;
        }
        of_b.iter().all(|&i| i != u32::MAX).then_some((worst, of_b, shapes))
    }
}

impl Context<'_> {
    /// Whether `part`'s strokes are some of `full`'s, under one translation (a copy left
    /// incomplete, or being drawn): the translation from `full` to it and, per stroke of
    /// `part`, its partner's index in `full`.
    fn subset(&self, full: &Instance, part: &Instance) -> Option<(Vec2, Vec<u32>)> {
        if part.strokes.len() >= full.strokes.len() {
            return None;
        }
        let tol = INCOMPLETE * full.size.max(1e-9);
        let at = |inst: &Instance, j: usize| inst.centre + inst.offsets[j];
        let fits = |i: usize, j: usize| {
            let (x, y) = (&self.strokes[full.strokes[i] as usize], &self.strokes[part.strokes[j] as usize]);
            (x.width - y.width).abs() < self.tol.width
                && paint_distance(x.stroke, y.stroke) < self.tol.color
                && paint_distance(x.fill, y.fill) < self.tol.color
                && self.shapes[full.strokes[i] as usize].within(&self.shapes[part.strokes[j] as usize], tol)
        };
        // Anchored on each partner of the first stroke in turn.
        (0..full.strokes.len()).filter(|&i| fits(i, 0)).find_map(|i0| {
            let t = at(part, 0) - at(full, i0);
            let mut taken = vec![false; full.strokes.len()];
            let mut of = Vec::with_capacity(part.strokes.len());
            for j in 0..part.strokes.len() {
                let want = at(part, j) - t;
                let i = (0..full.strokes.len())
                    .filter(|&i| !taken[i] && at(full, i).distance(want) < tol && fits(i, j))
                    .min_by(|&a, &b| at(full, a).distance(want).total_cmp(&at(full, b).distance(want)))?;
                taken[i] = true;
                of.push(i as u32);
            }
            Some((t, of))
        })
    }
}

/// Kinds, parts and classes of the `instances` of `strokes`. `tol`: the width and
/// colour tolerances (and the path tolerance, when `explicit_path`, for shared classes).
pub fn kinds(strokes: &[Stroke], groups: &[Vec<u32>], tol: Tolerances, explicit_path: bool) -> Kinds {
    let size = super::super::classify::typical_size(strokes);
    // Coarse samples (a twelfth of the typical size): costs are read against a hand's
    // wobble of a tenth or more, and the kinds are computed at every pen-up.
    let shapes = strokes.iter().map(|s| Shape::new(&s.points, size / 12.0)).collect();
    let cx = Context { strokes, shapes, tol };
    let instances: Vec<Instance> = groups
        .iter()
        .map(|g| {
            let bounds =
                g.iter().skip(1).fold(strokes[g[0] as usize].bounds(), |r, &s| r.union(strokes[s as usize].bounds()));
            let centre: Point = bounds.center();
            let offsets = g.iter().map(|&s| strokes[s as usize].reference_point() - centre).collect();
            Instance { strokes: g.clone(), offsets, size: bounds.size().to_vec2().hypot(), centre }
        })
        .collect();

    // The threshold: the largest clear gap of the costs between sampled instances.
    let step = instances.len().div_ceil(SAMPLE).max(1);
    let sample: Vec<&Instance> = instances.iter().step_by(step).collect();
    let mut costs = Vec::new();
    for (x, a) in sample.iter().enumerate() {
        for b in &sample[x + 1..] {
            if let Some((c, ..)) = cx.correspond(a, b, f64::INFINITY) {
                costs.push(c);
            }
        }
    }
    // On the scale of three sizes: a gap counts only when its upper side is 0.3 of the
    // size or more. Copies of one motif differ by the hand's wobble (exact copies, such as
    // accepted suggestions, by nothing; hand-drawn ones by up to a fifth of the size at a
    // wobble of 5% of the spacing), different motifs by a part or a shape.
    let threshold = split_at_gap(costs, 3.0);

    // Greedy kinds: an instance joins the first kind one of whose first members it
    // corresponds to within the threshold.
    // The correspondence to the kind's first member, when that is the one that matched,
    // is kept for the parts below.
    let mut kind = vec![u32::MAX; instances.len()];
    let mut members: Vec<Vec<usize>> = Vec::new();
    let mut to_first: Vec<Option<(Vec<u32>, Vec<f64>)>> = vec![None; instances.len()];
    for (x, inst) in instances.iter().enumerate() {
        let found = members.iter().position(|m| {
            m.iter().take(REPRESENTATIVES).enumerate().any(|(r, &y)| {
                match cx.correspond(&instances[y], inst, threshold) {
                    Some((cost, of, shapes)) if cost <= threshold => {
                        if r == 0 {
                            to_first[x] = Some((of, shapes));
                        }
                        true
                    }
                    _ => false,
                }
            })
        });
        match found {
            Some(k) => {
                kind[x] = k as u32;
                members[k].push(x);
            }
            None => {
                kind[x] = members.len() as u32;
                members.push(vec![x]);
            }
        }
    }

    // Incomplete copies: a kind of one instance whose strokes are some of a repeated
    // kind's joins that kind (otherwise it is a motif of its own, and placed at every
    // site of the pattern, on top of the whole ones).
    let mut incomplete: Vec<Option<(Vec2, Vec<u32>)>> = vec![None; instances.len()];
    let mut k = 0;
    while k < members.len() {
        let x = members[k][0];
        let joins = (members[k].len() == 1)
            .then(|| {
                (0..members.len())
                    .filter(|&l| l != k && members[l].len() >= 2)
                    .find_map(|l| cx.subset(&instances[members[l][0]], &instances[x]).map(|m| (l, m)))
            })
            .flatten();
        match joins {
            Some((l, m)) => {
                members[l].push(x);
                incomplete[x] = Some(m);
                members.remove(k);
            }
            None => k += 1,
        }
    }
    for (k, m) in members.iter().enumerate() {
        m.iter().for_each(|&x| kind[x] = k as u32);
    }

    // Parts: each stroke's partner in the first instance of its kind, and each part's
    // spread (the largest shape distance of a copy from the first).
    let mut part = vec![0u32; strokes.len()];
    let mut part_base = Vec::with_capacity(members.len());
    let mut spread: Vec<f64> = Vec::new();
    for m in &members {
        let first = &instances[m[0]];
        part_base.push(spread.len());
        spread.extend(std::iter::repeat_n(0.0, first.strokes.len()));
        for &x in m {
            let inst = &instances[x];
            let joined = incomplete[x].as_ref().map(|(_, of)| (of.clone(), vec![0.0; inst.strokes.len()]));
            // The first member is its own partner, stroke for stroke.
            let itself = (x == m[0]).then(|| ((0..inst.strokes.len() as u32).collect(), vec![0.0; inst.strokes.len()]));
            let known = joined.or(itself).or_else(|| to_first[x].take());
            let (of, shapes) =
                match known.or_else(|| cx.correspond(first, inst, f64::INFINITY).map(|(_, of, shapes)| (of, shapes))) {
                    Some(found) => found,
                    // Joined through another member: parts by drawing order.
                    None => ((0..inst.strokes.len() as u32).collect(), vec![0.0; inst.strokes.len()]),
                };
            for (j, &s) in inst.strokes.iter().enumerate() {
                part[s as usize] = of[j];
                let p = part_base.last().copied().unwrap_or(0) + of[j] as usize;
                spread[p] = spread[p].max(shapes[j]);
            }
        }
    }

    // Classes: parts that look alike share one.
    let first_of_part: Vec<u32> =
        members.iter().flat_map(|m| instances[m[0]].strokes.iter().copied()).collect::<Vec<u32>>();
    let parts = first_of_part.len();
    let kind_of_part: Vec<usize> =
        members.iter().enumerate().flat_map(|(k, m)| std::iter::repeat_n(k, instances[m[0]].strokes.len())).collect();
    let mut class_of_part: Vec<u32> = (0..parts as u32).collect();
    if parts <= MERGE_LIMIT {
        let floor = SPREAD_FLOOR * size;
        for p in 0..parts {
            for q in 0..p {
                if class_of_part[q] != q as u32 {
                    continue;
                }
                let (sp, sq) = (first_of_part[p] as usize, first_of_part[q] as usize);
                let (x, y) = (&strokes[sp], &strokes[sq]);
                if (x.width - y.width).abs() >= tol.width
                    || paint_distance(x.stroke, y.stroke) >= tol.color
                    || paint_distance(x.fill, y.fill) >= tol.color
                {
                    continue;
                }
                // Parts of one kind are different parts by the drawing's own account: they
                // share a class only when alike beyond doubt (exact copies).
                let one_kind = kind_of_part[p] == kind_of_part[q];
                let within = if explicit_path {
                    tol.path
                } else if one_kind {
                    floor
                } else {
                    SPREAD_MARGIN * spread[p].max(spread[q]).max(floor)
                };
                if cx.shapes[sp].within(&cx.shapes[sq], within) {
                    class_of_part[p] = q as u32;
                    break;
                }
            }
        }
    }
    // Renumber classes by first appearance in drawing order.
    let instance_of = {
        let mut v = vec![0usize; strokes.len()];
        for (x, inst) in instances.iter().enumerate() {
            inst.strokes.iter().for_each(|&s| v[s as usize] = x);
        }
        v
    };
    let mut number = vec![u32::MAX; parts];
    let mut next = 0;
    let classes = (0..strokes.len())
        .map(|s| {
            let k = kind[instance_of[s]] as usize;
            let p = class_of_part[part_base[k] + part[s] as usize] as usize;
            if number[p] == u32::MAX {
                number[p] = next;
                next += 1;
            }
            number[p]
        })
        .collect();
    let first = members.iter().map(|m| m[0]).collect::<Vec<usize>>();
    let incomplete =
        incomplete.into_iter().enumerate().map(|(x, m)| m.map(|(t, _)| (first[kind[x] as usize], t))).collect();
    Kinds { kind, part, classes, incomplete }
}
