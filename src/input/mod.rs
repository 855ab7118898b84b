//! Users' data in: points from text — CSV ([`csv`]) and SVG path data ([`svg_path`]). Every reader takes the text (reading the
//! file is the caller's), refuses what it cannot read with [`crate::Error::Parse`] naming the
//! line and column at fault, and returns nothing half-read.

pub mod csv;
pub mod svg_path;

pub use csv::{points_from_csv, Columns};
pub use svg_path::{contours_from_svg_document, contours_from_svg_path, Contour};
