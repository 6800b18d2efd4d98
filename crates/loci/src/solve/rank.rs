//! Which rows of the normalised Jacobian depend on which: the rank the factorisation of
//! `G = J Jᵀ` reveals, checked where rounding could have hidden a dependence, and the rows on
//! the circuits of the dependent ones (the constraints a solve names as redundant or
//! conflicting).

use super::gram::{Columns, Gram};
use super::newton::generic;

/// Kept pivots up to this multiple of the rank tolerance are looked at again by [`reveal`].
const SUSPECT: f64 = 1e4;

/// The rows dependent on the others at a solution, from `gram` factorised (at `lambda = 0`)
/// with the rank tolerance `eps` from the normalised Jacobian values `jn`.
///
/// A pivot is the squared distance of its row from the span of the rows eliminated before it,
/// but only in exact arithmetic: after thousands of dependent rows (a mesh of shared points
/// implies a distance per triangle), the pivot of a dependent row eliminated late carries
/// rounding amplified by the small pivots of nearly dependent rows before it, and can land
/// above `eps` (a pinned mesh then loses its rotation: DOF 0 for 1). So when a kept pivot is
/// within [`SUSPECT`] of `eps`, `G` is factorised again with the wider tolerance, and each row
/// that only the wider one drops is measured directly in the Jacobian, `‖J_kᵀ - Jᵀ c‖²` with
/// `G c = J J_kᵀ`, where rounding is not squared. Rows within `eps` there are dependent; when
/// every such row is, the wider factorisation stands, otherwise `G` is factorised with `eps`
/// again and the confirmed rows are added to its dropped ones. `gram` is left factorised.
pub(crate) fn reveal(gram: &mut Gram, columns: &Columns, jn: &[f64], eps: f64) -> Vec<usize> {
    let dropped = reveal_widened(gram, columns, jn, eps);
    drop_hidden(gram, columns, jn, dropped, eps)
}

/// [`reveal`]'s first look: the rows a wider tolerance drops, measured in `J`.
fn reveal_widened(gram: &mut Gram, columns: &Columns, jn: &[f64], eps: f64) -> Vec<usize> {
    let base = gram.dropped();
    let wide = eps * SUSPECT;
    if !(gram.smallest_kept_pivot() <= wide) {
        return base;
    }
    // The factorisation with `eps`, kept for when the wider one does not stand.
    let saved = gram.save_factor();
    if !gram.factor(0.0, wide) {
        gram.restore_factor(saved, eps);
        return base;
    }
    let widened = gram.dropped();
    let m = gram.rows();
    let suspects: Vec<usize> = widened
        .iter()
        .copied()
        .filter(|k| base.binary_search(k).is_err())
        .collect();
    let entries = row_entries(columns, &suspects, m);
    let mut confirmed = Vec::with_capacity(suspects.len());
    // The block's solutions row by row (`c_t[i]` at `i * k + t`), and `J_kᵀ - Jᵀ c` in one
    // column for all of them: `J` is read once per block.
    let mut by_row = Vec::new();
    for (block, ks) in suspects.chunks(DEPENDENCY_BLOCK).enumerate() {
        let k = ks.len();
        let mut b = vec![0.0; m * k];
        for (t, rhs) in b.chunks_mut(m.max(1)).enumerate() {
            gram_column(columns, jn, &entries[block * DEPENDENCY_BLOCK + t], rhs);
        }
        gram.solve_many(&mut b, k);
        by_row.clear();
        by_row.resize(m * k, 0.0);
        for (t, (&row, c)) in ks.iter().zip(b.chunks(m.max(1))).enumerate() {
            for (i, v) in c.iter().enumerate() {
                by_row[i * k + t] = *v;
            }
            // c_k = -1 stands for row k itself.
            by_row[row * k + t] = -1.0;
        }
        let mut dist2 = vec![0.0f64; k];
        let mut sum = vec![0.0f64; k];
        for col in columns.iter() {
            sum.fill(0.0);
            for &(row, idx) in col {
                let v = jn[idx as usize];
                let c = &by_row[row as usize * k..(row as usize + 1) * k];
                for (s, c) in sum.iter_mut().zip(c) {
                    *s += c * v;
                }
            }
            for (d, s) in dist2.iter_mut().zip(&sum) {
                *d += s * s;
            }
        }
        confirmed.extend(
            ks.iter()
                .zip(&dist2)
                .filter(|(_, &d)| d <= eps)
                .map(|(&k, _)| k),
        );
    }
    if confirmed.len() == suspects.len() {
        return widened;
    }
    gram.restore_factor(saved, eps);
    let mut out = base;
    out.extend(confirmed);
    out.sort_unstable();
    out
}

