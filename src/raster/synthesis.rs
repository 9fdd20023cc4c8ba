//! Multi-resolution Wei-Levoy synthesis against one exemplar, or two whose best matches
//! each output pixel mixes by weights mu and 1 - mu (the paper's blending).
//!
//! Coarse to fine; at each level the output is filled in scanline order on a torus,
//! from noise drawn from the exemplar (the paper's start). The coarsest level of an
//! output that is not a tile starts instead from a quilt of exemplar windows (`quilt`),
//! which its passes then join with full neighbourhoods: grown causally from noise, it
//! drifted towards the exemplar's smoothest region. A pixel's feature is its causal
//! neighbourhood at this level and a 3x3 block of the (finished) parent level, read
//! where the pixel lies on it (`Pass::parent_feature`).
//! For each exemplar with weight > 0 the best-matching exemplar position is found and
//! the colours are mixed.
//!
//! Search: `exhaustive` compares with every exemplar position (the reference mode). The
//! default compares with coherent candidates only (Ashikhmin 2001): for each already
//! synthesized neighbour, the exemplar position next to the one it copied, so that
//! patches of the exemplar continue; plus the parent's position scaled up and a few
//! random positions; a candidate that many neighbours propose is preferred. The
//! coarsest level, a few hundred positions, is always exhaustive, which lays the
//! large-scale structure; finer levels refine it coherently. Exemplar neighbourhoods are
//! read on the fly (no feature tables) and the output is kept only as source positions,
//! so memory stays a few times the images' size; partial distances stop as soon as they
//! exceed the best so far.

use super::image::{check_output, check_size, Image, Rgba};
use super::neighbourhood::Shape;
use super::pyramid::{self, Edge};
use super::quilt::Quilt;
use crate::error::{invalid, Error, Result};
use crate::progress::Throttle;
use crate::rng::Rng;
use std::sync::OnceLock;

#[derive(Clone, Debug)]
pub struct Params {
    pub width: usize,
    pub height: usize,
    pub seed: u64,
    /// Pyramid levels; `None` picks them so the coarsest exemplar is about 32 pixels
    /// (16 for a tile; see `default_levels`).
    pub levels: Option<usize>,
    /// Neighbourhood side (odd, at least 3): 5 means a 5x5 causal L-shape.
    pub neighbourhood: usize,
    pub exhaustive: bool,
    /// Make the output tile: its wrap-around seams are re-synthesized with full,
    /// wrapping neighbourhoods.
    pub tileable: bool,
    /// Random candidates per pixel and exemplar in the coherent search.
    pub random_candidates: usize,
    /// Correction passes per level after the causal one: every pixel matched again with
    /// its full (two-sided) neighbourhood, which joins structures the causal pass broke.
    pub corrections: usize,
    pub schedule: Schedule,
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
            exhaustive: false,
            tileable: false,
            random_candidates: 2,
            corrections: 1,
            schedule: Schedule::Auto,
        }
    }
}

/// One exemplar prepared for matching: its pyramid, and each level's parent read at
/// that level's pixels (`upsampled`).
struct Exemplar {
    levels: Vec<Image>,
    /// `upsampled[l]`: level `l + 1` at the positions of level `l`'s pixels.
    upsampled: Vec<Image>,
}

impl Exemplar {
    fn new(img: &Image, levels: usize) -> Exemplar {
        let levels = pyramid::build(img, levels, Edge::Clamp);
        let upsampled = levels.windows(2).map(|w| pyramid::upsample(&w[1], w[0].width, w[0].height)).collect();
        Exemplar { levels, upsampled }
    }
}

/// Pixel offsets of a shape turned into index deltas for one image width: the own
/// level's, and the parent's in the upsampled parent (two pixels per parent pixel).
struct Offsets {
    own: Vec<isize>,
    parent_points: Vec<(isize, isize)>,
    parent: Vec<isize>,
}

fn offsets(shape: &Shape, width: usize) -> Offsets {
    let parent_points: Vec<_> = shape.parent.iter().map(|&(dx, dy)| (2 * dx, 2 * dy)).collect();
    Offsets {
        own: shape.own.iter().map(|&(dx, dy)| dy * width as isize + dx).collect(),
        parent: parent_points.iter().map(|&(dx, dy)| dy * width as isize + dx).collect(),
        parent_points,
    }
}

/// Weight of the parent level's squared differences. Its 3x3 block carries the
/// large-scale structure against 12 (causal) or 24 (full) pixels of the own level;
/// measured on the four exemplar photographs, 3 lowers the patch energy of every one
/// (e.g. gravel 12.2 -> 11.0, brick 4.3 -> 3.7) against equal weights.
const PARENT_WEIGHT: f32 = 3.0;

