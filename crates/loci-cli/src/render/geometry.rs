//! The geometry to draw: points, line segments, circles, arcs and cubics on the drawing
//! plane, each with its ink, and how each is written as SVG.

use super::style::{self, Ink};
use super::svg::{num, Svg};
use super::view::{workplane_frame, Projection, ToPixels, View, P2};
use super::RenderOptions;
use loci::format::slvs::FIXED_GROUP;
use loci::{Diagnosis, EntityId, EntityKind, EntityType, GroupId, Member};
use std::collections::BTreeSet;
use std::f64::consts::TAU;

/// A shape on the drawing plane.
#[derive(Clone, Debug, PartialEq)]
pub(crate) enum Shape {
    Point(P2),
    Segment(P2, P2),
    Circle {
        c: P2,
        r: f64,
    },
    /// Counter-clockwise (y up) from angle `a0` over `sweep` radians.
    Arc {
        c: P2,
        r: f64,
        a0: f64,
        sweep: f64,
    },
    /// A curve seen at a slant (a circle or an arc whose plane is not the drawing plane).
    Polyline(Vec<P2>),
    Cubic([P2; 4]),
}

/// One entity as drawn.
#[derive(Clone, Debug)]
pub(crate) struct Item {
    pub entity: EntityId,
    pub kind: EntityType,
    pub shape: Shape,
    pub ink: Ink,
    pub construction: bool,
}

impl Shape {
    /// Points (drawing plane) that bound the shape.
    pub(crate) fn extent(&self) -> Vec<P2> {
        match self {
            Shape::Point(p) => vec![*p],
            Shape::Segment(a, b) => vec![*a, *b],
            Shape::Circle { c, r } => vec![P2::new(c.x - r, c.y - r), P2::new(c.x + r, c.y + r)],
            Shape::Arc { c, r, a0, sweep } => {
                let n = 64;
                (0..=n)
                    .map(|i| {
                        let t = a0 + sweep * f64::from(i) / f64::from(n);
                        P2::new(c.x + r * t.cos(), c.y + r * t.sin())
                    })
                    .collect()
            }
            Shape::Polyline(p) => p.clone(),
            Shape::Cubic(p) => p.to_vec(),
        }
    }
}

impl Shape {
    /// Points along the shape (drawing plane), close enough that straight pieces between
    /// them follow it.
    pub(crate) fn samples(&self) -> Vec<P2> {
        match self {
            Shape::Circle { c, r } => (0..=64)
                .map(|i| {
                    let t = TAU * f64::from(i) / 64.0;
                    P2::new(c.x + r * t.cos(), c.y + r * t.sin())
                })
                .collect(),
            Shape::Cubic(p) => (0..=32)
                .map(|i| {
                    let t = f64::from(i) / 32.0;
                    let s = 1.0 - t;
                    p[0].scale(s * s * s)
                        .plus(p[1].scale(3.0 * s * s * t))
                        .plus(p[2].scale(3.0 * s * t * t))
                        .plus(p[3].scale(t * t * t))
                })
                .collect(),
            _ => self.extent(),
        }
    }
}

/// Which groups besides `group` are drawn (muted): those `opts` names, or by default every
/// group with a lower handle.
fn shows_earlier(opts: &RenderOptions, group: GroupId, g: GroupId) -> bool {
    match &opts.earlier {
        Some(set) => set.contains(&g),
        None => g < group,
    }
}

