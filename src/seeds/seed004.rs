//! Seed 004 (Barsi & Milanesi 1986, *Un confronto operativo fra vari metodi di interpolazione
//! grafica*) as data: the shapes of Table I, the table's printed cells, the rules that place
//! points for each cell (the paper's points were chosen by hand and are lost), the polygonal
//! letter "a" and the Sicilian coastline. Decisions follow `spec/seed004.md` §4–§5 (A5–A20).

use crate::bspline::fit::fit_bspline;
use crate::curve::ParametricCurve;
use crate::error::Result;
use crate::interp::methods::{CubicEnd, Method};
use crate::shapes::Shape;
use nalgebra::Vector2;
use std::f64::consts::{FRAC_PI_2, PI, TAU};

/// The columns of Table I, in the paper's order, with its column names: the circle, the
/// ellipses 0.7 and 0.4 (A: Ellisse 1 = 0.7), the parabola `y = x²` on `|x| ≤ 2` (more closed)
/// and `|x| ≤ 1`, the hyperbola `y = b√(1 + x²)` with `b = 2` and `b = ½`, one period of the
/// sinusoid, the 2 : 1 rectangle.
pub const SHAPES: [(&str, Shape); 9] = [
    ("Circonferenza", Shape::Circle),
    ("Ellisse 1", Shape::Ellipse { ratio: 0.7 }),
    ("Ellisse 2", Shape::Ellipse { ratio: 0.4 }),
    ("Parabola 1", Shape::Parabola { half_width: 2.0 }),
    ("Parabola 2", Shape::Parabola { half_width: 1.0 }),
    ("Iperbole 1", Shape::Hyperbola { b: 2.0 }),
    ("Iperbole 2", Shape::Hyperbola { b: 0.5 }),
    ("Sinusoida", Shape::Sinusoid { periods: 1.0 }),
    (
        "Rettangolo",
        Shape::Rectangle {
            width: 2.0,
            height: 1.0,
        },
    ),
];

/// One printed cell of Table I: a method with its parameter and the number of points the paper
/// counts (repeated points of closed curves included).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PrintedCell {
    /// Column index into [`SHAPES`].
    pub column: usize,
    /// The method and its printed parameter.
    pub method: Method,
    /// The printed number of points.
    pub points: usize,
    /// What the transcription says beside the count, if anything.
    pub note: &'static str,
}

const fn cell(column: usize, method: Method, points: usize) -> PrintedCell {
    PrintedCell {
        column,
        method,
        points,
        note: "",
    }
}

const fn cardinal(a: f64) -> Method {
    Method::Cardinal { a }
}

const fn cubic(end: CubicEnd) -> Method {
    Method::Cubic { end }
}

const fn bspline(order: usize) -> Method {
    Method::BSpline { order }
}

