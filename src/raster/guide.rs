//! Guides: grey images that say where the output should be what (a path of stones,
//! moss thinning out, a letter's shape), compared beside the colours in every
//! neighbourhood (`synthesis::Guide`); and style transfer, whose guides are derived
//! from the two images (as Hertzmann et al.'s image analogies and texture-synthesis
//! do): the style image's luminance, and the target's luminance matched to the style's
//! mean and spread, both blurred a little, so that the output is the style's texture
//! laid out as the target's light and dark.

use super::image::{Image, Rgba};
use super::pyramid::{self, Edge};
use super::synthesis::Job;
use super::texture::{pool_job, run, Guides, TextureOptions};
use crate::error::{invalid, Result};
use crate::progress::{Progress, Throttle};
use serde::Deserialize;

/// The luminance (Rec. 601) of each pixel, in all three channels.
pub fn luminance(img: &Image) -> Image {
    let data = img.data.iter().map(|c| [luma(c); 3]).collect();
    Image { width: img.width, height: img.height, data }
}

/// The luminance (Rec. 601) of one colour (its first three channels).
pub fn luma(c: &[f32]) -> f32 {
    0.299 * c[0] + 0.587 * c[1] + 0.114 * c[2]
}

/// Options of `transfer_style`.
#[derive(Clone, Debug, Deserialize)]
#[serde(rename_all = "camelCase", default, deny_unknown_fields)]
pub struct StyleOptions {
    pub seed: u64,
    /// How much the target's layout counts against the style's texture (the guide's
    /// weight; see `synthesis::Guide`).
    pub weight: f32,
    pub levels: Option<usize>,
    pub neighbourhood: usize,
    /// The style's pixels never copied (a logo, a patch of sky), as `sampleMask` is for
    /// `synthesizeTexture` (read by hand at the wasm boundary: an image).
    #[serde(skip)]
    pub sample_mask: Option<Vec<bool>>,
}

impl Default for StyleOptions {
    fn default() -> Self {
        StyleOptions { seed: 1, weight: STYLE_WEIGHT, levels: None, neighbourhood: 5, sample_mask: None }
    }
}

/// The default weight of the target's layout in style transfer: one and a half times
/// the colours'. Measured against texture-synthesis 0.8.3 (`transfer-style`, its guide
/// alpha 0.8) on eight Debian photographs as styles and a photograph of the Eiffel
/// tower as the target (bench/peer-verbs.mjs, seeds 1-3, medians): the output's blurred
/// luminance followed the target's with a correlation of 0.88 at weight 1, 0.94 at 1.5,
/// 0.96 at 2 and 0.98 at 3, against the peer's 0.95; patch energy 5.05, 6.05, 6.60 and
/// 7.30 against the peer's 6.25. At 1 the tower was hardly to be seen on most of the
/// eight; at 1.5 it shows as the peer's does, with the texture kept closer. (Measured
/// with the coarsest level searched exhaustively; with the guided quilt that replaced
/// that search, `synthesis::start::GUIDED_QUILT`, the same run gives 0.93 and 5.95 in half the time.)
pub const STYLE_WEIGHT: f32 = 1.5;

/// The default weight of `guides` in `synthesizeTexture`: twice the colours'. Measured
/// against texture-synthesis 0.8.3 (its guide alpha 0.8, the default) on eight
/// photographs nobody on the project chose, a blurred-luminance guide and a disc as
/// the target, seeds 1-3 (medians of 24 runs): at weight 1 the output's luminance
/// followed the target with a correlation of 0.76 against the peer's 0.90, at 2 with
/// 0.90, at 3 with 0.92; patch energy 4.73, 5.42 and 6.01 against the peer's 6.27, and
/// ours at most the peer's in 24, 20 and 11 runs of 24. Two follows the guide as
/// closely as the peer does and keeps the texture closer to the photograph. (On eight
/// other photographs, with the guided quilt, `synthesis::start::GUIDED_QUILT`: 0.85 against the
/// peer's 0.84, patch energy 5.30 against 5.55.)
pub const GUIDE_WEIGHT: f32 = 2.0;

/// An image of `target`'s size in `style`'s texture, following `target`'s light and
/// dark.
pub fn transfer_style(style: &Image, target: &Image, opts: &StyleOptions, progress: &mut dyn Progress) -> Result<Rgba> {
    run(&style_job(style, target, opts)?, &mut Throttle::new(progress))
}

/// `transfer_style`'s work, prepared (for running its bands on several workers).
pub fn style_job(style: &Image, target: &Image, opts: &StyleOptions) -> Result<Job> {
    // (Said of the style image, not as "exemplar 1", which the person never named.)
    let side = opts.neighbourhood;
    if style.width < side || style.height < side {
        return invalid(format!(
            "The style image is {}x{}, smaller than the {side}x{side} neighbourhood.",
            style.width, style.height
        ));
    }
    let (ls, lt) = (soft(&luminance(style)), soft(&luminance(target)));
    let stats = |img: &Image| {
        let n = img.data.len() as f64;
        let mean = img.data.iter().map(|p| p[0] as f64).sum::<f64>() / n;
        let var = img.data.iter().map(|p| (p[0] as f64 - mean).powi(2)).sum::<f64>() / n;
        (mean, var.sqrt().max(1e-3))
    };
    let ((ms, ss), (mt, st)) = (stats(&ls), stats(&lt));
    let matched = Image {
        width: lt.width,
        height: lt.height,
        data: lt.data.iter().map(|p| [((p[0] as f64 - mt) * ss / st + ms) as f32; 3]).collect(),
    };
    let o = TextureOptions {
        width: target.width,
        height: target.height,
        seed: opts.seed,
        levels: opts.levels,
        neighbourhood: opts.neighbourhood,
        guides: Some(Guides { exemplars: vec![ls], target: matched, weight: opts.weight }),
        sample_masks: vec![opts.sample_mask.clone()],
        ..TextureOptions::default()
    };
    Ok(pool_job(std::slice::from_ref(style), &o)?.0)
}

/// The image blurred once by the pyramid's filter and brought back to its size: a
/// guide of the large shapes, not of every grain.
fn soft(img: &Image) -> Image {
    if img.width < 4 || img.height < 4 {
        return img.clone();
    }
    pyramid::upsample(&pyramid::downsample(img, Edge::Clamp), img.width, img.height)
}
