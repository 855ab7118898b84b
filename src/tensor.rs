//! Tensor-product evaluation of a 4×4 net of points, shared by the Hermite and Bézier forms.
//!
//! Both bicubic forms of seed 000 are `X(s, t) = a(s)ᵀ C b(t) = Σᵢ Σⱼ aᵢ(s) bⱼ(t) Cᵢⱼ` with a
//! basis row `a` (Hermite `H` or Bernstein `B`) and a 4×4 net `C` of points; this module
//! writes that double sum once.

use nalgebra::Vector3;
use num_dual::DualNum;

/// A 4×4 net of points; `net[i][j]` pairs the `i`-th s basis function with the `j`-th t one.
pub type Net = [[Vector3<f64>; 4]; 4];

/// The largest magnitude of a Bézier net entry, `f64::MAX / 16`: on `[0, 1]²` the Bernstein
/// weights sum to 1, so no evaluation of a valid net overflows.
pub const NET_LIMIT: f64 = f64::MAX / 16.0;

/// The largest magnitude of a Hermite matrix entry, `f64::MAX / 32`: the absolute Hermite
/// weights sum to at most `1.25²` on `[0, 1]²`, and the Bézier net of a Hermite matrix
/// (correct or as Codice 7 prints it) has entries at most `(1 + 1/3)² < 2` times as large, so
/// it is a valid net. (Matrices from corner data within [`crate::error::MAX_COORDINATE`] stay
/// at `f64::MAX / 64`.)
pub const HERMITE_LIMIT: f64 = f64::MAX / 32.0;

/// Checks every coordinate of a net is finite and at most `limit` in magnitude.
///
/// # Errors
/// [`crate::Error::NonFinite`] or [`crate::Error::CoordinateTooLarge`].
pub(crate) fn check_net(what: &'static str, net: &Net, limit: f64) -> crate::Result<()> {
    for x in net.iter().flatten().flat_map(|p| p.iter()) {
        crate::error::finite(what, *x)?;
        if x.abs() > limit {
            return Err(crate::Error::CoordinateTooLarge {
                what,
                value: *x,
                max: limit,
            });
        }
    }
    Ok(())
}

/// `Σᵢ Σⱼ a[i] b[j] net[i][j]` for any number type.
pub fn tensor_eval<D: DualNum<Primitive = f64> + Copy>(
    a: &[D; 4],
    b: &[D; 4],
    net: &Net,
) -> Vector3<D> {
    let mut acc = Vector3::zeros();
    for (ai, row) in a.iter().zip(net) {
        let mut inner: Vector3<D> = Vector3::zeros();
        for (bj, c) in b.iter().zip(row) {
            inner += c.map(D::from) * *bj;
        }
        acc += inner * *ai;
    }
    acc
}

/// One sample of a tabulation: which piece (patch row or column) it falls in and the four
/// basis values at its local parameter.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct BasisSample {
    pub piece: usize,
    pub w: [f64; 4],
}

/// Tabulates a grid of patches on `rows × cols` samples into `out` (row-major).
///
/// `nets[p * n_col_pieces + q]` is the patch of row piece `p` and column piece `q`. For each
/// row sample the partial sums `Rⱼ = Σᵢ aᵢ Cᵢⱼ` of every column piece are formed once, so each
/// output point costs four multiply-adds of 3-vectors, `Σⱼ bⱼ Rⱼ`.
pub(crate) fn tabulate_pieces(
    nets: &[Net],
    n_col_pieces: usize,
    rows: &[BasisSample],
    cols: &[BasisSample],
    out: &mut Vec<Vector3<f64>>,
) {
    debug_assert_eq!(nets.len() % n_col_pieces, 0);
    out.clear();
    out.reserve(rows.len() * cols.len());
    let mut partial = vec![[Vector3::<f64>::zeros(); 4]; n_col_pieces];
    for r in rows {
        for (q, pr) in partial.iter_mut().enumerate() {
            let net = &nets[r.piece * n_col_pieces + q];
            for (j, pj) in pr.iter_mut().enumerate() {
                *pj = net[0][j] * r.w[0]
                    + net[1][j] * r.w[1]
                    + net[2][j] * r.w[2]
                    + net[3][j] * r.w[3];
            }
        }
        out.extend(cols.iter().map(|c| {
            let p = &partial[c.piece];
            p[0] * c.w[0] + p[1] * c.w[1] + p[2] * c.w[2] + p[3] * c.w[3]
        }));
    }
}
