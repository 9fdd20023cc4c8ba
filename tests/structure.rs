//! Repetitions that are not lattices (issue 27), synthesized with the default options:
//! rings of petals drawn in part or whole become rosettes repeated over the output,
//! leaves along an arc continue along it, a spiral continues both ways, and the result
//! says which structure it found. Figures against the generator's own sites
//! (`vector::sequences`): every site covered; at a 1% wobble the median residual at
//! most 5-6.5% and the 95th percentile at most 10-15% of the step; at 3%, rings
//! within 10% of the step of the hand's own scatter.
use kurbo::{Point, Rect, Vec2};
use patternsynth::vector::chain::Structure;
use patternsynth::vector::exemplar::{family_list, irregular_dashes};
use patternsynth::vector::sequences::{sequences, Sequence};
use patternsynth::vector::{synthesize_strokes, Stroke, StrokeOptions, StrokeResult};
use patternsynth::Silent;
use std::f64::consts::TAU;

const W: f64 = 800.0;
const H: f64 = 600.0;

fn synth(strokes: &[Stroke]) -> StrokeResult {
    synthesize_strokes(strokes, &StrokeOptions { width: W, height: H, ..Default::default() }, &mut Silent).unwrap()
}

fn family(wobble: f64, seed: u64, name: &str) -> Sequence {
    sequences(wobble, seed).into_iter().find(|q| q.name == name).unwrap()
}

fn centroid(s: &Stroke) -> Point {
    let n = s.points.len() as f64;
    let (x, y) = s.points.iter().fold((0.0, 0.0), |a, p| (a.0 + p[0], a.1 + p[1]));
    Point::new(x / n, y / n)
}

fn quantile(v: &mut [f64], q: f64) -> f64 {
    v.sort_by(f64::total_cmp);
    v[((v.len() - 1) as f64 * q).round() as usize]
}

/// Rosettes of `n` petals: the output's petals grouped by where they start (a petal
/// starts at its ring's centre); each ring wholly inside the output must hold `n`
/// petals, one per `n`th of a turn. Returns (rings checked, residuals as shares of the
/// step, petals missing or stacked).
fn rosettes(r: &StrokeResult, n: usize, len: f64) -> (usize, Vec<f64>, usize) {
    let mut rings: Vec<(Point, Vec<Point>)> = Vec::new();
    for s in &r.strokes {
        let start = Point::new(s.points[0][0], s.points[0][1]);
        match rings.iter_mut().find(|(c, _)| c.distance(start) < 0.25 * len) {
            Some((_, petals)) => petals.push(centroid(s)),
            None => rings.push((start, vec![centroid(s)])),
        }
    }
    let inside = Rect::new(0.0, 0.0, W, H).inset(-1.2 * len);
    let (mut checked, mut residuals, mut bad) = (0, Vec::new(), 0);
    for (c, petals) in rings.iter().filter(|(c, _)| inside.contains(*c)) {
        checked += 1;
        let radius = petals.iter().map(|p| p.distance(*c)).sum::<f64>() / petals.len() as f64;
        let step = 2.0 * radius * (TAU / (2.0 * n as f64)).sin();
        let angle = |p: &Point| (p.y - c.y).atan2(p.x - c.x);
        // The ring's turn: the circular mean of n times each angle.
        let (sx, sy) = petals.iter().fold((0.0, 0.0), |a, p| {
            let t = n as f64 * angle(p);
            (a.0 + t.cos(), a.1 + t.sin())
        });
        let phase = sy.atan2(sx) / n as f64;
        let mut slots = vec![0usize; n];
        for p in petals {
            let k = ((angle(p) - phase) / (TAU / n as f64)).round();
            let ideal = phase + k * TAU / n as f64;
            let site = *c + Vec2::new(ideal.cos(), ideal.sin()) * radius;
            residuals.push(site.distance(*p) / step);
            slots[k.rem_euclid(n as f64) as usize] += 1;
        }
        bad += slots.iter().filter(|&&m| m != 1).count();
    }
    (checked, residuals, bad)
}

#[test]
fn rings_drawn_in_part_or_whole_become_rosettes() {
    // Three petals of five or eight, four of twelve (three of twelve at 3% put thirteen
    // round in one seed of three: the turn read 4% off). At 5% rings are not reliable
    // yet: three of eight read no ring, four of five a ring of six, in one seed of three.
    for wobble in [0.01, 0.03] {
        for seed in 1..=3 {
            for (n, fewest) in [(5usize, 3), (8, 3), (12, 4)] {
                let q = family(wobble, seed, &format!("ring of {n}"));
                // The hand's own: every petal drawn, measured the same way.
                let whole = synth(&q.strokes);
                let (_, mut own, _) = rosettes(&whole, n, 90.0);
                let (own_median, own_p95) = (quantile(&mut own, 0.5), quantile(&mut own, 0.95));
                for drawn in [fewest, n] {
                    let r = if drawn == n { whole.clone() } else { synth(&q.strokes[..drawn]) };
                    let what = format!("ring of {n}, {drawn} drawn, wobble {wobble}, seed {seed}");
                    assert_eq!(r.structure, Structure::Ring, "{what}");
                    assert!(r.periods.is_some(), "{what}: a rosette pattern repeats on a lattice");
                    let (checked, mut res, bad) = rosettes(&r, n, 90.0);
                    assert!(checked >= 4, "{what}: {checked} whole rosettes");
                    assert_eq!(bad, 0, "{what}: petals missing or stacked");
                    let (median, p95) = (quantile(&mut res, 0.5), quantile(&mut res, 0.95));
                    eprintln!(
                        "{what}: {checked} rosettes whole, residual median {median:.3}, p95 {p95:.3} of the step"
                    );
                    // At most 10% of the step beyond the hand's own scatter (at 1%: the
                    // issue's 5% outright).
                    assert!(
                        median <= own_median + 0.10 && p95 <= own_p95 + 0.15,
                        "{what}: residual median {median:.3}, p95 {p95:.3} (the hand's own {own_median:.3}, {own_p95:.3})"
                    );
                    if wobble == 0.01 {
                        assert!(median <= 0.065 && p95 <= 0.10, "{what}: residual median {median:.3}, p95 {p95:.3}");
                    }
                }
            }
        }
    }
}

/// The output copies against sites `sites` (generator's, moved by where the drawing
/// landed in the output): each copy's residual to its nearest site as a share of
/// `step`, and the share of the sites inside the output (half a step in) covered by a
/// copy within 0.3 of the step.
fn against_sites(r: &StrokeResult, drawn: &[Stroke], sites: &[Point], step: f64) -> (Vec<f64>, f64) {
    // The drawn strokes come first in the output, moved as a whole.
    let v = Point::new(r.strokes[0].points[0][0], r.strokes[0].points[0][1])
        - Point::new(drawn[0].points[0][0], drawn[0].points[0][1]);
    let sites: Vec<Point> = sites.iter().map(|&p| p + v).collect();
    let centres: Vec<Point> = r.strokes.iter().map(Stroke::reference_point).collect();
    let residuals =
        centres.iter().map(|c| sites.iter().map(|s| s.distance(*c)).fold(f64::INFINITY, f64::min) / step).collect();
    let inner = Rect::new(0.0, 0.0, W, H).inset(-0.5 * step);
    let wanted: Vec<&Point> = sites.iter().filter(|s| inner.contains(**s)).collect();
    let covered = wanted.iter().filter(|s| centres.iter().any(|c| c.distance(***s) < 0.3 * step)).count();
    (residuals, covered as f64 / wanted.len().max(1) as f64)
}

