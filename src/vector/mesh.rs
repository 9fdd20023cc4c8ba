//! Tessellations: examples whose pieces share their edges (a low-poly triangle mesh).
//!
//! Placed one by one, as elements, pieces from different places of the example meet
//! with gaps and overlaps (a third of a mesh's area uncovered, a third covered twice).
//! Here the pieces are not placed at all: the mesh's *vertices* are synthesized as
//! points (growth keeps their spacing and arrangement, as it keeps any element's),
//! triangulated afresh (Delaunay, which covers their hull with no gap and no overlap),
//! and each new triangle is painted like an example triangle whose neighbours' paints
//! agree best with its own neighbours' painted so far (a few random candidates each, as
//! the mosaic picks windows): the mix of paints and which paints sit together are the
//! example's.
//!
//! A mesh of larger pieces (quads, hexagons, any polygons up to twelve sides) is made
//! the dual way: the pieces' *centres* are grown, and each new piece is the Voronoi cell
//! of its centre (the circumcentres of the Delaunay triangles about it), which again
//! covers the area with no gap and no overlap; a square or hexagonal lattice of centres
//! gives back squares or hexagons, a jittered one cells of four to six sides.
//!
//! A filled stroke behind the mesh that covers its bounds (a background) is kept, as a
//! rectangle over the whole output.

use super::element::Element;
use super::grow::{grow, GrowOptions, Grown};
use super::stroke::Stroke;
use crate::error::{Error, Result};
use crate::progress::Throttle;
use crate::rng::Rng;
use kurbo::{Point, Rect, Vec2};

/// Share of the strokes that must be pieces (filled polygons), and of their edges that
/// must be shared with exactly one other piece, for the example to be read as a mesh (an
/// 8 x 8 grid of cells cut in two shares 85% of its edges; triangles that only meet at
/// corners, none).
const PIECES: f64 = 0.9;
const SHARED: f64 = 0.6;
/// The most corners of a piece: beyond, a filled outline is a shape, not a facet.
const MAX_CORNERS: usize = 12;
/// Share of the bounds of the mesh a stroke behind it must cover to be its background.
const BACKGROUND: f64 = 0.9;
/// Random example triangles tried per new one.
const TRIES: usize = 12;

/// A mesh joined afresh: its triangles, the example stroke each copies, and how the
/// vertices grew.
pub struct Joined {
    pub strokes: Vec<Stroke>,
    pub sources: Vec<u32>,
    pub grown: Grown,
}

/// A mesh read from an example: its vertices, each piece's corners and the pieces that
/// share an edge with each.
pub struct Mesh {
    vertices: Vec<Point>,
    /// Per stroke: its corners (`None` for a stroke that is no piece).
    corners: Vec<Option<Vec<u32>>>,
    neighbours: Vec<Vec<u32>>,
    /// Strokes behind the mesh that cover it.
    background: Vec<u32>,
}

