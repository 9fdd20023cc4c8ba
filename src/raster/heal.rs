//! Healing a fill into its surroundings (seamless cloning, Pérez, Gangnet and Blake
//! 2003, as Photoshop's healing brush does after its texture step): the filled pixels
//! keep their copied detail, and a smooth correction, harmonic inside the hole, takes
//! away the colour step at its edge.
//!
//! The step at an edge between a filled pixel `p` (a copy of the image's pixel `s`) and
//! a known neighbour `q = p + d` is what `q` is less what the copy would have put there,
//! the image's pixel `s + d`. The correction `c` solves Laplace's equation over the
//! filled pixels with those steps as its boundary values: at each filled pixel, `c` is
//! the mean over its four neighbours of `c` (filled neighbours) or the step (known
//! ones). It is solved coarse to fine (`solve`): the same equations over blocks of 2 x 2
//! pixels, and of their blocks, each scale's solution the start of the finer one's
//! successive over-relaxation.
//!
//! The price: the filled pixels are no longer verbatim copies, so patch energy (which
//! rewards copies) rises. Over the eight photographs of the peer comparison the fill's
//! energy went from 6.10 to 9.92 (texture-synthesis 8.40, the photograph's own content
//! 12.57) while the step at the hole's edge went from 2.05 times the steps around it to
//! 1.05 (texture-synthesis 1.21). Fading the correction out with the distance from the
//! edge (e^(-d/4)) lowered the energy by a tenth only, and left a brighter or darker
//! fill inside a ring; averaging the steps along the edge (Gaussian, 1-4 pixels) left
//! the energy as it was and the edge's step at 1.23-1.55: the correction the energy
//! pays for is the fill's offset in colour, not the texture's noise along its edge. So
//! a fill is matched again to its healed colours (`synthesis::REMATCH_ROUNDS`), which
//! shrinks the offset, and its last heal is partial (`inpaint::LAST_HEAL`).
//!
//! Where Pérez et al. hold every edge pixel to its step, a filled pixel whose known
//! neighbours are unlike its copy's (another material: a tower's platform under a sky
//! filled in) holds its steps weakly (`OUTLIER`), nearly as the image's own edge holds
//! none, rather than carrying that material's colour into the hole. Healed alike, the
//! platform's brown rose half way up a new user's hole of 30% in a photograph of the
//! Eiffel tower, and the re-match then copied brown pixels scattered over the sky; so,
//! the sky is clean. The price on twelve photographs (holes of 8.5-10.5%, seeds 1-5,
//! examples/inpaint_edge): edge ratio 1.050 -> 1.057, patch energy 6.44 -> 6.44.
//! Judged by the step's own size instead, a photograph lit from 5% to 100% across, a
//! hole on its bright border, kept a step of 3.3-4.8 times the steps around (so: 1.63;
//! all steps alike: 1.51): its light's growing offset was read as another material.

use super::image::{wrap, Rgba};

/// Sweeps of the solver at most on each scale, and the change (on the 0-255 scale) below
/// which it stops.
const SWEEPS: usize = 400;
const TOLERANCE: f32 = 0.05;
/// The over-relaxation factor (1 is Gauss-Seidel; close to 2 converges in about as
/// many sweeps as the hole is wide).
const OMEGA: f32 = 1.9;
/// A filled pixel's steps at the edge count `exp(-(u / (OUTLIER m))²)` of an ordinary
/// one's, `u` how unlike its known neighbours' surroundings are its copy's (`unlike`,
/// averaged over the edge within `NEAR` pixels), `m` the median `u` of the whole edge,
/// at least 1 (on a smooth image, a difference of 5 levels). At 3: edge ratio 1.066,
/// patch energy 6.42 on the twelve photographs; at 2: 1.094 and 6.38.
const OUTLIER: f32 = 5.0;
/// A separate hole none of whose edge pixels weighs this much is healed whole, as before:
/// held by weak steps only, it would drift towards their mean, a flat shift.
const ALONE: f32 = 0.5;
/// The steps within this many pixels (a square) are averaged for `OUTLIER`'s judgement:
/// a run of unlike steps is another material, one alone the texture's own contrast.
const NEAR: isize = 3;