#[test]
fn leaves_on_an_arc_continue_along_it() {
    // Round the whole circle from a few leaves: the centre of a far arc is read from
    // where the leaves are, so a hand's scatter moves it most (at 3%, four leaves put
    // the far side of the circle 15% of a step off): the figures hold at 1% from three
    // leaves, at 3% from six.
    for (wobble, drawn, median_max, p95_max) in [(0.01, 3, 0.065, 0.15), (0.01, 4, 0.055, 0.10), (0.03, 6, 0.10, 0.35)]
    {
        for seed in 1..=3 {
            let q = family(wobble, seed, "leaves on an arc");
            // The generator's sites: leaf centres every 14° on a circle of radius 260
            // (once round); a leaf's reference point sits half its length along its own
            // direction.
            let (r0, d) = (260.0, 14f64.to_radians());
            let sites: Vec<Point> = (-12..=13)
                .map(|k| {
                    let phi = -1.2 + k as f64 * d;
                    let at = Point::new(300.0, 560.0) + Vec2::new(phi.sin(), -phi.cos()) * r0;
                    at + Vec2::new((phi - 0.6).cos(), (phi - 0.6).sin()) * 22.5
                })
                .collect();
            let r = synth(&q.strokes[..drawn]);
            let what = format!("{drawn} leaves, wobble {wobble}, seed {seed}");
            assert_eq!(r.structure, Structure::Curve, "{what}");
            assert!(r.strokes.len() > drawn + 6, "{what}: {} leaves", r.strokes.len());
            let (mut res, covered) = against_sites(&r, &q.strokes[..drawn], &sites, q.step);
            let (median, p95) = (quantile(&mut res, 0.5), quantile(&mut res, 0.95));
            eprintln!("{what}: {:.0}% of sites covered, residual median {median:.3}, p95 {p95:.3}", 100.0 * covered);
            assert!(covered >= 0.99, "{what}: {:.0}% of the arc's sites covered", 100.0 * covered);
            assert!(median <= median_max && p95 <= p95_max, "{what}: residual median {median:.3}, p95 {p95:.3}");
        }
    }
}

#[test]
fn a_spiral_continues_both_ways() {
    for wobble in [0.01, 0.03] {
        for seed in 1..=3 {
            let q = family(wobble, seed, "spiral");
            let sites: Vec<Point> = (-40..40)
                .map(|k| {
                    let (r, theta) = (120.0 * 1.06f64.powi(k), k as f64 * TAU / 12.0);
                    let at = Point::new(300.0, 300.0) + Vec2::new(theta.cos(), theta.sin()) * r;
                    at + Vec2::new((theta + 1.2).cos(), (theta + 1.2).sin()) * (0.35 * r / 2.0)
                })
                .collect();
            let r = synth(&q.strokes[..4]);
            let what = format!("spiral, wobble {wobble}, seed {seed}");
            assert_eq!(r.structure, Structure::Sequence, "{what}");
            assert!(r.strokes.len() >= 12, "{what}: {} copies", r.strokes.len());
            // Residuals as shares of the step where each copy is (it grows 6% a step).
            let (res, _) = against_sites(&r, &q.strokes[..4], &sites, 1.0);
            let v = r.strokes[0].points[0][0] - q.strokes[0].points[0][0];
            let mut shares: Vec<f64> = res
                .iter()
                .zip(&r.strokes)
                .map(|(d, s)| {
                    let c = s.reference_point() - Vec2::new(v, r.strokes[0].points[0][1] - q.strokes[0].points[0][1]);
                    let k = (0..sites.len() - 1)
                        .min_by(|&i, &j| sites[i].distance(c).total_cmp(&sites[j].distance(c)))
                        .unwrap();
                    d / sites[k].distance(sites[k + 1])
                })
                .collect();
            let (median, p95) = (quantile(&mut shares, 0.5), quantile(&mut shares, 0.95));
            let (median_max, p95_max) = if wobble <= 0.01 { (0.05, 0.10) } else { (0.12, 0.16) };
            eprintln!("{what}: {} copies, residual median {median:.3}, p95 {p95:.3}", r.strokes.len());
            assert!(median <= median_max && p95 <= p95_max, "{what}: residual median {median:.3}, p95 {p95:.3}");
        }
    }
}

#[test]
fn the_result_names_the_structure() {
    let grid = family_list().into_iter().find(|f| f.name == "grid").unwrap();
    let (ex, _) = grid.canvas(4.0, 3.0, 0.0, 1);
    assert_eq!(synth(&ex.strokes).structure, Structure::Lattice);
    assert_eq!(synth(&irregular_dashes(60, 300.0, 2)).structure, Structure::Irregular);
}

/// A line from `p` to `q`, its ends off by up to `jitter`, seeded.
fn bar(p: Point, q: Point, jitter: f64, seed: u64) -> Stroke {
    let mut rng = patternsynth::rng::Rng::new(seed);
    let mut off = || (rng.next_f64() - 0.5) * 2.0 * jitter;
    Stroke::new(
        (0..=8)
            .map(|k| {
                let t = k as f64 / 8.0;
                [p.x + (q.x - p.x) * t + off(), p.y + (q.y - p.y) * t + off()]
            })
            .collect(),
        2.0,
        None,
    )
}

#[test]
fn bars_through_one_centre_and_rays_round_a_disc_repeat_whole() {
    // (From a new user's trial: an asterisk drawn by hand came back refused as
    // millions of elements, a sun icon's rays as a curve drawn once.)
    let c = Point::new(200.0, 200.0);
    let ray = |a: f64, r0: f64, r1: f64| (c + Vec2::new(a.cos(), a.sin()) * r0, c + Vec2::new(a.cos(), a.sin()) * r1);
    for seed in 1..=3 {
        let asterisk: Vec<Stroke> = (0..3)
            .map(|i| {
                let (p, q) = ray(i as f64 * TAU / 6.0, -70.0, 70.0);
                bar(p, q, 1.0, seed * 10 + i)
            })
            .collect();
        let r = synth(&asterisk);
        assert_eq!(r.structure, Structure::Ring, "asterisk, seed {seed}");
        // Whole asterisks: the bars group by centre, three to a centre inside.
        let centres: Vec<Point> = r.strokes.iter().map(Stroke::reference_point).collect();
        let inside = Rect::new(0.0, 0.0, W, H).inset(-80.0);
        let mut whole = 0;
        for p in centres.iter().filter(|p| inside.contains(**p)) {
            let here = centres.iter().filter(|q| q.distance(*p) < 5.0).count();
            assert_eq!(here, 3, "asterisk, seed {seed}: {here} bars at {p:?}");
            whole += 1;
        }
        assert!(whole >= 3 * 3, "asterisk, seed {seed}: {} whole", whole / 3);
        // A sun: a disc and eight rays round it, all drawn.
        let mut sun: Vec<Stroke> = (0..8)
            .map(|i| {
                let (p, q) = ray(i as f64 * TAU / 8.0, 40.0, 60.0);
                bar(p, q, 0.5, seed * 10 + i)
            })
            .collect();
        sun.push(Stroke::new(
            (0..=24)
                .map(|k| c + Vec2::new((k as f64 / 24.0 * TAU).cos(), (k as f64 / 24.0 * TAU).sin()) * 25.0)
                .map(|p| [p.x, p.y])
                .collect(),
            2.0,
            None,
        ));
        let r = synth(&sun);
        assert_eq!(r.structure, Structure::Ring, "sun, seed {seed}");
        assert!(
            r.periods.is_some() && r.strokes.len() >= 4 * sun.len(),
            "sun, seed {seed}: {} strokes",
            r.strokes.len()
        );
    }
}

/// The count of a ring drawn in part by a wobbling hand (rings of 5, 6, 8, 10 and 12,
/// seeds 1-10): from four petals at 3% of the step every count right, at 5% at least
/// 45 of 50 right and at most two wrong; from three petals at 5%, at least 35 right.
#[test]
fn a_ring_drawn_in_part_is_counted_right() {
    let count = |wobble: f64, drawn: usize| {
        let (mut right, mut wrong) = (0, 0);
        for seed in 1..=10 {
            for q in sequences(wobble, seed).into_iter().filter(|q| q.name.starts_with("ring")) {
                let n: usize = q.name.trim_start_matches("ring of ").parse().unwrap();
                match patternsynth::vector::chain::find(&q.strokes[..drawn]).and_then(|c| c.closes) {
                    Some(k) if k == n => right += 1,
                    Some(_) => wrong += 1,
                    None => {}
                }
            }
        }
        (right, wrong)
    };
    assert_eq!(count(0.03, 4), (50, 0));
    let (right, wrong) = count(0.05, 4);
    assert!(right >= 45 && wrong <= 2, "at 5% from four petals: {right} right, {wrong} wrong of 50");
    let (right, _) = count(0.05, 3);
    assert!(right >= 35, "at 5% from three petals: {right} right of 50");
}

