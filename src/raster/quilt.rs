//! The coarsest level's start: a quilt of exemplar windows (after Efros and Freeman's
//! image quilting, 2001), instead of noise grown in scanline order.
//!
//! Why: grown causally from noise, the layout drifts towards the exemplar's smoothest
//! region, whose neighbourhoods match everything well; tissue's outputs were 70% the
//! stroma that covers 30% of its exemplar. A quilt lays the exemplar's regions out in
//! about their proportions, and the correction passes then join its windows.
//!
//! Windows of side `b` are laid in rows `b - o` apart, overlapping by `o`; each row is
//! shifted sideways by a random amount, so that window corners do not line up. A window's
//! origin is the best of a few random ones by the squared difference over its overlap
//! with what is laid already (few, so that proportions stay those of the exemplar, not of
//! its best-matching part). It replaces what is laid only beyond the least-difference
//! cut through each overlap (a path found by dynamic programming), so windows meet along
//! their most alike pixels rather than along straight lines.
//!
//! With a guide (Efros and Freeman's texture transfer), a window's cost is the mean
//! squared difference over its overlap plus the mean squared difference between the
//! exemplar's guide under it and the target's where it is laid, and it tries up to
//! `candidates` origins (every one where there are no more; `synthesis::start::GUIDED_QUILT` asks
//! for 1,024): the windows then lay the target's light and dark out, which a few random
//! origins could not. Its windows are small (4 pixels), so their overlap is one pixel
//! and the cut is a straight line; the passes over the level join them.
//!
//! With `spread` (tiles), a window's cost also counts how much of the exemplar under it
//! is copied already against the share each pixel should take (`reach`), so that the
//! quilt covers the exemplar in about those proportions rather than copying some
//! regions several times and others never. The windows that close a torus's wrap go
//! by their fit alone. With both `spread` and a guide (a refined E-TFMCM tile following
//! its field: `synthesis::start::FIELD_QUILT`), the guide is one more term of the cost
//! of each of the `candidates` random origins, on the fit's scale, and the best is
//! taken, as without a guide.
//!
//! Windows are clipped at the output's edges, or, for a tile, laid round the torus:
//! spread evenly so that every gap is at most a step, each row's last window cut against
//! its first as well as its left neighbour, and the last row against the first as well
//! as the row above, so that the wrap is one more overlap, joined like the others.

use super::image::Image;
use crate::rng::Rng;

/// How a quilt is laid.
#[derive(Clone, Copy, Debug)]
pub struct Quilt {
    /// Window side (clamped to the exemplar's short side).
    pub side: usize,
    /// Random origins tried per window.
    pub candidates: usize,
    /// Weight of the coverage term (0: none). A window's cost is then its overlap's
    /// mean squared difference over the exemplar's (the mean squared difference of two
    /// of its pixels drawn at random), plus `spread` times how many times over the
    /// exemplar pixels under it are copied already, per the share each should copy
    /// (`reach`). Without it, a tile about the exemplar's size copies some regions two
    /// or three times and others never: the tile repeats and its colours drift from the
    /// exemplar's. (A guided quilt with no coverage term follows its guide alone; with
    /// one, the guide is a third term: see the module's doc.) The windows that close
    /// a torus's wrap leave the term out (see `lay`), and a window fitting worse than
    /// `MISFIT` is charged as if what it covers were copied its share already.
    pub spread: f32,
}

/// A guide for the quilt: the exemplar's guide at each of its positions, and the
/// target's at each output pixel, on one scale.
#[derive(Clone, Copy, Debug)]
pub struct QuiltGuide<'a> {
    pub exemplar: &'a [f32],
    pub target: &'a [f32],
    /// The guide term's weight against the overlap's colour difference (per pixel).
    pub weight: f32,
}

/// A guided window is drawn at random among the origins whose cost is within this share
/// of the least (Efros and Freeman's tolerance), so that seeds still vary the quilt and
/// ties (a flat guide, the first window) do not all go to the exemplar's top left.
const GUIDED_TOLERANCE: f32 = 0.1;
/// Pixel comparisons a guided quilt makes at most: on a large coarsest level (a chosen
/// `levels`, a thin exemplar) each window tries fewer origins (at least 16).
const GUIDED_BUDGET: usize = 50_000_000;

