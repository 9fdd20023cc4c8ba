// Types shared by the patternsynth entries (the functions: patternsynth.d.ts, vector.d.ts,
// texture.d.ts, codec.d.ts; the list of entry points: api.js).

export type Rgb = string;
export interface Stroke {
  points: [number, number][];
  width: number;
  /** The pen's colour (`#rrggbb`); black when left out, `null` for a shape only filled. */
  stroke?: Rgb | null;
  fill?: Rgb | null;
  opacity?: number;
  strokeOpacity?: number;
  fillOpacity?: number;
  closed?: boolean;
  /** Compound shapes (a ring, a letter with counters): indices in `points` where a
   *  subpath starts after the first. */
  breaks?: number[];
  /** Which areas of a compound shape are holes (SVG `fill-rule`; default 'nonzero'). */
  fillRule?: 'nonzero' | 'evenodd';
}
/** Called with the fraction done in [0, 1]; return false to cancel. */
export type Progress = (fraction: number) => boolean | void;
export interface ParseSvgOptions {
  /** Largest distance between a curve and its flattened polyline (user units; 0.25). */
  tolerance?: number;
  /** Split compound paths into their separate parts (default true; holes and crossing
   *  parts stay with their outline), or keep every path whole. */
  splitSubpaths?: boolean;
  maxPoints?: number;
}
export interface SvgImport { strokes: Stroke[]; warnings: string[]; width: number; height: number }
export interface Tolerances { path: number; width: number; color: number }
export interface Classification {
  /** Class of each stroke: its part in its motif (copies of one part share a class). */
  classes: number[]; count: number;
  /** The motif instance (one drawn copy of a motif of one or more strokes) of each stroke. */
  instances: number[];
  /** Kinds of motif: instances that are copies of one another. */
  kinds: number;
  tolerances: Tolerances; proposed: Tolerances;
}
export interface ClassifyOptions { pathTolerance?: number; widthTolerance?: number; colorTolerance?: number }
/** Options of `suggestStrokes`: `region` is the canvas `[x, y, width, height]` (required with `fill`). */
export interface SuggestOptions extends ClassifyOptions {
  region?: [number, number, number, number];
  /** Copies to propose beyond those begun (default 3, at most 64). */
  count?: number;
  /** Propose every copy in the region instead. */
  fill?: boolean;
  /** Indices of the strokes that are accepted proposals: they weigh little in the fit. */
  suggested?: number[];
  variation?: boolean;
  seed?: number;
}
/** Proposed strokes, each with its confidence in (0, 1], the drawn stroke whose place it repeats and its lattice cell. */
export interface Suggestions {
  strokes: Stroke[]; confidence: number[]; sources: number[]; cells: [number, number][];
  /** The repetition's period vectors: one for a row, two for a lattice, none when there is none. */
  periods: [number, number][];
  /** Why nothing is proposed, when nothing is. */
  reason?: string | null;
}
export interface StrokeOptions extends ClassifyOptions {
  /** variation (default true): each placed motif takes a random drawn copy of the same motif position. */
  width: number; height: number; variation?: boolean; seed?: number; support?: number;
  /** Refuse outputs estimated above this many elements (default 500,000; at most 2,000,000). */
  maxElements?: number;
  /** Grow on the drawing's fitted lattice (default true): no drift on large outputs. */
  regularize?: boolean;
  /** The two period vectors [[ax, ay], [bx, by]] to repeat the drawing on, when the ones
   *  it shows are wrong or missing (one motif drawn once repeats on them). */
  periods?: Periods;
}
/** Two period vectors of a lattice, [[ax, ay], [bx, by]]. */
export type Periods = [[number, number], [number, number]];
/** An image in: RGBA bytes, like a canvas ImageData. */
/** An engine's state, for diagnostics (`diagnostics()`). */
export interface Diagnostics { restarts: number; renewals: number; memoryBytes: number; baselineBytes: number; references: number; baselineReferences: number }
export interface Rgba { width: number; height: number; data: Uint8Array | Uint8ClampedArray }
/** An image out: `new ImageData(out.data, out.width, out.height)` works. */
export interface RgbaImage { width: number; height: number; data: Uint8ClampedArray<ArrayBuffer> }
export interface TextureBase {
  width: number; height: number; seed?: number; tileable?: boolean; exhaustive?: boolean;
  levels?: number; neighbourhood?: number;
  /** Pixel order: 'bands' (several workers can share it; PatternSynthClient does), the
   *  paper's 'scanline', or 'auto' (default): bands from 512 x 512 output pixels. */
  schedule?: 'auto' | 'scanline' | 'bands';
}
export interface TextureOptions extends TextureBase {
  /** Pixels of the exemplar never copied: a mask image of its size, opaque white where a
   *  pixel is kept out; with several exemplars an array of one mask (or null) per exemplar. */
  sampleMask?: Mask | (Mask | null)[];
  /** Guide images: the output follows `target`'s light and dark where the exemplar's
   *  own guide has them (luminance compared beside the colours; `weight` 1 counts it as
   *  much as all three colour channels, 2, the default, twice). `exemplar`: one per
   *  exemplar. */
  guides?: Guides;
  /** Also return the layout: which exemplar pixel each output pixel came from. */
  keepLayout?: boolean;
  /** Smooth the seams between the pieces copied from the exemplar (gradient-domain
   *  fusion, default true): softer joins on clouds, smoke and stone. false: every pixel
   *  is one of the exemplar's colours exactly. An exemplar of at most 64 colours (pixel
   *  art), one with transparency, blends, guided syntheses and style transfer are never
   *  fused (their steps follow the guide); nor is a synthesis with
   *  `keepLayout`, so that applyLayout on its exemplars gives its image pixel for pixel. */
  fuseSeams?: boolean;
}
/** Guide images (luminance is read): one per exemplar, and the output's. */
export interface Guides { exemplar: Rgba | Rgba[]; target: Rgba; weight?: number }
/** A mask: an image where opaque white (alpha and luminance at least half) marks a pixel. */
export type Mask = Rgba;
/** Which exemplar pixel each output pixel came from: one entry per pixel, row major,
 *  `exemplar << 24 | y << 12 | x` (read it as `v >>> 24`, `(v >>> 12) & 4095`, `v & 4095`). */
