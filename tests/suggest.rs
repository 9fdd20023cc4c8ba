//! Autocomplete (issue 10): drawing sessions replayed stroke by stroke through
//! `suggest_strokes`; the figures are in `cargo run --release --example replay_suggest`.
use patternsynth::vector::exemplar::{family_list, freehand_sketch, irregular_dashes};
use patternsynth::vector::replay::replay;
use patternsynth::vector::sequences::{begun_at, circle_grid, composite, drawn_by, posts, HandTurn};
use patternsynth::vector::{suggest_strokes, Stroke, SuggestOptions};

fn replayed(name: &str, jitter: f64) -> (patternsynth::vector::replay::Replay, usize) {
    replayed_with(name, jitter, 5)
}

fn replayed_with(name: &str, jitter: f64, seed: u64) -> (patternsynth::vector::replay::Replay, usize) {
    let f = family_list().into_iter().find(|f| f.name == name).unwrap();
    let (x, y) = if f.lattice.b.is_some() { (8.0, 6.0) } else { (12.0, 1.0) };
    let (ex, canvas) = f.canvas(x, y, jitter, seed);
    (replay(&ex.strokes, &ex.classes, canvas, 0.3 * f.lattice.spacing()), 2 * f.lattice.motif.len())
}

#[test]
fn every_lattice_family_comes_mostly_from_accepted_proposals_and_few_are_wrong() {
    // The aim (80% accepted, under 5% of shown ghosts wrong) at hand-drawn
    // jitters of 2% and 3% of the spacing. (At 5%, a grid's period is misjudged by more
    // than the matching tolerance over a few rows: see the replay example.)
    for jitter in [0.02, 0.03] {
        for f in family_list() {
            let (r, skip) = replayed(f.name, jitter);
            assert!(r.accepted_after(skip) >= 0.8, "{} at {jitter}: {r:?}", f.name);
            assert!(r.wrong_share() < 0.05, "{} at {jitter}: {r:?}", f.name);
            // A row needs three copies, a motif of several strokes two (and a lattice
            // a few more, to show its second period).
            assert!(r.before_first <= skip + 1, "{} at {jitter}: {r:?}", f.name);
        }
    }
}

#[test]
fn a_shaky_hand_never_gets_a_copy_proposed_beside_one_drawn() {
    // At a 5% wobble the fit is redrawn when the hand contradicts an accepted copy, and
    // its new origin put ghosts of a row (and of pairs) a few units from strokes of
    // their class already there (row seed 4: 3, pairs-row seed 1: 2 of 18 shown).
    // Copies on the canvas's edge are proposed (hexagonal and brick at 77.6-79.6% on
    // three seeds before).
    let (mut accepted, mut counted) = (0, 0);
    for seed in 1..=5 {
        for f in family_list() {
            let (r, skip) = replayed_with(f.name, 0.05, seed);
            assert_eq!(r.stacked, 0, "{} seed {seed}: {r:?}", f.name);
            if ["hexagonal", "brick"].contains(&f.name) {
                assert!(r.wrong == 0, "{} seed {seed}: {r:?}", f.name);
                accepted += r.accepted;
                counted += r.strokes - skip;
            }
        }
    }
    assert!(accepted as f64 >= 0.82 * counted as f64, "{accepted} of {counted}");
}

/// A hand-drawn cross: two strokes whose centres are a fraction of a unit apart.
fn cross(x: f64, y: f64, wobble: f64) -> [Stroke; 2] {
    [
        Stroke::new(vec![[x - 15.0, y - 15.0 + wobble], [x, y + wobble / 2.0], [x + 15.0, y + 15.0]], 3.0, None),
        Stroke::new(vec![[x + 15.0 + wobble, y - 15.0], [x, y], [x - 15.0, y + 15.0 - wobble]], 3.0, None),
    ]
}

/// A grid of crosses drawn row by row with no region (a helper's trial: the second
/// row's ghosts went to the left of the first column as often as to the right, off the
/// grid): once the first cross of the second row is drawn, its next three copies are
/// proposed under the first row's, from left to right; drawn from the right, from
/// right to left.
#[test]
fn a_grid_of_crosses_goes_on_row_by_row_within_its_columns() {
    for leftwards in [false, true] {
        let column = |i: usize| if leftwards { 150.0 - 40.0 * i as f64 } else { 30.0 + 40.0 * i as f64 };
        let mut strokes: Vec<Stroke> = (0..4).flat_map(|i| cross(column(i), 40.0, 0.0)).collect();
        strokes.extend(cross(column(0), 80.0, 0.0));
        let s = suggest_strokes(&strokes, &SuggestOptions::default()).unwrap();
        let mut centres: Vec<(f64, f64)> = s
            .strokes
            .chunks(2)
            .map(|pair| {
                let (a, b) = (pair[0].reference_point(), pair[1].reference_point());
                ((a.x + b.x) / 2.0, (a.y + b.y) / 2.0)
            })
            .collect();
        centres.sort_by(|p, q| p.0.total_cmp(&q.0));
        let mut want: Vec<f64> = (1..4).map(column).collect();
        want.sort_by(f64::total_cmp);
        assert_eq!(
            centres.len(),
            3,
            "leftwards {leftwards}: {centres:?} ({:?}) {:?} {:?}",
            s.reason,
            s.periods,
            s.cells
        );
        for (c, x) in centres.iter().zip(&want) {
            assert!((c.0 - x).abs() < 3.0 && (c.1 - 80.0).abs() < 3.0, "leftwards {leftwards}: {centres:?}");
        }
    }
}

/// One step down to begin the next row is no row (a review: four crosses in a row and
/// one under the second, a little off each, read on the periods (84.5, -43.6) and
/// (0, 43.6): the ghosts went down a diagonal nobody drew): the lattice's first period
/// stays along the row drawn, and the ghosts within its columns.
#[test]
fn one_step_down_a_row_is_no_row() {
    let off = |k: u64| ((k.wrapping_mul(0x9E37_79B9_7F4A_7C15) >> 11) as f64 / (1u64 << 53) as f64 - 0.5) * 0.6;
    for seed in [7u64, 23, 33] {
        let p = 40.0 + (seed % 13) as f64 * 0.31;
        let mut strokes: Vec<Stroke> = (0..4)
            .flat_map(|i| cross(30.0 + p * i as f64 + off(seed * 17 + i), 40.0 + off(seed * 31 + i), 0.0))
            .collect();
        strokes.extend(cross(30.0 + p + off(seed * 7), 83.7 + off(seed * 5), 0.0));
        let s = suggest_strokes(&strokes, &SuggestOptions::default()).unwrap();
        let a = s.periods.first().expect("a lattice");
        assert!(a[1].abs() < 0.05 * a[0].abs(), "seed {seed}: periods {:?}", s.periods);
        // (And the ghosts within the first row's columns: read as a lattice of two
        // copies a period, its second row went on to x = -54 and -12.)
        for g in &s.strokes {
            let x = g.reference_point().x;
            assert!((30.0 - 0.5 * p..=30.0 + 3.5 * p).contains(&x), "seed {seed}: a ghost at x {x:.0}");
        }
    }
}

#[test]
fn motifs_whose_parts_sit_on_one_another_repeat_by_their_own_period() {
    // The nearest stroke of any class is the cross's other half, 0.5 units away: the
    // spacing is taken between strokes further apart than a quarter of the class spacing.
    let strokes: Vec<Stroke> =
        [0.8, -0.6, 0.4].iter().enumerate().flat_map(|(i, &w)| cross(100.0 + 70.0 * i as f64, 120.0, w)).collect();
    let s = suggest_strokes(&strokes, &SuggestOptions { region: Some([0.0, 0.0, 800.0, 500.0]), ..Default::default() })
        .unwrap();
    assert_eq!(s.strokes.len(), 6, "{:?}", s.reason);
    for (k, p) in s.strokes.iter().enumerate() {
        let c = p.reference_point();
        let want = 100.0 + 70.0 * (3 + k / 2) as f64;
        assert!((c.x - want).abs() < 1.5 && (c.y - 120.0).abs() < 1.5, "proposal {k} at {c:?}, want x {want}");
    }
}

#[test]
fn accepted_proposals_weigh_little_so_the_next_hand_drawn_copy_corrects_the_period() {
    // Copies drawn at 0, 25 and 50, five accepted at 75-175, then one drawn by hand at
    // 201, a unit further than the period says: marked as accepted, the five no longer
    // hold the period at 25 and it moves toward the hand-drawn copies.
    let dash = |x: f64| Stroke::new(vec![[x, 0.0], [x, 12.0]], 2.0, None);
    let xs = [0.0, 25.0, 50.0, 75.0, 100.0, 125.0, 150.0, 175.0, 201.0];
    let strokes: Vec<Stroke> = xs.iter().map(|&x| dash(x)).collect();
    let next = |suggested: Vec<u32>| {
        let s = suggest_strokes(&strokes, &SuggestOptions { count: 1, suggested, ..Default::default() }).unwrap();
        assert_eq!(s.periods.len(), 1, "{:?}", s.reason);
        s.periods[0][0]
    };
    let unmarked = next(vec![]);
    let marked = next(vec![3, 4, 5, 6, 7]);
    // Least squares over all nine copies vs over the four hand-drawn ones (weight 1).
    assert!((unmarked - 25.0).abs() < 0.2, "{unmarked}");
    assert!(marked > unmarked + 0.05, "{marked} vs {unmarked}");
    let bad = suggest_strokes(&strokes, &SuggestOptions { suggested: vec![9], ..Default::default() });
    assert!(bad.unwrap_err().to_string().contains("suggested lists stroke 9"));
}

fn proposals_over_prefixes(strokes: &[Stroke]) -> usize {
    (1..=strokes.len()).map(|n| suggest_strokes(&strokes[..n], &SuggestOptions::default()).unwrap().strokes.len()).sum()
}

