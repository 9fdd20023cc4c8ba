//! A uniform grid over a rectangle: constant-time insertion and disc queries for
//! point elements. Cells are about the query radius, so a query visits 3x3 cells.

use kurbo::{Point, Rect};

pub struct Grid {
    origin: Point,
    cell: f64,
    cols: usize,
    rows: usize,
    cells: Vec<Vec<u32>>,
}

impl Grid {
    /// A grid over `area` with square cells of side at least `cell`, enlarged if needed
    /// so that there are at most `max_cells` of them.
    pub fn new(area: Rect, cell: f64, max_cells: usize) -> Grid {
        let mut cell = cell.max(1e-9);
        let w = area.width().max(cell);
        let h = area.height().max(cell);
        let cells_for = |c: f64| ((w / c).ceil() + 1.0) * ((h / c).ceil() + 1.0);
        while cells_for(cell) > max_cells.max(1) as f64 {
            cell *= 1.5;
        }
        let cols = (w / cell).ceil() as usize + 1;
        let rows = (h / cell).ceil() as usize + 1;
        Grid { origin: area.origin(), cell, cols, rows, cells: vec![Vec::new(); cols * rows] }
    }

    /// The cell holding `p`. Truncation, not `floor` (a libm call on x86-64): negative
    /// coordinates only occur outside the area, where every caller clamps to cell 0.
    #[inline]
    fn cell_of(&self, p: Point) -> (isize, isize) {
        (((p.x - self.origin.x) / self.cell) as isize, ((p.y - self.origin.y) / self.cell) as isize)
    }

    /// Adds `id` at `p`; points outside the area go to the border cells, so they are
    /// still found (queries near the border look there too).
    pub fn insert(&mut self, id: u32, p: Point) {
        let (cx, cy) = self.cell_of(p);
        let cx = cx.clamp(0, self.cols as isize - 1) as usize;
        let cy = cy.clamp(0, self.rows as isize - 1) as usize;
        self.cells[cy * self.cols + cx].push(id);
    }

    /// Calls `f` with every id whose cell touches the disc of `radius` around `p`.
    /// The caller checks the exact distance (it holds the positions).
    pub fn for_each_near(&self, p: Point, radius: f64, mut f: impl FnMut(u32)) {
        let (x0, y0) = self.cell_of(Point::new(p.x - radius, p.y - radius));
        let (x1, y1) = self.cell_of(Point::new(p.x + radius, p.y + radius));
        let clamp_x = |v: isize| v.clamp(0, self.cols as isize - 1) as usize;
        let clamp_y = |v: isize| v.clamp(0, self.rows as isize - 1) as usize;
        if x1 < 0 || y1 < 0 || x0 >= self.cols as isize || y0 >= self.rows as isize {
            return;
        }
        for cy in clamp_y(y0)..=clamp_y(y1) {
            let row = &self.cells[cy * self.cols..(cy + 1) * self.cols];
            for cell in &row[clamp_x(x0)..=clamp_x(x1)] {
                for &id in cell {
                    f(id);
                }
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn finds_exactly_what_is_near() {
        let pts: Vec<Point> = (0..400).map(|i| Point::new((i % 20) as f64 * 5.0, (i / 20) as f64 * 5.0)).collect();
        let mut g = Grid::new(Rect::new(0.0, 0.0, 100.0, 100.0), 6.0, 10_000);
        for (i, p) in pts.iter().enumerate() {
            g.insert(i as u32, *p);
        }
        let q = Point::new(47.0, 52.0);
        let mut found = Vec::new();
        g.for_each_near(q, 6.0, |id| {
            if pts[id as usize].distance(q) < 6.0 {
                found.push(id)
            }
        });
        found.sort();
        let mut want: Vec<u32> = (0..400u32).filter(|&i| pts[i as usize].distance(q) < 6.0).collect();
        want.sort();
        assert_eq!(found, want);
        assert_eq!(found.len(), 4);
    }

    #[test]
    fn caps_cell_count() {
        let g = Grid::new(Rect::new(0.0, 0.0, 1e6, 1e6), 1.0, 1000);
        assert!(g.cols * g.rows <= 1000);
    }
}
