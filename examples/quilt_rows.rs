//! Where a tile's quilt lays the exemplar's top rows (a feature its top edge cuts off has
//! no top anywhere in it): per tenth of the coarsest level's rows, how many pixels copy
//! exemplar rows 0-1 of that level, over seeds 1-32, with the tile's quilt (window 6,
//! 8 origins, coverage weight 3). A pile in the last tenths is the quilt paying what its
//! coverage term still owes where the wrap closes.
//! `cargo run --release --example quilt_rows <png> [output side at the coarsest level]`
use patternsynth::raster::pyramid::{build, Edge};
use patternsynth::raster::quilt::Quilt;
use patternsynth::raster::{codec::decode_image, Image};
use patternsynth::rng::Rng;

fn main() {
    let a: Vec<String> = std::env::args().collect();
    let img = decode_image(&std::fs::read(&a[1]).unwrap()).unwrap();
    let ex = Image::from_rgba8(img.width, img.height, &img.data).unwrap();
    let coarse = build(&ex, 4, Edge::Clamp).pop().unwrap();
    let n: usize = a.get(2).and_then(|s| s.parse().ok()).unwrap_or(75);
    let q = Quilt { side: 6, candidates: 8, spread: 3.0 };
    let mut rows = vec![0usize; n];
    for seed in 1..=32u64 {
        let map = q.lay(&coarse, None, None, (n, n), true, &mut Rng::new(seed)).unwrap();
        for (i, &p) in map.iter().enumerate() {
            if (p as usize) / coarse.width <= 1 {
                rows[i / n] += 1;
            }
        }
    }
    let bins: Vec<String> = rows.chunks(n.div_ceil(10)).map(|c| c.iter().sum::<usize>().to_string()).collect();
    println!("exemplar rows 0-1 copied, per tenth of the output's rows: {}", bins.join(" "));
}
