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
//! shrunk from, all four, stops short of holding from every start: it is shrunk again, each part
//! judged by those checks, and named.

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
    /// was shrunk from, when that fails alone, shrunk again by those checks ([`reshrunk`]);
    /// otherwise nothing. Where `set` or its candidate holds from a start drawn at random, the
    /// values there are pushed on `solutions`.
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
                if candidate.len() > RESHRUNK_UP_TO
                    || checked_alone(sys, group, candidate, cfg, solutions) != Checked::Fails
                {
                    return None;
                }
                Some(reshrunk(sys, group, candidate, cfg))
            }
        }
    }
}

/// The most members a candidate may have to be shrunk again by [`reshrunk`]: each member costs
/// a check alone, and one that creeps runs every scattered start to the end of its iterations.
const RESHRUNK_UP_TO: usize = 16;

/// `candidate`, which fails alone, less every member without which the rest still fails alone
/// ([`checked_alone`]): the deletion filter again, each part judged by every way the solve would
/// look for a solution rather than by Newton near the drawing. Random sketch 31,931 changed
/// (`tests/sketch_named_conflicts.rs`) shrinks near the drawing to a set that holds only far
/// from it and reads undecided; its candidate of seven fails alone and is shrunk here to the six
/// that conflict, where naming the candidate whole named an unneeded horizontal too. Called
/// verified when every part left without one member was shown to hold; a part that only crept
/// leaves its member in, unproven.
fn reshrunk(sys: &System, group: GroupId, candidate: &[Member], cfg: &Config) -> ConflictSet {
    // Solutions of the parts are not starts for the search: only a named set dropped gives one.
    let mut scratch = Vec::new();
    let mut members = candidate.to_vec();
    let mut verified = true;
    let mut i = 0;
    while i < members.len() {
        let mut less = members.clone();
        less.remove(i);
        match checked_alone(sys, group, &less, cfg, &mut scratch) {
            Checked::Fails => members = less,
            Checked::Holds => i += 1,
            Checked::Undecided => {
                verified = false;
                i += 1;
            }
        }
    }
    ConflictSet { members, verified }
}
