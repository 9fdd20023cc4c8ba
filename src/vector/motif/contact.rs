//! Motif instances by contact: strokes drawn on or against one another (the bars of a
//! cross, petals round a dot, the walls, roof and door of a house) are parts of one copy
//! of a motif.
//!
//! The gap between two strokes is the least distance between their paths less half
//! their widths (zero where they cross, or where one lies inside the other's closed
//! outline). The strokes are joined in order of increasing gap (a minimum spanning
//! forest, Kruskal) and the joins are cut at the largest ratio gap between consecutive
//! join lengths, when it is clear: parts of a motif touch or nearly touch, copies stand
//! apart. Copies that touch their neighbours (crosses whose arms meet) touch them where
//! a part meets the same part of the next copy: when no cut groups, joins between
//! strokes of one class are left out and the cut is sought again. A drawing with no
//! clear gap (a grid of single strokes, hatching, a mesh whose pieces all touch) has no
//! multi-stroke instances, and its strokes stay their own. (Houses whose eaves come
//! within a stroke's width of the next house's walls have no gap left either: they
//! stay their strokes.)

use super::super::classify::typical_size;
use super::super::spatial::Grid;
use super::super::stroke::Stroke;
use kurbo::{Point, Rect, Vec2};

/// Pairs further apart than this many stroke sizes (the 90th percentile) are never parts
/// of one copy (a shaky hand leaves gaps of a good part of a small stroke between parts).
const REACH: f64 = 2.0;
/// The join lengths must jump by at least this ratio between parts and copies.
const CLEAR: f64 = 2.5;
/// Gaps are compared above this floor (a share of the median stroke size): a hand never
/// makes two strokes meet exactly, so 0 against 0.01 is no gap.
const FLOOR: f64 = 0.03;
/// Pairs within reach per stroke beyond which the drawing is too dense to hold compact
/// copies (a flower of six parts among its eight neighbours has about 27).
const MAX_PAIRS_PER_STROKE: usize = 64;
/// Samples per stroke for the gap (the gap is then exact to about a sixtieth of its length).
const SAMPLES: usize = 32;

