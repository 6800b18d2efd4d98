//! What a diagnosis reports: typed, serialisable, and readable through `Display`.

use super::motion::Motion;
use crate::model::{ConstraintId, ConstraintKind, EntityId, EntityType, GroupId, ParamId};
use crate::solve::Outcome;
use serde::{Deserialize, Serialize};
use std::fmt;

/// Who owns an equation: a constraint, or an entity's implicit condition (a unit quaternion,
/// the equal radii of an arc).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "snake_case", tag = "kind", content = "h")]
pub enum Member {
    /// A constraint.
    Constraint(ConstraintId),
    /// The implicit condition of an entity.
    Entity(EntityId),
}

impl Member {
    /// Order of reports: constraints before entities, the most recently added (highest
    /// handle) first.
    pub(crate) fn report_order(a: &Member, b: &Member) -> std::cmp::Ordering {
        let key = |m: &Member| match *m {
            Member::Constraint(c) => (0, u32::MAX - c.0),
            Member::Entity(e) => (1, u32::MAX - e.0),
        };
        key(a).cmp(&key(b))
    }
}

impl fmt::Display for Member {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Member::Constraint(c) => c.fmt(f),
            Member::Entity(e) => write!(f, "{e} (implicit condition)"),
        }
    }
}

/// Constraints that cannot all hold together, while removing any one of them lets the rest
/// hold (on their own: the set is checked as a small system).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct ConflictSet {
    /// The members, most recently added (highest handle) first.
    pub members: Vec<Member>,
    /// Whether the set was shown minimal: it fails on its own, and every set with one member
    /// less solves. False when that was not shown: a set read off the Jacobian where the
    /// diagnosis could not solve it alone, a set too large to shrink that fails whole, or one
    /// a part of which neither solved nor failed alone (its solves were still creeping when
    /// their iterations ran out), so the member it lacks was kept.
    pub verified: bool,
}

/// Constraints that hold but constrain nothing new: any one of `members` can be removed
/// without changing the solution, and `excess` of them in all.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct RedundantSet {
    /// The removable members, most recently added first.
    pub members: Vec<Member>,
    /// How many equations of the set are dependent: how many members could go.
    pub excess: usize,
    /// Constraints with several equations of which only some are dependent: involved, but
    /// removing one would also remove something that is needed.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub involved: Vec<Member>,
}

/// A part of the system with more equations than unknowns, found by counting alone
/// (before any numerics): some of its members are necessarily redundant or conflicting.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct OverConstrained {
    /// The constraints (and implicit conditions) whose equations form the block.
    pub members: Vec<Member>,
    /// Equations in the block.
    pub equations: usize,
    /// Unknowns they reach.
    pub unknowns: usize,
}

/// The value a reference (driven) constraint measures, with the meaning of its `val`
/// (a distance, an angle in degrees, a ratio ...).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Measurement {
    /// The reference constraint.
    pub constraint: ConstraintId,
    /// Its type.
    pub kind: ConstraintKind,
    /// What it measures at the solved (or, on failure, the starting) values.
    pub value: f64,
}

/// How an entity can still move.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct EntityFreedom {
    /// The entity.
    pub entity: EntityId,
    /// Its type.
    pub kind: EntityType,
    /// Independent motions left (0: fixed).
    pub dof: usize,
    /// The motions in words and directions.
    pub motions: Vec<Motion>,
    /// The unknown parameters the entity reads, the coordinates of `basis`.
    pub params: Vec<ParamId>,
    /// An orthonormal basis of its possible first-order motions, one vector per degree of
    /// freedom, over `params`.
    pub basis: Vec<Vec<f64>>,
    /// For each basis vector, the weights of the null-space sketch that realise it.
    #[serde(skip)]
    pub(crate) weights: Vec<Vec<f64>>,
}

impl fmt::Display for EntityFreedom {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{} {}: ", kind_word(self.kind), self.entity.0)?;
        if self.dof == 0 {
            return f.write_str("fixed");
        }
        for (i, m) in self.motions.iter().enumerate() {
            if i > 0 {
                f.write_str("; ")?;
            }
            m.fmt(f)?;
        }
        Ok(())
    }
}

/// The word for an entity type in sentences.
pub(crate) fn kind_word(t: EntityType) -> &'static str {
    match t {
        EntityType::PointIn3d
        | EntityType::PointIn2d
        | EntityType::PointNTrans
        | EntityType::PointNRotTrans => "point",
        EntityType::NormalIn3d | EntityType::NormalIn2d | EntityType::NormalNRot => "normal",
        EntityType::Distance => "distance",
        EntityType::Workplane => "workplane",
        EntityType::LineSegment => "line",
        EntityType::Cubic => "cubic",
        EntityType::Circle => "circle",
        EntityType::ArcOfCircle => "arc",
    }
}

