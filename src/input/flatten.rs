//! Outlines as polylines: the one place where lines, Bézier curves and elliptical arcs become
//! the points of contours, within a stated distance. The SVG path-data reader
//! ([`super::svg_path`]) and the SVG document reader (`super::svg_document`) both draw
//! through one flattener (a crate-private type).
//!
//! - **Lines** are their end points.
//! - **Cubic Béziers** are halved at `u = ½` (de Casteljau) until both inner control points
//!   lie within the tolerance of the chord; the curve lies in the convex hull of its control
//!   points, so every chord is then within the tolerance of its piece of curve. Quadratics are
//!   first raised to cubics (exactly).
//! - **Elliptical arcs** (SVG's endpoint form, [`SvgArc`]) are cut at equal steps of the
//!   ellipse's angle `Δθ ≤ 4·asin(√(tol / 2r))`, `r` the larger radius: the sagitta of a chord
//!   of angle `Δθ` on the circle of radius `r` is `2r·sin²(Δθ/4) ≤ tol`, and the ellipse, an
//!   image of that circle shrunk along one axis, has no larger sagitta.
//! - **Limits**: a curve needing more than [`MAX_PIECES_PER_CURVE`] pieces within the
//!   tolerance, or a point beyond [`MAX_COORDINATE`], is refused with a message (never a
//!   polyline that misses the tolerance); more than [`MAX_ELEMENTS`] points in all is
//!   [`Error::TooLarge`].

use crate::bezier::de_casteljau::de_casteljau_levels;
use crate::error::{Error, Result, MAX_COORDINATE, MAX_ELEMENTS};
use crate::metrics::curve::segment_distance;
use nalgebra::Vector2;

/// The most segments one curve (Bézier or arc) flattens into (2¹⁶).
pub const MAX_PIECES_PER_CURVE: usize = 1 << 16;

/// A contour of an outline: its points, and whether it is closed (the first point is then
/// repeated at the end).
#[derive(Debug, Clone, PartialEq)]
pub struct Contour {
    /// The flattened points.
    pub points: Vec<Vector2<f64>>,
    /// Whether the contour is closed.
    pub closed: bool,
}

/// An elliptical arc as SVG writes it (the `A` command): radii, the `x`-axis rotation in
/// radians, and the large-arc and sweep flags; its end points are given when it is drawn.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SvgArc {
    /// The radii `(rx, ry)` (their signs are ignored, as SVG says).
    pub radii: Vector2<f64>,
    /// The rotation of the ellipse's `x` axis, radians.
    pub rotation: f64,
    /// The large-arc flag.
    pub large: bool,
    /// The sweep flag (the angle increasing).
    pub sweep: bool,
}

/// Why a piece of an outline is not drawn: the message a reader places at the command or
/// element that asked for it.
type Refusal = String;

/// A refusal as [`Error::Parse`] at line 0: the reader replaces the place with that of the
/// command or element that asked for the piece ([`Flattener`]'s callers).
fn refused(message: Refusal) -> Error {
    Error::Parse {
        what: "outline",
        line: 0,
        column: 0,
        message,
    }
}

/// Draws contours within a tolerance (module docs). Its refusals are [`Error::Parse`] at
/// line 0, which the reader places at the command or element that asked for the piece.
#[derive(Debug, Clone)]
pub(crate) struct Flattener {
    tolerance: f64,
    contours: Vec<Contour>,
    /// Whether the last contour is still open to new points.
    open: bool,
    start: Vector2<f64>,
    pos: Vector2<f64>,
    total: usize,
}

impl Flattener {
    /// A flattener whose polylines lie within `tolerance` of the curves drawn.
    ///
    /// # Errors
    /// [`Error::NotPositive`] unless `tolerance` is positive and finite.
    pub(crate) fn new(tolerance: f64) -> Result<Self> {
        crate::error::positive("outline flattening tolerance", tolerance)?;
        Ok(Flattener {
            tolerance,
            contours: Vec::new(),
            open: false,
            start: Vector2::zeros(),
            pos: Vector2::zeros(),
            total: 0,
        })
    }