/// Groups `strokes` (of the paper's `classes`) into motif instances: each instance's
/// strokes in drawing order, instances in the order of their first stroke. `None` when
/// no clear grouping exists (every stroke is then its own instance). `touching` reads
/// copies that touch their neighbours, when no cut separates them.
pub fn instances(
    strokes: &[Stroke],
    classes: &[u32],
    across: impl Fn(&[Vec<u32>]) -> bool,
    touching: impl FnOnce() -> Option<Vec<Vec<u32>>>,
) -> Option<Vec<Vec<u32>>> {
    let n = strokes.len();
    if n < 4 {
        return None;
    }
    let size = typical_size(strokes);
    // The reach is set by the large parts: a motif of many small ones (eyes, a mouth)
    // around a large outline has its gaps on the outline's scale.
    let mut sizes: Vec<f64> = strokes.iter().map(|s| s.bounds().size().to_vec2().hypot()).collect();
    crate::order::floats(&mut sizes);
    let reach = REACH * sizes[(sizes.len() - 1) * 9 / 10].max(size);
    let paths: Vec<Path> = strokes.iter().map(Path::of).collect();
    let bounds: Vec<Rect> = strokes.iter().map(Stroke::bounds).collect();
    let boxes: Vec<Rect> = bounds.iter().zip(strokes).map(|(b, s)| b.inflate(s.width / 2.0, s.width / 2.0)).collect();
    let all = boxes.iter().skip(1).fold(boxes[0], |r, b| r.union(*b));
    let biggest = boxes.iter().map(|b| b.width().max(b.height())).fold(0.0, f64::max);
    let mut grid = Grid::new(all, (size + reach).max(1e-9), 4 * n + 16);
    for (i, b) in boxes.iter().enumerate() {
        grid.insert(i as u32, b.center());
    }
    // Pairs whose boxes come within the reach, counted before any gap is measured: a
    // drawing of long strokes lying across one another (waves, contour lines) has no
    // compact copies to find, and measuring all its gaps would cost seconds.
    let mut pairs: Vec<(u32, u32)> = Vec::new();
    for i in 0..n {
        let bi = boxes[i].inflate(reach, reach);
        grid.for_each_near(boxes[i].center(), 0.5 * (boxes[i].width().max(boxes[i].height()) + biggest) + reach, |j| {
            let j = j as usize;
            if j > i && (!bi.intersect(boxes[j]).is_zero_area() || touches(bi, boxes[j])) {
                pairs.push((i as u32, j as u32));
            }
        });
        if pairs.len() > MAX_PAIRS_PER_STROKE * n {
            return None;
        }
    }
    let mut edges: Vec<(f64, u32, u32)> = Vec::new();
    for (i, j) in pairs {
        let (i, j) = (i as usize, j as usize);
        let g = gap(&strokes[i], &paths[i], &strokes[j], &paths[j], reach);
        if g < reach {
            edges.push((g, i as u32, j as u32));
        }
    }
    edges.sort_by(|a, b| a.0.total_cmp(&b.0).then(a.1.cmp(&b.1)).then(a.2.cmp(&b.2)));
    let cut = |edges: &[(f64, u32, u32)]| best_cut(n, edges, &boxes, reach, FLOOR * size, &across);
    // Copies that touch their neighbours (eaves that meet, arms that join): first as
    // `touching` reads them (the lattice's cells), else they touch them where a part
    // meets the same part of the next copy, and without joins between strokes of one
    // class the copies come apart again.
    cut(&edges).or_else(touching).or_else(|| {
        // (A loop wholly within another is an eye in its face: kept. Two faces drawn
        // overlapping put a point of one inside the other without being nested.)
        let within = |i: usize, j: usize| {
            let (outer, inner) = (bounds[i], bounds[j]);
            outer.union(inner) == outer && inside(&paths[i], &paths[j].points)
        };
        let nested = |i: usize, j: usize| within(i, j) || within(j, i);
        let apart: Vec<(f64, u32, u32)> = edges
            .iter()
            .copied()
            .filter(|&(_, i, j)| classes[i as usize] != classes[j as usize] || nested(i as usize, j as usize))
            .collect();
        (apart.len() < edges.len()).then(|| cut(&apart)).flatten()
    })
}

/// The grouping the minimum spanning forest of `edges` (sorted by gap) gives at its
/// best cut, if any; a grouping `across` the drawing's repetition (a group holding a
/// part and its copy one period on: a row of crosses whose arms meet) is none.
fn best_cut(
    n: usize,
    edges: &[(f64, u32, u32)],
    boxes: &[Rect],
    reach: f64,
    floor: f64,
    across: &dyn Fn(&[Vec<u32>]) -> bool,
) -> Option<Vec<Vec<u32>>> {
    // Kruskal: the joins of the minimum spanning forest, in order.
    let mut sets = Sets::new(n);
    let joins: Vec<(f64, u32, u32)> = edges.iter().copied().filter(|&(_, i, j)| sets.union(i, j)).collect();
    let lengths: Vec<f64> = joins.iter().map(|j| j.0).collect();
    // The clearest cut that gives repeated, compact copies (a word's letters stand
    // closer than its lines: the cut between words makes lines, the one between
    // letters makes letters).
    // Of the cuts that group, the one that puts the most strokes into instances of
    // several (a mask's eyes join its outline only at the cut between copies), then the
    // clearest.
    let mut best: Option<(usize, Vec<Vec<u32>>)> = None;
    for cut in cuts(&lengths, reach, floor) {
        if let Some(g) = grouped(n, &joins, cut, boxes).filter(|g| !across(g)) {
            let held = g.iter().filter(|i| i.len() >= 2).map(Vec::len).sum::<usize>();
            if best.as_ref().is_none_or(|b| held > b.0) {
                best = Some((held, g));
            }
        }
    }
    best.map(|b| b.1)
}

