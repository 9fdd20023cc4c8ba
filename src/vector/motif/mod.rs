//! The motif: the unit of repetition that growth, periodic extension, the mosaic, tiles
//! and suggestions all place.
//!
//! A person draws a motif of several strokes a few times (a cross of two bars, a flower
//! of five petals and a dot), each copy a little different. Read stroke by stroke, the
//! bars of a cross share a centre, so the nearest-neighbour spacing is a fraction of a
//! unit and no period fits; and a hand's variation, as large as the difference between
//! the parts, merges the parts into one class. Here the drawing is read as instances
//! (the strokes of one drawn copy, `contact`) of kinds (instances that are copies of one
//! another, `kinds`): each instance becomes one point element at its centre, of its
//! kind's class, and whatever places elements places whole motifs. Each placed motif is
//! then dressed with the strokes of a drawn copy of that very motif, so a part is never
//! put where another belongs.
//!
//! An example whose strokes are periodic one by one (an SVG tile repeated exactly) keeps
//! its strokes as elements: its periodic extension is exact as it is, and pieces cut at a
//! tile's edge that abut in the repeat would otherwise join across copies.

mod cells;
mod complete;
pub(crate) mod contact;
mod kinds;

use super::element::{Element, Placed};
use super::period::Periods;
use super::stroke::Stroke;
use crate::rng::Rng;
use kurbo::{Point, Rect, Vec2};

/// The drawing as motif instances.
#[derive(Clone, Debug, Default)]
pub struct Motifs {
    /// Strokes of each instance, in drawing order; instances by their first stroke.
    pub instances: Vec<Vec<u32>>,
    /// Kind of each instance (the class of its element).
    pub kind: Vec<u32>,
    /// Each instance's centre: the mean of its strokes' reference points.
    pub centre: Vec<Point>,
    /// Part of each stroke within its kind (0 for instances of one stroke).
    pub part: Vec<u32>,
    /// In an exact repeat (an SVG tile repeated), each instance's group of exact copies:
    /// variation keeps to them, since the paper's class may join unlike shapes (lines of
    /// several lengths) at places a period of that class maps onto one another.
    pub copies: Option<Vec<u32>>,
}

/// What `group` found: the motifs, and the stroke classes when they come from them.
pub struct Grouping {
    pub motifs: Motifs,
    /// Stroke classes by the motifs' evidence (`None`: keep the paper's classes).
    pub classes: Option<Vec<u32>>,
}

/// Reads `strokes` (with the paper's `classes` and tolerances) as motif instances.
/// `periods` gives the exact periods of the strokes one by one under some classes, and
/// `lattice` the periods or the lattice they are drawn on (a hand's copies).
/// - An exact repeat (most strokes have exact copies, and it is periodic with its copies
///   as classes, as an SVG tile repeated is): strokes stay their own instances, of their
///   paper classes, and their copies are kept for variation. Strokes marked `accepted`
///   (suggestions accepted, exact translates of drawn ones) are left out of "most".
/// - Strokes drawn on one another in compact, repeated copies: motif instances, classes
///   by the motifs' evidence (even when the strokes are periodic one by one: a copy's
///   parts then keep the relation the hand gave them, a cross's bars meet as drawn).
/// - Otherwise every stroke is its own instance, of its paper class.
pub fn group(
    strokes: &[Stroke],
    classes: &[u32],
    tol: super::classify::Tolerances,
    explicit_path: bool,
    accepted: &[bool],
    periods: impl Fn(&[u32]) -> Option<Periods>,
    lattice: impl Fn(&[u32]) -> Option<Periods>,
) -> Grouping {
    let copies = super::classify::copies(strokes);
    let mut count = vec![0usize; strokes.len()];
    copies.iter().for_each(|&g| count[g as usize] += 1);
    let hand = |i: usize| !accepted.get(i).copied().unwrap_or(false);
    let copied = (0..strokes.len()).filter(|&i| hand(i) && count[copies[i] as usize] >= 2).count();
    let drawn = (0..strokes.len()).filter(|&i| hand(i)).count();
    // Periodic with the copies as classes: a drawing and its accepted suggestions (exact
    // copies of drawn strokes among the hand's own) is not, since the hand's strokes have
    // no copies one period on.
    if 2 * copied >= drawn && periods(&copies).is_some() && periods(classes).is_some() {
        let motifs = Motifs { copies: Some(copies), ..Motifs::single(strokes, classes) };
        return Grouping { motifs, classes: None };
    }
    // Copies drawn against their neighbours have no gap to cut at: the repetition of the
    // strokes one by one, if there is one, shows them.
    // The strokes' own lattice, read once and only when needed.
    let read = std::cell::OnceCell::new();
    let lattice = || read.get_or_init(|| lattice(classes));
    let across = |groups: &[Vec<u32>]| {
        let same_class_twice = groups.iter().any(|g| {
            g.iter().enumerate().any(|(k, &i)| g[k + 1..].iter().any(|&j| classes[i as usize] == classes[j as usize]))
        });
        same_class_twice && lattice().as_ref().is_some_and(|p| holds_a_period(strokes, classes, groups, p))
    };
    let groups =
        contact::instances(strokes, classes, across, || lattice().as_ref().and_then(|p| cells::instances(strokes, p)));
    let Some(groups) = groups else {
        return Grouping { motifs: Motifs::single(strokes, classes), classes: None };
    };
    let groups = complete::complete(strokes, classes, groups);
    let k = kinds::kinds(strokes, &groups, tol, explicit_path);
    let mut centre: Vec<Point> = groups.iter().map(|g| centre_of(strokes, g)).collect();
    // An incomplete copy stands where its whole motif's centre would be.
    for (x, inc) in k.incomplete.iter().enumerate() {
        if let Some((first, t)) = *inc {
            centre[x] = centre_of(strokes, &groups[first]) + t;
        }
    }
    let motifs = Motifs { instances: groups, kind: k.kind, centre, part: k.part, copies: None };
    Grouping { motifs, classes: Some(k.classes) }
}