/// Whether [`short_of_solution`] counts the free directions through `K = Jᵀ J` for equations
/// of `nrows` rows in `ncols` unknowns: more rows than unknowns (else `K` has a direction per
/// missing row, and `G` is the smaller), and enough of them for rounding to matter.
pub(crate) fn counts_by_unknowns(nrows: usize, ncols: usize) -> bool {
    nrows > ncols && ncols >= 64
}

/// The rows dependent on the others where a solve stopped short of a solution (the
/// least-squares point of equations that cannot all hold), from `gram` factorised (at
/// `lambda = 0`) with the rank tolerance `eps` from the normalised Jacobian values `jn`.
///
/// There near-dependence is the conflict itself, and the pivots are read as they are, with
/// one check where rounding decides: a mesh with more equations than unknowns drops thousands
/// of dependent rows, and the pivot of the last one eliminated can carry enough rounding to
/// land just above `eps` (1.08e-10 for 1e-10 on a 75x75 mesh with one impossible diagonal:
/// its rotation about the pinned point was lost, dof 0 for 1, and the circuits computed
/// against that nearly singular basis ran through hundreds of rows). Raising the tolerance
/// does not help there: the next few pivots are as close, and dropping one keeps another.
///
/// So `k = Jᵀ J` (its structure from [`Gram::of_unknowns`], for [`counts_by_unknowns`]
/// equations) counts the free directions of the unknowns, each confirmed in `J` itself, and
/// where the rows `G` kept are more than that count leaves independent, the dependence among
/// them is found by inverse iteration with `G`'s factors and the rows with the largest shares
/// in it are dropped, `G` being factorised again without them: all missing rows at once
/// ([`drop_together`]; four on a 100x100 mesh), or where that fails one at a time
/// ([`drop_one_at_a_time`]). Where both fail, `G` is read as it was. `gram` is left factorised
/// without the rows returned (its factors those of the rows kept, as the dropped rows'
/// circuits need).
pub(crate) fn short_of_solution(
    gram: &mut Gram,
    k: Option<&mut Gram>,
    columns: &Columns,
    jn: &[f64],
    eps: f64,
) -> Vec<usize> {
    let base = gram.dropped();
    let (m, n) = (gram.rows(), columns.len());
    let Some(k) = k else {
        return base;
    };
    let Some(free) = super::unknowns::free_count(k, m, columns, jn, eps) else {
        return base;
    };
    // The rows less the rank, n - free.
    let target = m - n.saturating_sub(free).min(m);
    if base.len() >= target || target - base.len() > MAX_MISSING {
        return base;
    }
    let found = if target - base.len() > 1 {
        drop_together(gram, columns, jn, &base, target, eps)
    } else {
        None
    };
    if let Some(dropped) =
        found.or_else(|| drop_one_at_a_time(gram, columns, jn, &base, target, eps))
    {
        return dropped;
    }
    gram.assemble(jn);
    gram.factor(0.0, eps);
    base
}

/// Kept pivots up to this are looked for a dependence the factorisation hid (see
/// [`drop_hidden`]): a row of the normalised Jacobian within a hundredth of a unit of the span
/// of the rows before it. Rounding lifts a dependent row's pivot by about the unit roundoff
/// divided by the small pivots before it; above this it needs one of them under it, or two
/// under a millionth, so a hidden dependence comes with a kept pivot under this either way.
const NEAR: f64 = 1e-4;

/// How close to a dependence `‖Jᵀ y‖² / ‖y‖²` must be for [`drop_hidden`] to take `y` as one:
/// a millionth of the rank tolerance. A true dependence measures 1e-32 to 1e-24 there, while a
/// long chain or a wide sheet that merely bends easily has directions far above it (their
/// squared singular values fall under the rank tolerance only at hundreds of rows a side,
/// where [`marginal`] reads them at a tighter one).
const HIDDEN: f64 = 1e-6;

/// The most rows [`drop_hidden`] adds.
const MAX_HIDDEN: usize = 8;