    /// Starts a contour at `p`.
    ///
    /// # Errors
    /// A refusal for a point that is not finite or beyond [`MAX_COORDINATE`];
    /// [`Error::TooLarge`] beyond [`MAX_ELEMENTS`] points.
    pub(crate) fn move_to(&mut self, p: Vector2<f64>) -> Result<()> {
        check_point(p).map_err(refused)?;
        self.count(1)?;
        self.contours.push(Contour {
            points: vec![p],
            closed: false,
        });
        self.open = true;
        self.start = p;
        self.pos = p;
        Ok(())
    }

    /// A line to `p`.
    ///
    /// # Errors
    /// As [`Flattener::move_to`].
    pub(crate) fn line_to(&mut self, p: Vector2<f64>) -> Result<()> {
        self.extend(vec![p])
    }

    /// A cubic Bézier from the current point with control points `c1`, `c2` to `p`.
    ///
    /// # Errors
    /// As [`Flattener::move_to`]; a refusal for a curve that needs more than
    /// [`MAX_PIECES_PER_CURVE`] pieces.
    pub(crate) fn cubic_to(
        &mut self,
        c1: Vector2<f64>,
        c2: Vector2<f64>,
        p: Vector2<f64>,
    ) -> Result<()> {
        for q in [c1, c2, p] {
            check_point(q).map_err(refused)?;
        }
        let points = cubic_points(&[self.pos, c1, c2, p], self.tolerance).map_err(refused)?;
        self.extend(points)
    }

    /// A quadratic Bézier from the current point with control point `c` to `p` (raised to a
    /// cubic, exactly).
    ///
    /// # Errors
    /// As [`Flattener::cubic_to`].
    pub(crate) fn quad_to(&mut self, c: Vector2<f64>, p: Vector2<f64>) -> Result<()> {
        let s = self.pos;
        self.cubic_to(s + (c - s) * (2.0 / 3.0), p + (c - p) * (2.0 / 3.0), p)
    }

    /// The elliptical arc `arc` from the current point to `p` (SVG's endpoint form with its
    /// corrections: zero radii draw a line, radii too small for the end points are scaled up,
    /// equal end points draw nothing).
    ///
    /// # Errors
    /// As [`Flattener::cubic_to`]; a refusal for an arc that reaches beyond
    /// [`MAX_COORDINATE`].
    pub(crate) fn arc_to(&mut self, arc: &SvgArc, p: Vector2<f64>) -> Result<()> {
        check_point(p).map_err(refused)?;
        let points = arc.points(self.pos, p, self.tolerance).map_err(refused)?;
        self.extend(points)
    }

    /// Closes the current contour (its first point repeated at its end); the current point
    /// returns to the contour's start.
    pub(crate) fn close(&mut self) {
        if let Some(last) = self.contours.last_mut() {
            if self.open && !last.closed {
                if last.points.last() != Some(&self.start) {
                    last.points.push(self.start);
                    self.total = self.total.saturating_add(1);
                }
                last.closed = true;
            }
        }
        self.open = false;
        self.pos = self.start;
    }

    /// The contours drawn, without those of a single point (a move and nothing drawn from it
    /// draws nothing).
    pub(crate) fn finish(self) -> Vec<Contour> {
        self.contours
            .into_iter()
            .filter(|c| c.points.iter().any(|p| *p != c.points[0]))
            .collect()
    }

    /// Appends `points` to the current contour (a new one at the current point after a close,
    /// as SVG draws on after `Z`).
    fn extend(&mut self, points: Vec<Vector2<f64>>) -> Result<()> {
        for &p in &points {
            check_point(p).map_err(refused)?;
        }
        let Some(&last) = points.last() else {
            return Ok(());
        };
        if !self.open {
            self.move_to(self.pos)?;
        }
        self.count(points.len())?;
        if let Some(c) = self.contours.last_mut() {
            c.points.extend(points);
        }
        self.pos = last;
        Ok(())
    }

