// Writes pkg/node/embedded/<name>.js for each wasm module: the module gzipped, as a
// base64 string, which the Node entries instantiate at import (js/pkg/node/load.js).
// Usage: node scripts/embed-wasm.mjs pkg
import { mkdirSync, readFileSync, readdirSync, writeFileSync } from 'node:fs';
import { join } from 'node:path';
import { gzipSync } from 'node:zlib';

const pkg = process.argv[2] ?? 'pkg';
const out = join(pkg, 'node/embedded');
mkdirSync(out, { recursive: true });
// Not the scalar builds: every Node the package runs on has SIMD.
for (const file of readdirSync(join(pkg, 'wasm')).filter((f) => f.endsWith('_bg.wasm') && !f.endsWith('_scalar_bg.wasm'))) {
  const name = file.slice(0, -'_bg.wasm'.length);
  const base64 = gzipSync(readFileSync(join(pkg, 'wasm', file)), { level: 9 }).toString('base64');
  writeFileSync(join(out, `${name}.js`), `// ${file}, gzipped, base64 (written by scripts/embed-wasm.mjs).\nexport default '${base64}';\n`);
}
