//! PNG and JPEG in, PNG out, through the image crate, with decoding limits so that a
//! hostile file cannot allocate without bound.

use super::image::{check_size, Rgba, MAX_SIDE};
use crate::error::{Error, Result};
use image::{ColorType, ImageDecoder, ImageEncoder, ImageFormat, Limits};
use std::io::Cursor;

pub fn decode_image(bytes: &[u8]) -> Result<Rgba> {
    let format = image::guess_format(bytes)
        .map_err(|_| Error::Image("it is neither PNG nor JPEG (unrecognised data).".into()))?;
    let mut limits = Limits::default();
    limits.max_image_width = Some(MAX_SIDE as u32);
    limits.max_image_height = Some(MAX_SIDE as u32);
    limits.max_alloc = Some(512 << 20);
    let failed = |e: image::ImageError| match e {
        image::ImageError::Limits(_) => {
            Error::TooLarge(format!("The image is larger than {MAX_SIDE}x{MAX_SIDE} pixels."))
        }
        other => Error::Image(format!("{other}.")),
    };
    // A photograph larger than the engine takes is named by its size, with what to do
    // (its header is read before any pixel).
    let fits = |(w, h): (u32, u32)| {
        if w as usize > MAX_SIDE || h as usize > MAX_SIDE {
            return Err(Error::TooLarge(format!(
                "The image is {w}x{h} pixels; the largest side accepted is {MAX_SIDE}: scale it down first (the \
                 playground does so itself when an image is dropped on it)."
            )));
        }
        Ok(())
    };
    // The format decoders directly, not DynamicImage: its conversions between every
    // pixel type cost the wasm module about a hundred kilobytes.
    match format {
        ImageFormat::Png => {
            let mut d = image::codecs::png::PngDecoder::new(Cursor::new(bytes)).map_err(failed)?;
            fits(d.dimensions())?;
            d.set_limits(limits).map_err(failed)?;
            read(d).map_err(failed)
        }
        ImageFormat::Jpeg => {
            let mut d = image::codecs::jpeg::JpegDecoder::new(Cursor::new(bytes)).map_err(failed)?;
            fits(d.dimensions())?;
            d.set_limits(limits).map_err(failed)?;
            read(d).map_err(failed)
        }
        other => Err(Error::Image(format!("{other:?} is not supported; use PNG or JPEG."))),
    }
}

/// Reads a decoder's pixels and widens them to RGBA8.
fn read(d: impl ImageDecoder) -> std::result::Result<Rgba, image::ImageError> {
    let (w, h) = d.dimensions();
    let color = d.color_type();
    let mut buf = vec![0u8; d.total_bytes() as usize];
    d.read_image(&mut buf)?;
    let n = (w * h) as usize;
    let mut data = Vec::with_capacity(n * 4);
    let wide = |v: &[u8], i: usize| v[2 * i + usize::from(cfg!(target_endian = "little"))];
    for i in 0..n {
        let px: [u8; 4] = match color {
            ColorType::L8 => [buf[i], buf[i], buf[i], 255],
            ColorType::La8 => [buf[2 * i], buf[2 * i], buf[2 * i], buf[2 * i + 1]],
            ColorType::Rgb8 => [buf[3 * i], buf[3 * i + 1], buf[3 * i + 2], 255],
            ColorType::Rgba8 => [buf[4 * i], buf[4 * i + 1], buf[4 * i + 2], buf[4 * i + 3]],
            // 16-bit samples in native byte order: keep the high byte.
            ColorType::L16 => {
                let v = wide(&buf, i);
                [v, v, v, 255]
            }
            ColorType::La16 => {
                let v = wide(&buf, 2 * i);
                [v, v, v, wide(&buf, 2 * i + 1)]
            }
            ColorType::Rgb16 => [wide(&buf, 3 * i), wide(&buf, 3 * i + 1), wide(&buf, 3 * i + 2), 255],
            ColorType::Rgba16 => {
                [wide(&buf, 4 * i), wide(&buf, 4 * i + 1), wide(&buf, 4 * i + 2), wide(&buf, 4 * i + 3)]
            }
            other => {
                return Err(image::ImageError::Unsupported(image::error::UnsupportedError::from_format_and_kind(
                    image::error::ImageFormatHint::Unknown,
                    image::error::UnsupportedErrorKind::Color(other.into()),
                )))
            }
        };
        data.extend_from_slice(&px);
    }
    Ok(Rgba { width: w as usize, height: h as usize, data })
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

    #[test]
    fn a_photograph_too_large_is_named_by_its_size() {
        // A PNG whose header says 6028 x 3391 (a phone's photograph): refused before any
        // pixel is read, with its size and what to do.
        let mut png = encode_png(3, 2, &[0; 24]).unwrap();
        png[16..20].copy_from_slice(&6028u32.to_be_bytes());
        png[20..24].copy_from_slice(&3391u32.to_be_bytes());
        // (The header chunk's CRC-32 over its type and data, bit by bit.)
        let crc = !png[12..29].iter().fold(!0u32, |mut c, &b| {
            c ^= b as u32;
            for _ in 0..8 {
                c = if c & 1 == 1 { (c >> 1) ^ 0xEDB8_8320 } else { c >> 1 };
            }
            c
        });
        png[29..33].copy_from_slice(&crc.to_be_bytes());
        let err = decode_image(&png).unwrap_err().to_string();
        assert!(err.contains("6028x3391") && err.contains("largest side accepted is 4096"), "{err}");
    }
}
