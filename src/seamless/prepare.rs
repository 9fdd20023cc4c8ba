//! The image made into a tile's exemplar: checked, cropped and scaled as each method
//! needs, with a warning for each change.
//!
//! - E-TFMCM and TFMCM work on a square whose side is the tile's (their fractal halves a
//!   square, power-of-two tile): the image's centred square, scaled to the tile.
//! - Toroidal synthesis copies the image's own pixels: it takes the whole image at its
//!   own scale, whatever the tile's size, so that grass blades and bricks keep their
//!   size; only an image longer than `MAX_EXEMPLAR` on a side is scaled down (the
//!   search's cost grows with the exemplar's pixels). Until this module, it took the
//!   centred square, scaled to at most the tile's side: a 512² photograph's 256² tile had
//!   clouds and blades at half their size, a 96² one's default tile was 64² (the largest
//!   power of two, its sharpness 14.2 against 21.8), and a 127 x 80 photograph lost 37%
//!   of itself to the crop (helper-65's trial, Debian's gimp-data and scorched3d-data).

use crate::error::{invalid, Result};
use crate::raster::Rgba;

/// The smallest side of an image a tile is made from.
pub const MIN_SIDE: usize = 8;
/// The longest side of a synthesized tile's exemplar.
pub const MAX_EXEMPLAR: usize = 512;

/// An exemplar: its size, its colours averaged over each pixel's footprint by their
/// alpha (a clear ground's colour does not darken the edges of what is drawn on it),
/// and its alpha.
pub struct Prepared {
    pub width: usize,
    pub height: usize,
    pub rgb: Vec<[u8; 3]>,
    pub alpha: Vec<u8>,
}

/// Refuses an image that is not what its size says, or too small to tile.
fn check(input: &Rgba) -> Result<()> {
    let (w, h) = (input.width, input.height);
    crate::raster::image::check_size(w, h, "image")?;
    if input.data.len() != w * h * 4 {
        return invalid(format!("The image data has {} bytes; {w}x{h} RGBA needs {}.", input.data.len(), w * h * 4));
    }
    if w.min(h) < MIN_SIDE {
        return invalid(format!("The image is {w}x{h}; a seamless tile needs at least {MIN_SIDE} pixels on a side."));
    }
    Ok(())
}

/// E-TFMCM's exemplar: `input`'s centred square scaled to `side`, saying so (`why`:
/// the reason for the scale, in the warning).
pub fn square(input: &Rgba, side: usize, why: &str, warnings: &mut Vec<String>) -> Result<Prepared> {
    check(input)?;
    let (w, h) = (input.width, input.height);
    let short = w.min(h);
    if w != h {
        warnings.push(format!("Cropped the {w}x{h} image to its centre {short}x{short} (tiles are square)."));
    }
    if short != side {
        warnings.push(format!("Scaled {short}x{short} to {side}x{side} ({why})."));
    }
    Ok(resample(input, ((w - short) / 2, (h - short) / 2, short, short), (side, side)))
}

/// Synthesis's exemplar: the whole of `input` at its own scale, scaled down (keeping its
/// proportions) only to at most `MAX_EXEMPLAR` on its longer side. A strip too long for
/// that to leave `MIN_SIDE` across is first cropped to its centre.
pub fn whole(input: &Rgba, warnings: &mut Vec<String>) -> Result<Prepared> {
    check(input)?;
    let (w, h) = (input.width, input.height);
    let (short, long) = (w.min(h), w.max(h));
    let keep = long.min(short * MAX_EXEMPLAR / MIN_SIDE);
    let (cw, ch) = if w >= h { (keep, h) } else { (w, keep) };
    if keep < long {
        warnings.push(format!(
            "Cropped the {w}x{h} image to its centre {cw}x{ch} (scaled to {MAX_EXEMPLAR} pixels along, it would be under {MIN_SIDE} across)."
        ));
    }
    let (ow, oh) = if keep > MAX_EXEMPLAR {
        let f = MAX_EXEMPLAR as f64 / keep as f64;
        let scaled = |v: usize| ((v as f64 * f).round() as usize).clamp(MIN_SIDE, MAX_EXEMPLAR);
        (scaled(cw), scaled(ch))
    } else {
        (cw, ch)
    };
    if (ow, oh) != (cw, ch) {
        warnings.push(format!(
            "Scaled {cw}x{ch} to {ow}x{oh} (the exemplar of a synthesized tile is at most {MAX_EXEMPLAR} on a side)."
        ));
    }
    Ok(resample(input, ((w - cw) / 2, (h - ch) / 2, cw, ch), (ow, oh)))
}