impl Default for Quilt {
    fn default() -> Self {
        Quilt { side: 16, candidates: 4, spread: 0.0 }
    }
}

impl Quilt {
    /// The window side for an exemplar `ew` x `eh`: at most half of it, so that windows
    /// come from places enough to differ; `None` when that is too small to quilt (under
    /// 4 pixels).
    pub fn window(&self, ew: usize, eh: usize) -> Option<usize> {
        let b = self.side.min(ew / 2).min(eh / 2);
        (b >= 4).then_some(b)
    }

    /// The window side for an output `lw` x `lh` from an exemplar `ew` x `eh`: on a
    /// torus also at most half the output's side, so that a window never meets itself
    /// across the wrap.
    pub fn window_for(&self, (ew, eh): (usize, usize), (lw, lh): (usize, usize), torus: bool) -> Option<usize> {
        let b = self.window(ew, eh)?;
        let b = if torus { b.min(lw / 2).min(lh / 2) } else { b };
        (b >= 4).then_some(b)
    }

    /// Exemplar positions (row major in `ex`) for an output `lw` x `lh`, or `None` when
    /// `window_for` is. With `allowed` (a sample mask), a window is drawn again (up to 16
    /// times) while its corners or centre are not allowed (guided, with every origin
    /// tried, those not allowed are skipped); positions it still holds that are not
    /// allowed are the caller's to replace. With `guide`, windows follow its target too,
    /// trying up to `candidates` origins and drawing among the near-best, or with
    /// `spread`, taking the best of `candidates` random ones (see the module's doc).
    pub fn lay(
        &self,
        ex: &Image,
        allowed: Option<&[bool]>,
        guide: Option<QuiltGuide>,
        (lw, lh): (usize, usize),
        torus: bool,
        rng: &mut Rng,
    ) -> Option<Vec<u32>> {
        let (ew, eh) = (ex.width, ex.height);
        let b = self.window_for((ew, eh), (lw, lh), torus)?;
        let o = b / 4;
        let step = b - o;
        const FREE: u32 = u32::MAX;
        let mut out = vec![FREE; lw * lh];
        let mut err = vec![0f32; b * b];
        let mut cells: Vec<(u32, u32, u32)> = Vec::with_capacity(b * b);
        let (mut row_e, mut row_g) = (vec![0f32; ew], vec![0f32; ew]);
        // Coverage: output pixels copying each exemplar pixel, and the scales of the
        // two terms (see `spread`).
        let mut uses = vec![0u32; if self.spread > 0.0 { ew * eh } else { 0 }];
        let share = (lw * lh) as f32 / (ew * eh) as f32;
        let reach = if self.spread > 0.0 { reach(ew, eh, b) } else { Vec::new() };
        let contrast = if self.spread > 0.0 { 2.0 * variance(ex) } else { 1.0 };
        // (The exemplar's channels apart, for a guided quilt's rows of origins.)
        let channels: [Vec<f32>; 3] = match guide {
            Some(_) => [0, 1, 2].map(|k| ex.data.iter().map(|p| p[k]).collect()),
            None => Default::default(),
        };
        let windows = lw.div_ceil(step) * lh.div_ceil(step);
        let guided_cap = (GUIDED_BUDGET / (windows * b * b).max(1)).max(16);
        let diff = |a: u32, p: u32| {
            let (c, d) = (ex.data[a as usize], ex.data[p as usize]);
            (0..3).map(|k| (c[k] - d[k]) * (c[k] - d[k])).sum::<f32>()
        };
        let pos = |(ox, oy): (usize, usize), dx: usize, dy: usize| ((oy + dy) * ew + ox + dx) as u32;
        let along =
            |len: usize, shift: usize| if torus { around(len, step, shift) } else { starts(len, b, step, shift) };
        // Round a torus the rows start anywhere too: rows from 0 would put the last
        // row's cut against the first just below the wrap, on every tile.
        let rows = along(lh, if torus { rng.below(step) } else { 0 });
        for (r, &y0) in rows.iter().enumerate() {
            let cols = along(lw, rng.below(step));
            for (k, &x0) in cols.iter().enumerate() {
                // The window's pixel (dx, dy) in the output, if inside (on a torus, always).
                let at = |dx: usize, dy: usize| -> Option<usize> {
                    let (x, y) = (x0 + dx as isize, y0 + dy as isize);
                    if torus {
                        Some(y.rem_euclid(lh as isize) as usize * lw + x.rem_euclid(lw as isize) as usize)
                    } else {
                        (x >= 0 && (x as usize) < lw && (y as usize) < lh).then(|| y as usize * lw + x as usize)
                    }
                };
                // The best of a few random origins by the squared difference over the
                // pixels laid already; guided, also by the guide's, per pixel, drawn at
                // random among those within `GUIDED_TOLERANCE` of the best.
                let inside = |o: (usize, usize)| {
                    allowed.is_none_or(|a| {
                        [(0, 0), (b - 1, 0), (0, b - 1), (b - 1, b - 1), (b / 2, b / 2)]
                            .iter()
                            .all(|&(dx, dy)| a[pos(o, dx, dy) as usize])
                    })
                };
                let (nx, ny) = (ew - b + 1, eh - b + 1);
                let random = |rng: &mut Rng| {
                    let mut origin = (rng.below(nx), rng.below(ny));
                    for _ in 0..16 {
                        if inside(origin) {
                            break;
                        }
                        origin = (rng.below(nx), rng.below(ny));
                    }
                    origin
                };
                // The window's pixels inside the output, found once for every origin tried:
                // each one's offset from the origin in the exemplar, its output pixel, and
                // the position laid there (`FREE` if none). (Found again for each origin,
                // a guided quilt's 625-1,024 tries were a sixth of a guided synthesis.)
                cells.clear();
                for dy in 0..b {
                    for dx in 0..b {
                        if let Some(i) = at(dx, dy) {
                            cells.push(((dy * ew + dx) as u32, i as u32, out[i]));
                        }
                    }
                }
                let overlap = cells.iter().filter(|c| c.2 != FREE).count() as f32;
                let cells = &cells;
                // A guided cost from its overlap's sum `e` and its guide's sum `g`.
                let guided =
                    |e: f32, g: f32, weight: f32| e / overlap.max(1.0) + weight * g / (cells.len() as f32).max(1.0);
                // An origin's sums over the overlap and (guided) over the guide.
                let sums = |origin: (usize, usize)| {
                    let base = pos(origin, 0, 0);
                    let e: f32 = cells.iter().filter(|c| c.2 != FREE).map(|&(d, _, laid)| diff(base + d, laid)).sum();
                    let g: f32 = guide.map_or(0.0, |gd| {
                        cells
                            .iter()
                            .map(|&(d, i, _)| {
                                let d = gd.exemplar[(base + d) as usize] - gd.target[i as usize];
                                d * d
                            })
                            .sum()
                    });
                    (e, g)
                };
                let cost = |origin: (usize, usize)| {
                    let (e, g) = sums(origin);
                    guide.map_or(e, |gd| guided(e, g, gd.weight))
                };
                // (With the coverage term, a guide is one more term of the cost: see
                // `spread`.)
                let origin = match guide.filter(|_| self.spread == 0.0) {
                    None => {
                        let mut best = (f32::INFINITY, (0, 0));
                        // The windows that close a torus's wrap (a row's last, and the last
                        // row) meet laid pixels on two to four sides: they are chosen by
                        // how they fit alone. With the term, they had paid what it still
                        // owed at the quilt's end; a photograph with a cloud bank cut off
                        // by its top edge (a feature with no top anywhere in it) had the
                        // bank laid along the wrap in a straight step no pass could mend,
                        // 27 times the mean row's difference at 600 x 600.
                        let closing = torus && (r + 1 == rows.len() || k + 1 == cols.len());
                        for _ in 0..self.candidates.max(1) {
                            let origin = random(rng);
                            let (sum, g) = sums(origin);
                            // (Both terms on the coverage term's scale: over the exemplar's
                            // contrast. Unguided and without it, the sum alone ranks.)
                            let fit = sum / overlap.max(1.0) / contrast.max(1e-6);
                            let led = guide
                                .map_or(0.0, |gd| gd.weight * g / (cells.len() as f32).max(1.0) / contrast.max(1e-6));
                            let mut e = if guide.is_some() { fit + led } else { sum };
                            if self.spread > 0.0 && !closing {
                                let base = pos(origin, 0, 0) as usize;
                                let under = (0..b).flat_map(|dy| (0..b).map(move |dx| base + dy * ew + dx));
                                let (used, owed) = under.fold((0u32, 0f32), |(u, o), p| (u + uses[p], o + reach[p]));
                                let over = used as f32 / (share * owed).max(1e-6);
                                // (A window that fits worse than `MISFIT` earns nothing for
                                // what it would cover that is owed.)
                                let over = if fit > MISFIT { over.max(1.0) } else { over };
                                e = fit + led + self.spread * over;
                            }
                            if e < best.0 {
                                best = (e, origin);
                            }
                        }
                        best.1
                    }
                    Some(gd) => {
                        let tries = self.candidates.min(guided_cap).max(1);
                        let mut costs: Vec<(f32, (usize, usize))> = if nx * ny <= tries {
                            // Every origin, a row of them at a time: each cell's terms for
                            // the row's origins lie side by side in the exemplar, a loop the
                            // compiler turns into SIMD (the same sums as `cost`'s, in the
                            // same order; origin by origin, this was 10% of a guided
                            // synthesis).
                            let mut costs = Vec::with_capacity(nx * ny);
                            for oy in 0..ny {
                                let (e, g) = (&mut row_e[..nx], &mut row_g[..nx]);
                                e.fill(0.0);
                                g.fill(0.0);
                                for &(d, i, laid) in cells.iter() {
                                    let start = oy * ew + d as usize;
                                    if laid != FREE {
                                        let c = ex.data[laid as usize];
                                        let [r, g, b] = [0, 1, 2].map(|k| &channels[k][start..start + nx]);
                                        for (acc, ((r, g), b)) in e.iter_mut().zip(r.iter().zip(g).zip(b)) {
                                            let (dr, dg, db) = (r - c[0], g - c[1], b - c[2]);
                                            *acc += dr * dr + dg * dg + db * db;
                                        }
                                    }
                                    let t = gd.target[i as usize];
                                    for (acc, &v) in g.iter_mut().zip(&gd.exemplar[start..start + nx]) {
                                        *acc += (v - t) * (v - t);
                                    }
                                }
                                costs.extend(
                                    (0..nx)
                                        .filter(|&ox| inside((ox, oy)))
                                        .map(|ox| (guided(e[ox], g[ox], gd.weight), (ox, oy))),
                                );
                            }
                            costs
                        } else {
                            (0..tries).map(|_| random(rng)).map(|o| (cost(o), o)).collect()
                        };
                        if costs.is_empty() {
                            // (No origin clear of the sample mask: one drawn as unguided.)
                            let o = random(rng);
                            costs.push((cost(o), o));
                        }
                        let least = costs.iter().map(|c| c.0).fold(f32::INFINITY, f32::min);
                        costs.retain(|c| c.0 <= least * (1.0 + GUIDED_TOLERANCE) + 1e-3);
                        costs[rng.below(costs.len())].1
                    }
                };
                for dy in 0..b {
                    for dx in 0..b {
                        err[dy * b + dx] = match at(dx, dy) {
                            Some(i) if out[i] != FREE => diff(pos(origin, dx, dy), out[i]),
                            _ => 0.0,
                        };
                    }
                }
                // A cut through each side that meets laid pixels: the left one (every
                // window but a row's first) and the top one (every row but the first);
                // on a torus also the right one (a row's last window meets its first)
                // and the bottom one (the last row meets the first). Each gives, per row
                // or column, how far in the old side reaches.
                let none = || vec![0; b];
                let left = if k > 0 { cut(b, o, |t, j| err[t * b + j]) } else { none() };
                let top = if r > 0 { cut(b, o, |t, j| err[j * b + t]) } else { none() };
                let right =
                    if torus && k + 1 == cols.len() { cut(b, o, |t, j| err[t * b + b - 1 - j]) } else { none() };
                let bottom =
                    if torus && r + 1 == rows.len() { cut(b, o, |t, j| err[(b - 1 - j) * b + t]) } else { none() };
                for dy in 0..b {
                    for dx in 0..b {
                        let new =
                            dx >= left[dy] && dy >= top[dx] && b - 1 - dx >= right[dy] && b - 1 - dy >= bottom[dx];
                        match at(dx, dy) {
                            Some(i) if out[i] == FREE || new => {
                                let p = pos(origin, dx, dy);
                                if !uses.is_empty() {
                                    if out[i] != FREE {
                                        uses[out[i] as usize] -= 1;
                                    }
                                    uses[p as usize] += 1;
                                }
                                out[i] = p;
                            }
                            _ => {}
                        }
                    }
                }
            }
        }
        debug_assert!(out.iter().all(|&p| p != FREE));
        Some(out)
    }
}

