//! Writes the playground's built-in example drawings (the generated families the engine
//! is tested on, and a busy tile) to www/features/strokes/shared/examples.json.
//! `tests/playground_examples.rs` checks the file against the generator.
//! cargo run --example export_examples
use patternsynth::vector::exemplar::playground_examples;

fn main() -> std::io::Result<()> {
    let json = serde_json::to_string(&playground_examples()).expect("strokes serialise");
    std::fs::write("www/features/strokes/shared/examples.json", json + "\n")
}