export interface Layout { width: number; height: number; exemplars: [number, number][]; data: Uint32Array }
export interface TextureWithLayout { image: RgbaImage; layout: Layout }
export interface InpaintOptions {
  seed?: number; levels?: number;
  /** Side of the matched neighbourhood, odd (default 11: wider than synthesis's 5, the
   *  fill matched to more of the photograph round it); the finest level is matched
   *  5 x 5 whatever the side, where it only refines detail. */
  neighbourhood?: number;
  /** Pixels never copied into the hole (opaque white: kept out). */
  sampleMask?: Mask;
}
export interface StyleOptions {
  seed?: number;
  /** How much the target's light and dark counts against the style's texture (default 1.5:
   *  the target shows about as clearly as in texture-synthesis's transfer; higher follows
   *  it more closely at the cost of the texture). */
  weight?: number;
  levels?: number; neighbourhood?: number;
  /** The style's pixels never to copy (a logo, a patch of sky): a mask of the style's size. */
  sampleMask?: Mask;
}
export type Transition = 'linear' | 'ease' | 'steep';
export interface BlendOptions extends TextureBase {
  /** mu, the weight of A: 'linear' (1 at the top, 0 at the bottom, as in the paper), its
   *  'ease' and 'steep' transfers, 'radial' (A at the centre), or one value per pixel. */
  coefficient?: Transition | 'radial' | Float32Array;
  /** Direction of the ramp in degrees (90 = top to bottom, 0 = left to right). */
  angle?: number;
  /** Transfer applied to 'radial' or an angled ramp. */
  transfer?: Transition;
  /** [mask of A, mask of B] (null for none). */
  sampleMask?: (Mask | null)[];
}
export interface TileOptions extends ClassifyOptions {
  variation?: boolean; seed?: number;
  /** The tile spans this many smallest repeats across and down (1 to 8, default 1). */
  repeats?: number;
  /** The periods to tile on, when the drawing's own are wrong or missing. */
  periods?: Periods;
}
export interface TileResult {
  /** In tile coordinates; strokes cut by an edge appear again one period over. */
  strokes: Stroke[]; classes: number[]; width: number; height: number;
  /** The tile's exact lattice periods. */
  periods: [[number, number], [number, number]];
  /** Stroke sites in the tile (strokes before edge copies; a motif of several strokes has one per stroke). */
  sites: number; classification: Classification;
  /** width x height, repeats without seams as a CSS background. */
  svg: string;
}
export interface SeamlessOptions {
  /** 'synthesis' (toroidal neighbourhood synthesis: keeps structure; the default, as
   *  on the page), 'etfmcm' (the paper's co-occurrence tile), 'tfmcm' (its predecessor) or 'mend' (the image kept, any size, only a
   *  band around its wrap re-made). */
  method?: 'etfmcm' | 'tfmcm' | 'synthesis' | 'mend';
  /** 'mend': the band's whole width as a share of each side, half along each edge
   *  and at least 4 pixels there (default 0.25: the inner 75% x 75% kept bit for bit). */
  band?: number;
  /** 'synthesis' and 'mend': pixels of the image never copied (opaque white). */
  sampleMask?: Mask;
  /** Tile side, a power of two from 8 to 512 (default: 'synthesis' the image's own size,
   *  at most 512 on a side; E-TFMCM and TFMCM the largest power of two the image allows). */
  size?: number; seed?: number;
  /** Method 'synthesis' only, in place of `size`: any width and height from 8 to 4096
   *  (one alone: a square). */
  width?: number; height?: number;
  /** T0 of the density conversion (default 50). */
  maxCountDifference?: number;
  /** E-TFMCM and TFMCM: refine the co-occurrence tile by toroidal synthesis, which keeps
   *  its layout and re-makes its detail from the image (default true); false gives the
   *  paper's tile as it is. */
  refine?: boolean;
  /** 'synthesis', and E-TFMCM or TFMCM refined: smooth the seams between copied pieces
   *  (default true; see TextureOptions.fuseSeams). */
  fuseSeams?: boolean;
}
export interface SeamlessResult {
  image: RgbaImage;
  /** The paper's restoration rate: 1 is the exemplar's colour histogram exactly (of an
   *  image with transparency, as it shows over white). */
  restorationRate: number;
  /** Difference across the wrap-around over the difference across the 4 parallel lines on
   *  each side of it: about 1 is seamless; a photograph repeated as it is scores 2-8 (of
   *  an image with transparency, as it shows over white). */
  seamScore: number;
  /** What was done to the input: cropped square or scaled, and why; its transparency not
   *  read (E-TFMCM and TFMCM, whose tile is the image as it shows over white). */
  warnings: string[];
  channel: 'r' | 'g' | 'b' | null;
  countDifference: [number, number] | null;
  decisions: { byJ3: number[]; pairwise: number; mean: number } | null;
}
export interface StrokeResult {
  strokes: Stroke[]; classes: number[]; sources: number[]; classification: Classification; svg: string;
  /** The periods the output repeats on (found, fitted or given; a ring's rosettes are
   *  laid on a hexagonal lattice; a curve's copies in bricked rows); null when grown
   *  freely, along a curve the output holds once, or in rows of one copy each. */
  periods: Periods | null;
  /** What the drawing was repeated on: 'lattice' (translations: a grid, or a row, as
   *  three hatching lines grow into one), 'ring' (copies turned
   *  round a centre: completed, and repeated as rosettes where small beside the output),
   *  'curve' (continued along an arc), 'sequence' (each copy turned and scaled from the
   *  last: a spiral), 'irregular' (no repeat: a mosaic of the drawing, or a mesh). */
  structure: 'lattice' | 'ring' | 'curve' | 'sequence' | 'irregular';
  growingPoints: number; skippedFull: number; passedOver: number;
}

