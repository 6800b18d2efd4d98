//! Newton's steps on the unknowns' side, for components with more equations than unknowns (a
//! triangulated mesh: a distance on every edge, three equations for every two unknowns).
//!
//! [`Component::solve`] takes its steps through `G = J Jᵀ`, one row per equation: on a mesh
//! about a third of them are implied by the others, and every step factorises them all only to
//! drop them again. The same steps come from `K = Jᵀ J`, one row per unknown, which is smaller
//! and sparser there (a mesh's `K` has the pattern of the mesh itself, `G` that of its edges
//! meeting). [`Component::solve_by_unknowns`] takes Gauss-Newton steps through `K` to a
//! solution nearest the drawing; [`Component::solve`] then starts from it, where the
//! equations already hold, and reads the rank and the redundant equations from `G` once, as
//! it would have at the end of its own steps. Where no solution is reached this way (the
//! equations cannot all hold, a step fails), the unknowns are put back and the solve runs as
//! before, so that conflicts are found and named as they always were.
//!
//! A step through `K` solves the equations in the least-squares sense: where they are
//! consistent (as at and near a solution of consistent equations) it is the step through `G`;
//! implied equations that do not hold yet are weighed with the others rather than dropped.
//! Where some unknowns are free (`K` singular, its dependent columns dropped), the step is
//! moved along the free directions to the point nearest the drawing, which is the step
//! through `G` with the slide folded in.

use super::gram::{Columns, Gram};
use super::newton::{
    generic, largest_abs, stationary, Component, Finish, PROJECTED, SLIDE_NOISE, STALE_RANK,
    STATIONARY,
};
use super::rank::{DEPENDENCY_BLOCK, UNION_PROBES};
use super::Config;
use crate::equations::Kernel;

/// Where [`Component::solve_by_unknowns`] ended.
pub(crate) enum Reached {
    /// A solution, after this many steps; the rank is still to be read.
    Solution(usize),
    /// A solution and its rank, read from `K` (see [`Component::solve_by_unknowns`]).
    Finished(Finish),
    /// No solution: the least-squares point of equations that cannot all hold, after this
    /// many steps (see [`STATIONARY`]). The steps through `G` would only descend to it again.
    LeastSquares(usize),
}

/// The most free directions a step is moved along (each costs a solve with `K` and a column
/// of a small dense system); a component with more is left to [`Component::solve`] (a truss,
/// a mechanism, has fewer equations than unknowns anyway).
const MAX_FREE: usize = 8;

/// The most steps: consistent equations from a drawing close to a solution take a handful.
const MAX_STEPS: usize = 30;

/// Steps that each leave more than this fraction of the merit before them show equations that
/// cannot all hold (or a start too far off for plain steps): after [`SLOW_STEPS`] of them in
/// a row, the solve is left to [`Component::solve`].
const SLOW: f64 = 0.5;
const SLOW_STEPS: usize = 4;

/// Slow steps end at a least-squares point rather than give way when, before the last of
/// them, the merit is stationary ([`STATIONARY`]): a residual left there is equations that
/// cannot all hold. A 100x100 mesh with one impossible length reached it in 5 steps (cosine
/// 2e-8), which the steps through `G` then took 13 iterations and 54 factorisations to reach
/// again from the drawing. They go on past [`SLOW_STEPS`] while each shrinks that cosine by
/// this factor or more: they are closing in on it (by 10 a step on a 20x20 mesh).
const CLOSING: f64 = 0.5;

/// Columns of `K` are dropped at this multiple of the rank tolerance (see
/// [`Component::rank_by_unknowns`]), as `rank::reveal` looks again at rows of `J Jᵀ`.
const SUSPECT: f64 = 1e4;

/// Halvings of a step before it counts as failed.
const BACKTRACKS: usize = 12;

impl Component {
    /// Whether [`Component::solve_by_unknowns`] is worth trying: more equations than unknowns,
    /// and enough of them for a second factorisation's structure to pay.
    pub(super) fn by_unknowns(&self, ncols: usize, cfg: &Config) -> bool {
        cfg.unknowns_side && cfg.nearest && ncols >= 64 && self.rows > ncols
    }

