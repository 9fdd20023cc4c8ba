//! Multi-resolution Wei-Levoy synthesis against one exemplar, or two whose best matches
//! each output pixel mixes by weights mu and 1 - mu (the paper's blending).
//!
//! Coarse to fine; at each level the output is filled in scanline order on a torus,
//! from noise drawn from the exemplar (the paper's start). The coarsest level
//! starts instead from a quilt of exemplar windows (`quilt`), laid round the torus for
//! a tile, which its passes then join with full neighbourhoods: grown causally from
//! noise, it drifted towards the exemplar's smoothest region. A tile's quilt covers the
//! exemplar evenly (`quilt::Quilt::spread`); a tile from an exemplar too small to quilt
//! grows from noise. Either way a tile keeps to the exemplar's colours by a penalty on
//! colours copied more than their share, at every level (`reuse::Balance`). A pixel's
//! feature is its causal neighbourhood at this level and a 3x3 block of the (finished)
//! parent level, read where the pixel lies on it (`Pass::parent_feature`).
//! For each exemplar with weight > 0 the best-matching exemplar position is found and
//! the colours are mixed.
//!
//! Search: `exhaustive` compares with every exemplar position (the reference mode). The
//! default compares with coherent candidates only (Ashikhmin 2001): for each already
//! synthesized neighbour, the exemplar position next to the one it copied, so that
//! patches of the exemplar continue; plus the parent's position scaled up and a few
//! random positions; a candidate that many neighbours propose is preferred. The
//! coarsest level starts from a quilt of exemplar windows where they fit, which lays the
//! large-scale structure; grown from noise (small exemplars) it is searched
//! exhaustively where that is cheap (`job`'s `COARSE_EXHAUSTIVE_BUDGET`). Finer levels
//! refine it coherently. Exemplar neighbourhoods are
//! read on the fly (no feature tables) and the output is kept only as source positions,
//! so memory stays a few times the images' size; partial distances stop as soon as they
//! exceed the best so far.

mod exemplar;
mod fusion;
mod job;
mod lanes;
mod mask;
mod mixer;
mod opacity;
mod pass;
mod pinned;
mod reuse;
mod start;

pub use fusion::Keep;
pub use job::Job;
pub(crate) use pass::Scratch;
pub use pinned::REMATCH_ROUNDS;
pub(crate) use pinned::{begin as begin_pinned, Finest};
pub use reuse::Uses;

use super::image::{Image, Rgba};
use crate::error::Result;
use crate::progress::Throttle;
use crate::rng::Rng;

#[derive(Clone, Debug)]
pub struct Params {
    pub width: usize,
    pub height: usize,
    pub seed: u64,
    /// Pyramid levels; `None` picks them so the coarsest exemplar is nearest 32 pixels
    /// (16 for a tile, and at least 32 for a fill; see `default_levels`).
    pub levels: Option<usize>,
    /// Neighbourhood side (odd, at least 3): 5 means a 5x5 causal L-shape.
    pub neighbourhood: usize,
    /// Around known pixels (`pinned`), the finest levels matched with 5 x 5
    /// neighbourhoods whatever `neighbourhood` is: the wide side places the structure at
    /// the coarser levels, and its search, whose candidates come from every neighbour,
    /// costs the side's fourth power where the pixels are most.
    pub detail_levels: usize,
    pub exhaustive: bool,
    /// Make the output tile: its wrap-around seams are re-synthesized with full,
    /// wrapping neighbourhoods.
    pub tileable: bool,
    /// Random candidates per pixel and exemplar in the coherent search.
    pub random_candidates: usize,
    /// Correction passes per level after the causal one: every pixel matched again with
    /// its full (two-sided) neighbourhood, which joins structures the causal pass broke.
    /// One by default. Tiles from the twelve held-out photographs (128, seeds 1-8, issue
    /// 25): three lowered the median patch energy against texture-synthesis's from 0.97
    /// to 0.90 and brought all twelve to or below it, at 2.1 times the time (1.6 with the
    /// later passes matching only pixels whose neighbourhood changed: 8% of the finest
    /// level's pixels change in the first correction, 2-4% in the next); two, 0.93 and
    /// ten of twelve, at 1.5 times. On the ten fixtures the energy fell 1% and two seams
    /// left 0.8-1.2 (brick 0.75, coins 1.25). A 7 x 7 or 9 x 9 neighbourhood for tiles
    /// did as well on the held-out set at twice the time, and pulled print's and brick's
    /// wraps out of range; a coherence bias of 4 rather than `pass::COHERENCE`, or the
    /// colour balance in 8 bins a channel, traded one photograph for another at no cost.
    pub corrections: usize,
    /// Fuse the seams between copied pieces in the gradient domain (`fusion`): on by
    /// default; off, every output pixel is an exemplar pixel's colour exactly. Applies to
    /// one opaque exemplar of more than `fusion::PALETTE` colours, unguided (a guide's steps
    /// are where the output follows it), not around known pixels.
    pub fuse_seams: bool,
    pub schedule: Schedule,
    /// A picture of the output's size whose layout the coarsest level starts from
    /// (`Job::started`): the seamless tile's E-TFMCM field, refined.
    pub start: Option<Image>,
    /// Masks and guides (inpainting, mending a tile, sample masks, guided synthesis).
    pub constraints: Constraints,
}