/// The rows of `dropped` and those dependent on the rows kept that the pivots hid, with `gram`
/// left factorised without them all.
///
/// A pivot of `G` carries the rounding of the eliminations before it divided by their small
/// pivots, twice over when two are small: in seed 27,969 of the random assemblies a row
/// exactly dependent on the rows before it (its distance from their span 1e-47) read a pivot of
/// 1.7e-6 after two independent rows with pivots of 2e-5 and 3e-6, far above the rank
/// tolerance and outside what [`reveal`] widens to; the cylindrical part's slide was lost (dof
/// 0 for 1). So where a kept pivot is under [`NEAR`], the dependence among the kept rows is
/// looked for by inverse iteration with `G`'s factors (which rounding does not stop: the
/// factors are those of a matrix within rounding of `G`, and the null direction its smallest
/// eigenvalue's), confirmed in `J` itself at [`HIDDEN`] times `eps`, and the row with the
/// largest share in it dropped, `G` factorised again without it, until no dependence is
/// confirmed.
pub(super) fn drop_hidden(
    gram: &mut Gram,
    columns: &Columns,
    jn: &[f64],
    dropped: Vec<usize>,
    eps: f64,
) -> Vec<usize> {
    if !(gram.smallest_kept_pivot() <= NEAR) {
        return dropped;
    }
    let m = gram.rows();
    let mut out = vec![false; m];
    for &d in &dropped {
        out[d] = true;
    }
    let mut without = jn.to_vec();
    // The factors of the rows kept alone (the widened look may have confirmed rows the
    // factorisation kept).
    if gram.dropped() != dropped {
        zero_rows(columns, &mut without, &out);
        gram.assemble(&without);
        if !gram.factor(0.0, eps) {
            gram.assemble(jn);
            gram.factor(0.0, eps);
            return dropped;
        }
    }
    let mut now = gram.dropped();
    let mut y = vec![0.0; m];
    for round in 0..MAX_HIDDEN {
        if !(gram.smallest_kept_pivot() <= NEAR) {
            break;
        }
        let finite = inverse_iteration(gram, &mut y, &now, round);
        for &d in &now {
            y[d] = 0.0;
        }
        let yy: f64 = y.iter().map(|v| v * v).sum();
        if !finite || !(jt_norm2(columns, &without, &y) <= HIDDEN * eps * yy) {
            break;
        }
        let Some(worst) = (0..m)
            .filter(|&i| !out[i])
            .max_by(|&a, &b| y[a].abs().total_cmp(&y[b].abs()))
        else {
            break;
        };
        out[worst] = true;
        let mut next = without.clone();
        zero_rows(columns, &mut next, &out);
        gram.assemble(&next);
        let fewer = gram.factor(0.0, eps) && gram.dropped().len() > now.len();
        if !fewer {
            // As it was.
            out[worst] = false;
            gram.assemble(&without);
            gram.factor(0.0, eps);
            break;
        }
        without = next;
        now = gram.dropped();
        // Rows the factorisation dropped besides are out too.
        for &d in &now {
            out[d] = true;
        }
    }
    now
}

/// `y` after [`INVERSE_STEPS`] steps of inverse iteration with `gram`'s factors from a generic
/// start (`attempt` picks which), the rows `dropped` zeroed before each step and each step
/// scaled to a largest entry of one: the direction of `G`'s least eigenvalue on the kept rows,
/// their dependence if they have one. False when a step vanished or was not finite (`y` then
/// as that step left it).
fn inverse_iteration(gram: &mut Gram, y: &mut [f64], dropped: &[usize], attempt: usize) -> bool {
    for (i, v) in y.iter_mut().enumerate() {
        *v = generic(i, attempt);
    }
    for _ in 0..INVERSE_STEPS {
        for &d in dropped {
            y[d] = 0.0;
        }
        gram.solve(y);
        let size = super::newton::largest_abs(y);
        if !(size > 0.0 && size.is_finite()) {
            return false;
        }
        y.iter_mut().for_each(|v| *v /= size);
    }
    true
}

