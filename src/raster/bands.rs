//! The banded schedule: Wei-Levoy synthesis in an order that several workers can share
//! and that gives the same image however many there are.
//!
//! Each level starts from its parent's sources upsampled (Lefebvre and Hoppe 2005: the
//! child (2x + i, 2y + j) of the exemplar position a parent pixel copies), or at the
//! coarsest level from the same quilt as in scanline order (noise for a tile). Then come
//! the same passes as in scanline order (one causal, none on a quilt, then corrections
//! with full neighbourhoods, the first reversed; a tileable output ends each level with
//! the pixels along the wrap once more), but each pass cuts the level into bands of rows.
//! A band is synthesized in scanline order reading its own rows as they change and the rows around it as they were when the pass began, with a
//! random stream of its own; so the bands of a pass are independent, and a band's
//! result depends only on the pass's starting state. Consecutive passes shift the bands
//! by half a band, so that each band edge of one pass lies in the middle of a band of
//! the next, which joins the two sides in its scanline order.

use super::image::Rgba;
use super::synthesis::{Job, Scratch, Uses};
use crate::error::Result;
use crate::progress::Throttle;
use crate::rng::Rng;

/// Rows per band (at least; a level shorter than two bands is one band).
pub const BAND_ROWS: usize = 32;

/// One pass over one level.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Step {
    pub level: usize,
    /// 0 is the causal pass, then the corrections, then (for a tileable output) the wrap pass.
    pub pass: usize,
}

/// A band of a step: rows `first .. first + rows` of the level, modulo its height.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Band {
    pub first: usize,
    pub rows: usize,
}

/// What a pass does.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Kind {
    /// Every pixel with its causal neighbourhood (the first pass).
    Causal,
    /// Every pixel with its full neighbourhood, in reverse order or not.
    Correction { reverse: bool },
    /// A tileable output's last pass: only the pixels along the wrap, with full
    /// neighbourhoods (as in `synthesis::synthesize`). At 512 x 512 the wrap's mean
    /// difference was 1.23 times the mean across all boundaries; this pass alone took it
    /// to 1.20; with the coarsest level's causal pass as one band (`bands`) it is 1.11.
    Wrap,
}

fn kind(job: &Job, level: usize, pass: usize) -> Kind {
    match pass {
        0 if job.started(level) => Kind::Correction { reverse: false },
        0 => Kind::Causal,
        p if job.params.tileable && p == passes(job) - 1 => Kind::Wrap,
        p => Kind::Correction { reverse: p % 2 == 1 },
    }
}

/// Passes per level.
fn passes(job: &Job) -> usize {
    1 + job.params.corrections.max(1) + usize::from(job.params.tileable)
}

/// The steps in order: coarse to fine, each level's passes in turn.
pub fn steps(job: &Job) -> Vec<Step> {
    let passes = passes(job);
    (0..job.levels).rev().flat_map(|level| (0..passes).map(move |pass| Step { level, pass })).collect()
}

/// The bands of `step`. Their number depends on the level's size only, not on how many
/// workers run them.
pub fn bands(job: &Job, step: Step) -> Vec<Band> {
    let lh = job.sizes[step.level].1;
    // The coarsest level's causal pass (a tile's; a quilt, coherent from the start, has
    // none, and all its passes are banded) is one band: it starts from noise, so a band's
    // first rows would be made against noise above them, and the break between bands
    // carried down to every finer level (at 512 x 512, rows within 16 of the middle and
    // of the wrap differed 1.1-1.2 times the mean). Its later passes start from that
    // coherent state, like any finer level's, and are banded. With all of the coarsest
    // level serial (a 16th of the pixels with three levels) the 2-worker speed-up at
    // 1024 x 1024 was 1.69; with its causal pass only, 1.78 (`bench/workers.mjs`, one
    // session); the wrap at 512 x 512 is 1.11 times the mean boundary, against the 1.10
    // measured with the whole level as one band.
    let serial = kind(job, step.level, step.pass) == Kind::Causal && step.level + 1 == job.levels;
    let n = if lh >= 2 * BAND_ROWS && !serial { lh / BAND_ROWS } else { 1 };
    if n == 1 {
        return vec![Band { first: 0, rows: lh }];
    }
    let shift = if step.pass % 2 == 1 { lh / n / 2 } else { 0 };
    (0..n)
        .map(|b| {
            let (top, bottom) = (b * lh / n, (b + 1) * lh / n);
            Band { first: (top + shift) % lh, rows: bottom - top }
        })
        .collect()
}