/// Whether a group holds a stroke and a stroke of its class about one period (or a sum
/// or difference of the two) on: then it is several copies joined (crosses whose arms
/// meet along a row of a hexagonal lattice), not one.
fn holds_a_period(strokes: &[Stroke], classes: &[u32], groups: &[Vec<u32>], p: &Periods) -> bool {
    let (a, b) = (p.a, p.b);
    let det = a.cross(b);
    if det.abs() < 1e-12 {
        return false;
    }
    let tolerance = 0.25 * a.hypot().min(b.hypot());
    groups.iter().any(|g| {
        g.iter().enumerate().any(|(k, &i)| {
            g[k + 1..].iter().any(|&j| {
                if classes[i as usize] != classes[j as usize] {
                    return false;
                }
                let d = strokes[j as usize].reference_point() - strokes[i as usize].reference_point();
                let (u, w) = ((d.cross(b) / det).round(), (a.cross(d) / det).round());
                (u != 0.0 || w != 0.0) && (d - a * u - b * w).hypot() < tolerance
            })
        })
    })
}

/// An instance's centre: the mean of its strokes' reference points. Each point is the
/// middle of a stroke's box, so the hand's wobble of one extreme point moves it by half
/// that, and the mean over the parts halves it again; the box of the whole copy would
/// move with its single most wobbly extreme.
fn centre_of(strokes: &[Stroke], g: &[u32]) -> Point {
    let sum = g.iter().fold(Vec2::ZERO, |s, &i| s + strokes[i as usize].reference_point().to_vec2());
    (sum / g.len() as f64).to_point()
}

impl Motifs {
    /// Every stroke its own instance, of its class.
    pub fn single(strokes: &[Stroke], classes: &[u32]) -> Motifs {
        Motifs {
            instances: (0..strokes.len() as u32).map(|i| vec![i]).collect(),
            kind: classes.to_vec(),
            centre: strokes.iter().map(Stroke::reference_point).collect(),
            part: vec![0; strokes.len()],
            copies: None,
        }
    }

    /// One point element per instance, at its centre, of its kind.
    pub fn elements(&self) -> Vec<Element> {
        self.centre.iter().zip(&self.kind).map(|(&pos, &class)| Element { pos, class }).collect()
    }

    /// Half the size of each instance's drawing around its centre (strokes' widths in).
    pub fn extents(&self, strokes: &[Stroke]) -> Vec<Vec2> {
        self.instances
            .iter()
            .zip(&self.centre)
            .map(|(g, &c)| {
                let b = g.iter().fold(Rect::new(c.x, c.y, c.x, c.y), |r, &s| r.union(padded(&strokes[s as usize])));
                Vec2::new((b.x1 - c.x).max(c.x - b.x0), (b.y1 - c.y).max(c.y - b.y0))
            })
            .collect()
    }

