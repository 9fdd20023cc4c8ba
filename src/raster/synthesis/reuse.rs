//! The re-use penalty: how many pixels of a level copy each exemplar position.

use super::job::Job;

/// Weight of the re-use penalty (see `Uses`). Over 2 seeds on the ten fixture
/// photographs (128 -> 256), with the coarsest exemplar level at 16 pixels and the
/// penalty on every use, 0.1 raised the worst repetition score (1 at no repetition)
/// from 0.634 to 0.773, for a mean patch energy of 6.01 against 5.81. With the
/// coarsest level at 32 and the penalty on uses above the mean only, over 6 seeds,
/// 0.15 gives a mean energy of 5.73 (5.85 at 0.1, 5.91 with the penalty on every use
/// at 0.1) and keeps every photograph's repetition within 0.035 of its exemplar's own.
/// It applies in both schedules, to causal and correction passes alike.
const REUSE: f32 = 0.15;

/// A tile's penalty: on every use, at 0.1 (as `REUSE` was with the coarsest level at
/// 16 pixels, which tiles keep; see `default_levels`). With the threshold at 0.15,
/// brick's banded 256 tiles scored a mean seam of 0.59 over 4 seeds (below the 0.8 that
/// `tests/seamless.rs` asks for) and coins' scanline tiles 1.17 over 8 (1.10 with this).
const TILE_REUSE: f32 = 0.1;

/// `REUSE` (`TILE_REUSE` for a tile), which the probes (built with `test-support`) may
/// override through the environment variable `PATTERNSYNTH_REUSE` to measure other
/// weights.
fn reuse_weight(tileable: bool) -> f32 {
    #[cfg(feature = "test-support")]
    if let Some(w) = std::env::var("PATTERNSYNTH_REUSE").ok().and_then(|s| s.parse().ok()) {
        return w;
    }
    if tileable {
        TILE_REUSE
    } else {
        REUSE
    }
}

/// How many pixels of a level copy each exemplar position, kept up to date as pixels
/// change, for a penalty on positions that many copy (after the occurrence maps of
/// Kaspar et al. 2015): a candidate's distance is multiplied by
/// `1 + REUSE max(0, uses / mean - 1)`, `mean` being the count if all positions were
/// copied equally. Coherent copying otherwise repeats the same clump wherever its
/// neighbourhood fits. Positions copied no more than the mean go free: an exemplar
/// that is mostly one background (hubble: dark sky) must use its many background
/// positions about equally often, and a penalty on every use pushed the output towards
/// its rare stars (patch energy 1.85 against 1.49 with the threshold, over 6 seeds).
/// A tile's penalty applies to every use (`TILE_REUSE`).
#[derive(Clone)]
pub struct Uses {
    counts: Vec<Vec<u32>>,
    /// REUSE / mean, per exemplar.
    scale: Vec<f32>,
    /// The count up to which a position goes free, per exemplar: the mean (0 for a tile).
    free: Vec<f32>,
}

impl Uses {
    /// The counts of a level whose row `y` of exemplar `e`'s map `row(e, y, out)`
    /// appends to `out`, or `None` when there is no penalty.
    pub fn count(job: &Job, level: usize, row: impl Fn(usize, usize, &mut Vec<u32>)) -> Option<Uses> {
        let w = reuse_weight(job.params.tileable);
        if w == 0.0 {
            return None;
        }
        let pixels = job.level_pixels(level) as f32;
        let (mut counts, mut scale, mut free) = (Vec::new(), Vec::new(), Vec::new());
        for e in 0..job.exemplars() {
            let n = job.positions(e, level);
            let mut c = vec![0u32; n];
            let mut buf = Vec::with_capacity(job.sizes[level].0);
            for y in 0..job.sizes[level].1 {
                buf.clear();
                row(e, y, &mut buf);
                buf.iter().for_each(|&s| c[s as usize] += 1);
            }
            counts.push(c);
            // The mean over the positions that may be copied (a sample mask's others
            // are never used).
            let allowed = job.allowed_positions(e, level) as f32;
            scale.push(w * allowed / pixels);
            // A tile's penalty starts at the first use.
            free.push(if job.params.tileable { 0.0 } else { pixels / allowed });
        }
        Some(Uses { counts, scale, free })
    }

    #[inline]
    pub(crate) fn factor(&self, e: usize, pos: usize) -> f32 {
        1.0 + self.scale[e] * (self.counts[e][pos] as f32 - self.free[e]).max(0.0)
    }

    #[inline]
    pub(crate) fn moved(&mut self, e: usize, from: u32, to: u32) {
        self.counts[e][from as usize] -= 1;
        self.counts[e][to as usize] += 1;
    }
}
