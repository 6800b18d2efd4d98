//! `loci drag FILE --point P --to X,Y [--steps N]`: drags a shape of a sketch file toward a
//! target in equal steps and prints each step's outcome.

use crate::sketch::{load, to_file, write_shapes};
use std::path::Path;

/// Parses `X,Y`.
pub(crate) fn parse_xy(s: &str) -> Result<[f64; 2], String> {
    let bad = || format!("{s:?} is not X,Y (two numbers separated by a comma)");
    let (x, y) = s.split_once(',').ok_or_else(bad)?;
    let x: f64 = x.trim().parse().map_err(|_| bad())?;
    let y: f64 = y.trim().parse().map_err(|_| bad())?;
    if x.is_finite() && y.is_finite() {
        Ok([x, y])
    } else {
        Err(bad())
    }
}

/// Solves the sketch, then drags `shape` to `to` in `steps` equal steps.
pub(crate) fn run(
    file: &Path,
    shape: &str,
    to: [f64; 2],
    steps: usize,
    output: Option<&Path>,
) -> anyhow::Result<u8> {
    let mut l = load(file)?;
    let id = *l
        .shapes
        .get(shape)
        .ok_or_else(|| anyhow::anyhow!("{}: no shape is named {shape:?}", file.display()))?;
    let rep = l
        .sketch
        .solve()
        .map_err(|e| anyhow::anyhow!("{}: {e}", file.display()))?;
    outln!("{}: sketch {} before the drag", file.display(), rep.outcome);
    if !rep.outcome.is_ok() {
        return Ok(crate::exit_code(rep.outcome));
    }
    let steps = steps.max(1);
    let mut all_ok = true;
    {
        let mut drag = l
            .sketch
            .begin_drag(id)
            .map_err(|e| anyhow::anyhow!("{}: {e}", file.display()))?;
        let from = drag.grip();
        for k in 1..=steps {
            let t = k as f64 / steps as f64;
            let target = [
                from[0] + t * (to[0] - from[0]),
                from[1] + t * (to[1] - from[1]),
            ];
            let st = drag
                .step(target)
                .map_err(|e| anyhow::anyhow!("{}: {e}", file.display()))?;
            all_ok &= st.outcome.is_ok() && st.reached;
            outln!(
                "step {k}/{steps}: {}{}, {shape} at ({:.6}, {:.6}), {:.3e} from the target, {} solve(s){}",
                st.outcome,
                if st.reached { "" } else { ", stopped short" },
                st.at[0],
                st.at[1],
                st.miss,
                st.pieces + st.refused,
                if st.flips_prevented > 0 {
                    format!(", {} flip(s) prevented", st.flips_prevented)
                } else {
                    String::new()
                }
            );
        }
    }
    let mut s = String::new();
    write_shapes(&mut s, &l);
    out!("{s}");
    if let Some(out) = output {
        std::fs::write(out, to_file(&l).to_json() + "\n")
            .map_err(|e| anyhow::anyhow!("cannot write {}: {e}", out.display()))?;
    }
    Ok(if all_ok {
        crate::code::SOLVED
    } else {
        crate::code::DID_NOT_CONVERGE
    })
}
