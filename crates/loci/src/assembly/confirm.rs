//! A conflict named among mates, checked the way a user would check it before it is reported:
//! its mates alone, on the same components from the same poses, solved as an assembly of their
//! own.
//!
//! The core confirms a conflict by solving its constraints alone from where the whole assembly
//! started, after the whole assembly's prealignment. Solving is local, so a set can fail from
//! there and still hold: alone, its mates are prealigned for themselves and solved without the
//! unknowns of references they do not use, and the solve can find a placement where every one
//! of them holds. Such a set is no conflict,
//! and that placement is a better start for the whole assembly: solved again from it, the
//! assembly either solves, or fails naming a set that is checked in turn, a few rounds at
//! most. When every named set holds alone, the conflict is looked for mate by mate (a
//! deletion filter over the assembly's mates, [`Assembly::left_failing`]); only where that
//! finds none either is the outcome `did_not_converge`, not a conflict loci knows to be false.

use super::{Assembly, AssemblyReport, MateStatus, Pose};
use crate::geom::SplitMix;
use crate::par;

/// How many times an assembly is solved again from the placement of a set that held alone.
const MAX_ROUNDS: usize = 3;

/// The largest conflict whose mates are each checked to be needed (see [`Assembly::shrunk`]).
/// Seed 34,592 of the random assemblies, lengthened, has the core name nine mates of which
/// eight fail alone: the core's set is minimal among its equations, not among mates.
const MAX_SHRINK: usize = 12;

/// Starts drawn at random for the parts a set moves, tried once every other check of the set
/// has failed (see [`Assembly::held_scattered`]). Ten mates of seed 374 of the random
/// assemblies, lengthened, hold from 7 of 40 such starts (solved without the core's search,
/// as here): eight starts miss them a fifth of the time (0.825^8), and the ten would have been
/// named a conflict. Each start that fails costs a solve of a few milliseconds.
const SCATTERED_STARTS: usize = 32;

/// The most free parts a set may move for starts drawn at random to be tried.
const MAX_SCATTERED_PARTS: usize = 8;

/// The most mates with equations an assembly may have for its failure to be searched mate by
/// mate for a conflict, when every set the core named held alone (see
/// [`Assembly::left_failing`]): one check of a set per mate, a fraction of a second each
/// where the set fails. Seed 374 of the random assemblies, lengthened, has 13 and names 11.
const MAX_FILTER: usize = 24;

/// What checking the named conflicts found.
pub(super) enum Checked {
    /// These sets (mate indices), each failing alone from the present poses: the first named,
    /// or those of a solve again from the placement of a set that held alone.
    Confirmed(Vec<Vec<usize>>),
    /// The whole assembly solved from the placement of a set that held alone.
    Solved(Box<(Assembly, AssemblyReport)>),
    /// Every round named a set that held alone, or named none.
    Disproved,
}

impl Assembly {
    /// Checks `sets` (mate indices), each by solving its mates alone from the components'
    /// present poses. From the placement of one that holds, the whole assembly is solved
    /// again, and the sets that solve names are checked in turn, from the same present poses.
    /// `solved[i]` says whether mate `i` gave the solve equations: a set holding every such
    /// mate is the assembly as solved, whose solve and diagnosis have failed already.
    pub(super) fn check_conflicts(&self, mut sets: Vec<Vec<usize>>, solved: &[bool]) -> Checked {
        // The whole assembly alone is the solve that failed: it is tried once more from a
        // start placed one component at a time. Any other set is solved alone from the
        // present poses, and then from such a start.
        let holds = |set: &Vec<usize>| {
            let whole = (0..solved.len()).all(|i| !solved[i] || set.contains(&i));
            if whole {
                self.placed_in_turn(set)
            } else {
                self.held_alone(set)
            }
        };
        // Every mate named so far, in any round.
        let mut named: Vec<usize> = Vec::new();
        for round in 0..=MAX_ROUNDS {
            named.extend(sets.iter().flatten().copied());
            let Some(placed) = sets.iter().find_map(holds) else {
                return Checked::Confirmed(sets.into_iter().map(|s| self.shrunk(s)).collect());
            };
            if round == MAX_ROUNDS {
                break;
            }
            let mut again = self.posed(&placed);
            // The same components and mates as the solve that named the set: an error here
            // (none is known) leaves the set disproved all the same.
            let Ok(report) = again.solve_checked(false) else {
                break;
            };
            if report.outcome.is_ok() {
                return Checked::Solved(Box::new((again, report)));
            }
            let index = |id: &String| self.mates.iter().position(|m| &m.id == id);
            sets = report
                .conflicts
                .iter()
                .map(|s| s.iter().filter_map(index).collect())
                .collect();
            if sets.is_empty() {
                break;
            }
        }
        self.left_failing(solved, &named)
    }

