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
use crate::equations::Kernel;

/// How many times the size of the drawing ([`drawing_size`]) an unknown may move in one
/// solve. A root at infinity is reached when the distance times the tolerance on an angle's
/// sine passes the offset that cannot close: for offsets of 1e-3 or more of the drawing's
/// size, beyond 1e7 of its size. Real answers lie within the drawing's coordinates and
/// dimensions, save where two lines within a millionth of a radian of each other must meet.
const RUNAWAY: f64 = 1e6;

/// The size of the drawing: the largest value of any parameter at the start or of any
/// constraint's dimension, and at least 1.
fn drawing_size(values: &[f64], kernels: &[Kernel]) -> f64 {
    let params = values.iter().map(|v| v.abs());
    let dims = kernels.iter().map(|k| k.eq.val.abs());
    params
        .chain(dims)
        .filter(|v| v.is_finite())
        .fold(1.0, f64::max)
}

/// Marks every converged component whose unknowns `x` (one slice per component, in order;
/// component unknown `i` overall is column `cols[i]`) moved from their start (`start`, by
/// column) by more than [`RUNAWAY`] times the drawing's size as not converged, with
/// the rows on the unknowns that ran off unsatisfied. Nothing is computed beyond one pass over
/// the unknowns unless one of them moved more than [`RUNAWAY`].
pub(super) fn reject_runaways(
    components: &[Component],
    finishes: &mut [Finish],
    x: &[f64],
    cols: &[usize],
    start: &[f64],
    values: &[f64],
    kernels: &[Kernel],
) {
    let mut size: Option<f64> = None;
    let mut at = 0;
    for (comp, fin) in components.iter().zip(finishes.iter_mut()) {
        let n = comp.scale.len();
        let (x, cols) = (&x[at..at + n], &cols[at..at + n]);
        at += n;
        let moved = |i: usize| (x[i] - start[cols[i]]).abs();
        if !fin.converged || (0..n).all(|i| moved(i) <= RUNAWAY) {
            continue;
        }
        let bound = RUNAWAY * *size.get_or_insert_with(|| drawing_size(values, kernels));
        let mut rows: Vec<usize> = (0..n)
            .filter(|&i| moved(i) > bound)
            .flat_map(|c| comp.columns.col(c).iter().map(|&(r, _)| r as usize))
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
