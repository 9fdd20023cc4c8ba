//! How a finished drawing repeats over the output (issue 27): a curve continued as far
//! as it goes (leaves round an open wreath, a vine along its stem, hatching round its
//! fan), and the rosettes' rows (`brick`). The drawing's box, grown by a gap, is laid
//! in rows, each row offset by half a box (a brick bond), so copies side by side keep
//! the gap between their boxes and no two rows line up into columns.

use super::stroke::Stroke;
use kurbo::{Point, Rect, Vec2};

/// The box `strokes` cover with their pen (half the widest stroke's width round their
/// points), or none for no strokes.
pub fn inked_bounds(strokes: &[Stroke]) -> Option<Rect> {
    let pen = 0.5 * strokes.iter().map(|s| s.width).fold(0.0, f64::max);
    let bounds = strokes.iter().skip(1).fold(strokes.first()?.bounds(), |r, s| r.union(s.bounds()));
    Some(bounds.inflate(pen, pen))
}

/// Periods `[[ax, ay], [bx, by]]` laying boxes `w` wide and `h` high (gaps included)
/// in rows, each row offset by half a box.
pub fn brick(w: f64, h: f64) -> [[f64; 2]; 2] {
    [[w, 0.0], [0.5 * w, h]]
}

/// Periods repeating a continued curve of box `bounds` (pen included) `gap` apart over
/// `area`, where the output holds it at least twice along a side (else none: a curve
/// the output holds once, a wreath, is the output as continued): in bricked rows where
/// a copy fits across the output, copies at the rows' ends cut by its edge as a
/// wallpaper's are; where none fits with its gap (a vine continued across the whole
/// output), one to a row, the rows stacked a box and a gap apart.
pub fn curve(bounds: Rect, gap: f64, area: Rect) -> Option<[[f64; 2]; 2]> {
    let (w, h) = (bounds.width() + gap, bounds.height() + gap);
    let twice = 2.0 * w <= area.width() || 2.0 * h <= area.height();
    if w <= area.width() && twice {
        Some(brick(w, h))
    } else if 2.0 * h <= area.height() {
        // (The row's period past the output and the box: a row holds one copy.)
        Some([[area.width() + w, 0.0], [0.0, h]])
    } else {
        None
    }
}

/// Whether `curve`'s periods lay copies side by side (bricked rows), not one to a row.
pub fn side_by_side(lattice: [[f64; 2]; 2]) -> bool {
    lattice[1][0] != 0.0
}

/// The moves carrying a drawing of box `bounds` to each site of `lattice` (periods as
/// `curve` gives them: the first along the rows, the second's `y` positive) at which
/// its box meets `area`, the drawing's own (no move) first; none where there are more
/// than `max` (found out before they are listed: an output far larger than the
/// drawing). Each copy goes whole: a vine's leaves are not laid without their stem
/// where the stem's centre falls outside.
pub fn moves(bounds: Rect, [a, b]: [[f64; 2]; 2], area: Rect, max: usize) -> Option<Vec<Vec2>> {
    let (a, b) = (Vec2::new(a[0], a[1]), Vec2::new(b[0], b[1]));
    let meets = |v: Vec2| {
        let r = bounds + v;
        r.x1 > area.x0 && r.x0 < area.x1 && r.y1 > area.y0 && r.y0 < area.y1
    };
    // (Rows from the lowest whose box can reach the area to the highest, each holding
    // a copy that meets it; in each, the copies from the leftmost that can to the
    // rightmost, all but the end ones meeting it: counts past `max` are refused as
    // floats, before any loop runs that long.)
    let (low, high) = (((area.y0 - bounds.y1) / b.y).floor(), ((area.y1 - bounds.y0) / b.y).ceil());
    if !(high - low).is_finite() || high - low > max as f64 + 2.0 {
        return None;
    }
    let mut out = vec![Vec2::ZERO];
    for l in low as i64..=high as i64 {
        let shift = b * l as f64;
        let first = ((area.x0 - bounds.x1 - shift.x) / a.x).floor();
        let last = ((area.x1 - bounds.x0 - shift.x) / a.x).ceil();
        if !(last - first).is_finite() || last - first > max as f64 + 2.0 {
            return None;
        }
        for k in first as i64..=last as i64 {
            let v = shift + a * k as f64;
            if (k, l) != (0, 0) && meets(v) {
                out.push(v);
            }
        }
        if out.len() > max {
            return None;
        }
    }
    Some(out)
}

