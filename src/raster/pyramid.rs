//! Gaussian pyramids: each level is the previous one blurred by the binomial kernel
//! (1 4 6 4 1)/16 in x and y, then halved (sizes round up).

use super::image::Image;

#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Edge {
    /// Exemplars: the border pixel repeats.
    Clamp,
    /// Outputs on a torus.
    Wrap,
}

const TAPS: [f32; 5] = [1.0 / 16.0, 4.0 / 16.0, 6.0 / 16.0, 4.0 / 16.0, 1.0 / 16.0];

/// One level down: blur, then keep every other pixel.
pub fn downsample(img: &Image, edge: Edge) -> Image {
    let read = |x: isize, y: isize| match edge {
        Edge::Clamp => img.clamped(x, y),
        Edge::Wrap => img.wrapped(x, y),
    };
    let (w2, h2) = (img.width.div_ceil(2), img.height.div_ceil(2));
    // Horizontal pass at the kept columns, all rows.
    let mut tmp = Image::new(w2, img.height);
    for y in 0..img.height {
        for x2 in 0..w2 {
            let mut acc = [0.0f32; 3];
            for (k, t) in TAPS.iter().enumerate() {
                let p = read(2 * x2 as isize + k as isize - 2, y as isize);
                for c in 0..3 {
                    acc[c] += t * p[c];
                }
            }
            tmp.data[y * w2 + x2] = acc;
        }
    }
    let read_tmp = |x: usize, y: isize| match edge {
        Edge::Clamp => tmp.clamped(x as isize, y),
        Edge::Wrap => tmp.wrapped(x as isize, y),
    };
    let mut out = Image::new(w2, h2);
    for y2 in 0..h2 {
        for x in 0..w2 {
            let mut acc = [0.0f32; 3];
            for (k, t) in TAPS.iter().enumerate() {
                let p = read_tmp(x, 2 * y2 as isize + k as isize - 2);
                for c in 0..3 {
                    acc[c] += t * p[c];
                }
            }
            out.data[y2 * w2 + x] = acc;
        }
    }
    out
}

/// `coarse` (a level of a pyramid) read at the pixels of the `width x height` level
/// below it: pixel (x, y) there lies at (x / 2, y / 2) of `coarse`, since `downsample`
/// centres each coarse pixel on its even child; odd pixels take the mean of the two or
/// four coarse pixels around them, clamped at the border.
pub fn upsample(coarse: &Image, width: usize, height: usize) -> Image {
    let mut out = Image::new(width, height);
    for y in 0..height {
        for x in 0..width {
            let (x0, x1, y0, y1) = (x / 2, x.div_ceil(2), y / 2, y.div_ceil(2));
            let mut acc = [0.0f32; 3];
            for (cx, cy) in [(x0, y0), (x1, y0), (x0, y1), (x1, y1)] {
                let p = coarse.clamped(cx as isize, cy as isize);
                (0..3).for_each(|c| acc[c] += p[c] / 4.0);
            }
            out.data[y * width + x] = acc;
        }
    }
    out
}

/// `levels` images, finest first.
pub fn build(img: &Image, levels: usize, edge: Edge) -> Vec<Image> {
    let mut out = vec![img.clone()];
    while out.len() < levels {
        let next = downsample(out.last().unwrap(), edge);
        out.push(next);
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn constant_stays_constant_and_sizes_halve() {
        let mut img = Image::new(9, 6);
        img.data.iter_mut().for_each(|p| *p = [10.0, 20.0, 30.0]);
        let p = build(&img, 3, Edge::Clamp);
        assert_eq!((p[1].width, p[1].height, p[2].width, p[2].height), (5, 3, 3, 2));
        for level in &p {
            for px in &level.data {
                assert!((px[0] - 10.0).abs() < 1e-4 && (px[2] - 30.0).abs() < 1e-4);
            }
        }
    }

    #[test]
    fn upsample_reads_a_level_where_the_finer_pixels_lie() {
        let mut coarse = Image::new(3, 2);
        for (i, p) in coarse.data.iter_mut().enumerate() {
            *p = [i as f32 * 10.0; 3];
        }
        let up = upsample(&coarse, 6, 4);
        let at = |x: usize, y: usize| up.data[y * 6 + x][0];
        // Even pixels are the coarse pixels; odd ones lie between two or four.
        assert_eq!((at(0, 0), at(2, 0), at(4, 2)), (0.0, 10.0, 50.0));
        assert_eq!((at(1, 0), at(0, 1), at(1, 1)), (5.0, 15.0, 20.0));
        // Past the last coarse pixel the border repeats.
        assert_eq!((at(5, 0), at(5, 3)), (20.0, 50.0));
    }

    #[test]
    fn wrap_keeps_the_mean() {
        let mut img = Image::new(8, 8);
        for (i, p) in img.data.iter_mut().enumerate() {
            *p = [(i * 37 % 256) as f32; 3];
        }
        let mean = |im: &Image| im.data.iter().map(|p| p[0]).sum::<f32>() / im.data.len() as f32;
        let down = downsample(&img, Edge::Wrap);
        assert!((mean(&img) - mean(&down)).abs() < 1e-3);
    }
}
