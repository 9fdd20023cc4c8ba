//! The vector engine end to end: classify, grow, dress the grown elements with strokes,
//! write SVG. This is the entry point the wasm layer and the tests call.

use super::chain::{self, Bending, Chain, Structure};
use super::classify::{classify, median, propose_tolerances, Tolerances};
use super::grow::{find_periods, fit_lattice, grow, Element, GrowOptions, Grown};
use super::mesh::Mesh;
use super::motif::{self, Motifs};
use super::pack;
use super::period::Periods;
use super::reference::Spread;
use super::rosette;
use super::stroke::Stroke;
use super::svg::to_svg;
use crate::error::{invalid, Error, Result};
use crate::progress::{Progress, Throttle};
use kurbo::{Point, Rect};
use serde::{Deserialize, Serialize};

/// Options of `synthesize_strokes`; every tolerance left out is proposed from the data.
#[derive(Clone, Debug, Deserialize)]
#[serde(rename_all = "camelCase", default, deny_unknown_fields)]
pub struct StrokeOptions {
    pub width: f64,
    pub height: f64,
    /// e1: Fréchet distance between centred paths.
    pub path_tolerance: Option<f64>,
    /// e2: stroke width difference.
    pub width_tolerance: Option<f64>,
    /// e3: RGB distance of stroke and of fill colours.
    pub color_tolerance: Option<f64>,
    /// Each output element takes a random member of its class (else its own stroke).
    pub variation: bool,
    pub seed: u64,
    /// Support ratio of the growth rule (SPEC 1.3).
    pub support: f64,
    /// Refuse outputs with more elements than this.
    pub max_elements: usize,
    /// Grow on the example's fitted lattice so large outputs do not drift (each element
    /// keeps its hand-drawn deviation); off grows on the drawn positions as they are.
    pub regularize: bool,
    /// The two period vectors `[[ax, ay], [bx, by]]` to repeat the drawing on, when the
    /// ones it shows are wrong or missing (one motif drawn once repeats on them as it
    /// is); none: found in the drawing.
    pub periods: Option<[[f64; 2]; 2]>,
}

impl Default for StrokeOptions {
    fn default() -> Self {
        let g = GrowOptions::default();
        StrokeOptions {
            width: g.width,
            height: g.height,
            path_tolerance: None,
            width_tolerance: None,
            color_tolerance: None,
            variation: true,
            seed: 1,
            support: g.support,
            max_elements: g.max_elements,
            regularize: g.regularize,
            periods: None,
        }
    }
}

/// How the input was classified.
#[derive(Clone, Debug, Serialize)]
#[serde(rename_all = "camelCase")]
pub struct Classification {
    /// Class of each input stroke, numbered by first appearance.
    pub classes: Vec<u32>,
    pub count: u32,
    /// The motif instance (a drawn copy of a motif of one or more strokes) of each stroke.
    pub instances: Vec<u32>,
    /// Kinds of motif (instances that are copies of one another).
    pub kinds: u32,
    /// The tolerances used (the proposal where the caller gave none).
    pub tolerances: Tolerances,
    /// The automatic proposal, to show as a starting point.
    pub proposed: Tolerances,
    /// The drawing as motif instances: what growth, tiles and suggestions place.
    #[serde(skip)]
    pub motifs: Motifs,
}

impl Classification {
    /// Each motif instance as a point element: its centre and kind.
    pub fn elements(&self) -> Vec<Element> {
        self.motifs.elements()
    }
}

#[derive(Clone, Debug, Serialize)]
#[serde(rename_all = "camelCase")]
pub struct StrokeResult {
    pub strokes: Vec<Stroke>,
    /// Class of each output stroke.
    pub classes: Vec<u32>,
    /// Index of the input stroke each output stroke's position copies.
    pub sources: Vec<u32>,
    pub classification: Classification,
    pub svg: String,
    /// The periods the output repeats on (found, fitted or given), `[[ax, ay], [bx, by]]`;
    /// none when it was grown freely (irregular input).
    pub periods: Option<[[f64; 2]; 2]>,
    /// What the drawing was repeated on: a lattice, a ring (completed, and repeated as
    /// a rosette where it is small beside the output), a curve or a sequence (continued
    /// along its step), or nothing (irregular: a mosaic or a mesh).
    pub structure: Structure,
    pub growing_points: usize,
    pub skipped_full: usize,
    pub passed_over: usize,
}

