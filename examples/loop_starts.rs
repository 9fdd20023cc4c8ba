//! Autocomplete of loops begun anywhere (issue 27): each family of `vector::sequences`
//! whose copies are closed loops (rings, leaves on an arc, the spiral, leaves on an S),
//! every loop rebegun at a random point of its outline and read backwards one time in
//! two, replayed stroke by stroke at 1%, 3% and 5%, seeds 1-3: the mean share accepted
//! after three copies and the wrong ghosts over those shown, beside the same drawings
//! begun alike. `cargo run --release --example loop_starts`
use patternsynth::rng::Rng;
use patternsynth::vector::sequences::{begun_at, sequences};
use patternsynth::vector::Stroke;

fn main() {
    println!("| family | wobble | begun alike: accepted, wrong/shown | begun anywhere: accepted, wrong/shown |");
    println!("|---|---|---|---|");
    for wobble in [0.01, 0.03, 0.05] {
        let names: Vec<String> =
            sequences(wobble, 1).into_iter().map(|q| q.name).filter(|n| !n.contains("hatching")).collect();
        for name in names {
            let mut cells = Vec::new();
            for anywhere in [false, true] {
                let (mut acc, mut wrong, mut shown) = (0.0, 0, 0);
                for seed in 1..=3 {
                    let q = sequences(wobble, seed).into_iter().find(|q| q.name == name).unwrap();
                    let mut rng = Rng::new(seed + 40);
                    let strokes: Vec<Stroke> = if anywhere {
                        q.strokes.iter().map(|s| begun_at(s, rng.below(24), rng.below(2) == 1)).collect()
                    } else {
                        q.strokes.clone()
                    };
                    let r = q.replay(&strokes);
                    acc += r.accepted_after(3) / 3.0;
                    wrong += r.wrong;
                    shown += r.shown;
                }
                cells.push(format!("{:.1}%, {wrong}/{shown}", 100.0 * acc));
            }
            println!("| {name} | {:.0}% | {} | {} |", 100.0 * wobble, cells[0], cells[1]);
        }
    }
}
