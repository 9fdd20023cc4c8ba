//! The JavaScript binding: converts JS values to engine types and back, and nothing
//! else. Errors become JS `Error`s with the engine's message; a panic (a bug) is logged
//! by the panic hook and surfaces as a trap, never as silent garbage.

use crate::error::Error;
use crate::progress::Progress;
use crate::raster::{self, coefficient::Transfer, Coefficient, Image};
use crate::seamless;
use crate::vector;
use serde::de::DeserializeOwned;
use serde::Serialize;
use wasm_bindgen::prelude::*;

#[wasm_bindgen(typescript_custom_section)]
const TS_TYPES: &'static str = r#"
export type Rgb = string;
export interface Stroke {
  points: [number, number][];
  width: number;
  stroke?: Rgb | null;
  fill?: Rgb | null;
  opacity?: number;
  strokeOpacity?: number;
  fillOpacity?: number;
  closed?: boolean;
  /** Compound paths kept whole: indices in `points` where a subpath starts. */
  breaks?: number[];
}
/** Return false to cancel. */
export type Progress = (fraction: number) => boolean | void;
export interface ParseSvgOptions { tolerance?: number; splitSubpaths?: boolean; maxPoints?: number }
export interface SvgImport { strokes: Stroke[]; warnings: string[]; width: number; height: number }
export interface Tolerances { path: number; width: number; color: number }
export interface Classification { classes: number[]; count: number; tolerances: Tolerances; proposed: Tolerances }
export interface ClassifyOptions { pathTolerance?: number; widthTolerance?: number; colorTolerance?: number }
export interface StrokeOptions extends ClassifyOptions {
  width: number; height: number; variation?: boolean; seed?: number; support?: number; maxElements?: number;
  /** Grow on the drawing's fitted lattice (default true): no drift on large outputs. */
  regularize?: boolean;
}
export interface Rgba { width: number; height: number; data: Uint8Array | Uint8ClampedArray }
export interface TextureOptions {
  width: number; height: number; seed?: number; tileable?: boolean; exhaustive?: boolean;
  levels?: number; neighbourhood?: number;
}
export type Transition = 'linear' | 'ease' | 'steep';
export interface BlendOptions extends TextureOptions {
  /** mu, the weight of A: 'linear' (1 at the top, 0 at the bottom, as in the paper), its
   *  'ease' and 'steep' transfers, 'radial' (A at the centre), or one value per pixel. */
  coefficient: Transition | 'radial' | Float32Array;
  /** Direction of the ramp in degrees (90 = top to bottom, 0 = left to right). */
  angle?: number;
  /** Transfer applied to 'radial' or an angled ramp. */
  transfer?: Transition;
}
export interface TileOptions extends ClassifyOptions {
  variation?: boolean; seed?: number;
  /** The tile spans this many smallest repeats across and down (1 to 8, default 1). */
  repeats?: number;
}
export interface TileResult {
  /** In tile coordinates; strokes cut by an edge appear again one period over. */
  strokes: Stroke[]; classes: number[]; width: number; height: number;
  /** The tile's exact lattice periods. */
  periods: [[number, number], [number, number]];
  sites: number; classification: Classification;
  /** width x height, repeats without seams as a CSS background. */
  svg: string;
}
export interface SeamlessOptions {
  /** 'etfmcm' (the paper, default), 'tfmcm' (its predecessor) or 'synthesis' (toroidal
   *  neighbourhood synthesis: keeps structure). */
  method?: 'etfmcm' | 'tfmcm' | 'synthesis';
  /** Tile side, a power of two from 8 to 512 (default: the largest the image allows). */
  size?: number; seed?: number;
  /** T0 of the density conversion (default 50). */
  maxCountDifference?: number;
}
export interface SeamlessResult {
  image: Rgba;
  /** The paper's restoration rate: 1 is the exemplar's colour histogram exactly. */
  restorationRate: number;
  /** Wrap-around difference over neighbouring-pixel difference: about 1 is seamless. */
  seamScore: number;
  /** What was done to make the input square and a power of two. */
  warnings: string[];
  channel: 'r' | 'g' | 'b' | null;
  countDifference: [number, number] | null;
  decisions: { byJ3: number[]; pairwise: number; mean: number } | null;
}
export interface StrokeResult {
  strokes: Stroke[]; classes: number[]; sources: number[]; classification: Classification; svg: string;
  growingPoints: number; skippedFull: number; passedOver: number;
}
"#;

