//! One pass over one level: each pixel's neighbourhood read from the output, its
//! candidate exemplar positions, and the best of them by `exemplar::distance`.

use super::exemplar::{distance, Offsets, Plane};
use super::lanes::Px;
use super::mixer::Mixer;
use super::reuse::Uses;
use crate::raster::image::wrap;
use crate::raster::neighbourhood::Shape;
use crate::rng::Rng;

/// Coherence bias (after Ashikhmin's and Hertzmann's coherence terms): a candidate that
/// `v` of the `n` neighbours propose has its distance divided by `1 + COHERENCE (v - 1) / n`,
/// so an exemplar patch that most neighbours agree on wins over a lone, slightly closer
/// match; fewer seams, hence lower patch energy. Over 6 seeds on the four photographs
/// (with the reversed correction pass), 2 lowered the mean energy from 8.12 to 7.27 and
/// every photograph's; 4 and 8 cost brick more than they gained elsewhere.
pub(super) const COHERENCE: f32 = 2.0;

/// Source positions of one level's pixels, per exemplar, over rows `first .. first +
/// rows` (mod the level's height) of the torus: the whole level, or a band of it with
/// the rows around it that its neighbourhoods read (see `bands`). Made by `Pass::map`.
pub(crate) struct Map {
    pub src: Vec<Vec<u32>>,
    /// The whole level's use counts, updated as the map's pixels change.
    pub uses: Option<Uses>,
    /// The map's pixels as a neighbourhood reads them (`Pass::shown`), kept up to date
    /// with `src`; and the parent level's, over the parent rows this map's
    /// neighbourhoods read. Each only when it holds at most `CACHED` pixels (else read
    /// through the sources, as every pixel once was).
    colours: Option<Vec<Px>>,
    parent: Option<Rows>,
    first: usize,
    rows: usize,
    lw: usize,
    lh: usize,
}

/// Pixels a map keeps as colours besides their sources (`Map::colours`), and parent
/// pixels (`Map::parent`): 16 bytes a pixel, so at most 4 MiB each, about 5.3 MiB for
/// the largest band window (34 rows of 4096 and their parent rows). Every level of an
/// output in scanline order (under `BANDS_FROM`) and every band's window keep them; a
/// fill (`pinned`, one map of the whole level) keeps them for its levels of at most
/// 512 x 512 pixels (the parent's for photographs up to 1024 x 1024), whatever the
/// hole's size: making them is a read of each pixel, about 1.5 ms at 512 x 512 natively,
/// against passes over the hole that are then faster. Read from the colours rather than
/// through two lookups, a 256 x 256 synthesis took 0.95 of the time in wasm, and with
/// the parent's colours kept too, 0.89 (SIMD, -O3).
const CACHED: usize = 512 * 512;

/// Rows `first .. first + rows` (mod `height`) of a level's pixels, `width` wide.
struct Rows {
    data: Vec<Px>,
    first: usize,
    rows: usize,
    width: usize,
    height: usize,
}

impl Rows {
    #[inline(always)]
    fn at(&self, x: usize, y: usize) -> Px {
        // (y and `first` are rows of the level: one subtraction wraps, no division.)
        let row = y + self.height - self.first;
        let row = if row >= self.height { row - self.height } else { row };
        debug_assert!(row < self.rows, "parent row {y} outside the map's");
        self.data[row * self.width + x]
    }
}

/// A pixel whose neighbourhood of half size `half` lies in the map without wrapping:
/// its index, so that a neighbour (x + dx, y + dy) is at `index + dy lw + dx`. Made only
/// by `Map::inside`.
#[derive(Clone, Copy)]
struct Centre {
    index: isize,
    half: isize,
}

impl Map {
    /// (x, y) as a `Centre` when every pixel within `half` of it lies in the map without
    /// wrapping.
    #[inline(always)]
    fn inside(&self, x: usize, y: usize, half: isize) -> Option<Centre> {
        let (x, row) = (x as isize, y as isize - self.first as isize);
        let inside = x >= half && x + half < self.lw as isize && row >= half && row + half < self.rows as isize;
        inside.then_some(Centre { index: row * self.lw as isize + x, half })
    }

