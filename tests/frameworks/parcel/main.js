// Parcel 2 with no configuration: patternsynth/vector's init() and the worker client as
// the README shows them, no URLs passed (Parcel emits the wasm and the worker itself).
import { report } from './browser-checks.js';

report();