/// [`short_of_solution`]'s search for the rows still to drop, one at a time: with `target`
/// rows dependent where `gram` (factorised without the rows `base`) kept all but `base`, the
/// dependence among the kept rows is found by inverse iteration with `G`'s factors (its
/// near-null vector `y`, confirmed by `‖Jᵀ y‖² <= eps ‖y‖²`), the row with the largest share in
/// it is dropped and `G` factorised again without it, until `target` rows are dropped. `None`
/// when a dependence is not confirmed or a factorisation does not drop one more row (`gram`
/// then factorised without some rows).
pub(super) fn drop_one_at_a_time(
    gram: &mut Gram,
    columns: &Columns,
    jn: &[f64],
    base: &[usize],
    target: usize,
    eps: f64,
) -> Option<Vec<usize>> {
    let m = gram.rows();
    let mut without = jn.to_vec();
    let mut dropped = base.to_vec();
    let mut y = vec![0.0; m];
    while dropped.len() < target {
        inverse_iteration(gram, &mut y, &dropped, dropped.len());
        // Jᵀ y, with the rows already dropped left out.
        let gg = jt_norm2(columns, &without, &y);
        let yy: f64 = y.iter().map(|v| v * v).sum();
        let Some(worst) = (0..m)
            .filter(|i| dropped.binary_search(i).is_err())
            .max_by(|&a, &b| y[a].abs().total_cmp(&y[b].abs()))
        else {
            break;
        };
        if !(gg <= eps * yy) {
            break;
        }
        // Factorised again on the rows kept, less that one: every dropped row is zeroed, as
        // the rows kept may otherwise swap one of them back in, the count unchanged.
        let mut out = vec![false; m];
        for &d in dropped.iter().chain([&worst]) {
            out[d] = true;
        }
        zero_rows(columns, &mut without, &out);
        gram.assemble(&without);
        if !gram.factor(0.0, eps) {
            break;
        }
        let now = gram.dropped();
        if now.len() <= dropped.len() || now.len() > target {
            break;
        }
        dropped = now;
    }
    (dropped.len() == target).then_some(dropped)
}

/// [`short_of_solution`]'s search for the rows still to drop, all at once: with `target` rows
/// dependent where `gram` (factorised without the rows `base`) kept all but `base`, the
/// `target - base.len()` directions of the dependence among the kept rows are found together
/// by block inverse iteration (each step one solve of them all, then Gram-Schmidt, so that
/// they do not all turn into the most nearly null one), each confirmed in `J`
/// (`‖Jᵀ y‖² <= eps ‖y‖²`). The rows to drop are picked from them as the one-at-a-time search
/// picks them, one per direction, the row with the largest share: after each pick, that row is
/// eliminated from the directions still to pick from, which leaves them the dependence among
/// the rows not yet picked. `G` is then factorised once without them all. A 100x100 mesh with
/// one impossible diagonal has four such rows: found one at a time they took four
/// factorisations and twelve solves (about 170 ms), together one factorisation and three
/// solves of four right-hand sides. `None` (with `gram` factorised as it came) when a
/// direction is not confirmed or the factorisation does not drop exactly `target` rows.
pub(super) fn drop_together(
    gram: &mut Gram,
    columns: &Columns,
    jn: &[f64],
    base: &[usize],
    target: usize,
    eps: f64,
) -> Option<Vec<usize>> {
    let m = gram.rows();
    let d = target - base.len();
    let mut y = vec![0.0; m * d];
    for (j, yj) in y.chunks_mut(m.max(1)).enumerate() {
        for (i, v) in yj.iter_mut().enumerate() {
            *v = generic(i, base.len() + j);
        }
        for &b in base {
            yj[b] = 0.0;
        }
    }
    for _ in 0..INVERSE_STEPS {
        // `orthonormalise` zeroes the rows `base` again for the next solve.
        gram.solve_many(&mut y, d);
        if !orthonormalise(&mut y, m, base) {
            return None;
        }
    }
    // Each direction confirmed in `J` itself.
    for yj in y.chunks(m.max(1)) {
        if !(jt_norm2(columns, jn, yj) <= eps) {
            return None;
        }
    }
    let mut out = vec![false; m];
    for &b in base {
        out[b] = true;
    }
    for j in 0..d {
        let (done, rest) = y.split_at_mut((j + 1) * m);
        let yj = &done[j * m..];
        let worst = (0..m)
            .filter(|&i| !out[i])
            .max_by(|&a, &b| yj[a].abs().total_cmp(&yj[b].abs()))?;
        let pivot = yj[worst];
        if !(pivot != 0.0 && pivot.is_finite()) {
            return None;
        }
        out[worst] = true;
        for yl in rest.chunks_mut(m.max(1)) {
            let f = yl[worst] / pivot;
            yl.iter_mut().zip(yj).for_each(|(a, b)| *a -= f * b);
        }
    }
    let mut without = jn.to_vec();
    zero_rows(columns, &mut without, &out);
    gram.assemble(&without);
    if gram.factor(0.0, eps) {
        let now = gram.dropped();
        if now.len() == target {
            return Some(now);
        }
    }
    gram.assemble(jn);
    gram.factor(0.0, eps);
    None
}

