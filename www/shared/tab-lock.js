// One tab keeps the work. Every tab of the page reads and writes the same IndexedDB, so
// two tabs used at once overwrote each other's drawing and settings, silently (a tab
// reloaded showed the other tab's one stroke, its own undo history gone). The first
// tab holds a Web Lock and keeps the work as before; a tab opened while it is held
// shows what was kept, writes nothing (store.js `readOnly`) and says so, until the
// person takes it over: it reloads holding the lock (stolen), so it starts from the
// latest work kept, and the other tab becomes the read-only one. A browser without
// Web Locks behaves as before.

const NAME = 'patternsynth-keeper';
// Set by "Use this tab instead" just before it reloads: the new page steals the lock.
const TAKE_OVER = 'patternsynth.take-over';
// A page being left lets the lock go (pagehide), but the browser may hand it on a
// little later: a page that finds it held asks the tabs (BroadcastChannel) and waits
// for it until a live tab answers that it holds it, or this long (a frozen tab does
// not answer).
const GRACE_MS = 2000;

let release = null; // lets the lock go
let channel = null; // answers the tabs that ask, while this tab holds the lock

/** Requests the lock: resolves true once held, false when another tab holds it. */
function request(steal, onLost) {
  const abort = new AbortController();
  let held = false;
  let asking = null;
  const done = new Promise((resolve) => {
    const timer = steal ? 0 : setTimeout(() => abort.abort(), GRACE_MS);
    navigator.locks.request(NAME, steal ? { steal: true } : { signal: abort.signal }, () => {
      clearTimeout(timer);
      held = true;
      resolve(true);
      return new Promise((ok) => { release = ok; });
    }).catch(() => {
      // Stopped waiting (another tab holds it), or stolen from this tab.
      clearTimeout(timer);
      if (!held) return resolve(false);
      letGo();
      onLost?.();
    });
    if (steal || typeof BroadcastChannel === 'undefined') return;
    asking = new BroadcastChannel(NAME);
    asking.onmessage = (e) => { if (e.data === 'here') abort.abort(); };
    asking.postMessage('who');
  });
  return done.then((ok) => {
    asking?.close();
    if (ok && typeof BroadcastChannel !== 'undefined') {
      channel = new BroadcastChannel(NAME);
      channel.onmessage = (e) => { if (e.data === 'who') channel.postMessage('here'); };
    }
    return ok;
  });
}

/** Lets the lock go as the page is left (a reload then finds it free). */
function letGo() {
  channel?.close();
  channel = null;
  release?.();
  release = null;
}

/**
 * Takes the lock: true when this tab keeps the work (also without Web Locks), false
 * when another tab does. `onLost()` is called should this tab lose it later (another
 * tab took over, or took it while this page was in the back-forward cache).
 */
export async function claim(onLost) {
  if (!navigator.locks?.request) return true;
  let steal = false;
  try {
    steal = sessionStorage.getItem(TAKE_OVER) !== null;
    sessionStorage.removeItem(TAKE_OVER);
  } catch {
    // No sessionStorage: no take-over pending.
  }
  addEventListener('pagehide', letGo);
  addEventListener('pageshow', async (e) => {
    if (e.persisted && !(await request(false, onLost))) onLost?.();
  });
  return request(steal, onLost);
}

/** Reloads this tab to keep the work from now on (the other tab becomes read-only). */
export function takeOver() {
  try {
    sessionStorage.setItem(TAKE_OVER, '1');
  } catch {
    // Without sessionStorage the reload waits for the lock like a new tab.
  }
  location.reload();
}
