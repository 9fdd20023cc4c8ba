// Zoom and pan of a result preview, as image viewers do it: Ctrl/⌘ + wheel (a
// trackpad's pinch) or two fingers zoom about the pointer, a drag pans once zoomed,
// and the buttons and keys (+, −, 0 and the arrows on the focused view) do the same
// from a keyboard; 1 (or the 1:1 button, for a mouse or a finger) shows a picture of
// pixels one to one. A picture put in its place (the same result restyled) keeps the
// zoom; `reset()` fits a new result.

const MAX_ZOOM = 16;
const STEP = 1.5;

/** Makes `view` (its first child is the picture) zoomable; `controls`: the zoom in,
 *  zoom out and fit buttons, an output for the level and (with `scale`) a one to one
 *  button, `actual`, enabled where the fitted picture is shown smaller than that; `shown()`: whether there is a
 *  picture yet (a blank canvas is none); `scale()`: for a picture of pixels, the
 *  screen pixels (CSS) each of its pixels covers when fitted. The level then reads as a
 *  designer's image editor reads it, screen pixels per picture pixel: 100% is one to
 *  one, and a tile fitted at twice its size reads 200% (it read 100%, the fitted view's
 *  zoom, whatever the picture's scale); else it is the zoom over the fitted view. */
export function zoomable(view, { zoomIn, zoomOut, fit, actual, level, onSettle, shown = () => true, scale }) {
  let s = 1, x = 0, y = 0;
  // Once the zoom stops changing, the owner may draw the picture again at that scale
  // (sharp instead of a bitmap stretched).
  let settled = 1, timer = 0;
  const content = () => (shown() ? view.firstElementChild : null);
  const clamp = () => {
    const w = view.clientWidth, h = view.clientHeight;
    x = Math.min(0, Math.max(w - w * s, x));
    y = Math.min(0, Math.max(h - h * s, y));
  };
  /** The fitted picture's screen pixels per picture pixel (1 without `scale`). */
  const fitted = () => {
    const k = content() && scale?.();
    return k > 0 ? k : 1;
  };
  const apply = () => {
    const c = content();
    clamp();
    if (c) Object.assign(c.style, { transformOrigin: '0 0', transform: s === 1 ? '' : `translate(${x}px, ${y}px) scale(${s})` });
    level.value = `${Math.round(s * fitted() * 100)}%`;
    view.classList.toggle('zoomed', s > 1);
    zoomOut.disabled = fit.disabled = s === 1 || !c;
    zoomIn.disabled = s >= MAX_ZOOM || !c;
    if (actual) actual.disabled = !c || fitted() >= 1 || Math.abs(s * fitted() - 1) < 1e-6;
    clearTimeout(timer);
    if (onSettle && c && s !== settled) timer = setTimeout(() => { settled = s; onSettle(s); }, 250);
  };
  /** Zooms by `factor` keeping the point (px, py) of the view where it is. */
  const zoomAt = (factor, px = view.clientWidth / 2, py = view.clientHeight / 2) => {
    const next = Math.min(MAX_ZOOM, Math.max(1, s * factor));
    x = px - ((px - x) * next) / s;
    y = py - ((py - y) * next) / s;
    s = next;
    apply();
  };
  /** One to one, where the fitted picture is shown smaller than that. */
  const oneToOne = () => zoomAt(Math.max(1, 1 / fitted()) / s);
  const reset = () => {
    s = settled = 1;
    x = y = 0;
    apply();
  };
  new MutationObserver(apply).observe(view, { childList: true });
  zoomIn.addEventListener('click', () => zoomAt(STEP));
  zoomOut.addEventListener('click', () => zoomAt(1 / STEP));
  fit.addEventListener('click', reset);
  actual?.addEventListener('click', oneToOne);

  const local = (e) => {
    const r = view.getBoundingClientRect();
    return [e.clientX - r.left, e.clientY - r.top];
  };
  view.addEventListener('wheel', (e) => {
    if (!(e.ctrlKey || e.metaKey) || !content()) return;
    e.preventDefault();
    zoomAt(Math.exp(-e.deltaY * 0.002), ...local(e));
  }, { passive: false });

  // Pointers down on the view: one pans (once zoomed), two pinch.
  const pointers = new Map();
  view.addEventListener('pointerdown', (e) => {
    if (!content()) return;
    pointers.set(e.pointerId, local(e));
    view.setPointerCapture(e.pointerId);
  });
  view.addEventListener('pointermove', (e) => {
    const last = pointers.get(e.pointerId);
    if (!last) return;
    const now = local(e);
    if (pointers.size === 2) {
      const [other] = [...pointers].filter(([id]) => id !== e.pointerId).map(([, p]) => p);
      const before = Math.hypot(last[0] - other[0], last[1] - other[1]);
      const after = Math.hypot(now[0] - other[0], now[1] - other[1]);
      if (before > 0) zoomAt(after / before, (now[0] + other[0]) / 2, (now[1] + other[1]) / 2);
    } else if (s > 1) {
      x += now[0] - last[0];
      y += now[1] - last[1];
      apply();
    }
    pointers.set(e.pointerId, now);
  });
  const up = (e) => pointers.delete(e.pointerId);
  view.addEventListener('pointerup', up);
  view.addEventListener('pointercancel', up);

  view.addEventListener('keydown', (e) => {
    const pan = { ArrowLeft: [40, 0], ArrowRight: [-40, 0], ArrowUp: [0, 40], ArrowDown: [0, -40] }[e.key];
    if (e.key === '+' || e.key === '=') zoomAt(STEP);
    else if (e.key === '-') zoomAt(1 / STEP);
    else if (e.key === '0') reset();
    else if (e.key === '1' && scale) oneToOne();
    else if (pan && s > 1) {
      x += pan[0];
      y += pan[1];
      apply();
    } else return;
    e.preventDefault();
  });
  apply();
  return { reset, get zoom() { return s; } };
}