/// Coherence bias (after Ashikhmin's and Hertzmann's coherence terms): a candidate that
/// `v` of the `n` neighbours propose has its distance divided by `1 + COHERENCE (v - 1) / n`,
/// so an exemplar patch that most neighbours agree on wins over a lone, slightly closer
/// match; fewer seams, hence lower patch energy. Over 6 seeds on the four photographs
/// (with the reversed correction pass), 2 lowered the mean energy from 8.12 to 7.27 and
/// every photograph's; 4 and 8 cost brick more than they gained elsewhere.
const COHERENCE: f32 = 2.0;

/// Squared distance between `feature` and the neighbourhood of exemplar position `pos`
/// at `level`, stopping once it exceeds `bound`.
#[inline]
fn distance(ex: &Exemplar, level: usize, pos: usize, shape: &Shape, off: &Offsets, feature: &[f32], bound: f32) -> f32 {
    let img = &ex.levels[level];
    let (x, y) = ((pos % img.width) as isize, (pos / img.width) as isize);
    let mut acc = 0.0f32;
    let k = block(img, x, y, shape.half, &shape.own, &off.own, feature, 0, &mut acc);
    if acc > bound || k == feature.len() {
        return acc;
    }
    let mut parent = 0.0f32;
    block(&ex.upsampled[level], x, y, 2, &off.parent_points, &off.parent, feature, k, &mut parent);
    acc + PARENT_WEIGHT * parent
}

/// Adds to `acc` the squared differences between the pixels of `img` at `points` around
/// (x, y) and `feature` from index `k`; returns the next index. Index deltas `linear`
/// serve when the block lies inside the image (within `half` of the centre), clamped
/// reads at the border.
#[allow(clippy::too_many_arguments)]
#[inline]
fn block(
    img: &Image,
    x: isize,
    y: isize,
    half: isize,
    points: &[(isize, isize)],
    linear: &[isize],
    feature: &[f32],
    mut k: usize,
    acc: &mut f32,
) -> usize {
    let mut add = |p: [f32; 3], k: usize| {
        let d0 = p[0] - feature[k];
        let d1 = p[1] - feature[k + 1];
        let d2 = p[2] - feature[k + 2];
        *acc += d0 * d0 + d1 * d1 + d2 * d2;
    };
    let (w, h) = (img.width as isize, img.height as isize);
    if x >= half && x < w - half && y >= half && y < h - half {
        let base = y * w + x;
        for &o in linear {
            add(img.data[(base + o) as usize], k);
            k += 3;
        }
    } else {
        for &(dx, dy) in points {
            add(img.clamped(x + dx, y + dy), k);
            k += 3;
        }
    }
    k
}

/// Output pixels x exemplar positions x neighbourhood pixels up to which the coarsest
/// level is searched exhaustively (a 128-pixel exemplar at 256 x 256 out needs 7 M, at
/// 512 x 512 26 M). Above it, coherent search: at 1024 x 1024 (104 M) that was 17%
/// faster and lowered the mean patch energy of the four photographs from 7.20 to 6.60
/// (brick rose from 3.8 to 5.0 but kept its joints, which the exhaustive coarse level
/// had merged into long vertical stripes).
const COARSE_EXHAUSTIVE_BUDGET: usize = 25 << 21;
/// Output pixels x exemplar positions (in 5 x 5 neighbourhoods) the exhaustive
/// reference mode may compare.
const EXHAUSTIVE_BUDGET: f64 = 4e9;