    /// Gauss-Newton steps through `K = Jᵀ J` from `x` to a solution nearest the drawing `x`
    /// started at, with `x` left there, or to the least-squares point of equations that cannot
    /// all hold ([`Reached::LeastSquares`]), `x` left there too; `None` (with `x` wherever the
    /// steps left it) when they reached neither.
    ///
    /// At the solution, when more rows depend on the others than [`Component::solve`] would
    /// name one by one (it then names the rows on every circuit through a dependent one, the
    /// support of `J`'s left null space, whichever rows its elimination dropped), the rank and
    /// those rows are read from `K`, and the solve is [`Reached::Finished`]: the rank is the
    /// unknowns less the columns `K` drops, and for a generic `w` the part of `w` outside the
    /// span of `J`'s columns, `w - J u` with `K u = Jᵀ w`, is a generic vector of the left
    /// null space, whose support is those rows. `J Jᵀ`, a third larger than `K` on a mesh and
    /// factorised twice by the rank test, is then not built at all.
    pub(super) fn solve_by_unknowns(
        &mut self,
        kernels: &[Kernel],
        x: &mut [f64],
        values: &[f64],
        cfg: &Config,
    ) -> Option<Reached> {
        if self.unknowns.is_none() {
            self.unknowns = Some(Gram::of_unknowns(self.rows, &self.columns));
        }
        // Out of the component while its steps use the component's equations.
        let mut k = self.unknowns.take()?;
        let steps = match k.as_mut() {
            Some(k) => self.steps_by_unknowns(kernels, x, values, cfg, k),
            None => None,
        };
        self.unknowns = Some(k);
        steps
    }

