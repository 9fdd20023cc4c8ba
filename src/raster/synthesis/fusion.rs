//! Gradient-domain fusion of the finest level's seams (not in Wei and Levoy: the
//! gradient-domain compositing of Pérez et al. 2003 and Agarwala et al. 2004, screened).
//!
//! Where two neighbouring output pixels copy neighbouring exemplar pixels, their colour
//! difference is the exemplar's own; where they do not (a seam between two copied
//! pieces), it is whatever the pieces happen to be, and on soft exemplars (cloud, smoke,
//! plaster) a step shows as a straight shard edge. Fusion asks each edge between
//! neighbours for a target difference `g`: the exemplar's own where the pixels were
//! copied side by side, and across a seam the mean of the differences each source sees
//! in that direction in the exemplar (those that stay inside it and on allowed
//! positions). The output is the image `I` nearest the copied colours `C` whose
//! differences are nearest `g`:
//!
//! `min sum_edges (I_q - I_p - g_pq)^2 + lambda sum_p (I_p - C_p)^2`
//!
//! whose normal equations for the change `d = I - C` are
//! `(4 + lambda) d_p - sum_q d_q = sum_q ((C_q - C_p) - g_pq)`, the right side non-zero
//! only beside seams. The screen `lambda` keeps the colours: a change fades within about
//! `1 / sqrt(lambda)` pixels (2.2 at `LAMBDA`), so over-relaxed Gauss-Seidel settles in
//! `SWEEPS`, and a band of rows can be fused on its own with the rows beyond it as they
//! were copied (the banded schedule fuses band by band, whoever runs the bands).
//!
//! Measured (issue 25): tiles at 128 of the sixteen held-out photographs of
//! `bench/heldout-data.sh` (examples/tile_quality, seeds 1-3, each against itself
//! unfused): patch energy lower on all sixteen, by 4-22% (fire 1.08 -> 0.84, mist 2.13
//! -> 1.68, clouds 2.85 -> 2.39, brick 8.72 -> 7.90), colour distance at most 0.009
//! further; over seeds 1-8 against texture-synthesis 0.8.3's `--tiling` the synthesis
//! tile's energy is at or below the peer's on 14 of 16 (from 12; fire 1.14x, mist
//! 1.03x) and the refined E-TFMCM tile's on all 16, the seams still 0.8-1.2 but brick's
//! 0.76. On the ten fixtures (examples/seam_blend_probe) it fell on all ten, 4-17%.
//! Lambda 0.1 and 0.3 gave the same within 0.02, 0.02 and 0.5 a little more; the cost
//! is about a twelfth of a synthesis (wasm SIMD, 256 x 256 from 128: 80 ms against 74
//! unfused on 2026-12-03, 94 against 83 before the sweeps' steps were reordered, see
//! `relaxed`).
//!
//! The output then takes back the copied colours' distribution (`Keep`), counted over
//! the whole output, or, when it is coloured band by band, over strips spread down it
//! that every band reads alike (`Job::keep`). Measured on the sixteen (seeds 1-8, tiles
//! at 128): colour distance lower on 13 of them by synthesis, the same on 2 and 0.001
//! higher on roof (plaster 0.039 -> 0.030, bark 0.059 -> 0.053, sand 0.033 -> 0.027;
//! the peer's 0.025, 0.140, 0.059), and lower on 15 by refined E-TFMCM (fire the same),
//! at most the peer's on all sixteen (plaster 0.033 -> 0.024); patch energy up by at
//! most 2% (clouds 1.91 -> 1.95, the peer's 2.21).

use super::exemplar::Plane;
use crate::raster::image::Image;

/// An exemplar of at most this many colours is a palette (pixel art, flat line art):
/// its outputs keep to its colours exactly, unfused.
pub(crate) const PALETTE: usize = 64;

/// Whether fusion may run (always, but for a probe's `PATTERNSYNTH_FUSE=0`, which
/// measures outputs as before it).
pub(crate) fn probed() -> bool {
    !(cfg!(feature = "test-support") && std::env::var("PATTERNSYNTH_FUSE").is_ok_and(|v| v == "0"))
}

/// Whether `image` has at most `PALETTE` colours where `allowed` (if given) lets it be
/// copied (a pool's gutters are filled smoothly, and never copied).
pub(crate) fn palette(image: &Image, allowed: Option<&[bool]>) -> bool {
    // (A sorted list of at most PALETTE + 1: no hash table in the texture module.)
    let mut seen: Vec<[u32; 3]> = Vec::with_capacity(PALETTE + 1);
    let copied = |i: &usize| allowed.is_none_or(|a| a[*i]);
    for p in (0..image.data.len()).filter(copied).map(|i| image.data[i].map(f32::to_bits)) {
        if let Err(at) = seen.binary_search(&p) {
            seen.insert(at, p);
            if seen.len() > PALETTE {
                return false;
            }
        }
    }
    true
}

