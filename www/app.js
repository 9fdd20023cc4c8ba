// The playground shell: tabs, the shared worker client, and each feature's client.
import { PatternSynthClient } from './pkg/client.js';
import { mountStrokes } from './features/strokes/client/index.js';
import { mountBlend } from './features/blend/client/index.js';
import { mountSeamless } from './features/seamless/client/index.js';

const client = new PatternSynthClient(new URL('./pkg/worker.js', import.meta.url));
window.patternsynth = client; // handy from the console and for tests

const features = { strokes: mountStrokes, blend: mountBlend, seamless: mountSeamless };
for (const section of document.querySelectorAll('[data-feature]')) {
  features[section.dataset.feature]?.(section, client);
}

for (const tab of document.querySelectorAll('[role="tab"]')) {
  tab.addEventListener('click', () => {
    for (const t of document.querySelectorAll('[role="tab"]')) t.setAttribute('aria-selected', String(t === tab));
    for (const s of document.querySelectorAll('.tab')) s.hidden = s.id !== `tab-${tab.dataset.tab}`;
  });
}

client.version().then((v) => { document.getElementById('version').textContent = `v${v}`; });
