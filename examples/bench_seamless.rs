//! Seamless tiles of every fixture photograph (`support::textures::ALL`) by each method: time (median of 3), the
//! paper's restoration rate, the seam score (seed 1, and its mean, least and greatest over
//! seeds 1-8), the score of the photograph itself repeated as it is (a naive tile), and
//! E-TFMCM's decisions, as JSON lines; each seed-1 tile also saved repeated 2 x 2 in
//! out/seamless/ to look at the seams.
//! `cargo run --release --example bench_seamless [size]`
#[path = "support/textures.rs"]
mod textures;
use patternsynth::seamless::measure::seam_score;
use patternsynth::seamless::{seamless_tile, Method, SeamlessOptions};
use patternsynth::Silent;
use std::time::Instant;

fn main() {
    let size: Option<usize> = std::env::args().nth(1).and_then(|s| s.parse().ok());
    std::fs::create_dir_all("out/seamless").unwrap();
    for name in textures::ALL {
        let img = textures::rgba(name);
        let naive = seam_score(&img.rgb(), img.width, img.height);
        for method in [Method::Etfmcm, Method::Tfmcm, Method::Synthesis] {
            let opts = SeamlessOptions { method, size, seed: 1, ..Default::default() };
            let mut times = Vec::new();
            let mut last = None;
            for _ in 0..3 {
                let t = Instant::now();
                last = Some(seamless_tile(&img, &opts, &mut Silent).unwrap());
                times.push(t.elapsed().as_secs_f64() * 1e3);
            }
            times.sort_by(|a, b| a.total_cmp(b));
            let r = last.unwrap();
            let seeds: Vec<f64> = (1..=8)
                .map(|seed| {
                    seamless_tile(&img, &SeamlessOptions { seed, ..opts.clone() }, &mut Silent).unwrap().seam_score
                })
                .collect();
            let mean = seeds.iter().sum::<f64>() / seeds.len() as f64;
            let (lo, hi) = seeds.iter().fold((f64::MAX, f64::MIN), |(a, b), &v| (a.min(v), b.max(v)));
            let n = r.image.width;
            let m = format!("{method:?}").to_lowercase();
            textures::save_repeated(&r.image, &format!("out/seamless/{name}-{m}.png"));
            println!(
                "{{\"exemplar\":\"{name}\",\"method\":\"{m}\",\"size\":{n},\"ms\":{:.1},\"restoration\":{:.4},\"seam\":{:.3},\"seams\":[{mean:.3},{lo:.3},{hi:.3}],\"naive\":{naive:.3},\"channel\":{:?},\"count_difference\":{:?},\"decisions\":{}}}",
                times[1],
                r.restoration_rate,
                r.seam_score,
                r.channel.map(String::from).unwrap_or_default(),
                r.count_difference.map(|(a, b)| format!("{a:.0}->{b:.0}")).unwrap_or_default(),
                r.decisions.map(|d| format!("{{\"j3\":{:?},\"pairwise\":{},\"mean\":{}}}", d.by_j3, d.pairwise, d.mean)).unwrap_or("null".into())
            );
        }
    }
}
