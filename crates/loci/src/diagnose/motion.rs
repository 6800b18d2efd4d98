//! The words for how an entity can still move.

use crate::model::EntityId;
use serde::{Deserialize, Serialize};
use std::fmt;

/// One way an entity can move while every equation keeps holding (to first order).
///
/// Directions of 2D points are `(u, v)` in their workplane; others are `(x, y, z)` in space.
/// Directions have unit length, with the first non-zero component positive.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(tag = "type", rename_all = "snake_case")]
pub enum Motion {
    /// A point can slide along a direction.
    Along {
        /// The direction.
        direction: Vec<f64>,
    },
    /// A 3D point can move within a plane.
    InPlane {
        /// The plane's normal.
        normal: [f64; 3],
    },
    /// A 2D point can move anywhere in its workplane.
    InItsPlane,
    /// A 3D point can move anywhere in space.
    InSpace,
    /// An orientation can turn about an axis.
    TurnAbout {
        /// The axis, in space.
        axis: [f64; 3],
    },
    /// An orientation can turn in `dof` independent ways (2, or 3 for any direction).
    Turn {
        /// Independent rotations.
        dof: usize,
    },
    /// A distance (a radius) can change.
    ValueFree,
    /// A line can turn about one of its end points.
    PivotAbout {
        /// `start` or `end`.
        end: String,
        /// That end point.
        point: EntityId,
    },
    /// A line can slide without turning or stretching.
    Slide {
        /// The direction.
        direction: Vec<f64>,
    },
    /// A line can change length, one end staying and the other sliding along the line.
    Stretch {
        /// The end that stays: `start` or `end`.
        end: String,
        /// That end point.
        point: EntityId,
    },
    /// Every motion the entity could have is free.
    Free,
    /// A part of a composite entity (a line's end, a circle's radius ...) can move.
    Part {
        /// The part's role: `start`, `end`, `centre`, `radius`, `normal`, `origin` ...
        role: String,
        /// The part.
        part: EntityId,
        /// How it can move.
        motion: Box<Motion>,
    },
    /// The entity's motions are coupled: it has only `dof` of them in all, fewer than its
    /// parts' motions listed beside this.
    Coupled {
        /// Independent motions of the entity.
        dof: usize,
    },
}

impl fmt::Display for Motion {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Motion::Along { direction } => {
                f.write_str("free to move along ")?;
                write_vec(f, direction)
            }
            Motion::InPlane { normal } => {
                f.write_str("free to move in the plane normal to ")?;
                write_vec(f, normal)
            }
            Motion::InItsPlane => f.write_str("free to move in its plane"),
            Motion::InSpace => f.write_str("free to move in space"),
            Motion::TurnAbout { axis } => {
                f.write_str("free to turn about ")?;
                write_vec(f, axis)
            }
            Motion::Turn { dof } if *dof >= 3 => f.write_str("free to turn in any direction"),
            Motion::Turn { dof } => write!(f, "free to turn in {dof} independent ways"),
            Motion::ValueFree => f.write_str("value free"),
            Motion::PivotAbout { end, point } => {
                write!(f, "free to rotate about its {end} ({point})")
            }
            Motion::Slide { direction } => {
                f.write_str("free to slide along ")?;
                write_vec(f, direction)
            }
            Motion::Stretch { end, point } => {
                write!(f, "length free, its {end} ({point}) staying")
            }
            Motion::Free => f.write_str("free"),
            Motion::Part { role, motion, .. } => match **motion {
                Motion::ValueFree | Motion::Free => write!(f, "{role} free"),
                ref m => write!(f, "{role} {m}"),
            },
            Motion::Coupled { dof: 1 } => f.write_str("1 degree of freedom in all"),
            Motion::Coupled { dof } => write!(f, "{dof} degrees of freedom in all"),
        }
    }
}

fn write_vec(f: &mut fmt::Formatter<'_>, v: &[f64]) -> fmt::Result {
    f.write_str("(")?;
    for (i, x) in v.iter().enumerate() {
        if i > 0 {
            f.write_str(", ")?;
        }
        // Rounding noise is not a direction.
        let x = if x.abs() < 5e-5 { 0.0 } else { *x };
        write!(f, "{}", (x * 1e4).round() / 1e4)?;
    }
    f.write_str(")")
}

/// `v` scaled to unit length with its first clearly non-zero component positive.
pub(crate) fn direction(v: &[f64]) -> Vec<f64> {
    let n = v.iter().map(|x| x * x).sum::<f64>().sqrt();
    if n == 0.0 {
        return v.to_vec();
    }
    let first = v
        .iter()
        .find(|x| x.abs() > 1e-9 * n)
        .copied()
        .unwrap_or(1.0);
    let s = if first < 0.0 { -1.0 / n } else { 1.0 / n };
    v.iter().map(|x| x * s).collect()
}

/// [`direction`] for three components.
pub(crate) fn direction3(v: [f64; 3]) -> [f64; 3] {
    let d = direction(&v);
    [d[0], d[1], d[2]]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sentences() {
        let m = Motion::Along {
            direction: direction(&[-3.0, -4.0]),
        };
        assert_eq!(m.to_string(), "free to move along (0.6, 0.8)");
        let r = Motion::Part {
            role: "radius".into(),
            part: EntityId(5),
            motion: Box::new(Motion::ValueFree),
        };
        assert_eq!(r.to_string(), "radius free");
        let p = Motion::PivotAbout {
            end: "start".into(),
            point: EntityId(301),
        };
        assert_eq!(p.to_string(), "free to rotate about its start (entity 301)");
    }
}
