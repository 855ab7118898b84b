//! Formulas laid out for reading: a cell of mathematics in LaTeX and in MathML ([`Math`]) and
//! a table of them ([`MathTable`]), which a notebook shows as rendered mathematics — MathML,
//! which browsers render without a script (so a notebook's HTML copy shows it too), with the
//! LaTeX beside it for front ends that prefer it.

use super::print::{escape, Formula};
use crate::exact::{Polynomial, Rational, Written};
use nalgebra::Matrix4;

/// One cell of mathematics, in plain text, in LaTeX and in presentation MathML.
#[derive(Debug, Clone, PartialEq)]
pub struct Math {
    /// Plain text, as a terminal shows it (`-sin(s)*(2 + cos(t))`, `X_st`).
    pub plain: String,
    /// LaTeX (math mode).
    pub latex: String,
    /// MathML (the contents of a `<math>` element).
    pub mathml: String,
}

impl From<&Formula> for Math {
    fn from(f: &Formula) -> Math {
        Math {
            plain: f.plain(),
            latex: f.latex(),
            mathml: f.mathml(),
        }
    }
}

impl Math {
    /// Text set upright (a label, a heading).
    pub fn text(s: &str) -> Math {
        Math {
            plain: s.to_string(),
            latex: if s.is_empty() {
                String::new()
            } else {
                format!("\\text{{{}}}", latex_text(s))
            },
            mathml: format!("<mtext>{}</mtext>", escape(s)),
        }
    }

    /// A symbol with a subscript, `X_{st}` (no subscript if `sub` is empty).
    pub fn symbol(name: &str, sub: &str) -> Math {
        if sub.is_empty() {
            return Math {
                plain: name.into(),
                latex: name.into(),
                mathml: format!("<mi>{}</mi>", escape(name)),
            };
        }
        Math {
            plain: format!("{name}_{sub}"),
            latex: format!("{name}_{{{sub}}}"),
            mathml: format!(
                "<msub><mi>{}</mi><mi>{}</mi></msub>",
                escape(name),
                escape(sub)
            ),
        }
    }

    /// A numeric 4 × 4 matrix: its entries as fractions (`29/81`) if every one is a fraction
    /// within rounding (read as formulas read their constants), else to 6 significant digits.
    pub fn matrix(m: &Matrix4<f64>) -> Math {
        let scale = m.iter().fold(0.0f64, |s, x| s.max(x.abs()));
        // fractions only if every entry is one (as formulas read their constants)
        let read = m.iter().all(|x| super::coef::Coef::readable(*x, scale));
        let cell = |x: f64| -> String {
            if x == 0.0 {
                "0".into()
            } else if let Some((p, q)) = read
                .then(|| super::coef::Coef::read(x, scale).fraction())
                .flatten()
                .filter(|&(_, q)| q > 1)
            {
                format!("{p}/{q}")
            } else {
                let s = format!("{x:.6}");
                let s = format!("{}", s.parse::<f64>().unwrap_or(x));
                s
            }
        };
        let rows: Vec<Vec<String>> = (0..4)
            .map(|i| (0..4).map(|j| cell(m[(i, j)])).collect())
            .collect();
        let plain = format!(
            "[{}]",
            rows.iter()
                .map(|r| r.join(", "))
                .collect::<Vec<_>>()
                .join("; ")
        );
        let latex = crate::printed::latex_matrix(&rows);
        let mathml_cells: Vec<Vec<String>> = rows
            .iter()
            .map(|r| {
                r.iter()
                    .map(|x| match x.strip_prefix('-') {
                        Some(pos) => format!("<mo>\u{2212}</mo><mn>{pos}</mn>"),
                        None => format!("<mn>{x}</mn>"),
                    })
                    .collect()
            })
            .collect();
        let mathml = crate::printed::mathml_matrix(&mathml_cells);
        Math {
            plain,
            latex,
            mathml,
        }
    }
}

impl MathTable {
    /// Functions named `name₀, name₁, …` of the variable `var`, one row each:
    /// `MathTable::named("H", "t", &hermite_basis_formulas()?)`.
    pub fn named(name: &str, var: &str, formulas: &[Formula]) -> MathTable {
        MathTable {
            header: Vec::new(),
            rows: formulas
                .iter()
                .enumerate()
                .map(|(i, f)| {
                    let label = Math {
                        plain: format!("{name}_{i}({var}) ="),
                        latex: format!("{name}_{{{i}}}({var}) ="),
                        mathml: format!(
                            "<msub><mi>{}</mi><mn>{i}</mn></msub><mo>(</mo><mi>{}</mi><mo>)</mo><mo>=</mo>",
                            escape(name),
                            escape(var)
                        ),
                    };
                    vec![label, Math::from(f)]
                })
                .collect(),
            notes: Vec::new(),
        }
    }
}

