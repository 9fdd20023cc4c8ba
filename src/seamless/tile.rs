//! The seamless-tile entry point (SPEC 3): prepare the exemplar (square, a power of two
//! on a side), then either E-TFMCM (the paper: grey generation on the channel with the
//! lowest max count difference, then colourisation) or our own method, toroidal
//! Wei-Levoy synthesis (engine 2 with `tileable`), which keeps structure as well as the
//! histogram. Every tile comes with its restoration rate and seam score.

use super::colourise::colourise;
use super::cooccurrence::Grey;
use super::density::{convert, max_count_difference};
use super::etfmcm::{generate, Decisions, Rule};
use super::measure::{restoration_rgb, seam_score};
use crate::error::{invalid, Result};
use crate::progress::{Progress, Throttle};
use crate::raster::{synthesize_texture, Image, Rgba, TextureOptions};
use serde::{Deserialize, Serialize};

#[derive(Clone, Copy, Debug, PartialEq, Eq, Deserialize, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Method {
    /// The paper's extended method.
    Etfmcm,
    /// The earlier TFMCM, for comparison.
    Tfmcm,
    /// Toroidal neighbourhood synthesis (ours).
    Synthesis,
}

#[derive(Clone, Debug, Deserialize)]
#[serde(rename_all = "camelCase", default, deny_unknown_fields)]
pub struct SeamlessOptions {
    pub method: Method,
    /// Side of the tile, a power of two from 8 to `MAX_TILE`; by default the largest
    /// that fits the image.
    pub size: Option<usize>,
    pub seed: u64,
    /// T0 of the density conversion (the paper recommends at most 50 for 128 x 128).
    pub max_count_difference: f64,
}

impl Default for SeamlessOptions {
    fn default() -> Self {
        SeamlessOptions { method: Method::Etfmcm, size: None, seed: 1, max_count_difference: 50.0 }
    }
}

#[derive(Clone, Debug, Serialize)]
#[serde(rename_all = "camelCase")]
pub struct SeamlessResult {
    #[serde(skip)]
    pub image: Rgba,
    pub restoration_rate: f64,
    pub seam_score: f64,
    /// What was done to the input to make it square and a power of two.
    pub warnings: Vec<String>,
    /// E-TFMCM: the channel generated (`"r"`, `"g"` or `"b"`), the max count difference
    /// before and after conversion, and how the points were decided.
    pub channel: Option<char>,
    pub count_difference: Option<(f64, f64)>,
    pub decisions: Option<Decisions>,
}

/// Largest tile side (E-TFMCM's indexes grow with the exemplar's pixel count).
pub const MAX_TILE: usize = 512;
const MIN_TILE: usize = 8;

/// A seamless tile from `input` (RGBA).
pub fn seamless_tile(input: &Rgba, opts: &SeamlessOptions, progress: &mut dyn Progress) -> Result<SeamlessResult> {
    let mut warnings = Vec::new();
    // Synthesis makes a tile of any size from the image at its own scale; E-TFMCM's
    // tile is its exemplar's size, so the image is scaled to it.
    let synthesis = opts.method == Method::Synthesis;
    let (ex_side, side, rgb) = prepare(input, opts.size, !synthesis, &mut warnings)?;
    if !(opts.max_count_difference.is_finite() && opts.max_count_difference >= 0.0) {
        return invalid("maxCountDifference must be a number of at least 0.");
    }
    let mut progress = Throttle::new(progress);
    let (out, channel, count_difference, decisions) = match opts.method {
        Method::Synthesis => {
            let img =
                Image { width: ex_side, height: ex_side, data: rgb.iter().map(|p| p.map(|v| v as f32)).collect() };
            let o = TextureOptions { width: side, height: side, seed: opts.seed, tileable: true, ..Default::default() };
            let out = synthesize_texture(&img, &o, &mut |f| progress.tick(f).is_ok())?;
            (out.rgb(), None, None, None)
        }
        Method::Etfmcm | Method::Tfmcm => {
            // The channel whose histogram is least crowded.
            let channels: Vec<Grey> =
                (0..3).map(|c| Grey { width: side, height: side, data: rgb.iter().map(|p| p[c]).collect() }).collect();
            let c = (0..3)
                .min_by(|&a, &b| {
                    max_count_difference(&channels[a].histogram())
                        .total_cmp(&max_count_difference(&channels[b].histogram()))
                })
                .unwrap();
            let conv = convert(&channels[c], opts.max_count_difference, opts.seed);
            let rule = if opts.method == Method::Etfmcm { Rule::Etfmcm } else { Rule::Tfmcm };
            let (grey, decisions) = generate(&conv.image, rule, opts.seed, &mut progress)?;
            // Colours are matched on the converted levels (finer than the original).
            let out = colourise(&grey, &conv.image, &rgb);
            (out, Some(['r', 'g', 'b'][c]), Some((conv.before, conv.after)), Some(decisions))
        }
    };
    progress.tick(1.0)?;
    let restoration_rate = restoration_rgb(&rgb, &out);
    let seam_score = seam_score(&out, side, side);
    let data = out.iter().flat_map(|p| [p[0], p[1], p[2], 255]).collect();
    Ok(SeamlessResult {
        image: Rgba { width: side, height: side, data },
        restoration_rate,
        seam_score,
        warnings,
        channel,
        count_difference,
        decisions,
    })
}