/// What constrains a synthesis besides its exemplars: one neighbourhood search that
/// knows masks and guides (issue 30), rather than one special case per verb.
#[derive(Clone, Debug, Default)]
pub struct Constraints {
    /// Per exemplar, which of its pixels may be copied (`None`, or a missing entry: all).
    pub allowed: Vec<Option<Vec<bool>>>,
    /// Output pixels that are known (row major): each is pinned to the same pixel of
    /// exemplar 0, which must then be of the output's size, and conditions its
    /// neighbours at every level. The other pixels are synthesized (a hole filled, a
    /// tile's band mended); see `synthesize`.
    pub known: Option<Vec<bool>>,
    pub guide: Option<Guide>,
    /// Per exemplar, its alpha, one value per pixel (a fill of an RGBA image, a
    /// synthesis or blend of exemplars with transparency; a missing one opaque). The
    /// output takes the alpha of the pixel each of its pixels copies, blended as the
    /// colours are (`Job::colour_rows`). Where alpha varies, candidates are compared by
    /// it too (`opacity`): in the fourth lane, a fully transparent pixel's colour
    /// counting as black; or, when a guide holds that lane (it says where the output
    /// should be what, and is kept whole), by colours premultiplied by it. Alpha the
    /// same everywhere is shown but changes no match.
    pub alphas: Vec<Option<Vec<u8>>>,
    /// What keeps the disallowed pixels out, beginning the message when it leaves none
    /// to copy from (`None`: "The sample mask leaves"; a fill's hole: "The mask leaves").
    pub kept_out: Option<&'static str>,
}

impl Constraints {
    pub(crate) fn kept_out(&self) -> &'static str {
        self.kept_out.unwrap_or("The sample mask leaves")
    }
}

/// A guide: grey images of the exemplar's and of the output's size whose values are
/// compared, weighted, beside the colours in every neighbourhood (the fourth lane of a
/// pixel, `lanes`): the output then follows the target's layout.
#[derive(Clone, Debug)]
pub struct Guide {
    pub exemplar: Image,
    pub target: Image,
    /// 1 counts a guide's difference as much as the same difference in all three
    /// colour channels.
    pub weight: f32,
}

impl Guide {
    /// The guide lane's scale: its squared difference is `weight` times three channels'.
    pub(crate) fn scale(&self) -> f32 {
        (3.0 * self.weight.max(0.0)).sqrt()
    }
}

/// The order in which a level's pixels are synthesized.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, serde::Deserialize)]
#[serde(rename_all = "camelCase")]
pub enum Schedule {
    /// Bands for outputs of `BANDS_FROM` pixels or more, scanlines below.
    #[default]
    Auto,
    /// The paper's scanline order (one thread).
    Scanline,
    /// The banded order (`bands`), which workers can share.
    Bands,
}

/// Output pixels from which `Schedule::Auto` takes the banded order.
pub const BANDS_FROM: usize = 512 * 512;

impl Params {
    /// Whether this synthesis runs in the banded order.
    pub fn banded(&self) -> bool {
        match self.schedule {
            // Known pixels are filled in their own order (`pinned`), in one thread.
            _ if self.constraints.known.is_some() => false,
            Schedule::Auto => self.width * self.height >= BANDS_FROM,
            Schedule::Scanline => false,
            Schedule::Bands => true,
        }
    }
}

impl Default for Params {
    fn default() -> Self {
        Params {
            width: 256,
            height: 256,
            seed: 1,
            levels: None,
            neighbourhood: 5,
            detail_levels: 0,
            exhaustive: false,
            tileable: false,
            random_candidates: 2,
            corrections: 1,
            fuse_seams: true,
            schedule: Schedule::Auto,
            start: None,
            constraints: Constraints::default(),
        }
    }
}