/// The instances that joins up to `cut` make, if they are a grouping: at least two
/// instances of several strokes, holding most strokes, none holding three quarters of
/// the drawing (a mesh; a second copy being drawn may hold fewer strokes than the
/// first), and most smaller than the distance to the nearest other or laid side by side
/// both ways (rows of a dense grid touch along the row: they are lines of copies, not
/// copies).
fn grouped(n: usize, joins: &[(f64, u32, u32)], cut: f64, boxes: &[Rect]) -> Option<Vec<Vec<u32>>> {
    let mut sets = Sets::new(n);
    for &(g, i, j) in joins {
        if g <= cut {
            sets.union(i, j);
        }
    }
    let mut index = vec![u32::MAX; n];
    let mut out: Vec<Vec<u32>> = Vec::new();
    for i in 0..n {
        let root = sets.find(i as u32) as usize;
        if index[root] == u32::MAX {
            index[root] = out.len() as u32;
            out.push(Vec::new());
        }
        out[index[root] as usize].push(i as u32);
    }
    let largest = out.iter().map(Vec::len).max().unwrap_or(0);
    if !repeats(&out, n) || 4 * largest > 3 * n {
        return None;
    }
    let bounds: Vec<Rect> =
        out.iter().map(|g| g.iter().skip(1).fold(boxes[g[0] as usize], |r, &s| r.union(boxes[s as usize]))).collect();
    // Compact: no other instance's centre nearer than the diagonal over COMPACT (found
    // in a grid: a drawing of 50,000 strokes has tens of thousands of instances).
    let centres: Vec<Point> = bounds.iter().map(Rect::center).collect();
    let area = centres.iter().fold(Rect::from_points(centres[0], centres[0]), |r, &c| r.union_pt(c));
    let diagonals: Vec<f64> = bounds.iter().map(|b| b.size().to_vec2().hypot()).collect();
    let cell = crate::vector::classify::median(&mut diagonals.clone()) / COMPACT;
    let mut grid = Grid::new(area, cell.max(1e-9), 4 * centres.len() + 16);
    for (x, &c) in centres.iter().enumerate() {
        grid.insert(x as u32, c);
    }
    let compact = (0..bounds.len())
        .filter(|&x| {
            let radius = diagonals[x] / COMPACT;
            let mut crowded = false;
            grid.for_each_near(centres[x], radius, |y| {
                crowded |= y as usize != x && centres[y as usize].distance(centres[x]) < radius;
            });
            !crowded
        })
        .count();
    // Or copies side by side both ways, wide as they are (words in lines of text): two
    // centres further apart across than an instance is wide, and two further apart down
    // than it is tall. Rows of a grid lie one above the other only.
    let (w, h) = bounds.iter().fold((0.0f64, 0.0f64), |m, b| (m.0.max(b.width()), m.1.max(b.height())));
    let (x0, x1, y0, y1) = bounds.iter().fold((f64::MAX, f64::MIN, f64::MAX, f64::MIN), |m, b| {
        let c = b.center();
        (m.0.min(c.x), m.1.max(c.x), m.2.min(c.y), m.3.max(c.y))
    });
    let side_by_side = x1 - x0 > w && y1 - y0 > h;
    (4 * compact >= 3 * out.len() || side_by_side).then_some(out)
}

/// An instance's diagonal must stay within this multiple of the distance to the nearest
/// other instance (for three in four instances): an emoji 36 across on a 48 grid has a
/// diagonal of 51; a row of a grid, a diagonal of several rows' distance.
const COMPACT: f64 = 1.5;

/// The join lengths below which strokes may be parts of one instance, clearest first:
/// the geometric middle of every clear ratio gap between consecutive join lengths (the
/// reach counts as the length of every join beyond it).
fn cuts(joins: &[f64], reach: f64, floor: f64) -> Vec<f64> {
    let mut levels: Vec<f64> = joins.to_vec();
    levels.push(reach);
    let mut gaps: Vec<(f64, f64)> = levels
        .windows(2)
        .filter_map(|w| {
            let ratio = (w[1] + floor) / (w[0] + floor);
            (ratio > CLEAR).then(|| (ratio, ((w[0] + floor) * (w[1] + floor)).sqrt() - floor))
        })
        .collect();
    gaps.sort_by(|a, b| b.0.total_cmp(&a.0));
    gaps.into_iter().map(|g| g.1).collect()
}

