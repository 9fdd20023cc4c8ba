// patternsynth/vector: see vector.js.
import type { Diagnostics, Init, InitSync } from './types.js';
export type * from './types.js';

declare const init: Init;
export default init;
export declare const initSync: InitSync;
/** How many times the engine replaced its instance after a trap (a bug) or an exception thrown through it. */
export function restarts(): number;
/** Restarts, renewals (instances replaced after a call left memory over 64 MB above the start, to give it back) and wasm memory now and at the start, in bytes. */
export function diagnostics(): Diagnostics;
export function version(): string;
import type { Stroke, ParseSvgOptions, SvgImport, Classification, ClassifyOptions, StrokeOptions, StrokeResult, TileOptions, TileResult, SuggestOptions, Suggestions, Progress } from './types.js';
export function parseSvg(svg: string, opts?: ParseSvgOptions): Stroke[];
export function parseSvgReport(svg: string, opts?: ParseSvgOptions): SvgImport;
export function classifyStrokes(strokes: Stroke[], opts?: ClassifyOptions): Classification;
export function synthesizeStrokes(strokes: Stroke[], opts: StrokeOptions, onProgress?: Progress): StrokeResult;
export function strokeTile(strokes: Stroke[], opts?: TileOptions): TileResult;
/** The next strokes of the repetition in a drawing (autocomplete), or none with the reason. */
export function suggestStrokes(strokes: Stroke[], opts?: SuggestOptions): Suggestions;
