//! Constraint glyphs: one SVG group per constraint, with its dimension (see
//! [`super::dimensions`]) or its marker (H, V, coincident, point-on, tangent, parallel,
//! perpendicular, equal, midpoint, symmetric, dragged), in red when it is in a conflict.

use super::dimensions::{angle, label, linear, point_line, radial};
use super::geometry::{shape, Shape};
use super::labels::Labels;
use super::style::{self, Ink, FONT, SMALL_FONT};
use super::svg::{value, Svg};
use super::view::{ToPixels, View, P2};
use loci::{Constraint, ConstraintId, ConstraintKind as K, EntityId, EntityKind};
use std::collections::BTreeMap;

/// A circle or an arc in pixels: centre, radius, and for an arc its start angle and sweep.
type Round = (P2, f64, Option<(f64, f64)>);

/// What glyphs need: where things are, in pixels, and the labels placed so far.
pub(crate) struct Ctx<'a, 'v> {
    pub view: &'a View<'v>,
    pub px: ToPixels,
    /// The middle of the geometry, in pixels: dimensions stand off away from it.
    pub centre: P2,
    pub labels: Labels,
    /// Values measured by reference constraints.
    pub measured: BTreeMap<ConstraintId, f64>,
}

impl Ctx<'_, '_> {
    fn pt(&self, h: Option<EntityId>) -> Option<P2> {
        self.view.point(h?).map(|p| self.px.px(p))
    }

    fn line(&self, h: Option<EntityId>) -> Option<(P2, P2)> {
        match &self.view.sys.entity(h?)?.kind {
            EntityKind::LineSegment { points } => {
                Some((self.pt(Some(points[0]))?, self.pt(Some(points[1]))?))
            }
            _ => None,
        }
    }

    /// A circle or arc: pixel centre, pixel radius, and for an arc its start angle and
    /// counter-clockwise sweep (y up).
    fn round(&self, h: Option<EntityId>) -> Option<Round> {
        let h = h?;
        let centre = match &self.view.sys.entity(h)?.kind {
            EntityKind::Circle { center, .. } | EntityKind::ArcOfCircle { center, .. } => *center,
            _ => return None,
        };
        let c = self.pt(Some(centre))?;
        match shape(self.view, h)? {
            Shape::Circle { r, .. } => Some((c, r * self.px.scale, None)),
            Shape::Arc { r, a0, sweep, .. } => Some((c, r * self.px.scale, Some((a0, sweep)))),
            Shape::Polyline(p) => {
                let r = p
                    .iter()
                    .map(|q| self.px.px(*q).minus(c).norm())
                    .fold(0.0, f64::max);
                Some((c, r, None))
            }
            _ => None,
        }
    }

    /// An end of a curve: an arc's start (or end with `other`), a cubic's first (or last)
    /// point; with the direction away from the curve there.
    fn curve_end(&self, h: Option<EntityId>, other: bool) -> Option<(P2, P2)> {
        match &self.view.sys.entity(h?)?.kind {
            EntityKind::ArcOfCircle {
                center, start, end, ..
            } => {
                let p = self.pt(Some(if other { *end } else { *start }))?;
                let c = self.pt(Some(*center))?;
                Some((p, p.minus(c).unit().unwrap_or(P2::new(0.0, -1.0))))
            }
            EntityKind::Cubic { points } => {
                let p = self.pt(Some(points[if other { 3 } else { 0 }]))?;
                let q = self.pt(Some(points[if other { 2 } else { 1 }]))?;
                let n = q.minus(p).unit().map_or(P2::new(0.0, -1.0), P2::perp);
                Some((p, self.outward(p, n)))
            }
            _ => None,
        }
    }

