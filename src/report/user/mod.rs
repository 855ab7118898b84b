//! A user's own data through the seeds' methods: what the command line's `fit`, `fewest` and
//! `surface` do, as functions a notebook or a program calls with its own points, outlines and
//! partitions.
//!
//! - [`fit`]: one of seed 004's methods through a user's points — the curve sampled (CSV),
//!   drawn over its points, as SVG cubic Béziers, its formulas piece by piece.
//! - [`fewest`]: the fewest points on a user's outline ([`crate::study::outline::fewest`]) as a
//!   table and one figure per method.
//! - [`surface`]: a Hermite spline surface of a built-in surface on a user's partition, as a
//!   mesh for OBJ, PLY or STL.
//!
//! - [`outline`]: points and outlines from files by their extension — CSV, an SVG document, SVG
//!   path data, a font's glyph ([`crate::input`]'s readers).
//!
//! Writing the files is [`crate::report::export`]'s.

pub mod fewest;
pub mod fit;
pub mod outline;
pub mod surface;
