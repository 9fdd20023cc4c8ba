//! What autocomplete says once each sequence family is drawn to its end (accepting the
//! right ghosts on the way): `cargo run --release --example end_reason [wobble]`.
use patternsynth::vector::sequences::sequences;

fn main() {
    let wobble: f64 = std::env::args().nth(1).and_then(|a| a.parse().ok()).unwrap_or(0.03);
    for seed in 1..=3 {
        for q in sequences(wobble, seed) {
            let r = q.replay(&q.strokes);
            println!("seed {seed} {}: {} by hand, {} accepted: {:?}", q.name, r.by_hand, r.accepted, r.end_reason);
        }
    }
}
