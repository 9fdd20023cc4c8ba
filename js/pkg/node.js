// Node entry: the same API as the browser build, instantiated synchronously from the
// .wasm file beside this one, so `import { synthesizeStrokes } from 'patternsynth'`
// works with no init call.
import { readFileSync } from 'node:fs';
import { initSync } from './patternsynth.js';

initSync({ module: readFileSync(new URL('./patternsynth_bg.wasm', import.meta.url)) });

export * from './patternsynth.js';
export { default } from './patternsynth.js';
