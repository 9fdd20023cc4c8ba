//! Motifs of several strokes drawn by hand a few times: the input the playground exists
//! for (a person draws a cross, an asterisk, a flower or a house three times a row, each
//! copy a little different). Test support: the families the motif model is measured on.
//!
//! A motif is a template of parts (polylines in motif coordinates). Each drawn copy moves
//! every point of the template by a *wobble* `w` (a fraction of the lattice spacing): the
//! whole copy is shifted, each part's two ends are displaced on their own (interpolated
//! along the part, which turns and stretches it), the part bends (a half sine across it),
//! the pointer adds a little noise per point, and the part is resampled to its own point
//! count. The terms are scaled so that `w` is the root-mean-square distance of a drawn
//! point from where the template puts it.

use super::color::Rgb;
use super::exemplar::{Exemplar, Lattice};
use super::stroke::Stroke;
use crate::rng::Rng;
use kurbo::{Point, Rect, Vec2};
use std::f64::consts::{PI, TAU};

/// One part of a motif: its path in motif coordinates (spacing 1), closed or not, its
/// width and colour.
#[derive(Clone, Debug)]
pub struct Part {
    pub path: Vec<Point>,
    pub closed: bool,
    pub width: f64,
    pub color: [u8; 3],
}

/// A motif template and its name.
#[derive(Clone, Debug)]
pub struct Motif {
    pub name: &'static str,
    pub parts: Vec<Part>,
}

fn line(points: &[(f64, f64)], color: [u8; 3]) -> Part {
    Part { path: points.iter().map(|&(x, y)| Point::new(x, y)).collect(), closed: false, width: 2.5, color }
}

fn bar(angle_deg: f64, half: f64) -> Part {
    let (s, c) = angle_deg.to_radians().sin_cos();
    line(&[(-half * c, -half * s), (half * c, half * s)], [30, 30, 30])
}

fn loop_at(centre: (f64, f64), rx: f64, ry: f64, turn: f64, color: [u8; 3], points: usize) -> Part {
    let (s, c) = turn.sin_cos();
    let path = (0..points)
        .map(|k| {
            let t = k as f64 * TAU / points as f64;
            let (x, y) = (rx * t.cos(), ry * t.sin());
            Point::new(centre.0 + x * c - y * s, centre.1 + x * s + y * c)
        })
        .collect();
    Part { path, closed: true, width: 2.0, color }
}

/// The motifs of the hand-drawn families: parts that share a centre (cross, asterisk),
/// and parts of different shapes around one another (flower, house, letter A).
pub fn motifs() -> Vec<Motif> {
    let ink = [30, 30, 30];
    let petal = |k: usize| {
        let a = k as f64 * TAU / 5.0 - PI / 2.0;
        let r = 0.14;
        loop_at((r * a.cos(), r * a.sin()), 0.1, 0.045, a, [200, 70, 110], 14)
    };
    vec![
        Motif { name: "cross", parts: vec![bar(0.0, 0.22), bar(90.0, 0.22)] },
        Motif { name: "asterisk", parts: vec![bar(90.0, 0.22), bar(30.0, 0.22), bar(150.0, 0.22)] },
        Motif {
            name: "flower",
            parts: (0..5)
                .map(petal)
                .chain(std::iter::once(loop_at((0.0, 0.0), 0.035, 0.035, 0.0, [230, 170, 40], 8)))
                .collect(),
        },
        Motif {
            name: "house",
            parts: vec![
                line(&[(-0.2, -0.02), (-0.2, 0.22), (0.2, 0.22), (0.2, -0.02)], ink),
                line(&[(-0.26, 0.0), (0.0, -0.2), (0.26, 0.0)], [170, 50, 40]),
                line(&[(-0.05, 0.22), (-0.05, 0.08), (0.05, 0.08), (0.05, 0.22)], [90, 60, 30]),
                line(&[(0.1, -0.08), (0.1, -0.2), (0.16, -0.2), (0.16, -0.03)], ink),
            ],
        },
        Motif {
            name: "letter-a",
            parts: vec![
                line(&[(-0.17, 0.22), (0.0, -0.22)], ink),
                line(&[(0.0, -0.22), (0.17, 0.22)], ink),
                line(&[(-0.09, 0.04), (0.09, 0.04)], ink),
            ],
        },
    ]
}

/// The lattices of the hand-drawn families, spacing 1 (scaled by `spacing` when drawn).
pub fn lattices() -> Vec<(&'static str, Vec2, Vec2)> {
    vec![
        ("square", Vec2::new(1.0, 0.0), Vec2::new(0.0, 1.0)),
        ("hexagonal", Vec2::new(1.0, 0.0), Vec2::new(0.5, 0.75f64.sqrt())),
        ("brick", Vec2::new(1.2, 0.0), Vec2::new(0.6, 0.8)),
        ("oblique", Vec2::new(1.0, 0.0), Vec2::new(0.3, 0.95)),
    ]
}

