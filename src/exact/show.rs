//! Exact numbers, matrices and polynomials written for reading: plain text, LaTeX and MathML.

use super::{Polynomial, Rational};
use nalgebra::DMatrix;
use num_traits::{One, Zero};

/// A number, matrix or polynomial written as plain text, LaTeX and MathML.
pub trait Written {
    /// Plain text (`-3/2`, `[1, 0; -3, 2]`).
    fn plain(&self) -> String;
    /// LaTeX, math mode (`-\frac{3}{2}`, a `pmatrix`).
    fn latex(&self) -> String;
    /// Presentation MathML, the contents of a `<math>` element.
    fn mathml(&self) -> String;
}

/// Plain text of a rational number or matrix: `-3/2`; a matrix as rows `[a, b; c, d]`.
pub fn plain<W: Written + ?Sized>(x: &W) -> String {
    x.plain()
}

/// LaTeX of a rational number or matrix.
pub fn latex<W: Written + ?Sized>(x: &W) -> String {
    x.latex()
}

/// MathML of a rational number or matrix.
pub fn mathml<W: Written + ?Sized>(x: &W) -> String {
    x.mathml()
}

impl Written for Rational {
    fn plain(&self) -> String {
        self.to_string()
    }

    fn latex(&self) -> String {
        let sign = if self.is_negative() { "-" } else { "" };
        let a = self.abs();
        if a.is_integer() {
            format!("{sign}{}", a.numer())
        } else {
            format!("{sign}\\frac{{{}}}{{{}}}", a.numer(), a.denom())
        }
    }

    fn mathml(&self) -> String {
        let a = self.abs();
        let magnitude = if a.is_integer() {
            format!("<mn>{}</mn>", a.numer())
        } else {
            format!(
                "<mfrac><mn>{}</mn><mn>{}</mn></mfrac>",
                a.numer(),
                a.denom()
            )
        };
        if self.is_negative() {
            format!("<mrow><mo>\u{2212}</mo>{magnitude}</mrow>")
        } else {
            magnitude
        }
    }
}

impl Written for DMatrix<Rational> {
    fn plain(&self) -> String {
        let rows: Vec<String> = self
            .row_iter()
            .map(|r| {
                r.iter()
                    .map(|x| x.to_string())
                    .collect::<Vec<_>>()
                    .join(", ")
            })
            .collect();
        format!("[{}]", rows.join("; "))
    }

    fn latex(&self) -> String {
        crate::printed::latex_matrix(&cells(self, Written::latex))
    }

    fn mathml(&self) -> String {
        crate::printed::mathml_matrix(&cells(self, Written::mathml))
    }
}

impl<const N: usize> Written for nalgebra::SVector<Rational, N> {
    fn plain(&self) -> String {
        let parts: Vec<String> = self.iter().map(Written::plain).collect();
        format!("({})", parts.join(", "))
    }

    fn latex(&self) -> String {
        let parts: Vec<String> = self.iter().map(Written::latex).collect();
        format!("\\left({}\\right)", parts.join(",\\ "))
    }

    fn mathml(&self) -> String {
        let parts: Vec<String> = self.iter().map(Written::mathml).collect();
        format!(
            "<mrow><mo>(</mo>{}<mo>)</mo></mrow>",
            parts.join("<mo>,</mo>")
        )
    }
}

impl Polynomial<Rational> {
    /// The polynomial in plain text, ascending powers (`1 - 3*s^2 + 2*s^3`).
    pub fn plain(&self, var: &str) -> String {
        polynomial_plain(self, var)
    }

    /// The polynomial in LaTeX (`1 - 3s^{2} + 2s^{3}`).
    pub fn latex(&self, var: &str) -> String {
        polynomial_latex(self, var)
    }

    /// The polynomial in presentation MathML (the contents of a `<math>` element).
    pub fn mathml(&self, var: &str) -> String {
        polynomial_mathml(self, var)
    }
}

/// The entries of `m` written by `write`, row by row.
fn cells(m: &DMatrix<Rational>, write: fn(&Rational) -> String) -> Vec<Vec<String>> {
    m.row_iter()
        .map(|r| r.iter().map(write).collect())
        .collect()
}

/// The terms `(sign, |c|, k)` of the nonzero coefficients, ascending powers.
fn terms(p: &Polynomial<Rational>) -> Vec<(bool, Rational, usize)> {
    p.coefficients()
        .iter()
        .enumerate()
        .filter(|(_, c)| !c.is_zero())
        .map(|(k, c)| (c.is_negative(), c.abs(), k))
        .collect()
}

/// Joins terms with their signs: `first` written with a leading `-` if negative, the rest
/// after ` + ` or ` - `.
fn join(parts: Vec<(bool, String)>, minus: &str, plus: &str, lead: &str, zero: &str) -> String {
    if parts.is_empty() {
        return zero.to_string();
    }
    let mut out = String::new();
    for (i, (negative, body)) in parts.into_iter().enumerate() {
        match (i, negative) {
            (0, true) => out.push_str(lead),
            (0, false) => {}
            (_, true) => out.push_str(minus),
            (_, false) => out.push_str(plus),
        }
        out.push_str(&body);
    }
    out
}

fn polynomial_plain(p: &Polynomial<Rational>, var: &str) -> String {
    let parts = terms(p)
        .into_iter()
        .map(|(neg, c, k)| {
            let power = match k {
                0 => String::new(),
                1 => var.to_string(),
                _ => format!("{var}^{k}"),
            };
            let body = match (k, c.is_one(), c.is_integer()) {
                (0, _, _) => c.to_string(),
                (_, true, _) => power,
                (_, false, true) => format!("{c}*{power}"),
                // a fraction as a division, so that the text reads back: `s^3/3`, `3*s^2/2`
                (_, false, false) if c.numer().is_one() => format!("{power}/{}", c.denom()),
                (_, false, false) => format!("{}*{power}/{}", c.numer(), c.denom()),
            };
            (neg, body)
        })
        .collect();
    join(parts, " - ", " + ", "-", "0")
}

/// The terms `(negative, coefficient then power)` of a polynomial in a notation: a
/// coefficient 1 is left out before a power of the variable.
fn written(
    p: &Polynomial<Rational>,
    power: impl Fn(usize) -> String,
    coefficient: impl Fn(&Rational) -> String,
) -> Vec<(bool, String)> {
    terms(p)
        .into_iter()
        .map(|(neg, c, k)| {
            let c = if k > 0 && c.is_one() {
                String::new()
            } else {
                coefficient(&c)
            };
            (neg, format!("{c}{}", power(k)))
        })
        .collect()
}

fn polynomial_latex(p: &Polynomial<Rational>, var: &str) -> String {
    let power = |k: usize| match k {
        0 => String::new(),
        1 => var.to_string(),
        _ => format!("{var}^{{{k}}}"),
    };
    join(written(p, power, Written::latex), " - ", " + ", "-", "0")
}

fn polynomial_mathml(p: &Polynomial<Rational>, var: &str) -> String {
    let var = crate::printed::escape(var);
    let power = |k: usize| match k {
        0 => String::new(),
        1 => format!("<mi>{var}</mi>"),
        _ => format!("<msup><mi>{var}</mi><mn>{k}</mn></msup>"),
    };
    let minus = "<mo>\u{2212}</mo>";
    let body = join(
        written(p, power, Written::mathml),
        minus,
        "<mo>+</mo>",
        minus,
        "<mn>0</mn>",
    );
    format!("<mrow>{body}</mrow>")
}
