//! Writes the synthesized SVG of every exemplar family (and an irregular example) to
//! out/, with each family's seamless tile (`<name>-tile.svg`), to look at:
//! `cargo run --release --example export_svgs`, then e.g.
//! `node scripts/render-svg.mjs --tile out/tiles.png out/*-tile.svg`.
use patternsynth::vector::exemplar::{families, irregular_dashes};
use patternsynth::vector::svg::to_svg;
use patternsynth::vector::{stroke_tile, synthesize_strokes, Stroke, StrokeOptions, TileOptions};
use patternsynth::Silent;

fn main() -> std::io::Result<()> {
    std::fs::create_dir_all("out")?;
    let mut sets: Vec<(String, Vec<Stroke>)> =
        families(0.02, 11).into_iter().map(|e| (e.name.to_string(), e.strokes)).collect();
    sets.push(("irregular".into(), irregular_dashes(40, 150.0, 5)));
    for (name, strokes) in sets {
        let r = synthesize_strokes(
            &strokes,
            &StrokeOptions { width: 480.0, height: 400.0, ..Default::default() },
            &mut Silent,
        )
        .expect("synthesis");
        std::fs::write(format!("out/{name}.svg"), &r.svg)?;
        if let Ok(t) = stroke_tile(&strokes, &TileOptions { repeats: 2, ..Default::default() }) {
            std::fs::write(format!("out/{name}-tile.svg"), &t.svg)?;
        }
        std::fs::write(format!("out/{name}-example.svg"), to_svg(&strokes, &[], 480.0, 400.0))?;
    }
    Ok(())
}