/// A table of mathematics: a header row, rows of cells (the first usually a label) and notes
/// (the conditions under which the formulas hold).
#[derive(Debug, Clone, PartialEq)]
pub struct MathTable {
    /// The header cells (none: no header row).
    pub header: Vec<Math>,
    /// The rows.
    pub rows: Vec<Vec<Math>>,
    /// Notes printed under the table (plain text).
    pub notes: Vec<String>,
}

impl MathTable {
    /// Plain text, as a terminal shows it: the columns aligned, two spaces apart, a rule
    /// under the header, the notes under the table.
    pub fn plain(&self) -> String {
        let mut lines: Vec<Vec<&str>> = Vec::new();
        if !self.header.is_empty() {
            lines.push(self.header.iter().map(|m| m.plain.as_str()).collect());
        }
        lines.extend(
            self.rows
                .iter()
                .map(|r| r.iter().map(|m| m.plain.as_str()).collect()),
        );
        let columns = lines.iter().map(Vec::len).max().unwrap_or(0);
        let widths: Vec<usize> = (0..columns)
            .map(|k| {
                lines
                    .iter()
                    .filter_map(|l| l.get(k))
                    .map(|c| c.chars().count())
                    .max()
                    .unwrap_or(0)
            })
            .collect();
        let line = |cells: &[&str]| -> String {
            let padded: Vec<String> = cells
                .iter()
                .enumerate()
                .map(|(k, c)| format!("{c:<w$}", w = widths[k]))
                .collect();
            padded.join("  ").trim_end().to_string()
        };
        let mut out: Vec<String> = Vec::new();
        for (i, cells) in lines.iter().enumerate() {
            out.push(line(cells));
            if i == 0 && !self.header.is_empty() {
                let total = widths.iter().sum::<usize>() + 2 * columns.saturating_sub(1);
                out.push("-".repeat(total));
            }
        }
        out.extend(self.notes.iter().cloned());
        out.join("\n")
    }

    /// LaTeX: an `array` (for `$$ … $$`), the notes as `\text` lines under it.
    pub fn latex(&self) -> String {
        let columns = self
            .rows
            .iter()
            .map(Vec::len)
            .chain([self.header.len()])
            .max()
            .unwrap_or(1);
        let line = |cells: &[Math]| {
            cells
                .iter()
                .map(|c| c.latex.as_str())
                .collect::<Vec<_>>()
                .join(" & ")
        };
        let mut body: Vec<String> = Vec::new();
        if !self.header.is_empty() {
            body.push(line(&self.header));
        }
        body.extend(self.rows.iter().map(|r| line(r)));
        let mut out = format!(
            "\\begin{{array}}{{{}}}\n{}\n\\end{{array}}",
            "l".repeat(columns),
            body.join(" \\\\\n")
        );
        for n in &self.notes {
            out.push_str(&format!("\\\\ \\text{{{}}}", latex_text(n)));
        }
        out
    }

    /// HTML: a `<math display="block">` table, the notes as a paragraph.
    pub fn html(&self) -> String {
        let row = |cells: &[Math]| {
            format!(
                "<mtr>{}</mtr>",
                cells
                    .iter()
                    .map(|c| format!(
                        "<mtd style=\"text-align:left;padding:0.2em 0.8em\"><mstyle displaystyle=\"true\">{}</mstyle></mtd>",
                        c.mathml
                    ))
                    .collect::<String>()
            )
        };
        let mut rows = if self.header.is_empty() {
            String::new()
        } else {
            row(&self.header)
        };
        for r in &self.rows {
            rows.push_str(&row(r));
        }
        let mut out =
            format!("<math display=\"block\"><mtable columnalign=\"left\">{rows}</mtable></math>");
        for n in &self.notes {
            out.push_str(&format!("<p>{}</p>", escape(n)));
        }
        out
    }

    /// Shows the table as rendered mathematics (the evcxr kernel calls this for a cell's
    /// value): one output with a `text/html` (MathML) and a `text/latex` representation.
    pub fn evcxr_display(&self) {
        println!(
            "EVCXR_BEGIN_CONTENT text/html\n{}\nEVCXR_END_CONTENT",
            self.html()
        );
        println!(
            "EVCXR_BEGIN_CONTENT text/latex\n$${}$$\nEVCXR_END_CONTENT",
            self.latex()
        );
    }
}

impl Formula {
    /// Shows the formula as rendered mathematics in a notebook (MathML and LaTeX).
    pub fn evcxr_display(&self) {
        show_math(&self.mathml(), &self.latex());
    }
}