/// `motif` drawn `nx x ny` times (`copies`) on the lattice `a`, `b` (spacing 1, scaled by
/// `spacing`), copy by copy and part by part, with wobble `wobble` (see the module
/// comment). Each part is its own generator class.
pub fn draw(
    motif: &Motif,
    (a, b): (Vec2, Vec2),
    (nx, ny): (i32, i32),
    spacing: f64,
    wobble: f64,
    seed: u64,
) -> Exemplar {
    drawn(motif, (a, b), (nx, ny), None, spacing, wobble, seed)
}

/// `motif` drawn at every lattice site whose copy's centre lies on a canvas of about
/// `periods` spacings (the lattice's origin at `(spacing, spacing)`), row by row: a whole
/// canvas as a person fills it, for the autocomplete replay. Each edge of the canvas is
/// moved (by up to half a spacing) to where it is furthest from every site, so no copy
/// sits on an edge, half in and half out. Returns the drawing and the canvas.
pub fn draw_over(
    motif: &Motif,
    (a, b): (Vec2, Vec2),
    periods: (f64, f64),
    spacing: f64,
    wobble: f64,
    seed: u64,
) -> (Exemplar, Rect) {
    let nominal = Rect::new(0.5 * spacing, 0.5 * spacing, (periods.0 + 0.5) * spacing, (periods.1 + 0.5) * spacing);
    let origin = Point::new(spacing, spacing);
    let mut sites = Vec::new();
    for j in -40..=40 {
        for i in -40..=40 {
            let p = origin + a * (i as f64 * spacing) + b * (j as f64 * spacing);
            if nominal.inflate(spacing, spacing).contains(p) {
                sites.push(p);
            }
        }
    }
    // The edge position within half a spacing of `at` furthest from the sites' coordinates.
    let clear = |at: f64, coord: fn(&Point) -> f64| {
        (0..=40)
            .map(|k| at + spacing * (k as f64 / 40.0 - 0.5))
            .max_by(|x, y| {
                let gap = |e: f64| sites.iter().map(|p| (coord(p) - e).abs()).fold(f64::INFINITY, f64::min);
                gap(*x).total_cmp(&gap(*y))
            })
            .unwrap_or(at)
    };
    let canvas = Rect::new(
        clear(nominal.x0, |p| p.x),
        clear(nominal.y0, |p| p.y),
        clear(nominal.x1, |p| p.x),
        clear(nominal.y1, |p| p.y),
    );
    (drawn(motif, (a, b), (0, 0), Some(canvas), spacing, wobble, seed), canvas)
}

fn drawn(
    motif: &Motif,
    (a, b): (Vec2, Vec2),
    (nx, ny): (i32, i32),
    canvas: Option<Rect>,
    spacing: f64,
    wobble: f64,
    seed: u64,
) -> Exemplar {
    let mut rng = Rng::new(seed);
    let origin = Point::new(spacing, spacing);
    let (a, b) = (a * spacing, b * spacing);
    let site = |p: &Part| {
        let (lo, hi) =
            p.path.iter().fold((Point::new(f64::MAX, f64::MAX), Point::new(f64::MIN, f64::MIN)), |(lo, hi), q| {
                (Point::new(lo.x.min(q.x), lo.y.min(q.y)), Point::new(hi.x.max(q.x), hi.y.max(q.y)))
            });
        lo.midpoint(hi).to_vec2() * spacing
    };
    let lattice = Lattice {
        origin,
        a,
        b: Some(b),
        motif: motif.parts.iter().enumerate().map(|(k, p)| (site(p), k as u32)).collect(),
    };
    // Per-coordinate deviations of the terms; together about `wobble` RMS per point.
    let w = wobble * spacing;
    let (shift_sd, end_sd, bend_sd, noise_sd) = (0.5 * w, 0.45 * w, 0.55 * w, 0.1 * w);
    let gauss = |rng: &mut Rng, sd: f64| Vec2::new(rng.normal(), rng.normal()) * sd;
    let (mut strokes, mut classes) = (Vec::new(), Vec::new());
    let cells: Vec<(i32, i32)> = match canvas {
        // Every copy whose centre is on the canvas, row by row (rows along `a`).
        Some(c) => {
            let mut cells = Vec::new();
            let reach = ((c.width() + c.height()) / a.hypot().min(b.y.abs())).ceil() as i32 + 2;
            for j in -reach..=reach {
                for i in -reach..=reach {
                    if c.contains(origin + a * i as f64 + b * j as f64) {
                        cells.push((i, j));
                    }
                }
            }
            cells
        }
        None => (0..ny).flat_map(|j| (0..nx).map(move |i| (i, j))).collect(),
    };
    {
        for &(i, j) in &cells {
            let centre = origin + a * i as f64 + b * j as f64;
            let shift = gauss(&mut rng, shift_sd);
            for (k, part) in motif.parts.iter().enumerate() {
                let (e0, e1) = (gauss(&mut rng, end_sd), gauss(&mut rng, end_sd));
                let bend = rng.normal() * bend_sd;
                let template: Vec<Point> = part.path.iter().map(|p| centre + p.to_vec2() * spacing).collect();
                // Its own point count, as a pointer gives them: about one point per 1-2.5%
                // of the spacing along the part (so corners are kept to within that).
                let length: f64 = template.windows(2).map(|w| w[0].distance(w[1])).sum::<f64>()
                    + if part.closed { template[template.len() - 1].distance(template[0]) } else { 0.0 };
                let step = spacing * (0.01 + 0.015 * rng.next_f64());
                let count = ((length / step).round() as usize).max(template.len() + 2);
                let path = resample(&template, part.closed, count);
                let n = path.len();
                let points: Vec<[f64; 2]> = path
                    .iter()
                    .enumerate()
                    .map(|(m, &(p, normal))| {
                        let t = if n > 1 { m as f64 / (n - 1) as f64 } else { 0.0 };
                        let q = p
                            + shift
                            + e0 * (1.0 - t)
                            + e1 * t
                            + normal * (bend * (PI * t).sin())
                            + gauss(&mut rng, noise_sd);
                        [q.x, q.y]
                    })
                    .collect();
                let mut s = Stroke::new(points, part.width * spacing / 70.0, Some(Rgb(part.color)));
                s.closed = part.closed;
                strokes.push(s);
                classes.push(k as u32);
            }
        }
    }
    Exemplar { name: motif.name, strokes, classes, lattice }
}

