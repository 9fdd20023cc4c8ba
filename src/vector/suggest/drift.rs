//! How far copies drift off a model that reads their steps' turn wrong. Each step's
//! turn is off by `error` times its steps from the middle of those the hand-drawn
//! copies span (where the turn is read); past the last hand-drawn copy the headings add
//! up, step by step (copies accepted since pin nothing: they sit where the model put
//! them).
//!
//! A sequence counts its bend's error so (`sequence`: the turn changes along a stem),
//! taking the turn rate's error for the turn's: two copies or more past the hand's it
//! underrates the drift (a bend's error adds up once more), which its backtest and
//! `BEND_CHANGE` carry, and a clear bend goes one copy past the hand's only.
//! A row, which a lattice carries on straight, counts the turn its copies' shapes show
//! (`row_turn`): leaves along a gentle curve fit a row within the hand's wobble, each
//! turned a little more than the last, and a row's third ghost fell 16-22 off at a step
//! of 40 (leaves on a Bézier arch and S, turning 2.5-3 degrees a step); and two copies
//! or more past the hand's, the turn it may hide as well (its standard error, as the
//! shapes' own scatter shows it).

use super::sequence::{relations, SHAPE};
use crate::vector::similarity::samples;
use crate::vector::stroke::{Stroke, DOT};
use kurbo::Point;

/// How far off a copy `past` steps beyond the last hand-drawn one is put, the hand-drawn
/// copies spanning `span` steps, when each step's turn is off by `error` (radians) times
/// its steps from their middle: `step` times the headings' errors summed over the steps
/// from the last hand-drawn copy on.
pub(super) fn drift(step: f64, error: f64, span: f64, past: f64) -> f64 {
    step * error * (past * (0.5 * span + 1.0) + 0.5 * past * (past - 1.0))
}

/// The turn of a row's steps as its copies' shapes show it (radians a step), and its
/// standard error: each hand-drawn copy of a motif position against the next along the
/// row (`span` steps on), by least squares. From each motif position's hand-drawn
/// copies, in order along the row: their step along it and their stroke (copies of
/// several strokes are left out, as are shapes that look the same turned, a circle,
/// whose turn nothing shows). `None` without a relation; the error is 0 from one.
///
/// The turn read is what a row carried on straight misses by, however sure: the
/// lattice's own certainty holds the rest (a row whose shapes show no turn is not held
/// back for a prior turn they might hide: a hand's copies turn by a degree or two at
/// random, and a prior of that much cost a straight row its third ghost). Copies turned
/// at random by more read as a curve: ticks turned by up to 9 degrees get no ghost at
/// four copies (taking the turn only where it passed two standard errors mended that,
/// and put more ghosts straight on past a turning row's corner: 7 to 15 wrong at 1%).
///
/// The error is what the turn read may be off by, from the pairs' own scatter about
/// it, not a prior: a copy two or more past the hand-drawn ones is held back by it too
/// (leaves along a gentle wave, turning 3-5 degrees a step under the hand's turn of
/// each copy, read as turning 0.2 degrees a step: the row's second and third ghosts
/// fell 0.33-0.94 of the step off; counted so, 4 wrong of 19 later ghosts, not 8 of
/// 23, with a steady and a person's hand's replay as accepted as before).
pub(super) fn row_turn(rows: &[Vec<(i64, &Stroke)>]) -> Option<(f64, f64)> {
    // (span, turn) of consecutive hand-drawn copies.
    let pairs: Vec<(f64, f64)> = rows
        .iter()
        .flat_map(|row| row.windows(2))
        .filter_map(|w| Some(((w[1].0 - w[0].0) as f64, turn_between(w[0].1, w[1].1)?)))
        .collect();
    let s2: f64 = pairs.iter().map(|p| p.0 * p.0).sum();
    (s2 > 0.0).then(|| {
        let turn = pairs.iter().map(|p| p.0 * p.1).sum::<f64>() / s2;
        let n = pairs.len() as f64;
        let spread = pairs.iter().map(|p| (p.1 - p.0 * turn).powi(2)).sum::<f64>();
        (turn, if n > 1.0 { (spread / (n - 1.0) / s2).sqrt() } else { 0.0 })
    })
}

/// The least turn (radians) carrying stroke `from` onto `to`, when they are one shape
/// (up to a similarity) and it shows a turn: not a circle (see `looks_the_same_turned`), nor
/// a dot, a tap of the pen a few widths long whichever way it went.
pub(super) fn turn_between(from: &Stroke, to: &Stroke) -> Option<f64> {
    let size = from.bounds().size().to_vec2().hypot();
    if size < DOT * from.width.max(to.width) {
        return None;
    }
    let (p, q) = (samples(from), samples(to));
    if looks_the_same_turned(&p, size) {
        return None;
    }
    // (Of the fits that pass, the least turn: a row's copies are translated, and a line
    // shaken by a pointer's jitter may fit read backwards a little better, a half turn,
    // which read as a row bending by 0.6 radians a step and held hatching back.)
    relations(&p, &q, size).into_iter().map(|(t, _)| t.turn()).min_by(|x, y| x.abs().total_cmp(&y.abs()))
}

/// Whether a closed loop fits itself begun a quarter of the way round (a circle, a
/// square): its copies' turn is then not in their shapes.
fn looks_the_same_turned(p: &[Point], size: f64) -> bool {
    crate::vector::similarity::looks_the_same_turned(p, size, SHAPE)
}

/// Whether a closed loop is round, a circle (`similarity::looks_round`).
pub(super) fn looks_round(p: &[Point], size: f64) -> bool {
    crate::vector::similarity::looks_round(p, size, SHAPE)
}
