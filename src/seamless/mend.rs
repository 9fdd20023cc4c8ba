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

/// A band whose strongest line steps more than this many times the photograph's
/// strongest (`band_line`, on the band's copies before the finest level's last pass and
/// the heal) is made again from a finer coarsest level (`AGAIN_COARSEST`).
/// At the coarsest level a tile's pyramid aims at (14 pixels for a 224-pixel
/// photograph, 16 for 128 or 256: `synthesis::coarsest_side`), the band is matched
/// against a hundred-odd positions, and where one strip of the photograph fits both its
/// sides the passes carry that strip down the whole band. Paving's (one of twelve
/// held-out photographs from Debian's texture packs) copied columns 110-175 at a shift
/// of -80 in over half of its pixels, in every seed (the onion start had four shifts;
/// the coarsest level's two passes settled on that one, and every finer level kept it),
/// so the photograph's joint at column 130 ran straight the whole height of the tile at
/// 206-222, a line at every tile's edge: 3.05 times the tile's mean step (seed 1) where
/// the photograph's strongest line is 2.32 times its own, 1.28 times as strong (median
/// of seeds 1-3; its wrap 1.35). The other eleven bands stay at 0.63-1.02 of their
/// photograph's strongest line, the ten fixtures' at 0.47-1.01 (seeds 1-3; paving's
/// 1.25-1.32), so only paving's band is made again, a mend taking two syntheses' time
/// there. The fronts of the band, which meet at the wrap, are not the cause: the onion
/// start filled from a meeting line moved 16 or 32 pixels off the wrap left paving's
/// joint where it was.
pub const LINE_LIMIT: f64 = 1.1;

/// The coarsest level's aim for a band made again (`LINE_LIMIT`): a plain synthesis's
/// (28 pixels for a 224-pixel photograph, 32 for 128 or 256). Its coarsest level has
/// four times the positions, and the band keeps more of the photograph's own pixels
/// near its edges and copies from many places, laid out by the seed: paving's strongest
/// band line 0.73 of its photograph's, its wrap 1.13 (seeds 1-8), its stones no longer
/// split by one joint down the tile but some of them run together. Not the first
/// choice: brick's band, whose fronts meet between the joints, joined two bricks into
/// one 1.5-2 times as long in two of three seeds (at 14 pixels its joints keep their
/// spacing); its wrap there, 0.55 (seeds 1-3), is the middle of a course, within the
/// photograph's own lines (10th percentile 0.57).
pub const AGAIN_COARSEST: f64 = 32.0;

/// The share of the progress bar the first making of the band takes, up to its finest
/// level's last pass (that pass, or the band made again, `LINE_LIMIT`, takes the rest).
const FIRST_SHARE: f64 = 0.9;

/// `input` made to tile: the band re-made from the whole image (where `allowed`, if
/// given) on a torus; made again from a finer coarsest level where it holds a line the
/// photograph has nowhere (`LINE_LIMIT`), the band with the weaker line kept; healed once,
/// whichever is kept.
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
    let (w, h) = (input.width, input.height);
    let mask = band_mask(w, h, band);
    let margins = (margin(w, band), margin(h, band));
    let fill = Fill {
        known: mask.iter().map(|&m| !m).collect(),
        allowed,
        torus: true,
        seed,
        levels: None,
        coarsest: None,
        neighbourhood: NEIGHBOURHOOD,
        detail_levels: DETAIL_LEVELS,
        rematch: false,
        kept_out: "The sample mask leaves",
    };
    // The band's line is measured on its copies as they are, before the finest level's
    // last pass and the heal: what a band made again does not need.
    let mut first = fill.copies(input, &mut |f: f64| progress.report(FIRST_SHARE * f))?;
    let line = band_line(&first.colours(input), input, margins);
    if line <= LINE_LIMIT {
        first.finish(&mut |f: f64| progress.report(FIRST_SHARE + (1.0 - FIRST_SHARE) * f))?;
        return Ok(first.healed(input));
    }
    let again =
        first.again(input, AGAIN_COARSEST, &mut |f: f64| progress.report(FIRST_SHARE + (1.0 - FIRST_SHARE) * f))?;
    let kept = if band_line(&again.colours(input), input, margins) < line { again } else { first };
    Ok(kept.healed(input))
}

