// Promise-based, off-main-thread access to patternsynth, with progress and AbortSignal.
//
//   import { PatternSynthClient } from 'patternsynth/client';
//   const synth = new PatternSynthClient();
//   const out = await synth.synthesizeStrokes(strokes, { width: 800, height: 600 },
//     { signal: controller.signal, onProgress: (f) => bar.value = f });
//
// Calls run one at a time in a module worker. Large texture syntheses and blends (from
// 512 x 512 pixels) also use helper workers, started on the first such call, up to
// `navigator.hardwareConcurrency` in all (bands.js); the image is the same for any number. Aborting the running call
// terminates its workers (a synchronous wasm call cannot be interrupted any other way)
// and the next call starts fresh ones; aborting a queued call just drops it. A worker
// that fails to start or dies rejects the running call with the cause, and the next
// call starts a new one.
import { METHODS } from './api.js';
import { BANDED, NOT_BANDED, runBands } from './bands.js';

/** Workers for one banded call by default: the machine's cores, at most 8. */
const defaultWorkers = () => Math.max(1, Math.min(8, globalThis.navigator?.hardwareConcurrency || 1));

export class PatternSynthClient {
  /**
   * @param {Worker | (() => Worker) | URL | string} [worker] the worker, a function
   *   that makes one, or the URL of worker.js; by default the package's own worker,
   *   written in the form bundlers (Vite, webpack 5) turn into a worker chunk.
   * @param {{ workers?: number }} [options] how many workers a large texture call may
   *   use (default: the machine's cores, at most 8; 1 with a given Worker instance).
   */
  constructor(worker, { workers } = {}) {
    let size = workers ?? defaultWorkers();
    if (!(Number.isInteger(size) && size >= 1)) throw new TypeError(`workers must be a whole number from 1, got ${workers}.`);
    /** The worker script's URL, where the client knows it (for messages). */
    this.workerUrl = null;
    if (worker === undefined) {
      // For messages only, and not written as `new URL('./worker.js', import.meta.url)`:
      // bundlers emit a file for each such expression (Parcel a second worker bundle).
      this.workerUrl = String(import.meta.url).replace(/[^/?#]*([?#].*)?$/, 'worker.js');
      this.makeWorker = () => new Worker(new URL('./worker.js', import.meta.url), { type: 'module' });
    } else if (typeof worker === 'function') {
      this.makeWorker = worker;
    } else if (typeof worker === 'string' || worker instanceof URL) {
      this.workerUrl = String(worker);
      this.givenUrl = true;
      this.makeWorker = () => new Worker(worker, { type: 'module' });
    } else if (worker && typeof worker.postMessage === 'function') {
      // A given Worker is used until it is terminated; then no fresh one can be made.
      size = 1;
      let given = worker;
      this.makeWorker = () => {
        if (!given) throw new Error('The Worker passed to PatternSynthClient was terminated (after an abort or a failure); pass a function that makes Workers to allow restarts.');
        const w = given;
        given = null;
        return w;
      };
    } else {
      throw new TypeError('PatternSynthClient takes a Worker, a function returning a Worker, or the URL of worker.js.');
    }
    this.size = size;
    this.worker = null;
    /** Workers besides `worker`, started for banded calls and kept for the next. */
    this.helpers = [];
    /** Band messages awaiting their answer, by id. */
    this.requests = new Map();
    this.queue = [];
    this.current = null;
    this.nextId = 1;
  }

  /** Stops the workers; pending calls are rejected. */
  terminate() {
    this.stopWorkers();
    const pending = [this.current, ...this.queue].filter(Boolean);
    this.current = null;
    this.queue = [];
    for (const job of pending) job.reject(abortError('The worker was terminated.'));
  }

  /**
   * The stroke result last kept (`{ keep: true }` in a synthesizeStrokes or strokeTile
   * call's options) in another style, without synthesizing it again: `style` is
   * `{ colors, background, opacity }` (`colors[k]`: `#rrggbb` for class k, or null to
   * keep it; background `#rrggbb` or null; opacity 0 to 1). Resolves to `{ svgBlob,
   * preview? }` (`preview`: as in the call options, drawn in the worker).
   */
  restyle(style, preview, options = {}) {
    return this.run('restyle', [style, preview], options);
  }

  run(method, args, { signal, onProgress, fields, preview, keep } = {}) {
    return new Promise((resolve, reject) => {
      if (signal?.aborted) return reject(abortError());
      const job = { id: this.nextId++, method, args, resolve, reject, onProgress, signal, shape: { fields, preview, keep } };
      job.onAbort = () => this.abort(job);
      signal?.addEventListener('abort', job.onAbort, { once: true });
      this.queue.push(job);
      this.pump();
    });
  }

  abort(job) {
    if (this.current === job) {
      this.finish(job, abortError(), true);
    } else {
      const i = this.queue.indexOf(job);
      if (i >= 0) {
        this.queue.splice(i, 1);
        job.reject(abortError());
      }
    }
  }

  /** A new worker wired to this client. */
  start() {
    const worker = this.makeWorker();
    worker.onmessage = ({ data }) => this.receive(worker, data);
    worker.onerror = (e) => {
      e.preventDefault?.();
      this.dead(worker, e);
    };
    worker.onmessageerror = () => this.dead(worker, { message: 'a message could not be read' });
    return worker;
  }

  pump() {
    if (this.current || this.queue.length === 0) return;
    const job = (this.current = this.queue.shift());
    try {
      this.worker ??= this.start();
      if (this.size > 1 && BANDED.has(job.method)) return void this.runBanded(job);
      this.worker.postMessage({ id: job.id, method: job.method, args: job.args, ...job.shape });
    } catch (e) {
      // e.g. a SecurityError for a worker script on another origin.
      this.finish(job, new Error(`The patternsynth worker could not start: ${e?.message ?? e}${this.crossOrigin()}`, { cause: e }), true);
    }
  }

  /** Runs a texture call's bands on the main worker and helpers (bands.js). The job is
   *  opened on the main worker first: helpers start only for a call that has bands
   *  (from 512 x 512), not for every texture call. */
  async runBanded(job) {
    let result;
    try {
      const pool = () => [this.worker, ...this.helpers].map((worker) => ({
        request: (message, onProgress) => this.request(worker, message, onProgress),
      }));
      const first = await pool()[0].request({ bands: 'open', method: job.method, args: job.args });
      if (first) {
        while (this.helpers.length < this.size - 1) this.helpers.push(this.start());
      }
      result = first ? await runBands(pool(), job.method, job.args, job.onProgress, first) : NOT_BANDED;
    } catch (e) {
      if (this.current === job) this.finish(job, e, false);
      return;
    }
    if (this.current !== job) return;
    if (result === NOT_BANDED) this.worker.postMessage({ id: job.id, method: job.method, args: job.args, ...job.shape });
    else this.finish(job, null, false, result);
  }

  /** Sends a band message to `worker`; resolves with its result. */
  request(worker, message, onProgress) {
    return new Promise((resolve, reject) => {
      if (worker !== this.worker && !this.helpers.includes(worker)) return reject(abortError('The worker was terminated.'));
      const id = this.nextId++;
      this.requests.set(id, { worker, resolve, reject, onProgress });
      worker.postMessage({ id, ...message });
    });
  }

  receive(worker, data) {
    const request = this.requests.get(data.id);
    if (request) {
      if ('progress' in data) return void request.onProgress?.(data.progress);
      this.requests.delete(data.id);
      if (!('error' in data)) return void request.resolve(data.result);
      const err = new Error(data.error);
      if (data.name && data.name !== 'Error') err.name = data.name;
      return void request.reject(err);
    }
    const job = this.current;
    if (worker !== this.worker || !job || data.id !== job.id) return;
    if ('progress' in data) return void job.onProgress?.(data.progress);
    if ('error' in data) {
      const err = new Error(data.error);
      if (data.name && data.name !== 'Error') err.name = data.name;
      this.finish(job, err, false);
    } else {
      this.finish(job, null, false, data.result);
    }
  }

  /** A hint when the worker's script is on another origin (a CDN), which browsers do not
   *  start as a worker: the README's recipe starts it from a same-origin blob: module. */
  crossOrigin() {
    let url;
    try {
      url = this.workerUrl && new URL(this.workerUrl, globalThis.location?.href);
    } catch {
      return '';
    }
    if (!url || !globalThis.location || url.origin === globalThis.location.origin || url.protocol === 'blob:') return '';
    return ` The worker script ${url.href} is on another origin than the page (${globalThis.location.origin}), and browsers start workers only from the page's origin: start it from a same-origin blob: module that imports it (the package README, "From another origin").`;
  }

  /** The worker failed to load or died: the running call fails with the cause. */
  dead(worker, event) {
    if (worker !== this.worker && !this.helpers.includes(worker)) return;
    const where = event?.filename ? ` (${event.filename}${event.lineno ? `:${event.lineno}` : ''})` : '';
    const cause = event?.message || 'its script, or a module it imports, could not be loaded or evaluated; see the browser console';
    // Not loaded at all: most often a setup that does not serve the worker and its
    // modules (a bundler that bundles no workers); name the script where it was given.
    const given = this.workerUrl && this.givenUrl ? ` The worker script is ${new URL(this.workerUrl, globalThis.location?.href).href}.` : '';
    const recipe = event?.message ? '' : `${given} If your bundler does not bundle workers, copy the package's files beside your bundle and pass the worker's URL: see "With a bundler" in the package README.`;
    const error = new Error(`The patternsynth worker failed: ${cause}${where}.${this.crossOrigin() || recipe}`);
    if (this.current) this.finish(this.current, error, true);
    else this.stopWorkers();
  }

  /** Terminates every worker; their unanswered band messages fail. */
  stopWorkers() {
    for (const w of [this.worker, ...this.helpers]) w?.terminate();
    this.worker = null;
    this.helpers = [];
    const requests = [...this.requests.values()];
    this.requests.clear();
    for (const r of requests) r.reject(abortError('The worker was terminated.'));
  }

  /** Settles the running `job`; `stop` also ends its worker (the next call makes one). */
  finish(job, error, stop, result) {
    job.signal?.removeEventListener('abort', job.onAbort);
    if (stop) this.stopWorkers();
    this.current = null;
    if (error) job.reject(error);
    else job.resolve(result);
    this.pump();
  }
}

// One method per entry point of the table, taking its arguments and then CallOptions.
for (const [name, spec] of Object.entries(METHODS)) {
  Object.defineProperty(PatternSynthClient.prototype, name, {
    value: function (...args) {
      return this.run(name, args.slice(0, spec.args), args[spec.args]);
    },
    writable: true,
    configurable: true,
  });
}

function abortError(message = 'The operation was aborted.') {
  return new DOMException(message, 'AbortError');
}
