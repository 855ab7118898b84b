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

/// The distance from `p` to the segment `ab` in exact rational arithmetic, rounded once: the
/// test-side reference for distances at every magnitude. The inputs are converted exactly,
/// the foot `t = clamp((p − a)·(b − a)/|b − a|², 0, 1)` and the squared distance are exact,
/// and the square root is taken of the squared distance scaled by a power of 4 into
/// `[1/4, 16)` (so `f64` holds it whatever its magnitude) and scaled back: correct to about
/// one unit of rounding of the distance.
pub fn exact_segment_distance(p: Vector2<f64>, a: Vector2<f64>, b: Vector2<f64>) -> f64 {
    use num_bigint::BigInt;
    use num_rational::BigRational as Q;
    use num_traits::{ToPrimitive, Zero};
    let r = |x: f64| Q::from_float(x).expect("finite");
    let (dx, dy) = (r(p.x) - r(a.x), r(p.y) - r(a.y));
    let (wx, wy) = (r(b.x) - r(a.x), r(b.y) - r(a.y));
    let len2 = &wx * &wx + &wy * &wy;
    let dot = &dx * &wx + &dy * &wy;
    let t = if len2.is_zero() || dot <= Q::zero() {
        Q::zero()
    } else if dot >= len2 {
        Q::from_integer(BigInt::from(1))
    } else {
        dot / len2
    };
    let (ex, ey) = (dx - &t * wx, dy - &t * wy);
    let q = &ex * &ex + &ey * &ey;
    if q.is_zero() {
        return 0.0;
    }
    let e = (q.numer().bits() as i64 - q.denom().bits() as i64) / 2;
    let four_e = Q::from_integer(BigInt::from(1) << (2 * e.unsigned_abs()));
    let scaled = if e >= 0 { q / four_e } else { q * four_e };
    let root = scaled.to_f64().expect("in range").sqrt();
    // 2^e in two steps, so neither factor overflows before the product
    let half = 2f64.powi((e / 2) as i32);
    root * half * 2f64.powi((e - e / 2) as i32)
}

/// Distance from `x` to the polyline `line` (the textbook point-to-segment formula in `f64`,
/// a zero-length segment measured to its point): the test-side reference for curve errors
/// at ordinary magnitudes.
pub fn distance_to_polyline(line: &[Vector2<f64>], x: Vector2<f64>) -> f64 {
    line.windows(2)
        .map(|w| {
            let (a, b) = (w[0], w[1]);
            let len2 = (b - a).norm_squared();
            let t = if len2 > 0.0 {
                ((x - a).dot(&(b - a)) / len2).clamp(0.0, 1.0)
            } else {
                0.0
            };
            ((x - a) - (b - a) * t).norm()
        })
        .fold(f64::INFINITY, f64::min)
}

/// Distance from `x` to the polyline `line` as the minimum of the exact segment distances
/// ([`exact_segment_distance`]): the reference at every magnitude (slow).
pub fn exact_distance_to_polyline(line: &[Vector2<f64>], x: Vector2<f64>) -> f64 {
    line.windows(2)
        .map(|w| exact_segment_distance(x, w[0], w[1]))
        .fold(f64::INFINITY, f64::min)
}

/// Distances agree with the exact reference to rounding of the distance itself: a few `ε`
/// of it, plus `ε²` of the coordinates' differences `scale` (the library's stated bound).
pub fn distance_close(d: f64, exact: f64, scale: f64) -> bool {
    (d - exact).abs() <= 16.0 * f64::EPSILON * exact + f64::EPSILON * f64::EPSILON * scale
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
