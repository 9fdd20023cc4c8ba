//! Mending a photograph into a tile (the peer's tiling with an inpaint mask;
//! Substance Sampler's "make it tile"; Photoshop's offset and heal): the image is kept
//! as it is except a band straddling the wrap, which is re-made, reading the image on
//! a torus, so that its right edge continues into its left and its bottom into its
//! top without a seam. The band is `band` of each side in all: half of it along each
//! edge, and at least `MIN_MARGIN` pixels.

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

/// The least re-made pixels along each edge (a quarter of the side on an image under
/// 16 pixels): a narrower band cannot blend one edge into the other. On the ten fixture
/// photographs (128 pixels, seeds 1-2) a band of 1 or 2 pixels a side left seams of
/// 1.66 and 1.24 (medians; 12 and 11 of 20 outside 0.8-1.2), 3 pixels 0.99 (2 of 20).
const MIN_MARGIN: usize = 4;

/// The re-made pixels along each edge: half the band, at least `MIN_MARGIN`.
fn margin(side: usize, band: f64) -> usize {
    ((band * side as f64 / 2.0).round() as usize).max(MIN_MARGIN.min(side / 4)).clamp(1, side / 2)
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
        rematch: false,
        kept_out: "The sample mask leaves",
    };
    fill.run(input, progress)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn band_is_half_along_each_edge() {
        let m = band_mask(64, 32, 0.25);
        // 8 columns along each side edge, 4 rows along top and bottom.
        let row = |y: usize| (0..64).map(|x| m[y * 64 + x]).collect::<Vec<_>>();
        assert!(row(0).iter().all(|&b| b) && row(3).iter().all(|&b| b) && row(31).iter().all(|&b| b));
        let mid = row(10);
        assert_eq!(mid.iter().filter(|&&b| b).count(), 16);
        assert!(mid[7] && !mid[8] && !mid[55] && mid[56]);
    }

    #[test]
    fn a_narrow_band_is_widened_to_blend() {
        // 1% of 128 would re-make one pixel a side: four are.
        assert_eq!(margin(128, 0.01), 4);
        assert_eq!(margin(128, 0.25), 16);
        // A small image keeps a quarter of its side at most so.
        assert_eq!(margin(8, 0.01), 2);
    }
}
