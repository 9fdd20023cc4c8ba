// Banded texture synthesis on several workers, each with its own wasm instance (no
// shared memory, so no special headers). The engine cuts each pass of each pyramid
// level into bands of rows that depend only on the pass's starting state (see
// src/raster/bands.rs); this spreads a pass's bands over the workers, gathers the rows
// they return into the next state and sends that on. Any number of workers gives the
// image the one-call API gives.

/** The calls that have a banded schedule (for outputs from 512 x 512 pixels). */
export const BANDED = new Set(['synthesizeTexture', 'blendTextures', 'transferStyle']);

/** What `runBands` returns when the call runs in scanline order instead (small outputs). */
export const NOT_BANDED = Symbol('not banded');

/**
 * `pool`: one `{ request(message, onProgress?) => Promise }` per worker; `first`: the
 * plan the first worker already opened, if it did. Returns the RGBA image, or NOT_BANDED.
 */
export async function runBands(pool, method, args, onProgress, first) {
  const open = (w) => w.request({ bands: 'open', method, args });
  const plans = await Promise.all(pool.map((w, k) => (k === 0 && first ? first : open(w))));
  const plan = plans[0];
  if (!plan) return NOT_BANDED;
  try {
    const maps = plan.exemplars;
    const total = plan.steps.reduce((n, s) => n + s.height, 0);
    let finished = 0;
    let parent;
    let state;
    for (const [index, step] of plan.steps.entries()) {
      const { width, height, bands } = step;
      if (step.pass === 0) {
        parent = state;
        state = undefined;
      }
      // Bands go one at a time to whichever worker is free, so a slow worker (or a
      // costly band) holds up the step by one band at most. A worker gets the step's
      // starting state and the parent level with its first band of the step, and keeps
      // them. The last step's bands come back as colours: its rows are final.
      const last = index === plan.steps.length - 1;
      const next = last ? new Uint8ClampedArray(4 * width * height) : new Uint32Array(maps * width * height);
      const running = new Map();
      let done = 0;
      let queue = 0;
      const report = () => {
        let rows = done;
        for (const [b, f] of running) rows += f * bands[b][1];
        onProgress?.((finished + rows) / total);
      };
      await Promise.all(pool.slice(0, bands.length).map(async (worker, k) => {
        for (let first = true; queue < bands.length; first = false) {
          const b = queue++;
          running.set(b, 0);
          const rows = await worker.request({
            bands: 'run', handle: plans[k].handle, step: index, from: b, to: b + 1,
            state: first ? state : undefined, parent: first ? parent : undefined,
          }, (f) => { running.set(b, f); report(); });
          if (last) place(rows, bands[b], 1, 4 * width, height, next);
          else place(rows, bands[b], maps, width, height, next);
          running.delete(b);
          done += bands[b][1];
          report();
        }
      }));
      finished += height;
      state = next;
    }
    const { width, height } = plan.steps[plan.steps.length - 1];
    return { width, height, data: state };
  } finally {
    pool.forEach((w, k) => w.request({ bands: 'close', handle: plans[k].handle }).catch(() => {}));
  }
}

/** Copies a band's rows (each map's rows in turn; a band may wrap past the last
 *  row) into the level's maps `into`, `width` values a row (RGBA bytes: 4 a pixel). */
function place(rows, [first, count], maps, width, height, into) {
  if (rows.length !== maps * count * width) throw new Error(`patternsynth: a worker returned ${rows.length} values for a band of ${count} rows.`);
  let at = 0;
  for (let m = 0; m < maps; m++) {
    for (let r = 0; r < count; r++) {
      const y = (first + r) % height;
      into.set(rows.subarray(at, at + width), (m * height + y) * width);
      at += width;
    }
  }
}
