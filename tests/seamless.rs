//! Seamless tiles (SPEC 3) on the CC0 photographs: every method wraps without a seam,
//! E-TFMCM keeps the histogram (restoration rate) better than TFMCM and decides more
//! points by the multi-distance matrix, a seed reproduces a tile, odd sizes are cropped
//! and scaled with a message, and bad input gets a clear error.

use patternsynth::raster::codec::decode_image;
use patternsynth::raster::synthesis::Schedule;
use patternsynth::raster::{synthesize_texture, Image, Rgba, TextureOptions};
use patternsynth::seamless::measure::seam_score;
use patternsynth::seamless::{seamless_tile, Method, SeamlessOptions};
use patternsynth::Silent;

fn fixture(name: &str) -> Rgba {
    decode_image(&std::fs::read(format!("tests/fixtures/textures/{name}.png")).unwrap()).unwrap()
}

fn crop(img: &Rgba, w: usize, h: usize) -> Rgba {
    let mut data = Vec::with_capacity(w * h * 4);
    for y in 0..h {
        data.extend_from_slice(&img.data[y * img.width * 4..][..w * 4]);
    }
    Rgba { width: w, height: h, data }
}

#[test]
fn every_method_wraps_without_a_seam() {
    for name in ["gravel", "wood"] {
        let img = crop(&fixture(name), 64, 64);
        for method in [Method::Etfmcm, Method::Tfmcm, Method::Synthesis] {
            let r =
                seamless_tile(&img, &SeamlessOptions { method, seed: 2, ..Default::default() }, &mut Silent).unwrap();
            println!("{name} {method:?}: restoration {:.3} seam {:.2}", r.restoration_rate, r.seam_score);
            assert_eq!((r.image.width, r.image.height, r.image.data.len()), (64, 64, 64 * 64 * 4));
            // The wrap-around differs no more than neighbouring pixels inside do.
            assert!(r.seam_score < 1.3, "{name} {method:?}: seam {}", r.seam_score);
            assert!(r.restoration_rate > 0.75, "{name} {method:?}: restoration {}", r.restoration_rate);
        }
    }
}

/// Seam score of an image's wrap-around (for a photograph as it is: a naive tile).
fn seam_of(img: &Rgba) -> f64 {
    seam_score(&img.rgb(), img.width, img.height)
}

#[test]
fn the_wrap_of_a_synthesized_tile_is_no_seam_on_structured_photographs() {
    // Mean over seeds: a single tile's score depends on whether a structure (a mortar
    // line, a coin's rim) happens to run along the wrap; a seam is there for every seed.
    // One seed's score varies by about 0.4, so the mean of 16 is known to about 0.1
    // (brick's quilted tiles: 1.38 over seeds 1-4, 1.09 over 1-32).
    for name in ["brick", "coins", "print"] {
        let img = fixture(name);
        let naive = seam_of(&img);
        let over_seeds = |score: &dyn Fn(u64) -> f64| (1..=16).map(score).sum::<f64>() / 16.0;
        let tiles = over_seeds(&|seed| {
            let o = SeamlessOptions { method: Method::Synthesis, seed, ..Default::default() };
            seamless_tile(&img, &o, &mut Silent).unwrap().seam_score
        });
        // The banded schedule (which large tiles take, and workers share) too.
        let ex = Image::from_rgba8(img.width, img.height, &img.data).unwrap();
        let banded = over_seeds(&|seed| {
            let o = TextureOptions {
                width: 256,
                height: 256,
                seed,
                tileable: true,
                schedule: Schedule::Bands,
                ..Default::default()
            };
            seam_of(&synthesize_texture(&ex, &o, &mut Silent).unwrap())
        });
        println!("{name}: naive tile {naive:.2}, synthesized {tiles:.2}, banded at 256 {banded:.2}");
        // The measure sees the cut of a photograph repeated as it is...
        assert!(naive > 2.0, "{name}: naive {naive}");
        // ...and none in ours.
        assert!((0.8..1.25).contains(&tiles), "{name}: seam {tiles}");
        // Print's banded tiles vary too much from seed to seed to tell (1.16 over 4;
        // other lines of the same tiles reach 2): its figure is in the benchmark. Below
        // 1 the wrap is smoother than the lines inside: brick's banded wraps often run
        // along a course of bricks rather than across mortar (0.71 over 4 seeds), which
        // is no seam; a blurred or flat wrap would score far lower.
        if name != "print" {
            assert!((0.6..1.25).contains(&banded), "{name}: banded seam {banded}");
        }
    }
}

#[test]
fn a_256_print_tile_has_no_seam_where_coarse_pixels_meet() {
    // The wrap of a 256 tile lies on a boundary of the coarsest level's pixels. When
    // copies were locked to offsets of multiples of 8 there, print's wrap (a page of text)
    // scored 1.33 over seeds 1-8. One seed's score varies by about 0.2 (0.67-1.55), so
    // the mean of 16 is known to about 0.05: 1.18 before the colour balance, 1.20 with
    // it (`synthesis::reuse`), and the bound leaves that room.
    let img = fixture("print");
    let seams: Vec<f64> = (1..=16)
        .map(|seed| {
            let o = SeamlessOptions { method: Method::Synthesis, size: Some(256), seed, ..Default::default() };
            seamless_tile(&img, &o, &mut Silent).unwrap().seam_score
        })
        .collect();
    let mean = seams.iter().sum::<f64>() / seams.len() as f64;
    println!("print 256 synthesis tiles: {seams:.2?}, mean {mean:.3}");
    assert!((0.8..1.25).contains(&mean), "mean seam {mean}");
}

