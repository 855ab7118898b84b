//! Formulas laid out for reading: a cell of mathematics in LaTeX and in MathML ([`Math`]) and
//! a table of them ([`MathTable`]), which a notebook shows as rendered mathematics — MathML,
//! which browsers render without a script (so a notebook's HTML copy shows it too), with the
//! LaTeX beside it for front ends that prefer it.

use super::print::{escape, Formula};
use nalgebra::Matrix4;

/// One cell of mathematics, in LaTeX and in presentation MathML.
#[derive(Debug, Clone, PartialEq)]
pub struct Math {
    /// LaTeX (math mode).
    pub latex: String,
    /// MathML (the contents of a `<math>` element).
    pub mathml: String,
}

impl From<&Formula> for Math {
    fn from(f: &Formula) -> Math {
        Math {
            latex: f.latex(),
            mathml: f.mathml(),
        }
    }
}

impl Math {
    /// Text set upright (a label, a heading).
    pub fn text(s: &str) -> Math {
        Math {
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
                latex: name.into(),
                mathml: format!("<mi>{}</mi>", escape(name)),
            };
        }
        Math {
            latex: format!("{name}_{{{sub}}}"),
            mathml: format!(
                "<msub><mi>{}</mi><mi>{}</mi></msub>",
                escape(name),
                escape(sub)
            ),
        }
    }

    /// A numeric 4 × 4 matrix (6 significant digits).
    pub fn matrix(m: &Matrix4<f64>) -> Math {
        let cell = |x: f64| -> String {
            if x == 0.0 {
                "0".into()
            } else {
                let s = format!("{x:.6}");
                let s = format!("{}", s.parse::<f64>().unwrap_or(x));
                s
            }
        };
        let rows: Vec<Vec<String>> = (0..4)
            .map(|i| (0..4).map(|j| cell(m[(i, j)])).collect())
            .collect();
        let latex = format!(
            "\\begin{{pmatrix}}{}\\end{{pmatrix}}",
            rows.iter()
                .map(|r| r.join(" & "))
                .collect::<Vec<_>>()
                .join(" \\\\ ")
        );
        let mathml = format!(
            // brackets drawn as the table's rounded side borders: a stretched `(` needs an
            // OpenType MATH font, which a reader's browser may not have
            "<mrow><mtable style=\"border-left:1.5px solid;border-right:1.5px solid;border-radius:0.5em;padding:0 0.3em\">{}</mtable></mrow>",
            rows.iter()
                .map(|r| format!(
                    "<mtr>{}</mtr>",
                    r.iter()
                        .map(|x| match x.strip_prefix('-') {
                            Some(pos) => format!("<mtd><mo>\u{2212}</mo><mn>{pos}</mn></mtd>"),
                            None => format!("<mtd><mn>{x}</mn></mtd>"),
                        })
                        .collect::<String>()
                ))
                .collect::<String>()
        );
        Math { latex, mathml }
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
        println!(
            "EVCXR_BEGIN_CONTENT text/html\n<math display=\"block\">{}</math>\nEVCXR_END_CONTENT",
            self.mathml()
        );
        println!(
            "EVCXR_BEGIN_CONTENT text/latex\n$${}$$\nEVCXR_END_CONTENT",
            self.latex()
        );
    }
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