/// The 36 cells of Table I, row by row (Angular, Cardinal, Cubic, B-spline), as printed
/// (spec §3). "Ellisse 1, Angular: 5 punti (?)" cannot be a closed Angular curve (it needs
/// `m + 3 ≥ 6` points); it is kept as printed with a note (A20).
pub const TABLE_I: [PrintedCell; 36] = [
    cell(0, Method::Angular, 6),
    PrintedCell {
        column: 1,
        method: Method::Angular,
        points: 5,
        note: "printed \"5 punti (?)\": a closed Angular curve needs at least 6",
    },
    cell(2, Method::Angular, 9),
    cell(3, Method::Angular, 5),
    cell(4, Method::Angular, 5),
    cell(5, Method::Angular, 5),
    cell(6, Method::Angular, 5),
    cell(7, Method::Angular, 6),
    cell(8, Method::Angular, 15),
    cell(0, cardinal(0.83), 7),
    cell(1, cardinal(0.83), 7),
    cell(2, cardinal(0.83), 7),
    cell(3, cardinal(0.75), 5),
    cell(4, cardinal(0.70), 5),
    cell(5, cardinal(0.5), 5),
    cell(6, cardinal(0.6), 5),
    cell(7, cardinal(0.55), 6),
    cell(8, cardinal(0.001), 7),
    cell(0, cubic(CubicEnd::Relaxed), 11),
    cell(1, cubic(CubicEnd::Relaxed), 11),
    cell(2, cubic(CubicEnd::Cyclic), 15),
    cell(3, cubic(CubicEnd::Relaxed), 7),
    cell(4, cubic(CubicEnd::Relaxed), 5),
    cell(5, cubic(CubicEnd::Relaxed), 5),
    cell(6, cubic(CubicEnd::Relaxed), 5),
    PrintedCell {
        column: 7,
        method: cubic(CubicEnd::Anticyclic),
        points: 5,
        note: "printed \"accolica\" (anticyclic)",
    },
    cell(8, cubic(CubicEnd::Relaxed), 26),
    PrintedCell {
        column: 0,
        method: bspline(9),
        points: 9,
        note: "order 9 = Bézier",
    },
    cell(1, bspline(6), 7),
    cell(2, bspline(5), 5),
    cell(3, bspline(4), 4),
    cell(4, bspline(4), 4),
    cell(5, bspline(4), 4),
    cell(6, bspline(4), 4),
    cell(7, bspline(4), 6),
    cell(8, bspline(2), 5),
];

const RELAXED: Method = cubic(CubicEnd::Relaxed);

/// The letter "a" figures as printed (Figs 9–20): for each of the four versions, the three
/// "homogeneous" methods — Angular, cardinal with its `a`, relaxed cubic — with the number of
/// points each panel's label gives.
pub const LETTER_FIGURES: [[(Method, usize); 3]; 4] = [
    [(Method::Angular, 19), (cardinal(0.8), 22), (RELAXED, 23)],
    [(Method::Angular, 11), (cardinal(0.8), 12), (RELAXED, 12)],
    [(Method::Angular, 8), (cardinal(0.0001), 8), (RELAXED, 17)],
    [(Method::Angular, 8), (cardinal(0.7), 13), (RELAXED, 16)],
];

/// The points of one configuration: the distinct points a method is given (guides included
/// for open shapes) and whether the method closes the curve.
#[derive(Debug, Clone, PartialEq)]
pub struct PointSet {
    /// The points, in order (for a closed curve without the repeats the method adds).
    pub points: Vec<Vector2<f64>>,
    /// Close the curve as the paper does ([`Method::prepared`]).
    pub closed: bool,
    /// The rule that placed them, in words.
    pub rule: &'static str,
}

/// Where the guides of an open shape sit: on the shape, beyond each end by this fraction of
/// the parameter span (the spec's parabola check put them at `±1.1 X`, i.e. 5 %).
pub const GUIDE_OFFSET: f64 = 0.05;

/// How far the Angular rectangle's extra points sit from each corner, as a fraction of the
/// shorter side (three points per corner, "clustered at the corners").
pub const CORNER_OFFSET: f64 = 0.1;

