//! Masks, guides, image lists and layouts across the boundary (issue 30's verbs). A mask
//! is an RGBA image where opaque white means "this pixel is masked": a pixel is masked
//! when its alpha and its luminance are both at least half.

use super::read::{self, is_array, type_name};
use super::rgba::{rgba_from_js, rgba_to_js};
use super::{error, js_error};
use crate::raster::{self, Guides, Image, Layout, Rgba};
use wasm_bindgen::prelude::*;
use wasm_bindgen::JsCast;

/// Reads `{ width, height, data }` into an engine image.
pub fn image(v: &JsValue, what: &str) -> Result<Image, JsValue> {
    let (w, h, bytes) = rgba_from_js(v, what)?;
    Image::from_rgba8(w, h, &bytes).map_err(js_error)
}

/// Reads `{ width, height, data }` as RGBA.
pub fn rgba(v: &JsValue, what: &str) -> Result<Rgba, JsValue> {
    let (width, height, data) = rgba_from_js(v, what)?;
    Ok(Rgba { width, height, data })
}

/// Reads `{ width, height, data }` into an engine image and its alpha (`None` when it
/// is opaque everywhere).
pub fn image_and_alpha(v: &JsValue, what: &str) -> Result<(Image, Option<Vec<u8>>), JsValue> {
    let r = rgba(v, what)?;
    let image = Image::from_rgba8(r.width, r.height, &r.data).map_err(js_error)?;
    Ok((image, (!r.opaque()).then(|| r.alpha())))
}

/// Each image's alpha, or none when all are opaque (`TextureOptions::alphas`).
type Alphas = Vec<Option<Vec<u8>>>;

/// One image, or an array of them (`what` names them; items are numbered from 1), as
/// colours and, where any of them is not opaque everywhere, each one's alpha.
pub fn images(v: &JsValue, what: &str) -> Result<(Vec<Image>, Alphas), JsValue> {
    let read = if is_array(v, what)? {
        let a: &js_sys::Array = v.unchecked_ref();
        if a.length() == 0 {
            return Err(error(&format!("The {what} array is empty: pass at least one image.")));
        }
        if a.length() > 255 {
            return Err(error(&format!("The {what} array holds {} images; at most 255 are taken.", a.length())));
        }
        (0..a.length())
            .map(|i| image_and_alpha(&a.get(i), &format!("{what} {}", i + 1)))
            .collect::<Result<Vec<_>, _>>()?
    } else {
        vec![image_and_alpha(v, what)?]
    };
    let (images, alphas): (Vec<Image>, Alphas) = read.into_iter().unzip();
    Ok((images, if alphas.iter().all(Option::is_none) { Vec::new() } else { alphas }))
}

/// A mask image of `size`: `true` where masked (opaque white).
pub fn mask(v: &JsValue, what: &str, size: (usize, usize)) -> Result<Vec<bool>, JsValue> {
    let (w, h, bytes) = rgba_from_js(v, what)?;
    if (w, h) != size {
        return Err(error(&format!("The {what} is {w}x{h}; it must be {}x{} like its image.", size.0, size.1)));
    }
    Ok(bytes
        .chunks_exact(4)
        .map(|p| p[3] >= 128 && 299 * p[0] as u32 + 587 * p[1] as u32 + 114 * p[2] as u32 >= 128_000)
        .collect())
}

/// The `sampleMask` option for exemplars of `sizes`: one mask, or an array with one
/// per exemplar (`null` or `undefined` for none); as "may be copied" flags.
pub fn sample_masks(v: &JsValue, sizes: &[(usize, usize)]) -> Result<Vec<Option<Vec<bool>>>, JsValue> {
    if v.is_undefined() || v.is_null() {
        return Ok(Vec::new());
    }
    let items: Vec<JsValue> = if is_array(v, "sampleMask")? {
        let a: &js_sys::Array = v.unchecked_ref();
        if a.length() as usize != sizes.len() {
            return Err(error(&format!(
                "sampleMask holds {} masks for {} exemplars: give one per exemplar (null for none).",
                a.length(),
                sizes.len()
            )));
        }
        a.iter().collect()
    } else if sizes.len() == 1 {
        vec![v.clone()]
    } else {
        return Err(error(&format!(
            "With {} exemplars, sampleMask is an array of one mask per exemplar (null for none).",
            sizes.len()
        )));
    };
    items
        .iter()
        .zip(sizes)
        .enumerate()
        .map(|(i, (m, &size))| {
            if m.is_undefined() || m.is_null() {
                return Ok(None);
            }
            let what = if sizes.len() == 1 { "sampleMask".to_string() } else { format!("sampleMask {}", i + 1) };
            Ok(Some(mask(m, &what, size)?.into_iter().map(|masked| !masked).collect()))
        })
        .collect()
}

