//! Animated figures: a sequence of [`Figure`]s of one size, encoded as one looping GIF and
//! shown inline in a notebook (evcxr's `image/gif` content), for processes that run in time —
//! de Casteljau's construction as `u` runs, a blending window sliding along the data
//! ([`de_casteljau`], [`sliding_window`]).

use crate::report::error::{Error, Result};
use crate::report::figure::Figure;
use std::path::Path;

/// The most frames an animation takes (each is drawn and quantized to 256 colours).
pub const MAX_FRAMES: usize = 240;

/// Frames of one size shown in turn, `delay_ms` milliseconds each, looping.
#[derive(Debug, Clone)]
pub struct Animation {
    frames: Vec<Figure>,
    delay_ms: u32,
}

impl Animation {
    /// The animation of `frames`, each shown for `delay_ms` milliseconds (20 ms to 10 s).
    ///
    /// # Errors
    /// [`Error::Figure`] for no frame, more than [`MAX_FRAMES`], frames of different sizes, or
    /// a delay outside 20 ms … 10 s.
    pub fn try_new(frames: Vec<Figure>, delay_ms: u32) -> Result<Self> {
        let fail = |message: String| Error::Figure {
            name: "animation".into(),
            message,
        };
        let Some(first) = frames.first() else {
            return Err(fail("no frame to show".into()));
        };
        if frames.len() > MAX_FRAMES {
            return Err(fail(format!(
                "{} frames exceed the limit of {MAX_FRAMES}",
                frames.len()
            )));
        }
        if let Some((k, f)) = frames
            .iter()
            .enumerate()
            .find(|(_, f)| f.size() != first.size())
        {
            return Err(fail(format!(
                "frame {k} is {:?} pixels, frame 0 {:?}: all frames must have one size",
                f.size(),
                first.size()
            )));
        }
        if !(20..=10_000).contains(&delay_ms) {
            return Err(fail(format!(
                "a delay of {delay_ms} ms is outside 20 ms … 10 s"
            )));
        }
        Ok(Self { frames, delay_ms })
    }

    /// The frames.
    pub fn frames(&self) -> &[Figure] {
        &self.frames
    }

    /// The delay between frames, in milliseconds.
    pub fn delay_ms(&self) -> u32 {
        self.delay_ms
    }

    /// The animation as a looping GIF file's bytes: each frame drawn at its size without
    /// supersampling (a GIF's 256 colours and its compression suit sharp lines; anti-aliased
    /// frames would be three to four times larger) and quantized to its own palette.
    ///
    /// # Errors
    /// [`Error::Figure`] if a frame cannot be drawn or the encoder fails.
    pub fn to_gif(&self) -> Result<Vec<u8>> {
        let fail = |e: &dyn std::fmt::Display| Error::Figure {
            name: "animation".into(),
            message: e.to_string(),
        };
        let (w, h) = self.frames[0].size();
        let side = |x: u32| u16::try_from(x).map_err(|e| fail(&e));
        let mut bytes = Vec::new();
        {
            let mut encoder =
                gif::Encoder::new(&mut bytes, side(w)?, side(h)?, &[]).map_err(|e| fail(&e))?;
            encoder
                .set_repeat(gif::Repeat::Infinite)
                .map_err(|e| fail(&e))?;
            let mut previous: Option<Vec<u8>> = None;
            for figure in &self.frames {
                let rgb = aliased_rgb(figure)?;
                // after the first frame only the rectangle that changed is stored, drawn over
                // the previous frame, which stays (an unchanged frame keeps one pixel)
                let (x0, y0, x1, y1) = match &previous {
                    None => (0, 0, w, h),
                    Some(p) => changed(p, &rgb, w, h).unwrap_or((0, 0, 1, 1)),
                };
                let mut part = Vec::with_capacity(((x1 - x0) * (y1 - y0) * 3) as usize);
                for y in y0..y1 {
                    let row = (y * w) as usize * 3;
                    part.extend_from_slice(&rgb[row + x0 as usize * 3..row + x1 as usize * 3]);
                }
                // speed 10 of 1 … 30: a tenth of the quantizer's slowest sampling, no visible
                // loss on figures of few colours
                let mut frame =
                    gif::Frame::from_rgb_speed(side(x1 - x0)?, side(y1 - y0)?, &part, 10);
                (frame.left, frame.top) = (side(x0)?, side(y0)?);
                frame.delay = u16::try_from(self.delay_ms / 10).unwrap_or(u16::MAX);
                frame.dispose = gif::DisposalMethod::Keep;
                encoder.write_frame(&frame).map_err(|e| fail(&e))?;
                previous = Some(rgb);
            }
        }
        Ok(bytes)
    }

