// A route handler: patternsynth/vector on the server, at request time, answering JSON.
import { synthesizeStrokes, version } from 'patternsynth/vector';

const row = [0, 1, 2].map((i) => ({ points: [[20 + i * 30, 20], [35 + i * 30, 35]], width: 2, stroke: '#224466' }));

export function GET() {
  const out = synthesizeStrokes(row, { width: 200, height: 200, seed: 1 });
  return Response.json({ version: version(), strokes: out.strokes.length, svg: out.svg.startsWith('<svg') });
}