/// Hatching along a straight contour (4 or all 14 lines drawn, 1% and 3%, seeds
/// 1-3) continues as its row across the output, reported as a lattice (it was
/// 'irregular'): the output's lines on one straight line (each within 0.3 of the
/// spacing of their fitted line, which is level within 3 degrees: three lines drawn at
/// 3% leave the row's slope uncertain by about 1.2),
/// none closer to the next than half the spacing or further than 1.5 times it, and the
/// row spanning the output's width.
#[test]
fn straight_hatching_continues_as_its_row() {
    for wobble in [0.01, 0.03] {
        for seed in 1..=3 {
            let q = family(wobble, seed, "straight hatching");
            // Three lines are a row too, once grown (at 3% a row from three can drift).
            let three = if wobble < 0.02 { Some(3) } else { None };
            for drawn in three.into_iter().chain([4, q.strokes.len()]) {
                let r = synth(&q.strokes[..drawn]);
                let what = format!("{drawn} drawn at {wobble}, seed {seed}");
                assert_eq!(r.structure, Structure::Lattice, "{what}");
                let c: Vec<Point> = r.strokes.iter().map(Stroke::reference_point).collect();
                // The output's line by least squares (y on x: the row is level).
                let n = c.len() as f64;
                let (mx, my) = (c.iter().map(|p| p.x).sum::<f64>() / n, c.iter().map(|p| p.y).sum::<f64>() / n);
                let slope = c.iter().map(|p| (p.x - mx) * (p.y - my)).sum::<f64>()
                    / c.iter().map(|p| (p.x - mx).powi(2)).sum::<f64>();
                assert!(
                    slope.atan().to_degrees().abs() < 3.0,
                    "{what}: the row turns by {:.2} degrees",
                    slope.atan().to_degrees()
                );
                for p in &c {
                    let off = p.y - (my + slope * (p.x - mx));
                    assert!(off.abs() < 0.3 * q.step, "{what}: a line {off:.2} off the row at {p:?}");
                }
                let mut xs: Vec<f64> = c.iter().map(|p| p.x).collect();
                xs.sort_by(f64::total_cmp);
                for w in xs.windows(2) {
                    assert!((0.5 * q.step..=1.5 * q.step).contains(&(w[1] - w[0])), "{what}: gap {:?}", w);
                }
                assert!(
                    xs[0] < 2.0 * q.step && xs[xs.len() - 1] > W - 2.0 * q.step,
                    "{what}: {:?}",
                    (xs[0], xs.last())
                );
            }
        }
    }
}

/// Rings of 5-12 petals drawn whole, each petal begun at a random point of its outline
/// and read backwards one time in two (1% and 3%, seeds 1-5), synthesize as rings, as
/// they do begun alike (a new user's check: 43 of 100 did; leaves on an arc so begun
/// still come out irregular in some seeds).
#[test]
fn rings_of_loops_begun_anywhere_synthesize_as_rings() {
    use patternsynth::vector::sequences::begun_at;
    for wobble in [0.01, 0.03] {
        for seed in 1..=5 {
            let mut rng = patternsynth::rng::Rng::new(seed + 40);
            for q in sequences(wobble, seed).into_iter().filter(|q| q.name.starts_with("ring")) {
                let strokes: Vec<Stroke> =
                    q.strokes.iter().map(|s| begun_at(s, rng.below(24), rng.below(2) == 1)).collect();
                assert_eq!(synth(&strokes).structure, Structure::Ring, "{} at {wobble}, seed {seed}", q.name);
            }
        }
    }
}

/// Rings of motifs of several strokes (issue 27: petals drawn as two mirrored arcs
/// became a scatter of arcs), three copies drawn at 1% of the step and four at 3% (a
/// petal with a vein, three drawn at 3%, seed 3: its first copy's turn onto the second
/// is 6 degrees off the others', and no ring is read), seeds 1-3
/// (`sequences::composite`): synthesized as rings, each rosette wholly inside the output
/// holding every stroke of every copy (its strokes counted by where they begin: each
/// petal's begins at its ring's centre), and none stacked.
#[test]
fn rings_of_motifs_of_several_strokes_become_rosettes() {
    for wobble in [0.01, 0.03] {
        for seed in 1..=3 {
            for q in patternsynth::vector::sequences::composite(
                wobble,
                patternsynth::vector::sequences::HandTurn::STEADY,
                seed,
            )
            .into_iter()
            .filter(|q| q.name.starts_with("ring"))
            {
                let n: usize = q.name.split(' ').nth(2).unwrap().parse().unwrap();
                let drawn = if wobble < 0.02 { 3 } else { 4 };
                let r = synth(&q.strokes[..drawn * q.parts]);
                let what = format!("{} at {wobble}, seed {seed}", q.name);
                assert_eq!(r.structure, Structure::Ring, "{what}");
                if std::env::var("DUMP").is_ok() {
                    let lines: String = r
                        .strokes
                        .iter()
                        .map(|s| {
                            let p: Vec<String> = s.points.iter().map(|p| format!("{:.1},{:.1}", p[0], p[1])).collect();
                            format!("<polyline points='{}' fill='none' stroke='black'/>", p.join(" "))
                        })
                        .collect();
                    let svg = format!("<svg xmlns='http://www.w3.org/2000/svg' width='800' height='600'>{lines}</svg>");
                    std::fs::write(format!("/tmp/{}-{seed}-{wobble}.svg", q.name.replace(' ', "-")), svg).unwrap();
                }
                // Strokes grouped by where they begin, near a ring's centre (a vein
                // begins part way out and a dot at the tip: each only counted with its
                // petal, below).
                let len = q.step / (std::f64::consts::PI / n as f64).sin();
                let size = |s: &Stroke| s.bounds().size().to_vec2().hypot();
                let mut centres: Vec<(Point, usize)> = Vec::new();
                for s in r.strokes.iter().filter(|s| size(s) >= 10.0 && (s.points.len() > 13 || q.parts == 3)) {
                    let p = Point::new(s.points[0][0], s.points[0][1]);
                    match centres.iter_mut().find(|(c, _)| c.distance(p) < 0.25 * len) {
                        Some((_, k)) => *k += 1,
                        None => centres.push((p, 1)),
                    }
                }
                let inside = Rect::new(0.0, 0.0, W, H).inset(-1.2 * len);
                let whole: Vec<usize> = centres.iter().filter(|(c, _)| inside.contains(*c)).map(|(_, k)| *k).collect();
                assert!(!whole.is_empty(), "{what}: no rosette inside the output");
                // (Of a petal and its vein or its dot, the petal begins at the centre: one
                // a copy.)
                let per_ring = if q.name.contains("veined") || q.name.contains("dot") { n } else { n * q.parts };
                if q.name.contains("dot") {
                    // (The ring completed holds every dot; the rosettes repeated over the
                    // output may lose some: see the closing note of issue 27.)
                    let drawn = &q.strokes[..drawn * q.parts];
                    let ring = patternsynth::vector::chain::find(drawn).expect("a ring");
                    let done: Vec<Stroke> =
                        drawn.iter().cloned().chain(ring.complete(drawn, None).into_iter().map(|c| c.0)).collect();
                    let petals = done.iter().filter(|s| size(s) >= 10.0).count();
                    assert_eq!(
                        (petals, done.len() - petals),
                        (n, n),
                        "{what}: the ring completed, its petals and dots"
                    );
                }
                assert!(whole.iter().all(|&k| k == per_ring), "{what}: rosettes of {whole:?} strokes, want {per_ring}");
            }
        }
    }
}

/// A whole ring of veined petals, one drawn without its vein: every petal of every
/// rosette has its vein (the veins' run wrapped round the missing one, and every vein
/// was lost: petals alone).
#[test]
fn a_ring_drawn_with_one_vein_missing_gets_every_vein() {
    // (The whole ring, the third's vein left out; three or four petals, the second's:
    // its veins, every other petal's, made no run, and four petals of six were bare.)
    for (seed, copies, bare_one) in (1..=3).flat_map(|s| [(s, 6, 2), (s, 3, 1), (s, 4, 1)]) {
        let q =
            patternsynth::vector::sequences::composite(0.01, patternsynth::vector::sequences::HandTurn::STEADY, seed)
                .into_iter()
                .find(|q| q.name == "ring of 6 veined petals")
                .unwrap();
        // (Each copy a petal, then its vein.)
        let drawn: Vec<Stroke> = q.strokes[..2 * copies]
            .iter()
            .enumerate()
            .filter(|&(i, _)| i != 2 * bare_one + 1)
            .map(|(_, s)| s.clone())
            .collect();
        let r = synth(&drawn);
        assert_eq!(r.structure, Structure::Ring, "seed {seed}");
        let closed = |s: &Stroke| {
            let (a, b) = (s.points[0], s.points[s.points.len() - 1]);
            (a[0] - b[0]).hypot(a[1] - b[1]) < 5.0
        };
        // (Each petal wholly inside the output, with a vein through its middle.)
        let inside = Rect::new(0.0, 0.0, W, H);
        let petals: Vec<&Stroke> = r.strokes.iter().filter(|s| closed(s) && inside.contains_rect(s.bounds())).collect();
        let bare = petals
            .iter()
            .filter(|p| {
                !r.strokes.iter().any(|v| !closed(v) && v.reference_point().distance(p.reference_point()) < 8.0)
            })
            .count();
        assert!(
            petals.len() >= 12 && bare == 0,
            "seed {seed}, {copies} drawn: {bare} of {} petals without a vein",
            petals.len()
        );
    }
}