/// Prints one notebook output with a `text/html` (block MathML) and a `text/latex`
/// representation.
fn show_math(mathml: &str, latex: &str) {
    println!(
        "EVCXR_BEGIN_CONTENT text/html\n<math display=\"block\">{mathml}</math>\nEVCXR_END_CONTENT"
    );
    println!("EVCXR_BEGIN_CONTENT text/latex\n$${latex}$$\nEVCXR_END_CONTENT");
}

/// Text for `\text{…}`: LaTeX's special characters escaped.
fn latex_text(s: &str) -> String {
    let mut out = String::new();
    for c in s.chars() {
        match c {
            '\\' => out.push_str("\\backslash "),
            '{' | '}' | '_' | '^' | '#' | '$' | '%' | '&' => {
                out.push('\\');
                out.push(c);
            }
            _ => out.push(c),
        }
    }
    out
}

impl Math {
    /// A name as LaTeX writes it — letters, digits, commands (`\det`, `\lambda`), each
    /// with an optional subscript and superscript, braced or one character: `K`, `H_0(t)`,
    /// `K^{-1}`, `A^T`, `C^{(ij)}`, `N_{i,3}`, `\det K`, `\lambda_k(H_j)` — in both notations
    /// (the LaTeX as given, the MathML parsed from it).
    pub fn name(name: &str) -> Math {
        let chars: Vec<char> = name.chars().collect();
        Math {
            plain: name_plain(name),
            latex: name.to_string(),
            mathml: name_mathml(&chars),
        }
    }

    /// A polynomial with exact coefficients in the variable `var`.
    pub fn polynomial(p: &Polynomial<Rational>, var: &str) -> Math {
        Math {
            plain: p.plain(var),
            latex: p.latex(var),
            mathml: p.mathml(var),
        }
    }

    /// Shows the mathematics inline in a notebook (MathML and LaTeX).
    pub fn evcxr_display(&self) {
        show_math(&self.mathml, &self.latex);
    }
}

impl<W: Written> From<&W> for Math {
    fn from(x: &W) -> Math {
        Math {
            plain: x.plain(),
            latex: x.latex(),
            mathml: x.mathml(),
        }
    }
}

/// A LaTeX name as plain text: Greek commands as their letters, other commands without the
/// backslash, braces dropped (`\lambda_k(H_j)` → `λ_k(H_j)`, `K^{-1}` → `K^-1`).
fn name_plain(name: &str) -> String {
    let mut out = String::new();
    let mut rest = name;
    while let Some(c) = rest.chars().next() {
        if c == '\\' {
            let word: String = rest[1..]
                .chars()
                .take_while(|c| c.is_ascii_alphabetic())
                .collect();
            match GREEK.iter().find(|(n, _)| *n == word) {
                Some((_, letter)) => out.push(*letter),
                None => out.push_str(&word),
            }
            rest = &rest[1 + word.len()..];
            if word.is_empty() {
                // an escaped symbol (`\,`): the symbol itself
                if let Some(next) = rest.chars().next() {
                    out.push(next);
                    rest = &rest[next.len_utf8()..];
                }
            }
            continue;
        }
        if c != '{' && c != '}' {
            out.push(c);
        }
        rest = &rest[c.len_utf8()..];
    }
    out
}

/// The Greek letters a name may write as commands, by their LaTeX names.
const GREEK: [(&str, char); 24] = [
    ("alpha", 'α'),
    ("beta", 'β'),
    ("gamma", 'γ'),
    ("delta", 'δ'),
    ("epsilon", 'ε'),
    ("zeta", 'ζ'),
    ("eta", 'η'),
    ("theta", 'θ'),
    ("iota", 'ι'),
    ("kappa", 'κ'),
    ("lambda", 'λ'),
    ("mu", 'μ'),
    ("nu", 'ν'),
    ("xi", 'ξ'),
    ("pi", 'π'),
    ("rho", 'ρ'),
    ("sigma", 'σ'),
    ("tau", 'τ'),
    ("phi", 'φ'),
    ("chi", 'χ'),
    ("psi", 'ψ'),
    ("omega", 'ω'),
    ("Lambda", 'Λ'),
    ("Delta", 'Δ'),
];

/// MathML of a name's characters: atoms (a command, a digit run, a letter, another
/// character), each with the subscript and superscript that follow it.
fn name_mathml(chars: &[char]) -> String {
    let mut out = String::new();
    let mut i = 0;
    while i < chars.len() {
        let (atom, next) = name_atom(chars, i);
        i = next;
        let (mut sub, mut sup) = (None, None);
        while i < chars.len() && (chars[i] == '_' || chars[i] == '^') {
            let (group, next) = name_group(chars, i + 1);
            let group = Some(name_mathml(group));
            if chars[i] == '_' {
                sub = group;
            } else {
                sup = group;
            }
            i = next;
        }
        let wrap = |m: String| format!("<mrow>{m}</mrow>");
        out.push_str(&match (sub, sup) {
            (None, None) => atom,
            (Some(b), None) => format!("<msub>{atom}{}</msub>", wrap(b)),
            (None, Some(p)) => format!("<msup>{atom}{}</msup>", wrap(p)),
            (Some(b), Some(p)) => format!("<msubsup>{atom}{}{}</msubsup>", wrap(b), wrap(p)),
        });
    }
    out
}

