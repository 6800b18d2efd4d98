//! Reading a sketch file into a [`Sketch`].

use super::{SketchData, SketchFile};
use crate::sketch::{ShapeId, Sketch, SketchConstraintId, SketchError};
use std::collections::BTreeMap;
use thiserror::Error;

/// A sketch file that cannot be read; each names the place at fault.
#[derive(Debug, Error)]
#[non_exhaustive]
pub enum SketchFileError {
    /// Not JSON, or not the shape of a sketch file.
    #[error("not a sketch file: {0}")]
    Json(String),
    /// Two shapes (or two constraints) share a name.
    #[error("the name {0:?} is given twice")]
    DuplicateName(String),
    /// A reference to a name that no shape has.
    #[error("{owner}: {field} names {name:?}, which no shape has")]
    UnknownName {
        /// The shape or constraint holding the reference.
        owner: String,
        /// The field.
        field: &'static str,
        /// The missing name.
        name: String,
    },
    /// The sketch refused a shape or constraint.
    #[error("{owner}: {source}")]
    Sketch {
        /// The shape or constraint.
        owner: String,
        /// Why.
        source: SketchError,
    },
}

/// A sketch read from a file, with its names.
#[derive(Clone, Debug)]
pub struct LoadedSketch {
    /// The sketch.
    pub sketch: Sketch,
    /// Each shape's name.
    pub shapes: BTreeMap<String, ShapeId>,
    /// Each constraint's name (its own, or `#i` for the i-th constraint of the file, from 1).
    pub constraints: BTreeMap<String, SketchConstraintId>,
}

impl LoadedSketch {
    /// The name of a shape.
    #[must_use]
    pub fn shape_name(&self, s: ShapeId) -> Option<&str> {
        self.shapes
            .iter()
            .find(|(_, v)| **v == s)
            .map(|(k, _)| k.as_str())
    }

    /// The name of a constraint.
    #[must_use]
    pub fn constraint_name(&self, c: SketchConstraintId) -> Option<&str> {
        self.constraints
            .iter()
            .find(|(_, v)| **v == c)
            .map(|(k, _)| k.as_str())
    }
}

impl SketchFile {
    /// Parses a sketch file.
    ///
    /// # Errors
    /// Text that is not JSON or not a sketch file.
    pub fn from_json(text: &str) -> Result<Self, SketchFileError> {
        serde_json::from_str(text).map_err(|e| SketchFileError::Json(e.to_string()))
    }

    /// The file as pretty JSON.
    #[must_use]
    pub fn to_json(&self) -> String {
        serde_json::to_string_pretty(self).expect("a sketch file serialises")
    }

    /// Builds the sketch: shapes in the file's order (points, lines, circles, arcs, cubics),
    /// then constraints.
    ///
    /// # Errors
    /// A repeated or unknown name, or a shape or constraint the sketch refuses.
    pub fn load(&self) -> Result<LoadedSketch, SketchFileError> {
        load(&self.sketch)
    }
}

fn load(d: &SketchData) -> Result<LoadedSketch, SketchFileError> {
    let mut s = Sketch::new();
    let mut names: BTreeMap<String, ShapeId> = BTreeMap::new();
    let sk = |owner: &str| {
        let owner = owner.to_string();
        move |source| SketchFileError::Sketch { owner, source }
    };
    let name = |n: &str, id: ShapeId, names: &mut BTreeMap<String, ShapeId>| {
        if names.insert(n.to_string(), id).is_some() {
            return Err(SketchFileError::DuplicateName(n.to_string()));
        }
        Ok(())
    };
    let look = |names: &BTreeMap<String, ShapeId>, owner: &str, field: &'static str, n: &str| {
        names
            .get(n)
            .copied()
            .ok_or_else(|| SketchFileError::UnknownName {
                owner: owner.to_string(),
                field,
                name: n.to_string(),
            })
    };
    let point = |s: &Sketch, names: &BTreeMap<String, ShapeId>, owner: &str, field, n: &str| {
        let id = look(names, owner, field, n)?;
        s.as_point(id).ok_or_else(|| SketchFileError::Sketch {
            owner: owner.to_string(),
            source: SketchError::WrongShape {
                constraint: "shape",
                field,
                shape: id,
                found: s.kind(id).expect("named shapes exist"),
                expected: "a point",
            },
        })
    };
    for p in &d.points {
        let id = s.add_point(p.x, p.y).map_err(sk(&p.name))?;
        s.set_construction(id, p.construction)
            .map_err(sk(&p.name))?;
        name(&p.name, id.into(), &mut names)?;
    }
    for l in &d.lines {
        let a = point(&s, &names, &l.name, "a", &l.a)?;
        let b = point(&s, &names, &l.name, "b", &l.b)?;
        let id = s.add_line(a, b).map_err(sk(&l.name))?;
        s.set_construction(id, l.construction)
            .map_err(sk(&l.name))?;
        name(&l.name, id.into(), &mut names)?;
    }
    for c in &d.circles {
        let ctr = point(&s, &names, &c.name, "center", &c.center)?;
        let id = s.add_circle(ctr, c.radius).map_err(sk(&c.name))?;
        s.set_construction(id, c.construction)
            .map_err(sk(&c.name))?;
        name(&c.name, id.into(), &mut names)?;
    }
    for a in &d.arcs {
        let ctr = point(&s, &names, &a.name, "center", &a.center)?;
        let st = point(&s, &names, &a.name, "start", &a.start)?;
        let en = point(&s, &names, &a.name, "end", &a.end)?;
        let id = s.add_arc(ctr, st, en).map_err(sk(&a.name))?;
        s.set_construction(id, a.construction)
            .map_err(sk(&a.name))?;
        name(&a.name, id.into(), &mut names)?;
    }
    for c in &d.cubics {
        let mut pts = Vec::new();
        for p in &c.points {
            pts.push(point(&s, &names, &c.name, "points", p)?);
        }
        let id = s
            .add_cubic([pts[0], pts[1], pts[2], pts[3]])
            .map_err(sk(&c.name))?;
        s.set_construction(id, c.construction)
            .map_err(sk(&c.name))?;
        name(&c.name, id.into(), &mut names)?;
    }
    let mut constraints = BTreeMap::new();
    for (i, c) in d.constraints.iter().enumerate() {
        let label = c.name.clone().unwrap_or_else(|| format!("#{}", i + 1));
        let owner = format!("constraint {label} ({})", c.spec.name());
        let spec = c.spec.try_map(|field, n| look(&names, &owner, field, n))?;
        let id = if c.reference {
            s.add_reference(spec)
        } else {
            s.add(spec)
        }
        .map_err(sk(&owner))?;
        if constraints.insert(label.clone(), id).is_some() {
            return Err(SketchFileError::DuplicateName(label));
        }
    }
    Ok(LoadedSketch {
        sketch: s,
        shapes: names,
        constraints,
    })
}
