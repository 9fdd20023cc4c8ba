//! How often synthesis reads a hand-drawn ring's count right (issue 27): the first three
//! and four petals of rings of 5-12 (`vector::sequences`), at 3% and 5% of the step,
//! seeds 1-10; `chain::find`'s count against the drawn ring's.
//! `cargo run --release --example ring_count [hand's turn, degrees: 2.5 for a person's]`
use patternsynth::vector::chain::find;
use patternsynth::vector::sequences::{drawn_by, HandTurn};

fn main() {
    let turn: f64 = std::env::args().nth(1).and_then(|a| a.parse().ok()).unwrap_or(0.0);
    println!("| wobble | drawn | right | no chain | a chain, no ring | wrong count |");
    println!("|---|---:|---:|---:|---:|---:|");
    for wobble in [0.01, 0.03, 0.05] {
        for drawn in [3usize, 4] {
            let (mut right, mut none, mut open, mut wrong) = (0, 0, 0, 0);
            for seed in 1..=10 {
                for q in drawn_by(wobble, HandTurn(turn.to_radians()), seed)
                    .into_iter()
                    .filter(|q| q.name.starts_with("ring"))
                {
                    let n: usize = q.name.trim_start_matches("ring of ").parse().unwrap();
                    let found = find(&q.strokes[..drawn]).map(|c| c.closes);
                    if std::env::var("VERBOSE").is_ok() && found != Some(Some(n)) {
                        eprintln!("  {wobble} {drawn} drawn, {} seed {seed}: {found:?}", q.name);
                    }
                    match found {
                        Some(Some(k)) if k == n => right += 1,
                        Some(Some(_)) => wrong += 1,
                        Some(None) => open += 1,
                        None => none += 1,
                    }
                }
            }
            println!("| {wobble} | {drawn} | {right} | {none} | {open} | {wrong} |");
        }
    }
}
