//! The exemplar photographs of tests/fixtures/textures (see SOURCES.md there), shared by
//! the texture probes and benchmarks.
#![allow(dead_code)]

use patternsynth::raster::codec::decode_image;
use patternsynth::raster::{Image, Rgba};
use patternsynth::seamless::Method;

/// The four the engine was tuned on.
pub const TUNED: [&str; 4] = ["wood", "brick", "grass", "gravel"];

/// All of them: the tuned four and six of other kinds nobody chose for the engine.
pub const ALL: [&str; 10] = ["wood", "brick", "grass", "gravel", "moon", "hubble", "tissue", "fur", "print", "coins"];

/// A fixture as RGBA, or any PNG or JPEG by its path (a name holding a `/`).
pub fn rgba(name: &str) -> Rgba {
    let path = if name.contains('/') { name.to_string() } else { format!("tests/fixtures/textures/{name}.png") };
    decode_image(&std::fs::read(path).unwrap()).unwrap()
}

/// A fixture as an engine image.
pub fn load(name: &str) -> Image {
    let d = rgba(name);
    Image::from_rgba8(d.width, d.height, &d.data).unwrap()
}

/// The fixtures a probe's argument names: one, `all`, or every PNG in a folder.
pub fn named(arg: &str) -> Vec<String> {
    if arg == "all" {
        ALL.iter().map(|s| s.to_string()).collect()
    } else if std::path::Path::new(arg).is_dir() {
        let mut pngs: Vec<String> = std::fs::read_dir(arg)
            .unwrap()
            .filter_map(|e| e.ok().map(|e| e.path().to_string_lossy().into_owned()))
            .filter(|p| p.ends_with(".png"))
            .collect();
        pngs.sort();
        pngs
    } else {
        vec![arg.to_string()]
    }
}

/// The tile method a probe's argument names: `etfmcm`, `tfmcm`, otherwise synthesis.
pub fn method(arg: &str) -> Method {
    match arg {
        "etfmcm" => Method::Etfmcm,
        "tfmcm" => Method::Tfmcm,
        _ => Method::Synthesis,
    }
}

/// Writes `tile` repeated 2 x 2 as a PNG at `path`: the wrap crosses the middle, where a
/// seam would show.
pub fn save_repeated(tile: &Rgba, path: &str) {
    let (w, h) = (tile.width, tile.height);
    let mut rep = vec![0u8; 16 * w * h];
    for y in 0..2 * h {
        for x in 0..2 * w {
            let s = ((y % h) * w + x % w) * 4;
            rep[(y * 2 * w + x) * 4..][..4].copy_from_slice(&tile.data[s..s + 4]);
        }
    }
    std::fs::write(path, patternsynth::raster::codec::encode_png(2 * w, 2 * h, &rep).unwrap()).unwrap();
}

/// texture-synthesis 0.8.3's output (its CLI at `cli`, one thread) from `name` (a PNG's
/// path, or a fixture, written out first) at `size` x `size`, seeded, a tile with
/// `tiling`: the peer run on the same file in the same script.
pub fn peer(cli: &str, name: &str, size: usize, seed: u64, tiling: bool) -> Rgba {
    let dir = std::env::temp_dir().join("patternsynth_peer");
    std::fs::create_dir_all(&dir).unwrap();
    let stem = name.rsplit('/').next().unwrap_or(name).trim_end_matches(".png");
    let input = if name.contains('/') {
        std::path::PathBuf::from(name)
    } else {
        let r = rgba(name);
        let f = dir.join(format!("{stem}.png"));
        std::fs::write(&f, patternsynth::raster::codec::encode_png(r.width, r.height, &r.data).unwrap()).unwrap();
        f
    };
    let out = dir.join(format!("{stem}.{size}.{}s{seed}.png", if tiling { "t" } else { "" }));
    let mut cmd = std::process::Command::new(cli);
    cmd.args(["--no-progress", "-o"]).arg(&out).args(["--threads", "1", "--seed", &seed.to_string()]);
    if tiling {
        cmd.arg("--tiling");
    }
    let status = cmd.args(["--out-size", &size.to_string(), "generate"]).arg(&input).status().expect("the peer runs");
    assert!(status.success(), "the peer failed on {name}");
    decode_image(&std::fs::read(&out).unwrap()).unwrap()
}
