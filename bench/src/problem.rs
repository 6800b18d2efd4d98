//! The neutral problem description every solver is translated from.
//!
//! A problem is a list of points (with the starting position every solver receives, and
//! whether the point is fixed), line segments and arcs between those points, a few
//! workplanes, and constraints written in the plainest geometric terms. Each constraint has
//! one meaning, the one the residual checker measures (see [`crate::check`]).

use serde::{Deserialize, Serialize};

/// Which benchmark family a problem belongs to.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Family {
    /// A chain of line segments: coincident joints, fixed lengths, fixed angles between
    /// neighbours, first point fixed.
    Chain,
    /// Independent triangles, each fully constrained.
    Triangles,
    /// A grid of squares sharing their corners: horizontals, verticals, and lengths along two
    /// edges.
    Grid,
    /// A 2D mechanism: a chain of lines joined by tangent arcs (fillets).
    Fillets,
    /// Line segments in space: lengths, angles between neighbours, points in a few
    /// workplanes.
    Chain3d,
    /// A square lattice of shared points with a distance on every bar: one large component
    /// whose graph is two-dimensional.
    Truss,
    /// A triangulated planar mesh with a distance on every edge.
    Mesh,
    /// Closed profiles sharing edges, with slots of lines and tangent arcs inside them.
    Profiles,
}

impl Family {
    /// Every family, in report order.
    pub const ALL: [Family; 8] = [
        Family::Chain,
        Family::Triangles,
        Family::Grid,
        Family::Fillets,
        Family::Chain3d,
        Family::Truss,
        Family::Mesh,
        Family::Profiles,
    ];

    /// Whether the generator takes the side `n` of an `n x n` layout rather than a count.
    #[must_use]
    pub fn takes_side(self) -> bool {
        matches!(
            self,
            Family::Grid | Family::Truss | Family::Mesh | Family::Profiles
        )
    }

    /// The `snake_case` name.
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            Family::Chain => "chain",
            Family::Triangles => "triangles",
            Family::Grid => "grid",
            Family::Fillets => "fillets",
            Family::Chain3d => "chain_3d",
            Family::Truss => "truss",
            Family::Mesh => "mesh",
            Family::Profiles => "profiles",
        }
    }

    /// A sentence for the report.
    #[must_use]
    pub fn describe(self) -> &'static str {
        match self {
            Family::Chain => {
                "chain of N line segments: coincident joints, fixed lengths, fixed angles \
                 between neighbours, first point fixed (1 DOF left)"
            }
            Family::Triangles => {
                "N independent triangles of separate lines: coincident corners, three lengths, \
                 a horizontal base, one corner fixed (fully constrained)"
            }
            Family::Grid => {
                "grid of N = n x n squares sharing corners: every edge horizontal or vertical, \
                 lengths along the bottom row and left column, one corner fixed"
            }
            Family::Fillets => {
                "mechanism of N lines joined by tangent arcs (fillets): coincident ends, \
                 arc-line tangency at both ends of each arc, radii, lengths, angles between \
                 successive lines (1 DOF left)"
            }
            Family::Chain3d => {
                "chain of N line segments in space sharing end points: lengths, angles \
                 between neighbours, every other point in one of three workplanes, first point \
                 fixed (about N/2 DOF left)"
            }
            Family::Truss => {
                "truss of N = n x n shared points on a jittered square lattice: a distance on \
                 every horizontal and vertical bar, one diagonal bracing the first cell, one \
                 corner fixed (a mechanism with about 2n DOF left)"
            }
            Family::Mesh => {
                "triangulated mesh of N = n x n jittered points, each cell split by a random \
                 diagonal: a distance on every edge, one corner fixed. Rigid, and over-determined \
                 by one distance per interior point (a triangulation has 3N - 3 - B edges for \
                 2N - 3 degrees of freedom), so even the solvable variant holds about N \
                 consistent but implied distances"
            }
            Family::Profiles => {
                "sketch of N = n x n closed four-sided profiles on a jittered lattice, sharing \
                 their edges, dimensioned as a drafter dimensions bays: along the bottom and up \
                 every column each edge's length and its angle to the edge before it, the edges \
                 across implied, the first edge horizontal, one corner fixed; every third \
                 profile holds a slot (two lines and two arcs, tangent at all four joints, radii \
                 and one length given) placed by two distances and an angle (fully constrained)"
            }
        }
    }

    /// Whether the family lives in one plane (2D-only solvers can take it).
    #[must_use]
    pub fn is_2d(self) -> bool {
        self != Family::Chain3d
    }
}