#[test]
fn nothing_is_proposed_on_irregular_input_or_a_freehand_sketch() {
    for seed in 1..=3 {
        assert_eq!(proposals_over_prefixes(&irregular_dashes(60, 300.0, seed)), 0, "dashes, seed {seed}");
        assert_eq!(proposals_over_prefixes(&freehand_sketch(40, 300.0, seed)), 0, "sketch, seed {seed}");
    }
}

#[test]
fn proposals_continue_a_row_by_its_period_inside_the_region() {
    let f = family_list().into_iter().find(|f| f.name == "row").unwrap();
    let (ex, canvas) = f.canvas(12.0, 1.0, 0.0, 1);
    let region = Some([canvas.x0, canvas.y0, canvas.width(), canvas.height()]);
    // Two copies are not yet a repetition of a one-stroke motif; three are.
    let two = suggest_strokes(&ex.strokes[..2], &SuggestOptions { region, ..Default::default() }).unwrap();
    assert!(two.strokes.is_empty() && two.reason.is_some());
    let s = suggest_strokes(&ex.strokes[..3], &SuggestOptions { region, ..Default::default() }).unwrap();
    assert_eq!(s.periods.len(), 1);
    assert!((s.periods[0][0] - 24.0).abs() < 1e-6 && s.periods[0][1].abs() < 1e-6, "{:?}", s.periods);
    let xs: Vec<f64> = s.strokes.iter().map(|p| p.reference_point().x).collect();
    let want: Vec<f64> = ex.strokes[3..6].iter().map(|p| p.reference_point().x).collect();
    assert_eq!(xs.len(), 3);
    for (x, w) in xs.iter().zip(&want) {
        assert!((x - w).abs() < 1e-6, "{xs:?} vs {want:?}");
    }
    assert!(s.confidence.windows(2).all(|c| c[0] >= c[1]) && s.confidence[0] <= 1.0 && s.confidence[2] > 0.0);
    // Filling the region proposes every copy left, and nothing outside it.
    let all = suggest_strokes(&ex.strokes[..3], &SuggestOptions { region, fill: true, ..Default::default() }).unwrap();
    assert_eq!(all.strokes.len(), ex.strokes.len() - 3);
    assert!(all.strokes.iter().all(|p| canvas.contains(p.reference_point())));
    // A stroke off the row dismisses the proposals.
    let mut off = ex.strokes[..3].to_vec();
    off.push(ex.strokes[0].translated(10.0, 40.0));
    let s = suggest_strokes(&off, &SuggestOptions { region, ..Default::default() }).unwrap();
    assert!(s.strokes.is_empty(), "{:?} {:?} {:?}", s.reason, s.periods, s.cells);
}

#[test]
fn bad_options_are_refused_with_a_message() {
    let f = family_list().into_iter().next().unwrap();
    let (ex, _) = f.canvas(4.0, 1.0, 0.0, 1);
    let fill = suggest_strokes(&ex.strokes, &SuggestOptions { fill: true, ..Default::default() });
    assert!(fill.unwrap_err().to_string().contains("region"));
    let region =
        suggest_strokes(&ex.strokes, &SuggestOptions { region: Some([0.0, 0.0, -1.0, 5.0]), ..Default::default() });
    assert!(region.unwrap_err().to_string().contains("region"));
}

#[test]
fn a_shaky_hand_drawing_motifs_of_several_strokes_gets_whole_right_copies() {
    // The aim at a wobble of 5% of the spacing: at least 80% of the strokes
    // after the first two copies come from accepted proposals, under 5% of the shown
    // ones are wrong. Every motif on every lattice (the flower, the slowest, on two).
    use patternsynth::vector::handdrawn::{draw_over, lattices, motifs};
    let spacing = 70.0;
    for motif in motifs() {
        for (lattice, a, b) in lattices() {
            if motif.name == "flower" && !matches!(lattice, "square" | "hexagonal") {
                continue;
            }
            let (ex, canvas) = draw_over(&motif, (a, b), (8.0, 6.0), spacing, 0.05, 5);
            let r = replay(&ex.strokes, &ex.classes, canvas, 0.3 * spacing);
            let skip = 2 * motif.parts.len();
            assert!(r.accepted_after(skip) >= 0.8, "{} on {lattice}: {r:?}", motif.name);
            assert!(r.wrong_share() < 0.05, "{} on {lattice}: {r:?}", motif.name);
        }
    }
}

/// Repetitions that are not lattices (issue 27): rings of 5 to 12 petals, a spiral,
/// leaves along an arc, an S and wavier stems, along Bézier curves and a row that turns
/// a corner, hatching along a turning and a straight contour, drawn stroke by stroke
/// with a wobble of 1% and 3% of the step (seeds 1-3), accepting the right ghosts: each
/// family's mean share accepted after three copies, and the wrong ghosts over all of
/// them. Where the turn changes, less: leaves along an S (the turn reverses: no one
/// step carries them) at 0.45 and 0.4 (a clear bend goes one copy past the hand's: 0.55
/// and 0.45 before); along a wavy stem (the turn, up to 0.4 radian a step, changes sign
/// every six leaves) 0.2 and 0.12; along a curly one (up to 1 radian a step) nothing
/// but the wrong ghosts; along the Bézier arch 0.7 and 0.5, the Bézier S 0.4 and 0.35,
/// the rows that turn 0.45 and 0.3, an inward spiral (its turn grows) 0.75 and 0.5. At
/// most 5% of each family's ghosts and 2.5% of all are wrong, but for the Bézier curves
/// (the arch's turn grows from 2.5 to 8 degrees a step, which its first copies do not
/// show: 2 of 31 and 3 of 25 wrong; the S's, 2 of 17 at 3%) and the rows that turn,
/// whose ghosts straight on past the corner are wrong until a copy past it is drawn:
/// none after.
#[test]
fn rings_spirals_arcs_and_hatching_are_carried_on_by_their_step() {
    for wobble in [0.01, 0.03] {
        let (mut wrong, mut shown) = (0, 0);
        // Each family's name, mean share accepted, wrong and shown ghosts.
        let mut families: Vec<(String, f64, usize, usize)> = Vec::new();
        for seed in 1..=3 {
            for (k, q) in patternsynth::vector::sequences::sequences(wobble, seed).into_iter().enumerate() {
                let r = q.replay(&q.strokes);
                if q.name.contains("turning") && q.name.contains("row") {
                    // (The corner is the eleventh leaf: a copy past it is drawn by then.
                    // Before it, only ghosts that reach it may be wrong: three on from
                    // eight leaves.)
                    let off: Vec<&usize> = r.wrong_at.iter().filter(|&&n| !(8..=11).contains(&n)).collect();
                    assert!(off.is_empty(), "{} at {wobble}, seed {seed}: wrong with {off:?} drawn", q.name);
                } else {
                    wrong += r.wrong;
                    shown += r.shown;
                }
                if seed == 1 {
                    families.push((q.name.clone(), 0.0, 0, 0));
                }
                families[k].1 += r.accepted_after(3) / 3.0;
                families[k].2 += r.wrong;
                families[k].3 += r.shown;
            }
        }
        for (name, share, wrong, shown) in &families {
            let least = match (name.as_str(), wobble < 0.02) {
                ("leaves on an S-curve", true) => 0.45,
                ("leaves on an S-curve", false) => 0.4,
                ("leaves on a wavy stem", true) => 0.2,
                ("leaves on a wavy stem", false) => 0.12,
                ("leaves on a curly stem" | "leaves on a tight stem", _) => 0.0,
                ("leaves on a Bézier arch", true) => 0.7,
                ("leaves on a Bézier arch", false) => 0.5,
                ("leaves on a Bézier S", true) => 0.4,
                ("leaves on a Bézier S", false) => 0.35,
                ("leaves on a row turning 60°", true) => 0.45,
                ("leaves on a row turning 30°", true) => 0.5,
                ("leaves on a row turning 60°" | "leaves on a row turning 30°", false) => 0.3,
                ("leaves on an inward spiral", false) => 0.5,
                // (Its copies between accepted ones read no bend from their shapes, and
                // the places' reading holds the ghosts nearer: 86% before, see
                // `sequence::model`'s `UNREAD_BEND_PRIOR`.)
                ("spiral", true) => 0.7,
                (_, true) => 0.75,
                (_, false) => 0.6,
            };
            assert!(*share >= least, "{name} at {wobble}: {share:.2} accepted after three copies");
            // (Per family too: a wavy stem's 1 wrong of 12 hid in the others' 200.)
            let most = match name.as_str() {
                "leaves on a Bézier arch" | "leaves on a Bézier S" => 0.125,
                n if n.contains("turning") && n.contains("row") => 1.0,
                _ => 0.05,
            };
            assert!(*wrong as f64 <= most * *shown as f64, "{name} at {wobble}: {wrong} wrong of {shown} shown");
        }
        assert!(wrong as f64 <= 0.025 * shown as f64, "at {wobble}: {wrong} wrong of {shown} shown");
    }
}

/// A person's hand (issue 27's second trial: leaves along curves, each copy turned 2.5
/// degrees off at random, got "too uncertain" at every call): every sequence family
/// drawn so, at 1% and 3% of the step, seeds 1-3. Measured: 56% and 50% accepted after
/// three copies on the mean family (47% and 41% when the bend was read from the shapes
/// alone), 10 wrong of 237 and 13 of 217 shown but on the rows that turn a corner. Held
/// to at least half and 45% accepted, at most 5% and 7.5% wrong.
#[test]
fn a_hand_that_turns_its_copies_still_gets_ghosts() {
    for (wobble, least, most) in [(0.01, 0.5, 0.05), (0.03, 0.45, 0.075)] {
        let (mut share, mut families, mut wrong, mut shown) = (0.0, 0.0, 0, 0);
        for seed in 1..=3 {
            for q in drawn_by(wobble, HandTurn::PERSON, seed) {
                let r = q.replay(&q.strokes);
                share += r.accepted_after(3);
                families += 1.0;
                // (Ghosts straight on past a corner nobody could foresee: see
                // `rings_spirals_arcs_and_hatching_are_carried_on_by_their_step`.)
                if !(q.name.contains("turning") && q.name.contains("row")) {
                    wrong += r.wrong;
                    shown += r.shown;
                }
            }
        }
        let share = share / families;
        assert!(share >= least, "at {wobble}: {share:.2} accepted after three copies on the mean family");
        assert!(wrong as f64 <= most * shown as f64, "at {wobble}: {wrong} wrong of {shown} shown");
    }
}

