// Blend textures: label, options and defaults (shared by the page and tests).
export const label = 'Blend textures';

export const defaultOptions = {
  mode: 'blend', // or 'single': more of texture A
  width: 256,
  height: 256,
  transition: 'linear', // 'ease' | 'steep' | 'radial' | 'mask'
  angle: 90, // degrees; 90 = A at the top, B at the bottom (the paper's)
  neighbourhood: 5,
  levels: '',
  seed: 1,
  tileable: false,
  exhaustive: false,
  a: 'wood',
  b: 'gravel',
  // The mask's brush: its diameter in mask pixels, and what it paints ('a' white, 'b' black).
  brushSize: 28,
  brush: 'a',
};

/** Built-in exemplars: CC0, public-domain or unrestricted photographs (see tests/fixtures/textures/SOURCES.md). */
export const textures = ['wood', 'brick', 'grass', 'gravel', 'fur', 'hubble', 'tissue', 'coins'];

/** Exemplars larger than this are scaled down (uniformly, with a message). */
export const maxExemplarSide = 512;

export const maxOutputSide = 4096;

export const storageKey = 'patternsynth.blend.settings.v1';
export const maskKey = 'patternsynth.blend.mask.v1';
/** A texture the person opened or dropped, kept as a PNG data URL: `${exemplarKey}.a`. */
export const exemplarKey = 'patternsynth.blend.exemplar.v1';