/// How far apart a curve's copies lie along it: the median distance from each stroke
/// of the commonest class (the copies' largest part is drawn once a copy, as are its
/// others: of equal counts, the first) to the nearest other of that class, over at
/// most `SAMPLE` of them. Rows of copies repeat that far apart, as the copies along
/// each row do. None with fewer than two.
pub fn spacing(strokes: &[Stroke], classes: &[u32]) -> Option<f64> {
    const SAMPLE: usize = 512;
    let mut counts = std::collections::BTreeMap::new();
    classes.iter().for_each(|&c| *counts.entry(c).or_insert(0usize) += 1);
    let (&class, _) = counts.iter().max_by(|x, y| x.1.cmp(y.1).then(y.0.cmp(x.0)))?;
    let centres: Vec<Point> =
        strokes.iter().zip(classes).filter(|(_, &c)| c == class).map(|(s, _)| s.reference_point()).collect();
    let mut nearest: Vec<f64> = centres
        .iter()
        .take(SAMPLE)
        .enumerate()
        .map(|(i, p)| {
            centres
                .iter()
                .enumerate()
                .filter(|&(j, _)| j != i)
                .map(|(_, q)| p.distance(*q))
                .fold(f64::INFINITY, f64::min)
        })
        .filter(|d| d.is_finite() && *d > 0.0)
        .collect();
    (!nearest.is_empty()).then(|| super::classify::median(&mut nearest))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_curve_repeats_where_the_output_holds_it_twice() {
        let area = Rect::new(0.0, 0.0, 1200.0, 800.0);
        // A wreath 500 across: two fit across, rows offset by half.
        assert_eq!(curve(Rect::new(0.0, 0.0, 500.0, 500.0), 50.0, area), Some([[550.0, 0.0], [275.0, 550.0]]));
        // A vine 640 long and 130 high: bricked rows (the output holds it twice down).
        assert_eq!(curve(Rect::new(0.0, 0.0, 640.0, 130.0), 40.0, area), Some([[680.0, 0.0], [340.0, 170.0]]));
        // Hatching continued down the whole output, 300 wide: columns.
        assert_eq!(curve(Rect::new(0.0, -10.0, 300.0, 810.0), 10.0, area), Some([[310.0, 0.0], [155.0, 830.0]]));
        // A vine across the whole output, 300 high: rows stacked, one copy each.
        let vine = curve(Rect::new(-10.0, 250.0, 1210.0, 550.0), 40.0, area).expect("stacked");
        assert_eq!(vine[1], [0.0, 340.0]);
        assert!(vine[0][0] > area.width() + 1220.0);
        // A vine a little narrower than the output but not with its gap: stacked, not
        // bricked rows of half vines.
        assert_eq!(curve(Rect::new(0.0, 0.0, 1180.0, 200.0), 40.0, area), Some([[2420.0, 0.0], [0.0, 240.0]]));
        // A wreath the output holds once.
        assert_eq!(curve(Rect::new(0.0, 0.0, 700.0, 700.0), 50.0, area), None);
    }

    #[test]
    fn copies_go_whole_wherever_their_box_meets_the_output() {
        let area = Rect::new(0.0, 0.0, 1200.0, 800.0);
        let bounds = Rect::new(450.0, 300.0, 750.0, 500.0);
        let lattice = curve(bounds, 50.0, area).unwrap();
        let moves = moves(bounds, lattice, area, 1000).expect("a dozen copies");
        assert_eq!(super::moves(bounds, lattice, area, moves.len() - 1), None);
        assert_eq!(super::moves(bounds, lattice, area, moves.len()).map(|m| m.len()), Some(moves.len()));
        // Stacked rows of one: three copies are three, not refused at three.
        let vine = Rect::new(-10.0, 250.0, 1210.0, 550.0);
        let stacked = curve(vine, 40.0, area).unwrap();
        assert!(!side_by_side(stacked));
        assert_eq!(super::moves(vine, stacked, area, 3).map(|m| m.len()), Some(3));
        // An output a billion across is refused before its copies are counted.
        let huge = Rect::new(0.0, 0.0, 1e9, 1e9);
        assert_eq!(super::moves(Rect::new(0.0, 0.0, 10.0, 10.0), brick(12.0, 12.0), huge, 1000), None);
        assert_eq!(moves[0], Vec2::ZERO);
        // Every copy meets the output, none twice, and every site whose box meets it is
        // there (searched wide).
        let (a, b) = (Vec2::new(lattice[0][0], lattice[0][1]), Vec2::new(lattice[1][0], lattice[1][1]));
        let mut want = 0;
        for l in -20i64..=20 {
            for k in -20i64..=20 {
                let v = a * k as f64 + b * l as f64;
                let r = bounds + v;
                if r.x1 > 0.0 && r.x0 < 1200.0 && r.y1 > 0.0 && r.y0 < 800.0 {
                    want += 1;
                    assert!(moves.iter().any(|m| (*m - v).hypot() < 1e-9), "({k}, {l}) missing");
                }
            }
        }
        assert_eq!(moves.len(), want);
    }

    #[test]
    fn spacing_is_the_commonest_class_s_nearest_neighbour() {
        let dot = |x: f64, y: f64| Stroke::new(vec![[x, y], [x + 4.0, y]], 2.0, None);
        // Leaves 40 apart along a row (class 0), each with a stalk 5 off (class 1), and
        // a stem (class 2).
        let mut strokes = Vec::new();
        let mut classes = Vec::new();
        for k in 0..6 {
            strokes.push(dot(40.0 * k as f64, 0.0));
            classes.push(0);
            strokes.push(dot(40.0 * k as f64, 5.0));
            classes.push(1);
        }
        strokes.push(dot(0.0, 100.0));
        classes.push(2);
        assert_eq!(spacing(&strokes, &classes), Some(40.0));
        assert_eq!(spacing(&strokes[..1], &classes[..1]), None);
    }
}
