//! A seamless SVG tile (SPEC 1.4, beyond the paper): a rectangle that repeats as a CSS
//! background without seams.
//!
//! The example's lattice is fitted (two period vectors `a`, `b`; a row gets a second
//! period across it, one gap past the strokes' extent). A rectangular repeat needs two
//! lattice vectors `i a + j b = (W, 0)` and `k a + l b = (0, H)`: the shortest integer
//! combinations within `MAX_COMBINATION` periods that are horizontal and vertical to
//! within `SKEW` are taken, and the periods are then adjusted so that they are exact
//! (`[a'; b'] = M^-1 diag(W, H)`, M the integer matrix), a change of at most `SKEW`
//! that cannot show, while any mismatch left in a tile would repeat at every edge.
//!
//! The tile holds one element per lattice site of the torus `W x H`: every motif
//! position (the example's elements reduced modulo the lattice) at each of the `|det M|`
//! cells. As in growth, each element takes a random stroke of its class (or its own)
//! and the hand-drawn deviation of a random example element at that motif position.
//! Strokes that cross the tile's edge are drawn again one period over, so the parts cut
//! off at one edge come in at the opposite one.

use super::grow::fit_lattice;
use super::stroke::Stroke;
use super::svg::to_svg;
use super::synthesize::{classify_strokes, Classification};
use crate::error::{invalid, Error, Result};
use crate::rng::Rng;
use kurbo::{Point, Rect, Vec2};
use serde::{Deserialize, Serialize};

/// Options of `stroke_tile`.
#[derive(Clone, Debug, Deserialize)]
#[serde(rename_all = "camelCase", default, deny_unknown_fields)]
pub struct TileOptions {
    pub path_tolerance: Option<f64>,
    pub width_tolerance: Option<f64>,
    pub color_tolerance: Option<f64>,
    /// Each element takes a random member of its class (else its own stroke).
    pub variation: bool,
    pub seed: u64,
    /// The tile spans this many smallest repeats across and down (1 to 8): more
    /// variety between repeats with `variation`.
    pub repeats: u32,
    /// The periods to tile on, `[[ax, ay], [bx, by]]`, when the drawing's own are wrong
    /// or missing (see `StrokeOptions::periods`).
    pub periods: Option<[[f64; 2]; 2]>,
}

impl Default for TileOptions {
    fn default() -> Self {
        TileOptions {
            path_tolerance: None,
            width_tolerance: None,
            color_tolerance: None,
            variation: true,
            seed: 1,
            repeats: 1,
            periods: None,
        }
    }
}

#[derive(Clone, Debug, Serialize)]
#[serde(rename_all = "camelCase")]
pub struct TileResult {
    /// The tile's strokes in tile coordinates, edge-crossing ones repeated.
    pub strokes: Vec<Stroke>,
    pub classes: Vec<u32>,
    pub width: f64,
    pub height: f64,
    /// The exact periods of the tile's lattice.
    pub periods: [[f64; 2]; 2],
    /// Stroke sites in the tile (strokes before edge copies; a motif of several strokes
    /// has one site per stroke).
    pub sites: usize,
    pub classification: Classification,
    pub svg: String,
}

/// Integer combinations searched: `|i|, |j| <= MAX_COMBINATION`.
const MAX_COMBINATION: i64 = 8;
/// A combination counts as horizontal (vertical) when its other component is at most
/// this fraction of its length.
const SKEW: f64 = 0.03;
/// Largest tile side in spacings: beyond it the SVG would hold too many strokes.
const MAX_SIDE_SPACINGS: f64 = 400.0;

/// The shortest combination `i a + j b` along `axis` (0: x, 1: y), positive along it.
fn axis_combination(a: Vec2, b: Vec2, axis: usize) -> Option<(i64, i64, f64)> {
    let mut best: Option<(i64, i64, f64)> = None;
    for i in -MAX_COMBINATION..=MAX_COMBINATION {
        for j in -MAX_COMBINATION..=MAX_COMBINATION {
            let v = a * i as f64 + b * j as f64;
            let (along, across) = if axis == 0 { (v.x, v.y) } else { (v.y, v.x) };
            if along > 1e-9 && across.abs() <= SKEW * along && best.is_none_or(|(_, _, l)| along < l - 1e-9) {
                best = Some((i, j, along));
            }
        }
    }
    best
}

