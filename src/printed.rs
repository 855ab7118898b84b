//! How the crate writes a number in text (formulas, conditions, spans): an integer, a fraction
//! `p/q` with a small denominator when the number is exactly one, else the shortest decimal that
//! reads back to the same `f64`. The formula layer prints its constants with it, and the core
//! its spans and conditions, so both write `1/4` alike.

/// The largest denominator [`number`] prints a fraction with.
const MAX_DENOMINATOR: u32 = 64;

/// The fraction `(p, q)`, `q ≥ 1`, that `c` is exactly, if `q ≤ 64` and `|p| < 10¹⁵`.
pub(crate) fn fraction(c: f64) -> Option<(i64, u32)> {
    if !c.is_finite() {
        return None;
    }
    (1..=MAX_DENOMINATOR).find_map(|q| {
        let p = c * f64::from(q);
        (p.fract() == 0.0 && p.abs() < 1e15 && p / f64::from(q) == c).then_some((p as i64, q))
    })
}

/// A constant as printed: an integer, a fraction `p/q` with `q ≤ 64` when it is exactly one,
/// else the shortest decimal that reads back to the same `f64`.
pub fn number(c: f64) -> String {
    match fraction(c) {
        Some((p, 1)) => p.to_string(),
        Some((p, q)) => format!("{p}/{q}"),
        None => decimal(c),
    }
}

/// The shortest decimal that reads back to `c`: positional between `10⁻⁴` and `10¹⁶`, else
/// with an exponent (`5.551115123125783e-17`, not seventeen zeros).
pub(crate) fn decimal(c: f64) -> String {
    let m = c.abs();
    if c.is_finite() && m != 0.0 && !(1e-4..1e16).contains(&m) {
        format!("{c:e}")
    } else {
        format!("{c}")
    }
}

/// `c` rounded to `digits` significant digits (at least 1), written as [`decimal`] writes the
/// rounded value: `0.010000770459999999` to 6 digits is `0.0100008`. For text meant to be
/// read (titles, headers); data keep every digit.
#[cfg(feature = "report")]
pub(crate) fn rounded(c: f64, digits: usize) -> String {
    if !c.is_finite() || c == 0.0 {
        return decimal(c);
    }
    let text = format!("{:.*e}", digits.max(1) - 1, c);
    decimal(text.parse::<f64>().unwrap_or(c))
}

/// Text for HTML and MathML: `&`, `<`, `>` escaped.
pub(crate) fn escape(text: &str) -> String {
    text.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
}

/// A matrix in LaTeX: `\begin{pmatrix}a & b \\ c & d\end{pmatrix}`, from its cells' LaTeX,
/// row by row.
pub(crate) fn latex_matrix(rows: &[Vec<String>]) -> String {
    let rows: Vec<String> = rows.iter().map(|r| r.join(" & ")).collect();
    format!("\\begin{{pmatrix}}{}\\end{{pmatrix}}", rows.join(" \\\\ "))
}

/// A matrix in presentation MathML, from its cells' MathML, row by row; the brackets drawn as
/// the table's rounded side borders (a stretched `(` needs an OpenType MATH font, which a
/// reader's browser may not have).
pub(crate) fn mathml_matrix(rows: &[Vec<String>]) -> String {
    let rows: String = rows
        .iter()
        .map(|r| {
            let cells: String = r.iter().map(|c| format!("<mtd>{c}</mtd>")).collect();
            format!("<mtr>{cells}</mtr>")
        })
        .collect();
    format!("<mrow><mtable style=\"border-left:1.5px solid;border-right:1.5px solid;border-radius:0.5em;padding:0 0.3em\">{rows}</mtable></mrow>")
}
