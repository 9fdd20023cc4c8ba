//! Engines 2 and 3's entry points: texture synthesis, blends, seamless tiles.

use super::read::{self, options};
use super::rgba::{rgba_from_js, rgba_to_js};
use super::{error, js_error, to_js, JsProgress};
use crate::raster::{self, coefficient::Transfer, Coefficient, Image};
use crate::seamless;
use wasm_bindgen::prelude::*;

/// Reads `{ width, height, data }` (RGBA bytes) from JS into an engine image.
fn image_from_js(v: &JsValue, what: &str) -> Result<Image, JsValue> {
    let (w, h, bytes) = rgba_from_js(v, what)?;
    Image::from_rgba8(w, h, &bytes).map_err(js_error)
}

/// The options that carry the output size.
const SIZE: [&str; 2] = ["width", "height"];

/// More of one texture ("make more of this texture").
#[wasm_bindgen(js_name = synthesizeTexture)]
pub fn synthesize_texture(image: JsValue, opts: JsValue, on_progress: JsValue) -> Result<JsValue, JsValue> {
    let (ex, opts) = texture_args(image, opts)?;
    let mut progress = JsProgress::from_js(on_progress)?;
    let res = raster::synthesize_texture(&ex, &opts, &mut progress);
    let out = progress.finish(res)?;
    Ok(rgba_to_js(out.width, out.height, &out.data))
}

/// `synthesizeTexture`'s arguments read.
pub(super) fn texture_args(image: JsValue, opts: JsValue) -> Result<(Image, raster::TextureOptions), JsValue> {
    let ex = image_from_js(&image, "image")?;
    Ok((ex, options(&opts, "texture options", &[], &SIZE)?))
}

/// The blend options' own keys beside those of `TextureOptions` (read by hand:
/// `coefficient` may be a string or a Float32Array).
const BLEND_KEYS: [&str; 3] = ["coefficient", "angle", "transfer"];

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
    let a = image_from_js(&a, "first image (A)")?;
    let b = image_from_js(&b, "second image (B)")?;
    let base: raster::TextureOptions = options(&opts, "blend options", &BLEND_KEYS, &SIZE)?;
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
    let (width, height, data) = rgba_from_js(&image, "image")?;
    let opts: seamless::SeamlessOptions = options(&opts, "seamless tile options", &[], &[])?;
    let input = raster::Rgba { width, height, data };
    let mut progress = JsProgress::from_js(on_progress)?;
    let res = seamless::seamless_tile(&input, &opts, &mut progress);
    let res = progress.finish(res)?;
    let out = to_js(&res)?;
    let image = rgba_to_js(res.image.width, res.image.height, &res.image.data);
    let _ = js_sys::Reflect::set(&out, &JsValue::from_str("image"), &image);
    Ok(out)
}
