//! Autocomplete while drawing (SPEC 1.7, after Xing et al., "Autocomplete Painting
//! Repetitions", 2014): the drawing so far is the example; once it shows a repetition,
//! the next copies of the motif near the latest strokes are proposed as ghost strokes.
//!
//! A repetition is a lattice `origin_m + u a + w b` of motif positions `m` (a row when
//! there is no `b`). Its periods are offsets between same-class strokes that recur
//! (found at least twice among the latest strokes), tried shortest first; a candidate is
//! kept only when it explains the drawing:
//! - most strokes (70%) sit at a motif position drawn at least twice;
//! - no motif position is drawn twice in one cell, and none stops short of a stroke of
//!   its class further along its line (a period that skips drawn copies is a sub-period,
//!   such as the gap inside a pair);
//! - the strokes lie near their lattice sites (median residual at most 20% of the
//!   spacing).
//!
//! Of the lattices built on the first few periods that fit as a row, the one that
//! leaves fewest cells out inside its lines and then needs fewest motif positions
//! wins: the finest lattice the drawing bears out.
//!
//! Predictions then complete the cells already begun (the copy being drawn) and add the
//! next `count` cells along the rhythm of the latest cells. Nothing is proposed on a
//! first stroke, on irregular input, or when the latest stroke does not repeat anything
//! (a stroke that contradicts the prediction dismisses it). Each proposed copy is a
//! random drawn copy of its motif (so accepted copies keep the hand-drawn character)
//! placed at its site: the least-squares site is the best guess of where the hand
//! would put it, and a drawn copy's own deviation would only add to the miss.
//!
//! A proposal is shown only where it is likely right: where the hand's copy falls
//! within the matching tolerance of it with probability 0.98, given its expected miss
//! (the site's standard error, grown with each period away from the hand-drawn copies,
//! and the hand's own scatter) and how few copies that scatter is estimated from (an
//! F quantile, not a Gaussian one). The scatter is estimated with its degrees of
//! freedom (two copies fit a row exactly and say nothing of it) and a prior read from
//! the hand's wobble; accepted copies, which sit where an earlier fit put them, count
//! neither as evidence of the periods' error nor as whole copies of the hand (a copy
//! finished by hand weighs by its hand-drawn share).

mod ahead;
pub(crate) mod along;
mod certainty;
mod drift;
mod fit;
mod hatching;
mod lattice;
mod orbit;
mod sequence;
mod taps;
mod turning;

use self::certainty::hand_scatter;
use self::fit::Fit;
use super::classify::median;
use super::element::Element;
use super::reference::Spread;
use super::spatial::Grid;
use super::stroke::Stroke;
use super::synthesize::classify_drawing;
use crate::error::{invalid, Result};
use crate::rng::Rng;
use kurbo::{Point, Rect};
use serde::{Deserialize, Serialize};

/// Options of `suggest_strokes`.
#[derive(Clone, Debug, Deserialize)]
#[serde(rename_all = "camelCase", default, deny_unknown_fields)]
pub struct SuggestOptions {
    /// The area suggestions must fall in, `[x, y, width, height]` (the canvas); none:
    /// anywhere.
    pub region: Option<[f64; 4]>,
    /// How many copies of the motif to propose beyond those already begun.
    pub count: usize,
    /// Propose every copy in the region instead (the region is then required).
    pub fill: bool,
    pub path_tolerance: Option<f64>,
    pub width_tolerance: Option<f64>,
    pub color_tolerance: Option<f64>,
    /// Each proposal takes a random member of its class (else the stroke at its place).
    pub variation: bool,
    pub seed: u64,
    /// Indices of the strokes that are accepted proposals. They count for little in the
    /// periods' fit: they repeat the periods they were proposed with, so without this a
    /// period misjudged from the first copies drifts on through every accepted copy and
    /// the next hand-drawn stroke cannot correct it.
    pub suggested: Vec<u32>,
}

