//! Synthesis of a drawing saved as JSON (an array of strokes as the package takes them):
//! `cargo run --release --example synth_json drawing.json [width height]`; prints the
//! structure found and the output's size, and writes out/synth_json.svg. With `CHAIN=1`,
//! also the chain read from the drawing (`vector::chain`) and the rings beside it.
use patternsynth::vector::{synthesize_strokes, Stroke, StrokeOptions};
use patternsynth::Silent;

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let strokes: Vec<Stroke> = serde_json::from_str(&std::fs::read_to_string(&args[1]).unwrap()).unwrap();
    let size: Vec<f64> = args[2..].iter().filter_map(|a| a.parse().ok()).collect();
    let (width, height) = if size.len() == 2 { (size[0], size[1]) } else { (800.0, 600.0) };
    let opts = StrokeOptions { width, height, ..Default::default() };
    let r = match synthesize_strokes(&strokes, &opts, &mut Silent) {
        Ok(r) => r,
        Err(e) => {
            eprintln!("{e}");
            std::process::exit(1);
        }
    };
    if std::env::var("CHAIN").is_ok() {
        use patternsynth::vector::chain;
        let show = |c: &chain::Chain| {
            let turn = c.step.turn().to_degrees();
            format!("members {:?}, companions {:?}, turn {turn:.1}°, closes {:?}", c.members, c.companions, c.closes)
        };
        match chain::find_or_ring(&strokes) {
            Some((c, whole)) => {
                eprintln!("chain{}: {}", if whole { "" } else { " (a ring among others of its shape)" }, show(&c));
                chain::rings_beside(&strokes, &c).iter().for_each(|b| eprintln!("  beside: {}", show(b)));
            }
            None => eprintln!("no chain"),
        }
    }
    println!("{:?}: {} strokes, periods {:?}", r.structure, r.strokes.len(), r.periods);
    std::fs::create_dir_all("out").unwrap();
    std::fs::write("out/synth_json.svg", r.svg.replace("stroke=\"none\"", "stroke=\"black\"")).unwrap();
}
