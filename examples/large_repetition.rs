//! Repetition at large outputs: `cargo run --release --example large_repetition [name|path.png|all]
//! [size]`. For each exemplar, `SEEDS` seeds (default 2) at `size` (default 1024): the
//! output's repetition at shifts of 48 pixels or more (`energy::repetition`, 1 = none,
//! 0 = a verbatim translated copy) beside the exemplar's own, its patch energy, its
//! colour histogram's distance to the exemplar's (`energy::colour_distance`) and the
//! time; seed 1 is written to out/large/<name>-<size>.png. A small exemplar must recur
//! many times in a large output, but as scattered patches: a lattice of copies shows as
//! a low score. Beside it, the same measure in windows of the exemplar's size
//! (`energy::repetition_fair`, shifts of 24 pixels or more, as `tile_quality` measures
//! tiles), against the exemplar's own: how much more the output repeats than its
//! exemplar, with the output's size taken out. With `PEER` (texture-synthesis 0.8.3's
//! CLI), its outputs of the same exemplars, sizes and seeds are measured alike (its time
//! includes its process's start).
#[path = "support/textures.rs"]
mod textures;
use patternsynth::raster::codec::encode_png;
use patternsynth::raster::energy::{colour_distance, patch_energy, repetition, repetition_fair};
use patternsynth::raster::synthesis::Schedule;
use patternsynth::raster::{synthesize_texture, Image, TextureOptions};
use patternsynth::Silent;
use std::time::Instant;

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let names = textures::named(args.get(1).map_or("all", |s| s.as_str()));
    let size: usize = args.get(2).and_then(|s| s.parse().ok()).unwrap_or(1024);
    let seeds: u64 = std::env::var("SEEDS").ok().and_then(|s| s.parse().ok()).unwrap_or(2);
    let levels = std::env::var("LEVELS").ok().and_then(|s| s.parse().ok());
    let schedule = match std::env::var("SCHEDULE").as_deref() {
        Ok("bands") => Schedule::Bands,
        Ok("scanline") => Schedule::Scanline,
        _ => Schedule::Auto,
    };
    // PEER=path of texture-synthesis 0.8.3's CLI: its outputs of the same exemplars,
    // sizes and seeds, measured alike on the line below ours.
    let peer = std::env::var("PEER").ok();
    std::fs::create_dir_all("out/large").unwrap();
    let (mut worst, mut energy_sum) = (f64::INFINITY, 0.0);
    for (name, by_peer) in names.iter().flat_map(|n| [(n, false)].into_iter().chain(peer.as_ref().map(|_| (n, true)))) {
        let ex = textures::load(name);
        let (mut rep, mut energy, mut colour, mut fair, mut ms) = (0.0, 0.0, 0.0, 0.0, Vec::new());
        for seed in 1..=seeds {
            let o = TextureOptions { width: size, height: size, seed, levels, schedule, ..Default::default() };
            let t = Instant::now();
            let out = match (&peer, by_peer) {
                (Some(cli), true) => textures::peer(cli, name, size, seed, false),
                _ => synthesize_texture(&ex, &o, &mut Silent).unwrap(),
            };
            ms.push(t.elapsed().as_secs_f64() * 1e3);
            if seed == 1 {
                let name = name.rsplit('/').next().unwrap_or(name).trim_end_matches(".png");
                let who = if by_peer { "-peer" } else { "" };
                std::fs::write(format!("out/large/{name}-{size}{who}.png"), encode_png(size, size, &out.data).unwrap())
                    .unwrap();
            }
            let out = Image::from_rgba8(out.width, out.height, &out.data).unwrap();
            rep += repetition(&out, 48, seed);
            fair += repetition_fair(&out, (ex.width, ex.height), 24.min(ex.width / 4), 8, seed);
            energy += patch_energy(&out, &ex, 200, (0, size), seed);
            colour += colour_distance(&out, &ex);
        }
        let (rep, energy, colour) = (rep / seeds as f64, energy / seeds as f64, colour / seeds as f64);
        let fair = fair / seeds as f64;
        let own_fair = repetition(&ex, 24.min(ex.width / 4), 1);
        ms.sort_by(f64::total_cmp);
        let own = repetition(&ex, 48, 1);
        let name = if by_peer { "  (peer)" } else { name.rsplit('/').next().unwrap_or(name) };
        println!(
            "{name:7} repetition {rep:.3} (exemplar {own:.3}), in exemplar-sized crops {fair:.3} (exemplar {own_fair:.3})  energy {energy:.2}  colour {colour:.3}  {:.0} ms",
            ms[ms.len() / 2]
        );
        if !by_peer {
            worst = worst.min(fair - own_fair).min(rep - own);
            energy_sum += energy;
        }
    }
    println!(
        "worst repetition below the exemplar's own (whole or in exemplar-sized crops) {worst:+.3}, mean energy {:.2}",
        energy_sum / names.len() as f64
    );
}