/// How badly a window may fit and still earn the coverage term's credit for copying
/// what is owed: its overlap's mean squared difference over that of two exemplar pixels
/// drawn at random. The term is to choose among windows that fit, not to lay one that
/// does not: a cloud bank cut off by a sky's top edge is owed its share but fits under
/// nothing, and was laid inside tiles in flat-topped blobs (a synthetic sky, seeds 1-8
/// at 256: a row step over 8 times the median row's on 2 seeds, 21 and 15 times; with
/// this, on 1, 11 times). At 1 the blobs went entirely, but tiles of photographs lost
/// colour (marble 0.156 from the photograph, the peer's 0.095; examples/tile_quality);
/// at 1.5 the sixteen held-out exemplars' figures moved within a seed's spread (brick's
/// wrap 0.67 -> 0.85, clouds' and wisps' colour 0.156 -> 0.172, 0.094 -> 0.117).
const MISFIT: f32 = 1.5;

/// The share of the copies each exemplar pixel should take (mean 1): the square root
/// of how many windows of side `b` hold it, over the mean. Windows drawn at random
/// copy the exemplar's middle more than its edges (a pixel at a corner lies in one
/// window of its row, one in the middle in `b`); the term evens that out only halfway.
/// Pressed to copy the edges as often as the middle, a tile laid the exemplar's edges
/// where nothing in the exemplar meets them (a cloud bank cut off by a photograph's top
/// edge, in flat-topped blobs); with the edges' plain share (no root), a tile took too
/// few of them: marble's colour 0.139 from the photograph against the peer's 0.095
/// (examples/tile_quality, seeds 1-8, before `MISFIT`; with the root 0.123, and 13 of
/// the 16 held-out exemplars at most the peer's colour distance against 12).
fn reach(ew: usize, eh: usize, b: usize) -> Vec<f32> {
    // Windows holding column x of a side n long: origins max(0, x + 1 - b) ..= min(x, n - b).
    debug_assert!(b <= ew.min(eh), "window {b} larger than the exemplar {ew}x{eh}");
    let holding = |x: usize, n: usize| (x.min(n - b) + 1 - (x + 1).saturating_sub(b)) as f32;
    let root: Vec<f32> = (0..ew * eh).map(|i| (holding(i % ew, ew) * holding(i / ew, eh)).sqrt()).collect();
    let mean = root.iter().sum::<f32>() / root.len().max(1) as f32;
    root.iter().map(|r| r / mean).collect()
}

