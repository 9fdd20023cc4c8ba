//! Whether a tile's wrap is a seam or just one of its lines: the seam score
//! (`measure::seam_score`) of every boundary of the torus, found by rolling the tile so
//! that the boundary becomes the wrap, averaged over seeds 1-8 (`SEEDS`) and grouped by the
//! boundary's position modulo 8 (the finest pixels of one coarsest-level pixel of a
//! 256 synthesis tile). A wrap that scores like the lines of its own group is no seam;
//! the group's excess is the block structure of the synthesis. The photograph's own
//! lines are scored alike by phase: a grid of its own shows there too.
//! `cargo run --release --example seam_lines <exemplar|all> <etfmcm|tfmcm|synthesis> [size]`
#[path = "support/textures.rs"]
mod textures;
use patternsynth::seamless::measure::seam_score;
use patternsynth::seamless::{seamless_tile, SeamlessOptions};
use patternsynth::Silent;

fn main() {
    let a: Vec<String> = std::env::args().collect();
    let (names, method) = (textures::named(&a[1]), textures::method(&a[2]));
    let size = a.get(3).and_then(|s| s.parse().ok());
    // (SEEDS=n for seeds 1-n, default 8: one seed's wrap varies by about 0.4.)
    let seeds: u64 = std::env::var("SEEDS").ok().and_then(|s| s.parse().ok()).unwrap_or(8);
    for name in &names {
        let img = textures::rgba(name);
        let (mut wrap, mut groups) = (0.0, [(0.0, 0usize); 8]);
        for seed in 1..=seeds {
            let opts = SeamlessOptions { method, size, seed, ..Default::default() };
            let tile = seamless_tile(&img, &opts, &mut Silent).unwrap().image;
            let (n, rgb) = (tile.width, tile.rgb());
            for s in 0..n {
                // Rolled by s both ways: boundary s - 1 | s (columns and rows) is the wrap.
                let rolled: Vec<[u8; 3]> = (0..n * n).map(|i| rgb[((i / n + s) % n) * n + (i % n + s) % n]).collect();
                let score = seam_score(&rolled, n, n);
                if s == 0 {
                    wrap += score;
                } else {
                    let g = &mut groups[(s - 1) % 8];
                    *g = (g.0 + score, g.1 + 1);
                }
            }
        }
        let show = |groups: &[(f64, usize); 8]| -> String {
            let g: Vec<String> =
                groups.iter().enumerate().map(|(r, (s, k))| format!("{r}:{:.3}", s / *k as f64)).collect();
            g.join(" ")
        };
        println!("{name}: wrap {:.3}; inner boundaries by position mod 8: {}", wrap / seeds as f64, show(&groups));
        // The photograph's own lines scored alike, as if each were the wrap (those at
        // least 5 from its edges, whose cut is then 5 lines away): what a faithful copy
        // of it would read at each phase.
        let (w, h, rgb) = (img.width, img.height, img.rgb());
        let mut own = [(0.0, 0usize); 8];
        for s in 6..w.min(h).saturating_sub(5) {
            let rolled: Vec<[u8; 3]> = (0..w * h).map(|i| rgb[((i / w + s) % h) * w + (i % w + s) % w]).collect();
            let g = &mut own[(s - 1) % 8];
            *g = (g.0 + seam_score(&rolled, w, h), g.1 + 1);
        }
        println!("{name}: the photograph's own lines by position mod 8: {}", show(&own));
    }
}
