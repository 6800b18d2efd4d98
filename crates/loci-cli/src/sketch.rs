//! `loci solve` and `loci check` on sketch files (JSON with a top-level `"sketch"` key).

use crate::code;
use loci::format::sketch::{is_sketch_json, LoadedSketch, SketchFile};
use loci::sketch::{Sketch, SketchReport};
use std::fmt::Write as _;
use std::path::Path;

/// Whether the file is a sketch file, told by its content.
pub(crate) fn is_sketch(file: &Path) -> bool {
    file.extension().is_some_and(|e| e == "json")
        && std::fs::read_to_string(file).is_ok_and(|t| is_sketch_json(&t))
}

/// Reads and builds a sketch file.
pub(crate) fn load(file: &Path) -> anyhow::Result<LoadedSketch> {
    let text = std::fs::read_to_string(file)
        .map_err(|e| anyhow::anyhow!("cannot read {}: {e}", file.display()))?;
    let f = SketchFile::from_json(&text).map_err(|e| anyhow::anyhow!("{}: {e}", file.display()))?;
    f.load()
        .map_err(|e| anyhow::anyhow!("{}: {e}", file.display()))
}

/// The file of a loaded sketch as it is now, with its names.
pub(crate) fn to_file(l: &LoadedSketch) -> SketchFile {
    SketchFile::from_sketch(&l.sketch, |s| l.shape_name(s).map(str::to_string))
}

fn constraint_label(l: &LoadedSketch, id: loci::sketch::SketchConstraintId) -> String {
    let kind = l.sketch.constraint(id).map_or("?", |(s, _)| s.name());
    match l.constraint_name(id) {
        Some(n) => format!("{n} ({kind})"),
        None => format!("{id} ({kind})"),
    }
}

fn soft_label(l: &LoadedSketch, s: loci::sketch::Soft) -> String {
    use loci::sketch::Soft;
    let (what, shape) = match s {
        Soft::LineLength(x) => ("length", x.into()),
        Soft::ArcRadius(x) => ("radius", x.into()),
        Soft::ArcStart(x) => ("start angle", x.into()),
        Soft::ArcEnd(x) => ("end angle", x.into()),
    };
    format!("{what} of {}", l.shape_name(shape).unwrap_or("?"))
}

/// Solves a sketch file and prints the outcome, the soft constraints and the coordinates.
pub(crate) fn solve(file: &Path, json: bool, output: Option<&Path>) -> anyhow::Result<u8> {
    let mut l = load(file)?;
    let rep = l
        .sketch
        .solve()
        .map_err(|e| anyhow::anyhow!("{}: {e}", file.display()))?;
    if json {
        let v = serde_json::json!({
            "outcome": rep.outcome,
            "failed": rep.failed.iter().map(|c| constraint_label(&l, *c)).collect::<Vec<_>>(),
            "soft_kept": rep.kept.iter().map(|s| soft_label(&l, *s)).collect::<Vec<_>>(),
            "soft_dropped": rep.dropped.iter().map(|s| soft_label(&l, *s)).collect::<Vec<_>>(),
            "residual": rep.residual,
            "sketch": to_file(&l).sketch,
        });
        outln!("{}", serde_json::to_string_pretty(&v)?);
    } else {
        out!("{}", render(&file.display().to_string(), &l, &rep));
    }
    if let Some(out) = output {
        std::fs::write(out, to_file(&l).to_json() + "\n")
            .map_err(|e| anyhow::anyhow!("cannot write {}: {e}", out.display()))?;
    }
    Ok(crate::exit_code(rep.outcome))
}

fn render(name: &str, l: &LoadedSketch, rep: &SketchReport) -> String {
    let mut s = String::new();
    let _ = writeln!(s, "{name}: sketch {}", rep.outcome);
    for c in &rep.failed {
        let _ = writeln!(s, "  failed: {}", constraint_label(l, *c));
    }
    let _ = writeln!(
        s,
        "  soft constraints: {} kept, {} dropped",
        rep.kept.len(),
        rep.dropped.len()
    );
    for d in &rep.dropped {
        let _ = writeln!(s, "    dropped: {}", soft_label(l, *d));
    }
    write_shapes(&mut s, l);
    s
}

