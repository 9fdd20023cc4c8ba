// patternsynth/vector: engine 1 only (strokes, SVG import and export, tiles) in its own
// wasm module, for pages that make vector patterns. `await init()` once, then call.
import * as glue from './wasm/vector.js';
import { engine } from './instance.js';

const vector = engine(glue, new URL('./wasm/vector_bg.wasm', import.meta.url), 'patternsynth/vector');

export default vector.init;
export const initSync = vector.initSync;
/** How many times the engine replaced its instance after a trap (a bug) or an exception
 *  thrown through it, for diagnostics. */
export const restarts = () => vector.restarts;
/** The engine's restarts, renewals (instances replaced to give memory back) and memory. */
export const diagnostics = () => vector.diagnostics();

export const version = vector.method('version');
export const parseSvg = vector.method('parseSvg');
export const parseSvgReport = vector.method('parseSvgReport');
export const classifyStrokes = vector.method('classifyStrokes');
export const synthesizeStrokes = vector.method('synthesizeStrokes');
export const strokeTile = vector.method('strokeTile');
export const suggestStrokes = vector.method('suggestStrokes');