/// A seamless tile from the example `strokes`.
/// Most strokes a tile may hold, edge copies included.
pub const MAX_TILE_STROKES: usize = 100_000;

pub fn stroke_tile(strokes: &[Stroke], opts: &TileOptions) -> Result<TileResult> {
    if !(1..=8).contains(&opts.repeats) {
        return invalid("repeats must be from 1 to 8.");
    }
    let classification = classify_strokes(strokes, opts.path_tolerance, opts.width_tolerance, opts.color_tolerance)?;
    let elems = classification.elements();
    let motifs = &classification.motifs;
    let given = super::lattice::given_periods(opts.periods)?.map(|(a, b)| super::lattice::on_periods(&elems, a, b));
    let Some(fit) = given.map_or_else(|| fit_lattice(&elems), |f| Ok(Some(f)))? else {
        return invalid(
            "No regular repeat found in these strokes: a seamless tile needs a drawing that repeats \
             (a row, or a grid of at least 2 x 2 copies).",
        );
    };
    let a = fit.a;
    let b = fit.b.unwrap_or_else(|| row_period(strokes, a));

    let (Some((i, j, w1)), Some((k, l, h1))) = (axis_combination(a, b, 0), axis_combination(a, b, 1)) else {
        return invalid(format!(
            "The pattern's periods ({:.1}, {:.1}) and ({:.1}, {:.1}) do not line up with a rectangle within \
             {MAX_COMBINATION} periods, so no rectangular tile repeats it.",
            a.x, a.y, b.x, b.y
        ));
    };
    let r = opts.repeats as i64;
    let (i, j, k, l) = (i * r, j * r, k * r, l * r);
    let (width, height) = (w1 * r as f64, h1 * r as f64);
    let spacing = a.hypot().min(b.hypot());
    if width.max(height) > MAX_SIDE_SPACINGS * spacing {
        return invalid("The tile would be too large for the spacing of these strokes; use fewer repeats.");
    }
    let det = i * l - j * k;
    if det == 0 {
        return invalid("The pattern's periods are parallel: no rectangular tile repeats it.");
    }
    // Exact periods: M [a'; b'] = diag(W, H) with M = [i j; k l].
    let d = det as f64;
    let a2 = Vec2::new(l as f64 * width, -(j as f64) * height) / d;
    let b2 = Vec2::new(-(k as f64) * width, i as f64 * height) / d;

    // Motif positions: the snapped elements in lattice coordinates, modulo 1.
    let origin = fit.snapped[0];
    let inv = 1.0 / a.cross(b);
    let coords = |p: Point| {
        let v = p - origin;
        (v.cross(b) * inv, a.cross(v) * inv)
    };
    let wrap = |t: f64| {
        let f = t - t.floor();
        if f > 1.0 - 1e-6 {
            0.0
        } else {
            f
        }
    };
    // (fractional coordinates, class, members)
    let mut motif: Vec<((f64, f64), u32, Vec<usize>)> = Vec::new();
    for (e, (&s, el)) in fit.snapped.iter().zip(&elems).enumerate() {
        let (u, v) = coords(s);
        let f = (wrap(u), wrap(v));
        let near = |g: (f64, f64)| {
            let du = (f.0 - g.0).abs();
            let dv = (f.1 - g.1).abs();
            du.min(1.0 - du) < 1e-3 && dv.min(1.0 - dv) < 1e-3
        };
        match motif.iter_mut().find(|(g, c, _)| *c == el.class && near(*g)) {
            Some(m) => m.2.push(e),
            None => motif.push((f, el.class, vec![e])),
        }
    }

    let mut rng = Rng::new(opts.seed);
    let tile = Rect::new(0.0, 0.0, width, height);
    let reach = (i.abs() + j.abs() + k.abs() + l.abs()) + 1;
    // (source instance's first stroke, part order, stroke, class)
    let mut placed: Vec<(u32, usize, Stroke, u32)> = Vec::new();
    let mut sites = 0usize;
    for ((fu, fv), _, example) in &motif {
        let mut seen: Vec<Point> = Vec::new();
        for u in -reach..=reach {
            for v in -reach..=reach {
                let p = origin + a2 * (fu + u as f64) + b2 * (fv + v as f64);
                let p = Point::new(p.x.rem_euclid(width), p.y.rem_euclid(height));
                let torus_gap = |q: &Point| {
                    let dx = (q.x - p.x).abs();
                    let dy = (q.y - p.y).abs();
                    dx.min(width - dx).hypot(dy.min(height - dy))
                };
                if seen.iter().any(|q| torus_gap(q) < 1e-6 * spacing) {
                    continue;
                }
                seen.push(p);
                // Variation among the copies of this motif position only: another
                // place's motif of the same kind never stands in.
                let source = example[rng.below(example.len())];
                let pick = if opts.variation { example[rng.below(example.len())] } else { source };
                let target = p + (elems[source].pos - fit.snapped[source]);
                let first = motifs.instances[source][0];
                sites += motifs.instances[pick].len();
                for (part, &si) in motifs.instances[pick].iter().enumerate() {
                    let s = &strokes[si as usize];
                    let at = target + (s.reference_point() - motifs.centre[pick]);
                    let moved = s.translated(at.x - s.reference_point().x, at.y - s.reference_point().y);
                    // The copies of it that show in the tile: itself and one period over
                    // wherever it crosses an edge.
                    let half = 0.5 * moved.width.max(0.0);
                    let bb = moved.bounds().inflate(half, half);
                    let (nx0, nx1) = ((-bb.x1 / width).ceil(), ((width - bb.x0) / width).floor());
                    let (ny0, ny1) = ((-bb.y1 / height).ceil(), ((height - bb.y0) / height).floor());
                    // Counted before any is made: a stroke much wider than the repeat is
                    // copied at every period it covers, (width / period)^2 times.
                    let copies = (nx1 - nx0 + 1.0).max(1.0) * (ny1 - ny0 + 1.0).max(1.0);
                    if copies.is_nan() || placed.len() as f64 + copies > MAX_TILE_STROKES as f64 {
                        return Err(Error::TooLarge(format!(
                            "The tile would hold more than {MAX_TILE_STROKES} strokes: strokes much wider than the \
                             repeat ({:.0} x {:.0}) are repeated at every period they cover. Draw thinner strokes.",
                            width, height
                        )));
                    }
                    let (nx0, nx1, ny0, ny1) = (nx0 as i64, nx1 as i64, ny0 as i64, ny1 as i64);
                    for nx in nx0..=nx1 {
                        for ny in ny0..=ny1 {
                            let (dx, dy) = (nx as f64 * width, ny as f64 * height);
                            if bb.with_origin(bb.origin() + Vec2::new(dx, dy)).intersect(tile).area() > 0.0
                                || (nx, ny) == (0, 0)
                            {
                                placed.push((
                                    first,
                                    part,
                                    moved.translated(dx, dy),
                                    classification.classes[si as usize],
                                ));
                            }
                        }
                    }
                }
            }
        }
    }
    // Layering follows the example's drawing order.
    placed.sort_by_key(|(first, part, _, _)| (*first, *part));
    let (strokes, classes): (Vec<Stroke>, Vec<u32>) = placed.into_iter().map(|(_, _, s, c)| (s, c)).unzip();
    let svg = to_svg(&strokes, &classes, width, height);
    Ok(TileResult {
        strokes,
        classes,
        width,
        height,
        // (+ 0.0 turns -0 into 0.)
        periods: [[a2.x + 0.0, a2.y + 0.0], [b2.x + 0.0, b2.y + 0.0]],
        sites,
        classification,
        svg,
    })
}

/// The second period of a row: across it, the strokes' extent across plus the gap
/// between neighbours along it (a quarter period at least).
fn row_period(strokes: &[Stroke], a: Vec2) -> Vec2 {
    let along = a.normalize();
    let across = Vec2::new(-along.y, along.x);
    let extent = |dir: Vec2| {
        strokes
            .iter()
            .map(|s| {
                let (lo, hi) = s.points.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), p| {
                    let t = dir.dot(Vec2::new(p[0], p[1]));
                    (lo.min(t), hi.max(t))
                });
                hi - lo + s.width.max(0.0)
            })
            .fold(0.0, f64::max)
    };
    let gap = (a.hypot() - extent(along)).max(0.25 * a.hypot());
    let b = across * (extent(across) + gap);
    // Keep (a, b) right-handed like a fitted lattice.
    if a.cross(b) < 0.0 {
        -b
    } else {
        b
    }
}
