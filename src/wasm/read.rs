//! Reading the page's values (options objects, strokes) without letting page code throw
//! through wasm.
//!
//! Reading a property can run page code: a getter, a Proxy trap. If that code throws
//! through a binding that does not catch, the exception unwinds the Rust frames below
//! it without running their destructors or restoring the shadow-stack pointer: the
//! instance leaks memory and externref slots, and after enough such calls its stack
//! runs into its data. So everything here reads through `catch` bindings
//! (`Reflect.get`, `Reflect.ownKeys`, `Array.isArray`) and turns a throw into an `Error`
//! that names what was being read. Lengths are checked before elements are read (a
//! Proxy may claim a billion), and serde-wasm-bindgen, whose reads do not catch, only
//! ever sees fresh plain objects made here.

use super::error;
#[cfg(feature = "vector")]
use crate::vector::Stroke;
use wasm_bindgen::prelude::*;

#[wasm_bindgen]
extern "C" {
    /// `Array.isArray`, which throws on a revoked Proxy.
    #[wasm_bindgen(catch, js_namespace = Array, js_name = isArray)]
    fn is_array_js(v: &JsValue) -> Result<bool, JsValue>;
    /// A `Uint8Array`, made only to try a buffer.
    #[cfg(any(feature = "texture", feature = "codec"))]
    #[wasm_bindgen(js_name = Uint8Array)]
    type ByteView;
    /// `new Uint8Array(buffer)`, which throws on a detached buffer.
    #[cfg(any(feature = "texture", feature = "codec"))]
    #[wasm_bindgen(catch, constructor, js_class = "Uint8Array")]
    fn new(buffer: &JsValue) -> Result<ByteView, JsValue>;
    /// `Reflect.get(target, key, receiver)`: a getter of `target` run on `receiver`.
    #[cfg(any(feature = "texture", feature = "codec"))]
    #[wasm_bindgen(catch, js_namespace = Reflect, js_name = get)]
    fn get_on(target: &JsValue, key: &JsValue, receiver: &JsValue) -> Result<JsValue, JsValue>;
    #[cfg(any(feature = "texture", feature = "codec"))]
    #[wasm_bindgen(thread_local_v2, js_namespace = ArrayBuffer, js_name = prototype)]
    static ARRAY_BUFFER_PROTOTYPE: JsValue;
}

/// The most strokes any call reads (synthesis outputs hold up to 2,000,000 elements).
#[cfg(feature = "vector")]
pub const MAX_INPUT_STROKES: usize = 2_000_000;
/// The most points any call reads from strokes (an output's limit, so outputs go back in).
#[cfg(feature = "vector")]
pub const MAX_INPUT_POINTS: usize = 20_000_000;
/// Elements copied from one options object, nested arrays included.
const MAX_OPTION_VALUES: usize = 100_000;
/// Nesting depth copied from one options object.
const MAX_OPTION_DEPTH: usize = 4;

/// What a thrown value says: an `Error`'s message, a string, or its kind.
pub fn thrown(e: &JsValue) -> String {
    e.dyn_ref::<js_sys::Error>()
        .map(|e| String::from(e.message()))
        .or_else(|| e.as_string())
        .unwrap_or_else(|| type_name(e))
}

/// `v[key]`; a throwing getter or trap becomes an error naming `key` and `what`.
pub fn get(v: &JsValue, key: &str, what: &str) -> Result<JsValue, JsValue> {
    get_key(v, &JsValue::from_str(key), key, what)
}

/// `get` with the key already a JS string (making one from Rust text decodes it).
fn get_key(v: &JsValue, key: &JsValue, name: &str, what: &str) -> Result<JsValue, JsValue> {
    js_sys::Reflect::get(v, key).map_err(|e| error(&format!("Reading `{name}` of the {what} threw: {}", thrown(&e))))
}

/// `v[i]`; `what` names element `i` for the message if reading it throws.
fn get_index(v: &JsValue, i: usize, what: impl FnOnce() -> String) -> Result<JsValue, JsValue> {
    js_sys::Reflect::get_u32(v, i as u32).map_err(|e| error(&format!("Reading {} threw: {}", what(), thrown(&e))))
}

/// `Array.isArray(v)` (true for a Proxy of an array).
pub fn is_array(v: &JsValue, what: &str) -> Result<bool, JsValue> {
    is_array_js(v).map_err(|e| error(&format!("Reading the {what} threw: {}", thrown(&e))))
}