impl Default for SuggestOptions {
    fn default() -> Self {
        SuggestOptions {
            region: None,
            count: 3,
            fill: false,
            path_tolerance: None,
            width_tolerance: None,
            color_tolerance: None,
            variation: true,
            seed: 1,
            suggested: Vec::new(),
        }
    }
}

/// Proposed strokes (empty when the drawing shows no repetition yet).
#[derive(Clone, Debug, Default, Serialize)]
#[serde(rename_all = "camelCase")]
pub struct Suggestions {
    pub strokes: Vec<Stroke>,
    /// Of each proposed stroke, in (0, 1]: how well the lattice explains the drawing,
    /// lower for copies further from the drawn ones.
    pub confidence: Vec<f64>,
    /// The drawn stroke whose place (and deviation) each proposal repeats.
    pub sources: Vec<u32>,
    /// Lattice cell `[u, w]` of each proposal; proposals of one copy share it.
    pub cells: Vec<[i64; 2]>,
    /// The repetition's period vectors (one for a row, two for a lattice; none found).
    pub periods: Vec<[f64; 2]>,
    /// Why nothing is proposed, when nothing is.
    pub reason: Option<String>,
}

/// The most strokes a suggestion reads; beyond, only the latest ones (the repetition
/// is near them and the answer must come within a pen-up's patience).
pub const MAX_STROKES: usize = 400;
/// The most copies `fill` proposes, and the most points all its strokes may hold.
pub const MAX_FILL_CELLS: usize = 5_000;
pub const MAX_FILL_POINTS: usize = 2_000_000;
/// Matching tolerance, as a fraction of the spacing.
const TOLERANCE: f64 = 0.3;
/// Confidence lost per period of distance from the nearest drawn copy.
const FALLOFF: f64 = 0.85;
/// The least scatter of a copy about its site assumed before the drawing shows its
/// own, as a fraction of the spacing (a hand's own is read from its strokes' shapes:
/// see `hand_scatter`).
const MIN_SCATTER: f64 = 0.04;
/// A hand places its copies more loosely than it shapes them: the prior scatter of a
/// copy's place is this multiple of the mean square wobble of its strokes' ends...
const HAND_TO_PLACEMENT: f64 = 8.0;
/// ...and at most this fraction of the spacing: a hand judges a copy's place by the
/// copies beside it, not by its size (hatching 80 long and 20 apart, each line turned
/// by up to 2 degrees, read a prior of 3.6, and six lines within 0.5 of a row got no
/// ghost).
const MAX_SCATTER: f64 = 0.1;
/// A copy turned by more than this (radians, about 11 degrees) from the usual copy of
/// its place is no translated copy (a hand turns its copies by a few degrees at random).
const TURNED: f64 = 0.2;
/// Weight of an accepted proposal in the periods' fit (a hand-drawn stroke's is 1).
const SUGGESTED_WEIGHT: f64 = 0.05;

/// Why nothing is proposed where no repetition is read yet, or none carries on.
const NO_SPACING: &str = "The strokes have no spacing to repeat.";
const NO_REPETITION: &str = "The drawing shows no repetition yet.";
const NOT_REPEATED: &str = "The latest stroke does not repeat the pattern.";
pub(super) const UNCERTAIN: &str = "The copies drawn so far leave the next ones too uncertain: draw one more.";

fn nothing(reason: &str) -> Suggestions {
    Suggestions { reason: Some(reason.into()), ..Suggestions::default() }
}