    /// The instance of each stroke.
    pub fn instance_of(&self) -> Vec<u32> {
        let mut of = vec![0; self.part.len()];
        for (x, g) in self.instances.iter().enumerate() {
            g.iter().for_each(|&s| of[s as usize] = x as u32);
        }
        of
    }

    /// Dresses the placed elements (one per instance site) with strokes: each takes a
    /// drawn instance of its own orbit (`orbit` of each instance: the copies of one place
    /// of the pattern, e.g. one motif position under the periods) at random with
    /// `variation` (its seed), else its source, and that instance's strokes are drawn around the
    /// site as they were drawn around its centre. Strokes whose drawing misses `area` are
    /// left out. Returns the strokes, the class of each, and the input stroke each one's
    /// place copies (the source instance's stroke of the same part); layering follows
    /// the drawing order of the copied strokes.
    pub fn dress(
        &self,
        strokes: &[Stroke],
        classes: &[u32],
        placed: &[Placed],
        orbit: &[u32],
        variation: Option<u64>,
        area: Rect,
    ) -> (Vec<Stroke>, Vec<u32>, Vec<u32>) {
        // The copies each instance may vary among: its orbit (and its exact copies).
        let key = |x: usize| (orbit[x], self.copies.as_ref().map_or(0, |c| c[x]));
        let mut keys: Vec<(u32, u32)> = (0..orbit.len()).map(key).collect();
        keys.sort_unstable();
        keys.dedup();
        let group_of: Vec<usize> = (0..orbit.len()).map(|x| keys.binary_search(&key(x)).unwrap_or(0)).collect();
        // Variation takes whole copies: an incomplete one (fewer strokes than its kind's
        // most) only stands at its own place, or where its orbit has no whole copy.
        let mut most = vec![0usize; self.kind.iter().map(|&k| k as usize + 1).max().unwrap_or(0)];
        for (g, &k) in self.instances.iter().zip(&self.kind) {
            most[k as usize] = most[k as usize].max(g.len());
        }
        let mut by_orbit: Vec<Vec<u32>> = vec![Vec::new(); keys.len()];
        for (x, &g) in group_of.iter().enumerate() {
            if self.instances[x].len() >= most[self.kind[x] as usize] {
                by_orbit[g].push(x as u32);
            }
        }
        for (x, &g) in group_of.iter().enumerate() {
            if by_orbit[g].is_empty() {
                by_orbit[g].push(x as u32);
            }
        }
        // Each instance's stroke per part, to name the source stroke of a copied part.
        let of_part = |x: usize, part: u32| self.instances[x].iter().copied().find(|&s| self.part[s as usize] == part);
        let mut rng = Rng::new(variation.unwrap_or(0));
        let mut out: Vec<(u32, usize, Stroke, u32, u32)> =
            Vec::with_capacity(placed.len() * self.part.len() / self.instances.len().max(1));
        for e in placed {
            let source = e.source as usize;
            let copies = &by_orbit[group_of[source]];
            let chosen =
                if variation.is_some() && copies.len() > 1 { copies[rng.below(copies.len())] as usize } else { source };
            let shift = e.pos - self.centre[chosen];
            let first = self.instances[source][0];
            for (k, &s) in self.instances[chosen].iter().enumerate() {
                let stroke = &strokes[s as usize];
                let b = padded(stroke);
                if b.x1 + shift.x < area.x0
                    || b.x0 + shift.x > area.x1
                    || b.y1 + shift.y < area.y0
                    || b.y0 + shift.y > area.y1
                {
                    continue;
                }
                // The source's stroke of this part (an incomplete source may lack it: then
                // the copied stroke itself).
                let src = if chosen == source { s } else { of_part(source, self.part[s as usize]).unwrap_or(s) };
                out.push((first, k, stroke.translated(shift.x, shift.y), classes[s as usize], src));
            }
        }
        out.sort_by_key(|o| (o.0, o.1));
        let mut dressed = Vec::with_capacity(out.len());
        let (mut cls, mut sources) = (Vec::with_capacity(out.len()), Vec::with_capacity(out.len()));
        for (_, _, s, c, src) in out {
            dressed.push(s);
            cls.push(c);
            sources.push(src);
        }
        (dressed, cls, sources)
    }
}

/// A stroke's box with half its width around a stroked path.
fn padded(s: &Stroke) -> Rect {
    let pad = if s.stroke.is_some() { s.width / 2.0 } else { 0.0 };
    s.bounds().inflate(pad, pad)
}
