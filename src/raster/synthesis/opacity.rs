//! Opacity in the candidate distance (issue 30). Matched on colour alone, a fill copied
//! each pixel's alpha with it from anywhere: patches of another opacity in a photograph
//! with an alpha gradient, and an icon's transparent black matched as the dark of its
//! drawing. So where an exemplar's alpha varies, it is compared too:
//!
//! - Without a guide, alpha goes in the fourth lane, scaled by `ALPHA_LANE`, and the
//!   colours stay as they are, except that a fully transparent pixel's colour, which
//!   means nothing (often black, sometimes anything), counts as black: transparent
//!   pixels match one another whatever colour they hold, and an opaque one by its
//!   colour and its opacity. (Premultiplied colours instead weigh a faint texture's
//!   colours faintly: six Debian photographs given an alpha gradient or a vignette, a
//!   30% square hole, seeds 1-3, had their fills' colours at a patch energy of 7.66
//!   against 7.24 so, their alpha off by 3.5 levels against 4.8; unmatched, alpha was
//!   off by 41.)
//! - A guide keeps the fourth lane (it says where the output should be what): alpha
//!   then enters by premultiplying the colours, as the pixels show over black.
//!
//! The output's neighbourhoods are read through its source map from the same planes,
//! so a copied or pinned pixel carries the lane as its exemplar pixel does, at every
//! level; a target given as RGBA (`Job::rematch`) is put in lanes by `pixel`, the same
//! rule.

use super::lanes::Px;
use crate::raster::image::Image;

/// The alpha lane's scale: alpha's squared difference counts as the same difference in
/// all three colour channels. An opacity step of `d` levels moves a pixel composited
/// over a background by `d / 255` of the colour's distance from that background in
/// each channel, so by up to `d` in all three at once. And so a transparent pixel is
/// never nearer an opaque one than black is to white (`3 x 255²`). At 1 (one channel's
/// weight) transparency is a cheaper stand-in than a far colour: six Adwaita icons with
/// a hole across their edge had 3,546 opaque pixels filled where their background was
/// (4,325 at 0.5), against 2,315 so. (It is the scale of a guide of weight 1,
/// `Guide::scale`.)
pub(crate) const ALPHA_LANE: f32 = 1.732_050_8;

/// How an exemplar's pixels carry its opacity (see the module).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Opacity {
    /// Colours as they are, the fourth lane 0 or a guide's: opaque images, and images
    /// whose alpha is the same everywhere.
    Ignored,
    /// Colours premultiplied; the fourth lane holds a guide.
    Premultiplied,
    /// Alpha in the fourth lane; a transparent pixel's colour black.
    Lane,
}

impl Opacity {
    /// What varying alpha (`alpha`) and a guide leave for the lanes.
    pub fn of(alpha: bool, guide: bool) -> Opacity {
        match (alpha, guide) {
            (false, _) => Opacity::Ignored,
            (true, true) => Opacity::Premultiplied,
            (true, false) => Opacity::Lane,
        }
    }

    /// Colour `c` of a pixel of alpha `a` (0-255) as it is compared.
    #[inline]
    fn colour(self, c: [f32; 3], a: f32) -> [f32; 3] {
        match self {
            Opacity::Ignored => c,
            Opacity::Premultiplied => c.map(|v| v * (a / 255.0)),
            Opacity::Lane if a == 0.0 => [0.0; 3],
            Opacity::Lane => c,
        }
    }

    /// The colour shown for a pixel whose compared colour is `c` and alpha `a`: the
    /// premultiplication undone (a transparent pixel black).
    #[inline]
    pub fn shown(self, c: [f32; 3], a: f32) -> [f32; 3] {
        match self {
            Opacity::Premultiplied if a > 0.0 => c.map(|v| v * (255.0 / a)),
            _ => c,
        }
    }

    /// An RGBA pixel (0-255 each) as the planes hold it, the fourth lane 0 unless alpha
    /// goes there (a guide's lane is the caller's).
    #[inline]
    pub fn pixel(self, p: [f32; 4]) -> Px {
        let [r, g, b] = self.colour([p[0], p[1], p[2]], p[3]);
        [r, g, b, if self == Opacity::Lane { ALPHA_LANE * p[3] } else { 0.0 }]
    }

    /// `img`'s colours as they are compared, `alpha` holding its pixels' alpha.
    pub fn colours(self, img: &Image, alpha: &[u8]) -> Image {
        let data = img.data.iter().zip(alpha).map(|(&c, &a)| self.colour(c, a as f32)).collect();
        Image { width: img.width, height: img.height, data }
    }
}

