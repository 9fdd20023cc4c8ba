//! Lattices of hand-drawn circles and rings of teardrops begun anywhere on their
//! outline (issue 27): the lattice replay (accepting right ghosts) and synthesis's
//! structure, with every loop begun at the same point and begun at a random one.
//! `cargo run --release --example circle_starts`
use patternsynth::rng::Rng;
use patternsynth::vector::replay::replay;
use patternsynth::vector::{synthesize_strokes, Stroke, StrokeOptions};
use patternsynth::Silent;
use std::f64::consts::TAU;

/// A circle of radius `r` at `(x, y)` begun at angle `start`, `dir` = ±1, 24 points and
/// its first again, each point off by `noise`.
fn circle(x: f64, y: f64, r: f64, start: f64, dir: f64, rng: &mut Rng, noise: f64) -> Stroke {
    let mut pts: Vec<[f64; 2]> = (0..24)
        .map(|k| {
            let t = start + dir * k as f64 / 24.0 * TAU;
            [x + r * t.cos() + rng.normal() * noise, y + r * t.sin() + rng.normal() * noise]
        })
        .collect();
    pts.push(pts[0]);
    Stroke::new(pts, 2.0, None)
}

fn main() {
    let spacing = 60.0;
    for anywhere in [false, true] {
        for wobble in [0.01, 0.03, 0.05] {
            let (mut acc, mut wrong, mut shown, mut lattice) = (0.0, 0, 0, 0);
            for seed in 1..=3 {
                let mut rng = Rng::new(seed);
                let mut strokes = Vec::new();
                for j in 0..4 {
                    for i in 0..6 {
                        let (x, y) = (40.0 + spacing * i as f64, 40.0 + spacing * j as f64);
                        let (jx, jy) = (rng.normal() * wobble * spacing, rng.normal() * wobble * spacing);
                        let (start, dir) = if anywhere {
                            (rng.below(360) as f64 / 360.0 * TAU, if rng.below(2) == 0 { 1.0 } else { -1.0 })
                        } else {
                            (0.0, 1.0)
                        };
                        strokes.push(circle(x + jx, y + jy, 18.0, start, dir, &mut rng, 0.2 * wobble * spacing));
                    }
                }
                if std::env::var("CLASSES").is_ok() {
                    let (n, cl, tol) = classes_of(&strokes);
                    println!("  {n} classes {cl:?} path tolerance {tol:.2}");
                }
                let canvas = kurbo::Rect::new(10.0, 10.0, 40.0 + spacing * 5.5, 40.0 + spacing * 3.5);
                let r = replay(&strokes, &vec![0; strokes.len()], canvas, 0.3 * spacing);
                acc += r.accepted_after(2) / 3.0;
                wrong += r.wrong;
                shown += r.shown;
                let opts = StrokeOptions { width: 600.0, height: 400.0, ..Default::default() };
                let s = synthesize_strokes(&strokes[..8], &opts, &mut Silent).unwrap();
                lattice += usize::from(format!("{:?}", s.structure) == "Lattice");
            }
            println!(
                "circles begun {}, {:.0}%: accepted after two {:.1}%, wrong {wrong}/{shown}; synthesis of 8 a lattice {lattice}/3",
                if anywhere { "anywhere" } else { "alike" },
                100.0 * wobble,
                100.0 * acc
            );
        }
    }
}

#[allow(dead_code)]
fn classes_of(strokes: &[Stroke]) -> (usize, Vec<u32>, f64) {
    let c = patternsynth::vector::classify_strokes(strokes, None, None, None).unwrap();
    (c.count as usize, c.classes.clone(), c.tolerances.path)
}
