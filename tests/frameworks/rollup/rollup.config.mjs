// Rollup 4 with @rollup/plugin-node-resolve, nothing else: the README's recipe copies the
// package's worker and wasm files beside the bundle (done by the test, with the README's
// own commands) and the page passes their URLs.
import { nodeResolve } from '@rollup/plugin-node-resolve';

export default {
  input: 'main.js',
  output: { dir: 'dist', format: 'es' },
  plugins: [nodeResolve()],
};