/// Sets the filled pixels of `out` (those not `known`) to their copies of `image`'s
/// pixels `src[i]` plus `strength` times the correction (1: the whole step at the edge
/// taken away); `torus` reads neighbours across the edges. Alpha is healed like the
/// colours where the image's opacity varies. (Copied as it was before, a fill on a
/// half-transparent image showed as patches of another opacity: its mean off the
/// truth +69 and -94 on a new user's trial; healed, +39 and -62.) The colours are then
/// healed premultiplied by alpha, as they show: a transparent pixel's colour means
/// nothing (an icon's background is often transparent black), and a step from it
/// darkened the fill of a new user's icon along its transparent edge; premultiplied,
/// such a step says only that the fill turns transparent there.
pub fn heal(out: &mut Rgba, image: &Rgba, src: &[u32], known: &[bool], torus: bool, strength: f32) {
    let (w, h) = (out.width, out.height);
    let free: Vec<usize> = (0..w * h).filter(|&i| !known[i]).collect();
    // Whether (x, y) is read: inside the image, or anywhere on a torus.
    let read = |x: isize, y: isize| torus || ((0..w as isize).contains(&x) && (0..h as isize).contains(&y));
    // Opacity that is the same everywhere has no step to heal: three channels then.
    let channels = if image.alpha_varies() { 4 } else { 3 };
    let colour = |img: &Rgba, i: usize| {
        let p = [0, 1, 2, 3].map(|c| img.data[4 * i + c] as f32);
        let a = if channels == 4 { p[3] / 255.0 } else { 1.0 };
        [p[0] * a, p[1] * a, p[2] * a, p[3]]
    };
    if free.len() == w * h {
        // Nothing to heal to: the copies as they are.
        for &i in &free {
            let s = 4 * src[i] as usize;
            out.data[4 * i..4 * i + 4].copy_from_slice(&image.data[s..s + 4]);
        }
        return;
    }
    // Each filled pixel's filled neighbours, by their index in `free`.
    let mut slot = vec![u32::MAX; w * h];
    for (k, &i) in free.iter().enumerate() {
        slot[i] = k as u32;
    }
    let mut links: Vec<[u32; 4]> = Vec::with_capacity(free.len());
    // The steps to known neighbours, each with the filled pixel it belongs to.
    let mut edges: Vec<(u32, [f32; 4], f32)> = Vec::new();
    // How unlike the known pixel `q`'s surroundings are the copy's `s`'s, each taken
    // from its own pixel (a colour offset between them is what the heal is for): the
    // mean size of the difference of the differences over the known pixels of the 3 x 3
    // round `q`.
    let unlike = |q: usize, s: usize| {
        let (qx, qy, sx, sy) = ((q % w) as isize, (q / w) as isize, (s % w) as isize, (s / w) as isize);
        let (cq, cs) = (colour(image, q), colour(image, s));
        let (mut sum, mut n) = (0.0f32, 0.0f32);
        for (dx, dy) in [(-1, -1), (0, -1), (1, -1), (-1, 0), (1, 0), (-1, 1), (0, 1), (1, 1)] {
            let (ax, ay, bx, by) = (qx + dx, qy + dy, sx + dx, sy + dy);
            if !(read(ax, ay) && read(bx, by)) {
                continue;
            }
            let a = wrap(ay, h) * w + wrap(ax, w);
            if !known[a] {
                continue;
            }
            let (pa, pb) = (colour(image, a), colour(image, wrap(by, h) * w + wrap(bx, w)));
            sum += (0..channels).map(|c| ((pa[c] - cq[c]) - (pb[c] - cs[c])).powi(2)).sum::<f32>().sqrt();
            n += 1.0;
        }
        if n > 0.0 {
            sum / n
        } else {
            0.0
        }
    };
    for (k, &i) in free.iter().enumerate() {
        let (x, y) = ((i % w) as isize, (i / w) as isize);
        let (sx, sy) = ((src[i] as usize % w) as isize, (src[i] as usize / w) as isize);
        let mut link = [u32::MAX; 4];
        for (d, (dx, dy)) in [(1, 0), (-1, 0), (0, 1), (0, -1)].into_iter().enumerate() {
            let (nx, ny) = (x + dx, y + dy);
            if !read(nx, ny) {
                continue;
            }
            let q = wrap(ny, h) * w + wrap(nx, w);
            if known[q] {
                // What the copy would have put at q: its source's neighbour, read on the
                // torus or clamped like the image's own edge.
                let s = if torus {
                    wrap(sy + dy, h) * w + wrap(sx + dx, w)
                } else {
                    (sy + dy).clamp(0, h as isize - 1) as usize * w + (sx + dx).clamp(0, w as isize - 1) as usize
                };
                let (a, b) = (colour(image, q), colour(image, s));
                let step = [0, 1, 2, 3].map(|c| if c < channels { a[c] - b[c] } else { 0.0 });
                edges.push((k as u32, step, unlike(q, s)));
            } else {
                link[d] = slot[q];
            }
        }
        links.push(link);
    }
    // Each filled pixel on the edge (`edges` holds them in `free`'s order): its index in
    // `free`, the sum of its steps, how many, and the sum of their unlikeness.
    let mut border: Vec<(u32, [f32; 4], u32, f32)> = Vec::new();
    for (k, s, u) in edges {
        if border.last().is_none_or(|b| b.0 != k) {
            border.push((k, [0.0; 4], 0, 0.0));
        }
        let b = border.last_mut().expect("pushed above");
        (0..4).for_each(|c| b.1[c] += s[c]);
        b.2 += 1;
        b.3 += u;
    }
    // Each filled pixel's place in `border` (`NONE`: not on the edge).
    let mut at = vec![NONE; free.len()];
    for (j, b) in border.iter().enumerate() {
        at[b.0 as usize] = j as u32;
    }
    // The unlikeness of the steps within `NEAR` pixels, averaged.
    let near = |k: u32| {
        let i = free[k as usize];
        let (x, y) = ((i % w) as isize, (i / w) as isize);
        let (mut sum, mut n) = (0.0f32, 0u32);
        for (dx, dy) in (-NEAR..=NEAR).flat_map(|dy| (-NEAR..=NEAR).map(move |dx| (dx, dy))) {
            if read(x + dx, y + dy) {
                let k = slot[wrap(y + dy, h) * w + wrap(x + dx, w)];
                if let Some(&j) = at.get(k as usize).filter(|&&j| j != NONE) {
                    sum += border[j as usize].3;
                    n += border[j as usize].2;
                }
            }
        }
        sum / n.max(1) as f32
    };
    let unlikeness: Vec<f32> = border.iter().map(|b| near(b.0)).collect();
    let scale = if unlikeness.is_empty() {
        1.0
    } else {
        let mut all = unlikeness.clone();
        let mid = all.len() / 2;
        OUTLIER * all.select_nth_unstable_by(mid, f32::total_cmp).1.max(1.0)
    };
    let mut weights: Vec<f32> = unlikeness.iter().map(|u| (-(u / scale).powi(2)).exp()).collect();
    // A separate hole all of whose edge is unlike its fill is healed whole (`ALONE`).
    let parts = components(&links);
    let mut strongest = vec![0.0f32; parts.iter().max().map_or(0, |&p| p as usize + 1)];
    for (b, &wt) in border.iter().zip(&weights) {
        let p = parts[b.0 as usize] as usize;
        strongest[p] = strongest[p].max(wt);
    }
    for (b, wt) in border.iter().zip(weights.iter_mut()) {
        if strongest[parts[b.0 as usize] as usize] < ALONE {
            *wt = 1.0;
        }
    }
    drop((parts, strongest));
    let mut steps = vec![[0.0f32; 4]; free.len()];
    let mut degree: Vec<f32> = links.iter().map(|l| l.iter().filter(|&&q| q != u32::MAX).count() as f32).collect();
    for (b, wt) in border.iter().zip(weights) {
        let k = b.0 as usize;
        (0..4).for_each(|c| steps[k][c] = wt * b.1[c]);
        degree[k] += wt * b.2 as f32;
    }
    let xy: Vec<(u32, u32)> = free.iter().map(|&i| ((i % w) as u32, (i / w) as u32)).collect();
    let weights = links.iter().map(|l| l.map(|q| if q == NONE { 0.0 } else { 1.0 })).collect();
    let fine = System { xy, weights, links, diag: degree, rhs: steps, size: (w, h) };
    let c = solve(fine);
    for (k, &i) in free.iter().enumerate() {
        let s = 4 * src[i] as usize;
        let base = colour(image, src[i] as usize);
        let healed = |ch: usize| base[ch] + strength * c[k][ch];
        // (Alpha copied where it is the same everywhere.)
        out.data[4 * i..4 * i + 4].copy_from_slice(&image.data[s..s + 4]);
        if channels == 3 {
            for ch in 0..3 {
                out.data[4 * i + ch] = healed(ch).round().clamp(0.0, 255.0) as u8;
            }
            continue;
        }
        let a = healed(3).clamp(0.0, 255.0);
        out.data[4 * i + 3] = a.round() as u8;
        // Back from premultiplied; a pixel left transparent keeps its copy's colour.
        if out.data[4 * i + 3] > 0 {
            for ch in 0..3 {
                out.data[4 * i + ch] = (healed(ch) * 255.0 / a).round().clamp(0.0, 255.0) as u8;
            }
        }
    }
}