/// An array-like's `length` (read before any element: a Proxy may claim a billion).
fn length(v: &JsValue, what: &str) -> Result<usize, JsValue> {
    let n = get(v, "length", what)?.as_f64().unwrap_or(f64::NAN);
    if !(n.is_finite() && n >= 0.0 && n.fract() == 0.0 && n <= u32::MAX as f64) {
        return Err(error(&format!("The {what} has no valid length.")));
    }
    Ok(n as usize)
}

/// Whether a typed array's (or an ArrayBuffer's) memory was transferred away.
/// `ArrayBuffer.prototype.detached` says so where it exists (Node 22, browsers since
/// 2024); elsewhere an empty buffer is tried as a view's buffer, which throws only
/// when it is detached.
#[cfg(any(feature = "texture", feature = "codec"))]
pub fn detached(v: &JsValue) -> bool {
    let buffer = if v.is_instance_of::<js_sys::ArrayBuffer>() {
        v.clone()
    } else if js_sys::ArrayBuffer::is_view(v) {
        js_sys::Reflect::get(v, &"buffer".into()).unwrap_or(JsValue::UNDEFINED)
    } else {
        return false;
    };
    match js_sys::Reflect::get(&buffer, &"detached".into()).map(|d| d.as_bool()) {
        Ok(Some(detached)) => detached,
        _ => {
            let empty = js_sys::Reflect::get(&buffer, &"byteLength".into()).is_ok_and(|n| n.as_f64() == Some(0.0));
            empty && ByteView::new(&buffer).is_err()
        }
    }
}

/// `v` as a typed array of kind `T` when it is one (a Proxy of one is not: its
/// `length` and elements throw when read through the typed array's own methods, which
/// do not catch; `ArrayBuffer.isView` looks at the value itself and runs no page code).
#[cfg(any(feature = "texture", feature = "codec", feature = "vector"))]
pub fn view<T: JsCast>(v: &JsValue) -> Option<&T> {
    if js_sys::ArrayBuffer::is_view(v) {
        v.dyn_ref::<T>()
    } else {
        None
    }
}

/// `v` as an ArrayBuffer when it is one: its `byteLength` getter, run on `v` itself,
/// throws (caught) for a Proxy of one or anything else that only inherits from it.
#[cfg(feature = "codec")]
pub fn buffer(v: &JsValue) -> Option<js_sys::ArrayBuffer> {
    if !v.is_instance_of::<js_sys::ArrayBuffer>() {
        return None;
    }
    ARRAY_BUFFER_PROTOTYPE.with(|p| get_on(p, &"byteLength".into(), v)).ok()?;
    Some(v.clone().unchecked_into())
}

/// The error for bytes whose buffer was transferred (to a worker, by postMessage).
#[cfg(any(feature = "texture", feature = "codec"))]
pub fn detached_error(what: &str) -> JsValue {
    error(&format!(
        "The {what}'s ArrayBuffer was detached: it was transferred (to a worker or by postMessage) and holds \
         nothing here now. Pass a copy (bytes.slice()) or the buffer the receiver sent back."
    ))
}

/// A JS value's kind, for messages ("a number", "null", "an array", "a Map"...).
pub fn type_name(v: &JsValue) -> String {
    if v.is_null() {
        return "null".into();
    }
    match v.js_typeof().as_string().as_deref() {
        Some("object") if is_array_js(v).unwrap_or(false) => "an array".into(),
        Some("object") => {
            let ctor = js_sys::Reflect::get(v, &"constructor".into())
                .ok()
                .and_then(|c| js_sys::Reflect::get(&c, &"name".into()).ok())
                .and_then(|n| n.as_string());
            match ctor {
                Some(c) if c != "Object" && !c.is_empty() => format!("a {c}"),
                _ => "an object".into(),
            }
        }
        Some("undefined") => "undefined".into(),
        Some(other) => format!("a {other}"),
        None => "a value".into(),
    }
}

