//! Constraints: geometric conditions on entities, in SolveSpace's uniform shape.

use super::{ConstraintId, EntityId, GroupId};
use serde::{Deserialize, Serialize};
use std::fmt;

/// A geometric condition. The fields mirror SolveSpace's: which of `pt_a`, `pt_b`,
/// `entity_a`..`entity_d`, `val`, `other` and `other2` matter depends on `kind`
/// (see [`ConstraintKind::signature`]).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Constraint {
    /// Unique non-zero handle.
    pub h: ConstraintId,
    /// The group this constraint belongs to.
    pub group: GroupId,
    /// What the constraint says.
    #[serde(rename = "type")]
    pub kind: ConstraintKind,
    /// The workplane it applies in (projected), or `None` for free in 3D.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub workplane: Option<EntityId>,
    /// The dimension: a distance, an angle in degrees, a ratio ...
    #[serde(default, skip_serializing_if = "is_zero")]
    pub val: f64,
    /// First point.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub pt_a: Option<EntityId>,
    /// Second point.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub pt_b: Option<EntityId>,
    /// First entity.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub entity_a: Option<EntityId>,
    /// Second entity.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub entity_b: Option<EntityId>,
    /// Third entity.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub entity_c: Option<EntityId>,
    /// Fourth entity.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub entity_d: Option<EntityId>,
    /// A flag whose meaning depends on the type (supplementary angle, other end of a curve).
    #[serde(default, skip_serializing_if = "is_false")]
    pub other: bool,
    /// A second flag (the other end of the second curve).
    #[serde(default, skip_serializing_if = "is_false")]
    pub other2: bool,
    /// A reference (driven) dimension: it only measures, and generates no equations.
    #[serde(default, skip_serializing_if = "is_false")]
    pub reference: bool,
    /// For an `angle` in a workplane: `val` is the signed angle from `entity_a` to
    /// `entity_b`, counter-clockwise positive, and the solve turns a line over to reach it.
    /// Without it (SolveSpace's angle) only the size of `val` counts and the angle keeps the
    /// turning sense it has where the solve starts. In space an angle has no sign.
    #[serde(default, skip_serializing_if = "is_false")]
    pub signed: bool,
}

fn is_zero(v: &f64) -> bool {
    *v == 0.0
}

fn is_false(v: &bool) -> bool {
    !*v
}

