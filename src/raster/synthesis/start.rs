//! How the coarsest level starts when it is not grown from noise: a quilt of exemplar
//! windows (laid round the torus for a tile, `TILE_QUILT`; as a target guide asks,
//! `GUIDED_QUILT`), a picture's layout, or the onion around known pixels.

use super::exemplar::{distance, Exemplar, Offsets};
use super::lanes::Px;
use super::Job;
use crate::raster::guide::luma;
use crate::raster::image::torus_index;
use crate::raster::quilt::{Quilt, QuiltGuide};
use crate::rng::Rng;

/// A guided quilt's window side and the weight of its guide term (`quilt::QuiltGuide`).
/// The quilt lays the large structure and the coherent passes keep to it, so a guided
/// output follows its target as far as the quilt does. Measured on eight Debian
/// photographs of 224 pixels guided by a disc (examples/guided_probe, 256², seeds 1-3,
/// medians of 24 runs): the luminance's correlation with the disc was 0.81 with the
/// plain quilt's 16-pixel windows, and with the guide at 4 (or 16) 0.83 at 8 pixels,
/// 0.85 at 4 (0.86 with the guide at 16); searching the coarsest level exhaustively
/// instead (as before the quilt knew the guide) gave 0.85 at about twice the time.
/// Every origin is tried up to 1,024 (a 28-pixel coarsest level has 625).
const GUIDED_QUILT: Quilt = Quilt { side: 4, candidates: 1024, spread: 0.0 };
const GUIDED_QUILT_WEIGHT: f32 = 4.0;

/// How the coarsest level starts when it is not grown from noise.
pub(super) enum Start {
    /// A quilt of exemplar windows.
    Quilt(Quilt),
    /// A picture's layout: each pixel takes the exemplar position whose neighbourhood
    /// (centre included) best matches the picture's there, at the coarsest level, read
    /// on the torus. The picture's own colours are never copied.
    Layout(Vec<Px>),
    /// A tile's picture (refined E-TFMCM's field), followed by a quilt round the torus
    /// (`FIELD_QUILT`).
    FieldQuilt(Vec<Px>),
    /// Known pixels kept, the others filled from the edge of the known region inwards
    /// (`onion`).
    Onion,
}

impl Job {
    /// Whether `level` starts from a map made whole (`starts`) and so needs no causal
    /// pass: the coarsest level, when it starts from a picture's layout, or when its
    /// exemplars are large enough to quilt (a tile's round the torus, `TILE_QUILT`).
    pub(crate) fn started(&self, level: usize) -> bool {
        level + 1 == self.levels && self.start.is_some()
    }

    /// Whether the coarsest level starts from a quilt of exemplar windows.
    pub(crate) fn quilted(&self) -> bool {
        matches!(self.start, Some(Start::Quilt(_) | Start::FieldQuilt(_)))
    }

    /// The coarsest level's starting maps, one per exemplar (empty when it is not
    /// `started`): the same in both schedules, and made once per job, however many
    /// bands read them.
    pub(crate) fn starts(&self) -> &[Vec<u32>] {
        self.starts.get_or_init(|| {
            let level = self.levels - 1;
            let (lw, lh) = self.sizes[level];
            let exs = self.mix.exs.iter();
            match &self.start {
                None => Vec::new(),
                Some(Start::Quilt(quilt)) => exs
                    .enumerate()
                    .map(|(e, ex)| {
                        let mut rng = Rng::new(self.params.seed ^ (0x51 << 56) ^ e as u64);
                        let plane = &ex.levels[level];
                        // (A target guide lays the windows out as the target asks: see
                        // `GUIDED_QUILT`.)
                        let lane: Vec<f32>;
                        let (quilt, guide) = match &self.target {
                            Some(t) if self.params.constraints.guide.as_ref().is_some_and(|g| g.scale() > 0.0) => {
                                lane = plane.data.iter().map(|p| p[3]).collect();
                                let guide =
                                    QuiltGuide { exemplar: &lane, target: &t[level], weight: GUIDED_QUILT_WEIGHT };
                                (GUIDED_QUILT, Some(guide))
                            }
                            _ => (*quilt, None),
                        };
                        let mut map = quilt
                            .lay(&plane.image(), plane.allowed_mask(), guide, (lw, lh), self.params.tileable, &mut rng)
                            .expect("Job::new checked the window");
                        // Windows that still reach masked positions: those pixels start
                        // anywhere allowed, and the passes join them.
                        map.iter_mut().filter(|p| !plane.allows(**p)).for_each(|p| *p = plane.random(&mut rng));
                        map
                    })
                    .collect(),
                Some(Start::Layout(picture)) => exs.map(|ex| self.layout(ex, level, picture)).collect(),
                Some(Start::FieldQuilt(picture)) => exs
                    .enumerate()
                    .map(|(e, ex)| {
                        let mut rng = Rng::new(self.params.seed ^ (0x51 << 56) ^ e as u64);
                        field_quilt(ex, level, picture, (lw, lh), &mut rng).expect("Job::new checked the window")
                    })
                    .collect(),
                Some(Start::Onion) => vec![self.onion(level)],
            }
        })
    }

