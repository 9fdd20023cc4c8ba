//! An exemplar prepared for matching, and the distance between a neighbourhood of the
//! output and one of the exemplar: the sum of squared differences over the own level's
//! pixels, and over the parent level's weighted by `PARENT_WEIGHT`.

use super::lanes::{px, Px, Sum};
use super::mask;
use super::opacity::{self, Opacity};
use crate::error::{invalid, Result};
use crate::raster::divisor::Divisor;
use crate::raster::image::Image;
use crate::raster::neighbourhood::Shape;
use crate::raster::pyramid::{self, Edge};
use crate::rng::Rng;

/// One level of an exemplar, its pixels padded to four lanes (`lanes`): the colour,
/// and in the fourth lane the guide (scaled by its weight), or the alpha where it
/// varies and there is no guide (`opacity`), else 0.
pub(crate) struct Plane {
    pub width: usize,
    pub height: usize,
    pub data: Vec<Px>,
    /// The width, to turn positions into columns and rows.
    pub columns: Divisor,
    /// The positions that may be copied, when not all may (a sample mask).
    allowed: Option<Allowed>,
}

/// Positions that may be copied: as a mask, and listed (to draw from at random).
struct Allowed {
    mask: Vec<bool>,
    list: Vec<u32>,
}

impl Plane {
    fn new(img: &Image) -> Plane {
        let data = img.data.iter().map(|&c| px(c)).collect();
        Plane { width: img.width, height: img.height, data, columns: Divisor::new(img.width), allowed: None }
    }

    /// Sets the fourth lane from a grey image of the plane's size, times `scale`.
    fn guide(&mut self, grey: &Image, scale: f32) {
        for (p, g) in self.data.iter_mut().zip(&grey.data) {
            p[3] = scale * g[0];
        }
    }

    /// Whether position `pos` may be copied.
    #[inline(always)]
    pub fn allows(&self, pos: u32) -> bool {
        self.allowed.as_ref().is_none_or(|a| a.mask[pos as usize])
    }

    /// A position that may be copied, at random (without a mask, `rng.below` of the
    /// pixel count, as before masks existed).
    #[inline]
    pub fn random(&self, rng: &mut Rng) -> u32 {
        match &self.allowed {
            None => rng.below(self.data.len()) as u32,
            Some(a) => a.list[rng.below(a.list.len())],
        }
    }

    /// How many positions may be copied.
    pub fn allowed_count(&self) -> usize {
        self.allowed.as_ref().map_or(self.data.len(), |a| a.list.len())
    }

    /// The mask of positions that may be copied, if some may not.
    pub fn allowed_mask(&self) -> Option<&[bool]> {
        self.allowed.as_ref().map(|a| a.mask.as_slice())
    }

    /// Calls `f` with every position that may be copied, in order.
    #[inline]
    pub fn each_allowed(&self, mut f: impl FnMut(u32)) {
        match &self.allowed {
            None => (0..self.data.len() as u32).for_each(f),
            Some(a) => a.list.iter().for_each(|&p| f(p)),
        }
    }

    /// Back to an image (the quilt reads the coarsest level as one).
    pub fn image(&self) -> Image {
        Image { width: self.width, height: self.height, data: self.data.iter().map(|p| [p[0], p[1], p[2]]).collect() }
    }

    /// The continuation of a neighbour at offset (dx, dy) that copies `pos`: the position
    /// (dx, dy) before it, where that lies in the plane and may be copied.
    pub fn continuation(&self, pos: u32, dx: isize, dy: isize) -> Option<u32> {
        let (x, y) = self.xy(pos);
        let (cx, cy) = (x - dx, y - dy);
        let inside = (0..self.width as isize).contains(&cx) && (0..self.height as isize).contains(&cy);
        let c = inside.then(|| (cy as usize * self.width + cx as usize) as u32)?;
        self.allows(c).then_some(c)
    }

    /// (x, y) of position `pos`.
    #[inline(always)]
    pub fn xy(&self, pos: u32) -> (isize, isize) {
        let (x, y) = self.columns.split(pos);
        (x as isize, y as isize)
    }

    /// The pixel at (x, y) with coordinates clamped to the plane.
    #[inline]
    pub fn clamped(&self, x: isize, y: isize) -> &Px {
        let x = x.clamp(0, self.width as isize - 1) as usize;
        let y = y.clamp(0, self.height as isize - 1) as usize;
        &self.data[y * self.width + x]
    }
}

