// A tile's preview and exports, shared by the vector and the seamless tile: the tile
// repeated 3 x 3 (optionally offset by half a tile, Photoshop's check that the wrap is
// seamless), a CSS snippet with a copy button, and a download named for what it is.
import { offerDownload, withdrawDownload } from './run.js';

/** The CSS that repeats a tile: the SVG inline (a data URL), a PNG by its file name.
 *  Turned (`transform.rotate`), an SVG tile becomes an SVG `<pattern>` filling the
 *  element (as pattern.monster writes it): a turned lattice has no axis-aligned
 *  period for `background-repeat` to repeat. */
export function cssSnippet({ svg, file, width, height, transform }) {
  if (svg && transformed(transform)) {
    return `background-image: url("${dataUrl(patterned(svg, width, height, transform))}");`;
  }
  const image = svg ? dataUrl(svg) : file;
  const [w, h] = [width, height].map((v) => +(v * (transform?.scale ?? 1)).toFixed(3));
  return `background-image: url("${image}");\nbackground-size: ${w}px ${h}px;\nbackground-repeat: repeat;`;
}

const dataUrl = (svg) => `data:image/svg+xml,${encodeURIComponent(svg.replace(/\s*\n\s*/g, ''))}`;
// Scale alone stays a repeated background (background-size); a turn needs the pattern.
const transformed = (t) => t && (t.rotate ?? 0) % 360 !== 0;

/** An SVG that fills any box with `svg` (a `width x height` tile) repeated through a
 *  `<pattern>`, scaled and turned about the top left corner. */
export function patterned(svg, width, height, { scale = 1, rotate = 0 } = {}) {
  const open = svg.indexOf('>', svg.indexOf('<svg')) + 1;
  const inner = svg.slice(open, svg.lastIndexOf('</svg>'));
  return `<svg xmlns="http://www.w3.org/2000/svg" xmlns:xlink="http://www.w3.org/1999/xlink" width="100%" height="100%">`
    + `<defs><pattern id="tile" patternUnits="userSpaceOnUse" width="${+width.toFixed(3)}" height="${+height.toFixed(3)}" patternTransform="rotate(${rotate}) scale(${scale})">${inner}</pattern></defs>`
    + '<rect width="100%" height="100%" fill="url(#tile)"/></svg>';
}

/**
 * `els`: { preview, download, css, copy, offset } of one tile's panel. Returns
 * `show({ url, svg?, file, width, height, scale, transform? })` (`scale`: the
 * preview's; `transform`: `{ scale, rotate }` of the pattern, in the CSS too) and
 * `clear()`.
 */
export function tilePanel({ preview, download, css, copy, offset }) {
  let shown = null;
  const place = () => {
    if (!shown) return;
    const { url, w, h, svg, transform, width, height } = shown;
    const shift = offset.checked ? [w / 2, h / 2] : [0, 0];
    if (svg && transformed(transform)) {
      // The pattern at the preview's scale: the same SVG the CSS snippet holds.
      const k = w / width;
      const picture = patterned(svg, width, height, { rotate: transform.rotate, scale: (transform.scale ?? 1) * k });
      Object.assign(preview.style, {
        backgroundImage: `url("${dataUrl(picture)}")`, backgroundSize: '100% 100%', backgroundPosition: '0 0', width: `${3 * w}px`, height: `${3 * h}px`,
      });
      preview.replaceChildren();
      return;
    }
    const [sw, sh] = [w, h].map((v) => v * (transform?.scale ?? 1));
    Object.assign(preview.style, {
      backgroundImage: `url("${url}")`, backgroundSize: `${sw}px ${sh}px`, backgroundPosition: `${shift[0]}px ${shift[1]}px`,
      width: `${3 * w}px`, height: `${3 * h}px`,
    });
    const one = document.createElement('div');
    one.className = 'one';
    Object.assign(one.style, { width: `${sw}px`, height: `${sh}px`, left: `${shift[0]}px`, top: `${shift[1]}px` });
    preview.replaceChildren(one);
  };
  offset.addEventListener('change', place);
  copy.addEventListener('click', async () => {
    css.hidden = false;
    css.select();
    try {
      await navigator.clipboard.writeText(css.value);
      copy.textContent = 'Copied';
    } catch {
      copy.textContent = 'Select and copy';
    }
    setTimeout(() => { copy.textContent = 'Copy CSS'; }, 1500);
  });
  return {
    show({ url, svg, file, width, height, scale, transform }) {
      shown = { url, w: width * scale, h: height * scale, svg, transform, width, height };
      place();
      preview.classList.add('shown');
      offerDownload(download, url);
      download.download = file;
      css.value = cssSnippet({ svg, file, width, height, transform });
      copy.disabled = false;
      offset.disabled = false;
    },
    clear() {
      shown = null;
      preview.classList.remove('shown');
      withdrawDownload(download);
      css.value = '';
      css.hidden = true;
      copy.disabled = true;
      offset.disabled = true;
    },
  };
}