    /// For each pixel of `level` (`picture` at that level), the position of `ex` whose
    /// neighbourhood, centre included, is nearest the picture's (exhaustive: the
    /// coarsest level has a few hundred positions).
    fn layout(&self, ex: &Exemplar, level: usize, picture: &[Px]) -> Vec<u32> {
        let (lw, lh) = self.sizes[level];
        let mut shape = self.full.clone();
        shape.own.push((0, 0));
        shape.parent.clear();
        let off = Offsets::new(&shape, ex.levels[level].width);
        let mut feature = Vec::with_capacity(shape.own.len());
        let mut out = Vec::with_capacity(lw * lh);
        for y in 0..lh {
            for x in 0..lw {
                feature.clear();
                feature.extend(
                    shape.own.iter().map(|&(dx, dy)| picture[torus_index(x as isize + dx, y as isize + dy, lw, lh)]),
                );
                let mut best = (f32::INFINITY, 0u32);
                ex.levels[level].each_allowed(|pos| {
                    let d = distance(ex, level, pos, &shape, &off, &feature, best.0);
                    if d < best.0 {
                        best = (d, pos);
                    }
                });
                out.push(best.1);
            }
        }
        out
    }
}

/// How a tile that starts from a picture (refined E-TFMCM: its co-occurrence field) lays
/// its coarsest level: a quilt round the torus whose windows are chosen, besides their
/// fit and coverage (`TILE_QUILT`), by how near their luminance is to the picture's
/// where they are laid (`FIELD_WEIGHT` times its mean squared difference over twice the
/// exemplar's summed RGB variance, the fit's scale: so on a grey exemplar about a third
/// of a random window's fit, and less where the exemplar varies more in hue than in
/// light), among more origins than a plain tile's so that there are some that follow it.
///
/// Until this, each pixel took the exemplar position whose neighbourhood best matched
/// the picture's (`Job::layout`, still the start of an output too small to quilt). On
/// soft exemplars every smooth neighbourhood of one colour met its best match at the
/// same position, so the tile copied one region of the exemplar again and again: fire
/// and mist (`bench/heldout-data.sh`, 128, seeds 1-8) repeated at 0.19 against their
/// own 0.34 and 0.31, and a re-use penalty and colour balance in that search changed
/// nothing (0.190). The field's luminance is first matched rank for rank to the
/// exemplar's (`matched`): E-TFMCM's field drifts in tone (fire's to yellow, marble's
/// to its dark grey, without the veins), and followed as it was, the quilt drifted with
/// it (marble's colour distance 0.15-0.18 against the peer's 0.095).
///
/// Measured on the sixteen of `bench/heldout-data.sh`, tiles at 128, seeds 1-8, against
/// texture-synthesis 0.8.3's `--tiling` (`examples/tile_quality`, `METHOD="etfmcm
/// refined"`; origins and weight by `PATTERNSYNTH_FIELD`):
///
/// | start | energy <= peer's (<= 1.1x) | colour <= peer's | repetition >= own - 0.05 | seams 0.8-1.2 |
/// |---|---:|---:|---:|---:|
/// | the field's layout (before) | 16 (16) | 14 (marble 0.199, plaster 0.041) | 14 (fire, mist 0.19) | 16 |
/// | quilt, 16 origins, weight 1 | 16 (16) | 14 (marble 0.130, plaster) | 16 | 15 (brick 0.76) |
/// | **quilt, 32 origins, weight 2** | 15 (16; fire 0.75 against 0.74) | 15 (plaster 0.033 against 0.025) | 16 | 16 |
///
/// Fire's colour distance 0.267 -> 0.205 (the peer's 0.351), mist's 0.285 -> 0.243,
/// marble's 0.199 -> 0.089; median energy 0.87 of the peer's. The coarsest level is then
/// searched coherently, as a quilted tile's is (`Job::quilted`): searched exhaustively
/// (before the rank matching, seeds 1-4) fire and mist repeated more (0.278 and 0.265
/// against 0.321 and 0.279) and marble's colour was further off (0.166 against 0.145).
const FIELD_QUILT: Quilt = Quilt { side: 6, candidates: 32, spread: 3.0 };
const FIELD_WEIGHT: f32 = 2.0;

