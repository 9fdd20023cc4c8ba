// A stroke result restyled without synthesizing it again: colours by class, a
// background and an opacity for the whole pattern. The SVG export marks each
// definition and path with its class (`class="c<k>"`; copies are `<use>`s of a
// definition), so a recolour rewrites a few elements' paint, not the layout.

const HEX = /^#[0-9a-f]{6}$/i;

/**
 * The style checked: `colors[k]` the colour of class k (`#rrggbb`, or null/absent to
 * keep the drawn one), `background` (`#rrggbb` or null: transparent), `opacity` in
 * [0, 1] (default 1).
 */
export function checkStyle(style = {}) {
  if (style === null || typeof style !== 'object') throw new Error('The style must be an object: { colors, background, opacity }.');
  const { colors = [], background = null, opacity = 1 } = style;
  if (!Array.isArray(colors)) throw new Error('style.colors must be an array: one #rrggbb colour (or null) per class.');
  colors.forEach((c, k) => {
    if (c !== null && c !== undefined && !(typeof c === 'string' && HEX.test(c))) throw new Error(`style.colors[${k}] must be a #rrggbb colour or null, got ${JSON.stringify(c)}.`);
  });
  if (background !== null && !(typeof background === 'string' && HEX.test(background))) throw new Error(`style.background must be a #rrggbb colour or null, got ${JSON.stringify(background)}.`);
  if (!(typeof opacity === 'number' && opacity >= 0 && opacity <= 1)) throw new Error(`style.opacity must be a number from 0 to 1, got ${JSON.stringify(opacity)}.`);
  return { colors: colors.map((c) => c ?? null), background, opacity };
}

/** `strokes` with the paint of each class `colors` names replaced (outline and fill). */
export function restyleStrokes(strokes, classes, { colors }) {
  return strokes.map((s, i) => {
    const c = colors[classes[i]];
    if (!c) return s;
    return { ...s, stroke: s.stroke ? c : s.stroke, fill: s.fill ? c : s.fill };
  });
}

/** The SVG document with the style applied: paint of the recoloured classes rewritten,
 *  the picture in a group with the opacity, a background rectangle under it. */
export function restyleSvg(svg, { colors, background, opacity }) {
  let out = svg;
  if (colors.some(Boolean)) {
    out = out.replace(/<path [^>]*class="c(\d+)"[^>]*>/g, (tag, k) => {
      const c = colors[Number(k)];
      return c ? tag.replace(/ (stroke|fill)="#[0-9a-fA-F]{6}"/g, ` $1="${c}"`) : tag;
    });
  }
  if (background === null && opacity === 1) return out;
  const open = out.indexOf('>', out.indexOf('<svg')) + 1;
  const close = out.lastIndexOf('</svg>');
  if (open <= 0 || close < open) throw new Error('restyle: not an SVG document.');
  const under = background ? `\n<rect width="100%" height="100%" fill="${background}"/>` : '';
  const [start, end] = opacity === 1 ? ['', ''] : [`\n<g opacity="${opacity}">`, '</g>\n'];
  return out.slice(0, open) + under + start + out.slice(open, close) + end + out.slice(close);
}
