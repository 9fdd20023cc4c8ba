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
use serde::de::DeserializeOwned;
use serde::Serialize;
use wasm_bindgen::prelude::*;

#[cfg(feature = "texture")]
mod bands;
#[cfg(feature = "codec")]
mod codec;
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

/// Reads an options object: missing means defaults, a key set to `undefined` means that
/// option's default, and a misspelt option is an error (serde-wasm-bindgen reads only
/// the fields it knows, so unknown keys are checked here).
fn from_js<T: DeserializeOwned + Default>(v: JsValue, what: &str) -> Result<T, JsValue> {
    from_js_with(v, what, &[])
}

/// `from_js` where `extra` keys are read by the caller (not by serde).
fn from_js_with<T: DeserializeOwned + Default>(v: JsValue, what: &str, extra: &[&str]) -> Result<T, JsValue> {
    if v.is_undefined() || v.is_null() {
        return Ok(T::default());
    }
    if !v.is_object() || js_sys::Array::is_array(&v) {
        return Err(error(&format!("Invalid {what}: expected an object, got {}.", type_name(&v))));
    }
    let known = field_names::<T>();
    let object: &js_sys::Object = v.unchecked_ref();
    let defined = js_sys::Object::new();
    for key in js_sys::Object::keys(object).iter() {
        let Some(name) = key.as_string() else { continue };
        let value = js_sys::Reflect::get(object, &key).unwrap_or(JsValue::UNDEFINED);
        if value.is_undefined() {
            continue;
        }
        if !known.contains(&name.as_str()) && !extra.contains(&name.as_str()) {
            let msg = format!("Invalid {what}: unknown option `{name}` (expected one of {}).", known.join(", "));
            return Err(error(&msg));
        }
        if known.contains(&name.as_str()) {
            let _ = js_sys::Reflect::set(&defined, &key, &value);
        }
    }
    serde_wasm_bindgen::from_value(defined.into()).map_err(|e| error(&format!("Invalid {what}: {e}")))
}

/// A JS value's kind, for messages ("a number", "null", "an array"...).
fn type_name(v: &JsValue) -> String {
    if v.is_null() {
        "null".into()
    } else if js_sys::Array::is_array(v) {
        "an array".into()
    } else if let Some(name) = v.js_typeof().as_string() {
        match name.as_str() {
            "object" => {
                let ctor = js_sys::Reflect::get(v, &"constructor".into())
                    .ok()
                    .and_then(|c| js_sys::Reflect::get(&c, &"name".into()).ok())
                    .and_then(|n| n.as_string());
                match ctor {
                    Some(c) if c != "Object" => format!("a {c}"),
                    _ => "an object".into(),
                }
            }
            "undefined" => "undefined".into(),
            other => format!("a {other}"),
        }
    } else {
        "a value".into()
    }
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
                let message = thrown
                    .dyn_ref::<js_sys::Error>()
                    .map(|e| String::from(e.message()))
                    .or_else(|| thrown.as_string())
                    .unwrap_or_else(|| type_name(&thrown));
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
