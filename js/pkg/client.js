// Promise-based, off-main-thread access to patternsynth, with progress and AbortSignal.
//
//   import { PatternSynthClient } from 'patternsynth/client';
//   const synth = new PatternSynthClient();
//   const out = await synth.synthesizeStrokes(strokes, { width: 800, height: 600 },
//     { signal: controller.signal, onProgress: (f) => bar.value = f });
//
// Calls run one at a time in a module worker. Aborting the running call terminates the
// worker (a synchronous wasm call cannot be interrupted any other way) and the next
// call starts a fresh one; aborting a queued call just drops it.

export class PatternSynthClient {
  /** @param {URL | string} [workerUrl] where worker.js is served (defaults to beside this file) */
  constructor(workerUrl = new URL('./worker.js', import.meta.url)) {
    this.workerUrl = workerUrl;
    this.worker = null;
    this.queue = [];
    this.current = null;
    this.nextId = 1;
  }

  parseSvg(svg, opts, options) { return this.run('parseSvg', [svg, opts], options); }
  parseSvgReport(svg, opts, options) { return this.run('parseSvgReport', [svg, opts], options); }
  classifyStrokes(strokes, opts, options) { return this.run('classifyStrokes', [strokes, opts], options); }
  synthesizeStrokes(strokes, opts, options) { return this.run('synthesizeStrokes', [strokes, opts], options); }
  strokeTile(strokes, opts, options) { return this.run('strokeTile', [strokes, opts], options); }
  exampleStrokes(options) { return this.run('exampleStrokes', [], options); }
  synthesizeTexture(image, opts, options) { return this.run('synthesizeTexture', [image, opts], options); }
  blendTextures(a, b, opts, options) { return this.run('blendTextures', [a, b, opts], options); }
  seamlessTile(image, opts, options) { return this.run('seamlessTile', [image, opts], options); }
  decodeImage(bytes, options) { return this.run('decodeImage', [bytes], options); }
  encodePng(image, options) { return this.run('encodePng', [image], options); }
  version() { return this.run('version', []); }

  /** Stops the worker; pending calls are rejected. */
  terminate() {
    this.worker?.terminate();
    this.worker = null;
    const pending = [this.current, ...this.queue].filter(Boolean);
    this.current = null;
    this.queue = [];
    for (const job of pending) job.reject(abortError('The worker was terminated.'));
  }

  run(method, args, { signal, onProgress } = {}) {
    return new Promise((resolve, reject) => {
      if (signal?.aborted) return reject(abortError());
      const job = { id: this.nextId++, method, args, resolve, reject, onProgress, signal };
      job.onAbort = () => this.abort(job);
      signal?.addEventListener('abort', job.onAbort, { once: true });
      this.queue.push(job);
      this.pump();
    });
  }

  abort(job) {
    if (this.current === job) {
      this.worker?.terminate();
      this.worker = null;
      this.current = null;
      job.reject(abortError());
      this.pump();
    } else {
      const i = this.queue.indexOf(job);
      if (i >= 0) {
        this.queue.splice(i, 1);
        job.reject(abortError());
      }
    }
  }

  pump() {
    if (this.current || this.queue.length === 0) return;
    const job = (this.current = this.queue.shift());
    if (!this.worker) {
      this.worker = new Worker(this.workerUrl, { type: 'module' });
      this.worker.onmessage = ({ data }) => this.receive(data);
      this.worker.onerror = (e) => this.fail(new Error(e.message || 'The worker failed to start.'));
    }
    this.worker.postMessage({ id: job.id, method: job.method, args: job.args });
  }

  receive(data) {
    const job = this.current;
    if (!job || data.id !== job.id) return;
    if ('progress' in data) return void job.onProgress?.(data.progress);
    job.signal?.removeEventListener('abort', job.onAbort);
    this.current = null;
    if ('error' in data) job.reject(new Error(data.error));
    else job.resolve(data.result);
    this.pump();
  }

  fail(error) {
    const job = this.current;
    this.worker?.terminate();
    this.worker = null;
    this.current = null;
    job?.reject(error);
    this.pump();
  }
}

function abortError(message = 'The operation was aborted.') {
  return new DOMException(message, 'AbortError');
}