    /// [`Component::solve_by_unknowns`] with `K`'s structure in `k`.
    fn steps_by_unknowns(
        &self,
        kernels: &[Kernel],
        x: &mut [f64],
        values: &[f64],
        cfg: &Config,
        k: &mut Gram,
    ) -> Option<Reached> {
        let (m, ncols) = (self.rows, x.len());
        let mut xs = Vec::new();
        let mut jl = Vec::new();
        self.gather_all(kernels, x, values, &mut xs);
        let x0 = x.to_vec();
        let mut r = vec![0.0; m];
        let mut jn = vec![0.0; self.nnz];
        let mut inv = vec![0.0; m];
        let mut rt = vec![0.0; m];
        let mut u = vec![0.0; ncols];
        let mut dx = vec![0.0; ncols];
        let mut xt = vec![0.0; ncols];
        let mut t = vec![0.0; m];
        let mut free: Vec<f64> = Vec::new();
        let mut both: Vec<f64> = Vec::new();
        let merit = |r: &[f64], inv: &[f64]| {
            r.iter()
                .zip(inv)
                .map(|(a, b)| (a * b) * (a * b))
                .sum::<f64>()
        };
        let (mut settled, mut last_move, mut slow) = (false, f64::INFINITY, 0usize);
        // The gradient test of the last step (see `STATIONARY`).
        let mut last_level = f64::INFINITY;
        let columns = &self.columns;
        let scale = &self.scale;
        for steps in 0..=MAX_STEPS {
            self.jacobian(kernels, x, &mut r, &mut jn, &mut inv, &mut xs, &mut jl);
            let finite = r.iter().all(|v| v.is_finite());
            let holds = finite && r.iter().all(|v| v.abs() <= cfg.tolerance);
            if holds && (settled || steps == 0) {
                // The last step moved the unknowns by no more than `PROJECTED`: `K` as
                // factorised for it is `K` here but for rounding-sized changes.
                let current = steps > 0 && last_move <= PROJECTED;
                return Some(self.rank_by_unknowns(k, current, &jn, &r, steps, cfg));
            }
            // An equation without a gradient where it does not hold is nudged by the other
            // solve; so is anything not finite.
            if steps == MAX_STEPS
                || !finite
                || r.iter()
                    .zip(&inv)
                    .any(|(&ri, &iv)| iv == 0.0 && ri.abs() > cfg.tolerance)
            {
                return None;
            }
            k.assemble(&jn);
            // At the wider tolerance: a free direction's pivot carries the rounding of every
            // elimination before it, and can land above the rank tolerance (a 30x30 mesh kept
            // its rotation's), leaving the step to swing along it instead of sliding.
            if !k.factor(0.0, cfg.rank_tolerance * SUSPECT) {
                return None;
            }
            let dropped = k.dropped();
            if dropped.len() > MAX_FREE {
                return None;
            }
            // The least-squares step with the free unknowns left where they are:
            // K u = -Jnᵀ rn.
            for (c, col) in columns.iter().enumerate() {
                let mut acc = 0.0;
                for &(row, idx) in col {
                    acc -= jn[idx as usize] * r[row as usize] * inv[row as usize];
                }
                u[c] = acc;
            }
            if dropped.is_empty() {
                k.solve(&mut u);
            } else {
                // With the free directions' right-hand sides, in one pass over the factor
                // (which, on a large mesh, costs about what one right-hand side does).
                free_rhs(columns, &jn, &dropped, &mut free, &mut t);
                both.clear();
                both.extend_from_slice(&u);
                both.extend_from_slice(&free);
                k.solve_many(&mut both, 1 + dropped.len());
                u.copy_from_slice(&both[..ncols]);
                free.copy_from_slice(&both[ncols..]);
                free_finish(&mut free, &dropped, ncols);
            }
            for &d in &dropped {
                u[d] = 0.0;
            }
            if !dropped.is_empty() {
                let nf = dropped.len();
                // Along them to the point nearest the drawing: u + V a, with
                // (Vᵀ V) a = Vᵀ (z - u) and z the drawing in scaled unknowns.
                let mut a = vec![0.0; nf * nf];
                let mut rhs = vec![0.0; nf];
                for i in 0..nf {
                    let vi = &free[i * ncols..(i + 1) * ncols];
                    for j in 0..=i {
                        let vj = &free[j * ncols..(j + 1) * ncols];
                        let s: f64 = vi.iter().zip(vj).map(|(p, q)| p * q).sum();
                        a[i * nf + j] = s;
                        a[j * nf + i] = s;
                    }
                    rhs[i] = (0..ncols)
                        .map(|c| vi[c] * ((x0[c] - x[c]) / scale[c] - u[c]))
                        .sum();
                }
                if !solve_small(&mut a, &mut rhs, nf) {
                    return None;
                }
                for (f, &w) in rhs.iter().enumerate() {
                    let v = &free[f * ncols..(f + 1) * ncols];
                    u.iter_mut().zip(v).for_each(|(p, q)| *p += w * q);
                }
            }
            for c in 0..ncols {
                dx[c] = u[c] * scale[c];
            }
            // From a solution, the whole step: it only slides along the solutions, and the
            // steps after it restore what its curvature breaks.
            let m0 = merit(&r, &inv);
            // The gradient test, only once this step or the next can be the last slow one.
            let level = if slow + 2 >= SLOW_STEPS {
                stationary(columns, &jn, &r, &inv, m0)
            } else {
                f64::INFINITY
            };
            let mut alpha = 1.0;
            let mut accepted = false;
            for _ in 0..BACKTRACKS {
                for c in 0..ncols {
                    xt[c] = x[c] + alpha * dx[c];
                }
                self.residuals(kernels, &xt, &mut rt, &mut xs);
                let mt = merit(&rt, &inv);
                if mt.is_finite() && (holds || mt < m0 || mt == 0.0) {
                    accepted = true;
                    slow = if mt > SLOW * m0 { slow + 1 } else { 0 };
                    break;
                }
                alpha *= 0.5;
            }
            if !accepted {
                return None;
            }
            if slow >= SLOW_STEPS && !holds {
                if level <= STATIONARY {
                    x.copy_from_slice(&xt);
                    return Some(Reached::LeastSquares(steps + 1));
                }
                // Still on the way to it while the cosine shrinks fast; otherwise the steps
                // give way.
                if !(level <= CLOSING * last_level) {
                    return None;
                }
            }
            last_level = level;
            x.copy_from_slice(&xt);
            let before = last_move;
            last_move = if alpha == 1.0 {
                super::newton::relative_move(&dx, x)
            } else {
                f64::INFINITY
            };
            // As the folded slide settles (see `Component::solve`): a step below `PROJECTED`,
            // one below `SLIDE_NOISE` that no longer shrinks, or one shrinking at a rate `q`
            // at which the steps still to come add up to `PROJECTED` or less (`q / (1 - q)`
            // times the last).
            let rate = last_move / before;
            settled = last_move <= PROJECTED
                || (last_move <= SLIDE_NOISE && last_move >= 0.5 * before)
                || (last_move <= SLIDE_NOISE
                    && before.is_finite()
                    && rate < 0.5
                    && last_move * rate / (1.0 - rate) <= PROJECTED);
            // A whole step that settles the slide where the equations hold ends the steps
            // without another Jacobian, as the steps through `G` end (see
            // `Component::solve`): the rank is read from `K` as factorised for this step, with
            // the Jacobian it was factorised from, at the point the step left (by
            // `last_move`): within `PROJECTED`, or within `SLIDE_NOISE` where the kept pivots
            // are far above the rank tolerance, which so small a move cannot bring them near.
            // A 10x10 mesh slides 7e-6, 2e-9 (at a rate of 3e-4: settled) and took a step of
            // 7e-13 and a Jacobian more to see it.
            if alpha == 1.0
                && settled
                && rt.iter().all(|v| v.abs() <= cfg.tolerance)
                && (last_move <= PROJECTED
                    || k.smallest_kept_pivot() >= STALE_RANK * cfg.rank_tolerance)
            {
                return Some(self.rank_by_unknowns(k, true, &jn, &rt, steps + 1, cfg));
            }
        }
        None
    }
}

