//! Tile quality by method (issue 25): for each fixture photograph (or PNG given) and
//! seeds 1-3 (`SEEDS`; from `FIRST`), the seamless tile of E-TFMCM as the paper makes it, E-TFMCM
//! refined by toroidal synthesis, and toroidal synthesis alone (the default): patch
//! energy against the photograph, colour distance, repetition in windows of the
//! exemplar's size (`energy::repetition_fair`) beside the exemplar's own, and seam
//! score, means over the seeds, as a Markdown table; each seed-1 tile saved repeated
//! 2 x 2 in out/tiles/ to look at. With `PEER` (the path of texture-synthesis 0.8.3's
//! CLI) its `--tiling` tiles are made and measured alike, and a second table counts the
//! exemplars where each method meets issue 25's aims against it; the peer gets the
//! file as it is, so it runs only on square images of the tile's size (ours crop and
//! scale). `METHOD=synthesis` and the like keep those of ours whose label starts so.
//! `cargo run --release --example tile_quality [size] [fixture|all|path.png ...]`
#[path = "support/textures.rs"]
mod textures;
use patternsynth::raster::energy::{colour_distance, patch_energy, repetition, repetition_fair};
use patternsynth::raster::Image;
use patternsynth::seamless::{seamless_tile, Method, SeamlessOptions};
use patternsynth::Silent;

