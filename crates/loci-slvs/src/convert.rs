//! From the C structs to a [`loci::System`], checking everything libslvs would trust blindly.

use crate::abi::*;
use loci::{Constraint, ConstraintKind, Entity, ModelError, ObjectId, Param, System};
use std::fmt;
use std::os::raw::c_int;

/// Why the C input is not a model loci can solve.
#[derive(Clone, Debug, PartialEq)]
pub enum InputError {
    /// `sys` itself is null.
    NullSystem,
    /// An array pointer is null while its count is not zero.
    NullArray {
        /// `param`, `entity`, `constraint`.
        array: &'static str,
        /// Its count.
        count: c_int,
    },
    /// An array pointer is not aligned for its element type.
    Misaligned {
        /// `param`, `entity`, `constraint`.
        array: &'static str,
    },
    /// A count is negative.
    NegativeCount {
        /// `params`, `entities`, `constraints`.
        count_field: &'static str,
        /// Its value.
        count: c_int,
    },
    /// An entity's `type` is not one of the `SLVS_E_*` numbers.
    UnknownEntityType {
        /// The entity.
        entity: Slvs_hEntity,
        /// Its type field.
        ty: c_int,
    },
    /// A constraint's `type` is not one of the `SLVS_C_*` numbers.
    UnknownConstraintType {
        /// The constraint.
        constraint: Slvs_hConstraint,
        /// Its type field.
        ty: c_int,
    },
    /// The model itself is wrong: a dangling or repeated handle, a NaN, a wrong entity type ...
    Model(ModelError),
    /// loci refused to start the solve for another reason (its message).
    Solve(String),
}

impl fmt::Display for InputError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            InputError::NullSystem => write!(f, "Slvs_Solve was given a null Slvs_System"),
            InputError::NullArray { array, count } => {
                write!(f, "sys->{array} is null but its count is {count}")
            }
            InputError::Misaligned { array } => {
                write!(f, "sys->{array} is not aligned for its element type")
            }
            InputError::NegativeCount { count_field, count } => {
                write!(
                    f,
                    "sys->{count_field} is {count}; a count cannot be negative"
                )
            }
            InputError::UnknownEntityType { entity, ty } => write!(
                f,
                "entity {entity}: type {ty} is not an SLVS_E_* entity type"
            ),
            InputError::UnknownConstraintType { constraint, ty } => write!(
                f,
                "constraint {constraint}: type {ty} is not an SLVS_C_* constraint type"
            ),
            InputError::Model(e) => e.fmt(f),
            InputError::Solve(msg) => f.write_str(msg),
        }
    }
}

impl InputError {
    /// The constraint to blame in `failed[]`, when the problem lies in one.
    #[must_use]
    pub fn culprit(&self) -> Option<Slvs_hConstraint> {
        match self {
            InputError::UnknownConstraintType { constraint, .. } => Some(*constraint),
            InputError::Model(e) => match e {
                ModelError::Dangling { owner, .. }
                | ModelError::WrongKind { owner, .. }
                | ModelError::MissingField { owner, .. }
                | ModelError::NonFinite { owner, .. }
                | ModelError::OutOfRange { owner, .. } => match owner {
                    ObjectId::Constraint(c) => Some(c.0),
                    _ => None,
                },
                ModelError::DuplicateHandle {
                    object: ObjectId::Constraint(c),
                } => Some(c.0),
                ModelError::NeedsWorkplane { constraint, .. } => Some(constraint.0),
                _ => None,
            },
            _ => None,
        }
    }
}

impl From<ModelError> for InputError {
    fn from(e: ModelError) -> Self {
        InputError::Model(e)
    }
}

/// `0` (libslvs's "none", and `SLVS_FREE_IN_3D` for a workplane) as `None`.
fn opt(h: u32) -> Option<u32> {
    (h != 0).then_some(h)
}

