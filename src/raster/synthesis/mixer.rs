//! How the exemplars mix: an output colour is read through each exemplar's source map
//! and mixed by the weight mu of exemplar A at that pixel (the paper's blending).

use super::exemplar::Exemplar;
use super::lanes::Px;

/// mu = 1 in the 16-bit map.
pub(crate) const MU_ONE: f32 = 65535.0;

/// The exemplars and how they mix: output colours are read through source maps.
pub(crate) struct Mixer {
    pub exs: Vec<Exemplar>,
    /// The weight of exemplar 0 per output pixel, 65535 = 1 (None: one exemplar).
    pub mu: Option<Vec<u16>>,
    /// Full output size.
    pub width: usize,
    pub height: usize,
}

impl Mixer {
    /// The weight of exemplar `e` at (x, y) of `level`: mu sampled at the pixel's
    /// footprint in the full output.
    #[inline(always)]
    pub fn weight(&self, e: usize, level: usize, x: usize, y: usize) -> f32 {
        match &self.mu {
            None => 1.0,
            Some(mu) => {
                let (fx, fy) = ((x << level).min(self.width - 1), (y << level).min(self.height - 1));
                let m = mu[fy * self.width + fx] as f32 / MU_ONE;
                if e == 0 {
                    m
                } else {
                    1.0 - m
                }
            }
        }
    }

    /// The output colour of pixel (x, y) of `level`, at index `i` of the source maps
    /// `src`: the sources' colours mixed by weight.
    #[inline(always)]
    pub fn colour(&self, level: usize, src: &[Vec<u32>], i: usize, x: usize, y: usize) -> Px {
        let read = |e: usize| self.exs[e].levels[level].data[src[e][i] as usize];
        if self.mu.is_none() {
            return read(0);
        }
        let m = self.weight(0, level, x, y);
        if m >= 1.0 {
            read(0)
        } else if m <= 0.0 {
            read(1)
        } else {
            let (a, b) = (read(0), read(1));
            [0, 1, 2, 3].map(|c| m * a[c] + (1.0 - m) * b[c])
        }
    }
}
