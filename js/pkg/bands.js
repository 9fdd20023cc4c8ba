// Banded texture synthesis on several workers, each with its own wasm instance (no
// shared memory, so no special headers). The engine cuts each pass of each pyramid
// level into bands of rows that depend only on the pass's starting state (see
// src/raster/bands.rs); this spreads a pass's bands over the workers, gathers the rows
// they return into the next state and sends that on. Any number of workers gives the
// image the one-call API gives.

/** The calls that have a banded schedule (for outputs from 512 x 512 pixels). */
export const BANDED = new Set(['synthesizeTexture', 'blendTextures']);

/** What `runBands` returns when the call runs in scanline order instead (small outputs). */
export const NOT_BANDED = Symbol('not banded');

/**
 * `pool`: one `{ request(message, onProgress?) => Promise }` per worker.
 * Returns the RGBA image, or NOT_BANDED.
 */
export async function runBands(pool, method, args, onProgress) {
  const plans = await Promise.all(pool.map((w) => w.request({ bands: 'open', method, args })));
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
      const chunks = split(bands, pool.length);
      const fractions = chunks.map(() => 0);
      const report = () => onProgress?.((finished + chunks.reduce((n, c, k) => n + c.rows * fractions[k], 0)) / total);
      const next = new Uint32Array(maps * width * height);
      await Promise.all(chunks.map((chunk, k) => pool[k]
        .request({ bands: 'run', handle: plans[k].handle, step: index, state, parent: step.pass === 0 ? parent : undefined, from: chunk.from, to: chunk.to },
          (f) => { fractions[k] = f; report(); })
        .then((rows) => place(rows, bands, chunk, maps, width, height, next))));
      finished += height;
      state = next;
    }
    return await pool[0].request({ bands: 'finish', handle: plans[0].handle, state });
  } finally {
    pool.forEach((w, k) => w.request({ bands: 'close', handle: plans[k].handle }).catch(() => {}));
  }
}

/** Contiguous runs of bands, one per worker (at most one per band); bands are of
 *  equal height within a row, so equal counts are equal work. */
function split(bands, workers) {
  const n = Math.min(workers, bands.length);
  return Array.from({ length: n }, (_, k) => {
    const from = Math.round((k * bands.length) / n);
    const to = Math.round(((k + 1) * bands.length) / n);
    return { from, to, rows: bands.slice(from, to).reduce((s, [, rows]) => s + rows, 0) };
  });
}

/** Copies the rows of bands `chunk.from .. chunk.to` (band after band, each map's rows
 *  in turn; a band may wrap past the last row) into the level's maps `into`. */
function place(rows, bands, chunk, maps, width, height, into) {
  let at = 0;
  for (let b = chunk.from; b < chunk.to; b++) {
    const [first, count] = bands[b];
    for (let m = 0; m < maps; m++) {
      for (let r = 0; r < count; r++) {
        const y = (first + r) % height;
        into.set(rows.subarray(at, at + width), (m * height + y) * width);
        at += width;
      }
    }
  }
  if (at !== rows.length) throw new Error(`patternsynth: a worker returned ${rows.length} values for bands ${chunk.from}..${chunk.to}; ${at} were expected.`);
}
