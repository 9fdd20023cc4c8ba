//! Repetition along a similarity step, where the drawing holds no lattice (issue 27):
//! petals round a centre, leaves along a curved stem, hatching that turns, a spiral.
//! Each copy is the one before under one step `z -> a z + b` (`similarity`); the step
//! turns (a ring, or an arc: a turn about a far centre) or scales (a spiral).
//!
//! Finding it (`find`): strokes of one shape up to rotation and scale are related
//! pairwise, each pair by every fit as good as its best (an ellipse fits its neighbour
//! turned either way round); each fit is a candidate step. Of the steps that carry
//! within a tenth of the most strokes onto another of their shape, the shortest is
//! kept (a double step carries as many round a ring). Strokes carried beside the
//! chain's copies, drawn with them, are their motif's other strokes
//! (`Chain::companions`). Following it from a copy no other copy steps onto gives the
//! chain; it must hold at least three copies and two thirds of its shape's strokes (the
//! petals of one flower among several are a flower's, not the drawing's, repetition:
//! `find_ring` asks two thirds of those about the ring's own centre, and
//! `rings_beside` finds a drawing's other flowers). The step is then fitted by least
//! squares over every consecutive pair, and where its turn is close to a whole
//! fraction of a turn (and it does not scale) the ring closes: the turn is snapped to
//! it. A chain that does not close turns under a right angle a step.
//!
//! Continuing it: copies further along, both ways, each a drawn copy carried by the step
//! as many times as it lies from it (with variation, a random drawn copy, so the hand's
//! own differences recur; without, the nearest end), until a copy would leave the area,
//! land on one placed already (a circle closing), or shrink or grow past sense.
//!
//! Departs from the seed paper (which repeats by translation only, comparing shapes up
//! to translation); follows Xing et al. 2014's local similarity, read globally from all
//! the drawn copies since synthesis sees the whole drawing at once.

pub mod bend;
mod bending;
mod by_place;
mod carry;
mod find;

pub use bending::{find_bending, Bending};
pub use by_place::ring as find_by_place;
pub use find::{find, find_or_ring, find_ring, find_upright, ring_steps, rings_beside};

use super::similarity::{mul, Similarity};
use kurbo::{Point, Vec2};
use serde::Serialize;

/// Which structure a synthesis repeated the drawing on.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Structure {
    /// Translations (rows and grids; an exact tile).
    Lattice,
    /// Copies turned round a centre, closing after a whole number of steps.
    Ring,
    /// Copies along an arc (a turn about a far centre that does not close in view).
    Curve,
    /// Copies each turned and scaled from the last (a spiral, hatching that widens).
    Sequence,
    /// No repetition: a mosaic of the drawing's own windows, or a mesh joined afresh.
    Irregular,
}

/// Drawings with more strokes than this are not searched for a chain (each pair of
/// strokes of one shape is related; hand-drawn rings and curves are small).
pub const MAX_STROKES: usize = 160;

/// The drawn copies in order along the step, and the step.
#[derive(Clone, Debug)]
pub struct Chain {
    /// Strokes of the drawn copies, in order: `step` carries each onto the next.
    pub members: Vec<usize>,
    /// Each drawn copy's other strokes, of a motif of several (a petal drawn as two
    /// arcs, a leaf and its vein): each carried by the step onto the next copy's, drawn
    /// as near its member in the drawing's order in every copy; empty for a motif of one
    /// stroke, and for a copy short of some.
    pub companions: Vec<Vec<usize>>,
    pub step: Similarity,
    /// The copies keep their pose: the step carries their places only, each copy moved
    /// there unturned (fence posts along an arc, upright; `find_upright`).
    pub upright: bool,
    /// Copies round the whole ring, when it closes (a rosette: petals round a centre
    /// within `ROSETTE` copy sizes).
    pub closes: Option<usize>,
}

impl Chain {
    /// The structure the chain makes.
    pub fn structure(&self) -> Structure {
        if self.closes.is_some() {
            Structure::Ring
        } else if (self.step.scale() - 1.0).abs() < 0.04 {
            Structure::Curve
        } else {
            Structure::Sequence
        }
    }

    /// The chain with its drawing moved by `v`: the step conjugated by the move.
    pub fn moved(&self, v: Vec2) -> Chain {
        let t = self.step;
        Chain { step: Similarity { a: t.a, b: t.b + v - mul(t.a, v) }, ..self.clone() }
    }

