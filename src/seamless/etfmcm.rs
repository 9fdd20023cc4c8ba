//! TFMCM and E-TFMCM generation (SPEC 3.3, 3.4): grey values decided point by point in
//! midpoint-displacement order on the torus, from the exemplar's co-occurrences.
//!
//! - The corner and centre: the pair `(a, b)` maximising
//!   `C(a, b; n/2, n/2) + C(a, b; -n/2, n/2)`.
//! - The first diamond step: the pairwise rule, `k` maximising the sum over the four
//!   vertices of `C(V_v, k; centre - vertex)`.
//! - Every later point: `J3(k)` = number of the square's (or diamond's) four sides whose
//!   `(V_a, V_b)` occur in the exemplar with `k` at the apex; the `k` with the largest
//!   `J3` (ties at random). When the largest is 1, TFMCM falls back to the pairwise rule
//!   and E-TFMCM takes, among the `k` with `J3 = 1`, the one nearest the vertices' mean.
//!   When it is 0, the pairwise rule; if no `k` co-occurs at all, the vertices' mean.
//!
//! Ties are broken by the seeded generator, so a seed reproduces a tile.

use super::cooccurrence::{Grey, Levels, Pairs, Triples};
use super::order::{order, Kind, Step};
use crate::error::Result;
use crate::progress::Throttle;
use crate::rng::Rng;
use serde::Serialize;

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Rule {
    Tfmcm,
    Etfmcm,
}

/// How the points were decided (the paper's Table 1).
#[derive(Clone, Debug, Default, PartialEq, Serialize)]
#[serde(rename_all = "camelCase")]
pub struct Decisions {
    /// Points decided by the multi-distance matrix, by the largest `J3` (index 1..=4;
    /// index 1 only under E-TFMCM).
    pub by_j3: [usize; 5],
    /// Points decided by the pairwise rule.
    pub pairwise: usize,
    /// Points where nothing co-occurred: the vertices' mean.
    pub mean: usize,
}

/// Generates an `n x n` torus (`n` = the exemplar's side, a power of two).
pub fn generate(ex: &Grey, rule: Rule, seed: u64, progress: &mut Throttle) -> Result<(Grey, Decisions)> {
    let n = ex.width;
    debug_assert!(n == ex.height && n.is_power_of_two() && n >= 2);
    let mut out = vec![0u8; n * n];
    let mut rng = Rng::new(seed);
    let mut pairs = Pairs::new(ex);
    let mut decisions = Decisions::default();
    let steps = order(n);
    // The four sides' triples for the current kind and scale.
    let mut sides: Option<((Kind, usize), Vec<Triples>)> = None;
    let mut candidates: Vec<u8> = Vec::with_capacity(256);
    for (done, st) in steps.iter().enumerate() {
        if done % 4096 == 0 {
            progress.tick(done as f64 / steps.len() as f64)?;
        }
        if st.kind == Kind::First {
            let (a, b) = first_pair(&mut pairs, n, &mut rng);
            out[0] = a;
            out[st.y * n + st.x] = b;
            continue;
        }
        let verts = st.vertices();
        let values = verts.map(|(dx, dy)| {
            let x = (st.x as isize + dx).rem_euclid(n as isize) as usize;
            let y = (st.y as isize + dy).rem_euclid(n as isize) as usize;
            out[y * n + x]
        });
        let mean = values.iter().map(|&v| v as f64).sum::<f64>() / 4.0;
        // The apex values with J3 >= 4, 3, 2 and 1 (none at the first diamond step: the
        // pairwise rule), and the largest J3 any value has.
        let mut at_least = [Levels::default(); 4];
        if st.kind != Kind::FirstDiamond {
            match &mut sides {
                Some((key, t)) if *key != (st.kind, st.h) => {
                    for (i, side) in t.iter_mut().enumerate() {
                        side.rebuild(ex, verts[i], verts[(i + 1) % 4]);
                    }
                    *key = (st.kind, st.h);
                }
                Some(_) => {}
                None => {
                    let t = (0..4).map(|i| Triples::build(ex, verts[i], verts[(i + 1) % 4])).collect();
                    sides = Some(((st.kind, st.h), t));
                }
            }
            let t = &sides.as_ref().unwrap().1;
            at_least = Levels::at_least([0, 1, 2, 3].map(|i| t[i].apexes(values[i], values[(i + 1) % 4])));
        }
        let max = (0..4).find(|&i| !at_least[i].is_empty()).map_or(0, |i| 4 - i);
        let value = if max >= 2 || (max == 1 && rule == Rule::Etfmcm) {
            decisions.by_j3[max] += 1;
            // Exactly `max`: those with more would have made the largest larger.
            let ties = at_least[4 - max];
            if max == 1 {
                // E-TFMCM: among them, the one nearest the vertices' mean.
                candidates.clear();
                let best = ties.iter().map(|k| (k as f64 - mean).abs()).fold(f64::INFINITY, f64::min);
                candidates.extend(ties.iter().filter(|&k| (k as f64 - mean).abs() <= best + 1e-9));
                candidates[rng.below(candidates.len())]
            } else {
                // Ascending, as the seeded choice among ties expects.
                ties.nth(rng.below(ties.len()))
            }
        } else if let Some(k) = pairwise(&mut pairs, st, &values, &mut rng, &mut candidates) {
            decisions.pairwise += 1;
            k
        } else {
            decisions.mean += 1;
            mean.round() as u8
        };
        out[st.y * n + st.x] = value;
    }
    progress.tick(1.0)?;
    Ok((Grey { width: n, height: n, data: out }, decisions))
}

/// Step 1: the corner value `a` and centre value `b`.
fn first_pair(pairs: &mut Pairs, n: usize, rng: &mut Rng) -> (u8, u8) {
    let h = (n / 2) as isize;
    let t1 = pairs.table(h, h).to_vec();
    let t2 = pairs.table(-h, h);
    let mut best = 0u32;
    let mut ties: Vec<(u8, u8)> = Vec::new();
    for (idx, (&c1, &c2)) in t1.iter().zip(t2).enumerate() {
        let s = c1 + c2;
        if s > best {
            best = s;
            ties.clear();
        }
        if s == best && s > 0 {
            ties.push(((idx / 256) as u8, (idx % 256) as u8));
        }
    }
    if ties.is_empty() {
        return (0, 0);
    }
    ties[rng.below(ties.len())]
}

/// The pairwise rule: the `k` with the largest sum of vertex-to-point co-occurrences
/// (ties at random); `None` when no `k` co-occurs with any vertex.
fn pairwise(pairs: &mut Pairs, st: &Step, values: &[u8; 4], rng: &mut Rng, candidates: &mut Vec<u8>) -> Option<u8> {
    let mut score = [0u32; 256];
    for (i, (dx, dy)) in st.vertices().into_iter().enumerate() {
        // From the vertex to the point: the opposite of the vertex's offset.
        let t = pairs.table(-dx, -dy);
        let row = &t[values[i] as usize * 256..][..256];
        for (s, &c) in score.iter_mut().zip(row) {
            *s += c;
        }
    }
    let max = *score.iter().max().unwrap();
    if max == 0 {
        return None;
    }
    candidates.clear();
    candidates.extend((0..=255u8).filter(|&k| score[k as usize] == max));
    Some(candidates[rng.below(candidates.len())])
}
