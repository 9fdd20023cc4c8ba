// patternsynth/vector: see vector.js.
import type { Init, InitSync } from './types.js';
export type * from './types.js';

declare const init: Init;
export default init;
export declare const initSync: InitSync;
/** How many times a trap (a bug) made the engine restart. */
export function restarts(): number;
export function version(): string;
import type { Stroke, ParseSvgOptions, SvgImport, Classification, ClassifyOptions, StrokeOptions, StrokeResult, TileOptions, TileResult, SuggestOptions, Suggestions, Progress } from './types.js';
export function parseSvg(svg: string, opts?: ParseSvgOptions): Stroke[];
export function parseSvgReport(svg: string, opts?: ParseSvgOptions): SvgImport;
export function classifyStrokes(strokes: Stroke[], opts?: ClassifyOptions): Classification;
export function synthesizeStrokes(strokes: Stroke[], opts: StrokeOptions, onProgress?: Progress): StrokeResult;
export function strokeTile(strokes: Stroke[], opts?: TileOptions): TileResult;
/** The next strokes of the repetition in a drawing (autocomplete), or none with the reason. */
export function suggestStrokes(strokes: Stroke[], opts?: SuggestOptions): Suggestions;