    /// The centre a ring turns about.
    pub fn centre(&self) -> Option<Point> {
        self.closes.and(self.step.fixed_point())
    }
    /// The drawing's strokes the chain holds: its copies and their other strokes.
    pub fn held(&self) -> impl Iterator<Item = usize> + '_ {
        self.members.iter().chain(self.companions.iter().flatten()).copied()
    }

    /// How many of the drawing's strokes the chain holds.
    pub fn strokes(&self) -> usize {
        self.members.len() + self.companions.iter().map(Vec::len).sum::<usize>()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::vector::stroke::Stroke;
    use kurbo::Rect;
    use std::f64::consts::TAU;

    /// A petal: a loop `len` long from `at` along `theta`.
    fn petal(at: Point, theta: f64, len: f64) -> Stroke {
        let pts = (0..=20)
            .map(|k| {
                let t = k as f64 / 20.0 * TAU;
                let (along, across) = (0.5 * len * (1.0 - t.cos()), len / 6.0 * t.sin());
                let (c, s) = (theta.cos(), theta.sin());
                [at.x + along * c - across * s, at.y + along * s + across * c]
            })
            .collect();
        Stroke::new(pts, 2.0, None)
    }

    #[test]
    fn three_petals_of_eight_make_a_ring_and_complete_it() {
        let c = Point::new(100.0, 100.0);
        let drawn: Vec<Stroke> = (0..3).map(|k| petal(c, k as f64 * TAU / 8.0, 60.0)).collect();
        let chain = find(&drawn).expect("a ring");
        assert_eq!(chain.closes, Some(8));
        assert_eq!(chain.members, vec![0, 1, 2]);
        assert!(chain.centre().unwrap().distance(c) < 1.0);
        let rest = chain.complete(&drawn, None);
        assert_eq!(rest.len(), 5);
        for (k, (s, _)) in rest.iter().enumerate() {
            let want = petal(c, (3 + k) as f64 * TAU / 8.0, 60.0).reference_point();
            assert!(s.reference_point().distance(want) < 1.0, "petal {}", k + 3);
        }
    }

    #[test]
    fn a_petal_drawn_from_another_start_closes_the_ring() {
        // Five petals of five, the fifth (left out of the chain, as a shaky hand's may
        // be) a loop begun half way round its outline: the ring is whole.
        let c = Point::new(200.0, 200.0);
        let mut drawn: Vec<Stroke> = (0..5).map(|k| petal(c, k as f64 * TAU / 5.0, 60.0)).collect();
        let loop_points = &drawn[4].points;
        let half = loop_points.len() / 2;
        let begun_elsewhere: Vec<[f64; 2]> =
            loop_points[half..].iter().chain(&loop_points[1..=half]).copied().collect();
        drawn[4].points = begun_elsewhere;
        let a = Vec2::new((TAU / 5.0).cos(), (TAU / 5.0).sin());
        let chain = Chain {
            members: vec![0, 1, 2, 3],
            companions: vec![Vec::new(); 4],
            step: Similarity { a, b: c.to_vec2() - mul(a, c.to_vec2()) },
            upright: false,
            closes: Some(5),
        };
        assert!(chain.complete(&drawn, None).is_empty());
        // (Without the fifth, it is the one completed.)
        let four = &drawn[..4];
        let rest = chain.complete(four, None);
        assert_eq!(rest.len(), 1);
        assert!(rest[0].0.reference_point().distance(petal(c, 4.0 * TAU / 5.0, 60.0).reference_point()) < 1.0);
    }

    #[test]
    fn a_dense_ring_is_completed_whole() {
        // 48 petals 70 long and 10 wide, 60 from the centre, 20 drawn, each a loop begun
        // elsewhere on its outline: the 28 completed, and their veins, lie beside their
        // neighbours and about each other, never on them.
        let c = Point::new(400.0, 300.0);
        let step = TAU / 48.0;
        let narrow = |k: usize| {
            let (th, start) = (k as f64 * step, (k as f64 * 0.37).fract());
            let pts = (0..=40)
                .map(|i| {
                    let t = TAU * (start + i as f64 / 40.0);
                    let (x, y) = (60.0 + 35.0 * (1.0 - t.cos()), 5.0 * t.sin());
                    [c.x + x * th.cos() - y * th.sin(), c.y + x * th.sin() + y * th.cos()]
                })
                .collect();
            Stroke::new(pts, 2.0, None)
        };
        // (Each with a vein down its middle, drawn after it.)
        let vein = |k: usize| {
            let d = Vec2::new((k as f64 * step).cos(), (k as f64 * step).sin());
            let (p, q) = (c + d * 70.0, c + d * 120.0);
            Stroke::new(vec![[p.x, p.y], [q.x, q.y]], 2.0, None)
        };
        let drawn: Vec<Stroke> = (0..20).flat_map(|k| [narrow(k), vein(k)]).collect();
        let a = Vec2::new(step.cos(), step.sin());
        let chain = Chain {
            members: (0..20).map(|k| 2 * k).collect(),
            companions: (0..20).map(|k| vec![2 * k + 1]).collect(),
            step: Similarity { a, b: c.to_vec2() - mul(a, c.to_vec2()) },
            upright: false,
            closes: Some(48),
        };
        assert_eq!(chain.complete(&drawn, None).len(), 56);
    }

    #[test]
    fn a_ring_with_one_vein_missing_keeps_the_others() {
        // Six petals, each drawn with its vein but the third: the veins' run wraps round
        // from the fourth to the second (it lost every vein).
        let c = Point::new(200.0, 200.0);
        let mut drawn = Vec::new();
        for k in 0..6 {
            let th = k as f64 * TAU / 6.0;
            drawn.push(petal(c, th, 60.0));
            if k != 2 {
                let (p, q) = (c + Vec2::new(th.cos(), th.sin()) * 18.0, c + Vec2::new(th.cos(), th.sin()) * 42.0);
                drawn.push(Stroke::new(vec![[p.x, p.y], [q.x, q.y]], 2.0, None));
            }
        }
        let chain = find(&drawn).expect("a ring");
        assert_eq!(chain.closes, Some(6));
        assert_eq!(chain.strokes(), 11, "{:?} {:?}", chain.members, chain.companions);
        let with_vein = chain.companions.iter().filter(|v| v.len() == 1).count();
        assert_eq!(with_vein, 5);
    }

    #[test]
    fn leaves_on_an_arc_continue_along_it() {
        // Leaves every 12° on a circle of radius 300 about (0, 400), continued across
        // an area that holds part of the circle.
        let o = Point::new(0.0, 400.0);
        let leaf = |k: i32| {
            let phi = -0.3 + k as f64 * 12f64.to_radians();
            petal(o + Vec2::new(phi.sin(), -phi.cos()) * 300.0, phi, 30.0)
        };
        let drawn: Vec<Stroke> = (0..3).map(leaf).collect();
        let chain = find(&drawn).expect("an arc");
        // 12° would close after 30, but round a far centre that is a curve's business.
        assert_eq!(chain.structure(), Structure::Curve);
        let (more, _) = chain.extend(&drawn, Rect::new(-400.0, 0.0, 400.0, 400.0), None, 100);
        assert!(more.len() >= 4, "{}", more.len());
        for (s, _) in &more {
            let on = (s.reference_point().distance(o) - leaf(0).reference_point().distance(o)).abs();
            assert!(on < 1.0, "off the arc by {on}");
        }
    }

    #[test]
    fn a_motif_of_two_strokes_goes_on_whole_within_the_limit() {
        // A leaf and its vein every 12° on a circle: no more strokes than asked
        // for, and only whole copies (an odd limit once let a leaf go without its vein).
        let o = Point::new(0.0, 400.0);
        let drawn: Vec<Stroke> = (0..4)
            .flat_map(|k| {
                let phi = -0.3 + k as f64 * 12f64.to_radians();
                let (at, along) = (o + Vec2::new(phi.sin(), -phi.cos()) * 300.0, Vec2::new(phi.cos(), phi.sin()));
                let (p, q) = (at + along * 8.0, at + along * 22.0);
                [petal(at, phi, 30.0), Stroke::new(vec![[p.x, p.y], [q.x, q.y]], 2.0, None)]
            })
            .collect();
        let chain = find(&drawn).expect("an arc");
        assert_eq!(chain.strokes(), 8);
        for max in [5, 6, 7] {
            let (more, capped) = chain.extend(&drawn, Rect::new(-400.0, 0.0, 400.0, 400.0), None, max);
            assert!(more.len() <= max && more.len() % 2 == 0 && more.len() >= max - 1, "{max}: {}", more.len());
            assert!(capped, "{max}: the copies left out are said");
        }
    }

    #[test]
    fn unrelated_strokes_and_rows_make_no_chain() {
        let line = |p: [f64; 2], q: [f64; 2]| Stroke::new(vec![p, q], 2.0, None);
        let dashes =
            vec![line([10.0, 10.0], [30.0, 14.0]), line([80.0, 40.0], [84.0, 70.0]), line([20.0, 90.0], [45.0, 80.0])];
        assert!(find(&dashes).is_none());
        // A straight row: translations, the lattice's.
        let row: Vec<Stroke> = (0..5).map(|k| petal(Point::new(40.0 * k as f64, 0.0), 0.5, 30.0)).collect();
        assert!(find(&row).is_none());
    }
}
