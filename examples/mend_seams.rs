//! Mended tiles' seams on photographs: each PNG given is mended into a tile at the
//! default band over seeds 1-3 (`SEEDS=n` for 1-n), and per photograph printed:
//! - the seam score of each seed and their median, as bench/peer-verbs.mjs `seamScore`
//!   measures it (the tile repeated 2 x 2; the mean Euclidean RGB step across its two
//!   wrap lines over the mean step across every other line), and beside it the peer's
//!   where `PEER=dir` holds `NAME.peer.s{1,2,3}.png` (bench/peer-verbs.mjs's outputs);
//! - the share of the photograph's pixels kept as they were, and the time per mend;
//! - `own`: the 10th, 50th and 90th percentiles of the photograph's own lines scored as
//!   if each were the wrap (a wrap among them steps as a line of the photograph does;
//!   `PARTS=1` prints the vertical and horizontal wrap apart against the photograph's
//!   columns and rows);
//! - `near`: the mean step across the 9 lines round the wrap, each way, over the mean
//!   (below 1 where the middle of the band is smoothed over);
//! - `lines`: the band's strongest column and row against the photograph's strongest
//!   (as `seamless::mend::band_line`, each way, but with the band's boundaries along the
//!   kept photograph too; above 1, a line the photograph has nowhere);
//! - with `ENERGY=1`, the band's patch energy (7 x 7 windows round band pixels, read on
//!   the torus, against the photograph's, exact nearest neighbour, 300 samples);
//! - with `PROFILE=1`, each seed's column and row steps round the wrap;
//! - with `PLAIN=runs`, the plain synthesis of the photograph's size from it (same seed)
//!   timed beside each mend, `runs` interleaved pairs a seed, and the ratio of the
//!   medians (issue 30's speed bar: a mend within 1.5 times it).
//!
//! Seed 1's tile repeated 2 x 2 goes to out/mend/NAME-2x2.png (`OUT=dir` elsewhere; with
//! `ALL=1` the other seeds' too, NAME-sN-2x2.png). `SPEED=runs` times bench/verbs.mjs's
//! comparison natively instead; `BIG="side dir"` writes a side x side plain synthesis of
//! each photograph given to dir (larger photographs of the same materials).
//! `cargo run --release --example mend_seams -- photo.png ...`
#[path = "support/textures.rs"]
mod textures;
use patternsynth::raster::codec::decode_image;
use patternsynth::raster::Rgba;
use patternsynth::rng::Rng;
use patternsynth::seamless::mend::{band_mask, mend, DEFAULT_BAND};
use patternsynth::Silent;
use std::time::Instant;

/// The mean Euclidean RGB step across each column boundary and each row boundary of an
/// image read on the torus: `cols[b]` between columns `b` and `b + 1`, the last across
/// the wrap; likewise `rows`.
struct Lines {
    cols: Vec<f64>,
    rows: Vec<f64>,
}

impl Lines {
    fn of(t: &Rgba) -> Lines {
        let (w, h) = (t.width, t.height);
        let px = |x: usize, y: usize| &t.data[((y % h) * w + x % w) * 4..][..3];
        let step = |a: &[u8], b: &[u8]| (0..3).map(|c| (a[c] as f64 - b[c] as f64).powi(2)).sum::<f64>().sqrt();
        Lines {
            cols: (0..w).map(|b| (0..h).map(|y| step(px(b, y), px(b + 1, y))).sum::<f64>() / h as f64).collect(),
            rows: (0..h).map(|b| (0..w).map(|x| step(px(x, b), px(x, b + 1))).sum::<f64>() / w as f64).collect(),
        }
    }

    /// The mean step per pixel pair across the boundaries inside the image (the wrap left
    /// out), each line weighted by its length.
    fn inside_mean(&self) -> f64 {
        let (w, h) = (self.cols.len(), self.rows.len());
        (self.cols[..w - 1].iter().sum::<f64>() * h as f64 + self.rows[..h - 1].iter().sum::<f64>() * w as f64)
            / ((w - 1) * h + (h - 1) * w) as f64
    }

