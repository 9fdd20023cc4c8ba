//! Mean difference across each line boundary (columns and rows together; `ONLY=rows` or
//! `ONLY=cols` for one direction) over seeds 1-8, relative to the mean over all
//! boundaries, and the mean patch energy: shows whether the wrap stands out from the
//! lines inside. Saves seed 1's tile repeated 2 x 2 as out/seam-<exemplar>-<method>.png.
//! `cargo run --release --example seam_profile <exemplar|all> <etfmcm|tfmcm|synthesis|bands> [size]`
//! (`bands`: a tileable synthesis in the banded schedule, which workers share; `mend`: the
//! fixture mended into a tile, its band `BAND`, default 0.25.)
#[path = "support/textures.rs"]
mod textures;
use patternsynth::raster::energy::patch_energy;
use patternsynth::raster::synthesis::Schedule;
use patternsynth::raster::{synthesize_texture, Image, TextureOptions};
use patternsynth::seamless::{seamless_tile, SeamlessOptions};
use patternsynth::Silent;

fn main() {
    let a: Vec<String> = std::env::args().collect();
    let (names, method) = (textures::named(&a[1]), textures::method(&a[2]));
    let size = a.get(3).and_then(|s| s.parse().ok());
    let mut prof: Vec<f64> = Vec::new();
    let (mut energy, mut runs) = (0.0, 0);
    for name in &names {
        let img = textures::rgba(name);
        let mut one: Vec<f64> = Vec::new();
        for seed in 1..=8 {
            // "bands": a tileable synthesis in the banded schedule.
            let image = if a[2] == "bands" {
                let ex = Image::from_rgba8(img.width, img.height, &img.data).unwrap();
                let side = size.unwrap_or(256);
                let o = TextureOptions {
                    width: side,
                    height: side,
                    seed,
                    tileable: true,
                    schedule: Schedule::Bands,
                    ..Default::default()
                };
                synthesize_texture(&ex, &o, &mut Silent).unwrap()
            } else if a[2] == "mend" {
                let band = std::env::var("BAND").ok().and_then(|b| b.parse().ok()).unwrap_or(0.25);
                patternsynth::seamless::mend::mend(&img, band, None, seed, &mut Silent).unwrap()
            } else {
                seamless_tile(&img, &SeamlessOptions { method, size, seed, ..Default::default() }, &mut Silent)
                    .unwrap()
                    .image
            };
            let n = image.width;
            if seed == 1 {
                let stem = std::path::Path::new(name).file_stem().unwrap().to_string_lossy();
                textures::save_repeated(&image, &format!("out/seam-{stem}-{}.png", a[2]));
            }
            let out = Image::from_rgba8(n, n, &image.data).unwrap();
            energy += patch_energy(&out, &textures::load(name), 200, (0, n), seed);
            runs += 1;
            if one.is_empty() {
                one = vec![0.0; n];
            }
            let px = |x: usize, y: usize| &image.data[((y % n) * n + x % n) * 4..][..3];
            let d = |p: &[u8], q: &[u8]| (0..3).map(|c| (p[c] as f64 - q[c] as f64).abs()).sum::<f64>();
            let only = std::env::var("ONLY").unwrap_or_default();
            for (b, sum) in one.iter_mut().enumerate() {
                for i in 0..n {
                    let (col, row) = (d(px(b, i), px(b + 1, i)), d(px(i, b), px(i, b + 1)));
                    *sum += match only.as_str() {
                        "cols" => col,
                        "rows" => row,
                        _ => col + row,
                    };
                }
            }
        }
        let m = one.iter().sum::<f64>() / one.len() as f64;
        if prof.is_empty() {
            prof = vec![0.0; one.len()];
        }
        prof.iter_mut().zip(&one).for_each(|(p, o)| *p += o / m);
    }
    let n = prof.len();
    let mean = prof.iter().sum::<f64>() / n as f64;
    let rel: Vec<f64> = prof.iter().map(|v| v / mean).collect();
    println!("patch energy {:.3}", energy / runs as f64);
    println!(
        "wrap {:.3}  half {:.3}  quarter {:.3} {:.3}",
        rel[n - 1],
        rel[n / 2 - 1],
        rel[n / 4 - 1],
        rel[3 * n / 4 - 1]
    );
    let show: Vec<String> = (0..6).chain(n - 6..n).map(|b| format!("{b}:{:.2}", rel[b])).collect();
    println!("{}", show.join(" "));
    let mut s = rel.clone();
    s.sort_by(|a, b| a.total_cmp(b));
    let mut top: Vec<usize> = (0..n).collect();
    top.sort_by(|&a, &b| rel[b].total_cmp(&rel[a]));
    println!("top: {}", top[..12].iter().map(|&b| format!("{b}:{:.2}", rel[b])).collect::<Vec<_>>().join(" "));
    println!("p10 {:.3} p50 {:.3} p90 {:.3} max {:.3}", s[n / 10], s[n / 2], s[9 * n / 10], s[n - 1]);
}
