//! Generated example patterns with a known lattice: the families the vector engine must
//! handle (SPEC 1.5). They serve the tests, the benchmark and the playground's built-in
//! examples. Positions are jittered as hand-drawn patterns are.

use super::color::Rgb;
use super::stroke::Stroke;
use crate::rng::Rng;
use kurbo::{Point, Vec2};

/// A periodic arrangement: sites `origin + i a + j b + motif[k].0` (j = 0 only when `b`
/// is `None`, a row).
#[derive(Clone, Debug)]
pub struct Lattice {
    pub origin: Point,
    pub a: Vec2,
    pub b: Option<Vec2>,
    /// Offset and class of each site of one period.
    pub motif: Vec<(Vec2, u32)>,
}

impl Lattice {
    /// The smallest distance between two distinct sites: the scale of the pattern.
    pub fn spacing(&self) -> f64 {
        let mut best = f64::INFINITY;
        for (oi, _) in &self.motif {
            for (oj, _) in &self.motif {
                for i in -2i32..=2 {
                    for j in -2i32..=2 {
                        if self.b.is_none() && j != 0 {
                            continue;
                        }
                        let d = *oj + self.a * i as f64 + self.b.unwrap_or(Vec2::ZERO) * j as f64 - *oi;
                        if d.hypot() > 1e-9 {
                            best = best.min(d.hypot());
                        }
                    }
                }
            }
        }
        best
    }

    /// Every site whose position falls within `[x0, x1] x [y0, y1]`: position, class,
    /// cell indices `i`, `j` and motif offset.
    pub fn sites_in(&self, x0: f64, y0: f64, x1: f64, y1: f64) -> Vec<(Point, u32, i64, i64, Vec2)> {
        // Enough periods to cover the box from the origin in every direction.
        let reach = (x1 - x0).abs() + (y1 - y0).abs() + (self.origin.x - x0).abs() + (self.origin.y - y0).abs();
        let b = self.b.unwrap_or(Vec2::ZERO);
        let det = (self.a.x * b.y - self.a.y * b.x).abs();
        let n = |v: Vec2| (reach / (if det > 0.0 { det / v.hypot() } else { v.hypot() }).max(1e-9)).ceil() as i64 + 2;
        let ni = n(if self.b.is_some() { b } else { self.a }).max(n(self.a));
        let nj = if self.b.is_some() { n(self.a).max(n(b)) } else { 0 };
        let mut out = Vec::new();
        for i in -ni..=ni {
            for j in -nj..=nj {
                for &(m, c) in &self.motif {
                    let p = self.origin + self.a * i as f64 + b * j as f64 + m;
                    if p.x >= x0 && p.x <= x1 && p.y >= y0 && p.y <= y1 {
                        out.push((p, c, i, j, m));
                    }
                }
            }
        }
        out
    }
}

/// An example: strokes to synthesize from, and the lattice they were drawn on.
#[derive(Clone, Debug)]
pub struct Exemplar {
    pub name: &'static str,
    pub strokes: Vec<Stroke>,
    /// The generator's class of each stroke (the engine numbers its own).
    pub classes: Vec<u32>,
    pub lattice: Lattice,
}

fn dash(centre: Point, d: Vec2, width: f64, color: [u8; 3]) -> Stroke {
    let (p, q) = (centre - d * 0.5, centre + d * 0.5);
    Stroke::new(vec![[p.x, p.y], [q.x, q.y]], width, Some(Rgb(color)))
}

fn ring(centre: Point, r: f64, fill: Option<[u8; 3]>, stroke: Option<[u8; 3]>) -> Stroke {
    let points = (0..16)
        .map(|k| {
            let a = k as f64 * std::f64::consts::TAU / 16.0;
            [centre.x + r * a.cos(), centre.y + r * a.sin()]
        })
        .collect();
    let mut s = Stroke::new(points, if stroke.is_some() { 1.5 } else { 0.0 }, stroke.map(Rgb));
    s.fill = fill.map(Rgb);
    s.closed = true;
    s
}