    fn count(&mut self, n: usize) -> Result<()> {
        self.total = self.total.saturating_add(n);
        if self.total > MAX_ELEMENTS {
            return Err(Error::TooLarge {
                what: "outline points",
                got: self.total,
                max: MAX_ELEMENTS,
            });
        }
        Ok(())
    }
}

fn check_point(p: Vector2<f64>) -> std::result::Result<(), Refusal> {
    if p.iter().all(|x| x.abs() <= MAX_COORDINATE) {
        Ok(())
    } else {
        Err(point_message(p))
    }
}

fn point_message(p: Vector2<f64>) -> Refusal {
    format!(
        "the point ({}, {}) is not finite or beyond the largest coordinate, {MAX_COORDINATE:e}",
        p.x, p.y
    )
}

fn too_many_pieces(what: &str, tolerance: f64) -> Refusal {
    format!(
        "the {what} needs more than {MAX_PIECES_PER_CURVE} pieces to lie within the flattening tolerance {tolerance:e}: give a larger tolerance"
    )
}

/// The points of the cubic `p` after its start, within `tolerance` (module docs): halved by
/// de Casteljau's triangle ([`de_casteljau_levels`]: the left half is the first point of each
/// level, the right half the last, from the bottom up).
fn cubic_points(
    p: &[Vector2<f64>; 4],
    tolerance: f64,
) -> std::result::Result<Vec<Vector2<f64>>, Refusal> {
    let mut out = Vec::new();
    let mut stack = vec![(*p, 0u32)];
    // depth 16 gives at most MAX_PIECES_PER_CURVE pieces
    while let Some((q, depth)) = stack.pop() {
        let flat = [q[1], q[2]]
            .iter()
            .all(|&c| segment_distance(c, q[0], q[3]) <= tolerance);
        if flat {
            out.push(q[3]);
            continue;
        }
        if (1usize << depth) >= MAX_PIECES_PER_CURVE {
            return Err(too_many_pieces("Bézier curve", tolerance));
        }
        // four points make a triangle of four levels (the call cannot fail on them)
        let Ok(levels) = de_casteljau_levels(&q, 0.5) else {
            return Err(too_many_pieces("Bézier curve", tolerance));
        };
        let left = [0, 1, 2, 3].map(|k| levels[k][0]);
        let right = [3, 2, 1, 0].map(|k| levels[k][levels[k].len() - 1]);
        // the second half first on the stack, so the first half is emitted first
        stack.push((right, depth + 1));
        stack.push((left, depth + 1));
    }
    Ok(out)
}

/// The centre form of an arc: the ellipse `centre + R(rotation)·(rx cos θ, ry sin θ)` from
/// `θ = start` over `sweep` radians.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ArcCentre {
    /// The centre.
    pub centre: Vector2<f64>,
    /// The radii after SVG's correction (scaled up when too small for the end points).
    pub radii: Vector2<f64>,
    /// The start angle `θ₁`.
    pub start: f64,
    /// The signed sweep `Δθ`.
    pub sweep: f64,
}