/// The entities to draw, in system order: those of `group` and of the earlier groups.
pub(crate) fn collect(
    view: &View<'_>,
    group: GroupId,
    diagnosis: Option<&Diagnosis>,
    opts: &RenderOptions,
) -> Vec<Item> {
    let conflicted: BTreeSet<EntityId> = diagnosis
        .into_iter()
        .flat_map(|d| &d.conflicting)
        .flat_map(|s| &s.members)
        .filter_map(|m| match m {
            Member::Entity(e) => Some(*e),
            Member::Constraint(_) => None,
        })
        .collect();
    let sys = view.sys;
    let shown = |g: GroupId| g == group || shows_earlier(opts, group, g);
    let moves = |h: EntityId| diagnosis.is_some_and(|d| d.freedom(h).is_some_and(|f| f.dof > 0));
    let mut items = Vec::new();
    for e in sys.entities() {
        let current = e.group == group;
        // The curves loci holds constant for a `.slvs` file's copies are drawn with the
        // points they join when those are all drawn: the copies this group or an earlier
        // one makes, not those of later groups.
        let copy_of: Option<Vec<GroupId>> =
            (e.group == FIXED_GROUP && !shown(e.group)).then(|| {
                e.kind
                    .references()
                    .iter()
                    .filter_map(|(_, h)| sys.entity(*h))
                    .filter(|r| r.entity_type().is_point())
                    .map(|r| r.group)
                    .collect()
            });
        let joins_current = match &copy_of {
            Some(groups) => {
                if groups.is_empty()
                    || !groups.iter().all(|g| shown(*g))
                    || groups.iter().all(|g| *g == FIXED_GROUP)
                {
                    continue;
                }
                groups.contains(&group)
            }
            None if !current && !shown(e.group) => continue,
            None => false,
        };
        let Some(shape) = shape(view, e.h) else {
            continue;
        };
        let ink = if joins_current {
            let points = e.kind.references();
            match diagnosis {
                None => Ink::Plain,
                Some(_) if points.iter().any(|(_, h)| moves(*h)) => Ink::Free,
                Some(_) => Ink::Fixed,
            }
        } else if !current {
            Ink::Earlier
        } else if conflicted.contains(&e.h) {
            Ink::Conflict
        } else {
            match diagnosis {
                None => Ink::Plain,
                Some(_) if moves(e.h) => Ink::Free,
                Some(_) => Ink::Fixed,
            }
        };
        items.push(Item {
            entity: e.h,
            kind: e.entity_type(),
            shape,
            ink,
            construction: opts.construction.contains(&e.h),
        });
    }
    items
}

/// The shape of entity `h`, or `None` for what is not drawn (normals, workplanes,
/// distances) or cannot be placed.
pub(crate) fn shape(view: &View<'_>, h: EntityId) -> Option<Shape> {
    let e = view.sys.entity(h)?;
    let t = e.entity_type();
    if t.is_point() {
        return view.point(h).map(Shape::Point);
    }
    match &e.kind {
        EntityKind::LineSegment { points } => Some(Shape::Segment(
            view.point(points[0])?,
            view.point(points[1])?,
        )),
        EntityKind::Cubic { points } => Some(Shape::Cubic([
            view.point(points[0])?,
            view.point(points[1])?,
            view.point(points[2])?,
            view.point(points[3])?,
        ])),
        EntityKind::Circle {
            center,
            normal,
            radius,
        } => {
            let r = view.distance(*radius)?.abs();
            let axes = view.normal_frame(*normal)?;
            if view.faces(axes.n) {
                Some(Shape::Circle {
                    c: view.point(*center)?,
                    r,
                })
            } else {
                let c = view.point3(*center)?;
                Some(Shape::Polyline(view.sample(c, r, &axes, 0.0, TAU)))
            }
        }
        EntityKind::ArcOfCircle {
            center, start, end, ..
        } => {
            let wp = e.workplane?;
            if view.projection == Projection::Workplane(wp) {
                let (c, s, f) = (view.point(*center)?, view.point(*start)?, view.point(*end)?);
                let (a0, sweep) = arc_angles(c, s, f);
                return Some(Shape::Arc {
                    c,
                    r: s.minus(c).norm(),
                    a0,
                    sweep,
                });
            }
            // In another plane: the arc's own coordinates there, sampled and projected.
            let frame = workplane_frame(view.sys, wp)?;
            let local = |p: EntityId| -> Option<P2> {
                let q = view.point3(p)?;
                let d = [
                    q[0] - frame.origin[0],
                    q[1] - frame.origin[1],
                    q[2] - frame.origin[2],
                ];
                let dot = |a: [f64; 3]| d[0] * a[0] + d[1] * a[1] + d[2] * a[2];
                Some(P2::new(dot(frame.u), dot(frame.v)))
            };
            let (c, s, f) = (local(*center)?, local(*start)?, local(*end)?);
            let (a0, sweep) = arc_angles(c, s, f);
            let c3 = view.point3(*center)?;
            Some(Shape::Polyline(view.sample(
                c3,
                s.minus(c).norm(),
                &frame,
                a0,
                sweep,
            )))
        }
        _ => None,
    }
}

/// The start angle and counter-clockwise sweep of the arc about `c` from `s` to `f`;
/// coincident ends make a full turn, as in the model.
pub(crate) fn arc_angles(c: P2, s: P2, f: P2) -> (f64, f64) {
    let a0 = (s.y - c.y).atan2(s.x - c.x);
    let a1 = (f.y - c.y).atan2(f.x - c.x);
    let mut sweep = (a1 - a0).rem_euclid(TAU);
    if sweep < 1e-9 {
        sweep = TAU;
    }
    (a0, sweep)
}