fn chevron(centre: Point, size: f64, color: [u8; 3]) -> Stroke {
    let h = size * 0.5;
    Stroke::new(
        vec![[centre.x - h, centre.y + h * 0.6], [centre.x, centre.y - h * 0.6], [centre.x + h, centre.y + h * 0.6]],
        2.0,
        Some(Rgb(color)),
    )
}

/// The shape drawn for class `c` of a family.
type Motif = fn(Point, u32) -> Stroke;

fn build(name: &'static str, lattice: Lattice, ni: i32, nj: i32, draw: Motif, jitter: f64, seed: u64) -> Exemplar {
    let mut rng = Rng::new(seed);
    let sigma = jitter * lattice.spacing();
    let (mut strokes, mut classes) = (Vec::new(), Vec::new());
    let b = lattice.b.unwrap_or(Vec2::ZERO);
    for j in 0..nj {
        for i in 0..ni {
            for &(m, c) in &lattice.motif {
                let ideal = lattice.origin + lattice.a * i as f64 + b * j as f64 + m;
                let jit = Vec2::new(rng.normal(), rng.normal()) * sigma;
                strokes.push(draw(ideal + jit, c));
                classes.push(c);
            }
        }
    }
    Exemplar { name, strokes, classes, lattice }
}

/// A family of SPEC 1.5: its lattice, how its classes are drawn, and the periods its
/// example spans.
#[derive(Clone, Debug)]
pub struct Family {
    pub name: &'static str,
    pub lattice: Lattice,
    draw: Motif,
    ni: i32,
    nj: i32,
    /// Added to the seed, so the families' jitters differ.
    seed_offset: u64,
}

/// The families of SPEC 1.5.
pub fn family_list() -> Vec<Family> {
    let o = Point::new(20.0, 20.0);
    let one = |off: Vec2| vec![(off, 0u32)];
    vec![
        Family {
            name: "row",
            lattice: Lattice { origin: o, a: Vec2::new(24.0, 0.0), b: None, motif: one(Vec2::ZERO) },
            ni: 10,
            nj: 1,
            draw: |p, _| dash(p, Vec2::new(0.0, 12.0), 2.0, [20, 20, 20]),
            seed_offset: 0,
        },
        Family {
            name: "grid",
            lattice: Lattice {
                origin: o,
                a: Vec2::new(24.0, 0.0),
                b: Some(Vec2::new(0.0, 24.0)),
                motif: one(Vec2::ZERO),
            },
            ni: 6,
            nj: 6,
            draw: |p, _| dash(p, Vec2::new(9.0, 9.0), 2.0, [20, 20, 20]),
            seed_offset: 1,
        },
        Family {
            name: "hexagonal",
            lattice: Lattice {
                origin: o,
                a: Vec2::new(24.0, 0.0),
                b: Some(Vec2::new(12.0, 24.0 * 0.75f64.sqrt())),
                motif: one(Vec2::ZERO),
            },
            ni: 6,
            nj: 6,
            draw: |p, _| ring(p, 5.0, Some([40, 90, 160]), None),
            seed_offset: 2,
        },
        Family {
            name: "brick",
            lattice: Lattice {
                origin: o,
                a: Vec2::new(36.0, 0.0),
                b: Some(Vec2::new(18.0, 14.0)),
                motif: one(Vec2::ZERO),
            },
            ni: 5,
            nj: 6,
            draw: |p, _| dash(p, Vec2::new(26.0, 0.0), 3.0, [150, 60, 30]),
            seed_offset: 3,
        },
        Family {
            name: "classes-by-shape",
            lattice: Lattice {
                origin: o,
                a: Vec2::new(40.0, 0.0),
                b: Some(Vec2::new(0.0, 30.0)),
                motif: vec![(Vec2::ZERO, 0), (Vec2::new(20.0, 0.0), 1), (Vec2::new(10.0, 15.0), 2)],
            },
            ni: 4,
            nj: 5,
            draw: |p, c| match c {
                0 => dash(p, Vec2::new(0.0, 12.0), 2.0, [20, 20, 20]),
                1 => ring(p, 5.0, None, Some([20, 20, 20])),
                _ => chevron(p, 10.0, [20, 20, 20]),
            },
            seed_offset: 4,
        },
        Family {
            name: "classes-by-colour",
            lattice: Lattice {
                origin: o,
                a: Vec2::new(40.0, 0.0),
                b: Some(Vec2::new(0.0, 20.0)),
                motif: vec![(Vec2::ZERO, 0), (Vec2::new(20.0, 0.0), 1)],
            },
            ni: 4,
            nj: 7,
            draw: |p, c| ring(p, 6.0, Some(if c == 0 { [210, 40, 40] } else { [40, 60, 210] }), None),
            seed_offset: 5,
        },
        Family {
            name: "pairs-row",
            lattice: Lattice {
                origin: o,
                a: Vec2::new(34.0, 0.0),
                b: None,
                motif: vec![(Vec2::ZERO, 0), (Vec2::new(9.0, 0.0), 0)],
            },
            ni: 6,
            nj: 1,
            draw: |p, _| dash(p, Vec2::new(0.0, 14.0), 2.0, [20, 20, 20]),
            seed_offset: 6,
        },
        Family {
            name: "pairs-grid",
            lattice: Lattice {
                origin: o,
                a: Vec2::new(34.0, 0.0),
                b: Some(Vec2::new(0.0, 26.0)),
                motif: vec![(Vec2::ZERO, 0), (Vec2::new(9.0, 0.0), 0)],
            },
            ni: 5,
            nj: 5,
            draw: |p, _| dash(p, Vec2::new(0.0, 14.0), 2.0, [20, 20, 20]),
            seed_offset: 7,
        },
    ]
}

