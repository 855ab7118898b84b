//! Shared test helpers: one tolerance policy and a deterministic random source.
#![allow(dead_code)]

use nalgebra::{Vector2, Vector3};

/// Results that are exact up to rounding (dual numbers vs closed forms, Hermite vs Bézier):
/// `|a − b| ≤ EXACT · max(1, |b|)`.
pub const EXACT: f64 = 1e-13;

/// Central differences with step `FD_STEP` have truncation error `O(h²) ≈ 1e-10` plus
/// rounding `ε/h ≈ 1e-11`; `FD` bounds both with margin.
pub const FD: f64 = 1e-7;
/// Step of the central differences.
pub const FD_STEP: f64 = 1e-5;

/// Relative-or-absolute closeness of two vectors, componentwise.
pub fn close(a: &Vector3<f64>, b: &Vector3<f64>, tol: f64) -> bool {
    a.iter()
        .zip(b.iter())
        .all(|(x, y)| (x - y).abs() <= tol * y.abs().max(1.0))
}

/// Asserts [`close`] with a message carrying both vectors.
#[track_caller]
pub fn assert_close(a: &Vector3<f64>, b: &Vector3<f64>, tol: f64, what: &str) {
    assert!(
        close(a, b, tol),
        "{what}: got {a:?}, expected {b:?}, difference {:?}, tolerance {tol:e}",
        a - b
    );
}

/// SplitMix64: a small deterministic generator so every run checks the same points.
pub struct Rng(u64);

impl Rng {
    pub fn new(seed: u64) -> Self {
        Self(seed)
    }

    pub fn next_u64(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }

    /// Uniform in `[a, b)`.
    pub fn uniform(&mut self, a: f64, b: f64) -> f64 {
        a + (b - a) * ((self.next_u64() >> 11) as f64 / (1u64 << 53) as f64)
    }
}

/// Distance from `x` to the polyline `line` (exact point-to-segment distances): the test-side
/// reference for curve errors.
pub fn distance_to_polyline(line: &[Vector2<f64>], x: Vector2<f64>) -> f64 {
    line.windows(2)
        .map(|w| {
            let (a, b) = (w[0], w[1]);
            let t = ((x - a).dot(&(b - a)) / (b - a).norm_squared()).clamp(0.0, 1.0);
            (x - (a + (b - a) * t)).norm()
        })
        .fold(f64::INFINITY, f64::min)
}

/// Symmetric Hausdorff distance between two dense polylines, by brute force.
pub fn hausdorff(a: &[Vector2<f64>], b: &[Vector2<f64>]) -> f64 {
    let one = |p: &[Vector2<f64>], q: &[Vector2<f64>]| {
        p.iter()
            .map(|&x| distance_to_polyline(q, x))
            .fold(0.0, f64::max)
    };
    one(a, b).max(one(b, a))
}
