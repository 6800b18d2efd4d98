//! An assembly as an SVG picture: an isometric wireframe of every component's frame and
//! references at its pose.

use loci::assembly::{Assembly, Pose, Reference};
use std::fmt::Write as _;

type V3 = [f64; 3];

/// Isometric projection: x to the lower right, y to the lower left, z up (SVG y grows down).
fn project(p: V3) -> (f64, f64) {
    let c = 30f64.to_radians().cos();
    let s = 30f64.to_radians().sin();
    ((p[0] - p[1]) * c, (p[0] + p[1]) * s - p[2])
}

fn add(a: V3, b: V3) -> V3 {
    [a[0] + b[0], a[1] + b[1], a[2] + b[2]]
}

fn scale(a: V3, s: f64) -> V3 {
    [a[0] * s, a[1] * s, a[2] * s]
}

fn unit(a: V3) -> V3 {
    let n = (a[0] * a[0] + a[1] * a[1] + a[2] * a[2]).sqrt();
    if n > 0.0 {
        scale(a, 1.0 / n)
    } else {
        a
    }
}

fn cross(a: V3, b: V3) -> V3 {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

/// Two unit vectors spanning the plane normal to unit `n`.
fn basis(n: V3) -> (V3, V3) {
    let h = if n[2].abs() < 0.9 {
        [0.0, 0.0, 1.0]
    } else {
        [0.0, 1.0, 0.0]
    };
    let u = unit(cross(n, h));
    (u, cross(n, u))
}

enum Shape {
    Line(V3, V3, &'static str, f64),
    Poly(Vec<V3>, &'static str),
    Dot(V3, &'static str),
    Text(V3, String),
}

/// The picture of `asm` at its current poses; `size` is a length in model units for frame
/// axes and reference glyphs (the drawing is scaled to fit).
pub fn assembly_svg(asm: &Assembly, size: f64) -> String {
    let mut shapes = Vec::new();
    let world = |name: &str, pose: &Pose, r: &Reference, shapes: &mut Vec<Shape>| {
        let p = pose.point(r.point());
        match r {
            Reference::Face { normal, .. } => {
                let n = unit(pose.direction(*normal));
                let (u, v) = basis(n);
                let h = size * 0.4;
                let corners = [(1.0, 1.0), (-1.0, 1.0), (-1.0, -1.0), (1.0, -1.0)]
                    .map(|(a, b)| add(p, add(scale(u, a * h), scale(v, b * h))));
                shapes.push(Shape::Poly(corners.to_vec(), "#6a8"));
                shapes.push(Shape::Line(p, add(p, scale(n, size * 0.4)), "#6a8", 1.0));
            }
            Reference::Edge { direction, .. } | Reference::Axis { direction, .. } => {
                let d = unit(pose.direction(*direction));
                let dash = matches!(r, Reference::Axis { .. });
                shapes.push(Shape::Line(
                    add(p, scale(d, -size * 0.6)),
                    add(p, scale(d, size * 0.6)),
                    if dash { "#a6a" } else { "#333" },
                    if dash { 0.8 } else { 1.5 },
                ));
            }
            Reference::CircularEdge { axis, radius, .. } => {
                let n = unit(pose.direction(*axis));
                let (u, v) = basis(n);
                let pts = (0..=32)
                    .map(|k| {
                        let t = k as f64 / 32.0 * std::f64::consts::TAU;
                        add(
                            p,
                            add(scale(u, radius * t.cos()), scale(v, radius * t.sin())),
                        )
                    })
                    .collect();
                shapes.push(Shape::Poly(pts, "#c70"));
            }
            Reference::Vertex { .. } => shapes.push(Shape::Dot(p, "#333")),
            Reference::Frame => {}
        }
        let _ = name;
    };
    for c in &asm.components {
        let o = c.pose.translation;
        for (axis, colour) in [
            ([1.0, 0.0, 0.0], "#d33"),
            ([0.0, 1.0, 0.0], "#3a3"),
            ([0.0, 0.0, 1.0], "#33d"),
        ] {
            shapes.push(Shape::Line(
                o,
                add(o, scale(c.pose.direction(axis), size)),
                colour,
                1.2,
            ));
        }
        shapes.push(Shape::Text(o, c.name.clone()));
        for (n, r) in &c.references {
            world(n, &c.pose, r, &mut shapes);
        }
    }
    for (n, r) in &asm.world {
        world(n, &Pose::IDENTITY, r, &mut shapes);
    }
    // Each mate as a thin line between the points of its two selections (both ends of a
    // coincidence meet, so only mates at a distance show).
    let at = |sel: &loci::assembly::Selection| -> Option<V3> {
        match &sel.component {
            Some(c) => {
                let c = asm.component(c)?;
                Some(c.pose.point(c.reference(&sel.reference)?.point()))
            }
            None => asm
                .world
                .iter()
                .find(|(n, _)| *n == sel.reference)
                .map(|(_, r)| r.point()),
        }
    };
    for m in &asm.mates {
        if let (Some(a), Some(b)) = (at(&m.a), at(&m.b)) {
            shapes.push(Shape::Line(a, b, "#999", 0.6));
        }
    }
    // Fit the drawing in 800 x 600 with a margin.
    let mut pts: Vec<(f64, f64)> = Vec::new();
    for s in &shapes {
        match s {
            Shape::Line(a, b, ..) => pts.extend([project(*a), project(*b)]),
            Shape::Poly(v, _) => pts.extend(v.iter().map(|p| project(*p))),
            Shape::Dot(p, _) | Shape::Text(p, _) => pts.push(project(*p)),
        }
    }
    let (mut x0, mut y0, mut x1, mut y1) = (
        f64::INFINITY,
        f64::INFINITY,
        f64::NEG_INFINITY,
        f64::NEG_INFINITY,
    );
    for (x, y) in &pts {
        x0 = x0.min(*x);
        y0 = y0.min(*y);
        x1 = x1.max(*x);
        y1 = y1.max(*y);
    }
    if !x0.is_finite() {
        (x0, y0, x1, y1) = (0.0, 0.0, 1.0, 1.0);
    }
    let (w, h) = (800.0, 600.0);
    let k = ((w - 80.0) / (x1 - x0).max(1e-9)).min((h - 80.0) / (y1 - y0).max(1e-9));
    let map = |p: V3| {
        let (x, y) = project(p);
        (40.0 + (x - x0) * k, 40.0 + (y - y0) * k)
    };
    let mut out = String::new();
    let _ = writeln!(
        out,
        r#"<svg xmlns="http://www.w3.org/2000/svg" width="{w}" height="{h}" viewBox="0 0 {w} {h}">"#
    );
    let _ = writeln!(out, r##"<rect width="100%" height="100%" fill="#fff"/>"##);
    for s in &shapes {
        match s {
            Shape::Line(a, b, colour, width) => {
                let ((ax, ay), (bx, by)) = (map(*a), map(*b));
                let _ = writeln!(
                    out,
                    r#"<line x1="{ax:.2}" y1="{ay:.2}" x2="{bx:.2}" y2="{by:.2}" stroke="{colour}" stroke-width="{width}"/>"#
                );
            }
            Shape::Poly(v, colour) => {
                let pts: Vec<String> = v
                    .iter()
                    .map(|p| {
                        let (x, y) = map(*p);
                        format!("{x:.2},{y:.2}")
                    })
                    .collect();
                let _ = writeln!(
                    out,
                    r#"<polygon points="{}" fill="none" stroke="{colour}" stroke-width="1"/>"#,
                    pts.join(" ")
                );
            }
            Shape::Dot(p, colour) => {
                let (x, y) = map(*p);
                let _ = writeln!(
                    out,
                    r#"<circle cx="{x:.2}" cy="{y:.2}" r="2.5" fill="{colour}"/>"#
                );
            }
            Shape::Text(p, t) => {
                let (x, y) = map(*p);
                let t = t
                    .replace('&', "&amp;")
                    .replace('<', "&lt;")
                    .replace('>', "&gt;");
                let _ = writeln!(
                    out,
                    r##"<text x="{:.2}" y="{:.2}" font-family="sans-serif" font-size="12" fill="#222">{t}</text>"##,
                    x + 4.0,
                    y - 4.0
                );
            }
        }
    }
    out.push_str("</svg>\n");
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use loci::assembly::Component;

    #[test]
    fn draws_frames_references_and_names() {
        let mut asm = Assembly::new();
        asm.add_component(
            Component::new("a<b", Pose::IDENTITY)
                .with(
                    "f",
                    Reference::Face {
                        point: [0.0; 3],
                        normal: [0.0, 0.0, 1.0],
                    },
                )
                .with(
                    "h",
                    Reference::CircularEdge {
                        center: [0.0; 3],
                        axis: [0.0, 0.0, 1.0],
                        radius: 1.0,
                    },
                )
                .with(
                    "v",
                    Reference::Vertex {
                        point: [1.0, 0.0, 0.0],
                    },
                ),
        )
        .unwrap();
        let svg = assembly_svg(&asm, 1.0);
        assert!(svg.starts_with("<svg") && svg.ends_with("</svg>\n"));
        assert_eq!(
            svg.matches("<line").count(),
            4,
            "three frame axes and the face's normal"
        );
        assert_eq!(svg.matches("<polygon").count(), 2);
        assert_eq!(svg.matches("<circle").count(), 1);
        assert!(svg.contains(">a&lt;b</text>"));
        assert!(!svg.contains("NaN"));
        assert_eq!(svg, assembly_svg(&asm, 1.0), "deterministic");
    }
}
