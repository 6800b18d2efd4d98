//! Conflicts the core's names missed: found mate by mate, and checked from many starts.

use super::random::Rng;
use loci::assembly::{Assembly, MateStatus};
use loci::Outcome;

/// Whether `asm` solves, with every mate holding, from `starts` random placements of its
/// free components (and from its own): the independent check that a set is a conflict.
pub(super) fn solves_from_somewhere(asm: &Assembly, starts: usize, seed: u64) -> bool {
    let mut rng = Rng(seed);
    (0..=starts).any(|k| {
        let mut a = asm.clone();
        if k > 0 {
            for c in a.components.iter_mut().filter(|c| !c.grounded) {
                c.pose.translation = rng.point(4.0);
                c.pose.rotation = rng.rotation();
            }
        }
        a.options.diagnose = false;
        a.solve().is_ok_and(|r| r.outcome.is_ok() && r.all_hold())
    })
}

/// Four parts held by nine mates, eight of them redundant, and a distance from the ground
/// to one part lengthened (case 27,766 of the random assemblies). The core named a set of
/// seven mates, then, from the placement where those held, sets of four and five, and each
/// held alone: the report read `did_not_converge`, naming nothing, though no placement holds
/// them all (none of 200 random starts solves). The mates are now taken out one at a time
/// while the rest still fails alone, and what is left is named: a part pinned at a point
/// (`m1`), a second part on a cylindrical joint to the ground (`m7`) whose point must stay
/// on a sphere about the first one's (`m4`), and the lengthened distance. The four fail from
/// every start tried here, and any three of them hold.
#[test]
fn a_conflict_no_named_set_showed_is_found_mate_by_mate() {
    let text = include_str!("../data/assembly/conflict_found_mate_by_mate.json");
    let four = ["m1", "m4", "m7", "longer"].map(String::from).to_vec();
    let mut asm: Assembly = serde_json::from_str(text).unwrap();
    let grounded_before = asm.components[0].pose;
    let r = asm.solve().unwrap();
    assert_eq!(r.outcome, Outcome::Inconsistent, "{r}");
    assert_eq!(r.conflicts, vec![four.clone()], "{r}");
    for m in &r.mates {
        let conflicting = m.status == MateStatus::Conflicting;
        assert_eq!(conflicting, four.contains(&m.id), "{r}");
    }
    assert!(r
        .to_string()
        .contains("conflict: {m1, m4, m7, longer} cannot all hold"));
    assert_eq!(asm.components[0].pose, grounded_before);

    let whole: Assembly = serde_json::from_str(text).unwrap();
    let mut alone = whole.clone();
    alone.mates.retain(|m| four.contains(&m.id));
    assert!(!solves_from_somewhere(&alone, 10, 1), "the four held");
    for id in &four {
        let mut three = alone.clone();
        three.mates.retain(|m| &m.id != id);
        assert!(solves_from_somewhere(&three, 10, 2), "without {id}");
    }
}

/// Four parts held by thirteen mates, a distance from the ground to one of them lengthened
/// (case 374 of the random assemblies). Every set the core named held alone, and the search
/// mate by mate went up to twelve mates only: the report read `did_not_converge`. Searched
/// with thirteen, a smaller set that holds from a fifth of random starts missed all of the
/// eight it was tried from, its mate was taken out, and the ten left held: the search gave up
/// again. With each smaller set tried from 32 starts, eleven mates are named: all but two
/// distances (`m0` and `m6`). Checked outside loci's own check, none of 60 random starts
/// solves the eleven, and each ten solve; here, the eleven fail from every start tried, and
/// any ten of them hold.
#[test]
fn a_conflict_among_thirteen_mates_is_found_from_random_starts() {
    let text = include_str!("../data/assembly/conflict_of_eleven_of_thirteen.json");
    let eleven = [
        "m1", "m2", "m3", "m4", "m5", "m7", "m8", "m9", "m10", "m11", "longer",
    ]
    .map(String::from)
    .to_vec();
    let mut asm: Assembly = serde_json::from_str(text).unwrap();
    let r = asm.solve().unwrap();
    assert_eq!(r.outcome, Outcome::Inconsistent, "{r}");
    assert_eq!(r.conflicts, vec![eleven.clone()], "{r}");
    for m in &r.mates {
        let conflicting = m.status == MateStatus::Conflicting;
        assert_eq!(conflicting, eleven.contains(&m.id), "{r}");
    }

    let whole: Assembly = serde_json::from_str(text).unwrap();
    let mut alone = whole.clone();
    alone.mates.retain(|m| eleven.contains(&m.id));
    assert!(!solves_from_somewhere(&alone, 3, 3), "the eleven held");
    for id in &eleven {
        let mut ten = alone.clone();
        ten.mates.retain(|m| &m.id != id);
        assert!(solves_from_somewhere(&ten, 20, 4), "without {id}");
    }
}

/// Three free parts held by nine mates, a distance from the ground lengthened (case 267 of
/// the random assemblies), started from poses drawn at random. From its own poses the core
/// names sets that the assembly checks; from these, the core's diagnosis named nothing and
/// the report read `did_not_converge` (two of six random starts did so, the other four
/// named eight mates). The search mate by mate now runs there too, and names the same eight.
/// Checked outside loci's own check: none of 60 random starts solves the eight, and any seven
/// of them solve; here, any seven hold.
#[test]
fn a_conflict_the_diagnosis_gave_up_on_is_found_mate_by_mate() {
    let text = include_str!("../data/assembly/conflict_the_diagnosis_gave_up_on.json");
    let eight = ["m0", "m1", "m2", "m3", "m4", "m6", "m7", "longer"]
        .map(String::from)
        .to_vec();
    let mut asm: Assembly = serde_json::from_str(text).unwrap();
    let grounded_before = asm.components[0].pose;
    let r = asm.solve().unwrap();
    assert_eq!(r.outcome, Outcome::Inconsistent, "{r}");
    assert_eq!(r.conflicts, vec![eight.clone()], "{r}");
    for m in &r.mates {
        let conflicting = m.status == MateStatus::Conflicting;
        assert_eq!(conflicting, eight.contains(&m.id), "{r}");
    }
    assert_eq!(asm.components[0].pose, grounded_before);

    let whole: Assembly = serde_json::from_str(text).unwrap();
    let mut alone = whole.clone();
    alone.mates.retain(|m| eight.contains(&m.id));
    for id in &eight {
        let mut seven = alone.clone();
        seven.mates.retain(|m| &m.id != id);
        assert!(solves_from_somewhere(&seven, 20, 5), "without {id}");
    }
}
