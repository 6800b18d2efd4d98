//! The last checks of a set kept alone ([`super::built_alone`]), remembered on each thread.
//!
//! A sketch that cannot hold is solved several times over: once with its soft constraints,
//! once more by the diagnosis that picks the soft constraint in the way, again without it, and
//! so on. Each of those names the same conflict and checks it alone again, from the same
//! values: a check that fails from every one of its 64 scattered starts is the most expensive
//! solve there is (random sketch 31,931: three checks of one set of five constraints, 250 ms
//! each, a quarter of a second apiece). The check is a function of the set's own system
//! alone (its parameters, entities and constraints, with their values), the group and the
//! settings, so its answer is remembered for the same question, asked the same way: the
//! answer is the one the check gives, whether it is run or remembered.

use std::cell::RefCell;
use std::collections::VecDeque;

use crate::model::{GroupId, System};
use crate::solve::Config;

/// How a set kept alone solved.
#[derive(Clone, Debug)]
pub(super) enum Alone {
    /// By one of the solve's rescues from the drawing.
    Rescued,
    /// From a start drawn at random: every parameter of the set's system where it holds.
    Held(Vec<f64>),
    /// Not at all.
    Fails,
}

/// How many checks each thread remembers (the most recent).
const REMEMBERED: usize = 16;

/// The largest set's system, as JSON text, whose check is remembered: a larger one is rare
/// and its text is not worth keeping.
const LARGEST_KEY: usize = 1 << 16;

/// What a check is asked: the group, the settings and the set's system as JSON text (which
/// writes every parameter, entity and constraint, and every value exactly), and how the
/// equations are written on this thread (the tests compare the ways, see [`written`]).
#[derive(PartialEq)]
struct Question {
    group: GroupId,
    cfg: Config,
    part: Vec<u8>,
    written: (bool, bool),
}

/// How the equations are written on this thread: carried entities as expressions, and
/// derivatives by hand where they are written out. Other ways exist only in tests.
fn written() -> (bool, bool) {
    #[cfg(test)]
    let by_hand = !crate::equations::spatial::dual_only_now();
    #[cfg(not(test))]
    let by_hand = true;
    (crate::equations::as_expressions(), by_hand)
}

thread_local! {
    static CHECKED: RefCell<VecDeque<(Question, Alone)>> = const { RefCell::new(VecDeque::new()) };
}

/// The answer of `check` for the set's system `part`, remembered if it was asked before on
/// this thread with the same group and settings.
pub(super) fn remembered(
    part: &System,
    group: GroupId,
    cfg: &Config,
    check: impl FnOnce() -> Alone,
) -> Alone {
    let question = match serde_json::to_vec(part) {
        Ok(part) if part.len() <= LARGEST_KEY => Question {
            group,
            cfg: cfg.clone(),
            part,
            written: written(),
        },
        _ => return check(),
    };
    let known = CHECKED.with(|c| {
        c.borrow()
            .iter()
            .find(|(q, _)| *q == question)
            .map(|(_, a)| a.clone())
    });
    if let Some(answer) = known {
        return answer;
    }
    // Not borrowed while the check runs: it may check sets of its own.
    let answer = check();
    CHECKED.with(|c| {
        let mut c = c.borrow_mut();
        if c.len() >= REMEMBERED {
            c.pop_back();
        }
        c.push_front((question, answer.clone()));
    });
    answer
}
