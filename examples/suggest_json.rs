//! Autocomplete on a drawing saved as JSON (an array of strokes as the package takes
//! them): `cargo run --release --example suggest_json drawing.json [x y w h]`.
use patternsynth::vector::{suggest_strokes, Stroke, SuggestOptions};

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let strokes: Vec<Stroke> = serde_json::from_str(&std::fs::read_to_string(&args[1]).unwrap()).unwrap();
    let r: Vec<f64> = args[2..].iter().filter_map(|a| a.parse().ok()).collect();
    let region = (r.len() == 4).then(|| [r[0], r[1], r[2], r[3]]);
    let s = match suggest_strokes(&strokes, &SuggestOptions { region, ..Default::default() }) {
        Ok(s) => s,
        Err(e) => {
            eprintln!("{e}");
            std::process::exit(1);
        }
    };
    for (g, src) in s.strokes.iter().zip(&s.sources) {
        let c = g.reference_point();
        let n = g.points.len().max(1) as f64;
        let mean = g.points.iter().fold([0.0, 0.0], |m, p| [m[0] + p[0] / n, m[1] + p[1] / n]);
        println!(
            "ghost of {src} at ({:.1}, {:.1}), {} points, mean ({:.1}, {:.1})",
            c.x,
            c.y,
            g.points.len(),
            mean[0],
            mean[1]
        );
    }
    println!("reason: {:?}", s.reason);
    println!("periods: {:?}", s.periods);
}
