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

/** Where an older page kept the drawing (localStorage; moved to IndexedDB on load). */
export const storageKey = 'patternsynth.strokes.v1';
/** The drawing and its undo history, in IndexedDB (shared/store.js). */
export const sessionKey = 'strokes.session';
