//! A 2D sketcher on the core solver: shapes with typed handles, user constraints as typed
//! calls, soft constraints that keep shapes while the user edits, and dragging.
//!
//! A [`Sketch`] owns a [`System`]: its workplane is fixed in [`Sketch::WORKPLANE_GROUP`], its
//! shapes are the unknowns of [`Sketch::SHAPE_GROUP`]. Coordinates live in the system's
//! parameter vector and every shape keeps the indexes of its parameters there, so after a
//! solve a shape reads its new coordinates by index, without a copy or a look-up by handle.
//! Every user constraint writes one or more core constraints (see
//! [`Sketch::core_constraints`]).
//!
//! ```
//! use loci::sketch::Sketch;
//!
//! let mut s = Sketch::new();
//! let a = s.add_point(0.0, 0.0)?;
//! let b = s.add_point(9.0, 1.0)?;
//! let l = s.add_line(a, b)?;
//! s.fix(a)?;
//! s.horizontal(l)?;
//! s.length(l, 10.0)?;
//! let report = s.solve()?;
//! assert!(report.outcome.is_ok());
//! let [p, q] = s.line(l);
//! assert!((q[0] - p[0] - 10.0).abs() < 1e-9 && (q[1] - p[1]).abs() < 1e-9);
//! # Ok::<(), loci::sketch::SketchError>(())
//! ```

mod bars;
mod calls;
mod conflict_check;
mod constraints;
mod drag;
mod error;
mod ids;
mod measure;
mod shapes;
mod sides;
mod soft;
mod spec;
mod write;

pub use calls::Round;
pub use drag::{Drag, DragStep};
pub use error::SketchError;
pub use ids::{
    ArcId, Axis, CircleId, CubicId, End, LineId, PointId, ShapeId, ShapeKind, SketchConstraintId,
};
pub use measure::Measured;
pub use shapes::{ArcGeometry, Removed};
pub use soft::{SketchReport, Soft};
pub use spec::Spec;

use crate::model::{ConstraintId, Entity, EntityId, GroupId, Param, ParamId, System};
use crate::solve::Config;
use std::collections::{BTreeMap, HashMap};

/// A 2D sketch: shapes, user constraints and the system they are written into.
#[derive(Debug, Clone)]
pub struct Sketch {
    sys: System,
    shapes: BTreeMap<EntityId, shapes::Shape>,
    constraints: BTreeMap<SketchConstraintId, constraints::Rec>,
    /// Which sketch constraint wrote each core constraint.
    owner: HashMap<ConstraintId, SketchConstraintId>,
    next_param: u32,
    next_entity: u32,
    next_core: u32,
    next_constraint: u32,
    /// The revision at which shapes' parameter indexes were last brought up to date.
    indexed_at: u64,
    cfg: Config,
}

/// Fixed entities of every sketch, in the workplane group.
const WORKPLANE: EntityId = EntityId(3);
const NORMAL_2D: EntityId = EntityId(4);
/// A constant line along +x, that arcs' start and end angles are measured from.
const X_AXIS: EntityId = EntityId(7);

impl Default for Sketch {
    fn default() -> Self {
        Self::new()
    }
}

impl Sketch {
    /// The group of the workplane (constants).
    pub const WORKPLANE_GROUP: GroupId = GroupId(1);
    /// The group of the shapes (the unknowns).
    pub const SHAPE_GROUP: GroupId = GroupId(2);

    /// An empty sketch in the xy plane.
    #[must_use]
    pub fn new() -> Self {
        let mut sys = System::new();
        let g = Self::WORKPLANE_GROUP.0;
        // Origin and normal (identity quaternion) in params 1..=7, then the two ends of the x axis.
        sys.add_xy_workplane(g, 1, [1, 2, WORKPLANE.0])
            .expect("fresh handles");
        for (h, v) in [(8, 0.0), (9, 0.0), (10, 1.0), (11, 0.0)] {
            sys.add_param(Param::new(h, g, v)).expect("fresh handle");
        }
        for e in [
            Entity::normal_2d(NORMAL_2D.0, g, WORKPLANE.0),
            Entity::point_2d(5, g, WORKPLANE.0, [8, 9]),
            Entity::point_2d(6, g, WORKPLANE.0, [10, 11]),
            Entity::line(X_AXIS.0, g, Some(WORKPLANE.0), 5, 6),
        ] {
            sys.add_entity(e).expect("fresh handle");
        }
        Self {
            indexed_at: sys.revision(),
            sys,
            shapes: BTreeMap::new(),
            constraints: BTreeMap::new(),
            owner: HashMap::new(),
            next_param: 100,
            next_entity: 100,
            next_core: 1,
            next_constraint: 1,
            cfg: Config::default(),
        }
    }

    /// The system the sketch writes: read-only, so that the sketch's bookkeeping stays true.
    #[must_use]
    pub fn system(&self) -> &System {
        &self.sys
    }

    /// The workplane every shape lies in.
    #[must_use]
    pub fn workplane(&self) -> EntityId {
        WORKPLANE
    }

    /// The solver settings used by [`Sketch::solve`] and drags.
    #[must_use]
    pub fn config(&self) -> &Config {
        &self.cfg
    }

    /// Replaces the solver settings.
    pub fn set_config(&mut self, cfg: Config) {
        self.cfg = cfg;
    }

    fn param(&mut self, v: f64) -> Result<ParamId, SketchError> {
        let h = self.next_param;
        self.next_param += 1;
        Ok(self.sys.add_param(Param::new(h, Self::SHAPE_GROUP.0, v))?)
    }

    fn entity_handle(&mut self) -> u32 {
        let h = self.next_entity;
        self.next_entity += 1;
        h
    }

    fn core_handle(&mut self) -> u32 {
        let h = self.next_core;
        self.next_core += 1;
        h
    }
}
