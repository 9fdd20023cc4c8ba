//! Splitting a compound path into the parts a person sees as separate shapes.
//!
//! A `<path>` with several subpaths is split into groups that neither contain nor
//! cross one another: a ring's inner circle (its hole) stays with the outer one, the
//! two strokes of an X stay together, and the dots of a row drawn as one path come
//! apart. Containment: one subpath's box lies within another's (not equal) and most of
//! its vertices are inside the other's polygon. Crossing: two segments intersect
//! properly; edges that only touch or run along each other (abutting tiles) do not
//! count, so shapes cut at a tile edge stay separate.

/// An axis-aligned box `[x0, y0, x1, y1]`.
type Box2 = [f64; 4];

/// Segment pairs tested for crossings before the test falls back to overlapping boxes
/// (a path of thousands of subpaths piled on one another).
const MAX_SEGMENT_TESTS: u64 = 4_000_000;

/// Groups of subpath indices (each group ascending, groups by first index). A subpath
/// is `(points, closed)`; `filled` says whether closed areas count for containment
/// when the subpath is open (SVG fills an open subpath as if closed).
pub fn groups(subpaths: &[(Vec<[f64; 2]>, bool)], filled: bool) -> Vec<Vec<usize>> {
    let n = subpaths.len();
    let boxes: Vec<Box2> = subpaths.iter().map(|(p, _)| bounds(p)).collect();
    let mut parent: Vec<usize> = (0..n).collect();
    let order = crate::order::by_key(&boxes.iter().map(|b| b[0]).collect::<Vec<_>>());
    let mut tests = 0u64;
    for (k, &a) in order.iter().enumerate() {
        for &b in &order[k + 1..] {
            if boxes[b][0] > boxes[a][2] {
                break;
            }
            if boxes[b][1] > boxes[a][3] || boxes[a][1] > boxes[b][3] || find(&mut parent, a) == find(&mut parent, b) {
                continue;
            }
            let (pa, pb) = (&subpaths[a], &subpaths[b]);
            let area = |p: &(Vec<[f64; 2]>, bool)| (p.1 || filled) && p.0.len() >= 3;
            let related = (area(pa) && contains(&pa.0, &boxes[a], &pb.0, &boxes[b]))
                || (area(pb) && contains(&pb.0, &boxes[b], &pa.0, &boxes[a]))
                || if tests < MAX_SEGMENT_TESTS {
                    crosses(pa, pb, &boxes[a], &boxes[b], &mut tests)
                } else {
                    overlap_area(&boxes[a], &boxes[b]) > 0.0
                };
            if related {
                let (ra, rb) = (find(&mut parent, a), find(&mut parent, b));
                parent[ra.max(rb)] = ra.min(rb);
            }
        }
    }
    let mut out: Vec<Vec<usize>> = Vec::new();
    let mut slot = vec![usize::MAX; n];
    for i in 0..n {
        let r = find(&mut parent, i);
        if slot[r] == usize::MAX {
            slot[r] = out.len();
            out.push(Vec::new());
        }
        out[slot[r]].push(i);
    }
    out
}

fn find(parent: &mut [usize], mut i: usize) -> usize {
    while parent[i] != i {
        parent[i] = parent[parent[i]];
        i = parent[i];
    }
    i
}

fn bounds(points: &[[f64; 2]]) -> Box2 {
    points.iter().fold([f64::INFINITY, f64::INFINITY, f64::NEG_INFINITY, f64::NEG_INFINITY], |b, &[x, y]| {
        [b[0].min(x), b[1].min(y), b[2].max(x), b[3].max(y)]
    })
}

fn overlap_area(a: &Box2, b: &Box2) -> f64 {
    (a[2].min(b[2]) - a[0].max(b[0])).max(0.0) * (a[3].min(b[3]) - a[1].max(b[1])).max(0.0)
}

