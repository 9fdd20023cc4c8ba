// A server component: patternsynth/vector runs on the server (here when `next build`
// prerenders the page) and the page shows a number it computed. The client component
// below runs the browser checks.
import { synthesizeStrokes, version } from 'patternsynth/vector';
import Checks from './checks.js';

const row = [0, 1, 2].map((i) => ({ points: [[20 + i * 30, 20], [35 + i * 30, 35]], width: 2, stroke: '#224466' }));

export default function Page() {
  const out = synthesizeStrokes(row, { width: 200, height: 200, seed: 1 });
  return (
    <main>
      <p>patternsynth <span id="version">{version()}</span> made <span id="server-strokes">{out.strokes.length}</span> strokes on the server.</p>
      <Checks />
    </main>
  );
}