/// The colour channels' variances, summed: half the mean squared difference between
/// two pixels of `ex` drawn at random.
fn variance(ex: &Image) -> f32 {
    let n = ex.data.len().max(1) as f64;
    (0..3)
        .map(|k| {
            let mean = ex.data.iter().map(|p| p[k] as f64).sum::<f64>() / n;
            ex.data.iter().map(|p| (p[k] as f64 - mean).powi(2)).sum::<f64>() / n
        })
        .sum::<f64>() as f32
}

/// Where the windows of side `b` start along a side of length `len`: `step` apart from
/// `-shift` on, until the side is covered.
fn starts(len: usize, b: usize, step: usize, shift: usize) -> Vec<isize> {
    let mut v = vec![-(shift as isize)];
    while let Some(&x) = v.last().filter(|&&x| x + (b as isize) < len as isize) {
        v.push(x + step as isize);
    }
    v
}

/// Where `n` windows start round a torus side of length `len`, from `shift` on, spread
/// evenly with `n` the fewest that leave no gap over `step` (so every overlap, the one
/// across the wrap too, is at least the window side less `step`).
fn around(len: usize, step: usize, shift: usize) -> Vec<isize> {
    let n = len.div_ceil(step);
    (0..n).map(|k| (shift + (k * len + n / 2) / n) as isize).collect()
}

