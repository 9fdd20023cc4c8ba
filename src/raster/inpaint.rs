//! Filling where a mask says, from the rest of the image: `inpaint_texture` (a hole),
//! and the known-pixel synthesis it shares with mending a tile's wrap
//! (`seamless::mend`). See `synthesis::pinned` for how the fill is searched.

use super::image::{Image, Rgba};
use super::synthesis::{self, Constraints, Finest, Job, Params, Sources, REMATCH_ROUNDS};
use crate::error::{invalid, Result};
use crate::progress::{Progress, Throttle};
use crate::rng::Rng;
use serde::Deserialize;

/// Options of `inpaint_texture`.
#[derive(Clone, Debug, Deserialize)]
#[serde(rename_all = "camelCase", default, deny_unknown_fields)]
pub struct InpaintOptions {
    pub seed: u64,
    pub levels: Option<usize>,
    pub neighbourhood: usize,
    /// Pixels that may not be copied into the hole (the JS `sampleMask`, read by the
    /// wasm layer): `true` where a pixel may be copied.
    #[serde(skip)]
    pub sample_mask: Option<Vec<bool>>,
}

/// The fill's neighbourhood side by default, wider than synthesis's 5: a hole is matched
/// to more of the photograph round it. On eight photographs from Debian's game texture
/// packages (extremetuxracer, openarena) with holes of 8-11% (seeds 1-3,
/// examples/inpaint_edge), 11 against 5 took the fill's median patch energy from 12.11
/// to 10.35 and the step at its edge from 1.14 to 1.08 of the steps around it (9: 10.67
/// and 1.12).
pub const FILL_NEIGHBOURHOOD: usize = 11;

/// The fill's finest level is matched with 5 x 5 neighbourhoods (`Params::detail_levels`):
/// the wide side places the structure at the coarser levels. On the same eight
/// photographs (examples/inpaint_edge, seeds 1-3) the fill's median patch energy fell
/// from 11.06 to 9.35 and its edge step from 1.08 to 1.06, in about two thirds of the
/// time; with the two finest levels so, 10.15 and 1.09.
pub const FILL_DETAIL_LEVELS: usize = 1;

/// The share of the colour step left at a fill's edge that its last heal takes away,
/// once the fill has been matched again to healed colours (`synthesis::REMATCH_ROUNDS`).
/// Healed whole, the edge came out smoother than the photograph (twelve photographs,
/// holes of 8.5-10.5%, seeds 1-5, examples/inpaint_edge: the step across it 0.95 times the steps
/// around, the photograph's own content 0.96) and the fill's patch energy was 6.88;
/// at 0.75, 0.99 and 6.68; at 0.5, 1.05 and 6.47 (texture-synthesis 0.8.3: 1.32 and
/// 7.61). The same four photographs lit by a ramp from 45% to 135% across, filled where
/// they are brightest: 0.88, 0.91 and 0.96 against their own 0.79-1.04.
pub const LAST_HEAL: f32 = 0.5;

impl Default for InpaintOptions {
    fn default() -> Self {
        let p = Params::default();
        InpaintOptions { seed: p.seed, levels: None, neighbourhood: FILL_NEIGHBOURHOOD, sample_mask: None }
    }
}