/// How strong the band's strongest straight line is against the photograph's: the
/// largest mean step (Euclidean, RGB) across a column boundary whose two columns lie
/// wholly in the band (the wrap among them) and more than `EDGE` columns from the kept
/// photograph, over the mean step across every boundary of the tile, divided by the
/// same for the photograph's boundaries (its wrap left out); and the same for rows; the
/// larger of the two. Above 1 the band holds a line (a joint or an edge run straight
/// along it) stronger than any of the photograph's, which the tile repeats at each of
/// its edges. `margins`: the band's columns and rows along each edge.
pub fn band_line(tile: &Rgba, photo: &Rgba, margins: (usize, usize)) -> f64 {
    let (w, h) = (tile.width, tile.height);
    let (cols, rows) = (column_steps(tile), row_steps(tile));
    let (own_cols, own_rows) = (column_steps(photo), row_steps(photo));
    let mean = |c: &[f64], r: &[f64]| (c.iter().sum::<f64>() + r.iter().sum::<f64>()) / (c.len() + r.len()) as f64;
    let (m, own_m) = (mean(&cols, &rows), mean(&own_cols[..w - 1], &own_rows[..h - 1]));
    if m == 0.0 {
        return 0.0; // A flat tile: no line.
    }
    // A boundary of the band: the columns (rows) on both its sides re-made, each more than
    // `EDGE` from the kept photograph (at most half the margin).
    let in_band = |b: usize, n: usize, margin: usize| {
        let depth = |x: usize| {
            if x < margin {
                margin - x
            } else if x + margin >= n {
                x + margin + 1 - n
            } else {
                0
            }
        };
        [b, (b + 1) % n].iter().all(|&x| depth(x) > EDGE.min(margin / 2))
    };
    let strongest = |v: &[f64], n: usize, margin: usize| {
        (0..n).filter(|&b| in_band(b, n, margin)).map(|b| v[b]).fold(0.0, f64::max)
    };
    let own_strongest = |v: &[f64]| v[..v.len() - 1].iter().copied().fold(0.0, f64::max);
    let ratio = |band: f64, own: f64| {
        let (band, own) = (band / m, if own_m > 0.0 { own / own_m } else { 0.0 });
        if own > 0.0 {
            band / own
        } else if band > 0.0 {
            f64::INFINITY
        } else {
            0.0
        }
    };
    let c = ratio(strongest(&cols, w, margins.0), own_strongest(&own_cols));
    let r = ratio(strongest(&rows, h, margins.1), own_strongest(&own_rows));
    c.max(r)
}

/// The band's columns (rows) along the kept photograph that `band_line` leaves out: there
/// the band's first copies meet the photograph, and the heal's correction changes most.
/// Fur's and tissue's bands stepped most there (1.14-1.52 of their photographs'
/// strongest lines, healed; seeds 1-3), a line no finer coarsest level took away
/// (tissue's bands made again: 1.18-1.31), and each mend of them took the time of two;
/// without those two boundaries, 0.87-0.98.
const EDGE: usize = 2;

/// The mean step across each column boundary of `img`: boundary `b` between columns `b`
/// and `b + 1`, the last across the wrap.
fn column_steps(img: &Rgba) -> Vec<f64> {
    let (w, h) = (img.width, img.height);
    let mut sums = vec![0.0; w];
    for row in img.data.chunks_exact(4 * w).take(h) {
        for (b, s) in sums.iter_mut().enumerate() {
            *s += step(&row[4 * b..], &row[4 * ((b + 1) % w)..]);
        }
    }
    sums.iter().map(|s| s / h as f64).collect()
}

/// The mean step across each row boundary of `img`, the last across the wrap.
fn row_steps(img: &Rgba) -> Vec<f64> {
    let (w, h) = (img.width, img.height);
    let row = |y: usize| &img.data[4 * w * y..4 * w * (y + 1)];
    (0..h)
        .map(|b| {
            let (a, c) = (row(b), row((b + 1) % h));
            (0..w).map(|x| step(&a[4 * x..], &c[4 * x..])).sum::<f64>() / w as f64
        })
        .collect()
}

/// The Euclidean RGB distance between two pixels' first three bytes.
fn step(a: &[u8], b: &[u8]) -> f64 {
    (0..3).map(|c| (a[c] as f64 - b[c] as f64).powi(2)).sum::<f64>().sqrt()
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
    fn a_line_down_the_band_stands_out_and_the_photographs_own_do_not() {
        let (w, h) = (64, 48);
        let noise = |i: usize| ((i as u64).wrapping_mul(0x9E37_79B9_7F4A_7C15) >> 56) as u8 / 2 + 60;
        let photo =
            Rgba { width: w, height: h, data: (0..w * h).flat_map(|i| [noise(i), noise(i + 7), 90, 255]).collect() };
        let margins = (margin(w, 0.25), margin(h, 0.25));
        // The photograph as its own tile: its wrap steps as its other lines do.
        assert!(band_line(&photo, &photo, margins) < 1.1);
        // A dark joint painted down a column of the band, and one across a row of it.
        for (column, x0, y0) in [(true, w - 3, 0), (false, 0, 2)] {
            let mut tile = photo.clone();
            for i in 0..w * h {
                if (column && i % w == x0) || (!column && i / w == y0) {
                    tile.data[4 * i..4 * i + 3].copy_from_slice(&[20, 15, 10]);
                }
            }
            let l = band_line(&tile, &photo, margins);
            assert!(l > 1.5, "column {column}: {l}");
        }
        // The same joint in the kept part is not the band's.
        let mut kept = photo.clone();
        for y in 0..h {
            kept.data[4 * (y * w + 30)..][..3].copy_from_slice(&[20, 15, 10]);
        }
        assert!(band_line(&kept, &photo, margins) < 1.1);
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