    /// A conflict found without the core's names, once every set it named held alone: the
    /// mates with equations, less each mate in turn where the rest still fails alone (a
    /// deletion filter). What is left fails alone, and holds without any one of its mates:
    /// each was kept because the set less it held, at a placement where every smaller set
    /// holds too. Mates never named are taken out first, so that the set keeps what the core
    /// pointed at where it can. Seed 27,766 of the random assemblies, a distance lengthened
    /// on four parts locked by redundant mates, failed from every one of 200 random starts, and
    /// each of the three sets named in turn held alone: it read `did_not_converge`.
    ///
    /// Only up to [`MAX_FILTER`] mates: each check of a set that fails costs several solves.
    pub(super) fn left_failing(&self, solved: &[bool], named: &[usize]) -> Checked {
        let mut kept: Vec<usize> = (0..solved.len()).filter(|&i| solved[i]).collect();
        if kept.len() < 2 || kept.len() > MAX_FILTER {
            return Checked::Disproved;
        }
        if let Some(placed) = self.placed_in_turn(&kept) {
            // The whole assembly holds from a start placed in turn after all.
            let mut again = self.posed(&placed);
            return match again.solve_checked(false) {
                Ok(report) if report.outcome.is_ok() => Checked::Solved(Box::new((again, report))),
                _ => Checked::Disproved,
            };
        }
        // A loop of parts drawn far from where it closes can fail from its poses and from a
        // start placed in turn, with every smaller set holding: the whole is tried from the
        // scattered starts too before its mates are searched one by one. The far start of seed
        // 39,505 of the random assemblies (three parts closing a loop on the ground through a
        // slider and two hinges) read `did_not_converge` after 2.8 s; it solves in 1.2 s.
        if let Some(placed) = self.held_scattered(&kept) {
            let mut again = self.posed(&placed);
            if let Ok(report) = again.solve_checked(false) {
                if report.outcome.is_ok() {
                    return Checked::Solved(Box::new((again, report)));
                }
            }
        }
        let mut order: Vec<usize> = kept
            .iter()
            .copied()
            .filter(|i| !named.contains(i))
            .collect();
        order.extend(kept.iter().copied().filter(|i| named.contains(i)));
        // Each smaller set is checked by the quick solves of `held_alone` (plain, and placed
        // one part at a time) and from starts drawn at random; the set left is also checked
        // with the core's search, so that a set only that search can place is not named.
        // A set that holds from a fifth of random starts fails all of eight a fifth of the
        // time, and a mate taken out on such a failure leaves a set that holds: seed 374
        // lost one that way, and read `did_not_converge` with its starts at eight.
        let quick = |set: &[usize]| {
            self.holds_alone(set, true)
                .or_else(|| self.placed_in_turn(set))
                .or_else(|| self.held_scattered(set))
                .is_some()
        };
        // `kept` was checked from the random starts as a smaller set once a mate was taken
        // out.
        let whole = kept.len();
        for i in order {
            let less: Vec<usize> = kept.iter().copied().filter(|&m| m != i).collect();
            if !less.is_empty() && !quick(&less) {
                kept = less;
            }
        }
        if self
            .holds_alone(&kept, false)
            .or_else(|| {
                (kept.len() == whole)
                    .then(|| self.held_scattered(&kept))
                    .flatten()
            })
            .is_some()
        {
            return Checked::Disproved;
        }
        Checked::Confirmed(vec![kept])
    }

