//! Engine 1's entry points: SVG import, classification, synthesis, seamless SVG tiles.

use super::read::{self, options};
use super::{error, js_error, to_js, type_name, JsProgress};
use crate::vector;
use wasm_bindgen::prelude::*;

/// Reads an SVG document into strokes (one per subpath unless `splitSubpaths: false`).
#[wasm_bindgen(js_name = parseSvg)]
pub fn parse_svg(svg: JsValue, opts: JsValue) -> Result<JsValue, JsValue> {
    to_js(&import(svg, opts)?.strokes)
}

/// Like `parseSvg`, with the document size and warnings about what was left out.
#[wasm_bindgen(js_name = parseSvgReport)]
pub fn parse_svg_report(svg: JsValue, opts: JsValue) -> Result<JsValue, JsValue> {
    to_js(&import(svg, opts)?)
}

fn import(svg: JsValue, opts: JsValue) -> Result<vector::Import, JsValue> {
    let text = string_from_js(&svg, "SVG (the document's text)")?;
    let opts: vector::ImportOptions = options(&opts, "SVG options", &[], &[])?;
    vector::parse_svg(&text, &opts).map_err(js_error)
}

/// Strokes that are all examples (classified, grouped, grown from), within the
/// engine's limits; refused before reading past them.
fn examples(v: &JsValue) -> Result<Vec<vector::Stroke>, JsValue> {
    read::strokes(v, vector::synthesize::MAX_EXAMPLE_STROKES, vector::synthesize::MAX_EXAMPLE_POINTS)
}

#[derive(serde::Deserialize, Default)]
#[serde(rename_all = "camelCase", default, deny_unknown_fields)]
struct ClassifyOptions {
    path_tolerance: Option<f64>,
    width_tolerance: Option<f64>,
    color_tolerance: Option<f64>,
}

/// Classes of similar strokes, with the tolerances used and the automatic proposal.
#[wasm_bindgen(js_name = classifyStrokes)]
pub fn classify_strokes(strokes: JsValue, opts: JsValue) -> Result<JsValue, JsValue> {
    let strokes = examples(&strokes)?;
    let o: ClassifyOptions = options(&opts, "classification options", &[], &[])?;
    to_js(
        &vector::classify_strokes(&strokes, o.path_tolerance, o.width_tolerance, o.color_tolerance)
            .map_err(js_error)?,
    )
}

/// Grows a `width x height` pattern from example strokes.
#[wasm_bindgen(js_name = synthesizeStrokes)]
pub fn synthesize_strokes(strokes: JsValue, opts: JsValue, on_progress: JsValue) -> Result<JsValue, JsValue> {
    let strokes = examples(&strokes)?;
    let opts: vector::StrokeOptions = options(&opts, "synthesis options", &[], &["width", "height"])?;
    let mut progress = JsProgress::from_js(on_progress)?;
    let res = vector::synthesize_strokes(&strokes, &opts, &mut progress);
    to_js(&progress.finish(res)?)
}

/// The next strokes of the repetition in a drawing (autocomplete): ghost strokes with a
/// confidence each, or none with the reason.
#[wasm_bindgen(js_name = suggestStrokes)]
pub fn suggest_strokes(strokes: JsValue, opts: JsValue) -> Result<JsValue, JsValue> {
    // A drawing may hold more than the examples' limit: only its last strokes are read
    // for the repetition.
    let strokes =
        read::latest_strokes(&strokes, vector::suggest::MAX_STROKES, read::MAX_INPUT_STROKES, read::MAX_INPUT_POINTS)?;
    let opts: vector::SuggestOptions = options(&opts, "suggestion options", &[], &[])?;
    to_js(&vector::suggest_strokes(&strokes, &opts).map_err(js_error)?)
}

/// A seamless SVG tile of the strokes' repeat (SPEC 1.4): repeats as a CSS background.
#[wasm_bindgen(js_name = strokeTile)]
pub fn stroke_tile(strokes: JsValue, opts: JsValue) -> Result<JsValue, JsValue> {
    let strokes = examples(&strokes)?;
    let opts: vector::TileOptions = options(&opts, "tile options", &[], &[])?;
    to_js(&vector::stroke_tile(&strokes, &opts).map_err(js_error)?)
}

/// A string argument, or an error naming it.
fn string_from_js(v: &JsValue, what: &str) -> Result<String, JsValue> {
    v.as_string().ok_or_else(|| error(&format!("The {what} must be a string, got {}.", type_name(v))))
}
