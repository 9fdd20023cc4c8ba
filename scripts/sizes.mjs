// Prints what each wasm module of the package costs a page: raw, gzip -9 and brotli
// (quality 11) bytes, as a Markdown table.  node scripts/sizes.mjs [pkg/wasm]
import { readFileSync, readdirSync } from 'node:fs';
import { gzipSync, brotliCompressSync, constants } from 'node:zlib';

const dir = process.argv[2] ?? 'pkg/wasm';
const entry = { full: 'patternsynth', vector: 'patternsynth/vector', texture: 'patternsynth/texture', codec: 'patternsynth/codec (and Node)' };
console.log('| module | entry | raw | gzip | brotli |\n|---|---|---:|---:|---:|');
for (const file of readdirSync(dir).filter((f) => f.endsWith('_bg.wasm')).sort()) {
  const bytes = readFileSync(`${dir}/${file}`);
  const gz = gzipSync(bytes, { level: 9 }).length;
  const br = brotliCompressSync(bytes, { params: { [constants.BROTLI_PARAM_QUALITY]: 11 } }).length;
  const name = file.replace('_bg.wasm', '');
  console.log(`| ${name} | ${entry[name] ?? ''} | ${bytes.length} | ${gz} | ${br} |`);
}
