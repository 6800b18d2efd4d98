//! Dependent equations and the circuits behind them.
//!
//! The rank-revealing LDLᵀ of `G = Jn Jnᵀ` (the solver's [`Gram`]) drops each row that lies
//! in the span of the rows eliminated before it; the kept rows are a basis. A dropped row `k`
//! is a unique combination of basis rows, `Jn_k = Σ c_i Jn_i`, found by solving
//! `G c = Jn Jn_kᵀ`; the row with the basis rows of nonzero `c_i` is its *fundamental
//! circuit*: a dependent set from which removing any one row leaves independent rows.
//!
//! With `y = e_k - c`, `yᵀ Jn = 0`. The linearised equations `Jn dx = -rn` can hold on the
//! circuit only if `yᵀ rn = 0`: when it is not, the circuit conflicts where the solve stopped;
//! when it is (within tolerance), the circuit is redundant.

use super::unmerged::{Equations, Linear};
use crate::solve::gram::{Columns, Gram};
use crate::solve::rank;
use crate::solve::Config;

/// A minimal dependent set of rows.
#[derive(Clone, Debug)]
pub(crate) struct Circuit {
    /// The rows, ascending.
    pub rows: Vec<usize>,
    /// Whether the rows cannot hold together to first order.
    pub conflicting: bool,
}

/// The factorisation of the Jacobian's rows and which of them are dependent.
pub(crate) struct Rank {
    pub gram: Gram,
    /// Rows dropped as dependent, ascending.
    pub dropped: Vec<usize>,
    /// The rank tolerance it was read at: the configuration's, or the tighter one the solver
    /// reads a large structure that bends easily at ([`rank::marginal`]).
    pub tolerance: f64,
}

impl Rank {
    /// Factorises at `lin`. `None` when there are no rows or the factorisation fails.
    pub fn new(eqs: &Equations, lin: &Linear, cfg: &Config) -> Option<Self> {
        if eqs.rows == 0 {
            return None;
        }
        let columns = Columns::from_lists(&eqs.columns);
        let mut gram = Gram::new(eqs.rows, &columns)?;
        gram.assemble(&lin.jn);
        let mut tolerance = cfg.rank_tolerance;
        if !gram.factor(0.0, tolerance) {
            return None;
        }
        let first = gram.dropped();
        if let Some(tight) = rank::marginal(&mut gram, eqs.rows, columns.len(), tolerance, &first) {
            tolerance = tight;
        }
        // At a solution the rank is checked where rounding could hide a dependence, as the
        // solver checks it; where the solve stopped short, near-dependence is the conflict
        // itself and is left to the circuits and their verification, only the count checked
        // as the solver checks it.
        let dropped = if lin.r.iter().all(|v| v.abs() <= cfg.tolerance) {
            rank::reveal(&mut gram, &columns, &lin.jn, tolerance)
        } else {
            let mut k = rank::counts_by_unknowns(eqs.rows, columns.len())
                .then(|| Gram::of_unknowns(eqs.rows, &columns))
                .flatten();
            rank::short_of_solution(&mut gram, k.as_mut(), &columns, &lin.jn, tolerance)
        };
        Some(Self {
            gram,
            dropped,
            tolerance,
        })
    }

    /// The rank of the equations.
    pub fn rank(&self, rows: usize) -> usize {
        rows - self.dropped.len()
    }
}

/// Coefficients below this (rows have unit length) are rounding, not dependence.
const COEFF_EPS: f64 = 1e-6;

/// Dropped rows whose circuits are solved for together: the factor is read once for them all
/// (a 20x20 mesh drops about 400 rows, each a solve with a factor of tens of thousands of
/// entries).
pub(crate) const BATCH: usize = 32;

/// The fundamental circuit of every dropped row, classified as conflicting or redundant.
pub(crate) fn circuits(
    eqs: &Equations,
    lin: &Linear,
    rank: &mut Rank,
    cfg: &Config,
) -> Vec<Circuit> {
    let rows = rank.dropped.clone();
    circuits_of(eqs, lin, rank, cfg, &rows)
}