/// Whether polygon `outer` contains `inner`: its box within, not equal, and more than
/// half of its vertices inside (even-odd). Vertices on the outline (a cut-out touching
/// the edge of its frame, a tile cut at its border) decide nothing: rounding would put
/// them in or out differently in each copy of a repeat. When every vertex is on the
/// outline, the midpoints of the inner's edges vote instead.
fn contains(outer: &[[f64; 2]], ob: &Box2, inner: &[[f64; 2]], ib: &Box2) -> bool {
    let within = ib[0] >= ob[0] && ib[1] >= ob[1] && ib[2] <= ob[2] && ib[3] <= ob[3];
    if !within || ib == ob {
        return false;
    }
    let eps = 1e-7 * (ob[2] - ob[0]).max(ob[3] - ob[1]);
    let vote = |points: &mut dyn Iterator<Item = [f64; 2]>| {
        let (mut inside, mut decided) = (0, 0);
        for p in points {
            if let Some(is_in) = side(p, outer, eps) {
                decided += 1;
                inside += usize::from(is_in);
            }
        }
        (decided > 0).then_some(2 * inside > decided)
    };
    // At most 64 vertices, evenly spread: enough for a majority vote.
    let step = inner.len().div_ceil(64).max(1);
    vote(&mut inner.iter().copied().step_by(step)).or_else(|| {
        let n = inner.len();
        vote(&mut (0..n).step_by(step).map(|i| {
            let (a, b) = (inner[i], inner[(i + 1) % n]);
            [0.5 * (a[0] + b[0]), 0.5 * (a[1] + b[1])]
        }))
    }) == Some(true)
}

/// Whether `p` is inside `poly` (even-odd), or `None` within `eps` of its outline.
fn side([x, y]: [f64; 2], poly: &[[f64; 2]], eps: f64) -> Option<bool> {
    let mut inside = false;
    let mut j = poly.len() - 1;
    for i in 0..poly.len() {
        let ([xi, yi], [xj, yj]) = (poly[i], poly[j]);
        if near_segment([x, y], poly[j], poly[i], eps) {
            return None;
        }
        if (yi > y) != (yj > y) && x < (xj - xi) * (y - yi) / (yj - yi) + xi {
            inside = !inside;
        }
        j = i;
    }
    Some(inside)
}

/// Whether `p` lies within `eps` of the segment `a`-`b`.
fn near_segment(p: [f64; 2], a: [f64; 2], b: [f64; 2], eps: f64) -> bool {
    if p[0] < a[0].min(b[0]) - eps
        || p[0] > a[0].max(b[0]) + eps
        || p[1] < a[1].min(b[1]) - eps
        || p[1] > a[1].max(b[1]) + eps
    {
        return false;
    }
    let (dx, dy) = (b[0] - a[0], b[1] - a[1]);
    let len2 = dx * dx + dy * dy;
    let t = if len2 > 0.0 { (((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / len2).clamp(0.0, 1.0) } else { 0.0 };
    let (ex, ey) = (a[0] + t * dx - p[0], a[1] + t * dy - p[1]);
    ex * ex + ey * ey <= eps * eps
}

/// The segments of a subpath (with the closing one when closed).
fn segments(p: &(Vec<[f64; 2]>, bool)) -> impl Iterator<Item = ([f64; 2], [f64; 2])> + '_ {
    let pts = &p.0;
    let closing = (p.1 && pts.len() > 2).then(|| (pts[pts.len() - 1], pts[0]));
    pts.windows(2).map(|w| (w[0], w[1])).chain(closing)
}

/// Whether a segment of `a` properly crosses one of `b` (within the boxes' overlap).
fn crosses(a: &(Vec<[f64; 2]>, bool), b: &(Vec<[f64; 2]>, bool), ab: &Box2, bb: &Box2, tests: &mut u64) -> bool {
    let clip = [ab[0].max(bb[0]), ab[1].max(bb[1]), ab[2].min(bb[2]), ab[3].min(bb[3])];
    let touches = |(p, q): &([f64; 2], [f64; 2])| {
        p[0].max(q[0]) >= clip[0] && p[0].min(q[0]) <= clip[2] && p[1].max(q[1]) >= clip[1] && p[1].min(q[1]) <= clip[3]
    };
    let sb: Vec<_> = segments(b).filter(touches).collect();
    for s in segments(a).filter(touches) {
        *tests += sb.len() as u64;
        if sb.iter().any(|t| proper_crossing(s, *t)) {
            return true;
        }
    }
    false
}

fn orient(a: [f64; 2], b: [f64; 2], c: [f64; 2]) -> f64 {
    (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])
}