    /// `set`, a conflict shown to fail alone, less every mate it fails without as well: the
    /// core shrinks a conflict among the equations it solved, where a hinge's axes held
    /// opposed count as parallel, and the mates without one of them can still be impossible
    /// (seed 28,202 of the random assemblies named a hinge, a distance it cannot reach and a
    /// second distance, which the hinge and the first alone fail without). Each mate is
    /// left out in turn, and kept out where the rest fails alone as a named set must: solved
    /// from the present poses and from a start placed one component at a time. Sets of more
    /// than [`MAX_SHRINK`] mates are left as named: a solve per mate, each failing one
    /// placed in turn, would cost more than the diagnosis that named them.
    fn shrunk(&self, set: Vec<usize>) -> Vec<usize> {
        if set.len() < 2 || set.len() > MAX_SHRINK {
            return set;
        }
        let mut kept = set;
        let mut i = 0;
        while i < kept.len() && kept.len() > 1 {
            let mut less = kept.clone();
            less.remove(i);
            if self.held_alone(&less).is_none() {
                kept = less;
            } else {
                i += 1;
            }
        }
        kept
    }

    /// A placement where the mates `set` hold alone, by the check a named set must fail:
    /// solved from the present poses, then from a start placed one component at a time.
    ///
    /// The solve from the present poses is tried plainly first, and with the core's search
    /// for a solution where it fails (naming its conflicts, building the set up constraint by
    /// constraint) only after the start placed in turn: that search solves hundreds of subsets,
    /// and five mates of `mirror_branch_false_conflict.json` took it 0.5 to 2 s each time,
    /// where placing the parts in turn holds them in milliseconds.
    fn held_alone(&self, set: &[usize]) -> Option<Vec<Pose>> {
        self.holds_alone(set, true)
            .or_else(|| self.placed_in_turn(set))
            .or_else(|| self.holds_alone(set, false))
            .or_else(|| self.held_scattered(set))
    }

    /// A placement where the mates `set` hold alone, solved from [`SCATTERED_STARTS`] starts
    /// drawn at random for the free parts they join (anywhere as far from the origin as the
    /// farthest part, at any rotation; the same starts on every run): a loop of parts drawn
    /// far from where it closes can fail from its poses and from every start built from
    /// them. Four mates closing such a loop (two concentric pairs, a hinge and a slider:
    /// the far start of seed 32,718 of the random assemblies) failed every other check and
    /// were named a conflict; they hold from 97 of 100 random starts. Only sets that fail
    /// every other check pay for it.
    fn held_scattered(&self, set: &[usize]) -> Option<Vec<Pose>> {
        let mut parts: Vec<usize> = set
            .iter()
            .flat_map(|&m| {
                let mate = &self.mates[m];
                [self.component_of(&mate.a), self.component_of(&mate.b)]
            })
            .flatten()
            .filter(|&c| !self.components[c].grounded)
            .collect();
        parts.sort_unstable();
        parts.dedup();
        if parts.is_empty() || parts.len() > MAX_SCATTERED_PARTS {
            return None;
        }
        let reach = self
            .components
            .iter()
            .map(|c| c.pose.translation.iter().map(|v| v * v).sum::<f64>().sqrt())
            .fold(1.0, f64::max);
        let seed = set.iter().fold(0x5CA7_7E2Eu64, |h, &m| {
            h.wrapping_mul(0x100_0000_01B3).wrapping_add(m as u64 + 1)
        });
        let mut rng = SplitMix(seed);
        let mut poses: Vec<Pose> = self.components.iter().map(|c| c.pose).collect();
        let starts: Vec<Vec<Pose>> = (0..SCATTERED_STARTS)
            .map(|_| {
                for &c in &parts {
                    poses[c].translation = [0; 3].map(|_| reach * rng.uniform());
                    poses[c].rotation = loop {
                        let q = [0; 4].map(|_| rng.uniform());
                        let n = q.iter().map(|v| v * v).sum::<f64>().sqrt();
                        if n > 0.1 {
                            break q.map(|v| v / n);
                        }
                    };
                }
                poses.clone()
            })
            .collect();
        // The starts are tried on every core, the first that holds in their order kept: a
        // set that fails pays a solve per start, about half of a conflict's check on two
        // cores (0.4 to 1.1 s each time for seed 34,592's sets).
        par::first_some(starts.len(), |k| {
            self.posed(&starts[k]).holds_alone(set, true)
        })
    }

