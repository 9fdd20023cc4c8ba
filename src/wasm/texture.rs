//! Engines 2 and 3's entry points: texture synthesis, blends, seamless tiles.

use super::masks;
use super::read::{self, options};
use super::rgba::rgba_to_js;
use super::{error, js_error, to_js, JsProgress};
use crate::raster::{self, coefficient::Transfer, Coefficient, Image};
use crate::seamless;
use wasm_bindgen::prelude::*;

/// The options that carry the output size.
const SIZE: [&str; 2] = ["width", "height"];

/// The texture options read by hand beside `TextureOptions`' own (images: see `masks`).
const TEXTURE_KEYS: [&str; 2] = ["sampleMask", "guides"];

/// More of a texture, from one exemplar or several ("make more of this material").
/// With `keepLayout`, `{ image, layout }`.
#[wasm_bindgen(js_name = synthesizeTexture)]
pub fn synthesize_texture(image: JsValue, opts: JsValue, on_progress: JsValue) -> Result<JsValue, JsValue> {
    let (exemplars, opts) = texture_args(image, opts)?;
    let mut progress = JsProgress::from_js(on_progress)?;
    let res = raster::synthesize_textures(&exemplars, &opts, &mut progress);
    let out = progress.finish(res)?;
    let image = rgba_to_js(out.image.width, out.image.height, &out.image.data);
    match &out.layout {
        None => Ok(image),
        Some(layout) => {
            let o = js_sys::Object::new();
            js_sys::Reflect::set(&o, &"image".into(), &image)?;
            js_sys::Reflect::set(&o, &"layout".into(), &masks::layout_to_js(layout))?;
            Ok(o.into())
        }
    }
}

/// `synthesizeTexture`'s arguments read.
pub(super) fn texture_args(image: JsValue, opts: JsValue) -> Result<(Vec<Image>, raster::TextureOptions), JsValue> {
    let (exemplars, alphas) = masks::images(&image, "image")?;
    let mut o: raster::TextureOptions = options(&opts, "texture options", &TEXTURE_KEYS, &SIZE)?;
    o.alphas = alphas;
    if !(opts.is_undefined() || opts.is_null()) {
        let sizes: Vec<(usize, usize)> = exemplars.iter().map(|e| (e.width, e.height)).collect();
        o.sample_masks = masks::sample_masks(&read::get(&opts, "sampleMask", "texture options")?, &sizes)?;
        o.guides =
            masks::guides(&read::get(&opts, "guides", "texture options")?, exemplars.len(), (o.width, o.height))?;
    }
    Ok((exemplars, o))
}

/// The pixels of `image` where `mask` is opaque white filled from the rest of it; every
/// other pixel kept byte for byte.
#[wasm_bindgen(js_name = inpaintTexture)]
pub fn inpaint_texture(image: JsValue, mask: JsValue, opts: JsValue, on_progress: JsValue) -> Result<JsValue, JsValue> {
    let input = masks::rgba(&image, "image")?;
    let size = (input.width, input.height);
    let hole = masks::mask(&mask, "mask", size)?;
    let mut o: raster::InpaintOptions = options(&opts, "inpaint options", &["sampleMask"], &[])?;
    if !(opts.is_undefined() || opts.is_null()) {
        let m = read::get(&opts, "sampleMask", "inpaint options")?;
        o.sample_mask = masks::sample_masks(&m, &[size])?.pop().flatten();
    }
    let mut progress = JsProgress::from_js(on_progress)?;
    let res = raster::inpaint_texture(&input, &hole, &o, &mut progress);
    let out = progress.finish(res)?;
    Ok(rgba_to_js(out.width, out.height, &out.data))
}

/// An image of `target`'s size in `style`'s texture, following `target`'s light and dark.
#[wasm_bindgen(js_name = transferStyle)]
pub fn transfer_style(
    style: JsValue,
    target: JsValue,
    opts: JsValue,
    on_progress: JsValue,
) -> Result<JsValue, JsValue> {
    let (style, target, o) = style_args(style, target, opts)?;
    let mut progress = JsProgress::from_js(on_progress)?;
    let res = raster::transfer_style(&style, &target, &o, &mut progress);
    let out = progress.finish(res)?;
    Ok(rgba_to_js(out.width, out.height, &out.data))
}

/// `transferStyle`'s arguments read.
pub(super) fn style_args(
    style: JsValue,
    target: JsValue,
    opts: JsValue,
) -> Result<(Image, Image, raster::StyleOptions), JsValue> {
    let style = masks::image(&style, "style image")?;
    let target = masks::image(&target, "target image")?;
    let mut o: raster::StyleOptions = options(&opts, "style options", &["sampleMask"], &[])?;
    if !(opts.is_undefined() || opts.is_null()) {
        let m = read::get(&opts, "sampleMask", "style options")?;
        o.sample_mask = masks::sample_masks(&m, &[(style.width, style.height)])?.pop().flatten();
    }
    Ok((style, target, o))
}

/// Replays a synthesis's layout on other maps of its exemplars (normal, roughness,
/// height): one image per map.
#[wasm_bindgen(js_name = applyLayout)]
pub fn apply_layout(layout: JsValue, maps: JsValue) -> Result<JsValue, JsValue> {
    let layout = masks::layout_from_js(&layout)?;
    let maps = masks::maps(&maps, layout.exemplars.len())?;
    let out = raster::apply_layout(&layout, &maps).map_err(js_error)?;
    Ok(masks::images_to_js(&out))
}