    /// Writes the GIF to `path` (atomically: a temporary file renamed into place).
    ///
    /// # Errors
    /// As [`Animation::to_gif`]; [`Error::Io`] if the file cannot be written.
    pub fn write_gif(&self, path: &Path) -> Result<()> {
        crate::report::files::write_atomic(path, &self.to_gif()?)
    }

    /// Shows the animation inline in a notebook (the evcxr kernel calls this for a cell's
    /// value): the GIF as `image/gif` content, and as an HTML image for viewers that do not
    /// show `image/gif` (nbconvert's HTML pages).
    pub fn evcxr_display(&self) {
        use base64::Engine;
        match self.to_gif() {
            Ok(gif) => {
                let data = base64::engine::general_purpose::STANDARD.encode(gif);
                let (w, _) = self.frames[0].size();
                println!("EVCXR_BEGIN_CONTENT image/gif\n{data}\nEVCXR_END_CONTENT");
                println!(
                    "EVCXR_BEGIN_CONTENT text/html\n<img alt=\"an animation of {} frames\" \
                     width=\"{w}\" src=\"data:image/gif;base64,{data}\">\nEVCXR_END_CONTENT",
                    self.frames.len()
                );
            }
            Err(e) => eprintln!("{e}"),
        }
    }
}

/// The smallest rectangle `(x0, y0, x1, y1)` (end exclusive) holding every pixel where two
/// RGB frames of `w × h` differ; `None` if they are equal.
fn changed(a: &[u8], b: &[u8], w: u32, h: u32) -> Option<(u32, u32, u32, u32)> {
    let (mut x0, mut y0, mut x1, mut y1) = (w, h, 0, 0);
    for y in 0..h {
        for x in 0..w {
            let i = ((y * w + x) * 3) as usize;
            if a[i..i + 3] != b[i..i + 3] {
                (x0, y0) = (x0.min(x), y0.min(y));
                (x1, y1) = (x1.max(x + 1), y1.max(y + 1));
            }
        }
    }
    (x1 > x0).then_some((x0, y0, x1, y1))
}

/// The figure's pixels drawn directly at its size (no supersampling).
fn aliased_rgb(figure: &Figure) -> Result<Vec<u8>> {
    use plotters::prelude::{BitMapBackend, IntoDrawingArea};
    let (w, h) = figure.size();
    let mut rgb = vec![255u8; w as usize * h as usize * 3];
    {
        let root = BitMapBackend::with_buffer(&mut rgb, (w, h)).into_drawing_area();
        figure.render(&root)?;
        root.present().map_err(|e| Error::Figure {
            name: "animation".into(),
            message: e.to_string(),
        })?;
    }
    Ok(rgb)
}

