//! `loci assemble`: solve an assembly file and print its report.

use crate::code;
use loci::assembly::{AssemblyReport, MateStatus};
use loci::format::assembly::{read, write};
use std::path::Path;

/// Reads `file`, solves it (all mates at once, or with `steps` the stepped relaxation, each
/// pass printed), prints the report (or JSON) and writes the solved assembly to `output`.
/// The exit status is 0 when every mate holds, 1 when mates conflict, 2 otherwise.
pub fn run(file: &Path, json: bool, steps: bool, output: Option<&Path>) -> anyhow::Result<u8> {
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
            outln!("{}: stepped mode, {} passes, {}", file.display(), run.iterations.len(),
                if run.converged { "converged" } else { "not converged" });
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
                            c.name, t[0], t[1], t[2], q[0], q[1], q[2], q[3]
                        );
                    }
                }
            }
        }
        write_out(&asm, output)?;
        return Ok(if run.converged { code::SOLVED } else { code::DID_NOT_CONVERGE });
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
    write_out(&asm, output)?;
    Ok(exit_code(&report))
}

fn write_out(asm: &loci::assembly::Assembly, output: Option<&Path>) -> anyhow::Result<()> {
    if let Some(out) = output {
        std::fs::write(out, write(asm) + "\n")
            .map_err(|e| anyhow::anyhow!("cannot write {}: {e}", out.display()))?;
    }
    Ok(())
}

fn exit_code(r: &AssemblyReport) -> u8 {
    if r.mates.iter().any(|m| m.status == MateStatus::Conflicting) {
        code::INCONSISTENT
    } else if r.all_hold() {
        code::SOLVED
    } else {
        code::DID_NOT_CONVERGE
    }
}
