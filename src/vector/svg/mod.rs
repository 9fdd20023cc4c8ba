//! SVG in and out. Import resolves documents people actually have (CSS, `<use>`,
//! nested viewports, compound paths with holes) into strokes, within budgets measured
//! before it runs; export writes one `<path>` per stroke.

pub mod budget;
pub mod compound;
mod entities;
pub mod export;
pub mod import;
mod selector;
pub mod shape;
pub mod style;

pub use export::to_svg;
pub use import::{parse_svg, Import, ImportOptions, MAX_COORD, MAX_SVG_BYTES};