/// The most example strokes classified at once: each is compared with its neighbours,
/// and grouping them into motifs measures their gaps (50,000 take about 3.5 s in wasm).
pub const MAX_EXAMPLE_STROKES: usize = 50_000;
/// The most points the example strokes may hold together.
pub const MAX_EXAMPLE_POINTS: usize = 5_000_000;

fn check_strokes(strokes: &[Stroke]) -> Result<()> {
    if strokes.is_empty() {
        return invalid("There are no strokes: draw some or import an SVG first.");
    }
    if strokes.len() > MAX_EXAMPLE_STROKES {
        return Err(Error::TooLarge(format!(
            "There are {} example strokes; the limit is {MAX_EXAMPLE_STROKES} (each is compared with its \
             neighbours). Use an excerpt of the drawing.",
            strokes.len()
        )));
    }
    let points: usize = strokes.iter().map(|s| s.points.len()).sum();
    if points > MAX_EXAMPLE_POINTS {
        return Err(Error::TooLarge(format!(
            "The example strokes hold {points} points; the limit is {MAX_EXAMPLE_POINTS}. Simplify them \
             (import the SVG with a larger tolerance) or use an excerpt."
        )));
    }
    strokes.iter().enumerate().try_for_each(|(i, s)| s.validate(i))
}

/// Classifies `strokes`, filling in any tolerance left out with the proposal.
pub fn classify_strokes(
    strokes: &[Stroke],
    path: Option<f64>,
    width: Option<f64>,
    color: Option<f64>,
) -> Result<Classification> {
    classify_drawing(strokes, path, width, color, &[])
}

/// `classify_strokes` on a drawing in which the strokes marked in `accepted` are
/// accepted suggestions: exact translates of drawn copies, which say nothing of whether
/// the hand repeats its strokes exactly (see `motif::group`).
pub(crate) fn classify_drawing(
    strokes: &[Stroke],
    path: Option<f64>,
    width: Option<f64>,
    color: Option<f64>,
    accepted: &[bool],
) -> Result<Classification> {
    check_strokes(strokes)?;
    for (name, v) in [("path", path), ("width", width), ("colour", color)] {
        if v.is_some_and(|v| !v.is_finite() || v < 0.0) {
            return invalid(format!("The {name} tolerance must be a number of at least 0."));
        }
    }
    let proposed = propose_tolerances(strokes);
    let tolerances = Tolerances {
        path: path.unwrap_or(proposed.path),
        width: width.unwrap_or(proposed.width),
        color: color.unwrap_or(proposed.color),
    };
    let classes = classify(strokes, &tolerances);
    // Motifs of several strokes, unless the strokes repeat one by one (an exact tile).
    let elements = |classes: &[u32]| -> Vec<Element> {
        strokes.iter().zip(classes).map(|(s, &class)| Element { pos: s.reference_point(), class }).collect()
    };
    // Exact periods (a tile repeated), and the lattice a hand's copies are drawn on.
    let periods = |classes: &[u32]| find_periods(&elements(classes)).ok().flatten();
    let lattice = |classes: &[u32]| lattice_of(&elements(classes));
    let grouping = motif::group(strokes, &classes, tolerances, path.is_some(), accepted, periods, lattice);
    let classes = grouping.classes.unwrap_or(classes);
    let count = classes.iter().max().map_or(0, |m| m + 1);
    let motifs = grouping.motifs;
    let kinds = motifs.kind.iter().max().map_or(0, |m| m + 1);
    Ok(Classification { classes, count, instances: motifs.instance_of(), kinds, tolerances, proposed, motifs })
}

/// The most elements any output may hold, whatever `maxElements` says.
pub const MAX_ELEMENTS_CEILING: usize = 2_000_000;
/// The most points an output's strokes may hold together (about 20 bytes each as SVG).
pub const MAX_OUTPUT_POINTS: usize = 20_000_000;

