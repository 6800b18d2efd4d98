//! Components: rigid bodies placed by a pose, carrying named references in their own frame.

use super::math::{self, Q4, V3};
use serde::{Deserialize, Serialize};

/// Where a component is: world = `translation + rotation · local`, with `rotation` a unit
/// quaternion `[w, x, y, z]`.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct Pose {
    /// The world position of the component frame's origin.
    pub translation: V3,
    /// The component frame's orientation, a unit quaternion `[w, x, y, z]`.
    pub rotation: Q4,
}

impl Default for Pose {
    fn default() -> Self {
        Self::IDENTITY
    }
}

impl Pose {
    /// The component frame on the world frame.
    pub const IDENTITY: Pose = Pose {
        translation: [0.0; 3],
        rotation: math::IDENTITY,
    };

    /// A pose from a translation and a rotation quaternion (normalised here).
    #[must_use]
    pub fn new(translation: V3, rotation: Q4) -> Self {
        Self {
            translation,
            rotation: math::qunit(rotation).unwrap_or(math::IDENTITY),
        }
    }

    /// A pose from a translation, a unit rotation axis and an angle in degrees.
    #[must_use]
    pub fn from_axis_angle(translation: V3, axis: V3, degrees: f64) -> Self {
        let axis = math::unit(axis).unwrap_or([0.0, 0.0, 1.0]);
        Self::new(translation, math::axis_angle(axis, degrees.to_radians()))
    }

    /// A local point in world coordinates.
    #[must_use]
    pub fn point(&self, p: V3) -> V3 {
        math::add(self.translation, math::rotate(self.rotation, p))
    }

    /// A local direction in world coordinates.
    #[must_use]
    pub fn direction(&self, d: V3) -> V3 {
        math::rotate(self.rotation, d)
    }

    /// A world point in this frame.
    #[must_use]
    pub fn to_local_point(&self, p: V3) -> V3 {
        math::rotate(math::qconj(self.rotation), math::sub(p, self.translation))
    }

    /// A world direction in this frame.
    #[must_use]
    pub fn to_local_direction(&self, d: V3) -> V3 {
        math::rotate(math::qconj(self.rotation), d)
    }

    /// Whether every number is finite and the rotation has unit length (within 1e-9).
    #[must_use]
    pub fn is_valid(&self) -> bool {
        let n: f64 = self.rotation.iter().map(|x| x * x).sum();
        self.translation
            .iter()
            .chain(&self.rotation)
            .all(|x| x.is_finite())
            && (n - 1.0).abs() < 1e-9
    }

    /// This pose turned by the world rotation `q` about the world point `pivot`.
    #[must_use]
    pub fn rotated_about(&self, q: Q4, pivot: V3) -> Pose {
        let t = math::add(pivot, math::rotate(q, math::sub(self.translation, pivot)));
        Pose::new(t, math::qmul(q, self.rotation))
    }
}

/// A piece of a component's geometry that mates select, in the component's own frame.
///
/// What each can stand for: a *point* (vertices, a face's or edge's point, a circular edge's
/// centre, the frame's origin), a *direction* (a face's normal, an edge's or axis's
/// direction, a circular edge's axis, the frame's z axis), a *plane* (a face, a circular
/// edge's plane, the frame's xy plane) and a *line* (an edge, an axis, a circular edge's
/// axis, the frame's z axis). A vertex is only a point.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(tag = "type", rename_all = "snake_case")]
pub enum Reference {
    /// A planar face: a point on it and its outward normal.
    Face {
        /// A point of the face.
        point: V3,
        /// The outward normal.
        normal: V3,
    },
    /// A straight edge: a point on it and its direction.
    Edge {
        /// A point of the edge.
        point: V3,
        /// Its direction.
        direction: V3,
    },
    /// A circular edge: its centre, the axis of its circle and its radius.
    CircularEdge {
        /// The circle's centre.
        center: V3,
        /// The axis, normal to the circle's plane.
        axis: V3,
        /// The radius.
        radius: f64,
    },
    /// A vertex.
    Vertex {
        /// Where it is.
        point: V3,
    },
    /// An axis (a datum line): a point on it and its direction.
    Axis {
        /// A point of the axis.
        point: V3,
        /// Its direction.
        direction: V3,
    },
    /// The component frame itself: its origin and its z axis; the whole frame for `fixed`.
    Frame,
}

