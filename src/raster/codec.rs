//! PNG and JPEG in, PNG out, through the image crate, with decoding limits so that a
//! hostile file cannot allocate without bound.

use super::image::{check_size, MAX_SIDE};
use crate::error::{Error, Result};
use image::{ImageEncoder, ImageFormat, ImageReader, Limits};
use std::io::Cursor;

/// RGBA bytes and their size.
#[derive(Clone, Debug, PartialEq)]
pub struct Rgba {
    pub width: usize,
    pub height: usize,
    pub data: Vec<u8>,
}

pub fn decode_image(bytes: &[u8]) -> Result<Rgba> {
    let format = image::guess_format(bytes)
        .map_err(|_| Error::Image("it is neither PNG nor JPEG (unrecognised data).".into()))?;
    if !matches!(format, ImageFormat::Png | ImageFormat::Jpeg) {
        return Err(Error::Image(format!("{format:?} is not supported; use PNG or JPEG.")));
    }
    let mut reader = ImageReader::with_format(Cursor::new(bytes), format);
    let mut limits = Limits::default();
    limits.max_image_width = Some(MAX_SIDE as u32);
    limits.max_image_height = Some(MAX_SIDE as u32);
    limits.max_alloc = Some(512 << 20);
    reader.limits(limits);
    let img = reader.decode().map_err(|e| match e {
        image::ImageError::Limits(_) => {
            Error::TooLarge(format!("The image is larger than {MAX_SIDE}x{MAX_SIDE} pixels."))
        }
        other => Error::Image(format!("{other}.")),
    })?;
    let rgba = img.to_rgba8();
    Ok(Rgba { width: rgba.width() as usize, height: rgba.height() as usize, data: rgba.into_raw() })
}

pub fn encode_png(width: usize, height: usize, rgba: &[u8]) -> Result<Vec<u8>> {
    check_size(width, height, "image")?;
    if rgba.len() != width * height * 4 {
        return Err(Error::InvalidInput(format!(
            "{width}x{height} RGBA needs {} bytes, got {}.",
            width * height * 4,
            rgba.len()
        )));
    }
    let mut out = Vec::new();
    image::codecs::png::PngEncoder::new(&mut out)
        .write_image(rgba, width as u32, height as u32, image::ExtendedColorType::Rgba8)
        .map_err(|e| Error::Image(e.to_string()))?;
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn png_round_trip_and_bad_data() {
        let rgba: Vec<u8> = (0..4 * 3 * 2).map(|i| (i * 9) as u8).collect();
        let png = encode_png(3, 2, &rgba).unwrap();
        let back = decode_image(&png).unwrap();
        assert_eq!((back.width, back.height), (3, 2));
        assert_eq!(back.data, rgba);
        assert!(decode_image(b"GIF89a....").unwrap_err().to_string().contains("not supported"));
        assert!(decode_image(b"hello").is_err());
        assert!(decode_image(&png[..png.len() / 2]).is_err());
    }
}
