//! Free growth for examples with neither a period nor a lattice (SPEC 1.5: irregular
//! input degrades gracefully), as texture quilting grows an image from patches.
//!
//! The output is divided into cells about half the example across, and each cell takes
//! the elements of an example window of its size. Windows wrap round the example (taken
//! as a torus `GAP` spacings wider than its elements' box), so every element is in as
//! many windows as any other: windows kept inside the box would hold its middle more
//! often than its edges, and the output's mix of elements would drift from the
//! example's. Of a few random windows (and the one that continues a neighbouring cell's
//! window), the cell
//! takes the one whose surroundings agree best with what its neighbours already hold:
//! placed elements near the cell are looked up in the example around the window, +1
//! when the example has an element of their class there, -1 when not. An element is
//! dropped where it would come nearer to a placed one than the example ever brings
//! those two classes (`Apart`), so seams do not pile up.
//!
//! Every local arrangement in the output is then one of the example's, the density is
//! the example's (less what seams drop), and the cost is linear in the output: a cell
//! looks at a fixed number of windows, each judged on the elements along its border.

use super::element::Placed;
use super::reference::Reference;
use super::spatial::Grid;
use crate::error::{Error, Result};
use crate::progress::Throttle;
use crate::rng::Rng;
use kurbo::{Point, Rect, Vec2};

/// The gap the torus leaves between the example's far edge and its near one, in
/// spacings. A grid's next column would stand a whole spacing on, but a scatter's
/// extreme elements sit nearer its edges, and a whole gap thins its output (36 icons
/// in a 260 box: 13% fewer); much less, and elements that meet across the seam, which
/// the example never brings together, are dropped (classes lying apart lose share).
const GAP: f64 = 0.75;

/// Random windows tried per cell.
const TRIES: usize = 12;

/// Width of the band around a cell, in spacings, whose placed elements judge a window.
const BAND: f64 = 1.5;

/// Tolerance, in spacings, within which a placed element counts as found in the example.
const MATCH: f64 = 0.3;

/// A window holding fewer than this fraction of the elements a window of the example's
/// density holds is mostly outside the drawing (a sketch need not fill its box).
const SPARSE: f64 = 0.7;

/// Whether the example spans enough in both directions to cut windows from.
pub(super) fn applies(reference: &Reference) -> bool {
    let b = reference.bounds;
    b.width().min(b.height()) >= 2.0 * reference.spacing
}

/// Fills `area` with windows of `reference` (see the module comment). `extents`: half the
/// size of each element's drawing; every element whose drawing reaches into the area is
/// placed, so the output is covered to its edges.
pub(super) fn mosaic(
    reference: &Reference,
    extents: &[Vec2],
    area: Rect,
    seed: u64,
    max_elements: usize,
    progress: &mut Throttle,
) -> Result<Vec<Placed>> {
    let elems = reference.elems;
    let spacing = reference.spacing;
    // A hair wider than the positions, so windows include the elements on the box's edge.
    let example = reference.bounds.inflate(1e-9 * spacing, 1e-9 * spacing);
    let side = |len: f64| (0.5 * len).max((4.0 * spacing).min(len));
    let cell = Vec2::new(side(example.width()), side(example.height()));
    let half = |i: usize| extents.get(i).copied().unwrap_or(Vec2::ZERO);
    let reach = (0..elems.len()).map(half).fold(Vec2::ZERO, |m, h| Vec2::new(m.x.max(h.x), m.y.max(h.y)));
    let wide = area.inset((reach.x, reach.y));
    let (cols, rows) = ((wide.width() / cell.x).ceil().max(1.0), (wide.height() / cell.y).ceil().max(1.0));
    let density = reference.density();
    let estimate = density * wide.area();
    if estimate > max_elements as f64 || cols * rows > 4.0 * max_elements as f64 {
        return Err(Error::TooLarge(format!(
            "This output would hold about {estimate:.0} elements; the limit is {max_elements}. Use a smaller output or larger strokes."
        )));
    }
    let (cols, rows) = (cols as usize, rows as usize);
    let apart = &reference.apart;
    let mut placed: Vec<Placed> = Vec::with_capacity(estimate as usize + 16);
    let mut grid = Grid::new(wide, apart.max.max(BAND * spacing).max(1e-9), (estimate as usize).saturating_mul(2) + 64);
    let expected = density * cell.x * cell.y;
    let mut rng = Rng::new(seed);
    // The window origin each cell took, for continuations.
    let mut taken: Vec<Point> = Vec::with_capacity(cols * rows);
    let torus = Torus {
        origin: example.origin(),
        size: Vec2::new(example.width(), example.height()) + Vec2::splat(GAP * spacing),
    };
    let mut inside = Vec::new();
    for row in 0..rows {
        progress.tick(row as f64 / rows as f64)?;
        for col in 0..cols {
            let origin = Point::new(wide.x0 + col as f64 * cell.x, wide.y0 + row as f64 * cell.y);
            let here = Rect::from_origin_size(origin, (cell.x, cell.y));
            let mut tries: Vec<Point> = Vec::with_capacity(TRIES + 2);
            if col > 0 {
                tries.push(torus.wrap(taken[row * cols + col - 1] + Vec2::new(cell.x, 0.0)));
            }
            if row > 0 {
                tries.push(torus.wrap(taken[(row - 1) * cols + col] + Vec2::new(0.0, cell.y)));
            }
            tries.extend(
                (0..TRIES)
                    .map(|_| torus.origin + Vec2::new(rng.next_f64() * torus.size.x, rng.next_f64() * torus.size.y)),
            );
            let best = tries
                .iter()
                .map(|&w| {
                    let count = window(reference, &torus, w, cell, false, &mut inside);
                    let shortfall = (SPARSE * expected - count as f64).max(0.0);
                    (w, seam_agreement(reference, &torus, &placed, &grid, here, w) as f64 - 2.0 * shortfall)
                })
                .fold((tries[0], f64::NEG_INFINITY), |best, t| if t.1 > best.1 { t } else { best })
                .0;
            taken.push(best);
            let shift = origin - best;
            window(reference, &torus, best, cell, true, &mut inside);
            for &(i, at) in &inside {
                let e = &elems[i as usize];
                let pos = at + shift;
                let h = half(i as usize);
                let reaches = pos.x + h.x >= area.x0
                    && pos.x - h.x <= area.x1
                    && pos.y + h.y >= area.y0
                    && pos.y - h.y <= area.y1;
                if !reaches {
                    continue;
                }
                let mut near = false;
                grid.for_each_near(pos, apart.max, |id| {
                    let q = &placed[id as usize];
                    let d = apart.get(e.class, q.class);
                    near |= (q.pos - pos).hypot2() < d * d;
                });
                if !near {
                    grid.insert(placed.len() as u32, pos);
                    placed.push(Placed { pos, class: e.class, source: i });
                }
            }
        }
    }
    Ok(placed)
}

