//! A component's equations evaluated: every kernel's residuals and, when asked, its block of
//! the Jacobian of the scaled unknowns with each row normalised; and the nudge that moves an
//! equation off a point where it has no gradient.

use super::{Block, Component};
use crate::equations::{Kernel, Rows};

/// Where [`Component::evaluate`] writes: residuals, normalised Jacobian entries and inverse
/// row norms (both empty for residuals alone), and the local slots it loads.
struct Out<'a> {
    r: &'a mut [f64],
    jn: &'a mut [f64],
    inv: &'a mut [f64],
    xs: &'a mut [f64],
}

/// From this many rows on, a component's equations are evaluated on all cores.
#[cfg(feature = "parallel")]
const PARALLEL_ROWS: usize = 4096;

/// The size of such a move, relative to the equation's residual.
const NUDGE: f64 = 1e-3;

/// A row of the Jacobian of scaled unknowns no longer than this is empty: its equation has no
/// gradient there but for rounding. An angle of 137.87 degrees between a horizontal and a
/// vertical line has none (both merged exactly), yet its derivatives, differences of equal
/// products, came out near 6e-17: normalised to unit length, the row read the angle's miss as
/// 3e16, the merit as 1e33, and the solve stopped after two iterations with residuals of 4.5e8
/// (`did_not_converge`, where SolveSpace names the angle). Rows of equations that do have a
/// gradient are of the order of one in scaled unknowns.
const EMPTY_ROW: f64 = 1e-12;

impl Component {
    /// Every local slot of every block, in `slot_col` order: constants from `values`, unknowns
    /// from `x`. Done once per solve; afterwards each evaluation refreshes the unknowns.
    pub(in crate::solve) fn gather_all(
        &self,
        kernels: &[Kernel],
        x: &[f64],
        values: &[f64],
        xs: &mut Vec<f64>,
    ) {
        xs.clear();
        xs.resize(self.slot_col.len(), 0.0);
        for b in &self.blocks {
            let kern = &kernels[b.kernel];
            let s0 = b.slot0 as usize;
            let cols = &self.block_cols[b.cols0 as usize..];
            let slots = &self.slot_col[s0..s0 + kern.locals.len()];
            for ((o, &c), &p) in xs[s0..].iter_mut().zip(slots).zip(&kern.locals) {
                *o = if c >= 0 {
                    x[cols[c as usize] as usize]
                } else {
                    values[p as usize]
                };
            }
        }
    }

    /// Residuals only.
    pub(in crate::solve) fn residuals(
        &self,
        kernels: &[Kernel],
        x: &[f64],
        r: &mut [f64],
        xs: &mut [f64],
    ) {
        let out = Out {
            r,
            jn: &mut [],
            inv: &mut [],
            xs,
        };
        self.evaluate(kernels, x, out, &mut Vec::new(), false);
    }

    /// Residuals, and the Jacobian `jn` of the scaled unknowns with its rows normalised
    /// (`inv` holds the inverse of each row's norm, 0 for an empty row), so that the pivots of
    /// `G` measure independence, not units.
    #[allow(clippy::too_many_arguments)]
    pub(in crate::solve) fn jacobian(
        &self,
        kernels: &[Kernel],
        x: &[f64],
        r: &mut [f64],
        jn: &mut [f64],
        inv: &mut [f64],
        xs: &mut [f64],
        jl: &mut Vec<f64>,
    ) {
        self.evaluate(kernels, x, Out { r, jn, inv, xs }, jl, true);
    }

