//! Mates and joints: what the user asks of two components, and how many degrees of freedom
//! each removes.

use super::math::{Q4, V3};
use serde::{Deserialize, Serialize};
use std::fmt;

/// A reference picked for a mate: `component` names a component of the assembly, or is
/// empty for a reference of the world (fixed in space, attached to no component).
#[derive(Clone, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub struct Selection {
    /// The component's name; `None` for a world reference.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub component: Option<String>,
    /// The reference's name (`frame` is the component frame).
    pub reference: String,
}

impl Selection {
    /// The reference `reference` of component `component`.
    #[must_use]
    pub fn on(component: &str, reference: &str) -> Self {
        Self {
            component: Some(component.into()),
            reference: reference.into(),
        }
    }

    /// The world reference `reference`.
    #[must_use]
    pub fn world(reference: &str) -> Self {
        Self {
            component: None,
            reference: reference.into(),
        }
    }
}

impl fmt::Display for Selection {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match &self.component {
            Some(c) => write!(f, "{c}.{}", self.reference),
            None => write!(f, "world.{}", self.reference),
        }
    }
}

/// What a mate asks. The shape each selection takes (point, line or plane) comes from its
/// reference: see [`super::Reference`]. "DOF removed" counts what the mate takes away from
/// the relative motion of two free components.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(tag = "type", rename_all = "snake_case")]
pub enum MateKind {
    /// B is held where it is relative to A (frames): removes 6.
    Fixed,
    /// Point–point: removes 3. Point–plane: 1. Point–line: 2. Plane–plane (coplanar, normals
    /// aligned, or opposed with `flip`): 3. Line–line (collinear): 4. Line–plane (the line
    /// in the plane): 2.
    Coincident,
    /// Point–point: removes 1. Point–plane (signed, along A's normal): 1. Plane–plane (kept
    /// parallel, B's plane at signed `value` along A's normal): 3. Line–line (kept parallel,
    /// `value` apart): 3. Point–line: 1.
    Distance {
        /// The distance.
        value: f64,
    },
    /// The directions are parallel, pointing the same way or, with `flip`, opposite: removes 2.
    Parallel,
    /// The directions are perpendicular: removes 1.
    Perpendicular,
    /// The signed angle from A's direction to B's, about an axis held in A's frame (taken
    /// from the directions when the mate is first solved), is `degrees`: removes 1. See
    /// [`super::angle`].
    Angle {
        /// The signed target in degrees, normalised to `[-360, 360]` and then to
        /// `(-180, 180]` as the seed does.
        degrees: f64,
    },
    /// Touch align: face–face coplanar with opposed normals (removes 3), edge–edge collinear
    /// (4), point–point coincident (3).
    TouchAlign,
    /// Concentric (axial): the axes of two lines, axes or circular edges are collinear:
    /// removes 4.
    Concentric,
    /// Joint: fastened, B rigidly held to A (frames): removes 6.
    Fastened,
    /// Joint: revolute about the two axes (lines), their points coincident: removes 5,
    /// leaving one rotation. `limits` bound the angle in degrees.
    Revolute,
    /// Joint: slider along the two axes, no turning about them: removes 5, leaving one
    /// translation. `limits` bound the travel of B's point along A's axis.
    Slider,
    /// Joint: cylindrical, the axes collinear: removes 4 (slide and turn).
    Cylindrical,
    /// Joint: ball, the two points coincident: removes 3.
    Ball,
    /// Joint: planar, the two faces coplanar (normals aligned, or opposed with `flip`):
    /// removes 3.
    Planar,
    /// Joint: pin in slot. A's line is the slot, B's line the pin: the pin's point stays on
    /// the slot line and the pin's axis normal to the slot (in the direction normal to the
    /// slot nearest the pin's when first solved): removes 4, leaving the slide along the slot
    /// and the turn about the pin.
    PinSlot,
}

