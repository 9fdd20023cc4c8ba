//! The worker protocol of banded texture synthesis (`js/pkg/bands.js` drives it): each
//! worker opens the same job, runs the bands it is given of each step from the step's
//! starting state, and returns the rows of its bands of the last step as colours (for a
//! fused output, `synthesis::fusion`, a step of its own after the synthesis's, whose
//! bands are coloured from the whole finest level). Jobs live in this instance between
//! calls, under a handle.

use super::texture::{blend_args, style_args, texture_args};
use super::{error, js_error, JsProgress};
use crate::progress::Throttle;
use crate::raster::{self, bands, synthesis::Job, synthesis::Uses};
use std::cell::RefCell;
use std::collections::BTreeMap;
use wasm_bindgen::prelude::*;

/// An open job, the parent level's sources of the level it is at, and the step it is
/// at, kept for the step's next bands.
struct Open {
    job: Job,
    parent: Vec<Vec<u32>>,
    start: Option<StepStart>,
}

/// A step's starting maps (none at a level's first pass, which starts from the parent)
/// and their use counts; at the colour step, the fused output's colour map made from
/// them (`Job::keep`).
struct StepStart {
    step: usize,
    maps: Option<Vec<Vec<u32>>>,
    uses: Option<Uses>,
    keep: Option<crate::raster::synthesis::Keep>,
}

/// Jobs kept open at once. The client closes each job when its call ends, and runs one
/// call at a time; a job past this many was forgotten (a caller that never closed it),
/// so the oldest is closed to keep its memory from piling up.
const MAX_OPEN_JOBS: usize = 8;

thread_local! {
    static OPEN: RefCell<(u32, BTreeMap<u32, Open>)> = const { RefCell::new((0, BTreeMap::new())) };
}

fn with<T>(handle: u32, f: impl FnOnce(&mut Open) -> Result<T, JsValue>) -> Result<T, JsValue> {
    OPEN.with_borrow_mut(|(_, jobs)| match jobs.get_mut(&handle) {
        Some(open) => f(open),
        None => Err(error(&format!(
            "No open texture job {handle} in this worker (it was closed, or the engine restarted)."
        ))),
    })
}

/// Prepares `method(...args)` (`synthesizeTexture`, `blendTextures` or `transferStyle`) for banded runs:
/// `{ handle, exemplars, steps: [{ level, pass, width, height, bands: [[first, rows]...] }] }`,
/// or `null` when the call runs in scanline order (small outputs), in one call.
#[wasm_bindgen(js_name = bandsOpen)]
pub fn bands_open(method: &str, args: js_sys::Array) -> Result<JsValue, JsValue> {
    let job = match method {
        "synthesizeTexture" => {
            let (exemplars, opts) = texture_args(args.get(0), args.get(1))?;
            if opts.keep_layout {
                // The layout is the sources, which banded workers turn into colours.
                return Ok(JsValue::NULL);
            }
            raster::pool_job(&exemplars, &opts).map(|(job, _)| job)
        }
        "transferStyle" => {
            let (style, target, opts) = style_args(args.get(0), args.get(1), args.get(2))?;
            raster::style_job(&style, &target, &opts)
        }
        "blendTextures" => {
            let (a, b, opts) = blend_args(args.get(0), args.get(1), args.get(2))?;
            raster::blend_job(&a, &b, &opts)
        }
        other => return Err(error(&format!("{other} has no banded schedule."))),
    }
    .map_err(js_error)?;
    if !job.params.banded() {
        return Ok(JsValue::NULL);
    }
    let steps = js_sys::Array::new();
    let push = |level: usize, pass: usize, bands: Vec<bands::Band>| -> Result<(), JsValue> {
        let (width, height) = job.sizes[level];
        let list = js_sys::Array::new();
        for b in bands {
            list.push(&js_sys::Array::of2(&(b.first as u32).into(), &(b.rows as u32).into()));
        }
        let o = js_sys::Object::new();
        for (k, v) in [
            ("level", level.into()),
            ("pass", pass.into()),
            ("width", width.into()),
            ("height", height.into()),
            ("bands", list.into()),
        ] {
            js_sys::Reflect::set(&o, &k.into(), &v)?;
        }
        steps.push(&o);
        Ok(())
    };
    let synthesis = bands::steps(&job);
    for &step in &synthesis {
        push(step.level, step.pass, bands::bands(&job, step))?;
    }
    // A fused output's colours, in a step of their own after the last pass.
    if let Some(list) = bands::colour_bands(&job) {
        push(0, synthesis.last().map_or(0, |s| s.pass + 1), list)?;
    }
    let exemplars = job.exemplars();
    let handle = OPEN.with_borrow_mut(|(next, jobs)| {
        while jobs.len() >= MAX_OPEN_JOBS {
            jobs.pop_first();
        }
        *next += 1;
        jobs.insert(*next, Open { job, parent: Vec::new(), start: None });
        *next
    });
    let out = js_sys::Object::new();
    js_sys::Reflect::set(&out, &"handle".into(), &handle.into())?;
    js_sys::Reflect::set(&out, &"exemplars".into(), &exemplars.into())?;
    js_sys::Reflect::set(&out, &"steps".into(), &steps)?;
    Ok(out.into())
}