    /// A place on entity `h` for a marker, with the direction to set it off in: a line's
    /// middle (towards the drawing's middle, leaving the outside to dimensions), a
    /// circle's upper right, an arc's middle, a cubic's middle, a point itself.
    fn anchor(&self, h: Option<EntityId>) -> Option<(P2, P2)> {
        if let Some((a, b)) = self.line(h) {
            let n = b.minus(a).unit().map_or(P2::new(0.0, -1.0), P2::perp);
            return Some((a.mid(b), self.outward(a.mid(b), n).scale(-1.0)));
        }
        if let Some((c, r, arc)) = self.round(h) {
            // Off an arc's middle, where its radius is dimensioned.
            let t = arc.map_or(std::f64::consts::FRAC_PI_4, |(a0, s)| a0 + s * 0.3);
            let d = P2::new(t.cos(), -t.sin());
            return Some((c.plus(d.scale(r)), d));
        }
        match &self.view.sys.entity(h?)?.kind {
            EntityKind::Cubic { points } => {
                let p: Vec<P2> = points.iter().filter_map(|q| self.pt(Some(*q))).collect();
                if p.len() != 4 {
                    return None;
                }
                // The curve's point at t = 1/2.
                let m = p[0]
                    .plus(p[1].scale(3.0))
                    .plus(p[2].scale(3.0))
                    .plus(p[3])
                    .scale(0.125);
                Some((m, self.outward(m, P2::new(0.0, -1.0))))
            }
            _ => {
                let p = self.pt(h)?;
                Some((p, P2::new(0.0, -1.0)))
            }
        }
    }

    /// `n` or its opposite, whichever points away from the middle of the drawing at `at`.
    pub(crate) fn outward(&self, at: P2, n: P2) -> P2 {
        if at.minus(self.centre).dot(n) < 0.0 {
            n.scale(-1.0)
        } else {
            n
        }
    }
}

/// Writes the glyph of constraint `c` (nothing for constraints with no picture, such as
/// `same_orientation`).
pub(crate) fn draw(svg: &mut Svg, ctx: &mut Ctx<'_, '_>, c: &Constraint, conflict: bool) {
    let ink = if conflict { Ink::Conflict } else { Ink::Glyph };
    let mut g = svg.child();
    draw_kind(&mut g, ctx, c, ink);
    if g.body.is_empty() {
        return;
    }
    let mut class = format!("constraint {}", c.kind.name());
    if conflict {
        class.push_str(" conflict");
    }
    if c.reference {
        class.push_str(" reference");
    }
    svg.open(&format!("class=\"{class}\" data-constraint=\"{}\"", c.h.0));
    svg.append(g);
    svg.close();
}

/// The value shown for a dimension: the measured one for a reference (in parentheses).
fn dim_text(ctx: &Ctx<'_, '_>, c: &Constraint, f: impl Fn(f64) -> String) -> String {
    if c.reference {
        let v = ctx.measured.get(&c.h).copied().unwrap_or(c.val);
        format!("({})", f(v))
    } else {
        f(c.val)
    }
}