impl MateKind {
    /// The prefix of ids the assembly gives mates of this kind (the seed's `ANGL`).
    #[must_use]
    pub fn id_prefix(&self) -> &'static str {
        match self {
            MateKind::Fixed => "FIXD",
            MateKind::Coincident => "COIN",
            MateKind::Distance { .. } => "DIST",
            MateKind::Parallel => "PARA",
            MateKind::Perpendicular => "PERP",
            MateKind::Angle { .. } => "ANGL",
            MateKind::TouchAlign => "TALN",
            MateKind::Concentric => "CONC",
            MateKind::Fastened => "FAST",
            MateKind::Revolute => "REVO",
            MateKind::Slider => "SLID",
            MateKind::Cylindrical => "CYLI",
            MateKind::Ball => "BALL",
            MateKind::Planar => "PLAN",
            MateKind::PinSlot => "PINS",
        }
    }

    /// The `snake_case` name.
    #[must_use]
    pub fn name(&self) -> &'static str {
        match self {
            MateKind::Fixed => "fixed",
            MateKind::Coincident => "coincident",
            MateKind::Distance { .. } => "distance",
            MateKind::Parallel => "parallel",
            MateKind::Perpendicular => "perpendicular",
            MateKind::Angle { .. } => "angle",
            MateKind::TouchAlign => "touch_align",
            MateKind::Concentric => "concentric",
            MateKind::Fastened => "fastened",
            MateKind::Revolute => "revolute",
            MateKind::Slider => "slider",
            MateKind::Cylindrical => "cylindrical",
            MateKind::Ball => "ball",
            MateKind::Planar => "planar",
            MateKind::PinSlot => "pin_slot",
        }
    }

    /// Whether this is a joint (a bundle of mates with a joint coordinate).
    #[must_use]
    pub fn is_joint(&self) -> bool {
        matches!(
            self,
            MateKind::Fastened
                | MateKind::Revolute
                | MateKind::Slider
                | MateKind::Cylindrical
                | MateKind::Ball
                | MateKind::Planar
                | MateKind::PinSlot
        )
    }
}

/// A mate between a reference of component A and one of component B.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Mate {
    /// Its id, unique in the assembly; given by the assembly (`ANGL3`) when empty.
    #[serde(default)]
    pub id: String,
    /// What it asks.
    #[serde(flatten)]
    pub kind: MateKind,
    /// The selection on A.
    pub a: Selection,
    /// The selection on B.
    pub b: Selection,
    /// Opposed directions instead of aligned ones (parallel, plane–plane coincident and
    /// distance, planar).
    #[serde(default, skip_serializing_if = "std::ops::Not::not")]
    pub flip: bool,
    /// Joint limits `[min, max]`: degrees for a revolute, distance for a slider. Reported
    /// when violated, not enforced.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub limits: Option<[f64; 2]>,
    /// What the mate keeps between solves (the seed's `persistentData`). A file keeps the
    /// directions and the relative pose the mate holds, so that a solved assembly read back
    /// solves where it is; the measurements are the report's.
    #[serde(default, skip_serializing_if = "Persistent::holds_nothing")]
    pub persistent: Persistent,
}

impl Mate {
    /// A mate of `kind` from `a` to `b`, with an id the assembly gives.
    #[must_use]
    pub fn new(kind: MateKind, a: Selection, b: Selection) -> Self {
        Self {
            id: String::new(),
            kind,
            a,
            b,
            flip: false,
            limits: None,
            persistent: Persistent::default(),
        }
    }

    /// Sets [`Mate::flip`].
    #[must_use]
    pub fn flipped(mut self, flip: bool) -> Self {
        self.flip = flip;
        self
    }

    /// Sets [`Mate::limits`].
    #[must_use]
    pub fn with_limits(mut self, min: f64, max: f64) -> Self {
        self.limits = Some([min, max]);
        self
    }

    /// Sets the id.
    #[must_use]
    pub fn with_id(mut self, id: &str) -> Self {
        self.id = id.into();
        self
    }
}

/// One rotation a stepped iteration applied to a component.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct AppliedRotation {
    /// The component turned.
    pub component: String,
    /// The world rotation applied, a unit quaternion `[w, x, y, z]`.
    pub quaternion: Q4,
}

/// What a mate keeps from one solve to the next.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct Persistent {
    /// Directions fixed when the mate was first solved, in the frames of its components: the
    /// angle mate's reference axis (in A's frame), a joint's zero direction (A's, then B's),
    /// the pin-slot's slot normal (A's).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub axis: Option<V3>,
    /// A second captured direction (a joint's zero direction in B's frame).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub axis_b: Option<V3>,
    /// For `fixed` and `fastened`: B's pose in A's frame when first solved.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub relative: Option<(V3, Q4)>,
    /// The last measured value: a distance, or an angle in radians for angles.
    #[serde(default, skip)]
    pub measured: Option<f64>,
    /// For angles and revolutes: the last measured signed angle in radians...
    #[serde(default, skip)]
    pub angle_rad: Option<f64>,
    /// ... and in degrees.
    #[serde(default, skip)]
    pub angle_deg: Option<f64>,
    /// Rotations applied by the last stepped iteration (the seed's `lastAppliedRotations`).
    #[serde(default, skip)]
    pub last_applied_rotations: Vec<AppliedRotation>,
}

impl Persistent {
    /// Whether nothing the mate holds has been captured yet (measurements aside).
    #[must_use]
    pub fn holds_nothing(&self) -> bool {
        self.axis.is_none() && self.axis_b.is_none() && self.relative.is_none()
    }
}
