//! The vector engine against generated exemplars with a known lattice (SPEC 1.5):
//! coverage of ideal sites, strays, stacked duplicates and residual, per family.

use kurbo::{Rect, Vec2};
use patternsynth::vector::exemplar::{families, Exemplar};
use patternsynth::vector::regularity::{measure, Regularity};
use patternsynth::vector::{synthesize_strokes, StrokeOptions};
use patternsynth::Silent;

fn run(ex: &Exemplar, width: f64, height: f64) -> (Regularity, usize, u32) {
    run_with(ex, StrokeOptions { width, height, seed: 7, ..Default::default() })
}

fn run_with(ex: &Exemplar, opts: StrokeOptions) -> (Regularity, usize, u32) {
    let (width, height) = (opts.width, opts.height);
    let res = synthesize_strokes(&ex.strokes, &opts, &mut Silent).expect(ex.name);
    let bounds = ex
        .strokes
        .iter()
        .map(|s| s.reference_point())
        .fold(None::<Rect>, |r, p| Some(r.map_or(Rect::from_points(p, p), |r| r.union_pt(p))));
    let area = Rect::new(0.0, 0.0, width, height);
    let shift: Vec2 = area.center() - bounds.unwrap().center();
    let out: Vec<_> =
        res.strokes.iter().zip(&res.sources).map(|(s, &src)| (s.reference_point(), ex.classes[src as usize])).collect();
    (measure(&ex.lattice, shift, &out, area), res.strokes.len(), res.classification.count)
}

#[test]
fn every_family_grows_to_its_lattice() {
    let mut failures = Vec::new();
    // A small output and a large one (about 60 spacings across), where drift would show.
    for (ex, (w, h)) in
        families(0.02, 11).into_iter().flat_map(|e| [(e.clone(), (480.0, 400.0)), (e, (1500.0, 1500.0))])
    {
        let expected_classes = ex.classes.iter().max().unwrap() + 1;
        let (r, n, classes) = run(&ex, w, h);
        println!(
            "{:<18} {w:>4}x{h:<4} out {:>5} sites {:>5} coverage {:>6.2}% stray {:>3} stacked {:>3} median {:.3} p95 {:.3} period {:.4} classes {}",
            ex.name,
            n,
            r.sites,
            r.coverage * 100.0,
            r.stray,
            r.stacked,
            r.median_residual,
            r.p95_residual,
            r.period_error,
            classes
        );
        if classes != expected_classes || r.coverage < 0.99 || r.stray > 0 || r.stacked > 0 || r.median_residual >= 0.05
        {
            failures.push(format!("{}: {:?} classes {}", ex.name, r, classes));
        }
    }
    assert!(failures.is_empty(), "{failures:#?}");
}

#[test]
fn busy_tile_repeat_grows_to_its_periodic_extension() {
    // 3x3 repeat of a tile of 120 elements (1,080 in the example), 8x8 periods out.
    let ex = patternsynth::vector::exemplar::busy_tile(120, 100.0, 7.0, 3, 21);
    assert!(ex.lattice.motif.len() >= 110, "{}", ex.lattice.motif.len());
    let (r, n, classes) = run(&ex, 800.0, 800.0);
    println!("busy-tile: example {} out {n} {r:?} classes {classes}", ex.strokes.len());
    assert_eq!(classes, 3);
    assert!(r.coverage >= 0.999, "{r:?}");
    assert_eq!((r.stray, r.stacked), (0, 0), "{r:?}");
    assert!(r.p95_residual < 0.01, "no drift: {r:?}");
}

#[test]
fn growth_on_the_drawn_positions_holds_at_moderate_sizes() {
    // Without the lattice fit (the paper's growth with our frontier and conflict rules).
    for ex in families(0.02, 11) {
        let opts = StrokeOptions { width: 600.0, height: 600.0, seed: 7, regularize: false, ..Default::default() };
        let (r, _, _) = run_with(&ex, opts);
        println!("{:<18} unregularized {r:?}", ex.name);
        assert!(r.coverage >= 0.99 && r.stray == 0 && r.stacked == 0 && r.median_residual < 0.05, "{}: {r:?}", ex.name);
    }
}
