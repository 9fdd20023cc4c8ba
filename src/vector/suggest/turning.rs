//! The turn of a sequence's steps, read from its hand-drawn copies' shapes: each copy
//! against the next hand-drawn one however many steps on (`Relation`), and a line
//! through those turns over the steps' indices (`turning`): a constant turn for a ring,
//! an arc or a spiral; one that changes from step to step for a stem that bends one way
//! and then the other (an S), where the change is clear of the hand's noise.

/// What a hand-drawn copy says of the next hand-drawn one along a run, `span` steps on.
pub(super) struct Relation {
    /// The step the first copy is at (negative: the lead-in, before the run).
    pub from: i64,
    pub span: usize,
    pub turn: f64,
    pub scale: f64,
    /// The shape residual, in the drawing's units.
    pub residual: f64,
}

/// The turn of a run's steps, read from its relations: step `j` (from copy `j` to the
/// next) turns by `first + bend j`. `bend` is the least-squares slope where it passes
/// three times its standard error (a stem that bends one way and then the other), else
/// 0 (a ring, an arc, a spiral), with `bend_error` how far off it may be (the slope's
/// standard error, or with none taken the slope itself and its error); `spread` is the
/// relations' square residual about the fit over `dof` degrees of freedom.
pub(super) struct Turning {
    pub bend: f64,
    pub bend_error: f64,
    pub spread: f64,
    pub dof: f64,
    /// The least-squares slope and its standard error, clear of the noise or not (none
    /// from fewer than three relations).
    pub slope: Option<(f64, f64)>,
    /// The run's own relations' sums of spans, of their steps' indices and of turns.
    run: [f64; 3],
}

impl Turning {
    /// The first step's turn given the bend: the run's turns, less what the bend adds to
    /// each, over its steps (with no bend, the mean turn a step).
    pub fn first_given(&self, bend: f64) -> f64 {
        (self.run[2] - bend * self.run[1]) / self.run[0]
    }
}

pub(super) fn turning(rel: &[Relation], lead_in: Option<Relation>) -> Turning {
    let n = rel.len() as f64;
    // Each relation is `turn = first span + bend s` with `s` the sum of its steps'
    // indices.
    let rows: Vec<(f64, f64, f64)> = rel
        .iter()
        .map(|r| {
            let (span, from) = (r.span as f64, r.from as f64);
            (span, span * from + span * (span - 1.0) / 2.0, r.turn)
        })
        .collect();
    let run = rows.iter().fold([0.0; 3], |s, r| [s[0] + r.0, s[1] + r.1, s[2] + r.2]);
    let flat = run[2] / run[0];
    let flat_spread = rows.iter().map(|r| (r.2 - flat * r.0).powi(2)).sum::<f64>();
    let level = |bend_error: f64, slope: Option<(f64, f64)>| Turning {
        bend: 0.0,
        bend_error,
        spread: flat_spread,
        dof: (n - 1.0).max(0.0),
        slope,
        run,
    };
    // The bend from the run's relations and its lead-in's (which says how the turn came
    // to be the run's, and nothing of the run's own turn otherwise).
    let rows: Vec<(f64, f64, f64)> = rows
        .into_iter()
        .chain(lead_in.map(|r| {
            let (span, from) = (r.span as f64, r.from as f64);
            (span, span * from + span * (span - 1.0) / 2.0, r.turn)
        }))
        .collect();
    let n = rows.len() as f64;
    if rows.len() < 3 {
        return level(0.0, None);
    }
    let (mut a11, mut a12, mut a22, mut b1, mut b2) = (0.0, 0.0, 0.0, 0.0, 0.0);
    for &(x1, x2, y) in &rows {
        a11 += x1 * x1;
        a12 += x1 * x2;
        a22 += x2 * x2;
        b1 += x1 * y;
        b2 += x2 * y;
    }
    let det = a11 * a22 - a12 * a12;
    if det <= 1e-12 * a11 * a22 {
        return level(0.0, None);
    }
    let first = (b1 * a22 - b2 * a12) / det;
    let bend = (a11 * b2 - a12 * b1) / det;
    let spread = rows.iter().map(|r| (r.2 - first * r.0 - bend * r.1).powi(2)).sum::<f64>();
    let se = (spread / (n - 2.0).max(1.0) * a11 / det).sqrt();
    if bend.abs() > 3.0 * se {
        Turning { bend, bend_error: se, spread, dof: n - 2.0, slope: Some((bend, se)), run }
    } else {
        level(bend.abs() + se, Some((bend, se)))
    }
}
