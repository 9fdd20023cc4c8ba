//! The texture engines natively: blending puts A at the top and B at the bottom, plain
//! synthesis keeps the exemplar's look without repeating it, tileable outputs wrap
//! without seams, the accelerated search stays close to the exhaustive one, and bad
//! input gets a clear error.

use patternsynth::raster::bands;
use patternsynth::raster::codec::decode_image;
use patternsynth::raster::energy::{colour_distance, patch_energy, repetition};
use patternsynth::raster::synthesis::{Job, Schedule};
use patternsynth::raster::{
    blend_job, blend_textures, synthesize_texture, texture_job, BlendOptions, Coefficient, Image, Rgba, TextureOptions,
};
use patternsynth::{Error, Silent};

fn load(name: &str, side: usize) -> Image {
    let bytes = std::fs::read(format!("tests/fixtures/textures/{name}.png")).unwrap();
    let d = decode_image(&bytes).unwrap();
    let full = Image::from_rgba8(d.width, d.height, &d.data).unwrap();
    // A top-left crop keeps the tests quick.
    let mut out = Image::new(side, side);
    for y in 0..side {
        for x in 0..side {
            out.data[y * side + x] = full.at(x, y);
        }
    }
    out
}

/// An engine's RGBA result as an `Image`, for the measures.
fn image(out: Rgba) -> Image {
    Image::from_rgba8(out.width, out.height, &out.data).unwrap()
}

fn mean(img: &Image) -> [f32; 3] {
    let n = img.data.len() as f32;
    let mut m = [0.0; 3];
    for p in &img.data {
        for c in 0..3 {
            m[c] += p[c] / n;
        }
    }
    m
}

#[test]
fn blend_resembles_a_at_the_top_and_b_at_the_bottom() {
    let (a, b) = (load("wood", 64), load("gravel", 64));
    let opts = BlendOptions {
        base: TextureOptions { width: 96, height: 96, seed: 3, ..Default::default() },
        ..Default::default()
    };
    let out = image(blend_textures(&a, &b, &opts, &mut Silent).unwrap());
    assert_eq!((out.width, out.height), (96, 96));
    let top = (0, 16);
    let bottom = (80, 96);
    let (ta, tb) = (patch_energy(&out, &a, 120, top, 1), patch_energy(&out, &b, 120, top, 1));
    let (ba, bb) = (patch_energy(&out, &a, 120, bottom, 1), patch_energy(&out, &b, 120, bottom, 1));
    println!("top vs A {ta:.1} vs B {tb:.1}; bottom vs A {ba:.1} vs B {bb:.1}");
    assert!(ta < 0.6 * tb, "top is A: {ta} vs {tb}");
    assert!(bb < 0.6 * ba, "bottom is B: {bb} vs {ba}");
    // Wood is orange, gravel grey: the red-blue difference falls from top to bottom.
    let band = |y0: usize, y1: usize| {
        let px: Vec<_> = out.data[y0 * 96..y1 * 96].to_vec();
        px.iter().map(|p| p[0] - p[2]).sum::<f32>() / px.len() as f32
    };
    assert!(band(0, 16) > band(40, 56) && band(40, 56) > band(80, 96));
}

#[test]
fn single_exemplar_keeps_the_look_without_copying_it_whole() {
    let ex = load("grass", 64);
    let opts = TextureOptions { width: 128, height: 128, seed: 5, ..Default::default() };
    let out = image(synthesize_texture(&ex, &opts, &mut Silent).unwrap());
    let (m, me) = (mean(&out), mean(&ex));
    for c in 0..3 {
        assert!((m[c] - me[c]).abs() < 0.08 * me[c].max(20.0), "mean colour {m:?} vs {me:?}");
    }
    let energy = patch_energy(&out, &ex, 150, (0, 128), 2);
    let rep = repetition(&out, 16, 2);
    println!("patch energy {energy:.2}, repetition {rep:.3}");
    // A verbatim tiling of the 64-pixel exemplar would score ~0 at the 64-pixel shift.
    assert!(rep > 0.3, "repetition {rep}");
    // Noise of the exemplar's colours scores far higher than a good synthesis.
    let mut noise = out.clone();
    let mut rng = patternsynth::rng::Rng::new(9);
    for p in &mut noise.data {
        *p = ex.data[rng.below(ex.data.len())];
    }
    assert!(energy < 0.6 * patch_energy(&noise, &ex, 150, (0, 128), 2));
}

