//! The geometry of a `.slvs` file from loci's: points, normals, workplanes, lines, cubics,
//! circles and arcs as SolveSpace's requests make them, each placed where loci's is.

use super::*;
use crate::geom::Quat;
use crate::model::{Constraint, ConstraintKind, Entity, EntityId, EntityKind, GroupId, ParamId};

impl<'a> Writer<'a> {
    /// Where loci point `p` is in space.
    pub(super) fn position(&self, p: EntityId) -> Result<[f64; 3], ExportError> {
        let e = self.entity(p)?;
        match &e.kind {
            EntityKind::PointIn2d { params } => {
                let w = e.workplane.ok_or(ExportError::Unsupported {
                    entity: p,
                    why: "a 2D point without a workplane",
                })?;
                let (o, q) = self.frame(w)?;
                let (u, v) = (self.value(params[0]), self.value(params[1]));
                let (qu, qv) = (q.u(), q.v());
                Ok([0, 1, 2].map(|i| o[i] + u * qu.at(i) + v * qv.at(i)))
            }
            k => {
                let ps = k.params();
                Ok([0, 1, 2].map(|i| ps.get(i).map_or(0.0, |&q| self.value(q))))
            }
        }
    }

    pub(super) fn quat(&self, n: EntityId) -> Result<Quat<f64>, ExportError> {
        let e = self.entity(n)?;
        match &e.kind {
            EntityKind::NormalIn3d { params } | EntityKind::NormalNRot { params, .. } => {
                let [w, x, y, z] = params.map(|p| self.value(p));
                Ok(Quat { w, x, y, z })
            }
            EntityKind::NormalIn2d => {
                let w = e.workplane.ok_or(ExportError::Unsupported {
                    entity: n,
                    why: "a 2D normal without a workplane",
                })?;
                Ok(self.frame(w)?.1)
            }
            _ => Err(ExportError::Unsupported {
                entity: n,
                why: "not a normal",
            }),
        }
    }

    pub(super) fn frame(&self, w: EntityId) -> Result<([f64; 3], Quat<f64>), ExportError> {
        match self.entity(w)?.kind {
            EntityKind::Workplane { origin, normal } => {
                Ok((self.position(origin)?, self.quat(normal)?))
            }
            _ => Err(ExportError::Unsupported {
                entity: w,
                why: "not a workplane",
            }),
        }
    }

    pub(super) fn project(&self, w: EntityId, p: [f64; 3]) -> Result<[f64; 2], ExportError> {
        let (o, q) = self.frame(w)?;
        let d = crate::geom::Vec3::new(p[0] - o[0], p[1] - o[1], p[2] - o[2]);
        Ok([d.dot(q.u()), d.dot(q.v())])
    }

    /// The file point `k` of request `r` (entity 0 for a datum point), owning loci point `p`
    /// when it fits (a point of the request's workplane, or a 3D point for a request in 3D)
    /// and nothing owns it yet; else a point of its own at `p`'s position, tied to `p`'s
    /// owner (written later) by a coincident constraint.
    pub(super) fn point_at(
        &mut self,
        p: EntityId,
        (r, group): (u32, GroupId),
        k: u32,
        wp: Option<EntityId>,
    ) -> Result<u32, ExportError> {
        let e = self.entity(p)?;
        let h = r << 16 | k;
        let n = k.saturating_sub(1);
        let base = r << 16 | (16 + 3 * n);
        let file_wp = match wp {
            Some(w) => self.workplane_of(w)?,
            None => 0,
        };
        let fits = match (&e.kind, wp) {
            (EntityKind::PointIn2d { .. }, Some(w)) => e.workplane == Some(w),
            (EntityKind::PointIn2d { .. }, None) => false,
            (_, None) => true,
            (_, Some(_)) => false,
        };
        // A request's points are unknowns of its group: it owns only points of that group.
        let own = fits && e.group == group && !self.owner.contains_key(&p);
        let values: Vec<f64> = if own {
            e.kind.params().iter().map(|&q| self.value(q)).collect()
        } else {
            let pos = self.position(p)?;
            match wp {
                Some(w) => self.project(w, pos)?.to_vec(),
                None => pos.to_vec(),
            }
        };
        for (i, v) in values.iter().enumerate() {
            self.params.push((base + i as u32, *v));
        }
        if own {
            for (i, &q) in e.kind.params().iter().enumerate() {
                self.map.insert(q, ParamId(base + i as u32));
            }
            self.owner.insert(p, h);
        } else {
            // Tie the copy to the loci point (mapped when constraints are written).
            let both_in = match (wp, e.workplane, &e.kind) {
                (Some(w), Some(pw), EntityKind::PointIn2d { .. }) if w == pw => Some(w),
                _ => None,
            };
            // The tie belongs to the later of the two groups, which solves it.
            let c = Constraint::new(0, e.group.max(group).0, ConstraintKind::PointsCoincident)
                .in_workplane(both_in.map(|w| w.0))
                .with_points(h, p.0);
            self.ties(c);
        }
        let kind = if wp.is_some() { E_POINT_2D } else { E_POINT_3D };
        self.push_ent(h, kind, file_wp, vec![], 0, 0);
        Ok(h)
    }

