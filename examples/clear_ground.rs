//! Tiles and textures of pictures on a transparent ground (line art, stickers): how much
//! of the output is clear and how much inked against the picture, over seeds 1-3, and
//! each tile repeated 2 x 2 over white and over a checkerboard in `out/clear/`.
//!
//!   cargo run --release --example clear_ground -- [art.png ...]
//!
//! Without arguments, generated line art (wobbly rings of ink on a clear ground).

use patternsynth::raster::codec::{decode_image, encode_png};
use patternsynth::raster::{synthesize_texture, Image, Rgba, TextureOptions};
use patternsynth::seamless::measure::seam_score;
use patternsynth::seamless::{seamless_tile, SeamlessOptions};
use patternsynth::Silent;

#[path = "support/line_art.rs"]
mod line_art;
use line_art::line_art;

fn share(img: &Rgba, f: impl Fn(u8) -> bool) -> f64 {
    img.data.chunks_exact(4).filter(|p| f(p[3])).count() as f64 / (img.width * img.height) as f64
}

/// `img` repeated 2 x 2 over a checkerboard (left) and over white (right).
fn sheet(img: &Rgba) -> Rgba {
    let (w, h) = (img.width * 2, img.height * 2);
    let mut data = Vec::with_capacity(w * 2 * h * 4);
    for y in 0..h {
        for x in 0..2 * w {
            let p = &img.data[((y % img.height) * img.width + x % img.width) * 4..][..4];
            let ground = if x >= w {
                255.0
            } else if (x / 8 + y / 8) % 2 == 0 {
                200.0
            } else {
                150.0
            };
            let a = p[3] as f64 / 255.0;
            data.extend([0, 1, 2].map(|c| (p[c] as f64 * a + ground * (1.0 - a)).round() as u8));
            data.push(255);
        }
    }
    Rgba { width: 2 * w, height: h, data }
}

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let pictures: Vec<(String, Rgba)> = if args.is_empty() {
        (1..=3).map(|s| (format!("rings{s}"), line_art(128, 14, s))).collect()
    } else {
        args.iter()
            .map(|p| (p.rsplit('/').next().unwrap().to_string(), decode_image(&std::fs::read(p).unwrap()).unwrap()))
            .collect()
    };
    std::fs::create_dir_all("out/clear").unwrap();
    for (name, art) in &pictures {
        let (clear, inked) = (share(art, |a| a == 0), share(art, |a| a >= 128));
        print!("{name} ({}x{}): clear {clear:.3}, inked {inked:.3} |", art.width, art.height);
        for seed in 1..=std::env::var("SEEDS").ok().and_then(|s| s.parse().ok()).unwrap_or(3) {
            let tile = seamless_tile(art, &SeamlessOptions { seed, ..Default::default() }, &mut Silent).unwrap();
            let ex = Image::from_rgba8(art.width, art.height, &art.data).unwrap();
            let o = TextureOptions {
                width: (2 * art.width).min(384),
                height: (2 * art.height).min(384),
                seed,
                alphas: vec![Some(art.alpha())],
                ..Default::default()
            };
            let tex = synthesize_texture(&ex, &o, &mut Silent).unwrap();
            let t = &tile.image;
            // The alpha's seam score at the wrap, and at every other boundary (the tile
            // rolled so that boundary is the wrap): where the wrap ranks among them.
            let roll = |k: usize| -> f64 {
                let (w, h) = (t.width, t.height);
                let a: Vec<[u8; 3]> =
                    (0..w * h).map(|i| [t.data[(((i / w + k) % h) * w + (i % w + k) % w) * 4 + 3]; 3]).collect();
                seam_score(&a, w, h)
            };
            let wrap = roll(0);
            let mut inner: Vec<f64> = (1..t.width.min(t.height)).map(roll).collect();
            inner.sort_by(f64::total_cmp);
            let rank = inner.iter().filter(|&&v| v < wrap).count() as f64 / inner.len() as f64;
            print!(" alpha wrap {wrap:.2} (inner median {:.2}, rank {rank:.2})", inner[inner.len() / 2]);
            print!(
                " s{seed} tile {:.3}/{:.3} seam {:.2} texture {:.3}/{:.3} |",
                share(t, |a| a == 0),
                share(t, |a| a >= 128),
                tile.seam_score,
                share(&tex, |a| a == 0),
                share(&tex, |a| a >= 128)
            );
            // The tile rolled by half (its wrap through the middle), 3x, over white.
            let (w, h) = (t.width, t.height);
            let mut z = Vec::with_capacity(9 * w * h * 4);
            for y in 0..3 * h {
                for x in 0..3 * w {
                    let p = &t.data[(((y / 3 + h / 2) % h) * w + (x / 3 + w / 2) % w) * 4..][..4];
                    let [r, g, b] = patternsynth::raster::image::over_white([p[0], p[1], p[2]], p[3]);
                    z.extend([r, g, b, 255]);
                }
            }
            std::fs::write(format!("out/clear/{name}-wrap-s{seed}.png"), encode_png(3 * w, 3 * h, &z).unwrap())
                .unwrap();
            let s = sheet(t);
            std::fs::write(
                format!("out/clear/{name}-tile-s{seed}.png"),
                encode_png(s.width, s.height, &s.data).unwrap(),
            )
            .unwrap();
            let s = sheet(&tex);
            std::fs::write(
                format!("out/clear/{name}-texture-s{seed}.png"),
                encode_png(s.width, s.height, &s.data).unwrap(),
            )
            .unwrap();
        }
        let s = sheet(art);
        std::fs::write(format!("out/clear/{name}.png"), encode_png(s.width, s.height, &s.data).unwrap()).unwrap();
        println!();
    }
}