#[test]
fn etfmcm_improves_on_tfmcm() {
    let img = fixture("brick");
    // The paper's tiles, as they are (not refined).
    let run = |method| {
        seamless_tile(&img, &SeamlessOptions { method, refine: false, ..Default::default() }, &mut Silent).unwrap()
    };
    let (e, t) = (run(Method::Etfmcm), run(Method::Tfmcm));
    let (de, dt) = (e.decisions.unwrap(), t.decisions.unwrap());
    println!("E-TFMCM {:.3} {de:?}; TFMCM {:.3} {dt:?}", e.restoration_rate, t.restoration_rate);
    assert!(e.restoration_rate > t.restoration_rate + 0.05);
    // TFMCM decides the J3 = 1 points pairwise; E-TFMCM by the matrix.
    assert_eq!(dt.by_j3[1], 0);
    assert!(de.by_j3[1] > 0 && de.pairwise < dt.pairwise / 10);
    // Every point of the 128 x 128 torus but the corner and centre is decided once.
    let total = |d: &patternsynth::seamless::etfmcm::Decisions| d.by_j3.iter().sum::<usize>() + d.pairwise + d.mean;
    assert_eq!(total(&de), 128 * 128 - 2);
    assert_eq!(total(&dt), 128 * 128 - 2);
    // Brick's grey channel is crowded (the mortar): the conversion lowers it.
    let (before, after) = e.count_difference.unwrap();
    assert!(before > 1000.0 && after < 60.0, "{before} -> {after}");
}

#[test]
fn colours_come_from_the_exemplar_and_a_seed_repeats() {
    // (Unfused: by default the seams between copied pieces are smoothed, `fusion`.)
    let img = crop(&fixture("wood"), 32, 32);
    let o = SeamlessOptions { seed: 9, fuse_seams: false, ..Default::default() };
    let a = seamless_tile(&img, &o, &mut Silent).unwrap();
    let b = seamless_tile(&img, &o, &mut Silent).unwrap();
    assert_eq!(a.image, b.image);
    let colours: std::collections::HashSet<&[u8]> = img.data.chunks_exact(4).collect();
    assert!(a.image.data.chunks_exact(4).all(|p| colours.contains(p)));
    let c = seamless_tile(&img, &SeamlessOptions { seed: 10, ..o }, &mut Silent).unwrap();
    assert_ne!(a.image, c.image);
}

#[test]
fn odd_sizes_are_cropped_and_scaled_with_a_message() {
    let img = crop(&fixture("grass"), 100, 70);
    // E-TFMCM's tile is a square, a power of two on a side: the image's centred square,
    // scaled to it.
    let etfmcm = SeamlessOptions { method: Method::Etfmcm, ..Default::default() };
    let r = seamless_tile(&img, &etfmcm, &mut Silent).unwrap();
    assert_eq!(r.image.width, 64);
    assert!(r.warnings.iter().any(|w| w.contains("Cropped the 100x70 image to its centre 70x70")), "{:?}", r.warnings);
    assert!(r.warnings.iter().any(|w| w.contains("Scaled 70x70 to 64x64")), "{:?}", r.warnings);
    let r = seamless_tile(&img, &SeamlessOptions { size: Some(128), ..etfmcm }, &mut Silent).unwrap();
    assert_eq!(r.image.width, 128);
    // Synthesis, the default, takes the whole image at its own scale: the tile is the
    // image's size, nothing cropped or scaled.
    let r = seamless_tile(&img, &SeamlessOptions::default(), &mut Silent).unwrap();
    assert_eq!((r.image.width, r.image.height), (100, 70));
    assert!(r.warnings.is_empty(), "{:?}", r.warnings);
    assert!(r.seam_score < 1.3, "seam {}", r.seam_score);
    // It enlarges by making more texture, not by scaling the image up...
    let exact = crop(&fixture("grass"), 64, 64);
    let o = SeamlessOptions { method: Method::Synthesis, size: Some(128), ..Default::default() };
    let r = seamless_tile(&exact, &o, &mut Silent).unwrap();
    assert_eq!(r.image.width, 128);
    assert!(r.warnings.iter().any(|w| w.contains("from the 64x64 image at its own scale")), "{:?}", r.warnings);
    assert!(r.seam_score < 1.3, "seam {}", r.seam_score);
    assert!(seamless_tile(&exact, &SeamlessOptions::default(), &mut Silent).unwrap().warnings.is_empty());
    // ...and makes a smaller tile of the image's own pixels, not of the image scaled
    // down: unfused, every pixel is one of the 100 x 70 image's colours.
    let o = SeamlessOptions { size: Some(32), fuse_seams: false, ..Default::default() };
    let r = seamless_tile(&img, &o, &mut Silent).unwrap();
    assert_eq!(r.image.width, 32);
    let colours: std::collections::HashSet<&[u8]> = img.data.chunks_exact(4).collect();
    assert!(r.image.data.chunks_exact(4).all(|p| colours.contains(p)));
    assert!(r.warnings.is_empty(), "{:?}", r.warnings);
}

