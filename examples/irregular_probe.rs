use patternsynth::vector::{synthesize_strokes, Rgb, Stroke, StrokeOptions};
use patternsynth::Silent;
fn main() {
    let mut rng = patternsynth::rng::Rng::new(5);
    let strokes: Vec<Stroke> = (0..40)
        .map(|_| {
            let (x, y) = (rng.next_f64() * 150.0, rng.next_f64() * 150.0);
            Stroke::new(vec![[x, y], [x + 6.0, y + 6.0]], 1.5, Some(Rgb([30, 30, 30])))
        })
        .collect();
    let r =
        synthesize_strokes(&strokes, &StrokeOptions { width: 450.0, height: 450.0, ..Default::default() }, &mut Silent)
            .unwrap();
    println!(
        "out {} growing {} passed {} skipped {} classes {}",
        r.strokes.len(),
        r.growing_points,
        r.passed_over,
        r.skipped_full,
        r.classification.count
    );
}
