//! Greedy classification of strokes into classes of similar ones (SPEC 1.1), and an
//! automatic proposal of the three tolerances from the data (beyond the paper).

use super::color::paint_distance;
use super::frechet::Shape;
use super::stroke::Stroke;
use kurbo::Point;
use serde::{Deserialize, Serialize};
use std::collections::HashMap;

/// The three tolerances of `Match`: Fréchet distance of the centred paths (e1), stroke
/// width difference (e2) and Euclidean RGB distance of stroke and of fill colour (e3).
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "camelCase")]
pub struct Tolerances {
    pub path: f64,
    pub width: f64,
    pub color: f64,
}

/// Strokes prepared for comparison: shapes resampled once, at a common spacing.
pub struct Prepared<'a> {
    strokes: &'a [Stroke],
    shapes: Vec<Shape>,
}

impl<'a> Prepared<'a> {
    /// `spacing` is the arc-length step of the resampled shapes; it bounds the error of
    /// the discrete distance, so keep it well under the path tolerance.
    pub fn new(strokes: &'a [Stroke], spacing: f64) -> Self {
        let shapes = strokes.iter().map(|s| Shape::new(&s.points, spacing)).collect();
        Prepared { strokes, shapes }
    }

    /// `Match(Si, Sj)` of the spec, cheapest tests first.
    pub fn matches(&self, i: usize, j: usize, tol: &Tolerances) -> bool {
        let (a, b) = (&self.strokes[i], &self.strokes[j]);
        (a.width - b.width).abs() < tol.width
            && paint_distance(a.stroke, b.stroke) < tol.color
            && paint_distance(a.fill, b.fill) < tol.color
            && self.shapes[i].within(&self.shapes[j], tol.path)
    }
}

/// The median bounding-box diagonal: the scale against which shape distances are read.
pub fn typical_size(strokes: &[Stroke]) -> f64 {
    let mut d: Vec<f64> = strokes
        .iter()
        .map(|s| {
            let b = s.bounds();
            b.width().hypot(b.height())
        })
        .collect();
    median(&mut d).max(1e-6)
}

/// Resampling step for classification with path tolerance `path_tol`.
pub fn sample_spacing(strokes: &[Stroke], path_tol: f64) -> f64 {
    let size = typical_size(strokes);
    (path_tol * 0.25).min(size / 32.0).max(size * 1e-4)
}

pub(crate) fn median(v: &mut [f64]) -> f64 {
    if v.is_empty() {
        return 0.0;
    }
    crate::order::floats(v);
    v[v.len() / 2]
}

/// Greedy clustering: pop the first stroke left into a new class, then sweep the rest,
/// adding any stroke that matches any member, until a sweep adds nothing. Each pair is
/// compared at most once (a stroke remembers how many members it was checked against).
/// Returns the class of each stroke, numbered in order of first appearance.
///
/// The classes are the connected components of the `matches` relation, so copies of one
/// stroke (translates with the same paint: SVG patterns are made of them) are compared
/// once, through their first occurrence.
pub fn classify(strokes: &[Stroke], tol: &Tolerances) -> Vec<u32> {
    let (firsts, copy_of) = translates(strokes);
    if firsts.len() == strokes.len() {
        return components(strokes, tol);
    }
    let unique: Vec<Stroke> = firsts.iter().map(|&i| strokes[i].clone()).collect();
    let classes = components(&unique, tol);
    copy_of.iter().map(|&u| classes[u]).collect()
}