#[test]
fn synthesis_tiles_take_any_width_and_height() {
    // 96 x 40: neither square nor a power of two; the wrap seamless both ways.
    let img = crop(&fixture("grass"), 64, 64);
    let o =
        SeamlessOptions { method: Method::Synthesis, width: Some(96), height: Some(40), seed: 3, ..Default::default() };
    let r = seamless_tile(&img, &o, &mut Silent).unwrap();
    assert_eq!((r.image.width, r.image.height), (96, 40));
    assert_eq!(r.image.data.len(), 96 * 40 * 4);
    println!("96x40 synthesis tile: seam {:.2}, restoration {:.3}", r.seam_score, r.restoration_rate);
    assert!(r.seam_score < 1.3, "seam {}", r.seam_score);
    // One of the two: a square of that side.
    let r = seamless_tile(&img, &SeamlessOptions { width: Some(72), ..o.clone() }, &mut Silent);
    assert_eq!(r.map(|r| (r.image.width, r.image.height)).ok(), Some((72, 40)));
    let r = seamless_tile(&img, &SeamlessOptions { width: None, height: Some(24), ..o.clone() }, &mut Silent).unwrap();
    assert_eq!((r.image.width, r.image.height), (24, 24));
    let err = |o: SeamlessOptions| seamless_tile(&img, &o, &mut Silent).unwrap_err().to_string();
    assert!(err(SeamlessOptions { method: Method::Etfmcm, ..o.clone() })
        .contains("method 'synthesis' for a tile of any width"));
    assert!(err(SeamlessOptions { size: Some(64), ..o.clone() }).contains("not both"));
    assert!(err(SeamlessOptions { width: Some(5000), ..o.clone() }).contains("width must be from 8 to 4096"));
    assert!(err(SeamlessOptions { height: Some(4), ..o }).contains("height must be from 8 to 4096"));
}

#[test]
fn bad_input_is_a_clear_error() {
    let img = crop(&fixture("grass"), 64, 64);
    let err = |o: SeamlessOptions, i: &Rgba| seamless_tile(i, &o, &mut Silent).unwrap_err().to_string();
    assert!(err(SeamlessOptions { size: Some(100), ..Default::default() }, &img).contains("power of two"));
    assert!(err(SeamlessOptions { size: Some(4096), ..Default::default() }, &img).contains("power of two"));
    assert!(err(SeamlessOptions { max_count_difference: f64::NAN, ..Default::default() }, &img).contains("at least 0"));
    assert!(err(SeamlessOptions::default(), &crop(&img, 6, 6)).contains("at least 8"));
    assert!(err(SeamlessOptions::default(), &Rgba { width: 0, height: 4, data: vec![] }).contains("empty"));
    assert!(err(SeamlessOptions::default(), &Rgba { width: 8, height: 8, data: vec![0; 10] }).contains("needs 256"));
    let mut calls = 0;
    let mut cancel = |_: f64| {
        calls += 1;
        calls < 2
    };
    assert_eq!(
        seamless_tile(&img, &SeamlessOptions::default(), &mut cancel).unwrap_err(),
        patternsynth::Error::Cancelled
    );
}

/// Refined by toroidal synthesis from its layout, the E-TFMCM tile keeps structure the
/// paper's breaks (patch energy well below the paper's tile on bricks, wood grain and
/// letters), and both it and synthesis keep the image's colours: synthesis grown from
/// noise drifted to tissue's smoothest region (colour distance 0.68) until its coarsest
/// level kept the colours balanced (`synthesis::reuse`). Means over seeds 1-3 at 128.
#[test]
fn refined_etfmcm_keeps_structure_and_colours() {
    use patternsynth::raster::energy::{colour_distance, patch_energy};
    let measure = |name: &str, method, refine| {
        let img = fixture(name);
        let ex = Image::from_rgba8(img.width, img.height, &img.data).unwrap();
        let (mut energy, mut colour, mut seam) = (0.0, 0.0, 0.0);
        for seed in 1..=3 {
            let t = seamless_tile(&img, &SeamlessOptions { method, refine, seed, ..Default::default() }, &mut Silent)
                .unwrap();
            let out = Image::from_rgba8(t.image.width, t.image.height, &t.image.data).unwrap();
            energy += patch_energy(&out, &ex, 300, (0, out.height), 1) / 3.0;
            colour += colour_distance(&out, &ex) / 3.0;
            seam += t.seam_score / 3.0;
        }
        (energy, colour, seam)
    };
    for name in ["brick", "wood", "print"] {
        let (paper, refined) = (measure(name, Method::Etfmcm, false), measure(name, Method::Etfmcm, true));
        println!("{name}: paper {paper:.3?}, refined {refined:.3?}");
        assert!(refined.0 < 0.75 * paper.0, "{name}: energy {} against the paper's {}", refined.0, paper.0);
        assert!((0.5..1.4).contains(&refined.2), "{name}: seam {}", refined.2);
    }
    let (refined, synthesis) = (measure("tissue", Method::Etfmcm, true), measure("tissue", Method::Synthesis, true));
    println!("tissue: refined {refined:.3?}, synthesis {synthesis:.3?}");
    assert!(
        refined.1 < 0.35 && synthesis.1 < 0.35,
        "tissue colour distance {} refined, {} by synthesis",
        refined.1,
        synthesis.1
    );
}

