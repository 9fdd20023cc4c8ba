//! Seamless SVG tiles (SPEC 1.4): for every family the tile is a whole number of the
//! generator's periods, holds each lattice site once (on the torus), repeats every
//! stroke that crosses an edge one period over, and is a valid SVG; irregular input
//! gets a clear error.

use kurbo::{Point, Vec2};
use patternsynth::vector::exemplar::{families, irregular_dashes};
use patternsynth::vector::{parse_svg, stroke_tile, ImportOptions, Stroke, TileOptions};

/// Whether the lattice `a, b` of the generator has `v` as a period (within `tol`).
fn is_period(a: Vec2, b: Option<Vec2>, v: Vec2, tol: f64) -> bool {
    match b {
        Some(b) => {
            let det = a.cross(b);
            let (u, w) = (v.cross(b) / det, a.cross(v) / det);
            (u - u.round()).abs() * a.hypot() < tol && (w - w.round()).abs() * b.hypot() < tol
        }
        None => (v.x / a.x - (v.x / a.x).round()).abs() * a.hypot() < tol,
    }
}

#[test]
fn every_family_makes_a_seamless_tile() {
    for ex in families(0.02, 11) {
        let spacing = ex.lattice.spacing();
        for repeats in [1, 2] {
            let t = stroke_tile(&ex.strokes, &TileOptions { repeats, seed: 3, ..Default::default() }).expect(ex.name);
            let (w, h) = (t.width, t.height);
            println!("{:<18} x{repeats}: {w:.1} x {h:.1}, {} sites, {} strokes", ex.name, t.sites, t.strokes.len());
            // Its sides are periods of the pattern the example was drawn on.
            let tol = 0.05 * spacing * repeats as f64;
            assert!(is_period(ex.lattice.a, ex.lattice.b, Vec2::new(w, 0.0), tol), "{}: width {w}", ex.name);
            if let Some(b) = ex.lattice.b {
                assert!(is_period(ex.lattice.a, ex.lattice.b, Vec2::new(0.0, h), tol), "{}: height {h}", ex.name);
                // One site per motif position per cell of the lattice.
                let cells = w * h / ex.lattice.a.cross(b).abs();
                assert_eq!(t.sites as f64, (cells * ex.lattice.motif.len() as f64).round(), "{}", ex.name);
            } else {
                // A row repeats down by its own extent: `repeats` rows.
                let per_row = (w / ex.lattice.a.x).round() * ex.lattice.motif.len() as f64;
                assert_eq!(t.sites as f64, per_row * repeats as f64, "{}", ex.name);
            }
            // Sites on the torus: distinct and none stacked.
            let mut pts: Vec<Point> = Vec::new();
            for s in &t.strokes {
                let p = s.reference_point();
                let p = Point::new(p.x.rem_euclid(w), p.y.rem_euclid(h));
                let gap = |q: &Point| {
                    let (dx, dy) = ((q.x - p.x).abs(), (q.y - p.y).abs());
                    dx.min(w - dx).hypot(dy.min(h - dy))
                };
                match pts.iter().map(gap).fold(f64::INFINITY, f64::min) {
                    g if g < 1e-6 => {}
                    g => {
                        assert!(g > 0.4 * spacing, "{}: two sites {g} apart (spacing {spacing})", ex.name);
                        pts.push(p);
                    }
                }
            }
            assert_eq!(pts.len(), t.sites, "{}", ex.name);
            // Every stroke cut by an edge comes in again at the opposite edge.
            let has = |s: &Stroke, dx: f64, dy: f64| {
                let m = s.translated(dx, dy);
                t.strokes.iter().any(|o| {
                    o.points.len() == m.points.len()
                        && o.points.iter().zip(&m.points).all(|(p, q)| (p[0] - q[0]).abs() + (p[1] - q[1]).abs() < 1e-6)
                })
            };
            for s in &t.strokes {
                let b = s.bounds();
                if b.x1 > w {
                    assert!(has(s, -w, 0.0), "{}: no copy of a stroke cut by the right edge", ex.name);
                }
                if b.y1 > h {
                    assert!(has(s, 0.0, -h), "{}: no copy of a stroke cut by the bottom edge", ex.name);
                }
            }
            // A valid SVG of the tile's size that imports back.
            assert!(t.svg.contains(&format!("viewBox=\"0 0 {} {}", fmt(w), fmt(h))), "{}", &t.svg[..120]);
            let back = parse_svg(&t.svg, &ImportOptions::default()).expect("the tile's SVG parses");
            assert_eq!(back.strokes.len(), t.strokes.len());
        }
    }
}

fn fmt(v: f64) -> String {
    let s = format!("{v:.3}");
    s.trim_end_matches('0').trim_end_matches('.').to_string()
}

#[test]
fn hexagonal_tile_is_one_period_across_and_two_rows_down() {
    let hex = families(0.0, 1).into_iter().find(|e| e.name == "hexagonal").unwrap();
    let (a, b) = (hex.lattice.a, hex.lattice.b.unwrap());
    let t = stroke_tile(&hex.strokes, &TileOptions::default()).unwrap();
    assert!((t.width - a.x).abs() < 0.01 * a.x, "width {} vs {}", t.width, a.x);
    assert!((t.height - 2.0 * b.y).abs() < 0.01 * b.y, "height {} vs {}", t.height, 2.0 * b.y);
    assert_eq!(t.sites, 2);
}

#[test]
fn no_repeat_no_tile() {
    let strokes = irregular_dashes(40, 150.0, 5);
    let err = stroke_tile(&strokes, &TileOptions::default()).unwrap_err().to_string();
    assert!(err.contains("No regular repeat"), "{err}");
    let err = stroke_tile(&strokes[..1], &TileOptions::default()).unwrap_err().to_string();
    assert!(err.contains("at least two strokes"), "{err}");
    let err = stroke_tile(&strokes, &TileOptions { repeats: 0, ..Default::default() }).unwrap_err().to_string();
    assert!(err.contains("repeats"), "{err}");
}
