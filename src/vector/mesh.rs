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
//! Only triangle meshes are read so: Delaunay makes triangles, and a mesh of quads or
//! hexagons would come out cut into them.

use super::element::Element;
use super::grow::{grow, GrowOptions, Grown};
use super::stroke::Stroke;
use crate::error::Result;
use crate::progress::Throttle;
use crate::rng::Rng;
use kurbo::{Point, Rect, Vec2};

/// Share of the pieces that must be triangles, and of their edges that must be shared
/// with exactly one other piece, for the example to be read as a mesh (an 8 x 8 grid of
/// cells cut in two shares 85% of its edges; triangles that only meet at corners, none).
const TRIANGLES: f64 = 0.9;
const SHARED: f64 = 0.6;
/// Random example triangles tried per new one.
const TRIES: usize = 12;

/// A mesh joined afresh: its triangles, the example stroke each copies, and how the
/// vertices grew.
pub struct Joined {
    pub strokes: Vec<Stroke>,
    pub sources: Vec<u32>,
    pub grown: Grown,
}

/// A triangle mesh read from an example: its vertices, each piece's corners and the
/// pieces that share an edge with each.
pub struct Mesh {
    vertices: Vec<Point>,
    /// Per stroke: its three corners (`None` for a stroke that is no triangle).
    corners: Vec<Option<[u32; 3]>>,
    neighbours: Vec<Vec<u32>>,
}

impl Mesh {
    /// The mesh `strokes` form, if they are one: at least eight filled pieces, nearly
    /// all triangles (the few others, a frame or a stray, are left out of the output),
    /// most of whose edges border another piece's (corners meeting to a thousandth of
    /// the typical edge).
    pub fn of(strokes: &[Stroke]) -> Option<Mesh> {
        // (Checked before anything is copied: this runs on every synthesis.)
        let triangle = |s: &Stroke| {
            let p = &s.points;
            let closed_twice = p.len() == 4 && p[0] == p[3];
            (s.fill.is_some() && s.breaks.is_empty() && (p.len() == 3 || closed_twice)).then(|| p[..3].to_vec())
        };
        let tris: Vec<Option<Vec<[f64; 2]>>> = strokes.iter().map(triangle).collect();
        let count = tris.iter().flatten().count();
        if count < 8 || (count as f64) < TRIANGLES * strokes.len() as f64 {
            return None;
        }
        let mut edges: Vec<f64> = tris
            .iter()
            .flatten()
            .flat_map(|t| {
                (0..3).map(move |k| {
                    Point::new(t[k][0], t[k][1]).distance(Point::new(t[(k + 1) % 3][0], t[(k + 1) % 3][1]))
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
        let corners: Vec<Option<[u32; 3]>> = tris
            .iter()
            .map(|t| t.as_ref().map(|t| [vertex(t[0]), vertex(t[1]), vertex(t[2])]))
            // A piece whose corners merged is a sliver: no triangle of the mesh.
            .map(|c| c.filter(|c| c[0] != c[1] && c[1] != c[2] && c[0] != c[2]))
            .collect();
        // Pieces sharing an edge: a mesh's edges each border two pieces (one at its
        // rim). Pieces stacked on one another share an edge among more: not a mesh.
        let mut by_edge: std::collections::HashMap<(u32, u32), Vec<u32>> = std::collections::HashMap::new();
        for (i, c) in corners.iter().enumerate() {
            if let Some(c) = c {
                for k in 0..3 {
                    let (a, b) = (c[k], c[(k + 1) % 3]);
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
        Some(Mesh { vertices, corners, neighbours })
    }

    /// A new mesh over `area`: its triangles as strokes painted from the example's, with
    /// the example stroke each copies. `opts` carries growth's options for the vertices.
    /// `None` when the grown vertices make no triangle (they all lie on a line).
    pub fn synthesize(
        &self,
        strokes: &[Stroke],
        area: Rect,
        opts: &GrowOptions,
        progress: &mut Throttle,
    ) -> Result<Option<Joined>> {
        // The vertices grown a typical edge beyond the area, so its edges are covered.
        let elems: Vec<Element> = self.vertices.iter().map(|&pos| Element { pos, class: 0 }).collect();
        let spacing = super::reference::Spread::new(&elems)?.spacing;
        let pad = 1.5 * spacing;
        // About two triangles per vertex: the vertices take half the output's allowance.
        let grow_opts = GrowOptions {
            width: area.width() + 2.0 * pad,
            height: area.height() + 2.0 * pad,
            extents: Vec::new(),
            max_elements: opts.max_elements / 2,
            ..opts.clone()
        };
        let grown = grow(&elems, &grow_opts, progress)?;
        let shift = Vec2::new(area.x0 - pad, area.y0 - pad);
        let points: Vec<Point> = grown.placed.iter().map(|p| p.pos + shift).collect();
        let coords: Vec<delaunator::Point> = points.iter().map(|p| delaunator::Point { x: p.x, y: p.y }).collect();
        let t = delaunator::triangulate(&coords);
        let faces = t.triangles.len() / 3;
        if faces == 0 {
            return Ok(None);
        }
        // New triangles sharing an edge: across each half-edge.
        let halfedges = &t.halfedges;
        let adjacent = |f: usize| {
            (0..3).filter_map(move |k| {
                let h = halfedges[3 * f + k];
                (h != delaunator::EMPTY).then_some(h / 3)
            })
        };
        let examples: Vec<u32> = (0..strokes.len() as u32).filter(|&i| self.corners[i as usize].is_some()).collect();
        let paint = |s: &Stroke| (s.fill, s.stroke, s.width.to_bits(), s.opacity.to_bits());
        let mut rng = Rng::new(opts.seed ^ 0x6d65_7368);
        let mut source: Vec<Option<u32>> = vec![None; faces];
        let (mut out, mut sources) = (Vec::new(), Vec::new());
        for f in 0..faces {
            let corners: Vec<Point> = (0..3).map(|k| points[t.triangles[3 * f + k]]).collect();
            let bounds = Rect::from_points(corners[0], corners[1]).union_pt(corners[2]);
            if bounds.intersect(area).is_zero_area() {
                continue;
            }
            // Of a few random example triangles, the one whose neighbours' paints are
            // most like the paints around this one so far.
            let painted: Vec<u32> = adjacent(f).filter_map(|g| source[g]).collect();
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