/// No neighbour in a direction (`System::links`).
const NONE: u32 = u32::MAX;

/// The heal's linear system at one scale: at each node (a filled pixel, or at a coarser
/// scale a block of them), `diag c = rhs + sum of weights x c at the linked nodes`, in
/// four lanes (colours, and alpha where it varies; an unused lane stays 0).
struct System {
    /// Each node's column and row at its scale (its pixel, or its block).
    xy: Vec<(u32, u32)>,
    /// Linked nodes towards +x, -x, +y and -y (`NONE`: a known pixel or nothing there).
    links: Vec<[u32; 4]>,
    weights: Vec<[f32; 4]>,
    /// The weights of the links plus those of the steps to known pixels.
    diag: Vec<f32>,
    /// The weighted steps to known pixels.
    rhs: Vec<[f32; 4]>,
    /// The grid's width and height at this scale.
    size: (usize, usize),
}

/// Nodes below which a system is solved as it is, not from a coarser one.
const COARSEST: usize = 256;

impl System {
    /// The nodes that carry any weight laid out by colour, reds first (each colour's
    /// nodes depend only on the other's: a half-sweep never waits on the value it just
    /// wrote), links renumbered (`NONE`: the slot past the nodes, held at 0). With each
    /// new node's old number, and the reds' count.
    fn ordered(self) -> (System, Vec<usize>, usize) {
        let colour = |k: &usize| (self.xy[*k].0 + self.xy[*k].1) % 2;
        let held = |k: &usize| self.diag[*k] > 0.0;
        let n = self.links.len();
        let order: Vec<usize> =
            (0..n).filter(|k| held(k) && colour(k) == 0).chain((0..n).filter(|k| held(k) && colour(k) == 1)).collect();
        let reds = order.iter().take_while(|k| colour(k) == 0).count();
        let m = order.len() as u32;
        let mut at = vec![m; n];
        for (j, &k) in order.iter().enumerate() {
            at[k] = j as u32;
        }
        let sys = System {
            xy: order.iter().map(|&k| self.xy[k]).collect(),
            links: order.iter().map(|&k| self.links[k].map(|q| if q == NONE { m } else { at[q as usize] })).collect(),
            weights: order.iter().map(|&k| self.weights[k]).collect(),
            diag: order.iter().map(|&k| self.diag[k]).collect(),
            rhs: order.iter().map(|&k| self.rhs[k]).collect(),
            size: self.size,
        };
        (sys, order, reds)
    }
}

