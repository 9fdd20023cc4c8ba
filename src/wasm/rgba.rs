//! RGBA images across the boundary: `{ width, height, data }` objects (an `ImageData`
//! or anything shaped like one) to sizes and bytes, and back.

use super::read::{self, type_name};
use super::{error, js_error};
use crate::raster;
use wasm_bindgen::prelude::*;

/// Reads `{ width, height, data }` as size and RGBA bytes; the data's length is checked
/// against the size before anything is copied.
pub fn rgba_from_js(v: &JsValue, what: &str) -> Result<(usize, usize, Vec<u8>), JsValue> {
    if !v.is_object() {
        return Err(error(&format!(
            "The {what} must be an object {{ width, height, data }} (e.g. an ImageData), got {}.",
            type_name(v)
        )));
    }
    let get = |k: &str| read::get(v, k, what);
    let dim = |k: &str| -> Result<usize, JsValue> {
        let n = get(k)?.as_f64().ok_or_else(|| error(&format!("The {what}'s {k} must be a number.")))?;
        if !(n.is_finite() && n >= 0.0 && n.fract() == 0.0 && n <= u32::MAX as f64) {
            return Err(error(&format!("The {what}'s {k} must be a whole number, got {n}.")));
        }
        Ok(n as usize)
    };
    let (w, h) = (dim("width")?, dim("height")?);
    raster::image::check_size(w, h, what).map_err(js_error)?;
    let data = get("data")?;
    if read::detached(&data) {
        return Err(read::detached_error(&format!("{what}'s data")));
    }
    let length = if let Some(a) = read::view::<js_sys::Uint8ClampedArray>(&data) {
        a.length()
    } else if let Some(a) = read::view::<js_sys::Uint8Array>(&data) {
        a.length()
    } else {
        return Err(error(&format!(
            "The {what}'s data must be a Uint8Array or Uint8ClampedArray of RGBA bytes, got {}.",
            type_name(&data)
        )));
    };
    if length as usize != w * h * 4 {
        return Err(error(&format!("The {what}'s data holds {length} bytes; {w} x {h} RGBA needs {}.", w * h * 4)));
    }
    let bytes = match read::view::<js_sys::Uint8ClampedArray>(&data) {
        Some(a) => a.to_vec(),
        None => data.unchecked_ref::<js_sys::Uint8Array>().to_vec(),
    };
    Ok((w, h, bytes))
}

pub fn rgba_to_js(width: usize, height: usize, data: &[u8]) -> JsValue {
    let o = js_sys::Object::new();
    let set = |k: &str, v: JsValue| {
        let _ = js_sys::Reflect::set(&o, &JsValue::from_str(k), &v);
    };
    set("width", JsValue::from_f64(width as f64));
    set("height", JsValue::from_f64(height as f64));
    set("data", js_sys::Uint8ClampedArray::from(data).into());
    o.into()
}