/// Crops `input` to a centred square and scales it to the tile's power-of-two side,
/// saying so; without `enlarge`, a tile larger than the image keeps the image at its
/// own size. Returns the exemplar's side, the tile's side and the exemplar.
fn prepare(
    input: &Rgba,
    size: Option<usize>,
    enlarge: bool,
    warnings: &mut Vec<String>,
) -> Result<(usize, usize, Vec<[u8; 3]>)> {
    let (w, h) = (input.width, input.height);
    crate::raster::image::check_size(w, h, "image")?;
    if input.data.len() != w * h * 4 {
        return invalid(format!("The image data has {} bytes; {w}x{h} RGBA needs {}.", input.data.len(), w * h * 4));
    }
    let short = w.min(h);
    if short < MIN_TILE {
        return invalid(format!("The image is {w}x{h}; a seamless tile needs at least {MIN_TILE} pixels on a side."));
    }
    let side = match size {
        Some(s) if !(s.is_power_of_two() && (MIN_TILE..=MAX_TILE).contains(&s)) => {
            return invalid(format!("The tile size must be a power of two from {MIN_TILE} to {MAX_TILE} (got {s})."));
        }
        Some(s) => s,
        None => (1usize << short.ilog2()).min(MAX_TILE),
    };
    let (x0, y0) = ((w - short) / 2, (h - short) / 2);
    if w != h {
        warnings.push(format!("Cropped the {w}x{h} image to its centre {short}x{short} (tiles are square)."));
    }
    let ex_side = if enlarge { side } else { side.min(short) };
    if ex_side < side {
        warnings
            .push(format!("The {side}x{side} tile is synthesized from the {short}x{short} image at its own scale."));
    }
    if short != ex_side {
        warnings.push(format!(
            "Scaled {short}x{short} to {ex_side}x{ex_side} (tiles are a power of two on a side{}).",
            if short > MAX_TILE { format!(", at most {MAX_TILE}") } else { String::new() }
        ));
    }
    // Box filter over each output pixel's footprint (bilinear-like when enlarging).
    let scale = short as f64 / ex_side as f64;
    let mut rgb = Vec::with_capacity(ex_side * ex_side);
    for y in 0..ex_side {
        for x in 0..ex_side {
            let (fx0, fy0) = (x as f64 * scale, y as f64 * scale);
            let (sx0, sy0) = (fx0.floor() as usize, fy0.floor() as usize);
            let sx1 = ((fx0 + scale).ceil() as usize).clamp(sx0 + 1, short);
            let sy1 = ((fy0 + scale).ceil() as usize).clamp(sy0 + 1, short);
            let mut acc = [0u32; 3];
            for sy in sy0..sy1 {
                for sx in sx0..sx1 {
                    let i = ((y0 + sy) * w + x0 + sx) * 4;
                    for (a, &v) in acc.iter_mut().zip(&input.data[i..i + 3]) {
                        *a += v as u32;
                    }
                }
            }
            let n = ((sx1 - sx0) * (sy1 - sy0)) as u32;
            rgb.push(acc.map(|v| ((v + n / 2) / n) as u8));
        }
    }
    Ok((ex_side, side, rgb))
}
