// The latest result of each tab (a synthesized image, a tile) kept in IndexedDB
// (store.js), so that a reload finds it: it was gone, and a reload or a closed tab lost
// a result not yet downloaded. While a result is neither kept (its write under way, or
// refused: storage full, private mode, read-only tab) nor downloaded, leaving the page
// asks first (beforeunload). Results are not part of a session file: they are made
// again from it (seeded).
import { canWrite, get, set } from './store.js';

export const PREFIX = 'result:';

/** Names of the results that leaving the page would lose. */
const unsafe = new Set();
const ask = (e) => {
  e.preventDefault();
  e.returnValue = ''; // (older browsers ask only when it is set)
};
// (Listened for only while needed: a page that listens is kept out of some browsers'
// back-forward caches.)
const mark = (name, lost) => {
  if (lost) unsafe.add(name);
  else unsafe.delete(name);
  if (unsafe.size) addEventListener('beforeunload', ask);
  else removeEventListener('beforeunload', ask);
};

/**
 * The kept result of one tab, `name`. `onError(e)` hears when the browser will not keep
 * one; `links`: the download links whose click makes the result safe to leave.
 */
export function keptResult(name, { onError, links = [] } = {}) {
  const key = PREFIX + name;
  let latest = 0;
  for (const link of links) link.addEventListener('click', () => mark(name, false));
  return {
    /** Keeps `record` (a structured clone: Blobs, arrays, plain objects) as the latest. */
    async keep(record) {
      const mine = ++latest;
      mark(name, true);
      try {
        await set(key, record);
        if (mine === latest) mark(name, false);
      } catch (e) {
        if (mine === latest && canWrite()) onError?.(e);
      }
    },
    /** The record kept, or undefined. */
    restore: () => get(key).catch(() => undefined),
  };
}
