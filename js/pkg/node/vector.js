// Node entry of patternsynth/vector: ready at import.
import { initSync } from '../vector.js';
import { load } from './load.js';

load(initSync, 'vector');

export * from '../vector.js';
export { default } from '../vector.js';