#[test]
fn the_output_repeats_no_more_than_its_exemplar_does() {
    // Fur, the photograph whose large light patches recurred most (0.784 over seeds 1-3
    // with a 16-pixel coarsest level, against the exemplar's own 0.875): the issue's
    // allowance is 0.05 more repetition than the exemplar's own.
    let ex = load("fur", 128);
    let own = repetition(&ex, 48, 1);
    let rep = (1..=3)
        .map(|seed| {
            let o = TextureOptions { width: 256, height: 256, seed, ..Default::default() };
            repetition(&image(synthesize_texture(&ex, &o, &mut Silent).unwrap()), 48, seed)
        })
        .sum::<f64>()
        / 3.0;
    println!("fur: repetition {rep:.3}, exemplar's own {own:.3}");
    assert!(rep >= own - 0.05, "repetition {rep} vs own {own}");
}

#[test]
fn the_output_keeps_the_exemplars_colour_balance() {
    // Tissue is 70% brown tissue and 30% white stroma; fur has one orange streak. Grown
    // causally from noise, the coarsest level drifted to the smoothest region: tissue's
    // outputs were 70% stroma (colour distance 0.52 over seeds 1-3, texture-synthesis's
    // 0.23) and fur repeated its streak in rows (0.23; 0.21). Started from a quilt of
    // exemplar windows (`raster::quilt`), about 0.14 and 0.06.
    for (name, limit) in [("tissue", 0.25), ("fur", 0.15)] {
        let ex = load(name, 128);
        let d = (1..=3)
            .map(|seed| {
                let o = TextureOptions { width: 256, height: 256, seed, ..Default::default() };
                colour_distance(&image(synthesize_texture(&ex, &o, &mut Silent).unwrap()), &ex)
            })
            .sum::<f64>()
            / 3.0;
        println!("{name}: colour distance {d:.3}");
        assert!(d < limit, "{name}: colour distance {d:.3}");
    }
}

#[test]
fn an_exemplar_mostly_of_one_background_keeps_to_it() {
    // Hubble: dark sky with rare stars. A re-use penalty on every use pushed the output
    // towards the stars (patch energy 1.69 over seeds 1-3, texture-synthesis's 1.38);
    // free up to the mean use, 1.31.
    let ex = load("hubble", 128);
    let energy = (1..=3)
        .map(|seed| {
            let o = TextureOptions { width: 256, height: 256, seed, ..Default::default() };
            patch_energy(&image(synthesize_texture(&ex, &o, &mut Silent).unwrap()), &ex, 300, (0, 256), seed)
        })
        .sum::<f64>()
        / 3.0;
    println!("hubble: patch energy {energy:.2}");
    assert!(energy < 1.5, "patch energy {energy}");
}

#[test]
fn tileable_output_wraps_without_a_seam() {
    let ex = load("wood", 64);
    let opts = TextureOptions { width: 96, height: 96, seed: 2, tileable: true, ..Default::default() };
    let out = image(synthesize_texture(&ex, &opts, &mut Silent).unwrap());
    let diff = |x0: usize, y0: usize, x1: usize, y1: usize| {
        let (p, q) = (out.at(x0, y0), out.at(x1, y1));
        ((p[0] - q[0]).abs() + (p[1] - q[1]).abs() + (p[2] - q[2]).abs()) as f64
    };
    let n = 96;
    let seam_x: f64 = (0..n).map(|y| diff(n - 1, y, 0, y)).sum::<f64>() / n as f64;
    let seam_y: f64 = (0..n).map(|x| diff(x, n - 1, x, 0)).sum::<f64>() / n as f64;
    let inner: f64 =
        (0..n).flat_map(|y| (0..n - 1).map(move |x| (x, y))).map(|(x, y)| diff(x, y, x + 1, y)).sum::<f64>()
            / (n * (n - 1)) as f64;
    println!("seams {seam_x:.1} {seam_y:.1} vs interior {inner:.1}");
    assert!(seam_x < 1.5 * inner && seam_y < 1.5 * inner);
}