/// A second ring drawn after the first is complete (issue 27): three petals of it, and
/// its ghosts complete it too (five of each ring's eight accepted), nothing proposed
/// across from one ring to the other.
#[test]
fn a_second_ring_completes_as_the_first_did() {
    let ring = |seed| {
        patternsynth::vector::sequences::sequences(0.01, seed).into_iter().find(|q| q.name == "ring of 8").unwrap()
    };
    let (first, second) = (ring(1), ring(2));
    let moved: Vec<_> = second.strokes.iter().map(|s| s.translated(260.0, 40.0)).collect();
    let truth: Vec<_> = first.strokes.iter().cloned().chain(moved).collect();
    let canvas = first.canvas.union(second.canvas.with_origin((second.canvas.x0 + 260.0, second.canvas.y0 + 40.0)));
    let r = replay(&truth, &vec![0; truth.len()], canvas, 0.3 * first.step);
    assert_eq!(r.by_hand, 6, "{r:?}");
    assert_eq!(r.wrong, 0, "{r:?}");
    // Each ring's last five petals are accepted ghosts.
    let accepted: Vec<bool> = (0..16).map(|i| i % 8 >= 3).collect();
    let centres: Vec<_> = r.drawing.iter().map(|s| s.reference_point()).collect();
    for (k, c) in centres.iter().enumerate() {
        let near_second = c.x > first.canvas.x1 + 10.0;
        assert_eq!(near_second, k >= 8, "petal {k} at {c:?}");
    }
    assert_eq!(r.accepted, accepted.iter().filter(|&&a| a).count());
}

/// A ring finished by accepting ghosts says so (issue 27): rings of 5 to 12 at 1% to 5%,
/// seeds 1-3, each drawn to its end; a ring whose count was never sure enough to snap
/// (three petals of six, three accepted) is complete too, not "draw one more".
#[test]
fn a_finished_ring_is_reported_complete() {
    for wobble in [0.01, 0.03, 0.05] {
        for seed in 1..=3 {
            for q in patternsynth::vector::sequences::sequences(wobble, seed) {
                if !q.name.starts_with("ring") {
                    continue;
                }
                let r = q.replay(&q.strokes);
                let said = r.end_reason.unwrap_or_default();
                assert!(said.contains("ring is complete"), "{} at {wobble}, seed {seed}: {said:?}", q.name);
            }
        }
    }
}

/// Petals drawn round a disc, by a new user's generator (tests/fixtures/rings: six
/// teardrops or leaves, jittered, each turned off a little; the disc drawn first). Six
/// petals round a disc lie on a triangular lattice with it, and 15 of 25 such complete
/// rings got lattice ghosts outside the ring, as did four petals of six. Every ghost
/// now lies on the ring's circle, off the drawn petals, and a complete ring gets none.
#[test]
fn petals_round_a_disc_get_the_ring_s_ghosts_not_a_lattice_s() {
    for name in ["ring6_disc_teardrop", "ring6_disc_leaf", "ring6_disc_four_petals"] {
        let path = format!("{}/tests/fixtures/rings/{name}.json", env!("CARGO_MANIFEST_DIR"));
        let all: Vec<Stroke> = serde_json::from_str(&std::fs::read_to_string(path).unwrap()).unwrap();
        let centre = all[0].reference_point();
        let radius =
            all[1..].iter().map(|s| s.reference_point().distance(centre)).sum::<f64>() / (all.len() - 1) as f64;
        for drawn in 5..=all.len() {
            let s = suggest_strokes(&all[..drawn], &SuggestOptions::default()).unwrap();
            for g in &s.strokes {
                let p = g.reference_point();
                let r = p.distance(centre);
                assert!(
                    (0.75 * radius..=1.25 * radius).contains(&r),
                    "{name} ({drawn}): a ghost {r:.0} from the disc, the ring's radius {radius:.0}"
                );
                let on = all[1..drawn].iter().any(|t| t.reference_point().distance(p) < 0.3 * radius);
                assert!(!on, "{name} ({drawn}): a ghost on a drawn petal at {p:?}");
            }
            if drawn == 7 {
                assert!(s.strokes.is_empty(), "{name}: {} ghosts on a complete ring", s.strokes.len());
            }
            if name == "ring6_disc_four_petals" {
                assert!(!s.strokes.is_empty(), "{name}: no ghost: {:?}", s.reason);
            }
        }
    }
}

/// Petals each with a small circle drawn in them, round a disc, by a new user's
/// generator (tests/fixtures/rings). A circle a few pen widths across is mostly the
/// hand's wobble, and its copies said nothing of the ring: four circled petals got no
/// ghost in 18 of 20 rings, and a complete ring got a circle on a drawn one. Four
/// circled petals now get the next petal with its circle, on the ring's circle, none
/// on a drawn stroke of its size; a complete ring gets none.
#[test]
fn petals_with_small_circles_get_ghosts_with_their_circles() {
    for (name, complete) in [
        ("ring8_disc_four_circled_petals", false),
        ("ring_disc_four_circled_petals", false),
        ("ring8_disc_circled_petals", true),
    ] {
        let path = format!("{}/tests/fixtures/rings/{name}.json", env!("CARGO_MANIFEST_DIR"));
        let all: Vec<Stroke> = serde_json::from_str(&std::fs::read_to_string(path).unwrap()).unwrap();
        let centre = all[0].reference_point();
        let size = |s: &Stroke| s.bounds().size().to_vec2().hypot();
        let radius =
            all[1..].iter().map(|s| s.reference_point().distance(centre)).sum::<f64>() / (all.len() - 1) as f64;
        let s = suggest_strokes(&all, &SuggestOptions::default()).unwrap();
        if complete {
            assert!(s.strokes.is_empty(), "{name}: {} ghosts on a complete ring", s.strokes.len());
            continue;
        }
        let small = s.strokes.iter().filter(|g| size(g) < 0.5 * size(&all[1])).count();
        assert!(
            small >= 1 && s.strokes.len() > small,
            "{name}: {} ghosts, {small} circles: {:?}",
            s.strokes.len(),
            s.reason
        );
        for g in &s.strokes {
            let (p, r) = (g.reference_point(), g.reference_point().distance(centre));
            assert!(
                (0.75 * radius..=1.25 * radius).contains(&r),
                "{name}: a ghost {r:.0} from the disc, the ring's {radius:.0}"
            );
            let on = all[1..].iter().any(|t| {
                (size(t) / size(g)).clamp(0.5, 2.0) == size(t) / size(g)
                    && t.reference_point().distance(p) < 0.2 * radius
            });
            assert!(!on, "{name}: a ghost on a drawn stroke of its size at {p:?}");
        }
    }
}

/// Petals and leaves begun anywhere round their loop, either way round (issue 27: a
/// hand starts each copy where the pen lands, and only petals begun alike got ghosts):
/// rings of 5-12 and leaves along an arc at 1% and 3%, seeds 1-3, each loop rebegun at
/// a random point and read backwards one time in two, complete and continue as when
/// begun alike (each family's mean share accepted after three copies at least 0.75 at
/// 1%, 0.6 at 3%; at most 2.5% of the shown ghosts wrong).
#[test]
fn loops_begun_anywhere_are_carried_on() {
    for wobble in [0.01, 0.03] {
        let (mut wrong, mut shown) = (0, 0);
        let mut accepted: Vec<(String, f64)> = Vec::new();
        for seed in 1..=3 {
            let mut rng = patternsynth::rng::Rng::new(seed + 40);
            let families = patternsynth::vector::sequences::sequences(wobble, seed)
                .into_iter()
                .filter(|q| q.name.starts_with("ring") || q.name == "leaves on an arc");
            for (k, q) in families.enumerate() {
                let strokes: Vec<Stroke> =
                    q.strokes.iter().map(|s| begun_at(s, rng.below(24), rng.below(2) == 1)).collect();
                let r = q.replay(&strokes);
                if seed == 1 {
                    accepted.push((q.name.clone(), 0.0));
                }
                accepted[k].1 += r.accepted_after(3) / 3.0;
                wrong += r.wrong;
                shown += r.shown;
            }
        }
        let least = if wobble < 0.02 { 0.75 } else { 0.6 };
        for (name, share) in &accepted {
            assert!(*share >= least, "{name} at {wobble}: {share:.2} accepted after three copies");
        }
        assert!(wrong as f64 <= 0.025 * shown as f64, "at {wobble}: {wrong} wrong of {shown} shown");
    }
}

/// Circles on a grid, each begun at a random point of its outline and drawn either way
/// round (issue 27's trial: a grid of circles begun anywhere got no ghost, and
/// synthesis read no lattice): at 1% and 3% of the spacing, seeds 1-3, at least 70% of
/// the strokes after the first two come from accepted ghosts, under 2.5% of the shown
/// ones wrong, and eight circles synthesize as a lattice.
#[test]
fn circles_begun_anywhere_make_a_lattice() {
    use patternsynth::vector::{synthesize_strokes, StrokeOptions};
    let spacing = 60.0;
    for wobble in [0.01, 0.03] {
        let (mut accepted, mut wrong, mut shown) = (0.0, 0, 0);
        for seed in 1..=3 {
            let (strokes, canvas) = circle_grid(wobble, seed, true);
            let r = replay(&strokes, &vec![0; strokes.len()], canvas, 0.3 * spacing);
            accepted += r.accepted_after(2) / 3.0;
            wrong += r.wrong;
            shown += r.shown;
            let opts = StrokeOptions { width: 600.0, height: 400.0, ..Default::default() };
            let s = synthesize_strokes(&strokes[..8], &opts, &mut patternsynth::Silent).unwrap();
            assert_eq!(format!("{:?}", s.structure), "Lattice", "at {wobble}, seed {seed}");
        }
        assert!(accepted >= 0.7, "at {wobble}: {accepted:.2} accepted after two copies");
        assert!(wrong as f64 <= 0.025 * shown as f64, "at {wobble}: {wrong} wrong of {shown} shown");
    }
}