/// The least-difference cut through an overlap strip `o` wide along a window side `b`
/// long, whose squared differences are `e(t, k)` at step `t` along the side and depth
/// `k` into the window (dynamic programming, moving at most one pixel sideways per
/// step): for each step, the depth from which the new window's pixels are kept.
fn cut(b: usize, o: usize, e: impl Fn(usize, usize) -> f32) -> Vec<usize> {
    let mut cost = vec![0f32; b * o];
    let cheapest = |cost: &[f32], t: usize, k: usize| {
        let (lo, hi) = (k.saturating_sub(1), (k + 1).min(o - 1));
        (lo..=hi).min_by(|&i, &j| cost[t * o + i].total_cmp(&cost[t * o + j])).unwrap_or(k)
    };
    for t in 0..b {
        for k in 0..o {
            let prev = if t == 0 { 0.0 } else { cost[(t - 1) * o + cheapest(&cost, t - 1, k)] };
            cost[t * o + k] = e(t, k) + prev;
        }
    }
    // Back from the cheapest end; the cut pixel itself goes to the new window.
    let mut path = vec![0; b];
    let mut k = (0..o).min_by(|&i, &j| cost[(b - 1) * o + i].total_cmp(&cost[(b - 1) * o + j])).unwrap_or(0);
    for t in (0..b).rev() {
        path[t] = k;
        if t > 0 {
            k = cheapest(&cost, t - 1, k);
        }
    }
    path
}

