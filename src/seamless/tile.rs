//! The seamless-tile entry point (SPEC 3): prepare the exemplar (`prepare`: the image's
//! square at the tile's side for E-TFMCM, the whole image at its own scale for
//! synthesis), then either E-TFMCM (the paper: grey generation on the channel with the
//! lowest max count difference, then colourisation) or our own method, toroidal
//! Wei-Levoy synthesis (engine 2 with `tileable`), which keeps structure as well as the
//! histogram. Every tile comes with its restoration rate and seam score.
//!
//! Beyond the paper: by default (`refine`) the E-TFMCM (or TFMCM) tile is refined by
//! toroidal synthesis that starts from a quilt following its layout, so the
//! co-occurrence field gives the arrangement of colours and the exemplar's
//! neighbourhoods give the detail. The paper's
//! tile, decided pixel by pixel, breaks bricks, shingles and letters into pixelated
//! pieces that repeat with the tile; over the ten fixture photographs (128, seeds 1-3,
//! `examples/tile_quality`) refining lowered its patch energy on every one (mean 9.11
//! -> 6.31; toroidal synthesis alone 6.11) and kept colours closer than synthesis alone
//! (colour distance 0.111 against 0.160; tissue 0.29 against 0.68).

use super::colourise::colourise;
use super::cooccurrence::Grey;
use super::density::{convert, max_count_difference};
use super::etfmcm::{generate, Decisions, Rule};
use super::measure::{restoration_rgb, seam_score};
use super::prepare::{self, Prepared};
use crate::error::{invalid, Result};
use crate::progress::{Progress, Throttle};
use crate::raster::image::over_white;
use crate::raster::{synthesize_texture, Image, Rgba, TextureOptions};
use serde::{Deserialize, Serialize};

#[derive(Clone, Copy, Debug, PartialEq, Eq, Deserialize, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Method {
    /// The paper's extended method.
    Etfmcm,
    /// The earlier TFMCM, for comparison.
    Tfmcm,
    /// Toroidal neighbourhood synthesis (ours), the default: it takes any width and
    /// height, and keeps structure (bricks) that E-TFMCM's layout breaks on small crops.
    /// Its coarsest level starts from a quilt of the photograph's windows laid round the
    /// torus, chosen to cover the photograph evenly (`synthesis::start::TILE_QUILT`). On
    /// the sixteen held-out photographs of `bench/heldout-data.sh` (128, seeds 1-8,
    /// `examples/tile_quality` with texture-synthesis 0.8.3 `--tiling` beside it) its
    /// tiles' patch energy is at or below the peer's on 16 (refined E-TFMCM: 15, and
    /// within 1.1x on 16), a median 0.88 of it (0.88); colours at most the peer's
    /// distance on 16 (16); repetition within 0.05 of the photograph's own on 16 (16);
    /// seams within 0.8-1.2 on 15 (16), brick's wrap 0.75 on the photograph's own
    /// 8-pixel grid, whose lines at that phase read 0.72 in the photograph itself
    /// (`examples/seam_lines`).
    Synthesis,
    /// The image kept, a band around its wrap re-made (`mend`).
    Mend,
}

#[derive(Clone, Debug, Deserialize)]
#[serde(rename_all = "camelCase", default, deny_unknown_fields)]
pub struct SeamlessOptions {
    pub method: Method,
    /// Side of the tile, a power of two from 8 to `MAX_TILE`. By default a synthesized
    /// tile is the image's own size (its exemplar's: `prepare::whole`), an E-TFMCM or
    /// TFMCM tile the largest power of two that fits the image.
    pub size: Option<usize>,
    /// Width and height of the tile, any from 8 to `MAX_SYNTHESIS_TILE` (toroidal
    /// synthesis only: E-TFMCM's fractal halves a square, power-of-two tile at each
    /// step); one alone makes a square tile. They take the place of `size`.
    pub width: Option<usize>,
    pub height: Option<usize>,
    pub seed: u64,
    /// T0 of the density conversion (the paper recommends at most 50 for 128 x 128).
    pub max_count_difference: f64,
    /// E-TFMCM and TFMCM: refine the co-occurrence tile with toroidal synthesis (see
    /// `refine`); `false` gives the paper's tile as it is.
    pub refine: bool,
    /// Mend: the re-made band's whole width as a share of each side (half along each
    /// edge); by default `mend::DEFAULT_BAND`.
    pub band: Option<f64>,
    /// Which pixels of the image may be copied (the JS `sampleMask`, read by the wasm
    /// layer; methods 'synthesis' and 'mend').
    #[serde(skip)]
    pub sample_mask: Option<Vec<bool>>,
    /// Synthesis and refined tiles: smooth the seams between the copied pieces
    /// (`synthesis::fusion`); `false` keeps every pixel one of the image's colours.
    pub fuse_seams: bool,
}