/// Circles round a centre (issue 27's trial: five circles of a ring of six got ghosts
/// of the triangular lattice their places fit, 2.6 radii out; three and four read a turn
/// from whichever start of each circle fitted best): a circle shows no turn of its
/// own, and its ring is read from the places. Rings of five, six and eight circles,
/// small and large, at 1-5% of the step (seeds 1-3): no ghost wrong at 1% and 3%, under
/// 2.5% at 5%, and at least half the circles after the first four accepted.
#[test]
fn circles_round_a_centre_complete_their_ring() {
    use patternsynth::vector::sequences::circle_ring;
    for wobble in [0.01, 0.03, 0.05] {
        let (mut accepted, mut counted, mut wrong, mut shown) = (0, 0, 0, 0);
        for n in [5usize, 6, 8] {
            for (radius, size) in [(60.0, 8.0), (100.0, 20.0)] {
                for seed in 1..=3 {
                    let (strokes, canvas) = circle_ring(n, radius, size, wobble, seed);
                    let step = 2.0 * radius * (std::f64::consts::PI / n as f64).sin();
                    let r = replay(&strokes, &vec![0; n], canvas, 0.3 * step);
                    assert_eq!(r.stacked, 0, "{n} circles at {wobble}, seed {seed}: {r:?}");
                    accepted += r.accepted;
                    counted += n - 4;
                    wrong += r.wrong;
                    shown += r.shown;
                }
            }
        }
        let most = if wobble < 0.04 { 0.0 } else { 0.025 };
        assert!(wrong as f64 <= most * shown as f64, "at {wobble}: {wrong} wrong of {shown} shown");
        assert!(2 * accepted >= counted, "at {wobble}: {accepted} of {counted} accepted");
    }
}

/// What the page says while no ghost is shown (issue 27's trial: "The drawing shows no
/// repetition yet" with seventeen leaves drawn along a wavy stem): leaves along the S,
/// wavy and curly stems drawn one by one at 1% and 3% (seeds 1-3), every prefix of six
/// leaves or more that gets no ghost says why in other words; irregular dashes and a
/// freehand sketch are still "no repetition" at least nine times in ten, and never a
/// complete ring. So too three and four petals of a ring drawn by a person's hand (each
/// turned about 2.5 degrees off; helper-52's trial: "no repetition yet" after three
/// matching petals, 59 of 180 such calls of `examples/ring_ghosts` at 1-5%).
#[test]
fn a_repetition_without_ghosts_is_not_called_no_repetition() {
    let said = |strokes: &[Stroke]| suggest_strokes(strokes, &SuggestOptions::default()).unwrap();
    // (Prefixes of a sequence that repeats: none of them "no repetition" while no ghost
    // is shown.)
    let repeating = |q: &patternsynth::vector::sequences::Sequence, prefixes: &[usize], wobble: f64, seed: u64| {
        for &n in prefixes {
            let s = said(&q.strokes[..n]);
            let reason = s.reason.unwrap_or_default();
            assert!(
                !s.strokes.is_empty() || !reason.contains("no repetition"),
                "{} at {wobble}, seed {seed}, {n} drawn: {reason:?}",
                q.name
            );
        }
    };
    for wobble in [0.01, 0.03, 0.05] {
        for seed in 1..=3 {
            let rings =
                drawn_by(wobble, HandTurn::PERSON, seed).into_iter().chain(composite(wobble, HandTurn::PERSON, seed));
            for q in rings.filter(|q| q.name.starts_with("ring")) {
                repeating(&q, &[3 * q.parts, 4 * q.parts], wobble, seed);
            }
            if wobble > 0.03 {
                continue;
            }
            for q in patternsynth::vector::sequences::sequences(wobble, seed) {
                if q.name.contains("stem") || q.name.contains("S-curve") {
                    repeating(&q, &(6..=q.strokes.len()).collect::<Vec<_>>(), wobble, seed);
                }
            }
        }
    }
    let (mut none, mut calls) = (0, 0);
    for seed in 1..=3 {
        for strokes in [irregular_dashes(60, 300.0, seed), freehand_sketch(40, 300.0, seed)] {
            for n in 3..=strokes.len() {
                calls += 1;
                let reason = said(&strokes[..n]).reason.unwrap_or_default();
                none += usize::from(reason.contains("no repetition"));
                // (Dashes each about a half turn of the one before were a "complete
                // ring" in 14 of 288 calls.)
                assert!(!reason.contains("ring"), "seed {seed}, {n} drawn: {reason:?}");
            }
        }
    }
    assert!(none as f64 >= 0.9 * calls as f64, "{none} of {calls} calls on irregular input say no repetition");
}

/// Copies turned at random are still a lattice's (a review of issue 27's turned-copies
/// check, which compares the latest two with the place's usual copy): ticks whose angle
/// a hand varies by up to 5 degrees get ghosts from the fourth copy on, as a row of
/// ticks drawn alike does.
#[test]
fn copies_turned_at_random_are_still_a_row() {
    let mut rng = patternsynth::rng::Rng::new(3);
    let tick = |x: f64, a: f64| {
        let (dx, dy) = (12.0 * a.sin(), -12.0 * a.cos());
        Stroke::new(vec![[x - dx, 100.0 - dy], [x, 100.0], [x + dx, 100.0 + dy]], 2.0, None)
    };
    let region = Some([0.0, 60.0, 300.0, 80.0]);
    for spread in [0.0, 0.08] {
        let row: Vec<Stroke> = (0..8)
            .map(|k| tick(20.0 + 30.0 * k as f64, (rng.below(1000) as f64 / 1000.0 - 0.5) * 2.0 * spread))
            .collect();
        for n in 4..=8 {
            let s = suggest_strokes(&row[..n], &SuggestOptions { region, ..Default::default() }).unwrap();
            assert!(!s.strokes.is_empty(), "turned up to {spread} rad, {n} drawn: {:?}", s.reason);
        }
    }
}

/// Motifs of several strokes carried on by turns (issue 27: a ring of petals each drawn
/// as two mirrored arcs got "no repetition", leaves of three strokes along curves 0-10%
/// accepted): petals of two arcs, petals with a vein, leaves of three strokes in a ring,
/// along an arc and an S-curve, stalked leaves along a Bézier arch (`composite`), at 1%
/// of the step, seeds 1-3. Each ghost must be the part it repeats, at its place.
/// Measured: 97% accepted after three copies on the mean family, 14 wrong of 356 shown
/// (12 on the S-curve, past its first bend); every ring at least 100% (ghosts from two
/// and a half petals on), none wrong. Held to 85% and 5% wrong, each ring at least 90%
/// with none wrong.
#[test]
fn motifs_of_several_strokes_are_carried_on_whole() {
    let (mut share, mut families, mut wrong, mut shown) = (0.0, 0.0, 0, 0);
    for seed in 1..=3 {
        for q in patternsynth::vector::sequences::composite(0.01, HandTurn::STEADY, seed) {
            let r = q.replay(&q.strokes);
            let accepted = q.accepted_after_three(&r);
            if q.name.starts_with("ring") {
                assert!(accepted >= 0.9 && r.wrong == 0, "{} (seed {seed}): {accepted:.2} accepted, {r:?}", q.name);
                // (The ring closes whole: nothing more is proposed on the finished one.)
                assert!(
                    r.end_reason.as_deref().is_some_and(|w| w.contains("complete")),
                    "{}: {:?}",
                    q.name,
                    r.end_reason
                );
            }
            share += accepted.min(1.0);
            families += 1.0;
            wrong += r.wrong;
            shown += r.shown;
        }
    }
    let share = share / families;
    assert!(share >= 0.85, "{share:.2} accepted after three copies on the mean family");
    assert!(wrong as f64 <= 0.05 * shown as f64, "{wrong} wrong of {shown} shown");
}

/// A leaf and then its dot, or the dot and then its leaf: every leaf proposed comes
/// with its dot, at its tip, and no dot without a leaf (drawn leaf first, the last
/// leaf proposed came without one: the dots went with the copy after theirs).
#[test]
fn every_proposed_leaf_gets_its_dot_whichever_is_drawn_first() {
    let mut checked = 0;
    for seed in 1..=3 {
        let all = patternsynth::vector::sequences::composite(0.01, HandTurn::STEADY, seed);
        let q = all.iter().find(|q| q.name == "leaves with a dot on an arc").expect("the family");
        for dot_first in [false, true] {
            let strokes: Vec<Stroke> = q
                .strokes
                .chunks(2)
                .flat_map(|c| if dot_first { vec![c[1].clone(), c[0].clone()] } else { c.to_vec() })
                .collect();
            let opts = SuggestOptions { region: Some([0.0, 0.0, 600.0, 600.0]), ..SuggestOptions::default() };
            for copies in 3..=5 {
                let s = suggest_strokes(&strokes[..2 * copies], &opts).unwrap();
                let is_dot = |g: &Stroke| g.bounds().size().to_vec2().hypot() < 4.0 * g.width;
                let (dots, leaves): (Vec<&Stroke>, Vec<&Stroke>) = s.strokes.iter().partition(|g| is_dot(g));
                assert_eq!(dots.len(), leaves.len(), "seed {seed}, dot first {dot_first}, {copies} copies");
                // (Each dot within a fifth of a leaf's length of a proposed leaf's tip: the
                // leaf's end farthest from where its stalk would be, either end.)
                for dot in &dots {
                    let p = dot.reference_point();
                    let near = leaves.iter().any(|l| {
                        let (a, b) = (l.points[0], l.points[l.points.len() / 2]);
                        [a, b].iter().any(|&[x, y]| kurbo::Point::new(x, y).distance(p) < 8.0)
                    });
                    assert!(near, "seed {seed}, dot first {dot_first}: a dot at {p:?} by no proposed leaf's tip");
                }
                checked += leaves.len();
            }
        }
    }
    assert!(checked >= 20, "{checked} leaves proposed");
}

