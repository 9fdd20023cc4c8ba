//! Hole filling, growth's second phase: irregular input grown by the paper's rule
//! (`regularize: false`) leaves parts of the area empty, where no candidate is well
//! supported. Around each hole (a coverage cell, about half a window across, holding
//! under 0.9 of the example's density) the candidate that adds the most is stamped, and
//! only into such cells, never among regular elements, so the output is still covered
//! with the example's local arrangement.

use super::{Candidate, GrowOptions, GrowStats, Target, ERROR_QUANTUM};
use crate::error::Result;
use kurbo::Point;
use std::cmp::Reverse;

impl Target<'_, '_> {
    /// Fills the holes left by growth from every element placed so far.
    pub(super) fn fill_holes(&mut self, opts: &GrowOptions, stats: &mut GrowStats) -> Result<()> {
        self.fill_holes = true;
        let all: Vec<u32> = (0..self.placed.len() as u32).collect();
        let mut queue = self.queue(&all);
        let mut candidates: Vec<Candidate> = Vec::new();
        while let Some(Reverse((_, gi))) = queue.pop() {
            let g = self.placed[gi as usize];
            if !self.near_hole(g.pos) {
                continue;
            }
            stats.growing_points += 1;
            candidates.clear();
            for r in self.candidates(gi) {
                stats.candidates += 1;
                if let Some(c) = self.evaluate(g.pos, r, 0, 0) {
                    if c.adds > 0 {
                        candidates.push(c);
                    }
                }
            }
            // The most added wins, then the least error (errors this close are ties).
            let tiny = ((ERROR_QUANTUM * self.reference.pair_radius[g.class as usize]).powi(2)).max(1e-300);
            let best = candidates.iter().min_by(|a, b| {
                let (ea, eb) = ((a.error / tiny).floor(), (b.error / tiny).floor());
                b.adds.cmp(&a.adds).then(ea.total_cmp(&eb))
            });
            let Some(best) = best.copied() else {
                stats.passed_over += 1;
                continue;
            };
            self.stamp_and_queue(&best, &mut queue, opts.max_elements)?;
        }
        Ok(())
    }

    pub(super) fn cover_cell(&self, p: Point) -> Option<usize> {
        let (cols, rows, sx, sy) = self.cover_dims;
        let cx = ((p.x - self.area.x0) / sx).floor().min(cols as f64 - 1.0);
        let cy = ((p.y - self.area.y0) / sy).floor().min(rows as f64 - 1.0);
        (cx >= 0.0 && cy >= 0.0 && (cx as usize) < cols && (cy as usize) < rows)
            .then(|| cy as usize * cols + cx as usize)
    }

    /// Coverage cells (a window across) that hold no element.
    pub(super) fn holes(&self) -> usize {
        self.cover.iter().filter(|&&c| c == 0).count()
    }

    /// Whether an empty coverage cell touches the window around `p`.
    fn near_hole(&self, p: Point) -> bool {
        let r = self.reference.window_radius;
        let (cols, rows, sx, sy) = self.cover_dims;
        let x0 = ((p.x - r - self.area.x0) / sx).floor().max(0.0) as usize;
        let y0 = ((p.y - r - self.area.y0) / sy).floor().max(0.0) as usize;
        let x1 = (((p.x + r - self.area.x0) / sx).floor().max(0.0) as usize).min(cols - 1);
        let y1 = (((p.y + r - self.area.y0) / sy).floor().max(0.0) as usize).min(rows - 1);
        (y0..=y1).any(|y| (x0..=x1).any(|x| self.cover[y * cols + x] < self.hole_below))
    }
}
