//! Motif instances by the lattice's cells: copies drawn against their neighbours
//! (houses whose eaves meet the next house's walls, faces cheek to cheek) leave no gap
//! between copies for `contact` to cut at. When the strokes, one by one, repeat under
//! periods `a` and `b`, the copies are read from the repetition instead: each motif
//! position (one place of the pattern, `period::Periods`) is moved by whole periods to
//! its site nearest the others, so the motif's sites gather round one centre, and the
//! strokes that share a cell under those sites are one copy.
//!
//! The reading is kept only when it gives what a drawn motif is: the sites gather
//! within half the shorter period of their centre, and most copies' strokes touch or
//! nearly touch one another (a grid of separate dashes repeats too, but its dashes are
//! not parts of one drawn thing).

use super::super::classify::typical_size;
use super::super::period::Periods;
use super::super::stroke::Stroke;
use super::contact::{gap, repeats, Path, Sets};
use kurbo::{Point, Vec2};

/// Parts of one copy are at most this share of the typical stroke size apart.
const TOUCH: f64 = 0.25;
/// The most strokes a copy may hold.
const MAX_PARTS: usize = 64;

/// Groups `strokes` into the copies the periodic reading `periods` makes (see the
/// module comment), or `None`.
pub fn instances(strokes: &[Stroke], periods: &Periods) -> Option<Vec<Vec<u32>>> {
    let (a, b) = (periods.a, periods.b);
    let det = a.cross(b);
    if periods.motifs.len() < 2 || det.abs() < 1e-12 {
        return None;
    }
    // Whole periods nearest to `d`.
    let whole = |d: Vec2| ((d.cross(b) / det).round() as i32, (a.cross(d) / det).round() as i32);
    let step = |(u, w): (i32, i32)| a * u as f64 + b * w as f64;
    let origins: Vec<Point> = periods.motifs.iter().map(|m| m.1).collect();
    // Each position's shift toward the centre of the others, twice (the first centre is
    // one position's own origin).
    let mut centre = origins[0];
    let mut shift = vec![(0, 0); origins.len()];
    for _ in 0..2 {
        for (m, &o) in origins.iter().enumerate() {
            shift[m] = whole(centre - o);
        }
        let sum = origins.iter().zip(&shift).fold(Vec2::ZERO, |s, (&o, &t)| s + (o + step(t)).to_vec2());
        centre = (sum / origins.len() as f64).to_point();
    }
    let shorter = a.hypot().min(b.hypot());
    if origins.iter().zip(&shift).any(|(&o, &t)| (o + step(t)).distance(centre) > 0.5 * shorter) {
        return None;
    }
    // Strokes by their cell under the gathered sites; a position with one stroke (one no
    // period reached) is no part of the repetition and stays its own instance.
    let mut members = vec![0usize; origins.len()];
    periods.motif.iter().for_each(|&m| members[m as usize] += 1);
    let mut keyed: Vec<((i32, i32), u32)> = Vec::new();
    let mut out: Vec<Vec<u32>> = Vec::new();
    for i in 0..strokes.len() {
        let (m, (u, w)) = (periods.motif[i] as usize, periods.cell[i]);
        if members[m] < 2 {
            out.push(vec![i as u32]);
        } else {
            keyed.push(((u - shift[m].0, w - shift[m].1), i as u32));
        }
    }
    keyed.sort_unstable();
    out.extend(keyed.chunk_by(|p, q| p.0 == q.0).map(|g| g.iter().map(|x| x.1).collect::<Vec<u32>>()));
    out.sort_by_key(|g| g[0]);
    if !repeats(&out, strokes.len()) {
        return None;
    }
    let multi: Vec<&Vec<u32>> = out.iter().filter(|g| g.len() >= 2).collect();
    // Most copies hold together by touch (a copy of more strokes than this is no drawn
    // motif, and measuring all its gaps would cost too much).
    if multi.iter().any(|g| g.len() > MAX_PARTS) {
        return None;
    }
    let near = TOUCH * typical_size(strokes);
    let paths: Vec<Path> = strokes.iter().map(Path::of).collect();
    let whole_copies = multi.iter().filter(|g| {
        connected(g, |i, j| {
            let (i, j) = (i as usize, j as usize);
            // (Capped just past `near`: only whether it is within it counts.)
            gap(&strokes[i], &paths[i], &strokes[j], &paths[j], 2.0 * near + 1.0) <= near
        })
    });
    (4 * whole_copies.count() >= 3 * multi.len()).then_some(out)
}

/// Whether the strokes `g` form one piece under `touch`.
fn connected(g: &[u32], touch: impl Fn(u32, u32) -> bool) -> bool {
    let mut sets = Sets::new(g.len());
    let joins = (0..g.len())
        .flat_map(|k| (k + 1..g.len()).map(move |l| (k, l)))
        .filter(|&(k, l)| touch(g[k], g[l]) && sets.union(k as u32, l as u32))
        .count();
    joins + 1 == g.len()
}