/// Synthesizes a `width x height` pattern from the example `strokes`.
pub fn synthesize_strokes(
    strokes: &[Stroke],
    opts: &StrokeOptions,
    progress: &mut dyn Progress,
) -> Result<StrokeResult> {
    // (Checked here as well as in growth: a ring or a curve never reaches it.)
    if !(opts.width.is_finite() && opts.height.is_finite() && opts.width > 0.0 && opts.height > 0.0) {
        return invalid("Output width and height must be positive numbers.");
    }
    if !(opts.support.is_finite() && opts.support > 0.0 && opts.support <= 1.0) {
        return invalid("The support ratio must be in (0, 1].");
    }
    if opts.max_elements > MAX_ELEMENTS_CEILING {
        return Err(Error::TooLarge(format!(
            "maxElements can be raised to at most {MAX_ELEMENTS_CEILING} (the memory of the output), not {}.",
            opts.max_elements
        )));
    }
    let periods = super::lattice::given_periods(opts.periods)?;
    let classification = classify_strokes(strokes, opts.path_tolerance, opts.width_tolerance, opts.color_tolerance)?;
    // The output's size is its points, not only its elements: busy motifs lower the cap.
    let instances = classification.motifs.instances.len().max(1);
    let mean_points = strokes.iter().map(|s| s.points.len().max(1)).sum::<usize>() / instances;
    let max_elements = opts.max_elements.min(MAX_OUTPUT_POINTS / mean_points.max(1));
    // A limit lowered by the points says so: "the limit is 80000" beside a maxElements
    // of 2,000,000 reads as a bug.
    let explain = |e: Error| match e {
        Error::TooLarge(m) if max_elements < opts.max_elements => {
            let why = format!(
                " (not maxElements' {}: each element here holds about {mean_points} points, and an output may hold {MAX_OUTPUT_POINTS} points in all)",
                opts.max_elements
            );
            let said = [format!("the limit is {max_elements}"), format!("the limit of {max_elements} elements")];
            Error::TooLarge(match said.iter().find(|s| m.contains(s.as_str())) {
                Some(s) => m.replacen(s.as_str(), &format!("{s}{why}"), 1),
                None => format!("{m}{why}"),
            })
        }
        e => e,
    };
    Throttle::new(progress).tick(0.02)?;
    let elements = classification.elements();
    let motifs = &classification.motifs;
    let grow_opts = GrowOptions {
        width: opts.width,
        height: opts.height,
        support: opts.support,
        max_elements,
        regularize: opts.regularize,
        extents: motifs.extents(strokes),
        seed: opts.seed,
        periods,
        ..GrowOptions::default()
    };
    // Copies touching a curving stroke drawn once (a stem and its leaves) go all along it
    // (`suggest::along`), which neither a lattice nor a similarity step reads: from three
    // leaves on a drawn sine, a chain went off the stem in a spiral.
    if periods.is_none() {
        let seed = opts.variation.then_some(opts.seed);
        if let Some(more) = super::suggest::along::fill(strokes, seed, max_elements + 1) {
            return along_path(strokes, classification, more, opts, max_elements, progress).map_err(explain);
        }
    }
    let area = Rect::new(0.0, 0.0, opts.width, opts.height);
    let mut throttle = Throttle::with_range(progress, 0.02, 0.98);
    // A mesh (pieces that share their edges) is joined afresh, not placed piece by piece,
    // unless it repeats exactly (a tile repeated extends exactly as it is).
    let mesh = if motifs.copies.is_none() && periods.is_none() { Mesh::of(strokes) } else { None };
    let joined = match mesh {
        Some(mesh) => mesh.synthesize(strokes, area, &grow_opts, &mut throttle).map_err(explain)?,
        None => None,
    };
    // A drawing with no lattice may repeat along a similarity step: a ring, an arc, a
    // spiral (`chain`). A rosette (copies turned round a centre close by) is taken
    // before a lattice: a lattice read from a handful of petals is a chance one.
    // (Beside a ring, the drawing's other rings: two flowers side by side.)
    // (Whether the elements translate is asked once, and only where it decides.)
    let translated = std::cell::OnceCell::new();
    let lattice = || *translated.get_or_init(|| translates(&elements));
    // A ring of circles or taps is read by place first (`chain::find_by_place`): their
    // shapes show no turn for the search to read. (It holds though its copies are exact
    // ones: ghosts accepted round a ring of pen taps are the drawn taps' exact
    // translates, and it was read as an exact tile on a lattice.)
    let free = joined.is_none() && periods.is_none();
    let placed = free.then(|| chain::find_by_place(strokes)).flatten().map(|ring| (ring, true));
    let along = placed
        .or_else(|| (free && motifs.copies.is_none()).then(|| chain::find_or_ring(strokes)).flatten())
        .filter(|(_, whole)| *whole || !lattice())
        .map(|(c, whole)| {
            let beside = if c.closes.is_some() { chain::rings_beside(strokes, &c) } else { Vec::new() };
            (c, beside, whole)
        })
        .filter(|(c, beside, _)| {
            let held = c.strokes() + beside.iter().map(Chain::strokes).sum::<usize>();
            (c.closes.is_some() && 3 * held >= 2 * strokes.len()) || c.upright || !lattice()
        });
    // Copies along a curve whose turn changes (leaves along a wave or an S, no stem
    // drawn): no one step carries them. A chain read from them (a turn that carries each
    // leaf near the next, or a ring of a few of them) went on round a circle or closed
    // into rosettes, and with none, grown, they were a scatter (`chain::bending`). Where
    // no chain holds, a curve whose turn does not change goes on so too.
    let bending = (joined.is_none() && periods.is_none() && motifs.copies.is_none())
        .then(|| chain::find_bending(strokes))
        .flatten()
        .filter(|b| match &along {
            Some((c, _, whole)) => {
                let open = c.closes.is_none() && c.structure() == Structure::Curve;
                b.changes && !c.upright && (open || !whole)
            }
            None => !lattice(),
        });
    if let Some(bending) = bending {
        return along_bending(strokes, classification, &bending, opts, max_elements, progress).map_err(explain);
    }
    if let Some((chain, beside, _)) = along {
        return along_chain(strokes, classification, chain, beside, opts, max_elements, progress).map_err(explain);
    }
    let meshed = joined.is_some();
    // A row (hatching along a straight contour) grows along its one period: a lattice
    // too, though it has no second period to report. Three strokes are too few to call
    // a row (three petals of a ring lie about as evenly), but what grew from them is
    // not: three hatching lines grown into a row of 89 were called irregular.
    let (out, classes, sources, stats, periods, row) = if let Some(j) = joined {
        let classes = j.sources.iter().map(|&s| classification.classes[s as usize]).collect();
        (j.strokes, classes, j.sources, j.grown.stats, j.grown.periods, false)
    } else {
        let Grown { placed, stats, orbit, periods } = grow(&elements, &grow_opts, &mut throttle).map_err(explain)?;
        // (What grew is looked at only where the drawing is too few to say and no period
        // does: it may hold many thousands of elements.)
        let row = periods.is_none()
            && if elements.len() >= 4 {
                straight_row(&elements.iter().map(|e| e.pos).collect::<Vec<_>>())
            } else {
                straight_row(&placed.iter().map(|p| p.pos).collect::<Vec<_>>())
            };
        let (out, classes, sources) =
            motifs.dress(strokes, &classification.classes, &placed, &orbit, opts.variation.then_some(opts.seed), area);
        (out, classes, sources, stats, periods, row)
    };
    let structure = if !meshed && (periods.is_some() || row) { Structure::Lattice } else { Structure::Irregular };
    // A drawing too few and too loose to grow from (four leaves in an S the engine reads
    // no step of: growth added nothing, and Synthesize gave back the drawing alone) is
    // repeated whole over the output, as a finished curve is.
    if structure == Structure::Irregular && !meshed && out.len() <= strokes.len() {
        let v = centring(strokes, area);
        let drawn = strokes.iter().map(|s| s.translated(v.x, v.y)).collect();
        let sources = (0..strokes.len() as u32).collect();
        return continued(drawn, sources, classification, opts, structure, max_elements, progress);
    }
    Throttle::new(progress).tick(1.0)?;
    Ok(StrokeResult {
        periods: periods.map(|(a, b)| [[a.x, a.y], [b.x, b.y]]),
        growing_points: stats.growing_points,
        skipped_full: stats.skipped_full,
        passed_over: stats.passed_over,
        ..StrokeResult::new(out, classes, sources, classification, opts, structure)
    })
}