/// Proposes the next strokes of the repetition in `strokes` (in drawing order). Where
/// the structures read propose nothing, the latest strokes may still be hatching drawn
/// by hand, spaced by eye (`hatching`).
pub fn suggest_strokes(strokes: &[Stroke], opts: &SuggestOptions) -> Result<Suggestions> {
    let found = suggest_found(strokes, opts)?;
    // (Only where nothing was read or nothing carried on: a ring complete, a path at its
    // end, a copy being drawn or every copy in the region drawn is an answer that
    // stands: rays round a centre are no hatching, nor ties along a rail past its end.)
    let open = [NO_SPACING, NO_REPETITION, NOT_REPEATED, UNCERTAIN, sequence::UNFOLLOWED];
    let unread = found.reason.as_deref().is_some_and(|r| open.contains(&r));
    if !found.strokes.is_empty() || !unread || opts.fill || strokes.len() < 3 {
        return Ok(found);
    }
    let skip = strokes.len().saturating_sub(MAX_STROKES);
    let accepted: Vec<bool> = (skip..strokes.len()).map(|i| opts.suggested.contains(&(i as u32))).collect();
    let ask = sequence::Ask { count: opts.count, region: found_region(opts), offset: skip, seed: None, rows: true };
    Ok(hatching::propose(&strokes[skip..], &accepted, &ask).unwrap_or(found))
}

/// The sequence carrying on the latest strokes (`sequence`), unless they are lines of
/// hatching (`hatching`): the sequence compares lines as shapes and places them by
/// their middles, so that a line drawn past its end is another shape and its middle a
/// miss along it: it read a hand's fan as a motif of two lines, and its ghosts went a
/// third of a gap off (`hatching_that_turns_with_its_contour_gets_its_next_line`).
fn by_turns(strokes: &[Stroke], accepted: &[bool], ask: &sequence::Ask) -> Option<Suggestions> {
    let found = sequence::propose(strokes, accepted, ask)?;
    if !ask.rows || found.strokes.is_empty() {
        return Some(found);
    }
    Some(hatching::propose(strokes, accepted, ask).filter(|h| !h.strokes.is_empty()).unwrap_or(found))
}

/// The region asked for, once `suggest_found` has checked it.
fn found_region(opts: &SuggestOptions) -> Option<Rect> {
    opts.region.map(|[x, y, w, h]| Rect::new(x, y, x + w, y + h))
}

