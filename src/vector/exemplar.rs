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

/// All families of SPEC 1.5 at jitter `jitter` (fraction of the spacing, e.g. 0.02).
pub fn families(jitter: f64, seed: u64) -> Vec<Exemplar> {
    let o = Point::new(20.0, 20.0);
    let one = |off: Vec2| vec![(off, 0u32)];
    vec![
        build(
            "row",
            Lattice { origin: o, a: Vec2::new(24.0, 0.0), b: None, motif: one(Vec2::ZERO) },
            10,
            1,
            |p, _| dash(p, Vec2::new(0.0, 12.0), 2.0, [20, 20, 20]),
            jitter,
            seed,
        ),
        build(
            "grid",
            Lattice { origin: o, a: Vec2::new(24.0, 0.0), b: Some(Vec2::new(0.0, 24.0)), motif: one(Vec2::ZERO) },
            6,
            6,
            |p, _| dash(p, Vec2::new(9.0, 9.0), 2.0, [20, 20, 20]),
            jitter,
            seed + 1,
        ),
        build(
            "hexagonal",
            Lattice {
                origin: o,
                a: Vec2::new(24.0, 0.0),
                b: Some(Vec2::new(12.0, 24.0 * 0.75f64.sqrt())),
                motif: one(Vec2::ZERO),
            },
            6,
            6,
            |p, _| ring(p, 5.0, Some([40, 90, 160]), None),
            jitter,
            seed + 2,
        ),
        build(
            "brick",
            Lattice { origin: o, a: Vec2::new(36.0, 0.0), b: Some(Vec2::new(18.0, 14.0)), motif: one(Vec2::ZERO) },
            5,
            6,
            |p, _| dash(p, Vec2::new(26.0, 0.0), 3.0, [150, 60, 30]),
            jitter,
            seed + 3,
        ),
        build(
            "classes-by-shape",
            Lattice {
                origin: o,
                a: Vec2::new(40.0, 0.0),
                b: Some(Vec2::new(0.0, 30.0)),
                motif: vec![(Vec2::ZERO, 0), (Vec2::new(20.0, 0.0), 1), (Vec2::new(10.0, 15.0), 2)],
            },
            4,
            5,
            |p, c| match c {
                0 => dash(p, Vec2::new(0.0, 12.0), 2.0, [20, 20, 20]),
                1 => ring(p, 5.0, None, Some([20, 20, 20])),
                _ => chevron(p, 10.0, [20, 20, 20]),
            },
            jitter,
            seed + 4,
        ),
        build(
            "classes-by-colour",
            Lattice {
                origin: o,
                a: Vec2::new(40.0, 0.0),
                b: Some(Vec2::new(0.0, 20.0)),
                motif: vec![(Vec2::ZERO, 0), (Vec2::new(20.0, 0.0), 1)],
            },
            4,
            7,
            |p, c| ring(p, 6.0, Some(if c == 0 { [210, 40, 40] } else { [40, 60, 210] }), None),
            jitter,
            seed + 5,
        ),
        build(
            "pairs-row",
            Lattice {
                origin: o,
                a: Vec2::new(34.0, 0.0),
                b: None,
                motif: vec![(Vec2::ZERO, 0), (Vec2::new(9.0, 0.0), 0)],
            },
            6,
            1,
            |p, _| dash(p, Vec2::new(0.0, 14.0), 2.0, [20, 20, 20]),
            jitter,
            seed + 6,
        ),
        build(
            "pairs-grid",
            Lattice {
                origin: o,
                a: Vec2::new(34.0, 0.0),
                b: Some(Vec2::new(0.0, 26.0)),
                motif: vec![(Vec2::ZERO, 0), (Vec2::new(9.0, 0.0), 0)],
            },
            5,
            5,
            |p, _| dash(p, Vec2::new(0.0, 14.0), 2.0, [20, 20, 20]),
            jitter,
            seed + 7,
        ),
    ]
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