/// All families of SPEC 1.5 at jitter `jitter` (fraction of the spacing, e.g. 0.02).
pub fn families(jitter: f64, seed: u64) -> Vec<Exemplar> {
    family_list()
        .into_iter()
        .map(|f| build(f.name, f.lattice, f.ni, f.nj, f.draw, jitter, seed + f.seed_offset))
        .collect()
}

impl Family {
    /// The family drawn over a canvas `periods_x x periods_y` periods of `a` and `b`
    /// across (one row for a row family) from `origin - margin`: every site in it,
    /// jittered, in the order a person would draw them (row after row, copy after
    /// copy), with the canvas.
    pub fn canvas(&self, periods_x: f64, periods_y: f64, jitter: f64, seed: u64) -> (Exemplar, kurbo::Rect) {
        let l = &self.lattice;
        // Half the smallest gap before the first site, so no site sits on an edge.
        let margin = 0.5 * l.spacing();
        let (x0, y0) = (l.origin.x - margin, l.origin.y - margin);
        let extent = |v: Vec2| v.x.abs().max(v.y.abs());
        let motif_x = l.motif.iter().map(|(m, _)| m.x).fold(0.0, f64::max);
        let motif_y = l.motif.iter().map(|(m, _)| m.y).fold(0.0, f64::max);
        let x1 = x0 + periods_x * extent(l.a).max(motif_x + margin);
        let y1 = match l.b {
            Some(b) => y0 + periods_y * b.y.abs(),
            None => l.origin.y + motif_y + margin,
        };
        let mut sites = l.sites_in(x0, y0, x1, y1);
        let index = |m: Vec2| l.motif.iter().position(|(o, _)| *o == m).unwrap_or(0);
        sites.sort_by_key(|s| (s.3, s.2, index(s.4)));
        let mut rng = Rng::new(seed + self.seed_offset);
        let sigma = jitter * l.spacing();
        let (mut strokes, mut classes) = (Vec::new(), Vec::new());
        for (p, c, ..) in sites {
            let jit = Vec2::new(rng.normal(), rng.normal()) * sigma;
            strokes.push((self.draw)(p + jit, c));
            classes.push(c);
        }
        (Exemplar { name: self.name, strokes, classes, lattice: l.clone() }, kurbo::Rect::new(x0, y0, x1, y1))
    }
}

