//! Line art on a clear ground, as a person exports it from a drawing program: wobbly
//! rings of dark ink 2 pixels wide, antialiased, on a transparent white ground. Shared by
//! `examples/clear_ground` and `tests/seamless.rs`.

use patternsynth::raster::Rgba;

/// `rings` rings on a `side` x `side` clear ground, placed by `seed`.
pub fn line_art(side: usize, rings: usize, seed: u64) -> Rgba {
    let mut rng = patternsynth::rng::Rng::new(seed);
    let mut alpha = vec![0f64; side * side];
    for _ in 0..rings {
        let (cx, cy) = (rng.next_f64() * side as f64, rng.next_f64() * side as f64);
        let r = 5.0 + 5.0 * rng.next_f64();
        let (wobble, phase) = (0.8 + 0.8 * rng.next_f64(), rng.next_f64() * 6.3);
        for y in 0..side {
            for x in 0..side {
                let (dx, dy) = (x as f64 + 0.5 - cx, y as f64 + 0.5 - cy);
                let radius = r + wobble * (3.0 * dy.atan2(dx) + phase).sin();
                let ink = (1.5 - ((dx * dx + dy * dy).sqrt() - radius).abs()).clamp(0.0, 1.0);
                alpha[y * side + x] = alpha[y * side + x].max(ink);
            }
        }
    }
    let data = alpha
        .iter()
        .flat_map(|&a| if a > 0.0 { [20, 30, 90, (a * 255.0).round() as u8] } else { [255, 255, 255, 0] })
        .collect();
    Rgba { width: side, height: side, data }
}