/// A pen tap for a dot (three to six points within two pixels of one another, as a
/// stylus or mouse leaves them) goes with its leaf as a drawn circle does: its shape is
/// noise, so it is matched by its place, not by its outline; and round a ring, where one
/// pair's step carries a petal's dot, a step behind, less closely.
#[test]
fn pen_taps_go_with_their_leaves() {
    let mut checked = 0;
    for (seed, hand) in (1..=3).flat_map(|s| [(s, HandTurn::STEADY), (s, HandTurn::PERSON)]) {
        let all = patternsynth::vector::sequences::composite(0.01, hand, seed);
        for name in ["leaves with a dot on an arc", "ring of 8 petals with a dot"] {
            let q = all.iter().find(|q| q.name == name).expect("the family");
            let strokes = patternsynth::vector::sequences::pen_taps(&q.strokes, seed);
            let opts = SuggestOptions { region: Some([0.0, 0.0, 600.0, 600.0]), ..SuggestOptions::default() };
            for copies in 3..=5 {
                let s = suggest_strokes(&strokes[..2 * copies], &opts).unwrap();
                let (dots, leaves): (Vec<&Stroke>, Vec<&Stroke>) = s.strokes.iter().partition(|g| g.is_dot());
                assert_eq!(dots.len(), leaves.len(), "{name}, seed {seed}, {hand:?}, {copies} copies");
                checked += leaves.len();
            }
        }
    }
    assert!(checked >= 20, "{checked} leaves proposed");
}

/// Rings begun by a person's hand, each copy turned 2.5 degrees at random (issue 27):
/// three or four petals (of 5-12, and of motifs of several strokes) at 1% and 3% of the
/// step, seeds 1-10. Three petals of eight turned 47.9 and 50.3 degrees apart (their
/// places 49.0) were taken for a ring of seven, 27 times likelier, and its ghosts two and
/// three copies on were a whole step off. Measured: 37 wrong of 960 shown (3.9%; 30 of
/// 937 before the dots a person's hand spaced unevenly went with their petals,
/// `copies::companions`, onto rings whose count was read wrong too); 54 of 953 (5.7%)
/// before the count was judged as a person draws. Held to 4%.
#[test]
fn rings_begun_by_a_person_get_few_wrong_ghosts() {
    let (mut shown, mut wrong) = (0, 0);
    for wobble in [0.01, 0.03] {
        for seed in 1..=10 {
            let hand = HandTurn::PERSON;
            let all = drawn_by(wobble, hand, seed)
                .into_iter()
                .chain(patternsynth::vector::sequences::composite(wobble, hand, seed));
            for q in all.filter(|q| q.name.starts_with("ring")) {
                let region = Some([q.canvas.x0, q.canvas.y0, q.canvas.width(), q.canvas.height()]);
                for copies in [3, 4] {
                    let n = copies * q.parts;
                    let s = suggest_strokes(&q.strokes[..n], &SuggestOptions { region, ..Default::default() }).unwrap();
                    for g in &s.strokes {
                        let p = g.reference_point();
                        let miss = q.strokes[n..]
                            .iter()
                            .map(|t| t.reference_point().distance(p))
                            .fold(f64::INFINITY, f64::min);
                        wrong += usize::from(miss > 0.3 * q.step);
                    }
                    shown += s.strokes.len();
                }
            }
        }
    }
    assert!(shown >= 800, "{shown} ghosts shown");
    assert!((wrong as f64) <= 0.04 * shown as f64, "{wrong} wrong of {shown} shown");
}

/// Three petals of a ring of five by a person's hand at 5% of the step (each turned about
/// 2.5 degrees off) complete the ring: the count is clear, and the ring's places bear it
/// out though the two steps' turns disagree by more than the local test allows
/// (`RING_FROM_THREE`). Before, seeds 2 and 3 got no ghost until the fourth petal, or
/// none at all ("too uncertain" with one petal left).
#[test]
fn three_petals_by_a_person_complete_a_ring_of_five() {
    for seed in 1..=3 {
        let q = drawn_by(0.05, HandTurn::PERSON, seed).into_iter().find(|q| q.name == "ring of 5").unwrap();
        let s = suggest_strokes(&q.strokes[..3], &SuggestOptions::default()).unwrap();
        assert_eq!(s.strokes.len(), 2, "seed {seed}: {} ghosts ({:?})", s.strokes.len(), s.reason);
        for g in &s.strokes {
            let miss = q.miss(3, g.reference_point());
            assert!(
                miss <= 0.3 * q.step,
                "seed {seed}: a ghost {miss:.1} from the petals still to draw (step {:.1})",
                q.step
            );
        }
    }
}

/// Points that shake (a mouse's jaggies, a tremor: each point moved at random by 3% of
/// the step) on leaves along an arc: ghosts still come, none wrong. The shapes' residual
/// counted each point's own jitter as the hand's misplacement of a copy, and 31 of 70
/// calls were "too uncertain" (36 with ghosts); now 59 of 70 have ghosts, 1 wrong of 83.
#[test]
fn points_that_shake_still_get_ghosts() {
    let (mut calls, mut with, mut shown, mut wrong) = (0, 0, 0, 0);
    for seed in 1..=10 {
        let q = drawn_by(0.01, HandTurn::STEADY, seed).into_iter().find(|q| q.name == "leaves on an arc").unwrap();
        let strokes = patternsynth::vector::sequences::shaken(&q.strokes, 0.03 * q.step, seed + 100);
        let region = Some([q.canvas.x0, q.canvas.y0, q.canvas.width(), q.canvas.height()]);
        for n in 3..strokes.len() {
            let s = suggest_strokes(&strokes[..n], &SuggestOptions { region, ..Default::default() }).unwrap();
            calls += 1;
            with += usize::from(!s.strokes.is_empty());
            shown += s.strokes.len();
            wrong += s.strokes.iter().filter(|g| q.miss(n, g.reference_point()) > 0.3 * q.step).count();
        }
    }
    assert!(with as f64 >= 0.75 * calls as f64, "{with} of {calls} calls with ghosts");
    assert!(wrong as f64 <= 0.05 * shown as f64, "{wrong} wrong of {shown} shown");
}

/// Stalked leaves whose first copy was drawn without its stalk: a stalk is a leading
/// part (it touches the leaf drawn after it), so no stalk is proposed past the last leaf
/// (`trailing` took the stalks for parts drawn after their leaves, as a leaf's dot is,
/// and proposed one on its own).
#[test]
fn a_first_copy_without_its_stalk_gets_no_stray_stalk() {
    let mut checked = 0;
    for seed in 1..=3 {
        let all = patternsynth::vector::sequences::composite(0.01, HandTurn::STEADY, seed);
        let q = all.iter().find(|q| q.name == "stalked leaves on a Bézier arch").expect("the family");
        let opts = SuggestOptions { region: Some([0.0, 0.0, 800.0, 800.0]), ..SuggestOptions::default() };
        for copies in 3..=5 {
            let strokes = &q.strokes[1..2 * copies];
            let s = suggest_strokes(strokes, &opts).unwrap();
            let closed = |g: &Stroke| g.points.len() > 13;
            let (leaves, stalks): (Vec<&Stroke>, Vec<&Stroke>) = s.strokes.iter().partition(|g| closed(g));
            // (Each stalk ends where a proposed leaf begins.)
            for stalk in &stalks {
                let [x, y] = stalk.points[stalk.points.len() - 1];
                let end = kurbo::Point::new(x, y);
                let held = leaves.iter().any(|l| kurbo::Point::new(l.points[0][0], l.points[0][1]).distance(end) < 6.0);
                assert!(held, "seed {seed}, {copies} copies: a stalk ending at {end:?} holds no proposed leaf");
            }
            checked += stalks.len();
        }
    }
    assert!(checked >= 5, "{checked} stalks proposed");
}

/// Leaves along a stem drawn first (issue 27, "a stem and three leaves"): sines that
/// bend either way every few leaves, Bézier curves and a circle, each drawn by a
/// person's hand (copies turned 2.5 degrees at random) with a wobble of 3% of the step.
/// The ghosts follow the drawn stem: most leaves after the third are accepted, few
/// ghosts are wrong, and none go past the stem's end (no ghost is counted past it).
#[test]
fn leaves_follow_a_drawn_stem() {
    let (mut after, mut accepted, mut shown, mut wrong) = (0, 0, 0, 0);
    for seed in 1..=3 {
        for q in patternsynth::vector::sequences::along_drawn(0.03, HandTurn::PERSON, seed) {
            let r = q.replay(&q.strokes);
            assert_eq!(r.beyond, 0, "{}: a ghost past the stem's end", q.name);
            after += r.strokes - q.lead - 3;
            accepted += r.accepted;
            shown += r.shown;
            wrong += r.wrong;
        }
    }
    let share = accepted as f64 / after as f64;
    assert!(share >= 0.75, "{accepted} of {after} accepted");
    assert!(wrong as f64 <= 0.05 * shown as f64, "{wrong} of {shown} wrong");
}