/// A soft stochastic picture, smoke or fire: value noise of octaves with cells of 128,
/// 64 and 32 pixels, weights 4 : 2 : 1, smoothstep between them (at a side of 128 the
/// first is one cell, a constant ground), mapped from dark red through orange to
/// yellow, on a torus. Drawn from `seed`.
fn smoke(side: usize, seed: u64) -> Rgba {
    use patternsynth::rng::Rng;
    let mut rng = Rng::new(seed);
    let octaves: Vec<(usize, f64, Vec<f64>)> = [(128usize, 4.0), (64, 2.0), (32, 1.0)]
        .into_iter()
        .map(|(cell, weight)| {
            let n = side.div_ceil(cell);
            (cell, weight, (0..n * n).map(|_| rng.below(1000) as f64 / 1000.0).collect())
        })
        .collect();
    let total: f64 = octaves.iter().map(|o| o.1).sum();
    let smooth = |t: f64| t * t * (3.0 - 2.0 * t);
    let mut data = Vec::with_capacity(side * side * 4);
    for y in 0..side {
        for x in 0..side {
            let mut v = 0.0;
            for (cell, weight, grid) in &octaves {
                let n = side.div_ceil(*cell);
                let (gx, gy) = (x / cell, y / cell);
                let (tx, ty) = (smooth((x % cell) as f64 / *cell as f64), smooth((y % cell) as f64 / *cell as f64));
                let at = |i: usize, j: usize| grid[(j % n) * n + i % n];
                let top = at(gx, gy) * (1.0 - tx) + at(gx + 1, gy) * tx;
                let bottom = at(gx, gy + 1) * (1.0 - tx) + at(gx + 1, gy + 1) * tx;
                v += weight * (top * (1.0 - ty) + bottom * ty);
            }
            let v = v / total;
            data.extend([(120.0 + 135.0 * v) as u8, (20.0 + 200.0 * v * v) as u8, (10.0 + 40.0 * v) as u8, 255]);
        }
    }
    Rgba { width: side, height: side, data }
}

/// A refined E-TFMCM tile of a soft picture repeats no more than the picture does. Its
/// coarsest level once took, pixel by pixel, the exemplar position that best matched
/// the co-occurrence field there, and every smooth neighbourhood of one colour met its
/// best match at the same place: fire and mist photographs repeated at 0.19 against
/// their own 0.34 and 0.31. It now lays a quilt that follows the field
/// (`synthesis::start::FIELD_QUILT`). Over three seeds per picture, each tile may fall
/// 0.07 short of its picture's score (the aim's 0.05 plus a seed's spread on one
/// small picture) and 0.04 on average.
#[test]
fn a_refined_tile_of_a_soft_picture_repeats_no_more_than_the_picture() {
    use patternsynth::raster::energy::{repetition, repetition_fair};
    let (mut failed, mut short) = (Vec::new(), 0.0);
    for picture in 1..=6 {
        let img = smoke(128, picture);
        let ex = Image::from_rgba8(img.width, img.height, &img.data).unwrap();
        let own = repetition(&ex, 24, 1);
        let mut tile = 0.0;
        for seed in 1..=3 {
            let opts = SeamlessOptions { method: Method::Etfmcm, seed, ..Default::default() };
            let t = seamless_tile(&img, &opts, &mut Silent).unwrap();
            let out = Image::from_rgba8(t.image.width, t.image.height, &t.image.data).unwrap();
            tile += repetition_fair(&out, (ex.width, ex.height), 24, 8, 1) / 3.0;
        }
        println!("smoke {picture}: tile {tile:.3}, its own {own:.3}");
        if tile < own - 0.07 {
            failed.push(format!("smoke {picture}: the tile repeats at {tile:.3}, the picture at {own:.3}"));
        }
        short += (own - tile) / 6.0;
    }
    // (Measured: at most 0.050 short, 0.026 on average; before the quilt, 0.186 short on
    // picture 1 and 0.058 on average.)
    assert!(failed.is_empty(), "{failed:?}");
    assert!(short < 0.04, "the tiles repeat {short:.3} more than their pictures on average");
}