/// One exemplar prepared for matching: its pyramid, and each level's parent read at
/// that level's pixels (`upsampled`).
pub(crate) struct Exemplar {
    pub levels: Vec<Plane>,
    /// `upsampled[l]`: level `l + 1` at the positions of level `l`'s pixels.
    pub upsampled: Vec<Plane>,
}

impl Exemplar {
    /// `img`'s pyramid. `allowed` (one flag per pixel) keeps positions out of copying:
    /// their colours are first filled from around them (`mask::fill`), so that coarser
    /// levels do not carry them, and each level's allowed positions are eroded from the
    /// finer one's (`mask::pyramid`). `guide`: a grey image of `img`'s size and its
    /// lane's scale (see `Guide`). `alpha`: the pixels' alpha where it varies, and how
    /// they carry it (`opacity`; in the fourth lane, filled by the mask as the colours
    /// are, or in the colours where a guide holds the lane). `kept_out` begins the
    /// message when no allowed position is left ("The sample mask leaves", "The mask
    /// leaves").
    pub fn new(
        img: &Image,
        levels: usize,
        allowed: Option<&[bool]>,
        guide: Option<(&Image, f32)>,
        alpha: Option<(&[u8], Opacity)>,
        kept_out: &str,
    ) -> Result<Exemplar> {
        let compared;
        let img = match alpha {
            Some((a, opacity)) => {
                compared = opacity.colours(img, a);
                &compared
            }
            None => img,
        };
        let filled;
        let img = match allowed {
            Some(a) => {
                filled = mask::fill(img, a);
                &filled
            }
            None => img,
        };
        let images = pyramid::build(img, levels, Edge::Clamp);
        let upsample = |w: &[Image]| pyramid::upsample(&w[1], w[0].width, w[0].height);
        let mut planes: Vec<Plane> = images.iter().map(Plane::new).collect();
        let mut upsampled: Vec<Plane> = images.windows(2).map(|w| Plane::new(&upsample(w))).collect();
        let alpha_lane = match alpha {
            Some((a, Opacity::Lane)) => {
                let grey = opacity::grey(a, img.width, img.height);
                Some(match allowed {
                    Some(m) => mask::fill(&grey, m),
                    None => grey,
                })
            }
            _ => None,
        };
        if let Some((grey, scale)) = guide.or(alpha_lane.as_ref().map(|g| (g, opacity::ALPHA_LANE))) {
            let greys = pyramid::build(grey, levels, Edge::Clamp);
            planes.iter_mut().zip(&greys).for_each(|(p, g)| p.guide(g, scale));
            upsampled.iter_mut().zip(greys.windows(2)).for_each(|(p, w)| p.guide(&upsample(w), scale));
        }
        if let Some(a) = allowed {
            for (l, m) in mask::pyramid(a.to_vec(), img.width, img.height, levels, false).into_iter().enumerate() {
                let list: Vec<u32> = (0..m.len() as u32).filter(|&p| m[p as usize]).collect();
                if list.is_empty() {
                    // (Each coarser level reads blocks of the image: a level whose every
                    // block holds a masked pixel has nothing to copy.)
                    let what = if l == 0 {
                        "no pixel".to_string()
                    } else {
                        format!("no unmasked patch of {0}x{0} pixels", 1 << l)
                    };
                    return invalid(format!("{kept_out} {what} to copy from: keep more of the image."));
                }
                planes[l].allowed = Some(Allowed { mask: m, list });
            }
        }
        Ok(Exemplar { levels: planes, upsampled })
    }
}

/// Pixel offsets of a shape turned into index deltas for one image width: the own
/// level's, and the parent's in the upsampled parent (two pixels per parent pixel).
pub(crate) struct Offsets {
    own: Vec<isize>,
    parent_points: Vec<(isize, isize)>,
    parent: Vec<isize>,
}

impl Offsets {
    pub fn new(shape: &Shape, width: usize) -> Offsets {
        let parent_points: Vec<_> = shape.parent.iter().map(|&(dx, dy)| (2 * dx, 2 * dy)).collect();
        Offsets {
            own: shape.own.iter().map(|&(dx, dy)| dy * width as isize + dx).collect(),
            parent: parent_points.iter().map(|&(dx, dy)| dy * width as isize + dx).collect(),
            parent_points,
        }
    }
}