/// `suggest_strokes` by the structures the drawing shows: a drawn path, a lattice, a
/// ring or a sequence.
fn suggest_found(strokes: &[Stroke], opts: &SuggestOptions) -> Result<Suggestions> {
    if opts.count > 64 {
        return invalid("count can be at most 64 copies; use fill to propose the whole region.");
    }
    let region = match opts.region {
        Some([x, y, w, h]) => {
            if ![x, y, w, h].iter().all(|v| v.is_finite()) || w <= 0.0 || h <= 0.0 {
                return invalid("region must be [x, y, width, height] with finite numbers and a positive size.");
            }
            Some(Rect::new(x, y, x + w, y + h))
        }
        None if opts.fill => return invalid("fill needs a region: the canvas to fill."),
        None => None,
    };
    if let Some(&i) = opts.suggested.iter().find(|&&i| i as usize >= strokes.len()) {
        return invalid(format!("suggested lists stroke {i}, but there are {} strokes.", strokes.len()));
    }
    if strokes.len() < 3 {
        return Ok(nothing("Draw a motif two or three times and the next copies are proposed."));
    }
    let skip = strokes.len().saturating_sub(MAX_STROKES);
    let mut weight = vec![1.0; strokes.len() - skip];
    for &i in &opts.suggested {
        if let Some(w) = (i as usize).checked_sub(skip).and_then(|k| weight.get_mut(k)) {
            *w = SUGGESTED_WEIGHT;
        }
    }
    let (earlier, strokes) = strokes.split_at(skip);
    // What a sequence (repetition by turns, not a lattice) is asked for.
    let ask = |rows: bool| sequence::Ask {
        count: if opts.fill { 64 } else { opts.count },
        region,
        offset: skip,
        seed: opts.variation.then_some(opts.seed),
        rows,
    };
    let accepted: Vec<bool> = weight.iter().map(|&w| w < 1.0).collect();
    let classification =
        classify_drawing(strokes, opts.path_tolerance, opts.width_tolerance, opts.color_tolerance, &accepted)?;
    // Copies along a drawn path that curves go where the path takes them (`along`).
    if let Some(s) = along::propose(strokes, &accepted, &ask(true), !opts.fill) {
        return Ok(s);
    }
    // Pen taps round a centre, half round or more, complete their ring (`taps`).
    if let Some(s) = taps::propose(strokes, &ask(true)) {
        return Ok(s);
    }
    // The repetition is one of motifs: a copy of a motif of several strokes is one
    // element, proposed whole (an accepted copy is one whose strokes all were).
    let motifs = &classification.motifs;
    let elems = classification.elements();
    let parts: Vec<usize> = motifs.instances.iter().map(Vec::len).collect();
    // A copy with fewer strokes than its kind's most is still being drawn (or was left
    // so): its centre is only estimated from the parts drawn, so it weighs little.
    let mut most = vec![0usize; motifs.kind.iter().map(|&k| k as usize + 1).max().unwrap_or(0)];
    for (&p, &k) in parts.iter().zip(&motifs.kind) {
        most[k as usize] = most[k as usize].max(p);
    }
    let whole = |x: usize| parts[x] >= most[motifs.kind[x] as usize];
    let weight: Vec<f64> = motifs
        .instances
        .iter()
        .enumerate()
        .map(|(x, g)| {
            // A copy of accepted strokes sits where the lattice put it and says nothing
            // new about it; one finished by hand is placed by its hand-drawn strokes only.
            let hand = g.iter().filter(|&&s| weight[s as usize] >= 1.0).count() as f64 / g.len() as f64;
            if whole(x) {
                hand.max(SUGGESTED_WEIGHT)
            } else {
                SUGGESTED_WEIGHT
            }
        })
        .collect();
    let Ok(mut spread) = Spread::new(&elems) else {
        // (Petals drawn from one centre touch there: one motif, no spacing; they may
        // still carry on one another.)
        return Ok(by_turns(strokes, &accepted, &ask(true)).unwrap_or_else(|| nothing(NO_SPACING)));
    };
    spread.spacing = spread.apart(&elems);
    let Some(mut fit) = Fit::find(&elems, &weight, &parts, &spread) else {
        // No lattice: the latest strokes may still repeat one another by turns (a ring
        // of petals, hatching that bends: see `sequence`).
        let unread =
            || nothing(if sequence::repeats(strokes, &accepted) { sequence::UNFOLLOWED } else { NO_REPETITION });
        return Ok(by_turns(strokes, &accepted, &ask(true)).unwrap_or_else(unread));
    };
    // A ring round a centre that holds the latest stroke turns its copies: they carry
    // on by turns, whatever lattice their places also fit (six petals round a drawn
    // disc lie on a triangular lattice with it, and a new user's complete rings of six
    // got lattice ghosts outside them in 15 of 25).
    if ring_holds_latest(strokes) {
        return Ok(sequence::propose(strokes, &accepted, &ask(true)).unwrap_or_else(|| nothing(sequence::UNFOLLOWED)));
    }
    // (So too a ring the sequence snaps to its count and that holds every copy of its
    // shape, where `chain::find` reads none: where the sequence then proposes nothing
    // itself, the lattice goes on.)
    if sequence::snapped_ring(strokes, &accepted, &ask(true)) {
        if let Some(s) = sequence::propose(strokes, &accepted, &ask(true)) {
            return Ok(s);
        }
    }
    let prior = (HAND_TO_PLACEMENT * hand_scatter(strokes, &classification.classes, &accepted))
        .clamp((MIN_SCATTER * spread.spacing).powi(2), (MAX_SCATTER * spread.spacing).powi(2));
    fit.certainty = fit.certainty(&elems, &weight, prior);
    let latest = motifs.instance_of()[strokes.len() - 1] as usize;
    if !whole(latest) {
        // (Unless its strokes carry on one another: the second ring of petals of a
        // drawing of rings, three petals in.)
        if let Some(s) = sequence::propose(strokes, &accepted, &ask(false)).filter(|s| !s.strokes.is_empty()) {
            return Ok(s);
        }
        return Ok(nothing("The copy being drawn is not finished: the next copies are proposed once it is."));
    }
    if fit.motif[fit.cell[latest].0].members.len() < 2 {
        // The lattice of the earlier copies does not hold the latest, but they may carry
        // on one another (a row that turns a corner: the leaves past it).
        return Ok(by_turns(strokes, &accepted, &ask(true)).unwrap_or_else(|| nothing(NOT_REPEATED)));
    }
    // A lattice carries its copies on by translation: where the latest two hand-drawn
    // copies of a place are both turned one way from its usual copy (leaves past the
    // corner of a row that turns, read as a lattice of the periods before and after it),
    // they may carry on one another by turns instead; so too where the row's latest
    // copies bend steadily as they go (fence posts along an arc: the row's ghosts went
    // straight on off it).
    if turned_away(&fit, strokes, &motifs.instances, &weight) || row_bends(&fit, &elems, &weight) {
        return Ok(by_turns(strokes, &accepted, &ask(true)).unwrap_or_else(|| nothing(sequence::UNFOLLOWED)));
    }
    let points = strokes.iter().map(|s| s.points.len().max(1)).sum::<usize>();
    let per_copy = points.div_ceil(elems.len()) * fit.motif.len();
    let extents = motifs.extents(strokes);
    let wanted = fit.wanted(&elems, region, opts, (MAX_FILL_POINTS / per_copy.max(1)).clamp(1, MAX_FILL_CELLS));
    let mut out = Suggestions {
        periods: std::iter::once(fit.a).chain(fit.b).map(|v| [v.x, v.y]).collect(),
        ..Suggestions::default()
    };
    // A copy drawn where the lattice (fitted to hand-drawn copies) no longer puts it is
    // still drawn: nothing is proposed on a stroke of its class.
    let tol = TOLERANCE * spread.spacing;
    // Strokes before the latest `MAX_STROKES` are only looked up where a copy would go
    // (a fill of the region over 50,000 of them scanned every one per copy: 10 s).
    let earlier_index = (!earlier.is_empty()).then(|| {
        let points: Vec<Point> = earlier.iter().map(Stroke::reference_point).collect();
        let bounds = points.iter().fold(Rect::from_points(points[0], points[0]), |r, &p| r.union_pt(p));
        let mut grid = Grid::new(bounds, tol, 2 * points.len() + 16);
        for (i, &p) in points.iter().enumerate() {
            grid.insert(i as u32, p);
        }
        (grid, points)
    });
    let drawn_at = |class: u32, p: Point, size: f64| {
        let mut hit = false;
        spread.grid.for_each_near(p, tol, |j| {
            let o = &elems[j as usize];
            hit |= o.class == class && o.pos.distance(p) < tol;
        });
        if let Some((grid, points)) = &earlier_index {
            grid.for_each_near(p, tol, |j| {
                let e = &earlier[j as usize];
                hit |= points[j as usize].distance(p) < tol
                    && (e.bounds().size().to_vec2().hypot() - size).abs() <= 0.25 * size;
            });
        }
        hit
    };
    let stacked = Stacked::new(strokes, &classification.classes, &accepted);
    // A row may bend: each motif position's hand-drawn copies along it, whose shapes
    // show how much its steps turn (see `drift`); of a motif of several strokes, the
    // largest part of its whole copies (a leaf's stalk a few pixels long shows little).
    // (Only a part half again the size of any other shows the motif's turn: a cross's
    // two bars, each turned a degree or two by the hand, read as a row that bends, and
    // three crosses got two ghosts where they had three.)
    let largest = |x: usize| {
        let size = |s: u32| strokes[s as usize].bounds().size().to_vec2().hypot();
        let mut parts: Vec<(f64, u32)> = motifs.instances[x].iter().map(|&s| (size(s), s)).collect();
        parts.sort_by(|a, b| b.0.total_cmp(&a.0));
        // (Or one that holds the others inside its box, as a leaf's outline its midrib:
        // without, leaves drawn with their midribs along a gentle wave were carried on
        // straight past its bend, their third ghost 0.6 of a step off.)
        let holds = parts[1..].iter().all(|&(_, s)| encloses(&strokes[parts[0].1 as usize], &strokes[s as usize]));
        let dominant = parts.get(1).is_none_or(|second| parts[0].0 > 1.5 * second.0) || holds;
        dominant.then(|| motifs.part[parts[0].1 as usize])
    };
    let hand_rows: Vec<Vec<(i64, &Stroke)>> = if fit.b.is_none() {
        fit.motif
            .iter()
            .map(|mp| {
                let part = mp.members.iter().copied().find(|&x| whole(x)).and_then(largest);
                let mut row: Vec<(i64, &Stroke)> = mp
                    .members
                    .iter()
                    .filter(|&&x| weight[x] >= 1.0 && whole(x))
                    .filter_map(|&x| {
                        let s = motifs.instances[x].iter().find(|&&s| Some(motifs.part[s as usize]) == part)?;
                        Some((fit.cell[x].1 .0, &strokes[*s as usize]))
                    })
                    .collect();
                row.sort_by_key(|r| r.0);
                row
            })
            .collect()
    } else {
        Vec::new()
    };
    let row_turn = drift::row_turn(&hand_rows);
    let mut uncertain = 0;
    for (m, cell, steps) in wanted {
        // Not so far ahead of the hand-drawn copies that the site is likely off by more
        // than the tolerance (fill is asked for explicitly and goes everywhere); a row
        // drifts as far as its turn may take it.
        let bent = match (row_turn, hand_rows.get(m).and_then(|r| Some((r.first()?.0, r.last()?.0)))) {
            (Some((turn, error)), Some((first, last))) => {
                let past = (cell.0 - last).max(first - cell.0).max(0);
                // (Two copies or more past the hand's, the turn it may hide too: see
                // `drift::row_turn`.)
                let turn = turn.abs() + if past >= 2 { error } else { 0.0 };
                drift::drift(fit.a.hypot(), turn, (last - first) as f64, past as f64)
            }
            _ => 0.0,
        };
        if !opts.fill && fit.certainty.reach() * fit.miss_at(m, cell).hypot(bent) > tol {
            uncertain += 1;
            continue;
        }
        let motif = &fit.motif[m];
        // Seeded by the place, so a copy keeps its look from one pen-up to the next.
        let mut rng = Rng::new(
            opts.seed
                ^ (m as u64).wrapping_mul(0x9E37_79B9_7F4A_7C15)
                ^ (cell.0 as u64).wrapping_mul(0xC2B2_AE3D)
                ^ (cell.1 as u64).wrapping_mul(0x1656_67B1),
        );
        // Variation among the drawn copies of this motif position only.
        let source = motif.members[rng.below(motif.members.len())];
        // A whole drawn copy (not one still being drawn) when varying.
        let copies: Vec<usize> = motif.members.iter().copied().filter(|&x| whole(x)).collect();
        let pick = if opts.variation && !copies.is_empty() { copies[rng.below(copies.len())] } else { source };
        let target = fit.site(m, cell);
        if drawn_at(elems[source].class, target, extents[pick].hypot() * 2.0) {
            continue;
        }
        let shift = target - motifs.centre[pick];
        if motifs.instances[pick].iter().any(|&s| {
            let s = s as usize;
            stacked.on(classification.classes[s], strokes[s].reference_point() + shift)
        }) {
            continue;
        }
        for &s in &motifs.instances[pick] {
            let part = motifs.part[s as usize];
            let named = motifs.instances[source].iter().copied().find(|&t| motifs.part[t as usize] == part);
            out.strokes.push(strokes[s as usize].translated(shift.x, shift.y));
            out.confidence.push(fit.quality * FALLOFF.powi(steps as i32));
            out.sources.push(named.unwrap_or(s) + skip as u32);
            out.cells.push([cell.0, cell.1]);
        }
    }
    if out.strokes.is_empty() && uncertain > 0 {
        // A row that bends (hatching along a turning contour) fits a lattice too loosely
        // to propose from: the latest strokes may still carry on one another; and where
        // they do, with nothing to add, the sequence says why (a ring of six, three
        // petals accepted, is complete, not uncertain).
        if let Some(s) = by_turns(strokes, &accepted, &ask(true)) {
            return Ok(s);
        }
    }
    if out.strokes.is_empty() {
        out.reason = Some(if uncertain > 0 {
            UNCERTAIN.into()
        } else {
            "Every copy of the repetition in the region is drawn.".into()
        });
    }
    Ok(out)
}