impl Default for SeamlessOptions {
    fn default() -> Self {
        SeamlessOptions {
            method: Method::Synthesis,
            size: None,
            width: None,
            height: None,
            seed: 1,
            max_count_difference: 50.0,
            refine: true,
            band: None,
            sample_mask: None,
            fuse_seams: true,
        }
    }
}

#[derive(Clone, Debug, Serialize)]
#[serde(rename_all = "camelCase")]
pub struct SeamlessResult {
    #[serde(skip)]
    pub image: Rgba,
    /// The tile's colour histograms against the image's, and its wrap against the
    /// lines beside it (`measure`); of an image with transparency, as it shows over
    /// white.
    pub restoration_rate: f64,
    pub seam_score: f64,
    /// What was done to the input: cropped square or scaled (and why), its transparency
    /// not read (E-TFMCM, TFMCM).
    pub warnings: Vec<String>,
    /// E-TFMCM: the channel generated (`"r"`, `"g"` or `"b"`), the max count difference
    /// before and after conversion, and how the points were decided.
    pub channel: Option<char>,
    pub count_difference: Option<(f64, f64)>,
    pub decisions: Option<Decisions>,
}

/// Largest tile side (E-TFMCM's indexes grow with the exemplar's pixel count).
pub const MAX_TILE: usize = 512;
/// Largest side of a tile made by toroidal synthesis with `width` and `height` (its
/// exemplar is at most `prepare::MAX_EXEMPLAR` on a side; the output's cost is linear in
/// its pixels).
pub const MAX_SYNTHESIS_TILE: usize = 4096;
const MIN_TILE: usize = prepare::MIN_SIDE;

