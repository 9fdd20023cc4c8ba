//! A replay family's strokes as JSON, to look at or to feed `suggest_json` and
//! `synth_json`: `dump_seq wobble hand_degrees seed "name" > out.json` ("6 circles": a
//! ring of six circles).
fn main() {
    let a: Vec<String> = std::env::args().collect();
    let (w, h, seed): (f64, f64, u64) = (a[1].parse().unwrap(), a[2].parse().unwrap(), a[3].parse().unwrap());
    // ("N circles": a ring of N circles of radius 12, 90 round, `sequences::circle_ring`.)
    if let Some(n) = a[4].strip_suffix(" circles").and_then(|n| n.parse().ok()) {
        let (strokes, _) = patternsynth::vector::sequences::circle_ring(n, 90.0, 12.0, w, seed);
        println!("{}", serde_json::to_string(&strokes).unwrap());
        return;
    }
    let hand = patternsynth::vector::sequences::HandTurn(h.to_radians());
    let q = patternsynth::vector::sequences::drawn_by(w, hand, seed)
        .into_iter()
        .chain(patternsynth::vector::sequences::composite(w, hand, seed))
        .chain(patternsynth::vector::sequences::along_drawn(w, hand, seed))
        .find(|q| q.name == a[4])
        .unwrap();
    // (PEN_TAPS=1: each dot a pen tap of three to six points.)
    let strokes = if std::env::var("PEN_TAPS").is_ok() {
        patternsynth::vector::sequences::pen_taps(&q.strokes, seed)
    } else {
        q.strokes
    };
    println!("{}", serde_json::to_string(&strokes).unwrap());
}
