//! Quality probe for tuning the texture search: mean patch energy over seeds, 128 -> 256,
//! for the four photographs, and the median time. `cargo run --release --example tune_texture`
//! (`BLEND=1`: the blends' band energies and repetition in the middle band instead).
//! Each photograph's figure is `energy / repetition (exemplar's own repetition) colour
//! distance`: repetition at shifts of 48 pixels or more (`energy::repetition`), and the
//! colour histogram's distance to the exemplar's (`energy::colour_distance`).
#[path = "support/textures.rs"]
mod textures;
use patternsynth::raster::codec::{decode_image, encode_png};
use patternsynth::raster::energy::{colour_distance, patch_energy, repetition};
use patternsynth::raster::synthesis::Schedule;
use patternsynth::raster::{blend_textures, synthesize_texture, BlendOptions, Image, TextureOptions};
use patternsynth::Silent;
use std::time::Instant;

/// Band energies of the blends (top vs A, bottom vs B, middle vs both) and their times.
fn blends(seeds: u64, side: usize) {
    for (a, b) in [("wood", "gravel"), ("brick", "grass")] {
        let (ea, eb) = (textures::load(a), textures::load(b));
        let band = side / 6;
        let mut sums = [0.0; 5];
        let mut times = Vec::new();
        for seed in 1..=seeds {
            let o = BlendOptions {
                base: TextureOptions { width: side, height: side, seed, ..Default::default() },
                ..Default::default()
            };
            let t = Instant::now();
            let out = blend_textures(&ea, &eb, &o, &mut Silent).unwrap();
            times.push(t.elapsed().as_secs_f64() * 1e3);
            if seed == 1 {
                std::fs::create_dir_all("out/tune").unwrap();
                std::fs::write(format!("out/tune/{a}-{b}.png"), encode_png(side, side, &out.data).unwrap()).unwrap();
            }
            let out = Image::from_rgba8(out.width, out.height, &out.data).unwrap();
            let mid = (side / 2 - band / 2, side / 2 + band / 2);
            sums[0] += patch_energy(&out, &ea, 200, (0, band), seed);
            sums[1] += patch_energy(&out, &eb, 200, (side - band, side), seed);
            sums[2] += patch_energy(&out, &ea, 200, mid, seed);
            sums[3] += patch_energy(&out, &eb, 200, mid, seed);
            sums[4] += repetition(&out, 24, seed);
        }
        times.sort_by(|a, b| a.total_cmp(b));
        let m = sums.map(|v| v / seeds as f64);
        println!(
            "{a}->{b}: top vs A {:.2}, bottom vs B {:.2}, middle vs A {:.2} / B {:.2}, repetition {:.3} | median {:.0} ms",
            m[0], m[1], m[2], m[3], m[4], times[times.len() / 2]
        );
    }
}

fn main() {
    let seeds: u64 = std::env::var("SEEDS").ok().and_then(|s| s.parse().ok()).unwrap_or(3);
    let side: usize = std::env::var("SIDE").ok().and_then(|s| s.parse().ok()).unwrap_or(256);
    if std::env::var("BLEND").is_ok() {
        return blends(seeds, side);
    }
    let mut all = 0.0;
    let mut times = Vec::new();
    let names: Vec<&str> = if std::env::var("ALL").is_ok() { textures::ALL.to_vec() } else { textures::TUNED.to_vec() };
    for &name in &names {
        let ex = textures::load(name);
        let mut sum = 0.0;
        let mut rep = 0.0;
        let mut colour = 0.0;
        for seed in 1..=seeds {
            let nb = std::env::var("NB").ok().and_then(|s| s.parse().ok()).unwrap_or(5);
            let schedule = match std::env::var("SCHEDULE").as_deref() {
                Ok("bands") => Schedule::Bands,
                Ok("scanline") => Schedule::Scanline,
                _ => Schedule::Auto,
            };
            let o =
                TextureOptions { width: side, height: side, seed, neighbourhood: nb, schedule, ..Default::default() };
            let t = Instant::now();
            let out = match std::env::var("REF") {
                // Another synthesizer's outputs, named <dir>/<name>-<seed>.png.
                Ok(dir) => {
                    let d = decode_image(&std::fs::read(format!("{dir}/{name}-{seed}.png")).unwrap()).unwrap();
                    Image::from_rgba8(d.width, d.height, &d.data).unwrap()
                }
                Err(_) => {
                    let out = synthesize_texture(&ex, &o, &mut Silent).unwrap();
                    Image::from_rgba8(out.width, out.height, &out.data).unwrap()
                }
            };
            times.push(t.elapsed().as_secs_f64() * 1e3);
            if seed == 1 {
                std::fs::create_dir_all("out/tune").unwrap();
                std::fs::write(format!("out/tune/{name}.png"), encode_png(side, side, &out.to_rgba8()).unwrap())
                    .unwrap();
            }
            sum += patch_energy(&out, &ex, 300, (0, side), seed);
            rep += repetition(&out, 48, seed);
            colour += colour_distance(&out, &ex);
        }
        let own = repetition(&ex, 48, 1);
        let n = seeds as f64;
        print!("{name} {:.2} / {:.3} ({own:.3}) {:.3}  ", sum / n, rep / n, colour / n);
        all += sum / n;
    }
    times.sort_by(|a, b| a.total_cmp(b));
    println!("| mean {:.2} | median {:.0} ms", all / names.len() as f64, times[times.len() / 2]);
}
