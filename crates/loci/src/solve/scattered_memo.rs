//! The answers of the last few checks from scattered starts, kept per thread.
//!
//! A failing solve asks whether its group holds from starts drawn at random more than once
//! over: the solve that gives up asks, the diagnosis that follows asks again for the same
//! group (as it looks for a solution further off, and as it solves the group once more
//! before naming conflicts). Each asking solves a small group from 64 starts; a slider-crank
//! whose mates cannot all hold asked about its whole group three times, a third of its
//! diagnosis. The check is a function of the system, the group and the configuration alone
//! (its starts are drawn from each parameter's handle and value), so an answer is reused only
//! for a system equal to the one it was found for in every parameter, entity and constraint,
//! to the last bit of every value.

use super::rescue::Scattered;
use super::Config;
use crate::model::{GroupId, System};
use std::cell::RefCell;

/// How many answers a thread keeps: enough for a solve and the diagnosis after it.
const KEPT: usize = 4;

/// Systems larger than this (parameters, entities and constraints together) are not kept:
/// their description would cost memory, and the checks from scattered starts that repeat are
/// those of small groups.
const LARGEST: usize = 2_000;

thread_local! {
    static ANSWERS: RefCell<Vec<(String, Scattered)>> = const { RefCell::new(Vec::new()) };
}

/// Everything the check's answer depends on, exactly: every value written with all the
/// digits that give it back (`-0.0` apart from `0.0`).
fn key(sys: &System, group: GroupId, cfg: &Config) -> Option<String> {
    let size = sys.params().len() + sys.entities().len() + sys.constraints().len();
    (size <= LARGEST).then(|| {
        format!(
            "{group:?}|{cfg:?}|{:?}|{:?}|{:?}",
            sys.params(),
            sys.entities(),
            sys.constraints()
        )
    })
}

/// The answer of `check` for `sys`, `group` and `cfg`, found again or reused.
pub(super) fn remembered(
    sys: &System,
    group: GroupId,
    cfg: &Config,
    check: impl FnOnce() -> Scattered,
) -> Scattered {
    let Some(key) = key(sys, group, cfg) else {
        return check();
    };
    let found = ANSWERS.with_borrow(|answers| {
        answers
            .iter()
            .find(|(k, _)| *k == key)
            .map(|(_, answer)| answer.clone())
    });
    if let Some(answer) = found {
        return answer;
    }
    let answer = check();
    ANSWERS.with_borrow_mut(|answers| {
        if answers.len() == KEPT {
            answers.remove(0);
        }
        answers.push((key, answer.clone()));
    });
    answer
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::{Param, ParamId};
    use std::cell::Cell;

    fn one_param(val: f64) -> System {
        let mut sys = System::new();
        sys.add_param(Param::new(1, 2, val)).unwrap();
        sys
    }

    /// The answer for `sys`, counting in `checks` whether it was found afresh.
    fn asked(sys: &System, cfg: &Config, checks: &Cell<usize>) -> Vec<f64> {
        let answer = remembered(sys, GroupId(2), cfg, || {
            checks.set(checks.get() + 1);
            Scattered::Held(vec![sys.params()[0].val])
        });
        match answer {
            Scattered::Held(values) => values,
            _ => unreachable!("the check above always holds"),
        }
    }

    #[test]
    fn an_answer_is_reused_for_an_equal_system_only() {
        let cfg = Config::default();
        let checks = Cell::new(0);
        let sys = one_param(1.5);
        assert_eq!(asked(&sys, &cfg, &checks), [1.5]);
        assert_eq!(asked(&sys.clone(), &cfg, &checks), [1.5]);
        assert_eq!(
            checks.get(),
            1,
            "an equal system (a copy) is answered again"
        );

        // A value changed in its last bit, a zero of the other sign, another tolerance.
        let mut nudged = sys.clone();
        nudged.set_value(ParamId(1), f64::from_bits(1.5f64.to_bits() + 1));
        assert_eq!(asked(&nudged, &cfg, &checks), [nudged.params()[0].val]);
        assert_eq!(checks.get(), 2);
        assert_eq!(asked(&one_param(0.0), &cfg, &checks), [0.0]);
        let negative = asked(&one_param(-0.0), &cfg, &checks);
        assert!(negative[0].is_sign_negative());
        assert_eq!(checks.get(), 4);
        let loose = Config {
            tolerance: 1e-6,
            ..cfg.clone()
        };
        asked(&sys, &loose, &checks);
        assert_eq!(checks.get(), 5);

        // Only the last few answers are kept: the first is long gone.
        asked(&sys, &cfg, &checks);
        assert_eq!(checks.get(), 6);
    }
}
