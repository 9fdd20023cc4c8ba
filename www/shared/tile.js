// A tile's preview and exports, shared by the vector and the seamless tile: the tile
// repeated 3 x 3 (optionally offset by half a tile, Photoshop's check that the wrap is
// seamless), a CSS snippet with a copy button, and a download named for what it is.
import { offerDownload, withdrawDownload } from './run.js';

/** The CSS that repeats a tile: the SVG inline (a data URL), a PNG by its file name. */
export function cssSnippet({ svg, file, width, height }) {
  const image = svg ? `data:image/svg+xml,${encodeURIComponent(svg.replace(/\s*\n\s*/g, ''))}` : file;
  return `background-image: url("${image}");\nbackground-size: ${+width.toFixed(3)}px ${+height.toFixed(3)}px;\nbackground-repeat: repeat;`;
}

/**
 * `els`: { preview, download, css, copy, offset } of one tile's panel. Returns
 * `show({ url, svg?, file, width, height, scale })` and `clear()`.
 */
export function tilePanel({ preview, download, css, copy, offset }) {
  let shown = null;
  const place = () => {
    if (!shown) return;
    const { url, w, h } = shown;
    const shift = offset.checked ? [w / 2, h / 2] : [0, 0];
    Object.assign(preview.style, {
      backgroundImage: `url("${url}")`, backgroundSize: `${w}px ${h}px`, backgroundPosition: `${shift[0]}px ${shift[1]}px`,
      width: `${3 * w}px`, height: `${3 * h}px`,
    });
    const one = document.createElement('div');
    one.className = 'one';
    Object.assign(one.style, { width: `${w}px`, height: `${h}px`, left: `${shift[0]}px`, top: `${shift[1]}px` });
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
    show({ url, svg, file, width, height, scale }) {
      shown = { url, w: width * scale, h: height * scale };
      place();
      preview.classList.add('shown');
      offerDownload(download, url);
      download.download = file;
      css.value = cssSnippet({ svg, file, width, height });
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