/// `maxElements` below what a curve needs is an error, as for a lattice, not the
/// drawing returned as though nothing followed (a new user's trial: a limit under the
/// strokes drawn gave back the drawn strokes, and no word).
#[test]
fn a_curve_past_max_elements_is_an_error() {
    let q = family(0.01, 1, "leaves on an arc");
    let opts = |max| StrokeOptions { width: W, height: H, max_elements: max, ..Default::default() };
    let whole = synthesize_strokes(&q.strokes[..4], &opts(500_000), &mut Silent).unwrap();
    let n = whole.strokes.len();
    assert!(n > 8 && whole.structure == Structure::Curve, "{n} strokes, {:?}", whole.structure);
    for max in [2, 5, n - 1] {
        let e = synthesize_strokes(&q.strokes[..4], &opts(max), &mut Silent).map(|r| r.strokes.len());
        let said = format!("{e:?}");
        assert!(said.contains(&format!("the limit is {max}")), "maxElements {max}: {said}");
    }
    let exact = synthesize_strokes(&q.strokes[..4], &opts(n), &mut Silent).unwrap();
    assert_eq!(exact.strokes.len(), n);
}

/// A dot tapped with the pen (three to six points within two pixels: a shape of noise)
/// goes with its petal or leaf as a drawn circle does: the ring completed holds a dot
/// per petal, and the leaves continued along an arc hold a dot per leaf.
#[test]
fn pen_tapped_dots_go_with_their_copies() {
    let taps = patternsynth::vector::sequences::pen_taps;
    let hand = patternsynth::vector::sequences::HandTurn::STEADY;
    for seed in 1..=3 {
        let all = patternsynth::vector::sequences::composite(0.01, hand, seed);
        let ring = all.iter().find(|q| q.name == "ring of 8 petals with a dot").unwrap();
        let drawn = taps(&ring.strokes[..3 * ring.parts], seed);
        let chain = patternsynth::vector::chain::find(&drawn).expect("a ring");
        let done: Vec<Stroke> =
            drawn.iter().cloned().chain(chain.complete(&drawn, None).into_iter().map(|c| c.0)).collect();
        let dots = done.iter().filter(|s| s.is_dot()).count();
        assert_eq!((done.len() - dots, dots), (8, 8), "seed {seed}: the ring completed, its petals and dots");
        let arc = all.iter().find(|q| q.name == "leaves with a dot on an arc").unwrap();
        let r = synth(&taps(&arc.strokes[..4 * arc.parts], seed));
        let dots = r.strokes.iter().filter(|s| s.is_dot()).count();
        assert_eq!(r.structure, Structure::Curve, "seed {seed}");
        assert!(
            dots + 1 >= r.strokes.len() - dots && r.strokes.len() > 12,
            "seed {seed}: {} leaves, {dots} dots",
            r.strokes.len() - dots
        );
    }
}

#[test]
fn leaves_on_a_tight_arc_are_not_read_as_a_fine_lattice() {
    // Four to six leaves 40 long on arcs of radius 150-200, 55 apart, leaning 50 degrees
    // off the arc's normal, each with a dot at its tip or none; each copy off its place
    // by 3% of the step and turned 2.5 degrees at random (a person's hand). A few places
    // on a tight arc fit a lattice finer than the leaves (periods of 26 and 61 beside a
    // spacing of 62, in a trial): grown, it laid 654 overlapping leaves where the arc
    // should have continued, as a curve or a closed ring.
    use patternsynth::rng::Rng;
    use patternsynth::vector::sequences::{leaf, pen_taps};
    let (len, spacing) = (40.0, 55.0);
    let mut lattices = Vec::new();
    let mut runs = 0;
    for dots in [false, true] {
        for radius in [150.0, 175.0, 200.0] {
            for copies in 4..=6 {
                for seed in 1..=8 {
                    let mut rng = Rng::new(seed * 31 + copies);
                    let (start, turn) = (rng.next_f64() * TAU, spacing / radius);
                    let centre = Point::new(400.0, 300.0);
                    let mut drawn = Vec::new();
                    for k in 0..copies {
                        let phi = start + k as f64 * turn;
                        let at = centre
                            + Vec2::new(phi.cos(), phi.sin()) * radius
                            + Vec2::new(rng.normal(), rng.normal()) * (0.03 * spacing);
                        let theta = phi + 50f64.to_radians() + rng.normal() * 2.5f64.to_radians();
                        drawn.push(leaf(at, theta, len, &mut rng, 0.006 * spacing));
                        if dots {
                            let tip = at + Vec2::new(theta.cos(), theta.sin()) * len;
                            drawn.push(Stroke::new(vec![[tip.x, tip.y]], 3.0, None));
                        }
                    }
                    let r = synth(&pen_taps(&drawn, seed));
                    runs += 1;
                    if r.structure == Structure::Lattice {
                        lattices.push(format!(
                            "dots {dots}, radius {radius}, {copies} copies, seed {seed}: {} strokes",
                            r.strokes.len()
                        ));
                    }
                }
            }
        }
    }
    assert!(lattices.is_empty(), "{} of {runs}: {lattices:#?}", lattices.len());
}

/// A stem drawn once and three leaves touching it (issue 27, "a stem and three
/// leaves"), a person's hand at 3% (`sequences::along_drawn`): synthesized, leaves go
/// all along the drawn stem, both ways, each beginning on it (within a fifth of the
/// step, the median within 5%: the hand puts its own leaves 3% of the step off;
/// measured: median 0.8, 95% within 3.5, at most 6.2 of a step of 40, the most on the
/// tight stem's bends, of radius 32) and a leaf's gap on from
/// the last, and the result says it followed a curve (from these three leaves alone a
/// chain went off the stem in a spiral).
#[test]
fn leaves_drawn_on_a_stem_go_all_along_it() {
    use patternsynth::vector::sequences::{along_drawn, HandTurn};
    let (mut offsets, mut step) = (Vec::new(), 0.0);
    for seed in 1..=3 {
        let stems = ["wavy stem", "curly stem", "tight stem", "Bézier S"];
        for name in stems.map(|s| format!("leaves on a drawn {s}")) {
            let q = along_drawn(0.03, HandTurn::PERSON, seed).into_iter().find(|q| q.name == name).unwrap();
            step = q.step;
            // The stem and the first three leaves (of sixteen the stem carries).
            let r = synth(&q.strokes[..4]);
            assert_eq!(r.structure, Structure::Curve, "{name}");
            // (The vine continued is the first copy; where the output holds it twice it
            // repeats, a stem a copy: see the next test.)
            let copies = r.sources.iter().filter(|&&s| s == 0).count();
            let r = StrokeResult { strokes: r.strokes[..r.strokes.len() / copies].to_vec(), ..r };
            let stem: Vec<Point> = r.strokes[0].points.iter().map(|p| Point::new(p[0], p[1])).collect();
            let off = |p: Point| {
                stem.windows(2)
                    .map(|w| {
                        let (d, e) = (w[1] - w[0], p - w[0]);
                        (e - d * (e.dot(d) / d.hypot2()).clamp(0.0, 1.0)).hypot()
                    })
                    .fold(f64::INFINITY, f64::min)
            };
            let leaves = &r.strokes[1..];
            assert!(leaves.len() >= 14, "{name}, seed {seed}: {} leaves", leaves.len());
            for l in leaves {
                let base = Point::new(l.points[0][0], l.points[0][1]);
                assert!(off(base) < 0.2 * q.step, "{name}, seed {seed}: a leaf begins {:.1} off the stem", off(base));
                offsets.push(off(base));
            }
            // Each leaf a gap from its nearest neighbour: none stacked, none left out.
            let bases: Vec<Point> = leaves.iter().map(|l| Point::new(l.points[0][0], l.points[0][1])).collect();
            for (i, b) in bases.iter().enumerate() {
                let near = bases
                    .iter()
                    .enumerate()
                    .filter(|&(j, _)| j != i)
                    .map(|(_, c)| b.distance(*c))
                    .fold(f64::INFINITY, f64::min);
                assert!(
                    (0.6 * q.step..1.3 * q.step).contains(&near),
                    "{name}, seed {seed}: a leaf {near:.1} from the next"
                );
            }
        }
    }
    // (Over all: the median leaf begins within 5% of the step of the stem; measured 2%.)
    offsets.sort_by(f64::total_cmp);
    let median = offsets[offsets.len() / 2];
    assert!(median < 0.05 * step, "the median leaf begins {median:.1} off the stem");
}

