//! Filling a hole (`inpaint_texture`) where the photograph is lit unevenly: the fill
//! must take copies of the brightness around the hole, not copies of anywhere lifted
//! or darkened by the heal, and must not show its edge. And where the image's opacity
//! varies (issue 30): the fill keeps to the opacity around it, a transparent
//! background stays transparent, and opaque images fill as they did before.

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
/// 0.56 / 1.08 and 0.89 / 1.30. With the points past the image's border left out of
/// the neighbourhoods rather than read across the wrap (`Pass::cut`), 0.69 / 0.94,
/// 0.69 / 1.04 and 0.81 / 1.26 (over seeds 1-8: gravel 0.80 -> 0.68, grass 0.54 ->
/// 0.69, tissue 0.87 -> 0.82, every edge lower).
const BOUNDS: [(&str, f64, f64); 3] = [("gravel", 0.75, 0.97), ("grass", 0.74, 1.18), ("tissue", 0.87, 1.34)];

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

/// A fixture photograph whose alpha rises from 60 at its left edge to 210 at its right
/// (the trial's half-transparent photograph).
fn faded(name: &str) -> Rgba {
    let mut img = decode_image(&std::fs::read(format!("tests/fixtures/textures/{name}.png")).unwrap()).unwrap();
    let w = img.width;
    for (i, p) in img.data.chunks_exact_mut(4).enumerate() {
        p[3] = (60.0 + 150.0 * (i % w) as f32 / w as f32).round() as u8;
    }
    img
}

#[test]
fn a_fill_in_an_alpha_gradient_keeps_to_the_gradient() {
    // Copies matched on colour alone brought their own opacity from anywhere along the
    // gradient: patches of alpha 40-80 levels off it.
    for name in ["gravel", "grass", "brick"] {
        let img = faded(name);
        let (w, h) = (img.width, img.height);
        let hole: Vec<bool> = (0..w * h).map(|i| (40..90).contains(&(i % w)) && (30..80).contains(&(i / w))).collect();
        let out = inpaint_texture(&img, &hole, &InpaintOptions::default(), &mut Silent).unwrap();
        let off: Vec<f64> = (0..w * h)
            .filter(|&i| hole[i])
            .map(|i| (out.data[4 * i + 3] as f64 - img.data[4 * i + 3] as f64).abs())
            .collect();
        let mean = off.iter().sum::<f64>() / off.len() as f64;
        let worst = off.iter().cloned().fold(0.0, f64::max);
        println!("{name}: filled alpha off the gradient by {mean:.1} on average, {worst} at most");
        assert!(mean < 6.0 && worst < 30.0, "{name}: alpha off the gradient by {mean:.1} on average, {worst} at most");
    }
}

/// A 128 x 128 icon on a transparent black background: a camera lens, a dark disc in a
/// ring of light, noisy colour with a mid-tone rim (the trial's icon, H). The hole
/// crosses the ring's right edge into the background; the lens lies outside it.
fn icon() -> (Rgba, Vec<bool>, impl Fn(usize, usize) -> f64) {
    let (w, h) = (128usize, 128usize);
    let radius = |x: usize, y: usize| (x as f64 - 56.0).hypot(y as f64 - 64.0);
    let mut data = vec![0u8; w * h * 4];
    for i in 0..w * h {
        let r = radius(i % w, i / w);
        let n = ((i * 7919 + (i / w) * 104729) % 23) as u8;
        let px = if r < 22.0 {
            [35 + n, 35 + n, 45 + n, 255]
        } else if r < 36.0 {
            [210 + n, 190 + n, 90 + n, 255]
        } else if r < 40.0 {
            [150, 120, 60, 255]
        } else if r < 41.0 {
            [150, 120, 60, 128]
        } else {
            [0, 0, 0, 0]
        };
        data[4 * i..4 * i + 4].copy_from_slice(&px);
    }
    let hole = (0..w * h).map(|i| (80..112).contains(&(i % w)) && (48..80).contains(&(i / w))).collect();
    (Rgba { width: w, height: h, data }, hole, radius)
}

#[test]
fn a_hole_across_an_icons_edge_leaves_its_background_transparent_and_clean() {
    // Matched on colour alone, transparent black was as good a match as any dark, and
    // the heal carried the background's black into the drawing: a dark smear.
    let (img, hole, radius) = icon();
    let w = img.width;
    for seed in 1..=3 {
        let out = inpaint_texture(&img, &hole, &InpaintOptions { seed, ..Default::default() }, &mut Silent).unwrap();
        for i in (0..hole.len()).filter(|&i| hole[i]) {
            let (x, y) = (i % w, i / w);
            let p = &out.data[4 * i..4 * i + 4];
            let dark = p[3] > 64 && p[..3].iter().map(|&v| v as u32).sum::<u32>() < 3 * 100;
            assert!(!dark, "seed {seed}: a dark pixel {p:?} at ({x}, {y})");
            // Well outside the drawing, transparent; well inside it, opaque.
            if radius(x, y) > 46.0 {
                assert!(p[3] <= 8, "seed {seed}: alpha {} at ({x}, {y}), outside the drawing", p[3]);
            }
            if radius(x, y) < 30.0 {
                assert!(p[3] >= 247, "seed {seed}: alpha {} at ({x}, {y}), inside the drawing", p[3]);
            }
        }
    }
}