/// One scale of the heal's system, laid out (`System::ordered`).
struct Scale {
    sys: System,
    /// The nodes of the first colour.
    reds: usize,
    /// 1 over each node's `diag`.
    inv: Vec<f32>,
    /// Whether every link weighs 1 (between pixels; blocks are linked by several).
    unit: bool,
    /// Each node's block at the next coarser scale.
    parent: Vec<u32>,
}

impl Scale {
    fn new(sys: System, reds: usize) -> Scale {
        let inv = sys.diag.iter().map(|&d| 1.0 / d).collect();
        let unit = sys.weights.iter().all(|w| w.iter().all(|&x| x == 0.0 || x == 1.0));
        Scale { sys, reds, inv, unit, parent: Vec::new() }
    }

    fn len(&self) -> usize {
        self.sys.links.len()
    }

    /// `sweeps` red-black sweeps of over-relaxation by `omega` of `x` towards `b`, or
    /// fewer once no value changes by `tol`: the largest change of the last.
    fn relax(&self, x: &mut [[f32; 4]], b: &[[f32; 4]], omega: f32, sweeps: usize, tol: f32) -> f32 {
        let (n, s) = (self.len(), &self.sys);
        let mut change = f32::INFINITY;
        for _ in 0..sweeps {
            let (first, second) = if self.unit {
                (
                    half_sweep::<true>(x, 0..self.reds, &s.links, &s.weights, b, &self.inv, omega),
                    half_sweep::<true>(x, self.reds..n, &s.links, &s.weights, b, &self.inv, omega),
                )
            } else {
                (
                    half_sweep::<false>(x, 0..self.reds, &s.links, &s.weights, b, &self.inv, omega),
                    half_sweep::<false>(x, self.reds..n, &s.links, &s.weights, b, &self.inv, omega),
                )
            };
            change = first.max(second);
            if change < tol {
                break;
            }
        }
        change
    }
}

