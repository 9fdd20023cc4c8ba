//! Synthesis around known pixels (`Constraints::known`): a hole filled, a tile's band
//! mended. Known pixels are pinned, at every level, to the same pixel of the exemplar
//! (the image itself), so they keep their colours exactly and condition their
//! neighbours' matches; only the free pixels are searched.
//!
//! The coarsest level is filled from the edge of the known region inwards (onion
//! peeling, as in Criminisi et al. 2004 and Harrison's resynthesizer): each free pixel
//! takes the exemplar position that best matches the pixels around it already set, so
//! a hole's fill continues the structure at its border rather than growing from noise.
//! Each finer level starts from its parent's positions upsampled (Lefebvre and Hoppe
//! 2005) and every pass matches full neighbourhoods, alternately forwards and in
//! reverse: a free pixel sees known pixels on every side. Work is in proportion to
//! the free pixels, not the image.
//!
//! The fill's colours are then healed into the known ones (`raster::heal`), and each
//! free pixel of the finest level is matched again to the healed colours
//! (`Job::rematch`, with PatchMatch's local random search, Barnes et al. 2009): after
//! Wexler, Shechtman and Irani's (2007) alternation between choosing patches and
//! setting colours, with the heal in place of their vote.

use super::exemplar::{distance, Offsets, Plane};
use super::job::Job;
use super::lanes::{Px, Sum};
use super::pass::{Map, Scratch};
use super::reuse::Uses;
use crate::error::Result;
use crate::progress::Throttle;
use crate::raster::image::{wrap, Rgba};
use crate::raster::neighbourhood::Shape;
use crate::rng::Rng;
use std::collections::VecDeque;

/// The coherence bias around known pixels (`pass::COHERENCE` elsewhere): none. Known
/// neighbours propose nothing (their continuations lie in the hole), so the bias let
/// one patch, proposed by the free neighbours, spread over the whole hole and win
/// against the border: on eight photographs of the peer comparison (256², a 10% hole,
/// seeds 1-3) the hole's edge ratio (the step across its boundary over the steps just
/// outside) was 2.05 with the bias, 1.74 without; with the healing (`heal`) 1.12 and
/// 1.05 (texture-synthesis 0.8.3: 1.21).
pub(super) const PINNED_COHERENCE: f32 = 0.0;

/// Rounds of healing and matching again (`Job::rematch`) before the last heal: the fill
/// chosen for the structure at its border, then for the colours the heal gives it. On
/// twelve photographs from Debian's game packages (224 px, holes of 8.5-10.5%, seeds 1-5,
/// examples/inpaint_edge) the fill's patch energy (each window's RMS, averaged) went
/// from 7.79 to 7.09 after one round, 6.91 after two and 6.87 after three, and the step
/// across the hole's edge from 1.10 times the steps around it to 0.99, 0.95 and 0.94
/// (texture-synthesis 0.8.3 on the same holes: 7.61 and 1.32), at 23, 34, 43 and 51 ms
/// a fill natively (with the last heal whole; `inpaint::LAST_HEAL` takes half). Matched
/// again without the last heal, the fill stays verbatim copies but its edge shows
/// (1.13-1.20). More candidates or passes in the synthesis itself, or a local search in
/// its passes, gained a third as much at twice the time; a coherence bias, or
/// searching the coarsest level exhaustively, nothing. A mended tile's band is not
/// matched again (`inpaint::Fill::rematch` says why).
pub const REMATCH_ROUNDS: usize = 2;

/// Rounds of PatchMatch's local random search in `Job::rematch` (none: 7.57 rather
/// than 6.91 above; four: 6.87).
const REMATCH_LOCAL: usize = 2;

/// Free pixels x allowed positions x neighbours up to which the onion start searches
/// every allowed position; above it, each free pixel compares the continuations of its
/// set neighbours' positions and `ONION_RANDOM` random ones.
const ONION_EXHAUSTIVE_BUDGET: usize = 64 << 20;
const ONION_RANDOM: usize = 48;

