//! A figure as a value: a plane chart, a 3-D scene or a colour map, with its size. It draws on
//! any plotters backend ([`Figure::render`]), writes anti-aliased PNG and SVG files, and shows
//! itself inline in a notebook (evcxr's `evcxr_display`).
//!
//! Every figure of the CLI and of the notebooks is one of these, built by the functions of
//! [`crate::report::draw`] from data, so a user's own surface or curve is drawn the same way
//! as the seeds'.

use crate::report::error::{Error, Result};
use crate::report::files::write_atomic;
use crate::report::heatmap::HeatMap;
use crate::report::plot2d::Figure2d;
use crate::report::render3d::Figure3d;
use crate::report::style::{ensure_font, FIGURE_SIZE};
use crate::report::supersample::{downsample, Supersampled};
use plotters::coord::Shift;
use plotters::prelude::*;
use std::path::{Path, PathBuf};

/// How many times larger a PNG is drawn before it is averaged down (3: nine coverage levels
/// per edge pixel, and a 900 × 700 figure needs a 17 MB buffer while it is drawn).
pub const SUPERSAMPLE: u32 = 3;

/// The largest side of a figure in pixels; [`Figure::with_size`] clamps to it.
pub const MAX_SIDE: u32 = 8192;

/// The most pixels a supersampled buffer may hold (`2²⁶`, 192 MB of RGB); larger figures are
/// drawn with a smaller factor, down to 1 (no supersampling).
const MAX_BUFFER_PIXELS: u64 = 1 << 26;

/// The supersampling factor for a figure of `size`: [`SUPERSAMPLE`], or less so the buffer
/// stays within [`MAX_BUFFER_PIXELS`].
fn factor((w, h): (u32, u32)) -> u32 {
    let pixels = u64::from(w) * u64::from(h);
    (1..=SUPERSAMPLE)
        .rev()
        .find(|k| pixels * u64::from(k * k) <= MAX_BUFFER_PIXELS)
        .unwrap_or(1)
}

/// What a figure shows.
#[derive(Debug, Clone)]
pub enum Drawing {
    /// Panels of curves and points on Cartesian (or logarithmic) axes.
    Plane(Figure2d),
    /// A shaded 3-D scene.
    Scene(Figure3d),
    /// Values over a rectangle as colours, with a colour bar.
    Map(HeatMap),
}

/// A figure ready to be drawn, written or shown.
#[derive(Debug, Clone)]
pub struct Figure {
    /// What it shows.
    pub drawing: Drawing,
    /// Size in pixels (width, height), each side in `[64, MAX_SIDE]` ([`Figure::with_size`]).
    size: (u32, u32),
}

impl From<Figure2d> for Figure {
    fn from(f: Figure2d) -> Self {
        Self::new(Drawing::Plane(f))
    }
}

impl From<Figure3d> for Figure {
    /// At the default width, as tall as the fitted scene needs
    /// ([`crate::report::render3d::fitted_height`]: no blank band above or below it).
    fn from(f: Figure3d) -> Self {
        let height = match ensure_font() {
            Ok(()) => {
                crate::report::render3d::fitted_height(&f.title, &f.scene, f.view, FIGURE_SIZE)
            }
            Err(_) => FIGURE_SIZE.1,
        };
        Self::new(Drawing::Scene(f)).with_size(FIGURE_SIZE.0, height)
    }
}

impl From<HeatMap> for Figure {
    fn from(f: HeatMap) -> Self {
        Self::new(Drawing::Map(f))
    }
}

impl Figure {
    /// A figure of the default size ([`FIGURE_SIZE`]).
    pub fn new(drawing: Drawing) -> Self {
        Self {
            drawing,
            size: FIGURE_SIZE,
        }
    }

    /// The same figure at another size in pixels (each side clamped to `[64, MAX_SIDE]`).
    pub fn with_size(mut self, width: u32, height: u32) -> Self {
        self.size = (width.clamp(64, MAX_SIDE), height.clamp(64, MAX_SIDE));
        self
    }

    /// The size in pixels (width, height).
    pub fn size(&self) -> (u32, u32) {
        self.size
    }

    /// The figure's title.
    pub fn title(&self) -> &str {
        match &self.drawing {
            Drawing::Plane(f) => &f.title,
            Drawing::Scene(f) => &f.title,
            Drawing::Map(f) => &f.title,
        }
    }

    fn fail(&self, message: impl std::fmt::Display) -> Error {
        Error::Figure {
            name: self.title().to_string(),
            message: message.to_string(),
        }
    }