    /// Index of neighbour (dx, dy) of (x, y), `centre` being `inside`'s answer for it.
    #[inline(always)]
    fn around(&self, centre: Option<Centre>, x: usize, y: usize, dx: isize, dy: isize) -> usize {
        match centre {
            Some(c) => (c.index + dy * self.lw as isize + dx) as usize,
            None => self.at(x as isize + dx, y as isize + dy),
        }
    }

    /// The values of `plane` (one per map pixel: its colours, or an exemplar's sources)
    /// at the points `own` around (x, y), `centre` being `inside`'s answer for (x, y)
    /// with the points' half size.
    #[inline(always)]
    fn read<'s, T: Copy>(
        &'s self,
        plane: &'s [T],
        centre: Option<Centre>,
        x: usize,
        y: usize,
        own: &'s [(isize, isize)],
    ) -> impl Iterator<Item = T> + 's {
        assert_eq!(plane.len(), self.rows * self.lw, "a plane of one value per map pixel");
        own.iter().map(move |&(dx, dy)| match centre {
            Some(c) => {
                debug_assert!(dx.abs() <= c.half && dy.abs() <= c.half);
                let i = self.around(centre, x, y, dx, dy);
                debug_assert!(i < plane.len());
                // SAFETY: a `Centre` is made only where every pixel within its half size
                // lies in the map, the points reach no further (a `Shape`'s own points
                // lie within its half size, which `pixel` asked `inside` with), and
                // `plane` holds one value per map pixel (asserted above). The checks
                // were a few percent of a synthesis in wasm, which cannot drop them.
                unsafe { *plane.get_unchecked(i) }
            }
            None => plane[self.around(centre, x, y, dx, dy)],
        })
    }

    /// Index of pixel (x, y) of the torus, which must lie in the map's rows.
    #[inline(always)]
    fn at(&self, x: isize, y: isize) -> usize {
        let row = wrap(y - self.first as isize, self.lh);
        debug_assert!(row < self.rows, "row {y} outside the map's rows");
        row * self.lw + wrap(x, self.lw)
    }
}

/// Per-pixel working vectors, allocated once per pass.
pub(crate) struct Scratch {
    /// The output's neighbourhood feature.
    f: Vec<Px>,
    /// One exemplar's own-choices feature (partial weights).
    own: Vec<Px>,
    /// Candidate positions with their numbers of proposals.
    cands: Vec<(u32, u16)>,
    /// For a wide neighbourhood's candidates (`SLOTS_FROM`), each exemplar position's
    /// place in `cands` plus one (0: not proposed), cleared after each pixel.
    slots: Vec<u32>,
}

/// Neighbours from which the candidates they propose are told apart by `Scratch::slots`
/// rather than by looking through those already proposed: so, an 11 x 11 neighbourhood's
/// 120 proposals (a mend's coarser levels) took a tenth longer. The same candidates in
/// the same order, with the same votes.
const SLOTS_FROM: usize = 32;

impl Scratch {
    pub fn new(full: &Shape) -> Scratch {
        let points = full.own.len() + full.parent.len();
        Scratch {
            f: Vec::with_capacity(points),
            own: Vec::with_capacity(points),
            cands: Vec::with_capacity(64),
            slots: Vec::new(),
        }
    }
}

/// One pass over one level: what every pixel's match needs besides the level's map.
pub(crate) struct Pass<'a> {
    pub(super) mix: &'a Mixer,
    pub(super) level: usize,
    /// This level's size and the parent level's.
    pub(super) lw: usize,
    pub(super) lh: usize,
    pub(super) parent_size: (usize, usize),
    pub(super) with_parent: bool,
    pub(super) exhaustive: bool,
    pub(super) random: usize,
    /// Whether the parent's candidate also comes shifted by up to a pixel (tiles; see
    /// `coherent_candidates`).
    pub(super) jitter: bool,
    pub(super) parent_src: &'a [Vec<u32>],
    /// Index deltas per exemplar, for the causal shape and the full one.
    pub(super) offsets: Vec<(Offsets, Offsets)>,
    /// The target guide at this level and at the parent's (`Job::target`), which the
    /// output's features carry in their fourth lane.
    pub(super) target: Option<(&'a [f32], &'a [f32])>,
    /// The coherence bias: `COHERENCE`, or none around known pixels (`pinned`).
    pub(super) coherence: f32,
    /// Whether the output is read on a torus (`Job::torus`); if not, a neighbourhood
    /// leaves out the points past the output's border (`cut`).
    pub(super) torus: bool,
}