fn draw_kind(svg: &mut Svg, ctx: &mut Ctx<'_, '_>, c: &Constraint, ink: Ink) {
    let thin = style::thin(ink);
    match c.kind {
        K::PtPtDistance | K::ProjPtDistance => {
            if let (Some(a), Some(b)) = (ctx.pt(c.pt_a), ctx.pt(c.pt_b)) {
                let t = dim_text(ctx, c, value);
                linear(svg, ctx, a, b, &t, ink);
            }
        }
        K::PtLineDistance => {
            if let (Some(p), Some(l)) = (ctx.pt(c.pt_a), ctx.line(c.entity_a)) {
                let t = dim_text(ctx, c, value);
                point_line(svg, ctx, p, l, &t, ink);
            }
        }
        K::PtPlaneDistance | K::PtFaceDistance => {
            if let Some(p) = ctx.pt(c.pt_a) {
                let t = dim_text(ctx, c, |v| format!("↥{}", value(v)));
                label(svg, ctx, p, P2::new(0.0, -1.0), &t, FONT, ink);
            }
        }
        K::Diameter => {
            if let Some((centre, r, arc)) = ctx.round(c.entity_a) {
                match arc {
                    None => {
                        let d = P2::new(
                            std::f64::consts::FRAC_1_SQRT_2,
                            -std::f64::consts::FRAC_1_SQRT_2,
                        );
                        let t = dim_text(ctx, c, |v| format!("⌀{}", value(v)));
                        radial(svg, ctx, (centre, r), d, true, &t, ink);
                    }
                    Some((a0, s)) => {
                        let m = a0 + s / 2.0;
                        let d = P2::new(m.cos(), -m.sin());
                        let t = dim_text(ctx, c, |v| format!("R{}", value(v / 2.0)));
                        radial(svg, ctx, (centre, r), d, false, &t, ink);
                    }
                }
            }
        }
        K::Angle => {
            if let (Some(a), Some(b)) = (ctx.line(c.entity_a), ctx.line(c.entity_b)) {
                let v = if c.reference {
                    ctx.measured.get(&c.h).copied().unwrap_or(c.val)
                } else {
                    c.val
                };
                // The arc spans the angle the label states: of the four pairs of rays, the
                // one that makes `v` (`other` only says which directions the lines have).
                let t = dim_text(ctx, c, |v| format!("{}°", value(v)));
                angle(svg, ctx, a, b, v, &t, ink);
            } else if let Some((p, d)) = ctx.anchor(c.entity_a) {
                let t = dim_text(ctx, c, |v| format!("∠{}°", value(v)));
                label(svg, ctx, p, d, &t, FONT, ink);
            }
        }
        K::Horizontal | K::Vertical => {
            let s = if c.kind == K::Horizontal { "H" } else { "V" };
            let at = match (ctx.line(c.entity_a), ctx.pt(c.pt_a), ctx.pt(c.pt_b)) {
                (Some(l), _, _) => Some(l),
                (None, Some(a), Some(b)) => {
                    svg.line(
                        a,
                        b,
                        &format!("{thin} stroke-dasharray=\"{}\"", style::HELPER_DASH),
                    );
                    Some((a, b))
                }
                _ => None,
            };
            if let Some((a, b)) = at {
                let n = b.minus(a).unit().map_or(P2::new(0.0, -1.0), P2::perp);
                let dir = ctx.outward(a.mid(b), n).scale(-1.0);
                marker(svg, ctx, a.mid(b), dir, s, ink);
            }
        }
        K::PointsCoincident => {
            if let Some(p) = ctx.pt(c.pt_a).or(ctx.pt(c.pt_b)) {
                mark(svg, p, Mark::Coincident, ink);
            }
        }
        K::PtOnLine | K::PtOnCircle | K::PtInPlane | K::PtOnFace => {
            if let Some(p) = ctx.pt(c.pt_a) {
                mark(svg, p, Mark::OnCurve, ink);
            }
        }
        K::AtMidpoint => {
            let at = ctx
                .pt(c.pt_a)
                .or_else(|| ctx.line(c.entity_a).map(|(a, b)| a.mid(b)));
            if let Some(p) = at {
                mark(svg, p, Mark::Midpoint, ink);
            }
        }
        K::WhereDragged => {
            if let Some(p) = ctx.pt(c.pt_a) {
                mark(svg, p, Mark::Dragged, ink);
            }
        }
        K::Parallel
        | K::Perpendicular
        | K::EqualLengthLines
        | K::EqualLineArcLen
        | K::EqualRadius => {
            let s = match c.kind {
                K::Parallel => "∥",
                K::Perpendicular => "⊥",
                _ => "=",
            };
            for h in [c.entity_a, c.entity_b] {
                if let Some((p, d)) = ctx.anchor(h) {
                    marker(svg, ctx, p, d, s, ink);
                }
            }
        }
        K::EqualAngle => {
            for h in [c.entity_a, c.entity_b, c.entity_c, c.entity_d] {
                if let Some((p, d)) = ctx.anchor(h) {
                    marker(svg, ctx, p, d, "=∠", ink);
                }
            }
        }
        K::ArcLineTangent | K::CubicLineTangent | K::CurveCurveTangent => {
            if let Some((p, d)) = ctx.curve_end(c.entity_a, c.other) {
                marker(svg, ctx, p.plus(d.scale(4.0)), d, "T", ink);
            }
        }
        K::SymmetricHoriz | K::SymmetricVert | K::SymmetricLine | K::Symmetric => {
            if let (Some(a), Some(b)) = (ctx.pt(c.pt_a), ctx.pt(c.pt_b)) {
                if let Some(u) = b.minus(a).unit() {
                    // Arrowheads at both points, pointing at the mirror between them.
                    let fill = style::filled(ink);
                    svg.polygon(&super::svg::arrowhead(a.plus(u.scale(14.0)), u, 8.0), &fill);
                    svg.polygon(
                        &super::svg::arrowhead(b.minus(u.scale(14.0)), u.scale(-1.0), 8.0),
                        &fill,
                    );
                }
            }
        }
        K::LengthRatio | K::ArcArcLenRatio | K::ArcLineLenRatio => {
            if let Some((p, d)) = ctx.anchor(c.entity_a) {
                let t = dim_text(ctx, c, |v| format!("ratio {}", value(v)));
                label(svg, ctx, p, d, &t, SMALL_FONT, ink);
            }
        }
        K::LengthDifference | K::ArcArcDifference | K::ArcLineDifference => {
            if let Some((p, d)) = ctx.anchor(c.entity_a) {
                let t = dim_text(ctx, c, |v| format!("Δ{}", value(v)));
                label(svg, ctx, p, d, &t, SMALL_FONT, ink);
            }
        }
        K::EqLenPtLineD | K::EqPtLnDistances => {
            for h in [c.entity_a, c.entity_b] {
                if let Some((p, d)) = ctx.anchor(h) {
                    marker(svg, ctx, p, d, "=d", ink);
                }
            }
        }
        K::SameOrientation => {}
    }
}

