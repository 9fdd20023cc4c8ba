//! Looks at issue 30's verbs on one photograph (a PNG path or a fixture name): writes
//! out/fill/<name>-*.png and prints time and patch energy of what was made.
//! `cargo run --release --example fill_probe -- <photo> [seed]`.
#[path = "support/textures.rs"]
mod textures;

use patternsynth::raster::codec::{decode_image, encode_png};
use patternsynth::raster::energy::patch_energy;
use patternsynth::raster::{
    inpaint_texture, synthesize_textures, transfer_style, Guides, Image, InpaintOptions, Rgba, StyleOptions,
    TextureOptions,
};
use patternsynth::seamless::measure::seam_score;
use patternsynth::seamless::mend::mend;
use std::time::Instant;

fn save(img: &Rgba, path: &str) {
    std::fs::write(path, encode_png(img.width, img.height, &img.data).unwrap()).unwrap();
}

fn image(r: &Rgba) -> Image {
    Image::from_rgba8(r.width, r.height, &r.data).unwrap()
}

fn main() {
    let arg = std::env::args().nth(1).unwrap_or("brick".into());
    let seed: u64 = std::env::args().nth(2).and_then(|s| s.parse().ok()).unwrap_or(1);
    let photo =
        if arg.ends_with(".png") { decode_image(&std::fs::read(&arg).unwrap()).unwrap() } else { textures::rgba(&arg) };
    let name = std::path::Path::new(&arg).file_stem().unwrap().to_string_lossy().to_string();
    std::fs::create_dir_all("out/fill").unwrap();
    let (w, h) = (photo.width, photo.height);
    let none = &mut |_| true;

    // A hole: a disc in the middle, a quarter of the short side across, and a bar.
    let r = w.min(h) as f64 / 8.0;
    let mask: Vec<bool> = (0..w * h)
        .map(|i| {
            let (x, y) = ((i % w) as f64, (i / w) as f64);
            (x - w as f64 / 2.0).hypot(y - h as f64 / 2.0) < r
                || ((y - h as f64 * 0.75).abs() < r / 4.0 && x > w as f64 * 0.1 && x < w as f64 * 0.6)
        })
        .collect();
    let mut holed = photo.clone();
    for (i, &m) in mask.iter().enumerate() {
        if m {
            holed.data[4 * i..4 * i + 4].copy_from_slice(&[255, 0, 255, 255]);
        }
    }
    save(&holed, &format!("out/fill/{name}-hole.png"));
    let t = Instant::now();
    let filled = inpaint_texture(&photo, &mask, &InpaintOptions { seed, ..Default::default() }, none).unwrap();
    let ms = t.elapsed().as_secs_f64() * 1e3;
    save(&filled, &format!("out/fill/{name}-filled.png"));
    let kept = mask
        .iter()
        .enumerate()
        .filter(|(_, &m)| !m)
        .all(|(i, _)| filled.data[4 * i..4 * i + 4] == photo.data[4 * i..4 * i + 4]);
    let rows = ((h / 2) - r as usize, (h / 2) + r as usize);
    let e = patch_energy(&image(&filled), &image(&photo), 400, rows, 7);
    println!("inpaint {w}x{h}: {ms:.0} ms, kept pixels identical: {kept}, energy of the disc's rows {e:.2}");

    // Mend into a tile.
    for band in [0.125, 0.25, 0.375] {
        let t = Instant::now();
        let tile = mend(&photo, band, None, seed, none).unwrap();
        let ms = t.elapsed().as_secs_f64() * 1e3;
        println!(
            "mend band {band}: {ms:.0} ms, seam {:.2} (photo's own wrap {:.2})",
            seam_score(&tile.rgb(), w, h),
            seam_score(&photo.rgb(), w, h)
        );
        textures::save_repeated(&tile, &format!("out/fill/{name}-mend-{band}.png"));
    }
    textures::save_repeated(&photo, &format!("out/fill/{name}-repeated.png"));

    // A sample mask: the left half kept out.
    let ex = image(&photo);
    let left: Vec<bool> = (0..w * h).map(|i| i % w >= w / 2).collect();
    let o = TextureOptions {
        width: 2 * w,
        height: 2 * h,
        seed,
        keep_layout: true,
        sample_masks: vec![Some(left)],
        ..Default::default()
    };
    let s = synthesize_textures(std::slice::from_ref(&ex), &o, none).unwrap();
    let from_left = s.layout.as_ref().unwrap().data.iter().filter(|&&v| (v & 0xFFF) < (w / 2) as u32).count();
    println!("sample mask (left half out): {from_left} output pixels from the left half");
    save(&s.image, &format!("out/fill/{name}-right-only.png"));

    // A guide: the exemplar's left-to-right ramp; the target a disc.
    let ramp =
        Image { width: w, height: h, data: (0..w * h).map(|i| [255.0 * (i % w) as f32 / w as f32; 3]).collect() };
    let (tw, th) = (2 * w, 2 * h);
    let disc = Image {
        width: tw,
        height: th,
        data: (0..tw * th)
            .map(|i| {
                let (x, y) = ((i % tw) as f32 - tw as f32 / 2.0, (i / tw) as f32 - th as f32 / 2.0);
                [if x.hypot(y) < tw as f32 / 4.0 { 255.0 } else { 0.0 }; 3]
            })
            .collect(),
    };
    let o = TextureOptions {
        width: tw,
        height: th,
        seed,
        guides: Some(Guides { exemplars: vec![ramp], target: disc, weight: 1.0 }),
        ..Default::default()
    };
    let t = Instant::now();
    let g = synthesize_textures(std::slice::from_ref(&ex), &o, none).unwrap();
    println!("guided {tw}x{th}: {:.0} ms", t.elapsed().as_secs_f64() * 1e3);
    save(&g.image, &format!("out/fill/{name}-guided.png"));

    // Style: the photo's texture in the layout of a fixture (wood).
    let target = textures::load("moon");
    let t = Instant::now();
    let st = transfer_style(&ex, &target, &StyleOptions { seed, ..Default::default() }, none).unwrap();
    println!("style onto moon: {:.0} ms", t.elapsed().as_secs_f64() * 1e3);
    save(&st, &format!("out/fill/{name}-style.png"));
}
