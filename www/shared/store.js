// What the person made, kept in IndexedDB: drawings with their undo history, opened
// images as Blobs (not data URLs: a photograph as a data URL took 3.26 M characters
// of localStorage's 5 MB). Values are structured clones, so strokes shared between
// undo steps are stored once. Every call is async and throws when the browser will not
// keep the value (storage full, private mode); the caller says so on the page.

const DB = 'patternsynth';
const STORE = 'kept';
let opening = null;
let writable = true;
let asking = null;

/**
 * From now on nothing is written (another tab keeps the work: tab-lock.js); writes
 * refuse, and `saver`s skip theirs. Reads go on.
 */
export function readOnly() {
  writable = false;
}

/**
 * Writes wait until `allowed` (a promise) says whether this page may write at all
 * (tab-lock.js `claim`); false makes it read-only. Reads do not wait.
 */
export function writesAfter(allowed) {
  asking = Promise.resolve(allowed).then((ok) => { if (!ok) readOnly(); }, () => {});
}

/** Whether this page may write (see `readOnly`). */
export const canWrite = () => writable;

function db() {
  opening ??= new Promise((resolve, reject) => {
    if (typeof indexedDB === 'undefined') return reject(new Error('this browser has no IndexedDB'));
    const request = indexedDB.open(DB, 1);
    request.onupgradeneeded = () => request.result.createObjectStore(STORE);
    request.onsuccess = () => resolve(request.result);
    request.onerror = () => reject(request.error);
    request.onblocked = () => reject(new Error('the page is open in another tab with an older version'));
  }).catch((e) => {
    opening = null;
    throw e;
  });
  return opening;
}

/**
 * One request in its own transaction; resolves when the transaction has committed. A
 * write asks to commit at once (`commit()`) instead of when its request's answer comes
 * back to the page: a page being unloaded never hears that answer, and Chromium then
 * dropped the write (a reload just after an undo found the drawing as it was before the
 * undo in 6-7 of 20 tries; 0 of 20 with the commit).
 */
async function run(mode, act) {
  if (mode === 'readwrite') {
    if (asking) await asking;
    if (!writable) throw new Error('the page is open in another tab, which keeps the work');
  }
  const tx = (await db()).transaction(STORE, mode);
  const request = act(tx.objectStore(STORE));
  if (mode === 'readwrite') tx.commit?.();
  return new Promise((resolve, reject) => {
    tx.oncomplete = () => resolve(request.result);
    tx.onerror = () => reject(tx.error ?? request.error);
    tx.onabort = () => reject(tx.error ?? new Error('the browser refused to keep it'));
  });
}

/** The value kept under `key`, or undefined. */
export const get = (key) => run('readonly', (s) => s.get(key));
/** Keeps `value` under `key`. */
export const set = (key, value) => run('readwrite', (s) => s.put(value, key));
/** Forgets `key`. */
export const del = (key) => run('readwrite', (s) => s.delete(key));
/** Every key kept. */
export const keys = () => run('readonly', (s) => s.getAllKeys());

/**
 * Writes that follow changes, at most one at a time and the latest one last: `save()`
 * after every change starts a write at once (a reload right after a stroke must find
 * it), and changes made while one is under way are written together after it.
 * `write()` makes the value. `onError(e)` hears of a failure once per run of failures,
 * and `onSaved()` of the next success.
 */
export function saver(key, write, { delay = 0, onError, onSaved } = {}) {
  let timer = null;
  let busy = false;
  let again = false;
  let failing = false;
  const flush = async () => {
    timer = null;
    if (!writable) return;
    if (busy) return void (again = true);
    busy = true;
    try {
      await set(key, write());
      if (failing) onSaved?.();
      failing = false;
    } catch (e) {
      if (!writable) return; // (read-only: said at the top of the page)
      if (!failing) onError?.(e);
      failing = true;
    } finally {
      busy = false;
      if (again) {
        again = false;
        flush();
      }
    }
  };
  return {
    save() {
      clearTimeout(timer);
      timer = setTimeout(flush, delay);
    },
    /**
     * Writes now (before the page is hidden), even while a write is under way: the page
     * may be gone before that one ends, and IndexedDB applies the two in order.
     */
    flush() {
      if (writable && (timer || again)) {
        clearTimeout(timer);
        timer = null;
        again = false;
        return set(key, write()).catch((e) => writable && onError?.(e));
      }
      return Promise.resolve();
    },
  };
}
