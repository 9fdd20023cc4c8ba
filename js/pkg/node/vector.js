// Node entry of patternsynth/vector: ready at import.
import { initSync } from '../vector.js';
import wasm from './embedded/vector.js';
import { load } from './load.js';

load(initSync, wasm);

export * from '../vector.js';
export { default } from '../vector.js';