/// The correction at each node of `fine`, coarse to fine: each scale's system of 2 x 2
/// blocks (`System::coarser`) solved first, down to `COARSEST` nodes, and its solution
/// interpolated as the start of the finer one's over-relaxation, which then has mostly
/// the detail finer than the blocks to add. Started from zero, the sweeps carried the
/// correction in from the edge a few pixels at a time: a mended 224-pixel photograph's
/// band (22,000 pixels) took 60-130 sweeps, as long as a third of its synthesis, and
/// stopped up to 2.5 levels short of the solution (brick, seed 1); from the coarser
/// scales it takes about 45 sweeps of the finest, in red-black order (`System::ordered`),
/// and stops within 0.6-1.2 of it: the twelve photographs' bands healed in 1.6-5.3 ms
/// (seeds 1-3; brick's, seed 1, took 46 ms so).
fn solve(fine: System) -> Vec<[f32; 4]> {
    let n = fine.links.len();
    let (sys, order, reds) = fine.ordered();
    let mut scales = vec![Scale::new(sys, reds)];
    while scales.last().is_some_and(|s| s.len() > COARSEST && (s.sys.size.0 > 2 || s.sys.size.1 > 2)) {
        let last = scales.last_mut().expect("one scale at least");
        let (coarse, parent) = last.sys.coarser();
        let (coarse, corder, creds) = coarse.ordered();
        // (A block held by no weight, were there one, is left out: `NONE`, read as 0.)
        let mut at = vec![NONE; parent.iter().map(|&p| p as usize + 1).max().unwrap_or(0)];
        for (j, &k) in corder.iter().enumerate() {
            at[k] = j as u32;
        }
        last.parent = parent.iter().map(|&p| at[p as usize]).collect();
        scales.push(Scale::new(coarse, creds));
    }
    // Coarse to fine: each scale started from the coarser one's solution.
    let last = scales.len() - 1;
    let mut x = vec![[0.0f32; 4]; scales[last].len() + 1];
    scales[last].relax(&mut x, &scales[last].sys.rhs, OMEGA, SWEEPS, TOLERANCE);
    for l in (0..last).rev() {
        let (s, c) = (&scales[l], &scales[l + 1]);
        let mut f = vec![[0.0f32; 4]; s.len() + 1];
        for (k, v) in f.iter_mut().take(s.len()).enumerate() {
            // Linear between the block's value and its neighbour's on the node's side (a
            // quarter of the way: the node lies a quarter block off the block's centre);
            // the block's own where it has no neighbour there.
            let p = s.parent[k] as usize;
            if p >= c.len() {
                continue;
            }
            let (px, py) = s.sys.xy[k];
            let towards = |d: usize| match c.sys.links[p][d] as usize {
                q if q == c.len() => x[p],
                q => x[q],
            };
            let (nx, ny) = (towards(if px % 2 == 1 { 0 } else { 1 }), towards(if py % 2 == 1 { 2 } else { 3 }));
            *v = [0, 1, 2, 3].map(|ch| x[p][ch] + 0.25 * (nx[ch] - x[p][ch]) + 0.25 * (ny[ch] - x[p][ch]));
        }
        x = f;
        s.relax(&mut x, &s.sys.rhs, OMEGA, SWEEPS, TOLERANCE);
    }
    let mut out = vec![[0.0f32; 4]; n];
    for (j, &k) in order.iter().enumerate() {
        out[k] = x[j];
    }
    out
}

