//! Least-squares Newton on one component: minimum-norm steps through the normal equations,
//! with a backtracking line search as the safety net.

use super::gram::{Columns, Gram};
use super::rank;
use super::unknowns::Reached;
use super::Config;
use crate::equations::Kernel;
use crate::equations::Rows;

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
    /// ([`settles_above`], [`Config::settle`]).
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

/// How many past merits the line search compares a step with.
const NONMONOTONE: usize = 4;

/// Where no column of the Jacobian leans on the residual by more than this cosine (the
/// gradient test of MINPACK's `gtol`, [`stationary`]), the merit is as low as steps can take
/// it: a residual left there is equations that cannot all hold.
pub(super) const STATIONARY: f64 = 1e-6;

/// A relative decrease of the merit smaller than this is no progress.
const STALL: f64 = 1e-6;

/// Damped steps that lower the merit by less than this fraction over [`NONMONOTONE`]
/// iterations, taken with almost no damping (at most [`CRAWL_DAMPING`]) where some rows depend
/// on others, are Gauss-Newton converging linearly to a least-squares point whose residual is
/// not zero: constraints that cannot all hold. Near a solution the same steps converge
/// quadratically.
const CRAWL: f64 = 1e-2;

/// How many damped iterations a solve takes before a crawl (see [`CRAWL`]) may end it: the
/// first damped steps from a plain step's stall still move the point the rank test reads the
/// conflict at (random systems whose conflict is named after 10 to 20 such steps could not be
/// shown from where the crawl begins).
const CRAWL_PATIENCE: usize = 24;

/// [`CRAWL_PATIENCE`] for a solve that only says whether its equations hold
/// ([`Config::crawl_fails`]).
const CRAWL_FAILS_PATIENCE: usize = 2 * NONMONOTONE;

/// The largest residual, in tolerances, above which [`settles_above`] may end a solve: a
/// merit near rounding creeps down by rounding, at any rate.
const SETTLE_RESIDUAL: f64 = 1e4;

/// Damped iterations before [`settles_above`] may end a solve.
const SETTLE_PATIENCE: usize = 3;

/// The fraction of the merit that the decrease still to come, extrapolated from the last
/// steps' rate (see [`settles_above`]), must stay under.
const SETTLE: f64 = 0.1;

/// Whether the last merits of `history` (the current one last) fall ever more slowly, at a
/// steady linear rate, towards a limit above zero: the decrease still to come at the slowest
/// of the last rates, `d ρ / (1 - ρ)` after a decrease `d`, is under [`SETTLE`] of the merit.
/// Gauss-Newton steps converge so to a least-squares point whose residual is not zero, while
/// a merit falling to zero at a linear rate keeps its decreases a fixed fraction of itself.
fn settles_above(history: &[f64]) -> bool {
    let [a, b, c, d] = match history.len().checked_sub(4) {
        Some(k) => [history[k], history[k + 1], history[k + 2], history[k + 3]],
        None => return false,
    };
    let (d1, d2, d3) = (a - b, b - c, c - d);
    if !(d1 > 0.0 && d2 > 0.0 && d3 > 0.0 && d > 0.0) {
        return false;
    }
    let rate = (d2 / d1).max(d3 / d2);
    rate < 1.0 && d3 * rate / (1.0 - rate) < SETTLE * d
}

/// The largest damping at which a crawl (see [`CRAWL`]) reads as a least-squares point: with
/// more, short steps are the damping's, not the problem's.
const CRAWL_DAMPING: f64 = 1e-4;

/// A step no larger than this (relative to the unknown) leaves the Jacobian as it was for the
/// rank test.
const TINY_STEP: f64 = 1e-6;

/// A step that shrank to this fraction of the one before or less shows Newton converging
/// quadratically: the Jacobian is regular on the kept rows there (where rows become dependent
/// at the solution, steps only halve), and the next step would be about this fraction of the
/// last again (at most). A step up to [`QUADRATIC_STEP`] that shrank so ends the solve as a
/// [`TINY_STEP`] does (the 10-link assembly chain: steps 0.3, 2e-3, 3e-6, and a fourth
/// Jacobian and factorisation to confirm it before).
const QUADRATIC: f64 = 1e-2;

/// The largest step (relative to the unknown) that ends the solve when it shrank by
/// [`QUADRATIC`]: the Jacobian the rank is read from is then at most this far from the answer,
/// which moves a pivot of `G` by about this much times its size, far from the rank tolerance
/// unless it was already within rounding of it.
const QUADRATIC_STEP: f64 = 1e-5;

/// What a step solved with an earlier factorisation of `G` refines with (see `step` in
/// `Component::solve_at`): work vectors `b`, `res` and `v`, the rows that factorisation
/// dropped, and the last step's solution to start from.
type Refine<'a> = (
    &'a mut [f64],
    &'a mut [f64],
    &'a mut [f64],
    &'a [usize],
    Option<&'a [f64]>,
);

