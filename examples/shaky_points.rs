//! Ghosts when every point of a stroke shakes (a mouse's jaggies, a tremor): each point
//! moved at random by `p` of the step (up to a fifth: hatching 9 apart drawn with a
//! pointer that shakes by 1.8) on top of the families' own wobble (1%), seeds
//! 1-10, every call from three copies on. `cargo run --release --example shaky_points`
//! (`FAMILY=spiral` for another family of `vector::sequences`).
use patternsynth::vector::sequences::{drawn_by, shaken, HandTurn};
use patternsynth::vector::{suggest_strokes, SuggestOptions};

fn main() {
    let only = std::env::var("FAMILY").unwrap_or_else(|_| "leaves on an arc".into());
    for p in [0.0, 0.01, 0.02, 0.03, 0.05, 0.1, 0.2] {
        let (mut calls, mut with, mut shown, mut wrong) = (0, 0, 0, 0);
        let mut reasons = std::collections::BTreeMap::<String, usize>::new();
        for seed in 1..=10 {
            let q = drawn_by(0.01, HandTurn::STEADY, seed).into_iter().find(|q| q.name == only).unwrap();
            let strokes = shaken(&q.strokes, p * q.step, seed + 100);
            let region = Some([q.canvas.x0, q.canvas.y0, q.canvas.width(), q.canvas.height()]);
            for n in 3 * q.parts..strokes.len() {
                let s = suggest_strokes(&strokes[..n], &SuggestOptions { region, ..Default::default() }).unwrap();
                calls += 1;
                with += usize::from(!s.strokes.is_empty());
                shown += s.strokes.len();
                wrong += s.strokes.iter().filter(|g| q.miss(n, g.reference_point()) > 0.3 * q.step).count();
                if s.strokes.is_empty() {
                    *reasons.entry(s.reason.unwrap_or_default().chars().take(40).collect()).or_default() += 1;
                }
            }
        }
        println!(
            "points shaken {p}: {with} of {calls} calls with ghosts, {shown} shown, {wrong} wrong; none: {reasons:?}"
        );
    }
}