/// `ONION_EXHAUSTIVE_BUDGET` for a mended tile's band (on the torus). At the coarsest
/// level a tile's pyramid aims at (14-16 pixels for photographs of 128-256 pixels: 1.7-2.7
/// million comparisons) the band is still searched exhaustively; at 28-32 pixels (a band
/// made again, `seamless::mend::AGAIN_COARSEST`, or a photograph of 512: 32-50 million)
/// it is searched as a large fill's is, and the seed lays it out. Searched exhaustively,
/// paving's band made again came out alike in every seed, and six photographs of 512
/// pixels (plain syntheses of held-out photographs, seeds 1-3, examples/mend_seams)
/// took 442-563 ms a mend rather than 366-452, for wraps of 0.79-1.15 against 0.72-1.05.
const MEND_ONION_EXHAUSTIVE_BUDGET: usize = 16 << 20;

/// `synthesis::sources` for a job with known pixels (one exemplar, scanline order):
/// as many passes over the free pixels as a plain synthesis makes (two more passes
/// spread the border's structure no further once the fill is healed: the hole's edge
/// ratio 1.05 against 1.06, mended tiles' wraps 8 of the 10 fixtures within 0.8-1.2
/// against 9 without them, and a fifth longer).
pub(super) fn sources(job: &Job, progress: &mut Throttle) -> Result<Vec<Vec<u32>>> {
    let mut finest = begin(job, progress)?;
    finest.last_pass(job, progress)?;
    Ok(finest.map.src)
}

/// A synthesis around known pixels made but for its finest level's last pass (`begin`),
/// which a mend measures before it decides to make the band again or to finish it
/// (`Finest::last_pass`).
pub(crate) struct Finest {
    map: Map,
    parent: Vec<Vec<u32>>,
    rng: Rng,
    /// The free pixels' passes made so far, and in all.
    done: usize,
    total: usize,
}

/// Every level of `job` (`sources`) but the finest's last pass.
pub(crate) fn begin(job: &Job, progress: &mut Throttle) -> Result<Finest> {
    let known = job.known.as_ref().expect("a job with known pixels");
    let params = &job.params;
    let mut rng = Rng::new(params.seed);
    let passes = 1 + params.corrections;
    let free: Vec<Vec<u32>> = known.iter().map(|k| (0..k.len() as u32).filter(|&i| !k[i as usize]).collect()).collect();
    let total = free.iter().map(Vec::len).sum::<usize>().max(1) * passes;
    let mut done = 0usize;
    let mut parent_src: Vec<Vec<u32>> = Vec::new();
    for level in (0..job.levels).rev() {
        let (lw, lh) = job.sizes[level];
        let src =
            if job.started(level) { job.starts()[0].clone() } else { upsampled(job, level, &parent_src[0], &mut rng) };
        let uses = Uses::count(job, level, |_, y, out| out.extend_from_slice(&src[y * lw..(y + 1) * lw]));
        let mut map = job.pass(level, &parent_src).whole(vec![src], uses);
        let free = &free[level];
        let passes = if level == 0 { passes - 1 } else { passes };
        for p in 0..passes {
            each_pass(job, level, &parent_src, &mut map, free, p, |_, _| false, &mut rng, progress, (done, total))?;
            done += free.len();
        }
        if level == 0 {
            return Ok(Finest { map, parent: parent_src, rng, done, total });
        }
        debug_assert!((0..lw * lh).all(|i| !job.is_known(level, i) || map.src[0][i] == i as u32));
        parent_src = map.src;
    }
    unreachable!("a job has a finest level")
}

