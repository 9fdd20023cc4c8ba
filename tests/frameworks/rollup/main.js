// The README's Rollup recipe: init() with the wasm's URL, the client with the worker's URL.
import { report } from './browser-checks.js';

report({
  wasmUrl: new URL('/patternsynth/wasm/vector_bg.wasm', location.href),
  workerUrl: new URL('/patternsynth/worker.js', location.href),
});
