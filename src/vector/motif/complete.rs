//! Parts a shaky hand drew apart: a fish's tail drawn against its body in most copies
//! but a little off it in a few. The contact cut leaves those tails their own
//! instances, and the drawing then reads as three kinds (whole fish, tailless fish,
//! lone tails) instead of one.
//!
//! The copies themselves say where each part belongs: in the whole copies (those of the
//! most common make-up), each part sits at an offset from the copy's largest part (its
//! anchor) that varies only by the hand's scatter. A lone part of a class the copy
//! lacks, at that offset from an incomplete copy's anchor (within three times the
//! scatter, or a fifth of the anchor's size when the whole copies are too few to show
//! it), is that copy's missing part.
//!
//! The other way round, copies drawn against one another may be read as one group (three
//! cats drawn in an L, faces overlapping): a group holding the whole make-up some `m`
//! times over is split about its `m` anchors, each part going to the anchor where whole
//! copies put a part of its class.

use super::super::stroke::Stroke;
use kurbo::Vec2;

/// Whole copies needed to read where their parts sit.
const MIN_WHOLE: usize = 2;
/// A missing part is taken within this many root-mean-square deviations of its offset.
const SPREAD: f64 = 3.0;
/// ...and at least within this share of the anchor's size.
const FLOOR: f64 = 0.2;
/// A part of a group split about its anchors lands within this share of the anchor's
/// size of where the whole copies put a part of its class.
const SPLIT: f64 = 1.0 / 3.0;

/// `groups` (instances of `strokes` of the paper's `classes`) with the lone parts of
/// incomplete copies joined to them (see the module comment); groups joined into
/// another are left out, the rest keep their order.
pub fn complete(strokes: &[Stroke], classes: &[u32], groups: Vec<Vec<u32>>) -> Vec<Vec<u32>> {
    let make_up = |g: &[u32]| {
        let mut c: Vec<u32> = g.iter().map(|&s| classes[s as usize]).collect();
        c.sort_unstable();
        c
    };
    let makes: Vec<Vec<u32>> = groups.iter().map(|g| make_up(g)).collect();
    // The whole copies: the most common make-up of several strokes, each class once.
    let mut counted: Vec<(&Vec<u32>, usize)> = Vec::new();
    for m in makes.iter().filter(|m| m.len() >= 2) {
        match counted.iter_mut().find(|c| c.0 == m) {
            Some(c) => c.1 += 1,
            None => counted.push((m, 1)),
        }
    }
    let Some(&(whole, count)) = counted.iter().max_by_key(|c| (c.1, c.0.len())) else {
        return groups;
    };
    if count < MIN_WHOLE {
        return groups;
    }
    let size = |s: u32| strokes[s as usize].bounds().size().to_vec2().hypot();
    let at = |s: u32| strokes[s as usize].reference_point().to_vec2();
    let of_class = |g: &[u32], c: u32| g.iter().copied().find(|&s| classes[s as usize] == c);
    // The anchor: the class of the whole copies' largest part.
    let first = groups.iter().zip(&makes).find(|(_, m)| *m == whole).map(|(g, _)| g).expect("counted");
    let anchor = classes[*first.iter().max_by(|&&p, &&q| size(p).total_cmp(&size(q))).expect("several") as usize];
    let times = |m: &[u32], c: u32| m.iter().filter(|&&k| k == c).count();
    if times(whole, anchor) != 1 {
        return groups;
    }
    // Per other class: the mean offset from the anchor, and its mean square scatter.
    let wholes: Vec<&Vec<u32>> = groups.iter().zip(&makes).filter(|(_, m)| *m == whole).map(|(g, _)| g).collect();
    let mut unique: Vec<u32> = whole.iter().copied().filter(|&c| c != anchor && times(whole, c) == 1).collect();
    unique.dedup();
    let offsets: Vec<(u32, Vec2, f64)> = unique
        .iter()
        .map(|&c| {
            let d: Vec<Vec2> = wholes
                .iter()
                .map(|g| at(of_class(g, c).expect("whole")) - at(of_class(g, anchor).expect("whole")))
                .collect();
            let mean = d.iter().fold(Vec2::ZERO, |s, &v| s + v) / d.len() as f64;
            let scatter = d.iter().map(|&v| (v - mean).hypot2()).sum::<f64>() / (d.len() - 1).max(1) as f64;
            (c, mean, scatter)
        })
        .collect();
    let anchor_size =
        wholes.iter().map(|g| size(of_class(g, anchor).expect("whole"))).sum::<f64>() / wholes.len() as f64;
    let reach = |scatter: f64| (SPREAD * scatter.sqrt()).max(FLOOR * anchor_size);
    // Copies drawn against one another and read as one (three cats in an L): a group of
    // `m` times the whole make-up is split about its `m` anchors, each stroke to the
    // anchor where a whole copy has a part of its class (each anchor taking as many of
    // a class as a whole copy holds), if every stroke lands within a third of the
    // anchor's size of such a place.
    let seen: Vec<(u32, Vec2)> = wholes
        .iter()
        .flat_map(|g| {
            let a = at(of_class(g, anchor).expect("whole"));
            g.iter().filter(|&&s| classes[s as usize] != anchor).map(move |&s| (classes[s as usize], at(s) - a))
        })
        .collect();
    let mut groups = groups;
    let mut x = 0;
    while x < groups.len() {
        let m = times(&make_up(&groups[x]), anchor);
        let multiple = m >= 2 && whole.iter().all(|&c| times(&make_up(&groups[x]), c) == m * times(whole, c));
        match multiple.then(|| split(&groups[x], anchor, classes, &seen, whole, &at, SPLIT * anchor_size)).flatten() {
            Some(parts) => {
                groups.splice(x..=x, parts.clone());
                x += parts.len();
            }
            None => x += 1,
        }
    }
    let makes: Vec<Vec<u32>> = groups.iter().map(|g| make_up(g)).collect();
    // Lone parts, each joined at most once, to incomplete copies that hold the anchor.
    let mut joined: Vec<Option<usize>> = vec![None; groups.len()];
    let mut out = groups.clone();
    for (x, g) in groups.iter().enumerate() {
        let Some(a) = of_class(g, anchor) else { continue };
        if makes[x] == *whole || !makes[x].iter().all(|c| whole.contains(c)) {
            continue;
        }
        for &(c, mean, scatter) in offsets.iter().filter(|o| !makes[x].contains(&o.0)) {
            let want = at(a) + mean;
            let lone = (0..groups.len())
                .filter(|&y| {
                    joined[y].is_none() && y != x && groups[y].len() == 1 && classes[groups[y][0] as usize] == c
                })
                .map(|y| (y, (at(groups[y][0]) - want).hypot()))
                .filter(|&(_, d)| d <= reach(scatter))
                .min_by(|p, q| p.1.total_cmp(&q.1));
            if let Some((y, _)) = lone {
                joined[y] = Some(x);
                out[x].push(groups[y][0]);
            }
        }
        out[x].sort_unstable();
    }
    let mut out: Vec<Vec<u32>> =
        out.into_iter().enumerate().filter(|(y, _)| joined[*y].is_none()).map(|(_, g)| g).collect();
    // Instances stay in the order of their first stroke (a tail may be drawn first).
    out.sort_by_key(|g| g[0]);
    out
}

