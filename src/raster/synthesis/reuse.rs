//! The re-use penalty: how many pixels of a level copy each exemplar position.

use super::job::Job;
use crate::raster::image::colour_bin;

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
/// 16 pixels, which tiles aim at; see `default_levels`). With the threshold at 0.15,
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

/// Whether the colour balance applies (probes may turn it off with
/// `PATTERNSYNTH_BALANCE=0` to measure without it; `PATTERNSYNTH_REUSE=0`, which turns
/// the re-use penalty off, turns it off too).
fn balance_on() -> bool {
    #[cfg(feature = "test-support")]
    if std::env::var("PATTERNSYNTH_BALANCE").is_ok_and(|v| v == "0") {
        return false;
    }
    true
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
    /// The colour balance, where it applies (`Balance`), per exemplar.
    balance: Vec<Option<Balance>>,
}

/// Weight of the colour balance (see `Balance`): over-represented by half again, a
/// colour's positions cost `1 + BALANCE / 2` times their distance. Synthesis tiles at
/// 128 over seeds 1-6 (examples/tile_quality), means at weights 0 / 0.5 / 0.75 / 1:
/// - twelve held-out photographs (textures from Debian packages): patch energy 7.27 /
///   7.04 / 7.07 / 7.21, colour distance 0.088 / 0.083 / 0.081 / 0.076, repetition
///   more than 0.05 below the exemplar's own on 2 / 1 / 1 / 2 (clouds at every weight);
/// - the ten fixtures: energy 6.13 / 6.37 / 6.34 / 6.41 (tissue and print rise, as
///   their textured parts come back), colour 0.162 / 0.124 / 0.109 / 0.094 (tissue
///   0.68 at 0), repetition 2 / 0 / 0 / 0 below; every seam within 0.8-1.2 at 0.75.
const BALANCE: f32 = 0.75;
/// Bins per channel of the balance's colours.
const BALANCE_BINS: usize = 4;

/// The colour balance of a tile's coarsest level grown from noise, from one exemplar
/// and with no guide (after the histogram matching of Kopf et al. 2007, Solid texture
/// synthesis from 2D exemplars): each exemplar position's colour bin, how many of the
/// pixels being made copy a position of each bin, and how many would in the exemplar's
/// own shares. A candidate's distance is multiplied by
/// `1 + BALANCE max(0, copies / expected - 1)` of its bin. In the banded schedule each
/// band balances its own rows (`Uses::balance_rows`): every band seeing the whole
/// level's excess would correct it once per band.
///
/// Why: grown causally from noise, the layout drifts towards the exemplar's smoothest
/// region, whose neighbourhoods match everything well (tissue's tiles almost all the
/// pale stroma, colour distance 0.68; a clouds tile mostly sky), and a penalty per
/// position does not see it, the drift spreading over the region's many positions.
/// Outputs whose exemplar is large enough start from a quilt instead (`quilt`; tiles
/// since its coverage term, `job::TILE_QUILT`), so this is for tiles from small
/// exemplars and for probes that grow tiles from noise. A guide asks for other shares than the
/// exemplar's, and a blend's exemplar is seen only where its weight is, so neither is
/// balanced.
#[derive(Clone)]
struct Balance {
    weight: f32,
    bin: Vec<u16>,
    /// Each bin's share of the positions that may be copied.
    share: Vec<f32>,
    /// The pixels balanced, and how many of them copy each bin.
    pixels: f32,
    copies: Vec<u32>,
}

impl Balance {
    fn new(job: &Job, e: usize, level: usize, counts: &[u32]) -> Balance {
        let plane = job.plane(e, level);
        let bin: Vec<u16> = plane.data.iter().map(|p| colour_bin(p, BALANCE_BINS) as u16).collect();
        let mut share = vec![0f32; BALANCE_BINS.pow(3)];
        let mut copies = vec![0u32; share.len()];
        for (pos, &b) in bin.iter().enumerate() {
            if plane.allows(pos as u32) {
                share[b as usize] += 1.0;
            }
            copies[b as usize] += counts[pos];
        }
        let allowed = plane.allowed_count() as f32;
        share.iter_mut().for_each(|s| *s /= allowed);
        let pixels = counts.iter().sum::<u32>() as f32;
        #[cfg(feature = "test-support")]
        let weight = std::env::var("PATTERNSYNTH_BALANCE").ok().and_then(|v| v.parse().ok()).unwrap_or(BALANCE);
        #[cfg(not(feature = "test-support"))]
        let weight = BALANCE;
        Balance { weight: weight.max(0.0), bin, share, pixels, copies }
    }

    /// Counted again over `src` alone (a band's rows).
    fn recount(&mut self, src: &[u32]) {
        self.copies.iter_mut().for_each(|c| *c = 0);
        for &p in src {
            self.copies[self.bin[p as usize] as usize] += 1;
        }
        self.pixels = src.len() as f32;
    }

    #[inline]
    fn factor(&self, pos: usize) -> f32 {
        let b = self.bin[pos] as usize;
        let expected = (self.share[b] * self.pixels).max(1.0);
        1.0 + self.weight * (self.copies[b] as f32 / expected - 1.0).max(0.0)
    }

    #[inline]
    fn moved(&mut self, from: u32, to: u32) {
        self.copies[self.bin[from as usize] as usize] -= 1;
        self.copies[self.bin[to as usize] as usize] += 1;
    }
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
        let (mut counts, mut scale, mut free, mut balance) = (Vec::new(), Vec::new(), Vec::new(), Vec::new());
        // (A tile's coarsest level grown from noise keeps its colours balanced.)
        let balanced = job.params.tileable
            && level + 1 == job.levels
            && !job.started(level)
            && job.exemplars() == 1
            && job.target.is_none()
            && balance_on();
        for e in 0..job.exemplars() {
            let n = job.positions(e, level);
            let mut c = vec![0u32; n];
            let mut buf = Vec::with_capacity(job.sizes[level].0);
            for y in 0..job.sizes[level].1 {
                buf.clear();
                row(e, y, &mut buf);
                buf.iter().for_each(|&s| c[s as usize] += 1);
            }
            balance.push(balanced.then(|| Balance::new(job, e, level, &c)));
            counts.push(c);
            // The mean over the positions that may be copied (a sample mask's others
            // are never used).
            let allowed = job.allowed_positions(e, level) as f32;
            scale.push(w * allowed / pixels);
            // A tile's penalty starts at the first use.
            free.push(if job.params.tileable { 0.0 } else { pixels / allowed });
        }
        Some(Uses { counts, scale, free, balance })
    }

    /// The colour balance of exemplar `e` kept over `src` alone: the rows a band makes
    /// (its moves change only those).
    pub(crate) fn balance_rows(&mut self, e: usize, src: &[u32]) {
        if let Some(b) = &mut self.balance[e] {
            b.recount(src);
        }
    }

    #[inline]
    pub(crate) fn factor(&self, e: usize, pos: usize) -> f32 {
        let reuse = 1.0 + self.scale[e] * (self.counts[e][pos] as f32 - self.free[e]).max(0.0);
        self.balance[e].as_ref().map_or(reuse, |b| reuse * b.factor(pos))
    }

    #[inline]
    pub(crate) fn moved(&mut self, e: usize, from: u32, to: u32) {
        self.counts[e][from as usize] -= 1;
        self.counts[e][to as usize] += 1;
        if let Some(b) = &mut self.balance[e] {
            b.moved(from, to);
        }
    }
}