    /// The placement where the mates `set` all hold, solved alone from the present poses
    /// without a diagnosis, if there is one. A subset of mates that built and solved as part
    /// of the whole cannot be malformed alone; should its solve still fail with an error, the
    /// set counts as failing, as the core's own check found. `quietly`: without the core
    /// naming the conflicts of a failure ([`Assembly::solve_quietly`]).
    pub(super) fn holds_alone(&self, set: &[usize], quietly: bool) -> Option<Vec<Pose>> {
        let mut alone = self.alone(set);
        let report = if quietly {
            alone.solve_quietly()
        } else {
            alone.solve_checked(false)
        }
        .ok()?;
        (report.outcome.is_ok() && report.all_hold())
            .then(|| report.components.iter().map(|c| c.pose).collect())
    }
}

impl Assembly {
    /// The mates `set` alone, on the same components from the same poses, not diagnosed.
    fn alone(&self, set: &[usize]) -> Assembly {
        let mut alone = self.clone();
        alone.mates = set.iter().map(|&i| self.mates[i].clone()).collect();
        alone.options.diagnose = false;
        alone
    }

    /// The same assembly with its components at `poses`.
    pub(super) fn posed(&self, poses: &[Pose]) -> Assembly {
        let mut posed = self.clone();
        for (c, p) in posed.components.iter_mut().zip(poses) {
            c.pose = *p;
        }
        posed
    }
}

/// The report of an assembly solved again from another placement, told as the solve from
/// the user's poses: a mate that did not hold there was adjusted, not already satisfied.
pub(super) fn as_from_start(mut report: AssemblyReport, held: &[bool]) -> AssemblyReport {
    for (m, &held) in report.mates.iter_mut().zip(held) {
        if m.status == MateStatus::Satisfied && !held {
            m.status = MateStatus::Adjusted;
        }
    }
    report
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::assembly::MateReport;
    use crate::Outcome;

    fn mate(id: &str, status: MateStatus) -> MateReport {
        MateReport {
            id: id.into(),
            kind: "distance".into(),
            status,
            value: Some(1.0),
            error: 0.0,
            message: String::new(),
            limit_violated: false,
        }
    }

    #[test]
    fn a_mate_satisfied_only_at_the_new_start_reads_adjusted() {
        let report = AssemblyReport {
            outcome: Outcome::Okay,
            dof: 0,
            iterations: 3,
            residual: 0.0,
            mates: vec![
                mate("held", MateStatus::Satisfied),
                mate("moved", MateStatus::Satisfied),
                mate("solved", MateStatus::Adjusted),
                mate("spare", MateStatus::Redundant),
            ],
            components: Vec::new(),
            conflicts: Vec::new(),
            redundant: Vec::new(),
        };
        let told = as_from_start(report, &[true, false, false, false]);
        let statuses: Vec<MateStatus> = told.mates.iter().map(|m| m.status).collect();
        assert_eq!(
            statuses,
            [
                MateStatus::Satisfied,
                MateStatus::Adjusted,
                MateStatus::Adjusted,
                MateStatus::Redundant
            ]
        );
        assert_eq!(told.iterations, 3);
    }
}
