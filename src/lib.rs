//! patternsynth: example-based texture and pattern synthesis.
//!
//! Engines are plain Rust with no browser types:
//! - [`vector`]: near-regular vector patterns grown from a few example strokes.
//! - [`raster`]: texture synthesis and two-exemplar blending (Wei-Levoy).
//! - [`seamless`]: seamless colour tiles (E-TFMCM, and toroidal synthesis).
//!
//! The `wasm` module (wasm32 only) is the thin JS binding over them.

pub mod error;
#[cfg(feature = "vector")]
mod memo;
pub mod order;
pub mod progress;
#[cfg(any(feature = "texture", feature = "codec"))]
pub mod raster;
pub mod rng;
#[cfg(feature = "texture")]
pub mod seamless;
#[cfg(feature = "vector")]
pub mod vector;

#[cfg(target_arch = "wasm32")]
mod wasm;

pub use error::{Error, Result};
pub use progress::{Progress, Silent};
