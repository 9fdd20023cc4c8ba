//! Mending a photograph into a tile (the peer's tiling with an inpaint mask;
//! Substance Sampler's "make it tile"; Photoshop's offset and heal): the image is kept
//! as it is except a band straddling the wrap, which is re-made, reading the image on
//! a torus, so that its right edge continues into its left and its bottom into its
//! top without a seam. The band is `band` of each side in all: half of it along each
//! edge.

use crate::error::{invalid, Result};
use crate::progress::Progress;
use crate::raster::inpaint::Fill;
use crate::raster::Rgba;

/// The band's default share of each side: the outer 12.5% of each side re-made, the
/// inner 75% x 75% kept. Over the ten fixture photographs (seeds 1-8,
/// `examples/seam_profile <fixture> mend` with `BAND`), 9 wraps score 0.8-1.2 at 0.25,
/// 8 at 0.125 and 8 at 0.375; brick's, whose band fills with brick faces between
/// vertical joints, scores 0.2-0.4 at each.
pub const DEFAULT_BAND: f64 = 0.25;

/// The band is matched with 11 x 11 neighbourhoods at its coarser levels, which join
/// the structures that cross the wrap (a 5 x 5 one left blocks' and slate's mortar lines
/// broken at it), and 5 x 5 at the two finest (`Params::detail_levels`), where 11 x 11
/// tripled the time (its candidates come from each of 120 neighbours, each compared
/// over 121 pixels) and changed no seam.
const NEIGHBOURHOOD: usize = 11;
const DETAIL_LEVELS: usize = 2;

/// The mask of re-made pixels for an image `width x height` and a band of `band`:
/// `true` in the band.
pub fn band_mask(width: usize, height: usize, band: f64) -> Vec<bool> {
    let (bx, by) = (margin(width, band), margin(height, band));
    let mut mask = Vec::with_capacity(width * height);
    for y in 0..height {
        for x in 0..width {
            mask.push(x < bx || x + bx >= width || y < by || y + by >= height);
        }
    }
    mask
}

/// The re-made pixels along each edge: half the band, at least one pixel.
fn margin(side: usize, band: f64) -> usize {
    ((band * side as f64 / 2.0).round() as usize).clamp(1, side / 2)
}

/// `input` made to tile: the band re-made from the whole image (where `allowed`, if
/// given) on a torus.
pub fn mend(
    input: &Rgba,
    band: f64,
    allowed: Option<Vec<bool>>,
    seed: u64,
    progress: &mut dyn Progress,
) -> Result<Rgba> {
    if !(band.is_finite() && band > 0.0 && band < 1.0) {
        return invalid(format!("band must be above 0 and below 1 (a share of each side), got {band}."));
    }
    let mask = band_mask(input.width, input.height, band);
    let fill = Fill {
        known: mask.iter().map(|&m| !m).collect(),
        allowed,
        torus: true,
        seed,
        levels: None,
        neighbourhood: NEIGHBOURHOOD,
        detail_levels: DETAIL_LEVELS,
    };
    fill.run(input, progress)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn band_is_half_along_each_edge() {
        let m = band_mask(16, 8, 0.25);
        // 2 columns along each side edge, 1 row along top and bottom.
        let row = |y: usize| (0..16).map(|x| m[y * 16 + x]).collect::<Vec<_>>();
        assert!(row(0).iter().all(|&b| b) && row(7).iter().all(|&b| b));
        let mid = row(3);
        assert_eq!(mid.iter().filter(|&&b| b).count(), 4);
        assert!(mid[0] && mid[1] && !mid[2] && !mid[13] && mid[14] && mid[15]);
    }
}