impl Mesh {
    /// The mesh `strokes` form, if they are one: at least eight filled pieces (polygons
    /// of three to twelve corners), nearly all strokes (the few others, a frame or a
    /// stray, are left out of the output; a background is kept), most of whose edges
    /// border another piece's (corners meeting to a thousandth of the typical edge).
    pub fn of(strokes: &[Stroke]) -> Option<Mesh> {
        // (Checked before anything is copied: this runs on every synthesis.)
        let piece = |s: &Stroke| {
            let p = &s.points;
            let n = if p.len() > 3 && p.first() == p.last() { p.len() - 1 } else { p.len() };
            (s.fill.is_some() && s.breaks.is_empty() && (3..=MAX_CORNERS).contains(&n)).then(|| p[..n].to_vec())
        };
        let count = strokes.iter().filter(|s| piece(s).is_some()).count();
        if count < 8 || (count as f64) < PIECES * strokes.len() as f64 {
            return None;
        }
        let mut tris: Vec<Option<Vec<[f64; 2]>>> = strokes.iter().map(piece).collect();
        // A filled stroke that covers the pieces' bounds is behind them: their background
        // (a rectangle is a polygon too, but no facet to copy).
        let bounds = tris.iter().flatten().flatten().fold(Rect::new(f64::MAX, f64::MAX, f64::MIN, f64::MIN), |r, p| {
            Rect::new(r.x0.min(p[0]), r.y0.min(p[1]), r.x1.max(p[0]), r.y1.max(p[1]))
        });
        let background: Vec<u32> = (0..strokes.len() as u32)
            .filter(|&i| strokes[i as usize].fill.is_some())
            .filter(|&i| strokes[i as usize].bounds().intersect(bounds).area() >= BACKGROUND * bounds.area())
            .collect();
        for &i in &background {
            tris[i as usize] = None;
        }
        if tris.iter().flatten().count() < 8 {
            return None;
        }
        let mut edges: Vec<f64> = tris
            .iter()
            .flatten()
            .flat_map(|t| {
                (0..t.len()).map(move |k| {
                    let (a, b) = (t[k], t[(k + 1) % t.len()]);
                    Point::new(a[0], a[1]).distance(Point::new(b[0], b[1]))
                })
            })
            .collect();
        crate::order::floats(&mut edges);
        let eps = 1e-3 * edges[edges.len() / 2];
        // Degenerate pieces (points, not triangles), or coordinates so far out that the
        // rounding below would not hold them: no mesh.
        let far = tris.iter().flatten().flatten().any(|p| p[0].abs().max(p[1].abs()) / eps > 1e12);
        if !eps.is_finite() || eps <= 0.0 || far {
            return None;
        }
        // Corners merged by rounding to `eps` (and looked up in the neighbouring cells,
        // so two on either side of a rounding edge still meet).
        let mut index: std::collections::HashMap<(i64, i64), u32> = std::collections::HashMap::new();
        let mut vertices: Vec<Point> = Vec::new();
        let mut vertex = |p: [f64; 2]| -> u32 {
            let key = ((p[0] / eps).round() as i64, (p[1] / eps).round() as i64);
            for dx in -1..=1 {
                for dy in -1..=1 {
                    if let Some(&v) = index.get(&(key.0 + dx, key.1 + dy)) {
                        return v;
                    }
                }
            }
            index.insert(key, vertices.len() as u32);
            vertices.push(Point::new(p[0], p[1]));
            vertices.len() as u32 - 1
        };
        let corners: Vec<Option<Vec<u32>>> = tris
            .iter()
            .map(|t| t.as_ref().map(|t| t.iter().map(|&p| vertex(p)).collect::<Vec<u32>>()))
            // A piece two of whose corners merged is a sliver: no piece of the mesh.
            .map(|c| {
                c.filter(|c| {
                    let mut d = c.clone();
                    d.sort_unstable();
                    d.dedup();
                    d.len() == c.len()
                })
            })
            .collect();
        // Pieces sharing an edge: a mesh's edges each border two pieces (one at its
        // rim). Pieces stacked on one another share an edge among more: not a mesh.
        let mut by_edge: std::collections::HashMap<(u32, u32), Vec<u32>> = std::collections::HashMap::new();
        for (i, c) in corners.iter().enumerate() {
            if let Some(c) = c {
                for k in 0..c.len() {
                    let (a, b) = (c[k], c[(k + 1) % c.len()]);
                    let faces = by_edge.entry((a.min(b), a.max(b))).or_default();
                    if faces.len() >= 2 {
                        return None;
                    }
                    faces.push(i as u32);
                }
            }
        }
        let shared = by_edge.values().filter(|f| f.len() == 2).count();
        if (shared as f64) < SHARED * by_edge.len() as f64 {
            return None;
        }
        let mut neighbours = vec![Vec::new(); strokes.len()];
        for faces in by_edge.values().filter(|f| f.len() == 2) {
            neighbours[faces[0] as usize].push(faces[1]);
            neighbours[faces[1] as usize].push(faces[0]);
        }
        Some(Mesh { vertices, corners, neighbours, background })
    }

