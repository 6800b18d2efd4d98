//! Groups that copy or link geometry: a linked part's motion (its translation and the normal
//! over its rotation) and the points and normals it moves, and the equations that tie a copy
//! made by translation to its source.

use super::super::codes::GroupKind;
use super::super::records::Record;
use super::super::{GroupStatus, SlvsGroup};
use super::*;
use crate::geom::Quat;
use crate::model::{Constraint, Entity, EntityId, Param};
use std::collections::HashMap;

/// A linked part's motion: its translation parameters, the normal loci made over its
/// rotation, and their saved values (the rotation scaled to unit length).
pub(super) struct LinkedMotion {
    translation: [u32; 3],
    normal: u32,
    t: [f64; 3],
    q: Quat<f64>,
}

/// A group that copies the entities of another by translation: which copy number each of
/// its entities is, and the workplane that steers the translation.
pub(super) struct Copier {
    kind: GroupKind,
    /// Entity index in the group -> (source entity, copy number), from `Group.remap`.
    pub(super) remap: HashMap<u32, (u32, u32)>,
    /// Copy number -> times the translation is applied.
    times: HashMap<u32, i32>,
    /// `predef.entityB`: the extrusion goes along its normal, a step and repeat stays
    /// parallel to it. `None` for a skewed extrusion or one free in 3D.
    workplane: Option<u32>,
}

impl Copier {
    /// SolveSpace's copy numbers for an extrusion's top and bottom.
    const TOP: u32 = 1001;
    const BOTTOM: u32 = 1002;
    /// The last copy of a step and repeat.
    const LAST: u32 = 1000;

    /// The copier for a group record, or `None` when the group does not copy by
    /// translation (or has a subtype loci does not know).
    pub(super) fn of(kind: GroupKind, r: &Record) -> Option<Self> {
        const ONE_SIDED: i64 = 7000;
        const TWO_SIDED: i64 = 7001;
        const ONE_SKEWED: i64 = 7004;
        const TWO_SKEWED: i64 = 7005;
        let subtype = r.int("Group.subtype");
        let wp = match r.hex("Group.predef.entityB.v") {
            0 => None,
            w => Some(w),
        };
        let mut times = HashMap::new();
        let workplane = match kind {
            GroupKind::Extrude => {
                let (bottom, top, skewed) = match subtype {
                    ONE_SIDED => (0, 2, false),
                    TWO_SIDED => (-1, 1, false),
                    ONE_SKEWED => (0, 2, true),
                    TWO_SKEWED => (-1, 1, true),
                    _ => return None,
                };
                times.insert(Self::BOTTOM, bottom);
                times.insert(Self::TOP, top);
                if skewed {
                    None
                } else {
                    wp
                }
            }
            GroupKind::Translate => {
                let one_sided = match subtype {
                    ONE_SIDED => true,
                    TWO_SIDED => false,
                    _ => return None,
                };
                times = Self::repeat_times(
                    r.float("Group.valA"),
                    one_sided,
                    r.flag("Group.skipFirst"),
                )?;
                wp
            }
            _ => return None,
        };
        let remap = r
            .remap("Group.remap")
            .iter()
            .map(|&(i, src, copy)| (i, (src, copy)))
            .collect();
        Some(Self {
            kind,
            remap,
            times,
            workplane,
        })
    }

    /// Copy number -> times applied for a step and repeat of `copies` copies. Copy `a` of
    /// `a0..n` sits at `2a` translations (one side) or centred about the original (two
    /// sides); the last copy has its own number. (SolveSpace's translation vector is half
    /// the step.)
    fn repeat_times(copies: f64, one_sided: bool, skip_first: bool) -> Option<HashMap<u32, i32>> {
        if !(1.0..=1e6).contains(&copies) {
            return None;
        }
        let mut n = copies as i64;
        let mut a0 = 0;
        if one_sided && skip_first {
            a0 += 1;
            n += 1;
        }
        let mut times = HashMap::new();
        for a in a0..n {
            let t = a * 2 - if one_sided { 0 } else { n - 1 };
            let copy = if a == n - 1 { Self::LAST } else { a as u32 };
            times.insert(copy, i32::try_from(t).ok()?);
        }
        Some(times)
    }

    pub(super) fn times(&self, copy: u32) -> Option<i32> {
        self.times.get(&copy).copied()
    }
}

