//! PNG and JPEG in wasm, for Node and for pages that want bytes without a canvas.

use super::read::{self, type_name};
use super::rgba::{rgba_from_js, rgba_to_js};
use super::{error, js_error};
use crate::raster;
use wasm_bindgen::prelude::*;

/// Largest encoded image accepted: an uncompressed PNG at the 4096 x 4096 side limit
/// is 64 MB.
const MAX_ENCODED_BYTES: u32 = 96 << 20;

/// Decodes PNG or JPEG bytes to RGBA.
#[wasm_bindgen(js_name = decodeImage)]
pub fn decode_image(bytes: JsValue) -> Result<JsValue, JsValue> {
    if read::detached(&bytes) {
        return Err(read::detached_error("image file"));
    }
    let array = if let Some(a) = read::view::<js_sys::Uint8Array>(&bytes) {
        a.clone()
    } else if let Some(b) = read::buffer(&bytes) {
        js_sys::Uint8Array::new(&b)
    } else {
        let posing = bytes.is_instance_of::<js_sys::Uint8Array>() || bytes.is_instance_of::<js_sys::ArrayBuffer>();
        return Err(error(&format!(
            "decodeImage needs the file's bytes as a Uint8Array or ArrayBuffer, got {}{}.",
            type_name(&bytes),
            if posing { " that only inherits from one (a Proxy?): pass the bytes themselves" } else { "" }
        )));
    };
    if array.length() > MAX_ENCODED_BYTES {
        return Err(error(&format!(
            "The image file is {}; the limit is {}.",
            crate::error::megabytes(array.length() as u64),
            crate::error::megabytes(MAX_ENCODED_BYTES as u64)
        )));
    }
    let d = raster::codec::decode_image(&array.to_vec()).map_err(js_error)?;
    Ok(rgba_to_js(d.width, d.height, &d.data))
}

/// Encodes RGBA as PNG.
#[wasm_bindgen(js_name = encodePng)]
pub fn encode_png(image: JsValue) -> Result<Vec<u8>, JsValue> {
    let (w, h, bytes) = rgba_from_js(&image, "image")?;
    raster::codec::encode_png(w, h, &bytes).map_err(js_error)
}