impl SvgArc {
    /// The arc from `from` to `to` in centre form (SVG 1.1, appendix F.6.5–F.6.6), or `None`
    /// where SVG draws a line (a zero or non-finite radius, or radii so unequal that their ratio
    /// underflows) or nothing (`from == to`: `Some` is never returned then, and the caller
    /// draws nothing).
    ///
    /// Computed in the ellipse's unit-circle coordinates `p̂ = (x′/rx, y′/ry)` of the half
    /// chord, scaled first so no square overflows: `λ = |p̂|²`; for `λ ≥ 1` the radii are
    /// scaled by `√λ` and the centre is the chord's midpoint **exactly** (SVG's radicand
    /// `(1 − λ)/λ` is zero there; computing it from the scaled radii leaves a rounding residue
    /// of order `√ε`), else the centre is `±√((1 − λ)/λ)·(p̂_y, −p̂_x)` in those coordinates.
    pub fn centre_form(&self, from: Vector2<f64>, to: Vector2<f64>) -> Option<ArcCentre> {
        let (rx, ry) = (self.radii.x.abs(), self.radii.y.abs());
        let big = rx.max(ry);
        if from == to || !(rx > 0.0 && ry > 0.0 && big.is_finite()) {
            return None;
        }
        // the radii's shape (the larger 1) and size
        let shape = Vector2::new(rx / big, ry / big);
        if !(shape.x >= 1e-300 && shape.y >= 1e-300) {
            return None;
        }
        let (sin, cos) = self.rotation.sin_cos();
        // the half chord in the ellipse's axes, scaled to a largest component of 1
        let h = (from - to) * 0.5;
        let half = Vector2::new(cos * h.x + sin * h.y, -sin * h.x + cos * h.y);
        let scale = half.amax();
        if !(scale > 0.0 && scale.is_finite()) {
            return None;
        }
        let q = half / scale;
        // p̂ = q · (scale / big) / shape; its length's two factors kept apart
        let unit = Vector2::new(q.x / shape.x, q.y / shape.y);
        let w = unit.norm();
        let k = scale / big;
        let length = k * w; // |p̂| = √λ (may be ∞ for radii negligible beside the chord)
        let (size, p_hat, c_hat) = if length >= 1.0 || length.is_nan() {
            // radii scaled up to pass through both ends: the centre is the midpoint
            (scale * w, unit / w, Vector2::zeros())
        } else {
            let p_hat = unit * k;
            let mut root = ((1.0 - length) * (1.0 + length)).max(0.0).sqrt() / length;
            if self.large == self.sweep {
                root = -root;
            }
            (big, p_hat, Vector2::new(p_hat.y, -p_hat.x) * root)
        };
        let radii = shape * size;
        let c = Vector2::new(radii.x * c_hat.x, radii.y * c_hat.y);
        let centre = Vector2::new(cos * c.x - sin * c.y, sin * c.x + cos * c.y) + (from + to) * 0.5;
        let angle = |v: Vector2<f64>| v.y.atan2(v.x);
        let start = angle(p_hat - c_hat);
        let mut sweep = angle(-p_hat - c_hat) - start;
        let tau = std::f64::consts::TAU;
        if self.sweep && sweep < 0.0 {
            sweep += tau;
        } else if !self.sweep && sweep > 0.0 {
            sweep -= tau;
        }
        Some(ArcCentre {
            centre,
            radii,
            start,
            sweep,
        })
    }

    /// The points of the arc after `from` (the last one `to` exactly), at equal steps of the
    /// angle within `tolerance` (module docs).
    fn points(
        &self,
        from: Vector2<f64>,
        to: Vector2<f64>,
        tolerance: f64,
    ) -> std::result::Result<Vec<Vector2<f64>>, Refusal> {
        if from == to {
            return Ok(Vec::new());
        }
        let Some(arc) = self.centre_form(from, to) else {
            return Ok(vec![to]);
        };
        let r = arc.radii.amax();
        let reach = arc.centre.amax() + r;
        if reach.is_nan() || reach > MAX_COORDINATE {
            return Err(format!(
                "the arc (radii {:e}, {:e}) reaches beyond the largest coordinate, {MAX_COORDINATE:e}",
                arc.radii.x, arc.radii.y
            ));
        }
        let step = 4.0 * (tolerance / (2.0 * r)).sqrt().min(1.0).asin();
        let pieces = (arc.sweep.abs() / step).ceil().max(1.0);
        if pieces.is_nan() || pieces > MAX_PIECES_PER_CURVE as f64 {
            return Err(too_many_pieces("arc", tolerance));
        }
        let pieces = pieces as usize;
        let (sin, cos) = self.rotation.sin_cos();
        let mut out = Vec::with_capacity(pieces);
        for i in 1..pieces {
            let t = arc.start + arc.sweep * (i as f64 / pieces as f64);
            let e = Vector2::new(arc.radii.x * t.cos(), arc.radii.y * t.sin());
            out.push(Vector2::new(cos * e.x - sin * e.y, sin * e.x + cos * e.y) + arc.centre);
        }
        // the end exactly
        out.push(to);
        Ok(out)
    }
}