    /// The pieces' most common number of sides: triangles and quads are joined afresh
    /// from the vertices, larger pieces from their centres.
    fn sides(&self) -> usize {
        let mut count = [0usize; MAX_CORNERS + 1];
        self.corners.iter().flatten().for_each(|c| count[c.len()] += 1);
        (3..=MAX_CORNERS).max_by_key(|&n| (count[n], std::cmp::Reverse(n))).unwrap_or(3)
    }

    /// A new mesh over `area`: its pieces as strokes painted from the example's, with the
    /// example stroke each copies (the background first). `opts` carries growth's options
    /// for the points grown. `None` when the grown points make no triangle (they all lie
    /// on a line).
    pub fn synthesize(
        &self,
        strokes: &[Stroke],
        area: Rect,
        opts: &GrowOptions,
        progress: &mut Throttle,
    ) -> Result<Option<Joined>> {
        let sides = self.sides();
        // Triangles and quads are joined from the vertices, other pieces from their centres.
        let from_vertices = sides <= 4;
        let seeds: Vec<Point> = if from_vertices {
            self.vertices.clone()
        } else {
            self.corners
                .iter()
                .flatten()
                .map(|c| centroid(&c.iter().map(|&v| self.vertices[v as usize]).collect::<Vec<_>>()))
                .collect()
        };
        let elems: Vec<Element> = seeds.iter().map(|&pos| Element { pos, class: 0 }).collect();
        let spacing = super::reference::Spread::new(&elems)?.spacing;
        // The points grown a typical edge beyond the area, so its edges are covered.
        let pad = 1.5 * spacing;
        // The output's allowance is in pieces: about two triangles (or one quad) per
        // vertex, one cell per centre.
        let per_point = if sides == 3 { 2 } else { 1 };
        let grow_opts = GrowOptions {
            width: area.width() + 2.0 * pad,
            height: area.height() + 2.0 * pad,
            extents: Vec::new(),
            max_elements: opts.max_elements / per_point,
            ..opts.clone()
        };
        let grown = grow(&elems, &grow_opts, progress).map_err(|e| match e {
            Error::TooLarge(_) => Error::TooLarge(format!(
                "This mesh would be cut into more than {} pieces, the limit. Use a smaller output or larger pieces.",
                opts.max_elements
            )),
            e => e,
        })?;
        let shift = Vec2::new(area.x0 - pad, area.y0 - pad);
        let points: Vec<Point> = grown.placed.iter().map(|p| p.pos + shift).collect();
        let coords: Vec<delaunator::Point> = points.iter().map(|p| delaunator::Point { x: p.x, y: p.y }).collect();
        let t = delaunator::triangulate(&coords);
        if t.triangles.is_empty() {
            return Ok(None);
        }
        // The new pieces (corners, and the pieces across their edges).
        let (pieces, adjacent) = match sides {
            3 => faces(&t, &points),
            4 => quads(&t, &points),
            _ => cells(&t, &points),
        };
        let examples: Vec<u32> = (0..strokes.len() as u32).filter(|&i| self.corners[i as usize].is_some()).collect();
        let paint = |s: &Stroke| (s.fill, s.stroke, s.width.to_bits(), s.opacity.to_bits());
        let mut rng = Rng::new(opts.seed ^ 0x6d65_7368);
        let mut source: Vec<Option<u32>> = vec![None; pieces.len()];
        let (mut out, mut sources) = (Vec::new(), Vec::new());
        for &b in &self.background {
            let mut s = strokes[b as usize].clone();
            s.points = vec![[area.x0, area.y0], [area.x1, area.y0], [area.x1, area.y1], [area.x0, area.y1]];
            s.closed = true;
            s.breaks.clear();
            out.push(s);
            sources.push(b);
        }
        for (f, corners) in pieces.iter().enumerate() {
            let Some(corners) = corners else { continue };
            let bounds = corners.iter().fold(Rect::from_points(corners[0], corners[0]), |r, &p| r.union_pt(p));
            if bounds.intersect(area).is_zero_area() {
                continue;
            }
            // Of a few random example pieces, the one whose neighbours' paints are most
            // like the paints around this one so far.
            let painted: Vec<u32> = adjacent[f].iter().filter_map(|&g| source[g as usize]).collect();
            let score = |e: u32| {
                painted
                    .iter()
                    .filter(|&&p| {
                        self.neighbours[e as usize]
                            .iter()
                            .any(|&n| paint(&strokes[n as usize]) == paint(&strokes[p as usize]))
                    })
                    .count()
            };
            let mut best = examples[rng.below(examples.len())];
            let mut best_score = score(best);
            for _ in 1..TRIES {
                let e = examples[rng.below(examples.len())];
                let s = score(e);
                if s > best_score {
                    (best, best_score) = (e, s);
                }
            }
            source[f] = Some(best);
            let mut s = strokes[best as usize].clone();
            s.points = corners.iter().map(|p| [p.x, p.y]).collect();
            s.closed = true;
            out.push(s);
            sources.push(best);
        }
        Ok(Some(Joined { strokes: out, sources, grown }))
    }
}

