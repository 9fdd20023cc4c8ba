// The drawing: strokes in canvas coordinates, pointer-event input (mouse, pen, touch),
// undo/redo history, and rendering with an optional class overlay and ghost strokes
// (autocomplete's proposals, drawn faint; a tap on one is handed to `onTap`), and a lattice set
// by hand, its periods dragged by their handles (`onLattice`).

/** Draws one stroke (polyline, maybe compound and closed) on a 2D context. */
export function drawStroke(ctx, s) {
  const pts = s.points;
  if (!pts.length) return;
  const starts = new Set(s.breaks ?? []);
  ctx.beginPath();
  pts.forEach(([x, y], i) => {
    if (i === 0 || starts.has(i)) {
      if (i > 0 && s.closed) ctx.closePath();
      ctx.moveTo(x, y);
    } else ctx.lineTo(x, y);
  });
  if (s.closed) ctx.closePath();
  const alpha = s.opacity ?? 1;
  if (s.fill) {
    ctx.globalAlpha = alpha * (s.fillOpacity ?? 1);
    ctx.fillStyle = s.fill;
    ctx.fill(s.fillRule === 'evenodd' ? 'evenodd' : 'nonzero');
  }
  if (s.stroke) {
    ctx.globalAlpha = alpha * (s.strokeOpacity ?? 1);
    ctx.strokeStyle = s.stroke;
    ctx.lineWidth = Math.max(s.width, 0.5);
    if (pts.length === 1) {
      ctx.beginPath();
      ctx.arc(pts[0][0], pts[0][1], Math.max(s.width, 1) / 2, 0, Math.PI * 2);
      ctx.fillStyle = s.stroke;
      ctx.fill();
    } else ctx.stroke();
  }
  ctx.globalAlpha = 1;
}

export function bounds(strokes) {
  let x0 = Infinity, y0 = Infinity, x1 = -Infinity, y1 = -Infinity;
  for (const s of strokes) for (const [x, y] of s.points) {
    const r = (s.stroke ? s.width : 0) / 2;
    x0 = Math.min(x0, x - r); y0 = Math.min(y0, y - r); x1 = Math.max(x1, x + r); y1 = Math.max(y1, y + r);
  }
  return { x0, y0, x1, y1 };
}

/** Scales and moves strokes to fit a `w x h` box with a margin (never enlarging by more than 4x). */
export function fitStrokes(strokes, w, h, margin = 20) {
  if (!strokes.length) return strokes;
  const b = bounds(strokes);
  const bw = Math.max(b.x1 - b.x0, 1e-6), bh = Math.max(b.y1 - b.y0, 1e-6);
  const k = Math.min((w - 2 * margin) / bw, (h - 2 * margin) / bh, 4);
  const dx = (w - bw * k) / 2 - b.x0 * k, dy = (h - bh * k) / 2 - b.y0 * k;
  return strokes.map((s) => ({ ...s, width: s.width * k, points: s.points.map(([x, y]) => [x * k + dx, y * k + dy]) }));
}

export class Drawing {
  constructor(canvas, { onChange, getPen, onTap }) {
    this.canvas = canvas;
    this.ctx = canvas.getContext('2d');
    this.onChange = onChange;
    this.getPen = getPen;
    this.onTap = onTap;
    this.ghosts = [];
    /** A lattice set by hand ({ a, b } period vectors), shown over the drawing with a
     *  handle at the tip of each period; `onLattice(which, [x, y])` hears its drags. */
    this.lattice = null;
    this.onLattice = null;
    this.strokes = [];
    this.past = [];
    this.future = [];
    this.classes = null;
    this.colors = [];
    this.live = null;
    this.logical = { w: canvas.width, h: canvas.height };
    this.resize();
    this.listen();
  }

  resize() {
    const dpr = window.devicePixelRatio || 1;
    this.canvas.width = this.logical.w * dpr;
    this.canvas.height = this.logical.h * dpr;
    this.canvas.style.width = `${this.logical.w}px`;
    this.ctx.setTransform(dpr, 0, 0, dpr, 0, 0);
    this.render();
  }

