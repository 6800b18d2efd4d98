//! File entities into loci's: points, normals, lines, arcs, workplanes and faces, those a
//! group made by copying, and the ones loci skips with a note.

use super::super::codes::EntityCode;
use super::super::records::{Kind, Record};
use super::super::{Note, SlvsError};
use super::*;
use crate::geom::quaternion_from_uv;
use crate::model::{Entity, EntityId, Param};

/// SolveSpace's entity type of a translated point.
pub(super) const POINT_N_TRANS: i64 = 2010;
/// A point turned and moved (a linked part's points).
pub(super) const POINT_N_ROT_TRANS: i64 = 2011;
/// A normal turned (a linked part's normals).
pub(super) const NORMAL_N_ROT: i64 = 3011;
/// A face through a point with a fixed normal.
pub(super) const FACE_NORMAL_PT: i64 = 5000;
/// A face translated from another.
pub(super) const FACE_N_TRANS: i64 = 5003;

pub(super) const POINT_KEYS: [&str; 4] = [
    "Entity.point[0].v",
    "Entity.point[1].v",
    "Entity.point[2].v",
    "Entity.point[3].v",
];

impl Builder<'_> {
    pub(super) fn entities(&mut self) -> Result<(), SlvsError> {
        for r in self.records.iter().filter(|r| r.kind == Kind::Entity) {
            let h = Self::handle(r, "Entity.h.v")?;
            if let Some(&first) = self.entity_line.get(&h) {
                return Err(SlvsError::Duplicate {
                    line: r.line,
                    record: "Entity",
                    handle: h,
                    first,
                });
            }
            self.entity_line.insert(h, r.line);
            self.entity_rec.insert(h, r);
            let code = r.int("Entity.type");
            let Some(kind) = EntityCode::from_code(code) else {
                return Err(SlvsError::UnknownType {
                    line: r.line_of("Entity.type"),
                    record: "Entity",
                    handle: h,
                    code,
                });
            };
            if let Some(e) = self.entity(h, kind, r)? {
                let _ = self.sys.add_entity(e);
            }
        }
        Ok(())
    }

    /// The model of file entity `h`, or `None` when loci skips it (with a note).
    pub(super) fn entity(
        &mut self,
        h: u32,
        kind: EntityCode,
        r: &Record,
    ) -> Result<Option<Entity>, SlvsError> {
        use EntityCode as E;
        let code = r.int("Entity.type");
        let generated = h & GROUP_BIT != 0;
        let group = if generated {
            FIXED_GROUP.0
        } else {
            match self.owner_group(h) {
                Some(g) => g,
                None => {
                    self.skip(h, r, kind, "its request does not exist");
                    return Ok(None);
                }
            }
        };
        let wp = match r.hex("Entity.workplane.v") {
            0 => None,
            w => Some(w),
        };
        let pt = |i: usize| r.hex(POINT_KEYS[i]);
        let act_point = [
            r.float("Entity.actPoint.x"),
            r.float("Entity.actPoint.y"),
            r.float("Entity.actPoint.z"),
        ];
        let act_normal = [
            r.float("Entity.actNormal.w"),
            r.float("Entity.actNormal.vx"),
            r.float("Entity.actNormal.vy"),
            r.float("Entity.actNormal.vz"),
        ];
        let p = own_params(h, kind);
        let e = match kind {
            E::PointIn3d if p.len() == 3 => Entity::point_3d(h, group, [p[0], p[1], p[2]]),
            E::PointIn2d if p.len() == 2 => {
                let Some(wp) = wp else {
                    return Err(SlvsError::MissingField {
                        line: r.line,
                        owner: super::super::file_name("Entity", h),
                        field: "Entity.workplane.v",
                    });
                };
                Entity::point_2d(h, group, wp, [p[0], p[1]])
            }
            E::NormalIn3d if p.len() == 4 => Entity::normal_3d(h, group, [p[0], p[1], p[2], p[3]]),
            E::Distance if p.len() == 1 => Entity::distance(h, group, wp, p[0]),
            E::NormalIn2d => match wp {
                Some(wp) => Entity::normal_2d(h, group, wp),
                None => {
                    return Err(SlvsError::MissingField {
                        line: r.line,
                        owner: super::super::file_name("Entity", h),
                        field: "Entity.workplane.v",
                    })
                }
            },
            E::PointCopy if code == POINT_N_ROT_TRANS => match self.moved_point(h, act_point) {
                Some(e) => e,
                None => {
                    let params = act_point.map(|v| self.constant(v));
                    Entity::point_3d(h, FIXED_GROUP.0, params)
                }
            },
            E::NormalCopy if code == NORMAL_N_ROT => match self.rotated_normal(h, act_normal) {
                Some(e) => e,
                None => {
                    let params = act_normal.map(|v| self.constant(v));
                    Entity::normal_3d(h, FIXED_GROUP.0, params)
                }
            },
            E::PointCopy if code == POINT_N_TRANS => match self.translated(h, act_point) {
                Some(e) => e,
                None => {
                    let params = act_point.map(|v| self.constant(v));
                    Entity::point_3d(h, FIXED_GROUP.0, params)
                }
            },
            E::PointCopy => {
                let params = act_point.map(|v| self.constant(v));
                Entity::point_3d(h, FIXED_GROUP.0, params)
            }
            E::NormalCopy => {
                let params = act_normal.map(|v| self.constant(v));
                Entity::normal_3d(h, FIXED_GROUP.0, params)
            }
            E::DistanceCopy => {
                let p = self.constant(r.float("Entity.actDistance"));
                Entity::distance(h, FIXED_GROUP.0, None, p)
            }
            E::Face => {
                // A face is a plane: its point and its (unit) normal vector, which SolveSpace
                // saves as the vector part of `actNormal`. The normal of the faces a
                // translation makes is fixed; their point moves with the translation.
                let n = [act_normal[1], act_normal[2], act_normal[3]];
                let Some(q) = rotation_to(n) else {
                    self.skip(h, r, kind, "its normal is zero");
                    return Ok(None);
                };
                let copier = self.copiers.contains_key(&((h >> 16) & 0x7fff));
                if self.linked_rotation(h).is_some() {
                    // A face of a linked part turns and moves with the part; loci holds it
                    // where it was saved.
                    self.frozen.insert(h, (h >> 16) & 0x7fff);
                }
                let origin = match code {
                    // A face through a point the group copied (an extrusion's top or bottom).
                    FACE_NORMAL_PT if copier && pt(0) >> 16 == h >> 16 => pt(0),
                    // A copied face: the source face's point, translated.
                    FACE_N_TRANS if copier => match self.translated(h, act_point) {
                        Some(e) => {
                            let p = self.fresh_entity.take();
                            let e = Entity {
                                h: EntityId(p),
                                ..e
                            };
                            let _ = self.sys.add_entity(e);
                            p
                        }
                        None => self.constant_point(act_point),
                    },
                    _ => {
                        if copier && code != FACE_NORMAL_PT {
                            // Its normal turns with the translation (a line swept into a
                            // face); loci holds it where it was saved.
                            self.frozen.insert(h, (h >> 16) & 0x7fff);
                        }
                        self.constant_point(act_point)
                    }
                };
                let normal = self.constant_normal(q);
                Entity::workplane(h, FIXED_GROUP.0, origin, normal)
            }
            E::Workplane => Entity::workplane(h, group, pt(0), r.hex("Entity.normal.v")),
            E::LineSegment => Entity::line(h, group, wp, pt(0), pt(1)),
            E::Cubic if r.int("Entity.extraPoints") == 0 => {
                Entity::cubic(h, group, wp, [pt(0), pt(1), pt(2), pt(3)])
            }
            E::Cubic => {
                self.skip(
                    h,
                    r,
                    kind,
                    "a spline through more than four points is not modelled (its points are)",
                );
                return Ok(None);
            }
            E::Circle => Entity::circle(
                h,
                group,
                wp,
                pt(0),
                r.hex("Entity.normal.v"),
                r.hex("Entity.distance.v"),
            ),
            E::ArcOfCircle => match wp {
                Some(wp) => {
                    Entity::arc(h, group, wp, r.hex("Entity.normal.v"), pt(0), pt(1), pt(2))
                }
                None => {
                    self.skip(h, r, kind, "an arc outside a workplane is not modelled");
                    return Ok(None);
                }
            },
            E::CubicPeriodic => {
                self.skip(
                    h,
                    r,
                    kind,
                    "periodic splines are not modelled (their points are)",
                );
                return Ok(None);
            }
            E::TtfText | E::Image => {
                self.skip(
                    h,
                    r,
                    kind,
                    "text and images are not modelled (their points are)",
                );
                return Ok(None);
            }
            E::PointIn3d | E::PointIn2d | E::NormalIn3d | E::Distance => {
                self.skip(h, r, kind, "its handle is not one a request generates");
                return Ok(None);
            }
        };
        Ok(Some(e))
    }

    /// The model of a point group `g` made by translating another (`h` is the file's
    /// entity, at `at` as saved): its own coordinates, tied to its source point plus the
    /// group's translation times the copy's number. `None` when the group does not copy by
    /// translation, or the remap table, the source or the translation is missing; the
    /// caller then holds the point where it was saved, and a constraint of its group on it
    /// makes that group unsupported.
    pub(super) fn translated(&mut self, h: u32, at: [f64; 3]) -> Option<Entity> {
        let g = (h >> 16) & 0x7fff;
        let base_h = h & 0xffff_0000;
        let copier = self.copiers.get(&g)?;
        let found = copier
            .remap
            .get(&(h & 0xffff))
            .and_then(|&(src, copy)| Some((src, copier.times(copy)?)));
        let translation = [base_h, base_h | 1, base_h | 2];
        let ok = translation.iter().all(|p| self.param_handles.contains(p));
        let source = found.and_then(|(src, times)| {
            // The source of a copied face is a face: its point is the one translated.
            match self.sys.entity(EntityId(src)).map(|e| &e.kind) {
                Some(k) if k.entity_type().is_point() => Some((src, times)),
                Some(crate::EntityKind::Workplane { origin, .. }) if self.is_face(src) => {
                    Some((origin.0, times))
                }
                _ => None,
            }
        });
        let Some((src, times)) = source.filter(|_| ok) else {
            self.frozen.insert(h, g);
            return None;
        };
        // Start where the source and the saved translation put it: SolveSpace saves
        // `actPoint` as of its last regeneration, which need not be current.
        let at = match (self.position(EntityId(src)), self.values(translation)) {
            (Some(b), Some(t)) => [0, 1, 2].map(|i| b[i] + f64::from(times) * t[i]),
            _ => at,
        };
        let params = at.map(|v| {
            let p = self.fresh_param.take();
            let _ = self.sys.add_param(Param::new(p, g, v));
            p
        });
        Some(Entity::point_n_trans(h, g, params, src, translation, times))
    }

    pub(super) fn skip(&mut self, h: u32, r: &Record, kind: EntityCode, why: &'static str) {
        self.skipped.insert(h, kind.name());
        self.notes.push(Note {
            line: r.line,
            message: format!("Entity.h.v={h:08x} ({}) skipped: {why}", kind.name()),
        });
    }
}

