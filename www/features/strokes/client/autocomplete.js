// Autocomplete while drawing: after each change to the drawing, the worker proposes the
// next copies of the repetition (suggestStrokes) and the canvas shows them as ghosts.
// One request at a time: a change made while one runs is answered by one more request
// when it returns (aborting it would end the worker), and an answer for a drawing that
// has changed since is dropped. Accepting adds the ghosts as one undo step.

const DISMISSED = 'Dismissed; draw on for new suggestions.';

export class Autocomplete {
  /**
   * @param {object} o
   * @param {import('../../../pkg/client.js').PatternSynthClient} o.client
   * @param {import('./canvas.js').Drawing} o.drawing
   * @param {() => object} o.options suggestStrokes options (tolerances, seed, variation)
   * @param {() => boolean} o.enabled whether to propose at all
   * @param {() => boolean} o.busy whether the worker runs a long call (ask afterwards)
   * @param {(state: {count: number, reason: string | null, pending: boolean}) => void} o.onState
   */
  constructor({ client, drawing, options, enabled, busy, onState }) {
    Object.assign(this, { client, drawing, options, enabled, busy, onState });
    /** The drawing the shown ghosts belong to. */
    this.shownFor = null;
    /** The drawing whose ghosts were dismissed with Escape. */
    this.dismissedFor = null;
    this.running = null;
    this.again = false;
    this.reason = null;
    /** Strokes that came from accepted ghosts (they weigh little in the next fit). */
    this.accepted = new WeakSet();
  }

  /** Options for the drawing `strokes`, marking the accepted strokes. */
  request(strokes, extra) {
    const suggested = [];
    strokes.forEach((s, i) => this.accepted.has(s) && suggested.push(i));
    return { ...this.options(), region: this.region(), suggested, ...extra };
  }

  region() {
    return [0, 0, this.drawing.logical.w, this.drawing.logical.h];
  }

  /** Called on every change to the drawing (and when settings change). */
  update() {
    this.drawing.showGhosts([]);
    this.shownFor = null;
    // A reason given for the previous drawing no longer holds.
    this.reason = null;
    if (!this.enabled() || this.busy()) return this.state(null);
    if (this.running) {
      this.again = true;
      return this.state(null);
    }
    this.running = this.ask().finally(() => {
      this.running = null;
      if (this.again) {
        this.again = false;
        this.update();
      } else this.state(null); // settled: no longer pending
    });
    this.state(null);
  }

  async ask() {
    const strokes = this.drawing.strokes;
    try {
      const r = await this.client.suggestStrokes(strokes, this.request(strokes));
      // A stale answer (the drawing changed meanwhile) is dropped; `update` asks again.
      if (strokes !== this.drawing.strokes || this.again) return;
      if (strokes === this.dismissedFor) return this.state(DISMISSED);
      this.shownFor = strokes;
      this.drawing.showGhosts(r.strokes, r.confidence);
      this.state(r.reason ?? null);
    } catch (e) {
      if (e.name !== 'AbortError') this.state(e.message);
    }
  }

  state(reason) {
    if (reason !== null) this.reason = reason;
    this.onState?.({ count: this.ghosts().length, reason: this.ghosts().length ? null : this.reason, pending: !!this.running });
  }

  /** The ghosts shown for the drawing as it is now. */
  ghosts() {
    return this.shownFor === this.drawing.strokes ? this.drawing.ghosts : [];
  }

  /** Adds the shown ghosts to the drawing as one undo step; false when there are none. */
  async accept() {
    // A request under way for this very drawing: its answer is what the person expects.
    if (!this.ghosts().length && this.running) await this.running;
    const ghosts = this.ghosts();
    if (!ghosts.length) return false;
    for (const g of ghosts) this.accepted.add(g);
    this.drawing.set([...this.drawing.strokes, ...ghosts]);
    return true;
  }

  /** Hides the ghosts until the drawing changes. */
  dismiss() {
    if (!this.ghosts().length) return false;
    this.dismissedFor = this.drawing.strokes;
    this.drawing.showGhosts([]);
    this.shownFor = null;
    this.state(DISMISSED);
    return true;
  }

  /** Every copy of the repetition on the canvas, added as one undo step. */
  async fill() {
    const strokes = this.drawing.strokes;
    const r = await this.client.suggestStrokes(strokes, this.request(strokes, { fill: true }));
    if (strokes !== this.drawing.strokes) return { added: 0, reason: 'The drawing changed; try again.' };
    for (const g of r.strokes) this.accepted.add(g);
    if (r.strokes.length) this.drawing.set([...strokes, ...r.strokes]);
    return { added: r.strokes.length, reason: r.reason ?? null };
  }
}
