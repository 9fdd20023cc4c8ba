//! Filling a hole (`inpaint_texture`) where the photograph is lit unevenly: the fill
//! must take copies of the brightness around the hole, not copies of anywhere lifted
//! or darkened by the heal, and must not show its edge.

use patternsynth::raster::codec::decode_image;
use patternsynth::raster::{inpaint_texture, InpaintOptions, Rgba};
use patternsynth::Silent;

/// A fixture photograph lit by a ramp from 45% at its left edge to 135% at its right.
fn lit(name: &str) -> Rgba {
    let mut img = decode_image(&std::fs::read(format!("tests/fixtures/textures/{name}.png")).unwrap()).unwrap();
    let w = img.width;
    for (i, p) in img.data.chunks_exact_mut(4).enumerate() {
        let f = 0.45 + 0.9 * (i % w) as f32 / w as f32;
        p[..3].iter_mut().for_each(|c| *c = (*c as f32 * f).round().min(255.0) as u8);
    }
    img
}

fn rgb(img: &Rgba, x: usize, y: usize) -> [f64; 3] {
    let i = 4 * (y * img.width + x);
    [0, 1, 2].map(|c| img.data[i + c] as f64)
}

/// Mean over 7 x 7 windows centred in the hole (every 3rd pixel) of each one's RMS
/// distance to the nearest window of the photograph wholly outside the hole.
fn fill_energy(out: &Rgba, img: &Rgba, hole: &[bool]) -> f64 {
    let (w, h) = (img.width, img.height);
    let outside: Vec<(usize, usize)> = (3..h - 3)
        .flat_map(|y| (3..w - 3).map(move |x| (x, y)))
        .filter(|&(x, y)| (0..49).all(|k| !hole[(y + k / 7 - 3) * w + x + k % 7 - 3]))
        .collect();
    let mut energies = Vec::new();
    for y in (3..h - 3).step_by(3) {
        for x in (3..w - 3).step_by(3).filter(|&x| hole[y * w + x]) {
            let best = outside.iter().fold(f64::INFINITY, |best, &(sx, sy)| {
                let mut acc = 0.0;
                for k in 0..49 {
                    let (a, b) = (rgb(out, x + k % 7 - 3, y + k / 7 - 3), rgb(img, sx + k % 7 - 3, sy + k / 7 - 3));
                    acc += (0..3).map(|c| (a[c] - b[c]).powi(2)).sum::<f64>();
                    if acc > best {
                        return best;
                    }
                }
                acc
            });
            energies.push((best / 147.0).sqrt());
        }
    }
    energies.iter().sum::<f64>() / energies.len() as f64
}

/// The mean colour step across the hole's edge over the mean step between neighbours
/// outside it and within 8 pixels of it.
fn edge_ratio(out: &Rgba, hole: &[bool]) -> f64 {
    let (w, h) = (out.width, out.height);
    let near = |x: usize, y: usize| {
        (y.saturating_sub(8)..(y + 9).min(h)).any(|j| (x.saturating_sub(8)..(x + 9).min(w)).any(|i| hole[j * w + i]))
    };
    let step = |a: [f64; 3], b: [f64; 3]| (0..3).map(|c| (a[c] - b[c]).powi(2)).sum::<f64>().sqrt();
    let (mut across, mut na, mut around, mut nr) = (0.0, 0.0, 0.0, 0.0);
    for y in 0..h {
        for x in 0..w {
            for (x2, y2) in [(x + 1, y), (x, y + 1)].into_iter().filter(|&(a, b)| a < w && b < h) {
                let (p, q) = (hole[y * w + x], hole[y2 * w + x2]);
                let s = step(rgb(out, x, y), rgb(out, x2, y2));
                if p != q {
                    across += s;
                    na += 1.0;
                } else if !p && near(x, y) {
                    around += s;
                    nr += 1.0;
                }
            }
        }
    }
    (across / na) / (around / nr)
}

/// Per photograph: the bounds of the fill's patch energy (a share of the photograph's
/// own content's there) and of its edge ratio, means over seeds 1-3. Filled once and
/// healed whole (before `REMATCH_ROUNDS`), these were 0.87 / 1.02 (gravel), 0.67 / 1.28
/// (grass) and 0.94 / 1.37 (tissue); matched again and healed by half, 0.77 / 0.92,
/// 0.56 / 1.08 and 0.89 / 1.30.
const BOUNDS: [(&str, f64, f64); 3] = [("gravel", 0.82, 0.97), ("grass", 0.62, 1.18), ("tissue", 0.92, 1.34)];

#[test]
fn a_fill_where_the_photograph_is_brightest_copies_that_brightness_without_an_edge() {
    for (name, energy_bound, edge_bound) in BOUNDS {
        let img = lit(name);
        let (w, h) = (img.width, img.height);
        // A disc near the bright edge: few places are as bright as its surroundings.
        let hole: Vec<bool> = (0..w * h)
            .map(|i| ((i % w) as f64 - 0.8 * w as f64).hypot((i / w) as f64 - 0.5 * h as f64) < 16.0)
            .collect();
        let mut energies = Vec::new();
        let mut edges = Vec::new();
        for seed in 1..=3 {
            let out =
                inpaint_texture(&img, &hole, &InpaintOptions { seed, ..Default::default() }, &mut Silent).unwrap();
            assert!((0..w * h).filter(|&i| !hole[i]).all(|i| out.data[4 * i..4 * i + 4] == img.data[4 * i..4 * i + 4]));
            energies.push(fill_energy(&out, &img, &hole));
            edges.push(edge_ratio(&out, &hole));
        }
        let truth = fill_energy(&img, &img, &hole);
        let energy = energies.iter().sum::<f64>() / 3.0;
        let edge = edges.iter().sum::<f64>() / 3.0;
        println!("{name}: fill energy {energy:.2} (the photograph's own {truth:.2}), edge ratio {edge:.2}");
        assert!(energy < energy_bound * truth, "{name}: fill energy {energy:.2}, the photograph's own {truth:.2}");
        assert!(edge < edge_bound, "{name}: the step across the fill's edge is {edge:.2} times the steps around it");
    }
}
