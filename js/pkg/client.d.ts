import type {
  Stroke, StrokeOptions, StrokeResult, TileOptions, TileResult, ParseSvgOptions, SvgImport, Classification, ClassifyOptions, SuggestOptions, Suggestions,
  Rgba, RgbaImage, TextureOptions, BlendOptions, SeamlessOptions, SeamlessResult,
} from './types.js';

export interface CallOptions {
  signal?: AbortSignal;
  /** Called with the fraction done, in [0, 1]. */
  onProgress?: (fraction: number) => void;
  /** Only these fields of the result come back from the worker: a page that shows a
   *  large stroke result by its SVG (or `preview`) need not receive its `strokes`.
   *  `'svgBlob'` adds the SVG as a Blob made in the worker (no copy of the text). */
  fields?: string[];
  /** Stroke results: the strokes also drawn in the worker, fitted into `width x height`
   *  pixels (at most 8192), as `result.preview`: an ImageBitmap, or with
   *  `type: 'image/png'` a PNG Blob encoded in the worker; null without OffscreenCanvas. */
  preview?: { width: number; height: number; background?: string; type?: 'image/png' };
}

export interface ClientOptions {
  /** Workers a large texture synthesis or blend (from 512 x 512 pixels) may use; the
   *  image is the same for any number. Default: the machine's cores, at most 8 (1 when
   *  a Worker instance is given, which cannot be cloned). */
  workers?: number;
}

/** Runs patternsynth in module Web Workers; every call takes an AbortSignal. */
export class PatternSynthClient {
  /** The package's own worker by default; or a Worker, a function making Workers, or worker.js's URL. */
  constructor(worker?: Worker | (() => Worker) | URL | string, options?: ClientOptions);
  parseSvg(svg: string, opts?: ParseSvgOptions, options?: CallOptions): Promise<Stroke[]>;
  parseSvgReport(svg: string, opts?: ParseSvgOptions, options?: CallOptions): Promise<SvgImport>;
  classifyStrokes(strokes: Stroke[], opts?: ClassifyOptions, options?: CallOptions): Promise<Classification>;
  synthesizeStrokes(strokes: Stroke[], opts: StrokeOptions, options?: CallOptions): Promise<StrokeResult>;
  strokeTile(strokes: Stroke[], opts?: TileOptions, options?: CallOptions): Promise<TileResult>;
  suggestStrokes(strokes: Stroke[], opts?: SuggestOptions, options?: CallOptions): Promise<Suggestions>;
  synthesizeTexture(image: Rgba, opts: TextureOptions, options?: CallOptions): Promise<RgbaImage>;
  blendTextures(a: Rgba, b: Rgba, opts: BlendOptions, options?: CallOptions): Promise<RgbaImage>;
  seamlessTile(image: Rgba, opts?: SeamlessOptions, options?: CallOptions): Promise<SeamlessResult>;
  decodeImage(bytes: Uint8Array | ArrayBuffer, options?: CallOptions): Promise<RgbaImage>;
  encodePng(image: Rgba, options?: CallOptions): Promise<Uint8Array<ArrayBuffer>>;
  version(options?: CallOptions): Promise<string>;
  /** Stops the worker; pending calls are rejected with an AbortError. */
  terminate(): void;
}
