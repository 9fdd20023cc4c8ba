// Openly licensed SVG pattern tiles (npm `svg-patterns`, ISC licence, by Jannis R),
// repeated 3x3 as the example a person would import.
import { createRequire } from 'node:module';

const require = createRequire(import.meta.url);
const stringify = require('virtual-dom-stringify');

export const STYLES = {
  circles: { complement: false, radius: 8, fill: '#d04040' },
  crosses: {},
  hexagons: {},
  squares: {},
  caps: {},
  nylon: {},
  woven: {},
  waves: {},
  rhombic: {},
  lines: { orientations: [45] },
  'squares+background': { style: 'squares', background: '#f0e0c0' },
};

/** The tile's elements as SVG markup, its period, and the 3x3 repeat as a document. */
export function tile(name, size = 40) {
  const { style = name, ...opts } = STYLES[name];
  const make = require(`svg-patterns/p/${style}`);
  const pattern = make({ size, ...opts });
  const children = pattern.children.map((c) => stringify(c)).join('');
  const px = Number(pattern.properties.width), py = Number(pattern.properties.height);
  let body = '';
  for (let j = 0; j < 3; j++) for (let i = 0; i < 3; i++) body += `<g transform="translate(${i * px} ${j * py})">${children}</g>`;
  const svg = `<svg xmlns="http://www.w3.org/2000/svg" width="${3 * px}" height="${3 * py}">${body}</svg>`;
  return { svg, px, py };
}