/// de Casteljau's construction as `u` runs from 0 to 1 in `frames` steps (2 … [`MAX_FRAMES`],
/// `u` rounded to three decimals): each frame the control polygon, every level of repeated
/// linear interpolation at `u`, and the curve traced up to `P(u)` (seed 003's construction,
/// [`crate::report::draw::de_casteljau`] in time).
///
/// # Errors
/// [`Error::Figure`] for fewer than 2 or more than [`MAX_FRAMES`] frames; as
/// [`crate::bezier::de_casteljau::de_casteljau`] (no points, non-finite coordinates).
pub fn de_casteljau(
    points: &[nalgebra::Vector2<f64>],
    frames: usize,
    title: &str,
) -> Result<Animation> {
    use crate::report::plot2d::{Figure2d, SAMPLES};
    if !(2..=MAX_FRAMES).contains(&frames) {
        return Err(Error::Figure {
            name: "de Casteljau animation".into(),
            message: format!("{frames} frames: 2 … {MAX_FRAMES} are drawn"),
        });
    }
    let curve = crate::report::draw::bezier_samples(points)?;
    let mut figures = Vec::with_capacity(frames);
    for k in 0..frames {
        let u = (1000.0 * k as f64 / (frames - 1) as f64).round() / 1000.0;
        // the samples up to u, then P(u) itself
        let upto = ((SAMPLES - 1) as f64 * u).floor() as usize;
        let mut traced = curve[..=upto].to_vec();
        let p = crate::bezier::de_casteljau::de_casteljau(points, u)?;
        traced.push((p.x, p.y));
        let panel = crate::report::draw::de_casteljau_panel(points, &curve, u, Some(traced))?;
        figures.push(Figure::from(Figure2d::new(title, vec![panel], (1, 1))).with_size(640, 500));
    }
    Animation::try_new(figures, 120)
}

/// A 4-point blending window sliding along the data, `steps` frames per segment (1 … 24):
/// each frame the data, the four points the current segment blends (seed 003: "nel tratto
/// P2-P3 uso i punti P1-P4"), and the curve drawn up to the current point, for the Lagrange
/// window or the printed `bspline` procedure ([`crate::blending::window::WindowCurve`]).
///
/// # Errors
/// [`Error::Figure`] for `steps` outside 1 … 24 or more than [`MAX_FRAMES`] frames in all.
pub fn sliding_window(
    curve: &crate::blending::window::WindowCurve<2>,
    data: &[nalgebra::Vector2<f64>],
    steps: usize,
    title: &str,
) -> Result<Animation> {
    use crate::curve::ParametricCurve;
    use crate::report::plot2d::{xy, Figure2d, Panel, Series, Style, GREY, INK};
    use crate::report::style::LINE_PALETTE;
    let segments = curve.segments();
    let frames = segments.saturating_mul(steps).saturating_add(1);
    if !(1..=24).contains(&steps) || frames > MAX_FRAMES {
        return Err(Error::Figure {
            name: "sliding window animation".into(),
            message: format!(
                "{steps} steps per segment, {frames} frames in all: 1 … 24 steps and at most {MAX_FRAMES} frames are drawn"
            ),
        });
    }
    let whole = xy(&curve.polyline(crate::report::plot2d::SAMPLES)?);
    let mut figures = Vec::with_capacity(frames);
    for f in 0..frames {
        let s = f as f64 / steps as f64;
        let segment = (f / steps).min(segments - 1);
        let count = (f * 8).max(1) + 1;
        let traced = xy(&(0..count)
            .map(|i| curve.point(s * i as f64 / (count - 1) as f64))
            .collect::<Vec<_>>());
        let window = curve.window_of(segment);
        let here = curve.point(s);
        let panel = Panel::new(format!("segment {} of {segments}", segment + 1), "x", "y")
            .equal()
            .legend_at(plotters::prelude::SeriesLabelPosition::LowerRight)
            .with(Series::polygon("data", data))
            .with(
                Series::line("the whole curve", whole.clone(), GREY)
                    .styled(Style::Dashed)
                    .width(1),
            )
            .with(Series::line("drawn so far", traced, LINE_PALETTE[0]).width(3))
            .with(
                Series::line("the window's 4 points", xy(window), LINE_PALETTE[1])
                    .styled(Style::Crosses(8)),
            )
            .with(
                Series::line("current point", vec![(here.x, here.y)], INK).styled(Style::Points(6)),
            );
        figures.push(Figure::from(Figure2d::new(title, vec![panel], (1, 1))).with_size(640, 460));
    }
    Animation::try_new(figures, 150)
}
