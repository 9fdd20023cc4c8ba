//! Tessellations (issue 23): an example whose pieces share their edges (a low-poly
//! triangle mesh) grows to an output with the example's coverage (no gaps, no double
//! cover) and its mix of paints, with the default options.

use patternsynth::vector::{synthesize_strokes, Rgb, Stroke, StrokeOptions};
use patternsynth::Silent;

/// A square grid of `n x n` cells of side `s`, inner vertices jittered by up to a fifth
/// of a cell, each cell cut into two triangles of random paint from three.
fn mesh(n: usize, s: f64, seed: u64) -> Vec<Stroke> {
    pieces(n, s, seed, true)
}

/// The grid of `mesh`, its cells cut into two triangles or (`cut` false) left quads.
fn pieces(n: usize, s: f64, seed: u64, cut: bool) -> Vec<Stroke> {
    let mut state = seed;
    let mut next = move || {
        state = state.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
        (state >> 11) as f64 / (1u64 << 53) as f64
    };
    let mut v = Vec::new();
    for j in 0..=n {
        for i in 0..=n {
            let edge = i == 0 || j == 0 || i == n || j == n;
            let jit = |r: f64| if edge { 0.0 } else { (r - 0.5) * 0.4 * s };
            let (rx, ry) = (next(), next());
            v.push([i as f64 * s + jit(rx), j as f64 * s + jit(ry)]);
        }
    }
    let at = |i: usize, j: usize| v[j * (n + 1) + i];
    let paints = [Rgb([200, 90, 60]), Rgb([60, 120, 180]), Rgb([230, 190, 80])];
    let mut out = Vec::new();
    for j in 0..n {
        for i in 0..n {
            let quad = vec![at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)];
            let cells =
                if cut { vec![vec![quad[0], quad[1], quad[2]], vec![quad[0], quad[2], quad[3]]] } else { vec![quad] };
            for piece in cells {
                let mut st = Stroke::new(piece, 0.0, None);
                st.fill = Some(paints[(next() * 3.0) as usize]);
                st.closed = true;
                out.push(st);
            }
        }
    }
    out
}

/// Shares of sample points in the square `[x0, x1]^2` covered by no piece and by two
/// or more (a background, a piece covering the whole square, left out), and the share
/// of each paint among the covered points.
fn cover(strokes: &[Stroke], x0: f64, x1: f64, step: f64) -> (f64, f64, Vec<(Rgb, f64)>) {
    let strokes: Vec<&Stroke> = strokes.iter().filter(|s| !covers(s, x0, x1)).collect();
    // Even-odd crossings: pieces need not be convex.
    let inside = |p: [f64; 2], t: &[[f64; 2]]| {
        let mut odd = false;
        for k in 0..t.len() {
            let (a, b) = (t[k], t[(k + 1) % t.len()]);
            if (a[1] > p[1]) != (b[1] > p[1]) && p[0] < a[0] + (p[1] - a[1]) / (b[1] - a[1]) * (b[0] - a[0]) {
                odd = !odd;
            }
        }
        odd
    };
    let (mut none, mut twice, mut all) = (0usize, 0usize, 0usize);
    let mut paints: Vec<(Rgb, f64)> = Vec::new();
    let mut y = x0 + step / 2.0;
    while y < x1 {
        let mut x = x0 + step / 2.0;
        while x < x1 {
            let hits: Vec<&&Stroke> = strokes.iter().filter(|s| inside([x, y], &s.points)).collect();
            all += 1;
            none += hits.is_empty() as usize;
            twice += (hits.len() > 1) as usize;
            if let Some(fill) = hits.first().and_then(|s| s.fill) {
                match paints.iter_mut().find(|p| p.0 == fill) {
                    Some(p) => p.1 += 1.0,
                    None => paints.push((fill, 1.0)),
                }
            }
            x += step;
        }
        y += step;
    }
    let covered = (all - none) as f64;
    paints.iter_mut().for_each(|p| p.1 /= covered);
    (none as f64 / all as f64, twice as f64 / all as f64, paints)
}

/// Whether `s` covers the square `[x0, x1]^2`.
fn covers(s: &Stroke, x0: f64, x1: f64) -> bool {
    let (lo, hi) = s.points.iter().fold(([f64::MAX; 2], [f64::MIN; 2]), |(lo, hi), p| {
        ([lo[0].min(p[0]), lo[1].min(p[1])], [hi[0].max(p[0]), hi[1].max(p[1])])
    });
    lo[0] <= x0 && lo[1] <= x0 && hi[0] >= x1 && hi[1] >= x1
}