/// A paving-like picture: grey stones of one grain in three columns whose joints lie at
/// about the same places all down the picture (x near 60, 130 and 206, as in a
/// photograph of setts), each joint broken once by a stone across, each column's
/// stones of their own heights, between dark joints that wobble. Drawn from `seed`.
fn setts(side: usize, seed: u64) -> Rgba {
    use patternsynth::rng::Rng;
    let mut rng = Rng::new(seed);
    let grain = |x: usize, y: usize, k: u64| {
        let mut v = (x as u64).wrapping_mul(0x9E37_79B9_7F4A_7C15) ^ (y as u64).wrapping_mul(0xC2B2_AE3D_27D4_EB4F) ^ k;
        v ^= v >> 29;
        v = v.wrapping_mul(0xBF58_476D_1CE4_E5B9);
        v ^= v >> 32;
        (v % 1000) as f64 / 1000.0 - 0.5
    };
    // Column joints (x, first row of the stone across it, its height).
    let joints: Vec<(f64, usize, usize)> = [60, 130, 206]
        .iter()
        .map(|&x| ((x * side / 224 + rng.below(5)) as f64, rng.below(side), side / 5 + rng.below(side / 6)))
        .collect();
    // Each column's stones: the row each starts at, and its grey.
    let columns: Vec<Vec<(usize, f64)>> = (0..=joints.len())
        .map(|_| {
            let mut y = rng.below(side / 4);
            let mut stones = vec![(0, 135.0 + 15.0 * rng.next_f64())];
            while y < side {
                stones.push((y, 135.0 + 15.0 * rng.next_f64()));
                y += side / 5 + rng.below(side / 5);
            }
            stones
        })
        .collect();
    let wobble = |v: usize, k: f64| 1.5 * (v as f64 / 11.0 + k).sin();
    let mut data = Vec::with_capacity(side * side * 4);
    for y in 0..side {
        for x in 0..side {
            let column = joints.iter().filter(|j| x as f64 >= j.0 + wobble(y, j.0)).count();
            let across =
                |j: &&(f64, usize, usize)| (j.1..j.1 + j.2).contains(&y) || (j.1..j.1 + j.2).contains(&(y + side));
            let dx = joints
                .iter()
                .filter(|j| !across(j))
                .map(|j| (x as f64 - j.0 - wobble(y, j.0)).abs())
                .fold(f64::INFINITY, f64::min);
            let stones = &columns[column];
            let stone = stones.iter().rposition(|s| s.0 <= y).expect("the first stone starts at 0");
            let dy = stones[1..]
                .iter()
                .map(|s| (y as f64 - s.0 as f64 - wobble(x, s.0 as f64)).abs())
                .fold(f64::INFINITY, f64::min);
            let d = dx.min(dy);
            let n = grain(x, y, seed);
            let rgb = if d < 3.5 {
                let j = 60.0 + 40.0 * n;
                [j + 15.0, j, j - 10.0]
            } else {
                let g =
                    stones[stone].1 + 40.0 * n + 10.0 * grain(x / 4, y / 4, seed ^ 7) - 20.0 * (-(d - 3.5) / 4.0).exp();
                [g + 8.0, g, g - 6.0]
            };
            data.extend(rgb.map(|v| v.round().clamp(0.0, 255.0) as u8));
            data.push(255);
        }
    }
    Rgba { width: side, height: side, data }
}

/// The strongest straight line of a mended band against the picture's: the largest mean
/// step (Euclidean RGB) across a column boundary whose columns are both re-made (the
/// wrap among them), over the tile's mean step across all its boundaries, divided by the
/// picture's largest across a column boundary (its own wrap left out) over its mean;
/// the same for rows; the larger. `margin`: the columns (and rows) re-made along each edge.
fn strongest_band_line(tile: &Rgba, picture: &Rgba, margin: usize) -> f64 {
    let n = tile.width;
    let steps = |img: &Rgba, across_columns: bool| -> Vec<f64> {
        let px = |x: usize, y: usize| {
            let i = 4 * ((y % n) * n + x % n);
            [0, 1, 2].map(|c| img.data[i + c] as f64)
        };
        (0..n)
            .map(|b| {
                let step = |i: usize| {
                    let (p, q) = if across_columns { (px(b, i), px(b + 1, i)) } else { (px(i, b), px(i, b + 1)) };
                    (0..3).map(|c| (p[c] - q[c]).powi(2)).sum::<f64>().sqrt()
                };
                (0..n).map(step).sum::<f64>() / n as f64
            })
            .collect()
    };
    let remade = |b: usize| [b, (b + 1) % n].iter().all(|&x| x < margin || x + margin >= n);
    let (tile_steps, own_steps) =
        ([steps(tile, true), steps(tile, false)], [steps(picture, true), steps(picture, false)]);
    let tile_mean = tile_steps.iter().flatten().sum::<f64>() / (2 * n) as f64;
    let own_mean = own_steps.iter().map(|s| s[..n - 1].iter().sum::<f64>()).sum::<f64>() / (2 * (n - 1)) as f64;
    (0..2)
        .map(|d| {
            let band = (0..n).filter(|&b| remade(b)).map(|b| tile_steps[d][b]).fold(0.0, f64::max) / tile_mean;
            let own = own_steps[d][..n - 1].iter().copied().fold(0.0, f64::max) / own_mean;
            band / own
        })
        .fold(0.0, f64::max)
}

/// Setts mended into a tile: the band must not lay one strip of the picture, with its
/// joint, down the whole tile. At a tile's 14-pixel coarsest level one shift of the
/// picture fitted both sides of the band, and in every seed the band copied it all
/// down, so that a joint ran straight the whole height of the tile beside its wrap, a
/// line at every tile's edge 1.30-1.32 times as strong as any of the picture's (seeds
/// 1-3); the mend makes such a band again (`mend::LINE_LIMIT`): 0.95-1.08.
#[test]
fn a_mended_band_lays_no_joint_straight_down_the_tile() {
    let picture = setts(224, 10);
    let margin = 28; // the default band: 12.5% of each side
    let mut lines = Vec::new();
    for seed in 1..=3 {
        let o = SeamlessOptions { method: Method::Mend, seed, ..Default::default() };
        let tile = seamless_tile(&picture, &o, &mut Silent).unwrap().image;
        // The inner 75% x 75% kept bit for bit.
        for y in margin..224 - margin {
            let row = 4 * (y * 224 + margin)..4 * (y * 224 + 224 - margin);
            assert_eq!(tile.data[row.clone()], picture.data[row], "seed {seed}: row {y} changed");
        }
        lines.push(strongest_band_line(&tile, &picture, margin));
    }
    println!("the band's strongest line against the picture's, seeds 1-3: {lines:.2?}");
    let mean = lines.iter().sum::<f64>() / 3.0;
    assert!(lines.iter().all(|&l| l < 1.2) && mean < 1.1, "the band's strongest lines: {lines:.2?}");
}