/// `group` split about its strokes of class `anchor`: each other stroke, nearest first,
/// goes to the anchor where it is nearest a place `seen` for its class (offsets from
/// the anchor in whole copies), while that anchor lacks strokes of its class (`whole`
/// counts them); `None` when a stroke lands further than `reach` from such a place.
fn split(
    group: &[u32],
    anchor: u32,
    classes: &[u32],
    seen: &[(u32, Vec2)],
    whole: &[u32],
    at: &impl Fn(u32) -> Vec2,
    reach: f64,
) -> Option<Vec<Vec<u32>>> {
    let anchors: Vec<u32> = group.iter().copied().filter(|&s| classes[s as usize] == anchor).collect();
    let mut pairs: Vec<(f64, u32, usize)> = Vec::new();
    for &s in group.iter().filter(|&&s| classes[s as usize] != anchor) {
        let c = classes[s as usize];
        for (k, &a) in anchors.iter().enumerate() {
            let d =
                seen.iter().filter(|o| o.0 == c).map(|o| (at(s) - at(a) - o.1).hypot()).fold(f64::INFINITY, f64::min);
            pairs.push((d, s, k));
        }
    }
    pairs.sort_by(|p, q| p.0.total_cmp(&q.0).then(p.1.cmp(&q.1)).then(p.2.cmp(&q.2)));
    let mut out: Vec<Vec<u32>> = anchors.iter().map(|&a| vec![a]).collect();
    let mut placed: Vec<u32> = Vec::new();
    for (d, s, k) in pairs {
        let c = classes[s as usize];
        let held = out[k].iter().filter(|&&t| classes[t as usize] == c).count();
        if placed.contains(&s) || held >= whole.iter().filter(|&&w| w == c).count() {
            continue;
        }
        if d > reach {
            return None;
        }
        placed.push(s);
        out[k].push(s);
    }
    out.iter_mut().for_each(|g| g.sort_unstable());
    (placed.len() + anchors.len() == group.len()).then_some(out)
}
