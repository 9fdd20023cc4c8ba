//! Lattices of hand-drawn circles and rings of teardrops begun anywhere on their
//! outline (issue 27): the lattice replay (accepting right ghosts) and synthesis's
//! structure, with every loop begun at the same point and begun at a random one.
//! `cargo run --release --example circle_starts`
use patternsynth::vector::replay::replay;
use patternsynth::vector::sequences::circle_grid;
use patternsynth::vector::{synthesize_strokes, StrokeOptions};
use patternsynth::Silent;

fn main() {
    let spacing = 60.0;
    for anywhere in [false, true] {
        for wobble in [0.01, 0.03, 0.05] {
            let (mut acc, mut wrong, mut shown, mut lattice) = (0.0, 0, 0, 0);
            for seed in 1..=3 {
                let (strokes, canvas) = circle_grid(wobble, seed, anywhere);
                if std::env::var("CLASSES").is_ok() {
                    let c = patternsynth::vector::classify_strokes(&strokes, None, None, None).unwrap();
                    println!("  {} classes {:?}", c.count, c.classes);
                }
                let r = replay(&strokes, &vec![0; strokes.len()], canvas, 0.3 * spacing);
                acc += r.accepted_after(2) / 3.0;
                wrong += r.wrong;
                shown += r.shown;
                let opts = StrokeOptions { width: 600.0, height: 400.0, ..Default::default() };
                let s = synthesize_strokes(&strokes[..8], &opts, &mut Silent).unwrap();
                lattice += usize::from(format!("{:?}", s.structure) == "Lattice");
            }
            println!(
                "circles begun {}, {:.0}%: accepted after two {:.1}%, wrong {wrong}/{shown}; synthesis of 8 a lattice {lattice}/3",
                if anywhere { "anywhere" } else { "alike" },
                100.0 * wobble,
                100.0 * acc
            );
        }
    }
}