/// Every point's coordinates and every circle's radius, by name.
pub(crate) fn write_shapes(s: &mut String, l: &LoadedSketch) {
    let sk: &Sketch = &l.sketch;
    for (name, id) in &l.shapes {
        if let Some(p) = sk.as_point(*id) {
            let [x, y] = sk.point(p);
            let _ = writeln!(s, "  {name} = ({x:.6}, {y:.6})");
        } else if let Some(c) = sk.as_circle(*id) {
            let _ = writeln!(s, "  {name}: radius {:.6}", sk.circle(c).1);
        } else if let Some(a) = sk.as_arc(*id) {
            let g = sk.arc(a);
            let _ = writeln!(
                s,
                "  {name}: radius {:.6}, sweep {:.4} deg",
                g.radius, g.sweep
            );
        }
    }
}

/// Diagnoses a sketch file: degrees of freedom, each constraint's value and residual, and
/// the constraints in conflict or redundant.
pub(crate) fn check(file: &Path, json: bool) -> anyhow::Result<u8> {
    let mut l = load(file)?;
    // Values and residuals are read where the solve ends (the drawing stays as it was when
    // the solve fails).
    l.sketch
        .solve()
        .map_err(|e| anyhow::anyhow!("{}: {e}", file.display()))?;
    let sk = &l.sketch;
    if sk.shapes().next().is_none() {
        anyhow::bail!("{}: the sketch has no shapes", file.display());
    }
    let d = loci::diagnose(sk.system(), Sketch::SHAPE_GROUP, sk.config())
        .map_err(|e| anyhow::anyhow!("{}: {e}", file.display()))?;
    let names = |m: &[loci::Member]| -> Vec<String> {
        let mut v: Vec<String> = m
            .iter()
            .filter_map(|m| match m {
                loci::Member::Constraint(c) => sk.owner_of(*c).map(|id| constraint_label(&l, id)),
                loci::Member::Entity(e) => Some(format!("{e} (implicit)")),
            })
            .collect();
        v.dedup();
        v
    };
    let conflicts: Vec<Vec<String>> = d.conflicting.iter().map(|c| names(&c.members)).collect();
    let redundant: Vec<Vec<String>> = d.redundant.iter().map(|c| names(&c.members)).collect();
    let measured: Vec<(String, Option<f64>, f64)> = sk
        .constraints()
        .map(|(id, _)| {
            let m = sk.measure(id).expect("listed");
            (constraint_label(&l, id), m.value, m.residual)
        })
        .collect();
    let free: Vec<(String, usize)> = d
        .freedoms
        .iter()
        .filter(|f| f.dof > 0)
        .filter_map(|f| {
            let s = sk.shapes().find(|(s, _)| s.entity() == f.entity)?.0;
            Some((l.shape_name(s)?.to_string(), f.dof))
        })
        .collect();
    if json {
        let v = serde_json::json!({
            "outcome": d.outcome,
            "dof": d.dof,
            "conflicting": conflicts,
            "redundant": redundant,
            "constraints": measured.iter().map(|(n, v, r)| serde_json::json!({"constraint": n, "value": v, "residual": r})).collect::<Vec<_>>(),
            "free": free.iter().map(|(n, k)| serde_json::json!({"shape": n, "dof": k})).collect::<Vec<_>>(),
        });
        outln!("{}", serde_json::to_string_pretty(&v)?);
    } else {
        let mut s = String::new();
        let _ = writeln!(
            s,
            "{}: sketch {}, {} degrees of freedom",
            file.display(),
            d.outcome,
            d.dof
        );
        for c in &conflicts {
            let _ = writeln!(s, "  conflict: {}", c.join(", "));
        }
        for c in &redundant {
            let _ = writeln!(s, "  redundant: {}", c.join(", "));
        }
        for (n, v, r) in &measured {
            let v = v.map_or(String::new(), |v| format!(" = {v:.6}"));
            let _ = writeln!(s, "  {n}{v}, residual {r:.3e}");
        }
        for (n, k) in &free {
            let _ = writeln!(s, "  free: {n} ({k} dof)");
        }
        out!("{s}");
    }
    Ok(match d.outcome {
        loci::Outcome::Inconsistent => code::INCONSISTENT,
        loci::Outcome::DidNotConverge => code::DID_NOT_CONVERGE,
        _ => code::SOLVED,
    })
}
