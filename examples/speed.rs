//! Native side of the speed benchmark (`bench/speed.mjs`): median milliseconds of
//! `synthesize_texture` from a 128 x 128 crop of a fixture photograph to SIDE x SIDE,
//! one thread, as one JSON line per size. `cargo run --release --example speed -- 256 1024`
//! (`RUNS=n` runs per size, 5 by default; `FIXTURE=name`, gravel by default; `TILEABLE=1`
//! for tiles; `FUSE=0` without seam fusion, `FUSE=both` each in turn, interleaved; `HASH=1`
//! adds an FNV-1a hash of the last output's bytes, to show that a faster build makes the
//! same image).
use patternsynth::raster::codec::decode_image;
use patternsynth::raster::{synthesize_texture, Image, TextureOptions};
use patternsynth::Silent;
use std::time::Instant;

fn main() {
    let fixture = std::env::var("FIXTURE").unwrap_or_else(|_| "gravel".into());
    let runs: usize = std::env::var("RUNS").ok().and_then(|s| s.parse().ok()).unwrap_or(5);
    let rgba = decode_image(&std::fs::read(format!("tests/fixtures/textures/{fixture}.png")).unwrap()).unwrap();
    let full = Image::from_rgba8(rgba.width, rgba.height, &rgba.data).unwrap();
    let side = 128.min(full.width).min(full.height);
    let mut ex = Image::new(side, side);
    for y in 0..side {
        for x in 0..side {
            ex.data[y * side + x] = full.at(x, y);
        }
    }
    // A first call, untimed, as the wasm side makes (its allocations and caches warm).
    std::hint::black_box(
        synthesize_texture(&ex, &TextureOptions { width: 64, height: 64, ..Default::default() }, &mut Silent).unwrap(),
    );
    for arg in std::env::args().skip(1) {
        let out: usize = arg.parse().expect("sizes in pixels");
        let tileable = std::env::var("TILEABLE").is_ok_and(|v| v == "1");
        let fuse = std::env::var("FUSE").unwrap_or_default();
        let variants: Vec<bool> = match fuse.as_str() {
            "0" => vec![false],
            "both" => vec![true, false],
            _ => vec![true],
        };
        let mut ms = vec![Vec::new(); variants.len()];
        let mut hash = vec![0u64; variants.len()];
        for _ in 0..runs {
            for (k, &fuse_seams) in variants.iter().enumerate() {
                let opts =
                    TextureOptions { width: out, height: out, seed: 1, tileable, fuse_seams, ..Default::default() };
                let t = Instant::now();
                let image = std::hint::black_box(synthesize_texture(&ex, &opts, &mut Silent).unwrap());
                ms[k].push(t.elapsed().as_secs_f64() * 1e3);
                hash[k] = image
                    .data
                    .iter()
                    .fold(0xcbf2_9ce4_8422_2325u64, |h, &b| (h ^ u64::from(b)).wrapping_mul(0x100_0000_01b3));
            }
        }
        for (k, fuse_seams) in variants.iter().enumerate() {
            ms[k].sort_by(f64::total_cmp);
            let hashed = if std::env::var("HASH").is_ok_and(|v| v == "1") {
                format!(",\"hash\":\"{:016x}\"", hash[k])
            } else {
                String::new()
            };
            println!(
                "{{\"fixture\":\"{fixture}\",\"tileable\":{tileable},\"fused\":{fuse_seams},\"side\":{out},\"runs\":{runs},\"ms\":{:.1}{hashed}}}",
                ms[k][runs / 2]
            );
        }
    }
}