/// Pass `p` of `level` over `free` (in reverse on odd passes), each pixel matched with
/// its full neighbourhood unless `skip(i)`.
#[allow(clippy::too_many_arguments)]
fn each_pass(
    job: &Job,
    level: usize,
    parent_src: &[Vec<u32>],
    map: &mut Map,
    free: &[u32],
    p: usize,
    skip: impl Fn(&Map, usize) -> bool,
    rng: &mut Rng,
    progress: &mut Throttle,
    (done, total): (usize, usize),
) -> Result<()> {
    let params = &job.params;
    let lw = job.sizes[level].0;
    // (The finest `detail_levels` match 5 x 5 neighbourhoods: see `Params`.)
    let detail = Shape::full(2);
    let shape = if level < params.detail_levels && job.full.half > 2 { &detail } else { &job.full };
    let pass = job.pass_shaped(level, parent_src, shape);
    let mut scratch = Scratch::new(&job.full);
    for k in 0..free.len() {
        let i = free[if p % 2 == 1 { free.len() - 1 - k } else { k }] as usize;
        if !skip(map, i) {
            pass.pixel(map, shape, true, i % lw, i / lw, rng, &mut scratch);
        }
        if k % lw == lw - 1 {
            progress.tick((done + k) as f64 / total as f64)?;
        }
    }
    Ok(())
}

/// A mended band's finest level is matched a last time only where a copied patch meets
/// another: a pixel whose four neighbours all copy the continuation of its own copy (the
/// inside of a patch) keeps it. Matched again, such a pixel nearly always proposed its
/// copy again; over the whole band the last pass was a fifth of a mend's time, over the
/// patches' seams it is about half of that. On twelve held-out photographs and the ten
/// fixtures (seeds 1-3, examples/mend_seams) the band's patch energy rose 0.5% (median;
/// 1% with no last pass at all), the wraps moved by at most 0.06.
fn inside_a_patch(job: &Job, map: &Map, i: usize) -> bool {
    let (lw, lh) = job.sizes[0];
    let (x, y) = ((i % lw) as isize, (i / lw) as isize);
    let plane = job.plane(0, 0);
    let s = map.src[0][i];
    [(1, 0), (-1, 0), (0, 1), (0, -1)].iter().all(|&(dx, dy)| {
        let n = wrap(y + dy, lh) * lw + wrap(x + dx, lw);
        plane.continuation(map.src[0][n], dx, dy) == Some(s)
    })
}

impl Finest {
    /// The finest level's copies so far.
    pub(crate) fn src(&self) -> &[u32] {
        &self.map.src[0]
    }

    /// The finest level's last pass; a mended band's only where its copied patches meet
    /// (`inside_a_patch`).
    pub(crate) fn last_pass(&mut self, job: &Job, progress: &mut Throttle) -> Result<()> {
        let known = &job.known.as_ref().expect("a job with known pixels")[0];
        let free: Vec<u32> = (0..known.len() as u32).filter(|&i| !known[i as usize]).collect();
        let p = job.params.corrections;
        let mended = job.params.tileable;
        let skip = |map: &Map, i: usize| mended && inside_a_patch(job, map, i);
        let (done, total) = (self.done, self.total);
        each_pass(job, 0, &self.parent, &mut self.map, &free, p, skip, &mut self.rng, progress, (done, total))?;
        debug_assert!((0..known.len()).all(|i| !known[i] || self.map.src[0][i] == i as u32));
        progress.tick(1.0)
    }
}

/// A finer level's start: known pixels at themselves, free ones at the child of their
/// parent's position (clamped to the exemplar), or anywhere allowed when that child is
/// masked.
fn upsampled(job: &Job, level: usize, parent: &[u32], rng: &mut Rng) -> Vec<u32> {
    let (lw, lh) = job.sizes[level];
    let plw = job.sizes[level + 1].0;
    let plane = job.plane(0, level);
    let (ew, eh) = (plane.width, plane.height);
    let pw = job.plane(0, level + 1).width;
    let mut out = Vec::with_capacity(lw * lh);
    for y in 0..lh {
        for x in 0..lw {
            let i = y * lw + x;
            if job.is_known(level, i) {
                out.push(i as u32);
                continue;
            }
            let s = parent[(y / 2) * plw + x / 2] as usize;
            let sx = (2 * (s % pw) + x % 2).min(ew - 1);
            let sy = (2 * (s / pw) + y % 2).min(eh - 1);
            let c = (sy * ew + sx) as u32;
            out.push(if plane.allows(c) { c } else { plane.random(rng) });
        }
    }
    out
}