/// Whether `outline` is a closed loop with `part` inside it (a leaf's outline and its
/// midrib, most of whose points lie within: one end may touch the outline).
fn encloses(outline: &Stroke, part: &Stroke) -> bool {
    let ring = crate::vector::similarity::samples(outline);
    if !crate::vector::frechet::closed_loop(&ring) || part.points.is_empty() {
        return false;
    }
    let path = kurbo::BezPath::from_vec(
        std::iter::once(kurbo::PathEl::MoveTo(ring[0]))
            .chain(ring[1..].iter().map(|&p| kurbo::PathEl::LineTo(p)))
            .chain(std::iter::once(kurbo::PathEl::ClosePath))
            .collect(),
    );
    let inside = part.points.iter().filter(|p| kurbo::Shape::winding(&path, Point::new(p[0], p[1])) != 0).count();
    inside as f64 >= ENCLOSED * part.points.len() as f64
}

/// The share of a part's points inside an outline that holds it.
const ENCLOSED: f64 = 0.8;

/// Copies of the latest hand-drawn copy's place looked at for its usual turn.
const USUAL: usize = 16;

/// Strokes looked back over for a ring that holds the latest (rings are drawn
/// petal after petal: the ring is among the latest strokes).
const RING_LOOK_BACK: usize = 32;

