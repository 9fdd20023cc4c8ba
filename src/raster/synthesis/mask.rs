//! Masks through the pyramid: which exemplar positions may be copied (a sample mask,
//! or a hole's complement) and which output pixels are known, at every level; and the
//! smooth fill that keeps masked pixels' colours out of the coarser levels.
//!
//! A coarse pixel is a blur of the finer pixels around its even child (`pyramid`), so
//! it is allowed (or known) only when every finer pixel within one of that child is:
//! each level erodes the mask by a pixel. A coarse exemplar position then never holds a
//! masked pixel's colour in its own centre, and a pinned coarse output pixel is made of
//! known pixels only.

use crate::raster::image::{wrap, Image};

/// A boolean mask at each level of a pyramid, finest first, each eroded from the one
/// below it (see the module). `torus` reads the neighbours of edge pixels across the
/// wrap (an output tile); otherwise edges are clamped.
pub(crate) fn pyramid(finest: Vec<bool>, width: usize, height: usize, levels: usize, torus: bool) -> Vec<Vec<bool>> {
    let mut out = vec![finest];
    let (mut w, mut h) = (width, height);
    while out.len() < levels {
        let fine = out.last().expect("at least the finest level");
        let (w2, h2) = (w.div_ceil(2), h.div_ceil(2));
        let at = |x: isize, y: isize| {
            let (x, y) = if torus {
                (wrap(x, w), wrap(y, h))
            } else {
                (x.clamp(0, w as isize - 1) as usize, y.clamp(0, h as isize - 1) as usize)
            };
            fine[y * w + x]
        };
        let mut coarse = Vec::with_capacity(w2 * h2);
        for y in 0..h2 as isize {
            for x in 0..w2 as isize {
                let all = (-1..=1).all(|j| (-1..=1).all(|i| at(2 * x + i, 2 * y + j)));
                coarse.push(all);
            }
        }
        out.push(coarse);
        (w, h) = (w2, h2);
    }
    out
}

/// `img` with the pixels where `keep` is false filled smoothly from the others
/// (push-pull: the kept pixels averaged over ever coarser 2 x 2 blocks, each hole
/// filled from the coarsest block that reaches it, blended back down), so that a blur
/// near a hole mixes in the colours around it rather than the hole's own (a logo, a
/// pipe). Kept pixels are unchanged. With nothing kept, the image is returned as is.
pub(crate) fn fill(img: &Image, keep: &[bool]) -> Image {
    if keep.iter().all(|&k| k) || !keep.iter().any(|&k| k) {
        return img.clone();
    }
    // Pull: per level, the weighted sum of kept colours and the weight.
    let mut levels: Vec<(usize, usize, Vec<[f32; 4]>)> = Vec::new();
    let first = img.data.iter().zip(keep).map(|(c, &k)| if k { [c[0], c[1], c[2], 1.0] } else { [0.0; 4] }).collect();
    levels.push((img.width, img.height, first));
    loop {
        let (w, h, fine) = levels.last().expect("the finest level");
        if *w == 1 && *h == 1 {
            break;
        }
        let (w, h) = (*w, *h);
        let (w2, h2) = (w.div_ceil(2), h.div_ceil(2));
        let mut coarse = vec![[0.0f32; 4]; w2 * h2];
        for y in 0..h {
            for x in 0..w {
                let c = &mut coarse[(y / 2) * w2 + x / 2];
                (0..4).for_each(|k| c[k] += fine[y * w + x][k]);
            }
        }
        // Normalised to a weight of at most 1, so a coarse block counts as one pixel.
        for c in &mut coarse {
            if c[3] > 1.0 {
                let s = 1.0 / c[3];
                *c = [c[0] * s, c[1] * s, c[2] * s, 1.0];
            }
        }
        levels.push((w2, h2, coarse));
    }
    // Push: each level's missing weight taken from the (filled) level above it.
    for l in (0..levels.len() - 1).rev() {
        let (w2, coarse) = (levels[l + 1].0, levels[l + 1].2.clone());
        let (w, _, fine) = &mut levels[l];
        let w = *w;
        for (i, c) in fine.iter_mut().enumerate() {
            let p = coarse[((i / w) / 2) * w2 + (i % w) / 2];
            let missing = (1.0 - c[3]).max(0.0);
            let norm = if p[3] > 0.0 { missing / p[3] } else { 0.0 };
            (0..3).for_each(|k| c[k] += p[k] * norm);
            c[3] += p[3] * norm;
        }
    }
    let finest = &levels[0].2;
    let data = img
        .data
        .iter()
        .zip(keep)
        .zip(finest)
        .map(|((c, &k), f)| if k || f[3] <= 0.0 { *c } else { [f[0] / f[3], f[1] / f[3], f[2] / f[3]] })
        .collect();
    Image { width: img.width, height: img.height, data }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn each_level_erodes_by_a_pixel() {
        // A 16 x 16 mask with a hole at (8, 8): level 1 loses (3..=5, 3..=5) around (4, 4).
        let mut m = vec![true; 256];
        m[8 * 16 + 8] = false;
        let p = pyramid(m, 16, 16, 3, false);
        assert_eq!(p[1].len(), 64);
        let lost: Vec<usize> = (0..64).filter(|&i| !p[1][i]).collect();
        // Children within one of 2x: 2x - 1 ..= 2x + 1 holds 8 for x = 4 only (7, 8, 9).
        assert_eq!(lost, vec![4 * 8 + 4]);
        assert_eq!(p[2].iter().filter(|&&v| !v).count(), 1);
        // On a torus, a hole at the last pixel reaches the first coarse row and column.
        let mut m = vec![true; 256];
        m[255] = false;
        let p = pyramid(m, 16, 16, 2, true);
        assert_eq!(p[1].iter().filter(|&&v| !v).count(), 4);
        assert!(!p[1][0] && !p[1][7] && !p[1][7 * 8] && !p[1][63]);
        assert!(p[1][3]);
    }

    #[test]
    fn fill_keeps_kept_pixels_and_fills_from_around() {
        // Left half red, right half blue, a hole in the middle of the red half.
        let mut img = Image::new(32, 32);
        let mut keep = vec![true; 32 * 32];
        for y in 0..32 {
            for x in 0..32 {
                img.data[y * 32 + x] = if x < 16 { [200.0, 0.0, 0.0] } else { [0.0, 0.0, 200.0] };
                if (4..12).contains(&x) && (12..20).contains(&y) {
                    img.data[y * 32 + x] = [0.0, 255.0, 0.0];
                    keep[y * 32 + x] = false;
                }
            }
        }
        let f = fill(&img, &keep);
        for ((k, out), orig) in keep.iter().zip(&f.data).zip(&img.data) {
            if *k {
                assert_eq!(out, orig);
            } else {
                // No green left, and mostly the red around it.
                assert!(out[1] < 1.0 && out[0] > 150.0, "{out:?}");
            }
        }
    }
}
