//! libslvs's choice of starting point for parameters that constraints make equal.
//!
//! Both solvers remove equations of the form `a = b` between two unknowns by merging the two
//! parameters, but they start the merged unknown at different values: loci takes the mean of
//! the members (favouring dragged ones), libslvs keeps one member's value. With an
//! under-constrained sketch that decides where the geometry ends up, e.g. which of two
//! coincident points moves to the other. To behave as libslvs, this module gives every member
//! the value of the member libslvs keeps before loci solves; loci's mean is then that value.
//!
//! libslvs's rule: it visits the equations in constraint order; for `a - b` (with both
//! already replaced by what they were merged into) it keeps `b`, unless `a` is dragged, and
//! merging something into itself does nothing.

use crate::abi::*;
use std::collections::HashMap;

/// The pairs of parameters a constraint equates outright, in the order libslvs writes them:
/// coincident points (both 3D, or both in the constraint's workplane), horizontal and vertical
/// between points in the constraint's workplane, and equal radius between two circles.
fn equal_pairs(
    c: &Slvs_Constraint,
    entity: &HashMap<u32, &Slvs_Entity>,
) -> Vec<(Slvs_hParam, Slvs_hParam)> {
    let native = |h: u32| -> Option<Vec<Slvs_hParam>> {
        let e = entity.get(&h)?;
        match (e.r#type, c.wrkpl) {
            (SLVS_E_POINT_IN_3D, 0) => Some(e.param[..3].to_vec()),
            (SLVS_E_POINT_IN_2D, w) if w != 0 && e.wrkpl == w => Some(e.param[..2].to_vec()),
            _ => None,
        }
    };
    let ends = |h: u32| -> Option<(u32, u32)> {
        let e = entity.get(&h)?;
        (e.r#type == SLVS_E_LINE_SEGMENT).then_some((e.point[0], e.point[1]))
    };
    let radius = |h: u32| -> Option<Slvs_hParam> {
        let e = entity.get(&h)?;
        if e.r#type != SLVS_E_CIRCLE {
            return None;
        }
        let d = entity.get(&e.distance)?;
        (d.r#type == SLVS_E_DISTANCE).then_some(d.param[0])
    };
    let pairs = |a: u32, b: u32| -> Option<Vec<(u32, u32)>> {
        let (pa, pb) = (native(a)?, native(b)?);
        Some(pa.into_iter().zip(pb).collect())
    };
    let out = match c.r#type {
        100_000 => pairs(c.ptA, c.ptB),
        100_019 | 100_020 => {
            let (a, b) = if c.entityA != 0 {
                ends(c.entityA).unwrap_or((0, 0))
            } else {
                (c.ptA, c.ptB)
            };
            let axis = usize::from(c.r#type == 100_019);
            (c.wrkpl != 0)
                .then(|| pairs(a, b))
                .flatten()
                .map(|v| vec![v[axis]])
        }
        100_029 => radius(c.entityA).zip(radius(c.entityB)).map(|p| vec![p]),
        _ => None,
    };
    out.unwrap_or_default()
}

/// New starting values `(index into params, value)` so that parameters merged by equality
/// constraints of group `hg` all start where libslvs would start their merged unknown.
#[must_use]
pub fn merged_start_values(
    params: &[Slvs_Param],
    entities: &[Slvs_Entity],
    constraints: &[Slvs_Constraint],
    dragged: &[Slvs_hParam],
    hg: Slvs_hGroup,
) -> Vec<(usize, f64)> {
    let index: HashMap<u32, usize> = params.iter().enumerate().map(|(i, p)| (p.h, i)).collect();
    let entity: HashMap<u32, &Slvs_Entity> = entities.iter().map(|e| (e.h, e)).collect();
    let mut parent: Vec<usize> = (0..params.len()).collect();
    fn find(parent: &mut [usize], mut a: usize) -> usize {
        while parent[a] != a {
            parent[a] = parent[parent[a]];
            a = parent[a];
        }
        a
    }
    let mut touched = false;
    for c in constraints.iter().filter(|c| c.group == hg) {
        for (a, b) in equal_pairs(c, &entity) {
            let (Some(&ia), Some(&ib)) = (index.get(&a), index.get(&b)) else {
                continue;
            };
            // Only unknowns are merged; an equation with a constant is just solved.
            if params[ia].group != hg || params[ib].group != hg {
                continue;
            }
            let (mut ra, mut rb) = (find(&mut parent, ia), find(&mut parent, ib));
            if ra == rb {
                continue;
            }
            if dragged.contains(&params[ra].h) {
                std::mem::swap(&mut ra, &mut rb);
            }
            parent[ra] = rb;
            touched = true;
        }
    }
    if !touched {
        return Vec::new();
    }
    // A where-dragged point is held at the value it starts with, so its parameters keep theirs;
    // the merged unknown then ends where that point is, whatever it starts at.
    let pinned: Vec<Slvs_hParam> = constraints
        .iter()
        .filter(|c| c.group == hg && c.r#type == 100_031)
        .filter_map(|c| entity.get(&c.ptA))
        .flat_map(|e| e.param)
        .collect();
    (0..params.len())
        .filter_map(|i| {
            let r = find(&mut parent, i);
            (r != i && !pinned.contains(&params[i].h)).then(|| (i, params[r].val))
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn point2(h: u32, wp: u32, u: u32, v: u32) -> Slvs_Entity {
        Slvs_Entity {
            h,
            group: 2,
            r#type: SLVS_E_POINT_IN_2D,
            wrkpl: wp,
            point: [0; 4],
            normal: 0,
            distance: 0,
            param: [u, v, 0, 0],
        }
    }

    fn coincident(h: u32, a: u32, b: u32) -> Slvs_Constraint {
        Slvs_Constraint {
            h,
            group: 2,
            r#type: 100_000,
            wrkpl: 9,
            valA: 0.0,
            ptA: a,
            ptB: b,
            entityA: 0,
            entityB: 0,
            entityC: 0,
            entityD: 0,
            other: 0,
            other2: 0,
        }
    }

    fn params() -> Vec<Slvs_Param> {
        [(1, 10.0), (2, 20.0), (3, 30.0), (4, 40.0)]
            .map(|(h, val)| Slvs_Param { h, group: 2, val })
            .to_vec()
    }

    #[test]
    fn the_second_point_is_kept_unless_the_first_is_dragged() {
        let e = [point2(100, 9, 1, 2), point2(101, 9, 3, 4)];
        let c = [coincident(1, 100, 101)];
        assert_eq!(
            merged_start_values(&params(), &e, &c, &[], 2),
            vec![(0, 30.0), (1, 40.0)]
        );
        assert_eq!(
            merged_start_values(&params(), &e, &c, &[1, 2], 2),
            vec![(2, 10.0), (3, 20.0)]
        );
        // Another group's constraint, or points outside the constraint's workplane: nothing.
        assert!(merged_start_values(&params(), &e, &c, &[], 3).is_empty());
        let mut off = c;
        off[0].wrkpl = 0;
        assert!(merged_start_values(&params(), &e, &off, &[], 2).is_empty());
    }
}
