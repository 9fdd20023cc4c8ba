//! Writes one family's synthesis at a given size to out/<name>-<size>.svg.
use patternsynth::vector::exemplar::families;
use patternsynth::vector::{synthesize_strokes, StrokeOptions};
use patternsynth::Silent;
fn main() {
    let args: Vec<String> = std::env::args().collect();
    let (name, size): (&str, f64) = (&args[1], args[2].parse().unwrap());
    let ex = families(0.02, 11).into_iter().find(|e| e.name == name).unwrap();
    let r = synthesize_strokes(
        &ex.strokes,
        &StrokeOptions { width: size, height: size, ..Default::default() },
        &mut Silent,
    )
    .unwrap();
    std::fs::write(format!("out/{name}-{size}.svg"), r.svg).unwrap();
}
