// Line art on a clear ground, as a person exports it from a drawing program: `count`
// rings of dark ink 2 px wide, antialiased, on a transparent white ground, `side` on a
// side, placed by a seeded generator. Shared by the Node and browser transparency tests.
export function lineArt(side, count, seed) {
  let s = seed;
  const rand = () => ((s = (s * 1103515245 + 12345) % 2147483648) / 2147483648);
  const rings = Array.from({ length: count }, () => [rand() * side, rand() * side, 5 + 5 * rand()]);
  const data = new Uint8Array(side * side * 4);
  for (let i = 0; i < side * side; i++) {
    const [x, y] = [(i % side) + 0.5, Math.floor(i / side) + 0.5];
    const ink = Math.max(0, ...rings.map(([cx, cy, r]) => Math.min(1, 1.5 - Math.abs(Math.hypot(x - cx, y - cy) - r))));
    data.set(ink > 0 ? [20, 30, 90, Math.round(ink * 255)] : [255, 255, 255, 0], i * 4);
  }
  return { width: side, height: side, data };
}