fn image(r: &patternsynth::raster::Rgba) -> Image {
    Image::from_rgba8(r.width, r.height, &r.data).unwrap()
}

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let size: Option<usize> = args.get(1).and_then(|s| s.parse().ok());
    let names: Vec<String> = match args.get(2..) {
        Some(rest) if !rest.is_empty() => rest.iter().flat_map(|a| textures::named(a)).collect(),
        _ => textures::named("all"),
    };
    std::fs::create_dir_all("out/tiles").unwrap();
    // (SEEDS=n for seeds 1-n, default 3; METHOD=synthesis and the like for one method.)
    let seeds: u64 = std::env::var("SEEDS").ok().and_then(|s| s.parse().ok()).unwrap_or(3);
    // (FIRST=k starts the seeds at k, whose tiles are the ones saved.)
    let first: u64 = std::env::var("FIRST").ok().and_then(|s| s.parse().ok()).unwrap_or(1);
    let only = std::env::var("METHOD").ok();
    let methods: [(&str, Method, bool); 3] = [
        ("etfmcm (paper)", Method::Etfmcm, false),
        ("etfmcm refined", Method::Etfmcm, true),
        ("synthesis", Method::Synthesis, true),
    ];
    // PEER=path of texture-synthesis 0.8.3's CLI: its `--tiling` tiles of the same
    // exemplars and seeds, one thread, measured by the same code.
    let peer = std::env::var("PEER").ok();
    let labels: Vec<&str> = methods.iter().map(|m| m.0).chain(peer.as_ref().map(|_| PEER_LABEL)).collect();
    println!("| exemplar | method | energy | colour | repetition (exemplar) | seam |");
    println!("|---|---|---:|---:|---:|---:|");
    // Per exemplar and method: energy, colour, repetition, the exemplar's own, seam.
    let mut table: Vec<Vec<[f64; 5]>> = Vec::new();
    for name in &names {
        let img = textures::rgba(name);
        let ex = image(&img);
        let stem = name.rsplit('/').next().unwrap_or(name).trim_end_matches(".png").to_string();
        let mut row = Vec::new();
        for (k, label) in labels.iter().enumerate() {
            if k < methods.len() && only.as_deref().is_some_and(|o| !label.starts_with(o)) {
                row.push([f64::NAN; 5]);
                continue;
            }
            let side = size.unwrap_or(img.width);
            if k == methods.len() && (img.width, img.height) != (side, side) {
                eprintln!("{name}: not a square of the tile's size; the peer is left out");
                row.push([f64::NAN; 5]);
                continue;
            }
            let mut sum = [0.0; 5];
            for seed in first..first + seeds {
                let (tile, seam) = match methods.get(k) {
                    Some(&(_, method, refine)) => {
                        let opts = SeamlessOptions { method, size, seed, refine, ..Default::default() };
                        let t = seamless_tile(&img, &opts, &mut Silent).unwrap();
                        (t.image, t.seam_score)
                    }
                    None => peer_tile(peer.as_deref().unwrap(), name, img.width, seed),
                };
                let out = image(&tile);
                sum[0] += patch_energy(&out, &ex, 300, (0, out.height), 1);
                sum[1] += colour_distance(&out, &ex);
                sum[2] += repetition_fair(&out, (ex.width, ex.height), 24.min(ex.width / 4), 8, 1);
                sum[3] += repetition(&ex, 24.min(ex.width / 4), 1);
                sum[4] += seam;
                // (SAVE_ALL: every seed's tile, once, to out/all/.)
                if std::env::var("SAVE_ALL").is_ok() {
                    std::fs::create_dir_all("out/all").unwrap();
                    let png = patternsynth::raster::codec::encode_png(tile.width, tile.height, &tile.data).unwrap();
                    let tag = label.replace([' ', '(', ')', '-'], "");
                    std::fs::write(format!("out/all/{stem}-{tag}-s{seed}.png"), png).unwrap();
                }
                if seed == first {
                    textures::save_repeated(
                        &tile,
                        &format!("out/tiles/{stem}-{}.png", label.replace([' ', '(', ')', '-'], "")),
                    );
                }
            }
            let m = sum.map(|v| v / seeds as f64);
            println!("| {name} | {label} | {:.2} | {:.3} | {:.3} ({:.3}) | {:.2} |", m[0], m[1], m[2], m[3], m[4]);
            row.push(m);
        }
        table.push(row);
    }
    if peer.is_none() {
        return;
    }
    // Against the peer, per method: how many exemplars meet each of issue 25's aims.
    let p = labels.len() - 1;
    println!("\n| method | energy <= peer's | <= 1.1x | median ratio | colour <= peer's | repetition >= own - 0.05 | seam 0.8-1.2 |");
    println!("|---|---:|---:|---:|---:|---:|---:|");
    for (k, label) in labels.iter().enumerate() {
        let rows: Vec<(&[f64; 5], &[f64; 5])> =
            table.iter().map(|r| (&r[k], &r[p])).filter(|(m, q)| !m[0].is_nan() && !q[0].is_nan()).collect();
        let count = |f: &dyn Fn(&[f64; 5], &[f64; 5]) -> bool| rows.iter().filter(|(m, q)| f(m, q)).count();
        let mut ratios: Vec<f64> = rows.iter().map(|(m, q)| m[0] / q[0]).collect();
        ratios.sort_by(f64::total_cmp);
        let n = rows.len();
        println!(
            "| {label} | {}/{n} | {}/{n} | {:.2} | {}/{n} | {}/{n} | {}/{n} |",
            count(&|m, q| m[0] <= q[0]),
            count(&|m, q| m[0] <= 1.1 * q[0]),
            ratios.get(n / 2).copied().unwrap_or(f64::NAN),
            count(&|m, q| m[1] <= q[1]),
            count(&|m, _| m[2] >= m[3] - 0.05),
            count(&|m, _| (0.8..=1.2).contains(&m[4])),
        );
    }
}

const PEER_LABEL: &str = "texture-synthesis --tiling";

/// The peer's tile of `name` at `side`, and its seam score by our measure.
fn peer_tile(cli: &str, name: &str, side: usize, seed: u64) -> (patternsynth::raster::Rgba, f64) {
    let tile = textures::peer(cli, name, side, seed, true);
    let seam = patternsynth::seamless::measure::seam_score(&tile.rgb(), tile.width, tile.height);
    (tile, seam)
}