/// Opacity is matched only where it varies (issue 30): an image whose alpha is one
/// value everywhere fills and mends as the same image opaque, colour for colour, and
/// keeps its alpha.
#[test]
fn an_image_of_one_opacity_fills_and_mends_as_an_opaque_one() {
    for name in ["gravel", "tissue"] {
        let img = decode_image(&std::fs::read(format!("tests/fixtures/textures/{name}.png")).unwrap()).unwrap();
        let (w, h) = (img.width, img.height);
        let mut faded = img.clone();
        faded.data.chunks_mut(4).for_each(|p| p[3] = 200);
        let hole: Vec<bool> = (0..w * h)
            .map(|i| ((i % w) as f64 - 0.6 * w as f64).hypot((i / w) as f64 - 0.4 * h as f64) < w as f64 / 7.0)
            .collect();
        let fill = |im: &Rgba| {
            inpaint_texture(im, &hole, &InpaintOptions { seed: 3, ..Default::default() }, &mut Silent).unwrap()
        };
        let mend = |im: &Rgba| patternsynth::seamless::mend::mend(im, 0.2, None, 2, &mut Silent).unwrap();
        for (opaque, one) in [(fill(&img), fill(&faded)), (mend(&img), mend(&faded))] {
            let pixels = |im: &Rgba| im.data.chunks(4).map(|p| [p[0], p[1], p[2], p[3]]).collect::<Vec<_>>();
            let (p, q) = (pixels(&opaque), pixels(&one));
            assert!(p.iter().zip(&q).all(|(p, q)| p[..3] == q[..3]), "{name}: colours differ");
            assert!(q.iter().all(|q| q[3] == 200), "{name}: alpha changed");
        }
    }
}

/// A photograph of two materials, sky over ground (the sky a blue gradient with a
/// little grain, the ground the gravel fixture), `w x h`, the horizon at `horizon`.
fn sky_over_gravel(w: usize, h: usize, horizon: usize) -> Rgba {
    let gravel = decode_image(&std::fs::read("tests/fixtures/textures/gravel.png").unwrap()).unwrap();
    let mut data = vec![0u8; 4 * w * h];
    for y in 0..h {
        for x in 0..w {
            let i = 4 * (y * w + x);
            let px = if y < horizon {
                let grain = ((x * 7919 + y * 104729) % 13) as f32 - 6.0;
                let t = y as f32 / horizon as f32;
                [90.0 + 60.0 * t + grain, 140.0 + 50.0 * t + grain, 235.0 - 10.0 * t + grain]
            } else {
                let j = 4 * ((y % gravel.height) * gravel.width + x % gravel.width);
                [0, 1, 2].map(|c| gravel.data[j + c] as f32)
            };
            data[i..i + 3].copy_from_slice(&px.map(|c| c.round().clamp(0.0, 255.0) as u8));
            data[i + 3] = 255;
        }
    }
    Rgba { width: w, height: h, data }
}

/// A hole on the image's border is filled from the image, not from its opposite border
/// (a new user's trial: a hole along the bottom of a photograph of grass under the sky
/// came back with 27-33% of it sky, in each of three seeds; along its top, with grass).
/// The image is no tile: what lies past one border says nothing of what lies past
/// the other.
#[test]
fn a_hole_on_the_border_is_not_filled_from_the_opposite_border() {
    let (w, h) = (160, 128);
    let img = sky_over_gravel(w, h, 48);
    let blue = |p: [f64; 3]| p[2] > p[0] + 60.0;
    // (Along the bottom, in the ground: no sky; along the top, in the sky: all sky.)
    for (name, rows, sky_wanted) in [("bottom", h - 14..h, false), ("top", 0..14, true)] {
        let mask: Vec<bool> = (0..w * h).map(|i| rows.contains(&(i / w)) && (40..120).contains(&(i % w))).collect();
        let holed = mask.iter().filter(|&&m| m).count();
        for seed in 1..=3 {
            let out =
                inpaint_texture(&img, &mask, &InpaintOptions { seed, ..Default::default() }, &mut Silent).unwrap();
            let sky = (0..w * h).filter(|&i| mask[i] && blue(rgb(&out, i % w, i / w))).count();
            let wrong = if sky_wanted { holed - sky } else { sky };
            assert_eq!(wrong, 0, "{name} hole, seed {seed}: {wrong} of {holed} pixels from the other material");
        }
    }
}
