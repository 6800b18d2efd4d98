//! The slide of a solution along the solutions to the one nearest the drawing, for a solve
//! whose damped steps could not take the projection in their stride.

use super::rules::{larger, PROJECTED};
use super::Component;
use crate::equations::Kernel;
use crate::solve::gram::Gram;
use crate::solve::Config;

/// Work vectors of [`Component::project`], borrowed from the solve's.
pub(super) struct Work<'a> {
    pub(super) r: &'a mut [f64],
    pub(super) jn: &'a mut [f64],
    pub(super) inv: &'a mut [f64],
    pub(super) y: &'a mut [f64],
    pub(super) dz: &'a mut [f64],
    pub(super) keep: &'a mut [f64],
    /// The residuals at `keep`, as the solve left them.
    pub(super) r_keep: &'a mut [f64],
    pub(super) xs: &'a mut [f64],
    pub(super) jl: &'a mut Vec<f64>,
}

/// Most rounds of the projection onto the solution nearest the drawing, and of Newton steps
/// after it to restore the equations.
pub(super) const MAX_PROJECTION: usize = 30;
pub(super) const MAX_RESTORE: usize = 5;

impl Component {
    /// Moves a solution `x` of an under-constrained component along the solutions to the one
    /// nearest `x0` (least weighted movement, columns weighted by `1 / scale`): Gauss-Newton
    /// on that least-distance problem, each step the projection of `x0` onto the equations
    /// linearised at `x`. Ends with the factorisation at the final point, for the rank test;
    /// keeps `x` as it was if the equations no longer hold at the end. Returns the iterations.
    pub(super) fn project(
        &self,
        kernels: &[Kernel],
        x: &mut [f64],
        x0: &[f64],
        cfg: &Config,
        gram: &mut Gram,
        w: &mut Work<'_>,
    ) -> usize {
        let (m, ncols) = (self.rows, x.len());
        w.keep.copy_from_slice(x);
        w.r_keep.copy_from_slice(w.r);
        let mut its = 0;
        let holds = |r: &[f64]| r.iter().all(|v| v.abs() <= cfg.tolerance);
        let (mut projected, mut restores) = (false, 0);
        for round in 0..MAX_PROJECTION + MAX_RESTORE {
            // After the projection, plain Newton steps put the equations back to where Newton
            // leaves them: at least one, so that linear equations hold exactly again.
            let projecting = round < MAX_PROJECTION && !projected;
            if !projecting {
                if restores > 0 && holds(w.r) {
                    break;
                }
                restores += 1;
            }
            for c in 0..ncols {
                w.dz[c] = if projecting {
                    (x0[c] - x[c]) / self.scale[c]
                } else {
                    0.0
                };
            }
            // y = -rn - Jn z, then z + Jnᵀ y: the nearest point to z on J dz = -r.
            for i in 0..m {
                w.y[i] = -w.r[i] * w.inv[i];
            }
            for (c, col) in self.columns.iter().enumerate() {
                for &(row, idx) in col {
                    w.y[row as usize] -= w.jn[idx as usize] * w.dz[c];
                }
            }
            gram.solve(w.y);
            let mut largest = 0.0f64;
            for (c, col) in self.columns.iter().enumerate() {
                let mut acc = w.dz[c];
                for &(row, idx) in col {
                    acc += w.jn[idx as usize] * w.y[row as usize];
                }
                let d = acc * self.scale[c];
                x[c] += d;
                largest = larger(largest, d.abs() / (1.0 + x[c].abs()));
            }
            its += 1;
            self.jacobian(kernels, x, w.r, w.jn, w.inv, w.xs, w.jl);
            gram.assemble(w.jn);
            if !gram.factor(0.0, cfg.rank_tolerance) || !largest.is_finite() {
                break;
            }
            if projecting && largest <= PROJECTED {
                projected = true;
            }
        }
        if !holds(w.r) || x.iter().any(|v| !v.is_finite()) {
            x.copy_from_slice(w.keep);
            self.jacobian(kernels, x, w.r, w.jn, w.inv, w.xs, w.jl);
            gram.assemble(w.jn);
            gram.factor(0.0, cfg.rank_tolerance);
            // The residuals the solve converged with (a written-out evaluation can round
            // differently from the one with derivatives).
            w.r.copy_from_slice(w.r_keep);
        }
        its
    }
}