/// Whether a tile's picture is followed by a quilt (always, but for a probe's
/// `PATTERNSYNTH_FIELD=0`, which lays it out as before `FIELD_QUILT`).
pub(super) fn field_quilt_on() -> bool {
    !(cfg!(feature = "test-support") && std::env::var("PATTERNSYNTH_FIELD").is_ok_and(|v| v == "0"))
}

/// `FIELD_QUILT` and `FIELD_WEIGHT`, which probes may set through
/// `PATTERNSYNTH_FIELD=candidates,weight[,spread]`.
pub(super) fn field_params() -> (Quilt, f32) {
    #[cfg(feature = "test-support")]
    if let Ok(v) = std::env::var("PATTERNSYNTH_FIELD") {
        let n: Vec<f32> = v.split(',').filter_map(|s| s.parse().ok()).collect();
        if n.len() >= 2 {
            let spread = n.get(2).copied().unwrap_or(FIELD_QUILT.spread);
            return (Quilt { candidates: n[0] as usize, spread, ..FIELD_QUILT }, n[1]);
        }
    }
    (FIELD_QUILT, FIELD_WEIGHT)
}

/// `values` given the distribution of `to`, rank for rank (histogram matching): the
/// picture's arrangement of light and dark in the exemplar's own shares of them. Equal
/// values stay equal.
fn matched(values: Vec<f32>, to: &[f32]) -> Vec<f32> {
    if to.is_empty() {
        return values;
    }
    // (`order`'s sort: each closure given to `sort_by` is its own copy in the wasm.)
    let sorted: Vec<f32> = crate::order::sorted(to, |&v| v as f64);
    let rank = crate::order::by_key(&values.iter().map(|&v| v as f64).collect::<Vec<_>>());
    let mut out = vec![0.0; values.len()];
    // Equal values take the quantile of their run's middle rank: ranked one by one, a
    // flat region's target would run from dark at its top to light at its bottom.
    let mut start = 0;
    while start < rank.len() {
        let end = start + rank[start..].iter().take_while(|&&i| values[i] == values[rank[start]]).count();
        let middle = (start + end - 1) / 2;
        let value = sorted[(middle * sorted.len() + sorted.len() / 2) / values.len()];
        rank[start..end].iter().for_each(|&i| out[i] = value);
        start = end;
    }
    out
}

/// The coarsest level of exemplar `ex` quilted round the torus after `picture`
/// (`FIELD_QUILT`), or `None` when the level is too small to quilt.
fn field_quilt(ex: &Exemplar, level: usize, picture: &[Px], size: (usize, usize), rng: &mut Rng) -> Option<Vec<u32>> {
    let (quilt, weight) = field_params();
    let plane = &ex.levels[level];
    let image = plane.image();
    // (Luminance: the lane a picture guides a tile's quilt by.)
    let lane: Vec<f32> = image.data.iter().map(|p| luma(p)).collect();
    let target = matched(picture.iter().map(|p| luma(p)).collect(), &lane);
    let guide = QuiltGuide { exemplar: &lane, target: &target, weight };
    let mut map = quilt.lay(&image, plane.allowed_mask(), Some(guide), size, true, rng)?;
    // (As a plain tile's quilt.)
    map.iter_mut().filter(|p| !plane.allows(**p)).for_each(|p| *p = plane.random(rng));
    Some(map)
}

