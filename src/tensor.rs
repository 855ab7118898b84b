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
/// [`crate::error::Error::NonFinite`] or [`crate::error::Error::CoordinateTooLarge`].
pub(crate) fn check_net(what: &'static str, net: &Net, limit: f64) -> crate::error::Result<()> {
    for x in net.iter().flatten().flat_map(|p| p.iter()) {
        crate::error::finite(what, *x)?;
        if x.abs() > limit {
            return Err(crate::error::Error::CoordinateTooLarge {
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

/// Output points from which [`tabulate_pieces`] splits the rows between two threads (below,
/// a thread costs more than it saves).
pub(crate) const TABULATE_PARALLEL_MIN: usize = 1 << 16;

/// Tabulates a grid of patches on `rows × cols` samples into `out` (row-major; its former
/// contents are overwritten, so a reused buffer of the right size is not touched twice).
///
/// `nets[p * n_col_pieces + q]` is the patch of row piece `p` and column piece `q`. For each
/// row sample the partial sums `Rⱼ = Σᵢ aᵢ Cᵢⱼ` of every column piece are formed once, so each
/// output point costs four multiply-adds of 3-vectors, `Σⱼ bⱼ Rⱼ`. From
/// [`TABULATE_PARALLEL_MIN`] points, with `parallel` set, the rows are split in two halves
/// computed on two threads — each row by the same arithmetic, so the result is the same.
pub(crate) fn tabulate_pieces(
    nets: &[Net],
    n_col_pieces: usize,
    rows: &[BasisSample],
    cols: &[BasisSample],
    out: &mut Vec<Vector3<f64>>,
    parallel: bool,
) {
    debug_assert_eq!(nets.len() % n_col_pieces, 0);
    let width = cols.len();
    out.resize(rows.len() * width, Vector3::zeros());
    if width == 0 {
        return;
    }
    let fill = |rows: &[BasisSample], out: &mut [Vector3<f64>]| {
        let mut partial = vec![[Vector3::<f64>::zeros(); 4]; n_col_pieces];
        for (r, line) in rows.iter().zip(out.chunks_exact_mut(width)) {
            for (q, pr) in partial.iter_mut().enumerate() {
                let net = &nets[r.piece * n_col_pieces + q];
                for (j, pj) in pr.iter_mut().enumerate() {
                    *pj = net[0][j] * r.w[0]
                        + net[1][j] * r.w[1]
                        + net[2][j] * r.w[2]
                        + net[3][j] * r.w[3];
                }
            }
            for (o, c) in line.iter_mut().zip(cols) {
                let p = &partial[c.piece];
                *o = p[0] * c.w[0] + p[1] * c.w[1] + p[2] * c.w[2] + p[3] * c.w[3];
            }
        }
    };
    let half = rows.len() / 2;
    let (top_rows, bottom_rows) = rows.split_at(half);
    let (top, bottom) = out.split_at_mut(half * width);
    crate::parallel::join(
        parallel && rows.len() * width >= TABULATE_PARALLEL_MIN,
        || fill(top_rows, top),
        || fill(bottom_rows, bottom),
    );
}
