//! Entities: geometry defined by parameters and by other entities.

use super::{EntityId, GroupId, ParamId};
use serde::{Deserialize, Serialize};
use std::fmt;

/// A geometric object. `workplane` is the plane a 2D entity lives in; `None` means free in 3D.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Entity {
    /// Unique non-zero handle.
    pub h: EntityId,
    /// The group this entity belongs to.
    pub group: GroupId,
    /// The workplane of a 2D entity. Required for `point_in_2d`, `normal_in_2d` and
    /// `arc_of_circle`; optional elsewhere (a line whose points lie in a workplane may name it).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub workplane: Option<EntityId>,
    /// What the entity is, with its parameters and sub-entities.
    #[serde(flatten)]
    pub kind: EntityKind,
}

/// The entity types of the SolveSpace model, each with what defines it.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(tag = "type", rename_all = "snake_case")]
pub enum EntityKind {
    /// A point in 3D: x, y, z.
    #[serde(rename = "point_in_3d")]
    PointIn3d {
        /// x, y, z.
        params: [ParamId; 3],
    },
    /// A point in a workplane: u, v in the workplane's coordinates.
    #[serde(rename = "point_in_2d")]
    PointIn2d {
        /// u, v.
        params: [ParamId; 2],
    },
    /// A point in 3D held at another point moved by a multiple of a translation vector:
    /// its own coordinates x, y, z, with the implicit condition
    /// `(x, y, z) = base + times * translation`. Extrusions and step-and-repeat copies make
    /// these: the translation is the copying group's unknown, `times` which copy this is.
    #[serde(rename = "point_n_trans")]
    PointNTrans {
        /// x, y, z.
        params: [ParamId; 3],
        /// The point it is a copy of (any point).
        base: EntityId,
        /// The translation vector's x, y, z.
        translation: [ParamId; 3],
        /// How many times the translation is applied (negative for the other side).
        times: i32,
    },
    /// A point in 3D held at a constant point carried by a rigid motion: its own
    /// coordinates x, y, z, with the implicit condition `(x, y, z) = translation + q base q*`
    /// where `q` is the quaternion of the normal `rotation`. SolveSpace's linked parts make
    /// these: the imported file's points, placed by the linking group's translation and
    /// rotation (its unknowns).
    #[serde(rename = "point_n_rot_trans")]
    PointNRotTrans {
        /// x, y, z.
        params: [ParamId; 3],
        /// The point before the motion (a constant).
        base: [f64; 3],
        /// The translation vector's x, y, z.
        translation: [ParamId; 3],
        /// A `normal_in_3d` whose quaternion is the rotation; its own implicit unit length
        /// keeps it a rotation.
        rotation: EntityId,
    },
    /// An orientation in 3D held at a constant orientation turned by a rotation: its own
    /// quaternion w, x, y, z, with the implicit condition `(w, x, y, z) = q * base` where `q`
    /// is the quaternion of the normal `rotation`. The normals of SolveSpace's linked parts.
    #[serde(rename = "normal_n_rot")]
    NormalNRot {
        /// w, x, y, z.
        params: [ParamId; 4],
        /// The orientation before the rotation (a constant unit quaternion w, x, y, z).
        base: [f64; 4],
        /// A `normal_in_3d` whose quaternion is the rotation.
        rotation: EntityId,
    },
    /// An orientation in 3D as a unit quaternion w, x, y, z (with the implicit `|q| = 1`).
    #[serde(rename = "normal_in_3d")]
    NormalIn3d {
        /// w, x, y, z.
        params: [ParamId; 4],
    },
    /// The normal of a workplane, copied from it.
    #[serde(rename = "normal_in_2d")]
    NormalIn2d,
    /// A distance, e.g. a circle's radius.
    Distance {
        /// The value.
        param: ParamId,
    },
    /// An oriented plane: an origin point and a normal (quaternion).
    Workplane {
        /// A 3D point.
        origin: EntityId,
        /// A 3D normal.
        normal: EntityId,
    },
    /// A line segment between two points.
    LineSegment {
        /// Start and end.
        points: [EntityId; 2],
    },
    /// A cubic Bezier segment: P0, P1, P2, P3.
    Cubic {
        /// The four control points.
        points: [EntityId; 4],
    },
    /// A complete circle.
    Circle {
        /// Centre point.
        center: EntityId,
        /// The normal of its plane.
        normal: EntityId,
        /// A distance entity holding the radius.
        radius: EntityId,
    },
    /// An arc, counter-clockwise from `start` to `end` about the workplane normal, with the
    /// implicit condition `|start - center| = |end - center|`. Coincident ends make a full circle.
    ArcOfCircle {
        /// The normal (of its workplane).
        normal: EntityId,
        /// Centre point.
        center: EntityId,
        /// Where the arc begins.
        start: EntityId,
        /// Where the arc ends.
        end: EntityId,
    },
}