/// The region `(x0, y0, cw, ch)` of `input` scaled to `(ow, oh)` by a box filter over
/// each output pixel's footprint (bilinear-like when enlarging).
fn resample(input: &Rgba, (x0, y0, cw, ch): (usize, usize, usize, usize), (ow, oh): (usize, usize)) -> Prepared {
    let (sx, sy) = (cw as f64 / ow as f64, ch as f64 / oh as f64);
    let mut rgb = Vec::with_capacity(ow * oh);
    let mut alpha = Vec::with_capacity(ow * oh);
    for y in 0..oh {
        let (fy0, fy1) = (y as f64 * sy, (y + 1) as f64 * sy);
        let ya = fy0.floor() as usize;
        let yb = (fy1.ceil() as usize).clamp(ya + 1, ch);
        for x in 0..ow {
            let (fx0, fx1) = (x as f64 * sx, (x + 1) as f64 * sx);
            let xa = fx0.floor() as usize;
            let xb = (fx1.ceil() as usize).clamp(xa + 1, cw);
            let (mut acc, mut weighted, mut coverage) = ([0u32; 3], [0u64; 3], 0u64);
            for py in ya..yb {
                for px in xa..xb {
                    let i = ((y0 + py) * input.width + x0 + px) * 4;
                    let a = input.data[i + 3] as u64;
                    for c in 0..3 {
                        acc[c] += input.data[i + c] as u32;
                        weighted[c] += input.data[i + c] as u64 * a;
                    }
                    coverage += a;
                }
            }
            let n = ((xb - xa) * (yb - ya)) as u32;
            rgb.push(if coverage == 0 || coverage == 255 * n as u64 {
                acc.map(|v| ((v + n / 2) / n) as u8)
            } else {
                weighted.map(|v| ((v + coverage / 2) / coverage) as u8)
            });
            alpha.push(((coverage + n as u64 / 2) / n as u64) as u8);
        }
    }
    Prepared { width: ow, height: oh, rgb, alpha }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn image(w: usize, h: usize) -> Rgba {
        let data = (0..w * h).flat_map(|i| [(i % w) as u8, (i / w) as u8, 7, 255]).collect();
        Rgba { width: w, height: h, data }
    }

    #[test]
    fn synthesis_keeps_the_whole_image_at_its_scale() {
        let mut warnings = Vec::new();
        let p = whole(&image(127, 80), &mut warnings).unwrap();
        assert_eq!((p.width, p.height), (127, 80));
        assert!(warnings.is_empty(), "{warnings:?}");
        // Pixels as they were.
        assert_eq!(p.rgb[80 * 127 - 1], [126, 79, 7]);
        // Longer than MAX_EXEMPLAR: scaled down, proportions kept.
        let p = whole(&image(1024, 300), &mut warnings).unwrap();
        assert_eq!((p.width, p.height), (512, 150));
        assert!(warnings[0].contains("Scaled 1024x300 to 512x150"), "{warnings:?}");
        // A strip cropped so that it stays MIN_SIDE across.
        let mut warnings = Vec::new();
        let p = whole(&image(4000, 10), &mut warnings).unwrap();
        assert_eq!((p.width, p.height), (512, 8));
        assert!(warnings[0].contains("Cropped the 4000x10 image to its centre 640x10"), "{warnings:?}");
    }

    #[test]
    fn e_tfmcm_takes_the_centred_square_scaled_to_the_tile() {
        let mut warnings = Vec::new();
        let p = square(&image(100, 70), 64, "tiles are a power of two on a side", &mut warnings).unwrap();
        assert_eq!((p.width, p.height), (64, 64));
        assert!(warnings[0].contains("Cropped the 100x70 image to its centre 70x70"));
        assert!(warnings[1].contains("Scaled 70x70 to 64x64"));
        assert!(square(&image(6, 50), 8, "", &mut warnings).is_err());
    }
}
