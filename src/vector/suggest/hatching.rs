//! Hatching by hand: straight lines side by side, each placed by eye a little off the
//! spacing, a little longer or shorter, and ended anywhere (after Xing et al.,
//! "Autocomplete Painting Repetitions", 2014: the next stroke relates to the last as
//! the last relates to the one before).
//!
//! A line's place along itself says little (a hand ends each line where it likes and
//! overshoots some), nor its length: what hatching keeps is the lines' direction and
//! their spacing across it. So hatching is read from those, not from the lines' centres
//! as shapes: the lattice and the sequence fit a line 20% longer as another shape or a
//! zoom, and its centre, moved along it, as a hand's miss of a fifth of the spacing.
//!
//! Each step from a line to the next is read in the earlier line's frame: the move
//! across it (the spacing), the move along it, the turn and the change of length, from
//! hand-drawn lines only. The next lines are spaced by the mean gap, moved along as the
//! latest steps were, and turned and lengthened as the lines' own turns and lengths
//! trend, where the trend is clear of a hand's scatter. Shown only while the spacing
//! holds (`SPREAD`: a hand that spaces its lines evenly to within a tenth gets two
//! ghosts, one within a sixth gets none), two steps past the latest hand-drawn line
//! at most. The ghosts space the lines evenly: where the hand's next line would have
//! strayed, the ghost is the line it meant.

use super::sequence::Ask;
use super::{Suggestions, FALLOFF};
use crate::vector::similarity::{mul, Similarity};
use crate::vector::stroke::Stroke;
use kurbo::{Point, Vec2};

/// The fewest lines (the latest among them) that make hatching: three steps.
const FEWEST: usize = 4;
/// The most lines looked back over, and the most steps averaged for the next.
const LOOK_BACK: usize = 8;
const MEAN_OF: usize = 3;
/// Lengths changing by this factor each way by turns, twice running, are two motifs.
const ALTERNATE: f64 = 1.25;
/// A line: its points all within this share of its length of its chord...
const STRAIGHT: f64 = 0.06;
/// ...and at least this many pen widths long.
const LONG: f64 = 6.0;
/// Lines of one hatching turn by at most this much a step (radians, 20 degrees)...
const MAX_TURN: f64 = 0.35;
/// ...change length by at most this factor either way...
const MAX_LENGTH: f64 = 1.6;
/// ...move along the line by at most this share of its length...
const MAX_ALONG: f64 = 0.6;
/// ...and across it, each step by this factor of the steps' median at most, either way
/// (always the same way round), and by at most this share of the line's length (lines
/// further apart than they are long are a row of dashes, the lattice's).
const MAX_GAP: f64 = 1.6;
const MAX_GAP_OF_LENGTH: f64 = 1.0;
/// A ghost `j` steps past the latest hand-drawn line, the hand-drawn lines spanning
/// `n` steps, is shown while the spacing's spread (standard deviation over mean) times
/// `sqrt(1 + (j / n)^2)` is at most this: the latest line's own miss and the mean
/// gap's error over `j` steps against the matching tolerance (0.3 of the gap) at about
/// two standard deviations, across the lines.
const SPREAD: f64 = 0.15;
/// ...and no further than this many steps past it: further on, the hand's own drift
/// (a fan's turn read loosely, a spacing that grows) takes the ghosts off its lines: a
/// third ghost on made 24-50 of about 200 wrong in the replay's hatching.
const AHEAD: usize = 2;
/// Why nothing more is proposed once the ghosts ahead of the hand are accepted.
pub(super) const AHEAD_OF_HAND: &str =
    "The hatching goes on from the lines you draw: draw the next line and the ones after it are proposed.";
/// A ghost is on a drawn line of the hatching where their midpoints lie within this
/// share of the spacing (and the line is about as turned).
const DRAWN: f64 = 0.3;

/// A straight stroke: its midpoint, unit direction and length.
#[derive(Clone, Copy, Debug)]
struct Line {
    mid: Point,
    dir: Vec2,
    len: f64,
}

/// Whether `s` is a straight line (as hatching's lines are): any two lines are one shape
/// up to a similarity, which says nothing of a repetition.
pub(super) fn straight(s: &Stroke) -> bool {
    Line::through(s).is_some()
}