/// A random stream for each (level, pass, band), so a band draws the same numbers
/// whichever worker runs it and whenever.
fn stream(seed: u64, level: usize, pass: usize, band: usize) -> Rng {
    let mut mix = Rng::new(seed ^ ((level as u64) << 48) ^ ((pass as u64) << 40) ^ band as u64);
    Rng::new(mix.next_u64())
}

/// The `pass` number of the coarsest level's noise streams.
const NOISE: usize = 255;

/// The state a level starts from: a quilt (`Job::started`) or noise at the coarsest
/// level, otherwise the parent's sources upsampled (the child position under each pixel,
/// clamped to the exemplar).
pub fn initial(job: &Job, level: usize, parent: &[Vec<u32>]) -> Vec<Vec<u32>> {
    let (lw, lh) = job.sizes[level];
    (0..job.exemplars())
        .map(|e| {
            let mut out = Vec::with_capacity(lw * lh);
            (0..lh).for_each(|y| initial_row(job, level, parent, e, y, &mut out));
            out
        })
        .collect()
}

/// Appends row `y` of exemplar `e`'s map in `initial` to `out` (each row on its own, so
/// that a band's window is made without the rest of the level; a quilt is laid whole,
/// once per job).
fn initial_row(job: &Job, level: usize, parent: &[Vec<u32>], e: usize, y: usize, out: &mut Vec<u32>) {
    let lw = job.sizes[level].0;
    if job.started(level) {
        out.extend_from_slice(&job.starts()[e][y * lw..(y + 1) * lw]);
        return;
    }
    if level + 1 == job.levels {
        let mut rng = stream(job.params.seed, level, NOISE, y * job.exemplars() + e);
        out.extend((0..lw).map(|_| job.random_position(e, level, &mut rng)));
        return;
    }
    let plw = job.sizes[level + 1].0;
    let (ew, eh) = job.exemplar_size(e, level);
    let pw = job.exemplar_size(e, level + 1).0;
    let sy = |s: usize| (2 * (s / pw) + y % 2).min(eh - 1);
    out.extend((0..lw).map(|x| {
        let s = parent[e][(y / 2) * plw + x / 2] as usize;
        let sx = (2 * (s % pw) + x % 2).min(ew - 1);
        (sy(s) * ew + sx) as u32
    }));
}

/// What a step starts from.
#[derive(Clone, Copy)]
pub enum Start<'a> {
    /// The level's maps as the previous pass left them.
    Maps(&'a [Vec<u32>]),
    /// The level's `initial` state (its first pass), made row by row as bands need it.
    Initial,
}

/// Runs band `b` of `step` from the step's starting state `start` (with its use counts,
/// `uses(start)`, which the band then keeps up to date for itself) and the parent
/// level's sources; returns the band's rows of each map, top row first. `on_row` is called after each row (for progress; an error stops the band).
pub fn run(
    job: &Job,
    step: Step,
    start: Start,
    uses: &Option<Uses>,
    parent: &[Vec<u32>],
    b: usize,
    on_row: &mut dyn FnMut() -> Result<()>,
) -> Result<Vec<Vec<u32>>> {
    let Step { level, pass } = step;
    let (lw, lh) = job.sizes[level];
    let band = bands(job, step)[b];
    // The band and the rows its neighbourhoods reach, as they were at the start.
    let halo = if band.rows == lh { 0 } else { job.full.half as usize };
    let first = (band.first + lh - halo) % lh;
    let rows = band.rows + 2 * halo;
    let window = (0..job.exemplars())
        .map(|e| {
            let mut w = Vec::with_capacity(rows * lw);
            for r in 0..rows {
                let y = (first + r) % lh;
                match start {
                    Start::Maps(maps) => w.extend_from_slice(&maps[e][y * lw..(y + 1) * lw]),
                    Start::Initial => initial_row(job, level, parent, e, y, &mut w),
                }
            }
            w
        })
        .collect();
    let sweep = job.pass(level, parent);
    let mut map = sweep.map(window, uses.clone(), first, rows);
    if band.rows < lh {
        // (A band balances its own rows' colours: see `Uses::balance_rows`.)
        if let Some(u) = &mut map.uses {
            for (e, w) in map.src.iter().enumerate() {
                u.balance_rows(e, &w[halo * lw..(halo + band.rows) * lw]);
            }
        }
    }
    let kind = kind(job, level, pass);
    let (shape, use_full, reverse) = match kind {
        Kind::Causal => (&job.causal, false, false),
        Kind::Correction { reverse } => (&job.full, true, reverse),
        Kind::Wrap => (&job.full, true, false),
    };
    let mut rng = stream(job.params.seed, level, pass, b);
    let mut scratch = Scratch::new(&job.full);
    for r in 0..band.rows {
        let y = (band.first + if reverse { band.rows - 1 - r } else { r }) % lh;
        for c in 0..lw {
            let x = if reverse { lw - 1 - c } else { c };
            if kind == Kind::Wrap && !job.along_wrap(level, x, y) {
                continue;
            }
            sweep.pixel(&mut map, shape, use_full, x, y, &mut rng, &mut scratch);
        }
        on_row()?;
    }
    Ok(map.src.into_iter().map(|w| w[halo * lw..(halo + band.rows) * lw].to_vec()).collect())
}