#[cfg(test)]
mod tests {
    use super::*;

    fn gradient(w: usize, h: usize) -> Image {
        let mut img = Image::new(w, h);
        for y in 0..h {
            for x in 0..w {
                img.data[y * w + x] = [x as f32 * 4.0, y as f32 * 4.0, ((x * 7 + y * 13) % 64) as f32];
            }
        }
        img
    }

    #[test]
    fn every_pixel_copies_a_position_and_neighbours_mostly_continue() {
        let ex = gradient(32, 32);
        let (lw, lh) = (70, 45);
        let q = Quilt::default().lay(&ex, None, None, (lw, lh), false, &mut Rng::new(3)).unwrap();
        assert_eq!(q.len(), lw * lh);
        assert!(q.iter().all(|&p| (p as usize) < 32 * 32));
        // Inside a window the right neighbour copies the next exemplar pixel; windows are
        // 16 wide, so at least 3 in 4 horizontal pairs continue.
        let continued = (0..lh)
            .flat_map(|y| (0..lw - 1).map(move |x| (x, y)))
            .filter(|&(x, y)| q[y * lw + x + 1] == q[y * lw + x] + 1)
            .count();
        assert!(continued * 4 >= 3 * lh * (lw - 1), "{continued} of {}", lh * (lw - 1));
    }

