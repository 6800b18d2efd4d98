//! Dimensions with values: linear distances with extension lines and arrows, point-to-line
//! distances, radii and diameters, angles with an arc and degrees.

use super::glyphs::Ctx;
use super::style::{self, Ink, ARROW, DIM_OFFSET, FONT, HELPER_DASH};
use super::svg::{arrowhead, num, text_size, Svg};
use super::view::P2;

/// Writes `s` beside `anchor` on the side `dir` (a unit vector), clear of other labels.
pub(crate) fn label(
    svg: &mut Svg,
    ctx: &mut Ctx<'_, '_>,
    anchor: P2,
    dir: P2,
    s: &str,
    font: f64,
    ink: Ink,
) {
    let (w, h) = text_size(s, font);
    // Half the label's extent along `dir`, so that its near edge sits a few pixels out.
    let half = dir.x.abs() * w / 2.0 + dir.y.abs() * h / 2.0;
    let want = anchor.plus(dir.scale(half + 3.0));
    let at = ctx.labels.place(want, dir, s, font);
    svg.text(at, s, font, &style::text(ink));
}

fn arrow(svg: &mut Svg, tip: P2, dir: P2, ink: Ink) {
    svg.polygon(&arrowhead(tip, dir, ARROW), &style::filled(ink));
}

/// A distance between pixel points `a` and `b`: extension lines, a dimension line standing
/// off the drawing's middle, arrows, and `text`.
pub(crate) fn linear(svg: &mut Svg, ctx: &mut Ctx<'_, '_>, a: P2, b: P2, text: &str, ink: Ink) {
    let Some(d) = b.minus(a).unit() else {
        label(svg, ctx, a, P2::new(0.0, -1.0), text, FONT, ink);
        return;
    };
    let n = ctx.outward(a.mid(b), d.perp());
    let off = DIM_OFFSET;
    let (a2, b2) = (a.plus(n.scale(off)), b.plus(n.scale(off)));
    let thin = style::thin(ink);
    svg.line(a.plus(n.scale(3.0)), a.plus(n.scale(off + 4.0)), &thin);
    svg.line(b.plus(n.scale(3.0)), b.plus(n.scale(off + 4.0)), &thin);
    if b.minus(a).norm() > 2.5 * ARROW {
        svg.line(a2, b2, &thin);
        arrow(svg, a2, d.scale(-1.0), ink);
        arrow(svg, b2, d, ink);
    } else {
        // Too short for arrows inside: they point in from outside.
        let ext = ARROW * 2.0;
        svg.line(a2.minus(d.scale(ext)), b2.plus(d.scale(ext)), &thin);
        arrow(svg, a2, d, ink);
        arrow(svg, b2, d.scale(-1.0), ink);
    }
    label(svg, ctx, a2.mid(b2), n, text, FONT, ink);
}

/// The distance from pixel point `p` to the line through `a` and `b`: a dimension along
/// the perpendicular, with the line extended (dashed) to the foot when it falls outside.
pub(crate) fn point_line(
    svg: &mut Svg,
    ctx: &mut Ctx<'_, '_>,
    p: P2,
    (a, b): (P2, P2),
    text: &str,
    ink: Ink,
) {
    let Some(d) = b.minus(a).unit() else {
        label(svg, ctx, p, P2::new(0.0, -1.0), text, FONT, ink);
        return;
    };
    let t = p.minus(a).dot(d);
    let foot = a.plus(d.scale(t));
    let len = b.minus(a).norm();
    let helper = format!("{} stroke-dasharray=\"{HELPER_DASH}\"", style::thin(ink));
    if t < 0.0 {
        svg.line(a, foot, &helper);
    } else if t > len {
        svg.line(b, foot, &helper);
    }
    let Some(u) = p.minus(foot).unit() else {
        label(svg, ctx, p, d.perp(), text, FONT, ink);
        return;
    };
    svg.line(foot, p, &style::thin(ink));
    arrow(svg, foot, u.scale(-1.0), ink);
    arrow(svg, p, u, ink);
    let side = ctx.outward(foot.mid(p), d);
    label(svg, ctx, foot.mid(p), side, text, FONT, ink);
}

/// A radius (`diameter` false: from the centre out) or diameter (across) of the circle
/// at pixel centre `c` with pixel radius `r`, drawn along `dir`.
pub(crate) fn radial(
    svg: &mut Svg,
    ctx: &mut Ctx<'_, '_>,
    (c, r): (P2, f64),
    dir: P2,
    diameter: bool,
    text: &str,
    ink: Ink,
) {
    let thin = style::thin(ink);
    let far = c.plus(dir.scale(r));
    if diameter {
        let near = c.minus(dir.scale(r));
        svg.line(near, far, &thin);
        arrow(svg, near, dir.scale(-1.0), ink);
    } else {
        svg.line(c, far, &thin);
    }
    arrow(svg, far, dir, ink);
    // A short leader beyond the curve to the value.
    let out = far.plus(dir.scale(14.0));
    svg.line(far, out, &thin);
    label(svg, ctx, out, dir, text, FONT, ink);
}