/// The screen towards the copied colours.
pub(crate) const LAMBDA: f32 = 0.2;
/// Over-relaxed Gauss-Seidel sweeps, and the over-relaxation: for the screened
/// operator (diagonal 4.2) Jacobi's spectral radius is 4 / 4.2, whence the optimal
/// factor 2 / (1 + sqrt(1 - (4 / 4.2)^2)) = 1.53, which takes the error down about
/// 0.53 a sweep (plain Gauss-Seidel 0.91). Ten sweeps gave the energies of 200 plain
/// ones within 0.01 on the 26 photographs.
pub(crate) const SWEEPS: usize = 10;
const OVER_RELAXATION: f32 = 1.5;
/// Rows fused beside a band on each side (`Job::fused_band`): a change fades about
/// 0.44 a pixel (the screened operator's decay, `acosh(1 + lambda / 2)`), so 16 rows
/// away it is 0.001 of the step that made it.
pub(crate) const HALO: usize = 16;

/// The fused colours of `rows` output rows of `width` pixels copied from `plane` by
/// `src` (row-major, top first). `torus`: the rows are the whole output, read on the
/// torus; otherwise a band, whose rows above and below keep their copied colours.
pub(crate) fn fuse(plane: &Plane, src: &[u32], width: usize, rows: usize, torus: bool) -> Vec<[f32; 3]> {
    debug_assert_eq!(src.len(), width * rows);
    let colour = |p: u32| {
        let c = plane.data[p as usize];
        [c[0], c[1], c[2]]
    };
    let copied: Vec<[f32; 3]> = src.iter().map(|&p| colour(p)).collect();
    let n = width * rows;
    // The residual (C_q - C_p) - g_pq of each edge to the right and downwards, summed
    // into the right side of both its pixels. (Four lanes, the fourth 0, as in `lanes`:
    // the sweeps' arithmetic is then one vector operation a pixel, in wasm SIMD too.)
    let mut rhs = vec![[0.0f32; 4]; n];
    let mut any = false;
    let down_edges = if torus { rows } else { rows.saturating_sub(1) };
    let mut edge = |p: usize, q: usize, step: (isize, isize)| {
        if let Some(g) = target(plane, src[p], src[q], step) {
            for c in 0..3 {
                let r = (copied[q][c] - copied[p][c]) - g[c];
                rhs[p][c] += r;
                rhs[q][c] -= r;
            }
            any = true;
        }
    };
    for y in 0..rows {
        let row = y * width;
        for x in 0..width {
            edge(row + x, row + if x + 1 < width { x + 1 } else { 0 }, (1, 0));
        }
        if y < down_edges {
            let below = if y + 1 < rows { row + width } else { 0 };
            (0..width).for_each(|x| edge(row + x, below + x, (0, 1)));
        }
    }
    if !any {
        return copied;
    }
    // The change, with one more row of zeros: the neighbours beyond a band's edges.
    let mut d = vec![[0.0f32; 4]; n + width];
    for _ in 0..SWEEPS {
        for y in 0..rows {
            let row = y * width;
            let up = if y > 0 {
                row - width
            } else if torus {
                n - width
            } else {
                n
            };
            let down = if y + 1 < rows {
                row + width
            } else if torus {
                0
            } else {
                n
            };
            let mut at = |x: usize, l: usize, r: usize| {
                let p = row + x;
                d[p] = relaxed(rhs[p], [d[l], d[r], d[up + x], d[down + x]], d[p]);
            };
            if width == 1 {
                at(0, row, row);
                continue;
            }
            at(0, row + width - 1, row + 1);
            for x in 1..width - 1 {
                at(x, row + x - 1, row + x + 1);
            }
            at(width - 1, row + width - 2, row);
        }
    }
    copied.iter().zip(&d).map(|(c, d)| std::array::from_fn(|k| c[k] + d[k])).collect()
}

