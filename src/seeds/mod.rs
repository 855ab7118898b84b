//! The seeds' worked examples as data: knot vectors, control points, parameters and printed
//! values of the lecture seeds, with no I/O. Tests, the report layer and the notebooks take
//! their fixtures from here, so the mathematics can be tested without the report stack.
//! Seed 004's letter "a" in four versions is [`letters`] (feature `fonts`: three are glyphs of
//! the fonts the crate embeds).

#[cfg(feature = "fonts")]
pub mod letters;
pub mod seed000;
pub mod seed001;
pub mod seed003;
pub mod seed004;
