//! A bandwidth-reducing order of the equations of a component: reverse Cuthill-McKee.
//!
//! Rows of `G = J Jᵀ` are adjacent when their equations share an unknown. A breadth-first
//! walk from a far end of that graph, neighbours taken by increasing degree, then reversed,
//! numbers each row close to its neighbours (Cuthill and McKee, 1969; George, 1971): a chain
//! whose equations come in any order, or whose implicit equations (equal arc radii) come
//! last, becomes banded, and its LDLᵀ fits in a small envelope.

/// The order (position -> row) of `n` rows with symmetric adjacency lists
/// `adj[ptr[i]..ptr[i + 1]]` (self loops excluded). Ties are broken by row number, so the
/// order is deterministic.
pub(super) fn reverse_cuthill_mckee(n: usize, ptr: &[usize], adj: &[u32]) -> Vec<u32> {
    let degree = |i: usize| ptr[i + 1] - ptr[i];
    let mut order: Vec<u32> = Vec::with_capacity(n);
    let mut seen = vec![false; n];
    let mut level = vec![u32::MAX; n];
    let mut next: Vec<u32> = Vec::new();
    // Rows by increasing degree: each connected part starts from its least connected row
    // not yet numbered, moved to a far end of its part first.
    let mut by_degree: Vec<u32> = (0..n as u32).collect();
    by_degree.sort_by_key(|&i| (degree(i as usize), i));
    for &s in &by_degree {
        if seen[s as usize] {
            continue;
        }
        let start = far_end(s as usize, ptr, adj, &mut level, &degree);
        let begin = order.len();
        seen[start] = true;
        order.push(start as u32);
        let mut head = begin;
        while head < order.len() {
            let v = order[head] as usize;
            head += 1;
            next.clear();
            next.extend(
                adj[ptr[v]..ptr[v + 1]]
                    .iter()
                    .copied()
                    .filter(|&u| !seen[u as usize]),
            );
            next.sort_by_key(|&u| (degree(u as usize), u));
            for &u in &next {
                seen[u as usize] = true;
                order.push(u);
            }
        }
    }
    order.reverse();
    order
}

/// A lower estimate of the envelope any reverse Cuthill-McKee order of the rows could reach:
/// `n² / (2e + 1)`, with `e` the number of breadth-first levels beyond row 0, when row 0
/// reaches every row (`None` otherwise). No level structure has more than `2e + 1` levels,
/// and in such an order each row reaches back about a level's width, `n` over the number of
/// levels on average. One breadth-first walk: far cheaper than the order itself, and enough to
/// tell a two-dimensional mesh (levels of width about `√n`) from a chain (width about 1).
pub(super) fn envelope_estimate(n: usize, ptr: &[usize], adj: &[u32]) -> Option<usize> {
    if n == 0 {
        return None;
    }
    let mut level = vec![u32::MAX; n];
    let mut queue: Vec<u32> = Vec::with_capacity(n);
    breadth_first(0, ptr, adj, &mut level, &mut queue);
    if queue.len() < n {
        return None;
    }
    let e = level[*queue.last()? as usize] as usize;
    Some(n.saturating_mul(n) / (2 * e + 1))
}

/// Walks `root`'s connected part breadth first: `queue` receives its rows in the order met,
/// `level` (all `u32::MAX` there on entry) each one's distance from `root`.
fn breadth_first(root: usize, ptr: &[usize], adj: &[u32], level: &mut [u32], queue: &mut Vec<u32>) {
    queue.clear();
    queue.push(root as u32);
    level[root] = 0;
    let mut head = 0;
    while head < queue.len() {
        let v = queue[head] as usize;
        head += 1;
        for &u in &adj[ptr[v]..ptr[v + 1]] {
            if level[u as usize] == u32::MAX {
                level[u as usize] = level[v] + 1;
                queue.push(u);
            }
        }
    }
}

