//! Engine 2: texture synthesis and blending (SPEC section 2): Wei-Levoy multi-resolution
//! neighbourhood matching against one or two exemplars.

#[cfg(feature = "texture")]
pub mod bands;
#[cfg(feature = "codec")]
pub mod codec;
#[cfg(feature = "texture")]
pub mod coefficient;
#[cfg(feature = "texture")]
pub(crate) mod divisor;
#[cfg(feature = "texture")]
pub mod energy;
pub mod image;
#[cfg(feature = "texture")]
pub mod neighbourhood;
#[cfg(feature = "texture")]
pub mod pyramid;
#[cfg(feature = "texture")]
pub mod quilt;
#[cfg(feature = "texture")]
pub mod synthesis;
#[cfg(feature = "texture")]
pub mod texture;

pub use self::image::{Image, Rgba};
#[cfg(feature = "texture")]
pub use texture::{
    blend_job, blend_textures, synthesize_texture, texture_job, BlendOptions, Coefficient, TextureOptions,
};