impl Line {
    /// The line `s` is, if straight (see `STRAIGHT`, `LONG`).
    fn of(s: &Stroke) -> Option<Line> {
        Line::through(s).filter(|l| l.len >= LONG * s.width.max(1.0))
    }

    /// The line through `s`'s ends, if it keeps to it (see `STRAIGHT`), however short.
    fn through(s: &Stroke) -> Option<Line> {
        let (first, last) = (s.points.first()?, s.points.last()?);
        let (p, q) = (Point::new(first[0], first[1]), Point::new(last[0], last[1]));
        let chord = q - p;
        let len = chord.hypot();
        if len == 0.0 {
            return None;
        }
        let dir = chord / len;
        let off = |x: &[f64; 2]| (Point::new(x[0], x[1]) - p).cross(dir).abs();
        if s.points.iter().any(|x| off(x) > STRAIGHT * len) {
            return None;
        }
        Some(Line { mid: p.midpoint(q), dir, len })
    }

    /// The same line pointing within a quarter turn of `d` (a hand draws hatching
    /// either way).
    fn toward(self, d: Vec2) -> Line {
        if self.dir.dot(d) < 0.0 {
            Line { dir: -self.dir, ..self }
        } else {
            self
        }
    }
}

/// A step from one line to the next, in the first's frame.
#[derive(Clone, Copy, Debug)]
struct Step {
    across: f64,
    along: f64,
    turn: f64,
    /// Log of the length's change.
    grow: f64,
}

impl Step {
    fn between(a: Line, b: Line) -> Step {
        let d = b.mid - a.mid;
        let normal = Vec2::new(-a.dir.y, a.dir.x);
        Step {
            across: d.dot(normal),
            along: d.dot(a.dir),
            turn: a.dir.cross(b.dir).atan2(a.dir.dot(b.dir)),
            grow: (b.len / a.len).ln(),
        }
    }

    /// The line this step carries `a` onto.
    fn apply(self, a: Line) -> Line {
        let normal = Vec2::new(-a.dir.y, a.dir.x);
        let (c, s) = (self.turn.cos(), self.turn.sin());
        Line {
            mid: a.mid + normal * self.across + a.dir * self.along,
            dir: Vec2::new(a.dir.x * c - a.dir.y * s, a.dir.x * s + a.dir.y * c),
            len: a.len * self.grow.exp(),
        }
    }
}