/// Work vectors of [`Component::project`], borrowed from the solve's.
struct Work<'a> {
    r: &'a mut [f64],
    jn: &'a mut [f64],
    inv: &'a mut [f64],
    y: &'a mut [f64],
    dz: &'a mut [f64],
    keep: &'a mut [f64],
    /// The residuals at `keep`, as the solve left them.
    r_keep: &'a mut [f64],
    xs: &'a mut [f64],
    jl: &'a mut Vec<f64>,
}

/// Most rounds of the projection onto the solution nearest the drawing, and of Newton steps
/// after it to restore the equations.
const MAX_PROJECTION: usize = 30;
const MAX_RESTORE: usize = 5;

/// A projection step smaller than this (relative to the unknown) ends the projection: the
/// answer is then within about this much of the nearest solution, far below what a drawing
/// shows, and the rounds it would take to go further cost as much as Newton iterations.
pub(super) const PROJECTED: f64 = 1e-9;

/// Projection steps below this (relative to the unknown) that no longer shrink are rounding:
/// the answer is then within a few times this of the nearest solution.
pub(super) const SLIDE_NOISE: f64 = 1e-7;

/// How many times one solve may move the unknowns of an equation that has no gradient where
/// it does not hold (see [`Component::nudge_singular`]).
const MAX_NUDGES: usize = 3;

/// Thresholds (on pivots of rows of unit length) below which a truncated step treats rows as
/// dependent, tried in turn once damped steps are in use.
const TRUNCATIONS: [f64; 4] = [0.0, 1e-8, 1e-6, 1e-4];

/// Plain steps give way to damped ones once the kept rows' largest residual is below this
/// fraction of the dropped rows' (see `stuck` in [`Component::solve`]).
const STUCK: f64 = 1e-2;

/// The rule of [`STUCK`] applies only where more rows than this are dropped: there a window of
/// plain steps without progress costs factorisations of a large system, while in a small one
/// those steps reach the point where the kept rows hold, whose dropped rows' circuits name a
/// conflict (three random systems with one planted contradiction, switched to damped steps
/// early, ended at a least-squares point where no conflict could be shown).
const STUCK_ROWS: usize = 32;

/// The rule of [`STUCK`] applies whatever the number of rows dropped in a component of this
/// many rows or more, where each plain step is a factorisation of a large system: a truss
/// with one impossible length drops one row, and its plain steps waited out a window with the
/// kept rows holding and the merit unchanged (50x50: 12 iterations, now 7, 41 -> 32 ms;
/// 100x100: 15, now 9). The random systems of [`STUCK_ROWS`] are far smaller.
const STUCK_SIZE: usize = 4096;

/// A step that moved no unknown by more than this (relative to it) leaves `G` close enough
/// for the next step to be solved with the factorisation it was taken with, refined.
const REUSE_MOVE: f64 = 1e-4;

/// Refinement of such a step ends when the residual of `G y = b` is this small relative to
/// `b`, or gives up after `REFINE_SWEEPS` (or a sweep that does not gain a factor of 10).
const REFINED: f64 = 1e-13;
const REFINE_SWEEPS: usize = 4;

/// A factorisation made before the last steps that were solved with it gives the rank where
/// they end when its smallest pivot is at least this multiple of the rank tolerance (see
/// `stale` at the end of [`Component::solve`]).
pub(super) const STALE_RANK: f64 = 1e6;

/// From this many rows on, a step solved with an earlier factorisation starts from the last
/// step's solution (see `step` in [`Component::solve`]): the 200x200 truss's three such steps
/// took 12 solves, now 8. Below it, a solve costs about what testing the guess does, and the
/// answer stays the one the refinement from nothing gives (a point pinned to the origin
/// lands on 0 exactly rather than within 1e-17 of it).
const WARM_ROWS: usize = 4096;

