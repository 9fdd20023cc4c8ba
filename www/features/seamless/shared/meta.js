// Seamless tile: label, options and defaults (shared by the page and tests).
export const label = 'Seamless tile';

export const defaultOptions = {
  method: 'etfmcm', // 'tfmcm' | 'synthesis'
  size: '', // '' = the largest power of two the image allows
  seed: 1,
  maxCountDifference: 50,
  texture: 'gravel',
};

export const methods = [
  ['etfmcm', 'E-TFMCM (the paper: co-occurrence fractal)'],
  ['tfmcm', 'TFMCM (its predecessor, for comparison)'],
  ['synthesis', 'Toroidal synthesis (ours: keeps structure)'],
];

/** Built-in photographs (CC0, public domain or unrestricted; see tests/fixtures/textures/SOURCES.md). */
export const textures = ['wood', 'brick', 'grass', 'gravel', 'fur', 'hubble', 'tissue', 'coins'];

/** Images larger than this are scaled down before they reach the engine. */
export const maxInputSide = 1024;

export const storageKey = 'patternsynth.seamless.settings.v1';
export const imageKey = 'patternsynth.seamless.image.v1';
