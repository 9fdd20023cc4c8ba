//! The raster type the texture engines work on: RGB in `f32` (0-255 scale), row major.
//! RGBA bytes convert at the edges; alpha travels beside the colours: a synthesis copies
//! it with each pixel (`TextureOptions::alphas`), a fill matches, copies and heals it
//! (`inpaint`).

use crate::error::{invalid, Error, Result};

#[derive(Clone, Debug, PartialEq)]
pub struct Image {
    pub width: usize,
    pub height: usize,
    pub data: Vec<[f32; 3]>,
}

/// RGBA bytes (4 per pixel, row major) and their size: what decoders give and the
/// engines return.
#[derive(Clone, Debug, PartialEq)]
pub struct Rgba {
    pub width: usize,
    pub height: usize,
    pub data: Vec<u8>,
}

impl Rgba {
    /// The colours without alpha, one per pixel (what the seamless engine and its
    /// measures read).
    pub fn rgb(&self) -> Vec<[u8; 3]> {
        self.data.chunks_exact(4).map(|p| [p[0], p[1], p[2]]).collect()
    }

    /// The colours as they show over white (the measures' reading of an image with
    /// transparency: a clear ground reads as paper, not as the black it may hold).
    pub fn rgb_over_white(&self) -> Vec<[u8; 3]> {
        self.data.chunks_exact(4).map(|p| over_white([p[0], p[1], p[2]], p[3])).collect()
    }

    /// Each pixel's alpha.
    pub fn alpha(&self) -> Vec<u8> {
        self.data.chunks_exact(4).map(|p| p[3]).collect()
    }

    /// Whether every pixel is opaque.
    pub fn opaque(&self) -> bool {
        self.data.chunks_exact(4).all(|p| p[3] == 255)
    }

    /// Whether not every pixel has the same alpha (a fill then matches and heals it).
    pub fn alpha_varies(&self) -> bool {
        self.data.chunks_exact(4).any(|p| p[3] != self.data[3])
    }
}

/// Colour `c` of alpha `a` composited over white.
pub fn over_white(c: [u8; 3], a: u8) -> [u8; 3] {
    let a = a as u32;
    c.map(|v| ((v as u32 * a + 255 * (255 - a) + 127) / 255) as u8)
}

/// Largest side of an image the engines accept (memory stays bounded: see `MAX_PIXELS`).
pub const MAX_SIDE: usize = 4096;
/// Largest pixel count of an output (4096 x 4096). Texture synthesis's working memory
/// is about 10 bytes per output pixel from one exemplar and 21 when blending two
/// (`synthesis::synthesize`; peaks measured by `bench_texture --memory`, RGBA in to
/// RGBA out: 2048 x 2048 40 MB and 89 MB, 4096 x 4096 157 MB and 348 MB), within
/// wasm's 4 GB; the package gives an instance's memory back after such a call.
pub const MAX_PIXELS: usize = 4096 * 4096;

impl Image {
    pub fn new(width: usize, height: usize) -> Image {
        Image { width, height, data: vec![[0.0; 3]; width * height] }
    }

    /// From RGBA bytes (as a canvas `ImageData` holds them).
    pub fn from_rgba8(width: usize, height: usize, rgba: &[u8]) -> Result<Image> {
        check_size(width, height, "image")?;
        if rgba.len() != width * height * 4 {
            return invalid(format!(
                "The image data has {} bytes; {width}x{height} RGBA needs {}.",
                rgba.len(),
                width * height * 4
            ));
        }
        let data = rgba.chunks_exact(4).map(|p| [p[0] as f32, p[1] as f32, p[2] as f32]).collect();
        Ok(Image { width, height, data })
    }

    /// To RGBA bytes, opaque, rounded and clamped.
    pub fn to_rgba8(&self) -> Vec<u8> {
        let mut out = Vec::with_capacity(self.data.len() * 4);
        for p in &self.data {
            out.extend(p.iter().map(|&v| v.round().clamp(0.0, 255.0) as u8));
            out.push(255);
        }
        out
    }

    #[inline]
    pub fn at(&self, x: usize, y: usize) -> [f32; 3] {
        self.data[y * self.width + x]
    }

    /// The pixel at (x, y) read on a torus.
    #[inline]
    pub fn wrapped(&self, x: isize, y: isize) -> [f32; 3] {
        self.data[torus_index(x, y, self.width, self.height)]
    }

    /// The pixel at (x, y) with coordinates clamped to the image.
    #[inline]
    pub fn clamped(&self, x: isize, y: isize) -> [f32; 3] {
        let x = x.clamp(0, self.width as isize - 1) as usize;
        let y = y.clamp(0, self.height as isize - 1) as usize;
        self.data[y * self.width + x]
    }
}

/// Row-major index of (x, y) in a `width x height` grid read on a torus.
#[inline]
pub fn torus_index(x: isize, y: isize, width: usize, height: usize) -> usize {
    wrap(y, height) * width + wrap(x, width)
}

/// `v` read on a circle of `n`: `v mod n`, without a division for a value inside or one
/// lap outside (a neighbour of a pixel near the wrap), which the synthesis reads for
/// every neighbour of every pixel.
#[inline(always)]
pub fn wrap(v: isize, n: usize) -> usize {
    let n = n as isize;
    if (0..n).contains(&v) {
        v as usize
    } else if (-n..0).contains(&v) {
        (v + n) as usize
    } else if (n..2 * n).contains(&v) {
        (v - n) as usize
    } else {
        v.rem_euclid(n) as usize
    }
}

/// The bin of an RGB colour (0-255 a channel) among `bins` per channel, as one index
/// below `bins` cubed: the colour histograms' (`energy::colour_distance`, the tile's
/// colour balance in `synthesis::reuse`).
pub fn colour_bin(c: &[f32], bins: usize) -> usize {
    let q = |v: f32| ((v.clamp(0.0, 255.0) as usize) * bins / 256).min(bins - 1);
    (q(c[0]) * bins + q(c[1])) * bins + q(c[2])
}

/// Rejects empty and over-large sizes with a message naming `what`.
pub fn check_size(width: usize, height: usize, what: &str) -> Result<()> {
    if width == 0 || height == 0 {
        return invalid(format!("The {what} is empty ({width}x{height})."));
    }
    if width > MAX_SIDE || height > MAX_SIDE {
        return Err(Error::TooLarge(format!(
            "The {what} is {width}x{height}; the largest side accepted is {MAX_SIDE}."
        )));
    }
    Ok(())
}

/// Rejects output sizes beyond the memory cap.
pub fn check_output(width: usize, height: usize) -> Result<()> {
    check_size(width, height, "output")?;
    if width * height > MAX_PIXELS {
        return Err(Error::TooLarge(format!(
            "An output of {width}x{height} is {} pixels; the limit is {MAX_PIXELS} (4096x4096).",
            width * height
        )));
    }
    Ok(())
}
