//! Where an E-TFMCM tile's time goes (median of 5 per phase), for tuning:
//! `cargo run --release --example etfmcm_phases -- [size]`.
use patternsynth::progress::Throttle;
use patternsynth::raster::codec::decode_image;
use patternsynth::seamless::colourise::colourise;
use patternsynth::seamless::cooccurrence::Grey;
use patternsynth::seamless::density::convert;
use patternsynth::seamless::etfmcm::{generate, Rule};
use patternsynth::seamless::measure::{restoration_rgb, seam_score};
use patternsynth::Silent;
use std::time::Instant;

fn main() {
    let size: usize = std::env::args().nth(1).and_then(|s| s.parse().ok()).unwrap_or(256);
    for name in ["wood", "brick", "grass", "gravel"] {
        let img = decode_image(&std::fs::read(format!("tests/fixtures/textures/{name}.png")).unwrap()).unwrap();
        // Nearest-neighbour enlargement to the tile size (phase timings only).
        let k = size / img.width;
        let rgb: Vec<[u8; 3]> = (0..size * size)
            .map(|i| {
                let (x, y) = (i % size / k, i / size / k);
                let p = &img.data[(y * img.width + x) * 4..];
                [p[0], p[1], p[2]]
            })
            .collect();
        let grey = Grey { width: size, height: size, data: rgb.iter().map(|p| p[0]).collect() };
        println!("{name}: rebuilds alone {:.1} ms", rebuilds(&grey));
        let mut t = [Vec::new(), Vec::new(), Vec::new(), Vec::new()];
        for _ in 0..5 {
            let s = Instant::now();
            let conv = convert(&grey, 50.0, 1);
            t[0].push(s.elapsed().as_secs_f64() * 1e3);
            let s = Instant::now();
            let (g, _) = generate(&conv.image, Rule::Etfmcm, 1, &mut Throttle::new(&mut Silent)).unwrap();
            t[1].push(s.elapsed().as_secs_f64() * 1e3);
            let s = Instant::now();
            let out = colourise(&g, &conv.image, &rgb);
            t[2].push(s.elapsed().as_secs_f64() * 1e3);
            let s = Instant::now();
            let _ = (restoration_rgb(&rgb, &out), seam_score(&out, size, size));
            t[3].push(s.elapsed().as_secs_f64() * 1e3);
        }
        let m = t.map(|mut v| {
            v.sort_by(|a, b| a.total_cmp(b));
            v[2]
        });
        println!(
            "{name}: convert {:.1} ms, generate {:.1} ms, colourise {:.1} ms, measures {:.1} ms",
            m[0], m[1], m[2], m[3]
        );
    }
}

/// Time of the side sets' rebuilds alone (as `generate` does them at every kind and scale).
fn rebuilds(grey: &Grey) -> f64 {
    use patternsynth::seamless::cooccurrence::Triples;
    let n = grey.width as isize;
    let mut t = Triples::build(grey, (-1, -1), (1, -1));
    let s = Instant::now();
    let mut h = n / 2;
    while h >= 1 {
        for verts in [[(-h, -h), (h, -h), (h, h), (-h, h)], [(0, -h), (h, 0), (0, h), (-h, 0)]] {
            for i in 0..4 {
                t.rebuild(grey, verts[i], verts[(i + 1) % 4]);
            }
        }
        h /= 2;
    }
    s.elapsed().as_secs_f64() * 1e3
}
