//! Rings, arcs, spirals and hatching drawn by hand (issue 27, `vector::sequences`),
//! synthesized to 800 x 600 with the default options: the structure found, the output's
//! strokes and periods, and each output as SVG in out/chain/ to look at.
//! `cargo run --release --example chain_probe [wobble] [seed]`
use patternsynth::vector::sequences::sequences;
use patternsynth::vector::{synthesize_strokes, Rgb, StrokeOptions};
use patternsynth::Silent;

fn main() {
    let wobble: f64 = std::env::args().nth(1).and_then(|a| a.parse().ok()).unwrap_or(0.03);
    let seed: u64 = std::env::args().nth(2).and_then(|a| a.parse().ok()).unwrap_or(1);
    std::fs::create_dir_all("out/chain").unwrap();
    for q in sequences(wobble, seed) {
        for drawn in [3usize, 4, q.strokes.len()] {
            let mut strokes = q.strokes[..drawn].to_vec();
            strokes.iter_mut().for_each(|s| s.stroke = Some(Rgb([30, 60, 140])));
            let opts = StrokeOptions { width: 800.0, height: 600.0, ..Default::default() };
            let r = synthesize_strokes(&strokes, &opts, &mut Silent).unwrap();
            println!(
                "{} ({drawn} drawn): {:?}, {} strokes, periods {:?}",
                q.name,
                r.structure,
                r.strokes.len(),
                r.periods
            );
            std::fs::write(format!("out/chain/{}-{drawn}.svg", q.name.replace(' ', "-")), r.svg).unwrap();
        }
    }
}
