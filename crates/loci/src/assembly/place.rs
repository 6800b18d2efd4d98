//! A start built one component at a time, for a set of mates that failed solved together.
//!
//! Newton solves every mate at once, and from a start far from any solution it can stop at a
//! placement where the residuals are as small as they get nearby but not zero: a local
//! minimum, not a conflict. Assembly programs place parts in turn instead: the part most held
//! by parts already placed first, against those alone, then the next. Each of those solves
//! is small (one part's six freedoms) and its mates meet fixed references, so it reaches a
//! placement from far more starts; from the placement they build, the whole set is solved
//! again. A set that holds from there was no conflict.

use super::math;
use super::prim::Prim;
use super::{Assembly, Pose, Selection};

/// Newton iterations for one component's placement at most: one that converges takes 5 to 20
/// from a far start; one that cannot would run to the assembly's limit (100 by default), tried
/// from four rotations, for each component, twice.
const PLACING_ITERATIONS: usize = 30;

/// The rotations a component's placement is tried from, after its own: none, then half a
/// turn about each axis of its frame. Newton on a rotation can stop where the mates' residual
/// is least nearby, and such a minimum lies about half a turn from the solution.
const HALF_TURNS: [[f64; 4]; 4] = [
    [1.0, 0.0, 0.0, 0.0],
    [0.0, 1.0, 0.0, 0.0],
    [0.0, 0.0, 1.0, 0.0],
    [0.0, 0.0, 0.0, 1.0],
];

impl Assembly {
    /// Poses where the mates `set` (indices) all hold, found by placing the components they
    /// join one at a time and then solving the set whole from there, if that finds one.
    ///
    /// Grounded components are placed to begin with. Then, while some component is joined by
    /// a mate of the set to placed components (or to the world), the one those mates hold by
    /// the most conditions is solved against them, every other component held where it is,
    /// the first among equals: a ball joint's three and a pair of collinear edges' four place
    /// a part before a ball joint and a distance, 3 + 1, leave another free to turn. Its pose
    /// is kept whether or not those mates all held. Where no mate of the set ties a component
    /// left to the placed ones, the one the set's mates hold by the most conditions keeps its
    /// pose and counts as placed (a group of parts joined only among themselves floats), until
    /// none is left that a mate of the set joins. Then each placed component is solved once
    /// more in the same order, against all of its mates.
    ///
    /// Where a component could not be placed against all of the mates it met, it is left
    /// where its solve ended; if the set whole then fails, the placement is built once more
    /// with each such component placed against as many of those mates as hold together
    /// (see [`Assembly::placement`]). Neither way is better in every case: of the first
    /// thousand random assemblies from seed 27,500 solved from far away, the first alone named
    /// one false conflict (27,527), the second alone two others.
    pub(super) fn placed_in_turn(&self, set: &[usize]) -> Option<Vec<Pose>> {
        match self.placement(set, false) {
            Ok(poses) => Some(poses),
            Err(true) => self.placement(set, true).ok(),
            Err(false) => None,
        }
    }

    /// The index of the component a selection is on (`None` for the world).
    pub(super) fn component_of(&self, s: &Selection) -> Option<usize> {
        s.component
            .as_ref()
            .and_then(|n| self.components.iter().position(|c| &c.name == n))
    }