    /// The mean step across every boundary, the wrap's among them, lines unweighted.
    fn mean(&self) -> f64 {
        (self.cols.iter().sum::<f64>() + self.rows.iter().sum::<f64>()) / (self.cols.len() + self.rows.len()) as f64
    }
}

/// bench/peer-verbs.mjs `seamScore`: in the tile repeated 2 x 2, the mean step across its
/// two wrap lines over the mean step across all its other lines (each of the tile's
/// inner boundaries stands twice there, the wrap once a way).
fn seam_score(t: &Rgba) -> f64 {
    let l = Lines::of(t);
    let (w, h) = (t.width as f64, t.height as f64);
    let wrap = (h * l.cols[t.width - 1] + w * l.rows[t.height - 1]) / (h + w);
    wrap / l.inside_mean()
}

/// The band's patch energy: 7 x 7 windows round `samples` band pixels of `tile` (read on
/// the torus), each against its nearest 7 x 7 window inside `photo`, RMS per value, averaged.
fn band_energy(tile: &Rgba, photo: &Rgba, band: &[bool], samples: usize, seed: u64) -> f64 {
    const R: isize = 3;
    let (w, h) = (tile.width as isize, tile.height as isize);
    let centres: Vec<usize> = (0..band.len()).filter(|&i| band[i]).collect();
    let mut rng = Rng::new(seed);
    let mut total = 0.0;
    let mut q = Vec::with_capacity(147);
    for _ in 0..samples {
        let c = centres[rng.below(centres.len())];
        let (cx, cy) = ((c % tile.width) as isize, (c / tile.width) as isize);
        q.clear();
        for dy in -R..=R {
            for dx in -R..=R {
                let (x, y) = ((cx + dx).rem_euclid(w), (cy + dy).rem_euclid(h));
                q.extend(tile.data[((y * w + x) * 4) as usize..][..3].iter().map(|&v| v as f32));
            }
        }
        let mut best = f32::INFINITY;
        for sy in R..h - R {
            for sx in R..w - R {
                let mut d = 0.0f32;
                let mut k = 0;
                'win: for dy in -R..=R {
                    let row = (((sy + dy) * w + sx - R) * 4) as usize;
                    for dx in 0..7 {
                        let p = &photo.data[row + dx * 4..][..3];
                        for &c in p {
                            let v = c as f32 - q[k];
                            d += v * v;
                            k += 1;
                        }
                    }
                    if d >= best {
                        break 'win;
                    }
                }
                best = best.min(d);
            }
        }
        total += (best as f64 / 147.0).sqrt();
    }
    total / samples as f64
}

/// The photograph's own lines as `seam_score` would score them were they the wrap: for
/// every column boundary `bx` and row boundary `by` inside it, the mean step across the
/// two over the mean step across all; its 10th, 50th and 90th percentiles. A wrap within
/// them steps as a line of the photograph does.
fn own_lines(p: &Rgba) -> ([f64; 3], [f64; 3], [f64; 3]) {
    let l = Lines::of(p);
    let (w, h) = (p.width, p.height);
    let mean = l.inside_mean();
    let (cols, rows) = (&l.cols[..w - 1], &l.rows[..h - 1]);
    let pct = |mut all: Vec<f64>| {
        all.sort_by(|a, b| a.total_cmp(b));
        let n = all.len();
        [all[n / 10], all[n / 2], all[9 * n / 10]]
    };
    let both =
        cols.iter().flat_map(|c| rows.iter().map(move |r| (c * h as f64 + r * w as f64) / (h + w) as f64 / mean));
    (pct(both.collect()), pct(cols.iter().map(|c| c / mean).collect()), pct(rows.iter().map(|r| r / mean).collect()))
}