/// Leaves drawn on a stem across the drawing canvas (a new user's trial, in
/// tests/fixtures/curves: leaves on a drawn arc and on a drawn S; and the generator's
/// drawn stems, from a stem and three leaves), synthesized at the page's default output
/// of 1200 x 800: the vine, continued, repeats over the output, at least three copies,
/// each whole (its stem and every leaf), no copy's box over another's, and no quarter
/// of the output left bare. (Each was laid once in the middle of the output.)
#[test]
fn a_vine_repeats_over_a_large_output() {
    use patternsynth::vector::sequences::{along_drawn, HandTurn};
    let page = StrokeOptions { width: 1200.0, height: 800.0, ..Default::default() };
    let mut drawings: Vec<(String, Vec<Stroke>)> = ["leaves_on_a_drawn_arc", "leaves_on_a_drawn_s_curve"]
        .iter()
        .map(|name| {
            let path = format!("{}/tests/fixtures/curves/{name}.json", env!("CARGO_MANIFEST_DIR"));
            (name.to_string(), serde_json::from_str(&std::fs::read_to_string(path).unwrap()).unwrap())
        })
        .collect();
    for seed in 1..=2 {
        for q in
            along_drawn(0.03, HandTurn::PERSON, seed).into_iter().filter(|q| q.name.starts_with("leaves on a drawn"))
        {
            drawings.push((format!("{}, seed {seed}", q.name), q.strokes[..4].to_vec()));
        }
    }
    for (name, drawn) in &drawings {
        let r = synthesize_strokes(drawn, &page, &mut Silent).unwrap();
        assert_eq!(r.structure, Structure::Curve, "{name}");
        // The stem is the first stroke drawn: one a copy.
        let copies = r.sources.iter().filter(|&&s| s == 0).count();
        let n = r.strokes.len() / copies;
        assert!(copies >= 3 && n * copies == r.strokes.len(), "{name}: {} strokes, {copies} stems", r.strokes.len());
        let boxes: Vec<Rect> =
            r.strokes.chunks(n).map(|c| c.iter().skip(1).fold(c[0].bounds(), |b, s| b.union(s.bounds()))).collect();
        for (k, chunk) in r.sources.chunks(n).enumerate() {
            assert_eq!(chunk, &r.sources[..n], "{name}: copy {k} is not the whole vine");
        }
        // Copies side by side in rows: the periods reported, and each copy a whole
        // number of them from the first.
        let [a, b] = r.periods.unwrap_or_else(|| panic!("{name}: no periods reported"));
        let det = a[0] * b[1] - a[1] * b[0];
        for c in r.strokes.chunks(n) {
            let v = c[0].reference_point() - r.strokes[0].reference_point();
            let (k, l) = ((v.x * b[1] - v.y * b[0]) / det, (a[0] * v.y - a[1] * v.x) / det);
            assert!((k - k.round()).abs() < 1e-6 && (l - l.round()).abs() < 1e-6, "{name}: a copy off the periods");
        }
        for (i, a) in boxes.iter().enumerate() {
            for b in &boxes[i + 1..] {
                let apart = (a.x0 - b.x1).max(b.x0 - a.x1).max((a.y0 - b.y1).max(b.y0 - a.y1));
                assert!(apart > 0.0, "{name}: two copies overlap ({a:?}, {b:?})");
            }
        }
        for (x, y) in [(0.0, 0.0), (600.0, 0.0), (0.0, 400.0), (600.0, 400.0)] {
            let quarter = Rect::new(x, y, x + 600.0, y + 400.0);
            let held = r.strokes.iter().flat_map(|s| &s.points).any(|p| quarter.contains(Point::new(p[0], p[1])));
            assert!(held, "{name}: the quarter at ({x}, {y}) is bare");
        }
        eprintln!("{name}: {copies} copies of {n} strokes, periods {:?}", r.periods);
    }
}

/// Rings as a new user drew them (a helper's trial): petals 90 long and 50 wide, each
/// begun anywhere and drawn either way round, turned up to 4 degrees off its place, its
/// 30 points each shaken by 2.7 (a finger, a shaky mouse). Resampled as drawn, the
/// shaking paired unlike points: two petals of a ring of six read steps of 76 and 57
/// degrees, and rings of 6 and 9 from three or four petals synthesized as a scatter.
/// The paths are steadied first now (`similarity::steadied`). Rings of 6, 8 and 9 from
/// four petals, seeds 1-20: 40 of 60 found with their count (26 unsteadied), 10 with
/// another (12): a ring of 8 and one of 9 step 5 degrees apart, and four petals each
/// turned up to 4 degrees at random do not always tell them apart.
#[test]
fn rings_drawn_with_a_shaky_pointer_are_found() {
    let petal = |theta: f64, rng: &mut patternsynth::rng::Rng| {
        let start = rng.next_f64();
        let backwards = rng.next_f64() < 0.5;
        let turn = theta + (8.0 * rng.next_f64() - 4.0).to_radians();
        let (c, s) = (turn.cos(), turn.sin());
        let mut pts: Vec<[f64; 2]> = (0..29)
            .map(|k| {
                let t = TAU * (start + k as f64 / 29.0);
                let (x, y) = (60.0 + 45.0 * t.cos(), 25.0 * t.sin());
                [400.0 + x * c - y * s + 2.7 * rng.normal(), 300.0 + x * s + y * c + 2.7 * rng.normal()]
            })
            .collect();
        pts.push(pts[0]);
        if backwards {
            pts.reverse();
        }
        Stroke::new(pts, 3.0, None)
    };
    let (mut right, mut wrong, mut tried) = (0, 0, 0);
    for n in [6usize, 8, 9] {
        for seed in 1..=20u64 {
            let mut rng = patternsynth::rng::Rng::new(seed * 17 + n as u64);
            let drawn: Vec<Stroke> = (0..4).map(|k| petal(k as f64 * TAU / n as f64, &mut rng)).collect();
            tried += 1;
            match patternsynth::vector::chain::find(&drawn).and_then(|c| c.closes) {
                Some(k) if k == n => right += 1,
                Some(_) => wrong += 1,
                None => {}
            }
        }
    }
    eprintln!("shaky rings from four petals: {right} right, {wrong} wrong of {tried}");
    assert!(right >= 36 && wrong <= 12, "{right} right, {wrong} wrong of {tried}");
}

/// Two flowers drawn side by side, one whole and one begun with three petals, of
/// another petal count or of the same (1% and 3%, seeds 1-3): synthesis returned the
/// drawing as it was, the second flower unfinished (a new user's trial: 8 of 8 such
/// drawings). Each ring is completed and the two repeat together over the output: every
/// rosette wholly inside it holds its ring's petals, one a slot, and each flower is
/// laid at least three times.
#[test]
fn two_flowers_drawn_side_by_side_each_complete_and_repeat() {
    for wobble in [0.01, 0.03] {
        for seed in 1..=3 {
            for (first, second) in [(8usize, 5usize), (8, 8), (5, 12)] {
                two_flowers(first, second, 3, wobble, seed);
            }
        }
    }
}

/// The same flower drawn twice, the second begun with all but two petals or half of
/// them and one more (1% and 3%, seeds 1-3). A flower of an even count is its own copy
/// turned half round, so the half turn about the point between the two flowers carried
/// more petals onto petals than the ring's step did; it makes no chain, and a new
/// user's drawing came back as it was (6 of 10 seeds of six and four petals). Both
/// flowers are completed and repeat.
#[test]
fn the_same_flower_twice_the_second_begun_completes_both() {
    for wobble in [0.01, 0.03] {
        for seed in 1..=3 {
            for (n, drawn) in [(6usize, 4usize), (8, 6), (8, 5), (10, 6), (12, 10), (5, 3)] {
                two_flowers(n, n, drawn, wobble, seed);
            }
        }
    }
}

