//! Several exemplars of one material as one pool to draw from, and the layout of a
//! synthesis: which exemplar and pixel each output pixel copies.
//!
//! The pool is one image: the exemplars stacked top to bottom with a gutter of
//! positions that are never copied between them (a sample mask over the gutters and
//! the unused width right of narrower exemplars). One search then draws from all of
//! them, a coherent patch never runs from one exemplar into the next (the gutter
//! between them is masked), and the masks of each exemplar carry over. The gutter is
//! filled smoothly like any masked region (`synthesis::mask::fill`) and is wide enough
//! that no allowed position's neighbourhood, at any level, reads the other exemplar.

use super::image::{Image, Rgba, MAX_PIXELS, MAX_SIDE};
use crate::error::{invalid, Error, Result};

/// Exemplars stacked into one image (`pool`).
pub struct Pool {
    pub image: Image,
    /// Positions that may be copied (`None` for one exemplar without a mask).
    pub allowed: Option<Vec<bool>>,
    /// Each exemplar's first row in `image`, and its size.
    parts: Vec<(usize, usize, usize)>,
}

/// The gutter between exemplars for a synthesis of `levels` levels and neighbourhood
/// `side`: at the coarsest level, the neighbourhood's reach and the pyramid's blur
/// (two pixels per level) on each side.
pub fn gutter(levels: usize, side: usize) -> usize {
    (2 * (side / 2 + 4)) << (levels.max(1) - 1)
}

/// Stacks `exemplars` (each with its sample mask, `true` where it may be copied) with
/// `gutter` rows between them.
pub fn pool(exemplars: &[Image], masks: &[Option<Vec<bool>>], gutter: usize) -> Result<Pool> {
    if exemplars.is_empty() {
        return invalid("No exemplar given: pass an image, or an array of images.");
    }
    if exemplars.len() > 255 {
        return invalid(format!("{} exemplars given; at most 255 can be pooled.", exemplars.len()));
    }
    if masks.len() > exemplars.len() {
        return invalid(format!("{} sample masks for {} exemplars.", masks.len(), exemplars.len()));
    }
    if exemplars.len() == 1 {
        return Ok(Pool {
            image: exemplars[0].clone(),
            allowed: masks.first().cloned().flatten(),
            parts: vec![(0, exemplars[0].width, exemplars[0].height)],
        });
    }
    let width = exemplars.iter().map(|e| e.width).max().unwrap_or(0);
    let height = exemplars.iter().map(|e| e.height).sum::<usize>() + gutter * (exemplars.len() - 1);
    if width * height > MAX_PIXELS || width > MAX_SIDE || height > MAX_SIDE {
        return Err(Error::TooLarge(format!(
            "The {} exemplars make a pool of {width}x{height} with the gaps between them; the limits are {MAX_PIXELS} \
             pixels and {MAX_SIDE} a side: use smaller or fewer exemplars.",
            exemplars.len()
        )));
    }
    let mut image = Image::new(width, height);
    let mut allowed = vec![false; width * height];
    let mut parts = Vec::with_capacity(exemplars.len());
    let mut top = 0;
    for (i, e) in exemplars.iter().enumerate() {
        let mask = masks.get(i).and_then(|m| m.as_deref());
        if mask.is_some_and(|m| m.len() != e.width * e.height) {
            return invalid(format!("Sample mask {} does not match its exemplar ({}x{}).", i + 1, e.width, e.height));
        }
        for y in 0..e.height {
            let row = (top + y) * width;
            image.data[row..row + e.width].copy_from_slice(&e.data[y * e.width..(y + 1) * e.width]);
            for x in 0..e.width {
                allowed[row + x] = mask.is_none_or(|m| m[y * e.width + x]);
            }
        }
        parts.push((top, e.width, e.height));
        top += e.height + gutter;
    }
    Ok(Pool { image, allowed: Some(allowed), parts })
}

impl Pool {
    /// The exemplar and its pixel (x, y) at position `pos` of the pool.
    pub fn locate(&self, pos: u32) -> (usize, usize, usize) {
        let (x, y) = (pos as usize % self.image.width, pos as usize / self.image.width);
        let k = self.parts.partition_point(|&(top, ..)| top <= y).saturating_sub(1);
        (k, x, y - self.parts[k].0)
    }

    /// One byte per pixel of each exemplar (its alpha; `None`: `fill` throughout) laid out
    /// as the pool lays their colours, `fill` in the gutters.
    pub fn lay_out(&self, planes: &[Option<&[u8]>], fill: u8) -> Vec<u8> {
        let width = self.image.width;
        let mut out = vec![fill; width * self.image.height];
        for (&(top, w, h), plane) in self.parts.iter().zip(planes) {
            if let Some(p) = plane {
                for y in 0..h {
                    out[(top + y) * width..][..w].copy_from_slice(&p[y * w..(y + 1) * w]);
                }
            }
        }
        out
    }

    /// Each exemplar's size.
    pub fn sizes(&self) -> Vec<(usize, usize)> {
        self.parts.iter().map(|&(_, w, h)| (w, h)).collect()
    }
}

/// Which exemplar and pixel each output pixel copies: one `u32` per pixel, row major,
/// `exemplar << 24 | y << 12 | x` (exemplar index, then the pixel's row and column in
/// it; sides are at most 4096).
#[derive(Clone, Debug, PartialEq)]
pub struct Layout {
    pub width: usize,
    pub height: usize,
    /// Each exemplar's width and height, in order.
    pub exemplars: Vec<(usize, usize)>,
    pub data: Vec<u32>,
}