    /// [`Assembly::placed_in_turn`], one way: `partial` places a component whose mates
    /// cannot all hold against as many of them as do. `Err` says whether some component's
    /// mates could not all hold, so that `partial` would build another placement.
    fn placement(&self, set: &[usize], partial: bool) -> Result<Vec<Pose>, bool> {
        let ends: Vec<(usize, Option<usize>, Option<usize>)> = set
            .iter()
            .map(|&m| {
                let mate = &self.mates[m];
                (m, self.component_of(&mate.a), self.component_of(&mate.b))
            })
            .collect();
        let mut placed: Vec<bool> = self.components.iter().map(|c| c.grounded).collect();
        let mut work = self.clone();
        // How many conditions each mate sets (at least one: an angle, or one that compiles
        // to nothing here).
        let weight: Vec<usize> = work
            .compile_all()
            .iter()
            .map(|c| {
                c.as_ref()
                    .map_or(0, |p| p.iter().map(Prim::conditions).sum())
                    .max(1)
            })
            .collect();
        work.options.diagnose = false;
        let whole_iterations = work.options.max_iterations;
        work.options.max_iterations = whole_iterations.min(PLACING_ITERATIONS);
        // The mates of the set that join component `c` to placed components or the world.
        let holding = |c: usize, placed: &[bool]| -> Vec<usize> {
            let fixed = |x: Option<usize>| x.is_none_or(|x| placed[x]);
            ends.iter()
                .filter(|&&(_, a, b)| (a == Some(c) && fixed(b)) || (b == Some(c) && fixed(a)))
                .map(|&(m, _, _)| m)
                .collect()
        };
        // Every mate of the set that joins component `c`.
        let joining = |c: usize| -> Vec<usize> {
            ends.iter()
                .filter(|&&(_, a, b)| a == Some(c) || b == Some(c))
                .map(|&(m, _, _)| m)
                .collect()
        };
        // Component `c` solved against `mates` alone, every other held where it is: from where
        // it is, then turned half a turn about each axis of its frame, until they all hold
        // (`Ok`, the pose they hold at). Otherwise `Err` with where the first solve ended.
        let attempt = |work: &Assembly, c: usize, mates: &[usize]| -> Result<Pose, Pose> {
            let start = work.components[c].pose;
            let mut first = None;
            for turn in HALF_TURNS {
                let mut step = work.clone();
                for (i, comp) in step.components.iter_mut().enumerate() {
                    comp.grounded = i != c;
                }
                step.components[c].pose.rotation = math::qmul(start.rotation, turn);
                step.mates = mates.iter().map(|&m| self.mates[m].clone()).collect();
                // The solve writes the poses it ends at, solved or not. An error (none is
                // known: these mates built as part of the set) moves nothing.
                let Ok(report) = step.solve_quietly() else {
                    continue;
                };
                let pose = step.components[c].pose;
                if report.outcome.is_ok() && report.all_hold() {
                    return Ok(pose);
                }
                first.get_or_insert(pose);
            }
            Err(first.unwrap_or(start))
        };
        // Component `c` placed against `mates`: where they all hold (true). Where they cannot
        // all hold from here, as where `c` closes a loop whose other parts sit where their own
        // mates left them free to, `c` is placed against as many of them as hold together,
        // the mates setting the most conditions taken first (seed 27,527 of the far starts: a
        // part on a cylindrical joint to the ground and another to a part placed before it
        // stayed where it was drawn, 5.7 off its axis, and the set whole failed from there).
        let mut split = false;
        let mut place = |work: &mut Assembly, c: usize, mates: &[usize]| -> bool {
            let first = match attempt(work, c, mates) {
                Ok(pose) => {
                    work.components[c].pose = pose;
                    return true;
                }
                Err(pose) => pose,
            };
            split |= mates.len() > 1;
            if !partial {
                work.components[c].pose = first;
                return false;
            }
            let mut by_weight = mates.to_vec();
            by_weight.sort_by_key(|&m| std::cmp::Reverse(weight[m]));
            let mut kept: Vec<usize> = Vec::new();
            let mut best = None;
            if by_weight.len() > 1 {
                for m in by_weight {
                    kept.push(m);
                    match attempt(work, c, &kept) {
                        Ok(pose) => best = Some(pose),
                        Err(_) => {
                            kept.pop();
                        }
                    }
                }
            }
            work.components[c].pose = best.unwrap_or(first);
            false
        };
        let mut order = Vec::new();
        loop {
            let mut best: Option<(usize, Vec<usize>)> = None;
            let mut most = 0;
            for c in (0..placed.len()).filter(|&c| !placed[c]) {
                let mates = holding(c, &placed);
                let held: usize = mates.iter().map(|&m| weight[m]).sum();
                if held > most {
                    most = held;
                    best = Some((c, mates));
                }
            }
            let Some((c, mates)) = best else {
                // Parts joined only among themselves (none to a placed part or the world) float
                // as a group, which Newton may meet from anywhere: the one its mates hold by the
                // most conditions stays where it is, and the rest are placed about it.
                let mut anchor = None;
                let mut most = 0;
                for c in (0..placed.len()).filter(|&c| !placed[c]) {
                    let held: usize = joining(c).iter().map(|&m| weight[m]).sum();
                    if held > most {
                        most = held;
                        anchor = Some(c);
                    }
                }
                let Some(c) = anchor else {
                    break;
                };
                placed[c] = true;
                order.push(c);
                continue;
            };
            place(&mut work, c, &mates);
            placed[c] = true;
            order.push(c);
        }
        // A component placed early met only some of its mates, and those left it free to sit
        // anywhere they allow: once more in the same order, each against all of its mates.
        let mut missed = Vec::new();
        for &c in &order {
            if !place(&mut work, c, &joining(c)) {
                missed.push(c);
            }
        }
        // The set whole from there, quietly: from the user's poses its solve, and the
        // diagnosis's attempts to build it up, have failed already.
        work.options.max_iterations = whole_iterations;
        if let Some(poses) = work.holds_alone(set, true) {
            return Ok(poses);
        }
        // A component that could not be placed against all its mates closes a loop whose
        // other parts were placed at one of the angles their joints allow, not the one it
        // needs (seed 393 of the far starts: three parts joined in a ring by a revolute, a
        // concentric pair and collinear edges). The set whole once more from each half turn
        // of each such component.
        for &c in &missed {
            for turn in &HALF_TURNS[1..] {
                let mut turned = work.clone();
                let pose = &mut turned.components[c].pose;
                pose.rotation = math::qmul(pose.rotation, *turn);
                if let Some(poses) = turned.holds_alone(set, true) {
                    return Ok(poses);
                }
            }
        }
        Err(split)
    }
}