/// A failed solve whose largest residual is at most this many times the tolerance, with rows
/// dropped as dependent, goes on with steps at the tighter rank tolerance (see
/// [`Component::solve`]). Three satisfiable 3D sketches of 45,000 random ones stopped at 4.9e-10
/// and 9.5e-10 against a tolerance of 1e-10.
const NEAR_MISS: f64 = 1e3;

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

    /// Every local slot of every block, in `slot_col` order: constants from `values`, unknowns
    /// from `x`. Done once per solve; afterwards [`Component::load`] refreshes the unknowns.
    pub(super) fn gather_all(
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
    pub(super) fn residuals(&self, kernels: &[Kernel], x: &[f64], r: &mut [f64], xs: &mut [f64]) {
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
    pub(super) fn jacobian(
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

    /// Moves the unknowns of every equation whose gradient vanishes where it does not hold, by
    /// a small deterministic amount in a generic direction; true if anything moved.
    ///
    /// Such an equation is at a singular point of its own, not dependent on others: a distance
    /// between two points that start (or were merged) on top of each other, a line of zero
    /// length. Its row of the Jacobian is empty, so the rank test would call it a conflict and
    /// Newton could not move it. A user who swaps a horizontal constraint for a vertical one on
    /// a line with a fixed start and a length gets exactly this: substitution puts the end on
    /// the start.
    fn nudge_singular(
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

    /// Moves a solution `x` of an under-constrained component along the solutions to the one
    /// nearest `x0` (least weighted movement, columns weighted by `1 / scale`): Gauss-Newton
    /// on that least-distance problem, each step the projection of `x0` onto the equations
    /// linearised at `x`. Ends with the factorisation at the final point, for the rank test;
    /// keeps `x` as it was if the equations no longer hold at the end. Returns the iterations.
    fn project(
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

    /// [`Component::solve`], with `marginal` the test for a marginal row at the start.
    fn solve_at(
        &mut self,
        kernels: &[Kernel],
        x: &mut [f64],
        values: &[f64],
        cfg: &Config,
        scratch: &mut Scratch,
        marginal: bool,
    ) -> Finish {
        let m = self.rows;
        let ncols = x.len();
        if Gram::products(&self.columns) > super::gram::MAX_PRODUCTS {
            return Finish::without_steps(true, false);
        }
        let Scratch { fixed, xs, jl, x0 } = scratch;
        if cfg.nearest {
            x0.clear();
            x0.extend_from_slice(x);
        }
        // Steps through `Jᵀ J` where equations outnumber unknowns; the steps below then start
        // at their solution, and only read the rank there. Where they reach none, the steps
        // below start from the drawing again.
        let mut before = 0;
        // Whether the steps through `K` ended at the least-squares point of equations that
        // cannot all hold: `G` is then factorised there once, for the rank test, and no step
        // is taken through it.
        let mut least_squares = false;
        if self.by_unknowns(ncols, cfg) {
            match self.solve_by_unknowns(kernels, x, values, cfg) {
                Some(Reached::Finished(fin)) => return fin,
                Some(Reached::Solution(steps)) => before = steps,
                Some(Reached::LeastSquares(steps)) => (before, least_squares) = (steps, true),
                None => x.copy_from_slice(&x0[..]),
            }
        }
        if self.gram.is_none() {
            self.gram = Gram::new(m, &self.columns);
        }
        let mut gram_slot = self.gram.take();
        // The work vectors: residuals `r`, Jacobian `jn`, row norms `inv`, `y`, the step `dx`,
        // the trial point `xt` and its residuals `rt`; the first solution a sliding solve
        // reached (`keep`) and its residuals (`r_keep`), the answer if the slide towards the
        // nearest one fails; the movement towards the starting point in scaled unknowns (`dz`);
        // a step's right-hand side (`b`), the residual of its refinement (`res`) and `Jnᵀ y`
        // (`v`), for steps solved with the factorisation of an earlier iteration, and the last
        // step's `y` they start from (`y_last`, only from `WARM_ROWS` rows on). Cleared, so
        // that nothing of an earlier component's solve can reach this one's.
        let warm_start = m >= WARM_ROWS;
        let total = 7 * m + if warm_start { m } else { 0 } + self.nnz + 5 * ncols;
        if fixed.len() < total {
            fixed.resize(total, 0.0);
        }
        let rest = &mut fixed[..total];
        rest.fill(0.0);
        let (r, rest) = rest.split_at_mut(m);
        let (jn, rest) = rest.split_at_mut(self.nnz);
        let (inv, rest) = rest.split_at_mut(m);
        let (y, rest) = rest.split_at_mut(m);
        let (dx, rest) = rest.split_at_mut(ncols);
        let (xt, rest) = rest.split_at_mut(ncols);
        let (rt, rest) = rest.split_at_mut(m);
        let (keep, rest) = rest.split_at_mut(ncols);
        let (r_keep, rest) = rest.split_at_mut(m);
        let (dz, rest) = rest.split_at_mut(ncols);
        let (b, rest) = rest.split_at_mut(m);
        let (res, rest) = rest.split_at_mut(m);
        let (v, rest) = rest.split_at_mut(ncols);
        let (y_last, _) = rest.split_at_mut(if warm_start { m } else { 0 });
        // Whether `y_last` holds the `y` of a step taken in this solve.
        let mut has_last = false;
        self.gather_all(kernels, x, values, xs);
        let xs = &mut xs[..];
        let x0 = &x0[..];
        let mut iterations = 0;
        let mut converged = false;
        let mut factored = false;
        let merit = |r: &[f64], inv: &[f64]| {
            r.iter()
                .zip(inv)
                .map(|(a, b)| (a * b) * (a * b))
                .sum::<f64>()
        };
        // Step length of the last accepted step: the next line search starts at twice it, so a
        // problem that needs short steps (a long chain turning far) does not pay for failed
        // full steps every iteration.
        let mut alpha_prev = 1.0f64;
        // Levenberg-Marquardt damping, once plain Newton steps stop reducing the residual.
        let mut damping: Option<f64> = None;
        // The iteration that took the first damped step.
        let mut damped_from = usize::MAX - CRAWL_PATIENCE;
        // A check that names nothing needs no point the rank test can read (see
        // `CRAWL_PATIENCE`): a window of steps that gain next to nothing is its answer.
        let crawl_patience = if cfg.crawl_fails {
            CRAWL_FAILS_PATIENCE
        } else {
            CRAWL_PATIENCE
        };
        let mut history: Vec<f64> = Vec::new();
        // Iterations since the merit last reached a new low.
        let (mut best, mut since_best) = (f64::INFINITY, 0usize);
        let mut nudges = 0;
        // Sliding: Newton's steps are themselves the projections of the drawing onto the
        // equations linearised where they stand, so that they end at the solution nearest the
        // drawing rather than reach one and then slide along the solutions (half the
        // iterations on a truss). Only for an under-constrained component (a square one has one
        // step, which the projection would only round differently), and only while steps are
        // plain: damped steps do not project, and a solve that needed them slides afterwards
        // (`project`).
        let mut fold = false;
        // The last step was a whole projection step smaller than `PROJECTED` (or than
        // `SLIDE_NOISE` and no longer shrinking): the solution nearest the drawing once the
        // equations hold.
        let mut settled = false;
        // Whether `keep` holds a solution.
        let mut held = false;
        // Whether `settles_above` ended the damped steps.
        let mut stopped_settling = false;
        // Whether the factorisation is of an earlier iteration's `G` (see `REUSE_MOVE`); the
        // rows the last fresh one dropped; the largest relative move of the last step.
        let (mut stale, mut last_move) = (false, f64::INFINITY);
        // How far the unknowns moved since `G` was last factorised afresh (the sum of the
        // steps' relative moves; infinite after a shortened step).
        let mut moved_since_factor = 0.0f64;
        // Whether to try that: not again once a refinement has failed in this solve.
        let mut reuse = cfg.reuse_factor;
        let mut left_out: Vec<usize> = Vec::new();
        loop {
            self.jacobian(kernels, x, r, jn, inv, xs, jl);
            if nudges < MAX_NUDGES && self.nudge_singular(x, r, inv, cfg.tolerance, nudges) {
                nudges += 1;
                continue;
            }
            let Some(gram) = gram_slot.as_mut() else {
                break;
            };
            gram.assemble(jn);
            // Not where rows were dropped: a mesh's kept rows include nearly dependent ones,
            // whose rounding leaves the refinement short of `REFINED`.
            if reuse
                && damping.is_none()
                && factored
                && left_out.is_empty()
                && last_move <= REUSE_MOVE
            {
                stale = true;
            } else {
                factored = gram.factor(0.0, cfg.rank_tolerance);
                stale = false;
                moved_since_factor = 0.0;
                left_out = gram.dropped();
            }
            if marginal
                && iterations == 0
                && before == 0
                && nudges == 0
                && factored
                && rank::marginal(gram, m, ncols, cfg.rank_tolerance, &left_out).is_some()
            {
                self.gram = gram_slot;
                return Finish::without_steps(false, true);
            }
            if iterations == 0 && cfg.nearest && factored {
                fold = cfg.fold_slide && m - gram.dropped().len() < ncols;
            }
            // The slide converges linearly where the equations curve much over the distance
            // to the drawing: it gets as many steps as the separate slide would.
            let sliding = fold && damping.is_none() && iterations < MAX_PROJECTION + MAX_RESTORE;
            let max_r = largest_abs(r);
            // Plain steps solve the kept rows only: once those nearly hold and the dropped ones
            // are far off (a mesh whose first steps flipped a triangle: kept rows at 2e-3,
            // dropped ones at 2.5), further plain steps converge to a point where the
            // dropped rows still miss, and only damped steps, which weigh every row, move
            // on. Take them now rather than after a window of steps without progress.
            let stuck = damping.is_none()
                && (left_out.len() > STUCK_ROWS || (m >= STUCK_SIZE && !left_out.is_empty()))
                && {
                    let dropped = left_out.iter().fold(0.0f64, |a, &d| a.max(r[d].abs()));
                    let mut kept = 0.0f64;
                    let mut next = left_out.iter().copied().peekable();
                    for (i, v) in r.iter().enumerate() {
                        if next.peek() == Some(&i) {
                            next.next();
                        } else {
                            kept = kept.max(v.abs());
                        }
                    }
                    dropped > cfg.tolerance && kept <= STUCK * dropped
                };
            let holds = max_r <= cfg.tolerance && r.iter().all(|v| v.is_finite());
            // A start that already holds is its own nearest solution.
            if holds && (!sliding || settled || iterations == 0 || iterations >= cfg.max_iterations)
            {
                converged = true;
                break;
            }
            if !factored || iterations >= cfg.max_iterations || least_squares {
                break;
            }
            if holds {
                // A solution, not yet the nearest: kept in case the slide goes wrong.
                keep.copy_from_slice(x);
                r_keep.copy_from_slice(r);
                held = true;
            }
            iterations += 1;
            if sliding {
                for c in 0..ncols {
                    dz[c] = (x0[c] - x[c]) / self.scale[c];
                }
            }
            // The step of least (weighted) movement from `x`, or, with `project`, from the
            // drawing: `dz + Jnᵀ y` with `G y = -rn - Jn dz`, the point nearest `dz` on
            // `Jn d = -rn`.
            //
            // With `refine` (work vectors `b`, `res`, `v`), `gram` holds the factorisation of an
            // earlier `G`: `G y = b` is solved by iterative refinement, `y += G_old⁻¹ (b - G y)`
            // with `G y = Jn (Jnᵀ y)`, which converges fast while `Jn` has barely changed.
            // Rows that factorisation dropped would stay out, as a fresh one leaves them (their
            // `y` zero, their equations not solved). Returns false if it did not reach
            // `REFINED` within `REFINE_SWEEPS`.
            let step = |gram: &mut Gram,
                        y: &mut [f64],
                        dx: &mut [f64],
                        project: bool,
                        refine: Option<Refine<'_>>|
             -> bool {
                for i in 0..m {
                    y[i] = -r[i] * inv[i];
                }
                if project {
                    for (c, col) in self.columns.iter().enumerate() {
                        for &(row, idx) in col {
                            y[row as usize] -= jn[idx as usize] * dz[c];
                        }
                    }
                }
                let mut ok = true;
                if let Some((b, res, v, left_out, last_y)) = refine {
                    for &d in left_out {
                        y[d] = 0.0;
                    }
                    b.copy_from_slice(y);
                    let b_size = largest_abs(b);
                    let target = REFINED * b_size;
                    // `res = b - G y` with `G y = Jn (Jnᵀ y)`, and its largest entry.
                    let residual = |y: &[f64], res: &mut [f64], v: &mut [f64]| {
                        res.copy_from_slice(b);
                        for (c, col) in self.columns.iter().enumerate() {
                            let mut acc = 0.0;
                            for &(row, idx) in col {
                                acc += jn[idx as usize] * y[row as usize];
                            }
                            v[c] = acc;
                        }
                        for (c, col) in self.columns.iter().enumerate() {
                            for &(row, idx) in col {
                                res[row as usize] -= jn[idx as usize] * v[c];
                            }
                        }
                        for &d in left_out {
                            res[d] = 0.0;
                        }
                        largest_abs(res)
                    };
                    // From the last step's solution where it leaves less of `b` to solve: as a
                    // slide settles, `y` settles too (on the multipliers of the nearest
                    // solution), and the refinement starts from the change alone.
                    let mut last = f64::INFINITY;
                    let mut warm = false;
                    if let Some(prev) = last_y {
                        y.copy_from_slice(prev);
                        for &d in left_out {
                            y[d] = 0.0;
                        }
                        let size = residual(y, res, v);
                        if size < b_size {
                            warm = true;
                            last = size;
                            if size > target {
                                gram.solve(res);
                                y.iter_mut().zip(res.iter()).for_each(|(a, d)| *a += d);
                            }
                        }
                    }
                    if !warm {
                        y.copy_from_slice(b);
                        gram.solve(y);
                    }
                    ok = last <= target;
                    for _ in 0..REFINE_SWEEPS {
                        if ok {
                            break;
                        }
                        let size = residual(y, res, v);
                        if size <= target {
                            ok = true;
                            break;
                        }
                        // Not converging fast: a fresh factorisation is cheaper.
                        if !(size < 0.1 * last) {
                            break;
                        }
                        last = size;
                        gram.solve(res);
                        y.iter_mut().zip(res.iter()).for_each(|(a, d)| *a += d);
                    }
                } else {
                    gram.solve(y);
                }
                for (c, col) in self.columns.iter().enumerate() {
                    let mut acc = if project { dz[c] } else { 0.0 };
                    for &(row, idx) in col {
                        acc += jn[idx as usize] * y[row as usize];
                    }
                    dx[c] = acc * self.scale[c];
                }
                ok
            };
            // A step with the factorisation as it is, or with a fresh one if the earlier one
            // no longer serves.
            macro_rules! fresh_step {
                ($project:expr) => {{
                    let refine = stale.then_some((
                        &mut b[..],
                        &mut res[..],
                        &mut v[..],
                        &left_out[..],
                        has_last.then_some(&y_last[..]),
                    ));
                    if !step(gram, y, dx, $project, refine) {
                        reuse = false;
                        factored = gram.factor(0.0, cfg.rank_tolerance);
                        stale = false;
                        moved_since_factor = 0.0;
                        left_out = gram.dropped();
                        if !factored {
                            break;
                        }
                        step(gram, y, dx, $project, None);
                    }
                    if warm_start {
                        y_last.copy_from_slice(y);
                        has_last = true;
                    }
                }};
            }
            // The normalised residual, the quantity the step minimises.
            let m0 = merit(r, inv);
            // The whole step from the factorisation `gram` holds lands at `xt` (residuals in
            // `rt`): whether it lowers the merit.
            let full_step_lowers = |gram: &mut Gram,
                                    y: &mut [f64],
                                    dx: &mut [f64],
                                    xt: &mut [f64],
                                    rt: &mut [f64],
                                    xs: &mut [f64]| {
                step(gram, y, dx, false, None);
                for c in 0..ncols {
                    xt[c] = x[c] + dx[c];
                }
                self.residuals(kernels, xt, rt, xs);
                let mt = merit(rt, inv);
                mt.is_finite() && (mt < m0 || mt == 0.0)
            };
            // Non-monotone acceptance (Grippo, Lampariello and Lucidi, 1986): a step may raise the
            // merit above the current one as long as it stays below the largest of the last few,
            // and below ten times the current one. Long chains that must swing far take fewer,
            // longer steps this way (24 -> 18 iterations on 10,000 segments).
            history.push(m0);
            let m_ref = history
                .iter()
                .rev()
                .take(NONMONOTONE)
                .fold(0.0f64, |a, &b| a.max(b));
            let mut alpha = (2.0 * alpha_prev).min(1.0);
            let mut accepted = false;
            // Progress means a new low by more than rounding: constraints that cannot all hold
            // leave a merit that creeps down in the last digits for dozens of iterations.
            if m0 < best * (1.0 - STALL) {
                (best, since_best) = (m0, 0);
            } else {
                since_best += 1;
            }
            // Damped steps where some equations already depend on others.
            let damped_dependent = damping.is_some() && !gram.dropped().is_empty();
            // A window without a new low, or the merit stationary: the window would only wait
            // out steps that change its last digits (a 50x50 truss with one impossible length:
            // the last 2 of its 14 iterations, 12 factorisations).
            if damped_dependent
                && (since_best >= NONMONOTONE
                    || stationary(&self.columns, jn, r, inv, m0) <= STATIONARY)
            {
                // Damped steps found no new low for a whole window either, and some equations
                // already depend on others here: this is as close as they get. Stop and let the
                // rank test name what cannot hold (a 1,000-segment chain with two lengths on one
                // segment took 42 iterations to give up, now 14). Without a dependency yet, the
                // steps go on: the least-squares point of an impossible triangle, where its
                // lengths become dependent, is only reached by crawling.
                break;
            }
            if (damped_dependent || cfg.crawl_fails && max_r > SETTLE_RESIDUAL * cfg.tolerance)
                && damping.is_some_and(|d| d <= CRAWL_DAMPING)
                && iterations >= damped_from + crawl_patience
                && history.len() > NONMONOTONE
                && m0 > (1.0 - CRAWL) * history[history.len() - 1 - NONMONOTONE]
            {
                // The same, sooner: damped steps of Gauss-Newton length still lower the merit
                // but by next to nothing (a 30x30 sheet of profiles with one impossible length
                // crept from 0.1473 to 0.1469 over 50 iterations, and went on to 1,000).
                break;
            }
            if cfg.settle
                && damped_dependent
                && damping.is_some_and(|d| d <= CRAWL_DAMPING)
                && iterations >= damped_from + SETTLE_PATIENCE
                && max_r > SETTLE_RESIDUAL * cfg.tolerance
                && settles_above(&history)
            {
                stopped_settling = true;
                break;
            }
            if sliding && holds {
                // From a solution, a whole projection step, as the equations are off by no
                // more than rounding; the steps after it restore them. The search starts
                // afresh from where it lands.
                fresh_step!(true);
                for c in 0..ncols {
                    xt[c] = x[c] + dx[c];
                }
                self.residuals(kernels, xt, rt, xs);
                accepted = rt.iter().all(|v| v.is_finite());
                alpha = 1.0;
                history.clear();
                (best, since_best) = (f64::INFINITY, 0);
                if !accepted {
                    break;
                }
            } else if damping.is_none() && since_best < NONMONOTONE && !stuck {
                // Newton step with backtracking. Non-monotone steps that find no new low for a
                // whole window are wandering (an impossible triangle climbed from 323 to 690
                // and crawled there with steps of 1e-8 for 40 iterations): damped steps take
                // over, which descend monotonically.
                fresh_step!(sliding);
                for _ in 0..30 {
                    for c in 0..ncols {
                        xt[c] = x[c] + alpha * dx[c];
                    }
                    self.residuals(kernels, xt, rt, xs);
                    let mt = merit(rt, inv);
                    if mt.is_finite() && (mt < m_ref.min(m0 * 10.0) || mt == 0.0) {
                        accepted = true;
                        break;
                    }
                    alpha *= 0.5;
                }
                if sliding && (!accepted || alpha < 1.0) {
                    // The pull towards the drawing costs more than it gains here (a solution
                    // far from it, across much curvature): plain steps from now on, and the
                    // slide once they have reached a solution.
                    fold = false;
                }
            }
            if !accepted && damping.is_some() && factored {
                // Damped steps converge only linearly where rows are nearly dependent: the
                // rows of redundant constraints are dependent exactly at the solution and
                // nearly so around it, with singular values that shrink with the residual, so
                // a plain Newton step overshoots along them and damping creeps (s0158 went
                // from 6e-8 to 2e-10 over 60 iterations at a damping of 1e-7). Truncated
                // steps drop those rows as dependent, with a threshold raised until a step
                // lowers the merit: the others converge quadratically, and consistent
                // redundant rows follow them.
                //
                // Whether the step from the factorisation `gram` holds was tried and failed.
                let mut tried = false;
                for trunc in TRUNCATIONS {
                    let tol = cfg.rank_tolerance.max(trunc);
                    // No kept pivot at or below the raised threshold: each pivot would be kept
                    // or dropped as it was, the factorisation and its step would be the ones
                    // just tried (three in four of these factorisations, diagnosing a fuzzed
                    // sketch of 38 constraints).
                    if tried && gram.smallest_kept_pivot() > tol {
                        continue;
                    }
                    // The factorisation at the rank tolerance is the one this iteration began
                    // with: no other has been made since (plain steps are not tried once
                    // damping is in use).
                    let ready = if tol == cfg.rank_tolerance {
                        factored
                    } else {
                        gram.factor(0.0, tol)
                    };
                    tried = ready;
                    if ready && full_step_lowers(gram, y, dx, xt, rt, xs) {
                        accepted = true;
                        alpha = 1.0;
                        break;
                    }
                }
            }
            if !accepted {
                // Backtracking stalls where the Jacobian is nearly singular, typically on the
                // way to the least-squares point of constraints that cannot all hold. Damped
                // (Levenberg-Marquardt) steps keep descending to that point, where the rank test
                // can name the conflict; they also rescue consistent problems from a bad start.
                // Adaptive damping as in Nocedal & Wright, "Numerical Optimization", 10.3.
                let mut lambda = damping.unwrap_or(1e-6);
                while lambda < 1e12 {
                    if gram.factor(lambda, cfg.rank_tolerance)
                        && full_step_lowers(gram, y, dx, xt, rt, xs)
                    {
                        accepted = true;
                        break;
                    }
                    lambda *= 10.0;
                }
                if damping.is_none() {
                    damped_from = iterations;
                }
                damping = Some((lambda / 10.0).max(1e-12));
                alpha = 1.0;
                if !accepted {
                    // Leave the undamped factorisation for the rank test.
                    factored = gram.factor(0.0, cfg.rank_tolerance);
                    break;
                }
            }
            alpha_prev = alpha;
            x.copy_from_slice(xt);
            let before = last_move;
            last_move = if alpha == 1.0 {
                relative_move(dx, x)
            } else {
                f64::INFINITY
            };
            moved_since_factor += last_move;
            // Settled once the projection's steps are below `PROJECTED`, or below
            // `SLIDE_NOISE` and no longer shrinking: rounding in a long chain's projection
            // keeps its steps at a few 1e-9 (a 10,000-segment chain took 27 iterations to
            // happen on one below 1e-9, where 5 reach the nearest solution). Or below
            // `SLIDE_NOISE` and shrinking at a rate `q` at which the steps still to come add up
            // to `PROJECTED` or less (`q / (1 - q)` times the last): the answer is then as near
            // the nearest solution as a step below `PROJECTED` would leave it (a 200x200 truss
            // slides at a rate of 0.03, 1.4e-6, 4.4e-8, 1.4e-9, and took a ninth iteration of
            // 6e-11 to see it; a 10-segment chain at 2e-4 from 3e-4 to 6e-8). Not after a
            // shortened step, whose size says nothing of the rate.
            let quadratic = before.is_finite() && last_move <= QUADRATIC * before;
            let rate = last_move / before;
            settled = sliding
                && (last_move <= PROJECTED
                    || (last_move <= SLIDE_NOISE && last_move >= 0.5 * before)
                    || (last_move <= SLIDE_NOISE
                        && before.is_finite()
                        && rate < 0.5
                        && last_move * rate / (1.0 - rate) <= PROJECTED));
            // A full Newton step that lands within tolerance and moved the unknowns by next to
            // nothing ends the solve without another Jacobian: the rank and the dependencies
            // are read from the factorisation this step was taken with, at a point closer than
            // rounding would tell apart.
            if damping.is_none()
                && alpha == 1.0
                && (settled || !sliding)
                && rt.iter().all(|v| v.abs() <= cfg.tolerance)
                && (quadratic && last_move <= QUADRATIC_STEP
                    || dx
                        .iter()
                        .zip(x.iter())
                        .all(|(d, v)| d.abs() <= TINY_STEP * (1.0 + v.abs())))
            {
                r.copy_from_slice(rt);
                converged = true;
                break;
            }
        }
        if stale {
            // The rank is read from `G` where the solve stopped, factorised afresh, unless the
            // earlier factorisation already tells it: it dropped no row, its smallest pivot is
            // far above the rank tolerance, and the unknowns have moved too little since for
            // any pivot to fall that far. Each pivot is the squared distance of a unit row from
            // the span of the rows before it, and moves of `REUSE_MOVE` in all change it by a
            // small fraction (the 200x200 truss's smallest pivot, 1.98669e-3, reads the same
            // to six digits after the slide); the rank test does not look again at a pivot
            // above `SUSPECT` times its tolerance. Only where nothing below reads the
            // factorisation for a step (`project`) or for where a failed solve stopped.
            let known = converged
                && left_out.is_empty()
                && moved_since_factor <= REUSE_MOVE
                && (!cfg.nearest || (fold && damping.is_none()))
                && gram_slot
                    .as_ref()
                    .is_some_and(|g| g.smallest_kept_pivot() >= STALE_RANK * cfg.rank_tolerance);
            if !known {
                if let Some(gram) = gram_slot.as_mut() {
                    factored = gram.factor(0.0, cfg.rank_tolerance);
                }
            }
        }
        if !converged && held {
            // The slide from a solution failed: that solution is the answer.
            x.copy_from_slice(keep);
            self.jacobian(kernels, x, r, jn, inv, xs, jl);
            if let Some(gram) = gram_slot.as_mut() {
                gram.assemble(jn);
                factored = gram.factor(0.0, cfg.rank_tolerance);
            }
            r.copy_from_slice(r_keep);
            converged = true;
        }
        // The rows dependent at the solution, when the check below read them and no slide
        // moved the unknowns after it.
        let mut revealed: Option<Vec<usize>> = None;
        // A start that already holds is its own nearest solution; a solve whose steps slid
        // is at the nearest one (or as near as the slide's rounds took it).
        if converged && cfg.nearest && factored && iterations > 0 && !(fold && damping.is_none()) {
            if let Some(gram) = gram_slot.as_mut() {
                let mut kept = m - gram.dropped().len();
                // Whether a free direction is left is read from the rank at the solution:
                // rounding over thousands of dependent rows can keep a dependent pivot, and a
                // pinned 50x50 mesh then looked fully constrained, its rotation was left
                // 1.9e-7 short of the one nearest the drawing.
                if kept >= ncols {
                    let dropped = rank::reveal(gram, &self.columns, jn, cfg.rank_tolerance);
                    kept = m - dropped.len();
                    revealed = Some(dropped);
                }
                if kept < ncols {
                    revealed = None;
                    let mut work = Work {
                        r,
                        jn,
                        inv,
                        y,
                        dz: dx,
                        keep: xt,
                        r_keep: rt,
                        xs,
                        jl,
                    };
                    iterations += self.project(kernels, x, x0, cfg, gram, &mut work);
                }
            }
        }
        let mut fin = Finish {
            converged,
            iterations: before + iterations,
            dropped: Vec::new(),
            dependent: 0,
            dependencies: Vec::new(),
            unsatisfied: (0..m).filter(|&i| !(r[i].abs() <= cfg.tolerance)).collect(),
            residual: largest_abs(r),
            too_large: false,
            marginal: false,
            settled: stopped_settling,
        };
        self.gram = gram_slot;
        // `K`'s structure, shared with the steps through it, counts the free directions
        // where the solve stopped short (`solve_by_unknowns` builds it for the same components).
        if !converged && factored && rank::counts_by_unknowns(m, ncols) && self.unknowns.is_none() {
            self.unknowns = Some(Gram::of_unknowns(m, &self.columns));
        }
        if let (Some(gram), true) = (self.gram.as_mut(), factored) {
            // At a solution, the rank is checked where rounding could hide a dependence; where
            // the solve stopped short, near-dependence is the conflict itself, and only the
            // count is checked.
            fin.dropped = if let Some(dropped) = revealed {
                dropped
            } else if converged {
                rank::reveal(gram, &self.columns, jn, cfg.rank_tolerance)
            } else {
                let k = self.unknowns.as_mut().and_then(Option::as_mut);
                rank::short_of_solution(gram, k, &self.columns, jn, cfg.rank_tolerance)
            };
            if cfg.find_failed {
                fin.dependencies = rank::dependencies(gram, &self.columns, jn, &fin.dropped, m);
            }
        } else {
            // No factorisation: count every row as unresolved.
            fin.dropped = (0..m).collect();
        }
        fin.dependent = fin.dropped.len();
        fin
    }
}

/// The largest cosine between the residual `rn` (`r` times `inv`) and a column of `Jn`
/// (values `jn`), with `m0 = |rn|²`: zero where the merit is stationary. Infinity for a
/// residual of zero, which no least-squares point of impossible equations has.
pub(super) fn stationary(columns: &Columns, jn: &[f64], r: &[f64], inv: &[f64], m0: f64) -> f64 {
    if !(m0 > 0.0) {
        return f64::INFINITY;
    }
    let norm = m0.sqrt();
    columns.iter().fold(0.0f64, |a, col| {
        let (mut g, mut size) = (0.0, 0.0);
        for &(row, idx) in col {
            let j = jn[idx as usize];
            g += j * r[row as usize] * inv[row as usize];
            size += j * j;
        }
        if size > 0.0 {
            a.max(g.abs() / (size.sqrt() * norm))
        } else {
            a
        }
    })
}

/// The largest move of a step `dx` that landed at `x`, relative to each unknown's size.
pub(super) fn relative_move(dx: &[f64], x: &[f64]) -> f64 {
    dx.iter()
        .zip(x)
        .fold(0.0f64, |a, (d, v)| larger(a, d.abs() / (1.0 + v.abs())))
}

/// The larger of a running maximum `a` and `b`, a NaN `b` ignored, as `f64::max` does; but
/// inline in WebAssembly, where `f64::max` is a library call (its `f64.max` instruction keeps a
/// NaN).
#[inline]
pub(super) fn larger(a: f64, b: f64) -> f64 {
    if b > a {
        b
    } else {
        a
    }
}

/// The largest magnitude in `v` (0 when empty; NaNs ignored, as [`larger`] does).
#[inline]
pub(super) fn largest_abs(v: &[f64]) -> f64 {
    v.iter().fold(0.0f64, |a, x| larger(a, x.abs()))
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
