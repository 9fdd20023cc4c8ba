//! The edge a fill leaves at its hole's boundary: the mean colour step across the
//! boundary over the mean step between neighbours just outside it (about 1: no edge;
//! the measure of the issue-30 peer comparison), and the fill's patch energy (windows in
//! the hole against windows wholly outside it), for
//! photographs and hole masks given as PNG pairs (`photo.png:hole.png`, white = hole),
//! over seeds 1-3; and the share of filled pixels whose colour is nowhere outside the
//! hole (within 8 levels a channel: a heal that carries a structure's step into the
//! fill tints it, purple on a green circuit board). `cargo run --release --example inpaint_edge -- a.png:a_hole.png ...`
use patternsynth::raster::codec::{decode_image, encode_png};
use patternsynth::raster::{inpaint_texture, InpaintOptions, Rgba};
use patternsynth::Silent;

fn edge_ratio(im: &Rgba, hole: &[bool], r: isize) -> f64 {
    let (w, h) = (im.width as isize, im.height as isize);
    let d = |p: usize, q: usize| {
        (0..3).map(|c| (im.data[4 * p + c] as f64 - im.data[4 * q + c] as f64).abs()).sum::<f64>() / 3.0
    };
    let mut near = vec![false; hole.len()];
    for y in 0..h {
        for x in 0..w {
            if hole[(y * w + x) as usize] {
                for yy in (y - r).max(0)..(y + r + 1).min(h) {
                    for xx in (x - r).max(0)..(x + r + 1).min(w) {
                        near[(yy * w + xx) as usize] = true;
                    }
                }
            }
        }
    }
    let (mut bs, mut bn, mut rs, mut rn) = (0.0, 0, 0.0, 0);
    for y in 0..h {
        for x in 0..w {
            let p = (y * w + x) as usize;
            for q in [(x + 1 < w).then_some(p + 1), (y + 1 < h).then_some(p + w as usize)].into_iter().flatten() {
                if hole[p] != hole[q] {
                    bs += d(p, q);
                    bn += 1;
                } else if !hole[p] && near[p] && near[q] {
                    rs += d(p, q);
                    rn += 1;
                }
            }
        }
    }
    (bs / bn as f64) / (rs / rn as f64)
}

/// RMS distance of 7 x 7 windows centred in the hole (every 3rd pixel) to their best
/// match among the windows wholly outside it (the peer comparison's fill energy).
fn fill_energy(out: &Rgba, img: &Rgba, hole: &[bool]) -> f64 {
    let (w, h) = (img.width, img.height);
    let px = |im: &Rgba, x: usize, y: usize, c: usize| im.data[4 * (y * w + x) + c] as f64;
    let mut sources = Vec::new();
    for y in 3..h - 3 {
        for x in 3..w - 3 {
            if (0..7).all(|j| (0..7).all(|i| !hole[(y + j - 3) * w + x + i - 3])) {
                sources.push((x, y));
            }
        }
    }
    let (mut total, mut n) = (0.0, 0);
    for y in (3..h - 3).step_by(3) {
        for x in (3..w - 3).step_by(3) {
            if !hole[y * w + x] {
                continue;
            }
            let mut best = f64::INFINITY;
            for &(sx, sy) in &sources {
                let mut acc = 0.0;
                'win: for j in 0..7 {
                    for i in 0..7 {
                        for c in 0..3 {
                            let d = px(out, x + i - 3, y + j - 3, c) - px(img, sx + i - 3, sy + j - 3, c);
                            acc += d * d;
                        }
                    }
                    if acc > best {
                        break 'win;
                    }
                }
                best = best.min(acc);
            }
            // MEAN_RMS=1: each window's RMS averaged (bench/peer-verbs.mjs's patch energy),
            // rather than the RMS over every window.
            total += if mean_rms() { (best / 147.0).sqrt() } else { best / 147.0 };
            n += 1;
        }
    }
    if mean_rms() {
        total / n as f64
    } else {
        (total / n as f64).sqrt()
    }
}

fn mean_rms() -> bool {
    std::env::var("MEAN_RMS").is_ok_and(|v| v == "1")
}

