//! Tile quality by method (issue 25): for each fixture photograph and seeds 1-3, the
//! seamless tile of E-TFMCM as the paper makes it, E-TFMCM refined by toroidal
//! synthesis (the default), and toroidal synthesis alone: patch energy against the
//! photograph, colour distance,
//! repetition and seam score, means over the seeds, as a Markdown table; each seed-1
//! tile saved repeated 2 x 2 in out/tiles/ to look at.
//! `cargo run --release --example tile_quality [size] [fixture|all|path.png ...]`
#[path = "support/textures.rs"]
mod textures;
use patternsynth::raster::energy::{colour_distance, patch_energy, repetition};
use patternsynth::raster::Image;
use patternsynth::seamless::{seamless_tile, Method, SeamlessOptions};
use patternsynth::Silent;

fn image(r: &patternsynth::raster::Rgba) -> Image {
    Image::from_rgba8(r.width, r.height, &r.data).unwrap()
}

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let size: Option<usize> = args.get(1).and_then(|s| s.parse().ok());
    let names: Vec<String> = match args.get(2..) {
        Some(rest) if !rest.is_empty() => rest.iter().flat_map(|a| textures::named(a)).collect(),
        _ => textures::named("all"),
    };
    std::fs::create_dir_all("out/tiles").unwrap();
    let methods: [(&str, Method, bool); 3] = [
        ("etfmcm (paper)", Method::Etfmcm, false),
        ("etfmcm refined", Method::Etfmcm, true),
        ("synthesis", Method::Synthesis, true),
    ];
    println!("| exemplar | method | energy | colour | repetition (exemplar) | seam |");
    println!("|---|---|---:|---:|---:|---:|");
    for name in &names {
        // A fixture's name, or the path of any PNG or JPEG.
        let img = if name.contains('/') {
            patternsynth::raster::codec::decode_image(&std::fs::read(name).unwrap()).unwrap()
        } else {
            textures::rgba(name)
        };
        for (label, method, refine) in methods {
            let (mut e, mut c, mut r, mut s, mut own) = (0.0, 0.0, 0.0, 0.0, 0.0);
            for seed in 1..=3u64 {
                let opts = SeamlessOptions { method, size, seed, refine, ..Default::default() };
                let t = seamless_tile(&img, &opts, &mut Silent).unwrap();
                let out = image(&t.image);
                let ex = image(&img);
                e += patch_energy(&out, &ex, 300, (0, out.height), 1);
                c += colour_distance(&out, &ex);
                r += repetition(&out, 24.min(out.width / 4), 1);
                own += repetition(&ex, 24.min(ex.width / 4), 1);
                s += t.seam_score;
                if seed == 1 {
                    let stem = name.rsplit('/').next().unwrap_or(name).trim_end_matches(".png");
                    textures::save_repeated(
                        &t.image,
                        &format!("out/tiles/{stem}-{}.png", label.replace([' ', '(', ')'], "")),
                    );
                }
            }
            println!(
                "| {name} | {label} | {:.2} | {:.3} | {:.3} ({:.3}) | {:.2} |",
                e / 3.0,
                c / 3.0,
                r / 3.0,
                own / 3.0,
                s / 3.0
            );
        }
    }
}