/// A synthesized tile starts from a quilt of the photograph's windows laid round the
/// torus, which covers the photograph evenly (`quilt::Quilt::spread`), rather than from
/// noise: it keeps the photograph's make-up. Means over seeds 1-3 at 128; grown from
/// noise, tissue's tiles scored a patch energy of 8.52 and repeated 0.064 more than the
/// photograph (0.581 against its own 0.645), fur's 6.23 and 0.061; quilted 7.14 / 0.818
/// and 5.56 / 0.812. Its colours stay the photograph's by the balance of
/// `synthesis::reuse` at every level (print joins as the third: its colours drift most).
#[test]
fn a_tile_keeps_the_photograph_s_make_up() {
    use patternsynth::raster::energy::{colour_distance, patch_energy, repetition, repetition_fair};
    // (name, patch energy bound, colour distance bound): with the colour balance at every
    // level colour came to 0.221 / 0.131 / 0.162 (energy 6.93 / 4.71 / 9.21), without
    // it 0.244 / 0.160 / 0.191; the bounds lie halfway.
    for (name, bound, colours) in [("tissue", 8.0, 0.232), ("fur", 5.9, 0.145), ("print", 10.0, 0.176)] {
        let img = fixture(name);
        let ex = Image::from_rgba8(img.width, img.height, &img.data).unwrap();
        let (mut energy, mut repeats, mut colour) = (0.0, 0.0, 0.0);
        for seed in 1..=3 {
            let t = seamless_tile(&img, &SeamlessOptions { seed, ..Default::default() }, &mut Silent).unwrap();
            let out = Image::from_rgba8(t.image.width, t.image.height, &t.image.data).unwrap();
            energy += patch_energy(&out, &ex, 300, (0, out.height), 1) / 3.0;
            repeats += repetition_fair(&out, (ex.width, ex.height), 24, 8, 1) / 3.0;
            colour += colour_distance(&out, &ex) / 3.0;
        }
        let own = repetition(&ex, 24, 1);
        println!("{name}: patch energy {energy:.2}, repetition {repeats:.3} (its own {own:.3}), colour {colour:.3}");
        assert!(energy < bound, "{name}: patch energy {energy:.2}");
        assert!(repeats >= own - 0.05, "{name}: repetition {repeats:.3} against its own {own:.3}");
        assert!(colour <= colours, "{name}: colour distance {colour:.3} from the photograph's");
    }
}

#[path = "../examples/support/line_art.rs"]
mod line_art;
use line_art::line_art;

/// Each pixel premultiplied by its alpha (what it shows over any ground), with the alpha.
fn shown(img: &Rgba) -> Vec<[u8; 4]> {
    img.data
        .chunks_exact(4)
        .map(|p| {
            let a = p[3] as u32;
            [0, 1, 2].map(|c| ((p[c] as u32 * a + 127) / 255) as u8).into_iter().chain([p[3]]).collect::<Vec<_>>()
        })
        .map(|v| [v[0], v[1], v[2], v[3]])
        .collect()
}

/// Helper-59's finding: line art on a transparent ground came back opaque black. A
/// tile (and a texture) now keeps the alpha of each pixel it copies, and compares it.
#[test]
fn line_art_on_a_clear_ground_stays_on_a_clear_ground() {
    use std::collections::HashSet;
    let share = |img: &Rgba, f: &dyn Fn(u8) -> bool| {
        img.data.chunks_exact(4).filter(|p| f(p[3])).count() as f64 / (img.width * img.height) as f64
    };
    let (mut ink, mut ranks) = ([0.0; 2], 0.0);
    for seed in 1..=3 {
        let art = line_art(128, 14, seed);
        let palette: HashSet<[u8; 4]> = shown(&art).into_iter().collect();
        let (clear, inked) = (share(&art, &|a| a == 0), share(&art, &|a| a >= 128));
        let tile = seamless_tile(&art, &SeamlessOptions { seed, ..Default::default() }, &mut Silent).unwrap();
        let texture = {
            let ex = Image::from_rgba8(128, 128, &art.data).unwrap();
            let o =
                TextureOptions { width: 192, height: 160, seed, alphas: vec![Some(art.alpha())], ..Default::default() };
            synthesize_texture(&ex, &o, &mut Silent).unwrap()
        };
        assert!(tile.warnings.is_empty(), "{:?}", tile.warnings);
        for (k, (what, out)) in [("tile", &tile.image), ("texture", &texture)].into_iter().enumerate() {
            let (c, i) = (share(out, &|a| a == 0), share(out, &|a| a >= 128));
            println!("seed {seed} {what}: clear {c:.3} (art {clear:.3}), inked {i:.3} (art {inked:.3})");
            assert!((c - clear).abs() < 0.08, "seed {seed} {what}: clear {c:.3} against {clear:.3}");
            // One seed may draw its rings sparser or denser (a tile of 128 holds a dozen);
            // none is empty, and over seeds the ink is the drawing's.
            assert!(i > 0.3 * inked, "seed {seed} {what}: inked {i:.3} against {inked:.3}");
            ink[k] += i / inked / 3.0;
            // Every pixel is one of the drawing's, as it shows: no ink made up, no ground
            // turned opaque.
            let strange = shown(out).iter().filter(|p| !palette.contains(*p)).count();
            assert_eq!(strange, 0, "seed {seed} {what}: {strange} pixels the drawing does not have");
        }
        // The wrap of the opacity is no seam either. On sparse line art one ring along a
        // line moves its score from 0 (no ink there) to 2, so the wrap is ranked among
        // every boundary of the torus (the tile rolled to put each at the wrap): a cut
        // ranks at the top in every seed.
        let t = &tile.image;
        let roll = |k: usize| {
            let a: Vec<[u8; 3]> = (0..128 * 128)
                .map(|i| [t.data[(((i / 128 + k) % 128) * 128 + (i % 128 + k) % 128) * 4 + 3]; 3])
                .collect();
            seam_score(&a, 128, 128)
        };
        let wrap = roll(0);
        let rank = (1..128).filter(|&k| roll(k) < wrap).count() as f64 / 127.0;
        println!("seed {seed}: alpha's wrap {wrap:.2}, ranked {rank:.2} among the boundaries");
        ranks += rank / 3.0;
    }
    assert!(ranks < 0.9, "the alpha's wrap ranks {ranks:.2} among the tiles' boundaries over seeds 1-3");
    for (what, ratio) in ["tile", "texture"].into_iter().zip(ink) {
        assert!((0.7..1.4).contains(&ratio), "{what}: ink {ratio:.2} of the drawing's over seeds 1-3");
    }
    // E-TFMCM reads colours only, and says so.
    let art = line_art(64, 5, 1);
    let o = SeamlessOptions { method: Method::Etfmcm, ..Default::default() };
    let paper = seamless_tile(&art, &o, &mut Silent).unwrap();
    assert!(paper.warnings.iter().any(|w| w.contains("transparency")), "{:?}", paper.warnings);
}