/// Splits one array holding each exemplar's map of a level in turn.
fn maps(all: &js_sys::Uint32Array, exemplars: usize, pixels: usize, what: &str) -> Result<Vec<Vec<u32>>, JsValue> {
    if all.length() as usize != exemplars * pixels {
        return Err(error(&format!(
            "The {what} holds {} values; {exemplars} maps of {pixels} were expected.",
            all.length()
        )));
    }
    Ok((0..exemplars).map(|e| all.subarray((e * pixels) as u32, ((e + 1) * pixels) as u32).to_vec()).collect())
}

/// Runs bands `from..to` of step `step` (an index into `steps`). `state`: the level's
/// maps at the start of the step, with the step's first bands in this worker (kept for
/// its next ones); at a level's first pass there is none (the level starts from the
/// parent upsampled). `parent`: the parent level's maps, with the level's first bands
/// in this worker. Returns the bands' rows, band after band: each exemplar's rows in
/// turn (a `Uint32Array` of sources), or at the last step, whose rows are final, their
/// colours (a `Uint8Array` of RGBA), so that colouring is shared out too.
#[wasm_bindgen(js_name = bandsRun)]
pub fn bands_run(
    handle: u32,
    step: usize,
    state: Option<js_sys::Uint32Array>,
    parent: Option<js_sys::Uint32Array>,
    from: usize,
    to: usize,
    on_progress: JsValue,
) -> Result<JsValue, JsValue> {
    let mut progress = JsProgress::from_js(on_progress)?;
    with(handle, |open| {
        let job = &open.job;
        let steps = bands::steps(job);
        if step == steps.len() {
            if let Some(list) = bands::colour_bands(job) {
                return colour_step(open, step, state, &list, from, to);
            }
        }
        let &s = steps.get(step).ok_or_else(|| error(&format!("There is no step {step}.")))?;
        let list = bands::bands(job, s);
        if from > to || to > list.len() {
            return Err(error(&format!("Bands {from}..{to} are not among the step's {}.", list.len())));
        }
        let n = job.exemplars();
        if let Some(p) = parent {
            if s.level + 1 < job.levels {
                open.parent = maps(&p, n, job.level_pixels(s.level + 1), "parent")?;
            }
        }
        let kept = matches!(&open.start, Some(k) if k.step == step);
        if !kept || state.is_some() {
            let start = match state {
                Some(st) => Some(maps(&st, n, job.level_pixels(s.level), "state")?),
                None if s.pass == 0 => None,
                None => return Err(error(&format!("Step {step}'s starting state was not given to this worker."))),
            };
            let uses = match &start {
                Some(m) => bands::uses(job, s, bands::Start::Maps(m), &open.parent),
                None => bands::uses(job, s, bands::Start::Initial, &open.parent),
            };
            open.start = Some(StepStart { step, maps: start, uses, keep: None });
        }
        let Some(StepStart { maps, uses, .. }) = &open.start else { unreachable!("set above") };
        let start = match maps {
            Some(m) => bands::Start::Maps(m),
            None => bands::Start::Initial,
        };
        // (A fused output is coloured in a step of its own: `colour_step`.)
        let last = step + 1 == steps.len() && !job.fused();
        let total: usize = list[from..to].iter().map(|b| b.rows).sum();
        let mut done = 0usize;
        let mut throttle = Throttle::new(&mut progress);
        let width = job.sizes[s.level].0;
        let (mut sources, mut colours) = if last {
            (Vec::new(), Vec::with_capacity(4 * total * width))
        } else {
            (Vec::with_capacity(n * total * width), Vec::new())
        };
        let mut result = Ok(());
        for (b, band) in list.iter().enumerate().take(to).skip(from) {
            let rows = bands::run(job, s, start, uses, &open.parent, b, &mut || {
                done += 1;
                throttle.tick(done as f64 / total.max(1) as f64)
            });
            match rows {
                Ok(rows) if last => colours.extend(job.colour_rows(&rows, band.first, band.rows)),
                Ok(rows) => rows.iter().for_each(|r| sources.extend_from_slice(r)),
                Err(e) => {
                    result = Err(e);
                    break;
                }
            }
        }
        Ok((result, last, sources, colours))
    })
    .and_then(|(result, last, sources, colours)| {
        progress.finish(result)?;
        Ok(if last {
            js_sys::Uint8Array::from(&colours[..]).into()
        } else {
            js_sys::Uint32Array::from(&sources[..]).into()
        })
    })
}