    /// The 3D normal at entity 32 of request `r`, owning loci normal `n` when nothing owns it
    /// yet, else a copy tied by `same_orientation`.
    pub(super) fn normal_3d_at(
        &mut self,
        n: EntityId,
        (r, group): (u32, GroupId),
        point: u32,
    ) -> Result<u32, ExportError> {
        let h = r << 16 | 32;
        let q = self.quat(n)?;
        let e = self.entity(n)?;
        let same_group = e.group == group;
        let tie_group = e.group.max(group);
        let own_params: Option<Vec<ParamId>> = match &e.kind {
            EntityKind::NormalIn3d { params } | EntityKind::NormalNRot { params, .. } => {
                Some(params.to_vec())
            }
            _ => None,
        };
        for (i, v) in [q.w, q.x, q.y, q.z].into_iter().enumerate() {
            self.params.push((r << 16 | (32 + i as u32), v));
        }
        match own_params.filter(|_| same_group && !self.owner.contains_key(&n)) {
            Some(ps) => {
                for (i, p) in ps.into_iter().enumerate() {
                    self.map.insert(p, ParamId(r << 16 | (32 + i as u32)));
                }
                self.owner.insert(n, h);
            }
            None => {
                let c = Constraint::new(0, tie_group.0, ConstraintKind::SameOrientation)
                    .with_entities([h, n.0, 0, 0]);
                self.ties(c);
            }
        }
        self.push_ent(h, E_NORMAL_3D, 0, vec![point], 0, 0);
        Ok(h)
    }

    /// A workplane request for loci workplane `e` (or, with no origin, a request that only
    /// holds the 3D normal `normal`).
    pub(super) fn workplane(
        &mut self,
        e: &'a Entity,
        origin: Option<EntityId>,
        normal: Option<EntityId>,
    ) -> Result<(), ExportError> {
        let r = self.request(REQ_WORKPLANE, e.group, None)?;
        let b = r << 16;
        let pt = match origin {
            Some(o) => self.point_at(o, (r, e.group), 1, None)?,
            None => {
                let pos = [0.0; 3];
                for (i, v) in pos.into_iter().enumerate() {
                    self.params.push((b | (16 + i as u32), v));
                }
                self.push_ent(b | 1, E_POINT_3D, 0, vec![], 0, 0);
                b | 1
            }
        };
        if let Some(n) = normal {
            self.normal_3d_at(n, (r, e.group), pt)?;
        }
        // Only a loci workplane is this file workplane; a normal's carrier is not.
        if origin.is_some() {
            self.owner.insert(e.h, b);
        }
        self.push_ent(b, E_WORKPLANE, 0, vec![pt], b | 32, 0);
        Ok(())
    }