  /** Replaces the strokes; the previous drawing goes on the undo stack. */
  set(strokes, { record = true } = {}) {
    if (record) {
      this.past.push(this.strokes);
      if (this.past.length > 200) this.past.shift();
      this.future = [];
    }
    this.strokes = strokes;
    this.classes = null;
    this.render();
    this.onChange?.(this.strokes);
  }

  undo() {
    this.step(this.past, this.future);
  }

  redo() {
    this.step(this.future, this.past);
  }

  /** Moves one drawing from the `from` history to the screen, the current one to `to`. */
  step(from, to) {
    if (!from.length) return;
    to.push(this.strokes);
    this.strokes = from.pop();
    this.classes = null;
    this.render();
    this.onChange?.(this.strokes);
  }

  /** The drawing with its undo and redo history (to keep across a reload). */
  get session() {
    return { strokes: this.strokes, past: this.past, future: this.future };
  }

  /** Restores a kept `session` (without recording a step). */
  restore({ strokes = [], past = [], future = [] }) {
    this.past = past;
    this.future = future;
    this.set(strokes, { record: false });
  }

  showClasses(classes, colors) {
    this.classes = classes;
    this.colors = colors;
    this.render();
  }

  /** Shows proposed strokes faintly, fainter for lower `confidence` (0..1 each). */
  showGhosts(ghosts, confidence = []) {
    this.ghosts = ghosts;
    this.ghostAlpha = ghosts.map((_, i) => 0.2 + 0.25 * (confidence[i] ?? 1));
    this.render();
  }

  showLattice(lattice) {
    this.lattice = lattice;
    this.render();
  }

  /** Where the lattice shown is anchored: the middle of the drawing (or the canvas). */
  latticeOrigin() {
    if (!this.strokes.length) return [this.logical.w / 2, this.logical.h / 2];
    const b = bounds(this.strokes);
    return [(b.x0 + b.x1) / 2, (b.y0 + b.y1) / 2];
  }

  /** Canvas units per CSS pixel (the canvas is shrunk to fit a phone's width). */
  unitsPerPixel() {
    const w = this.canvas.getBoundingClientRect().width;
    return w > 0 ? this.logical.w / w : 1;
  }

  /** The lattice handle ('a' or 'b') under `p`: 12 CSS px round its tip (a 24 px
   *  target, at any size the canvas is shown at). */
  onHandle([x, y]) {
    if (!this.lattice) return null;
    const [ox, oy] = this.latticeOrigin();
    const reach = 12 * Math.max(1, this.unitsPerPixel());
    for (const k of ['a', 'b']) {
      const [vx, vy] = this.lattice[k];
      if (Math.hypot(x - ox - vx, y - oy - vy) <= reach) return k;
    }
    return null;
  }

  renderLattice(ctx) {
    const { a, b } = this.lattice;
    const [ox, oy] = this.latticeOrigin();
    const det = a[0] * b[1] - a[1] * b[0];
    if (!(Math.abs(det) > 1)) return;
    ctx.save();
    // The sites: every lattice point on the canvas (at most a few thousand).
    ctx.fillStyle = 'rgba(67, 99, 216, 0.45)';
    const corners = [[0, 0], [this.logical.w, 0], [0, this.logical.h], [this.logical.w, this.logical.h]]
      .map(([x, y]) => [((x - ox) * b[1] - (y - oy) * b[0]) / det, (a[0] * (y - oy) - a[1] * (x - ox)) / det]);
    const [u0, u1] = [Math.floor(Math.min(...corners.map((c) => c[0]))), Math.ceil(Math.max(...corners.map((c) => c[0])))];
    const [w0, w1] = [Math.floor(Math.min(...corners.map((c) => c[1]))), Math.ceil(Math.max(...corners.map((c) => c[1])))];
    if ((u1 - u0 + 1) * (w1 - w0 + 1) <= 5000) {
      for (let u = u0; u <= u1; u++) {
        for (let w = w0; w <= w1; w++) {
          ctx.beginPath();
          ctx.arc(ox + u * a[0] + w * b[0], oy + u * a[1] + w * b[1], 2.5, 0, 2 * Math.PI);
          ctx.fill();
        }
      }
    }
    // The two periods as arrows with round handles.
    ctx.strokeStyle = ctx.fillStyle = '#4363d8';
    ctx.lineWidth = 2;
    for (const [vx, vy] of [a, b]) {
      ctx.beginPath();
      ctx.moveTo(ox, oy);
      ctx.lineTo(ox + vx, oy + vy);
      ctx.stroke();
      ctx.beginPath();
      ctx.arc(ox + vx, oy + vy, 7 * Math.max(1, this.unitsPerPixel()), 0, 2 * Math.PI);
      ctx.fill();
    }
    ctx.restore();
  }