/// The step across the vertical wrap line and across the horizontal one, each over the
/// mean step across all lines (the two halves of `seam_score`, nearly).
fn wrap_parts(t: &Rgba) -> (f64, f64) {
    let l = Lines::of(t);
    let mean = l.inside_mean();
    (l.cols[t.width - 1] / mean, l.rows[t.height - 1] / mean)
}

/// The band's strongest line against the photograph's: the largest mean step across a
/// column boundary of the vertical band (the wrap included) over the largest across a
/// column boundary inside the photograph (its own wrap left out), each relative to the
/// image's mean step, and the same for rows. Above 1, the band holds a line (a joint, an
/// edge run straight along it) that the photograph has nowhere.
fn band_lines(t: &Rgba, photo: &Rgba, band: &[bool]) -> (f64, f64) {
    let (w, h) = (t.width, t.height);
    let (tile, own) = (Lines::of(t), Lines::of(photo));
    let (m, own_m) = (
        tile.mean(),
        (own.cols[..w - 1].iter().sum::<f64>() + own.rows[..h - 1].iter().sum::<f64>()) / (w + h - 2) as f64,
    );
    let max = |v: &mut dyn Iterator<Item = f64>| v.fold(0.0f64, f64::max);
    // A boundary of the band: both its sides in the band (read along the middle row or
    // column, which crosses the kept part).
    let (mid_x, mid_y) = (w / 2, h / 2);
    let in_cols = |b: usize| band[mid_y * w + b] && band[mid_y * w + (b + 1) % w];
    let in_rows = |b: usize| band[b * w + mid_x] && band[((b + 1) % h) * w + mid_x];
    let band_c = max(&mut (0..w).filter(|&b| in_cols(b)).map(|b| tile.cols[b])) / m;
    let band_r = max(&mut (0..h).filter(|&b| in_rows(b)).map(|b| tile.rows[b])) / m;
    let own_c = max(&mut own.cols[..w - 1].iter().copied()) / own_m;
    let own_r = max(&mut own.rows[..h - 1].iter().copied()) / own_m;
    (band_c / own_c, band_r / own_r)
}

/// The mean step across the column and row boundaries within 4 of the wrap (the middle
/// of the band, where its two fronts meet) over the mean across all: below 1 where the
/// meeting is smoothed over, above where it is a line.
fn near_wrap(t: &Rgba) -> f64 {
    let (w, h) = (t.width, t.height);
    let l = Lines::of(t);
    let near = (w - 5..w + 4).map(|b| l.cols[b % w]).sum::<f64>() + (h - 5..h + 4).map(|b| l.rows[b % h]).sum::<f64>();
    near / 18.0 / l.mean()
}

/// Each column and row boundary's mean step within `k` of the wrap (boundary `n - 1`
/// joins the last line to the first), over the mean of all: `PROFILE=1`.
fn profile(t: &Rgba, k: usize) -> String {
    let l = Lines::of(t);
    let mean = l.mean();
    let show = |v: &[f64]| {
        let n = v.len();
        (n - k..n + k).map(|b| format!("{:.2}", v[b % n] / mean)).collect::<Vec<_>>().join(" ")
    };
    format!("cols {} | rows {}", show(&l.cols), show(&l.rows))
}

fn median(mut v: Vec<f64>) -> f64 {
    if v.is_empty() {
        return f64::NAN;
    }
    v.sort_by(|a, b| a.total_cmp(b));
    let n = v.len();
    if n % 2 == 1 {
        v[n / 2]
    } else {
        (v[n / 2 - 1] + v[n / 2]) / 2.0
    }
}

