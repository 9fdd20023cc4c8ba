//! Native side of the vector benchmark: for each case, the median wall time of a few
//! runs, as JSON lines. Run through `bash scripts/bench.sh`, which also times the same
//! cases in wasm under Node and prints the table.
use patternsynth::vector::exemplar::playground_examples;
use patternsynth::vector::{synthesize_strokes, Stroke, StrokeOptions};
use patternsynth::Silent;
use std::time::Instant;

/// (family, target output elements): the sizes are derived from the family's density.
pub const CASES: &[(&str, usize)] = &[
    ("grid", 500),
    ("grid", 2000),
    ("grid", 10000),
    ("grid", 50000),
    ("hexagonal", 10000),
    ("pairs-grid", 10000),
    ("busy-tile", 10000),
];

fn example(name: &str) -> Vec<Stroke> {
    // The playground's drawings, as the wasm side reads them from its JSON file.
    playground_examples().into_iter().find(|e| e.name == name).expect("an example").strokes
}

fn main() {
    for &(name, target) in CASES {
        let strokes = example(name);
        // Side of a square output holding about `target` elements: calibrated on a run
        // at a small size.
        let probe = 600.0;
        let opts = StrokeOptions { width: probe, height: probe, ..Default::default() };
        let n = synthesize_strokes(&strokes, &opts, &mut Silent).expect("synthesis").strokes.len();
        let side = (probe * (target as f64 / n as f64).sqrt()).round();
        let runs = if target >= 50000 { 3 } else { 5 };
        let mut times = Vec::new();
        let mut count = 0;
        for _ in 0..runs {
            let opts = StrokeOptions { width: side, height: side, ..Default::default() };
            let t = Instant::now();
            let r = synthesize_strokes(&strokes, &opts, &mut Silent).expect("synthesis");
            times.push(t.elapsed().as_secs_f64() * 1e3);
            count = r.strokes.len();
        }
        times.sort_by(|a, b| a.total_cmp(b));
        println!(
            "{{\"name\":\"{name}\",\"target\":{target},\"side\":{side},\"example\":{},\"elements\":{count},\"ms\":{:.3}}}",
            strokes.len(),
            times[times.len() / 2]
        );
    }
}
