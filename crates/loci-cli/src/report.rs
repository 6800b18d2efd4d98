//! The human-readable solve report.

use loci::{GroupId, Outcome, Report, System};
use std::fmt::Write;

/// Renders a report of solving `group` with at most `max_iterations` Newton iterations,
/// comparing parameter values before and after.
pub(crate) fn render(
    name: &str,
    group: GroupId,
    before: &System,
    after: &System,
    rep: &Report,
    max_iterations: usize,
) -> String {
    let mut s = String::new();
    let verdict = match rep.outcome {
        Outcome::Okay => "solved",
        Outcome::RedundantOkay => "solved, with redundant constraints",
        Outcome::Inconsistent => "inconsistent: some constraints cannot hold together",
        Outcome::DidNotConverge => "did not converge",
    };
    let _ = writeln!(s, "{name}: {group}: {verdict}");
    let _ = writeln!(s, "  outcome      {}", rep.outcome);
    let _ = writeln!(s, "  dof          {}", rep.dof);
    let _ = writeln!(
        s,
        "  size         {} unknowns, {} equations, {} components",
        rep.unknowns, rep.equations, rep.components
    );
    let _ = writeln!(
        s,
        "  iterations   {}  (largest residual {:.3e})",
        rep.iterations, rep.residual
    );
    if rep.outcome == Outcome::DidNotConverge && rep.iterations >= max_iterations {
        // Stopped by the limit, not where the steps could go no further.
        let _ = writeln!(
            s,
            "  limit        ran out of iterations (max_iterations {max_iterations}) still \
             moving; a higher limit may reach a solution"
        );
    }
    let label = match rep.outcome {
        Outcome::Okay => "failed",
        Outcome::RedundantOkay => "redundant",
        Outcome::Inconsistent => "conflicting",
        Outcome::DidNotConverge => "unsatisfied",
    };
    if rep.failed.is_empty() && rep.failed_entities.is_empty() {
        let _ = writeln!(s, "  {label:<12} none");
    } else {
        let _ = writeln!(s, "  {label}:");
        let constraints = rep.failed.iter().map(|h| {
            let kind = after.constraint(*h).map(|c| c.kind.name()).unwrap_or("?");
            format!("{h} ({kind})")
        });
        let entities = rep.failed_entities.iter().map(|h| {
            let kind = after
                .entity(*h)
                .map(|e| e.entity_type().name())
                .unwrap_or("?");
            format!("{h} ({kind}, implicit condition)")
        });
        let total = rep.failed.len() + rep.failed_entities.len();
        for line in constraints.chain(entities).take(LINES_MAX) {
            let _ = writeln!(s, "    {line}");
        }
        if total > LINES_MAX {
            let _ = writeln!(
                s,
                "    ... and {} more (--json lists them all)",
                total - LINES_MAX
            );
        }
    }
    let moved: Vec<_> = before
        .params()
        .iter()
        .zip(after.params())
        .filter(|(b, a)| b.val != a.val)
        .collect();
    if moved.is_empty() {
        let _ = writeln!(s, "  moved        none");
    } else {
        let _ = writeln!(s, "  moved parameters ({}):", moved.len());
        for (b, a) in moved.iter().take(LINES_MAX) {
            let _ = writeln!(
                s,
                "    {:<12} {:>14.6} -> {:>14.6}",
                a.h.to_string(),
                b.val,
                a.val
            );
        }
        if moved.len() > LINES_MAX {
            let _ = writeln!(s, "    ... and {} more", moved.len() - LINES_MAX);
        }
    }
    s
}

/// The most constraints, or moved parameters, a report lists one per line: an impossible
/// dimension in a large mesh or a redundant one names thousands (`--json` lists them all).
const LINES_MAX: usize = 40;
