// SVG import speed in wasm under Node (medians of 5): the real-document fixtures, and
// large generated documents (many shapes, many CSS rules, <use> copies).
//   node bench/svg.mjs
import { readFileSync, readdirSync } from 'node:fs';
import { parseSvgReport } from '../pkg/node/vector.js';

const median = (f, n = 5) => {
  const t = [];
  for (let i = 0; i < n; i++) {
    const t0 = performance.now();
    f();
    t.push(performance.now() - t0);
  }
  return t.sort((a, b) => a - b)[n >> 1];
};
const root = new URL('../tests/fixtures/svg/', import.meta.url);
const docs = readdirSync(root, { withFileTypes: true }).filter((d) => d.isDirectory()).flatMap((d) =>
  readdirSync(new URL(`${d.name}/`, root)).filter((f) => f.endsWith('.svg')).map((f) => readFileSync(new URL(`${d.name}/${f}`, root), 'utf8')));
const bytes = docs.reduce((s, d) => s + d.length, 0);
console.log(`fixtures: ${docs.length} documents, ${(bytes / 1e3).toFixed(0)} KB: ${median(() => docs.forEach((d) => parseSvgReport(d))).toFixed(1)} ms for all`);

const wrap = (body, style = '') => `<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 2000 2000"><style>${style}</style>${body}</svg>`;
const circles = (n) => Array.from({ length: n }, (_, i) => `<circle class="c${i % 50}" cx="${(i * 37) % 2000}" cy="${(i * 53) % 2000}" r="${2 + (i % 5)}"/>`).join('');
const rules = Array.from({ length: 50 }, (_, i) => `.c${i} { fill: #${(i * 99991).toString(16).padStart(6, '0').slice(0, 6)} }`).join('\n');
const ring = '<path fill-rule="evenodd" d="M0 0 h10 v10 h-10 z M3 3 h4 v4 h-4 z"/>';
const uses = (n) => `<defs><g id="m">${ring}<circle cx="15" cy="5" r="3"/></g></defs>` +
  Array.from({ length: n }, (_, i) => `<use href="#m" x="${(i % 100) * 20}" y="${Math.floor(i / 100) * 20}"/>`).join('');
for (const [name, svg] of [
  ['20,000 circles, 50 CSS classes', wrap(circles(20000), rules)],
  ['5,000 <use> copies of a ring and a dot', wrap(uses(5000))],
]) {
  let strokes = 0;
  const ms = median(() => { strokes = parseSvgReport(svg).strokes.length; });
  console.log(`${name} (${(svg.length / 1e3).toFixed(0)} KB): ${ms.toFixed(1)} ms, ${strokes} strokes`);
}