/// A channel of one level has a max count difference of 0, the lowest there is: an
/// orange fire whose blue is all 0 was generated from its blue, and its E-TFMCM tile
/// came back one flat colour. The channel chosen carries the picture's layout.
#[test]
fn etfmcm_generates_a_channel_that_varies() {
    let mut img = crop(&fixture("wood"), 64, 64);
    img.data.chunks_exact_mut(4).for_each(|p| p[2] = 0);
    for refine in [false, true] {
        let o = SeamlessOptions { method: Method::Etfmcm, refine, ..Default::default() };
        let t = seamless_tile(&img, &o, &mut Silent).unwrap();
        let colours: std::collections::HashSet<&[u8]> = t.image.data.chunks_exact(4).collect();
        println!(
            "refine {refine}: channel {:?}, {} colours, restoration {:.3}",
            t.channel,
            colours.len(),
            t.restoration_rate
        );
        assert_ne!(t.channel, Some('b'));
        assert!(colours.len() > 200, "refine {refine}: {} colours", colours.len());
        assert!(t.restoration_rate > 0.8, "refine {refine}: restoration {:.3}", t.restoration_rate);
    }
}

/// Each output pixel shows as the exemplar pixel its layout names, alpha and colour
/// together, on a many-coloured photograph with an alpha that varies (a single ink colour
/// could not tell a pixel's alpha read from the wrong source).
#[test]
fn a_synthesis_copies_each_pixel_s_alpha_with_its_colour() {
    use patternsynth::raster::{synthesize_textures, Layout};
    let mut img = crop(&fixture("wood"), 64, 64);
    for (i, p) in img.data.chunks_exact_mut(4).enumerate() {
        let (x, y) = (i % 64, i / 64);
        p[3] = if (x / 8 + y / 8) % 3 == 0 { 0 } else { (120 + 2 * x + y) as u8 };
    }
    let ex = Image::from_rgba8(64, 64, &img.data).unwrap();
    let shown = |p: &[u8]| if p[3] == 0 { [0, 0, 0, 0] } else { [p[0], p[1], p[2], p[3]] };
    for tileable in [false, true] {
        let o = TextureOptions {
            width: 96,
            height: 80,
            seed: 2,
            tileable,
            keep_layout: true,
            alphas: vec![Some(img.alpha())],
            ..Default::default()
        };
        let s = synthesize_textures(std::slice::from_ref(&ex), &o, &mut Silent).unwrap();
        let layout = s.layout.unwrap();
        for (i, out) in s.image.data.chunks_exact(4).enumerate() {
            let (_, x, y) = Layout::unpack(layout.data[i]);
            let want = shown(&img.data[(y * 64 + x) * 4..][..4]);
            assert_eq!(shown(out), want, "tileable {tileable}: pixel {i} copies ({x}, {y})");
        }
        let clear = s.image.data.chunks_exact(4).filter(|p| p[3] == 0).count() as f64 / (96.0 * 80.0);
        println!("tileable {tileable}: clear {clear:.3} (the photograph's 0.333)");
        assert!((0.2..0.45).contains(&clear), "tileable {tileable}: clear {clear:.3}");
    }
}

