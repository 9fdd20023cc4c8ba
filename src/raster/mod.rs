//! Engine 2: texture synthesis and blending (SPEC section 2): Wei-Levoy multi-resolution
//! neighbourhood matching against one or two exemplars.

#[cfg(feature = "codec")]
pub mod codec;
pub mod coefficient;
pub mod energy;
pub mod image;
pub mod neighbourhood;
pub mod pyramid;
pub mod synthesis;
pub mod texture;

pub use self::image::{Image, Rgba};
pub use texture::{blend_textures, synthesize_texture, BlendOptions, Coefficient, TextureOptions};