/// The dropped rows whose circuits may conflict, those whose own residuals are largest first
/// (an impossible constraint's, and those of its neighbours, whose circuits are the
/// smallest conflicts), then by row; where few rows are dropped, all of them in order.
///
/// A dropped row `k`'s circuit conflicts when `yᵀ rn`, `y = e_k - c` with `G c = Jn Jn_kᵀ`, is
/// beyond the tolerance it allows, which is at least `tolerance / ‖J_k‖`. `cᵀ rn = Jn_k Jnᵀ z`
/// with `G z = rn` on the rows kept (`G` symmetric), so one solve for `z` (refined once
/// against `Jn`, as the circuits are) measures every dropped row; the rows within half that
/// least tolerance are left out. At the least-squares point of a 75x75 mesh with one
/// impossible diagonal, 509 of its 5,330 dropped rows conflict, and the circuits took four
/// fifths of the time to name its six constraints; 3,385 are left (the others' tolerance
/// also grows with their coefficients, which are not known before).
pub(crate) fn may_conflict(
    eqs: &Equations,
    lin: &Linear,
    rank: &mut Rank,
    cfg: &Config,
) -> Vec<usize> {
    if rank.dropped.len() <= SCREEN_FROM {
        return rank.dropped.clone();
    }
    let (m, n) = (eqs.rows, eqs.columns.len());
    let rn: Vec<f64> = (0..m).map(|i| lin.rn(i)).collect();
    let mut z = rn.clone();
    for &d in &rank.dropped {
        z[d] = 0.0;
    }
    rank.gram.solve(&mut z);
    // One step of refinement: rn - Jn Jnᵀ z on the rows kept.
    let mut w = vec![0.0; n];
    let mut res = vec![0.0; m];
    eqs.mul_t(lin, &z, &mut w);
    eqs.mul(lin, &w, &mut res);
    for (r, &v) in res.iter_mut().zip(&rn) {
        *r = v - *r;
    }
    for &d in &rank.dropped {
        res[d] = 0.0;
    }
    rank.gram.solve(&mut res);
    z.iter_mut().zip(&res).for_each(|(a, d)| *a += d);
    eqs.mul_t(lin, &z, &mut w);
    let mut rows: Vec<(f64, usize)> = rank
        .dropped
        .iter()
        .filter_map(|&k| {
            if lin.inv[k] == 0.0 {
                return Some((f64::INFINITY, k));
            }
            let c_rn: f64 = eqs
                .row_entries(k)
                .map(|(c, ik)| lin.jn[ik as usize] * w[c as usize])
                .sum();
            let ratio = (rn[k] - c_rn).abs() / (cfg.tolerance * lin.inv[k]);
            (!(ratio <= 0.5)).then_some((rn[k].abs(), k))
        })
        .collect();
    rows.sort_by(|a, b| b.0.total_cmp(&a.0).then(a.1.cmp(&b.1)));
    rows.into_iter().map(|(_, k)| k).collect()
}

/// Dropped rows up to which [`may_conflict`] keeps every row: a few batches of circuits, as
/// cheap as finding which need computing.
const SCREEN_FROM: usize = 2 * BATCH;

