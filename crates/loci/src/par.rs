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