/// The type of an entity without its data, for messages and type checks.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
#[allow(missing_docs)]
pub enum EntityType {
    #[serde(rename = "point_in_3d")]
    PointIn3d,
    #[serde(rename = "point_in_2d")]
    PointIn2d,
    #[serde(rename = "point_n_trans")]
    PointNTrans,
    #[serde(rename = "point_n_rot_trans")]
    PointNRotTrans,
    #[serde(rename = "normal_n_rot")]
    NormalNRot,
    #[serde(rename = "normal_in_3d")]
    NormalIn3d,
    #[serde(rename = "normal_in_2d")]
    NormalIn2d,
    Distance,
    Workplane,
    LineSegment,
    Cubic,
    Circle,
    ArcOfCircle,
}

impl EntityType {
    /// The `snake_case` name used in files and messages.
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            EntityType::PointIn3d => "point_in_3d",
            EntityType::PointIn2d => "point_in_2d",
            EntityType::PointNTrans => "point_n_trans",
            EntityType::PointNRotTrans => "point_n_rot_trans",
            EntityType::NormalNRot => "normal_n_rot",
            EntityType::NormalIn3d => "normal_in_3d",
            EntityType::NormalIn2d => "normal_in_2d",
            EntityType::Distance => "distance",
            EntityType::Workplane => "workplane",
            EntityType::LineSegment => "line_segment",
            EntityType::Cubic => "cubic",
            EntityType::Circle => "circle",
            EntityType::ArcOfCircle => "arc_of_circle",
        }
    }

    /// Whether this is a point.
    #[must_use]
    pub fn is_point(self) -> bool {
        matches!(
            self,
            EntityType::PointIn3d
                | EntityType::PointIn2d
                | EntityType::PointNTrans
                | EntityType::PointNRotTrans
        )
    }

    /// Whether this is a point with three coordinates of its own (a point in 3D or a
    /// moved copy of one), as a workplane's origin must be.
    #[must_use]
    pub fn is_point_3d(self) -> bool {
        matches!(
            self,
            EntityType::PointIn3d | EntityType::PointNTrans | EntityType::PointNRotTrans
        )
    }

    /// Whether this is a normal.
    #[must_use]
    pub fn is_normal(self) -> bool {
        self.is_normal_3d() || self == EntityType::NormalIn2d
    }

    /// Whether this is a normal with a quaternion of its own (in 3D or a rotated copy), as
    /// a workplane's normal must be.
    #[must_use]
    pub fn is_normal_3d(self) -> bool {
        matches!(self, EntityType::NormalIn3d | EntityType::NormalNRot)
    }
}

impl fmt::Display for EntityType {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

impl EntityKind {
    /// The type without its data.
    #[must_use]
    pub fn entity_type(&self) -> EntityType {
        match self {
            EntityKind::PointIn3d { .. } => EntityType::PointIn3d,
            EntityKind::PointIn2d { .. } => EntityType::PointIn2d,
            EntityKind::PointNTrans { .. } => EntityType::PointNTrans,
            EntityKind::PointNRotTrans { .. } => EntityType::PointNRotTrans,
            EntityKind::NormalNRot { .. } => EntityType::NormalNRot,
            EntityKind::NormalIn3d { .. } => EntityType::NormalIn3d,
            EntityKind::NormalIn2d => EntityType::NormalIn2d,
            EntityKind::Distance { .. } => EntityType::Distance,
            EntityKind::Workplane { .. } => EntityType::Workplane,
            EntityKind::LineSegment { .. } => EntityType::LineSegment,
            EntityKind::Cubic { .. } => EntityType::Cubic,
            EntityKind::Circle { .. } => EntityType::Circle,
            EntityKind::ArcOfCircle { .. } => EntityType::ArcOfCircle,
        }
    }