/// `‖Jᵀ y‖²`, with `J` given by its columns and the values `values`: how far `y` is from a
/// dependence among the rows of `J`.
fn jt_norm2(columns: &Columns, values: &[f64], y: &[f64]) -> f64 {
    columns
        .iter()
        .map(|col| {
            let g: f64 = col
                .iter()
                .map(|&(row, idx)| values[idx as usize] * y[row as usize])
                .sum();
            g * g
        })
        .sum()
}

/// Zeroes the entries of the rows marked in `out` among the Jacobian values `values`.
fn zero_rows(columns: &Columns, values: &mut [f64], out: &[bool]) {
    for col in columns.iter() {
        for &(row, idx) in col {
            if out[row as usize] {
                values[idx as usize] = 0.0;
            }
        }
    }
}

/// Modified Gram-Schmidt on the vectors of `y` (each `m` long, one after another), the rows
/// `base` zeroed first. False when one of them vanishes (or is not finite) against the others.
fn orthonormalise(y: &mut [f64], m: usize, base: &[usize]) -> bool {
    let d = y.len() / m.max(1);
    for j in 0..d {
        let (done, rest) = y.split_at_mut(j * m);
        let yj = &mut rest[..m];
        for &b in base {
            yj[b] = 0.0;
        }
        for yk in done.chunks(m.max(1)) {
            let dot: f64 = yj.iter().zip(yk).map(|(a, b)| a * b).sum();
            yj.iter_mut().zip(yk).for_each(|(a, b)| *a -= dot * b);
        }
        let norm = yj.iter().map(|v| v * v).sum::<f64>().sqrt();
        if !(norm > 0.0 && norm.is_finite()) {
            return false;
        }
        yj.iter_mut().for_each(|v| *v /= norm);
    }
    true
}

/// The most rows [`short_of_solution`] drops beyond those the factorisation dropped.
const MAX_MISSING: usize = 8;

/// Steps of inverse iteration for the dependence among the kept rows. Three left it confirmed
/// in `J` by far on the 75x75 and 100x100 meshes, `‖Jᵀ y‖² / ‖y‖²` at 1e-26 to 1e-24.
const INVERSE_STEPS: usize = 3;

/// `rhs = J J_kᵀ` for the row with `entries` (column, index into `jn`).
fn gram_column(columns: &Columns, jn: &[f64], entries: &[(usize, u32)], rhs: &mut [f64]) {
    for &(c, ik) in entries {
        let vk = jn[ik as usize];
        for &(row, idx) in columns.col(c) {
            rhs[row as usize] += jn[idx as usize] * vk;
        }
    }
}

/// The entries of each of `rows` (of `m`), in column order: (column, index into `jn`). Only
/// the first entry of a row in a column is listed, as a search by row would find it.
fn row_entries(columns: &Columns, rows: &[usize], m: usize) -> Vec<Vec<(usize, u32)>> {
    let mut slot = vec![usize::MAX; m];
    for (s, &k) in rows.iter().enumerate() {
        slot[k] = s;
    }
    let mut entries: Vec<Vec<(usize, u32)>> = vec![Vec::new(); rows.len()];
    for (c, col) in columns.iter().enumerate() {
        for &(row, ik) in col {
            let s = slot[row as usize];
            if s != usize::MAX && entries[s].last().is_none_or(|&(lc, _)| lc != c) {
                entries[s].push((c, ik));
            }
        }
    }
    entries
}

/// Rows dropped by a factorisation of a large component that a factorisation at this fraction
/// of the rank tolerance keeps are only just dependent there (see [`marginal`]).
pub(crate) const MARGINAL: f64 = 1e-3;

/// The most rows the tighter factorisation of [`MARGINAL`] may still drop (and by which
/// equations may outnumber unknowns), a few redundant constraints. Where thousands of rows
/// depend on others, the rounding of their eliminations lands pivots near the rank tolerance
/// too: a 70x70 mesh with 4,624 dependent rows, solved at the tighter tolerance, was read
/// with 0 DOF instead of 1.
const MARGINAL_DEPENDENT: usize = 8;

