//! The generation coefficient mu(x, y) in [0, 1]: the weight of exemplar A at each output
//! pixel (B gets 1 - mu). The paper's map is linear top to bottom; its two non-linear
//! transfers change slowly (`Ease`) or sharply (`Steep`) through the middle.

use crate::error::{invalid, Result};

#[derive(Clone, Debug, PartialEq)]
pub enum Shape {
    /// A along the side the direction comes from, B where it goes: `angle` in degrees,
    /// 90 = top to bottom (the paper's), 0 = left to right.
    Directional { angle: f64 },
    /// A at the centre, B at the corners.
    Radial,
    /// A caller-supplied map, one value per output pixel, row major.
    Map(Vec<f32>),
}

#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Transfer {
    Linear,
    /// `0.5 + 4 (t - 0.5)^3`: flat through the middle, the mix lingers there.
    Ease,
    /// A logistic curve through the middle: a sharp change.
    Steep,
}

impl Transfer {
    pub fn apply(self, t: f64) -> f64 {
        let t = t.clamp(0.0, 1.0);
        match self {
            Transfer::Linear => t,
            Transfer::Ease => 0.5 + 4.0 * (t - 0.5).powi(3),
            Transfer::Steep => {
                let k = 14.0;
                let s = |u: f64| 1.0 / (1.0 + (-k * (u - 0.5)).exp());
                (s(t) - s(0.0)) / (s(1.0) - s(0.0))
            }
        }
    }
}

/// The coefficient as a `width x height` map.
pub fn map(shape: &Shape, transfer: Transfer, width: usize, height: usize) -> Result<Vec<f32>> {
    let (w, h) = (width as f64, height as f64);
    match shape {
        Shape::Map(m) => {
            if m.len() != width * height {
                return invalid(format!(
                    "The coefficient map has {} values; a {width}x{height} output needs {}.",
                    m.len(),
                    width * height
                ));
            }
            if let Some(i) = m.iter().position(|v| !v.is_finite()) {
                return invalid(format!("The coefficient map has a value that is not a number (at index {i})."));
            }
            if let Some(i) = m.iter().position(|v| !(0.0..=1.0).contains(v)) {
                return invalid(format!("Coefficient values must lie in [0, 1]; index {i} holds {}.", m[i]));
            }
            Ok(m.iter().map(|&v| transfer.apply(v as f64) as f32).collect())
        }
        Shape::Directional { angle } => {
            if !angle.is_finite() {
                return invalid("The coefficient angle must be a number of degrees.");
            }
            let (dx, dy) = (angle.to_radians().cos(), angle.to_radians().sin());
            // Project the corners to normalise the ramp to [0, 1] over the image.
            let proj = |x: f64, y: f64| x * dx + y * dy;
            let corners = [proj(0.0, 0.0), proj(w - 1.0, 0.0), proj(0.0, h - 1.0), proj(w - 1.0, h - 1.0)];
            let lo = corners.iter().copied().fold(f64::MAX, f64::min);
            let hi = corners.iter().copied().fold(f64::MIN, f64::max);
            let span = (hi - lo).max(1e-9);
            Ok((0..height)
                .flat_map(|y| (0..width).map(move |x| (x as f64, y as f64)))
                .map(|(x, y)| transfer.apply(1.0 - (proj(x, y) - lo) / span) as f32)
                .collect())
        }
        Shape::Radial => {
            let (cx, cy) = ((w - 1.0) / 2.0, (h - 1.0) / 2.0);
            let rmax = cx.hypot(cy).max(1e-9);
            Ok((0..height)
                .flat_map(|y| (0..width).map(move |x| (x as f64, y as f64)))
                .map(|(x, y)| transfer.apply(1.0 - (x - cx).hypot(y - cy) / rmax) as f32)
                .collect())
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn linear_is_one_at_top_zero_at_bottom() {
        let m = map(&Shape::Directional { angle: 90.0 }, Transfer::Linear, 4, 11).unwrap();
        assert!((m[0] - 1.0).abs() < 1e-6 && m[10 * 4].abs() < 1e-6);
        assert!((m[5 * 4 + 2] - 0.5).abs() < 1e-6);
    }

    #[test]
    fn transfers_keep_ends_and_shape_the_middle() {
        for t in [Transfer::Ease, Transfer::Steep] {
            assert!(t.apply(0.0).abs() < 1e-9 && (t.apply(1.0) - 1.0).abs() < 1e-9);
            assert!((t.apply(0.5) - 0.5).abs() < 1e-9);
        }
        let slope = |t: Transfer| (t.apply(0.55) - t.apply(0.45)) / 0.1;
        assert!(slope(Transfer::Ease) < 0.2, "ease is flat in the middle");
        assert!(slope(Transfer::Steep) > 3.0, "steep is sharp in the middle");
    }

    #[test]
    fn bad_maps_are_refused() {
        assert!(map(&Shape::Map(vec![0.5; 5]), Transfer::Linear, 2, 2).is_err());
        assert!(map(&Shape::Map(vec![0.5, f32::NAN, 0.1, 0.2]), Transfer::Linear, 2, 2)
            .unwrap_err()
            .to_string()
            .contains("not a number"));
        assert!(map(&Shape::Map(vec![0.5, 1.5, 0.1, 0.2]), Transfer::Linear, 2, 2).is_err());
    }
}