/// A row at the far end of `s`'s connected part: breadth-first from `s`, then again from the
/// least connected row of the last level, while that moves further away (a pseudo-peripheral
/// row, as George and Liu find it). `level` is scratch, one entry per row, all `u32::MAX` on
/// entry and on return.
fn far_end(
    s: usize,
    ptr: &[usize],
    adj: &[u32],
    level: &mut [u32],
    degree: &dyn Fn(usize) -> usize,
) -> usize {
    let mut root = s;
    let mut depth: Option<u32> = None;
    let mut queue: Vec<u32> = Vec::new();
    for _ in 0..8 {
        breadth_first(root, ptr, adj, level, &mut queue);
        let last = queue.last().map_or(0, |&v| level[v as usize]);
        let candidate = queue
            .iter()
            .copied()
            .filter(|&v| level[v as usize] == last)
            .min_by_key(|&v| (degree(v as usize), v))
            .map_or(root, |v| v as usize);
        for &v in &queue {
            level[v as usize] = u32::MAX;
        }
        if depth.is_some_and(|d| last <= d) {
            break;
        }
        depth = Some(last);
        root = candidate;
    }
    root
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Adjacency lists from undirected edges.
    fn graph(n: usize, edges: &[(u32, u32)]) -> (Vec<usize>, Vec<u32>) {
        let mut lists = vec![Vec::new(); n];
        for &(a, b) in edges {
            lists[a as usize].push(b);
            lists[b as usize].push(a);
        }
        let mut ptr = vec![0];
        let mut adj = Vec::new();
        for l in lists {
            adj.extend(l);
            ptr.push(adj.len());
        }
        (ptr, adj)
    }

    #[test]
    fn a_shuffled_path_comes_out_in_path_order() {
        // The path 0-1-2-3-4-5 with its rows numbered 3, 5, 0, 4, 1, 2.
        let label = [3u32, 5, 0, 4, 1, 2];
        let edges: Vec<(u32, u32)> = (0..5).map(|i| (label[i], label[i + 1])).collect();
        let (ptr, adj) = graph(6, &edges);
        let order = reverse_cuthill_mckee(6, &ptr, &adj);
        let mut sorted = order.clone();
        sorted.sort_unstable();
        assert_eq!(sorted, vec![0, 1, 2, 3, 4, 5]);
        // Consecutive positions hold neighbours along the path: bandwidth 1.
        for w in order.windows(2) {
            assert!(
                edges.contains(&(w[0], w[1])) || edges.contains(&(w[1], w[0])),
                "{order:?}"
            );
        }
    }

    #[test]
    fn the_estimate_tells_a_grid_from_a_path() {
        // A path of 100 rows listed from its middle: 49 levels beyond row 0 at most.
        let label: Vec<u32> = (0..100).map(|i| ((i + 50) % 100) as u32).collect();
        let edges: Vec<(u32, u32)> = (0..99).map(|i| (label[i], label[i + 1])).collect();
        let (ptr, adj) = graph(100, &edges);
        let path = envelope_estimate(100, &ptr, &adj).unwrap();
        assert!(path <= 200, "{path}");
        // A 30 x 30 grid from a corner: 58 levels, an envelope of about 900 x 900 / 117.
        let at = |i: u32, j: u32| j * 30 + i;
        let mut edges = Vec::new();
        for j in 0..30 {
            for i in 0..30 {
                if i + 1 < 30 {
                    edges.push((at(i, j), at(i + 1, j)));
                }
                if j + 1 < 30 {
                    edges.push((at(i, j), at(i, j + 1)));
                }
            }
        }
        let (ptr, adj) = graph(900, &edges);
        assert_eq!(envelope_estimate(900, &ptr, &adj), Some(900 * 900 / 117));
        // Not every row reached: no estimate.
        let (ptr, adj) = graph(4, &[(0, 1), (2, 3)]);
        assert_eq!(envelope_estimate(4, &ptr, &adj), None);
    }

    #[test]
    fn every_row_is_numbered_once_across_separate_parts() {
        let (ptr, adj) = graph(7, &[(0, 4), (4, 2), (1, 5)]);
        let mut order = reverse_cuthill_mckee(7, &ptr, &adj);
        order.sort_unstable();
        assert_eq!(order, (0..7).collect::<Vec<u32>>());
    }
}
