//! The vector engine's contract beyond regularity: bad input, caps, determinism,
//! variation, draw order, irregular input, progress and cancellation.

use patternsynth::vector::exemplar::{families, irregular_dashes};
use patternsynth::vector::{parse_svg, synthesize_strokes, ImportOptions, Rgb, Stroke, StrokeOptions};
use patternsynth::{Error, Silent};

fn grid() -> Vec<Stroke> {
    families(0.02, 3).into_iter().find(|e| e.name == "grid").unwrap().strokes
}

fn opts(w: f64, h: f64) -> StrokeOptions {
    StrokeOptions { width: w, height: h, ..Default::default() }
}

#[test]
fn bad_input_is_a_clear_error() {
    let g = grid();
    let cases: Vec<(Vec<Stroke>, StrokeOptions, &str)> = vec![
        (vec![], opts(100.0, 100.0), "no strokes"),
        (vec![Stroke::new(vec![[f64::NAN, 1.0]], 1.0, None)], opts(100.0, 100.0), "finite"),
        (vec![Stroke::new(vec![], 1.0, None)], opts(100.0, 100.0), "no points"),
        (g[..1].to_vec(), opts(100.0, 100.0), "at least two"),
        (vec![g[0].clone(), g[0].clone()], opts(100.0, 100.0), "same point"),
        (g.clone(), opts(f64::NAN, 100.0), "positive"),
        (g.clone(), opts(-5.0, 100.0), "positive"),
        (g.clone(), opts(1e7, 1e7), "limit"),
        (g.clone(), StrokeOptions { path_tolerance: Some(-1.0), ..opts(100.0, 100.0) }, "tolerance"),
        (g.clone(), StrokeOptions { support: 0.0, ..opts(100.0, 100.0) }, "support"),
    ];
    for (strokes, o, want) in cases {
        let e = synthesize_strokes(&strokes, &o, &mut Silent).expect_err(want).to_string();
        assert!(e.contains(want), "expected '{want}' in '{e}'");
    }
}

/// Two classes by colour; members of a class differ slightly in length.
/// Strokes of many points lower the element cap below `maxElements`: the refusal says
/// why instead of contradicting the option.
#[test]
fn a_cap_set_by_points_says_so() {
    // A 4 x 4 grid of zigzags of 2,000 points each, 20 apart: 20,000,000 points allow
    // 10,000 such elements; 2000 x 2000 holds 10,000 sites, 5000 x 5000 about 62,500.
    let zigzag = |x0: f64, y0: f64| -> Stroke {
        let pts = (0..2000).map(|k| [x0 + k as f64 * 0.004, y0 + (k % 2) as f64]).collect();
        Stroke::new(pts, 1.0, None)
    };
    let strokes: Vec<Stroke> = (0..16).map(|i| zigzag((i % 4) as f64 * 20.0, (i / 4) as f64 * 20.0)).collect();
    let o = StrokeOptions { max_elements: 1_000_000, ..opts(5000.0, 5000.0) };
    let err = synthesize_strokes(&strokes, &o, &mut Silent).unwrap_err().to_string();
    assert!(
        err.contains("the limit is 10000 (not maxElements' 1000000: each element here holds about 2000 points, and an output may hold 20000000 points in all)"),
        "{err}"
    );
}

fn varied_row() -> Vec<Stroke> {
    let mut strokes = Vec::new();
    for i in 0..8 {
        let len = 10.0 + (i % 4) as f64 * 0.3;
        let color = if i % 2 == 0 { [200, 0, 0] } else { [0, 0, 200] };
        strokes.push(Stroke::new(
            vec![[20.0 + i as f64 * 20.0, 20.0], [20.0 + i as f64 * 20.0, 20.0 + len]],
            2.0,
            Some(Rgb(color)),
        ));
    }
    strokes
}

#[test]
fn same_seed_same_output_and_seed_changes_variation() {
    let row = varied_row();
    let a = synthesize_strokes(&row, &opts(400.0, 60.0), &mut Silent).unwrap();
    let b = synthesize_strokes(&row, &opts(400.0, 60.0), &mut Silent).unwrap();
    assert!(a.svg == b.svg, "same seed, same SVG");
    let c = synthesize_strokes(&row, &StrokeOptions { seed: 99, ..opts(400.0, 60.0) }, &mut Silent).unwrap();
    assert_eq!(a.sources, c.sources, "the seed changes attributes, not positions");
    assert!(a.svg != c.svg, "variation draws other class members under another seed");
}