/// Share of the hole's pixels whose colour, in steps of 8 levels a channel, is not
/// within one step (each channel) of a colour outside the hole.
fn foreign(out: &Rgba, img: &Rgba, hole: &[bool]) -> f64 {
    let bin = |im: &Rgba, i: usize| [0, 1, 2].map(|c| (im.data[4 * i + c] / 8) as i32);
    let mut seen = vec![false; 32 * 32 * 32];
    for i in (0..hole.len()).filter(|&i| !hole[i]) {
        let [r, g, b] = bin(img, i);
        for (dr, dg, db) in (-1..=1).flat_map(|x| (-1..=1).flat_map(move |y| (-1..=1).map(move |z| (x, y, z)))) {
            let (r, g, b) = (r + dr, g + dg, b + db);
            if [r, g, b].iter().all(|v| (0..32).contains(v)) {
                seen[((r * 32 + g) * 32 + b) as usize] = true;
            }
        }
    }
    let filled: Vec<usize> = (0..hole.len()).filter(|&i| hole[i]).collect();
    let alien = filled.iter().filter(|&&i| {
        let [r, g, b] = bin(out, i);
        !seen[((r * 32 + g) * 32 + b) as usize]
    });
    alien.count() as f64 / filled.len().max(1) as f64
}

fn main() {
    let mut all = Vec::new();
    // SEEDS=n: seeds 1-n (3 by default); the per-photograph figures are their medians.
    let seeds: u64 = std::env::var("SEEDS").ok().and_then(|s| s.parse().ok()).unwrap_or(3);
    let mut logs = (0.0f64, 0.0f64, 0usize);
    for arg in std::env::args().skip(1) {
        let (photo, mask) = arg.split_once(':').expect("photo.png:hole.png");
        let img = decode_image(&std::fs::read(photo).unwrap()).unwrap();
        let m = decode_image(&std::fs::read(mask).unwrap()).unwrap();
        let hole: Vec<bool> = m.data.chunks_exact(4).map(|p| p[0] > 127).collect();
        let mut ratios = Vec::new();
        let mut energies = Vec::new();
        let mut times = Vec::new();
        let mut aliens = Vec::new();
        for seed in 1..=seeds {
            let t = std::time::Instant::now();
            // OUTPUTS=dir/{}.tag: measure the fills saved there as NAME.tag.sSEED.png (another
            // program's, the peer's) rather than making ours.
            let out = match std::env::var("OUTPUTS") {
                Ok(pattern) => {
                    let name = std::path::Path::new(photo).file_stem().unwrap().to_string_lossy().to_string();
                    let path = format!("{}.s{seed}.png", pattern.replace("{}", &name));
                    decode_image(&std::fs::read(path).unwrap()).unwrap()
                }
                Err(_) => {
                    inpaint_texture(&img, &hole, &InpaintOptions { seed, ..Default::default() }, &mut Silent).unwrap()
                }
            };
            times.push(t.elapsed().as_secs_f64() * 1e3);
            ratios.push(edge_ratio(&out, &hole, 8));
            energies.push(fill_energy(&out, &img, &hole));
            aliens.push(foreign(&out, &img, &hole));
            logs.0 += ratios.last().unwrap().ln();
            logs.1 += energies.last().unwrap().ln();
            logs.2 += 1;
            if seed == 1 {
                let name = std::path::Path::new(photo).file_stem().unwrap().to_string_lossy().to_string();
                std::fs::create_dir_all("out/fill").unwrap();
                std::fs::write(
                    format!("out/fill/edge-{name}.png"),
                    encode_png(out.width, out.height, &out.data).unwrap(),
                )
                .unwrap();
            }
        }
        ratios.sort_by(f64::total_cmp);
        energies.sort_by(f64::total_cmp);
        times.sort_by(f64::total_cmp);
        aliens.sort_by(f64::total_cmp);
        println!(
            "{photo}: edge ratio {:.2} (photo's own {:.2}), fill energy {:.2} (photo's own {:.2}), foreign colours {:.2}% (photo's own {:.2}%), {:.0} ms",
            ratios[ratios.len() / 2],
            edge_ratio(&img, &hole, 8),
            energies[energies.len() / 2],
            fill_energy(&img, &img, &hole),
            100.0 * aliens[aliens.len() / 2],
            100.0 * foreign(&img, &img, &hole),
            times[times.len() / 2]
        );
        all.push((ratios[ratios.len() / 2], energies[energies.len() / 2], aliens[aliens.len() / 2]));
    }
    let median = |k: usize| {
        let mut v: Vec<f64> = all.iter().map(|a| [a.0, a.1, a.2][k]).collect();
        v.sort_by(f64::total_cmp);
        v[v.len() / 2]
    };
    println!(
        "median edge ratio {:.2}, fill energy {:.2}, foreign colours {:.2}%",
        median(0),
        median(1),
        100.0 * median(2)
    );
    println!(
        "geometric means over photographs and seeds: edge ratio {:.3}, fill energy {:.3}",
        (logs.0 / logs.2 as f64).exp(),
        (logs.1 / logs.2 as f64).exp()
    );
}