  /** Whether `p` is on a ghost (within a few pixels of its bounds). */
  onGhost([x, y]) {
    return this.ghosts.some((s) => {
      const b = bounds([s]);
      return x >= b.x0 - 6 && x <= b.x1 + 6 && y >= b.y0 - 6 && y <= b.y1 + 6;
    });
  }

  render() {
    const { ctx } = this;
    ctx.clearRect(0, 0, this.logical.w, this.logical.h);
    for (const s of this.strokes) drawStroke(ctx, s);
    this.ghosts.forEach((s, i) => drawStroke(ctx, { ...s, opacity: (s.opacity ?? 1) * this.ghostAlpha[i] }));
    if (this.live) drawStroke(ctx, this.live);
    if (this.lattice) this.renderLattice(ctx);
    if (this.classes && this.classes.length === this.strokes.length) {
      ctx.save();
      ctx.setLineDash([3, 2]);
      ctx.lineWidth = 1;
      this.strokes.forEach((s, i) => {
        const b = bounds([s]);
        ctx.strokeStyle = this.colors[this.classes[i] % this.colors.length];
        ctx.strokeRect(b.x0 - 2, b.y0 - 2, b.x1 - b.x0 + 4, b.y1 - b.y0 + 4);
      });
      ctx.restore();
    }
  }

  point(e) {
    const r = this.canvas.getBoundingClientRect();
    return [((e.clientX - r.left) * this.logical.w) / r.width, ((e.clientY - r.top) * this.logical.h) / r.height];
  }

  listen() {
    const c = this.canvas;
    c.addEventListener('pointerdown', (e) => {
      if (e.button !== 0) return;
      c.setPointerCapture(e.pointerId);
      // A drag from a lattice handle sets that period; it draws nothing.
      this.handle = this.onHandle(this.point(e));
      if (this.handle) return;
      this.liveTouch = e.pointerType === 'touch';
      const pen = this.getPen();
      this.live = {
        points: [this.point(e)],
        width: pen.width,
        stroke: pen.strokeOn ? pen.stroke : null,
        fill: pen.fillOn ? pen.fill : null,
        closed: pen.fillOn,
      };
      this.render();
    });
    c.addEventListener('pointermove', (e) => {
      if (this.handle) {
        const [x, y] = this.point(e);
        const [ox, oy] = this.latticeOrigin();
        this.onLattice?.(this.handle, [x - ox, y - oy]);
        return;
      }
      if (!this.live) return;
      const events = e.getCoalescedEvents ? e.getCoalescedEvents() : [e];
      for (const ev of events.length ? events : [e]) {
        const p = this.point(ev);
        const last = this.live.points[this.live.points.length - 1];
        if (Math.hypot(p[0] - last[0], p[1] - last[1]) >= 1.5) this.live.points.push(p);
      }
      this.render();
    });
    const finish = (keep) => {
      if (!this.live) return;
      const s = this.live;
      this.live = null;
      // A tap (no drag) on a ghost is not a dot: it is handed on (to accept the ghosts).
      // A finger's tap anywhere else is not a dot either (a stray touch, or one meant to
      // scroll or focus): on a touch screen dots are drawn as tiny strokes.
      const b = bounds([s]);
      const tap = Math.max(b.x1 - b.x0, b.y1 - b.y0) - s.width <= 4;
      if (keep && tap && this.ghosts.length && this.onGhost(s.points[0]) && this.onTap?.(s.points[0])) this.render();
      else if (keep && !(tap && this.liveTouch) && (s.stroke || s.fill)) this.set([...this.strokes, s]);
      else this.render();
    };
    c.addEventListener('pointerup', () => {
      this.handle = null;
      finish(true);
    });
    c.addEventListener('pointercancel', () => {
      this.handle = null;
      finish(false);
    });
  }
}