/// `image` with the pixels where `mask` is true filled from the rest of it; every other
/// pixel is returned as it was, byte for byte (alpha too), and a filled pixel is a copy
/// of the image pixel it was matched to, healed into the hole's border (`heal`: colour,
/// and opacity where the image's varies).
pub fn inpaint_texture(
    image: &Rgba,
    mask: &[bool],
    opts: &InpaintOptions,
    progress: &mut dyn Progress,
) -> Result<Rgba> {
    if mask.len() != image.width * image.height {
        return invalid(format!(
            "The mask has {} pixels; the image is {}x{} ({} pixels).",
            mask.len(),
            image.width,
            image.height,
            image.width * image.height
        ));
    }
    if let Some(s) = &opts.sample_mask {
        if s.len() != mask.len() {
            return invalid("The sample mask is not of the image's size.");
        }
    }
    if image.width.min(image.height) < 3 {
        return invalid(format!(
            "The image is {}x{}; a fill needs at least 3 pixels on a side.",
            image.width, image.height
        ));
    }
    let known: Vec<bool> = mask.iter().map(|&m| !m).collect();
    if !known.iter().any(|&k| k) {
        return invalid("The mask covers the whole image: nothing is left to fill it from.");
    }
    let allowed: Vec<bool> =
        known.iter().enumerate().map(|(i, &k)| k && opts.sample_mask.as_ref().is_none_or(|s| s[i])).collect();
    if !allowed.iter().any(|&a| a) {
        return invalid("The mask and the sample mask together leave no pixel to fill from.");
    }
    let fill = Fill {
        known,
        allowed: Some(allowed),
        torus: false,
        seed: opts.seed,
        levels: opts.levels,
        coarsest: None,
        neighbourhood: opts.neighbourhood,
        detail_levels: FILL_DETAIL_LEVELS,
        rematch: true,
        kept_out: if opts.sample_mask.is_some() { "The mask and the sample mask leave" } else { "The mask leaves" },
    };
    fill.run(image, progress)
}

/// A synthesis that keeps `known` pixels of an image and fills the others from it.
pub struct Fill {
    pub known: Vec<bool>,
    /// Pixels that may be copied (`None`: all).
    pub allowed: Option<Vec<bool>>,
    /// Read the image on a torus (mending a tile's wrap).
    pub torus: bool,
    pub seed: u64,
    pub levels: Option<usize>,
    /// Without `levels`, the short side the coarsest exemplar level aims at
    /// (`synthesis::default_levels`), or `None` for the job's own aim
    /// (`synthesis::coarsest_side`).
    pub coarsest: Option<f64>,
    pub neighbourhood: usize,
    /// The finest levels matched with 5 x 5 neighbourhoods (`Params::detail_levels`).
    pub detail_levels: usize,
    /// Match the fill again to its healed colours (`synthesis::REMATCH_ROUNDS`) and heal
    /// it last by `LAST_HEAL`; otherwise heal it once, whole. A mended tile's band is
    /// too wide for it: mending took 2.6-3.1 times a plain synthesis of its size so
    /// (bench/verbs.mjs, 256², SIMD) against 1.2-1.3 without, and its wrap, in the
    /// middle of the band, scored the same (within 0.05 on twelve photographs).
    pub rematch: bool,
    /// What keeps pixels out of copying, for the message when none is left (a fill
    /// copies whole neighbourhoods: a hole that leaves a strip of one pixel leaves none).
    pub kept_out: &'static str,
}

/// The neighbourhood side a fill uses on an image whose short side is `short`: `side`,
/// or on a small image the largest odd side that leaves at least four positions a row
/// and a column to copy from (at least 3). A 10-pixel image was refused as "smaller
/// than the 11x11 neighbourhood", which a fill's user never chose: mending promises 8
/// pixels a side, and did so with 5 x 5.
fn fitted_side(side: usize, short: usize) -> usize {
    let most = short.saturating_sub(3);
    let odd = if most % 2 == 1 { most } else { most.saturating_sub(1) };
    side.min(odd).max(3)
}

/// A fill's copies before they are healed, its finest level's last pass not yet made
/// (`Fill::copies`): a mend measures them before it makes its band again or finishes it.
pub struct Copies {
    /// The synthesis, until it is made again from it (`again`), and its copies so far;
    /// `None` when every pixel is known.
    job: Option<Job>,
    finest: Option<Finest>,
    known: Vec<bool>,
    torus: bool,
}

impl Copies {
    /// Each pixel's source in the image: itself where it is known.
    fn src(&self) -> Vec<u32> {
        match &self.finest {
            Some(finest) => finest.src().to_vec(),
            None => (0..self.known.len() as u32).collect(),
        }
    }

