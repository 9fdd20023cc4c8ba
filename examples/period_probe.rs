//! Prints what the period finder sees in an SVG example: strokes, classes, and the
//! periods and motif positions it finds (or that it finds none).
//!   cargo run --release --example period_probe -- example.svg
use patternsynth::vector::grow::{find_periods, Element};
use patternsynth::vector::{classify_strokes, parse_svg, ImportOptions};

fn main() {
    let path = std::env::args().nth(1).expect("an SVG file");
    let svg = std::fs::read_to_string(path).expect("readable");
    let strokes = parse_svg(&svg, &ImportOptions::default()).expect("an SVG").strokes;
    let t = std::time::Instant::now();
    let c = classify_strokes(&strokes, None, None, None).expect("strokes");
    println!("classified in {:?}", t.elapsed());
    let elems: Vec<Element> =
        strokes.iter().zip(&c.classes).map(|(s, &class)| Element { pos: s.reference_point(), class }).collect();
    println!("{} strokes, {} classes ({:?})", strokes.len(), c.count, c.tolerances);
    let t = std::time::Instant::now();
    match find_periods(&elems).expect("a spacing") {
        Some(p) => println!("periods {:?} {:?}, {} motif positions ({:?})", p.a, p.b, p.motifs.len(), t.elapsed()),
        None => println!("no periods ({:?})", t.elapsed()),
    }
    let b = strokes.iter().fold(kurbo::Rect::ZERO, |r, s| r.union(s.bounds()));
    let opts = patternsynth::vector::StrokeOptions {
        width: b.width() * 10.0 / 3.0,
        height: b.height() * 10.0 / 3.0,
        ..Default::default()
    };
    let t = std::time::Instant::now();
    let r = patternsynth::vector::synthesize_strokes(&strokes, &opts, &mut patternsynth::Silent).expect("synthesis");
    println!("synthesized {} strokes in {:?} (svg {} KB)", r.strokes.len(), t.elapsed(), r.svg.len() / 1000);
}