/// A ring of `first` drawn whole, and `drawn` petals of a ring of `second` (of the
/// same family, other noise) a flower's width to its right: the synthesis is a ring
/// structure, the flowers repeat spaced as drawn, and each is whole, one petal a slot,
/// and laid at least three times.
fn two_flowers(first: usize, second: usize, drawn: usize, wobble: f64, seed: u64) {
    let bounds = |s: &[Stroke]| s.iter().skip(1).fold(s[0].bounds(), |r, t| r.union(t.bounds()));
    let a = family(wobble, seed, &format!("ring of {first}")).strokes;
    let b = family(wobble, seed + 10, &format!("ring of {second}")).strokes;
    let (ra, rb) = (bounds(&a), bounds(&b[..]));
    let v = Vec2::new(ra.x1 + 0.5 * ra.width() - rb.x0, ra.center().y - rb.center().y);
    let strokes: Vec<Stroke> = a.iter().cloned().chain(b[..drawn].iter().map(|s| s.translated(v.x, v.y))).collect();
    let r = synth(&strokes);
    let what = format!("rings of {first} and {second} ({drawn} drawn), wobble {wobble}, seed {seed}");
    assert_eq!(r.structure, Structure::Ring, "{what}");
    // Spaced as drawn: each copy of the drawing at least its width and the drawn gap
    // (half the first flower's width) from the next in its row.
    let [p, _] = r.periods.expect("the flowers repeat on a lattice");
    let wide = bounds(&strokes).width() + 0.5 * ra.width();
    assert!(p[0].hypot(p[1]) >= 0.95 * wide, "{what}: copies {p:?} apart, drawn {wide:.0}");
    for (n, ours) in [(first, 0..first), (second, first..first + drawn)] {
        let mut one = r.clone();
        let keep: Vec<bool> = r.sources.iter().map(|&s| ours.contains(&(s as usize))).collect();
        let mut k = keep.iter();
        one.strokes.retain(|_| *k.next().unwrap());
        let (checked, _, bad) = rosettes(&one, n, 90.0);
        assert!(checked >= 1, "{what}: no whole ring of {n} inside the output");
        assert_eq!(bad, 0, "{what}: rings of {n} with petals missing or stacked");
        assert!(one.strokes.len() >= 3 * n, "{what}: {} petals of the ring of {n}", one.strokes.len());
    }
}

/// A flower with a long stem from its centre (rings of 5 and 8, drawn whole or with
/// three petals, 1% and 3%, seeds 1-3): the drawing is one cluster, with no drawn gap
/// to keep, and repeats packed as a rosette does. The gap was taken as the output's
/// side, and a new user's clover with its stem was laid once.
#[test]
fn a_flower_with_a_long_stem_repeats_packed() {
    let bounds = |s: &[Stroke]| s.iter().skip(1).fold(s[0].bounds(), |r, t| r.union(t.bounds()));
    for wobble in [0.01, 0.03] {
        for seed in 1..=3 {
            for (n, drawn) in [(5usize, 5usize), (5, 3), (8, 8), (8, 3)] {
                let petals = family(wobble, seed, &format!("ring of {n}")).strokes;
                let reach = bounds(&petals).width().max(bounds(&petals).height()) / 2.0;
                let c = petals[0].points[0];
                let stem: Vec<[f64; 2]> = (0..=20)
                    .map(|k| [c[0] + 3.0 * (k as f64 * 0.7).sin(), c[1] + 2.2 * reach * k as f64 / 20.0])
                    .collect();
                let stem = Stroke::new(stem, petals[0].width, None);
                let whole = bounds(&petals).union(stem.bounds());
                let strokes: Vec<Stroke> = petals[..drawn].iter().cloned().chain([stem]).collect();
                let what = format!("a ring of {n} ({drawn} drawn) with a stem, wobble {wobble}, seed {seed}");
                let r = synth(&strokes);
                assert_eq!(r.structure, Structure::Ring, "{what}");
                let [a, b] = r.periods.expect("the flower repeats on a lattice");
                assert!(
                    a[0].hypot(a[1]) <= 1.5 * whole.width() && b[1].abs() <= 1.5 * whole.height(),
                    "{what}: periods {a:?} {b:?}"
                );
                let stems = r.sources.iter().filter(|&&s| s as usize == drawn).count();
                assert!(stems >= 6, "{what}: the flower laid {stems} times");
                let mut petals_out = r.clone();
                let mut stem_of = r.sources.iter().map(|&s| s as usize == drawn);
                petals_out.strokes.retain(|_| !stem_of.next().unwrap());
                let (checked, _, bad) = rosettes(&petals_out, n, 90.0);
                assert!(checked >= 1 && bad == 0, "{what}: {checked} rosettes inside, {bad} not whole");
            }
        }
    }
}

/// Ellipses round a centre (a four-leaf clover, a daisy), drawn whole or three of them,
/// each begun anywhere, shaken by 1.5 and turned up to 3 degrees off its place (seeds
/// 1-10): each ring is read with its count and synthesizes as rosettes. An ellipse
/// fits its neighbour turned either way round, and with the smaller turn alone four
/// ellipses read turns of 90 and -90 degrees by the hand's noise: 4 of a new user's 7
/// such drawings came out a scatter, a lattice or the drawing as it was.
#[test]
fn ellipses_round_a_centre_make_rings() {
    let petal = |theta: f64, rng: &mut patternsynth::rng::Rng| {
        let start = rng.next_f64();
        let turn = theta + (6.0 * rng.next_f64() - 3.0).to_radians();
        let (c, s) = (turn.cos(), turn.sin());
        let mut pts: Vec<[f64; 2]> = (0..32)
            .map(|k| {
                let t = TAU * (start + k as f64 / 32.0);
                let (x, y) = (55.0 + 40.0 * t.cos(), 18.0 * t.sin());
                [400.0 + x * c - y * s + 1.5 * rng.normal(), 300.0 + x * s + y * c + 1.5 * rng.normal()]
            })
            .collect();
        pts.push(pts[0]);
        Stroke::new(pts, 3.0, None)
    };
    let (mut right, mut tried) = (0, 0);
    for n in [4usize, 6, 9] {
        for drawn in [3, n] {
            for seed in 1..=10u64 {
                let mut rng = patternsynth::rng::Rng::new(seed * 31 + n as u64);
                let strokes: Vec<Stroke> = (0..drawn).map(|k| petal(k as f64 * TAU / n as f64, &mut rng)).collect();
                let what = format!("{drawn} ellipses of a ring of {n}, seed {seed}");
                tried += 1;
                let read = patternsynth::vector::chain::find(&strokes).and_then(|c| c.closes);
                if read == Some(n) {
                    right += 1;
                    let r = synth(&strokes);
                    assert_eq!(r.structure, Structure::Ring, "{what}");
                    assert!(r.strokes.len() >= 4 * n, "{what}: {} strokes", r.strokes.len());
                } else {
                    eprintln!("{what}: read {read:?}");
                }
            }
        }
    }
    eprintln!("ellipse rings: {right} of {tried} read with their count");
    assert!(right >= 54, "{right} of {tried} read with their count");
}

/// Fence posts along an arc, upright (issue 27: "a row of fence posts along an arc ...
/// synthesis turns them into a scatter"): six posts drawn on arcs of radius 200 and
/// 400 at 1% of the step, and 200 at 3%, seeds 1-3, continue round the arc as a curve
/// (`chain::find_upright`; before, Irregular or a straight row), every post upright as
/// drawn, and each on the arc: its middle's distance from the arc's centre off the
/// radius. Measured: median 0.012-0.073 of the step, 95th percentile 0.05-0.21 at 1%;
/// 0.03-0.11 and 0.06-0.35 at 3% (the circle read from six places over a sixth of it
/// errs, and the far side of the circle twice as much). At 3% on the wider arc (a turn
/// of 0.1 radian a step against the hand's scatter of about 0.07), six posts may read
/// as a straight row.
#[test]
fn upright_posts_along_an_arc_continue_round_it() {
    use patternsynth::vector::sequences::posts;
    for (jitter, radii, median_max, p95_max) in
        [(0.01, &[200.0, 400.0][..], 0.08, 0.25), (0.03, &[200.0][..], 0.12, 0.4)]
    {
        for &radius in radii {
            for seed in 1..=3 {
                let (strokes, _) = posts(radius, 40.0, true, jitter, seed);
                let drawn = &strokes[..6];
                let r = synth(drawn);
                let what = format!("radius {radius}, jitter {jitter}, seed {seed}");
                assert_eq!(r.structure, Structure::Curve, "{what}");
                assert!(r.strokes.len() >= 12, "{what}: {} posts", r.strokes.len());
                // The drawn posts come first, moved as a whole; the arc's centre with
                // them (the posts' middles lie 20 above their feet).
                let v = Point::new(r.strokes[0].points[0][0], r.strokes[0].points[0][1])
                    - Point::new(drawn[0].points[0][0], drawn[0].points[0][1]);
                let centre = Point::new(400.0, 250.0 + radius - 20.0) + v;
                let mut off: Vec<f64> = Vec::new();
                for s in &r.strokes {
                    let (p, q) = (s.points[0], s.points[s.points.len() - 1]);
                    let lean = (q[0] - p[0]).atan2((q[1] - p[1]).abs()).abs();
                    assert!(lean < 8f64.to_radians(), "{what}: a post leans {:.1} degrees", lean.to_degrees());
                    // (Copies of the whole arc beside it, where the output holds them,
                    // are measured against their own: the nearest of the arc moved by
                    // whole periods.)
                    let c = s.reference_point();
                    let shifts = r.periods.map_or(vec![Vec2::ZERO], |[a, b]| {
                        (-3..=3)
                            .flat_map(|i| {
                                (-3..=3).map(move |j| {
                                    Vec2::new(i as f64 * a[0] + j as f64 * b[0], i as f64 * a[1] + j as f64 * b[1])
                                })
                            })
                            .collect()
                    });
                    let d = shifts
                        .iter()
                        .map(|&w| ((c - (centre + w)).hypot() - radius).abs())
                        .fold(f64::INFINITY, f64::min);
                    off.push(d / 40.0);
                }
                let (median, p95) = (quantile(&mut off.clone(), 0.5), quantile(&mut off, 0.95));
                eprintln!("{what}: {} posts, off the arc median {median:.3}, p95 {p95:.3}", r.strokes.len());
                assert!(median <= median_max && p95 <= p95_max, "{what}: off the arc median {median:.3}, p95 {p95:.3}");
            }
        }
    }
}

