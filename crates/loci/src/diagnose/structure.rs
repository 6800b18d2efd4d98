//! Counting before numerics: a maximum matching of equations to the unknowns they involve
//! (Hopcroft–Karp). An equation left unmatched, with every equation reachable from it by
//! alternating paths, forms a block with more equations than unknowns (the over-determined
//! part of the Dulmage–Mendelsohn decomposition): whatever the values, some of its equations
//! depend on the others.

use super::report::{Member, OverConstrained};
use super::unmerged::{Equations, Linear};
use std::collections::VecDeque;

const NONE: u32 = u32::MAX;

/// Which unknowns each row involves: the nonzeros of the Jacobian at a generic point.
pub(crate) fn pattern(eqs: &Equations, generic: &Linear) -> Vec<Vec<u32>> {
    (0..eqs.rows)
        .map(|row| {
            eqs.row_entries(row)
                .filter(|&(_, idx)| generic.jn[idx as usize] != 0.0)
                .map(|(c, _)| c)
                .collect()
        })
        .collect()
}

/// A maximum matching: per row its column, per column its row (or [`NONE`]).
fn hopcroft_karp(adj: &[Vec<u32>], ncols: usize) -> (Vec<u32>, Vec<u32>) {
    let nrows = adj.len();
    let mut row_match = vec![NONE; nrows];
    let mut col_match = vec![NONE; ncols];
    // A greedy start does most of the work on sketches.
    for (r, cols) in adj.iter().enumerate() {
        if let Some(&c) = cols.iter().find(|&&c| col_match[c as usize] == NONE) {
            row_match[r] = c;
            col_match[c as usize] = r as u32;
        }
    }
    let mut dist = vec![u32::MAX; nrows];
    let mut next = vec![0usize; nrows];
    let mut queue = VecDeque::new();
    let mut stack: Vec<usize> = Vec::new();
    loop {
        // Layers of alternating paths from the free rows.
        queue.clear();
        for r in 0..nrows {
            if row_match[r] == NONE {
                dist[r] = 0;
                queue.push_back(r);
            } else {
                dist[r] = u32::MAX;
            }
        }
        let mut found = false;
        while let Some(r) = queue.pop_front() {
            for &c in &adj[r] {
                let r2 = col_match[c as usize];
                if r2 == NONE {
                    found = true;
                } else if dist[r2 as usize] == u32::MAX {
                    dist[r2 as usize] = dist[r] + 1;
                    queue.push_back(r2 as usize);
                }
            }
        }
        if !found {
            break;
        }
        // Vertex-disjoint shortest augmenting paths, by an explicit-stack search (chains of
        // thousands of equations would overflow a recursive one).
        next.iter_mut().for_each(|v| *v = 0);
        for start in 0..nrows {
            if row_match[start] != NONE {
                continue;
            }
            stack.clear();
            stack.push(start);
            while let Some(&r) = stack.last() {
                if next[r] < adj[r].len() {
                    let c = adj[r][next[r]];
                    next[r] += 1;
                    let r2 = col_match[c as usize];
                    if r2 == NONE {
                        // Every row on the stack takes the column it went through.
                        for &row in &stack {
                            let col = adj[row][next[row] - 1];
                            row_match[row] = col;
                            col_match[col as usize] = row as u32;
                        }
                        break;
                    } else if dist[r2 as usize] == dist[r] + 1 {
                        stack.push(r2 as usize);
                    }
                } else {
                    dist[r] = u32::MAX;
                    stack.pop();
                }
            }
        }
    }
    (row_match, col_match)
}

/// The over-determined blocks: from each unmatched row, the rows and columns reachable by
/// alternating paths (a row reaches its columns, a column its matched row); blocks that touch
/// are merged.
pub(crate) fn over_constrained(eqs: &Equations, adj: &[Vec<u32>]) -> Vec<OverConstrained> {
    let ncols = eqs.columns.len();
    let (row_match, col_match) = hopcroft_karp(adj, ncols);
    let mut label = vec![NONE; adj.len()];
    let mut col_label = vec![NONE; ncols];
    let mut parent: Vec<u32> = Vec::new();
    fn find(p: &mut [u32], mut a: u32) -> u32 {
        while p[a as usize] != a {
            p[a as usize] = p[p[a as usize] as usize];
            a = p[a as usize];
        }
        a
    }
    let mut queue = VecDeque::new();
    for start in 0..adj.len() {
        if row_match[start] != NONE || label[start] != NONE {
            continue;
        }
        let l = parent.len() as u32;
        parent.push(l);
        label[start] = l;
        queue.push_back(start);
        while let Some(r) = queue.pop_front() {
            for &c in &adj[r] {
                match col_label[c as usize] {
                    NONE => col_label[c as usize] = l,
                    o => {
                        let (a, b) = (find(&mut parent, o), find(&mut parent, l));
                        parent[a.max(b) as usize] = a.min(b);
                        continue;
                    }
                }
                let r2 = col_match[c as usize];
                if r2 != NONE && label[r2 as usize] == NONE {
                    label[r2 as usize] = l;
                    queue.push_back(r2 as usize);
                }
            }
        }
    }
    if parent.is_empty() {
        return Vec::new();
    }
    let roots: Vec<u32> = (0..parent.len() as u32)
        .map(|l| find(&mut parent, l))
        .collect();
    let mut blocks: Vec<(Vec<usize>, usize)> = vec![(Vec::new(), 0); parent.len()];
    for (r, &l) in label.iter().enumerate() {
        if l != NONE {
            blocks[roots[l as usize] as usize].0.push(r);
        }
    }
    for &l in &col_label {
        if l != NONE {
            blocks[roots[l as usize] as usize].1 += 1;
        }
    }
    let mut out: Vec<OverConstrained> = blocks
        .into_iter()
        .filter(|(rows, cols)| rows.len() > *cols)
        .map(|(rows, cols)| {
            let mut members: Vec<Member> = rows
                .iter()
                .map(|&r| eqs.member(eqs.row_kernel[r] as usize))
                .collect();
            members.sort_by(Member::report_order);
            members.dedup();
            OverConstrained {
                members,
                equations: rows.len(),
                unknowns: cols,
            }
        })
        .collect();
    out.sort_by_key(|b| (b.equations - b.unknowns, b.members.len()));
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn matching_is_maximum_on_a_chain_that_greedy_gets_wrong() {
        // Rows 0..3 over columns 0..3: greedy matches row 0 to column 0, which row 2 needs.
        let adj = vec![vec![0, 1], vec![1, 2], vec![0]];
        let (rm, cm) = hopcroft_karp(&adj, 3);
        assert!(rm.iter().all(|&c| c != NONE));
        for (r, &c) in rm.iter().enumerate() {
            assert_eq!(cm[c as usize], r as u32);
        }
    }

    #[test]
    fn three_rows_on_two_columns_leave_one_unmatched() {
        let adj = vec![vec![0, 1], vec![0, 1], vec![1]];
        let (rm, _) = hopcroft_karp(&adj, 2);
        assert_eq!(rm.iter().filter(|&&c| c == NONE).count(), 1);
    }
}