/// Whether the latest strokes make a closed ring round a centre (`chain::find`: two
/// thirds of their shape's strokes there) that holds the latest stroke, as a petal or
/// a part of one (a stroke beside a petal, within its size: its vein or its dot; not
/// a petal of a second flower, which the lattice of flowers places whole), with no
/// other ring beside it (flowers on a lattice: the lattice places them).
fn ring_holds_latest(strokes: &[Stroke]) -> bool {
    let recent = &strokes[strokes.len().saturating_sub(RING_LOOK_BACK)..];
    let latest = recent.len() - 1;
    let Some(ring) = crate::vector::chain::find(recent).filter(|c| c.closes.is_some()) else { return false };
    let near = |k: usize, m: usize| {
        recent[k].reference_point().distance(recent[m].reference_point()) <= recent[m].bounds().size().to_vec2().hypot()
    };
    ring.members
        .iter()
        .zip(&ring.companions)
        .any(|(&m, parts)| m == latest || (parts.contains(&latest) && near(latest, m)))
        && crate::vector::chain::rings_beside(recent, &ring).is_empty()
}

/// Whether the latest two hand-drawn copies (of one stroke) of the latest one's motif
/// position are both turned by more than `TURNED` one way from the place's usual copy:
/// the median turn of its latest `USUAL` hand-drawn copies against its first. One copy
/// drawn askew, or a hand that turns its copies a little at random, is not; a dot,
/// whose turn is its pen's, says nothing (see `drift::turn_between`).
fn turned_away(fit: &Fit, strokes: &[Stroke], instances: &[Vec<u32>], weight: &[f64]) -> bool {
    let hand = |x: usize| weight[x] >= 1.0 && instances[x].len() == 1;
    let Some(last) = (0..fit.cell.len()).rev().find(|&x| hand(x)) else { return false };
    let copies: Vec<usize> = fit.motif[fit.cell[last].0].members.iter().copied().filter(|&x| hand(x)).collect();
    let (Some(&first), Some(&[before, latest])) = (copies.first(), copies.last_chunk::<2>()) else {
        return false;
    };
    if before == first || latest != last {
        return false;
    }
    let stroke = |x: usize| &strokes[instances[x][0] as usize];
    let recent = &copies[copies.len().saturating_sub(USUAL)..];
    // Each recent copy's turn from the first (read once: the latest two are among them).
    let read: Vec<Option<f64>> = recent
        .iter()
        .map(|&x| if x == first { Some(0.0) } else { drift::turn_between(stroke(first), stroke(x)) })
        .collect();
    let mut turns: Vec<f64> = read.iter().flatten().copied().collect();
    if turns.len() < 3 {
        return false;
    }
    let usual = median(&mut turns);
    let pi = std::f64::consts::PI;
    let off = |t: Option<f64>| t.map(|t| (t - usual + pi).rem_euclid(2.0 * pi) - pi);
    match (off(read[read.len() - 2]), off(read[read.len() - 1])) {
        (Some(a), Some(b)) => a.abs() > TURNED && b.abs() > TURNED && a.signum() == b.signum(),
        _ => false,
    }
}

