//! Native side of `bench/busy.mjs`: synthesizes an SVG example (a file) over a
//! `width x height` output and prints the median wall time of 5 runs and the count, as
//! JSON; a fourth argument names a file to write the last output SVG to.
//! cargo run --release --example bench_svg -- example.svg 1000 1000 [out.svg]
use patternsynth::vector::{parse_svg, synthesize_strokes, ImportOptions, StrokeOptions};
use patternsynth::Silent;
use std::time::Instant;

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let svg = std::fs::read_to_string(&args[1]).expect("an SVG file");
    let (width, height): (f64, f64) = (args[2].parse().expect("width"), args[3].parse().expect("height"));
    let strokes = parse_svg(&svg, &ImportOptions::default()).expect("an SVG").strokes;
    let opts = StrokeOptions { width, height, variation: false, ..Default::default() };
    let mut times = Vec::new();
    let mut count = 0;
    for _ in 0..5 {
        let t = Instant::now();
        let r = synthesize_strokes(&strokes, &opts, &mut Silent).expect("synthesis");
        times.push(t.elapsed().as_secs_f64() * 1e3);
        count = r.strokes.len();
        if let Some(out) = args.get(4) {
            std::fs::write(out, &r.svg).expect("the output file");
        }
    }
    times.sort_by(|a, b| a.total_cmp(b));
    println!("{{\"example\":{},\"out\":{count},\"ms\":{:.2}}}", strokes.len(), times[2]);
}
