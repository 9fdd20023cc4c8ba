//! Colourisation (SPEC 3.6): each output pixel copies the RGB of the exemplar pixel
//! whose 3x3 neighbourhood in the generated channel agrees with the output's (read on
//! the torus) in the most places.
//!
//! Naively that is `N^4` comparisons. The candidates here are the exemplar pixels with
//! the output pixel's own centre value (the centre is the place that decides the
//! colour; a level absent from the exemplar takes the nearest present one), found
//! through an index by level; the other 8 places are compared directly. A level with
//! more than `MAX_CANDIDATES` pixels is sampled at an even stride, so a crowded level
//! cannot make the search quadratic (at 512 x 512 a level can hold thousands).

use super::cooccurrence::Grey;

const MAX_CANDIDATES: usize = 256;
const PLACES: [(isize, isize); 8] = [(-1, -1), (0, -1), (1, -1), (-1, 0), (1, 0), (-1, 1), (0, 1), (1, 1)];

/// RGB per output pixel, from `rgb` (one per exemplar pixel) of exemplar `ex`.
pub fn colourise(out: &Grey, ex: &Grey, rgb: &[[u8; 3]]) -> Vec<[u8; 3]> {
    let (w, h) = (ex.width, ex.height);
    // Interior exemplar pixels (their whole 3x3 exists), indexed by level.
    let interior: Vec<u32> =
        (1..h.saturating_sub(1)).flat_map(|y| (1..w.saturating_sub(1)).map(move |x| (y * w + x) as u32)).collect();
    if interior.is_empty() {
        return out.data.iter().map(|&v| [v, v, v]).collect();
    }
    let mut start = vec![0u32; 257];
    for &i in &interior {
        start[ex.data[i as usize] as usize + 1] += 1;
    }
    for l in 0..256 {
        start[l + 1] += start[l];
    }
    let mut fill = start.clone();
    let mut by_level = vec![0u32; interior.len()];
    for &i in &interior {
        let l = ex.data[i as usize] as usize;
        by_level[fill[l] as usize] = i;
        fill[l] += 1;
    }
    let present = |l: usize| start[l + 1] > start[l];
    let offsets: Vec<isize> = PLACES.iter().map(|&(dx, dy)| dy * w as isize + dx).collect();
    // Each level's candidates, sampled at an even stride down to `MAX_CANDIDATES`, with
    // their 8 places packed in a word: the agreement of two neighbourhoods is the count
    // of equal bytes (`agreement`). Contiguous per level, so a pixel's search is one scan.
    let (mut words, mut pixels, mut first) = (Vec::new(), Vec::new(), vec![0u32; 257]);
    for l in 0..256 {
        let list = &by_level[start[l] as usize..start[l + 1] as usize];
        for &i in list.iter().step_by(list.len().div_ceil(MAX_CANDIDATES).max(1)) {
            words.push(pack(offsets.iter().map(|&o| ex.data[(i as isize + o) as usize])));
            pixels.push(i);
        }
        first[l + 1] = words.len() as u32;
    }
    // The level whose candidates serve each output value: its own, or the nearest
    // present one (the lower on a tie).
    let serve: Vec<usize> = (0..256usize)
        .map(|v| {
            (0..256usize)
                .flat_map(|d| [v.wrapping_sub(d), v + d])
                .find(|&l| l < 256 && present(l))
                .expect("an interior")
        })
        .collect();
    let (n, m) = (out.width as isize, out.height as isize);
    let mut result = Vec::with_capacity(out.data.len());
    for y in 0..m {
        for x in 0..n {
            let level = serve[out.data[(y * n + x) as usize] as usize];
            let around = pack(
                PLACES.iter().map(|&(dx, dy)| out.data[((y + dy).rem_euclid(m) * n + (x + dx).rem_euclid(n)) as usize]),
            );
            let range = first[level] as usize..first[level + 1] as usize;
            let mut best = (0u32, range.start);
            for (k, &word) in words[range.clone()].iter().enumerate() {
                let agree = agreement(word, around);
                if agree > best.0 {
                    best = (agree, range.start + k);
                    if agree == 8 {
                        break;
                    }
                }
            }
            result.push(rgb[pixels[best.1] as usize]);
        }
    }
    result
}

/// Eight grey levels in one word, the first in the lowest byte.
fn pack(levels: impl Iterator<Item = u8>) -> u64 {
    levels.enumerate().fold(0, |w, (k, v)| w | (v as u64) << (8 * k))
}

/// How many of the eight bytes of `a` and `b` are equal (SWAR: a byte of `a ^ b` is
/// zero exactly where they agree).
fn agreement(a: u64, b: u64) -> u32 {
    const LOW7: u64 = 0x7f7f_7f7f_7f7f_7f7f;
    let x = a ^ b;
    // High bit of each byte set when the byte is non-zero.
    let nonzero = ((x & LOW7) + LOW7) | x;
    8 - (nonzero & !LOW7).count_ones()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn agreement_counts_equal_bytes() {
        let a = pack([1u8, 2, 3, 4, 5, 6, 7, 8].into_iter());
        assert_eq!(agreement(a, a), 8);
        assert_eq!(agreement(a, pack([1u8, 0, 3, 0, 5, 0, 7, 0].into_iter())), 4);
        assert_eq!(agreement(a, pack([0u8, 0, 0, 0, 0, 0, 0, 128].into_iter())), 0);
        assert_eq!(agreement(pack([0u8; 8].into_iter()), pack([0u8, 0, 0, 0, 0, 0, 0, 255].into_iter())), 7);
    }

    #[test]
    fn a_copy_of_the_exemplar_gets_its_own_colours_back() {
        // A 6x6 exemplar with distinct levels; the output is its central 4x4 region as a
        // torus would not match at the wrap, so check interior pixels only.
        let ex = Grey { width: 6, height: 6, data: (0..36).map(|i| (i * 7 % 256) as u8).collect() };
        let rgb: Vec<[u8; 3]> = (0..36).map(|i| [i as u8, 0, 255 - i as u8]).collect();
        let out = ex.clone();
        let c = colourise(&out, &ex, &rgb);
        for y in 1..5 {
            for x in 1..5 {
                assert_eq!(c[y * 6 + x], rgb[y * 6 + x]);
            }
        }
    }
}
