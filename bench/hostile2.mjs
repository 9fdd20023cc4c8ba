// The hostile cases of issue 26 (round two: structure-level input), each in a fresh
// Node process through the built package, followed by a normal call in the same
// instance. Prints one row per case: what came back, the time, whether the next call
// worked, and the instance's wasm memory and externref table after it.
//   node bench/hostile2.mjs [pkgDir=pkg] [timeoutSeconds=10]   (CASE=regexp: only those)
import { spawnSync } from 'node:child_process';
import { mkdtempSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { fileURLToPath } from 'node:url';
import { join, resolve } from 'node:path';

const pkgDir = resolve(process.argv[2] ?? 'pkg');
const timeout = Number(process.argv[3] ?? 10) * 1000;

const svg = (body, head = '') => `${head}<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 100 100">${body}</svg>`;
const nested = (depth, rules) => svg(`<style>${rules}</style>${'<g>'.repeat(depth)}<rect width="5" height="5"/>${'</g>'.repeat(depth)}`);
const chain = (n) => `.nomatch ${'g '.repeat(n)}rect{fill:red}`;
const dtd = (entities) => `<?xml version="1.0"?><!DOCTYPE svg [${entities}]>`;
const STROKES = 'Array.from({ length: 16 }, (_, i) => ({ points: [[10 + (i % 4) * 20, 10 + Math.floor(i / 4) * 20], [15 + (i % 4) * 20, 15 + Math.floor(i / 4) * 20]], width: 1, stroke: "#000000" }))';
const IMAGE = '{ width: 16, height: 16, data: Uint8Array.from({ length: 1024 }, (_, i) => (i * 2654435761) >>> 24) }';

// Each case is a JS expression run with `ps` bound to the package.
export const CASES = [
  ['CSS: 95 nested <g>, a 6-g chain', `ps.parseSvg(${JSON.stringify(nested(95, chain(6)))}).length`],
  ['CSS: 95 nested <g>, a 20-g chain', `ps.parseSvg(${JSON.stringify(nested(95, chain(20)))}).length`],
  ['CSS: 95 nested <g>, 40 rules of 20-g chains', `ps.parseSvg(${JSON.stringify(nested(95, Array.from({ length: 40 }, () => chain(20)).join('')))}).length`],
  ['style attribute, 500,000 declarations', `ps.parseSvg(${JSON.stringify(svg('<rect width="5" height="5" style="PLACEHOLDER"/>'))}.replace('PLACEHOLDER', 'fill:red;'.repeat(500000))).length`],
  ['classifyStrokes, 200,000 distinct strokes', 'ps.classifyStrokes(Array.from({ length: 200000 }, (_, i) => ({ points: [[i % 1000 * 10, Math.floor(i / 1000) * 10], [i % 1000 * 10 + 1 + (i % 97) / 10, Math.floor(i / 1000) * 10 + 3 + (i % 89) / 10], [i % 1000 * 10 + 5, Math.floor(i / 1000) * 10 + (i % 7)]], width: 1 }))).count'],
  ['strokes: a Proxy array claiming length 1e9', 'ps.classifyStrokes(new Proxy([], { get: (t, k) => k === "length" ? 1e9 : typeof k === "string" && /^\\d+$/.test(k) ? { points: [[+k, 0], [+k + 1, 1]], width: 1 } : Reflect.get(t, k) })).count'],
  ['points: a Proxy array claiming length 1e9', 'ps.classifyStrokes([{ width: 1, points: new Proxy([], { get: (t, k) => k === "length" ? 1e9 : typeof k === "string" && /^\\d+$/.test(k) ? [+k, 0] : Reflect.get(t, k) }) }]).count'],
  ['1 MB entity referenced 4,500 times', `ps.parseSvg(${JSON.stringify(dtd('<!ENTITY big "X">'))}.replace('"X"', '"' + 'x'.repeat(1 << 20) + '"') + ${JSON.stringify(svg('<text>' + '&big;'.repeat(4500) + '</text><rect width="3" height="3"/>'))}).length`],
  ['billion laughs (10 levels of 10)', `ps.parseSvg(${JSON.stringify(dtd('<!ENTITY l0 "lol">' + Array.from({ length: 9 }, (_, k) => `<!ENTITY l${k + 1} "${`&l${k};`.repeat(10)}">`).join('')) + svg('<text>&l9;</text><rect width="3" height="3"/>'))}).length`],
  ['progress callback calls the engine', `(() => { let inner = 0; const r = ps.synthesizeStrokes(${STROKES}, { width: 300, height: 300 }, () => { if (inner++ < 3) ps.parseSvg('<svg/>'); }); return r.strokes.length; })()`],
  ['progress callback calls the engine, inner call fails', `(() => { let once = true; return ps.synthesizeStrokes(${STROKES}, { width: 300, height: 300 }, () => { if (once) { once = false; try { ps.synthesizeTexture(null, {}); } catch {} } }).strokes.length; })()`],
  ['progress callbacks recursing to the stack limit', `(() => { const go = () => ps.synthesizeStrokes(${STROKES}, { width: 120, height: 120 }, go); return go().strokes.length; })()`],
  ['a 100 MB string', `ps.parseSvg('<svg>' + ' '.repeat(100 << 20) + '</svg>')`],
  ['10,000 band jobs opened, never closed', `(() => { for (let i = 0; i < 10000; i++) ps.bands.open('synthesizeTexture', [${IMAGE}, { width: 512, height: 512 }]); return 'opened'; })()`],
  ['5,000 calls with throwing getters and proxies', `(() => { let n = 0; const bad = [{ get width() { throw new Error('getter'); }, height: 10 }, new Proxy({}, { ownKeys() { throw new Error('ownKeys'); } }), new Proxy({}, { get() { throw new Error('get'); } })]; for (let i = 0; i < 5000; i++) { try { ps.synthesizeStrokes(${STROKES}.slice(0, 2), bad[i % 3]); } catch { n++; } } return n + ' errors'; })()`],
  ['decodeImage of a detached ArrayBuffer', '(() => { const b = new ArrayBuffer(64); structuredClone(b, { transfer: [b] }); return ps.decodeImage(b); })()'],
  ['decodeImage of a Uint8Array over a detached buffer', '(() => { const a = new Uint8Array(64); structuredClone(a.buffer, { transfer: [a.buffer] }); return ps.decodeImage(a); })()'],
  ['blend coefficient over a detached buffer', `(() => { const c = new Float32Array(64); structuredClone(c.buffer, { transfer: [c.buffer] }); return ps.blendTextures(${IMAGE}, ${IMAGE}, { width: 8, height: 8, coefficient: c }).width; })()`],
  ['exemplar pixels over a detached buffer', `(() => { const im = ${IMAGE}; structuredClone(im.data.buffer, { transfer: [im.data.buffer] }); return ps.synthesizeTexture(im, { width: 8, height: 8 }).width; })()`],
  ['pixels in a SharedArrayBuffer', `(() => { const im = ${IMAGE}; const d = new Uint8Array(new SharedArrayBuffer(1024)); d.set(im.data); im.data = d; return ps.synthesizeTexture(im, { width: 8, height: 8 }).width; })()`],
  ['synthesizeStrokes: 50,000 distinct squares on a 3-unit grid to 2000 x 2000', 'ps.synthesizeStrokes(Array.from({ length: 50000 }, (_, i) => { const x = (i % 224) * 3, y = Math.floor(i / 224) * 3, j = (k) => (((i * 7919 + k * 104729) % 1000) / 1000 - 0.5) * 0.8; return { points: [[x + j(1), y + j(2)], [x + 2 + j(3), y + j(4)], [x + 2 + j(5), y + 2 + j(6)], [x + j(7), y + 2 + j(8)], [x, y]], width: 0.5 }; }), { width: 2000, height: 2000 }).strokes.length'],
  ['synthesizeStrokes: 50,000 overlapping squares scattered at random to 2000 x 2000', 'ps.synthesizeStrokes((() => { let s = 1; const r = () => ((s = (s * 1103515245 + 12345) % 2147483648) / 2147483648); return Array.from({ length: 50000 }, () => { const x = r() * 672, y = r() * 672, j = () => (r() - 0.5) * 0.8; return { points: [[x + j(), y + j()], [x + 2 + j(), y + j()], [x + 2 + j(), y + 2 + j()], [x + j(), y + 2 + j()], [x, y]], width: 0.5 }; }); })(), { width: 2000, height: 2000 }).strokes.length'],
  ['suggestStrokes fill of [0, 0, 1e6, 1e6] after 50,000 strokes', 'ps.suggestStrokes(Array.from({ length: 50000 }, (_, i) => ({ points: [[(i % 224) * 3, Math.floor(i / 224) * 3], [(i % 224) * 3 + 2, Math.floor(i / 224) * 3 + 2]], width: 0.5 })), { fill: true, region: [0, 0, 1e6, 1e6] }).strokes.length'],
  ['decodeImage of a Proxy of a Uint8Array', 'ps.decodeImage(new Proxy(new Uint8Array(10), {}))'],
  ['an option of the wrong type', `ps.synthesizeStrokes(${STROKES}, { width: 'wide', height: 100 }).strokes.length`],
  ['synthesizeStrokes(strokes, {})', `ps.synthesizeStrokes(${STROKES}, {}).strokes.length`],
  ['a getter that throws', `ps.synthesizeStrokes(${STROKES}, { width: 100, height: 100, get seed() { throw new Error('no seed for you'); } }).strokes.length`],
  ['a Map as options', `ps.synthesizeStrokes(${STROKES}, new Map([['width', 100], ['height', 100]])).strokes.length`],
  ['a class instance as options', `ps.synthesizeStrokes(${STROKES}, new (class { get width() { return 100; } get height() { return 50; } get seed() { return 3; } })()).width`],
  // The second independent check's cases over 10 s.
  ['CSS: one <rect> with 60,000 classes, 2,000 rules of 100-class compounds', `ps.parseSvg(${JSON.stringify(svg('<style>RULES</style><rect width="5" height="5" class="CLASSES"/>'))}.replace('RULES', Array.from({ length: 2000 }, (_, r) => Array.from({ length: 100 }, (_, k) => '.c' + ((r * 100 + k) % 60000)).join('') + '{fill:red}').join('')).replace('CLASSES', Array.from({ length: 60000 }, (_, k) => 'c' + k).join(' '))).length`],
  ['classifyStrokes, 50,000 distinct strokes of 100 points', 'ps.classifyStrokes(Array.from({ length: 50000 }, (_, i) => ({ points: Array.from({ length: 100 }, (_, k) => [i % 250 * 20 + k * 0.1, Math.floor(i / 250) * 20 + Math.sin(k * (1 + i % 13) / 10) * (3 + i % 7)]), width: 1 }))).count'],
  ['synthesizeStrokes: 20,000 strokes of 250 points to 5000 x 5000, maxElements 2,000,000', 'ps.synthesizeStrokes(Array.from({ length: 20000 }, (_, i) => ({ points: Array.from({ length: 250 }, (_, k) => [i % 200 * 10 + k * 0.02, Math.floor(i / 200) * 10 + Math.sin(k / 20 + i) * 2]), width: 1 })), { width: 5000, height: 5000, maxElements: 2000000 }).strokes.length'],
  ['suggestStrokes fill after 2,000,000 strokes', 'ps.suggestStrokes(Array.from({ length: 2000000 }, (_, i) => ({ points: [[(i % 2000) * 10, Math.floor(i / 2000) * 10], [(i % 2000) * 10 + 4, Math.floor(i / 2000) * 10 + 4]], width: 1 })), { fill: true, region: [0, 0, 30000, 30000] }).strokes.length'],
  ['seamlessTile synthesis 2048 x 2048', `ps.seamlessTile(${IMAGE.replace(/16/g, '64').replace('1024', '16384')}, { method: 'synthesis', width: 2048, height: 2048 }).width`],
  ['synthesizeTexture 256 x 256 to 2048 x 2048', `ps.synthesizeTexture({ width: 256, height: 256, data: Uint8Array.from({ length: 262144 }, (_, i) => (i * 2654435761) >>> 24) }, { width: 2048, height: 2048 }).width`],
];

const NORMAL = `ps.synthesizeStrokes(${STROKES}, { width: 100, height: 100, seed: 1 }).strokes.length`;

function child(expr) {
  return `
    const ps = await import(${JSON.stringify(pkgDir + '/node/index.js')});
    const { initSync } = await import(${JSON.stringify(pkgDir + '/wasm/full.js')});
    const wasm = () => initSync();
    const base = wasm().memory.buffer.byteLength;
    const t0 = performance.now();
    let outcome;
    try { const r = ${expr}; outcome = { kind: 'ok', detail: typeof r === 'object' && r ? Object.keys(r).slice(0, 4).join(',') : String(r) }; }
    catch (e) {
      const trap = e instanceof WebAssembly.RuntimeError || e?.name === 'InternalError' || /unreachable|out of bounds|RuntimeError|Table/.test(String(e));
      outcome = { kind: trap ? 'trap' : e instanceof Error && !(e instanceof TypeError) ? 'error' : 'throw ' + (e?.constructor?.name ?? typeof e), detail: String(e?.message ?? e).slice(0, 140) };
    }
    outcome.ms = Math.round(performance.now() - t0);
    try { const n = ${NORMAL}; outcome.next = n > 0 ? 'works' : 'empty'; } catch (e) { outcome.next = 'FAILS: ' + String(e?.message ?? e).slice(0, 60); }
    outcome.memory = ((wasm().memory.buffer.byteLength - base) / 2 ** 20).toFixed(1);
    outcome.table = wasm().__wbindgen_externrefs.length;
    console.log(JSON.stringify(outcome));
  `;
}

/** Runs one case in its own process: { kind, ms, next, memory, table, detail }. */
export function runCase(expr) {
  const dir = mkdtempSync(join(tmpdir(), 'hostile2-'));
  const file = join(dir, 'case.mjs');
  writeFileSync(file, child(expr));
  const r = spawnSync(process.execPath, [file], { encoding: 'utf8', timeout, maxBuffer: 1 << 26 });
  if (r.error?.code === 'ETIMEDOUT' || r.signal) return { kind: `hang (>${timeout / 1000} s)`, ms: '', next: '', memory: '', table: '', detail: '' };
  const line = (r.stdout ?? '').trim().split('\n').filter((l) => l.startsWith('{')).at(-1);
  return line ? JSON.parse(line) : { kind: 'crash', ms: '', next: '', memory: '', table: '', detail: (r.stderr || '').trim().split('\n').at(-1)?.slice(0, 140) };
}

if (process.argv[1] === fileURLToPath(import.meta.url)) {
  console.log('| case | outcome | ms | next call | memory kept (MB) | externref table | message |');
  console.log('|---|---|---|---|---|---|---|');
  const only = process.env.CASE ? new RegExp(process.env.CASE) : null;
  for (const [name, expr] of CASES.filter(([n]) => !only || only.test(n))) {
    const o = runCase(expr);
    console.log(`| ${name} | ${o.kind} | ${o.ms} | ${o.next} | ${o.memory} | ${o.table} | ${String(o.detail).replace(/\|/g, '/').replace(/\n/g, ' ')} |`);
  }
}