    /// Every block's residuals (and Jacobian): spread over the cores for a large component.
    /// Each block writes its own rows, entries and slots, the same whichever thread runs it.
    fn evaluate(
        &self,
        kernels: &[Kernel],
        x: &[f64],
        out: Out<'_>,
        jl: &mut Vec<f64>,
        jacobian: bool,
    ) {
        #[cfg(feature = "parallel")]
        if self.rows >= PARALLEL_ROWS {
            let threads = rayon::current_num_threads().min(8);
            if threads > 1 {
                // Several runs per thread, so that a thread held up by the machine leaves its
                // share to the others.
                let per = self.blocks.len().div_ceil(4 * threads);
                let Out {
                    mut r,
                    mut jn,
                    mut inv,
                    mut xs,
                } = out;
                rayon::scope(|scope| {
                    for chunk in self.blocks.chunks(per) {
                        let (first, last) = (&chunk[0], &chunk[chunk.len() - 1]);
                        let k = &kernels[last.kernel];
                        let rows = last.row0 + k.rows - first.row0;
                        let slots = last.slot0 as usize + k.locals.len() - first.slot0 as usize;
                        let (rc, rest) = std::mem::take(&mut r).split_at_mut(rows);
                        r = rest;
                        let (xc, rest) = std::mem::take(&mut xs).split_at_mut(slots);
                        xs = rest;
                        let (jc, ic) = if jacobian {
                            let nnz = last.jv0 + k.rows * last.ncols as usize - first.jv0;
                            let (jc, rest) = std::mem::take(&mut jn).split_at_mut(nnz);
                            jn = rest;
                            let (ic, rest) = std::mem::take(&mut inv).split_at_mut(rows);
                            inv = rest;
                            (jc, ic)
                        } else {
                            (&mut [][..], &mut [][..])
                        };
                        let part = Out {
                            r: rc,
                            jn: jc,
                            inv: ic,
                            xs: xc,
                        };
                        scope.spawn(move |_| {
                            self.evaluate_blocks(
                                kernels,
                                chunk,
                                x,
                                part,
                                &mut Vec::new(),
                                jacobian,
                            );
                        });
                    }
                });
                return;
            }
        }
        self.evaluate_blocks(kernels, &self.blocks, x, out, jl, jacobian);
    }

    /// [`Component::evaluate`] for consecutive `blocks`, whose rows, Jacobian entries and slots
    /// start `out`.
    fn evaluate_blocks(
        &self,
        kernels: &[Kernel],
        blocks: &[Block],
        x: &[f64],
        out: Out<'_>,
        jl: &mut Vec<f64>,
        jacobian: bool,
    ) {
        let Some(first) = blocks.first() else {
            return;
        };
        let (row_base, jv_base, slot_base) = (first.row0, first.jv0, first.slot0 as usize);
        for b in blocks {
            let k = &kernels[b.kernel];
            let w = b.ncols as usize;
            let cols = &self.block_cols[b.cols0 as usize..b.cols0 as usize + w];
            let na = b.nactive as usize;
            let active = &self.active[b.active0 as usize..b.active0 as usize + na];
            let active_col = &self.active_col[b.active0 as usize..b.active0 as usize + na];
            // The unknowns at `x` into the local slots (constants stay as gathered).
            let s0 = b.slot0 as usize - slot_base;
            let xs = &mut out.xs[s0..s0 + k.locals.len()];
            for (&s, &c) in active.iter().zip(active_col) {
                xs[s as usize] = x[cols[c as usize] as usize];
            }
            let r = &mut out.r[b.row0 - row_base..b.row0 - row_base + k.rows];
            if !jacobian {
                if !k.eq.residuals_fast(xs, r) {
                    let mut rows = Rows::new();
                    k.eq.eval(xs, &mut rows);
                    r.copy_from_slice(&rows.v[..k.rows]);
                }
                continue;
            }
            // Every entry is written: no need to clear between blocks.
            let need = k.rows * na;
            if jl.len() < need {
                jl.resize(need, 0.0);
            }
            let jl = &mut jl[..need];
            k.eq.jacobian_active(xs, active, r, jl);
            let j0 = b.jv0 - jv_base;
            let block = &mut out.jn[j0..j0 + k.rows * w];
            if na == w {
                // Every unknown appears once: the block is the Jacobian as computed.
                for row in 0..k.rows {
                    for (a, &c) in active_col.iter().enumerate() {
                        block[row * w + c as usize] = jl[row * na + a];
                    }
                }
            } else {
                // Merged parameters: several slots feed one column.
                block.iter_mut().for_each(|v| *v = 0.0);
                for row in 0..k.rows {
                    for (a, &c) in active_col.iter().enumerate() {
                        block[row * w + c as usize] += jl[row * na + a];
                    }
                }
            }
            let inv = &mut out.inv[b.row0 - row_base..b.row0 - row_base + k.rows];
            if w == 0 {
                inv.fill(0.0);
            }
            for (iv, vals) in inv.iter_mut().zip(block.chunks_exact_mut(w.max(1))) {
                let mut sq = 0.0;
                for (v, &c) in vals.iter_mut().zip(cols) {
                    *v *= self.scale[c as usize];
                    sq += *v * *v;
                }
                *iv = if sq > EMPTY_ROW * EMPTY_ROW {
                    1.0 / sq.sqrt()
                } else {
                    0.0
                };
                vals.iter_mut().for_each(|v| *v *= *iv);
            }
        }
    }