#[wasm_bindgen(start)]
fn start() {
    console_error_panic_hook::set_once();
}

fn js_error(e: Error) -> JsValue {
    js_sys::Error::new(&e.to_string()).into()
}

/// Reads an options object: missing means defaults, and a misspelt option is an error
/// (serde-wasm-bindgen reads only the fields it knows, so unknown keys are checked here).
fn from_js<T: DeserializeOwned + Default>(v: JsValue, what: &str) -> Result<T, JsValue> {
    from_js_with(v, what, &[])
}

/// `from_js` where `extra` keys are read by the caller (not by serde).
fn from_js_with<T: DeserializeOwned + Default>(v: JsValue, what: &str, extra: &[&str]) -> Result<T, JsValue> {
    if v.is_undefined() || v.is_null() {
        return Ok(T::default());
    }
    if !v.is_object() {
        return Err(js_sys::Error::new(&format!("Invalid {what}: expected an object.")).into());
    }
    let known = field_names::<T>();
    let object: &js_sys::Object = v.unchecked_ref();
    for key in js_sys::Object::keys(object).iter().filter_map(|k| k.as_string()) {
        if !known.contains(&key.as_str()) && !extra.contains(&key.as_str()) {
            let msg = format!("Invalid {what}: unknown option `{key}` (expected one of {}).", known.join(", "));
            return Err(js_sys::Error::new(&msg).into());
        }
    }
    serde_wasm_bindgen::from_value(v).map_err(|e| js_sys::Error::new(&format!("Invalid {what}: {e}")).into())
}

/// The field names a struct deserializes, read by a deserializer that stops at the
/// first question serde asks it.
fn field_names<'de, T: serde::Deserialize<'de>>() -> &'static [&'static str] {
    use serde::de::{self, Visitor};
    struct Probe<'a>(&'a mut &'static [&'static str]);
    impl<'de> de::Deserializer<'de> for Probe<'_> {
        type Error = de::value::Error;
        fn deserialize_any<V: Visitor<'de>>(self, _: V) -> Result<V::Value, Self::Error> {
            Err(de::Error::custom("probe"))
        }
        fn deserialize_struct<V: Visitor<'de>>(
            self,
            _: &'static str,
            fields: &'static [&'static str],
            _: V,
        ) -> Result<V::Value, Self::Error> {
            *self.0 = fields;
            Err(de::Error::custom("probe"))
        }
        serde::forward_to_deserialize_any! {
            bool i8 i16 i32 i64 i128 u8 u16 u32 u64 u128 f32 f64 char str string bytes byte_buf option
            unit unit_struct newtype_struct seq tuple tuple_struct map enum identifier ignored_any
        }
    }
    let mut fields: &'static [&'static str] = &[];
    let _ = T::deserialize(Probe(&mut fields));
    fields
}

fn to_js<T: Serialize>(v: &T) -> Result<JsValue, JsValue> {
    v.serialize(&serde_wasm_bindgen::Serializer::json_compatible())
        .map_err(|e| js_sys::Error::new(&format!("Could not return the result: {e}")).into())
}

/// Calls the page's progress callback; `false` (or a throw) cancels.
struct JsProgress(Option<js_sys::Function>);

impl Progress for JsProgress {
    fn report(&mut self, fraction: f64) -> bool {
        match &self.0 {
            None => true,
            Some(f) => match f.call1(&JsValue::NULL, &JsValue::from_f64(fraction)) {
                Ok(v) => v != JsValue::FALSE,
                Err(_) => false,
            },
        }
    }
}

/// The crate version, to check which build a page loaded.
#[wasm_bindgen]
pub fn version() -> String {
    env!("CARGO_PKG_VERSION").to_string()
}

