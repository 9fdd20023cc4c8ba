//! The JavaScript binding: converts JS values to engine types and back, and nothing
//! else. Each argument's type and shape is checked first and answered with a JS `Error`
//! naming the argument; engine errors become `Error`s with the engine's message. A
//! panic (a bug) traps; the package's JS entry re-instantiates the module after one.
//!
//! The TypeScript types of the package live in `js/pkg/*.d.ts`, beside the table of
//! entry points (`js/pkg/api.js`) that the entries, the worker and the client share.

// A codec-only module uses none of the option and progress plumbing.
#![cfg_attr(not(any(feature = "vector", feature = "texture")), allow(dead_code))]

use crate::error::Error;
use crate::progress::Progress;
use read::type_name;
use serde::Serialize;
use wasm_bindgen::prelude::*;

#[cfg(feature = "texture")]
mod bands;
#[cfg(feature = "codec")]
mod codec;
mod heap;
#[cfg(feature = "texture")]
mod masks;
mod read;
#[cfg(any(feature = "texture", feature = "codec"))]
mod rgba;
#[cfg(feature = "texture")]
mod texture;
#[cfg(feature = "vector")]
mod vector;

#[wasm_bindgen(start)]
fn start() {
    console_error_panic_hook::set_once();
}

/// The crate version, to check which build a page loaded.
#[wasm_bindgen]
pub fn version() -> String {
    env!("CARGO_PKG_VERSION").to_string()
}

fn error(msg: &str) -> JsValue {
    js_sys::Error::new(msg).into()
}

fn js_error(e: Error) -> JsValue {
    error(&e.to_string())
}

fn to_js<T: Serialize>(v: &T) -> Result<JsValue, JsValue> {
    v.serialize(&serde_wasm_bindgen::Serializer::json_compatible())
        .map_err(|e| error(&format!("Could not return the result: {e}")))
}

/// Calls the page's progress callback; `false` cancels. A callback that throws also
/// stops the work, and its exception is what the call then throws (`finish`).
struct JsProgress {
    callback: Option<js_sys::Function>,
    thrown: Option<JsValue>,
}

impl JsProgress {
    /// `undefined` or `null` means no callback; anything else must be a function.
    fn from_js(v: JsValue) -> Result<Self, JsValue> {
        let callback = if v.is_undefined() || v.is_null() {
            None
        } else if let Some(f) = v.dyn_ref::<js_sys::Function>() {
            Some(f.clone())
        } else {
            return Err(error(&format!(
                "The progress callback must be a function (fraction) => boolean | void, got {}.",
                type_name(&v)
            )));
        };
        Ok(JsProgress { callback, thrown: None })
    }

    /// The engine's result, with a cancellation caused by a throwing callback replaced
    /// by the callback's own exception.
    fn finish<T>(self, result: crate::Result<T>) -> Result<T, JsValue> {
        match (result, self.thrown) {
            (Err(Error::Cancelled), Some(thrown)) => {
                let message = read::thrown(&thrown);
                let e = js_sys::Error::new(&format!("The progress callback threw: {message}"));
                let _ = js_sys::Reflect::set(&e, &"cause".into(), &thrown);
                Err(e.into())
            }
            (r, _) => r.map_err(js_error),
        }
    }
}

impl Progress for JsProgress {
    fn report(&mut self, fraction: f64) -> bool {
        match &self.callback {
            None => true,
            Some(f) => match f.call1(&JsValue::NULL, &JsValue::from_f64(fraction)) {
                Ok(v) => v != JsValue::FALSE,
                Err(e) => {
                    self.thrown = Some(e);
                    false
                }
            },
        }
    }
}
