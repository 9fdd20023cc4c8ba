use patternsynth::vector::exemplar::families;
use patternsynth::vector::{synthesize_strokes, StrokeOptions};
use patternsynth::Silent;
use std::time::Instant;

fn main() {
    for ex in families(0.02, 11) {
        for size in [600.0, 2400.0, 5000.0] {
            let opts = StrokeOptions { width: size, height: size, ..Default::default() };
            let t = Instant::now();
            let r = synthesize_strokes(&ex.strokes, &opts, &mut Silent).unwrap();
            println!(
                "{:<18} {:>5} out {:>6} in {:>8.1} ms  growing {} skipped {} passed {}",
                ex.name,
                size,
                r.strokes.len(),
                t.elapsed().as_secs_f64() * 1e3,
                r.growing_points,
                r.skipped_full,
                r.passed_over
            );
        }
    }
}