/// A short marker text beside `at`.
fn marker(svg: &mut Svg, ctx: &mut Ctx<'_, '_>, at: P2, dir: P2, s: &str, ink: Ink) {
    label(svg, ctx, at.plus(dir.scale(3.0)), dir, s, SMALL_FONT, ink);
}

/// The markers drawn on a point, which the legend explains.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub(crate) enum Mark {
    /// A ring: points coincident.
    Coincident,
    /// A square: a point on a line, circle, arc, plane or face.
    OnCurve,
    /// A diamond: a point at a line's midpoint.
    Midpoint,
    /// A ground triangle under the point: it stays where it is.
    Dragged,
}

impl Mark {
    /// The marker of constraint kind `k`, if it draws one.
    pub(crate) fn of(k: K) -> Option<Mark> {
        match k {
            K::PointsCoincident => Some(Mark::Coincident),
            K::PtOnLine | K::PtOnCircle | K::PtInPlane | K::PtOnFace => Some(Mark::OnCurve),
            K::AtMidpoint => Some(Mark::Midpoint),
            K::WhereDragged => Some(Mark::Dragged),
            _ => None,
        }
    }

    /// Words for the legend.
    pub(crate) fn describe(self) -> &'static str {
        match self {
            Mark::Coincident => "coincident",
            Mark::OnCurve => "point on",
            Mark::Midpoint => "midpoint",
            Mark::Dragged => "stays put",
        }
    }
}

/// Draws marker `m` on the point at `p` (pixels).
pub(crate) fn mark(svg: &mut Svg, p: P2, m: Mark, ink: Ink) {
    let outline = format!(
        "fill=\"none\" stroke=\"{}\" stroke-width=\"1.3\"",
        ink.colour()
    );
    match m {
        Mark::Coincident => svg.circle(p, 6.0, &outline),
        Mark::OnCurve => {
            let s = 5.0;
            svg.polygon(
                &[
                    P2::new(p.x - s, p.y - s),
                    P2::new(p.x + s, p.y - s),
                    P2::new(p.x + s, p.y + s),
                    P2::new(p.x - s, p.y + s),
                ],
                &outline,
            );
        }
        Mark::Midpoint => {
            let s = 6.5;
            svg.polygon(
                &[
                    P2::new(p.x, p.y - s),
                    P2::new(p.x + s, p.y),
                    P2::new(p.x, p.y + s),
                    P2::new(p.x - s, p.y),
                ],
                &outline,
            );
        }
        Mark::Dragged => {
            let top = p.plus(P2::new(0.0, 4.0));
            svg.polygon(
                &[
                    top,
                    top.plus(P2::new(6.0, 8.0)),
                    top.plus(P2::new(-6.0, 8.0)),
                ],
                &style::filled(ink),
            );
        }
    }
}
