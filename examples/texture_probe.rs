//! Synthesizes and blends the fixture photographs and writes PNGs to out/ to look at,
//! with timings and patch energies.
use patternsynth::raster::codec::{decode_image, encode_png};
use patternsynth::raster::energy::{patch_energy, repetition};
use patternsynth::raster::{blend_textures, synthesize_texture, BlendOptions, Image, TextureOptions};
use patternsynth::Silent;
use std::time::Instant;

fn load(name: &str) -> Image {
    let bytes = std::fs::read(format!("tests/fixtures/textures/{name}.png")).unwrap();
    let d = decode_image(&bytes).unwrap();
    Image::from_rgba8(d.width, d.height, &d.data).unwrap()
}

fn save(img: &Image, name: &str) {
    std::fs::write(format!("out/{name}.png"), encode_png(img.width, img.height, &img.to_rgba8()).unwrap()).unwrap();
}

fn main() {
    std::fs::create_dir_all("out").unwrap();
    let exhaustive = std::env::args().any(|a| a == "--exhaustive");
    for name in ["wood", "brick", "grass", "gravel"] {
        let ex = load(name);
        let t = Instant::now();
        let nb: usize = std::env::var("NB").ok().and_then(|v| v.parse().ok()).unwrap_or(5);
        let levels: Option<usize> = std::env::var("LV").ok().and_then(|v| v.parse().ok());
        let out = synthesize_texture(
            &ex,
            &TextureOptions { width: 256, height: 256, exhaustive, neighbourhood: nb, levels, ..Default::default() },
            &mut Silent,
        )
        .unwrap();
        let ms = t.elapsed().as_secs_f64() * 1e3;
        println!(
            "{name}: {ms:.0} ms, patch energy {:.2}, repetition {:.3}",
            patch_energy(&out, &ex, 300, (0, 256), 1),
            repetition(&out, 24, 1)
        );
        save(&out, &format!("tex-{name}{}", if exhaustive { "-ex" } else { "" }));
    }
    let (a, b) = (load("brick"), load("grass"));
    let t = Instant::now();
    let out = blend_textures(
        &a,
        &b,
        &BlendOptions { width: 256, height: 256, exhaustive, ..Default::default() },
        &mut Silent,
    )
    .unwrap();
    let ms = t.elapsed().as_secs_f64() * 1e3;
    println!(
        "blend brick->grass: {ms:.0} ms, top vs A {:.2}, top vs B {:.2}, bottom vs A {:.2}, bottom vs B {:.2}",
        patch_energy(&out, &a, 200, (0, 48), 2),
        patch_energy(&out, &b, 200, (0, 48), 2),
        patch_energy(&out, &a, 200, (208, 256), 2),
        patch_energy(&out, &b, 200, (208, 256), 2)
    );
    save(&out, &format!("blend-brick-grass{}", if exhaustive { "-ex" } else { "" }));
}
