//! Autocomplete latency natively, on the drawings of bench/suggest.mjs (rings of eight
//! petals, the latest three petals in; hatching along a wide arc), and rings of six to
//! nine petals each turned a little by hand (`varied`), for profiling:
//! `cargo run --release --example suggest_latency [rings|varied|hatching] [strokes] [calls]`.
//! Each call is cold unless `WARM` is set (then the drawing grows a stroke a call).
use patternsynth::vector::{suggest_strokes, Stroke, SuggestOptions};
use std::f64::consts::PI;
use std::time::Instant;

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let kind = args.get(1).map_or("hatching", |s| s.as_str()).to_string();
    let n: usize = args.get(2).and_then(|s| s.parse().ok()).unwrap_or(200);
    let calls: usize = args.get(3).and_then(|s| s.parse().ok()).unwrap_or(10);
    let mut seed = 7u64;
    let mut jit = move || {
        seed = (seed * 1103515245 + 12345) % 2147483648;
        (seed as f64 / 2147483648.0 - 0.5) * 2.0
    };
    let mut make = |shift: f64| -> Vec<Stroke> {
        let mut out = Vec::new();
        if kind == "rings" || kind == "varied" {
            let mut r = 0;
            'rings: loop {
                let (cx, cy) = (60.0 + 120.0 * (r % 10) as f64 + shift, 60.0 + 120.0 * (r / 10) as f64);
                let count = if kind == "varied" { 6 + r % 4 } else { 8 };
                let petals = if out.len() + count <= n - 3 { count } else { 3.min(n - out.len()) };
                for k in 0..petals {
                    let hand = if kind == "varied" { jit() * 0.05 } else { 0.0 };
                    let theta = k as f64 * 2.0 * PI / count as f64 + hand;
                    let pts = (0..=20)
                        .map(|j| {
                            let t = j as f64 / 20.0 * 2.0 * PI;
                            let (along, across) = (25.0 * (1.0 - t.cos()), 50.0 / 6.0 * t.sin());
                            [
                                cx + along * theta.cos() - across * theta.sin() + jit() * 0.3,
                                cy + along * theta.sin() + across * theta.cos() + jit() * 0.3,
                            ]
                        })
                        .collect();
                    out.push(Stroke::new(pts, 2.0, None));
                }
                if petals < count {
                    break 'rings;
                }
                r += 1;
            }
        } else {
            for k in 0..n {
                let (phi, r) = (-1.2 + k as f64 * 0.012, 600.0);
                let (cx, cy) = (700.0 + r * phi.sin() + shift + jit() * 0.2, 700.0 - r * phi.cos() + jit() * 0.2);
                let (dx, dy) = (phi.sin() * 35.0, -phi.cos() * 35.0);
                out.push(Stroke::new(vec![[cx - dx, cy - dy], [cx + dx, cy + dy]], 2.0, None));
            }
        }
        out
    };
    let opts = SuggestOptions { region: Some([0.0, 0.0, 1400.0, 1400.0]), ..SuggestOptions::default() };
    let warm = std::env::var("WARM").is_ok();
    let full = make(0.0);
    let mut times = Vec::new();
    let mut shown = 0;
    for c in 0..calls {
        let d = if warm { full[..full.len() - calls + c + 1].to_vec() } else { make(0.01 * c as f64) };
        let t = Instant::now();
        shown = suggest_strokes(&d, &opts).unwrap().strokes.len();
        times.push(t.elapsed().as_secs_f64() * 1e3);
    }
    times.sort_by(f64::total_cmp);
    println!(
        "{kind} {n} strokes, {}: {shown} proposals, median {:.1} ms, slowest {:.1}",
        if warm { "stroke by stroke" } else { "cold" },
        times[times.len() / 2],
        times[times.len() - 1]
    );
}
