//! Least-squares Newton on one component: minimum-norm steps through the normal equations,
//! with a backtracking line search as the safety net.
//!
//! This file holds a component's structure ([`Component::new`]) and its solve
//! ([`Component::solve`]); the parts of the solve are beside it: `evaluate` (residuals and the
//! normalised Jacobian, block by block), `iterate` (the iterations), `rules` (when steps end
//! or change kind, and the measures they read) and `project` (the slide to the solution
//! nearest the drawing after damped steps).

use super::gram::{Columns, Gram};
use super::rank;
use super::Config;
use crate::equations::Kernel;

mod evaluate;
mod iterate;
mod project;
mod rules;

pub(crate) use evaluate::generic;
use rules::NEAR_MISS;
pub(super) use rules::{
    largest_abs, relative_move, stationary, PROJECTED, SLIDE_NOISE, STALE_RANK, STATIONARY,
};

/// One kernel's place in the component's Jacobian. Its lists live in the component's flat
/// arrays (one allocation per component, not four per kernel).
pub(crate) struct Block {
    pub kernel: usize,
    /// First row of the kernel in the component.
    pub row0: usize,
    /// First Jacobian value of the kernel's dense block (rows x cols, row-major).
    pub jv0: usize,
    /// The component columns this kernel touches: `Component::block_cols[cols0..cols0 + ncols]`.
    cols0: u32,
    ncols: u32,
    /// For each local slot, its position among the block's columns or -1 for a constant:
    /// `Component::slot_col[slot0..slot0 + locals]`.
    slot0: u32,
    /// The slots that are unknowns, and the position among the block's columns of each:
    /// `Component::active[active0..active0 + nactive]` (and `active_col` alike).
    active0: u32,
    nactive: u32,
}

/// How one component ended.
pub(crate) struct Finish {
    pub converged: bool,
    pub iterations: usize,
    /// Rows whose equations depend on others at the final point.
    pub dropped: Vec<usize>,
    /// How many rows depend on the others: `dropped.len()`, or, where the rank was read from
    /// `Jᵀ J` (see `solve::unknowns`) and `dropped` left empty, the rows less the rank.
    pub dependent: usize,
    /// For each dropped row: the rows it depends on (itself included).
    pub dependencies: Vec<Vec<usize>>,
    /// Rows whose residual is above tolerance at the end.
    pub unsatisfied: Vec<usize>,
    pub residual: f64,
    /// The normal equations would need more than [`super::gram::MAX_PRODUCTS`] products: not
    /// attempted.
    pub too_large: bool,
    /// Stopped before its first step: a row the first factorisation dropped was only just
    /// dependent (see [`rank::marginal`]); to be solved again at the tighter rank tolerance.
    pub marginal: bool,
    /// Damped steps stopped short of the least-squares point they were creeping towards
    /// ([`rules::settles_above`], [`Config::settle`]).
    pub settled: bool,
}

impl Finish {
    /// A solve that took no step: the component too large to try (`too_large`), or to be
    /// solved again at a tighter rank tolerance (`marginal`).
    fn without_steps(too_large: bool, marginal: bool) -> Self {
        Self {
            converged: false,
            iterations: 0,
            dropped: Vec::new(),
            dependent: 0,
            dependencies: Vec::new(),
            unsatisfied: Vec::new(),
            residual: f64::NAN,
            too_large,
            marginal,
            settled: false,
        }
    }
}

/// Work vectors reused across components, so that many small components cost no allocations.
#[derive(Default)]
pub(crate) struct Scratch {
    /// Every work vector of fixed length, one after another in one allocation (see
    /// [`Component::solve`]): the residuals, the Jacobian, the row norms, the steps, the
    /// starting point's copies. A small solve allocated each on its own, which cost more than
    /// its arithmetic (in WebAssembly above all).
    fixed: Vec<f64>,
    xs: Vec<f64>,
    jl: Vec<f64>,
    /// The starting point, for [`Component::project`].
    x0: Vec<f64>,
}

/// A component ready to solve repeatedly.
pub(crate) struct Component {
    pub blocks: Vec<Block>,
    pub rows: usize,
    /// Component row -> (block, row within block).
    pub row_block: Vec<(u32, u8)>,
    /// Scale of each column (dragged parameters are smaller).
    pub scale: Vec<f64>,
    block_cols: Vec<u32>,
    slot_col: Vec<i32>,
    active: Vec<u16>,
    active_col: Vec<u32>,
    /// Per column: (row, index into Jacobian values).
    pub columns: Columns,
    pub nnz: usize,
    pub gram: Option<Gram>,
    /// `K = Jᵀ J` for [`Component::solve_by_unknowns`], once tried (`None` inside when too
    /// large).
    pub(super) unknowns: Option<Option<Gram>>,
}

