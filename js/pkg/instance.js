// One wasm engine module's life: compiled once, instantiated by `init()` (or
// `initSync()`), checked before every call, and replaced after a trap. A trap is a bug
// (a Rust panic, a stack overflow): it leaves the instance's memory and stack pointer
// in an unknown state, so the broken instance is dropped and a fresh one made from the
// same compiled module; the call that trapped throws an `InternalError`, and the next
// call works.

/** `glue`: the wasm-bindgen module (web target, with `__wbg_reset` added by the build);
 *  `defaultUrl`: where its .wasm is served; `name` and `hint` make the message for a
 *  call before loading. */
export function engine(glue, defaultUrl, name, hint = '`await init()` first (or call initSync)') {
  let module = null;
  let loading = null;
  let restarts = 0;

  function start(compiled) {
    glue.initSync({ module: compiled });
    module = compiled;
  }

  async function compile(input) {
    if (input instanceof WebAssembly.Module) return input;
    if (typeof input === 'string' || input instanceof URL || (typeof Request === 'function' && input instanceof Request)) {
      input = fetch(input);
    }
    input = await input;
    if (typeof Response === 'function' && input instanceof Response) {
      if (!input.ok) throw new Error(`patternsynth: could not fetch ${name}'s wasm from ${input.url}: HTTP ${input.status}.`);
      if (typeof WebAssembly.compileStreaming === 'function' && input.headers.get('Content-Type')?.startsWith('application/wasm')) {
        return WebAssembly.compileStreaming(input);
      }
      // A server that does not send application/wasm: slower, but it works.
      input = await input.arrayBuffer();
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

  /** Calls `glue[method]`, replacing the instance if the call traps. */
  function call(method, args) {
    if (!module) {
      throw new Error(`${name}: ${method}() was called before the engine was loaded; ${hint}.`);
    }
    try {
      return glue[method](...args);
    } catch (e) {
      if (!isTrap(e)) throw e;
      glue.__wbg_reset();
      start(module);
      restarts += 1;
      const err = new Error(`Internal error in patternsynth's ${method}() (${e.message}). This is a bug; the engine was restarted, so the next call works.`);
      err.name = 'InternalError';
      err.cause = e;
      throw err;
    }
  }

  /** `method(name)`: the entry-point function that calls `name` (what entries export). */
  const method = (name) => (...args) => call(name, args);

  return { init, initSync, call, method, get restarts() { return restarts; } };
}