impl StrokeResult {
    /// The output strokes with their SVG; no periods and no growth figures.
    fn new(
        strokes: Vec<Stroke>,
        classes: Vec<u32>,
        sources: Vec<u32>,
        classification: Classification,
        opts: &StrokeOptions,
        structure: Structure,
    ) -> StrokeResult {
        let svg = to_svg(&strokes, &classes, opts.width, opts.height);
        StrokeResult {
            strokes,
            classes,
            sources,
            classification,
            svg,
            periods: None,
            structure,
            growing_points: 0,
            skipped_full: 0,
            passed_over: 0,
        }
    }
}

/// The periods `elems` repeat on: exact ones (a tile repeated), or the lattice a hand's
/// copies are drawn on.
fn lattice_of(elems: &[Element]) -> Option<Periods> {
    find_periods(elems).ok().flatten().or_else(|| fit_lattice(elems).ok().flatten()?.periods(elems))
}

/// Whether elements at `pos` make one straight row of four or more (three petals of a
/// ring lie about as evenly): evenly spaced along their principal axis
/// (every gap within half the median gap of it) and off its line by at most a quarter
/// of that gap. (A lattice fit reads a row into leaves along an S, which growth turns
/// into a scatter.)
fn straight_row(pos: &[Point]) -> bool {
    let n = pos.len();
    if n < 4 {
        return false;
    }
    let (mean, axis) = chain::bend::principal_axis(pos);
    let mut along: Vec<f64> = pos.iter().map(|p| (p.to_vec2() - mean).dot(axis)).collect();
    crate::order::floats(&mut along);
    let mut gaps: Vec<f64> = along.windows(2).map(|w| w[1] - w[0]).collect();
    let gap = median(&mut gaps.clone());
    gaps.retain(|g| (g - gap).abs() > 0.5 * gap);
    gap > 0.0 && gaps.is_empty() && pos.iter().all(|p| (p.to_vec2() - mean).cross(axis).abs() <= 0.25 * gap)
}