/// One over-relaxed Gauss-Seidel step at a pixel whose right side is `rhs`, its four
/// neighbours' changes `around` (left, right, up, down) and its own `old`:
/// `old + omega ((rhs + sum around) / (4 + lambda) - old)`, the same arithmetic in each
/// lane, written so that the left neighbour, made by the step before, comes in last:
/// a row's steps wait on one another only through a multiply and an add, not through
/// four adds and a division (natively the sweeps took a tenth of a 256 x 256
/// synthesis, a twentieth after). The change differs from the other order's within
/// rounding: the outputs hashed (plain and tiled, 201 to 600) kept every byte; a
/// review's 118 outputs kept all but 4 bytes in 2 of them, each 1 off.
#[inline(always)]
fn relaxed(rhs: [f32; 4], around: [[f32; 4]; 4], old: [f32; 4]) -> [f32; 4] {
    const STEP: f32 = OVER_RELAXATION / (4.0 + LAMBDA);
    let [l, r, u, v] = around;
    std::array::from_fn(|c| ((1.0 - OVER_RELAXATION) * old[c] + STEP * (rhs[c] + r[c] + u[c] + v[c])) + STEP * l[c])
}

/// Steps per colour unit of `Keep`'s histograms, and their lowest value: fused colours
/// may leave 0-255 a little before they are rounded.
const LEVELS: f32 = 64.0;
const LOWEST: f32 = -256.0;
const BINS: usize = 768 * LEVELS as usize;

fn bin(v: f32) -> usize {
    (((v - LOWEST) * LEVELS) as usize).min(BINS - 1)
}

/// How a fused output's colours are given back its copied colours' distribution, rank
/// for rank, channel by channel (histogram matching, in steps of 1/`LEVELS`): fusion
/// then moves where colours are, not which colours there are. Why: at a seam the
/// largest steps are where a copied pixel is extreme, so fusion pulls the extremes in,
/// and on fine-grained photographs, which are seams everywhere, the tile lost contrast:
/// plaster's colour distance from the photograph 0.039 fused against 0.030 copied
/// (texture-synthesis 0.8.3's 0.025). The map is monotone and the same for every pixel,
/// so the seams fusion hid stay hidden.
pub struct Keep {
    /// Per channel, the value each fused bin takes.
    map: [Vec<f32>; 3],
}

impl Keep {
    /// A fused colour, mapped.
    pub(crate) fn applied(&self, c: [f32; 3]) -> [f32; 3] {
        std::array::from_fn(|k| self.map[k][bin(c[k])])
    }
}

/// Copied and fused colours counted over some rows, channel by channel, for a `Keep`.
pub(crate) struct Shares {
    copied: [Vec<u32>; 3],
    fused: [Vec<u32>; 3],
}

impl Shares {
    pub fn new() -> Shares {
        let zeros = || std::array::from_fn(|_| vec![0u32; BINS]);
        Shares { copied: zeros(), fused: zeros() }
    }

    /// The same pixels' copied and fused colours, counted.
    pub fn of(copied: impl Iterator<Item = [f32; 3]>, fused: impl Iterator<Item = [f32; 3]>) -> Shares {
        let mut shares = Shares::new();
        shares.add(copied, fused);
        shares
    }

    /// Counts the same pixels' copied and fused colours.
    pub fn add(&mut self, copied: impl Iterator<Item = [f32; 3]>, fused: impl Iterator<Item = [f32; 3]>) {
        for c in copied {
            (0..3).for_each(|k| self.copied[k][bin(c[k])] += 1);
        }
        for c in fused {
            (0..3).for_each(|k| self.fused[k][bin(c[k])] += 1);
        }
    }

    /// Each fused bin's pixels take the copied value at their middle rank (walking both
    /// histograms once).
    pub fn keep(&self) -> Keep {
        let map = std::array::from_fn(|k| {
            let (want, have) = (&self.copied[k], &self.fused[k]);
            let mut map = vec![0f32; BINS];
            let (mut below, mut w, mut seen) = (0u64, 0usize, 0u64);
            for (b, &n) in have.iter().enumerate() {
                if n == 0 {
                    continue;
                }
                let middle = 2 * below + u64::from(n); // twice the middle rank, for odd counts
                while w + 1 < BINS && 2 * (seen + u64::from(want[w])) <= middle {
                    seen += u64::from(want[w]);
                    w += 1;
                }
                map[b] = LOWEST + w as f32 / LEVELS;
                below += u64::from(n);
            }
            fill(&mut map, have);
            map
        });
        Keep { map }
    }
}