/// Segments that cross at a point interior to both (not touching, not collinear).
fn proper_crossing((p, q): ([f64; 2], [f64; 2]), (r, s): ([f64; 2], [f64; 2])) -> bool {
    let (d1, d2) = (orient(p, q, r), orient(p, q, s));
    let (d3, d4) = (orient(r, s, p), orient(r, s, q));
    d1 * d2 < 0.0 && d3 * d4 < 0.0
}

#[cfg(test)]
mod tests {
    use super::*;

    fn square(x: f64, y: f64, s: f64) -> (Vec<[f64; 2]>, bool) {
        (vec![[x, y], [x + s, y], [x + s, y + s], [x, y + s]], true)
    }

    #[test]
    fn holes_stay_with_their_outline_and_separate_shapes_split() {
        // A ring (outer, hole), a separate square, and a square abutting the first.
        let parts = [square(0.0, 0.0, 10.0), square(3.0, 3.0, 4.0), square(20.0, 0.0, 5.0), square(10.0, 0.0, 10.0)];
        assert_eq!(groups(&parts, true), vec![vec![0, 1], vec![2], vec![3]]);
    }

    #[test]
    fn crossing_strokes_stay_together() {
        let x = [(vec![[0.0, 0.0], [10.0, 10.0]], false), (vec![[10.0, 0.0], [0.0, 10.0]], false)];
        assert_eq!(groups(&x, false), vec![vec![0, 1]]);
        let apart = [(vec![[0.0, 0.0], [10.0, 0.0]], false), (vec![[0.0, 5.0], [10.0, 5.0]], false)];
        assert_eq!(groups(&apart, false), vec![vec![0], vec![1]]);
    }

    #[test]
    fn cut_outs_touching_the_frame_stay_with_it_in_every_copy() {
        // A frame (a square with a triangular cut-out whose corner lies on the frame's
        // right edge), repeated at offsets where rounding differs.
        for k in 0..40 {
            let o = 36.0 * k as f64 + 0.1 * k as f64;
            let frame = (vec![[o + 36.0, 0.0], [o, 0.0], [o, 36.0], [o + 36.0, 36.0]], true);
            let cut = (vec![[o + 36.0, 22.874], [o + 36.0, 36.0], [o + 22.874, 36.0], [o + 30.0, 30.0]], true);
            assert_eq!(groups(&[frame, cut], true), vec![vec![0, 1]], "copy {k}");
        }
        // Every vertex on the outline: the edge midpoints decide.
        let frame = square(0.0, 0.0, 10.0);
        let corner = (vec![[10.0, 2.0], [10.0, 8.0], [5.0, 10.0]], true);
        assert_eq!(groups(&[frame, corner], true), vec![vec![0, 1]]);
    }

    #[test]
    fn an_open_outline_contains_only_when_filled() {
        let open = (vec![[0.0, 0.0], [10.0, 0.0], [10.0, 10.0], [0.0, 10.0]], false);
        let dot = square(4.0, 4.0, 1.0);
        assert_eq!(groups(&[open.clone(), dot.clone()], true).len(), 1);
        assert_eq!(groups(&[open, dot], false).len(), 2);
    }
}
