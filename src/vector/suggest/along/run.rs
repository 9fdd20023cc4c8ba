//! The run of copies along a path: back from the latest copy, each touching the path,
//! each a step on the same way along it, and each lying in the path's frame as the
//! latest copy of its kind does (its kind: every copy, or every other one on alternate
//! sides of a stem).

use super::path::Path;
use kurbo::Point;

/// A copy touches the path when it comes within this share of its size of it (plus
/// twice the stroke's width).
pub(super) const ATTACH: f64 = 0.3;
/// A copy lies in the path's frame as the latest of its kind does when, registered
/// there, its points are within this share of its size of that one's (rms).
const POSE: f64 = 0.2;
/// At most this many hand-drawn copies are read.
const MAX_COPIES: usize = 8;

/// A copy drawn along the path.
#[derive(Clone, Copy, Debug)]
pub(super) struct Copy {
    /// The stroke.
    pub index: usize,
    /// Its place (arc length).
    pub at: f64,
    /// Its mean square distance from the latest copy of its kind, registered at its place.
    pub msd: f64,
}

/// A copy the run may hold: its stroke, points, size and width, and where it comes
/// nearest the path (arc length, distance).
pub(super) struct Candidate<'a> {
    pub index: usize,
    pub points: &'a [Point],
    pub size: f64,
    pub width: f64,
    pub nearest: (f64, f64),
}

/// The copies in drawing order, the latest last.
pub(super) struct Run {
    pub copies: Vec<Copy>,
    pub stride: usize,
}

impl Run {
    /// The run ending at the last of `candidates` (in drawing order), each copy like the
    /// one `stride` before it; `hand` says which strokes the hand drew (at most
    /// `MAX_COPIES` of those are read).
    pub(super) fn read(
        path: &Path,
        candidates: &[Candidate],
        stride: usize,
        hand: &dyn Fn(usize) -> bool,
    ) -> Option<Run> {
        let mut run: Vec<Copy> = Vec::new();
        // (Each copy's points, beside the run: a copy is registered on the one of its
        // kind before it.)
        let mut outlines: Vec<&[Point]> = Vec::new();
        for c in candidates.iter().rev() {
            let (near, dist) = c.nearest;
            if dist > ATTACH * c.size + 2.0 * c.width {
                break;
            }
            // (Placed where, in the path's frame, it lies as the latest copy of its kind
            // does there: the point it comes nearest at is as loose as its outline, and
            // its centre's foot shifts with the path's curvature.)
            let kin = run.len() % stride;
            let (at, msd) = match run.get(kin).filter(|_| run.len() >= stride) {
                None => (near, 0.0),
                Some(latest) => path.register(c.points, outlines[kin], latest.at, near, c.size),
            };
            if msd > (POSE * c.size).powi(2) {
                break;
            }
            if let [.., a, b] = run[..] {
                // (Each gap one way, as the one after it.)
                if path.gap(at, b.at).signum() != path.gap(b.at, a.at).signum() {
                    break;
                }
            }
            run.push(Copy { index: c.index, at, msd });
            outlines.push(c.points);
            if run.iter().filter(|r| hand(r.index)).count() >= MAX_COPIES {
                break;
            }
        }
        run.reverse();
        (!run.is_empty()).then_some(Run { copies: run, stride })
    }

    /// The latest copy's position in the run.
    pub(super) fn end(&self) -> usize {
        self.copies.len() - 1
    }

    /// Which of the `stride` kinds copy `t` of the run (or past its end) is (0: the
    /// latest's).
    pub(super) fn kind(&self, t: usize) -> usize {
        let (end, stride) = (self.end(), self.stride);
        if t <= end {
            (end - t) % stride
        } else {
            (stride - (t - end) % stride) % stride
        }
    }

    /// The copies' places along the path, unwrapped round a closed one, in the run's order.
    pub(super) fn places(&self, path: &Path) -> Vec<f64> {
        let mut places = vec![self.copies[0].at];
        for w in self.copies.windows(2) {
            let last = places[places.len() - 1];
            places.push(last + path.gap(w[0].at, w[1].at));
        }
        places
    }
}