/// The example taken as a torus: `origin` and the `size` it repeats by.
struct Torus {
    origin: Point,
    size: Vec2,
}

impl Torus {
    /// `p` brought into the torus's one copy.
    fn wrap(&self, p: Point) -> Point {
        let d = p - self.origin;
        self.origin + Vec2::new(d.x.rem_euclid(self.size.x), d.y.rem_euclid(self.size.y))
    }
}

/// Fills `inside` with the example elements in the window of size `cell` at `w` on the
/// torus, each with its position as the window sees it, and counts them. `ordered`: in
/// the order they are to be placed (fixed, so drops at seams are reproducible).
fn window(
    reference: &Reference,
    torus: &Torus,
    w: Point,
    cell: Vec2,
    ordered: bool,
    inside: &mut Vec<(u32, Point)>,
) -> usize {
    let rect = Rect::from_origin_size(w, (cell.x, cell.y));
    inside.clear();
    // The window reaches past the torus's copy at most once each way (it is smaller).
    let end = torus.origin + torus.size;
    let xs: &[f64] = if rect.x1 > end.x { &[0.0, 1.0] } else { &[0.0] };
    let ys: &[f64] = if rect.y1 > end.y { &[0.0, 1.0] } else { &[0.0] };
    for &ty in ys {
        for &tx in xs {
            let shift = Vec2::new(tx * torus.size.x, ty * torus.size.y);
            let r = rect - shift;
            reference.grid.for_each_near(r.center(), 0.5 * cell.x.max(cell.y) * std::f64::consts::SQRT_2, |j| {
                let p = reference.elems[j as usize].pos;
                if p.x >= r.x0 && p.x < r.x1 && p.y >= r.y0 && p.y < r.y1 {
                    inside.push((j, p + shift));
                }
            });
        }
    }
    // Where the window wraps, elements of the example's far edge meet those of its near
    // edge, and of two too close the one placed first stays: in an order fixed by the
    // element but blind to its side, neither edge loses more.
    if ordered && xs.len() + ys.len() > 2 {
        inside.sort_by_key(|&(j, _)| (j as u64).wrapping_mul(0x9E37_79B9_7F4A_7C15));
    }
    inside.len()
}

