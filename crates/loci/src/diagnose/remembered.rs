//! The last checks of a set kept alone ([`super::checked_alone`]), remembered on each thread.
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
    /// Not within the iterations allowed, every solve still going when they ran out: not
    /// shown to fail ([`crate::solve::Scattered::Undecided`]).
    Undecided,
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::format::json::Problem;
    use std::cell::Cell;

    fn two_points(x: f64) -> System {
        let text = format!(
            r#"{{"params": [{{"h": 1, "group": 2, "val": 0.0}}, {{"h": 2, "group": 2, "val": 0.0}},
                {{"h": 3, "group": 2, "val": {x}}}, {{"h": 4, "group": 2, "val": 0.0}}],
              "entities": [{{"h": 1, "group": 2, "type": "point_in_3d", "params": [1, 2, 4]}},
                {{"h": 2, "group": 2, "type": "point_in_3d", "params": [3, 4, 4]}}],
              "constraints": [{{"h": 1, "group": 2, "type": "pt_pt_distance", "val": 2.0,
                "pt_a": 1, "pt_b": 2}}]}}"#
        );
        Problem::from_json(&text).expect("a valid problem").system
    }

    #[test]
    fn the_same_question_is_answered_once_and_a_changed_value_is_asked_again() {
        let cfg = Config::default();
        let runs = Cell::new(0);
        let check = || {
            runs.set(runs.get() + 1);
            Alone::Held(vec![f64::from(runs.get())])
        };
        let ask = |sys: &System| match remembered(sys, GroupId(2), &cfg, check) {
            Alone::Held(v) => v[0],
            other => panic!("{other:?}"),
        };
        assert_eq!(ask(&two_points(1.0)), 1.0);
        assert_eq!(ask(&two_points(1.0)), 1.0);
        assert_eq!(runs.get(), 1);
        // Another value, another question; and -0 is not 0.
        assert_eq!(ask(&two_points(1.5)), 2.0);
        assert_eq!(ask(&two_points(0.0)), 3.0);
        assert_eq!(ask(&two_points(-0.0)), 4.0);
        // Other settings, another question.
        let strict = Config::default().with_tolerance(1e-12);
        assert!(matches!(
            remembered(&two_points(1.0), GroupId(2), &strict, || Alone::Fails),
            Alone::Fails
        ));
        assert_eq!(runs.get(), 4);
        // Only the last REMEMBERED are kept.
        for k in 0..REMEMBERED {
            ask(&two_points(10.0 + k as f64));
        }
        let before = runs.get();
        assert_eq!(ask(&two_points(1.0)), f64::from(before + 1));
    }
}