/** Bytes of a .wasm file (DOM's BufferSource, spelt without the DOM library, so that
 *  Node-only TypeScript reads these types). */
export type WasmBytes = ArrayBuffer | ArrayBufferView;
/** A compiled module: `WebAssembly.Module` where the environment's types declare it. */
export type WasmModule = typeof globalThis extends { WebAssembly: { Module: abstract new (...args: any) => infer M } } ? M : object;
/** `fetch`'s Request and Response where the environment's types declare them. */
type FetchRequest = typeof globalThis extends { Request: abstract new (...args: any) => infer R } ? R : never;
type FetchResponse = typeof globalThis extends { Response: abstract new (...args: any) => infer R } ? R : never;
/** Where the .wasm comes from: a URL (default: beside the module), a Response, bytes or a compiled module. */
export type InitInput = string | URL | FetchRequest | FetchResponse | Promise<FetchResponse> | WasmBytes | WasmModule;
/** Fetches and instantiates an entry's wasm module; call (and await) once before anything
 *  else (Node entries are ready at import). */
export type Init = (input?: InitInput | { module_or_path: InitInput }) => Promise<void>;
/** Instantiates synchronously from bytes or a compiled module (Node, workers). */
export type InitSync = (input: WasmBytes | WasmModule | { module: WasmBytes | WasmModule }) => void;