impl System {
    /// The system of 2 x 2 blocks (Galerkin, each block's correction one value): a
    /// block's steps and weights are its pixels' summed, and a link between two blocks
    /// weighs as many links as join their pixels. With each node's block in it.
    fn coarser(&self) -> (System, Vec<u32>) {
        let (w, h) = self.size;
        let (cw, ch) = (w.div_ceil(2), h.div_ceil(2));
        let mut id = vec![NONE; cw * ch];
        let mut xy = Vec::new();
        let parent: Vec<u32> = self
            .xy
            .iter()
            .map(|&(x, y)| {
                let b = (y / 2) as usize * cw + (x / 2) as usize;
                if id[b] == NONE {
                    id[b] = xy.len() as u32;
                    xy.push((x / 2, y / 2));
                }
                id[b]
            })
            .collect();
        let m = xy.len();
        let (mut links, mut weights) = (vec![[NONE; 4]; m], vec![[0.0f32; 4]; m]);
        let (mut bound, mut rhs) = (vec![0.0f32; m], vec![[0.0f32; 4]; m]);
        for k in 0..self.links.len() {
            let p = parent[k] as usize;
            (0..4).for_each(|c| rhs[p][c] += self.rhs[k][c]);
            bound[p] += self.diag[k] - self.weights[k].iter().sum::<f32>();
            for d in 0..4 {
                let l = self.links[k][d];
                if l == NONE || l as usize >= parent.len() || parent[l as usize] as usize == p {
                    continue;
                }
                debug_assert!(links[p][d] == NONE || links[p][d] == parent[l as usize]);
                links[p][d] = parent[l as usize];
                weights[p][d] += self.weights[k][d];
            }
        }
        let diag = (0..m).map(|p| bound[p].max(0.0) + weights[p].iter().sum::<f32>()).collect();
        (System { xy, links, weights, diag, rhs, size: (cw, ch) }, parent)
    }
}

/// One colour's nodes `range` of `v` over-relaxed by `omega` towards `rhs` (`Scale::relax`;
/// `inv`: 1 over each node's diagonal): the largest change. `UNIT`: every link weighs 1
/// (`weights` unread), as between pixels.
#[inline(always)]
fn half_sweep<const UNIT: bool>(
    v: &mut [[f32; 4]],
    range: std::ops::Range<usize>,
    links: &[[u32; 4]],
    weights: &[[f32; 4]],
    rhs: &[[f32; 4]],
    inv: &[f32],
    omega: f32,
) -> f32 {
    // (The largest change per lane, compared by hand: with `f32::max`, which minds NaNs,
    // the sweeps took twice as long.)
    let mut change = [0.0f32; 4];
    let (links, rhs, inv) = (&links[range.clone()], &rhs[range.clone()], &inv[range.clone()]);
    let weights = if UNIT { weights } else { &weights[range.clone()] };
    for (j, k) in range.enumerate() {
        let mut sum = rhs[j];
        for d in 0..4 {
            let q = v[links[j][d] as usize];
            let wt = if UNIT { 1.0 } else { weights[j][d] };
            (0..4).for_each(|ch| sum[ch] += wt * q[ch]);
        }
        let old = v[k];
        for ch in 0..4 {
            let delta = omega * (sum[ch] * inv[j] - old[ch]);
            v[k][ch] = old[ch] + delta;
            let size = delta.abs();
            change[ch] = if size > change[ch] { size } else { change[ch] };
        }
    }
    change.into_iter().fold(0.0, f32::max)
}

