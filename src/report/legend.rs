//! Legend text: the words figures and tables use for the mathematics' named choices (a
//! method, an end condition, a node family…). The math core names its choices with enums and
//! prints nothing; the words live here, once each, behind one trait.
//!
//! ```
//! use splinelab::report::Legend;
//! use splinelab::{CubicEnd, Method};
//! assert_eq!(Method::Cubic { end: CubicEnd::Cyclic }.legend(), "Cubic cyclic");
//! assert_eq!(Method::Cardinal { a: 0.83 }.legend(), "Cardinal (a = 0.83)");
//! ```

use crate::blending::functions::Blending;
use crate::interp::choice::Start;
use crate::interp::cubic::EndCondition;
use crate::interp::methods::{CubicEnd, Method};
use crate::interp::polynomial::NodeFamily;
use crate::param::Parametrization;
use crate::study::hermite_error::PatchEvaluation;
use crate::study::table_i::Verdict;
use std::borrow::Cow;

/// The text a figure's legend or a table's cell gives a named choice of the mathematics.
pub trait Legend {
    /// The text (`Cubic cyclic`, `chord length`, `Chebyshev`, …).
    fn legend(&self) -> Cow<'static, str>;
}

/// Each enum's words as its [`Legend`], from one match.
macro_rules! legend {
    ($ty:ty, |$v:ident| $text:expr) => {
        impl Legend for $ty {
            fn legend(&self) -> Cow<'static, str> {
                let $v = self;
                Cow::Borrowed($text)
            }
        }
    };
}

legend!(NodeFamily, |f| match f {
    NodeFamily::Equispaced => "equispaced",
    NodeFamily::Chebyshev => "Chebyshev",
});

legend!(CubicEnd, |e| match e {
    CubicEnd::Relaxed => "relaxed",
    CubicEnd::Cyclic => "cyclic",
    CubicEnd::Anticyclic => "anticyclic",
});

legend!(Start, |s| match s {
    Start::ArcLength => "arc length",
    Start::Turning => "turning",
    Start::ShapeParameter => "shape parameter",
    Start::Corners => "corners",
    Start::Symmetric => "symmetric",
    Start::Random => "random",
    Start::Known => "given",
    Start::Fit => "least-squares fit",
    Start::Exact => "exact optimum",
    Start::Pruned => "pruned",
});

legend!(Parametrization, |p| match p {
    Parametrization::Uniform => "uniform",
    Parametrization::ChordLength => "chord length",
    Parametrization::Centripetal => "centripetal",
});

legend!(Blending, |b| match b {
    Blending::Lagrange => "Lagrange 4-point",
    Blending::UniformBSpline => "uniform cubic B-spline",
});

legend!(PatchEvaluation, |e| match e {
    PatchEvaluation::HermiteMatrix => "Hermite matrix form",
    PatchEvaluation::DeCasteljau => "de Casteljau, correct net",
    PatchEvaluation::ReportListing => "report's listing (Codice 7 as printed)",
});

legend!(Verdict, |v| match v {
    Verdict::Agrees => "agrees",
    Verdict::Fewer => "fewer",
    Verdict::More => "more",
    Verdict::NoneWithin => "none within 1 %",
});

impl<const N: usize> Legend for EndCondition<N> {
    fn legend(&self) -> Cow<'static, str> {
        Cow::Borrowed(match self {
            EndCondition::Clamped { .. } => "clamped",
            EndCondition::Natural => "natural (relaxed)",
            EndCondition::Periodic => "periodic (cyclic)",
            EndCondition::Cyclic => "cyclic (open ends)",
            EndCondition::Anticyclic => "anticyclic",
        })
    }
}

impl Legend for Method {
    /// `Angular`, `Cardinal (a = 0.83)`, `Cubic relaxed`, `B-spline order 4`, `Linear`.
    fn legend(&self) -> Cow<'static, str> {
        match *self {
            Method::Angular => "Angular".into(),
            Method::Cardinal { a } => format!("Cardinal (a = {a})").into(),
            Method::Cubic { end } => format!("Cubic {}", end.legend()).into(),
            Method::BSpline { order } => format!("B-spline order {order}").into(),
            Method::Linear => "Linear".into(),
        }
    }
}

/// A method's parameter as seed 004 prints it in Table I (`a = 0.83`, `relaxed`, `order 9`,
/// `—` for a method without one).
pub fn parameter_legend(method: &Method) -> String {
    match *method {
        Method::Angular | Method::Linear => "—".into(),
        Method::Cardinal { a } => format!("a = {a}"),
        Method::Cubic { end } => end.legend().into(),
        Method::BSpline { order } => format!("order {order}"),
    }
}

#[cfg(test)]
mod tests {
    use super::Legend;
    use crate::interp::cubic::EndCondition;
    use crate::interp::methods::{CubicEnd, Method};
    use crate::param::Parametrization;
    use crate::study::hermite_error::PatchEvaluation;

    /// The texts of an enum's variants differ (a legend that named two choices alike would
    /// mislead), and a method's legend names its end condition.
    #[test]
    fn variants_are_told_apart() {
        let ends: Vec<String> = CubicEnd::ALL.iter().map(|e| e.legend().into()).collect();
        assert_eq!(ends, ["relaxed", "cyclic", "anticyclic"]);
        let params: Vec<String> = Parametrization::ALL
            .iter()
            .map(|p| p.legend().into())
            .collect();
        assert_eq!(params.len(), 3);
        assert!(params
            .iter()
            .all(|p| params.iter().filter(|q| *q == p).count() == 1));
        let evaluations: Vec<String> = PatchEvaluation::ALL
            .iter()
            .map(|p| p.legend().into())
            .collect();
        assert!(evaluations
            .iter()
            .all(|p| evaluations.iter().filter(|q| *q == p).count() == 1));
        let m = Method::Cubic {
            end: CubicEnd::Anticyclic,
        };
        assert_eq!(m.legend(), "Cubic anticyclic");
        assert_eq!(EndCondition::<2>::Natural.legend(), "natural (relaxed)");
    }
}