impl Component {
    pub fn new(
        kernels: &[Kernel],
        members: &[usize],
        col_of_param: &dyn Fn(usize) -> Option<u32>,
        ncols: usize,
        scale: Vec<f64>,
    ) -> Self {
        let mut blocks = Vec::with_capacity(members.len());
        let nslots: usize = members.iter().map(|&k| kernels[k].locals.len()).sum();
        let mut block_cols: Vec<u32> = Vec::with_capacity(nslots);
        let mut slot_col: Vec<i32> = Vec::with_capacity(nslots);
        let mut active: Vec<u16> = Vec::with_capacity(nslots);
        let mut active_col: Vec<u32> = Vec::with_capacity(nslots);
        let mut row_block = Vec::new();
        let mut counts = vec![0u32; ncols + 1];
        let (mut row, mut jv) = (0usize, 0usize);
        for (bi, &k) in members.iter().enumerate() {
            let kern = &kernels[k];
            let cols0 = block_cols.len();
            let slot0 = slot_col.len();
            let active0 = active.len();
            for (s, &p) in kern.locals.iter().enumerate() {
                match col_of_param(p as usize) {
                    Some(c) => {
                        let pos = match block_cols[cols0..].iter().position(|&x| x == c) {
                            Some(i) => i,
                            None => {
                                block_cols.push(c);
                                block_cols.len() - 1 - cols0
                            }
                        };
                        slot_col.push(pos as i32);
                        active.push(s as u16);
                        active_col.push(pos as u32);
                    }
                    None => slot_col.push(-1),
                }
            }
            let n = block_cols.len() - cols0;
            for &c in &block_cols[cols0..] {
                counts[c as usize + 1] += kern.rows as u32;
            }
            for r in 0..kern.rows {
                row_block.push((bi as u32, r as u8));
            }
            blocks.push(Block {
                kernel: k,
                row0: row,
                jv0: jv,
                cols0: cols0 as u32,
                ncols: n as u32,
                slot0: slot0 as u32,
                active0: active0 as u32,
                nactive: (active.len() - active0) as u32,
            });
            row += kern.rows;
            jv += kern.rows * n;
        }
        // Columns as compressed lists: every (row, Jacobian entry) of each column.
        for c in 0..ncols {
            counts[c + 1] += counts[c];
        }
        // Filled through `counts` itself (each column's start moves up to the next one's as
        // its entries go in), then shifted back: one table less to allocate.
        let mut entries = vec![(0u32, 0u32); jv];
        for b in &blocks {
            let rows = kernels[b.kernel].rows;
            let cols = &block_cols[b.cols0 as usize..(b.cols0 + b.ncols) as usize];
            for r in 0..rows {
                for (ci, &c) in cols.iter().enumerate() {
                    let f = &mut counts[c as usize];
                    entries[*f as usize] =
                        ((b.row0 + r) as u32, (b.jv0 + r * cols.len() + ci) as u32);
                    *f += 1;
                }
            }
        }
        counts.copy_within(0..ncols, 1);
        counts[0] = 0;
        Self {
            blocks,
            rows: row,
            row_block,
            scale,
            block_cols,
            slot_col,
            active,
            active_col,
            columns: Columns {
                ptr: counts,
                entries,
            },
            nnz: jv,
            gram: None,
            unknowns: None,
        }
    }

    /// Solves from `x` in place.
    ///
    /// A large component whose first factorisation drops rows, some of which a factorisation
    /// at [`rank::MARGINAL`] times the rank tolerance keeps, is solved at that tighter
    /// tolerance throughout, its rank included, where only a few rows depend on others
    /// ([`rank::marginal`]). Such a row is no dependency but a structure that bends
    /// easily: each column of a 190x190 sheet of profiles is a chain of 190 edges held by
    /// relative angles, whose smallest squared singular value falls under the rank tolerance
    /// (1e-10) at that size. Dropped, the row was left out of every plain step, the steps
    /// folded the sheet, and a sketch built from a solution was reported inconsistent with
    /// 54,632 constraints named (190 did not converge; 199, 200, 201 and 210 inconsistent;
    /// sizes up to 185 solved in 6 iterations). At 1e-11 or below, it solves in 6 iterations
    /// with 0 DOF. The test runs whether or not the dropped rows hold: solved again from its
    /// answer, where they do, the sheet was read with 1 DOF and two distances named redundant.
    pub fn solve(
        &mut self,
        kernels: &[Kernel],
        x: &mut [f64],
        values: &[f64],
        cfg: &Config,
        scratch: &mut Scratch,
    ) -> Finish {
        let fin = self.solve_at(kernels, x, values, cfg, scratch, true);
        let tight = || Config {
            rank_tolerance: cfg.rank_tolerance * rank::MARGINAL,
            ..cfg.clone()
        };
        if fin.marginal {
            return self.solve_at(kernels, x, values, &tight(), scratch, false);
        }
        // Not a number (a residual that overflowed) is no near miss.
        let near = fin.residual <= NEAR_MISS * cfg.tolerance;
        if fin.converged || fin.dropped.is_empty() || !near {
            return fin;
        }
        // Within a few orders of the tolerance, with rows dropped: a root where rows become
        // dependent only at the solution, which Newton reaches linearly, its pivots shrinking
        // with the residual until the rank test drops one whose equation does not hold yet.
        // Plain steps leave a dropped row alone, so it is never mended: steps that keep it
        // (at the tighter tolerance) go on from here. The answer's rank is then read at the
        // usual tolerance, as any other solve's.
        let (missed, stop) = (x.to_vec(), fin.iterations);
        let again = self.solve_at(kernels, x, values, &tight(), scratch, false);
        if !again.converged {
            x.copy_from_slice(&missed);
            return fin;
        }
        let mut done = self.solve_at(kernels, x, values, cfg, scratch, false);
        done.iterations += stop + again.iterations;
        done
    }
}