/// The colour step of a fused output (`bands::colour_bands`), one past the synthesis's
/// steps: bands `from..to` of the finest level coloured from the whole level (`state`,
/// with this worker's first band of the step, kept for its next ones).
type Ran = (crate::Result<()>, bool, Vec<u32>, Vec<u8>);
fn colour_step(
    open: &mut Open,
    step: usize,
    state: Option<js_sys::Uint32Array>,
    list: &[bands::Band],
    from: usize,
    to: usize,
) -> Result<Ran, JsValue> {
    if from > to || to > list.len() {
        return Err(error(&format!("Bands {from}..{to} are not among the step's {}.", list.len())));
    }
    let job = &open.job;
    if let Some(st) = state {
        let m = maps(&st, job.exemplars(), job.level_pixels(0), "state")?;
        let keep = Some(job.keep(&m));
        open.start = Some(StepStart { step, maps: Some(m), uses: None, keep });
    }
    let Some(StepStart { maps: Some(m), step: kept, keep: Some(keep), .. }) = &open.start else {
        return Err(error(&format!("Step {step}'s starting state was not given to this worker.")));
    };
    if *kept != step {
        return Err(error(&format!("Step {step}'s starting state was not given to this worker.")));
    }
    let colours = list[from..to].iter().flat_map(|b| job.fused_band(m, b.first, b.rows, keep)).collect();
    Ok((Ok(()), true, Vec::new(), colours))
}

/// Frees a job (closing an unknown handle does nothing).
#[wasm_bindgen(js_name = bandsClose)]
pub fn bands_close(handle: u32) {
    OPEN.with_borrow_mut(|(_, jobs)| jobs.remove(&handle));
}

/// How many jobs are open (the package keeps an instance that holds any).
#[wasm_bindgen(js_name = bandsOpenJobs)]
pub fn bands_open_jobs() -> u32 {
    OPEN.with_borrow(|(_, jobs)| jobs.len() as u32)
}
