//! Solver settings.

use std::borrow::Cow;

/// How a solve runs. Every field has a documented default; build with the `with_*` methods.
#[derive(Clone, Debug, PartialEq)]
#[non_exhaustive]
pub struct Config {
    /// A constraint holds when every residual is at most this (in model units: millimetres
    /// for lengths; radians-like for angle rows). Default `1e-10`. On a drawing so large
    /// that its values cannot be stored this finely, the rounding of its values instead
    /// (see [`Config::tolerance_at`]).
    pub tolerance: f64,
    /// Newton iterations per component before giving up. Default `1000`: a solve that makes
    /// progress towards a solution is not cut short (a sketch near a singular configuration
    /// can creep for hundreds of damped steps), while one that stops making progress ends
    /// long before.
    pub max_iterations: usize,
    /// Relative size of a dragged parameter's steps: the step minimises
    /// `sum (dx_i / s_i)^2` with `s_i` this value for dragged parameters and 1 for the rest,
    /// so dragged parameters move least. Default `0.05`.
    pub dragged_scale: f64,
    /// An equation whose normalised Jacobian row lies within this squared distance of the span
    /// of the others is dependent (redundant or conflicting). Default `1e-10`.
    pub rank_tolerance: f64,
    /// Whether to name the redundant, conflicting or unsatisfied constraints. Default `true`.
    pub find_failed: bool,
    /// A conflict the solve names is first found by the rank test: a set of constraints any
    /// one of which, removed, restores the rank where the solve stopped (SolveSpace's
    /// meaning). Sets of at most this many members are then checked and shrunk to a minimal
    /// set that cannot hold, by solving subsets of them (one small solve per member); larger
    /// ones are reported as found, so that a long loop of constraints in conflict does not
    /// cost a solve per member while the user drags. [`crate::diagnose`] always checks.
    /// Default `8`.
    pub verify_conflicts_up_to: usize,
    /// Whether an under-constrained solve, once every constraint holds, moves on along the
    /// solutions to the one nearest the drawing: the least weighted movement
    /// `sum ((x_i - x0_i) / s_i)^2` (with `s_i` as in [`Config::dragged_scale`]) among the
    /// solutions around the one Newton reached. Without it the answer is where Newton's
    /// steps of least movement end, as in SolveSpace. Default `true`: users expect the
    /// solution nearest what they drew. Newton's steps then project the drawing onto the
    /// linearised equations, which converges to the nearest solution only linearly where
    /// the equations curve much over the distance moved (a 1,000-segment 3D chain with 529
    /// degrees of freedom takes 44 iterations instead of 6; a 2D chain of as many segments
    /// 4, as without it); `false` is the faster SolveSpace behaviour.
    pub nearest: bool,
    /// Whether 2D angles are written as SolveSpace writes them, `cos(angle) - cos(val)`,
    /// instead of loci's signed difference `angle - val`. Both hold at the same
    /// configurations on the branch the angle starts on, but Newton's steps follow the
    /// equations' form, so on an under-constrained sketch the two end at different solutions;
    /// with this (and `nearest` off) a solve ends where SolveSpace's does. The cosine form
    /// also holds at the angle's mirror image (SolveSpace's angle is unsigned), and it loses
    /// its gradient at 0 and 180 degrees: angles within about 8 degrees of those
    /// (`|cos(val)| > 0.99`) keep the signed form. The `slvs` C library and the `loci.slvs` Python module
    /// set it. Default `false`.
    pub solvespace_angles: bool,
    /// Whether the slide to the nearest solution is folded into Newton's steps (each the
    /// projection of the drawing onto the linearised equations) rather than run after Newton
    /// has reached a solution. Both end at the same solution, to the projection's tolerance;
    /// the separate slide is kept to check that.
    pub(crate) fold_slide: bool,
    /// Whether a step after a small one may be solved with the factorisation of the step
    /// before, refined, instead of a fresh one. The step is the same to the refinement's
    /// tolerance; the switch is kept to check that.
    pub(crate) reuse_factor: bool,
    /// Whether a component with more equations than unknowns takes its steps through
    /// `Jᵀ J` (see `solve::unknowns`); off, only through `J Jᵀ`, for tests that compare.
    pub(crate) unknowns_side: bool,
    /// Whether a failed solve checks its verdict and names the sets that cannot hold (and,
    /// when none is shown to, builds the solution up one constraint at a time). Off only for a
    /// solve whose failure is followed by another solve of the same request, written
    /// differently, that does all of it.
    pub(crate) name_conflicts: bool,
    /// Whether damped steps creeping towards a least-squares point above zero may stop once
    /// what is left to gain at their rate is small (see `newton::rules::settles_above`). Off for the
    /// second solve of a failure whose stop showed no conflict: the rows of a conflict may
    /// become dependent only at the least-squares point itself.
    pub(crate) settle: bool,
    /// Whether damped steps that crawl (see `newton::rules::CRAWL`) end the solve even where no rows
    /// depend on others yet. A solve whose stopping point the rank test reads goes on
    /// crawling until rows become dependent, so that it can name what cannot hold; a check
    /// of a candidate conflict's part only asks whether its equations hold, and names
    /// nothing from where it stops. Such a check's damped steps also measure the merit with
    /// the row weights of their first step throughout, and end where it settles above zero
    /// (`newton::rules::settles_above`) at any damping.
    pub(crate) crawl_fails: bool,
}