#[test]
fn a_triangle_mesh_grows_covered_once_with_its_mix_of_paints() {
    let example = mesh(8, 30.0, 3);
    let (gap0, twice0, mix0) = cover(&example, 0.0, 240.0, 3.0);
    assert!(gap0 < 0.005 && twice0 < 0.01, "the example itself: {gap0} {twice0}");
    for seed in [1, 2] {
        let opts = StrokeOptions { width: 480.0, height: 480.0, seed, ..Default::default() };
        let out = synthesize_strokes(&example, &opts, &mut Silent).unwrap();
        let (gap, twice, mix) = cover(&out.strokes, 0.0, 480.0, 4.0);
        assert!(gap < 0.01 && twice < 0.01, "seed {seed}: {gap} uncovered, {twice} twice");
        for (paint, share) in &mix0 {
            let got = mix.iter().find(|p| p.0 == *paint).map_or(0.0, |p| p.1);
            assert!((got - share).abs() < 0.08, "seed {seed}: {paint:?} covers {got}, {share} in the example");
        }
        // Pieces the size of the example's: as many per area (centres inside), within a fifth.
        let centred = |s: &&Stroke| {
            let c = s.points.iter().fold([0.0, 0.0], |a, p| [a[0] + p[0] / 3.0, a[1] + p[1] / 3.0]);
            (0.0..480.0).contains(&c[0]) && (0.0..480.0).contains(&c[1])
        };
        let inside = out.strokes.iter().filter(centred).count();
        let ratio = (inside as f64 / (480.0 * 480.0)) / (example.len() as f64 / (240.0 * 240.0));
        assert!((0.8..1.25).contains(&ratio), "seed {seed}: piece density {ratio} of the example's");
    }
}

#[test]
fn triangles_that_do_not_share_corners_are_placed_as_elements() {
    // The same triangles pulled apart (each shrunk about its centre): no mesh, so the
    // output holds copies of the example's own triangles, as any scatter's.
    let apart: Vec<Stroke> = mesh(8, 30.0, 3)
        .into_iter()
        .map(|mut s| {
            let c = s.points.iter().fold([0.0, 0.0], |a, p| [a[0] + p[0] / 3.0, a[1] + p[1] / 3.0]);
            s.points.iter_mut().for_each(|p| *p = [c[0] + 0.7 * (p[0] - c[0]), c[1] + 0.7 * (p[1] - c[1])]);
            s
        })
        .collect();
    assert!(placed_as_elements(&apart));
}

#[test]
fn triangles_that_meet_only_at_corners_are_no_mesh() {
    // The upward triangles of a triangular lattice, of random paints: every corner is
    // shared, no edge is; joined afresh, the gaps between them would be filled.
    let mut ups = Vec::new();
    let mut k = 7u32;
    for j in 0..6 {
        for i in 0..6 {
            let (x, y) = (30.0 * i as f64 + 15.0 * (j % 2) as f64, 26.0 * j as f64);
            let mut t = Stroke::new(vec![[x, y + 26.0], [x + 30.0, y + 26.0], [x + 15.0, y]], 0.0, None);
            k = k.wrapping_mul(1103515245).wrapping_add(12345);
            t.fill = Some([Rgb([200, 90, 60]), Rgb([60, 120, 180]), Rgb([230, 190, 80])][(k >> 16) as usize % 3]);
            t.closed = true;
            ups.push(t);
        }
    }
    assert!(placed_as_elements(&ups));
}

/// Whether the output of `example` holds only triangles of the example's own shapes
/// (placed as elements, not joined afresh).
fn placed_as_elements(example: &[Stroke]) -> bool {
    let opts = StrokeOptions { width: 300.0, height: 300.0, ..Default::default() };
    let out = synthesize_strokes(example, &opts, &mut Silent).unwrap();
    let shape = |s: &Stroke| {
        let p = &s.points;
        let mut e: Vec<i64> = (0..3)
            .map(|k| (((p[k][0] - p[(k + 1) % 3][0]).hypot(p[k][1] - p[(k + 1) % 3][1])) * 1000.0).round() as i64)
            .collect();
        e.sort();
        e
    };
    let shapes: Vec<Vec<i64>> = example.iter().map(shape).collect();
    !out.strokes.is_empty() && out.strokes.iter().all(|s| shapes.contains(&shape(s)))
}

