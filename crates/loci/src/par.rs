//! Work spread over the cores: the independent components of a solve, and chunks of a large
//! group's constraints when they are compiled.
//!
//! Every item is computed exactly as it would be alone and the results come back in item order,
//! so the answer is bit-identical whether the work runs on one thread or many. Small problems stay
//! on the calling thread: waking the pool costs more than a sketch of a few hundred equations.

/// Below this many equations (or constraints) in all, work stays on the calling thread.
pub(crate) const MIN_PARALLEL: usize = 2048;

/// `f(state, i, item)` for every item, in parallel when `parallel` (and the `parallel` feature)
/// allows; `init` makes one state per thread. Results in item order.
pub(crate) fn map_items<T, S, R>(
    items: Vec<T>,
    parallel: bool,
    init: impl Fn() -> S + Sync + Send,
    f: impl Fn(&mut S, usize, T) -> R + Sync + Send,
) -> Vec<R>
where
    T: Send,
    R: Send,
{
    #[cfg(feature = "parallel")]
    if parallel && items.len() > 1 {
        use rayon::prelude::*;
        return items
            .into_par_iter()
            .enumerate()
            .map_init(&init, |s, (i, t)| f(s, i, t))
            .collect();
    }
    let _ = parallel;
    let mut s = init();
    items
        .into_iter()
        .enumerate()
        .map(|(i, t)| f(&mut s, i, t))
        .collect()
}

/// The first `Some` of `f(0)`, `f(1)`, … `f(n - 1)` in index order, the same whatever the
/// number of threads: with the `parallel` feature the calls run on the pool, each exactly as
/// it would alone, and those after an index that gave `Some` are skipped where they have not
/// begun. For a few costly independent tries (solves from different starts), where most fail
/// and each failure costs a full solve.
pub(crate) fn first_some<R: Send>(
    n: usize,
    f: impl Fn(usize) -> Option<R> + Sync + Send,
) -> Option<R> {
    #[cfg(feature = "parallel")]
    if n > 1 {
        use rayon::prelude::*;
        return (0..n).into_par_iter().find_map_first(f);
    }
    (0..n).find_map(f)
}

/// Drops `items`: when there are many, on the thread pool after the caller has moved on, and
/// spread over the cores. Freeing the thousands of small components of a large solve costs
/// about as much as building them did, and the caller is waiting for its report, not for that.
pub(crate) fn discard<T: Send + 'static>(items: Vec<T>) {
    #[cfg(feature = "parallel")]
    if items.len() >= MIN_PARALLEL {
        rayon::spawn(move || {
            use rayon::prelude::*;
            items.into_par_iter().for_each(drop);
        });
        return;
    }
    drop(items);
}

/// `check` on every item; the error of the first failing item in item order (the same error
/// whatever the number of threads). Large lists are checked in parallel chunks.
pub(crate) fn first_error<T: Sync, E: Send>(
    items: &[T],
    check: impl Fn(&T) -> Result<(), E> + Sync + Send,
) -> Result<(), E> {
    #[cfg(feature = "parallel")]
    if items.len() >= 4 * MIN_PARALLEL {
        use rayon::prelude::*;
        let chunks: Vec<Result<(), E>> = items
            .par_chunks(MIN_PARALLEL)
            .map(|c| c.iter().try_for_each(&check))
            .collect();
        return chunks.into_iter().find(Result::is_err).unwrap_or(Ok(()));
    }
    items.iter().try_for_each(check)
}
