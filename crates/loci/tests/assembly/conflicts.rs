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

/// Solves the assembly of `text` and checks that it names exactly `set` as its conflict,
/// marks those mates `conflicting` and no others, and leaves the grounded part where it was.
/// The report, for more checks.
fn names_only(text: &str, set: &[&str]) -> loci::assembly::AssemblyReport {
    let set: Vec<String> = set.iter().map(|s| s.to_string()).collect();
    let mut asm: Assembly = serde_json::from_str(text).unwrap();
    let grounded_before = asm.components[0].pose;
    let r = asm.solve().unwrap();
    assert_eq!(r.outcome, Outcome::Inconsistent, "{r}");
    assert_eq!(r.conflicts, vec![set.clone()], "{r}");
    for m in &r.mates {
        let conflicting = m.status == MateStatus::Conflicting;
        assert_eq!(conflicting, set.contains(&m.id), "{r}");
    }
    assert_eq!(asm.components[0].pose, grounded_before);
    r
}

/// The mates `set` of the assembly of `text` alone: they fail from `whole_starts` random
/// starts (none when 0, where each failing solve is long), and any of them less one mate
/// holds from one of `smaller_starts`.
fn fails_and_is_minimal(text: &str, set: &[&str], whole_starts: usize, smaller_starts: usize) {
    let whole: Assembly = serde_json::from_str(text).unwrap();
    let mut alone = whole.clone();
    alone.mates.retain(|m| set.contains(&m.id.as_str()));
    if whole_starts > 0 {
        assert!(
            !solves_from_somewhere(&alone, whole_starts, 1),
            "{set:?} held"
        );
    }
    for id in set {
        let mut less = alone.clone();
        less.mates.retain(|m| m.id != *id);
        assert!(
            solves_from_somewhere(&less, smaller_starts, 2),
            "without {id}"
        );
    }
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
    let four = ["m1", "m4", "m7", "longer"];
    let r = names_only(text, &four);
    assert!(r
        .to_string()
        .contains("conflict: {m1, m4, m7, longer} cannot all hold"));
    fails_and_is_minimal(text, &four, 10, 10);
}

/// Four parts held by thirteen mates, a distance from the ground to one of them lengthened
/// (case 374 of the random assemblies). Every set the core named held alone, and the search
/// mate by mate went up to twelve mates only: the report read `did_not_converge`. Searched
/// with thirteen, a smaller set that holds from a fifth of random starts missed all of the
/// eight it was tried from, its mate was taken out, and the ten left held: the search gave up
/// again. With each smaller set tried from 32 starts, eleven mates are named. The file has
/// two such conflicts: all but the distances `m0` and `m6`, and all but `m0` and the touch
/// align `m3`. Which one is named follows the core's search: the first while its sets were
/// checked from starts near the drawing only; the second once its last check of a set also
/// solved the set alone from starts drawn further off; the first again since the core
/// searches anew from where a set it dropped holds. Checked outside loci's own check, none of
/// 30 to 60 random starts solves either eleven, and each ten solve; here, the eleven fail from
/// every start tried, and any ten of them hold.
#[test]
fn a_conflict_among_thirteen_mates_is_found_from_random_starts() {
    let text = include_str!("../data/assembly/conflict_of_eleven_of_thirteen.json");
    let eleven = [
        "m1", "m2", "m3", "m4", "m5", "m7", "m8", "m9", "m10", "m11", "longer",
    ];
    names_only(text, &eleven);
    fails_and_is_minimal(text, &eleven, 3, 20);
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
    let eight = ["m0", "m1", "m2", "m3", "m4", "m6", "m7", "longer"];
    names_only(text, &eight);
    fails_and_is_minimal(text, &eight, 0, 20);
}

/// Four parts held by thirteen mates, a distance from the ground lengthened (case 34,592 of
/// the random assemblies). The core named nine mates, minimal among its equations, where a
/// joint counts its axes held opposed as parallel; among mates, the eight without the
/// distance `m10` fail too. Sets of more than six mates were not shrunk among mates; up to
/// twelve now are, and the eight are named. Checked outside loci's own check: none of 40
/// random starts solves the eight, and any seven of them solve; here, any seven hold.
#[test]
fn a_conflict_named_by_the_core_is_shrunk_among_mates() {
    let text = include_str!("../data/assembly/conflict_of_eight_named_nine.json");
    let eight = ["m1", "m3", "m4", "m5", "m6", "m8", "m11", "longer"];
    let r = names_only(text, &eight);
    assert_eq!(r.mates[10].status, MateStatus::Unsatisfied, "{r}");
    fails_and_is_minimal(text, &eight, 0, 20);
}