/// Reads an SVG document into strokes (one per subpath unless `splitSubpaths: false`).
#[wasm_bindgen(js_name = parseSvg, unchecked_return_type = "Stroke[]")]
pub fn parse_svg(
    svg: &str,
    #[wasm_bindgen(unchecked_param_type = "ParseSvgOptions")] opts: JsValue,
) -> Result<JsValue, JsValue> {
    let opts: vector::ImportOptions = from_js(opts, "SVG options")?;
    to_js(&vector::parse_svg(svg, &opts).map_err(js_error)?.strokes)
}

/// Like `parseSvg`, with the document size and warnings about what was left out.
#[wasm_bindgen(js_name = parseSvgReport, unchecked_return_type = "SvgImport")]
pub fn parse_svg_report(
    svg: &str,
    #[wasm_bindgen(unchecked_param_type = "ParseSvgOptions")] opts: JsValue,
) -> Result<JsValue, JsValue> {
    let opts: vector::ImportOptions = from_js(opts, "SVG options")?;
    to_js(&vector::parse_svg(svg, &opts).map_err(js_error)?)
}

fn strokes_from_js(v: JsValue) -> Result<Vec<vector::Stroke>, JsValue> {
    if !js_sys::Array::is_array(&v) {
        return Err(js_sys::Error::new("Strokes must be an array of { points, width, stroke, fill }.").into());
    }
    serde_wasm_bindgen::from_value(v).map_err(|e| js_sys::Error::new(&format!("Invalid stroke: {e}")).into())
}

#[derive(serde::Deserialize, Default)]
#[serde(rename_all = "camelCase", default, deny_unknown_fields)]
struct ClassifyOptions {
    path_tolerance: Option<f64>,
    width_tolerance: Option<f64>,
    color_tolerance: Option<f64>,
}

/// Classes of similar strokes, with the tolerances used and the automatic proposal.
#[wasm_bindgen(js_name = classifyStrokes, unchecked_return_type = "Classification")]
pub fn classify_strokes(
    #[wasm_bindgen(unchecked_param_type = "Stroke[]")] strokes: JsValue,
    #[wasm_bindgen(unchecked_param_type = "ClassifyOptions")] opts: JsValue,
) -> Result<JsValue, JsValue> {
    let strokes = strokes_from_js(strokes)?;
    let o: ClassifyOptions = from_js(opts, "classification options")?;
    to_js(
        &vector::classify_strokes(&strokes, o.path_tolerance, o.width_tolerance, o.color_tolerance)
            .map_err(js_error)?,
    )
}

#[derive(serde::Serialize)]
struct NamedExample {
    name: &'static str,
    strokes: Vec<vector::Stroke>,
}

/// Built-in example drawings (the families the engine is tested on), for a page to
/// start from.
#[wasm_bindgen(js_name = exampleStrokes, unchecked_return_type = "{ name: string; strokes: Stroke[] }[]")]
pub fn example_strokes() -> Result<JsValue, JsValue> {
    let list: Vec<NamedExample> = vector::exemplar::families(0.015, 7)
        .into_iter()
        .chain(std::iter::once(vector::exemplar::busy_tile(120, 100.0, 7.0, 3, 21)))
        .map(|e| NamedExample { name: e.name, strokes: e.strokes })
        .collect();
    to_js(&list)
}

/// Grows a `width x height` pattern from example strokes.
#[wasm_bindgen(js_name = synthesizeStrokes, unchecked_return_type = "StrokeResult")]
pub fn synthesize_strokes(
    #[wasm_bindgen(unchecked_param_type = "Stroke[]")] strokes: JsValue,
    #[wasm_bindgen(unchecked_param_type = "StrokeOptions")] opts: JsValue,
    #[wasm_bindgen(unchecked_param_type = "Progress")] on_progress: Option<js_sys::Function>,
) -> Result<JsValue, JsValue> {
    let strokes = strokes_from_js(strokes)?;
    let opts: vector::StrokeOptions = from_js(opts, "synthesis options")?;
    let res = vector::synthesize_strokes(&strokes, &opts, &mut JsProgress(on_progress)).map_err(js_error)?;
    to_js(&res)
}

