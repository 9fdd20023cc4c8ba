//! Progress reporting and cancellation, passed to every long-running engine call.
//!
//! A `Progress` receives the fraction done in [0, 1] and answers whether to go on.
//! Engines call it often enough for a smooth bar; `Throttle` keeps the cost of a
//! JS callback out of inner loops.

use crate::error::{Error, Result};

pub trait Progress {
    /// Report `fraction` done; return `false` to cancel.
    fn report(&mut self, fraction: f64) -> bool;
}

impl<F: FnMut(f64) -> bool> Progress for F {
    fn report(&mut self, fraction: f64) -> bool {
        self(fraction)
    }
}

/// A progress sink that never cancels, for callers that do not care.
pub struct Silent;

impl Progress for Silent {
    fn report(&mut self, _: f64) -> bool {
        true
    }
}

/// Forwards to an inner `Progress` only when the fraction moved by at least `step`,
/// and turns a cancel answer into `Error::Cancelled`.
pub struct Throttle<'a> {
    inner: &'a mut dyn Progress,
    last: f64,
    step: f64,
    /// Maps the engine's own [0, 1] into a sub-range of the caller's bar.
    range: (f64, f64),
}

impl<'a> Throttle<'a> {
    pub fn new(inner: &'a mut dyn Progress) -> Self {
        Throttle { inner, last: -1.0, step: 0.005, range: (0.0, 1.0) }
    }

    /// Report within `[lo, hi]` of the caller's bar.
    pub fn with_range(inner: &'a mut dyn Progress, lo: f64, hi: f64) -> Self {
        Throttle { inner, last: -1.0, step: 0.005, range: (lo, hi) }
    }

    pub fn tick(&mut self, fraction: f64) -> Result<()> {
        let f = fraction.clamp(0.0, 1.0);
        if f - self.last < self.step && f < 1.0 {
            return Ok(());
        }
        self.last = f;
        let mapped = self.range.0 + (self.range.1 - self.range.0) * f;
        if self.inner.report(mapped) {
            Ok(())
        } else {
            Err(Error::Cancelled)
        }
    }
}
