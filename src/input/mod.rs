//! Users' data in: points from text — CSV ([`csv`]). Every reader takes the text (reading the
//! file is the caller's), refuses what it cannot read with [`crate::Error::Parse`] naming the
//! line and column at fault, and returns nothing half-read.

pub mod csv;

pub use csv::{points_from_csv, Columns};