#[test]
fn accelerated_search_stays_close_to_exhaustive() {
    let ex = load("gravel", 32);
    let opts = TextureOptions { width: 48, height: 48, seed: 4, ..Default::default() };
    let fast = image(synthesize_texture(&ex, &opts, &mut Silent).unwrap());
    let full = image(synthesize_texture(&ex, &TextureOptions { exhaustive: true, ..opts }, &mut Silent).unwrap());
    let (ef, ee) = (patch_energy(&fast, &ex, 200, (0, 48), 3), patch_energy(&full, &ex, 200, (0, 48), 3));
    println!("accelerated {ef:.2} exhaustive {ee:.2}");
    assert!(ef < 1.25 * ee, "accelerated {ef} vs exhaustive {ee}");
}

#[test]
fn same_seed_same_image() {
    let ex = load("brick", 32);
    let o = TextureOptions { width: 40, height: 40, seed: 8, ..Default::default() };
    assert_eq!(synthesize_texture(&ex, &o, &mut Silent).unwrap(), synthesize_texture(&ex, &o, &mut Silent).unwrap());
}

#[test]
fn bad_input_is_a_clear_error() {
    let ex = load("wood", 32);
    let tiny = Image::new(3, 3);
    let err = |r: Result<Rgba, Error>| r.unwrap_err().to_string();
    assert!(Image::from_rgba8(0, 5, &[]).unwrap_err().to_string().contains("empty"));
    assert!(Image::from_rgba8(2, 2, &[0; 15]).unwrap_err().to_string().contains("needs 16"));
    let o = |w, h| TextureOptions { width: w, height: h, ..Default::default() };
    assert!(err(synthesize_texture(&ex, &o(0, 10), &mut Silent)).contains("empty"));
    assert!(err(synthesize_texture(&ex, &o(100_000, 10), &mut Silent)).contains("largest side"));
    assert!(err(synthesize_texture(&ex, &o(4097, 16), &mut Silent)).contains("the largest side accepted is 4096"));
    assert!(err(synthesize_texture(&tiny, &o(10, 10), &mut Silent)).contains("smaller than the 5x5 neighbourhood"));
    assert!(
        err(synthesize_texture(&ex, &TextureOptions { neighbourhood: 4, ..o(10, 10) }, &mut Silent)).contains("odd")
    );
    let mut nan = vec![0.5f32; 100];
    nan[7] = f32::NAN;
    let b = BlendOptions { base: o(10, 10), coefficient: Coefficient::Map(nan) };
    assert!(err(blend_textures(&ex, &ex, &b, &mut Silent)).contains("not a number"));
    let short = BlendOptions { base: o(10, 10), coefficient: Coefficient::Map(vec![0.5; 99]) };
    assert!(err(blend_textures(&ex, &ex, &short, &mut Silent)).contains("needs 100"));
    let mut calls = 0;
    let mut cancel = |_: f64| {
        calls += 1;
        calls < 3
    };
    assert_eq!(synthesize_texture(&ex, &o(64, 64), &mut cancel).unwrap_err(), Error::Cancelled);
}

