// Server output with the Node adapter in standalone mode: `node dist/server/entry.mjs`
// serves the pages, rendered at request time.
import { defineConfig } from 'astro/config';
import node from '@astrojs/node';

export default defineConfig({
  output: 'server',
  adapter: node({ mode: 'standalone' }),
});
