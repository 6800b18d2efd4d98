//! The rows `rank::short_of_solution` drops where the factorisation kept rows that depend on
//! others: found all at once or one at a time, the same rows.

use super::gram::{Columns, Gram};
use super::rank::{drop_one_at_a_time, drop_together};

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
    let delta = (3.0 * EPS).sqrt();
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
        put(r + 2, c, a);
        put(r + 2, c + 1, b);
        put(r + 2, c + 2, delta);
    }
    for l in &mut lists {
        l.sort_unstable();
    }
    let columns = Columns::from_lists(&lists);
    let mut gram = Gram::new(6, &columns).expect("a Gram");
    gram.assemble(&jn);
    assert!(gram.factor(0.0, EPS));
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
