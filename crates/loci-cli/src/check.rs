//! The human-readable diagnosis.

use crate::code;
use loci::{Diagnosis, Member, Outcome, System};
use std::fmt::Write;

/// Exit status of `check`: conflicts first, then non-convergence; redundancy is fine.
pub(crate) fn exit_code(d: &Diagnosis) -> u8 {
    if !d.conflicting.is_empty() || d.outcome == Outcome::Inconsistent {
        code::INCONSISTENT
    } else if d.outcome == Outcome::DidNotConverge {
        code::DID_NOT_CONVERGE
    } else {
        code::SOLVED
    }
}

/// A member with its type, e.g. `constraint 4 (pt_pt_distance)`.
fn named(sys: &System, m: &Member) -> String {
    match m {
        Member::Constraint(c) => {
            let kind = sys.constraint(*c).map(|c| c.kind.name()).unwrap_or("?");
            format!("{c} ({kind})")
        }
        Member::Entity(e) => {
            let kind = sys
                .entity(*e)
                .map(|e| e.entity_type().name())
                .unwrap_or("?");
            format!("{e} ({kind}, implicit condition)")
        }
    }
}

fn list(sys: &System, ms: &[Member]) -> String {
    let mut out = ms
        .iter()
        .take(LIST_MAX)
        .map(|m| named(sys, m))
        .collect::<Vec<_>>()
        .join(", ");
    if ms.len() > LIST_MAX {
        let _ = write!(
            out,
            ", ... and {} more (--json lists them all)",
            ms.len() - LIST_MAX
        );
    }
    out
}

/// The most members a list names on one line: a block of a large mesh has thousands.
const LIST_MAX: usize = 24;

/// Renders a diagnosis; `all` lists fixed entities as well.
pub(crate) fn render(name: &str, sys: &System, d: &Diagnosis, all: bool) -> String {
    let mut s = String::new();
    let verdict = match d.outcome {
        Outcome::Okay => "solves",
        Outcome::RedundantOkay => "solves, with redundant constraints",
        Outcome::Inconsistent => "inconsistent: some constraints cannot hold together",
        Outcome::DidNotConverge => "did not converge",
    };
    let _ = writeln!(s, "{name}: {}: {verdict}", d.group);
    let _ = writeln!(
        s,
        "  dof          {}  ({} unknowns, {} equations of rank {})",
        d.dof, d.unknowns, d.equations, d.rank
    );
    if d.structural.is_empty() {
        let _ = writeln!(
            s,
            "  counting     no block has more equations than unknowns"
        );
    } else {
        let _ = writeln!(s, "  counting     over-constrained blocks:");
        for b in &d.structural {
            let _ = writeln!(
                s,
                "    {} equations on {} unknowns: {}",
                b.equations,
                b.unknowns,
                list(sys, &b.members)
            );
        }
    }
    if d.conflicting.is_empty() {
        let _ = writeln!(s, "  conflicting  none");
    } else {
        let _ = writeln!(
            s,
            "  conflicting  (each set cannot hold; removing any one member of it can, unless marked)"
        );
        for c in &d.conflicting {
            let note = if c.verified {
                ""
            } else {
                "  [not shown minimal]"
            };
            let _ = writeln!(s, "    {{{}}}{note}", list(sys, &c.members));
        }
    }
    if d.redundant.is_empty() {
        let _ = writeln!(s, "  redundant    none");
    } else {
        let _ = writeln!(s, "  redundant");
        for r in &d.redundant {
            let head = if r.members.is_empty() {
                format!("{{{}}} are partly redundant", list(sys, &r.involved))
            } else if r.members.len() == 1 {
                format!("{} is redundant", named(sys, &r.members[0]))
            } else if r.excess == 1 {
                format!("one of {{{}}} is redundant", list(sys, &r.members))
            } else {
                format!(
                    "{} of {{{}}} are redundant",
                    r.excess,
                    list(sys, &r.members)
                )
            };
            let _ = write!(s, "    {head}");
            if !r.involved.is_empty() && !r.members.is_empty() {
                let _ = write!(s, " (also involved: {})", list(sys, &r.involved));
            }
            let _ = writeln!(s);
        }
    }
    if !d.unsatisfied.is_empty() {
        let _ = writeln!(s, "  unsatisfied  {}", list(sys, &d.unsatisfied));
    }
    let shown: Vec<_> = d.freedoms.iter().filter(|f| all || f.dof > 0).collect();
    if shown.is_empty() {
        let _ = writeln!(s, "  free         nothing can move");
    } else {
        let _ = writeln!(s, "  free motions");
        for f in shown.iter().take(60) {
            let _ = writeln!(s, "    {f}");
        }
        if shown.len() > 60 {
            let _ = writeln!(s, "    ... and {} more", shown.len() - 60);
        }
    }
    if !d.measurements.is_empty() {
        let _ = writeln!(s, "  measured (reference constraints)");
        for m in &d.measurements {
            let unit = if m.kind == loci::ConstraintKind::Angle {
                " degrees"
            } else {
                ""
            };
            let _ = writeln!(
                s,
                "    {} ({}): {:.6}{unit}",
                m.constraint,
                m.kind.name(),
                m.value
            );
        }
    }
    s
}
