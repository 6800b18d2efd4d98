//! Newton's iterations on one component: minimum-norm steps through `G = J Jᵀ`, backtracking,
//! damped and truncated steps, steps refined with an earlier factorisation, and the slide
//! towards the solution nearest the drawing folded into the steps; then the rank where they
//! end.

use super::project::{Work, MAX_PROJECTION, MAX_RESTORE};
use super::rules::*;
use super::{Component, Finish, Scratch};
use crate::equations::Kernel;
use crate::solve::gram::Gram;
use crate::solve::rank;
use crate::solve::unknowns::Reached;
use crate::solve::Config;

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

impl Component {
    /// [`Component::solve`], with `marginal` the test for a marginal row at the start.
    pub(super) fn solve_at(
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
        if Gram::products(&self.columns) > crate::solve::gram::MAX_PRODUCTS {
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
        // In a check (`Config::crawl_fails`), the row weights damped steps measure the merit
        // with: those of the iteration that took the first damped step, held from then on
        // (empty before, and in every other solve). Each row normalised afresh at every
        // point, the merit is another function at every iteration: every damped step lowered
        // the merit it was measured with, and the next weights raised it again, so that the
        // steps wandered for hundreds of iterations (a check of 33 constraints of random
        // sketch 207, a dimension edited, went from 1.79 to 1.55 and back to 1.8, and was
        // still at 0.46 after 1,000 iterations). Not in a solve whose stop the rank test
        // reads: the weights move the least-squares point it stops at, and with them which
        // rows it names (held in every solve, 12 of 769 random sketches' reports changed,
        // one of them from a named conflict to `did_not_converge`).
        let mut weights: Vec<f64> = Vec::new();
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
            if !weights.is_empty() {
                self.hold_weights(kernels, jn, inv, &weights);
            }
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
            if cfg.crawl_fails
                && damping.is_some()
                && iterations >= damped_from + crawl_patience
                && max_r > SETTLE_RESIDUAL * cfg.tolerance
                && settles_above(&history)
            {
                // A check that only asks whether its equations hold: the merit, measured with
                // the weights held since the first damped step (`weights`), falls ever more
                // slowly towards a limit above zero, whatever the damping (the check of 33
                // constraints above, at a damping of 0.01, crept from 0.405 to 0.388 over its
                // last 550 iterations).
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
                    if cfg.crawl_fails {
                        weights.extend_from_slice(inv);
                    }
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
        if !weights.is_empty() {
            // The rank test reads rows of unit length (for a check, which reads nothing of
            // where it stopped, only so that its report is true).
            self.jacobian(kernels, x, r, jn, inv, xs, jl);
            if let Some(gram) = gram_slot.as_mut() {
                gram.assemble(jn);
                factored = gram.factor(0.0, cfg.rank_tolerance);
            }
            stale = false;
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