/// A seamless tile from `input` (RGBA).
pub fn seamless_tile(input: &Rgba, opts: &SeamlessOptions, progress: &mut dyn Progress) -> Result<SeamlessResult> {
    if opts.method == Method::Mend {
        return mended(input, opts, progress);
    }
    if opts.band.is_some() {
        return invalid("`band` is an option of method 'mend' (the image kept, a band around its wrap re-made).");
    }
    if opts.sample_mask.is_some() && opts.method != Method::Synthesis {
        return invalid(
            "sampleMask applies to methods 'synthesis' and 'mend' (E-TFMCM's statistics are of the whole image).",
        );
    }
    let mut warnings = Vec::new();
    // Synthesis makes a tile of any size from the whole image at its own scale; E-TFMCM's
    // tile is its exemplar's size, so the image's square is scaled to it.
    let synthesis = opts.method == Method::Synthesis;
    let (width, height, Prepared { width: ex_width, height: ex_height, mut rgb, alpha }) = if synthesis {
        let ex = prepare::whole(input, &mut warnings)?;
        let (w, h) = tile_size(opts, input, Some((ex.width, ex.height)))?;
        if w > ex.width || h > ex.height {
            warnings.push(format!(
                "The tile is larger than the image: synthesized from the {}x{} image at its own scale.",
                ex.width, ex.height
            ));
        }
        (w, h, ex)
    } else {
        let (w, h) = tile_size(opts, input, None)?;
        let why = if input.width.min(input.height) > MAX_TILE {
            format!("tiles are a power of two on a side, at most {MAX_TILE}")
        } else {
            "tiles are a power of two on a side".to_string()
        };
        (w, h, prepare::square(input, w, &why, &mut warnings)?)
    };
    // (E-TFMCM's exemplar is a square of the tile's side.)
    let side = ex_width;
    let opaque = alpha.iter().all(|&a| a == 255);
    if !(synthesis || opaque) {
        // E-TFMCM's statistics are of colours: it is given the picture as it shows.
        rgb = rgb.iter().zip(&alpha).map(|(&c, &a)| over_white(c, a)).collect();
        warnings.push(
            "The image has transparency, which E-TFMCM and TFMCM do not read (their statistics are of colours): \
             the tile is made of the image as it shows over white, and is opaque. Method 'synthesis' keeps the \
             transparency."
                .to_string(),
        );
    }
    if !(opts.max_count_difference.is_finite() && opts.max_count_difference >= 0.0) {
        return invalid("maxCountDifference must be a number of at least 0.");
    }
    let refined = opts.refine && !synthesis;
    let (out, channel, count_difference, decisions) = match opts.method {
        Method::Synthesis => {
            let mut progress = Throttle::new(progress);
            let img =
                Image { width: ex_width, height: ex_height, data: rgb.iter().map(|p| p.map(|v| v as f32)).collect() };
            // The sample mask cropped and scaled as the image was: a pixel is kept out
            // where any pixel of its footprint was.
            let sample_masks = match &opts.sample_mask {
                None => Vec::new(),
                Some(m) => {
                    if m.len() != input.width * input.height {
                        return invalid("The sample mask is not of the image's size.");
                    }
                    let out: Vec<u8> = m.iter().flat_map(|&a| if a { [0, 0, 0, 255] } else { [255; 4] }).collect();
                    let out = Rgba { width: input.width, height: input.height, data: out };
                    let scaled = prepare::whole(&out, &mut Vec::new())?;
                    vec![Some(scaled.rgb.iter().map(|p| p[0] == 0).collect())]
                }
            };
            // Transparency travels with the pixels copied (line art on a clear ground
            // stays on a clear ground).
            let alphas = if opaque { Vec::new() } else { vec![Some(alpha.clone())] };
            let o = TextureOptions {
                width,
                height,
                seed: opts.seed,
                tileable: true,
                sample_masks,
                alphas,
                fuse_seams: opts.fuse_seams,
                ..Default::default()
            };
            let out = synthesize_texture(&img, &o, &mut |f| progress.tick(f).is_ok())?;
            (out, None, None, None)
        }
        Method::Mend => unreachable!("made by `mended`"),
        Method::Etfmcm | Method::Tfmcm => {
            let channels: Vec<Grey> =
                (0..3).map(|c| Grey { width: side, height: side, data: rgb.iter().map(|p| p[c]).collect() }).collect();
            let c = layout_channel(&channels);
            let conv = convert(&channels[c], opts.max_count_difference, opts.seed);
            let rule = if opts.method == Method::Etfmcm { Rule::Etfmcm } else { Rule::Tfmcm };
            let (grey, decisions) = {
                let mut progress = Throttle::with_range(progress, 0.0, if refined { 0.3 } else { 1.0 });
                generate(&conv.image, rule, opts.seed, &mut progress)?
            };
            // Colours are matched on the converted levels (finer than the original).
            let mut out = colourise(&grey, &conv.image, &rgb);
            if refined {
                let mut progress = Throttle::with_range(progress, 0.3, 1.0);
                out = refine(&out, &rgb, side, opts, &mut progress)?;
            }
            let data = out.iter().flat_map(|p| [p[0], p[1], p[2], 255]).collect();
            let out = Rgba { width: side, height: side, data };
            (out, Some(['r', 'g', 'b'][c]), Some((conv.before, conv.after)), Some(decisions))
        }
    };
    let mut progress = Throttle::new(progress);
    progress.tick(1.0)?;
    // With transparency, measured as the pixels show over white (E-TFMCM's were so
    // already).
    let (colours, rgb) = if opaque || !synthesis {
        (out.rgb(), rgb)
    } else {
        (out.rgb_over_white(), rgb.iter().zip(&alpha).map(|(&c, &a)| over_white(c, a)).collect())
    };
    let restoration_rate = restoration_rgb(&rgb, &colours);
    let seam_score = seam_score(&colours, out.width, out.height);
    Ok(SeamlessResult { image: out, restoration_rate, seam_score, warnings, channel, count_difference, decisions })
}

/// The channel E-TFMCM generates: the one whose histogram is least crowded (the
/// lowest max count difference, SPEC 3), among those that carry the picture's layout.
/// The paper is silent on a channel of one level, whose max count difference is 0 (its
/// one level's count less the mean of one): an orange fire, its blue all 0, was made
/// from its blue, and the tile came back one flat colour. So a channel counts only if
/// it has at least a quarter as many levels present as the richest channel (and more
/// than one, unless every channel has one).
fn layout_channel(channels: &[Grey]) -> usize {
    let hists: Vec<[u32; 256]> = channels.iter().map(Grey::histogram).collect();
    let levels: Vec<usize> = hists.iter().map(|h| h.iter().filter(|&&n| n > 0).count()).collect();
    let richest = levels.iter().copied().max().unwrap_or(0);
    (0..channels.len())
        .filter(|&c| 4 * levels[c] >= richest && (levels[c] > 1 || richest == 1))
        .min_by(|&a, &b| max_count_difference(&hists[a]).total_cmp(&max_count_difference(&hists[b])))
        .unwrap_or(0)
}