    /// Draws the figure on a white background into `area` (any plotters backend).
    ///
    /// # Errors
    /// [`Error::Figure`] if the font cannot be registered or the backend fails.
    pub fn render<DB: DrawingBackend>(&self, area: &DrawingArea<DB, Shift>) -> Result<()> {
        ensure_font().map_err(|m| self.fail(m))?;
        let problem = match &self.drawing {
            Drawing::Plane(f) => f.layout_problem(),
            Drawing::Scene(f) => f.scene.problem(),
            Drawing::Map(_) => None,
        };
        if let Some(problem) = problem {
            return Err(self.fail(problem));
        }
        area.fill(&WHITE).map_err(|e| self.fail(e))?;
        match &self.drawing {
            Drawing::Plane(f) => f.draw(area),
            Drawing::Scene(f) => f.draw(area),
            Drawing::Map(f) => f.draw(area),
        }
        .map_err(|e| self.fail(e))
    }

    /// The figure as an SVG document.
    ///
    /// # Errors
    /// As [`Figure::render`].
    pub fn to_svg(&self) -> Result<String> {
        let mut text = String::new();
        {
            let root = SVGBackend::with_string(&mut text, self.size).into_drawing_area();
            self.render(&root)?;
            root.present().map_err(|e| self.fail(e))?;
        }
        Ok(text)
    }

    /// The figure as RGB pixels (`width · height · 3` bytes), drawn [`SUPERSAMPLE`] times
    /// larger and averaged down, so lines and edges are anti-aliased (for very large figures
    /// the factor is smaller, so the buffer stays under 192 MB).
    ///
    /// # Errors
    /// As [`Figure::render`].
    pub fn to_rgb(&self) -> Result<Vec<u8>> {
        // the size is private and set through `with_size`, which clamps it; checked again here
        // so the buffer's size arithmetic cannot overflow whatever the figure went through
        let (w, h) = (
            self.size.0.clamp(1, MAX_SIDE),
            self.size.1.clamp(1, MAX_SIDE),
        );
        let k = factor((w, h));
        let mut big = vec![255u8; (w * k) as usize * (h * k) as usize * 3];
        {
            let backend = BitMapBackend::with_buffer(&mut big, (w * k, h * k));
            let root = Supersampled::new(backend, k).into_drawing_area();
            self.render(&root)?;
            root.present().map_err(|e| self.fail(e))?;
        }
        Ok(downsample(&big, (w, h), k))
    }

    /// The figure as an anti-aliased PNG file's bytes ([`Figure::to_rgb`], encoded losslessly
    /// at the best compression).
    ///
    /// # Errors
    /// [`Error::Figure`] if drawing or encoding fails.
    pub fn to_png(&self) -> Result<Vec<u8>> {
        use image::ImageEncoder;
        let rgb = self.to_rgb()?;
        let (w, h) = self.size;
        let mut bytes = Vec::new();
        // the best deflate level with adaptive filters: about a quarter of the bytes of the
        // encoder's default (fast) settings, for a few milliseconds more per figure
        image::codecs::png::PngEncoder::new_with_quality(
            &mut bytes,
            image::codecs::png::CompressionType::Best,
            image::codecs::png::FilterType::Adaptive,
        )
        .write_image(&rgb, w, h, image::ColorType::Rgb8)
        .map_err(|e| self.fail(e))?;
        Ok(bytes)
    }

    /// Writes the figure as an anti-aliased PNG (through a temporary file renamed into place).
    ///
    /// # Errors
    /// [`Error::Figure`] if drawing or encoding fails, [`Error::Io`] if the file cannot be
    /// written.
    pub fn write_png(&self, path: &Path) -> Result<()> {
        write_atomic(path, &self.to_png()?)
    }

    /// Writes the figure as SVG (through a temporary file renamed into place).
    ///
    /// # Errors
    /// As [`Figure::to_svg`]; [`Error::Io`] if the file cannot be written.
    pub fn write_svg(&self, path: &Path) -> Result<()> {
        write_atomic(path, self.to_svg()?.as_bytes())
    }

    /// Writes `<dir>/<stem>.png` and `<dir>/<stem>.svg`, creating `dir`; returns the paths.
    ///
    /// # Errors
    /// As [`Figure::write_png`] and [`Figure::write_svg`].
    pub fn save(&self, dir: &Path, stem: &str) -> Result<Vec<PathBuf>> {
        std::fs::create_dir_all(dir).map_err(crate::report::error::io_err(dir))?;
        let png = dir.join(format!("{stem}.png"));
        self.write_png(&png)?;
        let svg = dir.join(format!("{stem}.svg"));
        self.write_svg(&svg)?;
        Ok(vec![png, svg])
    }

    /// Shows the figure inline in a notebook (the evcxr kernel calls this for a cell's value):
    /// the anti-aliased PNG, which a notebook keeps in its stored outputs and every notebook
    /// viewer shows, or the error's message if it cannot be drawn.
    pub fn evcxr_display(&self) {
        use base64::Engine;
        match self.to_png() {
            Ok(png) => println!(
                "EVCXR_BEGIN_CONTENT image/png\n{}\nEVCXR_END_CONTENT",
                base64::engine::general_purpose::STANDARD.encode(png)
            ),
            Err(e) => eprintln!("{e}"),
        }
    }
}
