//! The candidate each named set was shrunk from, for a set whose check alone decides nothing.
//!
//! The deletion filter shrinks a candidate conflict to a set that fails near the drawing while
//! each of its parts holds; before it is named, the set is solved alone every way the solve
//! would ([`super::checked_alone`]). Where every one of those solves was still going when its
//! iterations ran out, the set is undecided and not named: a set that holds only far from the
//! drawing is reached that way by creeping. A set that cannot hold creeps too where its
//! least-squares point lies where an equation is not differentiable: a triangle of three
//! distances with an angle at one corner that contradicts them (seed 570,880 of the random
//! systems against SolveSpace) shrinks to the angle and two of the distances, whose solves
//! run the third corner into the corner with the angle (the line between them shrinks to
//! nothing, where the angle's equation holds trivially) and creep there. The candidate it was
//! shrunk from, all four, stops short of holding from every start, and is named instead, not
//! called minimal.

use super::{checked_alone, Checked, ConflictSet, Member};
use crate::model::{GroupId, System};
use crate::solve::Config;

/// Each set the deletion filter shrank, with the candidate it was shrunk from.
#[derive(Default)]
pub(super) struct Shrunk {
    from: Vec<(Vec<Member>, Vec<Member>)>,
}

impl Shrunk {
    /// Records that `set` was shrunk from `candidate`.
    pub(super) fn record(&mut self, set: &[Member], candidate: &[Member]) {
        if set.len() < candidate.len() && !self.from.iter().any(|(s, _)| s == set) {
            self.from.push((set.to_vec(), candidate.to_vec()));
        }
    }

    /// `set`, when it fails alone ([`checked_alone`]); when it is undecided, the candidate it
    /// was shrunk from, when that fails alone; otherwise nothing. Where either holds from a
    /// start drawn at random, the values there are pushed on `solutions`.
    pub(super) fn failing_alone(
        &self,
        sys: &System,
        group: GroupId,
        set: ConflictSet,
        cfg: &Config,
        solutions: &mut Vec<Vec<f64>>,
    ) -> Option<ConflictSet> {
        match checked_alone(sys, group, &set.members, cfg, solutions) {
            Checked::Fails => Some(set),
            Checked::Holds => None,
            Checked::Undecided => {
                let (_, candidate) = self.from.iter().find(|(s, _)| *s == set.members)?;
                (checked_alone(sys, group, candidate, cfg, solutions) == Checked::Fails).then(
                    || ConflictSet {
                        members: candidate.clone(),
                        verified: false,
                    },
                )
            }
        }
    }
}
