//! Quality figures of a seamless tile: the paper's restoration rate (SPEC 3.7) and a
//! seam score.

use super::cooccurrence::Grey;

/// Grey restoration rate: `(1 - sum_n |K_n - C_n| / (2 N^2)) * (C / K)`, with `K_n`,
/// `C_n` the exemplar's and output's histograms and `K`, `C` their numbers of levels
/// present. 1 is a perfect histogram.
pub fn restoration_grey(ex: &Grey, out: &Grey) -> f64 {
    let (k, c) = (ex.histogram(), out.histogram());
    let diff: u64 = k.iter().zip(&c).map(|(&a, &b)| (a as i64 - b as i64).unsigned_abs()).sum();
    let present = |h: &[u32; 256]| h.iter().filter(|&&v| v > 0).count() as f64;
    // Histograms of different pixel counts compare as fractions.
    let scale = ex.data.len() as f64;
    (1.0 - diff as f64 / (2.0 * scale)) * (present(&c) / present(&k).max(1.0))
}

/// Colour restoration rate: `1 - sum over R, G, B and n of |C_n - K_n| / (2 N^2 x 3)`,
/// on histograms normalised to the exemplar's pixel count.
pub fn restoration_rgb(ex: &[[u8; 3]], out: &[[u8; 3]]) -> f64 {
    let mut diff = 0.0;
    for ch in 0..3 {
        let (mut k, mut c) = ([0f64; 256], [0f64; 256]);
        ex.iter().for_each(|p| k[p[ch] as usize] += 1.0);
        out.iter().for_each(|p| c[p[ch] as usize] += ex.len() as f64 / out.len() as f64);
        diff += k.iter().zip(&c).map(|(a, b)| (a - b).abs()).sum::<f64>();
    }
    1.0 - diff / (2.0 * ex.len() as f64 * 3.0)
}

/// How many boundaries on each side of the wrap the seam is compared with.
const NEAR: usize = 4;

/// How visible the wrap-around seams are: the mean colour difference across the wrap
/// (last column to first, last row to first) over the mean difference across the
/// `NEAR` parallel boundaries on each side of it, at the same places along the seam.
/// About 1 for a seamless tile; a cut shows as several times that.
///
/// The comparison is local because the eye sees a seam as a line that breaks from its
/// surroundings. Against the whole image's mean instead, an E-TFMCM tile whose wrap
/// happened to run along flat background (coins, 128) scored 0.27 and one whose wrap ran
/// along lines of text (print, 256) 1.64, with no seam to see in either.
pub fn seam_score(rgb: &[[u8; 3]], width: usize, height: usize) -> f64 {
    let d = |a: [u8; 3], b: [u8; 3]| (0..3).map(|c| (a[c] as f64 - b[c] as f64).abs()).sum::<f64>();
    let at = |x: usize, y: usize| rgb[(y % height) * width + x % width];
    // Boundary `b` lies between line `b` and line `b + 1`; the wrap is boundary `n - 1`.
    let (mut seam, mut near, mut n_seam, mut n_near) = (0.0, 0.0, 0usize, 0usize);
    let mut side = |n: usize, len: usize, pair: &dyn Fn(usize, usize) -> f64| {
        let k = NEAR.min(n.saturating_sub(1) / 2);
        for i in 0..len {
            seam += pair(n - 1, i);
            for o in 1..=k {
                near += pair(n - 1 - o, i) + pair(o - 1, i);
            }
        }
        n_seam += len;
        n_near += 2 * k * len;
    };
    side(width, height, &|b, y| d(at(b, y), at(b + 1, y)));
    side(height, width, &|b, x| d(at(x, b), at(x, b + 1)));
    let seam = seam / n_seam.max(1) as f64;
    let near = near / n_near.max(1) as f64;
    if near == 0.0 {
        return if seam == 0.0 { 1.0 } else { f64::INFINITY };
    }
    seam / near
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn same_histogram_restores_fully_and_a_cut_shows() {
        let ex = Grey { width: 4, height: 1, data: vec![1, 2, 3, 4] };
        let out = Grey { width: 4, height: 1, data: vec![4, 3, 2, 1] };
        assert!((restoration_grey(&ex, &out) - 1.0).abs() < 1e-12);
        let half = Grey { width: 4, height: 1, data: vec![1, 1, 2, 2] };
        // Half the pixels moved, half the levels present.
        assert!((restoration_grey(&ex, &half) - 0.5 * 0.5).abs() < 1e-12);
        // A horizontal ramp wraps with a jump: the seam is far above the inside.
        let ramp: Vec<[u8; 3]> = (0..64).map(|i| [((i % 8) * 10) as u8; 3]).collect();
        assert!(seam_score(&ramp, 8, 8) > 3.0);
        let rgb: Vec<[u8; 3]> = (0..64).map(|i| [((i % 8) * 10) as u8, 0, 0]).collect();
        assert!((restoration_rgb(&rgb, &rgb) - 1.0).abs() < 1e-12);
    }
}