/// New pieces with their corners (`None` for none) and the pieces across their edges.
type Pieces = (Vec<Option<Vec<Point>>>, Vec<Vec<u32>>);

/// The Delaunay triangles of `points`, and the triangles across each one's edges.
fn faces(t: &delaunator::Triangulation, points: &[Point]) -> Pieces {
    let faces = t.triangles.len() / 3;
    let corners = (0..faces).map(|f| Some((0..3).map(|k| points[t.triangles[3 * f + k]]).collect())).collect();
    let adjacent = (0..faces)
        .map(|f| {
            (0..3)
                .filter_map(|k| {
                    let h = t.halfedges[3 * f + k];
                    (h != delaunator::EMPTY).then_some((h / 3) as u32)
                })
                .collect()
        })
        .collect();
    (corners, adjacent)
}

/// The Delaunay triangles of `points` paired into quads: two triangles whose longest
/// edge is the one they share (a quad cut along its diagonal) become that quad; the
/// others stay triangles. With the pieces across each one's edges.
fn quads(t: &delaunator::Triangulation, points: &[Point]) -> Pieces {
    let faces = t.triangles.len() / 3;
    let next = |e: usize| if e % 3 == 2 { e - 2 } else { e + 1 };
    let length = |e: usize| points[t.triangles[e]].distance(points[t.triangles[next(e)]]);
    let longest = |f: usize| (3 * f..3 * f + 3).max_by(|&a, &b| length(a).total_cmp(&length(b))).expect("three edges");
    // Per triangle, the piece it is part of.
    let mut piece = vec![u32::MAX; faces];
    let mut corners: Vec<Option<Vec<Point>>> = Vec::new();
    for f in 0..faces {
        if piece[f] != u32::MAX {
            continue;
        }
        let e = longest(f);
        let h = t.halfedges[e];
        let paired = h != delaunator::EMPTY && piece[h / 3] == u32::MAX && longest(h / 3) == h;
        let at = |e: usize| points[t.triangles[e]];
        piece[f] = corners.len() as u32;
        if paired {
            // Triangles A B C and B A D: the quad A D B C.
            piece[h / 3] = corners.len() as u32;
            corners.push(Some(vec![at(e), at(next(next(h))), at(next(e)), at(next(next(e)))]));
        } else {
            corners.push(Some((3 * f..3 * f + 3).map(at).collect()));
        }
    }
    let mut adjacent: Vec<Vec<u32>> = vec![Vec::new(); corners.len()];
    for e in 0..t.triangles.len() {
        let h = t.halfedges[e];
        if h != delaunator::EMPTY {
            let (p, q) = (piece[e / 3], piece[h / 3]);
            if p != q && !adjacent[p as usize].contains(&q) {
                adjacent[p as usize].push(q);
            }
        }
    }
    (corners, adjacent)
}