/// Into `free` (`dropped.len()` vectors of the unknowns, one after another), each direction in
/// which the equations (the columns of `J`, values `jn`) do not move, from `k` factorised with
/// the columns `dropped` dropped: 1 on its dropped unknown, 0 on the others, the kept ones
/// moving so that no equation changes, `K_kk v_k = -K_kd`. `t` is work space of one per row.
fn free_directions(
    k: &mut Gram,
    columns: &Columns,
    jn: &[f64],
    dropped: &[usize],
    free: &mut Vec<f64>,
    t: &mut [f64],
) {
    free_rhs(columns, jn, dropped, free, t);
    k.solve_many(free, dropped.len());
    free_finish(free, dropped, columns.len());
}

/// The right-hand sides of [`free_directions`] into `free`: `-K_kd` for each dropped `d`
/// (with `K_dd`'s row among them, overwritten by [`free_finish`]).
fn free_rhs(columns: &Columns, jn: &[f64], dropped: &[usize], free: &mut Vec<f64>, t: &mut [f64]) {
    let ncols = columns.len();
    free.clear();
    free.resize(dropped.len() * ncols, 0.0);
    for (f, &d) in dropped.iter().enumerate() {
        t.fill(0.0);
        for &(row, idx) in columns.col(d) {
            t[row as usize] += jn[idx as usize];
        }
        let v = &mut free[f * ncols..(f + 1) * ncols];
        for (c, col) in columns.iter().enumerate() {
            let mut acc = 0.0;
            for &(row, idx) in col {
                acc -= jn[idx as usize] * t[row as usize];
            }
            v[c] = acc;
        }
    }
}

/// The free directions from their solved right-hand sides: 1 on their own dropped unknown, 0
/// on the other dropped ones.
fn free_finish(free: &mut [f64], dropped: &[usize], ncols: usize) {
    for (f, v) in free.chunks_mut(ncols.max(1)).enumerate() {
        for &d in dropped {
            v[d] = 0.0;
        }
        v[dropped[f]] = 1.0;
    }
}

/// Whether every direction in `dirs` (vectors of the unknowns, one after another) is free in
/// `J` itself, `‖J v‖² <= eps ‖v‖²`, where rounding is not squared as in `K`. `t` is work
/// space of one per row.
fn all_free(columns: &Columns, jn: &[f64], dirs: &[f64], eps: f64, t: &mut [f64]) -> bool {
    dirs.chunks(columns.len().max(1)).all(|v| {
        t.fill(0.0);
        for (c, col) in columns.iter().enumerate() {
            for &(row, idx) in col {
                t[row as usize] += jn[idx as usize] * v[c];
            }
        }
        let jv: f64 = t.iter().map(|a| a * a).sum();
        let vv: f64 = v.iter().map(|a| a * a).sum();
        jv <= eps * vv
    })
}

/// The number of directions in which the equations (`nrows` rows, the columns of `J` with
/// values `jn`) do not move the unknowns, read from `k = Jᵀ J` (its structure from
/// [`Gram::of_unknowns`]) as [`confirmed_free`] reads it. `None` when one is not confirmed, or
/// when there are more than [`MAX_FREE`] (a mechanism, whose freedoms `J Jᵀ` counts well).
pub(crate) fn free_count(
    k: &mut Gram,
    nrows: usize,
    columns: &Columns,
    jn: &[f64],
    eps: f64,
) -> Option<usize> {
    k.assemble(jn);
    if !k.factor(0.0, eps * SUSPECT) {
        return None;
    }
    confirmed_free(k, nrows, columns, jn, eps).map(|f| f.len())
}

/// The columns `k = Jᵀ J`, factorised at [`SUSPECT`] times the rank tolerance `eps`, dropped:
/// each a free direction of the unknowns, confirmed in `J` itself, where rounding is not
/// squared (a free direction's pivot carries the rounding of every elimination before it, and
/// can land above `eps`). `None` when one is not confirmed, or there are more than
/// [`MAX_FREE`].
fn confirmed_free(
    k: &mut Gram,
    nrows: usize,
    columns: &Columns,
    jn: &[f64],
    eps: f64,
) -> Option<Vec<usize>> {
    let free = k.dropped();
    if free.len() > MAX_FREE {
        return None;
    }
    if !free.is_empty() {
        let (mut dirs, mut t) = (Vec::new(), vec![0.0; nrows]);
        free_directions(k, columns, jn, &free, &mut dirs, &mut t);
        if !all_free(columns, jn, &dirs, eps, &mut t) {
            return None;
        }
    }
    Some(free)
}