/// The target difference from an output pixel copied from `a` to its neighbour one
/// `step` on, copied from `b`: `None` where they were copied side by side (the
/// exemplar's own difference, which the copies already have), else the mean of the
/// differences `a` sees one step on and `b` one step back, where those stay inside the
/// exemplar and on allowed positions (if neither does, the copies' own: no change).
fn target(plane: &Plane, a: u32, b: u32, step: (isize, isize)) -> Option<[f32; 3]> {
    let (w, h) = (plane.width as isize, plane.height as isize);
    // Side by side, the common case: one step on in memory, and not across a row's end.
    if i64::from(b) - i64::from(a) == (step.1 * w + step.0) as i64
        && (step.0 == 0 || plane.columns.split(a).0 as isize + step.0 < w)
    {
        return None;
    }
    let at = |p: u32| {
        let (x, y) = plane.columns.split(p);
        (x as isize, y as isize)
    };
    let ((ax, ay), (bx, by)) = (at(a), at(b));
    let shifted = |x: isize, y: isize| -> Option<u32> {
        let p = (x >= 0 && y >= 0 && x < w && y < h).then(|| (y * w + x) as u32)?;
        plane.allows(p).then_some(p)
    };
    let next = shifted(ax + step.0, ay + step.1);
    if next == Some(b) {
        return None;
    }
    let diff = |from: u32, to: u32| {
        let (f, t) = (plane.data[from as usize], plane.data[to as usize]);
        [t[0] - f[0], t[1] - f[1], t[2] - f[2]]
    };
    match (next.map(|n| diff(a, n)), shifted(bx - step.0, by - step.1).map(|p| diff(p, b))) {
        (Some(s), Some(t)) => Some(std::array::from_fn(|c| (s[c] + t[c]) / 2.0)),
        (one, other) => one.or(other),
    }
}

/// The bins of `map` that no counted pixel fell in (counted over strips, the rest of
/// the output has colours they did not): linear between the nearest counted bins on
/// either side, and beyond the first or last, that bin's shift.
fn fill(map: &mut [f32], counted: &[u32]) {
    let value = |b: usize| LOWEST + b as f32 / LEVELS;
    let seen: Vec<usize> = (0..map.len()).filter(|&b| counted[b] > 0).collect();
    let (Some(&first), Some(&last)) = (seen.first(), seen.last()) else {
        // (Nothing counted: every colour stays.)
        map.iter_mut().enumerate().for_each(|(b, m)| *m = value(b));
        return;
    };
    for b in 0..first {
        map[b] = value(b) + map[first] - value(first);
    }
    for b in last + 1..map.len() {
        map[b] = value(b) + map[last] - value(last);
    }
    for pair in seen.windows(2) {
        let (lo, hi) = (pair[0], pair[1]);
        for b in lo + 1..hi {
            let t = (b - lo) as f32 / (hi - lo) as f32;
            map[b] = map[lo] + t * (map[hi] - map[lo]);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::Shares;

    fn kept(fused: &mut [[f32; 3]], copied: &[[f32; 3]]) {
        let keep = Shares::of(copied.iter().copied(), fused.iter().copied()).keep();
        fused.iter_mut().for_each(|c| *c = keep.applied(*c));
    }

    #[test]
    fn the_copied_distribution_is_kept_in_the_fused_order() {
        // Copied: 0, 10, ..., 90 shuffled; fused: the same pixels pulled towards 45 (as
        // fusion pulls extremes in) and swapped in two places. Each fused pixel takes
        // the copied value of its rank: the extremes come back, the fused order stays.
        let copied: Vec<[f32; 3]> = [30, 90, 0, 60, 10, 80, 20, 50, 40, 70].map(|v| [v as f32; 3]).to_vec();
        let mut fused: Vec<[f32; 3]> = copied.iter().map(|c| [45.0 + 0.5 * (c[0] - 45.0); 3]).collect();
        fused.swap(0, 8); // 30 and 40's places
        kept(&mut fused, &copied);
        let got: Vec<f32> = fused.iter().map(|c| c[0]).collect();
        assert_eq!(got, [40, 90, 0, 60, 10, 80, 20, 50, 30, 70].map(|v| v as f32));
        // Equal fused values take one value (their middle rank's).
        let mut flat = vec![[7.0f32; 3]; 4];
        let copied: Vec<[f32; 3]> = [0, 10, 20, 30].map(|v| [v as f32; 3]).to_vec();
        kept(&mut flat, &copied);
        assert!(flat.iter().all(|c| c[0] == 20.0), "{flat:?}");
    }

    #[test]
    fn colours_the_count_missed_are_mapped_between_its_neighbours() {
        // Counted (a banded output's strips): fused 10 and 20 were copied 12 and 24.
        // Elsewhere, 15 lies between (18), 5 and 30 beyond (shifted as 10 and 20 are).
        let keep = Shares::of([[12.0; 3], [24.0; 3]].into_iter(), [[10.0; 3], [20.0; 3]].into_iter()).keep();
        for (fused, kept) in [(15.0, 18.0), (5.0, 7.0), (30.0, 34.0), (10.0, 12.0)] {
            let c = keep.applied([fused; 3]);
            assert!((c[0] - kept).abs() < 0.02, "{fused} -> {} (not {kept})", c[0]);
        }
    }
}