/// Runs a job's banded schedule as `workers` threads would: each with a job of its own,
/// taking the bands of each step in turn (reversed, to differ from the one-thread order).
fn run_on_threads(make: &(dyn Fn() -> Job + Sync), workers: usize) -> Rgba {
    let jobs: Vec<Job> = (0..workers).map(|_| make()).collect();
    let steps = bands::steps(&jobs[0]);
    let (mut parent, mut state) = (Vec::new(), Vec::new());
    for step in steps {
        if step.pass == 0 {
            parent = std::mem::take(&mut state);
            state = bands::initial(&jobs[0], step.level, &parent);
        }
        // Each worker makes a level's first windows itself, as in the browser.
        let start = if step.pass == 0 { bands::Start::Initial } else { bands::Start::Maps(&state) };
        let uses = bands::uses(&jobs[0], step, start, &parent);
        let n = bands::bands(&jobs[0], step).len();
        let results: Vec<(usize, Vec<Vec<u32>>)> = std::thread::scope(|scope| {
            let handles: Vec<_> = jobs
                .iter()
                .enumerate()
                .map(|(w, job)| {
                    let (parent, uses) = (&parent, &uses);
                    scope.spawn(move || {
                        (0..n)
                            .rev()
                            .filter(|b| b % workers == w)
                            .map(|b| (b, bands::run(job, step, start, uses, parent, b, &mut || Ok(())).unwrap()))
                            .collect::<Vec<_>>()
                    })
                })
                .collect();
            handles.into_iter().flat_map(|h| h.join().unwrap()).collect()
        });
        let mut next = state.clone();
        for (b, rows) in results {
            bands::store(&jobs[0], step, b, &rows, &mut next);
        }
        state = next;
    }
    jobs[0].colours(&state)
}

#[test]
fn banded_schedule_gives_one_image_for_any_number_of_workers() {
    let ex = load("brick", 48);
    let opts = TextureOptions { width: 100, height: 140, seed: 6, schedule: Schedule::Bands, ..Default::default() };
    let one = synthesize_texture(&ex, &opts, &mut Silent).unwrap();
    for workers in [2, 3] {
        assert!(run_on_threads(&|| texture_job(&ex, &opts).unwrap(), workers) == one, "{workers} workers");
    }
    // Blends too (two maps per level, mixed by mu).
    let (a, b) = (load("wood", 40), load("gravel", 40));
    let blend = BlendOptions { base: TextureOptions { width: 72, height: 130, ..opts.clone() }, ..Default::default() };
    let one = blend_textures(&a, &b, &blend, &mut Silent).unwrap();
    assert!(run_on_threads(&|| blend_job(&a, &b, &blend).unwrap(), 2) == one);
    // The scanline order is another image: the schedule option is honoured.
    assert!(
        synthesize_texture(&ex, &TextureOptions { schedule: Schedule::Scanline, ..opts.clone() }, &mut Silent).unwrap()
            != synthesize_texture(&ex, &opts, &mut Silent).unwrap()
    );
}

#[test]
fn banded_schedule_matches_scanline_quality_and_shows_no_band_edges() {
    let ex = load("grass", 64);
    let side = 160;
    let (mut banded, mut scanline, mut edge, mut inner) = (0.0, 0.0, 0.0, 0.0);
    for seed in 1..=3 {
        let o = TextureOptions { width: side, height: side, seed, ..Default::default() };
        let b = image(
            synthesize_texture(&ex, &TextureOptions { schedule: Schedule::Bands, ..o.clone() }, &mut Silent).unwrap(),
        );
        let s =
            image(synthesize_texture(&ex, &TextureOptions { schedule: Schedule::Scanline, ..o }, &mut Silent).unwrap());
        banded += patch_energy(&b, &ex, 200, (0, side), seed);
        scanline += patch_energy(&s, &ex, 200, (0, side), seed);
        // Row-to-row differences across the finest level's band edges (both passes'),
        // against all rows'.
        let row_diff = |y: usize| {
            (0..side)
                .map(|x| {
                    let (p, q) = (b.at(x, y), b.at(x, (y + 1) % side));
                    ((p[0] - q[0]).abs() + (p[1] - q[1]).abs() + (p[2] - q[2]).abs()) as f64
                })
                .sum::<f64>()
                / side as f64
        };
        let n = side / bands::BAND_ROWS;
        let edges: Vec<usize> =
            (0..n).flat_map(|k| [k * side / n, k * side / n + side / n / 2]).map(|y| (y + side - 1) % side).collect();
        edge += edges.iter().map(|&y| row_diff(y)).sum::<f64>() / edges.len() as f64;
        inner += (0..side).map(row_diff).sum::<f64>() / side as f64;
    }
    println!(
        "patch energy banded {:.2} scanline {:.2}; rows across band edges {:.1} vs all {:.1}",
        banded / 3.0,
        scanline / 3.0,
        edge / 3.0,
        inner / 3.0
    );
    assert!(banded < 1.1 * scanline, "banded {banded} vs scanline {scanline}");
    assert!(edge < 1.15 * inner, "band edges {edge} vs all rows {inner}");
}