/// Reads `{ width, height, data }` (RGBA bytes) from JS into an engine image.
fn image_from_js(v: &JsValue, what: &str) -> Result<Image, JsValue> {
    let (w, h, bytes) = rgba_from_js(v, what)?;
    Image::from_rgba8(w, h, &bytes).map_err(js_error)
}

/// Reads `{ width, height, data }` as size and RGBA bytes.
fn rgba_from_js(v: &JsValue, what: &str) -> Result<(usize, usize, Vec<u8>), JsValue> {
    let err = |m: String| -> JsValue { js_sys::Error::new(&m).into() };
    if !v.is_object() {
        return Err(err(format!("The {what} must be an object {{ width, height, data }} (e.g. an ImageData).")));
    }
    let get = |k: &str| js_sys::Reflect::get(v, &JsValue::from_str(k)).unwrap_or(JsValue::UNDEFINED);
    let dim = |k: &str| -> Result<usize, JsValue> {
        let n = get(k).as_f64().ok_or_else(|| err(format!("The {what}'s {k} must be a number.")))?;
        if !(n.is_finite() && n >= 0.0 && n.fract() == 0.0) {
            return Err(err(format!("The {what}'s {k} must be a whole number, got {n}.")));
        }
        Ok(n as usize)
    };
    let (w, h) = (dim("width")?, dim("height")?);
    let data = get("data");
    let bytes = if let Some(a) = data.dyn_ref::<js_sys::Uint8ClampedArray>() {
        a.to_vec()
    } else if let Some(a) = data.dyn_ref::<js_sys::Uint8Array>() {
        a.to_vec()
    } else {
        return Err(err(format!("The {what}'s data must be a Uint8Array or Uint8ClampedArray of RGBA bytes.")));
    };
    Ok((w, h, bytes))
}

fn rgba_to_js(width: usize, height: usize, data: &[u8]) -> JsValue {
    let o = js_sys::Object::new();
    let set = |k: &str, v: JsValue| {
        let _ = js_sys::Reflect::set(&o, &JsValue::from_str(k), &v);
    };
    set("width", JsValue::from_f64(width as f64));
    set("height", JsValue::from_f64(height as f64));
    set("data", js_sys::Uint8ClampedArray::from(data).into());
    o.into()
}

/// More of one texture ("make more of this texture").
#[wasm_bindgen(js_name = synthesizeTexture, unchecked_return_type = "Rgba")]
pub fn synthesize_texture(
    #[wasm_bindgen(unchecked_param_type = "Rgba")] image: JsValue,
    #[wasm_bindgen(unchecked_param_type = "TextureOptions")] opts: JsValue,
    #[wasm_bindgen(unchecked_param_type = "Progress")] on_progress: Option<js_sys::Function>,
) -> Result<JsValue, JsValue> {
    let ex = image_from_js(&image, "image")?;
    let opts: raster::TextureOptions = from_js(opts, "texture options")?;
    let out = raster::synthesize_texture(&ex, &opts, &mut JsProgress(on_progress)).map_err(js_error)?;
    Ok(rgba_to_js(out.width, out.height, &out.data))
}

/// The blend options' own keys beside those of `TextureOptions` (read by hand:
/// `coefficient` may be a string or a Float32Array).
const BLEND_KEYS: [&str; 3] = ["coefficient", "angle", "transfer"];

fn transfer(name: &str) -> Result<Transfer, JsValue> {
    match name {
        "linear" => Ok(Transfer::Linear),
        "ease" => Ok(Transfer::Ease),
        "steep" => Ok(Transfer::Steep),
        other => {
            Err(js_sys::Error::new(&format!("Unknown transition '{other}': use 'linear', 'ease' or 'steep'.")).into())
        }
    }
}