/// The greedy clustering itself, on strokes that are not copies of one another.
///
/// A class grows from its first stroke through its members: each member is compared
/// only with the unclassified strokes that could match it. The discrete Fréchet
/// distance couples the paths' first points and their last points (or, drawn the other
/// way, each one's first with the other's last), so a match has its first point within
/// the path tolerance of the member's first or last; strokes are looked up by their
/// first point in a grid of that cell size. Sweeping every stroke left for every class
/// made 200,000 distinct strokes 2e10 comparisons.
fn components(strokes: &[Stroke], tol: &Tolerances) -> Vec<u32> {
    let prepared = Prepared::new(strokes, sample_spacing(strokes, tol.path));
    let n = strokes.len();
    let ends: Vec<(Point, Point)> = prepared
        .shapes
        .iter()
        .map(|s| (s.points.first().copied().unwrap_or(Point::ZERO), s.points.last().copied().unwrap_or(Point::ZERO)))
        .collect();
    // Cells no smaller than a millionth of a stroke (a tolerance of 0 matches nothing).
    let cell = tol.path.max(1e-6 * typical_size(strokes));
    let key = |p: Point| ((p.x / cell).floor() as i64, (p.y / cell).floor() as i64);
    let mut grid: HashMap<(i64, i64), Vec<u32>> = HashMap::new();
    for (i, e) in ends.iter().enumerate() {
        grid.entry(key(e.0)).or_default().push(i as u32);
    }
    // Closed loops are matched from any start (see `Shape::starts`): filed by their
    // extents as well, which two loops within the tolerance share within it.
    let mut loops: HashMap<(i64, i64), Vec<u32>> = HashMap::new();
    let extent = |m: usize| prepared.shapes[m].half_extent.to_point();
    for m in (0..n).filter(|&m| prepared.shapes[m].closed) {
        loops.entry(key(extent(m))).or_default().push(m as u32);
    }
    let mut class = vec![u32::MAX; n];
    let mut next = 0u32;
    for seed in 0..n {
        if class[seed] != u32::MAX {
            continue;
        }
        class[seed] = next;
        let mut queue = vec![seed];
        while let Some(m) = queue.pop() {
            let closed = prepared.shapes[m].closed;
            for (in_loops, at) in
                [(false, Some(ends[m].0)), (false, Some(ends[m].1)), (true, closed.then(|| extent(m)))]
            {
                let Some(at) = at else { continue };
                let index = if in_loops { &mut loops } else { &mut grid };
                let (cx, cy) = key(at);
                for k in [(cx - 1, cy - 1), (cx, cy - 1), (cx + 1, cy - 1), (cx - 1, cy), (cx, cy), (cx + 1, cy)]
                    .into_iter()
                    .chain([(cx - 1, cy + 1), (cx, cy + 1), (cx + 1, cy + 1)])
                {
                    let Some(near) = index.get_mut(&k) else { continue };
                    // Classified strokes leave the grid as their cells are visited.
                    near.retain(|&s| class[s as usize] == u32::MAX);
                    for &s in near.iter() {
                        if class[s as usize] == u32::MAX && prepared.matches(s as usize, m, tol) {
                            class[s as usize] = next;
                            queue.push(s as usize);
                        }
                    }
                }
            }
        }
        next += 1;
    }
    class
}

/// Each stroke's group of exact copies (translates with the same width, paint and
/// subpaths), numbered by first appearance.
pub(crate) fn copies(strokes: &[Stroke]) -> Vec<u32> {
    translates(strokes).1.into_iter().map(|g| g as u32).collect()
}

/// Groups strokes that are exact translates of one another with the same width, paint
/// and subpaths: the index of each group's first stroke, and each stroke's group.
fn translates(strokes: &[Stroke]) -> (Vec<usize>, Vec<usize>) {
    use std::collections::HashMap;
    let size = typical_size(strokes);
    // Relative coordinates to a millionth of the typical size: a translation by a
    // non-representable offset changes only the last bits.
    let quantum = size * 1e-6;
    let key = |s: &Stroke| {
        let [x0, y0] = s.points.first().copied().unwrap_or([0.0, 0.0]);
        let shape: Vec<(i64, i64)> = s
            .points
            .iter()
            .map(|&[x, y]| (((x - x0) / quantum).round() as i64, ((y - y0) / quantum).round() as i64))
            .collect();
        let paint = (s.stroke, s.fill, s.width.to_bits(), s.closed, s.fill_rule);
        (shape, s.breaks.clone(), paint, s.opacity.to_bits(), s.stroke_opacity.to_bits(), s.fill_opacity.to_bits())
    };
    let mut groups = HashMap::new();
    let mut firsts = Vec::new();
    let copy_of = strokes
        .iter()
        .enumerate()
        .map(|(i, s)| {
            *groups.entry(key(s)).or_insert_with(|| {
                firsts.push(i);
                firsts.len() - 1
            })
        })
        .collect();
    (firsts, copy_of)
}

/// At most this many strokes are sampled to propose tolerances (pairs grow quadratically:
/// 64 took half of a cold autocomplete call on 200 petals; 48 gave every replay table
/// unchanged, lattices, motifs and sequences, and the call 0.72x the time).
const PROPOSAL_SAMPLE: usize = 48;
/// The strokes' shapes are resampled every this share of the typical size to propose
/// the path tolerance.
const PROPOSAL_SPACING: f64 = 16.0;