    /// The image with each filled pixel its copy, as it is.
    pub fn colours(&self, image: &Rgba) -> Rgba {
        let data = self.src().iter().flat_map(|&s| image.data[4 * s as usize..][..4].iter().copied()).collect();
        Rgba { width: image.width, height: image.height, data }
    }

    /// The finest level's last pass (`synthesis::Finest::last_pass`); none once the fill
    /// has been made again (`again`).
    pub fn finish(&mut self, progress: &mut dyn Progress) -> Result<()> {
        match (&self.job, &mut self.finest) {
            (Some(job), Some(finest)) => finest.last_pass(job, &mut Throttle::new(progress)),
            _ => Ok(()),
        }
    }

    /// The fill made again from a coarsest level nearest `coarsest` pixels on its short
    /// side (as `Fill::coarsest`) of the same pyramids, these copies kept as they are.
    pub fn again(&mut self, image: &Rgba, coarsest: f64, progress: &mut dyn Progress) -> Result<Copies> {
        let mut job = self.job.take();
        let finest = match &mut job {
            Some(job) => {
                let short = image.width.min(image.height);
                job.keep_finest(synthesis::levels_for(short, short, job.params().neighbourhood, coarsest));
                Some(synthesis::begin_pinned(job, &mut Throttle::new(progress))?)
            }
            None => None,
        };
        Ok(Copies { job, finest, known: self.known.clone(), torus: self.torus })
    }

    /// The copies healed into the known pixels, whole (`heal`).
    pub fn healed(&self, image: &Rgba) -> Rgba {
        let mut out = image.clone();
        super::heal::heal(&mut out, image, &self.src(), &self.known, self.torus, 1.0);
        out
    }
}

impl Fill {
    /// The synthesis prepared, or `None` when every pixel is known.
    fn job(&self, image: &Rgba) -> Result<Option<Job>> {
        if self.known.iter().all(|&k| k) {
            return Ok(None);
        }
        let img = Image::from_rgba8(image.width, image.height, &image.data)?;
        // Positions whose neighbourhood runs off the image are not copied: read clamped
        // there, an edge column matches a flat neighbourhood, and a band along the wrap
        // filled from such columns came out as streaks (brick's mended wrap: boundaries
        // 0.2 times the mean difference, then a step of 2.5 where the streaks met the
        // photograph).
        let (w, h) = (image.width, image.height);
        let side = fitted_side(self.neighbourhood, w.min(h));
        let half = side / 2;
        let inside = |i: usize| {
            let (x, y) = (i % w, i / w);
            x >= half && y >= half && x + half < w && y + half < h
        };
        let allowed: Vec<bool> = (0..w * h).map(|i| inside(i) && self.allowed.as_ref().is_none_or(|a| a[i])).collect();
        let params = Params {
            width: image.width,
            height: image.height,
            seed: self.seed,
            levels: self.levels.or_else(|| self.coarsest.map(|c| synthesis::default_levels(&[&img], w, h, side, c))),
            neighbourhood: side,
            detail_levels: self.detail_levels,
            tileable: self.torus,
            constraints: Constraints {
                allowed: vec![Some(allowed)],
                known: Some(self.known.clone()),
                guide: None,
                // Where the image's opacity varies, it is matched too (`synthesis::opacity`).
                alphas: vec![image.alpha_varies().then(|| image.alpha())],
                kept_out: Some(self.kept_out),
            },
            ..Params::default()
        };
        Job::new(Sources::One(&img), &params).map(Some)
    }

    /// The fill's copies, not yet healed nor finished (`Copies`).
    pub fn copies(self, image: &Rgba, progress: &mut dyn Progress) -> Result<Copies> {
        let job = self.job(image)?;
        let finest = match &job {
            Some(job) => Some(synthesis::begin_pinned(job, &mut Throttle::new(progress))?),
            None => None,
        };
        Ok(Copies { job, finest, known: self.known, torus: self.torus })
    }