/// Weight of the parent level's squared differences. Its 3x3 block carries the
/// large-scale structure against 12 (causal) or 24 (full) pixels of the own level;
/// measured on the four exemplar photographs, 3 lowers the patch energy of every one
/// (e.g. gravel 12.2 -> 11.0, brick 4.3 -> 3.7) against equal weights.
const PARENT_WEIGHT: f32 = 3.0;

/// Squared distance between `feature` (one pixel per point of `shape`, own level first)
/// and the neighbourhood of exemplar position `pos` at `level`, stopping once the own
/// level's part exceeds `bound`.
#[inline]
pub(crate) fn distance(
    ex: &Exemplar,
    level: usize,
    pos: u32,
    shape: &Shape,
    off: &Offsets,
    feature: &[Px],
    bound: f32,
) -> f32 {
    let img = &ex.levels[level];
    let (x, y) = img.xy(pos);
    let mut own = Sum::zero();
    let k = block(img, x, y, shape.half, &shape.own, &off.own, feature, bound, &mut own);
    let own = own.total();
    if own > bound || k == feature.len() {
        return own;
    }
    let mut parent = Sum::zero();
    block(&ex.upsampled[level], x, y, 2, &off.parent_points, &off.parent, &feature[k..], f32::INFINITY, &mut parent);
    own + PARENT_WEIGHT * parent.total()
}

/// Points from which a neighbourhood's own level is summed in runs of `RUN`, each
/// followed by a look at the bound: most candidates (the random ones, those only a
/// neighbour or two propose) are past it within a few points. The sums and so the
/// matches are the same. A 5 x 5 neighbourhood was summed whole (12 or 24 points): in
/// runs of 6, 256 x 256 from 128 took 0.95 of the time in wasm (SIMD, -O3) and 0.96
/// natively; an 11 x 11 one (a fill's and a mend's coarser levels, 120 points) summed
/// whole took 8% longer than in runs of 16.
const RUNS_FROM: usize = 12;
const RUN: usize = 6;

/// Adds to `acc` the squared differences between the pixels of `img` at `points` around
/// (x, y) and `feature`'s first pixels; returns how many it was given (it may stop
/// early once `acc` is past `bound`, `RUNS_FROM`). Index deltas `linear` serve when
/// the block lies inside the image (within `half` of the centre), clamped reads at the
/// border.
#[allow(clippy::too_many_arguments)]
#[inline(always)]
fn block(
    img: &Plane,
    x: isize,
    y: isize,
    half: isize,
    points: &[(isize, isize)],
    linear: &[isize],
    feature: &[Px],
    bound: f32,
    acc: &mut Sum,
) -> usize {
    let feature = &feature[..points.len()];
    if points.len() < RUNS_FROM {
        add_points(img, x, y, half, points, linear, feature, acc);
        return points.len();
    }
    for (start, f) in (0..points.len()).step_by(RUN).zip(feature.chunks(RUN)) {
        let end = start + f.len();
        add_points(img, x, y, half, &points[start..end], &linear[start..end], f, acc);
        if acc.total() > bound {
            break;
        }
    }
    points.len()
}

/// `block`'s sum over all of `points`.
#[allow(clippy::too_many_arguments)]
#[inline(always)]
fn add_points(
    img: &Plane,
    x: isize,
    y: isize,
    half: isize,
    points: &[(isize, isize)],
    linear: &[isize],
    feature: &[Px],
    acc: &mut Sum,
) {
    let (w, h) = (img.width as isize, img.height as isize);
    if x >= half && x < w - half && y >= half && y < h - half {
        let base = y * w + x;
        for (&o, f) in linear.iter().zip(feature) {
            let i = (base + o) as usize;
            debug_assert!(i < img.data.len());
            // SAFETY: (x, y) lies at least `half` inside the plane and every offset in
            // `linear` reaches at most `half` pixels in x and in y (`Offsets::new` made
            // them from the shape), so `i` is a pixel of the plane. The bounds check cost
            // a tenth of the distance in wasm, which cannot drop it by itself.
            acc.add(unsafe { img.data.get_unchecked(i) }, f);
        }
    } else {
        for (&(dx, dy), f) in points.iter().zip(feature) {
            acc.add(img.clamped(x + dx, y + dy), f);
        }
    }
}
