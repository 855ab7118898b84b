//! The notebooks' "Try it" figures from a program: your own surface, partition, knots and
//! points, drawn and tabulated with the public API, written to `out/try-it/`.
//!
//! `cargo run --release --example try_it`

use splinelab::prelude::*;
use splinelab::report::{draw, table};
use splinelab::{guide_point, CubicEnd, Method};
use std::path::Path;

fn main() -> std::result::Result<(), splinelab::report::Error> {
    let dir = Path::new("out/try-it");
    // 02: a surface of one's own, its corners and corner derivatives
    let mine = FnSurface::boxed(|s, t| Vector3::new(s, t, (s * 2.0).sin() * (-t * t).exp()));
    let rect = Rect::new(0.0, 1.5, -1.0, 1.0);
    Plot3d::new("my surface, its corners and corner derivatives")
        .surface(&mine, &rect, 30)?
        .corners(&mine, &rect)
        .derivatives(&mine, &rect)
        .figure()
        .save(dir, "surface")?;
    table::tabulation(&mine, &rect, 3, 3)?.write(dir)?;
    // 05: a partition of one's own, the patches, the seams, the error map
    let torus = Torus::default();
    let spline = HermiteSurface::try_from_surface(
        &torus,
        Partition::try_new(vec![0.0, 0.2, 0.7, 1.0])?,
        Partition::try_new(vec![0.0, 0.4, 1.0])?,
    )?;
    Plot3d::new("my partition")
        .view(splinelab::report::seed000::figures::PATCH_VIEW)
        .spline(&spline)?
        .figure()
        .save(dir, "partition")?;
    table::seam_continuity(&spline, 11)?.write(dir)?;
    draw::error_map(&torus, &spline, 81)?.save(dir, "error-map")?;
    // 06: a convergence study of one's own surface
    let rows = splinelab::study::hermite_error::convergence(&mine, &rect, &[1, 2, 4, 8, 16], 15)?;
    draw::convergence(&rows, "my convergence study").save(dir, "convergence")?;
    // 07: knots, degree, control points and weights of one's own
    let basis = BSplineBasis::try_new(
        KnotVector::try_new(vec![0.0, 0.0, 0.0, 0.0, 0.3, 0.5, 0.5, 1.0, 1.0, 1.0, 1.0])?,
        3,
    )?;
    let points = vec![
        Vector2::new(0.0, 0.0),
        Vector2::new(1.0, 2.0),
        Vector2::new(2.5, 2.5),
        Vector2::new(4.0, 0.5),
        Vector2::new(5.5, 2.0),
        Vector2::new(7.0, 2.2),
        Vector2::new(8.0, 0.0),
    ];
    let weights = vec![1.0, 1.0, 4.0, 1.0, 1.0, 1.0, 1.0];
    draw::bases(&basis, "my basis").save(dir, "basis")?;
    let bspline = BSplineCurve::try_new(basis.clone(), points.clone())?;
    Plot2d::new("my B-spline and NURBS curves", "x", "y")
        .control_polygon("control polygon", &points)
        .curve("B-spline", &bspline)?
        .curve(
            "NURBS with my weights",
            &NurbsCurve::try_new(basis, points.clone(), weights)?,
        )?
        .tangents(&bspline, &[0.25, 0.6], 0.15)
        .equal()
        .figure()
        .save(dir, "curves")?;
    // 08: de Casteljau for one's own points
    draw::de_casteljau(
        &points[..5],
        &[0.2, 0.5, 0.8],
        "my de Casteljau construction",
    )?
    .save(dir, "de-casteljau")?;
    // 10: one's own points with seed 004's four methods, and a guide for a given tangent
    let mine = vec![
        Vector2::new(0.0, 0.0),
        Vector2::new(1.0, 1.2),
        Vector2::new(2.2, 1.5),
        Vector2::new(3.0, 0.4),
        Vector2::new(4.1, -0.3),
        Vector2::new(5.0, 0.6),
        Vector2::new(6.0, 1.4),
    ];
    let methods = [
        Method::Angular,
        Method::Cardinal { a: 0.5 },
        Method::Cubic {
            end: CubicEnd::Relaxed,
        },
        Method::BSpline { order: 4 },
    ];
    let cases: Vec<_> = methods.iter().map(|&m| (m, mine.clone(), false)).collect();
    draw::methods("my points, four methods", &mine, &cases, (2, 2))?.save(dir, "methods")?;
    let angular = AngularSpline::try_new(mine.clone())?;
    let mut steered = mine.clone();
    steered[0] = guide_point(mine[1], mine[2], Vector2::new(0.0, 1.0))?;
    let steered = AngularSpline::try_new(steered)?;
    Plot2d::new("the first tangent steered by a guide point", "x", "y")
        .equal()
        .curve("your Angular spline", &angular)?
        .curve("with the guide for an upward tangent", &steered)?
        .tangents(&steered, &[0.0], 0.3)
        .points("points", &mine)
        .figure()
        .save(dir, "guide-point")?;
    println!("wrote {}", dir.display());
    Ok(())
}
