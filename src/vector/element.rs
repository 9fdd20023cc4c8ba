//! The point elements the engine works on: an example stroke reduced to its class and
//! reference point, and an output element that copies one. Growth, the lattice fit and
//! the period search all read these, so they live below all three.

use kurbo::Point;

/// A point element of the reference: its class and reference point.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Element {
    pub pos: Point,
    pub class: u32,
}

/// An element of the grown target: where it is and which reference element it copies.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Placed {
    pub pos: Point,
    pub class: u32,
    pub source: u32,
}