/// Whether the motif elements repeat by translation: only a drawing that does not is
/// searched for a chain (a rosette aside).
///
/// A lattice whose shorter period is well under the spacing of the drawn copies (under
/// `CHANCE` of their median nearest neighbour) is a chance one: any two sites of a
/// lattice are at least its shorter period apart, so a person who drew it would have
/// drawn some copies that close. Five leaves on a tight arc fit such a lattice (periods
/// of 26 and 61 beside a spacing of 62, each step a different lattice vector), and
/// growing it laid 654 overlapping leaves where the arc should have continued.
fn translates(elements: &[Element]) -> bool {
    const CHANCE: f64 = 0.75;
    if elements.len() > chain::MAX_STROKES {
        return true;
    }
    let Some(p) = (elements.len() >= 2).then(|| lattice_of(elements)).flatten() else {
        return false;
    };
    match Spread::new(elements) {
        Ok(spread) => p.a.hypot().min(p.b.hypot()) >= CHANCE * spread.spacing,
        Err(_) => true,
    }
}

/// The drawing, in the middle of the output, with `more` copies along its path (each
/// with the stroke it repeats: `suggest::along::fill`).
fn along_path(
    strokes: &[Stroke],
    classification: Classification,
    more: Vec<(Stroke, usize)>,
    opts: &StrokeOptions,
    max_elements: usize,
    progress: &mut dyn Progress,
) -> Result<StrokeResult> {
    if strokes.len() + more.len() > max_elements {
        return Err(too_large(max_elements));
    }
    let area = Rect::new(0.0, 0.0, opts.width, opts.height);
    let v = centring(strokes, area);
    let (out, sources): (Vec<Stroke>, Vec<u32>) = strokes
        .iter()
        .cloned()
        .enumerate()
        .chain(more.into_iter().map(|(s, from)| (from, s)))
        .map(|(from, s)| (s.translated(v.x, v.y), from as u32))
        .unzip();
    continued(out, sources, classification, opts, Structure::Curve, max_elements, progress)
}

