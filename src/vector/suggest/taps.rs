//! Pen taps round a centre (a ring of dots), completed once drawn half round. A dot has
//! no shape to carry (`sequence` follows none), and the lattice its places also fit put
//! ghosts off the ring (helper-55's trial: five taps of a ring of six got ten ghosts, all
//! wrong; rings of five to twelve otherwise "no repetition yet"). Read as synthesis
//! reads them (`chain::find_by_place`): evenly round one circle, from the latest taps
//! drawn one after another.

use super::sequence::{Ask, RING_COMPLETE};
use super::{Suggestions, FALLOFF};
use crate::vector::chain::find_by_place;
use crate::vector::stroke::Stroke;

/// Why nothing is proposed where the ring's copies left to draw are off the canvas.
const OFF_CANVAS: &str = "The ring's next copies would fall off the canvas.";

/// The latest taps' ring completed (its sites not yet drawn, the nearest along the way
/// the hand went first), or `None` where the latest stroke is no tap of a ring.
pub(super) fn propose(strokes: &[Stroke], ask: &Ask) -> Option<Suggestions> {
    let n = strokes.len();
    if !strokes.last()?.is_dot() {
        return None;
    }
    let from = (0..n).rev().find(|&i| !strokes[i].is_dot()).map_or(0, |i| i + 1);
    let taps = &strokes[from..];
    // (Every tap one of the ring: a hexagon of taps round a seventh is a lattice's.)
    let ring = find_by_place(taps).filter(|r| r.members.len() == taps.len())?;
    let copies = ring.complete(taps, ask.seed);
    if copies.is_empty() {
        return Some(Suggestions { reason: Some(RING_COMPLETE.into()), ..Suggestions::default() });
    }
    let mut out = Suggestions::default();
    for (k, (stroke, source)) in copies.into_iter().enumerate() {
        if out.strokes.len() >= ask.count {
            break;
        }
        if ask.region.is_some_and(|r| !r.contains(stroke.reference_point())) {
            continue;
        }
        out.strokes.push(stroke);
        out.confidence.push(FALLOFF.powi(k as i32 + 1));
        out.sources.push((from + source + ask.offset) as u32);
        out.cells.push([k as i64 + 1, 0]);
    }
    if out.strokes.is_empty() {
        out.reason = Some(OFF_CANVAS.into());
    }
    Some(out)
}