/// The use counts of a step's starting state (the same in every worker).
pub fn uses(job: &Job, step: Step, start: Start, parent: &[Vec<u32>]) -> Option<Uses> {
    let (level, lw) = (step.level, job.sizes[step.level].0);
    match start {
        Start::Maps(maps) => Uses::count(job, level, |e, y, out| out.extend_from_slice(&maps[e][y * lw..(y + 1) * lw])),
        Start::Initial => Uses::count(job, level, |e, y, out| initial_row(job, level, parent, e, y, out)),
    }
}

/// Writes a band's rows (as `run` returns them) into a level's maps.
pub fn store(job: &Job, step: Step, b: usize, rows: &[Vec<u32>], into: &mut [Vec<u32>]) {
    let (lw, lh) = job.sizes[step.level];
    let band = bands(job, step)[b];
    for (src, dst) in rows.iter().zip(into.iter_mut()) {
        for r in 0..band.rows {
            let y = (band.first + r) % lh;
            dst[y * lw..(y + 1) * lw].copy_from_slice(&src[r * lw..(r + 1) * lw]);
        }
    }
}

/// The bands a fused output's colours are made in, when it is banded (the last step's):
/// after the synthesis, one more step for the workers, each band fused from the whole
/// finest level with the rows around it (`Job::fused_band`), so band edges are no seams.
/// `None` when the last step's rows are coloured as they are made.
pub fn colour_bands(job: &Job) -> Option<Vec<Band>> {
    let last = *steps(job).last()?;
    (job.fused() && job.params.banded()).then(|| bands(job, last))
}

/// The banded schedule run in this thread: the same image as any number of workers
/// running the bands of each step (see `tests/texture.rs`).
pub fn synthesize(job: &Job, progress: &mut Throttle) -> Result<Rgba> {
    Ok(job.colours(&sources(job, progress)?))
}

/// `synthesize`'s finest level as exemplar positions (`synthesis::sources`).
pub fn sources(job: &Job, progress: &mut Throttle) -> Result<Vec<Vec<u32>>> {
    let steps = steps(job);
    let total: usize = steps.iter().map(|s| job.sizes[s.level].1).sum();
    let mut done = 0usize;
    let mut parent: Vec<Vec<u32>> = Vec::new();
    let mut state: Vec<Vec<u32>> = Vec::new();
    for &step in &steps {
        let start = if step.pass == 0 {
            parent = std::mem::take(&mut state);
            state = initial(job, step.level, &parent);
            Start::Initial
        } else {
            Start::Maps(&state)
        };
        let uses = uses(job, step, start, &parent);
        let mut next = state.clone();
        for b in 0..bands(job, step).len() {
            let rows = run(job, step, start, &uses, &parent, b, &mut || {
                done += 1;
                progress.tick(done as f64 / total as f64)
            })?;
            store(job, step, b, &rows, &mut next);
        }
        state = next;
    }
    progress.tick(1.0)?;
    Ok(state)
}