/// Two textures blended by a generation coefficient (A where it is 1, B where it is 0).
#[wasm_bindgen(js_name = blendTextures, unchecked_return_type = "Rgba")]
pub fn blend_textures(
    #[wasm_bindgen(unchecked_param_type = "Rgba")] a: JsValue,
    #[wasm_bindgen(unchecked_param_type = "Rgba")] b: JsValue,
    #[wasm_bindgen(unchecked_param_type = "BlendOptions")] opts: JsValue,
    #[wasm_bindgen(unchecked_param_type = "Progress")] on_progress: Option<js_sys::Function>,
) -> Result<JsValue, JsValue> {
    let a = image_from_js(&a, "first image (A)")?;
    let b = image_from_js(&b, "second image (B)")?;
    let key = |k: &str| {
        if opts.is_object() {
            js_sys::Reflect::get(&opts, &JsValue::from_str(k)).unwrap_or(JsValue::UNDEFINED)
        } else {
            JsValue::UNDEFINED
        }
    };
    let (coefficient_js, angle_js, transfer_js) = (key("coefficient"), key("angle"), key("transfer"));
    let base: raster::TextureOptions = from_js_with(opts, "blend options", &BLEND_KEYS)?;
    let angle = match angle_js.as_f64() {
        Some(a) => Some(a),
        None if angle_js.is_undefined() => None,
        None => return Err(js_sys::Error::new("angle must be a number of degrees.").into()),
    };
    let t = match transfer_js.as_string() {
        Some(name) => transfer(&name)?,
        None => Transfer::Linear,
    };
    let coefficient = if let Some(map) = coefficient_js.dyn_ref::<js_sys::Float32Array>() {
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
        return Err(
            js_sys::Error::new("coefficient must be 'linear', 'ease', 'steep', 'radial' or a Float32Array.").into()
        );
    };
    let opts = raster::BlendOptions { base, coefficient };
    let out = raster::blend_textures(&a, &b, &opts, &mut JsProgress(on_progress)).map_err(js_error)?;
    Ok(rgba_to_js(out.width, out.height, &out.data))
}

/// A seamless SVG tile of the strokes' repeat (SPEC 1.4): repeats as a CSS background.
#[wasm_bindgen(js_name = strokeTile, unchecked_return_type = "TileResult")]
pub fn stroke_tile(
    #[wasm_bindgen(unchecked_param_type = "Stroke[]")] strokes: JsValue,
    #[wasm_bindgen(unchecked_param_type = "TileOptions")] opts: JsValue,
) -> Result<JsValue, JsValue> {
    let strokes = strokes_from_js(strokes)?;
    let opts: vector::TileOptions = from_js(opts, "tile options")?;
    to_js(&vector::stroke_tile(&strokes, &opts).map_err(js_error)?)
}

/// A seamless tile (SPEC 3): E-TFMCM, TFMCM or toroidal synthesis.
#[wasm_bindgen(js_name = seamlessTile, unchecked_return_type = "SeamlessResult")]
pub fn seamless_tile(
    #[wasm_bindgen(unchecked_param_type = "Rgba")] image: JsValue,
    #[wasm_bindgen(unchecked_param_type = "SeamlessOptions")] opts: JsValue,
    #[wasm_bindgen(unchecked_param_type = "Progress")] on_progress: Option<js_sys::Function>,
) -> Result<JsValue, JsValue> {
    let (width, height, data) = rgba_from_js(&image, "image")?;
    let opts: seamless::SeamlessOptions = from_js(opts, "seamless tile options")?;
    let input = raster::Rgba { width, height, data };
    let res = seamless::seamless_tile(&input, &opts, &mut JsProgress(on_progress)).map_err(js_error)?;
    let out = to_js(&res)?;
    let image = rgba_to_js(res.image.width, res.image.height, &res.image.data);
    let _ = js_sys::Reflect::set(&out, &JsValue::from_str("image"), &image);
    Ok(out)
}

/// Decodes PNG or JPEG bytes to RGBA.
#[wasm_bindgen(js_name = decodeImage, unchecked_return_type = "Rgba")]
pub fn decode_image(bytes: &[u8]) -> Result<JsValue, JsValue> {
    let d = raster::codec::decode_image(bytes).map_err(js_error)?;
    Ok(rgba_to_js(d.width, d.height, &d.data))
}

/// Encodes RGBA as PNG.
#[wasm_bindgen(js_name = encodePng)]
pub fn encode_png(#[wasm_bindgen(unchecked_param_type = "Rgba")] image: JsValue) -> Result<Vec<u8>, JsValue> {
    let (w, h, bytes) = rgba_from_js(&image, "image")?;
    raster::codec::encode_png(w, h, &bytes).map_err(js_error)
}