/// Components from this many rows on are tested by [`marginal`]; the test costs one
/// factorisation.
const MARGINAL_SIZE: usize = 4096;

/// The tighter rank tolerance `tol * MARGINAL` where the rank of a large component is to be read
/// there: `gram`, of `m` rows over `ncols` unknowns, factorised at `tol`, dropped the rows
/// `dropped`, some of which a factorisation at the tighter tolerance keeps, and that one drops
/// at most [`MARGINAL_DEPENDENT`]. `gram` is then left factorised at the tighter tolerance;
/// otherwise (`None`) at `tol`, as it was.
///
/// Such a row is no dependency but a structure that bends easily: each column of a 190x190
/// sheet of profiles is a chain of 190 edges held by relative angles, whose smallest squared
/// singular value falls under the rank tolerance (1e-10) at that size. Read at the usual
/// tolerance, the solve left that row out of its steps and folded the sheet, and at a solution
/// the sheet was read with 1 DOF and its constraints named redundant.
pub(crate) fn marginal(
    gram: &mut Gram,
    m: usize,
    ncols: usize,
    tol: f64,
    dropped: &[usize],
) -> Option<f64> {
    if m < MARGINAL_SIZE || m > ncols + MARGINAL_DEPENDENT || dropped.is_empty() {
        return None;
    }
    let tight = tol * MARGINAL;
    if gram.factor(0.0, tight) {
        let kept = gram.dropped();
        if kept.len() < dropped.len() && kept.len() <= MARGINAL_DEPENDENT {
            return Some(tight);
        }
        if kept.len() == dropped.len() {
            // The same rows dropped (the tighter drops a subset): the same factorisation.
            return None;
        }
    }
    gram.factor(0.0, tol);
    None
}

/// How many dependency right-hand sides are solved together.
pub(crate) const DEPENDENCY_BLOCK: usize = 32;

/// For each dropped row `k`, the rows that row `k` of the normalised Jacobian is a combination
/// of: solve `G c = J J_kᵀ`; dropped rows get (almost) nothing, so `c` expresses row `k` in the
/// others. The right-hand sides are built in one pass over `J` and solved in blocks, since a
/// mesh of many shared points can drop thousands of implied rows.
pub(crate) fn dependencies(
    gram: &mut Gram,
    columns: &Columns,
    jn: &[f64],
    dropped: &[usize],
    m: usize,
) -> Vec<Vec<usize>> {
    // Most solves drop nothing: no pass over the Jacobian to list nobody's entries.
    if dropped.is_empty() {
        return Vec::new();
    }
    let entries = row_entries(columns, dropped, m);
    if dropped.len() > DEPENDENCY_BLOCK {
        return vec![dependent_union(gram, columns, jn, &entries, dropped, m)];
    }
    let mut out = Vec::with_capacity(dropped.len());
    for (block, ks) in dropped.chunks(DEPENDENCY_BLOCK).enumerate() {
        let mut b = vec![0.0; m * ks.len()];
        for (t, rhs) in b.chunks_mut(m.max(1)).enumerate() {
            gram_column(columns, jn, &entries[block * DEPENDENCY_BLOCK + t], rhs);
        }
        gram.solve_many(&mut b, ks.len());
        if gram.smallest_kept_pivot() <= REFINE_BELOW {
            let mut v = vec![0.0; columns.len() * ks.len()];
            for (t, vt) in v.chunks_mut(columns.len().max(1)).enumerate() {
                for &(c, ik) in &entries[block * DEPENDENCY_BLOCK + t] {
                    vt[c] += jn[ik as usize];
                }
            }
            refine(gram, columns, jn, dropped, &v, &mut b, m);
        }
        for (&k, c) in ks.iter().zip(b.chunks(m.max(1))) {
            let mut deps = vec![k];
            deps.extend(
                c.iter()
                    .enumerate()
                    .filter(|&(i, c)| i != k && c.abs() > 1e-6)
                    .map(|(i, _)| i),
            );
            deps.sort_unstable();
            out.push(deps);
        }
    }
    out
}

/// Kept pivots up to this make [`dependencies`] refine the coefficients it solved for. The
/// normal equations square the conditioning of the kept rows: rounding in the coefficients is
/// about 1e-16 over the smallest kept pivot, and from about 1e-10 down it reaches the 1e-6 by
/// which a row is read as part of a dependency. A 200x200 sheet of profiles, solved at a
/// tightened rank tolerance (see `newton::MARGINAL`) with a kept pivot near 5e-11, named 128
/// constraints redundant for the 7 that close a cell with the extra one.
const REFINE_BELOW: f64 = 1e-6;

