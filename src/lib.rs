//! patternsynth: example-based texture and pattern synthesis.
//!
//! Engines are plain Rust with no browser types:
//! - [`vector`]: near-regular vector patterns grown from a few example strokes.
//!
//! The `wasm` module (wasm32 only) is the thin JS binding over them.

pub mod error;
pub mod progress;
pub mod rng;
pub mod vector;

#[cfg(target_arch = "wasm32")]
mod wasm;

pub use error::{Error, Result};
pub use progress::{Progress, Silent};
