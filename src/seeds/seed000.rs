//! Numbers printed in seed 000, transcribed as text so their precision is known.
//!
//! These are the report's claims, shown beside ours in every table; they never enter a
//! computation.

use crate::exact::{self, Polynomial, Rational};

/// One printed row: a case and its x, y, z values as printed.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PrintedRow {
    /// Upper end `b` of the square domain `[0, b]²`.
    pub side: f64,
    /// Patches along u.
    pub n: usize,
    /// Patches along v.
    pub m: usize,
    /// x, y, z as printed.
    pub values: [&'static str; 3],
}

/// §3, "Errore di interpolazione": a single patch on `[0, 1]²` and on `[0, 0.5]²`.
pub const T3: [PrintedRow; 2] = [
    PrintedRow {
        side: 1.0,
        n: 1,
        m: 1,
        values: ["0.0717", "0.0396", "0.0114"],
    },
    PrintedRow {
        side: 0.5,
        n: 1,
        m: 1,
        values: ["0.0053", "0.0014", "3.7101e-04"],
    },
];

/// §6, "Errore di interpolazione nel caso spline": `n × m` patches on `[0, 1]²`.
pub const T6: [PrintedRow; 4] = [
    PrintedRow {
        side: 1.0,
        n: 1,
        m: 1,
        values: ["0.0717", "0.0396", "0.0114"],
    },
    PrintedRow {
        side: 1.0,
        n: 2,
        m: 1,
        values: ["0.0201", "0.0114", "0.0114"],
    },
    PrintedRow {
        side: 1.0,
        n: 2,
        m: 2,
        values: ["0.0113", "0.0136", "6.9577e-04"],
    },
    PrintedRow {
        side: 1.0,
        n: 3,
        m: 3,
        values: ["0.0054", "0.0075", "1.3694e-04"],
    },
];

/// Whether `value` rounds to `printed` at the printed precision: `"0.0717"` fixes 4
/// decimals, `"3.7101e-04"` the digit of `10⁻⁸`. `false` if `printed` does not parse.
///
/// # Examples
/// ```
/// use splinelab::seeds::seed000::agrees_to_printed;
/// assert!(agrees_to_printed("0.0717", 0.07174443));
/// assert!(agrees_to_printed("3.7101e-04", 3.71014e-4));
/// assert!(!agrees_to_printed("0.0113", 0.0043878));
/// ```
pub fn agrees_to_printed(printed: &str, value: f64) -> bool {
    let Ok(target) = printed.parse::<f64>() else {
        return false;
    };
    let (mantissa, exponent) = match printed.split_once(['e', 'E']) {
        Some((m, e)) => match e.parse::<i32>() {
            Ok(e) => (m, e),
            Err(_) => return false,
        },
        None => (printed, 0),
    };
    let decimals = mantissa.split_once('.').map_or(0, |(_, f)| f.len()) as i32;
    let quantum = 10f64.powi(exponent - decimals);
    value.is_finite() && (value / quantum).round() == (target / quantum).round()
}

/// §1's cubic Hermite basis as printed, `H₀ = 1 − 3t² + 2t³; H₁ = t − 2t² + t³;
/// H₂ = t³ − t²; H₃ = 3t² − 2t³`: each row the coefficients of `1, t, t², t³`.
pub const HERMITE_BASIS: [[i64; 4]; 4] =
    [[1, 0, -3, 2], [0, 1, -2, 1], [0, 0, -1, 1], [0, 0, 3, -2]];

/// [`HERMITE_BASIS`] as exact polynomials, to compare a derived basis with (notebook 01).
pub fn hermite_basis_printed() -> Vec<Polynomial<Rational>> {
    HERMITE_BASIS
        .iter()
        .map(|row| Polynomial::new(row.iter().map(|&c| exact::int(c)).collect()))
        .collect()
}