/// The short side the coarsest exemplar level aims at (`default_levels`): 32 pixels,
/// 16 for a tile, and for a fill (known pixels, not a tile) 32 sqrt 2.
///
/// At 16 pixels the coarsest level has a few hundred positions for several times as many
/// output pixels, and its exhaustive search lays the same best few out again and again:
/// the large structure repeats. Over 3 seeds on the ten photographs (128 -> 256), 32
/// raised fur's repetition score from 0.784 to 0.854 (its exemplar's own: 0.875) and
/// the worst distance below an exemplar's own from 0.091 to 0.034, and lowered the mean
/// patch energy from 5.99 to 5.82; 8 (five levels) repeated more (fur 0.710).
/// A tile aims at 16: the exhaustive coarsest level is what joins long structures across
/// the wrap, and at 32 (searched coherently) brick's tiles broke their mortar lines
/// there (seam score 1.51 over 8 seeds, against 0.93).
///
/// A fill reads its structure from the known pixels round the hole, and a coarser start
/// lost it: on eight Debian photographs of 224 pixels with holes of 9-10%
/// (bench/peer-verbs.mjs, seeds 1-3), a coarsest level of 28 rather than 56 raised the
/// fill's median patch energy from 7.65 to 8.35 and the step at its edge from 1.10 to
/// 1.21. 32 sqrt 2 keeps the fill's levels as they were (at least 32 pixels). A mend (a
/// fill on the torus) aims as tiles do: on the same photographs its seams went from
/// 0.67-1.34 (four of eight outside 0.8-1.2) to 0.83-1.24 (one), its band's energy from
/// 5.00 to 5.90 (the peer's 6.00).
pub(crate) fn coarsest_side(tileable: bool, fill: bool) -> f64 {
    match (tileable, fill) {
        (true, _) => 16.0,
        (false, true) => 32.0 * std::f64::consts::SQRT_2,
        (false, false) => 32.0,
    }
}

/// Default number of levels: the coarsest exemplar level nearest `coarsest` pixels on
/// its short side by ratio (above `coarsest / sqrt 2`; see `coarsest_side`), and at
/// least the neighbourhood; the coarsest output at least 8; at most 5.
///
/// Nearest, not "at least": a 112-pixel exemplar stopped at 56, where the coarsest level
/// lays too little of the large structure. Drawing from three quarter crops of eight
/// Debian photographs (112 -> 256), 28 lowered the median patch energy from 4.70 to
/// 3.15, texture-synthesis's being 4.20 (bench/peer-verbs.mjs, seeds 1-3). Natively
/// (`examples/multi_probe`, seeds 1-2, its RMS energy) from 8.12 to 6.57 from the three
/// crops and 8.14 to 6.66 from one, with their
/// repetition scores (0.886 -> 0.859, 0.886 -> 0.851) still above the crops' own
/// (0.787); from the whole photographs (224 -> 256, seeds 1-3, `WHOLE=1`) 6.25 to 5.78,
/// none repeating more than 0.025 beyond its own (grass 0.908 against 0.930). Sides that are 32 or 16 times a power of two
/// (the fixtures' 128) keep their levels.
pub(crate) fn default_levels(exemplars: &[&Image], width: usize, height: usize, side: usize, coarsest: f64) -> usize {
    let ex = exemplars.iter().map(|e| e.width.min(e.height)).min().unwrap_or(1);
    levels_for(ex, width.min(height), side, coarsest)
}

/// `default_levels` for exemplars whose short side is at least `ex` and an output whose
/// short side is `out`.
pub(crate) fn levels_for(ex: usize, out: usize, side: usize, coarsest: f64) -> usize {
    let mut levels = 1;
    while levels < 5
        && (ex >> levels) >= side
        && (ex >> levels) as f64 >= coarsest / std::f64::consts::SQRT_2
        && (out >> levels) >= 8
    {
        levels += 1;
    }
    levels
}

/// What to synthesize from.
pub enum Sources<'a> {
    /// More of one texture.
    One(&'a Image),
    /// Two exemplars mixed by `mu`, the weight of `a` at each output pixel (row major,
    /// one value in [0, 1] per pixel; `b` gets 1 - mu).
    Blend { a: &'a Image, b: &'a Image, mu: Vec<f32> },
}

/// Synthesizes the job's image, each level in scanline order
/// (the paper's schedule, one thread). `bands::synthesize` is the schedule that several
/// workers can share.
///
/// Memory: each level keeps, per exemplar and pixel, the exemplar position it copies
/// (4 bytes), and a pixel's colour is read through it (mixed by mu when blending). With
/// the parent level's map and mu in 16 bits, that is at most 5 bytes per output pixel
/// for one exemplar and 12 for two, plus the RGBA result (4) at the end, when the
/// parent's map is gone. A map of at most 512 x 512 pixels (every level of an output in
/// scanline order, a band's window) also keeps its pixels' colours, and its parent's,
/// for speed: 16 bytes a pixel, at most about 5.3 MiB (`pass::CACHED`). The job also keeps the coarsest
/// level's starting maps (`Job::starts`: 4 bytes per pixel of that level and exemplar, a
/// quarter of a byte per output pixel with three levels, 4 with one).
pub fn synthesize(job: &Job, progress: &mut Throttle) -> Result<Rgba> {
    Ok(job.colours(&sources(job, progress)?))
}