/// Writes the items: earlier groups' curves under the group's, then points on top of all
/// curves.
pub(crate) fn draw(svg: &mut Svg, items: &[Item], px: &ToPixels) {
    svg.open("id=\"geometry\"");
    for (points, earlier) in [(false, true), (false, false), (true, true), (true, false)] {
        for it in items {
            if matches!(it.shape, Shape::Point(_)) == points && (it.ink == Ink::Earlier) == earlier
            {
                draw_item(svg, it, px);
            }
        }
    }
    svg.close();
}

fn draw_item(svg: &mut Svg, it: &Item, px: &ToPixels) {
    let mut class = format!("entity {} {}", kind_class(it.kind), it.ink.class());
    if it.construction {
        class.push_str(" construction");
    }
    let head = format!("class=\"{class}\" data-entity=\"{}\"", it.entity.0);
    let stroke = style::stroke(it.ink, it.construction);
    let attrs = format!("{head} {stroke}");
    match &it.shape {
        Shape::Point(p) => {
            let r = if it.ink == Ink::Earlier { 2.5 } else { 3.0 };
            let fill = if it.construction {
                format!(
                    "fill=\"white\" stroke=\"{}\" stroke-width=\"1.2\"",
                    it.ink.colour()
                )
            } else {
                style::filled(it.ink)
            };
            svg.circle(px.px(*p), r, &format!("{head} {fill}"));
        }
        Shape::Segment(a, b) => svg.line(px.px(*a), px.px(*b), &attrs),
        Shape::Circle { c, r } => svg.circle(px.px(*c), r * px.scale, &attrs),
        Shape::Arc { c, r, a0, sweep } => {
            if *sweep >= TAU - 1e-9 {
                svg.circle(px.px(*c), r * px.scale, &attrs);
                return;
            }
            let at = |t: f64| px.px(P2::new(c.x + r * t.cos(), c.y + r * t.sin()));
            let (s, f) = (at(*a0), at(a0 + sweep));
            let rr = r * px.scale;
            // Counter-clockwise with y up is clockwise on screen: sweep flag 0.
            let d = format!(
                "M{} {} A{} {} 0 {} 0 {} {}",
                num(s.x),
                num(s.y),
                num(rr),
                num(rr),
                u8::from(*sweep > std::f64::consts::PI),
                num(f.x),
                num(f.y)
            );
            let extent: Vec<P2> = it.shape.extent().into_iter().map(|p| px.px(p)).collect();
            svg.path(&d, &extent, &attrs);
        }
        Shape::Polyline(pts) => {
            let pts: Vec<P2> = pts.iter().map(|p| px.px(*p)).collect();
            let d: Vec<String> = pts
                .iter()
                .enumerate()
                .map(|(i, p)| {
                    format!(
                        "{}{} {}",
                        if i == 0 { "M" } else { "L" },
                        num(p.x),
                        num(p.y)
                    )
                })
                .collect();
            svg.path(&d.join(" "), &pts, &attrs);
        }
        Shape::Cubic(p) => {
            let p = p.map(|q| px.px(q));
            let d = format!(
                "M{} {} C{} {} {} {} {} {}",
                num(p[0].x),
                num(p[0].y),
                num(p[1].x),
                num(p[1].y),
                num(p[2].x),
                num(p[2].y),
                num(p[3].x),
                num(p[3].y)
            );
            svg.path(&d, &p, &attrs);
            // The control polygon's handles, faint, as sketchers show them.
            let handle = format!(
                "class=\"handle\" fill=\"none\" stroke=\"{}\" stroke-width=\"0.8\" stroke-dasharray=\"{}\"",
                it.ink.colour(),
                style::HELPER_DASH
            );
            svg.line(p[0], p[1], &handle);
            svg.line(p[3], p[2], &handle);
        }
    }
}

/// The word for an entity type in `class` attributes.
pub(crate) fn kind_class(t: EntityType) -> &'static str {
    match t {
        EntityType::LineSegment => "line",
        EntityType::Circle => "circle",
        EntityType::ArcOfCircle => "arc",
        EntityType::Cubic => "cubic",
        t if t.is_point() => "point",
        _ => "other",
    }
}