/// Whether `groups` of `n` strokes repeat: at least two hold several strokes, and those
/// hold at least half of them.
pub(super) fn repeats(groups: &[Vec<u32>], n: usize) -> bool {
    let multi = groups.iter().filter(|g| g.len() >= 2);
    multi.clone().count() >= 2 && 2 * multi.map(Vec::len).sum::<usize>() >= n
}

/// Whether two boxes touch along an edge (zero-area intersection of degenerate boxes:
/// a horizontal line meeting a vertical one).
fn touches(a: Rect, b: Rect) -> bool {
    a.x0 <= b.x1 && b.x0 <= a.x1 && a.y0 <= b.y1 && b.y0 <= a.y1
}

/// A stroke's path resampled to at most `SAMPLES` points (each subpath kept apart is not
/// needed here: a gap is a least distance, and joining subpaths only adds segments).
fn sampled(s: &Stroke) -> Vec<Point> {
    let pts: Vec<Point> = s.points.iter().map(|&[x, y]| Point::new(x, y)).collect();
    if pts.len() <= SAMPLES {
        return pts;
    }
    let step = pts.len().div_ceil(SAMPLES);
    let mut out: Vec<Point> = pts.iter().step_by(step).copied().collect();
    if let Some(&last) = pts.last() {
        out.push(last);
    }
    out
}

/// A stroke's sampled path (`sampled`) as segments, each with its bounding box, made
/// once per stroke: a dense drawing measures each stroke's gap to dozens of others.
pub(super) struct Path {
    pub(super) points: Vec<Point>,
    segments: Vec<(Point, Point, Rect)>,
    /// Closed, filled, or a loop drawn by hand (seldom closed exactly: an open stroke
    /// whose ends come within a tenth of its size of each other; a face's eyes lie
    /// inside it), with three points at least: it has an inside.
    encloses: bool,
    /// The sampled points' bounding box.
    bounds: Rect,
    /// A digest of the stroke, under which its gaps are remembered (see `GAPS`).
    key: u64,
}

impl Path {
    pub(super) fn of(s: &Stroke) -> Path {
        let points = sampled(s);
        let mut ends: Vec<(Point, Point)> = points.windows(2).map(|w| (w[0], w[1])).collect();
        if s.closed && points.len() > 2 {
            ends.push((points[points.len() - 1], points[0]));
        }
        if points.len() == 1 {
            ends.push((points[0], points[0]));
        }
        let segments = ends.into_iter().map(|(p, q)| (p, q, Rect::from_points(p, q))).collect();
        let looped = points.len() >= 3
            && points[0].distance(points[points.len() - 1]) <= 0.1 * s.bounds().size().to_vec2().hypot();
        let encloses = points.len() >= 3 && (s.closed || s.fill.is_some() || looped);
        let bounds = points
            .iter()
            .skip(1)
            .fold(points.first().map_or(Rect::ZERO, |&p| Rect::from_points(p, p)), |r, &q| r.union_pt(q));
        let flags = [s.width, f64::from(u8::from(s.closed)), f64::from(u8::from(s.fill.is_some()))];
        let key = crate::memo::digest(s.points.iter().map(|p| (p[0], p[1])), &flags);
        Path { points, segments, encloses, bounds, key }
    }
}

/// The gap between two strokes: least distance between their paths less half their
/// widths, zero when the paths cross or one lies inside the other's closed outline; or
/// `cap` where it is at least `cap` (the callers ask only whether it is under a reach).
/// Segment pairs whose boxes lie further apart than the best distance so far (at first
/// the cap) are not measured: two neighbours' paths of 32 segments each are 1,024
/// pairs, of which a handful come close.
pub(super) fn gap(a: &Stroke, pa: &Path, b: &Stroke, pb: &Path, cap: f64) -> f64 {
    GAPS.with(|m| {
        // (Remembered exactly, or as "at least" a cap, stored negated.)
        match m.get(pa.key, pb.key) {
            Some(g) if g >= 0.0 => return g.min(cap),
            Some(g) if -g >= cap => return cap,
            _ => {}
        }
        let g = measure_gap(a, pa, b, pb, cap);
        // (A cap of zero says nothing, and stored as -0 it would read as a gap of 0.)
        if g < cap {
            m.insert(pa.key, pb.key, g);
        } else if cap > 0.0 {
            m.insert(pa.key, pb.key, -cap);
        }
        g
    })
}

