// Node entry of patternsynth/codec: ready at import.
import { initSync } from '../codec.js';
import wasm from './embedded/codec.js';
import { load } from './load.js';

load(initSync, wasm);

export * from '../codec.js';
export { default } from '../codec.js';