    /// The parameters this entity holds directly.
    #[must_use]
    pub fn params(&self) -> &[ParamId] {
        match self {
            EntityKind::PointIn3d { params } => params,
            EntityKind::PointIn2d { params } => params,
            EntityKind::PointNTrans { params, .. } => params,
            EntityKind::PointNRotTrans { params, .. } => params,
            EntityKind::NormalIn3d { params } => params,
            EntityKind::NormalNRot { params, .. } => params,
            EntityKind::Distance { param } => std::slice::from_ref(param),
            _ => &[],
        }
    }

    /// Parameters this entity reads besides its own: a moved point's translation.
    #[must_use]
    pub fn read_params(&self) -> &[ParamId] {
        match self {
            EntityKind::PointNTrans { translation, .. }
            | EntityKind::PointNRotTrans { translation, .. } => translation,
            _ => &[],
        }
    }

    /// The entities this entity refers to, with the name of each field.
    #[must_use]
    pub fn references(&self) -> Vec<(&'static str, EntityId)> {
        match self {
            EntityKind::PointNTrans { base, .. } => vec![("base", *base)],
            EntityKind::PointNRotTrans { rotation, .. }
            | EntityKind::NormalNRot { rotation, .. } => {
                vec![("rotation", *rotation)]
            }
            EntityKind::Workplane { origin, normal } => {
                vec![("origin", *origin), ("normal", *normal)]
            }
            EntityKind::LineSegment { points } => {
                vec![("points[0]", points[0]), ("points[1]", points[1])]
            }
            EntityKind::Cubic { points } => vec![
                ("points[0]", points[0]),
                ("points[1]", points[1]),
                ("points[2]", points[2]),
                ("points[3]", points[3]),
            ],
            EntityKind::Circle {
                center,
                normal,
                radius,
            } => {
                vec![
                    ("center", *center),
                    ("normal", *normal),
                    ("radius", *radius),
                ]
            }
            EntityKind::ArcOfCircle {
                normal,
                center,
                start,
                end,
            } => {
                vec![
                    ("normal", *normal),
                    ("center", *center),
                    ("start", *start),
                    ("end", *end),
                ]
            }
            _ => Vec::new(),
        }
    }
}

impl Entity {
    /// The type without its data.
    #[must_use]
    pub fn entity_type(&self) -> EntityType {
        self.kind.entity_type()
    }

    /// A 3D point.
    #[must_use]
    pub fn point_3d(h: u32, group: u32, params: [u32; 3]) -> Self {
        Self::plain(
            h,
            group,
            None,
            EntityKind::PointIn3d {
                params: params.map(ParamId),
            },
        )
    }

    /// A 3D point with coordinates `params`, held at `base + times * translation`.
    #[must_use]
    pub fn point_n_trans(
        h: u32,
        group: u32,
        params: [u32; 3],
        base: u32,
        translation: [u32; 3],
        times: i32,
    ) -> Self {
        Self::plain(
            h,
            group,
            None,
            EntityKind::PointNTrans {
                params: params.map(ParamId),
                base: EntityId(base),
                translation: translation.map(ParamId),
                times,
            },
        )
    }

    /// A 3D point with coordinates `params`, held at `translation + q base q*` where `q`
    /// is the quaternion of normal `rotation`.
    #[must_use]
    pub fn point_n_rot_trans(
        h: u32,
        group: u32,
        params: [u32; 3],
        base: [f64; 3],
        translation: [u32; 3],
        rotation: u32,
    ) -> Self {
        Self::plain(
            h,
            group,
            None,
            EntityKind::PointNRotTrans {
                params: params.map(ParamId),
                base,
                translation: translation.map(ParamId),
                rotation: EntityId(rotation),
            },
        )
    }

