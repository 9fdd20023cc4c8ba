// Vector strokes: label, options and their defaults (shared by the page and tests).
export const label = 'Vector strokes';

/** Output and synthesis options; a tolerance left null is proposed from the drawing. */
export const defaultOptions = {
  width: 1200,
  height: 800,
  pathTolerance: null,
  widthTolerance: null,
  colorTolerance: null,
  variation: true,
  regularize: true,
  seed: 1,
  /** Smallest repeats per side of a seamless tile. */
  tileRepeats: 2,
  /** Propose the next copies of a repetition while drawing. */
  autocomplete: true,
};

/** Copies autocomplete proposes beyond those begun. */
export const suggestCount = 3;

/** Drawing tool defaults. */
export const defaultPen = { width: 3, stroke: '#1f2a44', strokeOn: true, fill: '#e8a33d', fillOn: false };

/** Largest output side the page offers (the engine also caps element counts). */
export const maxSide = 20000;

/** Class colours for the class view. */
export const classColors = ['#e6194b', '#3cb44b', '#4363d8', '#f58231', '#911eb4', '#42d4f4', '#f032e6', '#9a6324', '#469990', '#808000'];

/** Palettes a result can be recoloured with (class k takes colour k modulo the
 *  palette's length); "as drawn" keeps the pen's colours. */
export const palettes = {
  'as drawn': [],
  ink: ['#1f2a44'],
  sunset: ['#ff6b35', '#f7c59f', '#2e294e', '#d7263d', '#1b998b'],
  ocean: ['#03045e', '#0077b6', '#00b4d8', '#90e0ef', '#caf0f8'],
  pastel: ['#ffadad', '#ffd6a5', '#fdffb6', '#caffbf', '#9bf6ff', '#bdb2ff'],
  forest: ['#2d6a4f', '#40916c', '#95d5b2', '#d8f3dc', '#081c15'],
};

/** The result's style by default: the drawn colours, no background (transparent, as
 *  the SVG has always been), opaque. */
export const defaultStyle = { palette: 'as drawn', background: '#ffffff', backgroundOn: false, opacity: 1 };

/** Where an older page kept the drawing (localStorage; moved to IndexedDB on load). */
export const storageKey = 'patternsynth.strokes.v1';
/** The drawing and its undo history, in IndexedDB (shared/store.js). */
export const sessionKey = 'strokes.session';