/// The atom at `i` as MathML and the index after it (spaces give an empty atom).
fn name_atom(chars: &[char], i: usize) -> (String, usize) {
    let c = chars[i];
    let run = |from: usize, keep: fn(char) -> bool| {
        let end = chars[from..]
            .iter()
            .position(|&c| !keep(c))
            .map_or(chars.len(), |k| from + k);
        (chars[from..end].iter().collect::<String>(), end)
    };
    match c {
        '\\' => {
            let (word, end) = run(i + 1, |c| c.is_ascii_alphabetic());
            let end = end.max(i + 1);
            match GREEK.iter().find(|(w, _)| *w == word) {
                Some((_, g)) => (format!("<mi>{g}</mi>"), end),
                // a function name (`\det`): upright, then the invisible function application,
                // which spaces it from its argument
                None => (format!("<mi>{}</mi><mo>\u{2061}</mo>", escape(&word)), end),
            }
        }
        c if c.is_ascii_digit() => {
            let (digits, end) = run(i, |c| c.is_ascii_digit());
            (format!("<mn>{digits}</mn>"), end)
        }
        ' ' => (String::new(), i + 1),
        '-' => ("<mo>\u{2212}</mo>".to_string(), i + 1),
        c if c.is_alphabetic() => (format!("<mi>{}</mi>", escape(&c.to_string())), i + 1),
        c => (format!("<mo>{}</mo>", escape(&c.to_string())), i + 1),
    }
}

/// The script group at `i` (`{…}` with nested braces, or one character) and the index after.
fn name_group(chars: &[char], i: usize) -> (&[char], usize) {
    match chars.get(i) {
        None => (&[], i),
        Some('{') => {
            let mut depth = 0;
            for (k, &c) in chars.iter().enumerate().skip(i) {
                match c {
                    '{' => depth += 1,
                    '}' => {
                        depth -= 1;
                        if depth == 0 {
                            return (&chars[i + 1..k], k + 1);
                        }
                    }
                    _ => {}
                }
            }
            (&chars[i + 1..], chars.len())
        }
        Some(_) => (&chars[i..i + 1], i + 1),
    }
}

impl MathTable {
    /// An empty table, to which [`MathTable::eq`] adds rows.
    pub fn new() -> MathTable {
        MathTable {
            header: Vec::new(),
            rows: Vec::new(),
            notes: Vec::new(),
        }
    }

    /// The table with one more row `name = value` (`name` as [`Math::name`] reads it):
    /// `MathTable::new().eq("K", &k).eq("K^{-1}", &k_inv)`.
    pub fn eq(mut self, name: &str, value: impl Into<Math>) -> MathTable {
        let mut label = Math::name(name);
        label.latex.push_str(" =");
        label.mathml.push_str("<mo>=</mo>");
        self.rows.push(vec![label, value.into()]);
        self
    }

    /// Polynomials with exact coefficients named `name₀, name₁, …` of the variable `var`, one
    /// row each: `MathTable::polynomials("H", "t", &basis)`.
    pub fn polynomials(name: &str, var: &str, polynomials: &[Polynomial<Rational>]) -> MathTable {
        polynomials
            .iter()
            .enumerate()
            .fold(MathTable::new(), |table, (i, p)| {
                table.eq(&format!("{name}_{{{i}}}({var})"), Math::polynomial(p, var))
            })
    }

    /// A triangle of exact values, level by level, one row each: entry `i` of level `r` named
    /// `name_i^r` (`MathTable::levels("P", &de_casteljau_levels(&points, u)?)`: the control
    /// points `P_i^0`, then each level of interpolation down to `P_0^n`, the curve point).
    pub fn levels<W: Written>(name: &str, levels: &[Vec<W>]) -> MathTable {
        let mut table = MathTable::new();
        for (r, level) in levels.iter().enumerate() {
            for (i, value) in level.iter().enumerate() {
                table = table.eq(&format!("{name}_{{{i}}}^{{{r}}}"), value);
            }
        }
        table
    }

    /// The table with one more note under it (plain text).
    pub fn note(mut self, text: &str) -> MathTable {
        self.notes.push(text.to_string());
        self
    }
}

/// [`MathTable::plain`].
impl std::fmt::Display for MathTable {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.plain())
    }
}

impl Default for MathTable {
    fn default() -> MathTable {
        MathTable::new()
    }
}