/// Proposes tolerances from the data: for each attribute, the sorted pairwise
/// distances are split at their largest relative gap, if that gap is clear; otherwise
/// the tolerance admits all of them (one class by that attribute).
pub fn propose_tolerances(strokes: &[Stroke]) -> Tolerances {
    // Evenly spread, at a stride that is not a whole number: a whole stride of two took
    // only the first part of every motif of two strokes.
    let count = strokes.len().min(PROPOSAL_SAMPLE);
    let sample: Vec<Stroke> = (0..count).map(|k| strokes[k * strokes.len() / count.max(1)].clone()).collect();
    let size = typical_size(&sample);
    // Path distances between copies are those of their originals: each computed once.
    let (firsts, copy_of) = translates(&sample);
    let unique: Vec<Stroke> = firsts.iter().map(|&i| sample[i].clone()).collect();
    // (Sampled every sixteenth of the typical size: the split falls in a gap of 2.5
    // times or more, which a sample's error of a few hundredths of the size does not
    // move; every 32nd took three times as long, 60 of a cold call's 106 ms at 200
    // petals.)
    let prepared = Prepared::new(&unique, size / PROPOSAL_SPACING);
    let mut known = vec![f64::NAN; unique.len() * unique.len()];
    let (mut paths, mut widths, mut colors) = (Vec::new(), Vec::new(), Vec::new());
    for i in 0..sample.len() {
        for j in i + 1..sample.len() {
            let (a, b) = (&sample[i], &sample[j]);
            let (u, v) = (copy_of[i], copy_of[j]);
            let d = &mut known[u.min(v) * unique.len() + u.max(v)];
            if d.is_nan() {
                *d = if u == v { 0.0 } else { prepared.shapes[u].distance(&prepared.shapes[v]) };
            }
            paths.push(*d);
            widths.push((a.width - b.width).abs());
            for d in [paint_distance(a.stroke, b.stroke), paint_distance(a.fill, b.fill)] {
                if d.is_finite() {
                    colors.push(d);
                }
            }
        }
    }
    let mut w: Vec<f64> = sample.iter().map(|s| s.width).collect();
    let typical_width = median(&mut w).max(0.5);
    Tolerances {
        path: split_at_gap(paths, size),
        width: split_at_gap(widths, typical_width),
        color: split_at_gap(colors, 100.0),
    }
}

/// The threshold between "same" and "different" in a set of distances measured on
/// the scale `unit`: the geometric middle of the largest ratio gap, when that gap is at
/// least 2.5x and its upper side is at least a tenth of `unit`.
pub(crate) fn split_at_gap(mut d: Vec<f64>, unit: f64) -> f64 {
    d.retain(|v| v.is_finite());
    crate::order::floats(&mut d);
    let floor = 0.02 * unit;
    let mut best: Option<(f64, f64)> = None;
    let mut best_ratio = 2.5;
    for w in d.windows(2) {
        let (a, b) = (w[0] + floor, w[1] + floor);
        if w[1] >= 0.1 * unit && b / a > best_ratio {
            best_ratio = b / a;
            best = Some((w[0], w[1]));
        }
    }
    match best {
        Some((lo, hi)) => ((lo + floor) * (hi + floor)).sqrt() - floor,
        None => d.last().copied().unwrap_or(0.0) * 1.25 + 0.1 * unit,
    }
}

#[cfg(test)]
mod tests {
    use super::super::color::Rgb;
    use super::*;

    fn seg(x: f64, y: f64, dx: f64, dy: f64, w: f64, c: [u8; 3]) -> Stroke {
        Stroke::new(vec![[x, y], [x + dx, y + dy]], w, Some(Rgb(c)))
    }

    #[test]
    fn separates_by_shape_width_and_colour() {
        let strokes = vec![
            seg(0.0, 0.0, 10.0, 0.0, 2.0, [0, 0, 0]),
            seg(20.0, 0.0, 0.0, 10.0, 2.0, [0, 0, 0]),   // rotated: other class
            seg(40.0, 0.0, 10.2, 0.1, 2.0, [0, 0, 0]),   // same as 0
            seg(60.0, 0.0, 10.0, 0.0, 6.0, [0, 0, 0]),   // wider
            seg(80.0, 0.0, 10.0, 0.0, 2.0, [250, 0, 0]), // red
            seg(0.0, 30.0, 0.1, 9.9, 2.0, [0, 0, 0]),    // same as 1
        ];
        let tol = Tolerances { path: 1.0, width: 1.0, color: 30.0 };
        assert_eq!(classify(&strokes, &tol), vec![0, 1, 0, 2, 3, 1]);
    }

