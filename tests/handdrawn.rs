//! Motifs of several strokes drawn by hand (issue 23): crosses and asterisks (parts that
//! share a centre), flowers, houses and letters A (parts of different shapes), on square,
//! hexagonal, brick and oblique lattices, each copy with its own wobble at 0.2%, 1%, 3%
//! and 5% of the spacing, drawn 3x3 and 4x3, grown to 10x8 periods with the default
//! options. Every site of every part covered, no strays, no stacked duplicates, each part
//! its own class, and residuals within the bounds or, where the hand itself is
//! further off (5%), within the drawing's own.

use kurbo::{Point, Rect, Vec2};
use patternsynth::vector::exemplar::Exemplar;
use patternsynth::vector::handdrawn::{draw, grow_and_measure, lattices, motifs};
use patternsynth::vector::regularity::{measure_at, Regularity};
use patternsynth::vector::{synthesize_strokes, StrokeOptions};
use patternsynth::Silent;

const SPACING: f64 = 70.0;

fn grown(ex: &Exemplar, a: Vec2, b: Vec2, seed: u64) -> (Regularity, u32) {
    let (r, res) = grow_and_measure(ex, (a, b), SPACING, StrokeOptions { seed, ..Default::default() });
    (r, res.classification.count)
}

/// The drawing's own residuals against the lattice it was drawn on.
fn drawn(ex: &Exemplar, a: Vec2, b: Vec2) -> Regularity {
    let pts: Vec<(Point, u32)> = ex.strokes.iter().zip(&ex.classes).map(|(s, &c)| (s.reference_point(), c)).collect();
    let area = pts.iter().fold(Rect::from_points(pts[0].0, pts[0].0), |r, p| r.union_pt(p.0)).inflate(1.0, 1.0);
    measure_at(&ex.lattice, SPACING * a.hypot().min(b.hypot()), Vec2::ZERO, &pts, area)
}

#[test]
fn hand_drawn_motifs_grow_whole_on_their_lattice() {
    let mut failures = Vec::new();
    for motif in motifs() {
        for (lattice, a, b) in lattices() {
            for wobble in [0.002, 0.01, 0.03, 0.05] {
                for (nx, ny) in [(3, 3), (4, 3)] {
                    let ex = draw(&motif, (a, b), (nx, ny), SPACING, wobble, 1);
                    let (r, classes) = grown(&ex, a, b, 1);
                    let own = drawn(&ex, a, b);
                    let name = format!("{} {lattice} {:.1}% {nx}x{ny}", motif.name, wobble * 100.0);
                    println!("{name:<28} {r:?} own median {:.3} p95 {:.3}", own.median_residual, own.p95_residual);
                    let median_bound = 0.05f64.max(1.1 * own.median_residual);
                    let p95_bound = 0.10f64.max(1.1 * own.p95_residual);
                    if r.coverage < 0.99
                        || r.stray > 0
                        || r.stacked > 0
                        || r.median_residual > median_bound
                        || r.p95_residual > p95_bound
                        || classes as usize != motif.parts.len()
                    {
                        failures.push(format!("{name}: {r:?}, classes {classes}"));
                    }
                }
            }
        }
    }
    assert!(failures.is_empty(), "{failures:#?}");
}

#[test]
fn variation_never_puts_one_part_where_another_belongs() {
    // A house with default variation: every output stroke's shape is its own part's
    // (the size of its box within the spread of that part's drawn copies).
    let motif = motifs().into_iter().find(|m| m.name == "house").unwrap();
    let (_, a, b) = lattices()[0];
    let ex = draw(&motif, (a, b), (3, 3), SPACING, 0.03, 2);
    let opts = StrokeOptions { width: 700.0, height: 560.0, seed: 3, ..Default::default() };
    let res = synthesize_strokes(&ex.strokes, &opts, &mut Silent).unwrap();
    let size = |s: &patternsynth::vector::Stroke| s.bounds().size();
    for (s, &src) in res.strokes.iter().zip(&res.sources) {
        let part = ex.classes[src as usize];
        let copies: Vec<_> =
            ex.strokes.iter().zip(&ex.classes).filter(|(_, &c)| c == part).map(|(s, _)| size(s)).collect();
        let fits =
            copies.iter().any(|c| (c.width - size(s).width).abs() < 0.5 && (c.height - size(s).height).abs() < 0.5);
        assert!(fits, "an output stroke of part {part} has the box {:?} of no drawn copy of it", size(s));
    }
}