/// The drawing repeated along its `chain`, centred in the output. A ring is completed,
/// and so is each of the drawing's other rings (`beside`); small beside the output, the
/// drawing is then repeated as rosettes (`rosette::lattice`). A larger ring, a curve or
/// a sequence is continued both ways across the output (a ring until it closes). Other
/// strokes stay as drawn (in a rosette, they repeat with it).
fn along_chain(
    strokes: &[Stroke],
    classification: Classification,
    chain: Chain,
    beside: Vec<Chain>,
    opts: &StrokeOptions,
    max_elements: usize,
    progress: &mut dyn Progress,
) -> Result<StrokeResult> {
    let area = Rect::new(0.0, 0.0, opts.width, opts.height);
    let v = centring(strokes, area);
    let drawn: Vec<Stroke> = strokes.iter().map(|s| s.translated(v.x, v.y)).collect();
    let chain = chain.moved(v);
    let seed = opts.variation.then_some(opts.seed);
    let mut out = drawn.clone();
    let mut sources: Vec<u32> = (0..strokes.len() as u32).collect();
    if let Some(c) = chain.centre() {
        // Every ring of the drawing completed (two flowers side by side are two rings),
        // each stroke with the ring it belongs to (none: a stroke of no ring).
        let rings: Vec<Chain> = std::iter::once(chain.clone()).chain(beside.iter().map(|r| r.moved(v))).collect();
        let mut ring_of: Vec<Option<usize>> = vec![None; out.len()];
        for (i, ring) in rings.iter().enumerate() {
            ring.held().for_each(|k| ring_of[k] = Some(i));
            for (s, from) in ring.complete(&out.clone(), seed) {
                out.push(s);
                sources.push(from as u32);
                ring_of.push(Some(i));
            }
        }
        if let Some(lattice) = rosette::lattice(&out, &ring_of, &rings, c, area) {
            return repeated(&out, &sources, lattice, classification, opts, Structure::Ring, progress);
        }
        // (The first ring is completed as the chain is extended; the others stay
        // completed.)
        (out, sources) = out
            .into_iter()
            .zip(sources)
            .enumerate()
            .filter(|&(k, _)| k < strokes.len() || ring_of[k] != Some(0))
            .map(|(_, kept)| kept)
            .unzip();
    }
    // (Past the limit, an error as for a lattice, not the output cut short.)
    let (more, capped) = chain.extend(&drawn, area, seed, max_elements.saturating_sub(out.len()));
    if capped || out.len() > max_elements {
        return Err(too_large(max_elements));
    }
    for (s, from) in more {
        out.push(s);
        sources.push(from as u32);
    }
    continued(out, sources, classification, opts, chain.structure(), max_elements, progress)
}

/// The move that centres the drawing's box in `area`.
fn centring(strokes: &[Stroke], area: Rect) -> kurbo::Vec2 {
    let bounds = strokes.iter().skip(1).fold(strokes[0].bounds(), |r, s| r.union(s.bounds()));
    area.center() - bounds.center()
}

/// The drawing, centred in the output, with its curve carried on past each end by the
/// end's own step (`Bending::ends`).
fn along_bending(
    strokes: &[Stroke],
    classification: Classification,
    bending: &Bending,
    opts: &StrokeOptions,
    max_elements: usize,
    progress: &mut dyn Progress,
) -> Result<StrokeResult> {
    let area = Rect::new(0.0, 0.0, opts.width, opts.height);
    let v = centring(strokes, area);
    let drawn: Vec<Stroke> = strokes.iter().map(|s| s.translated(v.x, v.y)).collect();
    let seed = opts.variation.then_some(opts.seed);
    let mut out = drawn.clone();
    let mut sources: Vec<u32> = (0..strokes.len() as u32).collect();
    for (end, by) in &bending.ends {
        let room = max_elements.saturating_sub(out.len());
        let end = end.moved(v);
        let (more, capped) = end.extend_by(&drawn, area, seed, room, [*by as i64, 0]);
        if capped {
            return Err(too_large(max_elements));
        }
        // Copy by copy (its stroke and its others), none where a stroke is already
        // placed within half a step: a curve whose end curls back, or a C whose ends
        // nearly meet, would lay two leaves in one place.
        let c = drawn[end.members[0]].reference_point();
        let near = 0.5 * end.step.apply(c).distance(c);
        // (Each copy begins with its member's stroke, kept wherever the copy is; its
        // others only inside the output.)
        let member = end.members[0];
        for copy in more.chunk_by(|_, (_, from)| *from != member) {
            let at = copy[0].0.reference_point();
            if out.iter().any(|s| s.reference_point().distance(at) < near) {
                break;
            }
            for (s, from) in copy {
                out.push(s.clone());
                sources.push(*from as u32);
            }
        }
    }
    continued(out, sources, classification, opts, Structure::Curve, max_elements, progress)
}

