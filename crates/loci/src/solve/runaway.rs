//! Answers that hold only because a point ran off towards infinity.
//!
//! Parallel, perpendicular and angle rows are written as sines and cosines of the angle
//! between two directions, whatever the lengths. Two sides that must be parallel but meet at
//! a point, as in a hexagon whose four sides are held parallel while its two ends are fixed
//! off their line, come within any angle of it as that point runs off: at 8e8 from a drawing
//! of size 11 the sine was 1.2e-10, and the tolerance of 1e-10 read that as held. Such a
//! placement is no answer: Newton went there because no finite one lies in that direction,
//! and the sketch's real answer (when there is one) is elsewhere. A component whose unknowns
//! moved more than [`RUNAWAY`] times the size of the drawing is therefore not converged, its
//! rows on those unknowns unsatisfied, so the rescues and the conflict search go on from there.

use super::newton::{Component, Finish};
use crate::equations::{EqKind, Kernel};
use crate::model::Param;

/// How many times the size of the drawing ([`drawing_size`]) an unknown may end from where the
/// drawing has it. A root at infinity is reached when the distance times the tolerance on an
/// angle's sine passes the offset that cannot close: at 8e8 for sketch 20,859 (size 11), and at
/// 1.2e6 for two free lines of a drawing of size 12 held at 145.6 degrees, one parallel to a
/// third, which had finite placements all round. Real answers lie within the drawing's
/// coordinates and lengths, save where two lines within 1e-4 radians of each other must meet.
const RUNAWAY: f64 = 1e4;

/// The size of the drawing: the largest value of any parameter at the start or of any
/// dimension that is a length, and at least 1. An angle's degrees are no size: with a
/// 147-degree angle counted, a pair of 3D lines of a drawing of size 16 ran off to 5.5e7 and
/// was read as solved.
fn drawing_size(params: &[Param], kernels: &[Kernel]) -> f64 {
    let params = params.iter().map(|p| p.val.abs());
    let dims = kernels
        .iter()
        .filter(|k| is_length(&k.eq.kind))
        .map(|k| k.eq.val.abs());
    params
        .chain(dims)
        .filter(|v| v.is_finite())
        .fold(1.0, f64::max)
}

/// Whether an equation's `val` is a length (a distance, a diameter, a difference of lengths),
/// not an angle, a ratio or a count.
fn is_length(kind: &EqKind) -> bool {
    use crate::model::ConstraintKind as K;
    matches!(
        kind,
        EqKind::Constraint(
            K::PtPtDistance
                | K::PtPlaneDistance
                | K::PtLineDistance
                | K::PtFaceDistance
                | K::ProjPtDistance
                | K::Diameter
                | K::LengthDifference
                | K::ArcArcDifference
                | K::ArcLineDifference
        )
    )
}

/// Marks every converged component whose unknowns `x` (one slice per component, in order;
/// component unknown `i` overall is column `cols[i]`) are more than [`RUNAWAY`] times the
/// drawing's size from where the drawing has them (column `c` reads `params[col_root[c]]`), as
/// not converged, with the rows on the unknowns that ran off unsatisfied. Measured from the drawing, not from the
/// start of this solve: a rescue that starts further off must not carry a placement that ran
/// off back as an answer. `params` are the drawing's parameters, also for its size. Nothing is
/// computed beyond one pass over the unknowns unless one of them is more than [`RUNAWAY`] off.
pub(super) fn reject_runaways(
    components: &[Component],
    finishes: &mut [Finish],
    x: &[f64],
    cols: &[usize],
    col_root: &[usize],
    params: &[Param],
    kernels: &[Kernel],
) {
    let mut size: Option<f64> = None;
    let mut at = 0;
    for (comp, fin) in components.iter().zip(finishes.iter_mut()) {
        let n = comp.scale.len();
        let (x, cols) = (&x[at..at + n], &cols[at..at + n]);
        at += n;
        let off = |i: usize| (x[i] - params[col_root[cols[i]]].val).abs();
        if !fin.converged || (0..n).all(|i| off(i) <= RUNAWAY) {
            continue;
        }
        let bound = RUNAWAY * *size.get_or_insert_with(|| drawing_size(params, kernels));
        let mut rows: Vec<usize> = (0..n)
            .filter(|&i| off(i) > bound)
            .flat_map(|i| comp.columns.col(i).iter().map(|&(r, _)| r as usize))
            .collect();
        if rows.is_empty() {
            continue;
        }
        rows.sort_unstable();
        rows.dedup();
        fin.converged = false;
        fin.dropped.clear();
        fin.dependencies.clear();
        fin.dependent = 0;
        fin.unsatisfied = rows;
    }
}
