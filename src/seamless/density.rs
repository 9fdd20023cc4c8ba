//! Density-distribution conversion (SPEC 3.5).
//!
//! "Max count difference" is the pixel count of the most frequent grey level less the
//! mean count over the levels present. A large one makes generation collapse onto
//! that level. Before generation it is lowered: while it exceeds `T0`, the most
//! frequent level gives its excess over `T1 = mean + T0` (at most `T1` pixels at a
//! time, chosen at random) to the unused level nearest it; the mapping back is kept
//! and applied to the generated texture.

use super::cooccurrence::Grey;
use crate::rng::Rng;

/// Max count difference of a histogram (0 for an empty one).
pub fn max_count_difference(hist: &[u32; 256]) -> f64 {
    let present = hist.iter().filter(|&&c| c > 0).count();
    if present == 0 {
        return 0.0;
    }
    let total: u64 = hist.iter().map(|&c| c as u64).sum();
    *hist.iter().max().unwrap() as f64 - total as f64 / present as f64
}

/// A converted exemplar and the way back to the original levels.
pub struct Conversion {
    pub image: Grey,
    /// Original level of each converted level.
    pub back: [u8; 256],
    /// Max count difference before and after.
    pub before: f64,
    pub after: f64,
}

impl Conversion {
    /// Maps converted levels back to the original ones.
    pub fn restore(&self, img: &Grey) -> Grey {
        Grey { width: img.width, height: img.height, data: img.data.iter().map(|&v| self.back[v as usize]).collect() }
    }
}

/// Lowers the max count difference of `img` to at most `t0` where the 256 levels allow.
///
/// The final threshold is found first: with `m` new levels the mean falls to
/// `N / (present + m)`, so `T1 = mean + t0` and the excess over it need
/// `ceil(excess / T1)` new levels; `m` grows until that holds. Each crowded level then
/// gives chunks of `T1` pixels (chosen at random) to the unused levels nearest it.
pub fn convert(img: &Grey, t0: f64, seed: u64) -> Conversion {
    let mut out = img.clone();
    let mut back = [0u8; 256];
    for (i, b) in back.iter_mut().enumerate() {
        *b = i as u8;
    }
    let mut hist = out.histogram();
    let before = max_count_difference(&hist);
    if before <= t0 {
        return Conversion { image: out, back, before, after: before };
    }
    let total = out.data.len() as f64;
    let present = hist.iter().filter(|&&c| c > 0).count();
    let threshold = |m: usize| ((total / (present + m) as f64 + t0).floor() as u32).max(1);
    let mut m = 0;
    while present + m < 256 {
        let t1 = threshold(m);
        let excess: u64 = hist.iter().map(|&c| c.saturating_sub(t1) as u64).sum();
        let need = excess.div_ceil(t1 as u64) as usize;
        if need <= m {
            break;
        }
        m = need.min(256 - present);
    }
    let t1 = threshold(m);
    let mut rng = Rng::new(seed);
    let mut crowded: Vec<usize> = (0..256).filter(|&l| hist[l] > t1).collect();
    crowded.sort_by_key(|&l| std::cmp::Reverse(hist[l]));
    for level in crowded {
        let mut at: Vec<usize> = (0..out.data.len()).filter(|&i| out.data[i] as usize == level).collect();
        let mut moved = 0usize;
        while hist[level] > t1 {
            // The unused level nearest the crowded one.
            let Some(free) = (1..256isize)
                .flat_map(|d| [level as isize - d, level as isize + d])
                .find(|&u| (0..256).contains(&u) && hist[u as usize] == 0)
            else {
                break;
            };
            let chunk = (hist[level] - t1).min(t1) as usize;
            // A seeded partial shuffle picks which pixels move.
            for i in moved..moved + chunk {
                let j = i + rng.below(at.len() - i);
                at.swap(i, j);
                out.data[at[i]] = free as u8;
            }
            moved += chunk;
            hist[level] -= chunk as u32;
            hist[free as usize] += chunk as u32;
            back[free as usize] = back[level];
        }
    }
    let after = max_count_difference(&hist);
    Conversion { image: out, back, before, after }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_crowded_level_is_spread_and_mapped_back() {
        // 1000 pixels of level 100, 24 of levels 0..24.
        let mut data = vec![100u8; 1000];
        data.extend(0..24u8);
        let img = Grey { width: 1024, height: 1, data };
        let c = convert(&img, 50.0, 1);
        assert!(c.before > 900.0 && c.after <= 50.0, "{} -> {}", c.before, c.after);
        assert_eq!(c.restore(&c.image), img);
        // The new levels are near 100.
        let h = c.image.histogram();
        let used: Vec<usize> = (24..256).filter(|&l| h[l] > 0).collect();
        assert!(used.iter().all(|l| (60..140).contains(l)), "{used:?}");
    }
}