impl Pass<'_> {
    /// The output's feature at (x, y): own level read on the torus, parent level too.
    fn feature(&self, map: &Map, centre: Option<Centre>, x: usize, y: usize, shape: &Shape, f: &mut Vec<Px>) {
        f.clear();
        let (lw, lh) = (self.lw, self.lh);
        match &map.colours {
            Some(c) => f.extend(map.read(c, centre, x, y, &shape.own)),
            None => f.extend(shape.own.iter().map(|&(dx, dy)| {
                let at = || (wrap(x as isize + dx, lw), wrap(y as isize + dy, lh));
                self.shown(self.level, &map.src, map.around(centre, x, y, dx, dy), at)
            })),
        }
        if self.with_parent {
            match &map.parent {
                Some(p) => self.parent_feature(shape, x, y, f, |nx, ny| p.at(nx, ny)),
                None => self.parent_feature(shape, x, y, f, |nx, ny| self.parent_shown(nx, ny)),
            }
        }
    }

    /// The output's pixel at index `i` of the sources `src` of `level` (this level or
    /// the parent), at `at()` on that level, as a neighbourhood reads it: its sources'
    /// colours mixed, and the target guide in the fourth lane.
    #[inline(always)]
    fn shown(&self, level: usize, src: &[Vec<u32>], i: usize, at: impl Fn() -> (usize, usize)) -> Px {
        let one = self.mix.mu.is_none();
        let (x, y) = if one && self.target.is_none() { (0, 0) } else { at() };
        let mut c = self.mix.colour(level, src, i, x, y);
        if let Some((own, parent)) = self.target {
            let (plane, w) = if level == self.level { (own, self.lw) } else { (parent, self.parent_size.0) };
            c[3] = plane[y * w + x];
        }
        c
    }

    /// The parent level's pixel (x, y), as `shown`.
    #[inline(always)]
    fn parent_shown(&self, x: usize, y: usize) -> Px {
        self.shown(self.level + 1, self.parent_src, y * self.parent_size.0 + x, || (x, y))
    }

    /// Rows `first .. first + rows` (mod this level's height) of every exemplar's
    /// sources, as one map (`Map`), with the colours it reads kept beside them.
    pub fn map(&self, src: Vec<Vec<u32>>, uses: Option<Uses>, first: usize, rows: usize) -> Map {
        let (lw, lh) = (self.lw, self.lh);
        assert!(rows <= lh && src.iter().all(|s| s.len() == rows * lw), "one source per map pixel");
        let colours = (rows * lw <= CACHED).then(|| {
            (0..rows * lw).map(|i| self.shown(self.level, &src, i, || (i % lw, (first + i / lw) % lh))).collect()
        });
        // The parent rows that rows `first ..` read (`parent_feature`: from y / 2 - 1 to
        // y / 2 + 2), one more for an odd height's wrap.
        let (pw, ph) = self.parent_size;
        let (parent_first, parent_rows) = if rows == lh {
            (0, ph)
        } else {
            (wrap((first / 2) as isize - 1, ph), ph.min((first + rows - 1) / 2 - first / 2 + 5))
        };
        let parent = (self.with_parent && parent_rows * pw <= CACHED).then(|| Rows {
            data: (0..parent_rows * pw).map(|k| self.parent_shown(k % pw, (parent_first + k / pw) % ph)).collect(),
            first: parent_first,
            rows: parent_rows,
            width: pw,
            height: ph,
        });
        Map { src, uses, colours, parent, first, rows, lw, lh }
    }

    /// The whole level as one map.
    pub fn whole(&self, src: Vec<Vec<u32>>, uses: Option<Uses>) -> Map {
        self.map(src, uses, 0, self.lh)
    }

    /// Appends the parent level's colours (`colour(px, py)` at parent pixel (px, py)) at
    /// the parent offsets around output pixel (x, y), read where the pixel lies at the
    /// parent level: (x / 2, y / 2) exactly, so between two or four parent pixels when x
    /// or y is odd (a parent pixel is the blur centred on its even child; see `pyramid`).
    /// The exemplar side reads the same points (`Exemplar::upsampled`), so a patch
    /// copied at an odd offset matches its parent as well as one at an even offset.
    /// Read at (x / 2, y / 2) rounded down, the parent feature stepped at every second
    /// pixel and a patch copied at an odd offset met its parent half a parent pixel off.
    /// Read here, over 8 seeds at 256, print's tile wrap scores 1.22 rather than 1.33 and
    /// tissue's 1.04 rather than 1.14; plain syntheses of the ten photographs (128 ->
    /// 256, 3 seeds) have a mean patch energy of 5.76 against 5.70, each still below
    /// texture-synthesis's, and take about 8% longer.
    fn parent_feature(&self, shape: &Shape, x: usize, y: usize, f: &mut Vec<Px>, colour: impl Fn(usize, usize) -> Px) {
        let (pw, ph) = self.parent_size;
        // The parent pixels the 3 x 3 points reach: 3 or 4 on a side.
        let (ox, oy) = (x % 2, y % 2);
        let cols: [usize; 4] = std::array::from_fn(|i| wrap((x / 2 + i) as isize - 1, pw));
        let rows: [usize; 4] = std::array::from_fn(|j| wrap((y / 2 + j) as isize - 1, ph));
        let mut window = [[0.0f32; 4]; 16];
        for j in 0..3 + oy {
            for i in 0..3 + ox {
                window[j * 4 + i] = colour(cols[i], rows[j]);
            }
        }
        f.extend(shape.parent.iter().map(|&(dx, dy)| {
            let (i, j) = ((dx + 1) as usize, (dy + 1) as usize);
            // Four reads, each pixel as many times as it counts (all four the same pixel
            // when x and y are even).
            let mut c = [0.0f32; 4];
            for q in
                [window[j * 4 + i], window[j * 4 + i + ox], window[(j + oy) * 4 + i], window[(j + oy) * 4 + i + ox]]
            {
                (0..4).for_each(|k| c[k] += q[k]);
            }
            c.map(|v| v * 0.25)
        }));
    }

    /// Synthesizes output pixel (x, y) at this level: sets its source in every exemplar.
    #[allow(clippy::too_many_arguments)]
    pub fn pixel(
        &self,
        map: &mut Map,
        shape: &Shape,
        use_full: bool,
        x: usize,
        y: usize,
        rng: &mut Rng,
        scratch: &mut Scratch,
    ) {
        let level = self.level;
        let Scratch { f, own, cands, slots } = scratch;
        let cut = if self.torus { None } else { self.cut(shape, x, y) };
        let shape = cut.as_ref().map_or(shape, |(s, _)| s);
        // Where the neighbourhood lies inside the map, neighbours are read by index delta.
        let centre = map.inside(x, y, shape.half);
        self.feature(map, centre, x, y, shape, f);
        let i = map.at(x as isize, y as isize);
        for (e, ex) in self.mix.exs.iter().enumerate() {
            let weight = self.mix.weight(e, level, x, y);
            let img = &ex.levels[level];
            let off = match &cut {
                Some((_, offsets)) => &offsets[e],
                None if use_full => &self.offsets[e].1,
                None => &self.offsets[e].0,
            };
            // Where an exemplar has a partial weight, it is matched against the mixed
            // neighbourhood only in proportion to that weight; the rest is its own
            // choices around the pixel. At weight 1 this is the paper's rule; as the
            // weight falls, a faint exemplar no longer collapses onto the one patch that
            // best imitates the other exemplar's colours (rows of repeated blobs). At
            // weight 0 it is synthesized against its own choices alone, so that where it
            // fades in it is already a texture of its own, not one long verbatim copy.
            let f: &[Px] = if weight < 1.0 {
                self.own_feature(map, centre, e, shape, x, y, own);
                for (o, m) in own.iter_mut().zip(f.iter()) {
                    *o = [0, 1, 2, 3].map(|c| weight * m[c] + (1.0 - weight) * o[c]);
                }
                own
            } else {
                f
            };
            let best = if self.exhaustive {
                let mut best = (f32::INFINITY, 0u32);
                img.each_allowed(|pos| {
                    let p = map.uses.as_ref().map_or(1.0, |u| u.factor(e, pos as usize));
                    let d = distance(ex, level, pos, shape, off, f, best.0 / p) * p;
                    if d < best.0 {
                        best = (d, pos);
                    }
                });
                best.1
            } else {
                let slots = (shape.own.len() >= SLOTS_FROM).then_some(&mut *slots);
                self.coherent_candidates(map, centre, e, shape, x, y, img, rng, cands, slots);
                let n = shape.own.len() as f32;
                let mut best = (f32::INFINITY, cands[0].0);
                for &(pos, votes) in cands.iter() {
                    let mut bias = 1.0 + self.coherence * (votes - 1) as f32 / n;
                    if let Some(u) = &map.uses {
                        bias /= u.factor(e, pos as usize);
                    }
                    let d = distance(ex, level, pos, shape, off, f, best.0 * bias) / bias;
                    if d < best.0 {
                        best = (d, pos);
                    }
                }
                best.1
            };
            let old = std::mem::replace(&mut map.src[e][i], best);
            if let Some(u) = &mut map.uses {
                u.moved(e, old, best);
            }
        }
        if let Some(colours) = &mut map.colours {
            colours[i] = self.shown(level, &map.src, i, || (x, y));
        }
    }

    /// `shape` around (x, y) without the points past the output's border, own and parent
    /// (where a parent point's reads reach past the parent level's), with its offsets per
    /// exemplar; `None` when the neighbourhood lies inside. An output that is no tile
    /// says nothing of what lies past one border by what lies inside the other: read on
    /// the torus, a hole along the bottom of grass under the sky was filled with sky
    /// (a new user's trial, issue 30), and clamped reads (the border's pixels repeated)
    /// made copies of the border's own pixels win: a fill beside a bright edge took
    /// more of that edge (`tests/fill.rs`).
    fn cut(&self, shape: &Shape, x: usize, y: usize) -> Option<(Shape, Vec<Offsets>)> {
        let (x, y, half) = (x as isize, y as isize, shape.half);
        let (lw, lh) = (self.lw as isize, self.lh as isize);
        let (pw, ph) = (self.parent_size.0 as isize, self.parent_size.1 as isize);
        let (ox, oy) = (x % 2, y % 2);
        let inside = |v: isize, n: isize| (0..n).contains(&v);
        // (Parent point (dx, dy) reads parent columns x / 2 + dx and, for odd x, the
        // next one; see `parent_feature`.)
        let parent = |dx: isize, dy: isize| {
            !self.with_parent
                || inside(x / 2 + dx, pw)
                    && inside(x / 2 + dx + ox, pw)
                    && inside(y / 2 + dy, ph)
                    && inside(y / 2 + dy + oy, ph)
        };
        let own = |dx: isize, dy: isize| inside(x + dx, lw) && inside(y + dy, lh);
        if own(-half, -half) && own(half, half) && parent(-1, -1) && parent(1, 1) {
            return None;
        }
        let cut = shape.clipped(own, parent)?;
        let offsets = self.mix.exs.iter().map(|ex| Offsets::new(&cut, ex.levels[self.level].width)).collect();
        Some((cut, offsets))
    }

    /// The neighbourhood of exemplar `e`'s own choices around (x, y): each neighbour's
    /// source colour, at this level and the parent's.
    #[allow(clippy::too_many_arguments)]
    fn own_feature(
        &self,
        map: &Map,
        centre: Option<Centre>,
        e: usize,
        shape: &Shape,
        x: usize,
        y: usize,
        v: &mut Vec<Px>,
    ) {
        v.clear();
        let ex = &self.mix.exs[e];
        let img = &ex.levels[self.level];
        v.extend(map.read(&map.src[e], centre, x, y, &shape.own).map(|p| img.data[p as usize]));
        if self.with_parent {
            let (parent, pw) = (&ex.levels[self.level + 1], self.parent_size.0);
            self.parent_feature(shape, x, y, v, |nx, ny| parent.data[self.parent_src[e][ny * pw + nx] as usize]);
        }
    }

    /// Candidate exemplar positions for exemplar `e` at (x, y), each with the number of
    /// proposals it got: each neighbour's source shifted back by the neighbour's offset,
    /// the parent's source scaled up (for a tile also shifted by -1, 0 or 1 in x and y
    /// at random), and a few random positions.
    ///
    /// The parent's candidate alone puts a child at twice its parent's offset into the
    /// exemplar, and coherent copies keep that offset, so the finest pixels copy at
    /// offsets that are multiples of 2 per level (in 256 print tiles, 86% at multiples
    /// of 8), and the exemplar's edges, where copied patches end, fall on the coarsest
    /// level's pixel boundaries: one line in 8 differs 1.24 times the mean across a
    /// line, and the wrap is one of them. The shifted candidate starts patches at other
    /// offsets too (61% at multiples of 8; that line 1.14): over 8 seeds at 256, print's
    /// wrap scores 1.19 (1.22 without it, 1.33 with the parent also read at rounded
    /// positions, see `parent_feature`) and no other photograph's above 1.12. Only
    /// tiles take it: in other outputs the extra seams raised the mean patch energy over
    /// the ten photographs from 5.76 to 5.84, hubble's above texture-synthesis's.
    #[allow(clippy::too_many_arguments)]
    fn coherent_candidates(
        &self,
        map: &Map,
        centre: Option<Centre>,
        e: usize,
        shape: &Shape,
        x: usize,
        y: usize,
        img: &Plane,
        rng: &mut Rng,
        cands: &mut Vec<(u32, u16)>,
        mut slots: Option<&mut Vec<u32>>,
    ) {
        cands.clear();
        let (ew, eh) = (img.width as isize, img.height as isize);
        if let Some(s) = slots.as_deref_mut() {
            s.resize(s.len().max(img.data.len()), 0);
        }
        // Positions a sample mask keeps out are never candidates.
        let mut push = |c: u32, cands: &mut Vec<(u32, u16)>| {
            let known = match slots.as_deref_mut() {
                Some(s) => match s[c as usize] {
                    0 => None,
                    k => Some(k as usize - 1),
                },
                None => cands.iter().position(|(q, _)| *q == c),
            };
            match known {
                Some(k) => cands[k].1 += 1,
                None if img.allows(c) => {
                    cands.push((c, 1));
                    if let Some(s) = slots.as_deref_mut() {
                        s[c as usize] = cands.len() as u32;
                    }
                }
                None => {}
            }
        };
        for (&(dx, dy), p) in shape.own.iter().zip(map.read(&map.src[e], centre, x, y, &shape.own)) {
            let (sx, sy) = img.xy(p);
            let (sx, sy) = (sx - dx, sy - dy);
            if sx >= 0 && sx < ew && sy >= 0 && sy < eh {
                push((sy * ew + sx) as u32, cands);
            }
        }
        if self.with_parent {
            let parent = &self.mix.exs[e].levels[self.level + 1];
            let plw = self.parent_size.0;
            let (px, py) = parent.xy(self.parent_src[e][(y / 2) * plw + x / 2]);
            let sx = (2 * px + (x % 2) as isize).min(ew - 1);
            let sy = (2 * py + (y % 2) as isize).min(eh - 1);
            push((sy * ew + sx) as u32, cands);
            if self.jitter {
                let j = |v: isize, n: isize, rng: &mut Rng| (v + rng.below(3) as isize - 1).clamp(0, n - 1);
                let (jx, jy) = (j(sx, ew, rng), j(sy, eh, rng));
                push((jy * ew + jx) as u32, cands);
            }
        }
        for _ in 0..self.random.max(usize::from(cands.is_empty())) {
            push(img.random(rng), cands);
        }
        if let Some(s) = slots {
            cands.iter().for_each(|&(c, _)| s[c as usize] = 0);
        }
    }
}
