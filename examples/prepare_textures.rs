//! Prepares the exemplar photographs in tests/fixtures/textures/ (128x128 PNG) from the
//! CC0 images shipped in scikit-image's wheel (skimage/data): brick, grass and gravel
//! (cc0textures.com / DeviantArt, CC0) and a wood crop of coffee.png (Rachel Michetti,
//! CC0). Usage: cargo run --example prepare_textures -- <path to skimage/data>
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
}