    #[test]
    fn chains_join_one_class() {
        // Each neighbour is within tolerance of the previous one: greedy clustering
        // adds by "matches any member", so the chain ends up in one class.
        let strokes: Vec<Stroke> =
            (0..5).map(|i| seg(i as f64 * 30.0, 0.0, 10.0 + i as f64 * 0.8, 0.0, 1.0, [0; 3])).collect();
        let tol = Tolerances { path: 0.5, width: 1.0, color: 1.0 };
        assert_eq!(classify(&strokes, &tol), vec![0; 5]);
    }

    #[test]
    fn proposal_separates_clear_groups() {
        let mut strokes = Vec::new();
        for i in 0..12 {
            let j = (i % 3) as f64 * 0.1;
            strokes.push(seg(i as f64 * 20.0, 0.0, 10.0 + j, j, 1.0, [0, 0, 0]));
            strokes.push(seg(i as f64 * 20.0, 40.0, j, 10.0 + j, 1.0, [0, 0, 0]));
            strokes.push(seg(i as f64 * 20.0, 80.0, 10.0 + j, j, 1.0, [200, 30, 30]));
        }
        let tol = propose_tolerances(&strokes);
        let classes = classify(&strokes, &tol);
        let count = *classes.iter().max().unwrap() + 1;
        assert_eq!(count, 3, "tolerances {tol:?}");
        assert!(tol.path > 0.3 && tol.path < 7.0, "{tol:?}");
    }

    #[test]
    fn copies_classify_as_their_original() {
        let mut strokes: Vec<Stroke> =
            (0..30).map(|i| seg(i as f64 * 20.0, 0.0, 10.0, (i % 3) as f64 * 4.0, 1.0, [0; 3])).collect();
        strokes.push(seg(5.0, 50.0, 0.0, 10.0, 1.0, [0; 3]));
        let tol = Tolerances { path: 1.0, width: 0.5, color: 1.0 };
        let (firsts, _) = translates(&strokes);
        assert_eq!(firsts, vec![0, 1, 2, 30]);
        assert_eq!(classify(&strokes, &tol), (0..30).map(|i| i % 3).chain([3]).collect::<Vec<u32>>());
    }

    #[test]
    fn classes_are_the_components_of_every_pair_that_matches() {
        // Against the definition (union of every matching pair, numbered by first
        // stroke), on wobbly strokes of a few shapes drawn either way round.
        let mut rng = crate::rng::Rng::new(11);
        let mut strokes = Vec::new();
        for i in 0..300 {
            let (x, y) = (rng.next_f64() * 500.0, rng.next_f64() * 500.0);
            let k = rng.below(4) as f64;
            let wob = |r: &mut crate::rng::Rng| (r.next_f64() - 0.5) * 3.0;
            let mut pts: Vec<[f64; 2]> =
                (0..6).map(|t| [x + t as f64 * (4.0 + k), y + (t as f64 * k).sin() * 6.0 + wob(&mut rng)]).collect();
            if i % 3 == 0 {
                pts.reverse();
            }
            strokes.push(Stroke::new(pts, 1.0 + (i % 2) as f64 * 0.1, None));
        }
        for path in [0.0, 0.8, 2.0, 5.0, 40.0] {
            let tol = Tolerances { path, width: 0.5, color: 1.0 };
            let prepared = Prepared::new(&strokes, sample_spacing(&strokes, path));
            let mut root: Vec<usize> = (0..strokes.len()).collect();
            fn find(r: &mut [usize], i: usize) -> usize {
                if r[i] != i {
                    let t = find(r, r[i]);
                    r[i] = t;
                }
                r[i]
            }
            for i in 0..strokes.len() {
                for j in 0..i {
                    if prepared.matches(i, j, &tol) {
                        let (a, b) = (find(&mut root, i), find(&mut root, j));
                        root[a.max(b)] = a.min(b);
                    }
                }
            }
            let mut number = std::collections::HashMap::new();
            let want: Vec<u32> = (0..strokes.len())
                .map(|i| {
                    let r = find(&mut root, i);
                    let next = number.len() as u32;
                    *number.entry(r).or_insert(next)
                })
                .collect();
            assert_eq!(components(&strokes, &tol), want, "path tolerance {path}");
            assert!(path < 1.0 || number.len() < strokes.len(), "path tolerance {path} joins some");
        }
    }

    #[test]
    fn proposal_keeps_identical_strokes_together() {
        let strokes: Vec<Stroke> = (0..10).map(|i| seg(i as f64 * 20.0, 0.0, 10.0, 0.0, 1.0, [0; 3])).collect();
        let tol = propose_tolerances(&strokes);
        assert!(classify(&strokes, &tol).iter().all(|&c| c == 0), "{tol:?}");
    }
}