/// The Voronoi cells of `points` (the circumcentres of the Delaunay triangles about
/// each, in turn), and the points whose cells share an edge with each. A point on the
/// hull has an unbounded cell: `None`.
fn cells(t: &delaunator::Triangulation, points: &[Point]) -> Pieces {
    let next = |e: usize| if e % 3 == 2 { e - 2 } else { e + 1 };
    let centre = |f: usize| {
        let [a, b, c] = [0, 1, 2].map(|k| points[t.triangles[3 * f + k]]);
        circumcentre(a, b, c)
    };
    // A halfedge ending at each point (the first found), to walk around it.
    let mut incoming = vec![delaunator::EMPTY; points.len()];
    for e in 0..t.triangles.len() {
        let end = t.triangles[next(e)];
        if incoming[end] == delaunator::EMPTY || t.halfedges[e] == delaunator::EMPTY {
            // A hull edge ending here is where a walk would stop: start there instead.
            incoming[end] = e;
        }
    }
    let mut corners = vec![None; points.len()];
    let mut adjacent = vec![Vec::new(); points.len()];
    for (p, &start) in incoming.iter().enumerate() {
        if start == delaunator::EMPTY {
            continue;
        }
        let (mut ring, mut around) = (Vec::new(), Vec::new());
        let mut e = start;
        let closed = loop {
            let c = centre(e / 3);
            // Cocircular points (a square lattice) give one circumcentre twice.
            if ring.last().is_none_or(|&q: &Point| q.distance(c) > 1e-9 * (1.0 + c.to_vec2().hypot())) {
                ring.push(c);
            }
            around.push(t.triangles[e] as u32);
            let out = next(e);
            match t.halfedges[out] {
                h if h == delaunator::EMPTY => break false,
                h if h == start => break true,
                h => e = h,
            }
        };
        if closed
            && ring.len() > 2
            && ring[0].distance(ring[ring.len() - 1]) <= 1e-9 * (1.0 + ring[0].to_vec2().hypot())
        {
            ring.pop();
        }
        adjacent[p] = around;
        if closed && ring.len() >= 3 {
            corners[p] = Some(ring);
        }
    }
    (corners, adjacent)
}

/// The centre of the circle through `a`, `b` and `c`.
fn circumcentre(a: Point, b: Point, c: Point) -> Point {
    let (b, c) = (b - a, c - a);
    let d = 2.0 * b.cross(c);
    let (b2, c2) = (b.hypot2(), c.hypot2());
    a + Vec2::new(c.y * b2 - b.y * c2, b.x * c2 - c.x * b2) / d
}

/// The centroid of the polygon `p` (its area's, not its corners').
fn centroid(p: &[Point]) -> Point {
    let (mut area, mut sum) = (0.0, Vec2::ZERO);
    for k in 0..p.len() {
        let (a, b) = (p[k].to_vec2(), p[(k + 1) % p.len()].to_vec2());
        let cross = a.cross(b);
        area += cross;
        sum += (a + b) * cross;
    }
    if area.abs() < 1e-12 {
        let mean = p.iter().fold(Vec2::ZERO, |s, q| s + q.to_vec2()) / p.len() as f64;
        return mean.to_point();
    }
    (sum / (3.0 * area)).to_point()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::vector::color::Rgb;

    fn filled(points: Vec<[f64; 2]>) -> Stroke {
        let mut s = Stroke::new(points, 0.0, None);
        s.fill = Some(Rgb([200, 90, 60]));
        s.closed = true;
        s
    }

    #[test]
    fn stacked_or_degenerate_pieces_are_no_mesh() {
        // 20,000 copies of one triangle share each edge among all of them: refused at
        // the third, not listed pairwise.
        let stacked: Vec<Stroke> = (0..20_000).map(|_| filled(vec![[0.0, 0.0], [10.0, 0.0], [0.0, 10.0]])).collect();
        assert!(Mesh::of(&stacked).is_none());
        // Triangles of three equal points, far out: no edge length to merge corners by.
        let points: Vec<Stroke> = (0..10).map(|i| filled(vec![[1e4, 1e4 + i as f64]; 3])).collect();
        assert!(Mesh::of(&points).is_none());
    }
}