/// Gaps already measured, by the two strokes' digests (see `crate::memo`): autocomplete
/// groups the whole drawing again after every stroke, and all but the new stroke's gaps
/// were measured the stroke before (rings of petals all touch at their centres: 19% of
/// a call on a hand's 200 petals).
const GAP_ENTRIES: usize = 1 << 16;
thread_local! {
    static GAPS: crate::memo::PairMemo = crate::memo::PairMemo::new(GAP_ENTRIES);
}

/// `gap`, measured.
fn measure_gap(a: &Stroke, pa: &Path, b: &Stroke, pb: &Path, cap: f64) -> f64 {
    let pad = 0.5 * (a.width + b.width);
    if inside(pa, &pb.points) || inside(pb, &pa.points) {
        return 0.0;
    }
    let mut best = cap + pad;
    for &(p0, p1, ra) in &pa.segments {
        for &(q0, q1, rb) in &pb.segments {
            let dx = (rb.x0 - ra.x1).max(ra.x0 - rb.x1).max(0.0);
            let dy = (rb.y0 - ra.y1).max(ra.y0 - rb.y1).max(0.0);
            if dx * dx + dy * dy >= best * best {
                continue;
            }
            best = best.min(segment_distance(p0, p1, q0, q1));
            if best <= pad {
                return 0.0;
            }
        }
    }
    (best - pad).clamp(0.0, cap)
}

/// Whether `other`'s first point lies inside the outline `path`, when it encloses.
fn inside(path: &Path, other: &[Point]) -> bool {
    let Some(&p) = other.first().filter(|_| path.encloses) else {
        return false;
    };
    if !path.bounds.contains(p) {
        return false;
    }
    let path = &path.points;
    let mut wind = false;
    for k in 0..path.len() {
        let (a, b) = (path[k], path[(k + 1) % path.len()]);
        if (a.y > p.y) != (b.y > p.y) && p.x < a.x + (p.y - a.y) / (b.y - a.y) * (b.x - a.x) {
            wind = !wind;
        }
    }
    wind
}

/// Distance between segments `p0 p1` and `q0 q1` (zero when they cross).
fn segment_distance(p0: Point, p1: Point, q0: Point, q1: Point) -> f64 {
    let (d1, d2) = (p1 - p0, q1 - q0);
    let cross = |u: Vec2, v: Vec2| u.cross(v);
    let (a, b, c, d) = (cross(d1, q0 - p0), cross(d1, q1 - p0), cross(d2, p0 - q0), cross(d2, p1 - q0));
    if a * b < 0.0 && c * d < 0.0 {
        return 0.0;
    }
    point_segment(p0, q0, q1)
        .min(point_segment(p1, q0, q1))
        .min(point_segment(q0, p0, p1))
        .min(point_segment(q1, p0, p1))
}

pub(crate) fn point_segment(p: Point, a: Point, b: Point) -> f64 {
    let d = b - a;
    let len2 = d.hypot2();
    let t = if len2 > 0.0 { ((p - a).dot(d) / len2).clamp(0.0, 1.0) } else { 0.0 };
    p.distance(a + d * t)
}

/// Union-find over stroke indices.
pub(super) struct Sets(Vec<u32>);

impl Sets {
    pub(super) fn new(n: usize) -> Sets {
        Sets((0..n as u32).collect())
    }

    fn find(&mut self, mut i: u32) -> u32 {
        while self.0[i as usize] != i {
            let up = self.0[self.0[i as usize] as usize];
            self.0[i as usize] = up;
            i = up;
        }
        i
    }