/// bench/verbs.mjs's comparison, natively: a 256 x 256 synthesis (seed 9) of each of three
/// fixtures is the photograph; the mend of it against a plain 256 x 256 synthesis from the
/// fixture, medians of `runs` interleaved runs (`SPEED=runs`).
fn speed(runs: usize) {
    use patternsynth::raster::{synthesize_texture, TextureOptions};
    for name in ["gravel", "brick", "grass"] {
        let ex = textures::load(name);
        let side = 256;
        let opts = |seed| TextureOptions { width: side, height: side, seed, ..Default::default() };
        let photo = synthesize_texture(&ex, &opts(9), &mut Silent).unwrap();
        let (mut plain, mut mended) = (Vec::new(), Vec::new());
        for _ in 0..runs {
            let t = Instant::now();
            synthesize_texture(&ex, &opts(1), &mut Silent).unwrap();
            plain.push(t.elapsed().as_secs_f64() * 1000.0);
            let t = Instant::now();
            mend(&photo, DEFAULT_BAND, None, 1, &mut Silent).unwrap();
            mended.push(t.elapsed().as_secs_f64() * 1000.0);
        }
        let (p, m) = (median(plain), median(mended));
        println!("{name}: plain synthesis {p:.0} ms, mend {m:.0} ms: {:.2}x", m / p);
    }
}

/// `BIG=side dir`: writes a side x side plain synthesis (seed 9) of each photograph given
/// to dir, as a larger photograph of its material to mend.
fn big(side: usize, dir: &str) {
    use patternsynth::raster::{synthesize_texture, Image, TextureOptions};
    for path in std::env::args().skip(1) {
        let name = std::path::Path::new(&path).file_stem().unwrap().to_string_lossy().to_string();
        let photo = decode_image(&std::fs::read(&path).unwrap()).unwrap();
        let ex = Image::from_rgba8(photo.width, photo.height, &photo.data).unwrap();
        let o = TextureOptions { width: side, height: side, seed: 9, ..Default::default() };
        let out = synthesize_texture(&ex, &o, &mut Silent).unwrap();
        let png = patternsynth::raster::codec::encode_png(side, side, &out.data).unwrap();
        std::fs::write(format!("{dir}/{name}.png"), png).unwrap();
    }
}