#[test]
fn large_outputs_take_the_banded_schedule_and_small_ones_scanlines() {
    let ex = load("wood", 32);
    let job =
        |w: usize, h: usize| texture_job(&ex, &TextureOptions { width: w, height: h, ..Default::default() }).unwrap();
    assert!(!job(511, 512).params().banded());
    assert!(job(512, 512).params().banded());
    assert!(job(2048, 128).params().banded());
}

/// A soft exemplar nobody photographed: smooth waves of colour (no period that fits
/// it), so the pieces a synthesis copies meet with steps between them.
fn soft(side: usize) -> Image {
    let mut img = Image::new(side, side);
    for y in 0..side {
        for x in 0..side {
            let (fx, fy) = (x as f32, y as f32);
            let a = (fx / 9.3 + fy / 13.1).sin();
            let b = (fy / 7.7 - fx / 17.9 + 1.3).sin();
            let c = ((fx * fx + fy * fy).sqrt() / 11.0).sin();
            img.data[y * side + x] =
                [128.0 + 60.0 * a + 30.0 * c, 120.0 + 50.0 * b + 20.0 * a, 140.0 + 40.0 * c - 30.0 * b];
        }
    }
    img
}

#[test]
fn fused_seams_lower_the_patch_energy_of_a_soft_exemplar() {
    let ex = soft(64);
    let (mut fused, mut copied, mut colour) = (0.0, 0.0, [0.0, 0.0]);
    for seed in 1..=3 {
        for tileable in [true, false] {
            let o = TextureOptions { width: 64, height: 64, seed, tileable, ..Default::default() };
            let f = image(synthesize_texture(&ex, &o, &mut Silent).unwrap());
            let c = image(synthesize_texture(&ex, &TextureOptions { fuse_seams: false, ..o }, &mut Silent).unwrap());
            fused += patch_energy(&f, &ex, 300, (0, 64), seed);
            copied += patch_energy(&c, &ex, 300, (0, 64), seed);
            colour[0] += colour_distance(&f, &ex);
            colour[1] += colour_distance(&c, &ex);
            // Unfused, every pixel is one of the exemplar's.
            assert!(c.data.iter().all(|p| ex.data.iter().any(|q| q.map(f32::round) == *p)));
        }
    }
    println!(
        "patch energy fused {:.2}, copied {:.2}; colour {:.3} / {:.3}",
        fused / 6.0,
        copied / 6.0,
        colour[0] / 6.0,
        colour[1] / 6.0
    );
    assert!(fused < 0.85 * copied, "fused {fused} against copied {copied}");
    // The colours move only beside seams (0.048 further on this exemplar, under 0.01 on
    // photographs: `synthesis::fusion`).
    assert!(colour[0] < colour[1] + 6.0 * 0.08, "colour {colour:?}");
}