/// The paper's configuration of `method` on `shape` with `count` points as the paper counts
/// them, placed by a stated rule (spec decision A11a): closed shapes get points equally
/// spaced in the shape's parameter from its start (the Angular rectangle: each corner with a
/// point on either side at [`CORNER_OFFSET`]; the cardinal and B-spline rectangle: its
/// corners), open shapes points equally spaced in the parameter with, for the Angular and
/// cardinal splines, two guides on the shape beyond the ends ([`GUIDE_OFFSET`]; the sinusoid:
/// its ends and extrema). B-spline vertices are fitted by least squares to the dense shape
/// ([`fit_bspline`], A10), with the first vertex fixed at the shape's start.
///
/// A count that the method cannot have on the shape (a closed Angular or cardinal curve with
/// fewer than 6) becomes 4 distinct points + 3 (the printed "5 (?)" of the ellipse becomes 7:
/// its 4 axis vertices, A20). The guided sinusoid takes its ends and the extrema between
/// them, at most `count` points in all (its printed 6 exactly).
///
/// # Errors
/// [`crate::error::Error::TooLarge`] for a count beyond [`crate::error::MAX_ELEMENTS`] (nothing is
/// allocated); [`crate::error::Error::NotPositive`] or [`crate::error::Error::OutOfDomain`] for an invalid
/// shape; the errors of the B-spline fit.
pub fn paper_points(shape: &Shape, method: &Method, count: usize) -> Result<PointSet> {
    crate::error::size("paper points", count)?;
    let shape = &shape.validated()?;
    let closed = shape.is_closed();
    let distinct = if closed {
        match method {
            Method::Angular | Method::Cardinal { .. } => count.saturating_sub(3),
            _ => count.saturating_sub(1),
        }
    } else {
        count
    };
    let distinct = match (method, closed) {
        (Method::Angular | Method::Cardinal { .. }, true) if distinct < 3 => 4,
        _ => distinct.max(2),
    };
    let (a, b) = shape.domain();
    if let Method::BSpline { order } = *method {
        if let Shape::Rectangle { .. } = shape {
            return Ok(PointSet {
                points: shape.corners(),
                closed,
                rule: "the corners (order 2 draws the polygon)",
            });
        }
        let dense = shape.reference(720)?;
        let vertices = if closed { distinct + 1 } else { distinct };
        let fit = fit_bspline(&dense, vertices, order, 40)?;
        let mut points = fit.curve.points().to_vec();
        if closed {
            points.pop();
        }
        return Ok(PointSet {
            points,
            closed,
            rule: "least-squares control polygon of the dense shape (A10)",
        });
    }
    let at = |t: f64| shape.point(t);
    if closed {
        if let (Shape::Rectangle { .. }, Method::Angular) = (shape, method) {
            let corners = shape.corners();
            let (x0, x1, y0, y1) = shape.bounding_box();
            let e = CORNER_OFFSET * (x1 - x0).min(y1 - y0);
            let mut points = Vec::new();
            for k in 0..4 {
                let c = corners[k];
                // unit directions scaled first, so tiny sides do not underflow
                let unit = |v: Vector2<f64>| (v / v.amax()).normalize();
                let back = unit(corners[(k + 3) % 4] - c);
                let ahead = unit(corners[(k + 1) % 4] - c);
                // the quarter circle of radius e tangent to both sides at the side points:
                // centre c + e(back + ahead), its midpoint e(1 − 1/√2)(back + ahead) from c
                let (p, q) = (c + back * e, c + ahead * e);
                let mid = c + (back + ahead) * (e * (1.0 - std::f64::consts::FRAC_1_SQRT_2));
                points.extend([p, mid, q]);
            }
            crate::error::derived_points("Angular rectangle points", &points)?;
            return Ok(PointSet {
                points,
                closed,
                rule: "each corner rounded: a point on either side and the midpoint of the quarter circle tangent there (clustered at the corners; the corner itself would make a collinear triple, which has no G¹ Angular piece)",
            });
        }
        if let (Shape::Rectangle { .. }, Method::Cardinal { .. }) = (shape, method) {
            return Ok(PointSet {
                points: shape.corners(),
                closed,
                rule: "the corners",
            });
        }
        let points = (0..distinct)
            .map(|i| at(a + (b - a) * i as f64 / distinct as f64))
            .collect();
        return Ok(PointSet {
            points,
            closed,
            rule: "equally spaced in the shape's parameter",
        });
    }
    let guided = matches!(method, Method::Angular | Method::Cardinal { .. });
    let inner = if guided {
        distinct.saturating_sub(2).max(2)
    } else {
        distinct
    };
    let mut ts: Vec<f64> = if let (Shape::Sinusoid { periods }, true) = (shape, guided) {
        // the ends and the extrema in between
        let mut ts = vec![a];
        let mut x = FRAC_PI_2;
        while x < TAU * periods && ts.len() < inner - 1 {
            ts.push(x);
            x += PI;
        }
        ts.push(b);
        ts
    } else {
        (0..inner)
            .map(|i| a + (b - a) * i as f64 / (inner - 1) as f64)
            .collect()
    };
    if guided {
        let g = GUIDE_OFFSET * (b - a);
        ts.insert(0, a - g);
        ts.push(b + g);
    }
    Ok(PointSet {
        points: ts.into_iter().map(at).collect(),
        closed,
        rule: if guided {
            "equally spaced (the sinusoid: ends and extrema), guides on the shape 5 % beyond the ends"
        } else {
            "equally spaced in the shape's parameter"
        },
    })
}

