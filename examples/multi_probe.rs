//! Several exemplars as one pool: patch energy of 256² outputs drawn from three quarter
//! crops of each photograph in a folder (top left, top right, bottom middle, as
//! bench/peer-verbs.mjs makes them), against all three; and from the first crop alone;
//! with each, repetition in windows of a crop's size (`energy::repetition_fair`) and the
//! crops' own. `WHOLE=1`: plain synthesis from each whole photograph instead.
//! `LEVELS=n` and `NEIGHBOURHOOD=n` set those options. Outputs of seed 1 go to out/multi/.
//! `cargo run --release --example multi_probe -- [folder] [seeds]`
#[path = "support/textures.rs"]
mod textures;
use patternsynth::raster::codec::encode_png;
use patternsynth::raster::energy::{patch_energy_pool, repetition_fair};
use patternsynth::raster::{synthesize_textures, Image, TextureOptions};
use patternsynth::Silent;

fn crop(img: &Image, x0: usize, y0: usize, w: usize, h: usize) -> Image {
    let data = (0..h)
        .flat_map(|y| (0..w).map(move |x| (x, y)))
        .map(|(x, y)| img.data[(y0 + y) * img.width + x0 + x])
        .collect();
    Image { width: w, height: h, data }
}

/// The least shift at which repetition is measured in windows of `window`: 24 pixels in
/// a quarter crop's (112), 48 in a photograph's (224).
fn shift(window: (usize, usize)) -> usize {
    if window.0.min(window.1) < 160 {
        24
    } else {
        48
    }
}

/// The options for one seed, with the environment's `LEVELS` and `NEIGHBOURHOOD`.
fn options(side: usize, seed: u64) -> TextureOptions {
    let mut o = TextureOptions { width: side, height: side, seed, ..Default::default() };
    if let Ok(v) = std::env::var("NEIGHBOURHOOD") {
        o.neighbourhood = v.parse().unwrap();
    }
    if let Ok(v) = std::env::var("LEVELS") {
        o.levels = Some(v.parse().unwrap());
    }
    o
}

/// A synthesis from `exemplars` as an engine image.
fn synthesize(exemplars: &[Image], o: &TextureOptions) -> Image {
    let r = synthesize_textures(exemplars, o, &mut Silent).unwrap().image;
    Image::from_rgba8(r.width, r.height, &r.data).unwrap()
}

/// Mean patch energy (against `pool`) and repetition (in windows of `window`) of
/// syntheses from `exemplars` over seeds 1..=`seeds`; seed 1's output saved as `save`.
fn measure(exemplars: &[Image], pool: &[&Image], window: (usize, usize), seeds: u64, save: &str) -> (f64, f64) {
    let side = 256;
    let (mut e, mut r) = (0.0, 0.0);
    for seed in 1..=seeds {
        let out = synthesize(exemplars, &options(side, seed));
        e += patch_energy_pool(&out, pool, 300, (0, side), seed);
        r += repetition_fair(&out, window, shift(window), 8, seed);
        if seed == 1 {
            std::fs::create_dir_all("out/multi").unwrap();
            std::fs::write(save, encode_png(side, side, &out.to_rgba8()).unwrap()).unwrap();
        }
    }
    (e / seeds as f64, r / seeds as f64)
}

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let dir = args.get(1).map_or("/tmp/peer30/data", |s| s.as_str());
    let seeds: u64 = args.get(2).map_or(2, |s| s.parse().unwrap());
    let whole = std::env::var("WHOLE").is_ok();
    let mut names: Vec<String> = std::fs::read_dir(dir)
        .unwrap()
        .filter_map(|e| e.ok()?.file_name().into_string().ok())
        .filter(|n| n.ends_with(".png") && n.matches('.').count() == 1)
        .collect();
    names.sort();
    // Per photograph: (energy, repetition) of each measured synthesis, then the own
    // repetition.
    let mut sums = [0.0f64; 5];
    for name in &names {
        let photo = textures::load(&format!("{dir}/{name}"));
        let row = if whole {
            let size = (photo.width, photo.height);
            let (e, r) =
                measure(std::slice::from_ref(&photo), &[&photo], size, seeds, &format!("out/multi/whole-{name}"));
            let own = repetition_fair(&photo, size, shift(size), 1, 1);
            println!("{name:12} whole {e:6.2} rep {r:.3}  own rep {own:.3}");
            [e, r, 0.0, 0.0, own]
        } else {
            let (hw, hh) = (photo.width / 2, photo.height / 2);
            let parts = [crop(&photo, 0, 0, hw, hh), crop(&photo, hw, 0, hw, hh), crop(&photo, hw / 2, hh, hw, hh)];
            let refs: Vec<&Image> = parts.iter().collect();
            let (em, rm) = measure(&parts, &refs, (hw, hh), seeds, &format!("out/multi/{name}"));
            let (eo, ro) = measure(&parts[..1], &refs[..1], (hw, hh), seeds, &format!("out/multi/one-{name}"));
            let own = parts.iter().map(|p| repetition_fair(p, (hw, hh), shift((hw, hh)), 1, 1)).sum::<f64>() / 3.0;
            println!("{name:12} three {em:6.2} rep {rm:.3}  one {eo:6.2} rep {ro:.3}  own rep {own:.3}");
            [em, rm, eo, ro, own]
        };
        (0..5).for_each(|k| sums[k] += row[k]);
    }
    let m = sums.map(|s| s / names.len() as f64);
    if whole {
        println!("mean         whole {:6.2} rep {:.3}  own rep {:.3}", m[0], m[1], m[4]);
    } else {
        println!(
            "mean         three {:6.2} rep {:.3}  one {:6.2} rep {:.3}  own rep {:.3}",
            m[0], m[1], m[2], m[3], m[4]
        );
    }
}
