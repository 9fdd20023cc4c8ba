// The playground shell: tabs, the shared worker client, and each feature's client.
import { PatternSynthClient } from './pkg/client.js';
import { mountStrokes } from './features/strokes/client/index.js';
import { mountBlend } from './features/blend/client/index.js';
import { mountSeamless } from './features/seamless/client/index.js';
import { mountRetouch } from './features/retouch/client/index.js';
import { exportSession, importSession } from './shared/session.js';
import { onTrouble, ready } from './shared/storage.js';
import { readOnly, writesAfter } from './shared/store.js';
import { claim, takeOver } from './shared/tab-lock.js';

const client = new PatternSynthClient(new URL('./pkg/worker.js', import.meta.url));
window.patternsynth = client; // handy from the console and for tests

// One tab keeps the work (tab-lock.js): another tab of the page open at the same time
// is read-only, says so at the top, and can take over. The page does not wait for the
// answer (a single tab shows at once, as before); its writes do.
const keeper = claim(() => readOnlyTab('patternsynth was taken over in another tab, which keeps your work now. This tab is read-only and may be out of date: nothing done here is kept.'));
writesAfter(keeper);
function readOnlyTab(message) {
  readOnly();
  const banner = document.getElementById('elsewhere');
  for (const el of document.querySelectorAll('main, header .session')) el.inert = true;
  document.getElementById('elsewhere-text').textContent = message;
  banner.hidden = false;
  // (Focus left inside what just went inert moves to the way out.)
  if (document.activeElement?.closest('[inert]')) document.getElementById('take-over').focus();
}
document.getElementById('take-over').addEventListener('click', takeOver);

// Settings are read from IndexedDB before anything shows them; a setting the browser
// will not keep is said beside the session buttons.
await ready();
onTrouble((message) => {
  const status = document.getElementById('session-status');
  status.className = 'session-status error';
  status.textContent = message;
});
const features = { strokes: mountStrokes, blend: mountBlend, seamless: mountSeamless, retouch: mountRetouch };
for (const section of document.querySelectorAll('[data-feature]')) {
  features[section.dataset.feature]?.(section, client);
}
keeper.then((ok) => ok || readOnlyTab('patternsynth is open in another tab, which keeps your work. This tab is read-only: nothing done here is kept. To work here, use this tab instead: it reloads with your latest work, and the other tab becomes read-only.'));

// Tabs as the WAI-ARIA tabs pattern: one tab in the Tab order (the selected one), the
// arrow keys, Home and End move between tabs and select them.
const tabs = [...document.querySelectorAll('[role="tab"]')];
function select(tab, focus = false) {
  for (const t of tabs) {
    t.setAttribute('aria-selected', String(t === tab));
    t.tabIndex = t === tab ? 0 : -1;
  }
  for (const s of document.querySelectorAll('.tab')) s.hidden = s.id !== tab.getAttribute('aria-controls');
  if (focus) tab.focus();
}
for (const [i, tab] of tabs.entries()) {
  tab.addEventListener('click', () => select(tab));
  tab.addEventListener('keydown', (e) => {
    const to = { ArrowRight: i + 1, ArrowLeft: i - 1, Home: 0, End: tabs.length - 1 }[e.key];
    if (to === undefined) return;
    e.preventDefault();
    select(tabs[(to + tabs.length) % tabs.length], true);
  });
}

// File pickers: a button (reachable by keyboard, named) opens the hidden input after it.
for (const button of document.querySelectorAll('.file-button')) {
  button.addEventListener('click', () => button.nextElementSibling.click());
}

// Hints for the device: keys on a keyboard, taps on a touch screen.
document.documentElement.classList.toggle('touch', matchMedia('(hover: none) and (pointer: coarse)').matches);

client.version().then((v) => { document.getElementById('version').textContent = `v${v}`; });

// The whole session in one file, and back.
document.getElementById('session-export').addEventListener('click', async () => {
  const blob = await exportSession({ 'strokes.session': window.playground?.drawing?.() });
  const a = Object.assign(document.createElement('a'), { href: URL.createObjectURL(blob), download: `patternsynth-session-${new Date().toISOString().slice(0, 10)}.json` });
  a.click();
  setTimeout(() => URL.revokeObjectURL(a.href), 10_000);
});
document.getElementById('session-import').addEventListener('change', async (e) => {
  const file = e.target.files[0];
  e.target.value = '';
  if (!file) return;
  // Said beside the buttons (a live region), not in a dialog that stops the page.
  const status = document.getElementById('session-status');
  status.className = 'session-status';
  status.textContent = `Reading ${file.name}…`;
  try {
    await importSession(file);
    location.reload();
  } catch (err) {
    status.className = 'session-status error';
    status.textContent = err.message;
  }
});
