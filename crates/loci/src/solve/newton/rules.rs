//! The rules that end or change Newton's steps: the line search's window, when plain steps
//! give way to damped and truncated ones, when a crawl or a slide has settled, when an earlier
//! factorisation still serves; and the measures of a step they read.

use crate::solve::gram::Columns;

/// How many past merits the line search compares a step with.
pub(super) const NONMONOTONE: usize = 4;

/// Where no column of the Jacobian leans on the residual by more than this cosine (the
/// gradient test of MINPACK's `gtol`, [`stationary`]), the merit is as low as steps can take
/// it: a residual left there is equations that cannot all hold.
pub(in crate::solve) const STATIONARY: f64 = 1e-6;

/// A relative decrease of the merit smaller than this is no progress.
pub(super) const STALL: f64 = 1e-6;

/// Damped steps that lower the merit by less than this fraction over [`NONMONOTONE`]
/// iterations, taken with almost no damping (at most [`CRAWL_DAMPING`]) where some rows depend
/// on others, are Gauss-Newton converging linearly to a least-squares point whose residual is
/// not zero: constraints that cannot all hold. Near a solution the same steps converge
/// quadratically.
pub(super) const CRAWL: f64 = 1e-2;

/// How many damped iterations a solve takes before a crawl (see [`CRAWL`]) may end it: the
/// first damped steps from a plain step's stall still move the point the rank test reads the
/// conflict at (random systems whose conflict is named after 10 to 20 such steps could not be
/// shown from where the crawl begins).
pub(super) const CRAWL_PATIENCE: usize = 24;

/// [`CRAWL_PATIENCE`] for a solve that only says whether its equations hold
/// ([`crate::solve::Config::crawl_fails`]).
pub(super) const CRAWL_FAILS_PATIENCE: usize = 2 * NONMONOTONE;

/// The largest residual, in tolerances, above which [`settles_above`] may end a solve: a
/// merit near rounding creeps down by rounding, at any rate.
pub(super) const SETTLE_RESIDUAL: f64 = 1e4;

/// Damped iterations before [`settles_above`] may end a solve.
pub(super) const SETTLE_PATIENCE: usize = 3;

/// The fraction of the merit that the decrease still to come, extrapolated from the last
/// steps' rate (see [`settles_above`]), must stay under.
pub(super) const SETTLE: f64 = 0.1;

