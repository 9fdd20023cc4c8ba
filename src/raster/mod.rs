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
#[cfg(feature = "texture")]
pub mod guide;
#[cfg(feature = "texture")]
pub mod heal;
pub mod image;
#[cfg(feature = "texture")]
pub mod inpaint;
#[cfg(feature = "texture")]
pub mod neighbourhood;
#[cfg(feature = "texture")]
pub mod pool;
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
    blend_job, blend_textures, pool_job, synthesize_texture, synthesize_textures, texture_job, BlendOptions,
    Coefficient, Guides, Synthesis, TextureOptions,
};
#[cfg(feature = "texture")]
pub use {
    guide::{style_job, transfer_style, StyleOptions},
    inpaint::{inpaint_texture, InpaintOptions},
    pool::{apply_layout, Layout},
};
