//! Engine 3: seamless colour tiles (SPEC section 3): E-TFMCM, co-occurrence statistics
//! grown by midpoint displacement on a torus, and toroidal neighbourhood synthesis.

pub mod colourise;
pub mod cooccurrence;
pub mod density;
pub mod etfmcm;
pub mod measure;
pub mod mend;
pub mod order;
pub mod prepare;
pub mod tile;

pub use tile::{seamless_tile, Method, SeamlessOptions, SeamlessResult};
