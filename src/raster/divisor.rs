//! Division by a number fixed for a whole pass (an image's width) as a multiply and a
//! shift: the synthesis turns exemplar positions into (x, y) for every candidate and
//! neighbour, and a hardware division costs 20-40 cycles where this costs 3 (it was an
//! eighth of the native profile).
//!
//! With `m = ceil(2^K / d)`, `floor(n m / 2^K) = floor(n / d)` whenever `n e < 2^K`,
//! where `e = m d - 2^K < d` (Granlund and Montgomery 1994). With `K = 37` that holds
//! for every `n < 2^25` and `d <= 2^12`: positions in images of up to 4096 x 4096
//! pixels (`image::MAX_SIDE`), and for larger divisors up to `n < 2^37 / d`.

/// `d` prepared for dividing numbers below `2^25` by it.
#[derive(Clone, Copy, Debug)]
pub struct Divisor {
    d: u32,
    m: u64,
}

const K: u32 = 37;

impl Divisor {
    /// `d` must be from 1 to 4096.
    pub fn new(d: usize) -> Divisor {
        assert!((1..=1 << 12).contains(&d), "divisor {d} out of range");
        Divisor { d: d as u32, m: (1u64 << K).div_ceil(d as u64) }
    }

    /// `n / d`, for `n < 2^25`.
    #[inline(always)]
    pub fn div(self, n: u32) -> u32 {
        debug_assert!(n < 1 << 25);
        ((n as u64 * self.m) >> K) as u32
    }

    /// `(n % d, n / d)`: column and row of position `n` in a grid `d` wide.
    #[inline(always)]
    pub fn split(self, n: u32) -> (u32, u32) {
        let q = self.div(n);
        (n - q * self.d, q)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn divides_exactly_over_the_whole_range() {
        let mut ns: Vec<u32> = (0..5000).collect();
        ns.extend((0..25).flat_map(|b| [(1u32 << b) - 1, 1 << b, (1 << b) + 1]));
        ns.extend((1u32..4096).map(|k| k * 4099));
        ns.push((1 << 25) - 1);
        for d in 1..=4096u32 {
            let div = Divisor::new(d as usize);
            for &n in ns.iter().filter(|&&n| n < 1 << 25) {
                assert_eq!(div.split(n), (n % d, n / d), "{n} / {d}");
            }
            // The last numbers below multiples of d, where a rounding error would show.
            for q in [(1u32 << 25) / d - 1, 4095, 1] {
                let n = q * d + d - 1;
                if n < 1 << 25 {
                    assert_eq!(div.div(n), q, "{n} / {d}");
                }
            }
        }
    }
}
