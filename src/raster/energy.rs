//! Quality measures for synthesized textures (benchmarks and tests, not the engine).
//!
//! Patch energy: for sampled output pixels, the RMS colour difference between the
//! pixel's 7x7 neighbourhood (read on the torus) and its best-matching 7x7 window of the
//! exemplar, found exhaustively; averaged (RMS) over the samples. A verbatim copy of the
//! exemplar scores zero, so `repetition` also reports how alike the output is to itself
//! under large shifts.

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