#[test]
fn variation_off_keeps_the_copied_stroke_and_on_uses_class_members() {
    let strokes = varied_row();
    let off =
        synthesize_strokes(&strokes, &StrokeOptions { variation: false, ..opts(400.0, 60.0) }, &mut Silent).unwrap();
    for (s, &src) in off.strokes.iter().zip(&off.sources) {
        let src = &strokes[src as usize];
        assert_eq!(s.stroke, src.stroke);
        assert!((s.bounds().height() - src.bounds().height()).abs() < 1e-9);
    }
    let on = synthesize_strokes(&strokes, &opts(400.0, 60.0), &mut Silent).unwrap();
    let mut lengths: Vec<u64> = on.strokes.iter().map(|s| (s.bounds().height() * 10.0).round() as u64).collect();
    lengths.sort();
    lengths.dedup();
    assert!(lengths.len() >= 3, "members of each class are drawn: {lengths:?}");
    for (s, &src) in on.strokes.iter().zip(&on.sources) {
        assert_eq!(s.stroke, strokes[src as usize].stroke, "variation stays within the class");
    }
}

#[test]
fn draw_order_follows_the_example() {
    // A filled disc drawn first, a dash drawn over it, repeated on a grid.
    let mut strokes = Vec::new();
    for i in 0..4 {
        for j in 0..4 {
            let (x, y) = (20.0 + i as f64 * 30.0, 20.0 + j as f64 * 30.0);
            let mut disc = Stroke::new(
                (0..12)
                    .map(|k| {
                        let a = k as f64 * std::f64::consts::TAU / 12.0;
                        [x + 8.0 * a.cos(), y + 8.0 * a.sin()]
                    })
                    .collect(),
                0.0,
                None,
            );
            disc.fill = Some(Rgb([250, 220, 0]));
            disc.closed = true;
            strokes.push(disc);
            strokes.push(Stroke::new(vec![[x - 5.0, y], [x + 5.0, y]], 2.0, Some(Rgb([0, 0, 0]))));
        }
    }
    let r = synthesize_strokes(&strokes, &opts(300.0, 300.0), &mut Silent).unwrap();
    // Each dash is drawn after the disc it sits on, as in the example.
    let mut dashes = 0;
    for (i, s) in r.strokes.iter().enumerate().filter(|(_, s)| s.stroke.is_some()) {
        let p = s.reference_point();
        let disc = r.strokes.iter().position(|d| d.fill.is_some() && d.reference_point().distance(p) < 1.0);
        if let Some(d) = disc {
            assert!(d < i, "disc {d} drawn after its dash {i}");
            dashes += 1;
        }
    }
    assert!(dashes > 70, "{dashes} dashes on discs");
    assert!(r.svg.contains("fill=\"#fadc00\"") && r.svg.contains("stroke=\"none\""), "fill-only shapes survive");
}

#[test]
fn irregular_input_degrades_gracefully() {
    // Random positions: no lattice to find. No crash, no pile-ups closer than the example's
    // own, the example's density, the area covered.
    let strokes = irregular_dashes(40, 150.0, 5);
    let r = synthesize_strokes(&strokes, &opts(450.0, 450.0), &mut Silent).unwrap();
    let pts: Vec<_> = r.strokes.iter().map(|s| s.reference_point()).collect();
    let example: Vec<_> = strokes.iter().map(|s| s.reference_point()).collect();
    let nearest = |pts: &[kurbo::Point], i: usize| {
        (0..pts.len()).filter(|&j| j != i).map(|j| pts[i].distance(pts[j])).fold(f64::MAX, f64::min)
    };
    let mut nn: Vec<f64> = (0..example.len()).map(|i| nearest(&example, i)).collect();
    nn.sort_by(|a, b| a.total_cmp(b));
    let spacing = nn[nn.len() / 2];
    let closest = (0..pts.len()).map(|i| nearest(&pts, i)).fold(f64::MAX, f64::min);
    assert!(closest >= 0.85 * nn[0], "pile-up: {closest} vs the example's closest pair {}", nn[0]);
    // Close pairs (under a quarter spacing) no more common than in the example.
    let close = |pts: &[kurbo::Point]| {
        (0..pts.len()).filter(|&i| nearest(pts, i) < 0.25 * spacing).count() as f64 / pts.len() as f64
    };
    assert!(close(&pts) <= close(&example) + 0.02, "close pairs {} vs {}", close(&pts), close(&example));
    // Cells of 4 spacings: even a uniform random layout leaves only ~3% of them empty.
    let cell = 4.0 * spacing;
    let n = (450.0 / cell).floor() as usize;
    let mut hit = vec![false; n * n];
    for p in &pts {
        let (cx, cy) = ((p.x / cell) as usize, (p.y / cell) as usize);
        if cx < n && cy < n {
            hit[cy * n + cx] = true;
        }
    }
    let covered = hit.iter().filter(|&&h| h).count() as f64 / hit.len() as f64;
    assert!(covered > 0.85, "area covered {covered}");
    let density_in = 40.0 / (150.0 * 150.0);
    let density_out = pts.len() as f64 / (450.0 * 450.0);
    assert!(
        (0.75 * density_in..=1.2 * density_in).contains(&density_out),
        "density {density_out} vs example {density_in}"
    );
}

