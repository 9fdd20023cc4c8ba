// Runs on the server at request time (`node build`): patternsynth/vector's Node entry.
import { synthesizeStrokes, version } from 'patternsynth/vector';

const row = [0, 1, 2].map((i) => ({ points: [[20 + i * 30, 20], [35 + i * 30, 35]], width: 2, stroke: '#224466' }));

export function load() {
  const out = synthesizeStrokes(row, { width: 200, height: 200, seed: 1 });
  return { version: version(), strokes: out.strokes.length };
}