/// Proposals continuing the hatching that ends with the latest stroke (none, with the
/// reason, where the ghosts ahead of the hand are taken), or `None` where the latest
/// strokes are no hatching (fewer than `FEWEST` lines side by side, turning,
/// lengthening and spaced alike) or it is too unevenly spaced to go on from.
pub(super) fn propose(strokes: &[Stroke], accepted: &[bool], ask: &Ask) -> Option<Suggestions> {
    let hand = |i: usize| !accepted.get(i).copied().unwrap_or(false);
    let latest = strokes.len().checked_sub(1)?;
    // The run of lines back from the latest, each a step of hatching from the one
    // before it.
    let mut run: Vec<(usize, Line)> = vec![(latest, Line::of(&strokes[latest])?)];
    for i in (latest.saturating_sub(LOOK_BACK - 1)..latest).rev() {
        let Some(line) = Line::of(&strokes[i]) else { break };
        let next = run.last()?.1;
        let line = line.toward(next.dir);
        let step = Step::between(line, next);
        let hatched = step.turn.abs() <= MAX_TURN
            && step.grow.abs() <= MAX_LENGTH.ln()
            && step.along.abs() <= MAX_ALONG * line.len
            && step.across.abs() <= MAX_GAP_OF_LENGTH * line.len
            && step.across.abs() > 0.0;
        if !hatched {
            break;
        }
        run.push((i, line));
    }
    run.reverse();
    // The steps are read from hand-drawn lines only, each pair of consecutive ones over
    // the steps between them (an accepted ghost sits where it was proposed and says
    // nothing of the hand's spacing; read with them, ghosts went on from ghosts, and a
    // hand's hatching drifted from them: a person's hatching got 107 wrong ghosts of 442
    // in the replay).
    let hands: Vec<(usize, Line)> =
        run.iter().enumerate().filter(|(_, (i, _))| hand(*i)).map(|(k, &(_, l))| (k, l)).collect();
    if run.len() < FEWEST || hands.len() < FEWEST - 1 {
        return None;
    }
    let steps: Vec<(Step, f64)> = hands
        .windows(2)
        .map(|w| {
            let (span, s) = ((w[1].0 - w[0].0) as f64, Step::between(w[0].1, w[1].1));
            (Step { across: s.across / span, along: s.along / span, turn: s.turn / span, grow: s.grow / span }, span)
        })
        .collect();
    // Always across the same way, each gap about the others'.
    let mut gaps: Vec<f64> = steps.iter().map(|s| s.0.across).collect();
    let sign = gaps[0].signum();
    if gaps.iter().any(|g| g.signum() != sign) {
        return None;
    }
    gaps.iter_mut().for_each(|g| *g = g.abs());
    let median = crate::vector::classify::median(&mut gaps.clone());
    if median <= 0.0 || gaps.iter().any(|&g| g > MAX_GAP * median || g < median / MAX_GAP) {
        return None;
    }
    // Lines long and short by turns are a rhythm of two motifs, not hatching: the
    // lattice's (a ghost would repeat the latest's length where the other's is due).
    let alternate = steps.windows(2).filter(|w| w[0].0.grow * w[1].0.grow < -(ALTERNATE.ln().powi(2))).count();
    if alternate >= 2 {
        return None;
    }
    // (A gap read over `s` steps holds the two lines' misses once, not `s` times: its
    // per-step deviation weighs `s^2` in the spread of one step's.)
    let spans: f64 = steps.iter().map(|s| s.1).sum();
    let mean = gaps.iter().zip(&steps).map(|(g, s)| g * s.1).sum::<f64>() / spans;
    let n = gaps.len() as f64;
    let spread =
        (gaps.iter().zip(&steps).map(|(g, s)| (s.1 * (g - mean)).powi(2)).sum::<f64>() / (n - 1.0)).sqrt() / mean;
    if !spread.is_finite() {
        return None;
    }
    // Lines whose places bend along them, each step moving further along than the one
    // before (fence posts along an arc), are a row that bends, the sequence's: hatching
    // goes on by its latest steps, and the ghosts went straight on off the arc.
    let mean_len = hands.iter().map(|(_, l)| l.len).sum::<f64>() / hands.len() as f64;
    let alongs: Vec<(f64, f64)> =
        hands.windows(2).zip(&steps).map(|(w, s)| (0.5 * (w[0].0 + w[1].0) as f64, s.0.along)).collect();
    if clear_slope(&alongs, HAND_ALONG * mean_len) != 0.0 {
        return None;
    }
    // The next step: across, the mean gap; along, the mean of the latest few steps';
    // the turn and the lengthening, each the slope of the hand-drawn lines' own (turn,
    // log length) against their place in the run, taken only where it is clear of its
    // standard error (`SURE`): a hand turns each line a few degrees at random, read
    // from three steps as the fan of a turning contour, and ghosts three steps on went
    // 0.3 of the gap along their line.
    let recent = &steps[steps.len().saturating_sub(MEAN_OF)..];
    let m: f64 = recent.iter().map(|s| s.1).sum();
    let latest_dir = hands.last()?.1.dir;
    let turns: Vec<(f64, f64)> =
        hands.iter().map(|&(k, l)| (k as f64, latest_dir.cross(l.dir).atan2(latest_dir.dot(l.dir)))).collect();
    let lengths: Vec<(f64, f64)> = hands.iter().map(|&(k, l)| (k as f64, l.len.ln())).collect();
    let step = Step {
        across: sign * mean,
        along: recent.iter().map(|s| s.0.along * s.1).sum::<f64>() / m,
        turn: clear_slope(&turns, HAND_TURN),
        grow: clear_slope(&lengths, HAND_LENGTH),
    };
    // The ghosts repeat the latest hand-drawn line, carried; those past the accepted
    // lines after it are proposed, each as far ahead of it as its steps.
    let (at_hand, from) = *hands.last()?;
    let source = run[at_hand].0;
    let taken = run.len() - 1 - at_hand;
    let lines: Vec<Line> = strokes.iter().filter_map(Line::of).collect();
    let mut out = Suggestions::default();
    let mut at = from;
    for j in 1..=taken + ask.count {
        at = step.apply(at);
        if j <= taken {
            continue;
        }
        if j > AHEAD {
            out.reason = out.strokes.is_empty().then(|| AHEAD_OF_HAND.to_string());
            break;
        }
        if spread * (1.0 + (j as f64 / spans).powi(2)).sqrt() > SPREAD {
            break;
        }
        if ask.region.is_some_and(|r| !r.contains(at.mid)) {
            break;
        }
        let drawn =
            lines.iter().any(|l| l.mid.distance(at.mid) < DRAWN * mean && l.dir.cross(at.dir).abs() < MAX_TURN.sin());
        if drawn {
            break;
        }
        // The similarity carrying `from` onto the line at `at`.
        let from = from.toward(at.dir);
        let turn = Vec2::new(from.dir.dot(at.dir), from.dir.cross(at.dir)) * (at.len / from.len);
        let carry = Similarity { a: turn, b: at.mid.to_vec2() - mul(turn, from.mid.to_vec2()) };
        let mut ghost = carry.carry(&strokes[source]);
        // (A line drawn longer keeps its pen.)
        ghost.width = strokes[source].width;
        let k = (j - taken) as i64;
        out.strokes.push(ghost);
        out.confidence.push(FALLOFF.powi(k as i32));
        out.sources.push((source + ask.offset) as u32);
        out.cells.push([k, 0]);
    }
    (!out.strokes.is_empty() || out.reason.is_some()).then_some(out)
}

