//! Colourisation (SPEC 3.6): each output pixel copies the RGB of the exemplar pixel
//! whose 3x3 neighbourhood in the generated channel agrees with the output's (read on
//! the torus) in the most places; the centre breaks ties.
//!
//! Naively that is `N^4` comparisons. Here an inverted index lists, for each of the 9
//! places and each grey level, the exemplar pixels with that level there; an output
//! pixel only visits the lists of its own 9 values and counts agreements per exemplar
//! pixel. A list longer than `MAX_LIST` is visited at an even stride, so a flat region
//! cannot make the search quadratic.

use super::cooccurrence::Grey;

const MAX_LIST: usize = 512;
const PLACES: [(isize, isize); 9] = [(-1, -1), (0, -1), (1, -1), (-1, 0), (0, 0), (1, 0), (-1, 1), (0, 1), (1, 1)];
const CENTRE: usize = 4;

/// RGB per output pixel, from `rgb` (one per exemplar pixel) of exemplar `ex`.
pub fn colourise(out: &Grey, ex: &Grey, rgb: &[[u8; 3]]) -> Vec<[u8; 3]> {
    let (w, h) = (ex.width, ex.height);
    // Interior exemplar pixels: their whole 3x3 exists.
    let interior: Vec<usize> =
        (1..h.saturating_sub(1)).flat_map(|y| (1..w.saturating_sub(1)).map(move |x| y * w + x)).collect();
    if interior.is_empty() {
        return out.data.iter().map(|&v| [v, v, v]).collect();
    }
    // lists[place][level]: CSR over interior pixels.
    let mut lists: Vec<(Vec<u32>, Vec<u32>)> = Vec::with_capacity(9);
    for &(dx, dy) in &PLACES {
        let level = |i: usize| ex.data[(i as isize + dy * w as isize + dx) as usize] as usize;
        let mut start = vec![0u32; 257];
        for &i in &interior {
            start[level(i) + 1] += 1;
        }
        for l in 0..256 {
            start[l + 1] += start[l];
        }
        let mut fill = start.clone();
        let mut entries = vec![0u32; interior.len()];
        for &i in &interior {
            let l = level(i);
            entries[fill[l] as usize] = i as u32;
            fill[l] += 1;
        }
        lists.push((start, entries));
    }
    let n = out.width;
    let mut score = vec![0u8; w * h];
    let mut touched: Vec<u32> = Vec::new();
    let mut result = Vec::with_capacity(out.data.len());
    for y in 0..out.height {
        for x in 0..n {
            touched.clear();
            let mut best = (0u8, interior[0]);
            for (p, &(dx, dy)) in PLACES.iter().enumerate() {
                let ox = (x as isize + dx).rem_euclid(n as isize) as usize;
                let oy = (y as isize + dy).rem_euclid(out.height as isize) as usize;
                let v = out.data[oy * n + ox] as usize;
                let (start, entries) = &lists[p];
                let list = &entries[start[v] as usize..start[v + 1] as usize];
                let stride = list.len().div_ceil(MAX_LIST).max(1);
                // The centre counts 3, the others 2: most agreements first, then the centre.
                let gain = if p == CENTRE { 3 } else { 2 };
                for &i in list.iter().step_by(stride) {
                    let s = &mut score[i as usize];
                    if *s == 0 {
                        touched.push(i);
                    }
                    *s += gain;
                    if *s > best.0 {
                        best = (*s, i as usize);
                    }
                }
            }
            for &i in &touched {
                score[i as usize] = 0;
            }
            result.push(rgb[best.1]);
        }
    }
    result
}

#[cfg(test)]
mod tests {
    use super::*;

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