/// Objects whose values are not properties (a Map's entries) or that are not options
/// at all: refused by name rather than read as an empty object.
fn not_options(v: &JsValue) -> Option<&'static str> {
    if v.is_instance_of::<js_sys::Map>() || v.is_instance_of::<js_sys::WeakMap>() {
        Some("its entries are not properties; Object.fromEntries(map) makes an options object of them")
    } else if v.is_instance_of::<js_sys::Set>() || v.is_instance_of::<js_sys::WeakSet>() {
        Some("a Set holds no named options")
    } else if v.is_instance_of::<js_sys::Promise>() {
        Some("await it first")
    } else if js_sys::ArrayBuffer::is_view(v) || v.is_instance_of::<js_sys::ArrayBuffer>() {
        Some("bytes are not options")
    } else if v.is_instance_of::<js_sys::Date>() || v.is_instance_of::<js_sys::RegExp>() {
        Some("it holds no named options")
    } else {
        None
    }
}

/// The field names a struct deserializes, read by a deserializer that stops at the
/// first question serde asks it.
pub fn field_names<'de, T: serde::Deserialize<'de>>() -> &'static [&'static str] {
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

/// A copy of `v` made of fresh arrays and plain objects (primitives and typed arrays
/// as they are), read through catching bindings, at most `budget` elements in all.
fn plain(v: &JsValue, what: &str, depth: usize, budget: &mut usize) -> Result<JsValue, JsValue> {
    if !v.is_object() || js_sys::ArrayBuffer::is_view(v) {
        return Ok(v.clone());
    }
    if depth >= MAX_OPTION_DEPTH {
        return Err(error(&format!("The {what} is nested too deeply.")));
    }
    if is_array(v, what)? {
        let n = length(v, what)?;
        *budget = budget.checked_sub(n).ok_or_else(|| error(&format!("The {what} holds too many values.")))?;
        let out = js_sys::Array::new_with_length(n as u32);
        for i in 0..n {
            let element = get_index(v, i, || format!("element {i} of the {what}"))?;
            out.set(i as u32, plain(&element, what, depth + 1, budget)?);
        }
        return Ok(out.into());
    }
    if let Some(why) = not_options(v) {
        return Err(error(&format!("The {what} is {}: {why}.", type_name(v))));
    }
    let out = js_sys::Object::new();
    for key in own_keys(v, what)? {
        *budget = budget.checked_sub(1).ok_or_else(|| error(&format!("The {what} holds too many values.")))?;
        let value = get(v, &key, what)?;
        js_sys::Reflect::set(&out, &JsValue::from_str(&key), &plain(&value, what, depth + 1, budget)?)?;
    }
    Ok(out.into())
}

/// An object's own string keys (`Reflect.ownKeys`, which a Proxy trap may make throw).
pub fn own_keys(v: &JsValue, what: &str) -> Result<Vec<String>, JsValue> {
    let keys = js_sys::Reflect::own_keys(v.unchecked_ref())
        .map_err(|e| error(&format!("Listing the {what}' keys threw: {}", thrown(&e))))?;
    Ok(keys.iter().filter_map(|k| k.as_string()).collect())
}

/// Reads an options object into `T`. Missing (`undefined` or `null`) means defaults
/// unless `required` keys are named; a key set to `undefined` means that option's
/// default; a misspelt key is an error. Options are read by name, so a class instance's
/// getters count; a Map, a Set or a Promise is refused by name instead of read as `{}`.
/// `extra`: keys the caller reads itself (with `get`).
pub fn options<T: serde::de::DeserializeOwned + Default>(
    v: &JsValue,
    what: &str,
    extra: &[&str],
    required: &[&str],
) -> Result<T, JsValue> {
    let missing = |given: &dyn Fn(&str) -> bool| -> Result<(), JsValue> {
        let absent: Vec<&str> = required.iter().copied().filter(|k| !given(k)).collect();
        if absent.is_empty() {
            return Ok(());
        }
        let example = required.iter().map(|k| format!("{k}: 512")).collect::<Vec<_>>().join(", ");
        Err(error(&format!(
            "Invalid {what}: {} {} required, e.g. {{ {example} }}.",
            absent.iter().map(|k| format!("`{k}`")).collect::<Vec<_>>().join(" and "),
            if absent.len() == 1 { "is" } else { "are" }
        )))
    };
    if v.is_undefined() || v.is_null() {
        missing(&|_| false)?;
        return Ok(T::default());
    }
    if !v.is_object() || is_array(v, what)? {
        return Err(error(&format!("Invalid {what}: expected an object, got {}.", type_name(v))));
    }
    if let Some(why) = not_options(v) {
        return Err(error(&format!("Invalid {what}: expected an object of options, got {}: {why}.", type_name(v))));
    }
    let known = field_names::<T>();
    for key in own_keys(v, what)? {
        if !known.contains(&key.as_str()) && !extra.contains(&key.as_str()) {
            let all: Vec<&str> = known.iter().chain(extra).copied().collect();
            let msg = format!("Invalid {what}: unknown option `{key}` (expected one of {}).", all.join(", "));
            return Err(error(&msg));
        }
    }
    let defined = js_sys::Object::new();
    let mut budget = MAX_OPTION_VALUES;
    for &key in known {
        let value = get(v, key, what)?;
        if !value.is_undefined() {
            let value = plain(&value, &format!("option `{key}`"), 0, &mut budget)?;
            js_sys::Reflect::set(&defined, &JsValue::from_str(key), &value)?;
        }
    }
    missing(&|k| js_sys::Reflect::has(&defined, &JsValue::from_str(k)).unwrap_or(false))?;
    serde_wasm_bindgen::from_value::<T>(defined.clone().into()).map_err(|e| {
        // serde names the expected type, not the option: try each alone to name it.
        let culprit = known.iter().find(|&&key| {
            let Ok(value) = js_sys::Reflect::get(&defined, &JsValue::from_str(key)) else { return false };
            if value.is_undefined() {
                return false;
            }
            let alone = js_sys::Object::new();
            js_sys::Reflect::set(&alone, &JsValue::from_str(key), &value).is_ok()
                && serde_wasm_bindgen::from_value::<T>(alone.into()).is_err()
        });
        let text = serde_words(&e);
        match culprit {
            Some(key) => error(&format!("Invalid {what}: option `{key}`: {text}.")),
            None => error(&format!("Invalid {what}: {text}.")),
        }
    })
}

/// serde-wasm-bindgen's error as a sentence for a person: without its "Error: "
/// prefix, the expected Rust type in words, and a JS object it could not read as "an
/// object" rather than its debug form (`JsValue(Object({}))`).
fn serde_words(e: &serde_wasm_bindgen::Error) -> String {
    let text = plain_types(&e.to_string());
    let text = text.strip_prefix("Error: ").unwrap_or(&text);
    let text = match (text.find("JsValue("), text.find(", expected")) {
        (Some(a), Some(b)) if a < b => format!("{}an object{}", &text[..a], &text[b..]),
        _ => text.to_string(),
    };
    given_words(&text)
}

/// serde's "invalid type: floating point `-1.0`, expected ..." as "got -1, expected
/// ...": the value the person wrote, as they wrote it (a JS number has no `.0`).
fn given_words(text: &str) -> String {
    let Some(rest) = text.strip_prefix("invalid type: ") else { return text.to_string() };
    let Some(comma) = rest.find(", expected") else { return text.to_string() };
    let (given, expected) = rest.split_at(comma);
    let given = match given.strip_prefix("floating point `").and_then(|g| g.strip_suffix('`')) {
        Some(number) => number.strip_suffix(".0").unwrap_or(number).to_string(),
        None if given.starts_with("string ") => format!("the {given}"),
        // (JS null reaches serde as the unit value.)
        None if given == "unit value" => "null".to_string(),
        None => given.to_string(),
    };
    format!("got {given}{expected}")
}

/// serde's message with the expected Rust type said in words ("expected f64" reads
/// "expected a number").
fn plain_types(text: &str) -> String {
    let words = [
        ("f64", "a number"),
        ("f32", "a number"),
        // (With its range where a JS number can pass it: counts are 32-bit in wasm.)
        ("u64", "a whole number from 0 to 9007199254740991"),
        ("u32", "a whole number from 0 to 4294967295"),
        ("usize", "a whole number from 0 to 4294967295"),
        ("i64", "a whole number"),
        ("i32", "a whole number from -2147483648 to 2147483647"),
        ("bool", "true or false"),
        ("a boolean", "true or false"),
    ];
    let mut out = text.to_string();
    for (rust, said) in words {
        out = out.replace(&format!("expected {rust}"), &format!("expected {said}"));
    }
    out
}

#[cfg(feature = "vector")]
/// Reads strokes: an array of `{ points: [[x, y]...], width, stroke, fill, ... }`, at
/// most `max_strokes` holding at most `max_points`, refused before reading past either.
pub fn strokes(v: &JsValue, max_strokes: usize, max_points: usize) -> Result<Vec<Stroke>, JsValue> {
    latest_strokes(v, usize::MAX, max_strokes, max_points)
}

/// `strokes`, reading every field of the `latest` last strokes only and just the points
/// of the ones before (their other fields take the defaults): a suggestion looks at
/// the earlier strokes of a long drawing only where they lie, and reading every field
/// of two million strokes through the boundary takes half a minute.
#[cfg(feature = "vector")]
pub fn latest_strokes(
    v: &JsValue,
    latest: usize,
    max_strokes: usize,
    max_points: usize,
) -> Result<Vec<Stroke>, JsValue> {
    if !v.is_object() || !is_array(v, "strokes")? {
        return Err(error(&format!(
            "Strokes must be an array of {{ points, width, stroke, fill }}, got {}.",
            type_name(v)
        )));
    }
    let n = length(v, "strokes array")?;
    if n > max_strokes {
        return Err(error(&format!("There are {n} strokes; the limit is {max_strokes}.")));
    }
    let whole_from = n.saturating_sub(latest);
    let fields: Vec<(&str, JsValue)> =
        field_names::<Stroke>().iter().filter(|&&f| f != "points").map(|&f| (f, JsValue::from_str(f))).collect();
    let points_key = JsValue::from_str("points");
    let mut budget = max_points;
    let mut out = Vec::with_capacity(n);
    for i in 0..n {
        let what = format!("stroke {i}");
        let s = get_index(v, i, || what.clone())?;
        if !s.is_object() || is_array(&s, "stroke")? {
            return Err(error(&format!(
                "Stroke {i} must be an object {{ points, width, stroke, fill }}, got {}.",
                type_name(&s)
            )));
        }
        let points = points(&get_key(&s, &points_key, "points", &what)?, i, &mut budget, max_points)?;
        if i < whole_from {
            out.push(Stroke::new(points, 0.0, None));
            continue;
        }
        let rest = js_sys::Object::new();
        let mut values = MAX_OPTION_VALUES;
        for (field, key) in &fields {
            let value = get_key(&s, key, field, &what)?;
            if !value.is_undefined() {
                js_sys::Reflect::set(&rest, key, &plain(&value, &what, 1, &mut values)?)?;
            }
        }
        let mut stroke: Stroke = serde_wasm_bindgen::from_value(rest.into())
            .map_err(|e| error(&format!("Invalid stroke {i}: {}", serde_words(&e))))?;
        stroke.points = points;
        out.push(stroke);
    }
    Ok(out)
}

#[cfg(feature = "vector")]
/// Stroke `i`'s points, `[x, y]` pairs of numbers, taken from the `budget` of points.
fn points(v: &JsValue, i: usize, budget: &mut usize, max_points: usize) -> Result<Vec<[f64; 2]>, JsValue> {
    let what = format!("points of stroke {i}");
    // x, y, x, y, ... as one typed array (what the package's JS passes: flat.js).
    if let Some(flat) = view::<js_sys::Float64Array>(v) {
        let len = flat.length() as usize;
        if len % 2 != 0 {
            return Err(error(&format!(
                "Stroke {i}'s points, a Float64Array, must hold x, y pairs: an even count of numbers, got {len}."
            )));
        }
        *budget = budget.checked_sub(len / 2).ok_or_else(|| {
            error(&format!(
                "The strokes hold more than {max_points} points (up to stroke {i}); the limit is {max_points}."
            ))
        })?;
        return Ok(flat.to_vec().chunks_exact(2).map(|c| [c[0], c[1]]).collect());
    }
    if !v.is_object() || !is_array(v, &what)? {
        return Err(error(&format!("Stroke {i}'s points must be an array of [x, y] pairs, got {}.", type_name(v))));
    }
    let n = length(v, &what)?;
    *budget = budget.checked_sub(n).ok_or_else(|| {
        error(&format!("The strokes hold more than {max_points} points (up to stroke {i}); the limit is {max_points}."))
    })?;
    let mut out = Vec::with_capacity(n);
    for k in 0..n {
        let name = || format!("point {k} of stroke {i}");
        let p = get_index(v, k, name)?;
        let xy = if p.is_object() {
            let x = get_index(&p, 0, name)?.as_f64();
            let y = get_index(&p, 1, name)?.as_f64();
            x.zip(y)
        } else {
            None
        };
        let Some((x, y)) = xy else {
            return Err(error(&format!(
                "Stroke {i}'s point {k} must be [x, y] with two numbers, got {}.",
                type_name(&p)
            )));
        };
        out.push([x, y]);
    }
    Ok(out)
}
