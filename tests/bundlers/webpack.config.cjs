// webpack 5 with no loaders or plugins: what a site's own config would hold.
const path = require('node:path');
module.exports = (env) => ({
  mode: 'production',
  context: path.resolve(env.work, 'site'),
  entry: './main.js',
  output: { path: path.resolve(env.work, 'dist-webpack'), filename: 'main.js', clean: true },
  performance: { hints: false },
});
