//! Quality measures for synthesized textures (benchmarks and tests, not the engine).
//!
//! Patch energy: for sampled output pixels, the RMS colour difference between the
//! pixel's 7x7 neighbourhood (read on the torus) and its best-matching 7x7 window of the
//! exemplar, found exhaustively; averaged (RMS) over the samples. A verbatim copy of the
//! exemplar scores zero, so `repetition` also reports how alike the output is to itself
//! under large shifts. Colour balance: how far the output's colours are distributed
//! from the exemplar's (`colour_distance`), which patch energy cannot see: an output
//! made of the exemplar's smoothest region alone matches well everywhere.

use super::image::Image;
use crate::rng::Rng;

const R: isize = 3; // 7x7

/// Patch energy of `out` against `exemplar` over `samples` pixels drawn from rows
/// `rows.0..rows.1` (seeded).
pub fn patch_energy(out: &Image, exemplar: &Image, samples: usize, rows: (usize, usize), seed: u64) -> f64 {
    let mut rng = Rng::new(seed);
    let (ew, eh) = (exemplar.width as isize, exemplar.height as isize);
    let mut total = 0.0f64;
    for _ in 0..samples {
        let x = rng.below(out.width) as isize;
        let y = (rows.0 + rng.below((rows.1 - rows.0).max(1))) as isize;
        let mut patch = Vec::with_capacity(49);
        for dy in -R..=R {
            for dx in -R..=R {
                patch.push(out.wrapped(x + dx, y + dy));
            }
        }
        let mut best = f32::INFINITY;
        for cy in R..eh - R {
            for cx in R..ew - R {
                let mut acc = 0.0f32;
                let mut k = 0;
                'window: for dy in -R..=R {
                    let row = ((cy + dy) * ew) as usize;
                    for dx in -R..=R {
                        let p = exemplar.data[row + (cx + dx) as usize];
                        let q = patch[k];
                        acc += (p[0] - q[0]).powi(2) + (p[1] - q[1]).powi(2) + (p[2] - q[2]).powi(2);
                        k += 1;
                        if acc >= best {
                            break 'window;
                        }
                    }
                }
                best = best.min(acc);
            }
        }
        total += best as f64 / (49.0 * 3.0);
    }
    (total / samples as f64).sqrt()
}

/// Self-similarity at large shifts: the smallest mean absolute difference between the
/// output and itself shifted by at least `min_shift` pixels (on the torus), relative to
/// the median over all such shifts. Near 0 means a verbatim repetition.
pub fn repetition(out: &Image, min_shift: usize, seed: u64) -> f64 {
    let mut rng = Rng::new(seed);
    let pts: Vec<(isize, isize)> =
        (0..1024).map(|_| (rng.below(out.width) as isize, rng.below(out.height) as isize)).collect();
    let mut diffs = Vec::new();
    for dy in (0..out.height).step_by(2) {
        for dx in (0..out.width).step_by(2) {
            let (sx, sy) = (dx.min(out.width - dx), dy.min(out.height - dy));
            if sx * sx + sy * sy < min_shift * min_shift {
                continue;
            }
            let mut acc = 0.0f64;
            for &(x, y) in &pts {
                let p = out.wrapped(x, y);
                let q = out.wrapped(x + dx as isize, y + dy as isize);
                acc += ((p[0] - q[0]).abs() + (p[1] - q[1]).abs() + (p[2] - q[2]).abs()) as f64;
            }
            diffs.push(acc / pts.len() as f64);
        }
    }
    if diffs.is_empty() {
        return 1.0;
    }
    crate::order::floats(&mut diffs);
    diffs[0] / diffs[diffs.len() / 2].max(1e-9)
}

/// Bins per channel of `colour_distance`'s histograms.
const BINS: usize = 8;

/// The distance between the colour distributions of `out` and `exemplar`: total
/// variation (half the L1 distance) between their RGB histograms of 8 bins per channel.
/// 0 means the same shares of every colour, 1 no colour in common. An output that fills
/// itself with one region of the exemplar scores high however well its patches match
/// (tissue's 256 outputs, 70% the stroma that covers 30% of the exemplar: 0.52).
pub fn colour_distance(out: &Image, exemplar: &Image) -> f64 {
    let histogram = |img: &Image| {
        let mut h = vec![0.0f64; BINS * BINS * BINS];
        let bin = |v: f32| ((v.clamp(0.0, 255.0) as usize) * BINS / 256).min(BINS - 1);
        for p in &img.data {
            h[(bin(p[0]) * BINS + bin(p[1])) * BINS + bin(p[2])] += 1.0;
        }
        let n = img.data.len().max(1) as f64;
        h.iter_mut().for_each(|v| *v /= n);
        h
    };
    let (a, b) = (histogram(out), histogram(exemplar));
    0.5 * a.iter().zip(&b).map(|(p, q)| (p - q).abs()).sum::<f64>()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn image(colours: &[[f32; 3]]) -> Image {
        Image { width: colours.len(), height: 1, data: colours.to_vec() }
    }

    #[test]
    fn colour_distance_is_the_share_of_colours_out_of_place() {
        let (dark, light) = ([10.0, 10.0, 10.0], [240.0, 200.0, 100.0]);
        let ex = image(&[dark, dark, light, light]);
        // The same shares in another order, and within the same bins: 0.
        assert_eq!(colour_distance(&image(&[light, dark, [12.0, 9.0, 11.0], light]), &ex), 0.0);
        // Three quarters light where the exemplar is half: a quarter out of place.
        assert!((colour_distance(&image(&[dark, light, light, light]), &ex) - 0.25).abs() < 1e-12);
        assert_eq!(colour_distance(&image(&[[128.0, 0.0, 0.0]; 4]), &ex), 1.0);
    }
}
