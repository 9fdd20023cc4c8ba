//! Replays a drawing session through `suggest_strokes` (test support): a person draws
//! a known pattern stroke by stroke and, after each stroke or acceptance, accepts the
//! proposals that are among the strokes still to draw. Counts what was drawn by hand,
//! what was accepted and how many shown proposals were wrong.

use super::stroke::Stroke;
use super::suggest::{suggest_strokes, SuggestOptions};
use kurbo::Rect;
use std::time::Instant;

/// What a replay counted.
#[derive(Clone, Debug, Default)]
pub struct Replay {
    /// Strokes of the finished drawing.
    pub strokes: usize,
    pub by_hand: usize,
    pub accepted: usize,
    /// Proposals shown over the session (a proposal shown again counts again).
    pub shown: usize,
    /// Shown proposals that are not among the strokes still to draw (nor beyond them).
    pub wrong: usize,
    /// Shown proposals where the hand would go on past the drawing's end.
    pub beyond: usize,
    /// How many strokes were on the page when each wrong proposal was shown.
    pub wrong_at: Vec<usize>,
    /// Of the wrong ones, those on a stroke of their class already drawn (or accepted):
    /// a copy proposed again beside itself.
    pub stacked: usize,
    /// Strokes drawn by hand before the first acceptance.
    pub before_first: usize,
    /// Slowest and median call, in milliseconds (native).
    pub slowest_ms: f64,
    pub median_ms: f64,
    /// The finished drawing (hand-drawn and accepted strokes, in order) and its classes.
    pub drawing: Vec<Stroke>,
    pub drawing_classes: Vec<u32>,
    /// What autocomplete says of the finished drawing (why it proposes nothing more).
    pub end_reason: Option<String>,
}

impl Replay {
    /// Share of the strokes after the first `skip` that came from accepted proposals.
    pub fn accepted_after(&self, skip: usize) -> f64 {
        self.accepted as f64 / (self.strokes.saturating_sub(skip)).max(1) as f64
    }

    pub fn wrong_share(&self) -> f64 {
        self.wrong as f64 / self.shown.max(1) as f64
    }
}

/// Replays drawing `truth` (strokes in drawing order with their classes) on the canvas
/// `region`; a proposal matches a stroke to draw of its class whose reference point is
/// within `tol`.
pub fn replay(truth: &[Stroke], classes: &[u32], region: Rect, tol: f64) -> Replay {
    replay_each(truth, classes, region, &vec![tol; truth.len()], &[])
}

/// `replay` with a tolerance for each stroke (a spiral's copies, and their spacing,
/// grow along it), and the strokes `beyond` the drawing's end, each with its tolerance:
/// the copies the hand would draw next were it to go on (a proposal there is neither
/// accepted nor wrong).
pub fn replay_each(truth: &[Stroke], classes: &[u32], region: Rect, tol: &[f64], beyond: &[(Stroke, f64)]) -> Replay {
    let mut opts =
        SuggestOptions { region: Some([region.x0, region.y0, region.width(), region.height()]), ..Default::default() };
    let mut done = vec![false; truth.len()];
    let mut drawn: Vec<Stroke> = Vec::new();
    let mut drawn_class: Vec<u32> = Vec::new();
    let mut r = Replay { strokes: truth.len(), ..Replay::default() };
    let mut times = Vec::new();
    let debug = std::env::var("REPLAY_DEBUG").is_ok();
    while let Some(first) = done.iter().position(|d| !d) {
        let t = Instant::now();
        let s = suggest_strokes(&drawn, &opts).expect("suggestions on a drawing");
        times.push(t.elapsed().as_secs_f64() * 1e3);
        r.shown += s.strokes.len();
        if debug {
            eprintln!(
                "drawn {} periods {:?} reason {:?} cells {:?}",
                drawn.len(),
                s.periods,
                s.reason,
                s.cells.iter().zip(&s.strokes).map(|(c, st)| (c, st.reference_point())).collect::<Vec<_>>()
            );
            eprintln!(
                "  truth next {:?}",
                (first..truth.len().min(first + 3)).map(|g| truth[g].reference_point()).collect::<Vec<_>>()
            );
        }
        let mut matched = Vec::new();
        for (k, stroke) in s.strokes.iter().enumerate() {
            let class = drawn_class[s.sources[k] as usize];
            let p = stroke.reference_point();
            let hit = (0..truth.len())
                .filter(|&g| !done[g] && classes[g] == class && !matched.iter().any(|&(h, _)| h == g))
                .map(|g| (g, truth[g].reference_point().distance(p)))
                .filter(|&(g, d)| d < tol[g])
                .min_by(|x, y| x.1.total_cmp(&y.1));
            let past = beyond.iter().any(|(b, t)| b.reference_point().distance(p) < *t);
            match hit {
                Some((g, _)) => matched.push((g, k)),
                None if past => r.beyond += 1,
                None => {
                    r.wrong += 1;
                    r.wrong_at.push(drawn.len());
                    r.stacked +=
                        usize::from((0..truth.len()).any(|g| {
                            done[g] && classes[g] == class && truth[g].reference_point().distance(p) < tol[g]
                        }));
                    if debug {
                        let near = (0..truth.len())
                            .map(|g| (truth[g].reference_point().distance(p), done[g], classes[g]))
                            .min_by(|x, y| x.0.total_cmp(&y.0));
                        eprintln!(
                            "  wrong {:?} class {class} (source {}) at {p:?}: nearest truth {near:?}",
                            s.cells[k], s.sources[k]
                        );
                    }
                }
            }
        }
        if matched.is_empty() {
            done[first] = true;
            drawn.push(truth[first].clone());
            drawn_class.push(classes[first]);
            r.by_hand += 1;
            if r.accepted == 0 {
                r.before_first += 1;
            }
        } else {
            for (g, k) in matched {
                done[g] = true;
                // As the page does: accepted strokes are marked so.
                opts.suggested.push(drawn.len() as u32);
                drawn.push(s.strokes[k].clone());
                drawn_class.push(classes[g]);
                r.accepted += 1;
            }
        }
    }
    r.end_reason = suggest_strokes(&drawn, &opts).expect("suggestions on a drawing").reason;
    r.drawing = drawn;
    r.drawing_classes = drawn_class;
    crate::order::floats(&mut times);
    r.slowest_ms = times.last().copied().unwrap_or(0.0);
    r.median_ms = times.get(times.len() / 2).copied().unwrap_or(0.0);
    r
}