/// Hatching as a new user drew it (a helper's trial): lines 80 long and 20 apart, each
/// turned up to 2 degrees at random and every point shaken by 1.6 (2% of the line, a
/// pointer's jitter), four to six drawn. The ends' jitter read as a hand that places its
/// copies 5 to 7 off, one pair of lines read backwards as a half turn, and no ghost came
/// at all; now 16 of the 30 calls get ghosts, none wrong (14 before the lines were
/// steadied: see `similarity::steadied`).
#[test]
fn hatching_drawn_with_a_shaky_pointer_goes_on() {
    let (mut calls, mut with, mut shown, mut wrong) = (0, 0, 0, 0);
    for seed in 1..=10u64 {
        let mut rng = patternsynth::rng::Rng::new(seed * 7 + 3);
        let (step, len) = (20.0, 80.0);
        let line = |k: usize, rng: &mut patternsynth::rng::Rng| {
            let a = (90.0 + 4.0 * rng.next_f64() - 2.0f64).to_radians();
            let base = (200.0 + step * k as f64, 300.0);
            let pts = (0..20)
                .map(|t| {
                    let r = t as f64 * len / 19.0;
                    [base.0 + r * a.cos() + 1.6 * rng.normal(), base.1 - r * a.sin() + 1.6 * rng.normal()]
                })
                .collect();
            Stroke::new(pts, 3.0, None)
        };
        let all: Vec<Stroke> = (0..12).map(|k| line(k, &mut rng)).collect();
        for n in 4..=6 {
            let s = suggest_strokes(&all[..n], &SuggestOptions::default()).unwrap();
            calls += 1;
            with += usize::from(!s.strokes.is_empty());
            shown += s.strokes.len();
            for g in &s.strokes {
                let c = g.reference_point();
                let miss = all[n..].iter().map(|t| t.reference_point().distance(c)).fold(f64::INFINITY, f64::min);
                wrong += usize::from(miss > 0.3 * step);
            }
        }
    }
    eprintln!("shaky hatching: {with} of {calls} calls with ghosts, {shown} shown, {wrong} wrong");
    assert!(with >= 12, "{with} of {calls} calls with ghosts");
    assert_eq!(wrong, 0, "{wrong} wrong of {shown} shown");
}

/// A line `len` long from `start` along `theta`, drawn the other way one time in five.
fn hand_line(start: [f64; 2], theta: f64, len: f64, rng: &mut patternsynth::rng::Rng) -> Stroke {
    let mut pts: Vec<[f64; 2]> = (0..=2)
        .map(|i| {
            let t = len * i as f64 / 2.0;
            [start[0] + t * theta.cos(), start[1] + t * theta.sin()]
        })
        .collect();
    if rng.next_f64() < 0.2 {
        pts.reverse();
    }
    Stroke::new(pts, 3.0, None)
}

/// Hatching as a hand draws it (issue 27, "draw four or five hatching strokes"): lines
/// 100 long, each begun 1-5% of the spacing off its place and turned up to 2 degrees
/// about its start, a fifth drawn the other way and a tenth past its end by 15-40%,
/// begun 25 or 40 apart along a level baseline (23.5 and 37.6 across the lines, at 70
/// degrees), seeds 1-12. After five lines, a ghost
/// on the sixth in most drawings (lattice, sequence or hatching: the lattice and the
/// sequence read a line drawn past its end as another shape or a zoom), and a ghost
/// off every line still to draw in few (measured: 22 of 24 and none; without
/// `suggest::hatching`, 15 of 24).
#[test]
fn hand_drawn_hatching_gets_its_next_line() {
    use patternsynth::rng::Rng;
    let (mut hit, mut wrong, mut runs) = (0, 0, 0);
    for spacing in [25.0, 40.0] {
        for seed in 1..=12u64 {
            let mut rng = Rng::new(seed * 977 + spacing as u64);
            let lines: Vec<Stroke> = (0..9)
                .map(|k| {
                    let off = spacing * (0.01 + 0.04 * rng.next_f64());
                    let phi = rng.next_f64() * std::f64::consts::TAU;
                    let start = [200.0 + spacing * k as f64 + off * phi.cos(), 300.0 + off * phi.sin()];
                    let theta = (-70.0 + 4.0 * rng.next_f64() - 2.0f64).to_radians();
                    let len = if rng.next_f64() < 0.1 { 100.0 * (1.15 + 0.25 * rng.next_f64()) } else { 100.0 };
                    hand_line(start, theta, len, &mut rng)
                })
                .collect();
            let s = suggest_strokes(&lines[..5], &SuggestOptions::default()).unwrap();
            // A ghost is on a line where it lies within 0.3 of the spacing of it across
            // the lines, and within a quarter of its length along it (a line's middle
            // moves along it as far as the hand ends it).
            let dir = kurbo::Vec2::new((-70f64).to_radians().cos(), (-70f64).to_radians().sin());
            let on = |g: &Stroke, l: &Stroke| {
                let d = g.reference_point() - l.reference_point();
                d.cross(dir).abs() < 0.3 * spacing && d.dot(dir).abs() < 25.0
            };
            hit += usize::from(s.strokes.iter().any(|g| on(g, &lines[5])));
            wrong += usize::from(s.strokes.iter().any(|g| !lines[5..].iter().any(|l| on(g, l))));
            runs += 1;
        }
    }
    eprintln!("hatching by hand: a ghost on the next line in {hit} of {runs}, one off every line in {wrong}");
    assert!(hit * 6 >= runs * 5 && wrong <= 1, "{hit} of {runs} on the next line, {wrong} off every line");
}

/// Hatching that turns with its contour (issue 27: "ghosts continue the hatching with
/// the same spacing, turning and lengthening as the last strokes do"): lines radiating
/// from a centre at `gap` apart across their middles, each turned `turn` degrees from
/// the one before and `grow` times as long, drawn as `hand_drawn_hatching_gets_its_next_line`
/// draws them (begun 1-5% of the gap off, turned up to 2 degrees, a fifth backwards, a
/// tenth past their end).
fn fan(gap: f64, turn: f64, grow: f64, seed: u64) -> Vec<Stroke> {
    use patternsynth::rng::Rng;
    let mut rng = Rng::new(seed * 131 + (turn * 10.0) as u64);
    let step = turn.to_radians();
    let radius = gap / step;
    let centre = [300.0, 500.0];
    (0..9)
        .map(|k| {
            let phi = (-150.0f64).to_radians() + step * k as f64 + (4.0 * rng.next_f64() - 2.0).to_radians();
            let len = 80.0 * grow.powi(k);
            let len_drawn = if rng.next_f64() < 0.1 { len * (1.15 + 0.25 * rng.next_f64()) } else { len };
            let off = gap * (0.01 + 0.04 * rng.next_f64());
            let psi = rng.next_f64() * std::f64::consts::TAU;
            let r0 = radius - len / 2.0;
            let start = [
                centre[0] + r0 * (step * k as f64 - 150f64.to_radians()).cos() + off * psi.cos(),
                centre[1] + r0 * (step * k as f64 - 150f64.to_radians()).sin() + off * psi.sin(),
            ];
            hand_line(start, phi, len_drawn, &mut rng)
        })
        .collect()
}

/// A ghost lies on `line` where its middle is within 0.3 of `gap` of the line's across
/// it, within a quarter of the line's length along it, and it is turned as the line is
/// to within 6 degrees.
fn on_line(g: &Stroke, l: &Stroke, gap: f64) -> bool {
    let chord = |s: &Stroke| {
        let (p, q) = (s.points[0], s.points[s.points.len() - 1]);
        kurbo::Vec2::new(q[0] - p[0], q[1] - p[1])
    };
    let (dg, dl) = (chord(g), chord(l));
    let dir = dl.normalize();
    let d = g.reference_point() - l.reference_point();
    d.cross(dir).abs() < 0.3 * gap
        && d.dot(dir).abs() < 0.25 * dl.hypot()
        && dg.normalize().cross(dir).abs() < 6f64.to_radians().sin()
}

/// Fans turning 4-16 degrees a line, as long or 6% longer each, 20 and 30 apart, seeds
/// 1-6, after five and six lines: a ghost on the next line in 188 of 192, one off every
/// line still to draw in 5 (before `by_turns` and the hatching's turn of up to 20
/// degrees a line: 143 and 23, the sequence reading pairs of lines as one motif).
#[test]
fn hatching_that_turns_with_its_contour_gets_its_next_line() {
    let (mut hit, mut wrong, mut runs) = (0, 0, 0);
    for gap in [20.0, 30.0] {
        for turn in [4.0, 8.0, 12.0, 16.0] {
            for grow in [1.0, 1.06] {
                let (mut h, mut w) = (0, 0);
                for seed in 1..=6u64 {
                    let lines = fan(gap, turn, grow, seed);
                    for drawn in [5, 6] {
                        let s = suggest_strokes(&lines[..drawn], &SuggestOptions::default()).unwrap();
                        h += usize::from(s.strokes.iter().any(|g| on_line(g, &lines[drawn], gap)));
                        w += usize::from(s.strokes.iter().any(|g| !lines[drawn..].iter().any(|l| on_line(g, l, gap))));
                        runs += 1;
                    }
                }
                eprintln!("fan gap {gap} turn {turn} grow {grow}: next line {h} of 12, off {w}");
                hit += h;
                wrong += w;
            }
        }
    }
    eprintln!("turning hatching: a ghost on the next line in {hit} of {runs}, one off every line in {wrong}");
    assert!(hit * 10 >= runs * 9 && wrong * 25 <= runs, "{hit} of {runs} on the next line, {wrong} off every line");
}

