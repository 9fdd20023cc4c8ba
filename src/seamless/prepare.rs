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

/// Refuses an image that is not what its size says, too small to tile, or clear.
pub(crate) fn check(input: &Rgba) -> Result<()> {
    let (w, h) = (input.width, input.height);
    crate::raster::image::check_size(w, h, "image")?;
    if input.data.len() != w * h * 4 {
        return invalid(format!("The image data has {} bytes; {w}x{h} RGBA needs {}.", input.data.len(), w * h * 4));
    }
    if w.min(h) < MIN_SIDE {
        return invalid(format!("The image is {w}x{h}; a seamless tile needs at least {MIN_SIDE} pixels on a side."));
    }
    // (A clear image would give a clear tile, or E-TFMCM's white one: nothing a person
    // meant to tile.)
    if input.data.chunks_exact(4).all(|p| p[3] == 0) {
        return invalid("The image is fully transparent: there is nothing in it to tile.");
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
        // (A strip loses most of itself: say which method keeps it whole.)
        let kept = 100 * short / w.max(h);
        warnings.push(format!(
            "Cropped the {w}x{h} image to its centre {short}x{short}, {kept}% of it (tiles are square; method 'synthesis' uses the whole image)."
        ));
    }
    if short != side {
        let verb = if side > short { "Enlarged" } else { "Scaled" };
        warnings.push(format!("{verb} {short}x{short} to {side}x{side} ({why})."));
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

/// The region `(x0, y0, cw, ch)` of `input` scaled to `(ow, oh)`, each axis apart
/// (`taps`): shrinking, each output pixel is the mean of the input pixels under its
/// footprint weighted by how much of each it covers (an area-weighted box filter);
/// enlarging, the two nearest input pixels weighted by distance (linear). Colours are
/// weighted by alpha, so a clear pixel's hidden colour does not bleed into its
/// neighbours. (The box once took every pixel the footprint touched at full weight:
/// shrinking a 640x900 gravel photograph to 364x512 it averaged 2-3 pixels a side for
/// 1.76, and the tile's sharpness, mean |dx| of luminance, was 12.8 against 14.9 for the
/// photograph area-weighted to the same size, helper-66's trial.)
fn resample(input: &Rgba, (x0, y0, cw, ch): (usize, usize, usize, usize), (ow, oh): (usize, usize)) -> Prepared {
    let (across, down) = (taps(cw, ow), taps(ch, oh));
    let mut rgb = Vec::with_capacity(ow * oh);
    let mut alpha = Vec::with_capacity(ow * oh);
    for ty in &down {
        for tx in &across {
            let (mut plain, mut weighted, mut coverage, mut total) = ([0f64; 3], [0f64; 3], 0f64, 0f64);
            for &(py, wy) in ty {
                for &(px, wx) in tx {
                    let i = ((y0 + py) * input.width + x0 + px) * 4;
                    let (w, a) = (wy * wx, input.data[i + 3] as f64 / 255.0);
                    for c in 0..3 {
                        plain[c] += w * input.data[i + c] as f64;
                        weighted[c] += w * a * input.data[i + c] as f64;
                    }
                    coverage += w * a;
                    total += w;
                }
            }
            // (Wholly clear: the plain mean, so the colour under it is kept.)
            let colour = if coverage > 1e-9 { weighted.map(|v| v / coverage) } else { plain.map(|v| v / total) };
            rgb.push(colour.map(|v| v.round().clamp(0.0, 255.0) as u8));
            alpha.push((255.0 * coverage / total).round().clamp(0.0, 255.0) as u8);
        }
    }
    Prepared { width: ow, height: oh, rgb, alpha }
}

/// For each of `out` pixels along an axis of `len` input pixels, the input pixels it
/// reads and their weights (summing to 1): the share of each under its footprint when
/// shrinking, the two nearest by distance when enlarging.
fn taps(len: usize, out: usize) -> Vec<Vec<(usize, f64)>> {
    let scale = len as f64 / out as f64;
    (0..out)
        .map(|o| {
            let taps: Vec<(usize, f64)> = if scale >= 1.0 {
                let (lo, hi) = (o as f64 * scale, (o + 1) as f64 * scale);
                (lo.floor() as usize..(hi.ceil() as usize).min(len))
                    .map(|i| (i, (hi.min(i as f64 + 1.0) - lo.max(i as f64)).max(0.0)))
                    .filter(|&(_, w)| w > 1e-9)
                    .collect()
            } else {
                let centre = ((o as f64 + 0.5) * scale - 0.5).clamp(0.0, (len - 1) as f64);
                let i = centre.floor() as usize;
                let t = centre - i as f64;
                vec![(i, 1.0 - t), ((i + 1).min(len - 1), t)]
            };
            let sum: f64 = taps.iter().map(|t| t.1).sum();
            taps.into_iter().map(|(i, w)| (i, w / sum)).collect()
        })
        .collect()
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
    fn shrinking_weighs_each_pixel_by_the_share_it_covers() {
        // Three columns into two: the middle one is half under each output pixel.
        let mut input = Rgba { width: 3, height: 1, data: vec![0, 0, 0, 255, 90, 90, 90, 255, 180, 180, 180, 255] };
        let p = resample(&input, (0, 0, 3, 1), (2, 1));
        assert_eq!(p.rgb, vec![[30; 3], [150; 3]]);
        // Enlarging: linear between the nearest two (output 4's centre is input 1.75).
        let p = resample(&input, (0, 0, 3, 1), (6, 1));
        assert_eq!(p.rgb[4][0], 158);
        assert_eq!(taps(3, 6).iter().map(|t| t.len()).max(), Some(2));
        // A clear pixel's colour does not bleed: the left output is its opaque pixels'.
        input.data[7] = 0;
        let p = resample(&input, (0, 0, 3, 1), (2, 1));
        assert_eq!((p.rgb[0], p.alpha[0]), ([0; 3], 170));
    }

    #[test]
    fn e_tfmcm_takes_the_centred_square_scaled_to_the_tile() {
        let mut warnings = Vec::new();
        let p = square(&image(100, 70), 64, "tiles are a power of two on a side", &mut warnings).unwrap();
        assert_eq!((p.width, p.height), (64, 64));
        assert!(warnings[0].contains("Cropped the 100x70 image to its centre 70x70"));
        assert!(warnings[1].contains("Scaled 70x70 to 64x64"));
        assert!(square(&image(6, 50), 8, "", &mut warnings).is_err());
        // A strip says how little is kept and which method keeps it; enlarging says so.
        let mut warnings = Vec::new();
        square(&image(9, 300), 16, "tiles are a power of two on a side", &mut warnings).unwrap();
        assert!(warnings[0].contains("centre 9x9, 3% of it") && warnings[0].contains("'synthesis'"), "{warnings:?}");
        assert!(warnings[1].starts_with("Enlarged 9x9 to 16x16"), "{warnings:?}");
        // A fully transparent image is refused, by every method's preparation.
        let mut clear = image(16, 16);
        clear.data.chunks_exact_mut(4).for_each(|p| p[3] = 0);
        for made in [whole(&clear, &mut warnings), square(&clear, 16, "", &mut warnings)] {
            let e = made.err().expect("refused").to_string();
            assert!(e.contains("fully transparent"), "{e}");
        }
    }
}