/// The connected parts of the filled pixels (4-neighbours, `links`): each one's part,
/// numbered from 0.
fn components(links: &[[u32; 4]]) -> Vec<u32> {
    let mut part = vec![u32::MAX; links.len()];
    let mut next = 0;
    let mut stack = Vec::new();
    for start in 0..links.len() {
        if part[start] != u32::MAX {
            continue;
        }
        part[start] = next;
        stack.push(start);
        while let Some(k) = stack.pop() {
            for &l in &links[k] {
                if l != u32::MAX && part[l as usize] == u32::MAX {
                    part[l as usize] = next;
                    stack.push(l as usize);
                }
            }
        }
        next += 1;
    }
    part
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A 32 x 32 image of `rest` with `corner` in its top-left 6 x 6, and a hole in its
    /// middle filled from the corner: the image, the known pixels and the copies.
    fn filled_from_the_corner(corner: [u8; 4], rest: [u8; 4]) -> (Rgba, Vec<bool>, Vec<u32>) {
        let (w, h) = (32, 32);
        let data = (0..w * h).flat_map(|i| if i % w < 6 && i / w < 6 { corner } else { rest }).collect();
        let hole = |i: usize| (12..20).contains(&(i % w)) && (12..20).contains(&(i / w));
        let known = (0..w * h).map(|i| !hole(i)).collect();
        let src = (0..w * h).map(|i| if hole(i) { (2 * w + 2) as u32 } else { i as u32 }).collect();
        (Rgba { width: w, height: h, data }, known, src)
    }

    #[test]
    fn a_fill_copied_from_a_darker_place_is_lifted_to_its_surroundings() {
        // A flat image at 100 with a darker patch (40) in its corner; a hole in the
        // middle filled from the dark patch: healed, it meets its border at 100.
        let (image, known, src) = filled_from_the_corner([40, 40, 40, 255], [100, 100, 100, 255]);
        let mut out = image.clone();
        heal(&mut out, &image, &src, &known, false, 1.0);
        for i in (0..known.len()).filter(|&i| !known[i]) {
            assert!((out.data[4 * i] as i32 - 100).abs() <= 1, "pixel {i}: {}", out.data[4 * i]);
        }
        // Known pixels untouched.
        assert!((0..known.len())
            .filter(|&i| known[i])
            .all(|i| out.data[4 * i..4 * i + 4] == image.data[4 * i..4 * i + 4]));
    }

    #[test]
    fn opacity_is_healed_where_it_varies() {
        // A half-transparent image (alpha 100) with a more opaque corner (220) that the
        // hole is filled from: healed, the hole's opacity meets its border's.
        let (image, known, src) = filled_from_the_corner([90, 120, 150, 220], [90, 120, 150, 100]);
        let mut out = image.clone();
        heal(&mut out, &image, &src, &known, false, 1.0);
        for i in (0..known.len()).filter(|&i| !known[i]) {
            assert!((out.data[4 * i + 3] as i32 - 100).abs() <= 1, "pixel {i}: alpha {}", out.data[4 * i + 3]);
            assert_eq!(out.data[4 * i..4 * i + 3], [90, 120, 150]);
        }
        // An opaque image stays opaque.
        let (opaque, _, _) = filled_from_the_corner([90, 120, 150, 255], [90, 120, 150, 255]);
        let mut out = opaque.clone();
        heal(&mut out, &opaque, &src, &known, false, 1.0);
        assert!(out.data.chunks(4).all(|p| p[3] == 255));
    }

    #[test]
    fn a_transparent_backgrounds_colour_does_not_darken_a_fill() {
        // Opaque grey on the left, transparent black on the right; the hole straddles
        // them and is filled with grey from the left. Its steps to the transparent side
        // say only that it turns transparent there: healed as straight colours, the
        // background's black pulled the grey down (a dark smear).
        let (w, h) = (32, 32);
        let data = (0..w * h).flat_map(|i| if i % w < 16 { [150, 150, 150, 255] } else { [0; 4] }).collect();
        let image = Rgba { width: w, height: h, data };
        let hole = |i: usize| (12..20).contains(&(i % w)) && (12..20).contains(&(i / w));
        let known: Vec<bool> = (0..w * h).map(|i| !hole(i)).collect();
        let src: Vec<u32> = (0..w * h).map(|i| if hole(i) { i - 8 } else { i } as u32).collect();
        let mut out = image.clone();
        heal(&mut out, &image, &src, &known, false, 1.0);
        let filled: Vec<&[u8]> = (0..w * h).filter(|&i| hole(i)).map(|i| &out.data[4 * i..4 * i + 4]).collect();
        for p in &filled {
            assert!(p[3] == 0 || p[..3].iter().all(|&v| v.abs_diff(150) <= 2), "{p:?}");
        }
        // The right of the hole has turned (mostly) transparent, its left stays opaque.
        let alpha = |x: usize| (12..20).map(|y| out.data[4 * (y * w + x) + 3] as f32).sum::<f32>() / 8.0;
        assert!(alpha(19) < 100.0 && alpha(12) > 150.0, "alpha {} at the left, {} at the right", alpha(12), alpha(19));
    }

    #[test]
    fn a_hole_edged_by_another_material_is_not_healed_into_it() {
        // Sky of fine noise; under the hole, and nowhere else, a brown lattice whose top
        // is the hole's lower edge (a new user's photograph of the Eiffel tower, its
        // middle taken out). The hole is filled with sky copied from 8 rows up, so every
        // step along its lower edge is lattice against sky. Healed with every step
        // alike, the lattice's brown rose half way up the hole.
        let (w, h) = (64, 64);
        let sky = [90.0f32, 150.0, 220.0];
        let lattice = |x: usize, y: usize| (16..48).contains(&x) && y >= 40;
        let hole = |i: usize| (16..48).contains(&(i % w)) && (8..40).contains(&(i / w));
        // And a small hole inside the lattice, filled with sky too: all its edge is
        // unlike its fill, and it is healed whole.
        let small = |i: usize| (24..30).contains(&(i % w)) && (50..56).contains(&(i / w));
        let mut image = Rgba { width: w, height: h, data: vec![255; w * h * 4] };
        for i in 0..w * h {
            let (x, y) = (i % w, i / w);
            let c = if lattice(x, y) {
                let d = if (x / 2 + y / 2) % 2 == 0 { -35.0 } else { 25.0 };
                [150.0 + d, 110.0 + d, 70.0 + d]
            } else {
                let n = ((i * 7919) % 9) as f32 - 4.0;
                sky.map(|v| v + n)
            };
            image.data[4 * i..4 * i + 3].copy_from_slice(&c.map(|v| v as u8));
        }
        let known: Vec<bool> = (0..w * h).map(|i| !hole(i) && !small(i)).collect();
        let src: Vec<u32> = (0..w * h)
            .map(|i| if hole(i) { i - 8 * w } else if small(i) { i - 40 * w } else { i } as u32)
            .collect();
        let mut out = image.clone();
        heal(&mut out, &image, &src, &known, false, 1.0);
        let mean = |i: &[usize], c: usize| i.iter().map(|&i| out.data[4 * i + c] as f32).sum::<f32>() / i.len() as f32;
        let lattice_mean = [145.0, 105.0, 65.0];
        let inside: Vec<usize> = (0..w * h).filter(|&i| small(i)).collect();
        let off_lattice = (0..3).map(|c| (mean(&inside, c) - lattice_mean[c]).powi(2)).sum::<f32>().sqrt();
        assert!(off_lattice < 15.0, "the small hole is {off_lattice:.1} off the lattice's mean");
        // The hole's rows more than 4 above the lattice: their mean colour off the sky.
        let upper: Vec<usize> = (0..w * h).filter(|&i| hole(i) && i / w < 36).collect();
        let off = (0..3).map(|c| (mean(&upper, c) - sky[c]).powi(2)).sum::<f32>().sqrt();
        assert!(off < 6.0, "the fill's mean is {off:.1} off the sky");
    }
}
