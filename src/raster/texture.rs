//! The texture engines' entry points: `synthesize_texture` (one exemplar, "more of this
//! texture") and `blend_textures` (two exemplars mixed by a generation coefficient).

use super::bands;
use super::coefficient::{self, Transfer};
use super::image::{Image, Rgba};
use super::pool::{self, Layout, Pool};
use super::synthesis::{self, Job, Params, Schedule, Sources};
use crate::error::{invalid, Result};
use crate::progress::{Progress, Throttle};
use serde::Deserialize;

/// Options of `synthesize_texture`.
#[derive(Clone, Debug, Deserialize)]
#[serde(rename_all = "camelCase", default, deny_unknown_fields)]
pub struct TextureOptions {
    pub width: usize,
    pub height: usize,
    pub seed: u64,
    pub tileable: bool,
    pub exhaustive: bool,
    pub levels: Option<usize>,
    pub neighbourhood: usize,
    pub schedule: Schedule,
    /// A picture of the output's size whose layout the synthesis starts from (the
    /// seamless tile's refined E-TFMCM; not an option of the JS API).
    #[serde(skip)]
    pub start: Option<Image>,
    /// Per exemplar, which of its pixels may be copied (the JS `sampleMask`, read by
    /// the wasm layer: a mask image is opaque white where a pixel is kept out).
    #[serde(skip)]
    pub sample_masks: Vec<Option<Vec<bool>>>,
    /// A guide (the JS `guides`, read by the wasm layer), one exemplar guide per
    /// exemplar.
    #[serde(skip)]
    pub guides: Option<Guides>,
    /// Return the layout too (`Synthesis::layout`).
    pub keep_layout: bool,
    /// Per exemplar (a blend's A and B), its alpha (one value per pixel) where any
    /// exemplar is not opaque everywhere (read by the wasm layer from RGBA): the output
    /// keeps the alpha of the pixels it copies (a blend mixes them), and where alpha
    /// varies candidates are compared by it too (`synthesis::opacity`). Empty: opaque.
    #[serde(skip)]
    pub alphas: Vec<Option<Vec<u8>>>,
    /// Smooth the seams between copied pieces (`synthesis::Params::fuse_seams`); never
    /// with `keep_layout`, whose layout replays the image exactly.
    pub fuse_seams: bool,
}

/// Guide images: grey values (luminance) of each exemplar's and of the output's size,
/// and the weight of their difference against the colours' (see `synthesis::Guide`).
#[derive(Clone, Debug)]
pub struct Guides {
    pub exemplars: Vec<Image>,
    pub target: Image,
    pub weight: f32,
}

/// What a synthesis gives: the image and, when asked, its layout.
pub struct Synthesis {
    pub image: Rgba,
    pub layout: Option<Layout>,
}

impl Default for TextureOptions {
    fn default() -> Self {
        let p = Params::default();
        TextureOptions {
            width: p.width,
            height: p.height,
            seed: p.seed,
            tileable: false,
            exhaustive: false,
            levels: None,
            neighbourhood: p.neighbourhood,
            schedule: p.schedule,
            start: None,
            sample_masks: Vec::new(),
            guides: None,
            keep_layout: false,
            alphas: Vec::new(),
            fuse_seams: p.fuse_seams,
        }
    }
}

/// How the coefficient varies (the JS `coefficient` option, with `angle`/`transfer`).
#[derive(Clone, Debug, PartialEq)]
pub enum Coefficient {
    /// The paper's maps, top to bottom, with a transfer.
    Vertical(Transfer),
    /// Any direction (degrees; 90 = top to bottom) with a transfer.
    Angle(f64, Transfer),
    /// A at the centre, B at the corners.
    Radial(Transfer),
    /// One value in [0, 1] per output pixel.
    Map(Vec<f32>),
}

#[derive(Clone, Debug, Default)]
pub struct BlendOptions {
    /// Size, seed and search settings, as for one exemplar.
    pub base: TextureOptions,
    pub coefficient: Coefficient,
}

impl Default for Coefficient {
    fn default() -> Self {
        Coefficient::Vertical(Transfer::Linear)
    }
}

impl TextureOptions {
    fn params(&self) -> Params {
        Params {
            width: self.width,
            height: self.height,
            seed: self.seed,
            levels: self.levels,
            neighbourhood: self.neighbourhood,
            exhaustive: self.exhaustive,
            tileable: self.tileable,
            schedule: self.schedule,
            // A layout replays exactly (`apply_layout` on the exemplars gives the image).
            fuse_seams: self.fuse_seams && !self.keep_layout,
            start: self.start.clone(),
            constraints: synthesis::Constraints { allowed: self.sample_masks.clone(), ..Default::default() },
            ..Params::default()
        }
    }
}

/// More of one texture: a `width x height` image that looks like `exemplar`.
pub fn synthesize_texture(exemplar: &Image, opts: &TextureOptions, progress: &mut dyn Progress) -> Result<Rgba> {
    Ok(synthesize_textures(std::slice::from_ref(exemplar), opts, progress)?.image)
}

/// More of a material seen in one or several exemplars: each output pixel is drawn
/// from any of them (`pool`), by the options' sample masks and guide; with
/// `keep_layout`, also which exemplar pixel each output pixel came from.
pub fn synthesize_textures(
    exemplars: &[Image],
    opts: &TextureOptions,
    progress: &mut dyn Progress,
) -> Result<Synthesis> {
    let (job, pool) = pool_job(exemplars, opts)?;
    let src = sources(&job, &mut Throttle::new(progress))?;
    let layout = opts.keep_layout.then(|| Layout::new(&pool, opts.width, opts.height, &src[0]));
    Ok(Synthesis { image: job.colours(&src), layout })
}