macro_rules! kinds {
    ($($(#[$doc:meta])* $variant:ident = $name:literal, $slvs:literal;)*) => {
        /// The 38 constraint types of SolveSpace's library.
        #[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash, Serialize, Deserialize)]
        #[serde(rename_all = "snake_case")]
        pub enum ConstraintKind {
            $($(#[$doc])* $variant,)*
        }

        impl ConstraintKind {
            /// Every constraint type, in SolveSpace's order.
            pub const ALL: &'static [ConstraintKind] = &[$(ConstraintKind::$variant,)*];

            /// The `snake_case` name used in files and messages.
            #[must_use]
            pub fn name(self) -> &'static str {
                match self { $(ConstraintKind::$variant => $name,)* }
            }

            /// The `SLVS_C_*` number of libslvs.
            #[must_use]
            pub fn slvs_code(self) -> u32 {
                match self { $(ConstraintKind::$variant => $slvs,)* }
            }

            /// The type with libslvs number `code`.
            #[must_use]
            pub fn from_slvs_code(code: u32) -> Option<Self> {
                match code { $($slvs => Some(ConstraintKind::$variant),)* _ => None }
            }

            /// The type named `name` (`snake_case`).
            #[must_use]
            pub fn from_name(name: &str) -> Option<Self> {
                match name { $($name => Some(ConstraintKind::$variant),)* _ => None }
            }
        }
    };
}

kinds! {
    /// `pt_a` and `pt_b` coincide.
    PointsCoincident = "points_coincident", 100000;
    /// Distance `pt_a`–`pt_b` is `val` (unsigned).
    PtPtDistance = "pt_pt_distance", 100001;
    /// Signed distance from `pt_a` to workplane `entity_a` is `val`.
    PtPlaneDistance = "pt_plane_distance", 100002;
    /// Distance from `pt_a` to line `entity_a` is `val`: unsigned in 3D; when projected,
    /// signed, positive to the right of the line's start→end (below a rightward line).
    PtLineDistance = "pt_line_distance", 100003;
    /// Signed distance from `pt_a` to the plane of face `entity_a` is `val`.
    PtFaceDistance = "pt_face_distance", 100004;
    /// `pt_a` lies in workplane `entity_a`.
    PtInPlane = "pt_in_plane", 100005;
    /// `pt_a` lies on line `entity_a`.
    PtOnLine = "pt_on_line", 100006;
    /// `pt_a` lies in the plane of face `entity_a`.
    PtOnFace = "pt_on_face", 100007;
    /// Lines `entity_a` and `entity_b` have equal length.
    EqualLengthLines = "equal_length_lines", 100008;
    /// Length of `entity_a` divided by length of `entity_b` is `val`.
    LengthRatio = "length_ratio", 100009;
    /// Length of line `entity_a` equals the distance from `pt_a` to line `entity_b`.
    EqLenPtLineD = "eq_len_pt_line_d", 100010;
    /// Distance `pt_a`–line `entity_a` equals distance `pt_b`–line `entity_b`.
    EqPtLnDistances = "eq_pt_ln_distances", 100011;
    /// Angle(`entity_a`, `entity_b`) equals angle(`entity_c`, `entity_d`); supplementary with `other`.
    /// Each may be a line or a normal (its axis).
    EqualAngle = "equal_angle", 100012;
    /// Length of line `entity_a` equals the length of arc `entity_b`.
    EqualLineArcLen = "equal_line_arc_len", 100013;
    /// `pt_a` and `pt_b` are symmetric about plane `entity_a`.
    Symmetric = "symmetric", 100014;
    /// `pt_a` and `pt_b` are symmetric about the workplane's vertical axis (side by side horizontally).
    SymmetricHoriz = "symmetric_horiz", 100015;
    /// `pt_a` and `pt_b` are symmetric about the workplane's horizontal axis (one above the other).
    SymmetricVert = "symmetric_vert", 100016;
    /// `pt_a` and `pt_b` are symmetric about line `entity_a`.
    SymmetricLine = "symmetric_line", 100017;
    /// `pt_a` lies at the midpoint of line `entity_a`; or, when `pt_a` is empty, the midpoint
    /// lies in workplane `entity_b`.
    AtMidpoint = "at_midpoint", 100018;
    /// Line `entity_a` (or `pt_a`–`pt_b`) is horizontal in the workplane.
    Horizontal = "horizontal", 100019;
    /// Line `entity_a` (or `pt_a`–`pt_b`) is vertical in the workplane.
    Vertical = "vertical", 100020;
    /// The diameter of circle or arc `entity_a` is `val`.
    Diameter = "diameter", 100021;
    /// `pt_a` lies on the cylinder of circle or arc `entity_a`.
    PtOnCircle = "pt_on_circle", 100022;
    /// Normals `entity_a` and `entity_b` are the same rotation.
    SameOrientation = "same_orientation", 100023;
    /// The angle between lines (or normals' axes) `entity_a` and `entity_b` is `val` degrees
    /// (`other`: cos = -cos(val)).
    Angle = "angle", 100024;
    /// Lines (or normals' axes) `entity_a` and `entity_b` are parallel.
    Parallel = "parallel", 100025;
    /// Lines (or normals' axes) `entity_a` and `entity_b` are perpendicular.
    Perpendicular = "perpendicular", 100026;
    /// Arc `entity_a` is tangent to line `entity_b` at its start (or end with `other`).
    ArcLineTangent = "arc_line_tangent", 100027;
    /// Cubic `entity_a` is tangent to line `entity_b` at its start (or end with `other`).
    CubicLineTangent = "cubic_line_tangent", 100028;
    /// Circles or arcs `entity_a` and `entity_b` have equal radius.
    EqualRadius = "equal_radius", 100029;
    /// The distance `pt_a`→`pt_b` projected onto line or normal `entity_a` is `val` (signed).
    ProjPtDistance = "proj_pt_distance", 100030;
    /// `pt_a` stays where it is.
    WhereDragged = "where_dragged", 100031;
    /// Curves (arcs or cubics) `entity_a` and `entity_b` are tangent at the ends chosen by `other`, `other2`.
    CurveCurveTangent = "curve_curve_tangent", 100032;
    /// Length of `entity_a` minus length of `entity_b` is `val`.
    LengthDifference = "length_difference", 100033;
    /// Length of arc `entity_a` divided by length of arc `entity_b` is `val`.
    ArcArcLenRatio = "arc_arc_len_ratio", 100034;
    /// Length of arc `entity_b` divided by length of line `entity_a` is `val` (SolveSpace's order:
    /// the line first).
    ArcLineLenRatio = "arc_line_len_ratio", 100035;
    /// Length of arc `entity_a` minus length of arc `entity_b` is `val`.
    ArcArcDifference = "arc_arc_difference", 100036;
    /// Length of arc `entity_b` minus length of line `entity_a` is `val` (the line first).
    ArcLineDifference = "arc_line_difference", 100037;
}

impl fmt::Display for ConstraintKind {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// What a constraint field must refer to.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Want {
    /// A point (2D or 3D).
    Point,
    /// A line segment.
    Line,
    /// A workplane (also stands for a face: its plane).
    Workplane,
    /// A normal (2D or 3D).
    Normal,
    /// A line segment or a normal (a direction).
    LineOrNormal,
    /// A circle or an arc.
    CircleOrArc,
    /// An arc.
    Arc,
    /// A cubic.
    Cubic,
    /// An arc or a cubic.
    Curve,
}

impl Want {
    /// Words for messages.
    #[must_use]
    pub fn describe(self) -> &'static str {
        match self {
            Want::Point => "a point",
            Want::Line => "a line segment",
            Want::Workplane => "a workplane",
            Want::Normal => "a normal",
            Want::LineOrNormal => "a line segment or a normal",
            Want::CircleOrArc => "a circle or an arc",
            Want::Arc => "an arc of circle",
            Want::Cubic => "a cubic",
            Want::Curve => "an arc or a cubic",
        }
    }

    /// Whether an entity of type `t` fits.
    #[must_use]
    pub fn accepts(self, t: super::EntityType) -> bool {
        use super::EntityType as T;
        match self {
            Want::Point => t.is_point(),
            Want::Line => t == T::LineSegment,
            Want::Workplane => t == T::Workplane,
            Want::Normal => t.is_normal(),
            Want::LineOrNormal => t == T::LineSegment || t.is_normal(),
            Want::CircleOrArc => matches!(t, T::Circle | T::ArcOfCircle),
            Want::Arc => t == T::ArcOfCircle,
            Want::Cubic => t == T::Cubic,
            Want::Curve => matches!(t, T::ArcOfCircle | T::Cubic),
        }
    }
}

/// How a constraint uses its `workplane` field.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum PlaneRule {
    /// Free in 3D or projected into a workplane (SolveSpace's `*`).
    Either,
    /// Must have a workplane (SolveSpace's `**`).
    Required,
    /// The workplane is ignored.
    Ignored,
}

/// Which fields a constraint type uses: `[pt_a, pt_b, entity_a, entity_b, entity_c, entity_d]`.
#[derive(Clone, Copy, Debug)]
pub struct Signature {
    /// What each of the six reference fields must be, or `None` when unused.
    pub fields: [Option<Want>; 6],
    /// The workplane rule.
    pub plane: PlaneRule,
}

/// The names of the six reference fields, in [`Signature::fields`] order.
pub const FIELD_NAMES: [&str; 6] = [
    "pt_a", "pt_b", "entity_a", "entity_b", "entity_c", "entity_d",
];

impl ConstraintKind {
    /// The fields this type needs and its workplane rule.
    ///
    /// `horizontal` and `vertical` take either a line (`entity_a`) or two points; their
    /// signature lists the line form and validation accepts the point form too.
    #[must_use]
    pub fn signature(self) -> Signature {
        use ConstraintKind as K;
        use PlaneRule::*;
        use Want::*;
        const N: Option<Want> = None;
        let p = Some(Point);
        let l = Some(Line);
        let d = Some(LineOrNormal);
        let (fields, plane) = match self {
            K::PointsCoincident | K::PtPtDistance => ([p, p, N, N, N, N], Either),
            K::PtPlaneDistance | K::PtInPlane | K::PtFaceDistance | K::PtOnFace => {
                ([p, N, Some(Workplane), N, N, N], Ignored)
            }
            K::PtLineDistance | K::PtOnLine | K::AtMidpoint => ([p, N, l, N, N, N], Either),
            K::EqualLengthLines | K::LengthRatio | K::LengthDifference => {
                ([N, N, l, l, N, N], Either)
            }
            // Directions: SolveSpace takes a normal's axis wherever it takes a line's.
            K::Parallel | K::Perpendicular | K::Angle => ([N, N, d, d, N, N], Either),
            K::EqLenPtLineD => ([p, N, l, l, N, N], Either),
            K::EqPtLnDistances => ([p, p, l, l, N, N], Either),
            K::EqualAngle => ([N, N, d, d, d, d], Either),
            K::EqualLineArcLen => ([N, N, l, Some(Arc), N, N], Either),
            K::Symmetric => ([p, p, Some(Workplane), N, N, N], Either),
            K::SymmetricHoriz | K::SymmetricVert => ([p, p, N, N, N, N], Required),
            K::SymmetricLine => ([p, p, l, N, N, N], Required),
            K::Horizontal | K::Vertical => ([N, N, l, N, N, N], Required),
            K::Diameter => ([N, N, Some(CircleOrArc), N, N, N], Ignored),
            K::PtOnCircle => ([p, N, Some(CircleOrArc), N, N, N], Ignored),
            K::SameOrientation => ([N, N, Some(Normal), Some(Normal), N, N], Ignored),
            K::ArcLineTangent => ([N, N, Some(Arc), l, N, N], Required),
            K::CubicLineTangent => ([N, N, Some(Cubic), l, N, N], Either),
            K::CurveCurveTangent => ([N, N, Some(Curve), Some(Curve), N, N], Required),
            K::EqualRadius => ([N, N, Some(CircleOrArc), Some(CircleOrArc), N, N], Ignored),
            K::ProjPtDistance => ([p, p, Some(LineOrNormal), N, N, N], Ignored),
            K::WhereDragged => ([p, N, N, N, N, N], Either),
            K::ArcArcLenRatio | K::ArcArcDifference => {
                ([N, N, Some(Arc), Some(Arc), N, N], Ignored)
            }
            K::ArcLineLenRatio | K::ArcLineDifference => ([N, N, l, Some(Arc), N, N], Either),
        };
        Signature { fields, plane }
    }

    /// Whether `val` is a dimension the user sets (and a reference constraint measures).
    #[must_use]
    pub fn has_value(self) -> bool {
        use ConstraintKind as K;
        matches!(
            self,
            K::PtPtDistance
                | K::PtPlaneDistance
                | K::PtLineDistance
                | K::PtFaceDistance
                | K::LengthRatio
                | K::LengthDifference
                | K::Diameter
                | K::Angle
                | K::ProjPtDistance
                | K::ArcArcLenRatio
                | K::ArcLineLenRatio
                | K::ArcArcDifference
                | K::ArcLineDifference
        )
    }
}

impl Constraint {
    /// A constraint of `kind` with every optional field empty; set the ones the kind needs.
    #[must_use]
    pub fn new(h: u32, group: u32, kind: ConstraintKind) -> Self {
        Self {
            h: ConstraintId(h),
            group: GroupId(group),
            kind,
            workplane: None,
            val: 0.0,
            pt_a: None,
            pt_b: None,
            entity_a: None,
            entity_b: None,
            entity_c: None,
            entity_d: None,
            other: false,
            other2: false,
            reference: false,
            signed: false,
        }
    }

    /// Sets the workplane (`None`: free in 3D).
    #[must_use]
    pub fn in_workplane(mut self, wp: Option<u32>) -> Self {
        self.workplane = wp.map(EntityId);
        self
    }

    /// Sets the value.
    #[must_use]
    pub fn with_val(mut self, val: f64) -> Self {
        self.val = val;
        self
    }

    /// Sets `pt_a` and `pt_b` (0 leaves one empty).
    #[must_use]
    pub fn with_points(mut self, a: u32, b: u32) -> Self {
        self.pt_a = nz(a);
        self.pt_b = nz(b);
        self
    }

    /// Sets `entity_a` .. `entity_d` (0 leaves one empty).
    #[must_use]
    pub fn with_entities(mut self, e: [u32; 4]) -> Self {
        self.entity_a = nz(e[0]);
        self.entity_b = nz(e[1]);
        self.entity_c = nz(e[2]);
        self.entity_d = nz(e[3]);
        self
    }

    /// Sets `other` and `other2`.
    #[must_use]
    pub fn with_flags(mut self, other: bool, other2: bool) -> Self {
        self.other = other;
        self.other2 = other2;
        self
    }

    /// Makes an angle signed: `val` counter-clockwise from `entity_a` to `entity_b` in the
    /// workplane, whichever way the lines turn at the start (see [`Constraint::signed`]).
    #[must_use]
    pub fn as_signed(mut self) -> Self {
        self.signed = true;
        self
    }

    /// Marks it a reference (driven) dimension.
    #[must_use]
    pub fn as_reference(mut self) -> Self {
        self.reference = true;
        self
    }

    /// What each of the six reference fields must be for this constraint, in [`FIELD_NAMES`]
    /// order, or `None` where the field is unused. This is [`ConstraintKind::signature`]
    /// adjusted for the alternative forms: `horizontal`/`vertical` on two points when
    /// `entity_a` is empty, and `at_midpoint` holding a line's midpoint on a plane
    /// (`entity_b`) when `pt_a` is empty. Validation checks exactly these fields and the
    /// solver reads only these.
    #[must_use]
    pub fn wants(&self) -> [Option<Want>; 6] {
        use ConstraintKind as K;
        if matches!(self.kind, K::Horizontal | K::Vertical) && self.entity_a.is_none() {
            return [Some(Want::Point), Some(Want::Point), None, None, None, None];
        }
        if self.kind == K::AtMidpoint && self.pt_a.is_none() && self.entity_b.is_some() {
            return [
                None,
                None,
                Some(Want::Line),
                Some(Want::Workplane),
                None,
                None,
            ];
        }
        self.kind.signature().fields
    }

    /// The six reference fields, in [`FIELD_NAMES`] order.
    #[must_use]
    pub fn fields(&self) -> [Option<EntityId>; 6] {
        [
            self.pt_a,
            self.pt_b,
            self.entity_a,
            self.entity_b,
            self.entity_c,
            self.entity_d,
        ]
    }
}

fn nz(h: u32) -> Option<EntityId> {
    (h != 0).then_some(EntityId(h))
}