impl Component {
    /// At a solution with Jacobian `jn` and residuals `r`, reached in `steps`: the rank and
    /// the rows on circuits from `K`, or only the solution when too few rows depend on others
    /// (see [`Component::solve_by_unknowns`]). With `current`, `k` is already factorised at
    /// the wider tolerance at a point closer to this one than anything the tests below tell
    /// apart (a free direction is measured to about `1e-9` against `eps`; a row's share of
    /// the left null space to about `1e-9` against `1e-6`).
    fn rank_by_unknowns(
        &self,
        k: &mut Gram,
        current: bool,
        jn: &[f64],
        r: &[f64],
        steps: usize,
        cfg: &Config,
    ) -> Reached {
        let (m, ncols) = (self.rows, self.columns.len());
        if !cfg.find_failed || m <= ncols + DEPENDENCY_BLOCK {
            return Reached::Solution(steps);
        }
        // As `rank::reveal` reads `J Jᵀ`: the columns dropped at a tolerance wider than the
        // rank tolerance are candidates, each confirmed in `J` itself. Where one is not
        // confirmed, `J Jᵀ` decides.
        let eps = cfg.rank_tolerance;
        if !current {
            k.assemble(jn);
            if !k.factor(0.0, eps * SUSPECT) {
                return Reached::Solution(steps);
            }
        }
        let Some(free) = confirmed_free(k, m, &self.columns, jn, eps) else {
            return Reached::Solution(steps);
        };
        let dependent = m - (ncols - free.len());
        if dependent <= DEPENDENCY_BLOCK {
            return Reached::Solution(steps);
        }
        let columns = &self.columns;
        // Jᵀ w for generic weights w, one right-hand side per probe.
        let mut u = vec![0.0; ncols * UNION_PROBES];
        for (p, up) in u.chunks_mut(ncols).enumerate() {
            for (c, col) in columns.iter().enumerate() {
                up[c] = col
                    .iter()
                    .map(|&(row, idx)| jn[idx as usize] * generic(row as usize, p))
                    .sum();
            }
        }
        k.solve_many(&mut u, UNION_PROBES);
        let mut on_circuit = vec![false; m];
        let mut y = vec![0.0; m];
        for (p, up) in u.chunks_mut(ncols).enumerate() {
            for &d in &free {
                up[d] = 0.0;
            }
            for (i, yi) in y.iter_mut().enumerate() {
                *yi = generic(i, p);
            }
            for (c, col) in columns.iter().enumerate() {
                for &(row, idx) in col {
                    y[row as usize] -= jn[idx as usize] * up[c];
                }
            }
            for (o, v) in on_circuit.iter_mut().zip(&y) {
                // As `rank::dependent_union` tells a coefficient from rounding.
                *o |= !(v.abs() <= 1e-6);
            }
        }
        let union: Vec<usize> = (0..m).filter(|&i| on_circuit[i]).collect();
        Reached::Finished(Finish {
            converged: true,
            iterations: steps,
            dropped: Vec::new(),
            dependent,
            dependencies: vec![union],
            unsatisfied: Vec::new(),
            residual: largest_abs(r),
            too_large: false,
            marginal: false,
            settled: false,
        })
    }
}

/// Solves the symmetric positive definite `a x = b` (`n x n`, row-major) in place by Gaussian
/// elimination with partial pivoting: false if singular.
fn solve_small(a: &mut [f64], b: &mut [f64], n: usize) -> bool {
    for col in 0..n {
        let piv = (col..n)
            .max_by(|&i, &j| a[i * n + col].abs().total_cmp(&a[j * n + col].abs()))
            .unwrap_or(col);
        if !(a[piv * n + col].abs() > 0.0) {
            return false;
        }
        if piv != col {
            for j in 0..n {
                a.swap(piv * n + j, col * n + j);
            }
            b.swap(piv, col);
        }
        for i in col + 1..n {
            let f = a[i * n + col] / a[col * n + col];
            for j in col..n {
                a[i * n + j] -= f * a[col * n + j];
            }
            b[i] -= f * b[col];
        }
    }
    for col in (0..n).rev() {
        let mut s = b[col];
        for j in col + 1..n {
            s -= a[col * n + j] * b[j];
        }
        b[col] = s / a[col * n + col];
    }
    b.iter().all(|v| v.is_finite())
}