/// `synthesize_texture`'s work, prepared (for running its bands on several workers).
pub fn texture_job(exemplar: &Image, opts: &TextureOptions) -> Result<Job> {
    Ok(pool_job(std::slice::from_ref(exemplar), opts)?.0)
}

/// `synthesize_textures`' work, prepared, and the pool its positions are in.
pub fn pool_job(exemplars: &[Image], opts: &TextureOptions) -> Result<(Job, Pool)> {
    if exemplars.is_empty() {
        return invalid("No exemplar given: pass an image, or an array of images.");
    }
    super::image::check_output(opts.width, opts.height)?;
    let mut params = opts.params();
    let pooled = exemplars.len() > 1;
    if pooled {
        for e in exemplars {
            super::image::check_size(e.width, e.height, "exemplar")?;
        }
        // The levels the exemplars themselves call for, which the gutters then fit.
        let refs: Vec<&Image> = exemplars.iter().collect();
        let side = opts.neighbourhood;
        params.levels = Some(opts.levels.unwrap_or_else(|| {
            let coarsest = synthesis::coarsest_side(opts.tileable, false);
            synthesis::default_levels(&refs, opts.width, opts.height, side, coarsest)
        }));
    }
    let gutter = pool::gutter(params.levels.unwrap_or(1), opts.neighbourhood);
    let pool = pool::pool(exemplars, &opts.sample_masks, gutter)?;
    params.constraints.allowed = vec![pool.allowed.clone()];
    params.constraints.alphas = vec![pooled_alpha(&pool, exemplars, &opts.alphas)?];
    if let Some(g) = &opts.guides {
        if g.exemplars.len() != exemplars.len() {
            return invalid(format!(
                "{} exemplar guides for {} exemplars: give one per exemplar, in their order.",
                g.exemplars.len(),
                exemplars.len()
            ));
        }
        for (i, (ge, e)) in g.exemplars.iter().zip(exemplars).enumerate() {
            if (ge.width, ge.height) != (e.width, e.height) {
                return invalid(format!(
                    "Exemplar guide {} is {}x{}; its exemplar is {}x{}.",
                    i + 1,
                    ge.width,
                    ge.height,
                    e.width,
                    e.height
                ));
            }
        }
        params.constraints.guide = Some(synthesis::Guide {
            exemplar: pool::pool(&g.exemplars, &[], gutter)?.image,
            target: g.target.clone(),
            weight: g.weight,
        });
    }
    let job = Job::new(Sources::One(&pool.image), &params)?;
    Ok((job, pool))
}

/// The exemplars' alphas (`TextureOptions::alphas`; a missing one opaque) laid out as
/// the pool lays their colours, or `None` when every exemplar is opaque.
fn pooled_alpha(pool: &Pool, exemplars: &[Image], alphas: &[Option<Vec<u8>>]) -> Result<Option<Vec<u8>>> {
    if alphas.iter().flatten().all(|a| a.iter().all(|&v| v == 255)) {
        return Ok(None);
    }
    if alphas.len() > exemplars.len() {
        return invalid(format!("{} alpha planes for {} exemplars.", alphas.len(), exemplars.len()));
    }
    for (i, (a, e)) in alphas.iter().zip(exemplars).enumerate() {
        if a.as_ref().is_some_and(|a| a.len() != e.width * e.height) {
            return invalid(format!("Alpha plane {} does not match its exemplar ({}x{}).", i + 1, e.width, e.height));
        }
    }
    let planes: Vec<Option<&[u8]>> = alphas.iter().map(|a| a.as_deref()).collect();
    Ok(Some(pool.lay_out(&planes, 255)))
}

/// Runs a job in the schedule its parameters ask for.
pub fn run(job: &Job, progress: &mut Throttle) -> Result<Rgba> {
    Ok(job.colours(&sources(job, progress)?))
}

/// A job's finest sources, in the schedule its parameters ask for.
pub fn sources(job: &Job, progress: &mut Throttle) -> Result<Vec<Vec<u32>>> {
    if job.params.banded() {
        bands::sources(job, progress)
    } else {
        synthesis::sources(job, progress)
    }
}

/// The coefficient map mu (weight of A) for these options.
pub fn coefficient_map(c: &Coefficient, width: usize, height: usize) -> Result<Vec<f32>> {
    use coefficient::Shape;
    match c {
        Coefficient::Vertical(t) => coefficient::map(&Shape::Directional { angle: 90.0 }, *t, width, height),
        Coefficient::Angle(a, t) => coefficient::map(&Shape::Directional { angle: *a }, *t, width, height),
        Coefficient::Radial(t) => coefficient::map(&Shape::Radial, *t, width, height),
        Coefficient::Map(m) => coefficient::map(&Shape::Map(m.clone()), Transfer::Linear, width, height),
    }
}

/// Two exemplars blended: each output pixel takes the best match in A and in B for the
/// same output neighbourhood and mixes them by mu(x, y) and 1 - mu(x, y).
pub fn blend_textures(a: &Image, b: &Image, opts: &BlendOptions, progress: &mut dyn Progress) -> Result<Rgba> {
    run(&blend_job(a, b, opts)?, &mut Throttle::new(progress))
}

/// `blend_textures`'s work, prepared.
pub fn blend_job(a: &Image, b: &Image, opts: &BlendOptions) -> Result<Job> {
    let base = &opts.base;
    super::image::check_output(base.width, base.height)?;
    let mu = coefficient_map(&opts.coefficient, base.width, base.height)?;
    if mu.is_empty() {
        return invalid("The output is empty.");
    }
    let mut params = base.params();
    params.constraints.alphas = base.alphas.clone();
    Job::new(Sources::Blend { a, b, mu }, &params)
}
