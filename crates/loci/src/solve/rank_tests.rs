//! The rows `rank::short_of_solution` drops where the factorisation kept rows that depend on
//! others: found all at once or one at a time, the same rows.

use super::gram::{Columns, Gram};
use super::rank::{drop_hidden, drop_one_at_a_time, drop_together};

/// The rank tolerance.
const EPS: f64 = 1e-10;

/// Six rows in six unknowns, two groups of three: rows 0 and 1 (3 and 4) are unit rows, row 2
/// is `r0 + 2 r1` and row 5 is `3 r3 + r4`, each off by `delta` in a third unknown of its
/// group, `delta² = 3 EPS`. So the pivots of rows 2 and 5 (their squared distances from the
/// rows before them, `3 EPS`) are kept, as rounding keeps the pivots of dependent rows in a
/// large mesh, while in `J` each group is dependent within the tolerance: with `y` of unit
/// length along `(1, 2, -1)` (`(3, 1, -1)`), `‖Jᵀ y‖² = delta² / 6` (`/ 11`). The row with the
/// largest share in each dependence is 1 (weight 2) and 3 (weight 3). `G` comes factorised
/// with [`EPS`], every row kept.
fn nearly_dependent() -> (Gram, Columns, Vec<f64>) {
    off_by(1.0, (3.0 * EPS).sqrt(), EPS)
}

/// The rows of [`nearly_dependent`] with rows 2 and 5 scaled by `s` and off by `delta`, `G`
/// factorised with the tolerance `eps` (which keeps every row).
fn off_by(s: f64, delta: f64, eps: f64) -> (Gram, Columns, Vec<f64>) {
    let mut jn = Vec::new();
    let mut lists: Vec<Vec<(u32, u32)>> = vec![Vec::new(); 6];
    let mut put = |row: u32, col: usize, v: f64| {
        lists[col].push((row, jn.len() as u32));
        jn.push(v);
    };
    for g in 0..2 {
        let (r, c) = (3 * g as u32, 3 * g);
        let (a, b) = if g == 0 { (1.0, 2.0) } else { (3.0, 1.0) };
        put(r, c, 1.0);
        put(r + 1, c + 1, 1.0);
        put(r + 2, c, s * a);
        put(r + 2, c + 1, s * b);
        put(r + 2, c + 2, delta);
    }
    for l in &mut lists {
        l.sort_unstable();
    }
    let columns = Columns::from_lists(&lists);
    let mut gram = Gram::new(6, &columns).expect("a Gram");
    gram.assemble(&jn);
    assert!(gram.factor(0.0, eps));
    assert!(gram.dropped().is_empty(), "{:?}", gram.dropped());
    (gram, columns, jn)
}

#[test]
fn the_rows_dropped_together_are_those_dropped_one_at_a_time() {
    let (mut gram, columns, jn) = nearly_dependent();
    let together = drop_together(&mut gram, &columns, &jn, &[], 2, EPS);
    assert_eq!(together, Some(vec![1, 3]));
    // `G` is left factorised without them, and the rows left are independent.
    assert_eq!(gram.dropped(), vec![1, 3]);
    assert!(gram.smallest_kept_pivot() > 1e-3);

    let (mut gram, columns, jn) = nearly_dependent();
    let one_by_one = drop_one_at_a_time(&mut gram, &columns, &jn, &[], 2, EPS);
    assert_eq!(one_by_one, Some(vec![1, 3]));
    assert_eq!(gram.dropped(), vec![1, 3]);
}

#[test]
fn a_dependence_that_does_not_hold_in_the_jacobian_drops_nothing() {
    // With a tenth of the tolerance, the first group's dependence (`‖Jᵀ y‖² = EPS / 2`) is
    // not confirmed: the search all at once gives up before factorising, and `G` is left
    // factorised as it came (every row kept).
    let (mut gram, columns, jn) = nearly_dependent();
    assert_eq!(
        drop_together(&mut gram, &columns, &jn, &[], 2, EPS / 10.0),
        None
    );
    assert!(gram.dropped().is_empty());
    let (mut gram, columns, jn) = nearly_dependent();
    assert_eq!(
        drop_one_at_a_time(&mut gram, &columns, &jn, &[], 2, EPS / 10.0),
        None
    );
}

#[test]
fn rows_kept_though_the_jacobian_shows_them_dependent_are_dropped() {
    // Rows 2 and 5 scaled by 1e-4 and off by 1e-10: each group is dependent by far in `J`
    // (`‖Jᵀ y‖² / ‖y‖²` about 1e-20), but a factorisation at 1e-30 kept their pivots (1e-20),
    // as rounding keeps the pivot of a dependent row. Both dependences are found, the rows
    // with the largest shares in them (2 and 5, weight 1 against 1e-4 and 3e-4) dropped, and
    // `G` left factorised without them at the rank tolerance.
    let (mut gram, columns, jn) = off_by(1e-4, 1e-10, 1e-30);
    assert_eq!(
        drop_hidden(&mut gram, &columns, &jn, Vec::new(), EPS),
        vec![2, 5]
    );
    assert_eq!(gram.dropped(), vec![2, 5]);
    assert!(gram.smallest_kept_pivot() > 1e-3);
}

#[test]
fn rows_that_are_only_nearly_dependent_are_not_hidden_dependences() {
    // `nearly_dependent`'s groups are within the rank tolerance in `J` (`EPS / 2`, `3 EPS /
    // 11`) but far from an exact dependence: the pivots stand, nothing is dropped, and the
    // factorisation is left as it was.
    let (mut gram, columns, jn) = nearly_dependent();
    assert!(drop_hidden(&mut gram, &columns, &jn, Vec::new(), EPS).is_empty());
    assert!(gram.dropped().is_empty());
    assert!(gram.smallest_kept_pivot() < 1e-9);
}
