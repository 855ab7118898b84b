//! Two minimal surfaces of one's own, written once for points, exact partials and formulas.

use splinelab::prelude::*;

// Enneper's minimal surface, a polynomial of degree 3
surface!(pub Enneper = |s, t| Vector3::new(
    s - s.powi(3) / 3.0 + s * t * t,
    t - t.powi(3) / 3.0 + t * s * s,
    s * s - t * t,
));

#[test]
fn enneper_mixed_partial_is_2t_2s_0() {
    let (s, t) = (0.5, 0.25);
    assert!((Enneper.partials(s, t).dst - Vector3::new(2.0 * t, 2.0 * s, 0.0)).norm() < 1e-12);
}

surface!(
    /// The associate family of the catenoid and the helicoid: the helicoid at `theta = 0`,
    /// the catenoid at `theta = π/2`, isometric to both in between.
    pub Associate { theta: f64 } = |s, t| {
        let (c, d) = (theta.cos(), theta.sin());
        Vector3::new(
            c * t.sinh() * s.sin() + d * t.cosh() * s.cos(),
            d * t.cosh() * s.sin() - c * t.sinh() * s.cos(),
            c * s + d * t,
        )
    }
);

#[cfg(test)]
mod tests {
    use super::*;
    use splinelab::symbolic::{surface_formulas, surface_formulas_with_parameters};

    /// Points of the plane, fixed and spread (no random crate needed).
    fn points() -> impl Iterator<Item = (f64, f64)> {
        (0..49).map(|k| (-1.3 + 0.11 * (k % 7) as f64, -0.9 + 0.27 * (k / 7) as f64))
    }

    fn close(a: Vector3<f64>, b: Vector3<f64>) {
        assert!((a - b).norm() <= 1e-12 * (1.0 + b.norm()), "{a} vs {b}");
    }

    #[test]
    fn enneper_partials_are_the_closed_forms() {
        for (s, t) in points() {
            let d = Enneper.partials(s, t);
            close(
                d.ds,
                Vector3::new(1.0 - s * s + t * t, 2.0 * s * t, 2.0 * s),
            );
            close(
                d.dt,
                Vector3::new(2.0 * s * t, 1.0 + s * s - t * t, -2.0 * t),
            );
            close(d.dst, Vector3::new(2.0 * t, 2.0 * s, 0.0));
        }
    }

    #[test]
    fn associate_partials_are_the_closed_forms() {
        for theta in [
            0.0,
            0.3,
            std::f64::consts::FRAC_PI_4,
            std::f64::consts::FRAC_PI_2,
        ] {
            let (c, d) = (theta.cos(), theta.sin());
            let surface = Associate { theta };
            for (s, t) in points() {
                let p = surface.partials(s, t);
                let (ss, cs, sh, ch) = (s.sin(), s.cos(), t.sinh(), t.cosh());
                close(
                    p.ds,
                    Vector3::new(c * sh * cs - d * ch * ss, d * ch * cs + c * sh * ss, c),
                );
                close(
                    p.dt,
                    Vector3::new(c * ch * ss + d * sh * cs, d * sh * ss - c * ch * cs, d),
                );
                close(
                    p.dst,
                    Vector3::new(c * ch * cs - d * sh * ss, d * sh * cs + c * ch * ss, 0.0),
                );
            }
        }
    }

    #[test]
    fn the_formulas_are_as_written() -> splinelab::Result<()> {
        let f = surface_formulas(&Enneper, 0.5, 0.25)?;
        assert_eq!(f.point[0].plain(), "s - s^3/3 + s*t^2");
        assert_eq!(f.dst[0].plain(), "2*t");
        let g = surface_formulas_with_parameters(&Associate { theta: 0.7 }, 0.5, 0.25)?;
        assert_eq!(g.point[2].plain(), "s*cos(theta) + t*sin(theta)");
        assert_eq!(g.ds[2].plain(), "cos(theta)");
        Ok(())
    }

    #[test]
    fn the_spline_of_a_cubic_is_the_cubic() -> splinelab::Result<()> {
        // the bicubic Hermite spline reproduces Enneper's surface: its formulas are Enneper's
        let spline = HermiteSurface::try_from_surface(
            &Enneper,
            Partition::uniform(0.0, 1.0, 3)?,
            Partition::uniform(0.0, 1.0, 3)?,
        )?;
        let f = surface_formulas(&spline, 0.5, 0.5)?;
        assert_eq!(f.point[1].plain(), "t + s^2*t - t^3/3");
        Ok(())
    }
}