/// A solvable problem, or one with an extra constraint that is implied by the others
/// (redundant) or contradicts them (inconsistent), for timing diagnosis.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Variant {
    /// Every constraint can hold and none is implied by the others.
    Solvable,
    /// One extra constraint, consistent but implied by the others.
    Redundant,
    /// One extra constraint that contradicts the others.
    Inconsistent,
}

impl Variant {
    /// Every variant.
    pub const ALL: [Variant; 3] = [Variant::Solvable, Variant::Redundant, Variant::Inconsistent];

    /// The `snake_case` name.
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            Variant::Solvable => "solvable",
            Variant::Redundant => "redundant",
            Variant::Inconsistent => "inconsistent",
        }
    }
}

/// A point: where solvers start, and whether it is fixed.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct Point {
    /// Starting coordinates (z is 0 in 2D problems).
    pub start: [f64; 3],
    /// A fixed point must not move.
    pub fixed: bool,
}

/// An arc, counter-clockwise from `start` to `end` about `center`; `start` and `end` are
/// equally far from `center` (an implicit condition every solver must keep).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub struct Arc {
    /// Centre point index.
    pub center: usize,
    /// Start point index.
    pub start: usize,
    /// End point index.
    pub end: usize,
}

/// A fixed plane: it passes through `origin` and its orientation is the unit quaternion
/// `quat` (w, x, y, z), whose third axis is the plane's normal.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct Plane {
    /// A point of the plane.
    pub origin: [f64; 3],
    /// Orientation as a unit quaternion w, x, y, z.
    pub quat: [f64; 4],
}

impl Plane {
    /// The unit normal: the quaternion's third axis.
    #[must_use]
    pub fn normal(&self) -> [f64; 3] {
        let [w, x, y, z] = self.quat;
        [
            2.0 * (w * y + x * z),
            2.0 * (y * z - w * x),
            w * w - x * x - y * y + z * z,
        ]
    }
}

/// A constraint, in neutral terms. Indices refer to [`Problem::points`], [`Problem::lines`],
/// [`Problem::arcs`] and [`Problem::planes`].
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(tag = "type", rename_all = "snake_case")]
pub enum Con {
    /// Two points are at the same place.
    Coincident {
        /// First point.
        a: usize,
        /// Second point.
        b: usize,
    },
    /// Two points are `d` apart.
    Distance {
        /// First point.
        a: usize,
        /// Second point.
        b: usize,
        /// The distance.
        d: f64,
    },
    /// The unsigned angle between the directions of two lines (first point to second) is
    /// `|deg|` degrees. In 2D the sign of `deg` tells which way the second line turns from
    /// the first in the intended solution (counter-clockwise positive); solvers whose angle is
    /// oriented receive the signed value.
    Angle {
        /// First line.
        l1: usize,
        /// Second line.
        l2: usize,
        /// The angle in degrees, signed in 2D.
        deg: f64,
    },
    /// A 2D line is parallel to the x axis.
    Horizontal {
        /// The line.
        l: usize,
    },
    /// A 2D line is parallel to the y axis.
    Vertical {
        /// The line.
        l: usize,
    },
    /// An arc's radius is `r`.
    ArcRadius {
        /// The arc.
        arc: usize,
        /// The radius.
        r: f64,
    },
    /// A line is tangent to an arc at the arc's start (or end): the line is perpendicular to
    /// the radius through that end point.
    Tangent {
        /// The arc.
        arc: usize,
        /// True: at the arc's end; false: at its start.
        at_end: bool,
        /// The line.
        l: usize,
    },
    /// A point lies in a plane.
    InPlane {
        /// The point.
        p: usize,
        /// The plane.
        plane: usize,
    },
}

/// One benchmark problem.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Problem {
    /// Which family.
    pub family: Family,
    /// Solvable, redundant or inconsistent.
    pub variant: Variant,
    /// The size N the family is measured by.
    pub size: usize,
    /// Whether the problem lives in the xy plane.
    pub planar: bool,
    /// Points with their starting positions.
    pub points: Vec<Point>,
    /// Line segments, as pairs of point indices.
    pub lines: Vec<[usize; 2]>,
    /// Arcs.
    pub arcs: Vec<Arc>,
    /// Fixed planes.
    pub planes: Vec<Plane>,
    /// Constraints.
    pub cons: Vec<Con>,
}

impl Problem {
    /// A short label such as `chain/1000` or `grid/redundant/100`.
    #[must_use]
    pub fn label(&self) -> String {
        match self.variant {
            Variant::Solvable => format!("{}/{}", self.family.name(), self.size),
            v => format!("{}/{}/{}", self.family.name(), v.name(), self.size),
        }
    }
}
