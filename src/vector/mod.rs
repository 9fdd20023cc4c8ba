//! Engine 1: near-regular vector pattern synthesis from example strokes (SPEC section 1).

pub mod chain;
pub mod classify;
pub mod color;
pub mod element;
#[cfg(feature = "test-support")]
pub mod exemplar;
pub mod frechet;
pub mod grow;
#[cfg(feature = "test-support")]
pub mod handdrawn;
pub mod lattice;
mod mesh;
mod mosaic;
pub mod motif;
mod pack;
pub mod period;
mod reference;
#[cfg(feature = "test-support")]
pub mod regularity;
#[cfg(feature = "test-support")]
pub mod replay;
mod rosette;
#[cfg(feature = "test-support")]
pub mod sequences;
pub mod similarity;
pub mod spatial;
pub mod stroke;
pub mod suggest;
pub mod svg;
pub mod synthesize;
pub mod tile;

pub use classify::Tolerances;
pub use color::Rgb;
pub use stroke::{FillRule, Stroke};
pub use suggest::{suggest_strokes, SuggestOptions, Suggestions};
pub use svg::{parse_svg, Import, ImportOptions};
pub use synthesize::{classify_strokes, synthesize_strokes, Classification, StrokeOptions, StrokeResult};
pub use tile::{stroke_tile, TileOptions, TileResult};
