//! Copies along a drawn path (issue 27: "a stem and three leaves"). Where the latest
//! copies of a shape each touch one long stroke that curves (a vine, a contour, a
//! flower's heart), the path itself says where the next copies go: as far on along it,
//! by arc length, as the copies are apart, each turned as the path's tangent turns,
//! up to where the path ends (round again, on a closed one, to the first copy).
//!
//! Read from the path, not from the copies' steps: a sine stem's turn changes sign
//! every few leaves, which no similarity between the last copies carries
//! (`sequence`: leaves over a wavy stem were 8% accepted, over a curly one none),
//! while the drawn stem shows it outright. A straight path is left to the lattice,
//! which reads a row with its own certainty.
//!
//! A copy's place on the path is where it comes nearest it (a leaf's base, a hatching
//! line's crossing); its pose is kept in the path's frame there: carried to arc length
//! `s'`, a copy at `s` turns by the tangent's turn from `s` to `s'` about the path's
//! point. The places along the path are fitted by a line in the copies' order; a ghost
//! is shown where the hand's copy is likely within the matching tolerance of it, as
//! for lattices (`certainty::reach`), from the spread of the places about that line and
//! of the copies' poses in the path's frame.

use super::sequence::{relations, Ask};
use super::{Suggestions, FALLOFF, TOLERANCE};
use crate::rng::Rng;
use crate::vector::similarity::samples;
use crate::vector::stroke::Stroke;
use fit::Fit;
use kurbo::Point;
use path::Path;
use run::{Candidate, Run, ATTACH};

mod fit;
mod path;
mod run;

/// Strokes looked back over for the path and the copies.
const LOOK_BACK: usize = 32;
/// A path is at least this many times as long as a copy is large...
const PATH_LENGTH: f64 = 3.0;
/// ...and its tangent turns by at least this much along it (radians, about 23 degrees;
/// a straight one, a row along a baseline drawn a little bowed, is the lattice's: a
/// sag of a twenty-fifth of its length turns it by 0.16).
const MIN_CURVE: f64 = 0.4;
/// At least this many hand-drawn copies.
const MIN_COPIES: usize = 3;
/// A copy's kind is every copy (1) or every other one (2: leaves on alternate sides of
/// a stem).
const MAX_STRIDE: usize = 2;
/// A ghost is on a drawn copy when their centres lie within this share of the gap.
const DRAWN: f64 = 0.3;

const PATH_ENDS: &str = "The next copy would go past the end of the path: draw it on, and the copies follow it.";
const UNCERTAIN: &str = "The copies along the path are spaced too unevenly to go on from: draw one more.";

/// Whether stroke `i` was drawn by hand (not an accepted proposal).
fn hand(accepted: &[bool], i: usize) -> bool {
    !accepted.get(i).copied().unwrap_or(false)
}

fn size(s: &Stroke) -> f64 {
    s.bounds().size().to_vec2().hypot()
}

/// Proposals carrying on the copies of the latest hand-drawn stroke (or, where that is
/// the path, the one before) along a drawn path they touch, those too uncertain to show
/// held back when `sure` (not for a fill of the canvas, asked for outright); `None`
/// where no curving path holds the latest copies.
pub(super) fn propose(strokes: &[Stroke], accepted: &[bool], ask: &Ask, sure: bool) -> Option<Suggestions> {
    follow(strokes, accepted, ask, sure)
}

/// Every copy along the path that the copies in `strokes` (a drawing to synthesize from)
/// touch, past the last drawn and before the first, up to its ends, each with the stroke
/// it repeats (with `seed`, a random drawn copy); at most `limit`, or `None` where no
/// curving path holds the latest copies (`propose`'s test). Not held back by certainty:
/// the path says where each goes.
pub(crate) fn fill(strokes: &[Stroke], seed: Option<u64>, limit: usize) -> Option<Vec<(Stroke, usize)>> {
    let n = strokes.len();
    let ask = Ask { count: limit, region: None, offset: 0, seed, rows: true };
    let on = follow(strokes, &[], &ask, false)?;
    // (Back from the first copy: the drawing read the other way round.)
    let reversed: Vec<Stroke> = strokes.iter().rev().cloned().collect();
    let back = follow(&reversed, &[], &ask, false)
        .map(|b| b.strokes.into_iter().zip(b.sources.into_iter().map(|i| n - 1 - i as usize)));
    let mut out: Vec<(Stroke, usize)> =
        on.strokes.into_iter().zip(on.sources.into_iter().map(|i| i as usize)).collect();
    out.extend(back.into_iter().flatten());
    out.truncate(limit);
    Some(out)
}