/// `count` points at equal arc length along `path` (round the loop when `closed`), each
/// with the unit normal of its segment.
fn resample(path: &[Point], closed: bool, count: usize) -> Vec<(Point, Vec2)> {
    let mut pts = path.to_vec();
    if closed {
        pts.push(path[0]);
    }
    let lengths: Vec<f64> = pts.windows(2).map(|w| w[0].distance(w[1])).collect();
    let total: f64 = lengths.iter().sum::<f64>().max(1e-12);
    // A closed loop does not repeat its first point at the end.
    let steps = if closed { count } else { count - 1 };
    (0..count)
        .map(|m| {
            let mut s = total * m as f64 / steps.max(1) as f64;
            let mut k = 0;
            while k + 1 < lengths.len() && s > lengths[k] {
                s -= lengths[k];
                k += 1;
            }
            let (p, q) = (pts[k], pts[(k + 1).min(pts.len() - 1)]);
            let d = q - p;
            let len = d.hypot().max(1e-12);
            let at = p + d * (s / len).clamp(0.0, 1.0);
            (at, Vec2::new(-d.y / len, d.x / len))
        })
        .collect()
}

/// Grows `ex` (drawn on the lattice `a`, `b` at `spacing`) to 10 x 8 periods with
/// `opts` (its size set here) and measures the output against the drawing's lattice on
/// the scale of its shorter period, as the table reads it.
pub fn grow_and_measure(
    ex: &Exemplar,
    (a, b): (Vec2, Vec2),
    spacing: f64,
    opts: super::StrokeOptions,
) -> (super::regularity::Regularity, super::StrokeResult) {
    let (w, h) = (10.0 * a.hypot() * spacing, 8.0 * b.y.abs() * spacing);
    let opts = super::StrokeOptions { width: w, height: h, ..opts };
    let res = super::synthesize_strokes(&ex.strokes, &opts, &mut crate::Silent).expect(ex.name);
    // Where the engine centres the example: the box of its motifs' centres.
    let c = &res.classification.motifs.centre;
    let bounds = c.iter().fold(Rect::from_points(c[0], c[0]), |r, &p| r.union_pt(p));
    let area = Rect::new(0.0, 0.0, w, h);
    let out: Vec<(Point, u32)> =
        res.strokes.iter().zip(&res.sources).map(|(s, &src)| (s.reference_point(), ex.classes[src as usize])).collect();
    let scale = spacing * a.hypot().min(b.hypot());
    (super::regularity::measure_at(&ex.lattice, scale, area.center() - bounds.center(), &out, area), res)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn wobble_is_the_rms_displacement_of_a_point() {
        let motif = &motifs()[0];
        let (a, b) = (Vec2::new(1.0, 0.0), Vec2::new(0.0, 1.0));
        let exact = draw(motif, (a, b), (3, 3), 70.0, 0.0, 1);
        let shaky = draw(motif, (a, b), (3, 3), 70.0, 0.05, 1);
        assert_eq!(exact.strokes.len(), 18);
        // Points are resampled per copy; compare each drawn point with the template line.
        let mut sum = 0.0;
        let mut n = 0;
        for (e, s) in exact.strokes.iter().zip(&shaky.strokes) {
            let (p, q) = (Point::new(e.points[0][0], e.points[0][1]), Point::new(e.points[1][0], e.points[1][1]));
            for &[x, y] in &s.points {
                let d = q - p;
                let off = (Point::new(x, y) - p).cross(d) / d.hypot();
                sum += off * off * 2.0; // across only: double for the along-line component
                n += 1;
            }
        }
        let rms = (sum / n as f64).sqrt() / 70.0;
        assert!((0.03..0.07).contains(&rms), "rms wobble {rms}");
    }
}