/// `alpha` as a grey image of `width x height` (in all three channels, as guides are),
/// to build its pyramid.
pub(crate) fn grey(alpha: &[u8], width: usize, height: usize) -> Image {
    Image { width, height, data: alpha.iter().map(|&a| [a as f32; 3]).collect() }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::raster::synthesis::{Constraints, Guide, Job, Params, Sources};

    /// A 32 x 32 picture and its alpha, which rises across it and is 0 in a corner.
    fn picture() -> (Image, Vec<u8>) {
        let data = (0..1024).map(|i| [(i * 7 % 256) as f32, (i * 13 % 256) as f32, 90.0]).collect();
        let alpha = (0..1024).map(|i| if i % 32 < 4 && i / 32 < 4 { 0 } else { (60 + 4 * (i % 32)) as u8 }).collect();
        (Image { width: 32, height: 32, data }, alpha)
    }

    fn params(constraints: Constraints) -> Params {
        Params { width: 32, height: 32, levels: Some(2), constraints, ..Params::default() }
    }

    #[test]
    fn a_transparent_pixel_shows_no_colour_and_alpha_weighs_as_three_channels() {
        let lane = Opacity::of(true, false);
        // Transparent black and transparent white are the same pixel.
        assert_eq!(lane.pixel([0.0, 0.0, 0.0, 0.0]), lane.pixel([255.0, 255.0, 255.0, 0.0]));
        // A step of 10 in alpha counts as 10 in each of three channels.
        let (a, b) = (lane.pixel([0.0, 0.0, 0.0, 100.0]), lane.pixel([0.0, 0.0, 0.0, 110.0]));
        assert!(((a[3] - b[3]).powi(2) - 300.0).abs() < 1e-2);
        // Transparent is as far from opaque black as black from white.
        let d = |p: Px, q: Px| (0..4).map(|c| (p[c] - q[c]).powi(2)).sum::<f32>();
        let black = lane.pixel([0.0, 0.0, 0.0, 255.0]);
        assert!((d(lane.pixel([9.0, 9.0, 9.0, 0.0]), black) - 3.0 * 255f32.powi(2)).abs() < 1.0);
        // Seen pixels keep their colours; without varying alpha nothing changes.
        assert_eq!(lane.pixel([10.0, 20.0, 30.0, 1.0])[..3], [10.0, 20.0, 30.0]);
        assert_eq!(Opacity::of(false, false).pixel([10.0, 20.0, 30.0, 7.0]), [10.0, 20.0, 30.0, 0.0]);
        // With a guide, alpha is in the colours only.
        assert_eq!(Opacity::of(true, true).pixel([100.0, 50.0, 0.0, 127.5]), [50.0, 25.0, 0.0, 0.0]);
    }

    #[test]
    fn known_pixels_carry_alpha_as_the_exemplar_does() {
        // A fill: the output reads its known pixels through the exemplar's planes, and a
        // target given as RGBA is put in lanes by `pixel`; both must agree.
        let (img, alpha) = picture();
        let hole = |i: usize| (12..20).contains(&(i % 32)) && (12..20).contains(&(i / 32));
        let known: Vec<bool> = (0..1024).map(|i| !hole(i)).collect();
        let c = Constraints {
            allowed: vec![Some(known.clone())],
            known: Some(known.clone()),
            alphas: vec![Some(alpha.clone())],
            ..Constraints::default()
        };
        let job = Job::new(Sources::One(&img), &params(c)).expect("a fill's job");
        assert_eq!(job.opacity, Opacity::Lane);
        for i in (0..1024).filter(|&i| known[i]) {
            let [r, g, b] = img.data[i];
            assert_eq!(job.plane(0, 0).data[i], job.opacity.pixel([r, g, b, alpha[i] as f32]), "pixel {i}");
        }
        // The coarser level holds alpha too, from the known pixels only (the hole's own
        // alpha, 0 here, filled from around it as its colours are).
        let mut holed = alpha.clone();
        (0..1024).filter(|&i| hole(i)).for_each(|i| holed[i] = 0);
        let c = Constraints { allowed: vec![Some(known.clone())], alphas: vec![Some(holed)], ..Constraints::default() };
        let job = Job::new(Sources::One(&img), &params(c)).expect("a job");
        let coarse = job.plane(0, 1);
        let centre = coarse.data[8 * 16 + 8][3] / ALPHA_LANE;
        assert!((100.0..150.0).contains(&centre), "alpha {centre} at the hole's centre, one level up");
    }

    #[test]
    fn a_guide_keeps_the_fourth_lane_and_alpha_goes_into_the_colours() {
        let (img, alpha) = picture();
        let grey = Image { width: 32, height: 32, data: (0..1024).map(|i| [(i % 32 * 8) as f32; 3]).collect() };
        let guide = Guide { exemplar: grey.clone(), target: grey.clone(), weight: 1.0 };
        let scale = guide.scale();
        let c = Constraints { guide: Some(guide), alphas: vec![Some(alpha.clone())], ..Constraints::default() };
        let job = Job::new(Sources::One(&img), &params(c)).expect("a guided job");
        assert_eq!(job.opacity, Opacity::Premultiplied);
        for (i, p) in job.plane(0, 0).data.iter().enumerate() {
            let a = alpha[i] as f32 / 255.0;
            assert_eq!(p[..3], img.data[i].map(|v| v * a), "pixel {i}");
            assert_eq!(p[3], scale * grey.data[i][0], "pixel {i}");
        }
        // Alpha the same everywhere (an opaque image) changes nothing.
        let c = Constraints { alphas: vec![Some(vec![255; 1024])], ..Constraints::default() };
        let job = Job::new(Sources::One(&img), &params(c)).expect("a job");
        assert_eq!(job.opacity, Opacity::Ignored);
        let plain = Job::new(Sources::One(&img), &params(Constraints::default())).expect("a job");
        assert!(job.plane(0, 0).data == plain.plane(0, 0).data && job.plane(0, 1).data == plain.plane(0, 1).data);
    }
}