/// One step of iterative refinement of the coefficients `b` (one column of `m` per
/// right-hand side, solved with `gram`'s factors, `dropped` its dropped rows) of right-hand
/// sides `J v` (the `v` one after another, each as long as `J` has columns): what `Jᵀ c`
/// misses of `v` is taken back to the rows, and the correction solved for with the same
/// factors (the corrected semi-normal equations), which takes the rounding to about its
/// square.
fn refine(
    gram: &mut Gram,
    columns: &Columns,
    jn: &[f64],
    dropped: &[usize],
    vs: &[f64],
    b: &mut [f64],
    m: usize,
) {
    let n = columns.len();
    let k = b.len() / m.max(1);
    let mut d = vec![0.0; m * k];
    for ((c, v), dj) in b
        .chunks_mut(m.max(1))
        .zip(vs.chunks(n.max(1)))
        .zip(d.chunks_mut(m.max(1)))
    {
        for &r in dropped {
            c[r] = 0.0;
        }
        // dj = J (v - Jᵀ c), column by column.
        for (col, &vc) in columns.iter().zip(v) {
            let jtc: f64 = col
                .iter()
                .map(|&(row, idx)| jn[idx as usize] * c[row as usize])
                .sum();
            let miss = vc - jtc;
            if miss != 0.0 {
                for &(row, idx) in col {
                    dj[row as usize] += jn[idx as usize] * miss;
                }
            }
        }
        for &r in dropped {
            dj[r] = 0.0;
        }
    }
    gram.solve_many(&mut d, k);
    for (c, dj) in b.chunks_mut(m.max(1)).zip(d.chunks(m.max(1))) {
        c.iter_mut().zip(dj).for_each(|(a, x)| *a += x);
        for &r in dropped {
            c[r] = 0.0;
        }
    }
}

/// How many random combinations of the dropped rows [`dependent_union`] solves for.
pub(crate) const UNION_PROBES: usize = 3;

/// The rows on some circuit through a dropped row, when there are too many dropped rows to
/// find each one's circuit (a mesh of shared points drops thousands of implied rows, and one
/// solve each grows as the square of the mesh). Only the union is reported, and it is the
/// support of the left null space of `J`: a generic combination `y = Σ w_k (e_k - c_k)` of the
/// dependencies has exactly that support, so a few such combinations, with weights fixed by
/// [`generic`], cost a few solves in all. A coefficient cancels to below the threshold only
/// where the weights happen to balance it out in every probe.
fn dependent_union(
    gram: &mut Gram,
    columns: &Columns,
    jn: &[f64],
    entries: &[Vec<(usize, u32)>],
    dropped: &[usize],
    m: usize,
) -> Vec<usize> {
    let n = columns.len();
    let mut b = vec![0.0; m * UNION_PROBES];
    let mut vs = vec![0.0; n * UNION_PROBES];
    for (p, (rhs, v)) in b
        .chunks_mut(m.max(1))
        .zip(vs.chunks_mut(n.max(1)))
        .enumerate()
    {
        // v = Σ w_k J_kᵀ over the columns, then rhs = J v.
        for (s, &k) in dropped.iter().enumerate() {
            let w = generic(k, p);
            for &(c, ik) in &entries[s] {
                v[c] += w * jn[ik as usize];
            }
        }
        for (c, &vc) in v.iter().enumerate() {
            if vc != 0.0 {
                for &(row, idx) in columns.col(c) {
                    rhs[row as usize] += jn[idx as usize] * vc;
                }
            }
        }
    }
    gram.solve_many(&mut b, UNION_PROBES);
    if gram.smallest_kept_pivot() <= REFINE_BELOW {
        refine(gram, columns, jn, dropped, &vs, &mut b, m);
    }
    let mut on_circuit = vec![false; m];
    for &k in dropped {
        on_circuit[k] = true;
    }
    for c in b.chunks(m.max(1)) {
        for (i, v) in c.iter().enumerate() {
            if v.abs() > 1e-6 {
                on_circuit[i] = true;
            }
        }
    }
    (0..m).filter(|&i| on_circuit[i]).collect()
}