/// A busy tile: `count` elements of three kinds at random places (at least `gap` apart,
/// across tile edges too) in a `period`-square tile, repeated `reps x reps` exactly, as
/// an imported SVG tile would be. A periodic pattern with an irregular motif.
pub fn busy_tile(count: usize, period: f64, gap: f64, reps: i32, seed: u64) -> Exemplar {
    let mut rng = Rng::new(seed);
    let mut motif: Vec<(Vec2, u32)> = Vec::new();
    let mut tries = 0;
    while motif.len() < count && tries < count * 200 {
        tries += 1;
        let p = Vec2::new(rng.next_f64() * period, rng.next_f64() * period);
        let clear = motif.iter().all(|(q, _)| {
            let d = *q - p;
            // Distance on the torus: the tile repeats.
            let dx = d.x.abs().min(period - d.x.abs());
            let dy = d.y.abs().min(period - d.y.abs());
            dx.hypot(dy) >= gap
        });
        if clear {
            motif.push((p, rng.below(3) as u32));
        }
    }
    let lattice =
        Lattice { origin: Point::new(10.0, 10.0), a: Vec2::new(period, 0.0), b: Some(Vec2::new(0.0, period)), motif };
    build(
        "busy-tile",
        lattice,
        reps,
        reps,
        |p, c| match c {
            0 => dash(p, Vec2::new(0.0, 6.0), 1.5, [30, 30, 30]),
            1 => ring(p, 3.0, Some([200, 80, 40]), None),
            _ => chevron(p, 6.0, [40, 90, 160]),
        },
        0.0,
        seed,
    )
}

/// `count` short dashes at random positions in a `side` square: irregular input, with
/// no lattice to find (SPEC 1.5's graceful-degradation case).
pub fn irregular_dashes(count: usize, side: f64, seed: u64) -> Vec<Stroke> {
    let mut rng = Rng::new(seed);
    (0..count)
        .map(|_| {
            let (x, y) = (rng.next_f64() * side, rng.next_f64() * side);
            Stroke::new(vec![[x, y], [x + 6.0, y + 6.0]], 1.5, Some(Rgb([30, 30, 30])))
        })
        .collect()
}

/// `count` freehand strokes in a `side` square: wandering curves of random length,
/// bend and colour, the way a sketch is drawn, with no repetition in it.
pub fn freehand_sketch(count: usize, side: f64, seed: u64) -> Vec<Stroke> {
    let mut rng = Rng::new(seed);
    let palette = [[30, 30, 30], [200, 60, 40], [40, 90, 160]];
    (0..count)
        .map(|_| {
            let (mut x, mut y) = (rng.next_f64() * side, rng.next_f64() * side);
            let mut heading = rng.next_f64() * std::f64::consts::TAU;
            let (steps, step, bend) = (4 + rng.below(12), 2.0 + rng.next_f64() * 10.0, rng.normal() * 0.6);
            let mut points = vec![[x, y]];
            for _ in 0..steps {
                heading += bend + rng.normal() * 0.3;
                x += step * heading.cos();
                y += step * heading.sin();
                points.push([x, y]);
            }
            Stroke::new(points, 1.0 + rng.next_f64() * 3.0, Some(Rgb(palette[rng.below(3)])))
        })
        .collect()
}

/// An example drawing with its name, as the playground lists it.
#[derive(Clone, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct NamedExample {
    pub name: String,
    pub strokes: Vec<Stroke>,
}

/// The playground's built-in examples: every family (lightly jittered, as drawn by
/// hand) and a busy tile repeated 3x3, with coordinates to a thousandth of a unit (what a
/// pointer gives; it keeps the file small).
pub fn playground_examples() -> Vec<NamedExample> {
    let milli = |v: f64| (v * 1000.0).round() / 1000.0;
    families(0.015, 7)
        .into_iter()
        .chain(std::iter::once(busy_tile(120, 100.0, 7.0, 3, 21)))
        .map(|e| NamedExample {
            name: e.name.to_string(),
            strokes: e
                .strokes
                .into_iter()
                .map(|mut s| {
                    s.points.iter_mut().for_each(|p| *p = [milli(p[0]), milli(p[1])]);
                    s.width = milli(s.width);
                    s
                })
                .collect(),
        })
        .collect()
}