/// `synthesize`'s finest level as exemplar positions, one map per exemplar (what
/// `Job::colours` reads; the layout that other maps of the exemplar can replay).
pub fn sources(job: &Job, progress: &mut Throttle) -> Result<Vec<Vec<u32>>> {
    if job.known.is_some() {
        return pinned::sources(job, progress);
    }
    let params = &job.params;
    let mut rng = Rng::new(params.seed);
    let total: usize = job.sizes.iter().map(|(w, h)| w * h).sum::<usize>() * (1 + params.corrections);
    let mut done = 0usize;
    // Source positions per exemplar at the current level and at its parent.
    let mut parent_src: Vec<Vec<u32>> = Vec::new();

    for level in (0..job.levels).rev() {
        let (lw, lh) = job.sizes[level];
        // A quilt at the coarsest level, else noise: every pixel copies a random position
        // of each exemplar.
        let started = job.started(level);
        let src: Vec<Vec<u32>> = if started {
            job.starts().to_vec()
        } else {
            (0..job.exemplars())
                .map(|e| (0..lw * lh).map(|_| job.random_position(e, level, &mut rng)).collect())
                .collect()
        };
        let uses = Uses::count(job, level, |e, y, out| out.extend_from_slice(&src[e][y * lw..(y + 1) * lw]));
        let pass = job.pass(level, &parent_src);
        let mut map = pass.whole(src, uses);
        let mut scratch = Scratch::new(&job.full);
        // One causal pass, then the correction passes with full neighbourhoods, the first
        // in reverse scanline order: structure then also spreads up and left, from the
        // pixels the causal pass made last (6 seeds: mean energy 8.29 -> 8.12).
        let first = if started { (&job.full, true, false) } else { (&job.causal, false, false) };
        let passes = std::iter::once(first).chain((0..params.corrections).map(|i| (&job.full, true, i % 2 == 0)));
        for (shape, use_full, reverse) in passes {
            for row in 0..lh {
                let y = if reverse { lh - 1 - row } else { row };
                for col in 0..lw {
                    let x = if reverse { lw - 1 - col } else { col };
                    pass.pixel(&mut map, shape, use_full, x, y, &mut rng, &mut scratch);
                }
                done += lw;
                progress.tick(done as f64 / total as f64)?;
            }
        }
        if params.tileable {
            // The first rows and columns were made against noise across the wrap, and the
            // correction passes do not join them fully: redo the rows and columns along the
            // wrap with full neighbourhoods once more. Over 8 seeds on the ten photographs
            // (256 tiles) the wrap's mean difference fell from 1.23 to 1.08 times the mean
            // across all boundaries (as much as other boundaries of the coarsest level's
            // pixels), patch energy 6.05 -> 5.97; a second, reversed sweep changed neither.
            for y in 0..lh {
                for x in 0..lw {
                    if job.along_wrap(level, x, y) {
                        pass.pixel(&mut map, &job.full, true, x, y, &mut rng, &mut scratch);
                    }
                }
            }
        }
        parent_src = map.src;
    }
    // The finest level's sources are `parent_src` now.
    progress.tick(1.0)?;
    Ok(parent_src)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn levels(ex: usize, out: usize, side: usize, coarsest: f64) -> usize {
        let e = Image::new(ex, ex);
        default_levels(&[&e], out, out, side, coarsest)
    }

    #[test]
    fn the_coarsest_level_is_the_nearest_to_its_aim_by_ratio() {
        let (plain, tile, fill) = (coarsest_side(false, false), coarsest_side(true, false), coarsest_side(false, true));
        // 112 -> 28 (not 56), 224 -> 28, 128 -> 32, 96 -> 24, 64 -> 32.
        assert_eq!([112, 224, 128, 96, 64].map(|ex| levels(ex, 256, 5, plain)), [3, 4, 3, 3, 2]);
        // A tile aims at 16: 128 -> 16, 100 -> 12 (not 25).
        assert_eq!([128, 100].map(|ex| levels(ex, 256, 5, tile)), [4, 4]);
        // A fill keeps at least 32: 224 -> 56, 112 -> 56.
        assert_eq!([224, 112].map(|ex| levels(ex, 224, 11, fill)), [3, 2]);
        // Never below the neighbourhood, nor a coarsest output under 8, nor over 5.
        assert_eq!(levels(28, 256, 11, tile), 2);
        assert_eq!(levels(1024, 32, 5, plain), 3);
        assert_eq!(levels(4096, 4096, 5, plain), 5);
    }
}
