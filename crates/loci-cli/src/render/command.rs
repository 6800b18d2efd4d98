//! `loci render FILE [-o OUT.svg] [--group G] [--no-solve]`: read a loci JSON problem or a
//! SolveSpace `.slvs` file, solve it, diagnose the group and draw it.

use super::{render_svg, RenderOptions};
use crate::{code, exit_code};
use loci::format::json::{JsonError, Problem};
use loci::format::slvs::{solve_all, solve_message, GroupResult, GroupStatus, FIXED_GROUP};
use loci::{Config, GroupId, Outcome, System};
use std::collections::BTreeSet;
use std::path::Path;

/// Draws `file` and writes the SVG to `output` (standard output when `None`). The exit
/// status is `loci solve`'s for the group drawn: the picture is written whatever the
/// outcome, so that a conflict can be seen.
pub(crate) fn run(
    file: &Path,
    output: Option<&Path>,
    group: Option<u32>,
    no_solve: bool,
) -> anyhow::Result<u8> {
    if file.extension().is_some_and(|e| e == "json") {
        if let Some(code) = assembly(file, output, no_solve)? {
            return Ok(code);
        }
    }
    let (sys, group, opts, diagnosis, outcome) = if file.extension().is_some_and(|e| e == "slvs") {
        from_slvs(file, group, no_solve)?
    } else if crate::sketch::is_sketch(file) {
        from_sketch(file, no_solve)?
    } else {
        from_json(file, group, no_solve)?
    };
    let svg = render_svg(&sys, group, diagnosis.as_ref(), &opts);
    match output {
        Some(out) => std::fs::write(out, svg)
            .map_err(|e| anyhow::anyhow!("cannot write {}: {e}", out.display()))?,
        None => crate::emit(&svg),
    }
    Ok(outcome.map_or(code::SOLVED, exit_code))
}

/// Draws an assembly file (one with a top-level `"loci_assembly"` key) as an isometric
/// wireframe; `None` for any other file. The exit status is `loci assemble`'s.
fn assembly(file: &Path, output: Option<&Path>, no_solve: bool) -> anyhow::Result<Option<u8>> {
    let text = std::fs::read_to_string(file)
        .map_err(|e| anyhow::anyhow!("cannot read {}: {e}", file.display()))?;
    let is_assembly = serde_json::from_str::<serde_json::Value>(&text)
        .ok()
        .is_some_and(|v| v.get("loci_assembly").is_some());
    if !is_assembly {
        return Ok(None);
    }
    let mut asm = loci::format::assembly::read(&text)
        .map_err(|e| anyhow::anyhow!("{}: {e}", file.display()))?;
    let status = if no_solve {
        code::SOLVED
    } else {
        let report = asm
            .solve()
            .map_err(|e| anyhow::anyhow!("{}: {e}", file.display()))?;
        crate::assemble::exit_code(&report)
    };
    let svg = crate::assemble::picture(&asm);
    match output {
        Some(out) => std::fs::write(out, svg)
            .map_err(|e| anyhow::anyhow!("cannot write {}: {e}", out.display()))?,
        None => crate::emit(&svg),
    }
    Ok(Some(status))
}

type Loaded = (
    System,
    GroupId,
    RenderOptions,
    Option<loci::Diagnosis>,
    Option<Outcome>,
);

fn from_json(file: &Path, group: Option<u32>, no_solve: bool) -> anyhow::Result<Loaded> {
    let text = std::fs::read_to_string(file)
        .map_err(|e| anyhow::anyhow!("cannot read {}: {e}", file.display()))?;
    let mut problem =
        Problem::from_json(&text).map_err(|e| anyhow::anyhow!("{}: {e}", file.display()))?;
    let mut req = problem.request();
    if let Some(g) = group {
        req.group = g.into();
    }
    let fail = |sys: &System, e: &loci::SolveError| {
        let e = JsonError::from_solve(&text, sys, e);
        anyhow::anyhow!("{}: {e}", file.display())
    };
    let mut outcome = None;
    if !no_solve {
        let rep = loci::solve(&mut problem.system, req.group, &req.dragged, &req.config())
            .map_err(|e| fail(&problem.system, &e))?;
        outcome = Some(rep.outcome);
    }
    let d = loci::diagnose(&problem.system, req.group, &req.config())
        .map_err(|e| fail(&problem.system, &e))?;
    let opts = RenderOptions {
        title: Some(title(file, req.group, &d)),
        ..RenderOptions::default()
    };
    Ok((problem.system, req.group, opts, Some(d), outcome))
}

