//! Prepares the exemplar photographs in tests/fixtures/textures/ (128x128 PNG) from the
//! CC0 images shipped in scikit-image's wheel (skimage/data): brick, grass and gravel
//! (cc0textures.com / DeviantArt, CC0) and a wood crop of coffee.png (Rachel Michetti,
//! CC0), and six crops of other kinds (see SOURCES.md). Usage: cargo run --example prepare_textures -- <path to skimage/data>
use image::{imageops, DynamicImage, RgbaImage};

fn main() {
    let dir = std::env::args().nth(1).expect("path to skimage/data");
    let out = std::path::Path::new("tests/fixtures/textures");
    std::fs::create_dir_all(out).unwrap();
    let load = |name: &str| image::open(format!("{dir}/{name}")).expect(name).to_rgba8();
    // The 512x512 greyscale textures: a 256x256 crop, halved, keeps their grain.
    for name in ["brick", "grass", "gravel"] {
        let img = load(&format!("{name}.png"));
        let crop = imageops::crop_imm(&img, 128, 128, 256, 256).to_image();
        let small: RgbaImage = imageops::resize(&crop, 128, 128, imageops::FilterType::Triangle);
        small.save(out.join(format!("{name}.png"))).unwrap();
    }
    // The wooden table at the bottom right of coffee.png, at full resolution.
    let coffee = load("coffee.png");
    let wood = DynamicImage::ImageRgba8(imageops::crop_imm(&coffee, 472, 272, 128, 128).to_image());
    wood.to_rgba8().save(out.join("wood.png")).unwrap();
    // More exemplars nobody on the project chose for the engine: photographs of other
    // kinds (stone-like, stochastic, fur, tissue) and structured images (print, coins),
    // each a crop scaled to 128x128 (halved from 256 where the grain is fine).
    let crops: [(&str, &str, u32, u32, u32); 6] = [
        ("moon", "moon.png", 256, 256, 256),
        ("hubble", "hubble_deep_field.jpg", 0, 0, 256),
        ("tissue", "ihc.png", 64, 64, 256),
        ("fur", "chelsea.png", 200, 0, 96),
        ("print", "page.png", 120, 40, 128),
        ("coins", "coins.png", 0, 0, 256),
    ];
    for (name, file, x, y, side) in crops {
        let crop = imageops::crop_imm(&load(file), x, y, side, side).to_image();
        let small: RgbaImage = imageops::resize(&crop, 128, 128, imageops::FilterType::Triangle);
        small.save(out.join(format!("{name}.png"))).unwrap();
    }
}