    /// Joins the sets of `i` and `j`; false when they were one already.
    pub(super) fn union(&mut self, i: u32, j: u32) -> bool {
        let (a, b) = (self.find(i), self.find(j));
        if a == b {
            return false;
        }
        self.0[a.max(b) as usize] = a.min(b);
        true
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::vector::color::Rgb;

    fn seg(x: f64, y: f64, dx: f64, dy: f64) -> Stroke {
        Stroke::new(vec![[x - dx, y - dy], [x + dx, y + dy]], 2.0, Some(Rgb([0, 0, 0])))
    }

    #[test]
    fn crosses_group_and_dashes_do_not() {
        let mut crosses = Vec::new();
        let mut dashes = Vec::new();
        for j in 0..3 {
            for i in 0..3 {
                let (x, y) = (70.0 * i as f64 + 0.7 * j as f64, 70.0 * j as f64);
                crosses.push(seg(x, y, 15.0, 0.3));
                crosses.push(seg(x + 0.4, y - 0.2, 0.2, 15.0));
                dashes.push(seg(x, y, 15.0, 0.0));
            }
        }
        let bars: Vec<u32> = (0..crosses.len() as u32).map(|i| i % 2).collect();
        let got = instances(&crosses, &bars, |_| false, || None).expect("crosses group");
        assert_eq!(got.len(), 9);
        assert!(got.iter().all(|g| g.len() == 2 && g[1] == g[0] + 1), "{got:?}");
        assert!(instances(&dashes, &vec![0; dashes.len()], |_| false, || None).is_none());
    }

    #[test]
    fn crosses_whose_arms_meet_their_neighbours_still_group() {
        // Arms of 35 on a 70 lattice: each bar meets the same bar of the next cross.
        let mut crosses = Vec::new();
        for j in 0..3 {
            for i in 0..3 {
                let (x, y) = (70.0 * i as f64, 70.0 * j as f64 + 0.3 * i as f64);
                crosses.push(seg(x, y, 35.0, 0.2));
                crosses.push(seg(x + 0.3, y, 0.2, 35.0));
            }
        }
        let bars: Vec<u32> = (0..crosses.len() as u32).map(|i| i % 2).collect();
        let got = instances(&crosses, &bars, |_| false, || None).expect("crosses group");
        assert_eq!(got.len(), 9, "{got:?}");
        assert!(got.iter().all(|g| g.len() == 2 && g[1] == g[0] + 1), "{got:?}");
    }

    #[test]
    fn a_mesh_whose_pieces_all_touch_is_no_grouping() {
        let mut mesh = Vec::new();
        for j in 0..5 {
            for i in 0..5 {
                let (x, y) = (20.0 * i as f64, 20.0 * j as f64);
                mesh.push(Stroke::new(vec![[x, y], [x + 20.0, y], [x, y + 20.0]], 1.0, Some(Rgb([0, 0, 0]))));
            }
        }
        assert!(instances(&mesh, &vec![0; mesh.len()], |_| false, || None).is_none());
    }

    #[test]
    fn a_gap_asked_with_no_reach_is_not_remembered_as_none() {
        let (a, b) = (seg(3.7, 1.3, 10.0, 0.0), seg(3.7, 21.3, 10.0, 0.0));
        let (pa, pb) = (Path::of(&a), Path::of(&b));
        assert_eq!(gap(&a, &pa, &b, &pb, 0.0), 0.0);
        let g = gap(&a, &pa, &b, &pb, 100.0);
        assert!((g - (20.0 - a.width)).abs() < 1e-9, "gap {g}");
        assert_eq!(gap(&a, &pa, &b, &pb, 5.0), 5.0);
    }

    #[test]
    fn the_cut_needs_a_clear_gap() {
        assert!(cuts(&[10.0, 11.0, 12.0], 13.0, 0.3).is_empty());
        let c = cuts(&[0.0, 0.1, 0.2], 10.0, 0.3);
        assert!(c.len() == 1 && c[0] > 0.2 && c[0] < 10.0, "{c:?}");
        // Strokes of letters, letters of words, words: both gaps, the clearer first.
        let c = cuts(&[0.0, 0.0, 4.0, 4.0, 30.0], 60.0, 0.3);
        assert!(c.len() == 2 && c[0] < 4.0 && c[1] > 4.0 && c[1] < 30.0, "{c:?}");
    }
}
