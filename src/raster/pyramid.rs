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