#[test]
fn fused_tiles_still_wrap_and_palettes_keep_their_colours() {
    // A fused tile's wrap is no seam: its rows and columns across the wrap differ no
    // more than any others.
    let ex = soft(64);
    let o = TextureOptions { width: 96, height: 80, seed: 4, tileable: true, ..Default::default() };
    let t = image(synthesize_texture(&ex, &o, &mut Silent).unwrap());
    let step = |a: [f32; 3], b: [f32; 3]| (0..3).map(|c| (a[c] - b[c]).abs() as f64).sum::<f64>();
    let row =
        |y: usize| (0..t.width).map(|x| step(t.at(x, y), t.at(x, (y + 1) % t.height))).sum::<f64>() / t.width as f64;
    let col =
        |x: usize| (0..t.height).map(|y| step(t.at(x, y), t.at((x + 1) % t.width, y))).sum::<f64>() / t.height as f64;
    let rows = (0..t.height).map(row).sum::<f64>() / t.height as f64;
    let cols = (0..t.width).map(col).sum::<f64>() / t.width as f64;
    assert!(row(t.height - 1) < 1.5 * rows, "wrap row {} against {rows}", row(t.height - 1));
    assert!(col(t.width - 1) < 1.5 * cols, "wrap column {} against {cols}", col(t.width - 1));
    // Four flat colours in blocks: a palette, which fusion leaves exact.
    let mut blocks = Image::new(48, 48);
    let colours = [[200.0, 40.0, 40.0], [30.0, 30.0, 30.0], [240.0, 230.0, 200.0], [40.0, 90.0, 200.0]];
    for y in 0..48 {
        for x in 0..48 {
            blocks.data[y * 48 + x] = colours[(x / 7 + 2 * (y / 5)) % 4];
        }
    }
    let out = image(
        synthesize_texture(
            &blocks,
            &TextureOptions { width: 64, height: 64, seed: 2, ..Default::default() },
            &mut Silent,
        )
        .unwrap(),
    );
    assert!(out.data.iter().all(|p| colours.contains(p)), "a palette's output keeps its colours");
}

#[test]
fn a_banded_output_is_fused_across_its_band_edges_as_a_whole() {
    // Each band is fused with the rows around it (`Job::fused_band`): the image is the
    // whole output fused at once, band edges and the wrap included. (Before, each band
    // was fused alone: steps across its edges stayed as copied, a line of unfused seams
    // every 32 rows; helper-61's review.)
    let ex = soft(64);
    for tileable in [false, true] {
        let o = TextureOptions {
            width: 192,
            height: 200,
            seed: 5,
            tileable,
            schedule: Schedule::Bands,
            ..Default::default()
        };
        let job = texture_job(&ex, &o).unwrap();
        assert!(job.fused());
        let src = patternsynth::raster::texture::sources(&job, &mut patternsynth::progress::Throttle::new(&mut Silent))
            .unwrap();
        let banded = job.colours(&src);
        let whole = job.fused_band(&src, 0, 200, &job.keep(&src));
        let worst = banded.data.iter().zip(&whole).map(|(a, b)| a.abs_diff(*b)).max().unwrap();
        let over = banded.data.iter().zip(&whole).filter(|(a, b)| a.abs_diff(**b) > 1).count();
        println!("tileable {tileable}: worst {worst}, {over} bytes over 1 of {}", whole.len());
        // (Ten sweeps leave the two a byte or two apart in a few places; 30 none.)
        assert!(
            worst <= 2 && over <= 16,
            "tileable {tileable}: banded and whole differ by {worst} ({over} bytes over 1)"
        );
        assert!(bands::colour_bands(&job).is_some_and(|b| b.len() > 1));
        // The map counted over four strips (`Job::keep`) against one counting every
        // pixel (the output coloured at once): under half a level apart on average, and
        // up to 7 in the tails, which 64 rows of 200 sample thinly.
        let all = job.colour_rows(&src, 0, 200);
        let worst = banded.data.iter().zip(&all).map(|(a, b)| a.abs_diff(*b)).max().unwrap();
        let mean = banded.data.iter().zip(&all).map(|(a, b)| a.abs_diff(*b) as f64).sum::<f64>() / all.len() as f64;
        println!("tileable {tileable}: strips against every pixel: worst {worst}, mean {mean:.3}");
        assert!(worst <= 8 && mean < 0.5, "strips against every pixel: worst {worst}, mean {mean:.3}");
    }
}