/// The fundamental circuits of the dropped rows `rows` (of `rank`'s), classified.
pub(crate) fn circuits_of(
    eqs: &Equations,
    lin: &Linear,
    rank: &mut Rank,
    cfg: &Config,
    rows: &[usize],
) -> Vec<Circuit> {
    let m = eqs.rows;
    let mut out = Vec::with_capacity(rows.len());
    let mut b = Vec::new();
    // A basis with a pivot within `REFINE_BELOW` of the rank tolerance leaves rounding of
    // about 1e-6 in the coefficients (the normal equations square its conditioning), as
    // large as `COEFF_EPS`: a circuit then spreads over hundreds of rows (a 75x75 mesh with
    // one impossible diagonal named 234 constraints for 6). One step of refinement against
    // `Jn` itself takes that rounding to the square of it.
    let refine = rank.gram.smallest_kept_pivot() <= cfg.rank_tolerance * REFINE_BELOW;
    let (mut d, mut v) = (Vec::new(), Vec::new());
    for batch in rows.chunks(BATCH) {
        // b = Jn Jn_kᵀ for each row k of the batch, one column after another. An empty row
        // (only constants, or no first-order effect) gets a column of zeros and is not read.
        b.clear();
        b.resize(m * batch.len(), 0.0);
        for (j, &k) in batch.iter().enumerate() {
            let col = &mut b[j * m..(j + 1) * m];
            for (c, ik) in eqs.row_entries(k) {
                let vk = lin.jn[ik as usize];
                for &(row, idx) in &eqs.columns[c as usize] {
                    col[row as usize] += lin.jn[idx as usize] * vk;
                }
            }
        }
        rank.gram.solve_many(&mut b, batch.len());
        if refine {
            refine_once(
                eqs,
                lin,
                &mut rank.gram,
                &rank.dropped,
                batch,
                &mut b,
                &mut d,
                &mut v,
            );
        }
        for (j, &k) in batch.iter().enumerate() {
            if lin.inv[k] == 0.0 {
                // It stands alone and holds or not by its value.
                out.push(Circuit {
                    rows: vec![k],
                    conflicting: !(lin.r[k].abs() <= cfg.tolerance),
                });
                continue;
            }
            let col = &b[j * m..(j + 1) * m];
            let mut rows = vec![k];
            // y = e_k - c: the certificate of dependence, and the test of consistency.
            let (mut s, mut bound) = (lin.rn(k), cfg.tolerance * lin.inv[k]);
            for (i, &c) in col.iter().enumerate() {
                if i != k && c.abs() > COEFF_EPS {
                    rows.push(i);
                    s -= c * lin.rn(i);
                    bound += c.abs() * cfg.tolerance * lin.inv[i];
                }
            }
            rows.sort_unstable();
            out.push(Circuit {
                rows,
                conflicting: !(s.abs() <= bound),
            });
        }
    }
    out
}

/// Kept pivots up to this multiple of the rank tolerance make [`circuits`] refine its
/// coefficients.
const REFINE_BELOW: f64 = 1e4;

/// One step of iterative refinement of the coefficients `b` (one column of `m` per row of
/// `batch`, as solved with `gram`'s factors, `dropped` its dropped rows): the part of each row `Jn_k` the combination
/// `Jnᵀ c` misses, `Jn_kᵀ - Jnᵀ c`, is taken back to the rows, and the correction solved for
/// with the same factors (the corrected semi-normal equations). `d` and `v` are work space.
#[allow(clippy::too_many_arguments)]
fn refine_once(
    eqs: &Equations,
    lin: &Linear,
    gram: &mut Gram,
    dropped: &[usize],
    batch: &[usize],
    b: &mut [f64],
    d: &mut Vec<f64>,
    v: &mut Vec<f64>,
) {
    let (m, n) = (eqs.rows, eqs.columns.len());
    d.clear();
    d.resize(m * batch.len(), 0.0);
    v.resize(n, 0.0);
    for (j, &k) in batch.iter().enumerate() {
        let c = &b[j * m..(j + 1) * m];
        eqs.mul_t(lin, c, v);
        for x in v.iter_mut() {
            *x = -*x;
        }
        for (col, ik) in eqs.row_entries(k) {
            v[col as usize] += lin.jn[ik as usize];
        }
        let dj = &mut d[j * m..(j + 1) * m];
        eqs.mul(lin, v, dj);
        for &r in dropped {
            dj[r] = 0.0;
        }
    }
    gram.solve_many(d, batch.len());
    for (x, dx) in b.iter_mut().zip(d.iter()) {
        *x += dx;
    }
}

/// Whether the point is stationary for the least-squares problem, `Jnᵀ rn ≈ 0`, with residuals
/// left: then `rn` itself is a dependence among the rows it touches, and those rows conflict.
pub(crate) fn stationary_with_residual(eqs: &Equations, lin: &Linear, cfg: &Config) -> bool {
    let rn: Vec<f64> = (0..eqs.rows).map(|i| lin.rn(i)).collect();
    let norm_r = rn.iter().map(|v| v * v).sum::<f64>().sqrt();
    if !(lin.r.iter().any(|v| !(v.abs() <= cfg.tolerance)) && norm_r.is_finite()) {
        return false;
    }
    let mut g = vec![0.0; eqs.columns.len()];
    eqs.mul_t(lin, &rn, &mut g);
    let norm_g = g.iter().map(|v| v * v).sum::<f64>().sqrt();
    norm_g <= 1e-5 * norm_r
}
