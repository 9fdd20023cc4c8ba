//! What autocomplete says once each sequence family is drawn to its end (accepting the
//! right ghosts on the way): `cargo run --release --example end_reason [wobble]`.
use patternsynth::vector::replay::replay_each;
use patternsynth::vector::sequences::sequences;

fn main() {
    let wobble: f64 = std::env::args().nth(1).and_then(|a| a.parse().ok()).unwrap_or(0.03);
    for seed in 1..=3 {
        for q in sequences(wobble, seed) {
            let classes = vec![0; q.strokes.len()];
            let tol: Vec<f64> = q.steps.iter().map(|s| 0.3 * s).collect();
            let past: Vec<_> = q.beyond.iter().map(|(b, step)| (b.clone(), 0.3 * step)).collect();
            let r = replay_each(&q.strokes, &classes, q.canvas, &tol, &past);
            println!("seed {seed} {}: {} by hand, {} accepted: {:?}", q.name, r.by_hand, r.accepted, r.end_reason);
        }
    }
}
