// One wasm engine module's life: compiled once, instantiated by `init()` (or
// `initSync()`), checked before every call, and replaced when its state cannot be
// trusted or its memory should be given back:
// - after a trap (a bug: a Rust panic, a stack overflow), which leaves the instance's
//   memory and stack pointer in an unknown state; the call throws an `InternalError`;
// - after an exception that unwound through the module instead of being returned by it
//   (page code, such as a getter, throwing where the engine did not catch it): the
//   frames it skipped never restored the stack pointer; the call throws that exception;
// - after a call that left its memory more than `SPARE_BYTES` above what the instance
//   started with: wasm memory only grows, and a page open all day should get it back;
//   or its table of JS references `SPARE_REFERENCES` above: wasm-bindgen 0.2 leaks a
//   slot each time a catching import catches (its shim stores the missing return
//   value), which page code that throws from getters can repeat without end.
// Each time a fresh instance is made from the same compiled module (a few ms), and
// the next call works. A call made while another is running (from its progress
// callback) is refused: it would run on the running call's stack, and a trap in it
// would replace the instance under the outer call.

import { METHODS } from './api.js';
import { flatStrokes } from './flat.js';

/** Where a page whose bundler does not emit the package's wasm finds the way round. */
const RECIPE = ' If your bundler does not emit the package\'s .wasm files, copy them beside your bundle and pass their URL to init(): see "With a bundler" in the package README.';

/** Memory an instance may keep above its starting size after a call. */
export const SPARE_BYTES = 64 << 20;
/** JS reference slots an instance may keep above its starting count after a call. */
export const SPARE_REFERENCES = 1024;

/** `glue`: the wasm-bindgen module (web target, with `__wbg_reset` added by the build);
 *  `defaultUrl`: where its .wasm is served; `name` and `hint` make the message for a
 *  call before loading. */
export function engine(glue, defaultUrl, name, hint = '`await init()` first (or call initSync)') {
  let module = null;
  let exports = null;
  let baseline = 0;
  let baselineReferences = 0;
  let loading = null;
  let restarts = 0;
  let renewals = 0;
  let running = null;

  function start(compiled) {
    exports = glue.initSync({ module: compiled });
    module = compiled;
    baseline = memoryBytes();
    baselineReferences = references();
  }

  const memoryBytes = () => exports?.memory?.buffer.byteLength ?? 0;
  const references = () => exports?.__wbindgen_externrefs?.length ?? 0;

  /** A fresh instance in place of the current one. */
  function renew() {
    glue.__wbg_reset();
    start(module);
  }

  async function compile(input) {
    if (input instanceof WebAssembly.Module) return input;
    if (typeof input === 'string' || input instanceof URL || (typeof Request === 'function' && input instanceof Request)) {
      const url = String(input.url ?? input);
      input = fetch(input).catch((e) => {
        throw new Error(`patternsynth: could not fetch ${name}'s wasm from ${url} (${e.message}).${RECIPE}`, { cause: e });
      });
    }
    input = await input;
    if (typeof Response === 'function' && input instanceof Response) {
      if (!input.ok) throw new Error(`patternsynth: could not fetch ${name}'s wasm from ${input.url}: HTTP ${input.status}.${RECIPE}`);
      if (typeof WebAssembly.compileStreaming === 'function' && input.headers.get('Content-Type')?.startsWith('application/wasm')) {
        return WebAssembly.compileStreaming(input);
      }
      // A server that does not send application/wasm: slower, but it works, unless what
      // came back is not wasm at all (a single-page app's fallback answers every
      // missing file with its index.html).
      const url = input.url;
      input = await input.arrayBuffer();
      const head = new Uint8Array(input, 0, Math.min(4, input.byteLength));
      if (!(head[0] === 0 && head[1] === 0x61 && head[2] === 0x73 && head[3] === 0x6d)) {
        const text = new TextDecoder().decode(head);
        throw new Error(`patternsynth: ${url} is not ${name}'s wasm (it starts with ${JSON.stringify(text)}${text.startsWith('<') ? ': a web page, probably a fallback page for a missing file' : ''}).${RECIPE}`);
      }
    }
    return WebAssembly.compile(input);
  }

  /** Fetches and instantiates the module (once; later calls return at once). */
  async function init(input) {
    if (module) return;
    if (input && Object.getPrototypeOf(input) === Object.prototype) input = input.module_or_path ?? input.module;
    loading ??= compile(input ?? defaultUrl).then(start, (e) => {
      loading = null;
      throw e;
    });
    return loading;
  }

  /** Instantiates synchronously from bytes or a compiled `WebAssembly.Module`. */
  function initSync(input) {
    if (module) return;
    if (input && Object.getPrototypeOf(input) === Object.prototype) input = input.module;
    start(input instanceof WebAssembly.Module ? input : new WebAssembly.Module(input));
  }

  function isTrap(e) {
    return e instanceof WebAssembly.RuntimeError || (e instanceof RangeError && /call stack/i.test(e.message));
  }

  /** Calls `glue[method]`: one call at a time, the instance replaced when needed. */
  function call(method, args) {
    if (!module) {
      throw new Error(`${name}: ${method}() was called before the engine was loaded; ${hint}.`);
    }
    if (running) {
      throw new Error(`patternsynth is busy: ${method}() was called while ${running}() is running (from its progress callback, or from a getter or valueOf of its arguments); a call from there must wait until the current call returns (setTimeout or queueMicrotask).`);
    }
    running = method;
    glue.__wbg_takeReturned?.();
    try {
      // (Inside the call: a getter read here that calls the engine is refused too.)
      if (METHODS[method]?.strokes) args = [flatStrokes(args[0]), ...args.slice(1)];
      const result = glue[method](...args);
      giveBack(method);
      return result;
    } catch (e) {
      if (isTrap(e)) {
        renew();
        restarts += 1;
        const err = new Error(`Internal error in patternsynth's ${method}() (${e.message}). This is a bug; the engine was restarted, so the next call works.`);
        err.name = 'InternalError';
        err.cause = e;
        throw err;
      }
      if (glue.__wbg_takeReturned && !glue.__wbg_takeReturned()) {
        renew();
        restarts += 1;
      } else {
        giveBack(method);
      }
      throw e;
    } finally {
      running = null;
    }
  }

  /** Replaces an instance whose memory or reference table grew past the spare
   *  allowance, unless `method` is a step of a banded job that stays open for the next
   *  (a worker runs a job's steps back to back; any other call means a job still open
   *  was forgotten, and goes with the instance). */
  function giveBack(method) {
    const grown = memoryBytes() > baseline + SPARE_BYTES || references() > baselineReferences + SPARE_REFERENCES;
    if (grown && !(method.startsWith('bands') && glue.bandsOpenJobs?.() > 0)) {
      renew();
      renewals += 1;
    }
  }

  /** `method(name)`: the entry-point function that calls `name` (what entries export). */
  const method = (name) => (...args) => call(name, args);

  /** For diagnostics and tests: restarts (after traps and exceptions through the
   *  module), renewals (to give memory back), and the memory and JS reference slots
   *  now and at the start. */
  const diagnostics = () => ({
    restarts, renewals, memoryBytes: memoryBytes(), baselineBytes: baseline, references: references(), baselineReferences,
  });

  return { init, initSync, call, method, diagnostics, get restarts() { return restarts; } };
}
