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
    tuned("PATTERNSYNTH_REUSE", if tileable { TILE_REUSE } else { REUSE })
}

/// `value`, or in the probes (built with `test-support`) the environment variable
/// `name`'s, to measure other weights.
#[cfg_attr(not(feature = "test-support"), allow(unused_variables))]
fn tuned(name: &str, value: f32) -> f32 {
    #[cfg(feature = "test-support")]
    if let Some(v) = std::env::var(name).ok().and_then(|s| s.parse().ok()) {
        return v;
    }
    value
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

/// Weight of the colour balance (see `Balance`): over-represented by a tenth, a
/// colour's positions cost `1 + BALANCE / 10` times their distance (up to
/// `BALANCE_CAP`).
///
/// Measured on synthesis tiles at 128 from the sixteen held-out photographs of
/// `bench/heldout-data.sh`, seeds 1-8, against texture-synthesis 0.8.3 `--tiling` in the
/// same run (examples/tile_quality), with the balance on every level and 8 bins, not
/// capped:
/// - weight 0 (the quilt alone): colour distance at most the peer's on 11 of 16 (clouds
///   0.172, wisps 0.117, marble 0.117 over), energy on 16, repetition within 0.05 of
///   the photograph's own on 15 (sand);
/// - 1.5 / 2 / 3: colour on 14 / 14 / 14 (clouds 0.116 / 0.103 / 0.087 against the
///   peer's 0.168, fire 0.256 / 0.246 / 0.231 against 0.351, marble 0.108 / 0.100 /
///   0.095 against 0.095), repetition on 16 / 16 / 15, energy on 15 (fire 0.75 / 0.75 /
///   0.77 against 0.74), median energy ratio 0.82 / 0.83 / 0.88.
///
/// Only the coarser levels balanced gave the same within a seed's spread (the finest
/// level copies coherent pieces of what they laid). 4 bins per channel, as before, left
/// marble (greys within two bins) where it was.
const BALANCE: f32 = 2.0;
/// Bins per channel of the balance's colours: those of `energy::colour_distance`.
const BALANCE_BINS: usize = 8;
/// The largest factor the balance puts on a distance. Capped, the balance chooses among
/// candidates that fit about equally well and never makes a misfit the best, as
/// `quilt::MISFIT` keeps the quilt from laying one for coverage. Uncapped, it laid
/// again what `MISFIT` had stopped: helper-62's cloud (colobot cloud03 cropped at
/// (300, 100), 128², as a tileable 600² in bands, seeds 1-8, examples/seam_profile)
/// grew rows of flat-bottomed dark blobs, its strongest row step 1.87 times the mean
/// row's at a cap of 1.3 against 1.57 with no balance.
///
/// Caps 1.15 / 1.2 / 1.3 at weight 2, as above: colour on 14 / 15 / 15 (marble 0.101 /
/// 0.091 / 0.091; plaster stays over at 0.038 / 0.039 / 0.035 against 0.025), sand's
/// repetition 0.894 / 0.909 / 0.900 (its own 0.933), energy on 16 at each (fire 0.72
/// against 0.74), the cloud's strongest row 1.55 / 1.54 / 1.87 (one small blob per tile
/// at 1.2, as with no balance). Brick's seam score falls from 0.85 with no balance to
/// 0.77 / 0.73 / 0.76 (seeds 9-16: 0.79 to 0.71 at 1.2). That is the photograph's own
/// 8-pixel grid, whose lines at phase 7 are smoother than the rest (0.74 of the mean
/// across rows, 0.80 across columns), kept in phase by coherent copies: the wrap always
/// falls on phase 7, and examples/seam_lines reads it 0.726 against 0.755 for the
/// tile's inner lines at that phase.
///
/// On the ten fixtures (tiles at 128, seeds 1-3), with no balance / as now: mean colour
/// distance 0.110 / 0.097 (fur 0.160 / 0.131, print 0.191 / 0.162, tissue 0.244 /
/// 0.221), mean patch energy 5.57 / 5.58, grass's repetition 0.064 / 0.043 under its
/// own, every seam within 0.8-1.2 (coins 1.24 / 1.07, brick 1.05 / 1.20).
///
/// A floor as well, under-used colours made cheaper down to 0.95 / 0.9 / 0.8 of their
/// distance, was measured and not kept (before `FINE_BALANCE`): plaster's colour, the one
/// over the peer's (its tiles lack the photograph's brightest and darkest specks, 0.5%
/// against 1.6% in the top bin, a standard deviation 25.0 against 26.5), went 0.039 ->
/// 0.032 / 0.029 / 0.029, still over the peer's 0.025, while fire's energy rose over the
/// peer's at 0.9 and 0.8 (0.76, 0.77 against 0.74), grass's repetition fell to 0.875 at
/// 0.95 (its own 0.928) and sand's to 0.872 at 0.8 (0.933).
const BALANCE_CAP: f32 = 1.2;

/// The balance's weight and cap at the finest level, stronger than at the coarser
/// ones (`BALANCE`, `BALANCE_CAP`). The coarser levels lay out the tile, where a strong
/// balance lays rare colours as shapes (the cloud crop's blobs above); the finest level
/// copies coherent pieces of that layout, and there the balance only chooses, among
/// candidates that fit about equally well, the pixels of under-copied colours: plaster's
/// bright specks, the warm and cool greys either side of a bin's edge. Its cap bounds
/// it, as `BALANCE_CAP` does.
///
/// Measured on synthesis tiles at 128 from the sixteen held-out photographs, seeds 1-8,
/// against texture-synthesis 0.8.3 `--tiling` (examples/tile_quality), from the finest
/// level at 2 / 1.2 as the coarser levels:
/// - 10 / 2 (kept): colour distance lower on all 16 and at most the peer's on 16
///   (plaster 0.030 -> 0.021 against 0.025; grass 0.074 -> 0.062, stones 0.040 -> 0.032,
///   paving 0.033 -> 0.025); patch energy at or below the peer's on 16, up by at most 4%
///   (grass 9.50 -> 9.89, plaster 10.74 -> 11.00; the peer's 10.52, 11.81); repetition
///   within 0.05 of the photograph's own on 16; seams as before. Refined E-TFMCM's tiles
///   alike: colour lower on 15 and the same on fire (plaster 0.024 -> 0.017), energy at
///   or below the peer's on 15 and within 1.1x on fire (0.75 against 0.74), as before.
/// - 6 / 2, 8 / 2.5, 10 / 3: plaster 0.025, 0.022, 0.021; 16 / 4: plaster 0.017, but
///   fire's energy over the peer's (0.75 against 0.74).
/// - The two finest levels at 3 / 1.3: plaster 0.029. Every level at 3 / 1.3: plaster
///   0.025, fire's energy 0.75, and the cloud crop's rows of dark blobs (strongest row
///   1.87 of the mean against 1.52); the finest level alone at 6 / 2 or 3 / 1.3 over the
///   two finest keeps 1.52.
const FINE_BALANCE: f32 = 10.0;
const FINE_BALANCE_CAP: f32 = 2.0;

/// The colour balance of a tile from one exemplar and with no guide, at every level
/// (after the histogram matching of Kopf et al. 2007, Solid texture synthesis from 2D
/// exemplars): each exemplar position's colour bin, how many of the pixels being made
/// copy a position of each bin, and how many would in the exemplar's own shares. A
/// candidate's distance is multiplied by `1 + BALANCE max(0, copies / expected - 1)` of
/// its bin, at most `BALANCE_CAP` (at the finest level `FINE_BALANCE`,
/// `FINE_BALANCE_CAP`). In the banded schedule each band balances its own rows
/// (`Uses::balance_rows`): every band seeing the whole level's excess would correct it
/// once per band.
///
/// Why: a tile is about its exemplar's size, so which regions it copies sets its
/// colours. Grown causally from noise, the layout drifts towards the exemplar's
/// smoothest region, whose neighbourhoods match everything well (tissue's tiles almost
/// all the pale stroma, colour distance 0.68; a clouds tile mostly sky). The quilt
/// (`quilt`, `start::TILE_QUILT`) lays an even spread of windows, yet the passes then
/// favour what fits best: a clouds tile's colours stood 0.172 from the photograph's
/// (the peer's 0.168), balanced 0.141 (capped; 0.103 uncapped). A penalty per position
/// (`Uses`) does not see either, the drift spreading over a region's many positions. A guide asks for other shares than
/// the exemplar's, and a blend's exemplar is seen only where its weight is, so neither
/// is balanced.
#[derive(Clone)]
struct Balance {
    weight: f32,
    bin: Vec<u16>,
    /// Each bin's share of the positions that may be copied.
    share: Vec<f32>,
    /// The pixels balanced, and how many of them copy each bin.
    pixels: f32,
    copies: Vec<u32>,
    /// The largest factor (`BALANCE_CAP`).
    cap: f32,
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
        // (The finest level's own weight and cap: see `FINE_BALANCE`.)
        let (weight, cap) = if level == 0 {
            (tuned("PATTERNSYNTH_FINE_BALANCE", FINE_BALANCE), tuned("PATTERNSYNTH_FINE_BALANCE_CAP", FINE_BALANCE_CAP))
        } else {
            (tuned("PATTERNSYNTH_BALANCE", BALANCE), tuned("PATTERNSYNTH_BALANCE_CAP", BALANCE_CAP))
        };
        Balance { weight: weight.max(0.0), bin, share, pixels, copies, cap: cap.max(1.0) }
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
        let expected = at_least(self.share[b] * self.pixels, 1.0);
        let factor = 1.0 + self.weight * at_least(self.copies[b] as f32 / expected - 1.0, 0.0);
        if factor < self.cap {
            factor
        } else {
            self.cap
        }
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
        // (A tile keeps its colours balanced at every level.)
        let balanced = job.params.tileable && job.exemplars() == 1 && job.target.is_none() && balance_on();
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

    #[inline(always)]
    pub(crate) fn factor(&self, e: usize, pos: usize) -> f32 {
        let reuse = 1.0 + self.scale[e] * at_least(self.counts[e][pos] as f32 - self.free[e], 0.0);
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

/// `v.max(floor)` for numbers (never NaN here) as a comparison: `f32::max` keeps a
/// number over a NaN, which wasm's `f32.max` does not, so in wasm it is a call to
/// `fmaxf`, and in the candidate loop those calls were 2.5% of a synthesis.
#[inline(always)]
fn at_least(v: f32, floor: f32) -> f32 {
    if v > floor {
        v
    } else {
        floor
    }
}