/// After four to seven posts, a ghost at the next post's site (within 0.3 of the step,
/// posed as it is to within 8 degrees), and none off every post still to draw; radii
/// 200 and 400, 1% and 3%, seeds 1-4. Measured: upright, the next post in 46 of 64,
/// a ghost off every post in 12 (the lattice's straight row through four posts of the
/// wider arc, which bow by a twentieth of the step: 14 and 28 before the sequence read
/// the step's turn from the places); turned with the arc, 62 and 0.
#[test]
fn fence_posts_along_an_arc_get_the_next_post() {
    for upright in [true, false] {
        let (mut h, mut w, mut r) = (0, 0, 0);
        for radius in [200.0, 400.0] {
            for jitter in [0.01, 0.03] {
                for seed in 1..=4u64 {
                    let (strokes, sites) = posts(radius, 40.0, upright, jitter, seed);
                    let at = |g: &Stroke, k: usize| {
                        let (p, q) = (g.points[0], g.points[g.points.len() - 1]);
                        let dir = kurbo::Vec2::new(q[0] - p[0], q[1] - p[1]).normalize();
                        let pose = kurbo::Vec2::new(sites[k].1.cos(), sites[k].1.sin());
                        g.reference_point().distance(sites[k].0) < 0.3 * 40.0
                            && dir.cross(pose).abs() < 8f64.to_radians().sin()
                    };
                    for drawn in 4..=7 {
                        let s = suggest_strokes(&strokes[..drawn], &SuggestOptions::default()).unwrap();
                        h += usize::from(s.strokes.iter().any(|g| at(g, drawn)));
                        w += usize::from(s.strokes.iter().any(|g| !(drawn..12).any(|k| at(g, k))));
                        r += 1;
                    }
                }
            }
        }
        eprintln!("posts along an arc, upright {upright}: the next post in {h} of {r}, one off every post in {w}");
        let (least, most) = if upright { (44, 14) } else { (58, 2) };
        assert!(h >= least && w <= most, "upright {upright}: the next post in {h} of {r}, one off every post in {w}");
    }
}

/// A fence seen from the side, drawn post, rail, post, rail: the rails run from post to
/// post along the arc (turning with it), the posts stay upright. Ghost posts must stay
/// upright too (a helper's trial: carried with the rail, which the sequence follows,
/// 291 of 400 calls had a post leaning by the arc's turn). Arcs of radius 200 (11.5
/// degrees a post) at 1% and 3%, seeds 1-4, after 4-7 posts and their rails.
#[test]
fn a_fence_of_posts_and_rails_keeps_its_ghost_posts_upright() {
    use patternsynth::vector::sequences::{posts_by, PostHand};
    let hand = PostHand { tilt: 2f64.to_radians(), length: 0.0 };
    let (mut h, mut leaning, mut r) = (0, 0, 0);
    for jitter in [0.01, 0.03] {
        for seed in 1..=4u64 {
            let (posts, sites) = posts_by(200.0, 40.0, true, jitter, hand, seed);
            // (A rail from 28 up one post, where the hand drew it, to 28 up the next.)
            let at = |k: usize, up: f64| {
                let p = posts[k].points[0];
                kurbo::Point::new(p[0], p[1] - up)
            };
            let mut strokes = Vec::new();
            let mut ends = Vec::new();
            for (k, post) in posts.iter().enumerate().take(11) {
                strokes.push(post.clone());
                let (a, b) = (at(k, 28.0), at(k + 1, 28.0));
                strokes.push(Stroke::new(
                    (0..=4)
                        .map(|i| {
                            let q = a.lerp(b, i as f64 / 4.0);
                            [q.x, q.y]
                        })
                        .collect(),
                    3.0,
                    None,
                ));
                ends.push(strokes.len());
            }
            for drawn in 4..=7 {
                let s = suggest_strokes(&strokes[..ends[drawn - 1]], &SuggestOptions::default()).unwrap();
                // Ghost posts: those near a post's middle still to draw.
                let post_at = |g: &Stroke| (drawn..12).find(|&k| g.reference_point().distance(sites[k].0) < 0.3 * 40.0);
                let upright = |g: &Stroke| {
                    let (p, q) = (g.points[0], g.points[g.points.len() - 1]);
                    let dir = kurbo::Vec2::new(q[0] - p[0], q[1] - p[1]).normalize();
                    dir.x.abs() < 8f64.to_radians().sin()
                };
                h += usize::from(s.strokes.iter().any(|g| post_at(g) == Some(drawn) && upright(g)));
                leaning += usize::from(s.strokes.iter().any(|g| post_at(g).is_some() && !upright(g)));
                r += 1;
            }
        }
    }
    eprintln!("posts and rails: the next post upright in {h} of {r}, a ghost post leaning in {leaning}");
    assert!(h >= r / 2 && leaning == 0, "the next post upright in {h} of {r}, a ghost post leaning in {leaning}");
}

/// Upright posts drawn by a looser hand (a new user's trial: 2 of 18 got the next post;
/// 8 of 40 here before the shape steps' turn was judged by their mean):
/// each tilted 3 degrees at random and 7% longer or shorter, 3% of the step off its
/// place, along an arc turning 11.5 degrees a post, after 4-8 posts. Each shape step
/// then turns by up to 10 degrees at random, past the 6 degrees a copy kept upright
/// could turn; what tells posts kept upright from posts turned with the arc is their
/// steps' mean turn against the places'.
#[test]
fn fence_posts_drawn_loosely_get_the_next_post() {
    use patternsynth::vector::sequences::{posts_by, PostHand};
    let hand = PostHand { tilt: 3f64.to_radians(), length: 0.07 };
    let (mut h, mut w, mut r) = (0, 0, 0);
    for seed in 1..=8u64 {
        let (strokes, sites) = posts_by(200.0, 40.0, true, 0.03, hand, seed);
        let at = |g: &Stroke, k: usize| g.reference_point().distance(sites[k].0) < 0.3 * 40.0;
        for drawn in 4..=8 {
            let s = suggest_strokes(&strokes[..drawn], &SuggestOptions::default()).unwrap();
            h += usize::from(s.strokes.iter().any(|g| at(g, drawn)));
            w += usize::from(s.strokes.iter().any(|g| !(drawn..12).any(|k| at(g, k))));
            r += 1;
        }
    }
    eprintln!("loosely drawn posts: the next post in {h} of {r}, one off every post in {w}");
    assert!(h >= 12 && w <= 3, "the next post in {h} of {r}, one off every post in {w}");
}

/// Leaves drawn each as an outline and its midrib, along a gentle wave (a trial's own
/// generator: seven leaves, 47 apart, the wave turning them up to about 6 degrees a
/// step): every ghost lies where the wave puts a leaf, within the replay's tolerance
/// (0.3 of the spacing). The outline holds the midrib, and its turn shows the row's
/// bend; read from neither part (the two of about one size), the row was carried on
/// straight past the wave's bend, ghosts one and two leaves on 0.33 and 0.6 of the
/// spacing off.
#[test]
fn leaves_with_midribs_along_a_wave_are_not_carried_on_straight() {
    #[derive(serde::Deserialize)]
    struct Case {
        spacing: f64,
        strokes: Vec<Stroke>,
        places: Vec<Vec<[f64; 2]>>,
    }
    let path = format!("{}/tests/fixtures/curves/trial_midrib_leaves_gentle_wave.json", env!("CARGO_MANIFEST_DIR"));
    let case: Case = serde_json::from_str(&std::fs::read_to_string(path).unwrap()).unwrap();
    let opts = SuggestOptions { region: Some([0.0, 0.0, 1200.0, 800.0]), ..Default::default() };
    let s = suggest_strokes(&case.strokes, &opts).unwrap();
    assert!(!s.strokes.is_empty(), "the next leaf is proposed");
    for g in &s.strokes {
        let n = g.points.len() as f64;
        let mean = g.points.iter().fold([0.0, 0.0], |m, p| [m[0] + p[0] / n, m[1] + p[1] / n]);
        let off =
            case.places.iter().flatten().map(|q| (q[0] - mean[0]).hypot(q[1] - mean[1])).fold(f64::INFINITY, f64::min);
        assert!(off < 0.3 * case.spacing, "a ghost {:.2} of the spacing off the wave's leaves", off / case.spacing);
    }
}

/// Where a ring closes onto its first petal, a person drew longer than the rest (a third
/// longer than the next), that petal is the ring's first still: no ghost is proposed over
/// it. Five and six petals each 10% longer or shorter at random, seed 10, four drawn: a
/// ghost 0.91 of the step from every petal still to draw, on the first one, before.
#[test]
fn a_ring_closes_onto_a_longer_first_petal() {
    let centre = kurbo::Point::new(300.0, 300.0);
    for name in ["ring of 5", "ring of 6"] {
        let q = drawn_by(0.01, HandTurn::PERSON, 10)
            .into_iter()
            .find(|q| q.name == name)
            .unwrap()
            .sized_about(centre, 0.1, 10);
        let n = 4 * q.parts;
        let s = suggest_strokes(&q.strokes[..n], &SuggestOptions::default()).unwrap();
        assert!(!s.strokes.is_empty(), "{name}: no ghost ({:?})", s.reason);
        for g in &s.strokes {
            let miss = q.miss(n, g.reference_point());
            assert!(miss <= 0.3 * q.step, "{name}: a ghost {miss:.1} off (step {:.1})", q.step);
        }
    }
}

