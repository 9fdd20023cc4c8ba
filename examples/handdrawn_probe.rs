//! The hand-drawn motif table (issue 23): every motif of `handdrawn` on every lattice at
//! wobbles 0.2%, 1%, 3% and 5% of the spacing, drawn 3x3 (and 4x3), grown to 10x8
//! periods with the default options; coverage of every site of every part, strays,
//! stacked duplicates and residuals against the generator's lattice, and the classes.
//! `handdrawn_probe [seed] [--sheet DIR]`: with `--sheet`, each output's SVG is written
//! for the contact sheets.
use patternsynth::vector::handdrawn::{draw, grow_and_measure, lattices, motifs};
use patternsynth::vector::StrokeOptions;

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let seed: u64 = args.first().and_then(|s| s.parse().ok()).unwrap_or(1);
    let sheet = args.iter().position(|a| a == "--sheet").and_then(|i| args.get(i + 1)).cloned();
    let off = args.iter().any(|a| a == "--variation-off");
    let spacing = 70.0;
    println!("motif      lattice    wobble copies  out    cov%   stray stacked  median   p95   classes/parts");
    let mut worst = (100.0f64, 0usize, 0usize, 0.0f64, 0.0f64);
    for motif in motifs() {
        for (lname, a, b) in lattices() {
            for wobble in [0.002, 0.01, 0.03, 0.05] {
                for (nx, ny) in [(3, 3), (4, 3)] {
                    let ex = draw(&motif, (a, b), (nx, ny), spacing, wobble, seed);
                    let opts = StrokeOptions { seed, variation: !off, ..Default::default() };
                    let (r, res) = grow_and_measure(&ex, (a, b), spacing, opts);
                    let (n, classes, svg) = (res.strokes.len(), res.classification.count, res.svg);
                    println!(
                        "{:<10} {:<10} {:>5.1}% {}x{} {:>6} {:>7.2} {:>5} {:>7} {:>7.3} {:>6.3}   {}/{}",
                        motif.name,
                        lname,
                        wobble * 100.0,
                        nx,
                        ny,
                        n,
                        r.coverage * 100.0,
                        r.stray,
                        r.stacked,
                        r.median_residual,
                        r.p95_residual,
                        classes,
                        motif.parts.len()
                    );
                    worst = (
                        worst.0.min(r.coverage * 100.0),
                        worst.1.max(r.stray),
                        worst.2.max(r.stacked),
                        worst.3.max(r.median_residual),
                        worst.4.max(r.p95_residual),
                    );
                    if let Some(dir) = &sheet {
                        let name = format!("{dir}/{}-{lname}-{}-{nx}x{ny}.svg", motif.name, (wobble * 1000.0) as u32);
                        std::fs::write(name, svg).expect("write");
                    }
                }
            }
        }
    }
    println!(
        "worst: coverage {:.2}% strays {} stacked {} median {:.3} p95 {:.3}",
        worst.0, worst.1, worst.2, worst.3, worst.4
    );
}
