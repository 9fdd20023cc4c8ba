//! Guided synthesis as bench/peer-verbs.mjs makes it, natively: for each photograph in
//! the folder it wrote (NAME.png, NAME.exguide.png, NAME.disc.png), 256² outputs
//! guided by the disc at the default weight, seeds 1-3; the median correlation of the
//! output's luminance (blurred, sigma 4) with the disc's, and the median time.
//! `cargo run --release --example guided_probe -- [folder, default /tmp/peer30/out/in]`
use patternsynth::raster::codec::decode_image;
use patternsynth::raster::guide::GUIDE_WEIGHT;
use patternsynth::raster::{synthesize_textures, Guides, Image, TextureOptions};
use patternsynth::Silent;
use std::time::Instant;

fn load(path: &str) -> Image {
    let d = decode_image(&std::fs::read(path).unwrap()).unwrap();
    Image::from_rgba8(d.width, d.height, &d.data).unwrap()
}

fn luminance(data: &[u8]) -> Vec<f64> {
    data.chunks(4).map(|p| 0.299 * p[0] as f64 + 0.587 * p[1] as f64 + 0.114 * p[2] as f64).collect()
}

/// Gaussian blur with clamped edges, as the bench's.
fn blur(v: &[f64], w: usize, h: usize, sigma: f64) -> Vec<f64> {
    let r = (3.0 * sigma).ceil() as isize;
    let k: Vec<f64> = (-r..=r).map(|i| (-(i * i) as f64 / (2.0 * sigma * sigma)).exp()).collect();
    let s: f64 = k.iter().sum();
    let at = |a: isize, n: usize| a.clamp(0, n as isize - 1) as usize;
    let mut t = vec![0.0; w * h];
    for y in 0..h {
        for x in 0..w {
            t[y * w + x] = (-r..=r).map(|i| k[(i + r) as usize] / s * v[y * w + at(x as isize + i, w)]).sum();
        }
    }
    let mut o = vec![0.0; w * h];
    for y in 0..h {
        for x in 0..w {
            o[y * w + x] = (-r..=r).map(|i| k[(i + r) as usize] / s * t[at(y as isize + i, h) * w + x]).sum();
        }
    }
    o
}

fn correlation(a: &[f64], b: &[f64]) -> f64 {
    let n = a.len() as f64;
    let (ma, mb) = (a.iter().sum::<f64>() / n, b.iter().sum::<f64>() / n);
    let (mut ab, mut aa, mut bb) = (0.0, 0.0, 0.0);
    for (x, y) in a.iter().zip(b) {
        ab += (x - ma) * (y - mb);
        aa += (x - ma) * (x - ma);
        bb += (y - mb) * (y - mb);
    }
    ab / (aa * bb).sqrt().max(1e-12)
}

fn median(v: &mut [f64]) -> f64 {
    v.sort_by(|a, b| a.total_cmp(b));
    v[v.len() / 2]
}

fn main() {
    let dir = std::env::args().nth(1).unwrap_or("/tmp/peer30/out/in".into());
    let (mut all, mut times) = (Vec::new(), Vec::new());
    for name in ["bark", "brick", "grass", "gravel", "paving", "roof", "tiles", "weave"] {
        let photo = load(&format!("{dir}/{name}.png"));
        let exguide = load(&format!("{dir}/{name}.exguide.png"));
        let disc = load(&format!("{dir}/{name}.disc.png"));
        let (side, target) = (disc.width, luminance(&disc.to_rgba8()));
        let mut corrs = Vec::new();
        for seed in 1..=3 {
            let opts = TextureOptions {
                width: side,
                height: side,
                seed,
                guides: Some(Guides { exemplars: vec![exguide.clone()], target: disc.clone(), weight: GUIDE_WEIGHT }),
                ..Default::default()
            };
            let t = Instant::now();
            let out = synthesize_textures(std::slice::from_ref(&photo), &opts, &mut Silent).unwrap().image;
            times.push(t.elapsed().as_secs_f64() * 1e3);
            corrs.push(correlation(&blur(&luminance(&out.data), side, side, 4.0), &target));
        }
        println!("{name}: correlation {:.2}", median(&mut corrs.clone()));
        all.extend(corrs);
    }
    println!("median correlation {:.2}, median {:.0} ms", median(&mut all), median(&mut times));
}
