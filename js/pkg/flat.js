// Strokes' points copied into one Float64Array each (x, y, x, y, ...) before they
// cross into wasm: read pair by pair through the boundary they cost three calls a
// point (five million points: four seconds); a JS loop copies them in milliseconds.
// Anything unusual (points that are not arrays of [x, y] numbers, a stroke that is
// not a plain object, a getter that throws, more strokes or points than the engine
// takes) is passed on as it came, for the engine to read and, if wrong, to name
// exactly.

/** The engine's limits on a drawing (read.rs: MAX_INPUT_STROKES, MAX_INPUT_POINTS). */
const MAX_STROKES = 2_000_000;
const MAX_POINTS = 20_000_000;

/** `strokes` with each plain object's points flattened (in a copy of the stroke), or
 *  `strokes` itself. Strokes of other kinds (class instances, whose fields a copy
 *  would lose) are passed as they are. */
export function flatStrokes(strokes) {
  try {
    if (!Array.isArray(strokes) || !(strokes.length <= MAX_STROKES)) return strokes;
    // One buffer for all (a typed array each, with its own memory, made the garbage
    // collector run for a second over fifty thousand strokes), counted first.
    const plain = (s) => s !== null && typeof s === 'object' && Object.getPrototypeOf(s) === Object.prototype;
    let total = 0;
    for (let i = 0; i < strokes.length; i++) {
      const s = strokes[i];
      const points = plain(s) ? s.points : undefined;
      if (Array.isArray(points) && (total += points.length) > MAX_POINTS) return strokes;
    }
    const flat = new Float64Array(2 * total);
    const out = new Array(strokes.length);
    let at = 0;
    for (let i = 0; i < strokes.length; i++) {
      const s = strokes[i];
      out[i] = s;
      const points = plain(s) ? s.points : undefined;
      // (A getter that answers longer the second time is left to the engine.)
      if (!Array.isArray(points)) continue;
      if (at + 2 * points.length > flat.length) return strokes;
      const start = at;
      let k = 0;
      for (; k < points.length; k++) {
        const p = points[k];
        if (!Array.isArray(p) || typeof p[0] !== 'number' || typeof p[1] !== 'number') break;
        flat[at++] = p[0];
        flat[at++] = p[1];
      }
      if (k === points.length) out[i] = { ...s, points: flat.subarray(start, at) };
      else at = start;
    }
    return out;
  } catch {
    return strokes;
  }
}