/// A few vectors spanning (or, when the system has many degrees of freedom, sampling) the
/// null space of the Jacobian: enough for every entity's motions. Not serialised.
#[derive(Clone, Debug, Default, PartialEq)]
pub(crate) struct NullSketch {
    /// Per sample, one value per parameter of the system (zero for constants).
    pub vectors: Vec<Vec<f64>>,
    pub params: Vec<ParamId>,
}

/// Everything the diagnosis found about one group.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Diagnosis {
    /// The group.
    pub group: GroupId,
    /// How the solve ends. A solve that did not converge but stopped at a least-squares
    /// minimum whose equations provably conflict is reported as inconsistent.
    pub outcome: Outcome,
    /// Degrees of freedom: unknowns minus the rank of the equations.
    pub dof: usize,
    /// Unknowns (the group's parameters).
    pub unknowns: usize,
    /// Equations, with every equality between parameters counted as one.
    pub equations: usize,
    /// The rank of the equations where the solve ended.
    pub rank: usize,
    /// Newton iterations the solve took.
    pub iterations: usize,
    /// Largest residual left.
    pub residual: f64,
    /// Blocks with more equations than unknowns, found by counting before any numerics.
    pub structural: Vec<OverConstrained>,
    /// Minimal sets of constraints that cannot hold together, smallest first. A set that
    /// holds once the constraints shared by every set before it are left out is not listed:
    /// changing those ends it too.
    pub conflicting: Vec<ConflictSet>,
    /// Sets of constraints that hold but are not needed.
    pub redundant: Vec<RedundantSet>,
    /// When the solve did not converge and no conflict was found: the equations left unmet.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub unsatisfied: Vec<Member>,
    /// For every entity of the group with unknowns, how it can still move.
    pub freedoms: Vec<EntityFreedom>,
    /// Values measured by reference constraints.
    pub measurements: Vec<Measurement>,
    #[serde(skip)]
    pub(crate) sketch: NullSketch,
}

impl Diagnosis {
    /// Whether the group solves (possibly with redundant constraints) and nothing conflicts.
    #[must_use]
    pub fn is_ok(&self) -> bool {
        self.outcome.is_ok() && self.conflicting.is_empty()
    }

    /// The entities that can still move.
    pub fn free_entities(&self) -> impl Iterator<Item = &EntityFreedom> {
        self.freedoms.iter().filter(|f| f.dof > 0)
    }

    /// The freedom of entity `h`, if it has unknowns in this group.
    #[must_use]
    pub fn freedom(&self, h: EntityId) -> Option<&EntityFreedom> {
        self.freedoms.iter().find(|f| f.entity == h)
    }

    /// A displacement of the whole system that moves entity `h` along its `i`-th basis motion
    /// (with unit length over the entity's parameters) and keeps every equation satisfied to
    /// first order: the other parameters move along as they must. `None` for an unknown
    /// entity or motion, or for a diagnosis read back from JSON (the null space is not
    /// serialised).
    #[must_use]
    pub fn displacement(&self, h: EntityId, i: usize) -> Option<Vec<(ParamId, f64)>> {
        let w = self.freedom(h)?.weights.get(i)?;
        if self.sketch.vectors.len() != w.len() {
            return None;
        }
        let mut out: Vec<(ParamId, f64)> = self.sketch.params.iter().map(|&p| (p, 0.0)).collect();
        for (v, &a) in self.sketch.vectors.iter().zip(w) {
            for (o, &x) in out.iter_mut().zip(v) {
                o.1 += a * x;
            }
        }
        Some(out)
    }
}

impl fmt::Display for ConflictSet {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write_members(f, &self.members)
    }
}

impl fmt::Display for RedundantSet {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if self.members.is_empty() {
            write_members(f, &self.involved)?;
            return f.write_str(" are partly redundant");
        } else if self.members.len() == 1 {
            write!(f, "{} is redundant", self.members[0])?;
        } else if self.excess == 1 {
            f.write_str("one of ")?;
            write_members(f, &self.members)?;
            f.write_str(" is redundant")?;
        } else {
            write!(f, "{} of ", self.excess)?;
            write_members(f, &self.members)?;
            f.write_str(" are redundant")?;
        }
        if !self.involved.is_empty() {
            f.write_str(" (also involved: ")?;
            write_members(f, &self.involved)?;
            f.write_str(")")?;
        }
        Ok(())
    }
}

fn write_members(f: &mut fmt::Formatter<'_>, m: &[Member]) -> fmt::Result {
    f.write_str("{")?;
    for (i, x) in m.iter().enumerate() {
        if i > 0 {
            f.write_str(", ")?;
        }
        fmt::Display::fmt(x, f)?;
    }
    f.write_str("}")
}
