//! Prints the formulas of two surfaces of one's own and their splines' convergence; with the
//! `report` feature, draws each surface and its convergence into the folder given (default
//! `out/own-crate`).

use my_surfaces::{Associate, Enneper};
use splinelab::prelude::*;
use splinelab::study::hermite_error::{convergence, ConvergenceRow};
use splinelab::symbolic::{surface_formulas, surface_formulas_with_parameters};

/// The observed orders of the max-abs error, or why there is none.
fn orders(rows: &[ConvergenceRow]) {
    println!("   n        h     max |error| (x, y, z)                         order (x, y, z)");
    for row in rows {
        let e = row.errors.max_abs;
        let order = |k: usize| match row.order.and_then(|o| o.max_abs[k]) {
            Some(p) => format!("{p:5.2}"),
            None if row.at_rounding(e[k]) => "  (rounding)".to_string(),
            None => "    —".to_string(),
        };
        println!(
            "{:4} {:8.5}   {:9.2e} {:9.2e} {:9.2e}   {} {} {}",
            row.n,
            row.h,
            e[0],
            e[1],
            e[2],
            order(0),
            order(1),
            order(2)
        );
    }
}

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let out = std::env::args()
        .nth(1)
        .unwrap_or_else(|| "out/own-crate".into());
    let rect = Rect::new(-1.0, 1.0, -1.0, 1.0);
    let bent = Associate {
        theta: std::f64::consts::FRAC_PI_4,
    };

    println!(
        "Enneper's surface\n{}\n",
        surface_formulas(&Enneper, 0.5, 0.25)?
    );
    println!(
        "The associate surface, theta as a symbol\n{}\n",
        surface_formulas_with_parameters(&bent, 0.5, 0.25)?
    );
    let spline = HermiteSurface::uniform(&Enneper, &Rect::new(0.0, 1.0, 0.0, 1.0), 3, 3)?;
    println!(
        "Its Hermite spline on thirds, one patch (local parameters)\n{}\n",
        splinelab::symbolic::patch_formulas(&spline.patch(1, 1))?
    );

    let ns = [1, 2, 4, 8, 16];
    let enneper = convergence(&Enneper, &rect, &ns, 15)?;
    println!("Enneper: the bicubic spline reproduces it (errors at rounding level, no order)");
    orders(&enneper);
    let associate = convergence(&bent, &rect, &ns, 15)?;
    println!("\nThe associate surface at theta = pi/4: order 4 in x and y, z reproduced");
    orders(&associate);

    #[cfg(feature = "report")]
    {
        use splinelab::report::draw;
        let dir = std::path::Path::new(&out);
        for (name, rows) in [("enneper", &enneper), ("associate", &associate)] {
            let figure = draw::convergence(rows, &format!("{name}: max error against h"));
            let written = figure.save(dir, &format!("{name}-convergence"))?;
            println!("wrote {}", written[0].display());
        }
        let figure = Plot3d::new("Enneper's surface")
            .surface(&Enneper, &rect, 40)?
            .figure();
        println!("wrote {}", figure.save(dir, "enneper")?[0].display());
        let figure = Plot3d::new("the associate surface, θ = π/4")
            .surface(&bent, &Rect::new(0.0, 6.3, -1.0, 1.0), 40)?
            .figure();
        println!("wrote {}", figure.save(dir, "associate")?[0].display());
    }
    #[cfg(not(feature = "report"))]
    let _ = out;
    Ok(())
}
