//! SolveSpace's own type numbers, as its files store them. They differ from libslvs's
//! `SLVS_C_*` / `SLVS_E_*` numbers (which [`ConstraintKind::slvs_code`] gives).

use crate::model::ConstraintKind;

/// What a file constraint type becomes in loci.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum ConstraintCode {
    /// A constraint loci models.
    Kind(ConstraintKind),
    /// A comment: a label on the drawing, no equations.
    Comment,
}

/// The constraint type with file number `code`.
pub(crate) fn constraint(code: i64) -> Option<ConstraintCode> {
    use ConstraintKind as K;
    let k = match code {
        20 => K::PointsCoincident,
        30 => K::PtPtDistance,
        31 => K::PtPlaneDistance,
        32 => K::PtLineDistance,
        33 => K::PtFaceDistance,
        34 => K::ProjPtDistance,
        41 => K::PtInPlane,
        42 => K::PtOnLine,
        43 => K::PtOnFace,
        50 => K::EqualLengthLines,
        51 => K::LengthRatio,
        52 => K::EqLenPtLineD,
        53 => K::EqPtLnDistances,
        54 => K::EqualAngle,
        55 => K::EqualLineArcLen,
        56 => K::LengthDifference,
        60 => K::Symmetric,
        61 => K::SymmetricHoriz,
        62 => K::SymmetricVert,
        63 => K::SymmetricLine,
        70 => K::AtMidpoint,
        80 => K::Horizontal,
        81 => K::Vertical,
        90 => K::Diameter,
        100 => K::PtOnCircle,
        110 => K::SameOrientation,
        120 => K::Angle,
        121 => K::Parallel,
        122 => K::Perpendicular,
        123 => K::ArcLineTangent,
        124 => K::CubicLineTangent,
        125 => K::CurveCurveTangent,
        130 => K::EqualRadius,
        200 => K::WhereDragged,
        210 => K::ArcArcLenRatio,
        211 => K::ArcLineLenRatio,
        212 => K::ArcArcDifference,
        213 => K::ArcLineDifference,
        1000 => return Some(ConstraintCode::Comment),
        _ => return None,
    };
    Some(ConstraintCode::Kind(k))
}

/// Entity types of the file format.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum EntityCode {
    PointIn3d,
    PointIn2d,
    /// A point a group computes from another (translated, rotated, copied): its value is
    /// known, not solved, once its group is solved.
    PointCopy,
    NormalIn3d,
    NormalIn2d,
    /// A normal a group computes from another.
    NormalCopy,
    Distance,
    DistanceCopy,
    /// A face of a solid: a plane through a point.
    Face,
    Workplane,
    LineSegment,
    Cubic,
    CubicPeriodic,
    Circle,
    ArcOfCircle,
    TtfText,
    Image,
}

impl EntityCode {
    /// The entity type with file number `code`.
    pub(crate) fn from_code(code: i64) -> Option<Self> {
        use EntityCode as E;
        Some(match code {
            2000 => E::PointIn3d,
            2001 => E::PointIn2d,
            2010..=2013 => E::PointCopy,
            3000 => E::NormalIn3d,
            3001 => E::NormalIn2d,
            3010..=3012 => E::NormalCopy,
            4000 => E::Distance,
            4001 => E::DistanceCopy,
            5000..=5006 => E::Face,
            10000 => E::Workplane,
            11000 => E::LineSegment,
            12000 => E::Cubic,
            12001 => E::CubicPeriodic,
            13000 => E::Circle,
            14000 => E::ArcOfCircle,
            15000 => E::TtfText,
            16000 => E::Image,
            _ => return None,
        })
    }

    /// The SolveSpace name, for notes.
    pub(crate) fn name(self) -> &'static str {
        use EntityCode as E;
        match self {
            E::PointIn3d => "point in 3d",
            E::PointIn2d => "point in 2d",
            E::PointCopy => "copied point",
            E::NormalIn3d => "normal in 3d",
            E::NormalIn2d => "normal in 2d",
            E::NormalCopy => "copied normal",
            E::Distance => "distance",
            E::DistanceCopy => "copied distance",
            E::Face => "face",
            E::Workplane => "workplane",
            E::LineSegment => "line segment",
            E::Cubic => "cubic",
            E::CubicPeriodic => "periodic cubic spline",
            E::Circle => "circle",
            E::ArcOfCircle => "arc of circle",
            E::TtfText => "TrueType text",
            E::Image => "image",
        }
    }
}

/// Group types of the file format.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum GroupKind {
    /// A sketch in 3D (`DRAWING_3D`).
    Drawing3d,
    /// A sketch in a new workplane (`DRAWING_WORKPLANE`).
    DrawingWorkplane,
    /// An extrusion of a sketch.
    Extrude,
    /// A lathe (solid of revolution, full turn).
    Lathe,
    /// A revolution by an angle.
    Revolve,
    /// A helix.
    Helix,
    /// Step and repeat by rotation.
    Rotate,
    /// Step and repeat by translation.
    Translate,
    /// A linked (imported) part.
    Linked,
    /// A type number loci does not know.
    Unknown(i64),
}

impl GroupKind {
    /// The group type with file number `code`.
    #[must_use]
    pub fn from_code(code: i64) -> Self {
        match code {
            5000 => GroupKind::Drawing3d,
            5001 => GroupKind::DrawingWorkplane,
            5100 => GroupKind::Extrude,
            5101 => GroupKind::Lathe,
            5102 => GroupKind::Revolve,
            5103 => GroupKind::Helix,
            5200 => GroupKind::Rotate,
            5201 => GroupKind::Translate,
            5300 => GroupKind::Linked,
            c => GroupKind::Unknown(c),
        }
    }

    /// The file number.
    #[must_use]
    pub fn code(self) -> i64 {
        match self {
            GroupKind::Drawing3d => 5000,
            GroupKind::DrawingWorkplane => 5001,
            GroupKind::Extrude => 5100,
            GroupKind::Lathe => 5101,
            GroupKind::Revolve => 5102,
            GroupKind::Helix => 5103,
            GroupKind::Rotate => 5200,
            GroupKind::Translate => 5201,
            GroupKind::Linked => 5300,
            GroupKind::Unknown(c) => c,
        }
    }

    /// A name for reports.
    #[must_use]
    pub fn name(self) -> String {
        match self {
            GroupKind::Drawing3d => "sketch in 3d".into(),
            GroupKind::DrawingWorkplane => "sketch in workplane".into(),
            GroupKind::Extrude => "extrude".into(),
            GroupKind::Lathe => "lathe".into(),
            GroupKind::Revolve => "revolve".into(),
            GroupKind::Helix => "helix".into(),
            GroupKind::Rotate => "step and repeat (rotate)".into(),
            GroupKind::Translate => "step and repeat (translate)".into(),
            GroupKind::Linked => "linked part".into(),
            GroupKind::Unknown(c) => format!("unknown group type {c}"),
        }
    }

    /// Whether this kind is a sketch. Of the others, which build solids from earlier
    /// groups, loci solves extrusions and step and repeat by translation; the rest's
    /// generated geometry is read from the file as constants.
    #[must_use]
    pub fn is_sketch(self) -> bool {
        matches!(self, GroupKind::Drawing3d | GroupKind::DrawingWorkplane)
    }
}