    pub fn run(self, image: &Rgba, progress: &mut dyn Progress) -> Result<Rgba> {
        let mut out = image.clone();
        let Some(job) = self.job(image)? else {
            progress.report(1.0);
            return Ok(out);
        };
        let mut src = synthesis::sources(&job, &mut Throttle::new(progress))?;
        // The copies keep their detail; a smooth correction takes away the colour step
        // at the hole's edge (`heal`). Matched again to the healed colours, the copies
        // need less of it (`synthesis::REMATCH_ROUNDS`), and the last heal takes half
        // the step that is left (`LAST_HEAL`).
        let mut rng = Rng::new(self.seed ^ 0x4EA1_3A7C);
        let rounds = if self.rematch { REMATCH_ROUNDS } else { 0 };
        for round in 0..=rounds {
            let last = round == rounds;
            let strength = if last && self.rematch { LAST_HEAL } else { 1.0 };
            super::heal::heal(&mut out, image, &src[0], &self.known, self.torus, strength);
            if !last {
                job.rematch(&mut src[0], &out, &mut rng);
            }
        }
        Ok(out)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Silent;

    #[test]
    fn a_small_image_is_filled_with_the_neighbourhood_it_allows() {
        assert_eq!([8, 10, 13, 14, 40].map(|short| fitted_side(11, short)), [5, 7, 9, 11, 11]);
        assert_eq!(fitted_side(5, 40), 5);
        assert_eq!(fitted_side(11, 2), 3);
        // A 10 x 10 picture with a 2 x 2 hole, by default (11): filled, the rest kept.
        let data: Vec<u8> = (0..100).flat_map(|i| [(i * 7 % 256) as u8, (i * 13 % 256) as u8, 90, 255]).collect();
        let image = Rgba { width: 10, height: 10, data };
        let hole: Vec<bool> = (0..100).map(|i| (4..6).contains(&(i % 10)) && (4..6).contains(&(i / 10))).collect();
        let out = inpaint_texture(&image, &hole, &InpaintOptions::default(), &mut Silent).expect("a small fill");
        for i in (0..100).filter(|&i| !hole[i]) {
            assert_eq!(out.data[4 * i..4 * i + 4], image.data[4 * i..4 * i + 4]);
        }
    }

    #[test]
    fn a_fill_says_what_leaves_it_nothing_to_copy() {
        let picture = |w: usize, h: usize| Rgba {
            width: w,
            height: h,
            data: (0..w * h).flat_map(|i| [(i * 7 % 256) as u8, (i * 13 % 256) as u8, 90, 255]).collect(),
        };
        let fill = |img: &Rgba, hole: &dyn Fn(usize, usize) -> bool, sample: Option<Vec<bool>>| {
            let mask: Vec<bool> = (0..img.width * img.height).map(|i| hole(i % img.width, i / img.width)).collect();
            let opts = InpaintOptions { sample_mask: sample, ..Default::default() };
            inpaint_texture(img, &mask, &opts, &mut Silent).unwrap_err().to_string()
        };
        // A hole that leaves one pixel: the mask is why (no sample mask was given).
        let all_but_one = fill(&picture(64, 64), &|x, y| (x, y) != (5, 5), None);
        assert!(all_but_one.starts_with("The mask leaves no"), "{all_but_one}");
        let centre = fill(&picture(3, 3), &|x, y| (x, y) == (1, 1), None);
        assert!(centre.starts_with("The mask leaves no pixel"), "{centre}");
        // With a sample mask that keeps a corner only, both.
        let corner: Vec<bool> = (0..64 * 64).map(|i| i % 64 < 2 && i / 64 < 2).collect();
        let both = fill(&picture(64, 64), &|x, _| x > 40, Some(corner));
        assert!(both.starts_with("The mask and the sample mask leave no"), "{both}");
        let thin = fill(&picture(1, 40), &|_, y| y == 5, None);
        assert_eq!(thin, "The image is 1x40; a fill needs at least 3 pixels on a side.");
    }
}
