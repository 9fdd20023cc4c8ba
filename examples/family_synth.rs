//! Synthesis of the first strokes of a replay family (`vector::sequences`): what a
//! person gets who draws that many and presses the button, with the default options.
//! `cargo run --release --example family_synth -- "leaves on an S-curve" 6 [wobble]
//! [seed] [width height]` (FROM=k: the strokes from the k-th on): prints the structure found and the output's size, and writes
//! out/family_synth.svg (the drawn strokes over it in red, where the output centres
//! them). HAND_TURN as for replay_suggest.
use patternsynth::vector::sequences::{along_drawn, composite, drawn_by, HandTurn};
use patternsynth::vector::{synthesize_strokes, StrokeOptions};
use patternsynth::Silent;

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let name = &args[1];
    let n: usize = args[2].parse().unwrap();
    let wobble: f64 = args.get(3).and_then(|a| a.parse().ok()).unwrap_or(0.03);
    let seed: u64 = args.get(4).and_then(|a| a.parse().ok()).unwrap_or(1);
    let (width, height) = match (args.get(5), args.get(6)) {
        (Some(w), Some(h)) => (w.parse().unwrap(), h.parse().unwrap()),
        _ => (800.0, 600.0),
    };
    let turn = std::env::var("HAND_TURN").ok().and_then(|t| t.parse::<f64>().ok()).unwrap_or(0.0).to_radians();
    let hand = HandTurn(turn);
    let q = drawn_by(wobble, hand, seed)
        .into_iter()
        .chain(composite(wobble, hand, seed))
        .chain(along_drawn(wobble, hand, seed))
        .find(|q| &q.name == name)
        .unwrap_or_else(|| panic!("no family {name}"));
    let from: usize = std::env::var("FROM").ok().and_then(|f| f.parse().ok()).unwrap_or(0);
    let drawn = &q.strokes[from..(from + n).min(q.strokes.len())];
    let opts = StrokeOptions { width, height, ..Default::default() };
    let r = synthesize_strokes(drawn, &opts, &mut Silent).unwrap();
    if std::env::var("CHAIN").is_ok() {
        match patternsynth::vector::chain::find_or_ring(drawn) {
            Some((c, whole)) => eprintln!(
                "chain (whole {whole}): members {:?}, turn {:.1}°, scale {:.3}, closes {:?}",
                c.members,
                c.step.turn().to_degrees(),
                c.step.scale(),
                c.closes
            ),
            None => eprintln!("no chain"),
        }
    }
    if std::env::var("PLACES").is_ok() {
        for (s, from) in r.strokes.iter().zip(&r.sources).take(n + 12) {
            let c = s.reference_point();
            eprintln!("  from {from}: ({:.0}, {:.0})", c.x, c.y);
        }
    }
    println!("{name}, {n} drawn, seed {seed}: {:?}, {} strokes, periods {:?}", r.structure, r.strokes.len(), r.periods);
    std::fs::create_dir_all("out").unwrap();
    // (The drawn strokes over the output in red, where the output centres them.)
    let bounds = drawn.iter().skip(1).fold(drawn[0].bounds(), |b, s| b.union(s.bounds()));
    let v = kurbo::Point::new(width / 2.0, height / 2.0) - bounds.center();
    let red: String = drawn
        .iter()
        .map(|s| {
            let pts: Vec<String> = s.points.iter().map(|p| format!("{:.1},{:.1}", p[0] + v.x, p[1] + v.y)).collect();
            format!("<polyline points=\"{}\" fill=\"none\" stroke=\"red\" stroke-width=\"2\"/>", pts.join(" "))
        })
        .collect();
    let svg = r.svg.replace("stroke=\"none\"", "stroke=\"black\"").replace("</svg>", &format!("{red}</svg>"));
    std::fs::write("out/family_synth.svg", svg).unwrap();
}
