// Node entry of patternsynth/texture: ready at import.
import { initSync } from '../texture.js';
import wasm from './embedded/texture.js';
import { load } from './load.js';

load(initSync, wasm);

export * from '../texture.js';
export { default } from '../texture.js';
