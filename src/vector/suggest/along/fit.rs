//! Where the next copies go along the path, and how sure that is: the places of the
//! hand-drawn copies fitted by lines of one slope in the run's order, one line for each
//! kind (copies on alternate sides of a stem may sit apart along it); the scatter about
//! them, and of the copies' poses in the path's frame, with a prior of the hand's
//! scatter, says how far the hand's next copy may be from each ghost (as for lattices,
//! `certainty::reach`).

use super::run::Run;
use crate::vector::suggest::certainty::reach;

/// Each gap along the path between copies of one kind is within this factor of the
/// median either way.
const GAP_SPREAD: f64 = 1.6;
/// The hand's prior scatter of a copy's place, as a share of the gap, counted as
/// `PRIOR_COPIES` copies.
const PRIOR_SCATTER: f64 = 0.05;
const PRIOR_COPIES: f64 = 3.0;

pub(super) struct Fit {
    /// For each kind: its mean position in the run, mean place and count.
    means: Vec<(f64, f64, f64)>,
    /// The sum of squares of the positions about their kinds' means.
    sxx: f64,
    /// The step along the path from one copy to the next (signed).
    pub step: f64,
    var_along: f64,
    var_pose: f64,
    /// How many standard deviations a ghost's reach is.
    pub reach: f64,
}

impl Fit {
    /// The fit of `places` (the run's, unwrapped) over the hand-drawn copies at
    /// positions `hands`; `None` where the gaps are too uneven to carry on.
    pub(super) fn new(run: &Run, places: &[f64], hands: &[usize]) -> Option<Fit> {
        // (Between copies of one kind: leaves on alternate sides of a stem need not sit
        // half way between those of the other side, and a hand's at 29 and 51 of a
        // period of 80 were taken for uneven.)
        let stride = run.stride;
        let mut gaps: Vec<f64> = places.windows(stride + 1).map(|w| (w[stride] - w[0]).abs()).collect();
        gaps.sort_by(f64::total_cmp);
        let median = *gaps.get(gaps.len() / 2)?;
        if median <= 0.0 || gaps.iter().any(|&g| g > GAP_SPREAD * median || g < median / GAP_SPREAD) {
            return None;
        }
        // (Hand-drawn copies only: an accepted one sits where the line put it.)
        let of_kind = |j: usize| hands.iter().copied().filter(move |&t| run.kind(t) == j);
        let means: Vec<(f64, f64, f64)> = (0..stride)
            .map(|j| {
                let n = of_kind(j).count() as f64;
                (of_kind(j).map(|t| t as f64).sum::<f64>() / n, of_kind(j).map(|t| places[t]).sum::<f64>() / n, n)
            })
            .collect();
        let centred = |t: usize| (t as f64 - means[run.kind(t)].0, places[t] - means[run.kind(t)].1);
        let sxx: f64 = hands.iter().map(|&t| centred(t).0.powi(2)).sum();
        let sxy: f64 = hands.iter().map(|&t| centred(t).0 * centred(t).1).sum();
        let step = sxy / sxx.max(1e-12);
        // The scatter about the lines: of the places along the path, and of the copies'
        // poses in its frame (each copy's mean square distance from the latest of its
        // kind, registered there).
        let (h, k) = (hands.len() as f64, stride as f64);
        let prior = (PRIOR_SCATTER * step).powi(2);
        let along_ss: f64 = hands.iter().map(|&t| (centred(t).1 - step * centred(t).0).powi(2)).sum();
        let pose_ss: f64 = hands.iter().map(|&t| run.copies[t].msd).sum();
        Some(Fit {
            var_along: (along_ss + PRIOR_COPIES * prior) / (h - k - 1.0 + PRIOR_COPIES),
            var_pose: (pose_ss + PRIOR_COPIES * prior) / (h - k + PRIOR_COPIES),
            // (As for lattices, the scatter's degrees of freedom with the prior's copies.)
            reach: reach(h - k - 1.0 + PRIOR_COPIES),
            means,
            sxx,
            step,
        })
    }

    /// The place (unwrapped arc length) of copy `t` of kind `kind`.
    pub(super) fn place(&self, t: usize, kind: usize) -> f64 {
        let (mt, mp, _) = self.means[kind];
        mp + self.step * (t as f64 - mt)
    }

    /// The variance of the hand's copy `t` of kind `kind` about its place.
    pub(super) fn spread(&self, t: usize, kind: usize) -> f64 {
        let (mt, _, n) = self.means[kind];
        self.var_along * (1.0 + 1.0 / n + (t as f64 - mt).powi(2) / self.sxx) + self.var_pose
    }
}
