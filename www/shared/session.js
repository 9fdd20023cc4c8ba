// The whole session as one file: the drawing with its undo history, the images opened,
// and every tab's settings (IndexedDB; an older page's in localStorage). Export writes
// it; import puts it back and reloads the page.
import { get, keys, set } from './store.js';
import { PREFIX as RESULT } from './results.js';

const FORMAT = 'patternsynth-session';

const dataUrl = (blob) => new Promise((ok, fail) => {
  const r = new FileReader();
  r.onload = () => ok(r.result);
  r.onerror = () => fail(r.error);
  r.readAsDataURL(blob);
});

// Typed arrays (a painted mask's pixels) as base64 in JSON: as they are, JSON wrote them
// as objects of numbered keys, which came back as plain objects, and the mask was lost.
const bytesOut = (_, v) => (v instanceof Uint8Array || v instanceof Uint8ClampedArray)
  ? { $bytes: btoa(Array.from(v, (b) => String.fromCharCode(b)).join('')), clamped: v instanceof Uint8ClampedArray }
  : v;
const bytesIn = (_, v) => {
  if (typeof v?.$bytes !== 'string') return v;
  const raw = atob(v.$bytes);
  const out = v.clamped ? new Uint8ClampedArray(raw.length) : new Uint8Array(raw.length);
  for (let i = 0; i < raw.length; i++) out[i] = raw.charCodeAt(i);
  return out;
};

/** The session as a JSON Blob. `current`: values newer than what is kept (the drawing). */
export async function exportSession(current = {}) {
  const kept = {};
  for (const key of await keys().catch(() => [])) {
    if (typeof key === 'string' && key.startsWith(RESULT)) continue; // (made again from the rest)
    const value = await get(key);
    // (A Blob kept as it is, the blend's painted mask, is marked `whole`.)
    kept[key] = value instanceof Blob ? { blob: await dataUrl(value), whole: true }
      : value?.blob instanceof Blob ? { ...value, blob: await dataUrl(value.blob) } : value;
  }
  Object.assign(kept, current);
  const settings = {};
  for (let i = 0; i < localStorage.length; i++) {
    const k = localStorage.key(i);
    if (k.startsWith('patternsynth.')) settings[k] = localStorage.getItem(k);
  }
  return new Blob([JSON.stringify({ format: FORMAT, version: 1, saved: new Date().toISOString(), kept, settings }, bytesOut)], { type: 'application/json' });
}

/** Puts a session file's contents back (the page then reloads to show them). */
export async function importSession(file) {
  let session;
  try {
    session = JSON.parse(await file.text(), bytesIn);
  } catch {
    throw new Error(`${file.name} is not a patternsynth session (not JSON); nothing was changed.`);
  }
  if (session?.format !== FORMAT) throw new Error(`${file.name} is not a patternsynth session (no "format": "${FORMAT}"); nothing was changed.`);
  for (const [key, value] of Object.entries(session.kept ?? {})) {
    const blob = typeof value?.blob === 'string' ? await (await fetch(value.blob)).blob() : null;
    await set(key, blob ? (value.whole ? blob : { ...value, blob }) : value);
  }
  for (const [key, value] of Object.entries(session.settings ?? {})) {
    if (key.startsWith('patternsynth.') && typeof value === 'string') localStorage.setItem(key, value);
  }
}