    /// A 3D normal with quaternion `params`, held at `q * base` where `q` is the quaternion
    /// of normal `rotation`.
    #[must_use]
    pub fn normal_n_rot(
        h: u32,
        group: u32,
        params: [u32; 4],
        base: [f64; 4],
        rotation: u32,
    ) -> Self {
        Self::plain(
            h,
            group,
            None,
            EntityKind::NormalNRot {
                params: params.map(ParamId),
                base,
                rotation: EntityId(rotation),
            },
        )
    }

    /// A point in workplane `wp`.
    #[must_use]
    pub fn point_2d(h: u32, group: u32, wp: u32, params: [u32; 2]) -> Self {
        Self::plain(
            h,
            group,
            Some(wp),
            EntityKind::PointIn2d {
                params: params.map(ParamId),
            },
        )
    }

    /// A 3D normal from quaternion parameters w, x, y, z.
    #[must_use]
    pub fn normal_3d(h: u32, group: u32, params: [u32; 4]) -> Self {
        Self::plain(
            h,
            group,
            None,
            EntityKind::NormalIn3d {
                params: params.map(ParamId),
            },
        )
    }

    /// The normal of workplane `wp`.
    #[must_use]
    pub fn normal_2d(h: u32, group: u32, wp: u32) -> Self {
        Self::plain(h, group, Some(wp), EntityKind::NormalIn2d)
    }

    /// A distance (radius) entity.
    #[must_use]
    pub fn distance(h: u32, group: u32, wp: Option<u32>, param: u32) -> Self {
        Self::plain(
            h,
            group,
            wp,
            EntityKind::Distance {
                param: ParamId(param),
            },
        )
    }

    /// A workplane from an origin point and a normal.
    #[must_use]
    pub fn workplane(h: u32, group: u32, origin: u32, normal: u32) -> Self {
        Self::plain(
            h,
            group,
            None,
            EntityKind::Workplane {
                origin: EntityId(origin),
                normal: EntityId(normal),
            },
        )
    }

    /// A line segment; `wp` is its workplane, or `None` in 3D.
    #[must_use]
    pub fn line(h: u32, group: u32, wp: Option<u32>, a: u32, b: u32) -> Self {
        Self::plain(
            h,
            group,
            wp,
            EntityKind::LineSegment {
                points: [EntityId(a), EntityId(b)],
            },
        )
    }

    /// A cubic Bezier segment.
    #[must_use]
    pub fn cubic(h: u32, group: u32, wp: Option<u32>, points: [u32; 4]) -> Self {
        Self::plain(
            h,
            group,
            wp,
            EntityKind::Cubic {
                points: points.map(EntityId),
            },
        )
    }

    /// A circle.
    #[must_use]
    pub fn circle(
        h: u32,
        group: u32,
        wp: Option<u32>,
        center: u32,
        normal: u32,
        radius: u32,
    ) -> Self {
        Self::plain(
            h,
            group,
            wp,
            EntityKind::Circle {
                center: EntityId(center),
                normal: EntityId(normal),
                radius: EntityId(radius),
            },
        )
    }

    /// An arc of a circle in workplane `wp`.
    #[must_use]
    pub fn arc(
        h: u32,
        group: u32,
        wp: u32,
        normal: u32,
        center: u32,
        start: u32,
        end: u32,
    ) -> Self {
        Self::plain(
            h,
            group,
            Some(wp),
            EntityKind::ArcOfCircle {
                normal: EntityId(normal),
                center: EntityId(center),
                start: EntityId(start),
                end: EntityId(end),
            },
        )
    }

    fn plain(h: u32, group: u32, wp: Option<u32>, kind: EntityKind) -> Self {
        Self {
            h: EntityId(h),
            group: GroupId(group),
            workplane: wp.map(EntityId),
            kind,
        }
    }
}
