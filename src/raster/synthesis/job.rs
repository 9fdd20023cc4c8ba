//! A synthesis prepared: the exemplars' pyramids, the mixing weights, the level sizes
//! and the neighbourhood shapes, which both schedules run their passes over.

use super::exemplar::{Exemplar, Offsets, Plane};
use super::fusion::{self, Keep, Shares};
use super::lanes::px;
use super::mask;
use super::mixer::{Mixer, MU_ONE};
use super::opacity::Opacity;
use super::pass::Pass;
use super::start::{field_params, field_quilt_on, quilt_params, tile_quilt, Start};
use super::{coarsest_side, default_levels, Params, Sources};
use crate::error::{invalid, Error, Result};
use crate::raster::bands;
use crate::raster::image::{check_output, check_size, Rgba};
use crate::raster::neighbourhood::Shape;
use crate::raster::pyramid::{self, Edge};
use crate::raster::quilt::Quilt;
use crate::rng::Rng;
use std::sync::OnceLock;

/// Output pixels x exemplar positions x neighbourhood pixels up to which the coarsest
/// level grown from noise is searched exhaustively (a 128-pixel exemplar, coarsest at
/// 32, at 256 x 256 out needs 105 M; a 128-pixel tile, coarsest at 16, 26 M at
/// 512 x 512). A quilted coarsest level is always searched coherently (`pass_shaped`);
/// a target guide lays the quilt out itself (`GUIDED_QUILT`). Above it, coherent search: at
/// 1024 x 1024 (104 M, with the coarsest at 16) that was 17%
/// faster and lowered the mean patch energy of the four photographs from 7.20 to 6.60
/// (brick rose from 3.8 to 5.0 but kept its joints, which the exhaustive coarse level
/// had merged into long vertical stripes).
const COARSE_EXHAUSTIVE_BUDGET: usize = 25 << 21;
/// Output pixels x exemplar positions (in 5 x 5 neighbourhoods) the exhaustive
/// reference mode may compare.
const EXHAUSTIVE_BUDGET: f64 = 4e9;

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
    /// How the coarsest level starts, or `None` when it grows from noise (see `started`).
    pub(super) start: Option<Start>,
    /// The coarsest level's starting maps, made once (`starts`).
    pub(super) starts: OnceLock<Vec<Vec<u32>>>,
    /// The known output pixels at each level, finest first (`Constraints::known`).
    pub(crate) known: Option<Vec<Vec<bool>>>,
    /// The target guide at each level, finest first, scaled as the exemplars' guide lane.
    pub(crate) target: Option<Vec<Vec<f32>>>,
    /// How the exemplar's pixels carry its opacity (`Constraints::alpha`).
    pub(crate) opacity: Opacity,
    /// Each exemplar's alpha when any is not opaque everywhere: each output pixel takes
    /// the alpha of the pixel it copies, or blends them (`colour_rows`).
    shown_alpha: Option<Vec<Vec<u8>>>,
    /// Whether the finest level's seams are fused (`fusion`, `Params::fuse_seams`).
    fused: bool,
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
            None => {
                let coarsest = coarsest_side(params.tileable, params.constraints.known.is_some());
                default_levels(&exemplars, width, height, side, coarsest)
            }
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
        let c = &params.constraints;
        if c.allowed.len() > exemplars.len() {
            return invalid(format!("{} sample masks for {} exemplars.", c.allowed.len(), exemplars.len()));
        }
        for (i, (e, a)) in exemplars.iter().zip(&c.allowed).enumerate() {
            if a.as_ref().is_some_and(|a| a.len() != e.width * e.height) {
                return invalid(format!(
                    "Sample mask {} does not match its exemplar ({}x{}).",
                    i + 1,
                    e.width,
                    e.height
                ));
            }
        }
        let e0 = exemplars[0];
        if let Some(known) = &c.known {
            if known.len() != width * height || (e0.width, e0.height) != (width, height) {
                return invalid("Known pixels need an exemplar of the output's size, and one flag per pixel.");
            }
            if exemplars.len() > 1 {
                return invalid("Known pixels come from one exemplar.");
            }
        }
        let guide = match &c.guide {
            None => None,
            Some(g) => {
                if exemplars.len() > 1 {
                    return invalid("A guide applies to one exemplar (blends take none).");
                }
                if (g.exemplar.width, g.exemplar.height) != (e0.width, e0.height) {
                    return invalid(format!(
                        "The exemplar's guide is {}x{}; the exemplar is {}x{}.",
                        g.exemplar.width, g.exemplar.height, e0.width, e0.height
                    ));
                }
                if (g.target.width, g.target.height) != (width, height) {
                    return invalid(format!(
                        "The target guide is {}x{}; the output is {width}x{height}.",
                        g.target.width, g.target.height
                    ));
                }
                Some(g)
            }
        };
        if c.alphas.len() > exemplars.len() {
            return invalid(format!("{} alpha planes for {} exemplars.", c.alphas.len(), exemplars.len()));
        }
        for (i, (a, e)) in c.alphas.iter().zip(&exemplars).enumerate() {
            if a.as_ref().is_some_and(|a| a.len() != e.width * e.height) {
                return invalid(format!("Alpha plane {} is not one value per pixel of its exemplar.", i + 1));
            }
        }
        // Each exemplar's alpha (a missing one opaque) where any of them is not opaque
        // everywhere: shown through the source maps; compared where it varies.
        let alphas: Vec<Vec<u8>> = exemplars
            .iter()
            .enumerate()
            .map(|(i, e)| c.alphas.get(i).cloned().flatten().unwrap_or_else(|| vec![255; e.width * e.height]))
            .collect();
        let first = alphas[0].first().copied().unwrap_or(255);
        let varies = alphas.iter().flatten().any(|&v| v != first);
        let shown_alpha = alphas.iter().flatten().any(|&v| v != 255).then(|| alphas.clone());
        let opacity = Opacity::of(varies, guide.is_some());
        let exs: Vec<Exemplar> = exemplars
            .iter()
            .enumerate()
            .map(|(i, e)| {
                let allowed = c.allowed.get(i).and_then(|a| a.as_deref());
                let guide = guide.map(|g| (&g.exemplar, g.scale()));
                let alpha = varies.then(|| (&alphas[i][..], opacity));
                Exemplar::new(e, levels, allowed, guide, alpha, c.kept_out())
            })
            .collect::<Result<_>>()?;
        let sizes: Vec<_> = (0..levels).map(|l| (width.div_ceil(1 << l), height.div_ceil(1 << l))).collect();
        let known = c.known.as_ref().map(|k| mask::pyramid(k.clone(), width, height, levels, params.tileable));
        let target = guide.map(|g| {
            let scale = g.scale();
            pyramid::build(&g.target, levels, Edge::Clamp)
                .into_iter()
                .map(|l| l.data.iter().map(|p| scale * p[0]).collect())
                .collect()
        });
        // Whether every exemplar's coarsest level takes `quilt`'s windows.
        let fits = |quilt: &Quilt, torus: bool| {
            exs.iter().all(|ex| {
                let coarsest = &ex.levels[levels - 1];
                quilt.window_for((coarsest.width, coarsest.height), sizes[levels - 1], torus).is_some()
            })
        };
        let quilt = quilt_params(params.tileable);
        let quiltable = fits(&quilt, params.tileable);
        let start = match &params.start {
            Some(picture) => {
                if (picture.width, picture.height) != (width, height) {
                    return invalid(format!(
                        "The starting picture is {}x{}; the output is {width}x{height}.",
                        picture.width, picture.height
                    ));
                }
                let coarsest = pyramid::build(picture, levels, Edge::Wrap).pop().expect("at least one level");
                debug_assert_eq!((coarsest.width, coarsest.height), sizes[levels - 1]);
                let picture = coarsest.data.iter().map(|&c| px(c)).collect();
                // (A tile's picture is followed by a quilt where the level is large
                // enough: `start::FIELD_QUILT`.)
                if params.tileable && fits(&field_params().0, true) && field_quilt_on() {
                    Some(Start::FieldQuilt(picture))
                } else {
                    Some(Start::Layout(picture))
                }
            }
            None if known.is_some() => Some(Start::Onion),
            None => (quiltable && (!params.tileable || tile_quilt())).then_some(Start::Quilt(quilt)),
        };
        let fused = params.fuse_seams
            && fusion::probed()
            && exemplars.len() == 1
            && known.is_none()
            && guide.is_none()
            && shown_alpha.is_none()
            && !fusion::palette(e0, c.allowed.first().and_then(|a| a.as_deref()));
        Ok(Job {
            mix: Mixer { exs, mu, width, height },
            params: params.clone(),
            levels,
            sizes,
            causal: Shape::causal(half),
            full: Shape::full(half),
            start,
            starts: OnceLock::new(),
            known,
            target,
            opacity,
            shown_alpha,
            fused,
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

    /// The job with its `levels` finest levels only, the coarsest of them started afresh
    /// (a mended band made again from a finer coarsest level, `inpaint::Copies::again`):
    /// what `Job::new` makes with that many levels, without building the pyramids again.
    pub(crate) fn keep_finest(&mut self, levels: usize) {
        debug_assert!(self.known.is_some(), "a job started from its known pixels");
        if levels == 0 || levels >= self.levels {
            return;
        }
        self.levels = levels;
        self.params.levels = Some(levels);
        self.sizes.truncate(levels);
        for ex in &mut self.mix.exs {
            ex.levels.truncate(levels);
            ex.upsampled.truncate(levels - 1);
        }
        if let Some(k) = &mut self.known {
            k.truncate(levels);
        }
        if let Some(t) = &mut self.target {
            t.truncate(levels);
        }
        self.starts = OnceLock::new();
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

    /// Exemplar `e` at `level`.
    pub(crate) fn plane(&self, e: usize, level: usize) -> &Plane {
        &self.mix.exs[e].levels[level]
    }

    /// Positions of exemplar `e` at `level` that may be copied.
    pub(crate) fn allowed_positions(&self, e: usize, level: usize) -> usize {
        self.mix.exs[e].levels[level].allowed_count()
    }

    /// A position of exemplar `e` at `level` that may be copied, at random (the noise a
    /// level grows from).
    pub(crate) fn random_position(&self, e: usize, level: usize, rng: &mut Rng) -> u32 {
        self.mix.exs[e].levels[level].random(rng)
    }

    /// Whether the output is read on a torus: a tile, and a synthesis from scratch (whose
    /// output then nearly tiles; its first rows are matched against its last); not an
    /// image filled around known pixels (`inpaint`), which is no tile.
    pub(crate) fn torus(&self) -> bool {
        self.params.tileable || self.known.is_none()
    }

    /// Whether output pixel `i` of `level` is known (pinned to the same exemplar pixel).
    #[inline]
    pub(crate) fn is_known(&self, level: usize, i: usize) -> bool {
        self.known.as_ref().is_some_and(|k| k[level][i])
    }

    /// One pass over `level`, whose parent level's sources are `parent_src` (empty at the
    /// coarsest level).
    pub(crate) fn pass<'a>(&'a self, level: usize, parent_src: &'a [Vec<u32>]) -> Pass<'a> {
        self.pass_shaped(level, parent_src, &self.full)
    }

    /// `pass` whose full neighbourhood is `full` (a known pixel's fine levels).
    pub(crate) fn pass_shaped<'a>(&'a self, level: usize, parent_src: &'a [Vec<u32>], full: &Shape) -> Pass<'a> {
        let (lw, lh) = self.sizes[level];
        let exs = &self.mix.exs;
        let with_parent = level + 1 < self.levels;
        let side = self.params.neighbourhood;
        let offsets = exs
            .iter()
            .map(|ex| (Offsets::new(&self.causal, ex.levels[level].width), Offsets::new(full, ex.levels[level].width)))
            .collect();
        Pass {
            mix: &self.mix,
            level,
            lw,
            lh,
            parent_size: self.sizes.get(level + 1).copied().unwrap_or((1, 1)),
            with_parent,
            // The coarsest level grown from noise is searched exhaustively when that is
            // cheap (a few hundred exemplar positions); a thin exemplar has only one
            // level, at full size, where exhaustive search would take minutes: coherent
            // search there. A quilt has laid the large structure already, and searching
            // it exhaustively again only made the same best few windows win everywhere:
            // searched coherently, the ten 128 fixtures at 128 x 128 (seeds 1-3) went from
            // a mean patch energy of 7.02 to 5.94 and a median 96 ms to 16 (native), and
            // the eight 224-pixel photographs at 256 x 256 from 5.78 to 5.13. A target
            // guide lays the quilt out itself (`GUIDED_QUILT`).
            // Around known pixels the onion start has searched the coarsest level already
            // (`pinned`): its passes search coherently, as the finer levels' do (searching
            // again with 11 x 11 neighbourhoods was a third of a small tile's mending: the
            // 128-pixel grass and gravel fixtures took 35-36 ms rather than 23-24).
            exhaustive: self.params.exhaustive
                || (level + 1 == self.levels
                    && self.known.is_none()
                    && !self.quilted()
                    && (lw * lh)
                        .saturating_mul(exs.iter().map(|e| e.levels[level].data.len()).sum())
                        .saturating_mul(side * side)
                        <= COARSE_EXHAUSTIVE_BUDGET),
            random: self.params.random_candidates,
            jitter: self.params.tileable,
            parent_src,
            offsets,
            target: self.target.as_ref().map(|t| (&t[level][..], t.get(level + 1).map_or(&[][..], |p| &p[..]))),
            // Around known pixels the bias grew one coherent patch over the whole hole and
            // kept it against the hole's border (see `pinned::PINNED_COHERENCE`).
            coherence: if self.known.is_some() { super::pinned::PINNED_COHERENCE } else { super::pass::COHERENCE },
            torus: self.torus(),
        }
    }

    /// The output image from the finest level's sources.
    pub fn colours(&self, src: &[Vec<u32>]) -> Rgba {
        let (width, height) = (self.params.width, self.params.height);
        let data = match bands::colour_bands(self) {
            None => self.colour_rows(src, 0, height),
            // Band by band, as the workers colour them (`fused_band`).
            Some(list) => {
                let mut data = vec![0u8; 4 * width * height];
                let keep = self.keep(src);
                for band in list {
                    let colours = self.fused_band(src, band.first, band.rows, &keep);
                    for (r, c) in colours.chunks_exact(4 * width).enumerate() {
                        let row = ((band.first + r) % height) * width;
                        data[4 * row..4 * (row + width)].copy_from_slice(c);
                    }
                }
                data
            }
        };
        Rgba { width, height, data }
    }

    /// Whether the finest level's seams are fused (`fusion`): the output's colours are
    /// then made from the whole finest level, a band with the rows around it.
    pub fn fused(&self) -> bool {
        self.fused
    }

    /// RGBA bytes of rows `first .. first + rows` (mod the height) of a fused output, from
    /// the whole finest level's sources `src`, given back the copied colours'
    /// distribution by `keep` (`Job::keep`, the same for every band).
    pub fn fused_band(&self, src: &[Vec<u32>], first: usize, rows: usize, keep: &Keep) -> Vec<u8> {
        let (span, skip) = self.fused_span(src, first, rows, fusion::HALO);
        rgba(self.span_rows(&span, skip, rows).map(|&c| keep.applied(c)))
    }

    /// The map that gives a fused output back its copied colours' distribution
    /// (`fusion::Keep`): counted over the whole output when it is about as small as
    /// `KEEP_STRIPS` strips with their halos, else over those strips, spread evenly down
    /// it. A band sees only its own rows, and a map from each band's differed from band
    /// to band by up to 5 levels at 192 x 200; the strips are the same for every band and
    /// worker.
    pub fn keep(&self, src: &[Vec<u32>]) -> Keep {
        let height = self.params.height;
        let mut shares = Shares::new();
        let mut count = |first: usize, rows: usize, halo: usize| {
            let (span, skip) = self.fused_span(src, first, rows, halo);
            shares.add(self.copied_rows(src, first, rows), self.span_rows(&span, skip, rows).copied());
        };
        if KEEP_STRIPS * (KEEP_ROWS + 2 * KEEP_HALO) >= height {
            count(0, height, fusion::HALO);
        } else {
            for k in 0..KEEP_STRIPS {
                count(k * height / KEEP_STRIPS, KEEP_ROWS, KEEP_HALO);
            }
        }
        shares.keep()
    }

    /// The copied colours of rows `first .. first + rows` (mod the height).
    fn copied_rows<'a>(
        &'a self,
        src: &'a [Vec<u32>],
        first: usize,
        rows: usize,
    ) -> impl Iterator<Item = [f32; 3]> + 'a {
        let (width, height) = (self.params.width, self.params.height);
        let plane = &self.mix.exs[0].levels[0];
        (0..rows).flat_map(move |r| {
            let y = (first + r) % height;
            src[0][y * width..(y + 1) * width].iter().map(|&p| {
                let c = plane.data[p as usize];
                [c[0], c[1], c[2]]
            })
        })
    }

    /// Rows `first .. first + rows` (mod the height) fused from the whole finest level's
    /// sources `src`, with `halo` rows on each side (the whole torus when that is all of
    /// it), so that bands coloured apart meet as the whole output fused at once would,
    /// within rounding: the span fused, and the index of the band's first row in it.
    fn fused_span(&self, src: &[Vec<u32>], first: usize, rows: usize, halo: usize) -> (Vec<[f32; 3]>, usize) {
        debug_assert!(self.fused);
        let (width, height) = (self.params.width, self.params.height);
        let plane = &self.mix.exs[0].levels[0];
        if rows + 2 * halo >= height {
            return (fusion::fuse(plane, &src[0], width, height, true), first);
        }
        let top = first + height - halo;
        let span = rows + 2 * halo;
        let rows: Vec<u32> = (0..span)
            .flat_map(|r| {
                let y = (top + r) % height;
                src[0][y * width..(y + 1) * width].iter().copied()
            })
            .collect();
        (fusion::fuse(plane, &rows, width, span, false), halo)
    }

    /// The `rows` rows of a fused span (`fused_span`) from its row `skip` on (wrapping
    /// round a whole torus).
    fn span_rows<'a>(&self, span: &'a [[f32; 3]], skip: usize, rows: usize) -> impl Iterator<Item = &'a [f32; 3]> + 'a {
        let width = self.params.width;
        let n = span.len() / width;
        (0..rows).flat_map(move |r| span[((skip + r) % n) * width..][..width].iter())
    }

    /// The colour and alpha of output pixel (x, y) at index `i` of the finest sources,
    /// from exemplars with transparency: each source's colour as it shows, and its alpha;
    /// blended, the colours premultiplied by their alpha and mixed, then divided by the
    /// mixed alpha (a transparent source adds no colour, only clearness).
    fn shown(&self, alphas: &[Vec<u8>], src: &[Vec<u32>], i: usize, x: usize, y: usize) -> ([f32; 3], f32) {
        let mut sum = ([0.0f32; 3], 0.0f32);
        for (e, ex) in self.mix.exs.iter().enumerate() {
            let w = self.mix.weight(e, 0, x, y);
            if w <= 0.0 {
                continue;
            }
            let p = src[e][i] as usize;
            let a = alphas[e][p] as f32;
            let c = ex.levels[0].data[p];
            let c = self.opacity.shown([c[0], c[1], c[2]], a);
            for (s, v) in sum.0.iter_mut().zip(c) {
                *s += w * a * v;
            }
            sum.1 += w * a;
        }
        let (c, a) = sum;
        (if a > 0.0 { c.map(|v| v / a) } else { [0.0; 3] }, a)
    }

    /// RGBA bytes of the output's rows `first .. first + rows` (mod its height) from
    /// their sources at the finest level (`src`: those rows of each map, top first), so
    /// that the workers of the banded schedule colour the rows of their last bands. A
    /// fused output's colours need the rows around too (`fused_band`); the whole output
    /// (`first` 0, `rows` the height) is fused on the torus here.
    pub fn colour_rows(&self, src: &[Vec<u32>], first: usize, rows: usize) -> Vec<u8> {
        let (width, height) = (self.params.width, self.params.height);
        if self.fused {
            debug_assert!(first == 0 && rows == height, "a fused band is coloured by fused_band");
            // (Coloured at once: the map counts every pixel.)
            let (colours, _) = self.fused_span(src, 0, height, fusion::HALO);
            let keep = Shares::of(self.copied_rows(src, 0, height), colours.iter().copied()).keep();
            return rgba(colours.iter().map(|&c| keep.applied(c)));
        }
        let mut data = Vec::with_capacity(width * rows * 4);
        for r in 0..rows {
            let y = (first + r) % height;
            for x in 0..width {
                let i = r * width + x;
                let (c, a) = match &self.shown_alpha {
                    None => {
                        let c = self.mix.colour(0, src, i, x, y);
                        ([c[0], c[1], c[2]], 255.0)
                    }
                    Some(alphas) => self.shown(alphas, src, i, x, y),
                };
                data.extend(c.iter().map(|&v| v.round().clamp(0.0, 255.0) as u8));
                data.push(a.round().clamp(0.0, 255.0) as u8);
            }
        }
        data
    }
}

/// Strips of `KEEP_ROWS` rows that a banded output's `Keep` is counted over, each fused
/// with `KEEP_HALO` rows on either side (a change fades 0.44 a row, so 8 rows away it is
/// 0.0014 of its step, far under the map's 1/64 steps): each worker fuses 128 rows once
/// more, a quarter of its colour step's rows at 1024 x 1024 with two workers, half at
/// 512 x 512.
const KEEP_STRIPS: usize = 4;
const KEEP_ROWS: usize = 16;
const KEEP_HALO: usize = 8;

/// Fused colours as opaque RGBA bytes.
fn rgba(colours: impl Iterator<Item = [f32; 3]>) -> Vec<u8> {
    colours
        .flat_map(|c| {
            let [r, g, b] = c.map(|v| v.round().clamp(0.0, 255.0) as u8);
            [r, g, b, 255]
        })
        .collect()
}
