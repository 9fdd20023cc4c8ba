//! Quality measures for synthesized textures (benchmarks and tests, not the engine).
//!
//! Patch energy: for sampled output pixels, the RMS colour difference between the
//! pixel's 7x7 neighbourhood (read on the torus) and its best-matching 7x7 window of the
//! exemplar, found exhaustively; averaged (RMS) over the samples. A verbatim copy of the
//! exemplar scores zero, so `repetition` also reports how alike the output is to itself
//! under large shifts. Colour balance: how far the output's colours are distributed
//! from the exemplar's (`colour_distance`), which patch energy cannot see: an output
//! made of the exemplar's smoothest region alone matches well everywhere.

use super::image::{colour_bin, Image};
use crate::rng::Rng;

const R: isize = 3; // 7x7

/// Patch energy of `out` against `exemplar` over `samples` pixels drawn from rows
/// `rows.0..rows.1` (seeded).
pub fn patch_energy(out: &Image, exemplar: &Image, samples: usize, rows: (usize, usize), seed: u64) -> f64 {
    patch_energy_pool(out, &[exemplar], samples, rows, seed)
}

/// Patch energy against several exemplars drawn from as one pool: each sample's best
/// window in any of them (windows lie wholly inside one exemplar).
pub fn patch_energy_pool(out: &Image, exemplars: &[&Image], samples: usize, rows: (usize, usize), seed: u64) -> f64 {
    let mut rng = Rng::new(seed);
    let mut total = 0.0f64;
    let mut patch = Vec::with_capacity(49);
    for _ in 0..samples {
        let x = rng.below(out.width) as isize;
        let y = (rows.0 + rng.below((rows.1 - rows.0).max(1))) as isize;
        patch.clear();
        for dy in -R..=R {
            for dx in -R..=R {
                patch.push(out.wrapped(x + dx, y + dy));
            }
        }
        let best = exemplars.iter().fold(f32::INFINITY, |best, e| best_window(&patch, e, best));
        total += best as f64 / (49.0 * 3.0);
    }
    (total / samples as f64).sqrt()
}

/// The smallest squared distance from `patch` (7x7, row-major) to a window of
/// `exemplar`, or `best` if none is closer.
fn best_window(patch: &[[f32; 3]], exemplar: &Image, mut best: f32) -> f32 {
    let (ew, eh) = (exemplar.width as isize, exemplar.height as isize);
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
    best
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

/// `repetition` in windows of the exemplar's size: the mean over `crops` windows cut
/// from `out` at seeded places (read on the torus, where a tile wraps), each scored as
/// the exemplar is, so that an output of any size compares with its exemplar's own
/// score over the same shifts. (Measured whole, a large output is scored over shifts
/// its exemplar does not have; a lattice of copies far apart shows only so: report
/// both.) An output no larger than the exemplar gives `repetition` itself.
pub fn repetition_fair(out: &Image, (ew, eh): (usize, usize), min_shift: usize, crops: usize, seed: u64) -> f64 {
    if (out.width, out.height) == (ew, eh) || out.width < ew || out.height < eh {
        return repetition(out, min_shift, seed);
    }
    let mut rng = Rng::new(seed ^ 0xC0);
    let mut total = 0.0;
    for _ in 0..crops.max(1) {
        let (x0, y0) = (rng.below(out.width) as isize, rng.below(out.height) as isize);
        let mut crop = Image::new(ew, eh);
        for y in 0..eh {
            for x in 0..ew {
                crop.data[y * ew + x] = out.wrapped(x0 + x as isize, y0 + y as isize);
            }
        }
        total += repetition(&crop, min_shift, seed);
    }
    total / crops.max(1) as f64
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
        for p in &img.data {
            h[colour_bin(p, BINS)] += 1.0;
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
    fn repetition_fair_scores_windows_of_the_exemplars_size() {
        // Smooth noise with no repetition, 64 px (the exemplar) and 256 px of it: in
        // windows of 64 the large one scores as the exemplar does. Made of a 32 px block
        // repeated, every window of 64 holds a verbatim copy at a shift of 32: near 0.
        let noise = |side: usize, period: usize, seed: u64| {
            let mut rng = Rng::new(seed);
            let raw: Vec<f32> = (0..period * period).map(|_| rng.below(256) as f32).collect();
            let mut img = Image::new(side, side);
            for y in 0..side {
                for x in 0..side {
                    let mut v = 0.0;
                    for (dx, dy) in [(0, 0), (1, 0), (0, 1), (1, 1)] {
                        v += raw[((y + dy) % period) * period + (x + dx) % period] / 4.0;
                    }
                    img.data[y * side + x] = [v; 3];
                }
            }
            img
        };
        let exemplar = noise(64, 64, 1);
        let own = repetition(&exemplar, 16, 1);
        let fair = repetition_fair(&noise(256, 256, 2), (64, 64), 16, 8, 1);
        assert!((fair - own).abs() < 0.03, "fair {fair:.3}, exemplar {own:.3}");
        let repeated = repetition_fair(&noise(256, 32, 3), (64, 64), 16, 8, 1);
        assert!(repeated < 0.05, "a block repeated: {repeated:.3}");
        // A block of 128 repeated is a lattice of copies too far apart for a window of
        // 64 to hold two: the whole output shows it, the windows do not.
        let far = noise(256, 128, 4);
        let (whole, fair) = (repetition(&far, 16, 1), repetition_fair(&far, (64, 64), 16, 8, 1));
        assert!(whole < 0.05 && (fair - own).abs() < 0.05, "whole {whole:.3}, in windows {fair:.3}");
        assert_eq!(repetition_fair(&exemplar, (64, 64), 16, 8, 1), own);
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
