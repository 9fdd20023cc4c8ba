// CommonJS copies of the package's type declarations (X.d.ts -> X.d.cts, importing
// one another as './X.cjs'), which the package's "require" conditions name: TypeScript reads a
// .d.ts in a "type": "module" package as ESM and refuses `require` of it under
// `module: node16` (TS1479), although Node itself requires the entries (require(esm)).
//   node scripts/cts-types.mjs pkg
import { readFileSync, readdirSync, writeFileSync } from 'node:fs';
import { join } from 'node:path';

const dir = process.argv[2];
for (const file of readdirSync(dir).filter((f) => f.endsWith('.d.ts'))) {
  // Every relative import to its CommonJS copy: './types.js' -> './types.cjs'.
  const text = readFileSync(join(dir, file), 'utf8').replace(/from '\.\/([\w-]+)\.js'/g, "from './$1.cjs'");
  writeFileSync(join(dir, file.replace(/\.d\.ts$/, '.d.cts')), text);
}