#[test]
fn five_bars_through_one_centre_stay_five_parts() {
    // Only their shapes tell the bars of an asterisk apart (all share its centre).
    let mut strokes = Vec::new();
    // A deterministic jitter of +-0.3 units per coordinate.
    let noise = |k: usize| ((k * 7919 % 13) as f64 / 13.0 - 0.5) * 0.6;
    for j in 0..3 {
        for i in 0..3 {
            let (cx, cy) = (70.0 + 70.0 * i as f64 + 35.0 * j as f64, 70.0 + 60.62 * j as f64);
            for k in 0..5 {
                let a = std::f64::consts::PI * k as f64 / 5.0;
                let (dx, dy) = (17.0 * a.cos(), 17.0 * a.sin());
                let n = strokes.len();
                strokes.push(patternsynth::vector::Stroke::new(
                    vec![
                        [cx - dx + noise(4 * n), cy - dy + noise(4 * n + 1)],
                        [cx + dx + noise(4 * n + 2), cy + dy + noise(4 * n + 3)],
                    ],
                    2.5,
                    None,
                ));
            }
        }
    }
    let res =
        synthesize_strokes(&strokes, &StrokeOptions { width: 500.0, height: 500.0, ..Default::default() }, &mut Silent)
            .unwrap();
    assert_eq!((res.classification.kinds, res.classification.count), (1, 5));
    assert_eq!(res.strokes.len() % 5, 0, "whole asterisks only: {}", res.strokes.len());
    // Each placed asterisk has its five bars at five angles.
    let angle = |s: &patternsynth::vector::Stroke| {
        let (p, q) = (s.points[0], s.points[1]);
        ((q[1] - p[1]).atan2(q[0] - p[0]).to_degrees().rem_euclid(180.0) / 36.0).round() as usize % 5
    };
    let mut per_angle = [0usize; 5];
    res.strokes.iter().for_each(|s| per_angle[angle(s)] += 1);
    assert!(per_angle.iter().all(|&c| c == per_angle[0]), "{per_angle:?}");
}

#[test]
fn a_copy_left_incomplete_is_not_a_motif_of_its_own() {
    // Crosses drawn 3x3, the centre one without its vertical bar (a copy being drawn):
    // the output holds whole crosses, one per site, not a lone bar stacked on each.
    let motif = motifs().into_iter().find(|m| m.name == "cross").unwrap();
    let (_, a, b) = lattices()[0];
    let mut ex = draw(&motif, (a, b), (3, 3), SPACING, 0.02, 4);
    ex.strokes.remove(9);
    ex.classes.remove(9);
    let (r, res) = grow_and_measure(&ex, (a, b), SPACING, StrokeOptions::default());
    assert_eq!(res.classification.kinds, 1);
    assert!(r.coverage >= 0.99 && r.stray == 0 && r.stacked == 0, "{r:?}");
}

#[test]
fn a_drawing_finished_with_accepted_proposals_grows_as_the_hand_drawn_one() {
    // The playground's story: draw a motif a few times with a shaky hand (5%), accept
    // the proposed copies, synthesize. Accepted copies are exact translates of drawn
    // ones; the drawing must still read as hand-drawn motifs, not as an exact tile.
    use patternsynth::vector::handdrawn::draw_over;
    use patternsynth::vector::replay::replay;
    let all = motifs();
    for (name, lattice) in [("cross", "brick"), ("house", "square"), ("asterisk", "hexagonal")] {
        let motif = all.iter().find(|m| m.name == name).unwrap();
        let (_, a, b) = lattices().into_iter().find(|l| l.0 == lattice).unwrap();
        let (ex, canvas) = draw_over(motif, (a, b), (8.0, 6.0), SPACING, 0.05, 5);
        let r = replay(&ex.strokes, &ex.classes, canvas, 0.3 * SPACING);
        assert!(r.accepted * 2 > r.strokes, "{name} on {lattice}: {r:?}");
        let finished = Exemplar { strokes: r.drawing.clone(), classes: r.drawing_classes.clone(), ..ex.clone() };
        let (g, res) = grow_and_measure(&finished, (a, b), SPACING, StrokeOptions::default());
        assert!(res.classification.motifs.copies.is_none(), "{name} on {lattice}: read as an exact tile");
        assert!(g.coverage >= 0.99 && g.stray == 0 && g.stacked == 0, "{name} on {lattice}: {g:?}");
        assert!(g.median_residual <= 0.05 && g.p95_residual <= 0.1, "{name} on {lattice}: {g:?}");
    }
}

