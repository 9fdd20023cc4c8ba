// Scale and rotation of the result: the drawing is scaled and turned about its middle
// before synthesis (its strokes' widths scaled too), and periods set by hand with it,
// so the output fills the same width and height with the pattern larger, smaller or
// turned. Turning the example, not the output, keeps every corner of the output
// covered.
import { bounds } from './canvas.js';

/** `strokes` scaled by `scale` and turned by `degrees` (clockwise on screen). */
export function transformStrokes(strokes, { scale = 1, degrees = 0 }) {
  if (scale === 1 && degrees % 360 === 0) return strokes;
  const b = bounds(strokes);
  const [cx, cy] = [(b.x0 + b.x1) / 2, (b.y0 + b.y1) / 2];
  const [c, s] = [Math.cos((degrees * Math.PI) / 180) * scale, Math.sin((degrees * Math.PI) / 180) * scale];
  const map = ([x, y]) => [cx + c * (x - cx) - s * (y - cy), cy + s * (x - cx) + c * (y - cy)];
  return strokes.map((st) => ({ ...st, points: st.points.map(map), width: st.width * scale }));
}

/** Period vectors scaled and turned as `transformStrokes` does the strokes. */
export function transformPeriods(periods, { scale = 1, degrees = 0 }) {
  if (!periods) return periods;
  const [c, s] = [Math.cos((degrees * Math.PI) / 180) * scale, Math.sin((degrees * Math.PI) / 180) * scale];
  return periods.map(([x, y]) => [c * x - s * y, s * x + c * y]);
}