/// How well the example around window `w` agrees with what is already placed around the
/// output cell `here`: each placed element in the band around the cell whose position
/// maps into the example scores +1 when the example has an element of its class there.
fn seam_agreement(reference: &Reference, torus: &Torus, placed: &[Placed], grid: &Grid, here: Rect, w: Point) -> i64 {
    let band = BAND * reference.spacing;
    let tol = MATCH * reference.spacing;
    let shift = w - here.origin();
    let outer = here.inflate(band, band);
    let mut score = 0;
    let b = reference.bounds;
    grid.for_each_near(here.center(), 0.5 * outer.width().max(outer.height()) * std::f64::consts::SQRT_2, |id| {
        let q = &placed[id as usize];
        if !outer.contains(q.pos) {
            return;
        }
        let x = torus.wrap(q.pos + shift);
        if x.x < b.x0 || x.x > b.x1 || x.y < b.y0 || x.y > b.y1 {
            return;
        }
        let mut found = false;
        reference.grid.for_each_near(x, tol, |j| {
            let e = &reference.elems[j as usize];
            found |= e.class == q.class && (e.pos - x).hypot2() < tol * tol;
        });
        score += if found { 1 } else { -1 };
    });
    score
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::progress::Silent;
    use crate::vector::element::Element;

    fn scatter(n: usize, side: f64, gap: f64, seed: u64) -> Vec<Element> {
        let mut rng = Rng::new(seed);
        let mut out: Vec<Element> = Vec::new();
        for _ in 0..n * 200 {
            if out.len() == n {
                break;
            }
            let p = Point::new(rng.next_f64() * side, rng.next_f64() * side);
            if out.iter().all(|e| e.pos.distance(p) >= gap) {
                out.push(Element { pos: p, class: rng.below(3) as u32 });
            }
        }
        out
    }

    #[test]
    fn keeps_density_and_closest_approach() {
        let elems = scatter(300, 170.0, 7.0, 3);
        let reference = Reference::new(&elems).unwrap();
        let area = Rect::new(0.0, 0.0, 600.0, 500.0);
        let out = mosaic(&reference, &[], area, 1, 1_000_000, &mut Throttle::new(&mut Silent)).unwrap();
        let ratio = out.len() as f64 / area.area() / (elems.len() as f64 / (170.0 * 170.0));
        assert!((0.85..=1.1).contains(&ratio), "density ratio {ratio}");
        let closest = (0..out.len())
            .flat_map(|i| (i + 1..out.len()).map(move |j| (i, j)))
            .map(|(i, j)| out[i].pos.distance(out[j].pos))
            .fold(f64::INFINITY, f64::min);
        assert!(closest >= 0.9 * 7.0 - 1e-9, "closest {closest}");
        assert!(out.iter().all(|p| area.contains(p.pos)));
        // Every cell of four spacings holds something.
        let cell = 40.0;
        let (nx, ny) = ((600.0 / cell) as usize, (500.0 / cell) as usize);
        let mut hit = vec![false; nx * ny];
        for p in &out {
            let (x, y) = ((p.pos.x / cell) as usize, (p.pos.y / cell) as usize);
            if x < nx && y < ny {
                hit[y * nx + x] = true;
            }
        }
        assert!(hit.iter().all(|&h| h), "an empty cell");
    }

    #[test]
    fn keeps_the_mix_of_an_example_whose_classes_lie_apart() {
        // Class by third of the example, left to right: windows that favoured the
        // example's middle would fill the output with the middle class.
        let mut elems = scatter(120, 170.0, 12.0, 7);
        for e in &mut elems {
            e.class = ((e.pos.x / 170.0 * 3.0) as u32).min(2);
        }
        let share = |v: &[u32], n: usize| {
            let mut c = [0.0; 3];
            v.iter().for_each(|&k| c[k as usize] += 1.0 / n as f64);
            c
        };
        let classes: Vec<u32> = elems.iter().map(|e| e.class).collect();
        let want = share(&classes, elems.len());
        let reference = Reference::new(&elems).unwrap();
        let area = Rect::new(0.0, 0.0, 900.0, 900.0);
        for seed in 1..=3 {
            let out = mosaic(&reference, &[], area, seed, 1_000_000, &mut Throttle::new(&mut Silent)).unwrap();
            let got = share(&out.iter().map(|p| p.class).collect::<Vec<_>>(), out.len());
            for k in 0..3 {
                assert!((got[k] - want[k]).abs() < 0.05, "seed {seed}: mix {got:?}, example {want:?}");
            }
        }
    }

    #[test]
    fn is_reproducible_and_seeded() {
        let elems = scatter(200, 140.0, 7.0, 5);
        let reference = Reference::new(&elems).unwrap();
        let area = Rect::new(0.0, 0.0, 400.0, 400.0);
        let run = |seed| mosaic(&reference, &[], area, seed, 1_000_000, &mut Throttle::new(&mut Silent)).unwrap();
        assert_eq!(run(1), run(1));
        assert_ne!(run(1), run(2));
    }
}