impl Job {
    /// The coarsest level's start for a job with known pixels (`Start::Onion`; see the
    /// module): known pixels at themselves, free ones in order of their distance from
    /// the known region, each matched over the neighbours already set.
    pub(super) fn onion(&self, level: usize) -> Vec<u32> {
        let (lw, lh) = self.sizes[level];
        let known = &self.known.as_ref().expect("a job with known pixels")[level];
        let plane = self.plane(0, level);
        let target = self.target.as_ref().map(|t| &t[level]);
        let torus = self.torus();
        let neighbour = |x: usize, y: usize, dx: isize, dy: isize| -> Option<usize> {
            let (nx, ny) = (x as isize + dx, y as isize + dy);
            if torus {
                Some(wrap(ny, lh) * lw + wrap(nx, lw))
            } else {
                ((0..lw as isize).contains(&nx) && (0..lh as isize).contains(&ny))
                    .then(|| ny as usize * lw + nx as usize)
            }
        };
        let half = self.full.half;
        let order = peel(known, lw, lh, neighbour);
        let budget = if torus { MEND_ONION_EXHAUSTIVE_BUDGET } else { ONION_EXHAUSTIVE_BUDGET };
        let exhaustive =
            order.len().saturating_mul(plane.allowed_count()).saturating_mul(self.full.own.len()) <= budget;
        let mut rng = Rng::new(self.params.seed ^ 0x0_4A10_4E00);
        let mut src: Vec<u32> = (0..(lw * lh) as u32).collect();
        let mut set = known.clone();
        let mut points: Vec<((isize, isize), Px)> = Vec::new();
        let mut offsets: Vec<isize> = Vec::new();
        let mut cands: Vec<u32> = Vec::new();
        let padded = Padded::new(plane, half as usize);
        for i in order {
            let (x, y) = (i % lw, i / lw);
            points.clear();
            for dy in -half..=half {
                for dx in -half..=half {
                    if let Some(j) = neighbour(x, y, dx, dy).filter(|&j| j != i && set[j]) {
                        let mut c = plane.data[src[j] as usize];
                        if let Some(t) = target {
                            c[3] = t[j];
                        }
                        points.push(((dx, dy), c));
                    }
                }
            }
            // The target guide at the pixel itself: with nothing set around it, it is all
            // there is to match.
            if let Some(t) = target {
                points.push(((0, 0), [0.0, 0.0, 0.0, t[i]]));
            }
            offsets.clear();
            offsets.extend(points.iter().map(|&((dx, dy), _)| padded.offset(dx, dy)));
            let score =
                |pos: u32, bound: f32| masked_distance(&padded, padded.at(plane, pos), &points, &offsets, bound);
            let mut best = (f32::INFINITY, u32::MAX);
            if points.is_empty() {
                best.1 = plane.random(&mut rng);
            } else if exhaustive {
                plane.each_allowed(|pos| {
                    let d = score(pos, best.0);
                    if d < best.0 {
                        best = (d, pos);
                    }
                });
            } else {
                cands.clear();
                for &((dx, dy), _) in &points {
                    if let Some(j) = neighbour(x, y, dx, dy).filter(|&j| set[j]) {
                        cands.extend(plane.continuation(src[j], dx, dy));
                    }
                }
                cands.extend((0..ONION_RANDOM).map(|_| plane.random(&mut rng)));
                for &pos in &cands {
                    let d = score(pos, best.0);
                    if d < best.0 {
                        best = (d, pos);
                    }
                }
            }
            src[i] = best.1;
            set[i] = true;
        }
        src
    }
}