    pub(super) fn curve(
        &mut self,
        e: &Entity,
        req: u32,
        kind: u32,
        points: &[EntityId],
    ) -> Result<(), ExportError> {
        let r = self.request(req, e.group, e.workplane)?;
        let mut hs = Vec::new();
        for (i, &p) in points.iter().enumerate() {
            hs.push(self.point_at(p, (r, e.group), i as u32 + 1, e.workplane)?);
        }
        let wp = match e.workplane {
            Some(w) => self.workplane_of(w)?,
            None => 0,
        };
        self.push_ent(r << 16, kind, wp, hs, 0, 0);
        self.owner.insert(e.h, r << 16);
        Ok(())
    }

    /// The normal of a request drawn in workplane `wp`: a 2D normal (SolveSpace's normal in
    /// 2D copies its workplane's).
    pub(super) fn normal_2d_at(&mut self, n: EntityId, r: u32, wp: u32, point: u32) -> u32 {
        let h = r << 16 | 32;
        self.owner.entry(n).or_insert(h);
        self.push_ent(h, E_NORMAL_2D, wp, vec![point], 0, 0);
        h
    }

    pub(super) fn circle(&mut self, e: &Entity) -> Result<(), ExportError> {
        let EntityKind::Circle {
            center,
            normal,
            radius,
        } = e.kind
        else {
            return Ok(());
        };
        // In a workplane when its normal is that workplane's; else free in 3D.
        let planar = e.workplane.filter(|&w| {
            self.sys
                .entity(normal)
                .is_some_and(|n| n.kind == EntityKind::NormalIn2d && n.workplane == Some(w))
        });
        let r = self.request(REQ_CIRCLE, e.group, planar)?;
        let b = r << 16;
        let c = self.point_at(center, (r, e.group), 1, planar)?;
        let n = match planar {
            Some(w) => {
                let fw = self.workplane_of(w)?;
                self.normal_2d_at(normal, r, fw, c)
            }
            None => self.normal_3d_at(normal, (r, e.group), c)?,
        };
        let d = b | 64;
        let rp = match self.entity(radius)?.kind {
            EntityKind::Distance { param } => param,
            _ => {
                return Err(ExportError::Unsupported {
                    entity: radius,
                    why: "a circle's radius must be a distance",
                })
            }
        };
        self.params.push((d, self.value(rp)));
        let fw = match planar {
            Some(w) => self.workplane_of(w)?,
            None => 0,
        };
        let radius_group = self.entity(radius)?.group;
        match self.radius_circle.get(&radius) {
            // A radius of an earlier group is written as a value of the circle's own.
            None if radius_group != e.group => {}
            None => {
                self.map.insert(rp, ParamId(d));
                self.owner.insert(radius, d);
                self.radius_circle.insert(radius, b);
            }
            Some(&first) => {
                let c = Constraint::new(0, e.group.0, ConstraintKind::EqualRadius)
                    .with_entities([b, first, 0, 0]);
                self.constraints.push(Queued::File(c));
            }
        }
        self.push_ent(d, E_DISTANCE, fw, vec![], 0, 0);
        self.push_ent(b, E_CIRCLE, fw, vec![c], n, d);
        self.owner.insert(e.h, b);
        Ok(())
    }

    pub(super) fn arc(&mut self, e: &Entity) -> Result<(), ExportError> {
        let EntityKind::ArcOfCircle {
            normal,
            center,
            start,
            end,
        } = e.kind
        else {
            return Ok(());
        };
        let Some(w) = e.workplane else {
            return Err(ExportError::Unsupported {
                entity: e.h,
                why: "an arc needs a workplane",
            });
        };
        let r = self.request(REQ_ARC, e.group, Some(w))?;
        let b = r << 16;
        let fw = self.workplane_of(w)?;
        let c = self.point_at(center, (r, e.group), 1, Some(w))?;
        let s = self.point_at(start, (r, e.group), 2, Some(w))?;
        let f = self.point_at(end, (r, e.group), 3, Some(w))?;
        let n = self.normal_2d_at(normal, r, fw, c);
        self.push_ent(b, E_ARC, fw, vec![c, s, f], n, 0);
        self.owner.insert(e.h, b);
        Ok(())
    }
}