/// The hand-made polygonal letter "a" standing in for the paper's version 3 (made of straight
/// segments: the cardinal spline drew it with `a = 0.0001`): an outer contour of 8 corners and
/// a counter of 4, in a unit em square, counter-clockwise.
pub fn polygonal_a() -> Vec<Vec<Vector2<f64>>> {
    let v = Vector2::new;
    vec![
        vec![
            v(0.0, 0.0),
            v(0.8, 0.0),
            v(0.8, 1.0),
            v(0.05, 1.0),
            v(0.05, 0.85),
            v(0.62, 0.85),
            v(0.62, 0.6),
            v(0.0, 0.6),
        ],
        vec![v(0.18, 0.15), v(0.18, 0.45), v(0.62, 0.45), v(0.62, 0.15)],
    ]
}

/// The coastline of Sicily (`data/sicily-coastline.csv`: Natural Earth 1:10m through
/// `world-atlas` 2.0.2, public domain; 357 points, a closed ring) in kilometres, projected
/// equirectangularly about the mean latitude and measured from the south-west corner of its
/// bounding box, without the repeated closing point.
pub fn coastline() -> Vec<Vector2<f64>> {
    const CSV: &str = include_str!("../../data/sicily-coastline.csv");
    const KM_PER_DEGREE: f64 = 111.195;
    let lonlat: Vec<(f64, f64)> = CSV
        .lines()
        .skip(1)
        .filter_map(|line| {
            let (lon, lat) = line.split_once(',')?;
            Some((lon.trim().parse().ok()?, lat.trim().parse().ok()?))
        })
        .collect();
    let mean_lat = lonlat.iter().map(|p| p.1).sum::<f64>() / lonlat.len() as f64;
    let k = mean_lat.to_radians().cos();
    let mut points: Vec<Vector2<f64>> = lonlat
        .iter()
        .map(|&(lon, lat)| Vector2::new(lon * k * KM_PER_DEGREE, lat * KM_PER_DEGREE))
        .collect();
    if points.len() > 1 && points[0] == points[points.len() - 1] {
        points.pop();
    }
    // from the south-west corner of the bounding box
    let (x0, y0) = points
        .iter()
        .fold((f64::INFINITY, f64::INFINITY), |(x, y), p| {
            (x.min(p.x), y.min(p.y))
        });
    points
        .iter()
        .map(|p| Vector2::new(p.x - x0, p.y - y0))
        .collect()
}

/// `count` points of a closed ring, evenly spaced by index from the first (the stand-in for
/// the paper's hand-chosen coastline points).
pub fn evenly_spaced(points: &[Vector2<f64>], count: usize) -> Vec<Vector2<f64>> {
    let count = count.min(points.len());
    (0..count)
        .map(|i| points[i * points.len() / count])
        .collect()
}

/// Every `step`-th point of `points` (the paper's "1 in 50"), starting with the first.
pub fn decimate(points: &[Vector2<f64>], step: usize) -> Vec<Vector2<f64>> {
    points.iter().step_by(step.max(1)).copied().collect()
}

/// The decimation step that leaves about as many points of [`coastline`] as the paper's 1 in
/// 50 of about 2500 digitised points (≈ 50): our ring has 357 points, so 1 in 7.
pub const COAST_STEP: usize = 7;