impl Reference {
    /// The word for messages.
    #[must_use]
    pub fn kind_name(&self) -> &'static str {
        match self {
            Reference::Face { .. } => "face",
            Reference::Edge { .. } => "edge",
            Reference::CircularEdge { .. } => "circular edge",
            Reference::Vertex { .. } => "vertex",
            Reference::Axis { .. } => "axis",
            Reference::Frame => "frame",
        }
    }

    /// The point it stands for, in the component frame.
    #[must_use]
    pub fn point(&self) -> V3 {
        match *self {
            Reference::Face { point, .. }
            | Reference::Edge { point, .. }
            | Reference::Vertex { point }
            | Reference::Axis { point, .. } => point,
            Reference::CircularEdge { center, .. } => center,
            Reference::Frame => [0.0; 3],
        }
    }

    /// The unit direction it stands for, if it has one: a face's normal, an edge's or axis's
    /// direction, a circular edge's axis, the frame's z axis. `None` for a vertex or a
    /// zero vector.
    #[must_use]
    pub fn direction(&self) -> Option<V3> {
        match *self {
            Reference::Face { normal: d, .. }
            | Reference::Edge { direction: d, .. }
            | Reference::Axis { direction: d, .. }
            | Reference::CircularEdge { axis: d, .. } => math::unit(d),
            Reference::Frame => Some([0.0, 0.0, 1.0]),
            Reference::Vertex { .. } => None,
        }
    }

    /// What shape a mate takes it for: a face is a plane, a vertex (or the frame) a point,
    /// edges and axes lines.
    #[must_use]
    pub fn shape(&self) -> Shape {
        match self {
            Reference::Face { .. } => Shape::Plane,
            Reference::Edge { .. } | Reference::Axis { .. } | Reference::CircularEdge { .. } => {
                Shape::Line
            }
            Reference::Vertex { .. } | Reference::Frame => Shape::Point,
        }
    }

    /// Whether every number is finite.
    #[must_use]
    pub fn is_finite(&self) -> bool {
        let finite = |v: &[f64]| v.iter().all(|x| x.is_finite());
        finite(&self.point())
            && match *self {
                Reference::Face { normal: d, .. }
                | Reference::Edge { direction: d, .. }
                | Reference::Axis { direction: d, .. } => finite(&d),
                Reference::CircularEdge { axis, radius, .. } => finite(&axis) && radius.is_finite(),
                _ => true,
            }
    }
}

/// The shape a reference takes in a mate.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Shape {
    /// A point.
    Point,
    /// A line (point and direction).
    Line,
    /// A plane (point and normal).
    Plane,
}

/// A rigid body of the assembly.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Component {
    /// Its name, unique in the assembly.
    pub name: String,
    /// Where it is.
    #[serde(default)]
    pub pose: Pose,
    /// A grounded component never moves.
    #[serde(default)]
    pub grounded: bool,
    /// Its named references, in its own frame (the frame itself is always there as `frame`).
    /// In files, an object from name to reference, kept in file order.
    #[serde(default, with = "named")]
    pub references: Vec<(String, Reference)>,
}

impl Component {
    /// A free component at `pose`, with no references but its frame.
    #[must_use]
    pub fn new(name: impl Into<String>, pose: Pose) -> Self {
        Self {
            name: name.into(),
            pose,
            grounded: false,
            references: Vec::new(),
        }
    }

    /// Makes it grounded.
    #[must_use]
    pub fn grounded(mut self) -> Self {
        self.grounded = true;
        self
    }

    /// Adds a named reference.
    #[must_use]
    pub fn with(mut self, name: impl Into<String>, r: Reference) -> Self {
        self.references.push((name.into(), r));
        self
    }

    /// The reference named `name` (`frame` is the component frame).
    #[must_use]
    pub fn reference(&self, name: &str) -> Option<&Reference> {
        if name == "frame" {
            return Some(&Reference::Frame);
        }
        self.references
            .iter()
            .find(|(n, _)| n == name)
            .map(|(_, r)| r)
    }
}

/// A list of named references as a JSON object, in order.
pub(crate) mod named {
    use super::Reference;
    use serde::de::{MapAccess, Visitor};
    use serde::ser::SerializeMap;
    use serde::{Deserializer, Serializer};
    use std::fmt;

    pub fn serialize<S: Serializer>(v: &[(String, Reference)], s: S) -> Result<S::Ok, S::Error> {
        let mut m = s.serialize_map(Some(v.len()))?;
        for (k, r) in v {
            m.serialize_entry(k, r)?;
        }
        m.end()
    }

    pub fn deserialize<'de, D: Deserializer<'de>>(
        d: D,
    ) -> Result<Vec<(String, Reference)>, D::Error> {
        struct V;
        impl<'de> Visitor<'de> for V {
            type Value = Vec<(String, Reference)>;
            fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
                f.write_str("an object from reference name to reference")
            }
            fn visit_map<A: MapAccess<'de>>(self, mut a: A) -> Result<Self::Value, A::Error> {
                let mut out: Vec<(String, Reference)> = Vec::new();
                while let Some((k, r)) = a.next_entry::<String, Reference>()? {
                    if k == "frame" || out.iter().any(|(n, _)| *n == k) {
                        return Err(serde::de::Error::custom(format!(
                            "reference `{k}` is defined twice (`frame` is always the component frame)"
                        )));
                    }
                    out.push((k, r));
                }
                Ok(out)
            }
        }
        d.deserialize_map(V)
    }
}
