//! The part of a group a conflict can lie in, so that naming it costs what the conflict is
//! worth rather than what the group is: the constraints the solver found dependent (on the
//! merged equations, where equalities are gone), and the equalities that tie their parameters
//! to each other and to fixed values.
//!
//! Every dependent set of a part of the rows is a dependent set of all of them, so nothing
//! named here is wrong; a conflict the part misses is looked for in the whole group.

use crate::equations::{Kernel, Link, Owner};
use crate::model::{GroupId, System};
use std::collections::{HashSet, VecDeque};

/// The owners to keep: `seed`, and for each set of parameters the equalities join, the links
/// on paths from one parameter `seed` reads to the others it reads, and to the nearest fixed
/// one (a constant of the group, or a parameter fixed by a link, that link included).
pub(super) fn focus(
    sys: &System,
    group: GroupId,
    seed: &HashSet<Owner>,
    kernels: &[Kernel],
    links: &[Link],
) -> HashSet<Owner> {
    let params = sys.params();
    let np = params.len();
    let mut keep = seed.clone();
    let mut touched = vec![false; np];
    let mut list = Vec::new();
    let mut touch = |p: usize| {
        if !touched[p] {
            touched[p] = true;
            list.push(p);
        }
    };
    for k in kernels.iter().filter(|k| seed.contains(&k.owner)) {
        k.locals.iter().for_each(|&p| touch(p as usize));
    }
    for l in links {
        match *l {
            Link::Equal { owner, a, b } if seed.contains(&owner) => {
                touch(a);
                touch(b);
            }
            Link::Fix { owner, p, .. } if seed.contains(&owner) => touch(p),
            _ => {}
        }
    }
    // The equalities as a graph on parameters (compressed adjacency: neighbour, link).
    let mut ptr = vec![0usize; np + 1];
    let mut fix_of = vec![usize::MAX; np];
    for (i, l) in links.iter().enumerate() {
        match *l {
            Link::Equal { a, b, .. } => {
                ptr[a + 1] += 1;
                ptr[b + 1] += 1;
            }
            Link::Fix { p, .. } => {
                if fix_of[p] == usize::MAX {
                    fix_of[p] = i;
                }
            }
        }
    }
    for p in 0..np {
        ptr[p + 1] += ptr[p];
    }
    let mut fill = ptr.clone();
    let mut adj = vec![(0usize, 0usize); ptr[np]];
    for (i, l) in links.iter().enumerate() {
        if let Link::Equal { a, b, .. } = *l {
            adj[fill[a]] = (b, i);
            fill[a] += 1;
            adj[fill[b]] = (a, i);
            fill[b] += 1;
        }
    }
    let owner = |i: usize| match links[i] {
        Link::Equal { owner, .. } | Link::Fix { owner, .. } => owner,
    };
    let anchored = |p: usize| params[p].group != group || fix_of[p] != usize::MAX;
    // Breadth-first from each touched parameter not reached yet: the tree of shortest paths
    // of its set, then the paths back from the set's other touched parameters and its nearest
    // anchor. `on_path` stops a walk where an earlier one already kept the rest.
    let mut parent = vec![usize::MAX; np];
    let mut seen = vec![false; np];
    let mut on_path = vec![false; np];
    let mut queue = VecDeque::new();
    let mut reached = Vec::new();
    for &t in &list {
        if seen[t] {
            continue;
        }
        seen[t] = true;
        on_path[t] = true;
        queue.push_back(t);
        reached.clear();
        let mut anchor = None;
        while let Some(p) = queue.pop_front() {
            reached.push(p);
            if anchor.is_none() && anchored(p) {
                anchor = Some(p);
            }
            for &(q, i) in &adj[ptr[p]..ptr[p + 1]] {
                if !seen[q] {
                    seen[q] = true;
                    parent[q] = i;
                    queue.push_back(q);
                }
            }
        }
        let targets = reached
            .iter()
            .copied()
            .filter(|&p| touched[p])
            .chain(anchor);
        for mut p in targets {
            while !on_path[p] {
                on_path[p] = true;
                let i = parent[p];
                keep.insert(owner(i));
                p = match links[i] {
                    Link::Equal { a, b, .. } => {
                        if a == p {
                            b
                        } else {
                            a
                        }
                    }
                    Link::Fix { p, .. } => p,
                };
            }
        }
        if let Some(a) = anchor.filter(|&a| fix_of[a] != usize::MAX) {
            keep.insert(owner(fix_of[a]));
        }
    }
    keep
}