impl Job {
    /// Each free pixel of the finest level matched again against `target` (the fill as
    /// healed, `heal`; put in lanes as the exemplar's pixels are, `opacity`), in
    /// scanline order: the allowed position whose 5 x 5 neighbourhood, centre included,
    /// is nearest the target's around the pixel, among its source, its neighbours'
    /// continuations and a local random search.
    /// A pixel the heal had to lighten or darken then copies a position of that colour,
    /// and the next heal has less to correct (`REMATCH_ROUNDS`).
    pub(crate) fn rematch(&self, src: &mut [u32], target: &Rgba, rng: &mut Rng) {
        let target: Vec<Px> =
            target.data.chunks_exact(4).map(|p| self.opacity.pixel([0, 1, 2, 3].map(|c| p[c] as f32))).collect();
        let (w, h) = self.sizes[0];
        let known = &self.known.as_ref().expect("a job with known pixels")[0];
        let ex = &self.mix.exs[0];
        let plane = &ex.levels[0];
        let mut shape = Shape::full(2);
        shape.own.push((0, 0));
        shape.parent.clear();
        let whole = (Offsets::new(&shape, plane.width), shape);
        let torus = self.torus();
        let at = |x: usize, y: usize, dx: isize, dy: isize| wrap(y as isize + dy, h) * w + wrap(x as isize + dx, w);
        let mut f: Vec<Px> = Vec::with_capacity(whole.1.own.len());
        for i in (0..w * h).filter(|&i| !known[i]) {
            let (x, y) = (i % w, i / w);
            // Off a torus, the points past the border are left out (as `Pass::cut` does).
            let inside = |dx: isize, dy: isize| {
                (0..w as isize).contains(&(x as isize + dx)) && (0..h as isize).contains(&(y as isize + dy))
            };
            let cut = (!(torus || inside(-2, -2) && inside(2, 2)))
                .then(|| whole.1.clipped(inside, |_, _| true))
                .flatten()
                .map(|s| (Offsets::new(&s, plane.width), s));
            let (off, shape) = cut.as_ref().unwrap_or(&whole);
            f.clear();
            f.extend(shape.own.iter().map(|&(dx, dy)| target[at(x, y, dx, dy)]));
            let score = |pos: u32, bound: f32| distance(ex, 0, pos, shape, off, &f, bound);
            let mut best = (score(src[i], f32::INFINITY), src[i]);
            for &(dx, dy) in &shape.own {
                if let Some(c) = plane.continuation(src[at(x, y, dx, dy)], dx, dy).filter(|&c| c != best.1) {
                    let d = score(c, best.0);
                    if d < best.0 {
                        best = (d, c);
                    }
                }
            }
            best = local_search(plane, best, REMATCH_LOCAL, rng, score);
            src[i] = best.1;
        }
    }
}

/// PatchMatch's random search (Barnes et al. 2009): positions drawn about the best so far
/// within a window that halves each time, from half the plane's side down to a pixel,
/// `rounds` times over; each kept where `score(pos, bound)` (the distance, given up past
/// `bound`) is lower.
fn local_search(
    plane: &Plane,
    mut best: (f32, u32),
    rounds: usize,
    rng: &mut Rng,
    score: impl Fn(u32, f32) -> f32,
) -> (f32, u32) {
    let (w, h) = (plane.width as isize, plane.height as isize);
    for _ in 0..rounds {
        let mut r = w.max(h) / 2;
        while r >= 1 {
            let (bx, by) = plane.xy(best.1);
            let mut near = |v: isize, n: isize| (v + rng.below(2 * r as usize + 1) as isize - r).clamp(0, n - 1);
            let (x, y) = (near(bx, w), near(by, h));
            let pos = (y * w + x) as u32;
            if pos != best.1 && plane.allows(pos) {
                let d = score(pos, best.0);
                if d < best.0 {
                    best = (d, pos);
                }
            }
            r /= 2;
        }
    }
    best
}

/// A plane with `pad` pixels more on every side, each a copy of the nearest edge pixel
/// (what `Plane::clamped` reads), so that the onion start reads any neighbourhood within
/// `pad` by index: on a coarsest level of 14-16 pixels nearly every 11 x 11
/// neighbourhood reaches past the edge, and clamping each read took two fifths of the
/// start's time (the ten fixtures and three photographs, seeds 1-3: 196 ms in all, now
/// 121).
struct Padded {
    data: Vec<Px>,
    width: usize,
    pad: usize,
}