    #[test]
    fn a_torus_quilt_continues_across_the_wrap() {
        // Laid round the torus, the pixels either side of the wrap are as often one
        // window's neighbours as either side of any row or column (a cut may fall on
        // the wrap as on any line); clipped, they never are. Means over eight seeds.
        let ex = gradient(64, 64);
        let (lw, lh) = (72, 40);
        let across = |q: &[u32]| {
            let right = (0..lh).filter(|&y| q[y * lw] == q[y * lw + lw - 1] + 1).count();
            let down = (0..lw).filter(|&x| q[x] == q[(lh - 1) * lw + x] + 64).count();
            (right as f64 / lh as f64, down as f64 / lw as f64)
        };
        let (mut torus, mut clipped) = ((0.0, 0.0), (0.0, 0.0));
        for seed in 1..=8 {
            let q = Quilt::default().lay(&ex, None, None, (lw, lh), true, &mut Rng::new(seed)).unwrap();
            assert!(q.iter().all(|&p| (p as usize) < 64 * 64));
            let (r, d) = across(&q);
            torus = (torus.0 + r / 8.0, torus.1 + d / 8.0);
            let q = Quilt::default().lay(&ex, None, None, (lw, lh), false, &mut Rng::new(seed)).unwrap();
            let (r, d) = across(&q);
            clipped = (clipped.0 + r / 8.0, clipped.1 + d / 8.0);
        }
        assert!(torus.0 >= 0.5 && torus.1 >= 0.5, "across the wrap {torus:?}");
        assert!(clipped.0 < 0.2 && clipped.1 < 0.2, "clipped {clipped:?}");
        // A window never meets itself: on a 20 px torus it is at most 10.
        assert_eq!(Quilt::default().window_for((64, 64), (20, 40), true), Some(10));
        assert_eq!(Quilt::default().window_for((64, 64), (6, 40), true), None);
    }

    #[test]
    fn the_cut_follows_the_cheapest_path() {
        // A 4 x 4 window with a 2-column strip: column 1 is free in rows 0-1, column 0 in 2-3.
        let mut err = [9.0; 16];
        for (t, k) in [(0, 1), (1, 1), (2, 0), (3, 0)] {
            err[t * 4 + k] = 0.0;
        }
        assert_eq!(cut(4, 2, |t, k| err[t * 4 + k]), vec![1, 1, 0, 0]);
        // Mirrored: the same path in from the right side.
        assert_eq!(cut(4, 2, |t, k| err[t * 4 + 1 - k]), vec![0, 0, 1, 1]);
    }

    #[test]
    fn windows_are_at_most_half_the_exemplar() {
        assert_eq!(Quilt::default().window(32, 40), Some(16));
        assert_eq!(Quilt::default().window(20, 64), Some(10));
        assert_eq!(Quilt::default().window(6, 64), None);
    }

    /// An exemplar dark on its left and bright on its right, with its guide lane (the
    /// same grey on the synthesis's scale at weight 2, sqrt 6 times the colours), and a
    /// target guide the other way round.
    fn swapped(side: usize, out: usize) -> (Image, Vec<f32>, Vec<f32>) {
        let mut ex = Image::new(side, side);
        let mut rng = Rng::new(4);
        for (i, p) in ex.data.iter_mut().enumerate() {
            *p = [if i % side < side / 2 { 20.0 } else { 200.0 } + rng.below(20) as f32; 3];
        }
        let bright = 180.0 * 6f32.sqrt();
        let lane = (0..side * side).map(|i| if i % side < side / 2 { 0.0 } else { bright }).collect();
        let target = (0..out * out).map(|i| if i % out < out / 2 { bright } else { 0.0 }).collect();
        (ex, lane, target)
    }

    #[test]
    fn a_guided_quilt_lays_its_windows_where_the_target_asks() {
        // Guided, the output's left copies the exemplar's right: with every origin tried
        // (a 32-pixel exemplar, 4-pixel windows: 841) and with 1,024 drawn at random.
        for (side, b) in [(32, 4), (64, 8)] {
            let (ex, lane, target) = swapped(side, 128);
            let guide = QuiltGuide { exemplar: &lane, target: &target, weight: 4.0 };
            let quilt = Quilt { side: b, candidates: 1024, spread: 0.0 };
            let follows = |q: &[u32]| {
                (0..128 * 128).filter(|&i| (q[i] as usize % side >= side / 2) == (i % 128 < 64)).count() as f64
                    / (128.0 * 128.0)
            };
            let q = quilt.lay(&ex, None, Some(guide), (128, 128), false, &mut Rng::new(1)).unwrap();
            assert!(follows(&q) > 0.9, "{} of the pixels follow the target", follows(&q));
            // Another seed lays other windows.
            let other = quilt.lay(&ex, None, Some(guide), (128, 128), false, &mut Rng::new(2)).unwrap();
            let same = q.iter().zip(&other).filter(|(a, b)| a == b).count();
            assert!(same * 4 < q.len(), "{same} of {} pixels alike across seeds", q.len());
            let q = Quilt { side: b, candidates: 4, spread: 0.0 }
                .lay(&ex, None, None, (128, 128), false, &mut Rng::new(1))
                .unwrap();
            assert!(follows(&q) < 0.7, "{} without the guide", follows(&q));
        }
        // A sample mask that leaves no window clear: still a whole quilt.
        let (ex, lane, target) = swapped(32, 64);
        let allowed: Vec<bool> = (0..32 * 32).map(|i| i % 3 == 0).collect();
        let guide = QuiltGuide { exemplar: &lane, target: &target, weight: 4.0 };
        let q = Quilt { side: 4, candidates: 1024, spread: 0.0 }.lay(
            &ex,
            Some(&allowed),
            Some(guide),
            (64, 64),
            true,
            &mut Rng::new(1),
        );
        assert!(q.is_some_and(|q| q.len() == 64 * 64 && q.iter().all(|&p| p < 32 * 32)));
    }