/// The loci entity for a C entity.
///
/// # Errors
/// An unknown type.
pub fn entity(e: &Slvs_Entity) -> Result<Entity, InputError> {
    let (h, g, wp) = (e.h, e.group, e.wrkpl);
    let [p0, p1, p2, p3] = e.param;
    let [a, b, c, d] = e.point;
    Ok(match e.r#type {
        SLVS_E_POINT_IN_3D => Entity::point_3d(h, g, [p0, p1, p2]),
        SLVS_E_POINT_IN_2D => Entity::point_2d(h, g, wp, [p0, p1]),
        SLVS_E_NORMAL_IN_3D => Entity::normal_3d(h, g, [p0, p1, p2, p3]),
        SLVS_E_NORMAL_IN_2D => Entity::normal_2d(h, g, wp),
        SLVS_E_DISTANCE => Entity::distance(h, g, opt(wp), p0),
        SLVS_E_WORKPLANE => Entity::workplane(h, g, a, e.normal),
        SLVS_E_LINE_SEGMENT => Entity::line(h, g, opt(wp), a, b),
        SLVS_E_CUBIC => Entity::cubic(h, g, opt(wp), [a, b, c, d]),
        SLVS_E_CIRCLE => Entity::circle(h, g, opt(wp), a, e.normal, e.distance),
        SLVS_E_ARC_OF_CIRCLE => Entity::arc(h, g, wp, e.normal, a, b, c),
        ty => return Err(InputError::UnknownEntityType { entity: h, ty }),
    })
}

/// The loci constraint for a C constraint. loci's equations follow libslvs's conventions (the side a
/// signed point-line distance takes, a line's direction from its second point to its first),
/// so values pass through unchanged.
///
/// # Errors
/// An unknown type.
pub fn constraint(c: &Slvs_Constraint) -> Result<Constraint, InputError> {
    let kind = u32::try_from(c.r#type)
        .ok()
        .and_then(ConstraintKind::from_slvs_code)
        .ok_or(InputError::UnknownConstraintType {
            constraint: c.h,
            ty: c.r#type,
        })?;
    Ok(Constraint::new(c.h, c.group, kind)
        .in_workplane(opt(c.wrkpl))
        .with_val(c.valA)
        .with_points(c.ptA, c.ptB)
        .with_entities([c.entityA, c.entityB, c.entityC, c.entityD])
        .with_flags(c.other != 0, c.other2 != 0))
}

/// A [`System`] holding the C arrays, in their order (so parameter `i` of the system is
/// `param[i]`), with every reference checked.
///
/// # Errors
/// The first unknown type, repeated or zero handle, non-finite value or bad reference.
pub fn system(
    params: &[Slvs_Param],
    entities: &[Slvs_Entity],
    constraints: &[Slvs_Constraint],
) -> Result<System, InputError> {
    let mut sys = System::new();
    for p in params {
        sys.add_param(Param::new(p.h, p.group, p.val))?;
    }
    for e in entities {
        sys.add_entity(entity(e)?)?;
    }
    for c in constraints {
        sys.add_constraint(constraint(c)?)?;
    }
    sys.validate()?;
    Ok(sys)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn blank_entity(h: u32, ty: c_int) -> Slvs_Entity {
        Slvs_Entity {
            h,
            group: 1,
            r#type: ty,
            wrkpl: 0,
            point: [0; 4],
            normal: 0,
            distance: 0,
            param: [0; 4],
        }
    }

    #[test]
    fn unknown_entity_type_is_named() {
        let err = entity(&blank_entity(7, 12345)).unwrap_err();
        assert_eq!(
            err,
            InputError::UnknownEntityType {
                entity: 7,
                ty: 12345
            }
        );
        assert_eq!(
            err.to_string(),
            "entity 7: type 12345 is not an SLVS_E_* entity type"
        );
        assert_eq!(err.culprit(), None);
    }

    #[test]
    fn dangling_constraint_reference_blames_the_constraint() {
        let params = [
            Slvs_Param {
                h: 1,
                group: 1,
                val: 0.0,
            },
            Slvs_Param {
                h: 2,
                group: 1,
                val: 0.0,
            },
            Slvs_Param {
                h: 3,
                group: 1,
                val: 0.0,
            },
        ];
        let mut p = blank_entity(10, SLVS_E_POINT_IN_3D);
        p.param = [1, 2, 3, 0];
        let c = Slvs_Constraint {
            h: 5,
            group: 1,
            r#type: 100000,
            wrkpl: 0,
            valA: 0.0,
            ptA: 10,
            ptB: 99,
            entityA: 0,
            entityB: 0,
            entityC: 0,
            entityD: 0,
            other: 0,
            other2: 0,
        };
        let err = system(&params, &[p], &[c]).unwrap_err();
        assert_eq!(err.culprit(), Some(5));
        assert!(err.to_string().contains("entity 99"), "{err}");
    }
}
