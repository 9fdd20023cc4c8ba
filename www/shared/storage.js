// Settings (and the blend's painted mask) kept in IndexedDB (store.js), read once
// before the features mount (`ready()`) so that a page never shows defaults first and
// then jumps; reads after that are synchronous, from memory. A write that the browser
// refuses (storage full, private mode) is said on the page (`onTrouble`) and the value
// lasts until the page closes. Values an older page kept in localStorage are read
// once and moved.
import { canWrite, del, get, keys, set } from './store.js';

const PREFIX = 'settings:';
const kept = new Map();
let durable = true;
let trouble = () => {};

/** Reads every setting kept; call (and await) before `load`. Never throws. */
export async function ready() {
  try {
    const names = (await keys()).filter((k) => typeof k === 'string' && k.startsWith(PREFIX));
    const values = await Promise.all(names.map((k) => get(k)));
    names.forEach((k, i) => kept.set(k.slice(PREFIX.length), values[i]));
  } catch {
    durable = false;
  }
}

/** `report(message)` hears when a setting cannot be kept. */
export function onTrouble(report) {
  trouble = report;
}

/** The value kept under `key` (an older page's from localStorage), or `fallback`. */
export function load(key, fallback) {
  if (kept.has(key)) return kept.get(key);
  try {
    const v = localStorage.getItem(key);
    if (v) {
      const value = JSON.parse(v);
      store(key, value);
      return value;
    }
  } catch {
    // Disabled or unreadable: nothing kept there.
  }
  return fallback;
}

/** Keeps `value` (a structured clone: objects, Blobs); written in the background. */
export function store(key, value) {
  kept.set(key, value);
  if (!canWrite()) return; // another tab keeps the work (tab-lock.js)
  if (!durable) {
    // No IndexedDB here: localStorage, as before, for what JSON can hold.
    try {
      localStorage.setItem(key, JSON.stringify(value));
    } catch (e) {
      trouble(`Settings could not be kept (${e?.message ?? e}): they last until this page closes.`);
    }
    return;
  }
  // Cloned now: later changes to the same object are written by their own `store`.
  set(PREFIX + key, structuredClone(value)).then(
    () => {
      try {
        localStorage.removeItem(key);
      } catch {
        // Nothing to move.
      }
    },
    (e) => canWrite() && trouble(`Settings could not be kept (${e?.message ?? e}): they last until this page closes.`),
  );
}

export function forget(key) {
  kept.delete(key);
  if (!canWrite()) return;
  del(PREFIX + key).catch(() => {});
  try {
    localStorage.removeItem(key);
  } catch {
    // Disabled storage holds nothing to forget.
  }
}
