// Node entry: the same API as the browser entry, instantiated synchronously from the
// .wasm file beside it at import (no fetch), so `import { synthesizeStrokes } from
// 'patternsynth'` works with no init call, also during server-side rendering.
import { readFileSync } from 'node:fs';
import { initSync } from './patternsynth.js';

initSync({ module: readFileSync(new URL('./wasm/full_bg.wasm', import.meta.url)) });

export * from './patternsynth.js';
export { default } from './patternsynth.js';