/// The `guides` option: `{ exemplar, target, weight }` (`exemplar` one image, or one per
/// exemplar), read as luminance.
pub fn guides(v: &JsValue, exemplars: usize, output: (usize, usize)) -> Result<Option<Guides>, JsValue> {
    if v.is_undefined() || v.is_null() {
        return Ok(None);
    }
    if !v.is_object() || is_array(v, "guides")? {
        return Err(error(&format!("guides must be an object {{ exemplar, target, weight }}, got {}.", type_name(v))));
    }
    let get = |k: &str| read::get(v, k, "guides");
    let (ex, _) = images(&get("exemplar")?, "exemplar guide")?;
    if ex.len() != exemplars {
        return Err(error(&format!("guides.exemplar holds {} images for {exemplars} exemplars.", ex.len())));
    }
    let target = image(&get("target")?, "target guide")?;
    if (target.width, target.height) != output {
        return Err(error(&format!(
            "The target guide is {}x{}; it must be the output's size, {}x{}.",
            target.width, target.height, output.0, output.1
        )));
    }
    let weight = match get("weight")? {
        w if w.is_undefined() => raster::guide::GUIDE_WEIGHT,
        w => match w.as_f64() {
            Some(x) if x.is_finite() && x >= 0.0 => x as f32,
            _ => return Err(error("guides.weight must be a number of at least 0.")),
        },
    };
    for k in super::read::own_keys(v, "guides")? {
        if !["exemplar", "target", "weight"].contains(&k.as_str()) {
            return Err(error(&format!("Unknown key `{k}` in guides (expected exemplar, target, weight).")));
        }
    }
    let grey = |i: &Image| raster::guide::luminance(i);
    Ok(Some(Guides { exemplars: ex.iter().map(grey).collect(), target: grey(&target), weight }))
}

/// A layout to JS: `{ width, height, exemplars: [[w, h], ...], data: Uint32Array }`.
pub fn layout_to_js(l: &Layout) -> JsValue {
    let o = js_sys::Object::new();
    let set = |k: &str, v: JsValue| {
        let _ = js_sys::Reflect::set(&o, &JsValue::from_str(k), &v);
    };
    set("width", JsValue::from_f64(l.width as f64));
    set("height", JsValue::from_f64(l.height as f64));
    let sizes = js_sys::Array::new();
    for &(w, h) in &l.exemplars {
        sizes.push(&js_sys::Array::of2(&JsValue::from_f64(w as f64), &JsValue::from_f64(h as f64)));
    }
    set("exemplars", sizes.into());
    set("data", js_sys::Uint32Array::from(&l.data[..]).into());
    o.into()
}

/// A layout from JS (as `layout_to_js` made it).
pub fn layout_from_js(v: &JsValue) -> Result<Layout, JsValue> {
    if !v.is_object() {
        return Err(error(&format!(
            "The layout must be the `layout` a synthesizeTexture call with keepLayout returned, got {}.",
            type_name(v)
        )));
    }
    let get = |k: &str| read::get(v, k, "layout");
    let whole = |k: &str| -> Result<usize, JsValue> {
        match get(k)?.as_f64() {
            Some(n) if n.is_finite() && n >= 0.0 && n.fract() == 0.0 && n <= 4096.0 => Ok(n as usize),
            _ => Err(error(&format!("The layout's {k} must be a whole number up to 4096."))),
        }
    };
    let (width, height) = (whole("width")?, whole("height")?);
    let data = get("data")?;
    let Some(data) = read::view::<js_sys::Uint32Array>(&data) else {
        return Err(error(&format!("The layout's data must be a Uint32Array, got {}.", type_name(&data))));
    };
    if read::detached(data) {
        return Err(read::detached_error("layout's data"));
    }
    let list = get("exemplars")?;
    if !is_array(&list, "layout exemplars")? {
        return Err(error("The layout's exemplars must be an array of [width, height]."));
    }
    let list: &js_sys::Array = list.unchecked_ref();
    let mut exemplars = Vec::new();
    for item in list.iter() {
        let pair: Option<(usize, usize)> = item.dyn_ref::<js_sys::Array>().and_then(|a| {
            let n = |i: u32| a.get(i).as_f64().filter(|v| v.fract() == 0.0 && *v >= 1.0 && *v <= 4096.0);
            Some((n(0)? as usize, n(1)? as usize))
        });
        exemplars.push(pair.ok_or_else(|| error("The layout's exemplars must be an array of [width, height]."))?);
    }
    let layout = Layout { width, height, exemplars, data: data.to_vec() };
    layout.check().map_err(js_error)?;
    Ok(layout)
}

/// `applyLayout`'s maps: an array with, per map, one image (one exemplar) or an array
/// of one image per exemplar.
pub fn maps(v: &JsValue, exemplars: usize) -> Result<Vec<Vec<Rgba>>, JsValue> {
    if !is_array(v, "maps")? {
        return Err(error(&format!(
            "maps must be an array of maps (each an image, or with several exemplars an array of one image per exemplar), got {}.",
            type_name(v)
        )));
    }
    let a: &js_sys::Array = v.unchecked_ref();
    let mut out = Vec::new();
    for (m, item) in a.iter().enumerate() {
        let what = format!("map {}", m + 1);
        if is_array(&item, &what)? {
            let list: &js_sys::Array = item.unchecked_ref();
            out.push(
                list.iter()
                    .enumerate()
                    .map(|(e, i)| rgba(&i, &format!("{what}, exemplar {}", e + 1)))
                    .collect::<Result<_, _>>()?,
            );
        } else if exemplars == 1 {
            out.push(vec![rgba(&item, &what)?]);
        } else {
            return Err(error(&format!(
                "{what} must be an array of {exemplars} images, one per exemplar, in their order."
            )));
        }
    }
    Ok(out)
}

/// Images to a JS array.
pub fn images_to_js(images: &[Rgba]) -> JsValue {
    let a = js_sys::Array::new();
    for i in images {
        a.push(&rgba_to_js(i.width, i.height, &i.data));
    }
    a.into()
}