/// A slope is taken where it passes this many standard errors...
const SURE: f64 = 2.0;
/// ...its residual pooled with a hand's own scatter, counted as this many lines: a
/// hand's lines turn by about 2.5 degrees at random and differ in length by about a
/// tenth (three lines fit a slope all but exactly, and say nothing of that).
const PRIOR_LINES: f64 = 2.0;
const HAND_TURN: f64 = 0.0436;
const HAND_LENGTH: f64 = 0.1;
/// A hand moves each line along itself by about this share of its length at random
/// (where it begins and ends it).
const HAND_ALONG: f64 = 0.1;

/// The least-squares slope of `y` on `x` over `points` (a line's turn or log length
/// against its place in the run), where it is clear of its standard error (`SURE`),
/// the residual pooled with a prior scatter `prior` (standard deviation); else 0.
fn clear_slope(points: &[(f64, f64)], prior: f64) -> f64 {
    let n = points.len() as f64;
    if n < 3.0 {
        return 0.0;
    }
    let (mx, my) = (points.iter().map(|p| p.0).sum::<f64>() / n, points.iter().map(|p| p.1).sum::<f64>() / n);
    let sxx: f64 = points.iter().map(|p| (p.0 - mx).powi(2)).sum();
    if sxx <= 0.0 {
        return 0.0;
    }
    let slope = points.iter().map(|p| (p.0 - mx) * (p.1 - my)).sum::<f64>() / sxx;
    let ss: f64 = points.iter().map(|p| (p.1 - my - slope * (p.0 - mx)).powi(2)).sum();
    let residual = (ss + PRIOR_LINES * prior * prior) / (n - 2.0 + PRIOR_LINES);
    if slope.abs() > SURE * (residual / sxx).sqrt() {
        slope
    } else {
        0.0
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::rng::Rng;

    fn ask(count: usize) -> Ask {
        Ask { count, region: None, offset: 0, seed: None, rows: true }
    }

    /// Lines 100 long at `angle`, `gap` apart across them (each gap off by `spread` of
    /// it at random), each ended up to `ends` along itself off at random.
    fn hatching(n: usize, gap: f64, spread: f64, ends: f64, seed: u64) -> Vec<Stroke> {
        let mut rng = Rng::new(seed);
        let dir = Vec2::new(0.34, -0.94);
        let normal = Vec2::new(0.94, 0.34);
        let mut across = 0.0;
        (0..n)
            .map(|k| {
                if k > 0 {
                    across += gap * (1.0 + spread * rng.normal());
                }
                let start = Point::new(200.0, 300.0) + normal * across + dir * (ends * rng.normal());
                let end = start + dir * (100.0 * (1.0 + 0.1 * rng.normal()));
                Stroke::new(vec![[start.x, start.y], [end.x, end.y]], 3.0, None)
            })
            .collect()
    }

    #[test]
    fn evenly_spaced_lines_go_on_at_their_spacing() {
        let normal = Vec2::new(0.94, 0.34);
        for seed in 1..=5 {
            let lines = hatching(9, 15.0, 0.05, 5.0, seed);
            let s = propose(&lines[..5], &[], &ask(3)).expect("hatching");
            // Two steps past the latest line, each ghost about a gap on from the last.
            assert_eq!(s.strokes.len(), 2, "seed {seed}");
            let last = Line::of(&lines[4]).unwrap().mid;
            for (k, g) in s.strokes.iter().enumerate() {
                let line = Line::of(g).expect("a ghost is a line");
                let across = (line.mid - last).dot(normal);
                assert!(
                    (across - 15.0 * (k + 1) as f64).abs() < 3.0 + 1.5 * k as f64,
                    "seed {seed}, ghost {k}: {across:.1}"
                );
                assert!(line.dir.cross(Vec2::new(0.34, -0.94)).abs() < 0.1, "seed {seed}, ghost {k} turned");
            }
            // Both accepted: nothing further till the hand draws the next line; then
            // the next two from it.
            let mut drawn = lines[..5].to_vec();
            drawn.extend(s.strokes.iter().cloned());
            let accepted = [false, false, false, false, false, true, true];
            let waits = propose(&drawn, &accepted, &ask(3)).expect("the hatching still read");
            assert!(waits.strokes.is_empty() && waits.reason.as_deref() == Some(AHEAD_OF_HAND), "seed {seed}");
            drawn.push(lines[7].clone());
            let next = propose(&drawn, &[false, false, false, false, false, true, true, false], &ask(3)).expect("on");
            let from = Line::of(&lines[7]).unwrap().mid;
            let across = (Line::of(&next.strokes[0]).unwrap().mid - from).dot(normal);
            assert!((across - 15.0).abs() < 3.0, "seed {seed}: {across:.1} on from the line drawn");
        }
    }

    #[test]
    fn uneven_lines_few_lines_and_scattered_dashes_get_nothing() {
        // Spaced anyhow: no ghost, or one.
        let uneven = hatching(6, 15.0, 0.35, 5.0, 3);
        assert!(propose(&uneven, &[], &ask(3)).is_none_or(|s| s.strokes.len() <= 1));
        // Long and short by turns: two motifs.
        let mut rhythm = hatching(6, 15.0, 0.0, 0.0, 1);
        for l in rhythm.iter_mut().skip(1).step_by(2) {
            let (p, q) = (l.points[0], l.points[1]);
            l.points[1] = [p[0] + 1.5 * (q[0] - p[0]), p[1] + 1.5 * (q[1] - p[1])];
        }
        assert!(propose(&rhythm, &[], &ask(3)).is_none());
        // Accepted lines back and forth on two places: no gap to go on by.
        let zigzag: Vec<Stroke> = (0..5)
            .map(|k| Stroke::new(vec![[10.0 * (k % 2) as f64, 0.0], [10.0 * (k % 2) as f64, 100.0]], 2.0, None))
            .collect();
        assert!(propose(&zigzag, &[false, true, false, true, false], &ask(3)).is_none());
        // Three lines are too few.
        assert!(propose(&hatching(3, 15.0, 0.0, 0.0, 1), &[], &ask(3)).is_none());
        // Dashes at random places and turns.
        let mut rng = Rng::new(7);
        let dashes: Vec<Stroke> = (0..12)
            .map(|_| {
                let (x, y, t) = (rng.next_f64() * 400.0, rng.next_f64() * 400.0, rng.next_f64() * 6.3);
                Stroke::new(vec![[x, y], [x + 40.0 * t.cos(), y + 40.0 * t.sin()]], 2.0, None)
            })
            .collect();
        for n in 4..=dashes.len() {
            assert!(propose(&dashes[..n], &[], &ask(3)).is_none(), "{n} dashes");
        }
    }
}
