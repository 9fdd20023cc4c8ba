import type {
  Stroke, StrokeOptions, StrokeResult, TileOptions, TileResult, ParseSvgOptions, SvgImport, Classification, ClassifyOptions,
  Rgba, TextureOptions, BlendOptions, SeamlessOptions, SeamlessResult,
} from './patternsynth.js';

export interface CallOptions {
  signal?: AbortSignal;
  /** Called with the fraction done, in [0, 1]. */
  onProgress?: (fraction: number) => void;
}

/** Runs patternsynth in a module Web Worker; every call takes an AbortSignal. */
export class PatternSynthClient {
  constructor(workerUrl?: URL | string);
  parseSvg(svg: string, opts?: ParseSvgOptions, options?: CallOptions): Promise<Stroke[]>;
  parseSvgReport(svg: string, opts?: ParseSvgOptions, options?: CallOptions): Promise<SvgImport>;
  classifyStrokes(strokes: Stroke[], opts?: ClassifyOptions, options?: CallOptions): Promise<Classification>;
  synthesizeStrokes(strokes: Stroke[], opts: StrokeOptions, options?: CallOptions): Promise<StrokeResult>;
  strokeTile(strokes: Stroke[], opts?: TileOptions, options?: CallOptions): Promise<TileResult>;
  exampleStrokes(options?: CallOptions): Promise<{ name: string; strokes: Stroke[] }[]>;
  synthesizeTexture(image: Rgba, opts: TextureOptions, options?: CallOptions): Promise<Rgba>;
  blendTextures(a: Rgba, b: Rgba, opts: BlendOptions, options?: CallOptions): Promise<Rgba>;
  seamlessTile(image: Rgba, opts?: SeamlessOptions, options?: CallOptions): Promise<SeamlessResult>;
  decodeImage(bytes: Uint8Array, options?: CallOptions): Promise<Rgba>;
  encodePng(image: Rgba, options?: CallOptions): Promise<Uint8Array>;
  version(): Promise<string>;
  terminate(): void;
}