impl Builder<'_> {
    /// The linked parts' rotations: SolveSpace holds a linked group's quaternion (its
    /// parameters 3..6, after the translation's 0..2) at unit length with an equation of the
    /// group; loci makes it a normal of the group, whose implicit condition is the same. A
    /// group without its seven parameters is not modelled.
    pub(super) fn linked_rotations(&mut self, groups: &mut [SlvsGroup]) {
        let mut hs: Vec<u32> = self.linked.keys().copied().collect();
        hs.sort_unstable();
        for g in hs {
            let base_h = GROUP_BIT | g << 16;
            if !(0..7).all(|i| self.param_handles.contains(&(base_h | i))) {
                self.linked.remove(&g);
                groups[self.groups[&g]].status = GroupStatus::Unsupported(
                    "the file does not hold the linked part's translation and rotation".into(),
                );
                continue;
            }
            let normal = self.fresh_entity.take();
            let q = [3, 4, 5, 6].map(|i| base_h | i);
            let _ = self.sys.add_entity(Entity::normal_3d(normal, g, q));
            self.linked.insert(g, normal);
        }
    }

    /// For an entity of a linked part: its group's translation parameters, the normal holding
    /// its rotation, and their saved values (the rotation scaled to unit length).
    pub(super) fn linked_rotation(&self, h: u32) -> Option<LinkedMotion> {
        if h & GROUP_BIT == 0 {
            return None;
        }
        let g = (h >> 16) & 0x7fff;
        let normal = *self.linked.get(&g).filter(|&&n| n != 0)?;
        let base_h = h & 0xffff_0000;
        let translation = [base_h, base_h | 1, base_h | 2];
        let t = self.values(translation)?;
        let [w, x, y, z] = self.values([3, 4, 5, 6].map(|i| base_h | i))?;
        let len = (w * w + x * x + y * y + z * z).sqrt();
        // A zero (or NaN) quaternion is no rotation.
        if len.is_nan() || len <= 1e-12 {
            return None;
        }
        let q = Quat {
            w: w / len,
            x: x / len,
            y: y / len,
            z: z / len,
        };
        Some(LinkedMotion {
            translation,
            normal,
            t,
            q,
        })
    }

    /// A point of a linked part, saved at `at`: coordinates of its own tied to the base point
    /// of the linked file, recovered from the saved values as `q* (at - t) q`. `None` outside
    /// a modelled linked part (the caller holds it where it was saved).
    pub(super) fn moved_point(&mut self, h: u32, at: [f64; 3]) -> Option<Entity> {
        let LinkedMotion {
            translation,
            normal,
            t,
            q,
        } = self.linked_rotation(h)?;
        let d = crate::geom::Vec3::new(at[0] - t[0], at[1] - t[1], at[2] - t[2]);
        // The inverse rotation of d: its components along the rotated axes.
        let base = [d.dot(q.u()), d.dot(q.v()), d.dot(q.n())];
        let g = (h >> 16) & 0x7fff;
        let params = at.map(|v| {
            let p = self.fresh_param.take();
            let _ = self.sys.add_param(Param::new(p, g, v));
            p
        });
        Some(Entity::point_n_rot_trans(
            h,
            g,
            params,
            base,
            translation,
            normal,
        ))
    }

    /// A normal of a linked part, saved as `at`: a quaternion of its own tied to the linked
    /// file's orientation, recovered as `q* at`.
    pub(super) fn rotated_normal(&mut self, h: u32, at: [f64; 4]) -> Option<Entity> {
        let LinkedMotion { normal, q, .. } = self.linked_rotation(h)?;
        let a = Quat {
            w: at[0],
            x: at[1],
            y: at[2],
            z: at[3],
        };
        let b = q.conj().times(a);
        let g = (h >> 16) & 0x7fff;
        let params = at.map(|v| {
            let p = self.fresh_param.take();
            let _ = self.sys.add_param(Param::new(p, g, v));
            p
        });
        Some(Entity::normal_n_rot(
            h,
            g,
            params,
            [b.w, b.x, b.y, b.z],
            normal,
        ))
    }

    /// The values of parameters `ps`, if all are in the model.
    pub(super) fn values<const N: usize>(&self, ps: [u32; N]) -> Option<[f64; N]> {
        let mut out = [0.0; N];
        for (o, p) in out.iter_mut().zip(ps) {
            *o = self.sys.value(crate::ParamId(p))?;
        }
        Some(out)
    }

    /// Where point `h` is, from the current parameter values.
    pub(super) fn position(&self, h: EntityId) -> Option<[f64; 3]> {
        use crate::geom::Quat;
        let e = self.sys.entity(h)?;
        match &e.kind {
            crate::EntityKind::PointIn3d { params }
            | crate::EntityKind::PointNTrans { params, .. }
            | crate::EntityKind::PointNRotTrans { params, .. } => self.values(params.map(|p| p.0)),
            crate::EntityKind::PointIn2d { params } => {
                let [u, v] = self.values(params.map(|p| p.0))?;
                let crate::EntityKind::Workplane { origin, normal } =
                    &self.sys.entity(e.workplane?)?.kind
                else {
                    return None;
                };
                let o = self.position(*origin)?;
                let crate::EntityKind::NormalIn3d { params } = &self.sys.entity(*normal)?.kind
                else {
                    return None;
                };
                let [w, x, y, z] = self.values(params.map(|p| p.0))?;
                let q = Quat { w, x, y, z };
                let (qu, qv) = (q.u(), q.v());
                Some([0, 1, 2].map(|i| o[i] + u * qu.at(i) + v * qv.at(i)))
            }
            _ => None,
        }
    }

    /// Whether file entity `h` is a face (a workplane loci made for it).
    pub(super) fn is_face(&self, h: u32) -> bool {
        h & GROUP_BIT != 0 && self.entity_line.contains_key(&h)
    }

    /// The conditions a group that copies by translation puts on its translation vector
    /// (SolveSpace writes them as the group's own equations): an extrusion goes along the
    /// normal of its workplane (unless skewed), a step and repeat stays parallel to its
    /// workplane. Written as constraints of the group on the vector as a point from the
    /// origin, with handles the file does not use.
    pub(super) fn copier_equations(&mut self, groups: &mut [SlvsGroup]) {
        let mut hs: Vec<u32> = self.copiers.keys().copied().collect();
        hs.sort_unstable();
        for g in hs {
            let c = &self.copiers[&g];
            let (kind, wp) = (c.kind, c.workplane);
            let base_h = GROUP_BIT | g << 16;
            let translation = [base_h, base_h | 1, base_h | 2];
            let gi = self.groups[&g];
            if !translation.iter().all(|p| self.param_handles.contains(p)) {
                groups[gi].status = GroupStatus::Unsupported(
                    "the file does not hold the group's translation vector".into(),
                );
                continue;
            }
            let Some(wp) = wp else { continue };
            let plane = match self.sys.entity(EntityId(wp)).map(|e| &e.kind) {
                Some(crate::EntityKind::Workplane { normal, .. }) => *normal,
                _ => {
                    groups[gi].status = GroupStatus::Unsupported(format!(
                        "its workplane Entity.h.v={wp:08x} is not one loci models"
                    ));
                    continue;
                }
            };
            let vector = self.fresh_entity.take();
            let _ = self
                .sys
                .add_entity(Entity::point_3d(vector, g, translation));
            let origin = self.constant_point([0.0; 3]);
            let h = self.fresh_constraint.take();
            let c = match kind {
                // u . t = 0 and v . t = 0: the vector projects onto the workplane's origin.
                GroupKind::Extrude => {
                    Constraint::new(h, g, crate::ConstraintKind::PointsCoincident)
                        .in_workplane(Some(wp))
                        .with_points(vector, origin)
                }
                // n . t = 0: the vector lies in a plane through the origin with the
                // workplane's normal.
                _ => {
                    let through = self.fresh_entity.take();
                    let _ = self.sys.add_entity(Entity::workplane(
                        through,
                        FIXED_GROUP.0,
                        origin,
                        plane.0,
                    ));
                    Constraint::new(h, g, crate::ConstraintKind::PtInPlane)
                        .with_points(vector, 0)
                        .with_entities([through, 0, 0, 0])
                }
            };
            let _ = self.sys.add_constraint(c);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn step_and_repeat_copies_are_numbered_as_solvespace_does() {
        let sorted = |m: HashMap<u32, i32>| {
            let mut v: Vec<(u32, i32)> = m.into_iter().collect();
            v.sort_unstable();
            v
        };
        // One side, three copies: the original's place, then 2t and 4t (the last).
        let t = Copier::repeat_times(3.0, true, false).unwrap();
        assert_eq!(sorted(t), vec![(0, 0), (1, 2), (Copier::LAST, 4)]);
        // Skipping the first keeps three copies, moved one step on.
        let t = Copier::repeat_times(3.0, true, true).unwrap();
        assert_eq!(sorted(t), vec![(1, 2), (2, 4), (Copier::LAST, 6)]);
        // Two sides: centred on the original.
        let t = Copier::repeat_times(3.0, false, false).unwrap();
        assert_eq!(sorted(t), vec![(0, -2), (1, 0), (Copier::LAST, 2)]);
        assert!(Copier::repeat_times(0.0, true, false).is_none());
        assert!(Copier::repeat_times(f64::NAN, true, false).is_none());
    }
}
