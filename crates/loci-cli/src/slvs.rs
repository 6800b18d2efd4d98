//! `.slvs` files on the command line: solve every group in order, report, save.

use crate::{code, exit_code};
use anyhow::Context;
use loci::format::json::{JsonError, Problem};
use loci::format::slvs::{
    solve_all, solve_message, ExportError, GroupResult, GroupSolve, SlvsFile,
};
use loci::{Config, Outcome};
use std::fmt::Write;
use std::path::Path;

/// Reads and parses a `.slvs` file.
pub(crate) fn load(file: &Path) -> anyhow::Result<SlvsFile> {
    let bytes = std::fs::read(file).with_context(|| format!("cannot read {}", file.display()))?;
    SlvsFile::parse(&bytes).with_context(|| format!("{}", file.display()))
}

/// `loci solve FILE.slvs`: solves every group as SolveSpace does and reports each (or only
/// `group`); `-o OUT.slvs` saves the solved file, `-o OUT.json` loci's model of it.
pub(crate) fn solve(
    file: &Path,
    json: bool,
    group: Option<u32>,
    output: Option<&Path>,
) -> anyhow::Result<u8> {
    let mut f = load(file)?;
    let results = solve_all(&mut f, &Config::default());
    let shown: Vec<&GroupSolve> = results
        .iter()
        .filter(|r| group.is_none_or(|g| r.group.0 == g))
        .collect();
    if shown.is_empty() {
        let have: Vec<String> = results.iter().map(|r| r.group.0.to_string()).collect();
        anyhow::bail!(
            "{}: there is no group {}; the file's groups are {}",
            file.display(),
            group.unwrap_or(0),
            have.join(", ")
        );
    }
    if json {
        let v: Vec<serde_json::Value> = shown.iter().map(|r| group_json(r)).collect();
        outln!("{}", serde_json::to_string_pretty(&v)?);
    } else {
        out!("{}", render(&file.display().to_string(), &f, &shown));
    }
    if let Some(out) = output {
        let bytes = if out.extension().is_some_and(|e| e == "json") {
            Problem {
                system: f.system.clone(),
                solve: None,
            }
            .to_json()
            .into_bytes()
        } else {
            f.to_bytes()
        };
        std::fs::write(out, bytes).with_context(|| format!("cannot write {}", out.display()))?;
    }
    // The worst outcome decides, as for one group: a conflict over a failure to converge.
    let mut status = code::SOLVED;
    for r in &shown {
        match &r.result {
            GroupResult::Solved(rep) => status = status.max(exit_code(rep.outcome)),
            GroupResult::Error(e) => anyhow::bail!(
                "{}: Group.h.v={:08x} ({}): {}",
                file.display(),
                r.group.0,
                r.name,
                solve_message(e)
            ),
            GroupResult::References | GroupResult::Unsupported(_) => {}
        }
    }
    Ok(status)
}

fn group_json(r: &GroupSolve) -> serde_json::Value {
    let (status, report) = match &r.result {
        GroupResult::Solved(rep) => ("solved", serde_json::to_value(rep).ok()),
        GroupResult::References => ("references", None),
        GroupResult::Unsupported(_) => ("unsupported", None),
        GroupResult::Error(_) => ("error", None),
    };
    let reason = match &r.result {
        GroupResult::Unsupported(why) => Some(why.clone()),
        GroupResult::Error(e) => Some(solve_message(e)),
        _ => None,
    };
    serde_json::json!({
        "group": r.group.0,
        "name": r.name,
        "kind": r.kind.name(),
        "status": status,
        "reason": reason,
        "report": report,
    })
}

fn render(name: &str, f: &SlvsFile, shown: &[&GroupSolve]) -> String {
    let mut s = String::new();
    let _ = writeln!(s, "{name}: {} groups", f.groups.len());
    for r in shown {
        let _ = write!(s, "  group {} ({}, {}): ", r.group.0, r.name, r.kind.name());
        match &r.result {
            GroupResult::Solved(rep) => {
                let _ = write!(s, "{}, dof {}", rep.outcome, rep.dof);
                if rep.outcome == Outcome::RedundantOkay && !r.allow_redundant {
                    let _ = write!(s, " (SolveSpace would reject: the group does not allow redundant constraints)");
                }
                let _ = writeln!(s);
                if !rep.failed.is_empty() {
                    let names: Vec<String> = rep
                        .failed
                        .iter()
                        .map(|c| {
                            let kind = f.system.constraint(*c).map_or("?", |c| c.kind.name());
                            format!("{:08x} ({kind})", c.0)
                        })
                        .collect();
                    let _ = writeln!(s, "    constraints: {}", names.join(", "));
                }
            }
            other => {
                let _ = writeln!(s, "{other}");
            }
        }
    }
    for n in &f.notes {
        if n.line > 0 {
            let _ = writeln!(s, "  note (line {}): {}", n.line, n.message);
        } else {
            let _ = writeln!(s, "  note: {}", n.message);
        }
    }
    s
}

/// `loci convert FILE.slvs --to json`: loci's model of the file (SolveSpace's handles, the
/// constants loci adds in group 0) as a loci JSON problem.
pub(crate) fn to_json(file: &Path) -> anyhow::Result<String> {
    let f = load(file)?;
    // The last group solved that the system has objects in: a file's last group may hold
    // nothing loci keeps (a comment alone), and a request for it would not load back.
    let present = f.system.groups();
    let last = f
        .groups
        .iter()
        .rev()
        .find(|g| {
            g.status == loci::format::slvs::GroupStatus::Solve
                && present.binary_search(&g.h).is_ok()
        })
        .map(|g| g.h);
    let problem = Problem {
        system: f.system,
        solve: last.map(|group| loci::format::json::SolveRequest {
            group,
            dragged: Vec::new(),
            calculate_failed: true,
            options: Default::default(),
        }),
    };
    Ok(problem.to_json())
}

/// `loci convert FILE.json --to slvs`: the problem's system as a `.slvs` file SolveSpace
/// opens (see [`loci::format::slvs::export`] for what is lost).
pub(crate) fn from_json(file: &Path) -> anyhow::Result<Vec<u8>> {
    let text =
        std::fs::read_to_string(file).with_context(|| format!("cannot read {}", file.display()))?;
    let problem =
        Problem::from_json(&text).map_err(|e| anyhow::anyhow!("{}: {e}", file.display()))?;
    let out = loci::format::slvs::export(&problem.system).map_err(|e| {
        let sys = &problem.system;
        match &e {
            ExportError::Model(m) => {
                let e = JsonError::from_model(&text, sys, m);
                anyhow::anyhow!("{}: {e}", file.display())
            }
            ExportError::Unsupported { entity, why } => {
                let kind = sys.entity(*entity).map_or("?", |e| e.entity_type().name());
                let at = loci::format::json::locate(&text, loci::ObjectId::Entity(*entity), "")
                    .map(|p| format!("{p}: "))
                    .unwrap_or_default();
                anyhow::anyhow!(
                    "{}: {at}{entity} ({kind}): cannot be written as a .slvs file: {why}",
                    file.display()
                )
            }
            _ => anyhow::anyhow!("{}: {e}", file.display()),
        }
    })?;
    Ok(out.bytes)
}
