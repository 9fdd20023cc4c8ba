//! A replay family's strokes as JSON, to look at or to feed `suggest_json` and
//! `synth_json`: `dump_seq wobble hand_degrees seed "name" > out.json`.
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
    // (PEN_TAPS=1: each dot a pen tap of three to six points.)
    let strokes = if std::env::var("PEN_TAPS").is_ok() {
        patternsynth::vector::sequences::pen_taps(&q.strokes, seed)
    } else {
        q.strokes
    };
    println!("{}", serde_json::to_string(&strokes).unwrap());
}
