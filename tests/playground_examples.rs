//! The playground's example drawings (a static JSON file, so the shipped library carries
//! no generator) are exactly what the generator makes: regenerate them with
//! `cargo run --example export_examples` after changing `exemplar`.
use patternsynth::vector::exemplar::{playground_examples, NamedExample};

#[test]
fn the_json_file_is_the_generators_output() {
    let text = std::fs::read_to_string("www/features/strokes/shared/examples.json").expect("the examples file");
    let file: Vec<NamedExample> = serde_json::from_str(&text).expect("valid JSON of named stroke lists");
    let made = playground_examples();
    let names = |v: &[NamedExample]| v.iter().map(|e| e.name.clone()).collect::<Vec<_>>();
    assert_eq!(names(&file), names(&made), "run `cargo run --example export_examples`");
    for (f, m) in file.iter().zip(&made) {
        assert_eq!(f.strokes, m.strokes, "{}: run `cargo run --example export_examples`", f.name);
    }
    assert!(made.iter().any(|e| e.name == "classes-by-shape"), "the page starts on this one");
}
