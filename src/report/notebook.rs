//! What the Jupyter notebooks (evcxr kernel) call: figures as inline SVG, tables shown as
//! DataFrames with their notes, live timings. Cells stay one line; logic stays here.

use crate::error::Result;
use crate::report::figures::FigureId;
use crate::report::style::FIGURE_SIZE;
use crate::report::tables::Table;
use plotters::prelude::{IntoDrawingArea, SVGBackend};

/// An SVG picture that evcxr shows inline (its `evcxr_display` protocol).
#[derive(Debug, Clone, PartialEq)]
pub struct Svg(pub String);

impl Svg {
    /// Prints the evcxr display block; called by the kernel for a cell's value.
    pub fn evcxr_display(&self) {
        println!(
            "EVCXR_BEGIN_CONTENT text/html\n<div>{}</div>\nEVCXR_END_CONTENT",
            self.0
        );
    }
}

/// Draws `figure` into an SVG string: the same drawing the CLI writes to
/// `out/figures/<id>.svg`.
///
/// # Errors
/// As [`FigureId::render`].
pub fn figure_svg(figure: FigureId) -> Result<Svg> {
    let mut buffer = String::new();
    {
        let root = SVGBackend::with_string(&mut buffer, FIGURE_SIZE).into_drawing_area();
        figure.render(&root)?;
        root.present().map_err(|e| crate::Error::Figure {
            id: figure.id().to_string(),
            message: e.to_string(),
        })?;
    }
    Ok(Svg(buffer))
}

impl Table {
    /// Shows the title, every row of the DataFrame and the notes in a notebook (HTML; the
    /// plain DataFrame is `table.df`). Falls back to polars' text display if a cell cannot
    /// be read.
    pub fn evcxr_display(&self) {
        match crate::report::output::to_html(self) {
            Ok(html) => println!("EVCXR_BEGIN_CONTENT text/html\n{html}\nEVCXR_END_CONTENT"),
            Err(_) => println!("{}\n\n{}", self.title, self.df),
        }
    }
}
