// Node entry of patternsynth: the same API as the browser entry, every module
// (engines and codecs) instantiated at import from the copies embedded in the package
// (load.js), so `import { synthesizeStrokes } from 'patternsynth'` works with no init
// call, bundled or not.
import { initSync, initCodecsSync } from '../patternsynth.js';
import full from './embedded/full.js';
import codec from './embedded/codec.js';
import { load } from './load.js';

load(initSync, full);
load(initCodecsSync, codec);

export * from '../patternsynth.js';
export { default } from '../patternsynth.js';
