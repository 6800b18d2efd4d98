//! Writing a [`Sketch`] as a sketch file, with its current coordinates.

use super::{
    ArcData, CircleData, ConstraintData, CubicData, LineData, PointData, SketchData, SketchFile,
};
use crate::sketch::{ShapeId, ShapeKind, Sketch};

impl SketchFile {
    /// A file for `sketch` as it is now. `name` gives each shape its name (say, from
    /// [`super::LoadedSketch::shape_name`]); shapes it does not name are called by kind and
    /// handle (`point_105`). Constraints are written unnamed, in the order added.
    #[must_use]
    pub fn from_sketch(sketch: &Sketch, name: impl Fn(ShapeId) -> Option<String>) -> Self {
        let label = |s: ShapeId| {
            name(s).unwrap_or_else(|| {
                let k = sketch.kind(s).map_or("shape", ShapeKind::name);
                format!("{k}_{}", s.entity().0)
            })
        };
        let mut d = SketchData::default();
        for (s, kind) in sketch.shapes() {
            let construction = sketch.is_construction(s.entity());
            let n = label(s);
            match kind {
                ShapeKind::Point => {
                    let [x, y] = sketch.point(sketch.as_point(s).expect("a point"));
                    d.points.push(PointData {
                        name: n,
                        x,
                        y,
                        construction,
                    });
                }
                ShapeKind::Line => {
                    let [a, b] = sketch.line_points(sketch.as_line(s).expect("a line"));
                    d.lines.push(LineData {
                        name: n,
                        a: label(a.into()),
                        b: label(b.into()),
                        construction,
                    });
                }
                ShapeKind::Circle => {
                    let c = sketch.as_circle(s).expect("a circle");
                    d.circles.push(CircleData {
                        name: n,
                        center: label(sketch.circle_center(c).into()),
                        radius: sketch.circle(c).1,
                        construction,
                    });
                }
                ShapeKind::Arc => {
                    let [c, st, en] = sketch.arc_points(sketch.as_arc(s).expect("an arc"));
                    d.arcs.push(ArcData {
                        name: n,
                        center: label(c.into()),
                        start: label(st.into()),
                        end: label(en.into()),
                        construction,
                    });
                }
                ShapeKind::Cubic => {
                    let pts = sketch
                        .defining_points(s)
                        .into_iter()
                        .map(|p| label(p.into()));
                    let pts: Vec<String> = pts.collect();
                    d.cubics.push(CubicData {
                        name: n,
                        points: [
                            pts[0].clone(),
                            pts[1].clone(),
                            pts[2].clone(),
                            pts[3].clone(),
                        ],
                        construction,
                    });
                }
            }
        }
        for (id, spec) in sketch.constraints() {
            let reference = sketch.constraint(id).is_some_and(|(_, r)| r);
            let spec = spec
                .try_map::<String, ()>(|_, s| Ok(label(*s)))
                .expect("labels never fail");
            d.constraints.push(ConstraintData {
                name: None,
                spec,
                reference,
            });
        }
        SketchFile { sketch: d }
    }
}
