//! Growth statistics and regularity per family at growing output sizes (a quick look;
//! the benchmark proper is `cargo bench`).
use kurbo::{Rect, Vec2};
use patternsynth::vector::exemplar::families;
use patternsynth::vector::regularity::measure;
use patternsynth::vector::{synthesize_strokes, StrokeOptions};
use patternsynth::Silent;
use std::time::Instant;

fn main() {
    let sizes: Vec<f64> = std::env::args().skip(1).filter_map(|a| a.parse().ok()).collect();
    let sizes = if sizes.is_empty() { vec![600.0, 2400.0] } else { sizes };
    for ex in families(0.02, 11) {
        for &size in &sizes {
            let opts = StrokeOptions { width: size, height: size, ..Default::default() };
            let t = Instant::now();
            let r = synthesize_strokes(&ex.strokes, &opts, &mut Silent).unwrap();
            let ms = t.elapsed().as_secs_f64() * 1e3;
            let b = ex
                .strokes
                .iter()
                .map(|s| s.reference_point())
                .fold(None::<Rect>, |r, p| Some(r.map_or(Rect::from_points(p, p), |r| r.union_pt(p))));
            let area = Rect::new(0.0, 0.0, size, size);
            let shift: Vec2 = area.center() - b.unwrap().center();
            let out: Vec<_> = r
                .strokes
                .iter()
                .zip(&r.sources)
                .map(|(s, &src)| (s.reference_point(), ex.classes[src as usize]))
                .collect();
            let q = measure(&ex.lattice, shift, &out, area);
            println!(
                "{:<18} {:>5} out {:>6} {:>7.1} ms cov {:>6.2}% stray {} stacked {} med {:.3} p95 {:.3} | grow {} skip {} pass {}",
                ex.name,
                size,
                r.strokes.len(),
                ms,
                q.coverage * 100.0,
                q.stray,
                q.stacked,
                q.median_residual,
                q.p95_residual,
                r.growing_points,
                r.skipped_full,
                r.passed_over
            );
        }
    }
}