/// The blend options' own keys beside those of `TextureOptions` (read by hand:
/// `coefficient` may be a string or a Float32Array).
const BLEND_KEYS: [&str; 4] = ["coefficient", "angle", "transfer", "sampleMask"];

fn transfer(name: &str) -> Result<Transfer, JsValue> {
    match name {
        "linear" => Ok(Transfer::Linear),
        "ease" => Ok(Transfer::Ease),
        "steep" => Ok(Transfer::Steep),
        other => Err(error(&format!("Unknown transition '{other}': use 'linear', 'ease' or 'steep'."))),
    }
}

/// Two textures blended by a generation coefficient (A where it is 1, B where it is 0).
#[wasm_bindgen(js_name = blendTextures)]
pub fn blend_textures(a: JsValue, b: JsValue, opts: JsValue, on_progress: JsValue) -> Result<JsValue, JsValue> {
    let (a, b, opts) = blend_args(a, b, opts)?;
    let mut progress = JsProgress::from_js(on_progress)?;
    let res = raster::blend_textures(&a, &b, &opts, &mut progress);
    let out = progress.finish(res)?;
    Ok(rgba_to_js(out.width, out.height, &out.data))
}

/// `blendTextures`'s arguments read.
pub(super) fn blend_args(
    a: JsValue,
    b: JsValue,
    opts: JsValue,
) -> Result<(Image, Image, raster::BlendOptions), JsValue> {
    let (a, alpha_a) = masks::image_and_alpha(&a, "first image (A)")?;
    let (b, alpha_b) = masks::image_and_alpha(&b, "second image (B)")?;
    let mut base: raster::TextureOptions = options(&opts, "blend options", &BLEND_KEYS, &SIZE)?;
    if alpha_a.is_some() || alpha_b.is_some() {
        base.alphas = vec![alpha_a, alpha_b];
    }
    if base.keep_layout {
        return Err(error("keepLayout applies to synthesizeTexture (a blend mixes two sources per pixel)."));
    }
    if !(opts.is_undefined() || opts.is_null()) {
        // (false asks for what a blend does anyway: one options object may serve all calls.)
        if read::get(&opts, "fuseSeams", "blend options")?.as_bool() == Some(true) {
            return Err(error(
                "fuseSeams applies to synthesizeTexture and seamlessTile: a blend mixes two sources per pixel and is not fused.",
            ));
        }
        let sizes = [(a.width, a.height), (b.width, b.height)];
        base.sample_masks = masks::sample_masks(&read::get(&opts, "sampleMask", "blend options")?, &sizes)?;
    }
    let key = |k: &str| read::get(&opts, k, "blend options");
    let (coefficient_js, angle_js, transfer_js) = (key("coefficient")?, key("angle")?, key("transfer")?);
    let angle = match angle_js.as_f64() {
        Some(a) if a.is_finite() => Some(a),
        None if angle_js.is_undefined() => None,
        _ => return Err(error("angle must be a finite number of degrees.")),
    };
    let t = match transfer_js.as_string() {
        Some(name) => transfer(&name)?,
        None if transfer_js.is_undefined() => Transfer::Linear,
        None => return Err(error("transfer must be 'linear', 'ease' or 'steep'.")),
    };
    let coefficient = if let Some(map) = coefficient_js.dyn_ref::<js_sys::Float32Array>() {
        if read::detached(map) {
            return Err(read::detached_error("coefficient map"));
        }
        Coefficient::Map(map.to_vec())
    } else if let Some(name) = coefficient_js.as_string() {
        match (name.as_str(), angle) {
            ("radial", _) => Coefficient::Radial(t),
            (n, Some(angle)) => Coefficient::Angle(angle, transfer(n)?),
            (n, None) => Coefficient::Vertical(transfer(n)?),
        }
    } else if coefficient_js.is_undefined() {
        Coefficient::Vertical(Transfer::Linear)
    } else {
        return Err(error("coefficient must be 'linear', 'ease', 'steep', 'radial' or a Float32Array."));
    };
    Ok((a, b, raster::BlendOptions { base, coefficient }))
}

/// A seamless tile (SPEC 3): E-TFMCM, TFMCM or toroidal synthesis.
#[wasm_bindgen(js_name = seamlessTile)]
pub fn seamless_tile(image: JsValue, opts: JsValue, on_progress: JsValue) -> Result<JsValue, JsValue> {
    let input = masks::rgba(&image, "image")?;
    let mut o: seamless::SeamlessOptions = options(&opts, "seamless tile options", &["sampleMask"], &[])?;
    if !(opts.is_undefined() || opts.is_null()) {
        let size = [(input.width, input.height)];
        let m = read::get(&opts, "sampleMask", "seamless tile options")?;
        o.sample_mask = masks::sample_masks(&m, &size)?.pop().flatten();
    }
    let opts = o;
    let mut progress = JsProgress::from_js(on_progress)?;
    let res = seamless::seamless_tile(&input, &opts, &mut progress);
    let res = progress.finish(res)?;
    let out = to_js(&res)?;
    let image = rgba_to_js(res.image.width, res.image.height, &res.image.data);
    let _ = js_sys::Reflect::set(&out, &JsValue::from_str("image"), &image);
    Ok(out)
}