#[test]
fn motifs_drawn_against_their_neighbours_grow_whole() {
    // Plus signs whose arms meet the next plus, houses whose eaves meet the next house's,
    // faces whose outlines meet: no gap separates the copies, the repetition does.
    use patternsynth::vector::handdrawn::{Motif, Part};
    let part = |pts: &[(f64, f64)], color: [u8; 3]| Part {
        path: pts.iter().map(|&(x, y)| Point::new(x, y)).collect(),
        closed: false,
        width: 2.5,
        color,
    };
    let ink = [30, 30, 30];
    let touching = [
        Motif {
            name: "plus-touching",
            parts: vec![
                part(&[(-0.5, 0.0), (0.5, 0.0)], ink),
                part(&[(0.0, -0.5), (0.0, 0.5)], ink),
                part(&[(0.15, 0.15), (0.25, 0.15), (0.25, 0.25), (0.15, 0.25), (0.15, 0.15)], [200, 40, 40]),
            ],
        },
        Motif {
            name: "house-touching",
            parts: vec![
                part(&[(-0.3, 0.0), (-0.3, 0.3), (0.3, 0.3), (0.3, 0.0)], ink),
                part(&[(-0.5, 0.02), (0.0, -0.3), (0.5, 0.02)], [170, 50, 40]),
                part(&[(-0.06, 0.3), (-0.06, 0.12), (0.06, 0.12), (0.06, 0.3)], [90, 60, 30]),
                part(&[(0.16, -0.14), (0.16, -0.28), (0.24, -0.28), (0.24, -0.09)], ink),
            ],
        },
    ];
    // Faces cheek to cheek (each outline crosses the next one), eyes inside.
    let ring = |cx: f64, cy: f64, r: f64, n: usize| Part {
        path: (0..n)
            .map(|k| {
                let t = k as f64 * std::f64::consts::TAU / n as f64;
                Point::new(cx + r * t.cos(), cy + r * t.sin())
            })
            .collect(),
        closed: true,
        width: 2.5,
        color: ink,
    };
    let smiley = Motif {
        name: "smiley-touching",
        parts: vec![
            ring(0.0, 0.0, 0.53, 48),
            ring(-0.15, -0.12, 0.06, 12),
            ring(0.15, -0.12, 0.06, 12),
            part(&[(-0.2, 0.15), (-0.1, 0.22), (0.0, 0.24), (0.1, 0.22), (0.2, 0.15)], [170, 30, 30]),
        ],
    };
    let touching: Vec<Motif> = touching.into_iter().chain(std::iter::once(smiley)).collect();
    // On a hexagonal or oblique lattice the plus signs touch only along their rows: a
    // cut there made rows of three pluses (each holding a bar and its copy one period
    // on) and grew them over one another (356-360 stacked strokes at 1%).
    let mut failures = Vec::new();
    for (lattice, a, b) in lattices() {
        for motif in &touching {
            for wobble in [0.01, 0.03] {
                let ex = draw(motif, (a, b), (3, 3), SPACING, wobble, 41);
                let (r, classes) = grown(&ex, a, b, 1);
                println!("{} {lattice} {:.0}%: {r:?} classes {classes}", motif.name, wobble * 100.0);
                if r.coverage < 0.99 || r.stray > 0 || r.stacked > 0 || r.p95_residual > 0.1 {
                    failures.push(format!("{} on {lattice} at {wobble}: {r:?}", motif.name));
                }
            }
        }
    }
    assert!(failures.is_empty(), "{failures:#?}");
}

#[test]
fn overlapping_faces_are_nine_smileys_not_a_merged_pair() {
    // Faces drawn so that neighbours overlap: a point of one face lies inside the next,
    // which is no eye inside its face; the copies are the nine smileys.
    let strokes: Vec<patternsynth::vector::Stroke> =
        serde_json::from_str(include_str!("fixtures/handdrawn/smileys-touching-5pct.json")).unwrap();
    let c = patternsynth::vector::classify_strokes(&strokes, None, None, None).unwrap();
    assert_eq!(c.motifs.instances.len(), 9, "{:?}", c.motifs.instances);
    assert!(c.motifs.instances.iter().all(|g| g.len() == 4), "{:?}", c.motifs.instances);
    assert_eq!(c.kinds, 1);
}

/// A fixture of the drawing package's strokes.
fn fixture(name: &str) -> Vec<patternsynth::vector::Stroke> {
    let path = format!("{}/tests/fixtures/handdrawn/{name}.json", env!("CARGO_MANIFEST_DIR"));
    serde_json::from_str(&std::fs::read_to_string(path).unwrap()).unwrap()
}

