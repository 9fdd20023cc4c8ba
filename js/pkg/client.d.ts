import type {
  Stroke, StrokeOptions, StrokeResult, TileOptions, TileResult, ParseSvgOptions, SvgImport, Classification, ClassifyOptions, SuggestOptions, Suggestions,
  Rgba, RgbaImage, TextureOptions, BlendOptions, SeamlessOptions, SeamlessResult,
  Mask, Layout, TextureWithLayout, InpaintOptions, StyleOptions,
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
  preview?: { width: number; height: number; background?: string; type?: 'image/png'; opacity?: number };
  /** Stroke results (synthesizeStrokes, strokeTile): the worker keeps this result for
   *  `restyle` (one result: the last kept). */
  keep?: boolean;
}

/** A kept stroke result's style (see `PatternSynthClient.restyle`). */
export interface StrokeStyle {
  /** Per class: its new colour (`#rrggbb`) for outline and fill, or null to keep it. */
  colors?: (string | null)[];
  /** `#rrggbb` under the pattern, or null (transparent). */
  background?: string | null;
  /** The whole pattern's opacity, 0 to 1 (default 1). */
  opacity?: number;
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
  synthesizeTexture(image: Rgba | Rgba[], opts: TextureOptions & { keepLayout: true }, options?: CallOptions): Promise<TextureWithLayout>;
  synthesizeTexture(image: Rgba | Rgba[], opts: TextureOptions, options?: CallOptions): Promise<RgbaImage>;
  inpaintTexture(image: Rgba, mask: Mask, opts?: InpaintOptions, options?: CallOptions): Promise<RgbaImage>;
  transferStyle(style: Rgba, target: Rgba, opts?: StyleOptions, options?: CallOptions): Promise<RgbaImage>;
  applyLayout(layout: Layout, maps: (Rgba | Rgba[])[], options?: CallOptions): Promise<RgbaImage[]>;
  blendTextures(a: Rgba, b: Rgba, opts: BlendOptions, options?: CallOptions): Promise<RgbaImage>;
  seamlessTile(image: Rgba, opts?: SeamlessOptions, options?: CallOptions): Promise<SeamlessResult>;
  decodeImage(bytes: Uint8Array | ArrayBuffer, options?: CallOptions): Promise<RgbaImage>;
  encodePng(image: Rgba, options?: CallOptions): Promise<Uint8Array<ArrayBuffer>>;
  version(options?: CallOptions): Promise<string>;
  /** The last result kept with `{ keep: true }` in another style, without synthesizing it
   *  again: its SVG (classes recoloured, a background rectangle, an opacity group) and,
   *  with `preview`, drawn in the worker. */
  restyle(style: StrokeStyle, preview?: CallOptions['preview'], options?: CallOptions): Promise<{ svgBlob: Blob; preview?: ImageBitmap | Blob | null }>;
  /** Stops the worker; pending calls are rejected with an AbortError. */
  terminate(): void;
}