/// A unit quaternion whose N axis is along `n`, or `None` for a zero vector.
pub(super) fn rotation_to(n: [f64; 3]) -> Option<[f64; 4]> {
    let len = (n[0] * n[0] + n[1] * n[1] + n[2] * n[2]).sqrt();
    // (A NaN length is no direction either.)
    if len.is_nan() || len <= 1e-12 {
        return None;
    }
    let n = n.map(|v| v / len);
    // Any unit u perpendicular to n: cross n with the axis it is least aligned with.
    let a = if n[0].abs() < 0.6 {
        [1.0, 0.0, 0.0]
    } else {
        [0.0, 1.0, 0.0]
    };
    let cross = |a: [f64; 3], b: [f64; 3]| {
        [
            a[1] * b[2] - a[2] * b[1],
            a[2] * b[0] - a[0] * b[2],
            a[0] * b[1] - a[1] * b[0],
        ]
    };
    let u = cross(a, n);
    let ul = (u[0] * u[0] + u[1] * u[1] + u[2] * u[2]).sqrt();
    let u = u.map(|v| v / ul);
    let v = cross(n, u);
    Some(quaternion_from_uv(u, v))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geom::Quat;

    #[test]
    fn rotation_to_maps_z_onto_the_normal() {
        for n in [[1.0, 0.0, 0.0], [0.0, 0.0, -2.0], [0.3, -0.4, 0.5]] {
            let q = rotation_to(n).unwrap();
            let q = Quat {
                w: q[0],
                x: q[1],
                y: q[2],
                z: q[3],
            };
            let len = (n[0] * n[0] + n[1] * n[1] + n[2] * n[2]).sqrt();
            let got = q.n();
            for i in 0..3 {
                assert!((got.at(i) - n[i] / len).abs() < 1e-12, "{n:?}");
            }
        }
        assert!(rotation_to([0.0; 3]).is_none());
    }
}