fn main() {
    if let Ok(b) = std::env::var("BIG") {
        let (side, dir) = b.split_once(' ').unwrap();
        return big(side.parse().unwrap(), dir);
    }
    if let Some(runs) = std::env::var("SPEED").ok().and_then(|r| r.parse().ok()) {
        return speed(runs);
    }
    let out = std::env::var("OUT").unwrap_or_else(|_| "out/mend".into());
    std::fs::create_dir_all(&out).unwrap();
    let peer = std::env::var("PEER").ok();
    let energy = std::env::var("ENERGY").is_ok_and(|e| e == "1");
    let seeds: u64 = std::env::var("SEEDS").ok().and_then(|s| s.parse().ok()).unwrap_or(3);
    let plain_runs: usize = std::env::var("PLAIN").ok().and_then(|s| s.parse().ok()).unwrap_or(0);
    let mut all = Vec::new();
    println!(
        "{:<12} {:<40} median  peer  kept   ms  own             near  lines    {}{}",
        "photograph",
        "seam by seed",
        if energy { "energy " } else { "" },
        if plain_runs > 0 { "plain ms  ratio" } else { "" }
    );
    for path in std::env::args().skip(1) {
        let name = std::path::Path::new(&path).file_stem().unwrap().to_string_lossy().to_string();
        let photo = decode_image(&std::fs::read(&path).unwrap()).unwrap();
        let band = band_mask(photo.width, photo.height, DEFAULT_BAND);
        let (mut seams, mut ms, mut kept, mut pe, mut near) =
            (Vec::new(), Vec::new(), Vec::new(), Vec::new(), Vec::new());
        let (mut wc, mut wr) = (Vec::new(), Vec::new());
        let (mut lc, mut lr) = (Vec::new(), Vec::new());
        let mut plain = Vec::new();
        let ex = patternsynth::raster::Image::from_rgba8(photo.width, photo.height, &photo.data).unwrap();
        for seed in 1..=seeds {
            let mut tile = None;
            for _ in 0..plain_runs.max(1) {
                if plain_runs > 0 {
                    use patternsynth::raster::{synthesize_texture, TextureOptions};
                    let o = TextureOptions { width: photo.width, height: photo.height, seed, ..Default::default() };
                    let t = Instant::now();
                    synthesize_texture(&ex, &o, &mut Silent).unwrap();
                    plain.push(t.elapsed().as_secs_f64() * 1000.0);
                }
                let t = Instant::now();
                tile = Some(mend(&photo, DEFAULT_BAND, None, seed, &mut Silent).unwrap());
                ms.push(t.elapsed().as_secs_f64() * 1000.0);
            }
            let tile = tile.unwrap();
            seams.push(seam_score(&tile));
            near.push(near_wrap(&tile));
            let (c, r) = wrap_parts(&tile);
            wc.push(c);
            wr.push(r);
            let (c, r) = band_lines(&tile, &photo, &band);
            lc.push(c);
            lr.push(r);
            let same = tile.data.chunks_exact(4).zip(photo.data.chunks_exact(4)).filter(|(a, b)| a == b).count();
            kept.push(same as f64 / band.len() as f64);
            let inner = (0..band.len()).all(|i| band[i] || tile.data[4 * i..4 * i + 4] == photo.data[4 * i..4 * i + 4]);
            assert!(inner, "{name}: a pixel outside the band changed");
            if energy {
                pe.push(band_energy(&tile, &photo, &band, 300, seed));
            }
            if std::env::var("PROFILE").is_ok() {
                println!("  s{seed} {}", profile(&tile, 5));
            }
            if seed == 1 {
                textures::save_repeated(&tile, &format!("{out}/{name}-2x2.png"));
            } else if std::env::var("ALL").is_ok() {
                textures::save_repeated(&tile, &format!("{out}/{name}-s{seed}-2x2.png"));
            }
        }
        let peers: Vec<Rgba> = peer.as_ref().map_or(Vec::new(), |dir| {
            (1..=3)
                .filter_map(|s| std::fs::read(format!("{dir}/{name}.peer.s{s}.png")).ok())
                .map(|b| decode_image(&b).unwrap())
                .collect()
        });
        let theirs = peer.as_ref().map(|_| median(peers.iter().map(seam_score).collect()));
        if energy && !peers.is_empty() {
            let pe: Vec<f64> = peers.iter().zip(1..).map(|(t, s)| band_energy(t, &photo, &band, 300, s)).collect();
            println!("  {name}: the peer's band energy {:.2}", median(pe));
        }
        let m = median(seams.clone());
        let (own, own_cols, own_rows) = own_lines(&photo);
        if std::env::var("PARTS").is_ok() {
            println!(
                "  {name}: wrap column {:.2} (the photograph's columns {:.2}-{:.2}-{:.2}), wrap row {:.2} (rows {:.2}-{:.2}-{:.2})",
                median(wc.clone()),
                own_cols[0],
                own_cols[1],
                own_cols[2],
                median(wr.clone()),
                own_rows[0],
                own_rows[1],
                own_rows[2]
            );
        }
        all.push(m);
        let list: Vec<String> = seams.iter().take(8).map(|s| format!("{s:.2}")).collect();
        let mend_ms = median(ms);
        println!(
            "{name:<12} {:<40} {m:.2}    {}  {:.3}  {:<3.0}  {:.2}-{:.2}-{:.2}  {:.2}  {:.2} {:.2}{}{}",
            list.join(" "),
            theirs.map_or("-   ".into(), |p| format!("{p:.2}")),
            median(kept),
            mend_ms,
            own[0],
            own[1],
            own[2],
            median(near),
            median(lc.clone()),
            median(lr.clone()),
            if energy { format!("  {:.2}", median(pe)) } else { String::new() },
            if plain_runs > 0 {
                let p = median(plain);
                format!("  {p:<4.0}  {:.2}", mend_ms / p)
            } else {
                String::new()
            }
        );
    }
    let inside = all.iter().filter(|&&s| (0.8..=1.2).contains(&s)).count();
    println!("medians within 0.8-1.2: {inside} of {}; median of medians {:.2}", all.len(), median(all));
}