impl Padded {
    fn new(plane: &Plane, pad: usize) -> Padded {
        let (w, h) = (plane.width + 2 * pad, plane.height + 2 * pad);
        let p = pad as isize;
        let data = (0..w * h).map(|i| *plane.clamped((i % w) as isize - p, (i / w) as isize - p)).collect();
        Padded { data, width: w, pad }
    }

    /// The index of plane position `pos`.
    fn at(&self, plane: &Plane, pos: u32) -> usize {
        let (x, y) = plane.xy(pos);
        (y as usize + self.pad) * self.width + x as usize + self.pad
    }

    /// The index step to the pixel (dx, dy) away.
    fn offset(&self, dx: isize, dy: isize) -> isize {
        dy * self.width as isize + dx
    }
}

/// Squared distance over `points` (offsets with the colour set there, and the target
/// guide in the fourth lane; `offsets`, the same as index steps in `padded`) between the
/// output and the exemplar around index `at`, read clamped to the plane; at the centre,
/// the guide alone. Stops past `bound`.
fn masked_distance(padded: &Padded, at: usize, points: &[((isize, isize), Px)], offsets: &[isize], bound: f32) -> f32 {
    let mut sum = Sum::zero();
    for (k, (&((dx, dy), c), &o)) in points.iter().zip(offsets).enumerate() {
        let e = &padded.data[(at as isize + o) as usize];
        if (dx, dy) == (0, 0) {
            sum.add(&[0.0, 0.0, 0.0, e[3]], &[0.0, 0.0, 0.0, c[3]]);
        } else {
            sum.add(e, &c);
        }
        if k % 8 == 7 && sum.total() > bound {
            break;
        }
    }
    sum.total()
}

/// The free pixels (not `known`) in order of their distance, in 8-neighbour steps, from
/// the known ones (`neighbour` reads a neighbour of (x, y), or `None` past an edge);
/// when nothing is known, from the first free pixel.
fn peel(
    known: &[bool],
    lw: usize,
    lh: usize,
    neighbour: impl Fn(usize, usize, isize, isize) -> Option<usize>,
) -> Vec<usize> {
    let mut seen = known.to_vec();
    let mut queue: VecDeque<usize> = VecDeque::new();
    let mut order = Vec::with_capacity(known.iter().filter(|&&k| !k).count());
    let ring = |i: usize, seen: &mut Vec<bool>, queue: &mut VecDeque<usize>| {
        for dy in -1..=1 {
            for dx in -1..=1 {
                if let Some(j) = neighbour(i % lw, i / lw, dx, dy) {
                    if !seen[j] {
                        seen[j] = true;
                        queue.push_back(j);
                    }
                }
            }
        }
    };
    for i in (0..lw * lh).filter(|&i| known[i]) {
        ring(i, &mut seen, &mut queue);
    }
    loop {
        while let Some(i) = queue.pop_front() {
            order.push(i);
            ring(i, &mut seen, &mut queue);
        }
        // Free pixels no known one reaches (nothing known, or an island): start anew.
        match seen.iter().position(|&s| !s) {
            Some(i) => {
                seen[i] = true;
                queue.push_back(i);
            }
            None => break,
        }
    }
    order
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn peels_from_the_known_border_inwards() {
        // 5 x 5, the middle 3 x 3 free: the ring of 8 before the centre.
        let mut known = vec![true; 25];
        for y in 1..4 {
            for x in 1..4 {
                known[y * 5 + x] = false;
            }
        }
        let n = |x: usize, y: usize, dx: isize, dy: isize| {
            let (nx, ny) = (x as isize + dx, y as isize + dy);
            ((0..5).contains(&nx) && (0..5).contains(&ny)).then(|| ny as usize * 5 + nx as usize)
        };
        let order = peel(&known, 5, 5, n);
        assert_eq!(order.len(), 9);
        assert_eq!(*order.last().unwrap(), 12);
        // Nothing known: every pixel, once.
        let order = peel(&[false; 25], 5, 5, n);
        let mut sorted = order.clone();
        sorted.sort();
        assert_eq!(sorted, (0..25).collect::<Vec<_>>());
    }
}