/// Whether the last merits of `history` (the current one last) fall ever more slowly, at a
/// steady linear rate, towards a limit above zero: the decrease still to come at the slowest
/// of the last rates, `d ρ / (1 - ρ)` after a decrease `d`, is under [`SETTLE`] of the merit.
/// Gauss-Newton steps converge so to a least-squares point whose residual is not zero, while
/// a merit falling to zero at a linear rate keeps its decreases a fixed fraction of itself.
pub(super) fn settles_above(history: &[f64]) -> bool {
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
pub(super) const CRAWL_DAMPING: f64 = 1e-4;

/// A step no larger than this (relative to the unknown) leaves the Jacobian as it was for the
/// rank test.
pub(super) const TINY_STEP: f64 = 1e-6;

/// A step that shrank to this fraction of the one before or less shows Newton converging
/// quadratically: the Jacobian is regular on the kept rows there (where rows become dependent
/// at the solution, steps only halve), and the next step would be about this fraction of the
/// last again (at most). A step up to [`QUADRATIC_STEP`] that shrank so ends the solve as a
/// [`TINY_STEP`] does (the 10-link assembly chain: steps 0.3, 2e-3, 3e-6, and a fourth
/// Jacobian and factorisation to confirm it before).
pub(super) const QUADRATIC: f64 = 1e-2;

/// The largest step (relative to the unknown) that ends the solve when it shrank by
/// [`QUADRATIC`]: the Jacobian the rank is read from is then at most this far from the answer,
/// which moves a pivot of `G` by about this much times its size, far from the rank tolerance
/// unless it was already within rounding of it.
pub(super) const QUADRATIC_STEP: f64 = 1e-5;

/// A projection step smaller than this (relative to the unknown) ends the projection: the
/// answer is then within about this much of the nearest solution, far below what a drawing
/// shows, and the rounds it would take to go further cost as much as Newton iterations.
pub(in crate::solve) const PROJECTED: f64 = 1e-9;

/// Projection steps below this (relative to the unknown) that no longer shrink are rounding:
/// the answer is then within a few times this of the nearest solution.
pub(in crate::solve) const SLIDE_NOISE: f64 = 1e-7;

/// How many times one solve may move the unknowns of an equation that has no gradient where
/// it does not hold (see [`super::Component::nudge_singular`]).
pub(super) const MAX_NUDGES: usize = 3;

/// Thresholds (on pivots of rows of unit length) below which a truncated step treats rows as
/// dependent, tried in turn once damped steps are in use.
pub(super) const TRUNCATIONS: [f64; 4] = [0.0, 1e-8, 1e-6, 1e-4];

/// Plain steps give way to damped ones once the kept rows' largest residual is below this
/// fraction of the dropped rows' (see `stuck` in [`super::Component::solve`]).
pub(super) const STUCK: f64 = 1e-2;

/// The rule of [`STUCK`] applies only where more rows than this are dropped: there a window of
/// plain steps without progress costs factorisations of a large system, while in a small one
/// those steps reach the point where the kept rows hold, whose dropped rows' circuits name a
/// conflict (three random systems with one planted contradiction, switched to damped steps
/// early, ended at a least-squares point where no conflict could be shown).
pub(super) const STUCK_ROWS: usize = 32;

/// The rule of [`STUCK`] applies whatever the number of rows dropped in a component of this
/// many rows or more, where each plain step is a factorisation of a large system: a truss
/// with one impossible length drops one row, and its plain steps waited out a window with the
/// kept rows holding and the merit unchanged (50x50: 12 iterations, now 7, 41 -> 32 ms;
/// 100x100: 15, now 9). The random systems of [`STUCK_ROWS`] are far smaller.
pub(super) const STUCK_SIZE: usize = 4096;

/// A step that moved no unknown by more than this (relative to it) leaves `G` close enough
/// for the next step to be solved with the factorisation it was taken with, refined.
pub(super) const REUSE_MOVE: f64 = 1e-4;

/// Refinement of such a step ends when the residual of `G y = b` is this small relative to
/// `b`, or gives up after `REFINE_SWEEPS` (or a sweep that does not gain a factor of 10).
pub(super) const REFINED: f64 = 1e-13;
pub(super) const REFINE_SWEEPS: usize = 4;

/// A factorisation made before the last steps that were solved with it gives the rank where
/// they end when its smallest pivot is at least this multiple of the rank tolerance (see
/// `stale` at the end of [`super::Component::solve`]).
pub(in crate::solve) const STALE_RANK: f64 = 1e6;

/// From this many rows on, a step solved with an earlier factorisation starts from the last
/// step's solution (see `step` in [`super::Component::solve`]): the 200x200 truss's three such steps
/// took 12 solves, now 8. Below it, a solve costs about what testing the guess does, and the
/// answer stays the one the refinement from nothing gives (a point pinned to the origin
/// lands on 0 exactly rather than within 1e-17 of it).
pub(super) const WARM_ROWS: usize = 4096;

/// A failed solve whose largest residual is at most this many times the tolerance, with rows
/// dropped as dependent, goes on with steps at the tighter rank tolerance (see
/// [`super::Component::solve`]). Three satisfiable 3D sketches of 45,000 random ones stopped at 4.9e-10
/// and 9.5e-10 against a tolerance of 1e-10.
pub(super) const NEAR_MISS: f64 = 1e3;

/// The largest cosine between the residual `rn` (`r` times `inv`) and a column of `Jn`
/// (values `jn`), with `m0 = |rn|²`: zero where the merit is stationary. Infinity for a
/// residual of zero, which no least-squares point of impossible equations has.
pub(in crate::solve) fn stationary(
    columns: &Columns,
    jn: &[f64],
    r: &[f64],
    inv: &[f64],
    m0: f64,
) -> f64 {
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
pub(in crate::solve) fn relative_move(dx: &[f64], x: &[f64]) -> f64 {
    dx.iter()
        .zip(x)
        .fold(0.0f64, |a, (d, v)| larger(a, d.abs() / (1.0 + v.abs())))
}

/// The larger of a running maximum `a` and `b`, a NaN `b` ignored, as `f64::max` does; but
/// inline in WebAssembly, where `f64::max` is a library call (its `f64.max` instruction keeps a
/// NaN).
#[inline]
pub(in crate::solve) fn larger(a: f64, b: f64) -> f64 {
    if b > a {
        b
    } else {
        a
    }
}

/// The largest magnitude in `v` (0 when empty; NaNs ignored, as [`larger`] does).
#[inline]
pub(in crate::solve) fn largest_abs(v: &[f64]) -> f64 {
    v.iter().fold(0.0f64, |a, x| larger(a, x.abs()))
}