/// The angle between lines `(a0, a1)` and `(b0, b1)` (pixels): an arc about their
/// intersection between the rays that make the angle closest to `degrees`, with `text`.
pub(crate) fn angle(
    svg: &mut Svg,
    ctx: &mut Ctx<'_, '_>,
    (a0, a1): (P2, P2),
    (b0, b1): (P2, P2),
    degrees: f64,
    text: &str,
    ink: Ink,
) {
    let (Some(da), Some(db)) = (a1.minus(a0).unit(), b1.minus(b0).unit()) else {
        return;
    };
    let denom = da.cross(db);
    if denom.abs() < 1e-9 {
        // Parallel: nowhere to put the arc; the value between the two lines.
        let m = a0.mid(a1).mid(b0.mid(b1));
        label(svg, ctx, m, da.perp(), text, FONT, ink);
        return;
    }
    // Intersection of the two infinite lines.
    let s = b0.minus(a0).cross(db) / denom;
    let x = a0.plus(da.scale(s));
    // Prefer the rays towards each segment's middle; among the four sign choices, the one
    // whose angle matches the dimension.
    let toward = |p: P2, q: P2, d: P2| {
        let m = p.mid(q);
        if m.minus(x).dot(d) >= 0.0 {
            d
        } else {
            d.scale(-1.0)
        }
    };
    let (ra, rb) = (toward(a0, a1, da), toward(b0, b1, db));
    let target = degrees.to_radians();
    let mut best = (f64::INFINITY, ra, rb);
    for (sa, sb) in [(1.0, 1.0), (1.0, -1.0), (-1.0, 1.0), (-1.0, -1.0)] {
        let (u, v) = (ra.scale(sa), rb.scale(sb));
        let ang = u.dot(v).clamp(-1.0, 1.0).acos();
        // Rays toward the segments win ties.
        let cost = (ang - target).abs() + if sa < 0.0 || sb < 0.0 { 1e-6 } else { 0.0 };
        if cost < best.0 - 1e-9 {
            best = (cost, u, v);
        }
    }
    let (_, u, v) = best;
    // A narrow angle gets a wider arc, so that the value fits between its rays.
    let opening = u.dot(v).clamp(-1.0, 1.0).acos().max(1e-3);
    let least = (30.0_f64).max(22.0 / opening).min(160.0);
    // Where both segments lie along their rays: an arc there touches both lines, so the
    // angle reads as theirs even when the lines meet far away.
    let span = |p: P2, q: P2, r: P2| {
        let (tp, tq) = (p.minus(x).dot(r), q.minus(x).dot(r));
        (tp.min(tq), tp.max(tq))
    };
    let ((la, ha), (lb, hb)) = (span(a0, a1, u), span(b0, b1, v));
    let (lo, hi) = (la.max(lb), ha.min(hb));
    let radius = if lo <= hi && hi >= least {
        if lo < least {
            least
        } else {
            lo + ((hi - lo) / 4.0).min(20.0)
        }
    } else {
        least
    };
    // Dashed extensions where the vertex lies off a segment.
    let helper = format!("{} stroke-dasharray=\"{HELPER_DASH}\"", style::thin(ink));
    for (p, q, r) in [(a0, a1, u), (b0, b1, v)] {
        let (tp, tq) = (p.minus(x).dot(r), q.minus(x).dot(r));
        let near = tp.min(tq);
        if near > radius {
            let end = if tp < tq { p } else { q };
            svg.line(x, end, &helper);
        } else if tp.max(tq) < radius {
            svg.line(x, x.plus(r.scale(radius + 6.0)), &helper);
        }
    }
    let (s0, s1) = (x.plus(u.scale(radius)), x.plus(v.scale(radius)));
    // On screen (y down), a positive cross product turns clockwise: sweep flag 1.
    let sweep = u8::from(u.cross(v) > 0.0);
    let d = format!(
        "M{} {} A{} {} 0 0 {sweep} {} {}",
        num(s0.x),
        num(s0.y),
        num(radius),
        num(radius),
        num(s1.x),
        num(s1.y)
    );
    svg.path(
        &d,
        &[s0, s1, x.plus(u.plus(v).unit().unwrap_or(u).scale(radius))],
        &style::thin(ink),
    );
    let bis = u.plus(v).unit().unwrap_or(u.perp());
    label(
        svg,
        ctx,
        x.plus(bis.scale(radius + 2.0)),
        bis,
        text,
        FONT,
        ink,
    );
}
