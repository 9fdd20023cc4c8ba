// The hostile cases of issue 9, each in a fresh Node process through the built package,
// followed by a normal call in the same instance. Prints one row per case: what came
// back (ok, a clear error, a trap, a hang), the time, and whether the next call worked.
//   node bench/hostile.mjs [pkgDir=pkg] [timeoutSeconds=25]
import { spawnSync } from 'node:child_process';
import { mkdtempSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { fileURLToPath } from 'node:url';
import { join, resolve } from 'node:path';

const pkgDir = resolve(process.argv[2] ?? 'pkg');
const timeout = Number(process.argv[3] ?? 25) * 1000;

const nest = (open, close, n, inner) => open.repeat(n) + inner + close.repeat(n);
const svg = (body) => `<svg xmlns="http://www.w3.org/2000/svg" xmlns:xlink="http://www.w3.org/1999/xlink" viewBox="0 0 100 100">${body}</svg>`;
const circle = '<circle cx="5" cy="5" r="3" fill="#000"/>';
const grid = 'Array.from({ length: 16 }, (_, i) => ({ points: [[10 + (i % 4) * 20, 10 + Math.floor(i / 4) * 20], [15 + (i % 4) * 20, 15 + Math.floor(i / 4) * 20]], width: W, stroke: "#000000" }))';

// Each case is a JS expression run with `ps` bound to the package.
export const CASES = [
  ['<g> nested 240 deep', `ps.parseSvg(${JSON.stringify(svg(nest('<g>', '</g>', 240, circle)))})`],
  ['<a> nested 240 deep', `ps.parseSvg(${JSON.stringify(svg(nest('<a>', '</a>', 240, circle)))})`],
  ['400 nested scale(10)', `ps.parseSvg(${JSON.stringify(svg(nest('<g transform="scale(10)">', '</g>', 400, circle)))})`],
  ['chain of 200 <use>', `ps.parseSvg(${JSON.stringify(svg('<defs><circle id="u0" r="2"/>' + Array.from({ length: 200 }, (_, i) => `<use id="u${i + 1}" href="#u${i}"/>`).join('') + '</defs><use href="#u200"/>'))})`],
  ['circle r=1e20', `ps.parseSvg(${JSON.stringify(svg('<circle cx="0" cy="0" r="1e20" fill="#000"/>'))})`],
  ['scale(1e15) on a circle', `ps.parseSvg(${JSON.stringify(svg('<g transform="scale(1e15)"><circle r="3" fill="#000"/></g>'))})`],
  ['cubic control points at 1e30', `ps.parseSvg(${JSON.stringify(svg('<path d="M0 0 C1e30 1e30 -1e30 1e30 10 10" stroke="#000"/>'))})`],
  ['tolerance 1e-300', `ps.parseSvg(${JSON.stringify(svg(circle))}, { tolerance: 1e-300 })`],
  ['strokeTile, width 1e300', `ps.strokeTile(${grid.replace('W', '1e300')}, {})`],
  ['strokeTile, width 20000', `ps.strokeTile(${grid.replace('W', '20000')}, {})`],
  ['strokeTile, width 60000', `ps.strokeTile(${grid.replace('W', '60000')}, {})`],
  ['decodeImage({ length: -1 })', 'ps.decodeImage({ length: -1 })'],
  ['decodeImage({ length: 1e9 })', 'ps.decodeImage({ length: 1e9 })'],
  ['decodeImage(null)', 'ps.decodeImage(null)'],
  ['parseSvg(42)', 'ps.parseSvg(42)'],
  ['parseSvg({})', 'ps.parseSvg({})'],
  ['parseSvg(null)', 'ps.parseSvg(null)'],
  ['parseSvg(new Uint8Array(4))', 'ps.parseSvg(new Uint8Array(4))'],
  ['{ seed: undefined }', `ps.synthesizeStrokes(${grid.replace('W', '1')}, { width: 100, height: 100, seed: undefined })`],
  ['progress callback throws', `ps.synthesizeStrokes(${grid.replace('W', '1')}, { width: 400, height: 400 }, () => { throw new Error('boom from the callback'); })`],
  ['progress callback not a function', `ps.synthesizeStrokes(${grid.replace('W', '1')}, { width: 400, height: 400 }, 42)`],
  ['path with 40,000 attributes', `ps.parseSvg(${JSON.stringify(svg('<path d="M0 0 L10 10" stroke="#000" ' + Array.from({ length: 40000 }, (_, i) => `data-a${i}="1"`).join(' ') + '/>'))})`],
  ['8,000 CSS class rules', `ps.parseSvg(${JSON.stringify(svg('<style>' + Array.from({ length: 8000 }, (_, i) => `.c${i}{fill:#${(i % 4096).toString(16).padStart(3, '0')}}`).join('') + '</style>' + Array.from({ length: 400 }, (_, i) => `<rect class="c${i * 20}" x="${i % 20 * 5}" y="${Math.floor(i / 20) * 5}" width="3" height="3"/>`).join('')))})`],
  ['blend two 16x64 exemplars to 256²', `(() => { const im = (w, h, s) => ({ width: w, height: h, data: Uint8Array.from({ length: w * h * 4 }, (_, i) => (i * s * 2654435761 >>> 24) | (i % 4 === 3 ? 255 : 0)) }); return ps.blendTextures(im(16, 64, 3), im(16, 64, 7), { width: 256, height: 256, coefficient: 'linear', seed: 1 }); })()`],
  ['texture from a 6x256 exemplar to 256²', `(() => { const im = (w, h, s) => ({ width: w, height: h, data: Uint8Array.from({ length: w * h * 4 }, (_, i) => (i * s * 2654435761 >>> 24) | (i % 4 === 3 ? 255 : 0)) }); return ps.synthesizeTexture(im(6, 256, 3), { width: 256, height: 256, seed: 1 }); })()`],
  ['strokes 2e5 x 2e5, maxElements 1e9', `ps.synthesizeStrokes(${grid.replace('W', '1')}, { width: 2e5, height: 2e5, maxElements: 1e9 })`],
  ['300 of the above in a row', `(() => { const bad = [${JSON.stringify(svg('<circle cx="0" cy="0" r="1e20" fill="#000"/>'))}, ${JSON.stringify(svg(nest('<g>', '</g>', 240, circle)))}, 42, null]; let errors = 0; for (let i = 0; i < 300; i++) { try { ps.parseSvg(bad[i % 4], i % 8 === 0 ? { tolerance: 1e-300 } : undefined); } catch (e) { if (e instanceof WebAssembly.RuntimeError || e.name === 'InternalError') throw e; errors++; } } return errors + ' clean errors'; })()`],
];

const NORMAL = `ps.synthesizeStrokes(${grid.replace('W', '1')}, { width: 100, height: 100, seed: 1 }).strokes.length`;

function child(expr) {
  return `
    const ps = await import(${JSON.stringify(pkgDir + '/node/index.js')});
    const t0 = performance.now();
    let outcome;
    try { const r = ${expr}; outcome = { kind: 'ok', detail: typeof r === 'object' && r ? Object.keys(r).slice(0, 4).join(',') : String(r) }; }
    catch (e) {
      const trap = e instanceof WebAssembly.RuntimeError || e?.name === 'InternalError' || /unreachable|out of bounds|RuntimeError/.test(String(e));
      outcome = { kind: trap ? 'trap' : e instanceof Error && !(e instanceof TypeError) ? 'error' : 'throw ' + (e?.constructor?.name ?? typeof e), detail: String(e?.message ?? e).slice(0, 110) };
    }
    outcome.ms = Math.round(performance.now() - t0);
    try { const n = ${NORMAL}; outcome.next = n > 0 ? 'works' : 'empty'; } catch (e) { outcome.next = 'FAILS: ' + String(e?.message ?? e).slice(0, 60); }
    console.log(JSON.stringify(outcome));
  `;
}

if (process.argv[1] === fileURLToPath(import.meta.url)) {
  const dir = mkdtempSync(join(tmpdir(), 'hostile-'));
  console.log('| case | outcome | ms | next call | message |');
  console.log('|---|---|---|---|---|');
  for (const [name, expr] of CASES) {
    const file = join(dir, 'case.mjs');
    writeFileSync(file, child(expr));
    const r = spawnSync(process.execPath, [file], { encoding: 'utf8', timeout, maxBuffer: 1 << 26 });
    let o;
    if (r.error?.code === 'ETIMEDOUT' || r.signal) o = { kind: `hang (>${timeout / 1000} s)`, ms: '', next: '', detail: '' };
    else {
      const line = (r.stdout ?? '').trim().split('\n').filter((l) => l.startsWith('{')).at(-1);
      o = line ? JSON.parse(line) : { kind: 'crash', ms: '', next: '', detail: (r.stderr || '').trim().split('\n').at(-1)?.slice(0, 110) };
    }
    console.log(`| ${name} | ${o.kind} | ${o.ms} | ${o.next} | ${String(o.detail).replace(/\|/g, '/').replace(/\n/g, ' ')} |`);
  }
}