/// How a tile's quilt is laid: round the torus, with the coverage term (`Quilt::spread`)
/// and more origins to choose from, since the term now keeps the proportions that few
/// origins kept before, in windows of 6 pixels (at a 16-pixel coarsest level, where 16
/// would be cut to half the exemplar).
///
/// Tiles grew from noise until the coverage term. Quilted without it (four origins a
/// window, windows half the exemplar), tiles were lower in patch energy (the twelve
/// held-out photographs at 128 against texture-synthesis 0.8.3's `--tiling`, seeds 1-3:
/// median 0.84 of the peer's, from noise 1.00) but a tile about the exemplar's size
/// copied some of its regions two or three times and others never: colour further from
/// the photograph's than the peer's on 4 of 12 (marble 0.207 against 0.089), repetition
/// past the fixtures' own on 5 of 10 against 2 from noise (measured at 772de4b).
/// Measured with the term over seeds 1-8 (examples/tile_quality, the twelve; from noise:
/// energy at or below the peer's on 7, median 0.99; colour at most the peer's on 10;
/// repetition within 0.05 of the photograph's own on 11; seams in 0.8-1.2 on 11):
///
/// | window, origins, weight | energy | median | colour | repetition | seams |
/// |---|---|---|---|---|---|
/// | 8, 8, 2 | 11 | 0.82 | 11 | 11 | 12 |
/// | 8, 8, 3 | 12 | 0.83 | 10 | 10 | 12 |
/// | 8, 8, 4 | 11 | 0.86 | 12 | 11 | 12 |
/// | 8, 16, 3 | 12 | 0.85 | 11 | 12 | 11 |
/// | 8, 32, 6 | 11 | 0.86 | 11 | 10 | 11 |
/// | **6, 8, 3** | 11 | 0.89 | 11 | 12 | 11 |
/// | 6, 16, 3 | 11 | 0.86 | 11 | 12 | 11 |
/// | 4, 8, 3 | 11 | 0.88 | 10 | 12 | 12 |
///
/// Windows half the exemplar's side cover its middle twice as often as its edges,
/// however they are chosen (two ways into the middle for one into a corner): gravel's
/// 8-pixel tiles repeat their few dark pebbles (0.070 below the photograph's own), which
/// a 2 x 2 repeat shows at once. Sand, whose energy is the one above the peer's at 6
/// pixels (1.05), is there in every row (0.98-1.05; from noise 1.06). On the ten fixtures
/// (seeds 1-8, against noise) 6-pixel windows lower the energy on 8 (tissue 8.48 ->
/// 7.54, print 8.97 -> 8.87; coins 6.73 -> 7.10 and gravel's repetition 0.048 below its
/// own), and the wrap over seeds 1-32 (examples/seam_lines) reads print 1.18 (from noise
/// 1.12; 8-pixel windows 1.22, with 16 origins 1.25 and coins 1.17), brick 1.09, coins
/// 1.05. (Where the 8-pixel windows' wrap rose, it was not where the windows meet:
/// rolled at random before the passes, the same; nor mended by a wider band matched
/// again along the wrap, by finer levels started from their parent rather than noise,
/// or by an exhaustive search over the quilt, which lost the energy gained: median 0.93.)
///
/// On four soft stochastic photographs too (`bench/heldout-data.sh`'s clouds, mist, wisps
/// and fire-smoke; seeds 1-8, with the twelve), weight 3 stays: 1 and 2 lowered mist's
/// and fire's energy (1.63 and 0.89 at 1, from 2.03 and 1.08; the peer's 1.55 and 0.74,
/// its tiles one smooth band repeated) but lost repetition on grass and gravel (1) or
/// colour on marble and wisps (2), and brick's or roof's seam (1). Without the term
/// (0) fire's energy is still 0.80, and wisps' colour 0.258 against the peer's 0.098;
/// 7 x 7 and 9 x 9 neighbourhoods for tiles, at two to three times the work, left fire
/// above the peer's and mist's colour further off.
///
/// The term first asked every exemplar pixel for an even share, and every window for
/// it: a tile's quilt copied the exemplar's edges as often as its middle, and paid what
/// it still owed in its last windows, those that close the wrap. A feature the
/// photograph's edge cuts off (a cloud bank along its top) has no top in it, so the
/// bank was laid in flat-topped blobs along the wrap (27 times the mean row's step at
/// 600 x 600). Now each pixel's share is `quilt::reach` (the edges' halfway to the
/// middle's), the closing windows go by their fit alone, and a window that fits badly
/// earns no credit for what it would cover (`quilt::MISFIT`). Over seeds 1-8 against
/// the peer (the twelve and the soft four): energy at or below the peer's on 16 of 16
/// (from 14; fire 0.73 against the peer's 0.74, mist 1.46 against 1.55), median 0.84
/// (from 0.88); colour at most the peer's on 11 (from 12; marble 0.117 against 0.098
/// before and the peer's 0.095, clouds 0.172 against 0.168, wisps 0.117 against
/// 0.098, plaster, grass); repetition on 15 (sand 0.869 against its own 0.933, from
/// 0.900); seams in 0.8-1.2 on 16 (from 15; brick 0.85).
///
/// The windows' one-pixel overlap makes their cut a straight line, and on soft
/// photographs some windows' edges still show in the tile (a bright puff of cloud with
/// a straight side: helper-66's trial, supertuxkart-data's clouds). Wider overlaps, for
/// cuts that can wander, were measured over seeds 1-8 on the sixteen and not kept: 6-pixel
/// windows overlapping by 2 (so 4 apart), colour at most the peer's on 12 and energy on
/// 15 (sand 6.59 against 6.46); 7-pixel windows overlapping by 2 (5 apart, as now),
/// colour on 11 (marble 0.155, mist 0.359 against the peer's 0.095, 0.347), and neither
/// took the straight edges away.
///
/// Most of the straight edges that stay are where a window copies the photograph's own
/// edge (a cloud bank its top edge cuts off, in helper-67's megaglest sky: the pixels
/// along two of the three straight edges in a 256 x 190 tile copy its top row), which no
/// pass can move, since nothing lies beyond it to continue. Measured and not kept (seeds
/// 1-8 on the sixteen at 128; 1-3 on fifteen photographs of 64-1024 from helper-66's and
/// helper-67's trials at their own size): cutting the finest level's long straight seams
/// again within 8 pixels of where they lie (the least-difference path through the two
/// pieces extended across it, after Kwatra et al. 2003) changed nothing, since the passes
/// leave no long straight seam at the finest level (patch energy and the straight-edge
/// share within 0.01); drawing no window within one pixel of the exemplar's edges cost
/// colour at 128 (at most the peer's distance on 10 of 16, marble 0.185, mist 0.393) and
/// was mixed at the photographs' own sizes (lower on 8 of 15, higher on 6: bark 0.044 ->
/// 0.062).
const TILE_QUILT: Quilt = Quilt { side: 6, candidates: 8, spread: 3.0 };