/// Whether a lattice of one period is a row that bends: the latest hand-drawn copies of
/// its latest place, in drawing order, each move turned from the one before alike
/// (`chain::bend::steady_bend`).
fn row_bends(fit: &Fit, elems: &[Element], weight: &[f64]) -> bool {
    let Some(last) = (0..fit.cell.len()).rev().find(|&x| weight[x] >= 1.0) else { return false };
    if fit.b.is_some() {
        return false;
    }
    let copies: Vec<Point> =
        fit.motif[fit.cell[last].0].members.iter().filter(|&&x| weight[x] >= 1.0).map(|&x| elems[x].pos).collect();
    let recent = &copies[copies.len().saturating_sub(BENDS_OVER)..];
    let turns = crate::vector::chain::bend::move_turns(recent);
    turns.len() >= BENDS_READ && crate::vector::chain::bend::steady_bend(&turns).is_some()
}

/// A row's bend is read over this many of its latest copies, from at least this many
/// turns (a shaky hand's hatching, read from two, bent off its row).
const BENDS_OVER: usize = 6;
const BENDS_READ: usize = 3;

/// Where a proposed stroke would stack on a drawn one: a stroke of its class within
/// half the distance at which the hand puts two strokes of that class (the median of
/// each hand-drawn stroke's nearest of its class). Whatever lattice a fit reads, two
/// copies of one part are never that close; a refit that moves the lattice's origin
/// (after the hand contradicts an accepted copy) must not propose the drawn copies
/// again beside themselves.
struct Stacked<'a> {
    /// Each stroke's reference point, computed once: `on` runs for every part of every
    /// proposed copy (a fill proposes thousands).
    points: Vec<Point>,
    classes: &'a [u32],
    radius: Vec<f64>,
}

impl<'a> Stacked<'a> {
    fn new(strokes: &[Stroke], classes: &'a [u32], accepted: &[bool]) -> Self {
        let count = classes.iter().map(|&c| c as usize + 1).max().unwrap_or(0);
        let points: Vec<Point> = strokes.iter().map(Stroke::reference_point).collect();
        let mut nearest = vec![Vec::new(); count];
        for i in (0..strokes.len()).filter(|&i| !accepted[i]) {
            let d = (0..strokes.len())
                .filter(|&j| j != i && classes[j] == classes[i])
                .map(|j| points[i].distance(points[j]))
                .filter(|&d| d > 0.0)
                .fold(f64::INFINITY, f64::min);
            if d.is_finite() {
                nearest[classes[i] as usize].push(d);
            }
        }
        let radius = nearest.iter_mut().map(|d| if d.is_empty() { 0.0 } else { 0.5 * median(d) }).collect();
        Stacked { points, classes, radius }
    }

    fn on(&self, class: u32, p: Point) -> bool {
        let r = self.radius.get(class as usize).copied().unwrap_or(0.0);
        r > 0.0 && self.points.iter().zip(self.classes).any(|(q, &c)| c == class && q.distance(p) < r)
    }
}