impl Default for Config {
    fn default() -> Self {
        Self {
            tolerance: 1e-10,
            max_iterations: 1000,
            dragged_scale: 0.05,
            rank_tolerance: 1e-10,
            find_failed: true,
            verify_conflicts_up_to: 8,
            nearest: true,
            solvespace_angles: false,
            fold_slide: true,
            reuse_factor: true,
            unknowns_side: true,
            name_conflicts: true,
            settle: true,
            crawl_fails: false,
        }
    }
}

/// How finely a residual can be computed, relative to the size of the values it reads. A
/// value of size `s` is stored to within `f64::EPSILON * s / 2`, and an equation combines
/// a few of them, its terms a few times larger than the values: a site plan drawn in
/// millimetres a kilometre from its origin stores its coordinates to 1.2e-10, and no step
/// brings a distance between two of them within the default tolerance of 1e-10.
pub(crate) const ROUNDING: f64 = 32.0 * f64::EPSILON;

/// The most the rounding of a drawing's values raises the tolerance to (SolveSpace's own
/// length epsilon), reached at a size of 1.4e8. The size is that of the largest value of a
/// group: one stray value of 1e50 must not excuse errors of the rest of its group larger
/// than this, and a drawing larger still cannot be solved to a useful precision anyway.
const ROUNDING_CAP: f64 = 1e-6;

impl Config {
    /// The tolerance residuals are held to on a drawing whose values are at most `size` in
    /// magnitude: [`Config::tolerance`], or the rounding of such values (32 `f64::EPSILON`
    /// times `size`, at most 1e-6) where that is larger. The default tolerance stands up to a
    /// size of about 14,000 (14 m in millimetres); at a million, 7.1e-9.
    ///
    /// ```
    /// let cfg = loci::Config::default();
    /// assert_eq!(cfg.tolerance_at(1000.0), 1e-10);
    /// assert_eq!(cfg.tolerance_at(1e6), 32.0 * f64::EPSILON * 1e6);
    /// assert_eq!(cfg.tolerance_at(1e50), 1e-6);
    /// ```
    #[must_use]
    pub fn tolerance_at(&self, size: f64) -> f64 {
        self.tolerance.max((ROUNDING * size).min(ROUNDING_CAP))
    }

    /// This configuration with its tolerance at the size of the values of `group` of `sys`
    /// (see [`Config::tolerance_at`]): what every solve and diagnosis of the group holds its
    /// residuals to.
    pub(crate) fn for_group(&self, sys: &crate::System, group: crate::GroupId) -> Cow<'_, Self> {
        let size = sys
            .params()
            .iter()
            .filter(|p| p.group == group)
            .fold(0.0f64, |m, p| m.max(p.val.abs()));
        let tol = self.tolerance_at(size);
        if tol == self.tolerance {
            Cow::Borrowed(self)
        } else {
            Cow::Owned(self.clone().with_tolerance(tol))
        }
    }

    /// Sets [`Config::nearest`].
    #[must_use]
    pub fn with_nearest(mut self, v: bool) -> Self {
        self.nearest = v;
        self
    }

    /// Sets [`Config::solvespace_angles`].
    #[must_use]
    pub fn with_solvespace_angles(mut self, v: bool) -> Self {
        self.solvespace_angles = v;
        self
    }

    /// Sets [`Config::tolerance`].
    #[must_use]
    pub fn with_tolerance(mut self, v: f64) -> Self {
        self.tolerance = v;
        self
    }

    /// Sets [`Config::max_iterations`].
    #[must_use]
    pub fn with_max_iterations(mut self, v: usize) -> Self {
        self.max_iterations = v;
        self
    }

    /// Sets [`Config::dragged_scale`].
    #[must_use]
    pub fn with_dragged_scale(mut self, v: f64) -> Self {
        self.dragged_scale = v;
        self
    }

    /// Sets [`Config::rank_tolerance`].
    #[must_use]
    pub fn with_rank_tolerance(mut self, v: f64) -> Self {
        self.rank_tolerance = v;
        self
    }

    /// Sets [`Config::find_failed`].
    #[must_use]
    pub fn with_find_failed(mut self, v: bool) -> Self {
        self.find_failed = v;
        self
    }

    /// Sets whether a failed solve is checked further: its verdict confirmed, the sets of
    /// constraints that cannot hold named, and a solution looked for another way (built up
    /// one constraint at a time, with angles turned, from further off). On by default. Off
    /// for a caller that answers a failure itself, as a drag does by taking a shorter step:
    /// the checks cost many solves, and a solution found far off is a jump there.
    #[must_use]
    pub fn with_failure_checks(mut self, v: bool) -> Self {
        self.name_conflicts = v;
        self
    }

    /// Sets [`Config::verify_conflicts_up_to`].
    #[must_use]
    pub fn with_verify_conflicts_up_to(mut self, v: usize) -> Self {
        self.verify_conflicts_up_to = v;
        self
    }

    pub(crate) fn check(&self) -> Result<(), crate::SolveError> {
        let bad = |name, value: f64, expected| {
            Err(crate::SolveError::BadOption {
                name,
                value,
                expected,
            })
        };
        if !(self.tolerance > 0.0 && self.tolerance.is_finite()) {
            return bad("tolerance", self.tolerance, "a positive finite number");
        }
        if !(self.dragged_scale > 0.0 && self.dragged_scale <= 1.0) {
            return bad("dragged_scale", self.dragged_scale, "in (0, 1]");
        }
        if !(self.rank_tolerance > 0.0 && self.rank_tolerance < 1.0) {
            return bad("rank_tolerance", self.rank_tolerance, "in (0, 1)");
        }
        Ok(())
    }
}