#[test]
fn progress_is_monotone_and_cancel_stops() {
    let g = grid();
    let mut seen = Vec::new();
    let mut record = |f: f64| {
        seen.push(f);
        true
    };
    synthesize_strokes(&g, &opts(600.0, 600.0), &mut record).unwrap();
    assert!(seen.len() > 10);
    assert!(seen.windows(2).all(|w| w[1] >= w[0]), "monotone");
    assert_eq!(*seen.last().unwrap(), 1.0);
    let mut calls = 0;
    let mut cancel = |_: f64| {
        calls += 1;
        calls < 5
    };
    assert_eq!(synthesize_strokes(&g, &opts(600.0, 600.0), &mut cancel).unwrap_err(), Error::Cancelled);
}

#[test]
fn svg_output_is_valid_xml_with_finite_numbers() {
    let r = synthesize_strokes(&grid(), &opts(200.0, 150.0), &mut Silent).unwrap();
    let doc = roxmltree::Document::parse(&r.svg).expect("well-formed XML");
    let root = doc.root_element();
    assert_eq!(root.attribute("viewBox"), Some("0 0 200 150"));
    // A path or a use of a defined path per stroke; every path's numbers finite.
    let drawn = root.children().filter(|n| n.has_tag_name("path") || n.has_tag_name("use")).count();
    assert_eq!(drawn, r.strokes.len());
    for p in root.descendants().filter(|n| n.has_tag_name("path")) {
        let d = p.attribute("d").unwrap();
        assert!(!d.contains("NaN") && !d.contains("inf"), "{d}");
    }
}

/// A pattern is copies: each drawn stroke is defined once and placed with `<use>`, and
/// the document reads back to the same strokes (117 hand-drawn flowers: 367 KB as a
/// path per stroke, 59 KB).
#[test]
fn svg_defines_each_drawn_stroke_once_and_uses_it() {
    use patternsynth::vector::{handdrawn, svg::export::path_element};
    let flower = handdrawn::motifs().into_iter().find(|m| m.name == "flower").unwrap();
    let (_, a, b) = handdrawn::lattices()[0];
    let ex = handdrawn::draw(&flower, (a, b), (3, 3), 70.0, 0.03, 1);
    let r = synthesize_strokes(&ex.strokes, &opts(13.0 * 70.0, 9.0 * 70.0), &mut Silent).unwrap();
    let flat: usize = r.strokes.iter().map(|s| path_element(s).len() + 1).sum();
    assert!(r.strokes.len() >= 600, "{} strokes", r.strokes.len());
    assert_eq!(r.svg.matches("<use ").count(), r.strokes.len(), "every output stroke is a copy of a drawn one");
    assert!(r.svg.len() * 4 < flat, "{} bytes against {flat} as a path per stroke", r.svg.len());
    let back = parse_svg(&r.svg, &ImportOptions::default()).unwrap().strokes;
    assert_eq!(back.len(), r.strokes.len());
    for (p, q) in back.iter().flat_map(|s| &s.points).zip(r.strokes.iter().flat_map(|s| &s.points)) {
        assert!((p[0] - q[0]).abs() <= 2e-3 && (p[1] - q[1]).abs() <= 2e-3, "{p:?} against {q:?}");
    }
}