/// A curve continued as far as it goes, or an irregular drawing too few to grow from
/// (`out`, each stroke with the drawn one it repeats; a ring or a spiral is returned
/// as it is), repeated over the output where
/// the output holds it at least twice along a
/// side (`pack::curve`), the rows as far apart as its copies along it, each copy whole
/// (`pack::moves`): leaves on a drawn arc were one arc in the middle of the page's
/// 1200 x 800 output, and a vine drawn across the page one vine. The periods are
/// reported where copies lie side by side (bricked rows); rows of one copy each repeat
/// on one period only, as a row does.
fn continued(
    out: Vec<Stroke>,
    sources: Vec<u32>,
    classification: Classification,
    opts: &StrokeOptions,
    structure: Structure,
    max_elements: usize,
    progress: &mut dyn Progress,
) -> Result<StrokeResult> {
    let classes: Vec<u32> = sources.iter().map(|&i| classification.classes[i as usize]).collect();
    let area = Rect::new(0.0, 0.0, opts.width, opts.height);
    let Some(bounds) = pack::inked_bounds(&out) else {
        return Ok(StrokeResult::new(out, classes, sources, classification, opts, structure));
    };
    // (A curve only: a ring is a rosette or the output's, by `rosette::lattice`; a
    // spiral is one. And only where even with no gap the output would hold it twice:
    // the spacing reads every copy.)
    let repeats =
        matches!(structure, Structure::Curve | Structure::Irregular) && pack::curve(bounds, 0.0, area).is_some();
    let lattice =
        repeats.then(|| pack::spacing(&out, &classes)).flatten().and_then(|gap| pack::curve(bounds, gap, area));
    let Some(lattice) = lattice else {
        Throttle::new(progress).tick(1.0)?;
        return Ok(StrokeResult::new(out, classes, sources, classification, opts, structure));
    };
    let Some(moves) = pack::moves(bounds, lattice, area, max_elements / out.len()) else {
        return Err(too_large(max_elements));
    };
    let (mut all, mut from, mut of) = (Vec::new(), Vec::new(), Vec::new());
    for v in moves {
        all.extend(out.iter().map(|s| s.translated(v.x, v.y)));
        from.extend_from_slice(&sources);
        of.extend_from_slice(&classes);
    }
    Throttle::new(progress).tick(1.0)?;
    Ok(StrokeResult {
        periods: pack::side_by_side(lattice).then_some(lattice),
        ..StrokeResult::new(all, of, from, classification, opts, structure)
    })
}

/// The error of an output past `max_elements`, as a lattice's says it.
fn too_large(max_elements: usize) -> Error {
    Error::TooLarge(format!(
        "This output would hold more than {max_elements} elements; the limit is {max_elements}. Use a smaller output or larger strokes."
    ))
}

/// The finished drawing `out` (each stroke with the drawn one it repeats, `sources`)
/// repeated on `lattice` over the output (the lattice engine's, with periods given),
/// reported as `structure`, with the drawing's own classes.
fn repeated(
    out: &[Stroke],
    sources: &[u32],
    lattice: [[f64; 2]; 2],
    classification: Classification,
    opts: &StrokeOptions,
    structure: Structure,
    progress: &mut dyn Progress,
) -> Result<StrokeResult> {
    let mut r = synthesize_strokes(out, &StrokeOptions { periods: Some(lattice), ..opts.clone() }, progress)?;
    r.sources = r.sources.iter().map(|&i| sources[i as usize]).collect();
    r.classes = r.sources.iter().map(|&i| classification.classes[i as usize]).collect();
    r.svg = to_svg(&r.strokes, &r.classes, opts.width, opts.height);
    r.classification = classification;
    r.structure = structure;
    Ok(r)
}