/// Default number of levels: the coarsest exemplar about 32 pixels on its short side
/// (16 for a tile), at least the neighbourhood; the coarsest output at least 8; at most 5.
///
/// At 16 pixels the coarsest level has a few hundred positions for several times as many
/// output pixels, and its exhaustive search lays the same best few out again and again:
/// the large structure repeats. Over 3 seeds on the ten photographs (128 -> 256), 32
/// raised fur's repetition score from 0.784 to 0.854 (its exemplar's own: 0.875) and
/// the worst distance below an exemplar's own from 0.091 to 0.034, and lowered the mean
/// patch energy from 5.99 to 5.82; 8 (five levels) repeated more (fur 0.710).
/// A tile keeps 16: the exhaustive coarsest level is what joins long structures across
/// the wrap, and at 32 (searched coherently) brick's tiles broke their mortar lines
/// there (seam score 1.51 over 8 seeds, against 0.93).
fn default_levels(exemplars: &[&Image], width: usize, height: usize, side: usize, tileable: bool) -> usize {
    let ex = exemplars.iter().map(|e| e.width.min(e.height)).min().unwrap_or(1);
    let out = width.min(height);
    let coarsest = if tileable { 16 } else { 32 };
    let mut levels = 1;
    while levels < 5 && (ex >> levels) >= coarsest.max(side) && (out >> levels) >= 8 {
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

/// A synthesis prepared: the sources' pyramids, the mixing weights, the level sizes and
/// the neighbourhood shapes. Both schedules (`synthesize`'s scanline order and the
/// banded one in `bands`) run their passes over it.
pub struct Job {
    pub(crate) mix: Mixer,
    pub(crate) params: Params,
    /// Pyramid levels.
    pub levels: usize,
    /// Output size per level, finest first; they round up like the exemplars'.
    pub sizes: Vec<(usize, usize)>,
    pub(crate) causal: Shape,
    pub(crate) full: Shape,
    /// How the coarsest level is quilted, or `None` when it is not (see `quilted`).
    quilt: Option<Quilt>,
    /// The coarsest level's quilts, laid once (`quilts`).
    quilts: OnceLock<Vec<Vec<u32>>>,
}

impl Job {
    /// Checks the parameters and builds the exemplars' pyramids.
    pub fn new(sources: Sources, params: &Params) -> Result<Job> {
        let (width, height) = (params.width, params.height);
        check_output(width, height)?;
        let (exemplars, mu) = match sources {
            Sources::One(e) => (vec![e], None),
            Sources::Blend { a, b, mu } => {
                if mu.len() != width * height {
                    return invalid("The coefficient map does not match the output size.");
                }
                let quantized = mu.iter().map(|&m| (m.clamp(0.0, 1.0) * MU_ONE).round() as u16).collect();
                (vec![a, b], Some(quantized))
            }
        };
        let side = params.neighbourhood;
        if side < 3 || side % 2 == 0 || side > 15 {
            return invalid(format!("The neighbourhood size must be odd, from 3 to 15 (got {side})."));
        }
        for (i, e) in exemplars.iter().enumerate() {
            check_size(e.width, e.height, "exemplar")?;
            if e.width < side || e.height < side {
                return invalid(format!(
                    "Exemplar {} is {}x{}, smaller than the {side}x{side} neighbourhood.",
                    i + 1,
                    e.width,
                    e.height
                ));
            }
        }
        let levels = match params.levels {
            Some(l) if l == 0 || l > 8 => return invalid("Levels must be from 1 to 8."),
            Some(l) => l,
            None => default_levels(&exemplars, width, height, side, params.tileable),
        };
        if params.exhaustive {
            let positions: f64 = exemplars.iter().map(|e| (e.width * e.height) as f64).sum();
            // In 5 x 5 neighbourhoods: a larger one costs proportionally more.
            let comparisons = (width * height) as f64 * positions * 4.0 / 3.0 * (side * side) as f64 / 25.0;
            if comparisons > EXHAUSTIVE_BUDGET {
                return Err(Error::TooLarge(format!(
                    "Exhaustive search would compare {comparisons:.1e} neighbourhoods (the limit is {EXHAUSTIVE_BUDGET:.0e}, \
                     minutes of work); use the default search, or smaller images."
                )));
            }
        }
        let half = (side / 2) as isize;
        let exs: Vec<Exemplar> = exemplars.iter().map(|e| Exemplar::new(e, levels)).collect();
        let quilt = quilt_params();
        let quiltable = exs.iter().all(|ex| {
            let coarsest = &ex.levels[levels - 1];
            quilt.window(coarsest.width, coarsest.height).is_some()
        });
        Ok(Job {
            mix: Mixer { exs, mu, width, height },
            params: params.clone(),
            levels,
            sizes: (0..levels).map(|l| (width.div_ceil(1 << l), height.div_ceil(1 << l))).collect(),
            causal: Shape::causal(half),
            full: Shape::full(half),
            quilt: (quiltable && !params.tileable).then_some(quilt),
            quilts: OnceLock::new(),
        })
    }

    /// Whether pixel (x, y) of `level` lies in the rows and columns along the wrap that a
    /// tileable synthesis matches once more at the end of the level: the first
    /// neighbourhood's width of rows and columns, made against the state across the
    /// wrap before it was synthesized, and half that before the wrap.
    pub(crate) fn along_wrap(&self, level: usize, x: usize, y: usize) -> bool {
        let (lw, lh) = self.sizes[level];
        let band = (2 * self.causal.half as usize).min(lh).min(lw);
        y < band || x < band || y + band / 2 >= lh || x + band / 2 >= lw
    }

    /// Whether `level` starts from a quilt of exemplar windows (`quilt`) and so needs no
    /// causal pass: the coarsest level, when its exemplars are large enough to quilt,
    /// of an output that is not a tile. A tile's coarsest level is grown causally: quilted
    /// (windows wrapped round the torus, cut against the first ones), tissue's 256 tiles
    /// kept its make-up better (colour distance 0.63 -> 0.31 over seeds 1-3) but print's
    /// wrap became a seam (`seam_lines`: 1.07 -> 1.22-1.47 over seeds 1-8, against the
    /// issue's 1.2).
    pub(crate) fn quilted(&self, level: usize) -> bool {
        level + 1 == self.levels && self.quilt.is_some()
    }

    /// The coarsest level's quilts, one per exemplar (empty when it is not `quilted`):
    /// the same in both schedules, and laid once per job, however many bands read them.
    pub(crate) fn quilts(&self) -> &[Vec<u32>] {
        self.quilts.get_or_init(|| {
            let Some(quilt) = self.quilt else { return Vec::new() };
            let level = self.levels - 1;
            let (lw, lh) = self.sizes[level];
            let lay = |(e, ex): (usize, &Exemplar)| {
                let mut rng = Rng::new(self.params.seed ^ (0x51 << 56) ^ e as u64);
                quilt.lay(&ex.levels[level], lw, lh, &mut rng).expect("Job::new checked the window")
            };
            self.mix.exs.iter().enumerate().map(lay).collect()
        })
    }

    /// The parameters it was made with.
    pub fn params(&self) -> &Params {
        &self.params
    }

    /// Number of exemplars (one, or two when blending).
    pub fn exemplars(&self) -> usize {
        self.mix.exs.len()
    }

    /// Pixel count of `level`'s source maps, per exemplar.
    pub fn level_pixels(&self, level: usize) -> usize {
        self.sizes[level].0 * self.sizes[level].1
    }

    /// Width and height of exemplar `e` at `level`.
    pub(crate) fn exemplar_size(&self, e: usize, level: usize) -> (usize, usize) {
        let img = &self.mix.exs[e].levels[level];
        (img.width, img.height)
    }

    /// Positions in exemplar `e` at `level`.
    pub(crate) fn positions(&self, e: usize, level: usize) -> usize {
        self.mix.exs[e].levels[level].data.len()
    }

    /// One pass over `level`, whose parent level's sources are `parent_src` (empty at the
    /// coarsest level).
    pub(crate) fn pass<'a>(&'a self, level: usize, parent_src: &'a [Vec<u32>]) -> Pass<'a> {
        let (lw, lh) = self.sizes[level];
        let exs = &self.mix.exs;
        let with_parent = level + 1 < self.levels;
        let side = self.params.neighbourhood;
        let offsets = exs
            .iter()
            .map(|ex| (offsets(&self.causal, ex.levels[level].width), offsets(&self.full, ex.levels[level].width)))
            .collect();
        Pass {
            mix: &self.mix,
            level,
            lw,
            lh,
            parent_size: self.sizes.get(level + 1).copied().unwrap_or((1, 1)),
            with_parent,
            // The coarsest level is searched exhaustively when that is cheap (a few
            // hundred exemplar positions); a thin exemplar has only one level, at full
            // size, where exhaustive search would take minutes: coherent search there.
            exhaustive: self.params.exhaustive
                || (level + 1 == self.levels
                    && (lw * lh)
                        .saturating_mul(exs.iter().map(|e| e.levels[level].data.len()).sum())
                        .saturating_mul(side * side)
                        <= COARSE_EXHAUSTIVE_BUDGET),
            random: self.params.random_candidates,
            jitter: self.params.tileable,
            parent_src,
            offsets,
        }
    }

    /// The output image from the finest level's sources.
    pub fn colours(&self, src: &[Vec<u32>]) -> Rgba {
        let (width, height) = (self.params.width, self.params.height);
        Rgba { width, height, data: self.colour_rows(src, 0, height) }
    }

    /// RGBA bytes of the output's rows `first .. first + rows` (mod its height) from
    /// their sources at the finest level (`src`: those rows of each map, top first), so
    /// that the workers of the banded schedule colour the rows of their last bands.
    pub fn colour_rows(&self, src: &[Vec<u32>], first: usize, rows: usize) -> Vec<u8> {
        let (width, height) = (self.params.width, self.params.height);
        let mut data = Vec::with_capacity(width * rows * 4);
        for r in 0..rows {
            let y = (first + r) % height;
            for x in 0..width {
                let c = self.mix.colour(0, src, r * width + x, x, y);
                data.extend(c.iter().map(|&v| v.round().clamp(0.0, 255.0) as u8));
                data.push(255);
            }
        }
        data
    }
}

/// Synthesizes the job's image, each level in scanline order
/// (the paper's schedule, one thread). `bands::synthesize` is the schedule that several
/// workers can share.
///
/// Memory: the output is never stored as colours. Each level keeps, per exemplar and
/// pixel, the exemplar position it copies (4 bytes), and a pixel's colour is read through
/// it (mixed by mu when blending). With the parent level's map and mu in 16 bits, that
/// is at most 5 bytes per output pixel for one exemplar and 12 for two, plus the RGBA
/// result (4) at the end, when the parent's map is gone. The job also keeps the coarsest
/// level's quilts (`Job::quilts`: 4 bytes per pixel of that level and exemplar, a
/// quarter of a byte per output pixel with three levels, 4 with one).
pub fn synthesize(job: &Job, progress: &mut Throttle) -> Result<Rgba> {
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
        let quilted = job.quilted(level);
        let src: Vec<Vec<u32>> = if quilted {
            job.quilts().to_vec()
        } else {
            (0..job.exemplars())
                .map(|e| {
                    let n = job.positions(e, level);
                    (0..lw * lh).map(|_| rng.below(n) as u32).collect()
                })
                .collect()
        };
        let uses = Uses::count(job, level, |e, y, out| out.extend_from_slice(&src[e][y * lw..(y + 1) * lw]));
        let mut map = Map::whole(src, uses, lw, lh);
        let pass = job.pass(level, &parent_src);
        let mut scratch = Scratch::new(&job.full);
        // One causal pass, then the correction passes with full neighbourhoods, the first
        // in reverse scanline order: structure then also spreads up and left, from the
        // pixels the causal pass made last (6 seeds: mean energy 8.29 -> 8.12).
        let first = if quilted { (&job.full, true, false) } else { (&job.causal, false, false) };
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
    Ok(job.colours(&parent_src))
}

/// Source positions of one level's pixels, per exemplar, over rows `first .. first +
/// rows` (mod the level's height) of the torus: the whole level, or a band of it with
/// the rows around it that its neighbourhoods read (see `bands`).
pub(crate) struct Map {
    pub src: Vec<Vec<u32>>,
    /// The whole level's use counts, updated as the map's pixels change.
    pub uses: Option<Uses>,
    first: usize,
    rows: usize,
    lw: usize,
    lh: usize,
}

impl Map {
    /// The whole level.
    pub fn whole(src: Vec<Vec<u32>>, uses: Option<Uses>, lw: usize, lh: usize) -> Map {
        Map { src, uses, first: 0, rows: lh, lw, lh }
    }

    /// Rows `first .. first + rows` (mod `lh`) of a level `lw` wide and `lh` high.
    pub fn rows(src: Vec<Vec<u32>>, uses: Option<Uses>, first: usize, rows: usize, lw: usize, lh: usize) -> Map {
        debug_assert!(rows <= lh && src.iter().all(|s| s.len() == rows * lw));
        Map { src, uses, first, rows, lw, lh }
    }

    /// Index of pixel (x, y) of the torus, which must lie in the map's rows.
    #[inline]
    fn at(&self, x: isize, y: isize) -> usize {
        let (w, h) = (self.lw as isize, self.lh as isize);
        let row = (y - self.first as isize).rem_euclid(h) as usize;
        debug_assert!(row < self.rows, "row {y} outside the map's rows");
        row * self.lw + x.rem_euclid(w) as usize
    }
}

/// mu = 1 in the 16-bit map.
const MU_ONE: f32 = 65535.0;

/// The exemplars and how they mix: output colours are read through source maps.
pub(crate) struct Mixer {
    exs: Vec<Exemplar>,
    /// The weight of exemplar 0 per output pixel, 65535 = 1 (None: one exemplar).
    mu: Option<Vec<u16>>,
    /// Full output size.
    width: usize,
    height: usize,
}

impl Mixer {
    /// The weight of exemplar `e` at (x, y) of `level`: mu sampled at the pixel's
    /// footprint in the full output.
    #[inline]
    fn weight(&self, e: usize, level: usize, x: usize, y: usize) -> f32 {
        match &self.mu {
            None => 1.0,
            Some(mu) => {
                let (fx, fy) = ((x << level).min(self.width - 1), (y << level).min(self.height - 1));
                let m = mu[fy * self.width + fx] as f32 / MU_ONE;
                if e == 0 {
                    m
                } else {
                    1.0 - m
                }
            }
        }
    }

    /// The output colour of pixel (x, y) of `level`, at index `i` of the source maps
    /// `src`: the sources' colours mixed by weight.
    #[inline]
    fn colour(&self, level: usize, src: &[Vec<u32>], i: usize, x: usize, y: usize) -> [f32; 3] {
        let read = |e: usize| self.exs[e].levels[level].data[src[e][i] as usize];
        if self.mu.is_none() {
            return read(0);
        }
        let m = self.weight(0, level, x, y);
        if m >= 1.0 {
            read(0)
        } else if m <= 0.0 {
            read(1)
        } else {
            let (a, b) = (read(0), read(1));
            [0, 1, 2].map(|c| m * a[c] + (1.0 - m) * b[c])
        }
    }
}

/// Per-pixel working vectors, allocated once per pass.
pub(crate) struct Scratch {
    /// The output's neighbourhood feature.
    f: Vec<f32>,
    /// One exemplar's own-choices feature (partial weights).
    own: Vec<f32>,
    /// Candidate positions with their numbers of proposals.
    cands: Vec<(u32, u16)>,
}

impl Scratch {
    pub fn new(full: &Shape) -> Scratch {
        Scratch {
            f: Vec::with_capacity(full.dim(true)),
            own: Vec::with_capacity(full.dim(true)),
            cands: Vec::with_capacity(64),
        }
    }
}

/// One pass over one level: what every pixel's match needs besides the level's map.
pub(crate) struct Pass<'a> {
    mix: &'a Mixer,
    level: usize,
    /// This level's size and the parent level's.
    lw: usize,
    lh: usize,
    parent_size: (usize, usize),
    with_parent: bool,
    exhaustive: bool,
    random: usize,
    /// Whether the parent's candidate also comes shifted by up to a pixel (tiles; see
    /// `coherent_candidates`).
    jitter: bool,
    parent_src: &'a [Vec<u32>],
    /// Index deltas per exemplar, for the causal shape and the full one.
    offsets: Vec<(Offsets, Offsets)>,
}

/// The quilt's window side and candidates; probes may set them through
/// `PATTERNSYNTH_QUILT=side,candidates`.
fn quilt_params() -> Quilt {
    #[cfg(feature = "test-support")]
    if let Ok(v) = std::env::var("PATTERNSYNTH_QUILT") {
        let n: Vec<usize> = v.split(',').filter_map(|s| s.parse().ok()).collect();
        if n.len() == 2 {
            return Quilt { side: n[0], candidates: n[1] };
        }
    }
    Quilt::default()
}

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
            scale.push(w * n as f32 / pixels);
            // A tile's penalty starts at the first use.
            free.push(if job.params.tileable { 0.0 } else { pixels / n as f32 });
        }
        Some(Uses { counts, scale, free })
    }

    #[inline]
    fn factor(&self, e: usize, pos: usize) -> f32 {
        1.0 + self.scale[e] * (self.counts[e][pos] as f32 - self.free[e]).max(0.0)
    }

    #[inline]
    fn moved(&mut self, e: usize, from: u32, to: u32) {
        self.counts[e][from as usize] -= 1;
        self.counts[e][to as usize] += 1;
    }
}