#[test]
fn overlapping_cats_and_fish_with_a_tail_apart_are_nine_whole_copies() {
    // Cats: faces wider than the spacing leave no gap to cut, and the lattice of the
    // strokes one by one must not take the offset between a copy's two eyes (or ears)
    // for a period. Fish: a tail drawn off its body is still that fish's tail.
    for (name, parts) in [("cats-overlapping-5pct", 6), ("fish-tail-apart-5pct", 3)] {
        let strokes = fixture(name);
        let c = patternsynth::vector::classify_strokes(&strokes, None, None, None).unwrap();
        assert_eq!(c.motifs.instances.len(), 9, "{name}: {:?}", c.motifs.instances);
        assert!(c.motifs.instances.iter().all(|g| g.len() == parts), "{name}: {:?}", c.motifs.instances);
        assert_eq!(c.kinds, 1, "{name}");
        // Grown with the defaults, every copy is whole: around each copy's first part
        // (away from the edges), one of each other part where the drawn copies put it.
        let opts = patternsynth::vector::StrokeOptions { width: 640.0, height: 480.0, ..Default::default() };
        let out = patternsynth::vector::synthesize_strokes(&strokes, &opts, &mut patternsynth::Silent).unwrap();
        let part_of = |src: u32| c.motifs.part[src as usize] as usize;
        let at = |s: &patternsynth::vector::Stroke| s.reference_point().to_vec2();
        let mut offset = vec![kurbo::Vec2::ZERO; parts];
        for g in &c.motifs.instances {
            let first = g.iter().find(|&&s| c.motifs.part[s as usize] == 0).unwrap();
            for &s in g {
                offset[part_of(s)] += (at(&strokes[s as usize]) - at(&strokes[*first as usize])) / 9.0;
            }
        }
        // How far the drawn copies themselves put each part from where it is on average.
        let mut reach = vec![0.0f64; parts];
        for g in &c.motifs.instances {
            let first = g.iter().find(|&&s| c.motifs.part[s as usize] == 0).unwrap();
            for &s in g {
                let d = at(&strokes[s as usize]) - at(&strokes[*first as usize]) - offset[part_of(s)];
                reach[part_of(s)] = reach[part_of(s)].max(d.hypot() + 1.0);
            }
        }
        let (mut copies, mut whole) = (0, 0);
        for (s, &src) in out.strokes.iter().zip(&out.sources) {
            let p = at(s);
            if part_of(src) != 0 || !(100.0..540.0).contains(&p.x) || !(100.0..380.0).contains(&p.y) {
                continue;
            }
            copies += 1;
            whole += (1..parts).all(|k| {
                let near = out
                    .strokes
                    .iter()
                    .zip(&out.sources)
                    .filter(|(o, &os)| part_of(os) == k && (at(o) - p - offset[k]).hypot() < reach[k]);
                near.count() == 1
            }) as usize;
        }
        assert!(copies > 15 && whole as f64 >= 0.97 * copies as f64, "{name}: {whole} of {copies} copies whole");
    }
}

#[test]
fn cats_drawn_against_one_another_are_split_into_copies_and_bring_ghosts() {
    // Three cats in an L overlap and read as one group of eighteen strokes; the three
    // drawn apart show what one cat holds, so the group is three cats.
    let strokes = fixture("cats-six-apart-and-touching-5pct");
    let c = patternsynth::vector::classify_strokes(&strokes, None, None, None).unwrap();
    assert_eq!(c.motifs.instances.len(), 6, "{:?}", c.motifs.instances);
    assert!(c.motifs.instances.iter().all(|g| g.len() == 6), "{:?}", c.motifs.instances);
    assert_eq!(c.kinds, 1);
    // The faces of one copy are 70 apart: each copy holds one face and what lies round it.
    for g in &c.motifs.instances {
        let b = g.iter().fold(strokes[g[0] as usize].bounds(), |r, &s| r.union(strokes[s as usize].bounds()));
        assert!(b.width() < 90.0 && b.height() < 90.0, "a copy spans {b:?}");
    }
    let s = patternsynth::vector::suggest_strokes(
        &strokes,
        &patternsynth::vector::SuggestOptions { region: Some([0.0, 0.0, 500.0, 500.0]), ..Default::default() },
    )
    .unwrap();
    assert!(!s.strokes.is_empty() && s.strokes.len() % 6 == 0, "{} ghosts: {:?}", s.strokes.len(), s.reason);
}
