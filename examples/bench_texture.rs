//! Native side of the texture benchmark: timings (median of runs), patch energies, band
//! energies and repetition, as JSON lines; outputs saved in out/bench/. Run through
//! `bash scripts/bench.sh`, which times the same cases in wasm under Node.
//!
//! `--reference PATH...` instead measures images made by another synthesizer (patch
//! energy and repetition against the named fixture).
use patternsynth::raster::codec::{decode_image, encode_png};
use patternsynth::raster::energy::{patch_energy, repetition};
use patternsynth::raster::{blend_textures, synthesize_texture, BlendOptions, Image, Rgba, TextureOptions};
use patternsynth::Silent;
use std::alloc::{GlobalAlloc, Layout, System};
use std::sync::atomic::{AtomicUsize, Ordering::Relaxed};
use std::time::Instant;

/// The system allocator, counting live bytes and their peak (for the memory figures).
struct Counting;
static LIVE: AtomicUsize = AtomicUsize::new(0);
static PEAK: AtomicUsize = AtomicUsize::new(0);

unsafe impl GlobalAlloc for Counting {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        let live = LIVE.fetch_add(layout.size(), Relaxed) + layout.size();
        PEAK.fetch_max(live, Relaxed);
        unsafe { System.alloc(layout) }
    }
    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        LIVE.fetch_sub(layout.size(), Relaxed);
        unsafe { System.dealloc(ptr, layout) }
    }
}

#[global_allocator]
static ALLOC: Counting = Counting;

/// Peak bytes allocated while `f` runs, above what was live before.
fn peak_bytes<T>(f: impl FnOnce() -> T) -> (usize, T) {
    let before = LIVE.load(Relaxed);
    PEAK.store(before, Relaxed);
    let out = f();
    (PEAK.load(Relaxed) - before, out)
}

/// Working memory of a call from RGBA exemplars to the RGBA result (the wasm path: bytes
/// in, `Image` conversion, synthesis, bytes out), against the images' own RGBA size.
fn memory_case(name: &str, exemplars: &[&str], out_side: usize) {
    let rgba: Vec<_> = exemplars
        .iter()
        .map(|n| decode_image(&std::fs::read(format!("tests/fixtures/textures/{n}.png")).unwrap()).unwrap())
        .collect();
    let own: usize = rgba.iter().map(|r| r.data.len()).sum::<usize>() + out_side * out_side * 4;
    let (peak, _) = peak_bytes(|| {
        let ims: Vec<Image> = rgba.iter().map(|r| Image::from_rgba8(r.width, r.height, &r.data).unwrap()).collect();
        let base = TextureOptions { width: out_side, height: out_side, seed: 1, ..Default::default() };
        match &ims[..] {
            [a] => synthesize_texture(a, &base, &mut Silent).unwrap(),
            [a, b] => blend_textures(a, b, &BlendOptions { base, ..Default::default() }, &mut Silent).unwrap(),
            _ => unreachable!(),
        }
    });
    println!(
        "{{\"case\":\"memory\",\"what\":\"{name}\",\"out\":{out_side},\"images_bytes\":{own},\"peak_bytes\":{peak},\"ratio\":{:.2}}}",
        peak as f64 / own as f64
    );
}

fn load(name: &str, side: usize) -> Image {
    let bytes = std::fs::read(format!("tests/fixtures/textures/{name}.png")).expect(name);
    let d = decode_image(&bytes).unwrap();
    let full = Image::from_rgba8(d.width, d.height, &d.data).unwrap();
    resize(&full, side)
}

/// A square exemplar of `side`: a crop when smaller, pixel repetition never (a 2x box
/// upscale of the 128 photograph gives the 256 case, documented as such).
fn resize(img: &Image, side: usize) -> Image {
    let mut out = Image::new(side, side);
    for y in 0..side {
        for x in 0..side {
            out.data[y * side + x] =
                if side <= img.width { img.at(x, y) } else { img.at(x * img.width / side, y * img.height / side) };
        }
    }
    out
}

