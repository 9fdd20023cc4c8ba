//! Pixels as four `f32` lanes (red, green, blue, and a fourth), and the sum of squared
//! differences between neighbourhoods, the synthesis's inner loop.
//!
//! The fourth lane holds a guide's value (`synthesis::Guide`), or the alpha where it
//! varies and no guide holds the lane (`opacity`), else 0, and pads a pixel to 16
//! bytes, so that one SIMD instruction subtracts, squares and adds a whole pixel:
//! built with `simd128` the wasm module uses `f32x4`, a native build the
//! portable loop below, which LLVM turns into SSE, and the module for browsers without
//! SIMD adds the four lanes one by one. Every build sums each lane on its own and adds
//! the lanes in one order at the end, so all three give the same sums to the bit, and
//! the same images.

/// One pixel: red, green, blue on the 0-255 scale, and the guide, the alpha or 0.
pub type Px = [f32; 4];

/// A colour padded to a pixel.
#[inline(always)]
pub fn px(c: [f32; 3]) -> Px {
    [c[0], c[1], c[2], 0.0]
}

/// A running sum of squared differences, one per lane.
#[derive(Clone, Copy)]
pub struct Sum(Acc);

#[cfg(all(target_arch = "wasm32", target_feature = "simd128"))]
type Acc = core::arch::wasm32::v128;
#[cfg(not(all(target_arch = "wasm32", target_feature = "simd128")))]
type Acc = [f32; 4];

/// Lanes added one by one where there is no SIMD (all four: the guide's too).
#[cfg(not(all(target_arch = "wasm32", target_feature = "simd128")))]
const LANES: usize = 4;

impl Sum {
    #[inline(always)]
    pub fn zero() -> Sum {
        #[cfg(all(target_arch = "wasm32", target_feature = "simd128"))]
        return Sum(core::arch::wasm32::f32x4_splat(0.0));
        #[cfg(not(all(target_arch = "wasm32", target_feature = "simd128")))]
        Sum([0.0; 4])
    }

    /// Adds the squared difference of `a` and `b`, lane by lane.
    #[inline(always)]
    pub fn add(&mut self, a: &Px, b: &Px) {
        #[cfg(all(target_arch = "wasm32", target_feature = "simd128"))]
        {
            use core::arch::wasm32::*;
            // SAFETY: each reference is to 16 readable bytes; v128 loads need no alignment.
            let (a, b) = unsafe { (v128_load(a.as_ptr().cast()), v128_load(b.as_ptr().cast())) };
            let d = f32x4_sub(a, b);
            self.0 = f32x4_add(self.0, f32x4_mul(d, d));
        }
        #[cfg(not(all(target_arch = "wasm32", target_feature = "simd128")))]
        for c in 0..LANES {
            let d = a[c] - b[c];
            self.0[c] += d * d;
        }
    }

    /// The lanes added: red, then green, then blue, then the guide.
    #[inline(always)]
    pub fn total(self) -> f32 {
        #[cfg(all(target_arch = "wasm32", target_feature = "simd128"))]
        {
            use core::arch::wasm32::f32x4_extract_lane as lane;
            ((lane::<0>(self.0) + lane::<1>(self.0)) + lane::<2>(self.0)) + lane::<3>(self.0)
        }
        #[cfg(not(all(target_arch = "wasm32", target_feature = "simd128")))]
        {
            ((self.0[0] + self.0[1]) + self.0[2]) + self.0[3]
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sums_squared_differences_per_channel() {
        let mut s = Sum::zero();
        s.add(&px([1.0, 2.0, 3.0]), &px([4.0, 0.0, 3.5]));
        s.add(&px([0.0, 0.0, 0.0]), &px([0.0, 10.0, 0.0]));
        assert_eq!(s.total(), 9.0 + 4.0 + 0.25 + 100.0);
    }
}