    /// Gives the rows of `jn` (normalised, with their inverse norms in `inv`) the weights
    /// `held` instead: each row becomes its Jacobian row times its weight in `held`, and `inv`
    /// that weight. An empty row stays empty, and a row with no weight held keeps its own.
    pub(super) fn hold_weights(
        &self,
        kernels: &[Kernel],
        jn: &mut [f64],
        inv: &mut [f64],
        held: &[f64],
    ) {
        for b in &self.blocks {
            let w = b.ncols as usize;
            for row in 0..kernels[b.kernel].rows {
                let i = b.row0 + row;
                if inv[i] == 0.0 || held[i] == 0.0 {
                    continue;
                }
                let f = held[i] / inv[i];
                let at = b.jv0 + row * w;
                jn[at..at + w].iter_mut().for_each(|v| *v *= f);
                inv[i] = held[i];
            }
        }
    }

    /// Moves the unknowns of every equation whose gradient vanishes where it does not hold, by
    /// a small deterministic amount in a generic direction; true if anything moved.
    ///
    /// Such an equation is at a singular point of its own, not dependent on others: a distance
    /// between two points that start (or were merged) on top of each other, a line of zero
    /// length. Its row of the Jacobian is empty, so the rank test would call it a conflict and
    /// Newton could not move it. A user who swaps a horizontal constraint for a vertical one on
    /// a line with a fixed start and a length gets exactly this: substitution puts the end on
    /// the start.
    pub(super) fn nudge_singular(
        &self,
        x: &mut [f64],
        r: &[f64],
        inv: &[f64],
        tol: f64,
        attempt: usize,
    ) -> bool {
        let mut moved = false;
        for (i, (&ri, &iv)) in r.iter().zip(inv).enumerate() {
            if iv != 0.0 || ri.abs() <= tol || !ri.is_finite() {
                continue;
            }
            let b = &self.blocks[self.row_block[i].0 as usize];
            let cols = &self.block_cols[b.cols0 as usize..(b.cols0 + b.ncols) as usize];
            let size = NUDGE * ri.abs().max(1.0);
            for &c in cols {
                let c = c as usize;
                x[c] += size * self.scale[c] * generic(c, attempt);
                moved = true;
            }
        }
        moved
    }
}

/// A number in [-1, -0.5] or [0.5, 1] that depends only on `c` and `attempt`: directions of
/// nudges that are reproducible and that no constraint is likely to be singular along.
pub(crate) fn generic(c: usize, attempt: usize) -> f64 {
    let mut z = (c as u64)
        .wrapping_mul(0x9E37_79B9_7F4A_7C15)
        .wrapping_add((attempt as u64 + 1).wrapping_mul(0xBF58_476D_1CE4_E5B9));
    z = (z ^ (z >> 31)).wrapping_mul(0x94D0_49BB_1331_11EB);
    z ^= z >> 29;
    let u = (z >> 11) as f64 / (1u64 << 53) as f64;
    let m = 0.5 + 0.5 * u;
    if z & 1 == 0 {
        m
    } else {
        -m
    }
}