/// Median time of `runs` calls, and the last output as an `Image` for the measures.
fn median_ms(runs: usize, mut f: impl FnMut() -> Rgba) -> (f64, Image) {
    let mut times = Vec::new();
    let mut last = None;
    for _ in 0..runs {
        let t = Instant::now();
        last = Some(f());
        times.push(t.elapsed().as_secs_f64() * 1e3);
    }
    times.sort_by(|a, b| a.total_cmp(b));
    let out = last.unwrap();
    (times[times.len() / 2], Image::from_rgba8(out.width, out.height, &out.data).unwrap())
}

fn save(img: &Image, name: &str) {
    std::fs::create_dir_all("out/bench").unwrap();
    std::fs::write(format!("out/bench/{name}.png"), encode_png(img.width, img.height, &img.to_rgba8()).unwrap())
        .unwrap();
}

fn main() {
    let args: Vec<String> = std::env::args().collect();
    if args.get(1).map(String::as_str) == Some("--full-exhaustive") {
        // The configuration, 128 -> 256 blend, against the exhaustive reference
        // (several minutes native; not part of the default run).
        let (ea, eb) = (load("wood", 128), load("gravel", 128));
        for exhaustive in [false, true] {
            let o = BlendOptions {
                base: TextureOptions { width: 256, height: 256, seed: 1, exhaustive, ..Default::default() },
                ..Default::default()
            };
            let (ms, out) = median_ms(1, || blend_textures(&ea, &eb, &o, &mut Silent).unwrap());
            save(&out, &format!("blend-wood-gravel-256-{}", if exhaustive { "exhaustive" } else { "default" }));
            println!(
                "{{\"case\":\"blend\",\"ex\":128,\"out\":256,\"exhaustive\":{exhaustive},\"ms\":{ms:.0},\"top_a\":{:.3},\"top_b\":{:.3},\"bottom_a\":{:.3},\"bottom_b\":{:.3},\"all_a\":{:.3},\"all_b\":{:.3}}}",
                patch_energy(&out, &ea, 200, (0, 43), 1),
                patch_energy(&out, &eb, 200, (0, 43), 1),
                patch_energy(&out, &ea, 200, (213, 256), 1),
                patch_energy(&out, &eb, 200, (213, 256), 1),
                patch_energy(&out, &ea, 300, (0, 256), 1),
                patch_energy(&out, &eb, 300, (0, 256), 1),
            );
        }
        return;
    }
    if args.get(1).map(String::as_str) == Some("--reference") {
        // name=path pairs: energies of another synthesizer's outputs.
        for pair in &args[2..] {
            let (name, path) = pair.split_once('=').unwrap();
            let ex = load(name, 128);
            let d = decode_image(&std::fs::read(path).unwrap()).unwrap();
            let out = Image::from_rgba8(d.width, d.height, &d.data).unwrap();
            println!(
                "{{\"case\":\"reference\",\"a\":\"{name}\",\"energy\":{:.3},\"repetition\":{:.3}}}",
                patch_energy(&out, &ex, 300, (0, out.height), 1),
                repetition(&out, 24, 1)
            );
        }
        return;
    }
    if args.get(1).map(String::as_str) == Some("--memory") {
        for side in [256, 512, 1024, 2048, 4096] {
            memory_case("single wood", &["wood"], side);
            memory_case("blend wood-gravel", &["wood", "gravel"], side);
        }
        return;
    }
    // Single exemplar, 128 -> 256 and 512, default mode.
    for (name, out_side) in
        [("wood", 256), ("brick", 256), ("grass", 256), ("gravel", 256), ("wood", 512), ("gravel", 512)]
    {
        let ex = load(name, 128);
        let o = TextureOptions { width: out_side, height: out_side, seed: 1, ..Default::default() };
        let (ms, out) = median_ms(3, || synthesize_texture(&ex, &o, &mut Silent).unwrap());
        save(&out, &format!("single-{name}-{out_side}"));
        println!(
            "{{\"case\":\"single\",\"a\":\"{name}\",\"ex\":128,\"out\":{out_side},\"exhaustive\":false,\"ms\":{ms:.1},\"energy\":{:.3},\"repetition\":{:.3}}}",
            patch_energy(&out, &ex, 300, (0, out_side), 1),
            repetition(&out, 24, 1)
        );
    }
    // Exemplar size scaling (wood, out 256).
    for ex_side in [64, 256] {
        let ex = load("wood", ex_side);
        let o = TextureOptions { width: 256, height: 256, seed: 1, ..Default::default() };
        let (ms, out) = median_ms(3, || synthesize_texture(&ex, &o, &mut Silent).unwrap());
        println!(
            "{{\"case\":\"single\",\"a\":\"wood\",\"ex\":{ex_side},\"out\":256,\"exhaustive\":false,\"ms\":{ms:.1},\"energy\":{:.3},\"repetition\":{:.3}}}",
            patch_energy(&out, &ex, 200, (0, 256), 1),
            repetition(&out, 24, 1)
        );
    }
    // Blends, 128 -> 256 and 512.
    for (a, b, out_side) in [("wood", "gravel", 256), ("brick", "grass", 256), ("wood", "gravel", 512)] {
        let (ea, eb) = (load(a, 128), load(b, 128));
        let o = BlendOptions {
            base: TextureOptions { width: out_side, height: out_side, seed: 1, ..Default::default() },
            ..Default::default()
        };
        let (ms, out) = median_ms(3, || blend_textures(&ea, &eb, &o, &mut Silent).unwrap());
        save(&out, &format!("blend-{a}-{b}-{out_side}"));
        let band = out_side / 6;
        let top = (0, band);
        let bottom = (out_side - band, out_side);
        println!(
            "{{\"case\":\"blend\",\"a\":\"{a}\",\"b\":\"{b}\",\"ex\":128,\"out\":{out_side},\"exhaustive\":false,\"ms\":{ms:.1},\"top_a\":{:.3},\"top_b\":{:.3},\"bottom_a\":{:.3},\"bottom_b\":{:.3}}}",
            patch_energy(&out, &ea, 200, top, 1),
            patch_energy(&out, &eb, 200, top, 1),
            patch_energy(&out, &ea, 200, bottom, 1),
            patch_energy(&out, &eb, 200, bottom, 1)
        );
    }
    // Default against the exhaustive reference, on 64 -> 128 (exhaustive is quadratic).
    for name in ["wood", "brick", "grass", "gravel"] {
        let ex = load(name, 64);
        for exhaustive in [false, true] {
            let o = TextureOptions { width: 128, height: 128, seed: 1, exhaustive, ..Default::default() };
            let (ms, out) = median_ms(1, || synthesize_texture(&ex, &o, &mut Silent).unwrap());
            println!(
                "{{\"case\":\"single\",\"a\":\"{name}\",\"ex\":64,\"out\":128,\"exhaustive\":{exhaustive},\"ms\":{ms:.1},\"energy\":{:.3},\"repetition\":{:.3}}}",
                patch_energy(&out, &ex, 300, (0, 128), 1),
                repetition(&out, 16, 1)
            );
        }
    }
    let (ea, eb) = (load("wood", 64), load("gravel", 64));
    for exhaustive in [false, true] {
        let o = BlendOptions {
            base: TextureOptions { width: 128, height: 128, seed: 1, exhaustive, ..Default::default() },
            ..Default::default()
        };
        let (ms, out) = median_ms(1, || blend_textures(&ea, &eb, &o, &mut Silent).unwrap());
        println!(
            "{{\"case\":\"blend\",\"a\":\"wood\",\"b\":\"gravel\",\"ex\":64,\"out\":128,\"exhaustive\":{exhaustive},\"ms\":{ms:.1},\"top_a\":{:.3},\"top_b\":{:.3},\"bottom_a\":{:.3},\"bottom_b\":{:.3}}}",
            patch_energy(&out, &ea, 200, (0, 21), 1),
            patch_energy(&out, &eb, 200, (0, 21), 1),
            patch_energy(&out, &ea, 200, (107, 128), 1),
            patch_energy(&out, &eb, 200, (107, 128), 1)
        );
    }
}
