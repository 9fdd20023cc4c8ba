// The Repeat panel: the layout and spacing of the copies, set by hand when the ones
// the drawing shows are wrong or missing (one motif drawn once is enough). A layout is
// two period vectors, a = (across, 0) and b = (shift, down), with the shift and down
// that the layout implies; the canvas shows them as arrows to drag.

/** The period vectors of a layout, or null for the drawing's own. */
export function layoutPeriods({ type, across, down, shift }) {
  const s = Number(across) || 0;
  switch (type) {
    case 'square': return [[s, 0], [0, s]];
    case 'rectangle': return [[s, 0], [0, Number(down) || 0]];
    case 'hexagonal': return [[s, 0], [s / 2, (s * Math.sqrt(3)) / 2]];
    case 'brick': return [[s, 0], [s / 2, Number(down) || 0]];
    case 'oblique': return [[s, 0], [Number(shift) || 0, Number(down) || 0]];
    default: return null;
  }
}

/** Which inputs a layout reads. */
const READS = {
  auto: [], square: ['across'], rectangle: ['across', 'down'], hexagonal: ['across'],
  brick: ['across', 'down'], oblique: ['across', 'down', 'shift'],
};

/** Mounts the panel: `$` finds the page's elements, `settings` (saved by `save`) keeps
 *  `repeat` ({ type, across, down, shift }), `drawing` shows the lattice. */
export function repeatPanel({ $, settings, save, drawing }) {
  const repeat = (settings.repeat = { type: 'auto', across: 60, down: 60, shift: 0, ...settings.repeat });
  const type = $('repeat-type');
  const inputs = { across: $('period-across'), down: $('period-down'), shift: $('period-shift') };
  /** The periods the last synthesis repeated on: the start of a layout set by hand. */
  let found = null;

  const show = () => {
    type.value = repeat.type;
    for (const [k, input] of Object.entries(inputs)) {
      input.value = Math.round(repeat[k] * 10) / 10;
      input.closest('label').hidden = !READS[repeat.type].includes(k);
    }
    const periods = layoutPeriods(repeat);
    drawing.showLattice(periods && { a: periods[0], b: periods[1] });
  };
  const changed = () => {
    save(settings);
    show();
  };

  type.addEventListener('change', () => {
    const was = repeat.type;
    repeat.type = type.value;
    // Leaving "as the drawing shows it": start from the periods it showed (in the frame
    // of the first period), so the designer adjusts rather than starts over.
    if (was === 'auto' && found) {
      const [[ax, ay], [bx, by]] = found;
      const len = Math.hypot(ax, ay);
      if (len > 0) Object.assign(repeat, { across: len, down: Math.abs(ax * by - ay * bx) / len, shift: (ax * bx + ay * by) / len });
    }
    changed();
  });
  for (const [k, input] of Object.entries(inputs)) {
    input.addEventListener('input', () => {
      const v = Number(input.value);
      if (!Number.isFinite(v) || (k !== 'shift' && v < 4)) return;
      repeat[k] = v;
      changed();
    });
  }
  // A handle dragged on the canvas: `a` sets the spacing across; `b` what the layout
  // lets the second period set (its height, or with a free shift, both).
  drawing.onLattice = (which, [x, y]) => {
    if (which === 'a') repeat.across = Math.max(4, x);
    else if (repeat.type === 'square') repeat.across = Math.max(4, Math.abs(y));
    else if (repeat.type === 'hexagonal') repeat.across = Math.max(4, Math.abs(y) / (Math.sqrt(3) / 2));
    else {
      repeat.down = Math.max(4, Math.abs(y));
      if (repeat.type === 'oblique') repeat.shift = x;
    }
    changed();
  };
  show();

  return {
    /** The periods to synthesize on (engine options), or undefined for the drawing's own. */
    periods: () => layoutPeriods(repeat) ?? undefined,
    /** Remembers the periods a synthesis found (a layout set by hand starts from them). */
    found: (periods) => { if (periods) found = periods; },
  };
}
