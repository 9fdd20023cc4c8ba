//! The texture engines' entry points: `synthesize_texture` (one exemplar, "more of this
//! texture") and `blend_textures` (two exemplars mixed by a generation coefficient).

use super::bands;
use super::coefficient::{self, Transfer};
use super::image::{Image, Rgba};
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
            start: self.start.clone(),
            ..Params::default()
        }
    }
}

/// More of one texture: a `width x height` image that looks like `exemplar`.
pub fn synthesize_texture(exemplar: &Image, opts: &TextureOptions, progress: &mut dyn Progress) -> Result<Rgba> {
    run(&texture_job(exemplar, opts)?, &mut Throttle::new(progress))
}

/// `synthesize_texture`'s work, prepared (for running its bands on several workers).
pub fn texture_job(exemplar: &Image, opts: &TextureOptions) -> Result<Job> {
    Job::new(Sources::One(exemplar), &opts.params())
}

/// Runs a job in the schedule its parameters ask for.
pub fn run(job: &Job, progress: &mut Throttle) -> Result<Rgba> {
    if job.params.banded() {
        bands::synthesize(job, progress)
    } else {
        synthesis::synthesize(job, progress)
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
    Job::new(Sources::Blend { a, b, mu }, &base.params())
}
