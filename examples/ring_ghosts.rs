//! Ghosts after the first three and four copies of rings drawn by a person's hand
//! (issue 27): how many are shown, how many are wrong (further than 0.3 of the step
//! from every copy still to draw), over seeds 1-10.
//! `cargo run --release --example ring_ghosts [turn degrees, default 2.5]` (`REASONS=1`: what
//! each case with no ghost is told; `SIZE=0.1`: each petal 10% longer or shorter at random)
use kurbo::Point;
use patternsynth::vector::sequences::{composite, drawn_by, HandTurn};
use patternsynth::vector::{suggest_strokes, SuggestOptions};

fn main() {
    let turn: f64 = std::env::args().nth(1).and_then(|a| a.parse().ok()).unwrap_or(2.5);
    let verbose = std::env::var("VERBOSE").is_ok();
    let size: f64 = std::env::var("SIZE").ok().and_then(|v| v.parse().ok()).unwrap_or(0.0);
    // (REPLAY=name:seed:wobble replays that sequence alone, stroke by stroke.)
    if let Ok(r) = std::env::var("REPLAY") {
        let f: Vec<&str> = r.split(':').collect();
        let (seed, wobble): (u64, f64) = (f[1].parse().unwrap(), f[2].parse().unwrap());
        let hand = HandTurn(turn.to_radians());
        let q = drawn_by(wobble, hand, seed)
            .into_iter()
            .chain(composite(wobble, hand, seed))
            .find(|q| q.name == f[0])
            .unwrap();
        println!("{:?}", q.replay(&q.strokes));
        return;
    }
    // (ONLY=name:seed:wobble:copies for one case.)
    let only = std::env::var("ONLY").ok();
    let wanted = |name: &str, seed: u64, wobble: f64, drawn: usize| {
        only.as_deref().is_none_or(|o| o == format!("{name}:{seed}:{wobble}:{drawn}"))
    };
    println!("| wobble | copies drawn | cases | shown | wrong | cases with a wrong ghost |");
    println!("|---|---:|---:|---:|---:|---:|");
    for wobble in [0.01, 0.03, 0.05] {
        for drawn in [3usize, 4] {
            let (mut cases, mut shown, mut wrong, mut bad) = (0, 0, 0, 0);
            for seed in 1..=10 {
                let hand = HandTurn(turn.to_radians());
                let all = drawn_by(wobble, hand, seed).into_iter().chain(composite(wobble, hand, seed));
                for q in all.filter(|q| q.name.starts_with("ring") && wanted(&q.name, seed, wobble, drawn)) {
                    // (SIZE=s: each petal drawn s longer or shorter at random, a standard
                    // deviation, out from the ring's centre, as a person's petals vary.)
                    let q = if size > 0.0 { q.sized_about(Point::new(300.0, 300.0), size, seed) } else { q };
                    let n = drawn * q.parts;
                    let opts = SuggestOptions {
                        region: Some([q.canvas.x0, q.canvas.y0, q.canvas.width(), q.canvas.height()]),
                        ..SuggestOptions::default()
                    };
                    let s = suggest_strokes(&q.strokes[..n], &opts).unwrap();
                    if std::env::var("REASONS").is_ok() && s.strokes.is_empty() {
                        println!("  REASON {} seed {seed} w {wobble} drawn {drawn}: {:?}", q.name, s.reason);
                    }
                    if let Ok(path) = std::env::var("DUMP_JSON") {
                        std::fs::write(path, serde_json::to_string(&q.strokes[..n]).unwrap()).unwrap();
                    }
                    let misses: Vec<f64> = s.strokes.iter().map(|g| q.miss(n, g.reference_point()) / q.step).collect();
                    let w = misses.iter().filter(|&&m| m > 0.3).count();
                    cases += 1;
                    shown += misses.len();
                    wrong += w;
                    bad += usize::from(w > 0);
                    if verbose && w > 0 {
                        let m: Vec<String> = misses.iter().map(|m| format!("{m:.2}")).collect();
                        println!("  {} seed {seed}: misses {}", q.name, m.join(" "));
                    }
                }
            }
            println!("| {wobble} | {drawn} | {cases} | {shown} | {wrong} | {bad} |");
        }
    }
}
