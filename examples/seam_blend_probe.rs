//! Probe: gradient-domain blending of a synthesized tile's seams. Each output edge
//! between two pixels takes the exemplar's own difference where the pixels were copied
//! side by side, and the mean of the two sources' differences where they were not (a
//! seam); the tile is then the torus image nearest those differences, screened by
//! `lambda` towards the copied colours. Prints patch energy, colour distance and
//! repetition, plain and blended, means over seeds.
//! `cargo run --release --example seam_blend_probe [names...]` (LAMBDAS=0.05,0.2 SEEDS=3)
#[path = "support/textures.rs"]
mod textures;
use patternsynth::progress::Throttle;
use patternsynth::raster::energy::{colour_distance, patch_energy, repetition_fair};
use patternsynth::raster::texture::{sources, texture_job, TextureOptions};
use patternsynth::raster::Image;
use patternsynth::Silent;

/// Blended colours (3 f32 per pixel) of a w x h torus output copied from `ex` by `src`.
fn blend(ex: &Image, src: &[u32], w: usize, h: usize, lambda: f32, iterations: usize) -> Vec<[f32; 3]> {
    let ew = ex.width;
    let eh = ex.height;
    let at = |p: u32| ex.data[p as usize];
    let copied: Vec<[f32; 3]> = src.iter().map(|&p| at(p)).collect();
    // Target difference from pixel i to its right / lower neighbour.
    let diff = |i: usize, j: usize, step: (isize, isize)| -> [f32; 3] {
        let (si, sj) = (src[i] as usize, src[j] as usize);
        let (xi, yi) = ((si % ew) as isize, (si / ew) as isize);
        let (xj, yj) = ((sj % ew) as isize, (sj / ew) as isize);
        let inside = |x: isize, y: isize| x >= 0 && y >= 0 && x < ew as isize && y < eh as isize;
        let mut sum = [0.0f32; 3];
        let mut n = 0.0;
        let (ax, ay) = (xi + step.0, yi + step.1);
        if inside(ax, ay) {
            let a = ex.data[ay as usize * ew + ax as usize];
            let b = ex.data[si];
            (0..3).for_each(|c| sum[c] += a[c] - b[c]);
            n += 1.0;
        }
        let (bx, by) = (xj - step.0, yj - step.1);
        if inside(bx, by) {
            let a = ex.data[sj];
            let b = ex.data[by as usize * ew + bx as usize];
            (0..3).for_each(|c| sum[c] += a[c] - b[c]);
            n += 1.0;
        }
        if n == 0.0 {
            let (a, b) = (copied[j], copied[i]);
            return [a[0] - b[0], a[1] - b[1], a[2] - b[2]];
        }
        sum.map(|v| v / n)
    };
    let mut right = Vec::with_capacity(w * h);
    let mut down = Vec::with_capacity(w * h);
    for y in 0..h {
        for x in 0..w {
            let i = y * w + x;
            right.push(diff(i, y * w + (x + 1) % w, (1, 0)));
            down.push(diff(i, ((y + 1) % h) * w + x, (0, 1)));
        }
    }
    // (4 + lambda) I_p - sum I_q = lambda C_p - sum_q g(p -> q); Gauss-Seidel.
    let mut out = copied.clone();
    for _ in 0..iterations {
        for y in 0..h {
            for x in 0..w {
                let i = y * w + x;
                let l = y * w + (x + w - 1) % w;
                let r = y * w + (x + 1) % w;
                let u = ((y + h - 1) % h) * w + x;
                let d = ((y + 1) % h) * w + x;
                for c in 0..3 {
                    // g(p->r) = right[i], g(p->l) = -right[l], g(p->d) = down[i], g(p->u) = -down[u].
                    let g = right[i][c] - right[l][c] + down[i][c] - down[u][c];
                    let s = out[l][c] + out[r][c] + out[u][c] + out[d][c];
                    out[i][c] = (lambda * copied[i][c] + s - g) / (4.0 + lambda);
                }
            }
        }
    }
    out
}

fn main() {
    let names: Vec<String> = std::env::args().skip(1).flat_map(|a| textures::named(&a)).collect();
    let seeds: u64 = std::env::var("SEEDS").ok().and_then(|s| s.parse().ok()).unwrap_or(3);
    let lambdas: Vec<f32> = std::env::var("LAMBDAS")
        .unwrap_or_else(|_| "0.02,0.1,0.5".into())
        .split(',')
        .filter_map(|s| s.parse().ok())
        .collect();
    let iterations: usize = std::env::var("ITER").ok().and_then(|s| s.parse().ok()).unwrap_or(200);
    print!("| exemplar | plain E / C / R |");
    lambdas.iter().for_each(|l| print!(" lambda {l} |"));
    println!();
    std::fs::create_dir_all("out/blend").unwrap();
    for name in &names {
        let ex = textures::load(name);
        let stem = name.rsplit('/').next().unwrap().trim_end_matches(".png").to_string();
        let (w, h) = (ex.width, ex.height);
        let mut sums = vec![[0.0f64; 3]; 1 + lambdas.len()];
        for seed in 1..=seeds {
            let o = TextureOptions { width: w, height: h, seed, tileable: true, ..Default::default() };
            let job = texture_job(&ex, &o).unwrap();
            let src = sources(&job, &mut Throttle::new(&mut Silent)).unwrap();
            let plain = job.colours(&src);
            let mut outs = vec![Image::from_rgba8(w, h, &plain.data).unwrap()];
            for &l in &lambdas {
                let px = blend(&ex, &src[0], w, h, l, iterations);
                outs.push(Image {
                    width: w,
                    height: h,
                    data: px.iter().map(|p| p.map(|v| v.round().clamp(0.0, 255.0))).collect(),
                });
            }
            for (k, out) in outs.iter().enumerate() {
                sums[k][0] += patch_energy(out, &ex, 300, (0, h), 1);
                sums[k][1] += colour_distance(out, &ex);
                sums[k][2] += repetition_fair(out, (w, h), 24.min(w / 4), 8, 1);
                if seed == 1 {
                    let rgba = patternsynth::raster::Rgba {
                        width: w,
                        height: h,
                        data: out.data.iter().flat_map(|p| [p[0] as u8, p[1] as u8, p[2] as u8, 255]).collect(),
                    };
                    textures::save_repeated(&rgba, &format!("out/blend/{stem}-{k}.png"));
                }
            }
        }
        print!("| {stem} |");
        for s in &sums {
            let n = seeds as f64;
            print!(" {:.2} / {:.3} / {:.3} |", s[0] / n, s[1] / n, s[2] / n);
        }
        println!();
    }
}
