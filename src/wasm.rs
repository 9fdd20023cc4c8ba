//! The JavaScript binding: converts JS values to engine types and back, and nothing
//! else. Errors become JS `Error`s with the engine's message; a panic (a bug) is logged
//! by the panic hook and surfaces as a trap, never as silent garbage.

use crate::error::Error;
use crate::progress::Progress;
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

fn from_js<T: DeserializeOwned + Default>(v: JsValue, what: &str) -> Result<T, JsValue> {
    if v.is_undefined() || v.is_null() {
        return Ok(T::default());
    }
    serde_wasm_bindgen::from_value(v).map_err(|e| js_sys::Error::new(&format!("Invalid {what}: {e}")).into())
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