/// Method 'mend': the image itself, any size, a band around its wrap re-made.
fn mended(input: &Rgba, opts: &SeamlessOptions, progress: &mut dyn Progress) -> Result<SeamlessResult> {
    let (w, h) = (input.width, input.height);
    prepare::check(input)?;
    if opts.size.is_some() || opts.width.is_some() || opts.height.is_some() {
        return invalid("Method 'mend' keeps the image's own size: leave out `size`, `width` and `height`.");
    }
    let band = opts.band.unwrap_or(super::mend::DEFAULT_BAND);
    if opts.sample_mask.as_ref().is_some_and(|m| m.len() != w * h) {
        return invalid("The sample mask is not of the image's size.");
    }
    let image = super::mend::mend(input, band, opts.sample_mask.clone(), opts.seed, progress)?;
    // With transparency, measured as the pixels show over white.
    let shown = |i: &Rgba| if input.opaque() { i.rgb() } else { i.rgb_over_white() };
    let rgb = shown(&image);
    Ok(SeamlessResult {
        restoration_rate: restoration_rgb(&shown(input), &rgb),
        seam_score: seam_score(&rgb, w, h),
        image,
        warnings: Vec::new(),
        channel: None,
        count_difference: None,
        decisions: None,
    })
}

/// The co-occurrence tile `field` (side x side) refined by toroidal synthesis from the
/// exemplar `rgb`: the synthesis's coarsest level starts from a quilt of the exemplar's
/// windows laid round the torus after the field (each window chosen by its fit, by how
/// little of the exemplar under it is copied already, and by how near its light and
/// dark are to the field's where it is laid, the field's luminance matched rank for
/// rank to the exemplar's: `synthesis::start::FIELD_QUILT`), and its levels are then
/// made as for a synthesized tile, so the field gives the arrangement and the
/// exemplar's own neighbourhoods the detail. (A level too small to quilt starts from
/// the field's layout: each pixel the exemplar position whose neighbourhood best
/// matches the field's there. That was every tile's start until the quilt, and soft
/// exemplars repeated: fire and mist at 0.19 against their own 0.34 and 0.31.) This is
/// not in the paper: its tile is the field, colourised, whose pixel-by-pixel decisions break
/// structured exemplars into pixelated pieces that repeat with the tile.
fn refine(
    field: &[[u8; 3]],
    rgb: &[[u8; 3]],
    side: usize,
    opts: &SeamlessOptions,
    progress: &mut Throttle,
) -> Result<Vec<[u8; 3]>> {
    let image = |p: &[[u8; 3]]| Image { width: side, height: side, data: p.iter().map(|c| c.map(f32::from)).collect() };
    let o = TextureOptions {
        width: side,
        height: side,
        seed: opts.seed,
        tileable: true,
        start: Some(image(field)),
        fuse_seams: opts.fuse_seams,
        ..Default::default()
    };
    Ok(synthesize_texture(&image(rgb), &o, &mut |f| progress.tick(f).is_ok())?.rgb())
}

/// The tile's width and height from the options: `width`/`height` (synthesis only, any
/// size) or `size` (a power of two); by default the size of a synthesized tile's
/// `exemplar`, else the largest power of two the image allows, at most `MAX_TILE`.
fn tile_size(opts: &SeamlessOptions, input: &Rgba, exemplar: Option<(usize, usize)>) -> Result<(usize, usize)> {
    let short = input.width.min(input.height);
    match (opts.width.or(opts.height), opts.size) {
        (Some(_), Some(_)) => invalid("Give the tile's `size` or its `width` and `height`, not both."),
        (Some(one), None) => {
            if opts.method != Method::Synthesis {
                return invalid(
                    "E-TFMCM and TFMCM tiles are square, a power of two on a side (the fractal halves the tile at each step): give `size`, or method 'synthesis' for a tile of any width and height.",
                );
            }
            let (w, h) = (opts.width.unwrap_or(one), opts.height.unwrap_or(one));
            for (name, v) in [("width", w), ("height", h)] {
                if !(MIN_TILE..=MAX_SYNTHESIS_TILE).contains(&v) {
                    return invalid(format!(
                        "The tile's {name} must be from {MIN_TILE} to {MAX_SYNTHESIS_TILE} pixels (got {v})."
                    ));
                }
            }
            Ok((w, h))
        }
        (None, Some(s)) if !(s.is_power_of_two() && (MIN_TILE..=MAX_TILE).contains(&s)) => invalid(format!(
            "The tile size must be a power of two from {MIN_TILE} to {MAX_TILE} (got {s}); for any other size, pass `width` and `height` instead of `size` (method 'synthesis')."
        )),
        (None, Some(s)) => Ok((s, s)),
        (None, None) if let Some(size) = exemplar => Ok(size),
        (None, None) => {
            // `prepare` refuses images under MIN_TILE; `max(1)` keeps ilog2 defined first.
            let s = (1usize << short.max(1).ilog2()).min(MAX_TILE);
            Ok((s, s))
        }
    }
}
