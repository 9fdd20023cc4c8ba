// Node entry of patternsynth: the same API as the browser entry, every module
// (engines and codecs) instantiated at import from the files beside it, so
// `import { synthesizeStrokes } from 'patternsynth'` works with no init call.
import { initSync, initCodecsSync } from '../patternsynth.js';
import { load } from './load.js';

load(initSync, 'full');
load(initCodecsSync, 'codec');

export * from '../patternsynth.js';
export { default } from '../patternsynth.js';