impl Pass<'_> {
    /// The output's feature at (x, y): own level read on the torus, parent level too.
    fn feature(&self, map: &Map, x: usize, y: usize, shape: &Shape, f: &mut Vec<f32>) {
        f.clear();
        let (lw, lh) = (self.lw as isize, self.lh as isize);
        for &(dx, dy) in &shape.own {
            let (nx, ny) = (x as isize + dx, y as isize + dy);
            let (gx, gy) = (nx.rem_euclid(lw) as usize, ny.rem_euclid(lh) as usize);
            f.extend_from_slice(&self.mix.colour(self.level, &map.src, map.at(nx, ny), gx, gy));
        }
        if self.with_parent {
            let pw = self.parent_size.0;
            self.parent_feature(shape, x, y, f, |nx, ny| {
                self.mix.colour(self.level + 1, self.parent_src, ny * pw + nx, nx, ny)
            });
        }
    }

    /// Appends the parent level's colours (`colour(px, py)` at parent pixel (px, py)) at
    /// the parent offsets around output pixel (x, y), read where the pixel lies at the
    /// parent level: (x / 2, y / 2) exactly, so between two or four parent pixels when x
    /// or y is odd (a parent pixel is the blur centred on its even child; see `pyramid`).
    /// The exemplar side reads the same points (`Exemplar::upsampled`), so a patch
    /// copied at an odd offset matches its parent as well as one at an even offset.
    /// Read at (x / 2, y / 2) rounded down, the parent feature stepped at every second
    /// pixel and a patch copied at an odd offset met its parent half a parent pixel off.
    /// Read here, over 8 seeds at 256, print's tile wrap scores 1.22 rather than 1.33 and
    /// tissue's 1.04 rather than 1.14; plain syntheses of the ten photographs (128 ->
    /// 256, 3 seeds) have a mean patch energy of 5.76 against 5.70, each still below
    /// texture-synthesis's, and take about 8% longer.
    fn parent_feature(
        &self,
        shape: &Shape,
        x: usize,
        y: usize,
        f: &mut Vec<f32>,
        colour: impl Fn(usize, usize) -> [f32; 3],
    ) {
        let (pw, ph) = (self.parent_size.0 as isize, self.parent_size.1 as isize);
        // The parent pixels the 3 x 3 points reach: 3 or 4 on a side.
        let (ox, oy) = (x % 2, y % 2);
        let mut window = [[0.0f32; 3]; 16];
        for j in 0..3 + oy {
            for i in 0..3 + ox {
                let (px, py) = ((x / 2 + i) as isize - 1, (y / 2 + j) as isize - 1);
                window[j * 4 + i] = colour(px.rem_euclid(pw) as usize, py.rem_euclid(ph) as usize);
            }
        }
        for &(dx, dy) in &shape.parent {
            let (i, j) = ((dx + 1) as usize, (dy + 1) as usize);
            // Four reads, each pixel as many times as it counts (all four the same pixel
            // when x and y are even).
            let mut c = [0.0f32; 3];
            for q in
                [window[j * 4 + i], window[j * 4 + i + ox], window[(j + oy) * 4 + i], window[(j + oy) * 4 + i + ox]]
            {
                (0..3).for_each(|k| c[k] += q[k]);
            }
            f.extend(c.iter().map(|v| v * 0.25));
        }
    }

    /// Synthesizes output pixel (x, y) at this level: sets its source in every exemplar.
    #[allow(clippy::too_many_arguments)]
    pub fn pixel(
        &self,
        map: &mut Map,
        shape: &Shape,
        use_full: bool,
        x: usize,
        y: usize,
        rng: &mut Rng,
        scratch: &mut Scratch,
    ) {
        let level = self.level;
        let Scratch { f, own, cands } = scratch;
        self.feature(map, x, y, shape, f);
        for (e, ex) in self.mix.exs.iter().enumerate() {
            let weight = self.mix.weight(e, level, x, y);
            let img = &ex.levels[level];
            let off = if use_full { &self.offsets[e].1 } else { &self.offsets[e].0 };
            // Where an exemplar has a partial weight, it is matched against the mixed
            // neighbourhood only in proportion to that weight; the rest is its own
            // choices around the pixel. At weight 1 this is the paper's rule; as the
            // weight falls, a faint exemplar no longer collapses onto the one patch that
            // best imitates the other exemplar's colours (rows of repeated blobs). At
            // weight 0 it is synthesized against its own choices alone, so that where it
            // fades in it is already a texture of its own, not one long verbatim copy.
            let f: &[f32] = if weight < 1.0 {
                self.own_feature(map, e, shape, x, y, own);
                for (o, m) in own.iter_mut().zip(f.iter()) {
                    *o = weight * m + (1.0 - weight) * *o;
                }
                own
            } else {
                f
            };
            let best = if self.exhaustive {
                let mut best = (f32::INFINITY, 0u32);
                for pos in 0..img.data.len() {
                    let p = map.uses.as_ref().map_or(1.0, |u| u.factor(e, pos));
                    let d = distance(ex, level, pos, shape, off, f, best.0 / p) * p;
                    if d < best.0 {
                        best = (d, pos as u32);
                    }
                }
                best.1
            } else {
                self.coherent_candidates(map, e, shape, x, y, img, rng, cands);
                let n = shape.own.len() as f32;
                let mut best = (f32::INFINITY, cands[0].0);
                for &(pos, votes) in cands.iter() {
                    let mut bias = 1.0 + COHERENCE * (votes - 1) as f32 / n;
                    if let Some(u) = &map.uses {
                        bias /= u.factor(e, pos as usize);
                    }
                    let d = distance(ex, level, pos as usize, shape, off, f, best.0 * bias) / bias;
                    if d < best.0 {
                        best = (d, pos);
                    }
                }
                best.1
            };
            let i = map.at(x as isize, y as isize);
            let old = std::mem::replace(&mut map.src[e][i], best);
            if let Some(u) = &mut map.uses {
                u.moved(e, old, best);
            }
        }
    }

    /// The neighbourhood of exemplar `e`'s own choices around (x, y): each neighbour's
    /// source colour, at this level and the parent's.
    fn own_feature(&self, map: &Map, e: usize, shape: &Shape, x: usize, y: usize, v: &mut Vec<f32>) {
        v.clear();
        let ex = &self.mix.exs[e];
        let img = &ex.levels[self.level];
        for &(dx, dy) in &shape.own {
            let n = map.at(x as isize + dx, y as isize + dy);
            v.extend_from_slice(&img.data[map.src[e][n] as usize]);
        }
        if self.with_parent {
            let (parent, pw) = (&ex.levels[self.level + 1], self.parent_size.0);
            self.parent_feature(shape, x, y, v, |nx, ny| parent.data[self.parent_src[e][ny * pw + nx] as usize]);
        }
    }

    /// Candidate exemplar positions for exemplar `e` at (x, y), each with the number of
    /// proposals it got: each neighbour's source shifted back by the neighbour's offset,
    /// the parent's source scaled up (for a tile also shifted by -1, 0 or 1 in x and y
    /// at random), and a few random positions.
    ///
    /// The parent's candidate alone puts a child at twice its parent's offset into the
    /// exemplar, and coherent copies keep that offset, so the finest pixels copy at
    /// offsets that are multiples of 2 per level (in 256 print tiles, 86% at multiples
    /// of 8), and the exemplar's edges, where copied patches end, fall on the coarsest
    /// level's pixel boundaries: one line in 8 differs 1.24 times the mean across a
    /// line, and the wrap is one of them. The shifted candidate starts patches at other
    /// offsets too (61% at multiples of 8; that line 1.14): over 8 seeds at 256, print's
    /// wrap scores 1.19 (1.22 without it, 1.33 with the parent also read at rounded
    /// positions, see `parent_feature`) and no other photograph's above 1.12. Only
    /// tiles take it: in other outputs the extra seams raised the mean patch energy over
    /// the ten photographs from 5.76 to 5.84, hubble's above texture-synthesis's.
    #[allow(clippy::too_many_arguments)]
    fn coherent_candidates(
        &self,
        map: &Map,
        e: usize,
        shape: &Shape,
        x: usize,
        y: usize,
        img: &Image,
        rng: &mut Rng,
        cands: &mut Vec<(u32, u16)>,
    ) {
        cands.clear();
        let (ew, eh) = (img.width as isize, img.height as isize);
        let push = |c: u32, cands: &mut Vec<(u32, u16)>| match cands.iter_mut().find(|(q, _)| *q == c) {
            Some((_, votes)) => *votes += 1,
            None => cands.push((c, 1)),
        };
        for &(dx, dy) in &shape.own {
            let s = map.src[e][map.at(x as isize + dx, y as isize + dy)] as isize;
            let (sx, sy) = (s % ew - dx, s / ew - dy);
            if sx >= 0 && sx < ew && sy >= 0 && sy < eh {
                push((sy * ew + sx) as u32, cands);
            }
        }
        if self.with_parent {
            let parent = &self.mix.exs[e].levels[self.level + 1];
            let (pw, plw) = (parent.width as isize, self.parent_size.0);
            let s = self.parent_src[e][(y / 2) * plw + x / 2] as isize;
            let sx = (2 * (s % pw) + (x % 2) as isize).min(ew - 1);
            let sy = (2 * (s / pw) + (y % 2) as isize).min(eh - 1);
            push((sy * ew + sx) as u32, cands);
            if self.jitter {
                let j = |v: isize, n: isize, rng: &mut Rng| (v + rng.below(3) as isize - 1).clamp(0, n - 1);
                let (jx, jy) = (j(sx, ew, rng), j(sy, eh, rng));
                push((jy * ew + jx) as u32, cands);
            }
        }
        for _ in 0..self.random.max(usize::from(cands.is_empty())) {
            push(rng.below(img.data.len()) as u32, cands);
        }
    }
}
