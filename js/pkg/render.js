// Stroke results drawn to an image in the worker (OffscreenCanvas), so that a page can
// show a result of tens of thousands of strokes without parsing and painting its SVG on
// the main thread. Drawn as the SVG export draws them: round caps and joins, fill then
// outline, subpaths at `breaks`, even-odd where the stroke says, opacities multiplied.

/**
 * `result.strokes` (in a `sceneWidth x sceneHeight` scene) scaled to fit `width x height`
 * (the aspect kept), on `background` (CSS colour; transparent by default). Returns an
 * ImageBitmap, or with `type: 'image/png'` a promise of a PNG Blob (encoded here, off
 * the page's thread); null where OffscreenCanvas is missing.
 */
export function renderStrokes(strokes, sceneWidth, sceneHeight, { width, height, background, type, opacity = 1 } = {}) {
  if (typeof OffscreenCanvas !== 'function') return null;
  if (!(sceneWidth > 0 && sceneHeight > 0)) throw new Error('preview: the result has no size to draw.');
  if (type !== undefined && type !== 'image/png') throw new Error(`preview: type may be 'image/png' (or left out for an ImageBitmap), got ${type}.`);
  if (!(width >= 1 && height >= 1 && width <= 8192 && height <= 8192)) {
    throw new Error(`preview: width and height must be from 1 to 8192 pixels, got ${width} x ${height}.`);
  }
  if (!(typeof opacity === 'number' && opacity >= 0 && opacity <= 1)) throw new Error(`preview: opacity must be from 0 to 1, got ${opacity}.`);
  const k = Math.min(width / sceneWidth, height / sceneHeight);
  const canvas = new OffscreenCanvas(Math.max(1, Math.round(sceneWidth * k)), Math.max(1, Math.round(sceneHeight * k)));
  const page = canvas.getContext('2d');
  if (background) {
    page.fillStyle = background;
    page.fillRect(0, 0, canvas.width, canvas.height);
  }
  // A pattern's opacity applies to the picture as a whole (as an SVG group's does), so
  // it is drawn on a layer of its own first.
  const layer = opacity < 1 ? new OffscreenCanvas(canvas.width, canvas.height) : canvas;
  const ctx = layer.getContext('2d');
  ctx.setTransform(k, 0, 0, k, 0, 0);
  ctx.lineCap = 'round';
  ctx.lineJoin = 'round';
  for (const s of strokes) {
    const path = new Path2D();
    const breaks = [...(s.breaks ?? []), s.points.length];
    let start = 0;
    for (const end of breaks) {
      for (let i = start; i < end; i++) {
        const [x, y] = s.points[i];
        if (i === start) path.moveTo(x, y);
        else path.lineTo(x, y);
      }
      // (A subpath of one point, a pen tap, is a dot: a lone moveTo strokes nothing, so a
      // segment a hair long takes the round caps, as the SVG's `l0 0` does.)
      if (end - start === 1) path.lineTo(s.points[start][0] + 1e-3, s.points[start][1]);
      if (s.closed) path.closePath();
      start = end;
    }
    const alpha = s.opacity ?? 1;
    if (s.fill) {
      ctx.globalAlpha = alpha * (s.fillOpacity ?? 1);
      ctx.fillStyle = s.fill;
      ctx.fill(path, s.fillRule === 'evenodd' ? 'evenodd' : 'nonzero');
    }
    if (s.stroke && s.width > 0) {
      ctx.globalAlpha = alpha * (s.strokeOpacity ?? 1);
      ctx.strokeStyle = s.stroke;
      ctx.lineWidth = s.width;
      ctx.stroke(path);
    }
  }
  if (layer !== canvas) {
    page.globalAlpha = opacity;
    page.drawImage(layer, 0, 0);
  }
  return type ? canvas.convertToBlob({ type }) : canvas.transferToImageBitmap();
}