/// A sketch file: solved with its soft constraints (which never outlive the solve), then
/// diagnosed and drawn as the core system it writes, construction shapes dashed.
fn from_sketch(file: &Path, no_solve: bool) -> anyhow::Result<Loaded> {
    use loci::sketch::Sketch;
    let mut l = crate::sketch::load(file)?;
    let mut outcome = None;
    if !no_solve {
        let rep = l
            .sketch
            .solve()
            .map_err(|e| anyhow::anyhow!("{}: {e}", file.display()))?;
        outcome = Some(rep.outcome);
    }
    let sys = l.sketch.system().clone();
    let group = Sketch::SHAPE_GROUP;
    let d = loci::diagnose(&sys, group, &Config::default())
        .map_err(|e| anyhow::anyhow!("{}: {e}", file.display()))?;
    let construction: BTreeSet<loci::EntityId> = sys
        .entities()
        .iter()
        .map(|e| e.h)
        .filter(|&h| l.sketch.is_construction(h))
        .collect();
    let opts = RenderOptions {
        title: Some(title(file, group, &d)),
        construction,
        ..RenderOptions::default()
    };
    Ok((sys, group, opts, Some(d), outcome))
}

fn from_slvs(file: &Path, group: Option<u32>, no_solve: bool) -> anyhow::Result<Loaded> {
    let mut f = crate::slvs::load(file)?;
    let solvable: Vec<GroupId> = f
        .groups
        .iter()
        .filter(|g| g.status == GroupStatus::Solve)
        .map(|g| g.h)
        .collect();
    let g = match group {
        Some(g) => {
            let g = GroupId(g);
            if f.group(g).is_none() {
                let have: Vec<String> = f.groups.iter().map(|g| g.h.0.to_string()).collect();
                anyhow::bail!(
                    "{}: there is no group {}; the file's groups are {}",
                    file.display(),
                    g.0,
                    have.join(", ")
                );
            }
            g
        }
        None => *solvable.last().ok_or_else(|| {
            anyhow::anyhow!("{}: the file has no sketch group to draw", file.display())
        })?,
    };
    let mut outcome = None;
    if !no_solve {
        // Every group in order, as SolveSpace does: later groups start from earlier ones.
        for r in solve_all(&mut f, &Config::default()) {
            match r.result {
                GroupResult::Solved(rep) if r.group == g => outcome = Some(rep.outcome),
                GroupResult::Error(e) if r.group == g => anyhow::bail!(
                    "{}: Group.h.v={:08x} ({}): {}",
                    file.display(),
                    r.group.0,
                    r.name,
                    solve_message(&e)
                ),
                _ => {}
            }
        }
    }
    let diagnosis = if solvable.contains(&g) && f.system.groups().contains(&g) {
        Some(
            loci::diagnose(&f.system, g, &Config::default()).map_err(|e| {
                anyhow::anyhow!(
                    "{}: Group.h.v={:08x}: {}",
                    file.display(),
                    g.0,
                    solve_message(&e)
                )
            })?,
        )
    } else {
        None
    };
    // The groups before this one in the file's order. Not the constants loci adds
    // (FIXED_GROUP): they include copies that later groups make of this one.
    let earlier: BTreeSet<GroupId> = f
        .groups
        .iter()
        .take_while(|x| x.h != g)
        .map(|x| x.h)
        .filter(|h| *h != FIXED_GROUP)
        .collect();
    let name = f.group(g).map_or(String::new(), |x| x.name.clone());
    let title = match &diagnosis {
        Some(d) => format!(
            "{}: group {:08x} ({name}): {}, {} dof",
            file_name(file),
            g.0,
            d.outcome,
            d.dof
        ),
        None => format!("{}: group {:08x} ({name})", file_name(file), g.0),
    };
    let opts = RenderOptions {
        construction: f.construction.clone(),
        earlier: Some(earlier),
        title: Some(title),
        ..RenderOptions::default()
    };
    Ok((f.system, g, opts, diagnosis, outcome))
}

fn file_name(file: &Path) -> String {
    file.file_name().map_or_else(
        || file.display().to_string(),
        |n| n.to_string_lossy().into_owned(),
    )
}

fn title(file: &Path, group: GroupId, d: &loci::Diagnosis) -> String {
    format!(
        "{}: group {}: {}, {} dof",
        file_name(file),
        group.0,
        d.outcome,
        d.dof
    )
}