/// A sky photographed with a cloud bank along its top edge: soft light noise (a few
/// low sine waves), and rows above a wavy line 28 px down a dark red-brown, softly edged.
/// The bank has no top in the exemplar: the edge cuts it off.
fn cloud_bank(side: usize, seed: u64) -> Rgba {
    let mut rng = patternsynth::rng::Rng::new(seed);
    let waves: Vec<(f64, f64, f64)> = (0..6)
        .map(|_| {
            let f = |r: &mut patternsynth::rng::Rng| (r.below(1000) as f64 / 1000.0 - 0.5) * 0.3;
            (f(&mut rng), f(&mut rng), rng.below(628) as f64 / 100.0)
        })
        .collect();
    let mut data = Vec::with_capacity(side * side * 4);
    for y in 0..side {
        for x in 0..side {
            let (fx, fy) = (x as f64, y as f64);
            let light = 135.0 + waves.iter().map(|&(a, b, p)| 1.5 * (a * fx + b * fy + p).sin()).sum::<f64>();
            let line = 28.0 + 6.0 * (fx * std::f64::consts::TAU / 64.0).sin();
            let dark = ((line - fy) / 3.0 + 0.5).clamp(0.0, 1.0);
            let mix = |l: f64, d: f64| (l * (1.0 - dark) + d * dark).round() as u8;
            data.extend_from_slice(&[mix(light, 117.0), mix(light - 1.0, 109.0), mix(light + 2.0, 112.0), 255]);
        }
    }
    Rgba { width: side, height: side, data }
}

/// The mean colour difference across each row boundary of a tile (row y to y + 1, the
/// last to the first), per pixel.
fn row_steps(tile: &Rgba) -> Vec<f64> {
    let (w, h) = (tile.width, tile.height);
    let px = |x: usize, y: usize| &tile.data[((y % h) * w + x) * 4..][..3];
    (0..h)
        .map(|y| {
            let sum: u32 = (0..w)
                .map(|x| {
                    px(x, y).iter().zip(px(x, y + 1)).map(|(&a, &b)| (a as i32 - b as i32).unsigned_abs()).sum::<u32>()
                })
                .sum();
            sum as f64 / w as f64
        })
        .collect()
}

#[test]
fn a_feature_cut_off_by_the_exemplar_s_edge_is_seldom_laid_in_a_step() {
    // The cloud bank has no top anywhere in the exemplar, so a tile (which has no top
    // row) can hold it only where something above meets it in a step. A tile's quilt
    // owes the bank its share of the copies (`quilt::reach`), and had paid what it still
    // owed in the rows that close the wrap: on a photograph with such a bank (600 x 600,
    // seed 3) the row above the wrap differed 27 times as much as the mean row. Here,
    // seeds 1-8 at 256: the strongest row step was over 8 times the median row's on 5
    // seeds (up to 41 times). With the closing windows by fit alone and `quilt::reach`,
    // on 2 (21 and 15 times: the bank laid inside the tile, which the coverage term
    // still owed it); with `quilt::MISFIT` too, on 1 (11 times).
    let img = cloud_bank(128, 7);
    let mut strong = Vec::new();
    for seed in 1..=8 {
        let o = SeamlessOptions { method: Method::Synthesis, size: Some(256), seed, ..Default::default() };
        let tile = seamless_tile(&img, &o, &mut Silent).unwrap().image;
        let mut steps = row_steps(&tile);
        let strongest = steps.iter().copied().fold(0.0, f64::max);
        steps.sort_by(f64::total_cmp);
        let ratio = strongest / steps[steps.len() / 2];
        println!("seed {seed}: strongest row step {ratio:.2} times the median");
        if ratio > 8.0 {
            strong.push(ratio);
        }
    }
    assert!(strong.len() <= 1, "steps over 8 times the median row's: {strong:.1?}");
}

#[test]
fn fusion_keeps_the_copied_colours_distribution() {
    // A fused tile and the same tile unfused copy the same positions (the seed decides
    // them; fusion only colours): channel by channel, the fused tile's values are the
    // copied ones, moved between pixels but not changed (`fusion::Keep`).
    // Fused as before (each seam pulled in, extremes first), 27-39% of the ranked values
    // differed, by up to 10; plaster's tile lost contrast.
    for name in ["gravel", "tissue"] {
        let img = crop(&fixture(name), 96, 96);
        let tile = |fuse_seams| {
            let opts = SeamlessOptions {
                method: Method::Synthesis,
                size: Some(64),
                seed: 3,
                fuse_seams,
                ..Default::default()
            };
            seamless_tile(&img, &opts, &mut Silent).unwrap().image
        };
        let (fused, copied) = (tile(true), tile(false));
        let moved = fused.data.iter().zip(&copied.data).filter(|(a, b)| a != b).count();
        assert!(moved * 20 > fused.data.len(), "{name}: fusion changed {moved} bytes");
        for k in 0..3 {
            let values = |t: &Rgba| {
                let mut v: Vec<u8> = t.data.chunks_exact(4).map(|p| p[k]).collect();
                v.sort_unstable();
                v
            };
            let (f, c) = (values(&fused), values(&copied));
            // (Fused values are ranked in steps of 1/64: a few ties fall either way.)
            let off = f.iter().zip(&c).map(|(a, b)| a.abs_diff(*b)).max().unwrap();
            let differ = f.iter().zip(&c).filter(|(a, b)| a != b).count();
            assert!(
                off <= 2 && differ * 25 <= f.len(),
                "{name}, channel {k}: {differ} ranked values differ, by up to {off}"
            );
        }
    }
}
