//! Synthesis of loops begun anywhere (issue 27): rings of 5-12 petals and leaves on an
//! arc from `vector::sequences`, every loop begun at a random point of its outline and
//! read backwards one time in two, synthesized at 800 x 600 with the default options;
//! how often the structure found is the one found for the same drawing begun alike.
//! `cargo run --release --example loop_synthesis`
use patternsynth::rng::Rng;
use patternsynth::vector::sequences::{begun_at, sequences};
use patternsynth::vector::{synthesize_strokes, Stroke, StrokeOptions};
use patternsynth::Silent;

fn main() {
    let opts = StrokeOptions { width: 800.0, height: 600.0, ..Default::default() };
    for wobble in [0.01, 0.03] {
        let (mut same, mut runs) = (0, 0);
        for seed in 1..=5 {
            let mut rng = Rng::new(seed + 40);
            for q in sequences(wobble, seed) {
                if !(q.name.starts_with("ring") || q.name == "leaves on an arc") {
                    continue;
                }
                let anywhere: Vec<Stroke> =
                    q.strokes.iter().map(|s| begun_at(s, rng.below(24), rng.below(2) == 1)).collect();
                let alike = synthesize_strokes(&q.strokes, &opts, &mut Silent).unwrap().structure;
                let r = synthesize_strokes(&anywhere, &opts, &mut Silent).unwrap();
                runs += 1;
                if r.structure == alike {
                    same += 1;
                } else {
                    println!("  {} seed {seed}: {:?} begun anywhere, {alike:?} begun alike", q.name, r.structure);
                }
            }
        }
        println!("at {:.0}%: {same} of {runs} drawings begun anywhere synthesize as when begun alike", 100.0 * wobble);
    }
}
