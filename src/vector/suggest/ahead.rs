//! The cells to propose: those begun, then the next along the rhythm (or all the
//! region's, for `fill`).

use super::fit::Fit;
use super::SuggestOptions;
use crate::vector::element::Element;
use kurbo::Rect;

impl Fit {
    fn at(&self, i: usize) -> (i64, i64) {
        self.cell[i].1
    }

    /// The (motif position, cell, periods from the nearest drawn copy) to propose.
    pub(super) fn wanted(
        &self,
        elems: &[Element],
        region: Option<Rect>,
        opts: &SuggestOptions,
        max_cells: usize,
    ) -> Vec<(usize, (i64, i64), usize)> {
        // A copy is proposed when its site is on the region (the canvas): the hand draws
        // copies up to the edge, and one whose site is off it belongs to no canvas.
        let inside = |m: usize, c: (i64, i64)| region.is_none_or(|r| r.contains(self.site(m, c)));
        let mut drawn = self.cell.clone();
        drawn.sort_unstable();
        let mut occupied: Vec<(i64, i64)> = self.cell.iter().map(|c| c.1).collect();
        occupied.sort_unstable();
        occupied.dedup();
        let neighbours: Vec<(i64, i64)> =
            if self.b.is_some() { vec![(1, 0), (-1, 0), (0, 1), (0, -1)] } else { vec![(1, 0), (-1, 0)] };
        let any_inside = |c: (i64, i64)| (0..self.motif.len()).any(|m| inside(m, c));
        let latest = self.at(elems.len() - 1);
        // The rhythm: from the cell drawn before the latest one to the latest.
        let previous = (0..elems.len()).rev().map(|i| self.at(i)).find(|&c| c != latest);
        let rhythm = previous.map_or((1, 0), |p| (latest.0 - p.0, latest.1 - p.1));

        let occupied_cells = occupied.len();
        let mut cells: Vec<((i64, i64), usize)> = occupied.iter().map(|&c| (c, 0)).collect();
        let mut taken = Cells(occupied);
        if opts.fill {
            // Every cell reachable from the drawn ones through cells in the region, in
            // breadth-first order (`cells` is the queue).
            let mut head = 0;
            while let Some(&(c, d)) = cells.get(head) {
                head += 1;
                for &(du, dw) in &neighbours {
                    let n = (c.0 + du, c.1 + dw);
                    if taken.len() < max_cells && !taken.contains(n) && any_inside(n) {
                        taken.insert(n);
                        cells.push((n, d + 1));
                    }
                }
            }
        } else {
            // The next cells along the rhythm, else the free neighbour nearest the latest:
            // within the columns drawn so far (a hand fills a grid row by row, each row as
            // wide as the first), and where two are as near, the way the hand went along
            // its rows (a second row begun under the first: its ghosts went left, off the
            // grid, as often as right).
            // (Only where the hand went along the lattice's rows of cells, one after the
            // next: on a basis that crosses the rows it drew, a row of cells is a diagonal.
            // Along them as the sites lie: a brick lattice's rows begin half a period
            // apart.)
            let moves: Vec<(i64, i64)> = (1..elems.len())
                .map(|i| (self.at(i - 1), self.at(i)))
                .filter(|(p, c)| p != c)
                .map(|(p, c)| (c.0 - p.0, c.1 - p.1))
                .collect();
            let along: Vec<i64> = moves.iter().filter(|m| m.1 == 0).map(|m| m.0.signum()).collect();
            let rowwise = self.b.is_some() && !along.is_empty() && 2 * along.len() >= moves.len();
            let way = if rowwise { along.iter().sum::<i64>().signum() } else { 0 };
            let a = self.a / self.a.hypot2();
            let along_rows = |c: (i64, i64)| self.lattice().step(c.0, c.1).dot(a);
            let (lo, hi) = taken.0.iter().fold((f64::MAX, f64::MIN), |(lo, hi), &c| {
                let x = along_rows(c);
                (lo.min(x), hi.max(x))
            });
            // (Once a second row is begun: the first row's span is known only when it ends.
            // Half a period either side: a brick lattice's next row may begin half out.)
            let rows = {
                let mut w: Vec<i64> = taken.0.iter().map(|c| c.1).collect();
                w.sort_unstable();
                w.dedup();
                w.len()
            };
            let outside =
                |c: (i64, i64)| rowwise && rows > 1 && (along_rows(c) < lo - 0.75 || along_rows(c) > hi + 0.75);
            let mut last = latest;
            for _ in 0..opts.count {
                let along = (last.0 + rhythm.0, last.1 + rhythm.1);
                let next = if !taken.contains(along)
                    && any_inside(along)
                    && taken.adjacent(along, &neighbours)
                    && !outside(along)
                {
                    Some(along)
                } else {
                    // (Measured from the latest by the cells' difference, so that two cells
                    // either side of it are exactly as near; from the copy proposed last
                    // instead, nine lattice families took 2-6 more copies by hand.)
                    let from = |c: (i64, i64)| self.lattice().step(c.0 - latest.0, c.1 - latest.1).hypot2();
                    taken
                        .0
                        .iter()
                        .flat_map(|&c| neighbours.iter().map(move |&(du, dw)| (c.0 + du, c.1 + dw)))
                        .filter(|&c| !taken.contains(c) && any_inside(c))
                        // The latest copy's line of cells first: a row is finished before the next.
                        .min_by(|p, q| {
                            let against = |c: &(i64, i64)| (c.0 - latest.0).signum() * way < 0;
                            outside(*p)
                                .cmp(&outside(*q))
                                .then((p.1 != latest.1).cmp(&(q.1 != latest.1)))
                                .then(from(*p).total_cmp(&from(*q)))
                                .then(against(p).cmp(&against(q)))
                                .then(p.cmp(q))
                        })
                };
                let Some(next) = next else { break };
                let steps = neighbours
                    .iter()
                    .filter_map(|&(du, dw)| cells.iter().find(|(c, _)| *c == (next.0 - du, next.1 - dw)).map(|x| x.1))
                    .min()
                    .unwrap_or(0)
                    + 1;
                taken.insert(next);
                cells.push((next, steps));
                last = next;
            }
        }
        // A motif position missing from most drawn cells is not a part the copies leave
        // out by mistake (a stroke the fit reads as its own position, two pairs drawn a
        // little apart): old cells are completed only with positions most of them hold.
        let mut held = vec![0usize; self.motif.len()];
        let mut seen = drawn.clone();
        seen.dedup();
        for &(m, _) in &seen {
            held[m] += 1;
        }
        let mut out = Vec::new();
        for (c, steps) in cells {
            // Motif positions drawn once are not yet part of the repetition.
            for (m, (motif, &held)) in self.motif.iter().zip(&held).enumerate() {
                let usual = steps > 0 || c == latest || 2 * held >= occupied_cells;
                if usual && motif.members.len() >= 2 && drawn.binary_search(&(m, c)).is_err() && inside(m, c) {
                    out.push((m, c, steps));
                }
            }
        }
        out
    }
}

/// A set of lattice cells, kept sorted.
struct Cells(Vec<(i64, i64)>);

impl Cells {
    fn len(&self) -> usize {
        self.0.len()
    }

    fn contains(&self, c: (i64, i64)) -> bool {
        self.0.binary_search(&c).is_ok()
    }

    fn insert(&mut self, c: (i64, i64)) {
        if let Err(at) = self.0.binary_search(&c) {
            self.0.insert(at, c);
        }
    }

    /// Whether a neighbour of `c` is in the set.
    fn adjacent(&self, c: (i64, i64), neighbours: &[(i64, i64)]) -> bool {
        neighbours.iter().any(|&(du, dw)| self.contains((c.0 - du, c.1 - dw)))
    }
}