/// A honeycomb of `cols x rows` regular hexagons of circumradius `r`, of random paints
/// from three.
fn honeycomb(cols: usize, rows: usize, r: f64, seed: u64) -> Vec<Stroke> {
    let mut k = seed as u32;
    let paints = [Rgb([200, 90, 60]), Rgb([60, 120, 180]), Rgb([230, 190, 80])];
    let w = 3f64.sqrt() * r;
    let mut out = Vec::new();
    for j in 0..rows {
        for i in 0..cols {
            let (cx, cy) = (w * (i as f64 + 0.5 * (j % 2) as f64), 1.5 * r * j as f64);
            let corners: Vec<[f64; 2]> = (0..6)
                .map(|c| {
                    let a = std::f64::consts::PI / 3.0 * c as f64 + std::f64::consts::PI / 6.0;
                    // Rounded as an SVG's coordinates are, so neighbours' corners meet.
                    [((cx + r * a.cos()) * 1e3).round() / 1e3, ((cy + r * a.sin()) * 1e3).round() / 1e3]
                })
                .collect();
            let mut h = Stroke::new(corners, 0.0, None);
            k = k.wrapping_mul(1103515245).wrapping_add(12345);
            h.fill = Some(paints[(k >> 16) as usize % 3]);
            h.closed = true;
            out.push(h);
        }
    }
    out
}

/// Shares of the pieces (of those with their centre inside `[0, size]^2`) with each
/// number of sides, from three to eight.
fn sides(strokes: &[Stroke], size: f64) -> [f64; 6] {
    let mut count = [0.0; 6];
    let mut all = 0.0;
    for s in strokes.iter().filter(|s| !covers(s, 0.0, size)) {
        let c = s.points.iter().fold([0.0, 0.0], |a, p| [a[0] + p[0], a[1] + p[1]]);
        let c = [c[0] / s.points.len() as f64, c[1] / s.points.len() as f64];
        if (0.0..size).contains(&c[0]) && (0.0..size).contains(&c[1]) {
            all += 1.0;
            if (3..=8).contains(&s.points.len()) {
                count[s.points.len() - 3] += 1.0;
            }
        }
    }
    count.map(|c| c / all)
}

#[test]
fn quads_and_hexagons_grow_covered_once_in_their_own_shapes_over_their_background() {
    let quads = pieces(8, 30.0, 3, false);
    let mut backed = quads.clone();
    let mut back = Stroke::new(vec![[0.0, 0.0], [240.0, 0.0], [240.0, 240.0], [0.0, 240.0]], 0.0, None);
    back.fill = Some(Rgb([250, 250, 245]));
    back.closed = true;
    backed.insert(0, back.clone());
    let hexagons = honeycomb(10, 10, 15.0, 5);
    for (name, example, side, shape) in
        [("quads", &quads, 4, 0.9), ("quads over a background", &backed, 4, 0.9), ("hexagons", &hexagons, 6, 0.9)]
    {
        let (_, _, mix0) = cover(example, 0.0, 220.0, 2.0);
        let opts = StrokeOptions { width: 480.0, height: 480.0, seed: 1, ..Default::default() };
        let out = synthesize_strokes(example, &opts, &mut Silent).unwrap();
        let (gap, twice, mix) = cover(&out.strokes, 0.0, 480.0, 4.0);
        assert!(gap < 0.01 && twice < 0.01, "{name}: {gap} uncovered, {twice} twice");
        for (paint, share) in &mix0 {
            let got = mix.iter().find(|p| p.0 == *paint).map_or(0.0, |p| p.1);
            assert!((got - share).abs() < 0.08, "{name}: {paint:?} covers {got}, {share} in the example");
        }
        // The example's own shape for nearly all pieces, and as many pieces per area.
        let got = sides(&out.strokes, 480.0);
        assert!(got[side - 3] >= shape, "{name}: sides {got:?}");
        let pieces = out.strokes.iter().filter(|s| !covers(s, 0.0, 480.0)).count() as f64;
        let example_pieces = example.iter().filter(|s| !covers(s, 0.0, 240.0)).count() as f64;
        let example_area = if side == 6 { 10.0 * 3f64.sqrt() * 15.0 * 10.0 * 22.5 } else { 240.0 * 240.0 };
        let ratio = (pieces / (480.0 * 480.0)) / (example_pieces / example_area);
        assert!((0.8..1.25).contains(&ratio), "{name}: piece density {ratio} of the example's");
        // The background stays behind, over the whole output.
        let kept = out.strokes.iter().position(|s| s.fill == back.fill);
        if name.contains("background") {
            assert_eq!(kept, Some(0), "{name}: the background first");
            assert!(covers(&out.strokes[0], 0.0, 480.0));
        } else {
            assert_eq!(kept, None);
        }
    }
}

#[test]
fn a_mesh_too_large_for_the_limit_names_the_limit_given() {
    let opts = StrokeOptions { width: 4800.0, height: 4800.0, max_elements: 5_000, ..Default::default() };
    for example in [mesh(8, 30.0, 3), pieces(8, 30.0, 3, false)] {
        let err = synthesize_strokes(&example, &opts, &mut Silent).unwrap_err().to_string();
        assert!(err.contains("5000") && err.contains("pieces"), "{err}");
    }
}