/// Periods set by hand (issue 29): one flower drawn once repeats on them as it is, and
/// a drawn grid is repeated on the periods given, not the ones it shows.
#[test]
fn periods_set_by_hand() {
    use kurbo::Vec2;
    use patternsynth::vector::handdrawn::{draw, motifs};
    use patternsynth::vector::{stroke_tile, TileOptions};
    let flower = motifs().into_iter().find(|m| m.name == "flower").unwrap();
    let once = draw(&flower, (Vec2::new(1.0, 0.0), Vec2::new(0.0, 1.0)), (1, 1), 60.0, 0.01, 3);
    let parts = once.strokes.len();
    assert!(parts >= 5, "{parts} parts");
    let (a, b) = ([50.0, 0.0], [25.0, 43.3]);
    let o = StrokeOptions { periods: Some([a, b]), seed: 2, ..opts(600.0, 400.0) };
    let r = synthesize_strokes(&once.strokes, &o, &mut Silent).unwrap();
    assert_eq!(r.periods, Some([a, b]));
    // Every output stroke is a drawn part moved by one shift (the drawing is centred in
    // the output) and a whole combination of the periods.
    let (av, bv) = (Vec2::new(a[0], a[1]), Vec2::new(b[0], b[1]));
    let mut sites: std::collections::HashMap<(i64, i64), Vec<kurbo::Point>> = Default::default();
    let moved = |k: usize| r.strokes[k].reference_point() - once.strokes[r.sources[k] as usize].reference_point();
    let shift = moved(0);
    for k in 0..r.strokes.len() {
        let d = moved(k) - shift;
        let (u, w) = (d.cross(bv) / av.cross(bv), av.cross(d) / av.cross(bv));
        assert!((u - u.round()).abs() < 1e-6 && (w - w.round()).abs() < 1e-6, "off the lattice: {u}, {w}");
        sites.entry((u.round() as i64, w.round() as i64)).or_default().push(r.strokes[k].reference_point());
    }
    // About one flower per cell of 50 x 43.3 over 600 x 400 (edges included): 111.
    assert!((100..=150).contains(&sites.len()), "{} copies", sites.len());
    // Every copy whole, except where the output's edge cuts it.
    let inside = kurbo::Rect::new(40.0, 40.0, 560.0, 360.0);
    for points in sites.values() {
        let centre = points.iter().fold(kurbo::Vec2::ZERO, |s, p| s + p.to_vec2()) / points.len() as f64;
        assert!(points.len() == parts || !inside.contains(centre.to_point()), "{} parts at {centre:?}", points.len());
    }

    // A tile on the same periods: one cell across, two rows down (a hexagonal lattice
    // repeats in a 50 x 86.6 rectangle).
    let t = stroke_tile(&once.strokes, &TileOptions { periods: Some([a, b]), ..TileOptions::default() }).unwrap();
    assert!((t.width - 50.0).abs() < 1e-6 && (t.height - 86.6).abs() < 1e-6, "{} x {}", t.width, t.height);

    // One cross drawn once: two bars on one centre, which show no spacing of their own.
    let cross = motifs().into_iter().find(|m| m.name == "cross").unwrap();
    let once = draw(&cross, (Vec2::new(1.0, 0.0), Vec2::new(0.0, 1.0)), (1, 1), 60.0, 0.01, 5);
    let o = StrokeOptions { periods: Some([[40.0, 0.0], [0.0, 40.0]]), ..opts(400.0, 400.0) };
    let r = synthesize_strokes(&once.strokes, &o, &mut Silent).unwrap();
    assert!((200..=242).contains(&r.strokes.len()), "{} bars: two per cell of 40 x 40 over 400 x 400", r.strokes.len());

    // Bad periods are named.
    for bad in [[[1.0, 0.0], [2.0, 0.0]], [[0.0, 0.0], [0.0, 5.0]], [[f64::NAN, 1.0], [0.0, 5.0]]] {
        let o = StrokeOptions { periods: Some(bad), ..opts(100.0, 100.0) };
        let e = synthesize_strokes(&once.strokes, &o, &mut Silent).unwrap_err().to_string();
        assert!(e.contains("not parallel"), "{e}");
    }
}
