//! What the motif model makes of a drawing: `motif_probe strokes.json` (an array of
//! strokes as the package takes them) prints its instances, kinds and classes.
use patternsynth::vector::{classify_strokes, Stroke};

fn main() {
    let path = std::env::args().nth(1).expect("a strokes JSON file");
    let strokes: Vec<Stroke> =
        serde_json::from_str(&std::fs::read_to_string(path).expect("readable")).expect("strokes");
    let t = std::time::Instant::now();
    let c = classify_strokes(&strokes, None, None, None).expect("strokes");
    println!(
        "{} strokes, {} instances, {} kinds, {} classes in {:?}",
        strokes.len(),
        c.motifs.instances.len(),
        c.kinds,
        c.count,
        t.elapsed()
    );
    println!("instances {:?}", &c.motifs.instances[..c.motifs.instances.len().min(12)]);
    // Synthesized to a square of `size` (second argument), variation on and off.
    if let Some(size) = std::env::args().nth(2).and_then(|a| a.parse::<f64>().ok()) {
        for variation in [true, false] {
            let opts =
                patternsynth::vector::StrokeOptions { width: size, height: size, variation, ..Default::default() };
            let r = patternsynth::vector::synthesize_strokes(&strokes, &opts, &mut patternsynth::Silent)
                .expect("synthesis");
            println!("variation {variation}: {} strokes", r.strokes.len());
        }
    }
}
