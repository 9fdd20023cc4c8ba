//! Scratch: a replay family's strokes as JSON: dump_seq wobble hand_deg seed "name" > out.json
fn main() {
    let a: Vec<String> = std::env::args().collect();
    let (w, h, seed): (f64, f64, u64) = (a[1].parse().unwrap(), a[2].parse().unwrap(), a[3].parse().unwrap());
    let hand = patternsynth::vector::sequences::HandTurn(h.to_radians());
    let q = patternsynth::vector::sequences::drawn_by(w, hand, seed)
        .into_iter()
        .chain(patternsynth::vector::sequences::composite(w, hand, seed))
        .chain(patternsynth::vector::sequences::along_drawn(w, hand, seed))
        .find(|q| q.name == a[4])
        .unwrap();
    println!("{}", serde_json::to_string(&q.strokes).unwrap());
}