/// `propose`, holding back ghosts too uncertain to show when `sure`.
fn follow(strokes: &[Stroke], accepted: &[bool], ask: &Ask, sure: bool) -> Option<Suggestions> {
    let n = strokes.len();
    let lo = n.saturating_sub(LOOK_BACK);
    let hand = |i: usize| hand(accepted, i);
    // The latest few hand-drawn strokes, the largest first (a leaf's outline before its
    // midrib, which touches the stem too but is not the leaf).
    let mut motifs: Vec<usize> = (lo..n).rev().filter(|&i| hand(i) && !strokes[i].is_dot()).take(3).collect();
    motifs.sort_by(|&a, &b| size(&strokes[b]).total_cmp(&size(&strokes[a])));
    // (Each recent stroke's length, measured once for every motif tried.)
    let lengths: Vec<f64> = (0..n)
        .map(|i| {
            if i < lo {
                0.0
            } else {
                strokes[i].points.windows(2).map(|w| (w[0][0] - w[1][0]).hypot(w[0][1] - w[1][1])).sum()
            }
        })
        .collect();
    motifs.into_iter().find_map(|m| along(strokes, accepted, ask, m, sure, &lengths))
}

/// `propose` with the copies of stroke `m` as the motif (`lengths`: each of the latest
/// `LOOK_BACK` strokes' length).
fn along(
    strokes: &[Stroke],
    accepted: &[bool],
    ask: &Ask,
    m: usize,
    sure: bool,
    lengths: &[f64],
) -> Option<Suggestions> {
    let n = strokes.len();
    let lo = n.saturating_sub(LOOK_BACK);
    let hand = |i: usize| hand(accepted, i);
    let big = size(&strokes[m]);
    let length = |s: usize| lengths[s];
    // Paths first (cheap): long hand-drawn strokes that curve.
    let window = 0.5 * big;
    let paths: Vec<(usize, Path)> = (lo..n)
        .filter(|&j| j != m && hand(j) && length(j) >= PATH_LENGTH * big)
        .filter_map(|j| Some((j, Path::new(&strokes[j], window)?)))
        .filter(|(_, p)| p.curve() >= MIN_CURVE)
        .collect();
    // (A path is drawn once: a stroke with copies of its own is a motif's, a petal of
    // a ring whose veins all reach its base.)
    let paths: Vec<(usize, Path)> = paths
        .into_iter()
        .filter(|(j, _)| {
            let (l, mine) = (length(*j), samples(&strokes[*j]));
            !(lo..n).any(|i| {
                i != *j
                    && (length(i) - l).abs() < 0.3 * l
                    && !relations(&samples(&strokes[i]), &mine, size(&strokes[i])).is_empty()
            })
        })
        .collect();
    if paths.is_empty() {
        return None;
    }
    let mine = samples(&strokes[m]);
    let sampled: Vec<Option<Vec<Point>>> = (0..n).map(|i| (i >= lo).then(|| samples(&strokes[i]))).collect();
    // Copies of its shape, in drawing order.
    let copies: Vec<usize> = (lo..n)
        .filter(|&i| {
            i == m
                || (!strokes[i].is_dot()
                    && !paths.iter().any(|p| p.0 == i)
                    && !relations(sampled[i].as_ref().expect("sampled"), &mine, size(&strokes[i])).is_empty())
        })
        .collect();
    paths.iter().find_map(|(j, path)| along_path(strokes, accepted, ask, (*j, path), &copies, &sampled, sure))
}

