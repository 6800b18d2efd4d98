//! Reference (driven) constraints generate no equations; they measure.
//!
//! A dimension's residual is affine in its value for every kind but the angle (`m - val`,
//! `a - b val` ...), so two evaluations give the value that would make it hold. An angle is
//! read from its residual at two chosen values instead, which gives its cosine and sine.

use super::report::Measurement;
use crate::equations::{compile_unmerged, Kernel, Owner, Rows};
use crate::error::ModelError;
use crate::model::{ConstraintKind, GroupId, System};

/// The value of every reference dimension of `group` at `values`; `start` (the values before
/// solving) picks branches as it would for a driving constraint.
pub(crate) fn measurements(
    sys: &System,
    group: GroupId,
    start: &[f64],
    values: &[f64],
) -> Result<Vec<Measurement>, ModelError> {
    let kernels = compile_unmerged(sys, group, start, true)?;
    let mut out = Vec::new();
    let mut xs = Vec::new();
    for k in &kernels {
        let Owner::Constraint(h) = k.owner else {
            continue;
        };
        let Some(c) = sys.constraint(h) else { continue };
        if !c.kind.has_value() {
            continue;
        }
        k.gather(values, &mut xs);
        let value = if c.kind == ConstraintKind::Angle {
            angle(k, &xs)
        } else {
            let (r0, r1) = (residual(k, &xs, 0.0, false), residual(k, &xs, 1.0, false));
            r0 / (r0 - r1)
        };
        if value.is_finite() {
            out.push(Measurement {
                constraint: h,
                kind: c.kind,
                value,
            });
        }
    }
    Ok(out)
}

fn residual(k: &Kernel, xs: &[f64], val: f64, other: bool) -> f64 {
    let mut eq = k.eq.clone();
    eq.val = val;
    eq.other = other;
    let mut out = Rows::new();
    eq.eval(xs, &mut out);
    out.v[0]
}

/// The angle in degrees between the two lines, as `val` means it (the supplement with
/// `other`). In space the residual at 90 degrees is the cosine; in a workplane the residual
/// at 0 degrees is the signed angle itself (in radians, wrapped to (-180, 180] degrees). A
/// signed angle is measured with its sign, counter-clockwise from A to B (with `other`, to B
/// reversed); SolveSpace's by its size.
fn angle(k: &Kernel, xs: &[f64]) -> f64 {
    if k.eq.wp.is_some() && k.eq.signed {
        let theta = residual(k, xs, 0.0, false).to_degrees();
        return if k.eq.other {
            // To B reversed: half a turn off, back into (-180, 180].
            if theta > 0.0 {
                theta - 180.0
            } else {
                theta + 180.0
            }
        } else {
            theta
        };
    }
    let theta = match k.eq.wp {
        None => {
            let c = residual(k, xs, 90.0, false) + 90f64.to_radians().cos();
            c.clamp(-1.0, 1.0).acos()
        }
        Some(_) => residual(k, xs, 0.0, false).abs(),
    }
    .to_degrees();
    if k.eq.other {
        180.0 - theta
    } else {
        theta
    }
}
