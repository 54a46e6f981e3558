//! The image as file bytes: OpenEXR (linear RGB, f32) and PNG (tone-mapped sRGB, 8 bits) (docs/model.md §11).
//! The bytes are returned, not written: callers write them with their own (atomic) writer.

use crate::film::Image;
use std::io::Cursor;

/// Why an image could not be encoded.
#[derive(Debug)]
pub struct EncodeError(String);

impl std::fmt::Display for EncodeError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.0)
    }
}

impl std::error::Error for EncodeError {}

/// The image's mean radiance as an OpenEXR file: channels R, G, B as 32-bit floats, RLE
/// compression, encoded on one thread (the same image gives the same bytes).
pub fn exr_bytes(image: &Image) -> Result<Vec<u8>, EncodeError> {
    use exr::prelude::{
        Encoding, Image as ExrImage, Layer, LayerAttributes, SpecificChannels, Vec2, WritableImage,
    };
    let (w, h) = (image.width as usize, image.height as usize);
    let channels = SpecificChannels::rgb(|Vec2(x, y): Vec2<usize>| {
        let p = image.mean[y * w + x];
        (p[0], p[1], p[2])
    });
    let layer = Layer::new(
        (w, h),
        LayerAttributes::named("render"),
        Encoding::FAST_LOSSLESS,
        channels,
    );
    let mut bytes = Vec::new();
    ExrImage::from_layer(layer)
        .write()
        .non_parallel()
        .to_buffered(Cursor::new(&mut bytes))
        .map_err(|e| EncodeError(format!("encoding the EXR image: {e}")))?;
    Ok(bytes)
}

/// The image's mean radiance with a fourth channel `alpha` (one value per pixel, e.g. a
/// coverage) as an OpenEXR file: channels R, G, B, A as 32-bit floats, otherwise as
/// [`exr_bytes`].
///
/// # Panics
/// When `alpha` does not hold one value per pixel.
pub fn exr_rgba_bytes(image: &Image, alpha: &[f32]) -> Result<Vec<u8>, EncodeError> {
    use exr::prelude::{
        Encoding, Image as ExrImage, Layer, LayerAttributes, SpecificChannels, Vec2, WritableImage,
    };
    let (w, h) = (image.width as usize, image.height as usize);
    assert_eq!(alpha.len(), w * h, "one alpha value per pixel");
    let channels = SpecificChannels::rgba(|Vec2(x, y): Vec2<usize>| {
        let p = image.mean[y * w + x];
        (p[0], p[1], p[2], alpha[y * w + x])
    });
    let layer = Layer::new(
        (w, h),
        LayerAttributes::named("render"),
        Encoding::FAST_LOSSLESS,
        channels,
    );
    let mut bytes = Vec::new();
    ExrImage::from_layer(layer)
        .write()
        .non_parallel()
        .to_buffered(Cursor::new(&mut bytes))
        .map_err(|e| EncodeError(format!("encoding the EXR image: {e}")))?;
    Ok(bytes)
}

/// Tone mapping of linear radiance `x` at `exposure`: 1 − e^(−exposure·x), which is linear
/// for dark values and rolls highlights off smoothly toward 1.
#[inline]
#[must_use]
pub fn tone_map(x: f32, exposure: f32) -> f32 {
    let v = 1.0 - (-(x * exposure).max(0.0)).exp();
    if v.is_finite() {
        v
    } else {
        0.0
    }
}

/// The sRGB transfer function (IEC 61966-2-1) of a linear value in [0, 1].
#[inline]
#[must_use]
pub fn srgb_encode(v: f32) -> f32 {
    let v = v.clamp(0.0, 1.0);
    if v <= 0.003_130_8 {
        12.92 * v
    } else {
        1.055 * v.powf(1.0 / 2.4) - 0.055
    }
}

/// The image as an 8-bit sRGB PNG after [`tone_map`] at `exposure`.
pub fn png_bytes(image: &Image, exposure: f32) -> Result<Vec<u8>, EncodeError> {
    let data: Vec<u8> = image
        .mean
        .iter()
        .flat_map(|p| p.map(|c| (srgb_encode(tone_map(c, exposure)) * 255.0).round() as u8))
        .collect();
    let mut bytes = Vec::new();
    {
        let mut encoder = png::Encoder::new(&mut bytes, image.width, image.height);
        encoder.set_color(png::ColorType::Rgb);
        encoder.set_depth(png::BitDepth::Eight);
        encoder.set_source_srgb(png::SrgbRenderingIntent::Perceptual);
        let mut writer = encoder
            .write_header()
            .map_err(|e| EncodeError(format!("encoding the PNG image: {e}")))?;
        writer
            .write_image_data(&data)
            .map_err(|e| EncodeError(format!("encoding the PNG image: {e}")))?;
    }
    Ok(bytes)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn tiny() -> Image {
        Image {
            width: 2,
            height: 1,
            mean: vec![[0.0, 0.5, 1.0], [2.0, f32::NAN, -1.0]],
            variance: vec![[0.0; 3]; 2],
        }
    }

    #[test]
    fn exr_round_trips_the_floats() {
        use exr::prelude::*;
        let bytes = exr_bytes(&tiny()).unwrap();
        let img = read_first_rgba_layer_from_file(
            {
                let path =
                    std::env::temp_dir().join(format!("render-exr-{}.exr", std::process::id()));
                std::fs::write(&path, &bytes).unwrap();
                path
            },
            |res, _| vec![[0.0f32; 3]; res.width() * res.height()],
            |px: &mut Vec<[f32; 3]>, Vec2(x, _y), (r, g, b, _a): (f32, f32, f32, f32)| {
                px[x] = [r, g, b]
            },
        )
        .unwrap();
        let px = &img.layer_data.channel_data.pixels;
        assert_eq!(px[0], [0.0, 0.5, 1.0]);
        assert_eq!(px[1][0], 2.0);
        assert_eq!(bytes, exr_bytes(&tiny()).unwrap());
    }

    #[test]
    fn png_tone_maps_into_srgb_without_nan() {
        let bytes = png_bytes(&tiny(), 1.0).unwrap();
        assert_eq!(&bytes[1..4], b"PNG");
        assert_eq!(tone_map(f32::NAN, 1.0), 0.0);
        assert!((srgb_encode(1.0) - 1.0).abs() < 1e-6 && srgb_encode(-1.0) == 0.0);
        assert!((tone_map(0.01, 1.0) - 0.01).abs() < 1e-4);
    }
}