/// The drawing synthesized over an output just large enough for it and a few steps
/// round it (which holds it once: it is continued, not repeated).
fn synth_alone(strokes: &[Stroke], margin: f64) -> StrokeResult {
    let b = strokes.iter().skip(1).fold(strokes[0].bounds(), |r, s| r.union(s.bounds()));
    let opts = StrokeOptions { width: b.width() + margin, height: b.height() + margin, ..Default::default() };
    synthesize_strokes(strokes, &opts, &mut Silent).unwrap()
}

fn centre_of(s: &Stroke) -> Point {
    let n = s.points.len() as f64;
    let v = s.points.iter().fold(Vec2::ZERO, |m, p| m + Vec2::new(p[0], p[1]));
    (v / n).to_point()
}

/// Leaves drawn along a wave with no stem (a new user's: grown, they were a scatter of
/// leaves in rows, `Irregular`), with the default options: a curve, its drawn leaves
/// kept, and carried on past each end by its end's own step, each leaf past them where
/// the wave puts its next (the generator's leaves before and after the drawn ones).
#[test]
fn leaves_along_a_wave_with_no_stem_go_on_along_it() {
    use patternsynth::vector::sequences::{drawn_by, HandTurn};
    let mut offs: Vec<f64> = Vec::new();
    for hand in [HandTurn::STEADY, HandTurn::PERSON] {
        for seed in 1..=3 {
            // (From five, a turn alike at every step carries the leaves within a hand's
            // scatter: they are an arc's, `leaves_on_an_arc_continue_along_it`.)
            for drawn in [6, 7, 8] {
                let q = drawn_by(0.03, hand, seed).into_iter().find(|q| q.name == "leaves on a wavy stem").unwrap();
                let mine = &q.strokes[2..2 + drawn];
                let what = format!("{drawn} leaves, hand {:.3}, seed {seed}", hand.0);
                let r = synth_alone(mine, 6.0 * q.step);
                assert_eq!(r.structure, Structure::Curve, "{what}");
                let v = centre_of(&r.strokes[0]) - centre_of(&mine[0]);
                for (s, d) in r.strokes.iter().zip(mine) {
                    assert!((centre_of(s) - (centre_of(d) + v)).hypot() < 1e-6, "{what}: a drawn leaf moved");
                }
                // (Where the output holds the curve twice it repeats it, each copy the
                // curve moved: the first, the drawing's own, is the sources' period.)
                let n = r.strokes.len();
                let copy = (1..=n).find(|&p| n % p == 0 && (p..n).all(|i| r.sources[i] == r.sources[i % p])).unwrap();
                let more = &r.strokes[drawn..copy];
                assert!(more.len() >= 2, "{what}: {} leaves added", more.len());
                // The truth past the drawn ones: the two before, and those after.
                let truth: Vec<Point> = q.strokes[..2]
                    .iter()
                    .chain(&q.strokes[2 + drawn..])
                    .chain(q.beyond.iter().map(|b| &b.0))
                    .map(|s| centre_of(s) + v)
                    .collect();
                for s in more {
                    let c = centre_of(s);
                    let off = truth.iter().map(|t| t.distance(c)).fold(f64::INFINITY, f64::min) / q.step;
                    // (The next leaf past an end, a step from a drawn one, and those after.)
                    let next = mine.iter().any(|d| (centre_of(d) + v).distance(c) < 1.5 * q.step);
                    let most = if next { 0.35 } else { 0.8 };
                    assert!(off < most, "{what}: a leaf added {off:.2} of the step from the wave's");
                    offs.push(off);
                }
            }
        }
    }
    let (median, p90) = (quantile(&mut offs.clone(), 0.5), quantile(&mut offs, 0.9));
    eprintln!("{} leaves added: off the wave's median {median:.3}, 90th percentile {p90:.3} of the step", offs.len());
    assert!(median < 0.25 && p90 < 0.6, "off the wave's: median {median:.3}, p90 {p90:.3}");
}

/// A stem and three leaves on alternate sides of it (a new user's: the drawing came
/// back as drawn, nothing added), with the default options: leaves all along the stem,
/// each beginning on it, on alternate sides.
#[test]
fn a_stem_and_three_leaves_on_alternate_sides_go_all_along_it() {
    use patternsynth::vector::sequences::{along_drawn, HandTurn};
    for hand in [HandTurn::STEADY, HandTurn::PERSON] {
        for wobble in [0.01, 0.03, 0.05] {
            for seed in 1..=3 {
                let q = along_drawn(wobble, hand, seed)
                    .into_iter()
                    .find(|q| q.name == "leaves alternating on a drawn wavy stem")
                    .unwrap();
                let what = format!("wobble {wobble}, hand {:.3}, seed {seed}", hand.0);
                let r = synth_alone(&q.strokes[..4], 2.0 * q.step);
                assert_eq!(r.structure, Structure::Curve, "{what}");
                let stem: Vec<Point> = r.strokes[0].points.iter().map(|p| Point::new(p[0], p[1])).collect();
                // Each leaf's base: where it begins; its side: which way it points
                // across the stem there.
                let (mut along, mut sides) = (Vec::new(), Vec::new());
                for l in &r.strokes[1..] {
                    let (base, tip) = (Point::new(l.points[0][0], l.points[0][1]), centre_of(l));
                    let (k, off) = stem
                        .windows(2)
                        .enumerate()
                        .map(|(k, w)| {
                            let (d, e) = (w[1] - w[0], base - w[0]);
                            (k, (e - d * (e.dot(d) / d.hypot2()).clamp(0.0, 1.0)).hypot())
                        })
                        .min_by(|x, y| x.1.total_cmp(&y.1))
                        .unwrap();
                    assert!(off < 0.2 * q.step, "{what}: a leaf begins {off:.1} off the stem");
                    along.push(k);
                    sides.push((stem[k + 1] - stem[k]).cross(tip - base) > 0.0);
                }
                // (The generator's stem carries sixteen leaves.)
                assert!(along.len() >= 14, "{what}: {} leaves", along.len());
                let mut order: Vec<usize> = (0..along.len()).collect();
                order.sort_by_key(|&i| along[i]);
                let flips = order.windows(2).filter(|w| sides[w[0]] != sides[w[1]]).count();
                assert_eq!(flips, order.len() - 1, "{what}: leaves not on alternate sides");
            }
        }
    }
}

