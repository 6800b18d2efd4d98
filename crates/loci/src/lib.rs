//! # loci
//!
//! A geometric constraint solver for CAD. loci implements the SolveSpace solver model —
//! [`Param`]eters, [`Entity`]s and [`Constraint`]s in groups, addressed by handles — with a
//! sparse least-squares Newton solver that names what is redundant or in conflict.
//!
//! ```
//! use loci::{Constraint, ConstraintKind as K, Entity, Param, System};
//!
//! let mut sys = System::new();
//! // A workplane (the xy plane) in group 1: origin point and normal.
//! for (h, v) in [(1, 0.0), (2, 0.0), (3, 0.0), (4, 1.0), (5, 0.0), (6, 0.0), (7, 0.0)] {
//!     sys.add_param(Param::new(h, 1, v))?;
//! }
//! sys.add_entity(Entity::point_3d(101, 1, [1, 2, 3]))?;
//! sys.add_entity(Entity::normal_3d(102, 1, [4, 5, 6, 7]))?;
//! sys.add_entity(Entity::workplane(200, 1, 101, 102))?;
//! // Two points in group 2, 10 mm apart and horizontal.
//! for (h, v) in [(11, 1.0), (12, 2.0), (13, 9.0), (14, 3.0)] {
//!     sys.add_param(Param::new(h, 2, v))?;
//! }
//! sys.add_entity(Entity::point_2d(301, 2, 200, [11, 12]))?;
//! sys.add_entity(Entity::point_2d(302, 2, 200, [13, 14]))?;
//! sys.add_constraint(Constraint::new(1, 2, K::PtPtDistance).in_workplane(Some(200)).with_points(301, 302).with_val(10.0))?;
//! sys.add_constraint(Constraint::new(2, 2, K::Horizontal).in_workplane(Some(200)).with_points(301, 302))?;
//!
//! let report = sys.solve_group(2)?;
//! assert!(report.outcome.is_ok());
//! assert_eq!(report.dof, 2);
//! let (x1, x2) = (sys.value(11.into()).unwrap(), sys.value(13.into()).unwrap());
//! assert!(((x2 - x1).abs() - 10.0).abs() < 1e-9);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

pub mod assembly;
mod diagnose;
mod equations;
mod error;
pub mod format;
pub mod geom;
mod model;
mod par;
pub mod sketch;
mod solve;

pub use diagnose::{
    diagnose, minimal_groups, ConflictSet, Diagnosis, EntityFreedom, Measurement, Member, Motion,
    OverConstrained, RedundantSet,
};
pub use error::{ModelError, SolveError};
pub use model::{
    Constraint, ConstraintId, ConstraintKind, ConstraintMut, Entity, EntityId, EntityKind,
    EntityType, GroupId, ObjectId, Param, ParamId, PlaneRule, Signature, System, Want, FIELD_NAMES,
    MAX_MAGNITUDE,
};
pub use solve::{solve, Config, Outcome, Report, Solver};
