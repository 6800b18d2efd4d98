//! `loci assemble`: solve an assembly file and print its report.

use crate::code;
use loci::assembly::{AssemblyReport, MateStatus};
use loci::format::assembly::{read, write};
use std::path::Path;

/// Reads `file`, solves it (all mates at once, or with `steps` the stepped relaxation, each
/// pass printed), prints the report (or JSON), writes the solved assembly to `output` and its
/// picture to `svg`.
/// The exit status is 0 when every mate holds, 1 when mates conflict, 2 otherwise.
pub fn run(
    file: &Path,
    json: bool,
    steps: bool,
    output: Option<&Path>,
    svg: Option<&Path>,
) -> anyhow::Result<u8> {
    let text = std::fs::read_to_string(file)
        .map_err(|e| anyhow::anyhow!("cannot read {}: {e}", file.display()))?;
    let mut asm = read(&text).map_err(|e| anyhow::anyhow!("{}: {e}", file.display()))?;
    if steps {
        let run = asm
            .solve_stepped()
            .map_err(|e| anyhow::anyhow!("{}: {e}", file.display()))?;
        if json {
            outln!("{}", serde_json::to_string_pretty(&run)?);
        } else {
            let ids: Vec<&str> = asm.mates.iter().map(|m| m.id.as_str()).collect();
            outln!(
                "{}: stepped mode, {} passes, {}",
                file.display(),
                run.iterations.len(),
                if run.converged {
                    "converged"
                } else {
                    "not converged"
                }
            );
            for it in &run.iterations {
                out!("pass {:>4}:", it.index);
                for (id, e) in ids.iter().zip(&it.errors) {
                    out!(" {id} {e:.2e}");
                }
                outln!("");
                for (c, p) in asm.components.iter().zip(&it.poses) {
                    if !c.grounded {
                        let t = p.translation;
                        let q = p.rotation;
                        outln!(
                            "    {} at ({:.6}, {:.6}, {:.6}) rotation ({:.6}, {:.6}, {:.6}, {:.6})",
                            c.name,
                            t[0],
                            t[1],
                            t[2],
                            q[0],
                            q[1],
                            q[2],
                            q[3]
                        );
                    }
                }
            }
        }
        write_out(&asm, output, svg)?;
        return Ok(if run.converged {
            code::SOLVED
        } else {
            code::DID_NOT_CONVERGE
        });
    }
    let report = asm
        .solve()
        .map_err(|e| anyhow::anyhow!("{}: {e}", file.display()))?;
    if json {
        outln!("{}", serde_json::to_string_pretty(&report)?);
    } else {
        outln!("{}:", file.display());
        out!("{report}");
    }
    write_out(&asm, output, svg)?;
    Ok(exit_code(&report))
}

fn write_out(
    asm: &loci::assembly::Assembly,
    output: Option<&Path>,
    svg: Option<&Path>,
) -> anyhow::Result<()> {
    if let Some(p) = svg {
        std::fs::write(p, picture(asm))
            .map_err(|e| anyhow::anyhow!("cannot write {}: {e}", p.display()))?;
    }
    if let Some(out) = output {
        std::fs::write(out, write(asm) + "\n")
            .map_err(|e| anyhow::anyhow!("cannot write {}: {e}", out.display()))?;
    }
    Ok(())
}

/// The exit status of an assembly solve: 0 when every mate holds, 1 when mates conflict, 2
/// otherwise.
pub fn exit_code(r: &AssemblyReport) -> u8 {
    if r.mates.iter().any(|m| m.status == MateStatus::Conflicting) {
        code::INCONSISTENT
    } else if r.all_hold() {
        code::SOLVED
    } else {
        code::DID_NOT_CONVERGE
    }
}

/// The assembly's isometric wireframe, glyphs a tenth of the spread of its components, so
/// that small and large assemblies both read.
pub fn picture(asm: &loci::assembly::Assembly) -> String {
    let t: Vec<[f64; 3]> = asm.components.iter().map(|c| c.pose.translation).collect();
    let spread = (0..3)
        .map(|k| {
            let lo = t.iter().map(|v| v[k]).fold(f64::INFINITY, f64::min);
            let hi = t.iter().map(|v| v[k]).fold(f64::NEG_INFINITY, f64::max);
            if lo.is_finite() {
                hi - lo
            } else {
                0.0
            }
        })
        .fold(0.0, f64::max);
    let size = if spread > 0.0 { spread / 10.0 } else { 1.0 };
    crate::assembly_svg::assembly_svg(asm, size)
}