/// Leaves drawn along waves and S-curves with no stem by a new user's generator
/// (tests/fixtures/curves/trial_*: an S, a strong wave, gentle waves with and without
/// an inflection, small arcs along an S, a gentle arc of ten leaves, an S of leaves
/// each drawn with its midrib), at the page's
/// default output of 1200 x 800. Before: irregular (a scatter, the drawn leaves lost:
/// 1 of 8 kept), a straight row, or a circle closed round from one end. Now each is a
/// curve holding the drawing as drawn, carried on past its ends a step at a time (each
/// added copy a step from its nearest, none on another), and repeated.
#[test]
fn a_new_users_waves_and_s_curves_go_on_as_curves() {
    let page = StrokeOptions { width: 1200.0, height: 800.0, ..Default::default() };
    for name in [
        "trial_s_curve",
        "trial_strong_wave",
        "trial_gentle_wave_inflection",
        "trial_gentle_wave",
        "trial_s_curve_arcs",
        "trial_gentle_arc",
        "trial_s_curve_midribs",
        // (An S of two arcs, whose steps turn one way and then at once the other.)
        "trial_s_of_two_arcs",
        "trial_s_of_two_arcs_leaning",
        "trial_s_two_stroke_leaves",
    ] {
        let path = format!("{}/tests/fixtures/curves/{name}.json", env!("CARGO_MANIFEST_DIR"));
        let drawn: Vec<Stroke> = serde_json::from_str(&std::fs::read_to_string(path).unwrap()).unwrap();
        let r = synthesize_strokes(&drawn, &page, &mut Silent).unwrap();
        assert_eq!(r.structure, Structure::Curve, "{name}");
        let n = r.strokes.len();
        let copy = (1..=n).find(|&p| n % p == 0 && (p..n).all(|i| r.sources[i] == r.sources[i % p])).unwrap();
        assert!(n >= 2 * copy, "{name}: repeated over the output ({n} strokes, {copy} a copy)");
        let v = centre_of(&r.strokes[0]) - centre_of(&drawn[0]);
        for (s, d) in r.strokes.iter().zip(&drawn) {
            assert!((centre_of(s) - (centre_of(d) + v)).hypot() < 1e-6, "{name}: a drawn leaf moved");
        }
        // (Of a motif of several strokes, its copies' largest strokes: the leaves.)
        let big = |s: &Stroke| s.bounds().size().to_vec2().hypot();
        let largest = drawn.iter().map(big).fold(0.0, f64::max);
        let leaf = |s: &Stroke| big(s) > 0.6 * largest;
        let parts = r.strokes[..copy].len() as f64 / r.strokes[..copy].iter().filter(|s| leaf(s)).count() as f64;
        assert_eq!(parts, drawn.len() as f64 / drawn.iter().filter(|s| leaf(s)).count() as f64, "{name}: copies whole");
        let drawn: Vec<Stroke> = drawn.iter().filter(|s| leaf(s)).cloned().collect();
        let first: Vec<&Stroke> = r.strokes[..copy].iter().filter(|s| leaf(s)).collect();
        let copy = first.len();
        let centres: Vec<Point> = first.iter().map(|s| centre_of(s)).collect();
        let nearest = |i: usize| {
            (0..copy).filter(|&j| j != i).map(|j| centres[i].distance(centres[j])).fold(f64::INFINITY, f64::min)
        };
        let mut drawn_gaps: Vec<f64> = (0..drawn.len()).map(nearest).collect();
        let step = quantile(&mut drawn_gaps, 0.5);
        assert!(copy >= drawn.len() + 2, "{name}: {} added", copy - drawn.len());
        for i in drawn.len()..copy {
            let gap = nearest(i) / step;
            assert!((0.6..1.6).contains(&gap), "{name}: an added leaf {gap:.2} of a step from its nearest");
        }
    }
}

/// Four leaves drawn in an S (a new user's, from a trial's own generator), which no step
/// nor lattice reads and which growth adds nothing to: Synthesize gave back the drawing
/// alone on an empty page. The drawing is repeated whole over the output instead, each
/// copy apart from the others.
#[test]
fn a_drawing_too_few_to_grow_from_is_repeated_whole() {
    let page = StrokeOptions { width: 1200.0, height: 800.0, ..Default::default() };
    let path = format!("{}/tests/fixtures/curves/trial_s_four_leaves.json", env!("CARGO_MANIFEST_DIR"));
    let drawn: Vec<Stroke> = serde_json::from_str(&std::fs::read_to_string(path).unwrap()).unwrap();
    let r = synthesize_strokes(&drawn, &page, &mut Silent).unwrap();
    assert_eq!(r.structure, Structure::Irregular);
    let n = drawn.len();
    assert!(r.strokes.len() >= 8 * n, "{} strokes from {n}", r.strokes.len());
    assert_eq!(r.strokes.len() % n, 0, "whole copies");
    // Each copy is the drawing moved, its strokes in order.
    let bounds = |s: &[Stroke]| s.iter().skip(1).fold(s[0].bounds(), |b, t| b.union(t.bounds()));
    let mut boxes = Vec::new();
    for copy in r.strokes.chunks(n) {
        let v = centre_of(&copy[0]) - centre_of(&drawn[0]);
        for (s, d) in copy.iter().zip(&drawn) {
            assert!((centre_of(s) - (centre_of(d) + v)).hypot() < 1e-6, "a copy is the drawing moved");
        }
        boxes.push(bounds(copy));
    }
    // (Copies apart: no two boxes overlap by more than a tenth of one.)
    for (i, a) in boxes.iter().enumerate() {
        for b in &boxes[i + 1..] {
            assert!(a.intersect(*b).area() < 0.1 * a.area(), "copies overlap: {a:?} {b:?}");
        }
    }
}

/// Circles and pen-tapped dots round a centre (helper-55's trial: rings of five to twelve
/// beads synthesized as lattices, scatters or rings, 15 of 36 rings; of dots, none of
/// 36): neither shows a turn, and the ring is read from the places (`chain::by_place`).
/// Rings of 5, 6, 8 and 12 circles, and of pen taps at the circles' centres (each its
/// own, or all alike), at 1% and 3%
/// of the step, seeds 1-3, are rings, no two copies of the output within half a step;
/// and the rosettes of five and eight are whole: every copy two ring radii from the
/// output's edges has two others about a step away (its neighbours round its ring,
/// within 0.3 of the step). (Rosettes of six and twelve pack so closely that a copy of
/// one ring is left out where it would fall on another's.)
#[test]
fn rings_of_circles_and_dots_become_rosettes() {
    use patternsynth::vector::sequences::circle_ring;
    for wobble in [0.01, 0.03] {
        for n in [5usize, 6, 8, 12] {
            for seed in 1..=3 {
                let (radius, size) = (90.0, 12.0);
                let step = 2.0 * radius * (std::f64::consts::PI / n as f64).sin();
                let (circles, _) = circle_ring(n, radius, size, wobble, seed);
                let dots: Vec<Stroke> = circles
                    .iter()
                    .map(|c| {
                        let p = centroid(c);
                        Stroke::new(vec![[p.x, p.y], [p.x + 1.0, p.y]], 4.0, None)
                    })
                    .collect();
                let taps = patternsynth::vector::sequences::pen_taps(&dots, seed);
                // (And taps all alike: a ring completed by accepting ghosts holds exact
                // copies of its drawn taps.)
                let exact: Vec<Stroke> = dots
                    .iter()
                    .map(|d| {
                        let [x, y] = d.points[0];
                        Stroke::new(vec![[x, y], [x + 1.0, y + 0.5], [x + 0.5, y + 1.2]], 4.0, None)
                    })
                    .collect();
                for (what, strokes) in [("circles", circles), ("taps", taps), ("exact taps", exact)] {
                    let r = synth(&strokes);
                    let what = format!("{n} {what} at {wobble}, seed {seed}");
                    assert_eq!(r.structure, Structure::Ring, "{what}");
                    let centres: Vec<Point> = r.strokes.iter().map(centroid).collect();
                    // (A rosette cut by the output's edge keeps only the copies inside it.)
                    let inner = Rect::new(2.0 * radius, 2.0 * radius, W - 2.0 * radius, H - 2.0 * radius);
                    let (mut checked, mut ringed) = (0, 0);
                    for (i, c) in centres.iter().enumerate().filter(|(_, c)| inner.contains(**c)) {
                        let apart: Vec<f64> =
                            centres.iter().enumerate().filter(|&(j, _)| j != i).map(|(_, d)| c.distance(*d)).collect();
                        let near = apart.iter().filter(|&&d| (d - step).abs() <= 0.3 * step).count();
                        assert!(apart.iter().all(|&d| d >= 0.5 * step), "{what}: two copies on one another at {c:?}");
                        checked += 1;
                        ringed += usize::from(near >= 2);
                    }
                    assert!(checked >= n, "{what}: {checked} copies inside");
                    if n == 5 || n == 8 {
                        assert_eq!(ringed, checked, "{what}: copies not between two neighbours");
                    }
                }
            }
        }
    }
}
