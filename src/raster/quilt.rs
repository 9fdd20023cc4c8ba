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
//! The quilt is not tileable: windows are clipped at the output's edges.

use super::image::Image;
use crate::rng::Rng;

/// How a quilt is laid.
#[derive(Clone, Copy, Debug)]
pub struct Quilt {
    /// Window side (clamped to the exemplar's short side).
    pub side: usize,
    /// Random origins tried per window.
    pub candidates: usize,
}

impl Default for Quilt {
    fn default() -> Self {
        Quilt { side: 16, candidates: 4 }
    }
}

impl Quilt {
    /// Exemplar positions (row major in `ex`) for an output `lw` x `lh`.
    pub fn lay(&self, ex: &Image, lw: usize, lh: usize, rng: &mut Rng) -> Vec<u32> {
        let (ew, eh) = (ex.width, ex.height);
        let b = self.side.min(ew).min(eh);
        if b < 4 {
            // Too small an exemplar to quilt: noise.
            return (0..lw * lh).map(|_| rng.below(ew * eh) as u32).collect();
        }
        let o = b / 4;
        let step = b - o;
        const FREE: u32 = u32::MAX;
        let mut out = vec![FREE; lw * lh];
        let mut err = vec![0f32; b * b];
        let mut y0 = 0usize;
        loop {
            let shift = rng.below(step) as isize;
            let mut x0 = -shift;
            let mut first = true;
            while x0 < lw as isize {
                let has_left = !first;
                let has_top = y0 > 0;
                // The window's pixels inside the output, as (dx, dy) -> output index.
                let at = |dx: usize, dy: usize| -> Option<usize> {
                    let (x, y) = (x0 + dx as isize, y0 + dy);
                    (x >= 0 && (x as usize) < lw && y < lh).then(|| y * lw + x as usize)
                };
                let overlap = |dx: usize, dy: usize| (has_left && dx < o) || (has_top && dy < o);
                let diff = |a: u32, p: u32| {
                    let (c, d) = (ex.data[a as usize], ex.data[p as usize]);
                    (0..3).map(|k| (c[k] - d[k]) * (c[k] - d[k])).sum::<f32>()
                };
                let pos = |(ox, oy): (usize, usize), dx: usize, dy: usize| ((oy + dy) * ew + ox + dx) as u32;
                // The best of a few random origins by the overlap's squared difference.
                let mut best = (f32::INFINITY, (0, 0));
                for _ in 0..self.candidates.max(1) {
                    let origin = (rng.below(ew - b + 1), rng.below(eh - b + 1));
                    let mut e = 0.0;
                    for dy in 0..b {
                        for dx in 0..b {
                            if let (true, Some(i)) = (overlap(dx, dy), at(dx, dy)) {
                                if out[i] != FREE {
                                    e += diff(pos(origin, dx, dy), out[i]);
                                }
                            }
                        }
                    }
                    if e < best.0 {
                        best = (e, origin);
                    }
                }
                let origin = best.1;
                for dy in 0..b {
                    for dx in 0..b {
                        err[dy * b + dx] = match at(dx, dy) {
                            Some(i) if out[i] != FREE => diff(pos(origin, dx, dy), out[i]),
                            _ => 0.0,
                        };
                    }
                }
                // The cuts: per row, the first column that is new; per column, the first row.
                let left = if has_left { cut(&err, b, o, false) } else { vec![0; b] };
                let top = if has_top { cut(&err, b, o, true) } else { vec![0; b] };
                for (dy, &l) in left.iter().enumerate() {
                    for (dx, &t) in top.iter().enumerate() {
                        if let Some(i) = at(dx, dy) {
                            if out[i] == FREE || (dx >= l && dy >= t) {
                                out[i] = pos(origin, dx, dy);
                            }
                        }
                    }
                }
                first = false;
                x0 += step as isize;
            }
            // The next row's top overlap starts where this row's windows end minus `o`.
            if y0 + b >= lh {
                break;
            }
            y0 += step;
        }
        debug_assert!(out.iter().all(|&p| p != FREE));
        out
    }
}

/// The least-difference cut through the overlap strip of a `b` x `b` window's squared
/// differences `err` (row major): the first `o` columns (`horizontal` false), giving for
/// each row the first column on the new side; or the first `o` rows, giving for each
/// column the first row on the new side.
fn cut(err: &[f32], b: usize, o: usize, horizontal: bool) -> Vec<usize> {
    // e(t, k): the error at step t along the strip, offset k across it.
    let e = |t: usize, k: usize| if horizontal { err[k * b + t] } else { err[t * b + k] };
    let mut cost = vec![0f32; b * o];
    for t in 0..b {
        for k in 0..o {
            let prev = if t == 0 {
                0.0
            } else {
                let lo = k.saturating_sub(1);
                let hi = (k + 1).min(o - 1);
                (lo..=hi).map(|j| cost[(t - 1) * o + j]).fold(f32::INFINITY, f32::min)
            };
            cost[t * o + k] = e(t, k) + prev;
        }
    }
    // Back from the cheapest end; the cut pixel itself goes to the new window.
    let mut path = vec![0; b];
    let mut k = (0..o).min_by(|&i, &j| cost[(b - 1) * o + i].total_cmp(&cost[(b - 1) * o + j])).unwrap_or(0);
    for t in (0..b).rev() {
        path[t] = k;
        if t > 0 {
            let lo = k.saturating_sub(1);
            let hi = (k + 1).min(o - 1);
            k = (lo..=hi).min_by(|&i, &j| cost[(t - 1) * o + i].total_cmp(&cost[(t - 1) * o + j])).unwrap_or(k);
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
        let q = Quilt::default().lay(&ex, lw, lh, &mut Rng::new(3));
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
    fn the_cut_follows_the_cheapest_path() {
        // A 4 x 4 window with a 2-column strip: column 1 is free in rows 0-1, column 0 in 2-3.
        let mut err = vec![9.0; 16];
        for (t, k) in [(0, 1), (1, 1), (2, 0), (3, 0)] {
            err[t * 4 + k] = 0.0;
        }
        assert_eq!(cut(&err, 4, 2, false), vec![1, 1, 0, 0]);
        // Transposed: the same path across the top rows.
        let mut tr = vec![0.0; 16];
        for y in 0..4 {
            for x in 0..4 {
                tr[x * 4 + y] = err[y * 4 + x];
            }
        }
        assert_eq!(cut(&tr, 4, 2, true), vec![1, 1, 0, 0]);
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
        let q = Quilt::default().lay(&ex, 128, 128, &mut Rng::new(1));
        let left = q.iter().filter(|&&p| (p % 64) < 32).count() as f64 / q.len() as f64;
        assert!((0.3..0.7).contains(&left), "left share {left}");
    }
}