/// A ring drawn whole gets no ghost over a copy already drawn (helper-55's trial): its
/// first petal drawn a quarter longer than the rest, rings of five to twelve petals by a
/// person's hand at 1-5% of the step, seeds 1-3 (11 of 45 got one on that petal, the
/// part left of a copy where the petals were read in pairs); twelve squares each turned
/// with their ring, drawn whole and with one to go (42 ghosts on the first three drawn,
/// over 90 calls: a run holds eight copies, and the ring was checked for closing on
/// those only).
#[test]
fn a_ring_drawn_whole_gets_no_ghost_on_its_copies() {
    let centre = kurbo::Point::new(300.0, 300.0);
    for wobble in [0.01, 0.03, 0.05] {
        for seed in 1..=3 {
            for q in drawn_by(wobble, HandTurn::PERSON, seed).into_iter().filter(|q| q.name.starts_with("ring of")) {
                let mut strokes = q.strokes.clone();
                for p in strokes[0].points.iter_mut() {
                    *p = [centre.x + 1.25 * (p[0] - centre.x), centre.y + 1.25 * (p[1] - centre.y)];
                }
                let s = suggest_strokes(&strokes, &SuggestOptions::default()).unwrap();
                assert!(s.strokes.is_empty(), "{} at {wobble}, seed {seed}: {} ghosts", q.name, s.strokes.len());
            }
        }
    }
    // Squares of side 14 at radius 60-120, each turned with the ring and 2.5 degrees
    // off at random, 3% of the step off its place, begun at a random corner.
    for radius in [60.0, 90.0, 120.0] {
        for seed in 1..=3u64 {
            let mut rng = patternsynth::rng::Rng::new(seed);
            let step = 2.0 * radius * (std::f64::consts::PI / 12.0).sin();
            let squares: Vec<Stroke> = (0..12)
                .map(|k| {
                    let theta = k as f64 * std::f64::consts::TAU / 12.0;
                    let at = [
                        centre.x + radius * theta.cos() + 0.03 * step * rng.normal(),
                        centre.y + radius * theta.sin() + 0.03 * step * rng.normal(),
                    ];
                    let turn = theta + 0.0436 * rng.normal();
                    let first = rng.below(4);
                    let corners: Vec<[f64; 2]> = (0..=4)
                        .map(|c| {
                            let a = turn
                                + std::f64::consts::FRAC_PI_4
                                + ((first + c) % 4) as f64 * std::f64::consts::FRAC_PI_2;
                            [
                                at[0] + 7.0 * std::f64::consts::SQRT_2 * a.cos(),
                                at[1] + 7.0 * std::f64::consts::SQRT_2 * a.sin(),
                            ]
                        })
                        .collect();
                    // (Each side in four, as a pointer samples it.)
                    let points = corners
                        .windows(2)
                        .flat_map(|w| {
                            (0..4).map(move |i| {
                                let f = i as f64 / 4.0;
                                [w[0][0] + f * (w[1][0] - w[0][0]), w[0][1] + f * (w[1][1] - w[0][1])]
                            })
                        })
                        .chain(std::iter::once(corners[4]))
                        .collect();
                    Stroke::new(points, 2.0, None)
                })
                .collect();
            for n in [11, 12] {
                let s = suggest_strokes(&squares[..n], &SuggestOptions::default()).unwrap();
                for g in &s.strokes {
                    let c = g.reference_point();
                    let on = squares[..n].iter().map(|q| q.reference_point().distance(c)).fold(f64::INFINITY, f64::min);
                    assert!(
                        on > 0.3 * step,
                        "radius {radius}, seed {seed}, {n} drawn: a ghost {on:.1} from a drawn square"
                    );
                }
                if n == 12 {
                    assert!(
                        s.strokes.is_empty(),
                        "radius {radius}, seed {seed}: {} ghosts on a whole ring",
                        s.strokes.len()
                    );
                }
            }
        }
    }
}

/// Flowers of petals alone drawn side by side, the second drawn whole: the lattice of
/// flowers goes on, not the second ring alone, which is complete (helper-56's review:
/// a ring snapped by the sequence was carried on before the lattice, and two flowers
/// of six petals read "The ring is complete" with no ghost of the third).
#[test]
fn flowers_of_petals_on_a_row_go_on_as_a_row() {
    let q = drawn_by(0.01, HandTurn::STEADY, 1).into_iter().find(|q| q.name == "ring of 6").unwrap();
    let moved = |dx: f64| {
        q.strokes.iter().map(move |s| {
            let mut s = s.clone();
            s.points.iter_mut().for_each(|p| p[0] += dx);
            s
        })
    };
    let strokes: Vec<Stroke> = moved(-150.0).chain(moved(100.0)).collect();
    let opts = SuggestOptions { region: Some([0.0, 0.0, 1000.0, 600.0]), ..Default::default() };
    let s = suggest_strokes(&strokes, &opts).unwrap();
    assert!(!s.strokes.is_empty(), "no ghost: {:?}", s.reason);
    for g in &s.strokes {
        let c = g.reference_point();
        assert!((c.x - 650.0).abs() < 90.0 && (c.y - 300.0).abs() < 90.0, "a ghost at {c:?}, off the third flower");
    }
}

/// A ring whose petals a person drew longer and shorter (each 10% at random, out from
/// the centre) reads from three petals as a spiral about the ring's centre as often as a
/// ring: its ghosts past the first are then held back, not carried on round the spiral
/// (`PERSON_SIZE`). Six plain and six veined petals, seed 2, at 1%: ghosts off every
/// petal still to draw by 0.36-0.45 of the step before; now the plain ring keeps a ghost
/// and every ghost shown is within 0.3 of the step of a petal to draw (the veined ring
/// waits for a fourth).
#[test]
fn petals_of_varying_length_are_not_carried_round_a_spiral() {
    let centre = kurbo::Point::new(300.0, 300.0);
    for name in ["ring of 6", "ring of 6 veined petals"] {
        let q = drawn_by(0.01, HandTurn::PERSON, 2)
            .into_iter()
            .chain(composite(0.01, HandTurn::PERSON, 2))
            .find(|q| q.name == name)
            .unwrap()
            .sized_about(centre, 0.1, 2);
        let n = 3 * q.parts;
        let s = suggest_strokes(&q.strokes[..n], &SuggestOptions::default()).unwrap();
        // (The plain petals keep the ghost both readings agree on; the veined ones, whose
        // veins read the turn loosely, wait for a fourth petal.)
        if name == "ring of 6" {
            assert!(!s.strokes.is_empty(), "{name}: no ghost ({:?})", s.reason);
        }
        for g in &s.strokes {
            let miss = q.miss(n, g.reference_point());
            assert!(miss <= 0.3 * q.step, "{name}: a ghost {miss:.1} off (step {:.1})", q.step);
        }
    }
}

/// A ring's count is read from its copies' mean turn: a person's petals whose turns
/// happen to drift one way read as a bend, and each count was judged against the first
/// step's turn. Helper-57's trial (tests/fixtures/rings/petals8_person.json: eight
/// elliptic petals from one centre, each turned -2.9, 3.7, 5.4, 2.9, 0.1 and 2.4 degrees
/// off at random, pair turns read 52.4, 46.6, 43.1 and 41.6): four drawn read as a ring
/// of seven (the first step's 51.1 degrees), its ghosts up to half the step off, and
/// five drawn "too uncertain". Every ghost from four to seven drawn lies on the ring of eight, and
/// each of those calls shows one.
#[test]
fn a_ring_s_count_is_read_from_its_mean_turn() {
    let path = format!("{}/tests/fixtures/rings/petals8_person.json", env!("CARGO_MANIFEST_DIR"));
    let all: Vec<Stroke> = serde_json::from_str(&std::fs::read_to_string(path).unwrap()).unwrap();
    let centre = kurbo::Point::new(300.0, 300.0);
    // (Each petal's centre, 40 out along its own turn of 45 degrees a petal.)
    let site = |k: usize| {
        let t = (45.0 * k as f64).to_radians();
        centre + kurbo::Vec2::new(t.cos(), t.sin()) * 40.0
    };
    let step = site(0).distance(site(1));
    for drawn in 4..all.len() {
        let s = suggest_strokes(&all[..drawn], &SuggestOptions::default()).unwrap();
        assert!(!s.strokes.is_empty(), "{drawn} drawn: no ghost ({:?})", s.reason);
        for g in &s.strokes {
            let p = g.reference_point();
            let miss = (drawn..all.len()).map(|k| site(k).distance(p)).fold(f64::INFINITY, f64::min);
            assert!(miss <= 0.3 * step, "{drawn} drawn: a ghost {:.2} of the step off", miss / step);
        }
    }
}

/// Pen taps round a centre complete their ring once drawn half round (helper-55's trial:
/// a dot has no shape to follow; five taps of a ring of six got ten lattice ghosts, all
/// wrong, and rings of five to twelve taps "no repetition yet" throughout). Rings of 6, 8
/// and 12 taps at radius 90, 3% of the step off, seeds 1-3, drawn tap by tap: no ghost
/// wrong (each within 0.3 of the step of a site still to draw) at any prefix, and from
/// five taps half round on every site left is proposed; the whole ring is complete.
#[test]
fn pen_taps_round_a_centre_complete_their_ring() {
    use patternsynth::vector::sequences::{circle_ring, pen_taps};
    for n in [6usize, 8, 12] {
        for seed in 1..=3 {
            let (circles, _) = circle_ring(n, 90.0, 12.0, 0.03, seed);
            let sites: Vec<kurbo::Point> = (0..n)
                .map(|k| {
                    let t = k as f64 * std::f64::consts::TAU / n as f64;
                    kurbo::Point::new(300.0 + 90.0 * t.cos(), 300.0 + 90.0 * t.sin())
                })
                .collect();
            let dots: Vec<Stroke> = circles
                .iter()
                .map(|c| {
                    let p = c.reference_point();
                    Stroke::new(vec![[p.x, p.y], [p.x + 1.0, p.y]], 4.0, None)
                })
                .collect();
            let taps = pen_taps(&dots, seed);
            let step = 2.0 * 90.0 * (std::f64::consts::PI / n as f64).sin();
            for drawn in 3..=n {
                let s = suggest_strokes(&taps[..drawn], &SuggestOptions { count: 64, ..SuggestOptions::default() })
                    .unwrap();
                let what = format!("{n} taps, seed {seed}, {drawn} drawn");
                for g in &s.strokes {
                    let p = g.reference_point();
                    let miss = sites[drawn..].iter().map(|q| q.distance(p)).fold(f64::INFINITY, f64::min);
                    assert!(miss <= 0.3 * step, "{what}: a ghost {:.2} of the step off", miss / step);
                }
                if drawn >= 5 && 2 * (drawn - 1) >= n {
                    assert_eq!(s.strokes.len(), n - drawn, "{what}: {:?}", s.reason);
                }
                if drawn == n {
                    assert_eq!(s.reason.as_deref(), Some("The ring is complete: draw the next one."), "{what}");
                }
            }
        }
    }
}