/// Whether tiles quilt (always, but for a probe's `PATTERNSYNTH_TILE_QUILT=0`, which
/// grows them from noise as before `TILE_QUILT`).
pub(super) fn tile_quilt() -> bool {
    !(cfg!(feature = "test-support") && std::env::var("PATTERNSYNTH_TILE_QUILT").is_ok_and(|v| v == "0"))
}

/// The quilt's window side, candidates and coverage weight (`TILE_QUILT` for a tile);
/// probes may set them through `PATTERNSYNTH_QUILT=side,candidates[,spread]`.
pub(super) fn quilt_params(tileable: bool) -> Quilt {
    #[cfg(feature = "test-support")]
    if let Ok(v) = std::env::var("PATTERNSYNTH_QUILT") {
        let n: Vec<usize> = v.split(',').filter_map(|s| s.parse().ok()).collect();
        let spread = v.split(',').nth(2).and_then(|s| s.parse().ok()).unwrap_or(0.0);
        if n.len() >= 2 {
            return Quilt { side: n[0], candidates: n[1], spread };
        }
    }
    if tileable {
        TILE_QUILT
    } else {
        Quilt::default()
    }
}

#[cfg(test)]
mod tests {
    use super::matched;

    #[test]
    fn matching_keeps_the_order_and_takes_the_exemplar_s_values() {
        // Four values in the exemplar's eight: each takes the exemplar's value at the
        // middle of its rank's share (ranks 0-3: positions 1, 3, 5, 7).
        let to = [80.0, 10.0, 70.0, 20.0, 60.0, 30.0, 50.0, 40.0];
        assert_eq!(matched(vec![0.3, 0.1, 0.4, 0.2], &to), vec![60.0, 20.0, 80.0, 40.0]);
        // A flat region stays flat: equal values take their run's middle rank (1).
        assert_eq!(matched(vec![5.0, 5.0, 5.0, 9.0], &to), vec![40.0, 40.0, 40.0, 80.0]);
    }
}