/// The copies (`copies`, in drawing order, the motif's last) carried on along `path`:
/// each copy like the one before in the path's frame, or else like the one two before
/// (leaves on alternate sides of a stem, each the other's mirror image).
fn along_path(
    strokes: &[Stroke],
    accepted: &[bool],
    ask: &Ask,
    path: (usize, &Path),
    copies: &[usize],
    sampled: &[Option<Vec<Point>>],
    sure: bool,
) -> Option<Suggestions> {
    let candidates: Vec<Candidate> = copies
        .iter()
        .map(|&i| {
            let points = sampled[i].as_deref()?;
            Some(Candidate {
                index: i,
                points,
                size: size(&strokes[i]),
                width: strokes[i].width,
                nearest: path.1.nearest(points),
            })
        })
        .collect::<Option<_>>()?;
    let hand = |i: usize| hand(accepted, i);
    (1..=MAX_STRIDE).find_map(|stride| {
        let run = Run::read(path.1, &candidates, stride, &hand)?;
        ghosts(strokes, &hand, ask, path, copies, &run, sure)
    })
}

/// The ghosts carrying `run` on along the path.
fn ghosts(
    strokes: &[Stroke],
    hand: &dyn Fn(usize) -> bool,
    ask: &Ask,
    (path_index, path): (usize, &Path),
    copies: &[usize],
    run: &Run,
    sure: bool,
) -> Option<Suggestions> {
    let (end, stride) = (run.end(), run.stride);
    let hands: Vec<usize> = (0..run.copies.len()).filter(|&t| hand(run.copies[t].index)).collect();
    let of_kind = |j: usize| hands.iter().copied().filter(move |&t| run.kind(t) == j);
    // (Each kind seen at least twice before a ghost is shown: its own copies say how it
    // lies on the path. A synthesis, asked outright, goes on from one copy of a kind: a
    // stem and three leaves on alternate sides came back as drawn, nothing added.)
    let least = if sure { 2 } else { 1 };
    if hands.len() < MIN_COPIES || (stride > 1 && (0..stride).any(|j| of_kind(j).count() < least)) {
        return None;
    }
    let fit = Fit::new(run, &run.places(path), &hands)?;
    let gap = fit.step.abs();
    // A copy's other strokes (drawn after it and before the next copy, near it: a leaf's
    // dot, its midrib) go with each ghost carried from it.
    let parts = |own: usize| -> Vec<usize> {
        let next = copies.iter().copied().find(|&i| i > own).unwrap_or(strokes.len());
        let previous = copies.iter().copied().rfind(|&i| i < own);
        // (A stroke drawn before the copy is its own where it lies nearer it than the
        // copy before: a leaf's midrib drawn first; not the one before's, drawn after it.)
        let at = |i: usize| strokes[i].reference_point();
        let nearer = |i: usize| previous.is_none_or(|p| i > own || at(i).distance(at(own)) < at(i).distance(at(p)));
        (previous.map_or(0, |i| i + 1)..next)
            .filter(|&i| i != own && i != path_index && hand(i) && nearer(i))
            .filter(|&i| at(i).distance(at(own)) < size(&strokes[own]))
            .collect()
    };
    let drawn = |g: &Stroke| {
        let c = g.reference_point();
        copies.iter().any(|&i| strokes[i].reference_point().distance(c) < DRAWN * gap)
    };
    let mut rng = ask.seed.map(Rng::new);
    let mut out = Suggestions::default();
    let mut why = None;
    for k in 1..=ask.count {
        let t = end + k;
        let j = run.kind(t);
        // (Read off the line, round a closed path's length.)
        let Some(s) = path.on(fit.place(t, j)) else {
            why = Some(PATH_ENDS);
            break;
        };
        if sure && fit.reach * fit.spread(t, j).sqrt() > TOLERANCE * gap {
            why = Some(UNCERTAIN);
            break;
        }
        // The latest hand-drawn copy of its kind carried to its place, or with variation
        // a random one.
        let mine: Vec<usize> = of_kind(j).collect();
        let latest = run.copies[*mine.last()?];
        let from = match &mut rng {
            Some(r) => run.copies[mine[r.below(mine.len())]],
            None => latest,
        };
        let ghost = path.carry(from.at, s).carry(&strokes[from.index]);
        // (A ghost touches the path inside its ends, as the drawn copies do: near an end
        // its place, read off a line, may hang it past.)
        let (touch, dist) = path.nearest(&samples(&ghost));
        let inside = path.closed || (2.0 * path.ds..=path.length() - 2.0 * path.ds).contains(&touch);
        if !inside || dist > ATTACH * size(&ghost) + 2.0 * ghost.width {
            why = Some(PATH_ENDS);
            break;
        }
        if ask.region.is_some_and(|r| !r.contains(ghost.reference_point())) {
            break;
        }
        if drawn(&ghost) {
            why = Some("The copies along the path are complete.");
            break;
        }
        let with = path.carry(latest.at, s);
        let ghosts = std::iter::once((ghost, from.index))
            .chain(parts(latest.index).into_iter().map(|p| (with.carry(&strokes[p]), p)));
        for (g, source) in ghosts {
            out.strokes.push(g);
            out.confidence.push(FALLOFF.powi(k as i32));
            out.sources.push((source + ask.offset) as u32);
            out.cells.push([k as i64, 0]);
        }
    }
    // (Nothing sure enough: other readings of the drawing may be.)
    if out.strokes.is_empty() {
        if why == Some(UNCERTAIN) {
            return None;
        }
        out.reason = Some(why.unwrap_or(PATH_ENDS).into());
    }
    Some(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A loop 36 long from `at` along `theta`.
    fn leaf(at: Point, theta: f64) -> Stroke {
        let (c, s) = (theta.cos(), theta.sin());
        let pts = (0..=24)
            .map(|k| {
                let t = k as f64 / 24.0 * std::f64::consts::TAU;
                let (along, across) = (18.0 * (1.0 - t.cos()), 6.0 * t.sin());
                [at.x + along * c - across * s, at.y + along * s + across * c]
            })
            .collect();
        Stroke::new(pts, 2.0, None)
    }

    fn propose_sure(strokes: &[Stroke], accepted: &[bool], ask: &Ask) -> Option<Suggestions> {
        propose(strokes, accepted, ask, true)
    }

    fn ask(count: usize) -> Ask {
        Ask { count, region: None, offset: 0, seed: None, rows: true }
    }

    /// A stem along `y = 300 + 40 sin((x - 300) / 64)` from x = 40 to `to`, and leaves
    /// every 40 of its arc length from x = 60, each leaning 0.6 off the stem.
    fn vine(leaves: usize, to: f64) -> (Vec<Stroke>, Vec<Point>) {
        vine_leaning(leaves, to, &|_| -0.6)
    }

    /// `vine` with leaf `k` leaning `lean(k)` off the stem.
    fn vine_leaning(leaves: usize, to: f64, lean: &dyn Fn(usize) -> f64) -> (Vec<Stroke>, Vec<Point>) {
        let f = |x: f64| Point::new(x, 300.0 + 40.0 * ((x - 300.0) / 64.0).sin());
        let stem = Stroke::new(
            (0..=200).map(|k| f(40.0 + (to - 40.0) * k as f64 / 200.0)).map(|p| [p.x, p.y]).collect(),
            2.0,
            None,
        );
        // (Each site with the stem's direction there.)
        let site = |x: f64| (f(x), (f(x + 0.01) - f(x)).atan2());
        let (mut x, mut along, mut sites) = (60.0, 0.0, vec![site(60.0)]);
        while sites.len() < leaves + 5 {
            along += f(x).distance(f(x + 0.05));
            x += 0.05;
            if along >= 40.0 {
                along = 0.0;
                sites.push(site(x));
            }
        }
        let strokes = std::iter::once(stem)
            .chain(sites.iter().take(leaves).enumerate().map(|(k, &(p, phi))| leaf(p, phi + lean(k))))
            .collect();
        let truth = sites.iter().enumerate().map(|(k, &(p, phi))| leaf(p, phi + lean(k)).reference_point()).collect();
        (strokes, truth)
    }

    #[test]
    fn leaves_go_on_along_a_drawn_stem_and_stop_at_its_end() {
        let (strokes, truth) = vine(3, 560.0);
        let s = propose_sure(&strokes, &[], &ask(3)).expect("leaves along a stem");
        assert!(s.strokes.len() >= 2, "{:?}", s.reason);
        for (k, g) in s.strokes.iter().enumerate() {
            let d = g.reference_point().distance(truth[3 + k]);
            assert!(d < 0.1 * 40.0, "ghost {k} is {d:.1} off");
        }
        // The stem drawn on only past the fourth leaf: one ghost, and the page says why
        // no more.
        let (short, _) = vine(3, 200.0);
        let s = propose_sure(&short, &[], &ask(3)).expect("leaves along a stem");
        assert_eq!(s.strokes.len(), 1);
        let (none, _) = vine(4, 200.0);
        let s = propose_sure(&none, &[], &ask(3)).expect("leaves along a stem");
        assert!(s.strokes.is_empty() && s.reason.as_deref() == Some(PATH_ENDS), "{s:?}");
    }

    #[test]
    fn leaves_on_alternate_sides_go_on_alternating() {
        let lean = |k: usize| if k % 2 == 0 { -0.6 } else { 0.6 };
        // (Three drawn show the other side once, which says too little: nothing yet.)
        let (three, _) = vine_leaning(3, 560.0, &lean);
        assert!(propose_sure(&three, &[], &ask(3)).is_none_or(|s| s.strokes.is_empty()));
        for drawn in [4, 5] {
            let (strokes, truth) = vine_leaning(drawn, 560.0, &lean);
            let s = propose_sure(&strokes, &[], &ask(3)).expect("leaves along a stem");
            assert!(!s.strokes.is_empty(), "{drawn} drawn: {:?}", s.reason);
            for (k, g) in s.strokes.iter().enumerate() {
                let d = g.reference_point().distance(truth[drawn + k]);
                assert!(d < 0.1 * 40.0, "{drawn} drawn: ghost {k} is {d:.1} off");
            }
        }
    }

    #[test]
    fn copies_off_the_path_or_along_a_straight_one_are_not_its() {
        let (mut strokes, _) = vine(3, 560.0);
        // Straight: left to the lattice.
        strokes[0] = Stroke::new(vec![[40.0, 300.0], [560.0, 300.0]], 2.0, None);
        let leaves: Vec<Stroke> = (0..3).map(|k| leaf(Point::new(60.0 + 40.0 * k as f64, 300.0), -0.6)).collect();
        let straight: Vec<Stroke> = std::iter::once(strokes[0].clone()).chain(leaves.iter().cloned()).collect();
        assert!(propose_sure(&straight, &[], &ask(3)).is_none());
        // The leaves 60 away from a curving stem.
        let (vine, _) = vine(3, 560.0);
        let away: Vec<Stroke> =
            std::iter::once(vine[0].clone()).chain(vine[1..].iter().map(|l| l.translated(0.0, 60.0))).collect();
        assert!(propose_sure(&away, &[], &ask(3)).is_none());
    }

    /// A circle of radius 80 about (300, 300) drawn from `from` radians round by `turn`
    /// (its end short of its start, or past it), and leaves every 30 degrees round it
    /// from 0, each leaning 0.6 off it; the truth's reference points.
    fn ring(from: f64, turn: f64, leaves: usize) -> (Vec<Stroke>, Vec<Point>) {
        let at = |t: f64| Point::new(300.0 + 80.0 * t.cos(), 300.0 + 80.0 * t.sin());
        let points = (0..=360).map(|k| at(from + turn * k as f64 / 360.0)).map(|p| [p.x, p.y]).collect();
        let step = std::f64::consts::TAU / 12.0;
        let site = |k: usize| leaf(at(k as f64 * step), k as f64 * step + std::f64::consts::FRAC_PI_2 - 0.6);
        let strokes = std::iter::once(Stroke::new(points, 2.0, None)).chain((0..leaves).map(site)).collect();
        (strokes, (0..12).map(|k| site(k).reference_point()).collect())
    }

    #[test]
    fn leaves_round_a_circle_go_on_past_where_the_hand_began_it() {
        use std::f64::consts::TAU;
        // Begun at 100 degrees (between the fourth leaf and the fifth), its end 12 short
        // of its start or 20 past it: closed all the same, so the ghosts go on past 100
        // degrees (an open path ended there).
        for turn in [TAU - 0.15, TAU + 0.25] {
            let (strokes, truth) = ring(100f64.to_radians(), turn, 4);
            let s = propose_sure(&strokes, &[], &ask(3)).expect("leaves round a circle");
            assert!(s.strokes.len() >= 2, "turn {turn:.2}: {:?}", s.reason);
            for (k, g) in s.strokes.iter().enumerate() {
                let d = g.reference_point().distance(truth[4 + k]);
                assert!(d < 0.1 * 80.0 * TAU / 12.0, "turn {turn:.2}: ghost {k} is {d:.1} off");
            }
        }
    }
}