    #[test]
    fn the_layout_keeps_the_exemplars_proportions() {
        // Left half dark and smooth, right half bright and noisy: a quilt of 16-wide
        // windows from a 64 px exemplar copies about as much of each half.
        let mut ex = Image::new(64, 64);
        let mut rng = Rng::new(9);
        for y in 0..64 {
            for x in 0..64 {
                ex.data[y * 64 + x] = if x < 32 { [20.0; 3] } else { [rng.below(256) as f32; 3] };
            }
        }
        let q = Quilt::default().lay(&ex, None, None, (128, 128), false, &mut Rng::new(1)).unwrap();
        let left = q.iter().filter(|&&p| (p % 64) < 32).count() as f64 / q.len() as f64;
        assert!((0.3..0.7).contains(&left), "left share {left}");
    }

    #[test]
    fn the_coverage_term_copies_the_exemplar_as_it_should() {
        // A tile three times the exemplar's side from 8-pixel windows of a 16-pixel
        // exemplar of noise (no origin's overlap matches better than another's): in
        // quarters of the exemplar side, how often each of its sixteen squares is copied
        // against the share `reach` gives it, over 32 seeds. Random origins favour the
        // middle, which more windows cover (without the term, squares are copied 0.14
        // to 2.79 times an even share, 0.25 to 1.80 times their own); the term takes
        // every square to 0.38-1.50 times its own.
        let mut ex = Image::new(16, 16);
        let mut rng = Rng::new(5);
        ex.data.iter_mut().for_each(|p| *p = [rng.below(256) as f32; 3]);
        const N: usize = 48;
        let owed = reach(16, 16, 8);
        let shares = |quilt: Quilt| {
            let (mut copied, mut due) = ([0.0f64; 16], [0.0f64; 16]);
            for seed in 1..=32 {
                for p in quilt.lay(&ex, None, None, (N, N), true, &mut Rng::new(seed)).unwrap() {
                    let (x, y) = (p as usize % 16, p as usize / 16);
                    copied[x / 4 + 4 * (y / 4)] += 1.0;
                }
            }
            for (p, r) in owed.iter().enumerate() {
                due[p % 16 / 4 + 4 * (p / 16 / 4)] += *r as f64 * (32 * N * N) as f64 / 256.0;
            }
            let ratios: Vec<f64> = copied.iter().zip(&due).map(|(c, d)| c / d).collect();
            (ratios.iter().copied().fold(f64::INFINITY, f64::min), ratios.iter().copied().fold(0.0, f64::max))
        };
        let (least, most) = shares(Quilt { side: 16, candidates: 4, spread: 0.0 });
        println!("without: {least:.2}-{most:.2}");
        assert!(least < 0.3 && most > 1.7, "without: {least:.2}-{most:.2}");
        let (least, most) = shares(Quilt { side: 16, candidates: 8, spread: 3.0 });
        println!("with: {least:.2}-{most:.2}");
        assert!(least > 0.33 && most < 1.6, "with: {least:.2}-{most:.2}");
    }
}