impl Layout {
    /// The layout of a synthesis from `pool` whose finest sources are `src`.
    pub fn new(pool: &Pool, width: usize, height: usize, src: &[u32]) -> Layout {
        let data = src
            .iter()
            .map(|&p| {
                let (e, x, y) = pool.locate(p);
                (e as u32) << 24 | (y as u32) << 12 | x as u32
            })
            .collect();
        Layout { width, height, exemplars: pool.sizes(), data }
    }

    /// Exemplar, x and y of an entry.
    pub fn unpack(v: u32) -> (usize, usize, usize) {
        ((v >> 24) as usize, (v & 0xFFF) as usize, ((v >> 12) & 0xFFF) as usize)
    }

    /// Checks the fields agree (a layout that came back from JS).
    pub fn check(&self) -> Result<()> {
        if self.width == 0 || self.height == 0 || self.data.len() != self.width * self.height {
            return invalid(format!(
                "The layout holds {} entries; a {}x{} layout needs one per pixel.",
                self.data.len(),
                self.width,
                self.height
            ));
        }
        for (i, &v) in self.data.iter().enumerate() {
            let (e, x, y) = Layout::unpack(v);
            match self.exemplars.get(e) {
                Some(&(w, h)) if x < w && y < h => {}
                _ => {
                    return invalid(format!(
                        "Layout entry {i} points at exemplar {} pixel ({x}, {y}), which its exemplars do not have.",
                        e + 1
                    ))
                }
            }
        }
        Ok(())
    }
}

/// Replays `layout` on `maps`: each map is one image per exemplar, of the exemplars'
/// sizes (a normal, roughness or height map of each), and gives one image of the
/// layout's size whose every pixel (alpha too) is the map's pixel the layout names.
pub fn apply_layout(layout: &Layout, maps: &[Vec<Rgba>]) -> Result<Vec<Rgba>> {
    layout.check()?;
    let mut out = Vec::with_capacity(maps.len());
    for (m, images) in maps.iter().enumerate() {
        if images.len() != layout.exemplars.len() {
            return invalid(format!(
                "Map {} has {} images; the layout is from {} exemplars (one image per exemplar, in their order).",
                m + 1,
                images.len(),
                layout.exemplars.len()
            ));
        }
        for (e, (img, &(w, h))) in images.iter().zip(&layout.exemplars).enumerate() {
            if (img.width, img.height) != (w, h) {
                return invalid(format!(
                    "Map {}'s image for exemplar {} is {}x{}; the exemplar is {w}x{h}.",
                    m + 1,
                    e + 1,
                    img.width,
                    img.height
                ));
            }
        }
        let mut data = Vec::with_capacity(layout.data.len() * 4);
        for &v in &layout.data {
            let (e, x, y) = Layout::unpack(v);
            let img = &images[e];
            let i = 4 * (y * img.width + x);
            data.extend_from_slice(&img.data[i..i + 4]);
        }
        out.push(Rgba { width: layout.width, height: layout.height, data });
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn flat(w: usize, h: usize, v: f32) -> Image {
        Image { width: w, height: h, data: vec![[v; 3]; w * h] }
    }

    #[test]
    fn stacks_with_masked_gutters_and_locates_back() {
        let p = pool(&[flat(8, 4, 10.0), flat(6, 5, 20.0)], &[], 3).unwrap();
        assert_eq!((p.image.width, p.image.height), (8, 4 + 3 + 5));
        let allowed = p.allowed.as_ref().unwrap();
        // Gutter rows and the unused columns right of the narrower exemplar.
        assert!((4..7).all(|y| (0..8).all(|x| !allowed[y * 8 + x])));
        assert!(!allowed[7 * 8 + 6] && allowed[7 * 8 + 5] && allowed[3 * 8 + 7]);
        assert_eq!(p.locate((7 * 8 + 5) as u32), (1, 5, 0));
        assert_eq!(p.locate((3 * 8 + 7) as u32), (0, 7, 3));
        let layout = Layout::new(&p, 2, 1, &[(7 * 8 + 5) as u32, (3 * 8 + 7) as u32]);
        assert_eq!(layout.data.iter().map(|&v| Layout::unpack(v)).collect::<Vec<_>>(), vec![(1, 5, 0), (0, 7, 3)]);
        layout.check().unwrap();
    }

    #[test]
    fn a_pool_taller_than_a_side_allows_is_refused_as_a_pool() {
        // Three narrow exemplars of 1,400 rows and their gutters: 4,392 rows, under the
        // pixel cap but over the side's.
        let tall = flat(8, 1400, 0.0);
        let err = pool(&[tall.clone(), tall.clone(), tall], &[], 96).err().expect("too tall").to_string();
        assert!(err.contains("make a pool of 8x4392") && err.contains("4096 a side"), "{err}");
    }

    #[test]
    fn replays_a_layout_on_other_maps() {
        let p = pool(&[flat(4, 4, 0.0), flat(4, 4, 0.0)], &[], 2).unwrap();
        let layout = Layout::new(&p, 2, 1, &[(6 * 4 + 1) as u32, 2]);
        let map = |base: u8| Rgba { width: 4, height: 4, data: (0..64).map(|i| base.wrapping_add(i as u8)).collect() };
        let out = apply_layout(&layout, &[vec![map(0), map(100)]]).unwrap();
        // Exemplar 1's (1, 0) and exemplar 0's (2, 0).
        assert_eq!(out[0].data, vec![104, 105, 106, 107, 8, 9, 10, 11]);
        let err = apply_layout(&layout, &[vec![map(0)]]).unwrap_err().to_string();
        assert!(err.contains("one image per exemplar"), "{err}");
    }
}
