//! Pictures of sketches: a solved [`System`] group as SVG, with its geometry coloured by
//! how constrained it is, construction geometry dashed, constraint glyphs and dimensions,
//! conflicting constraints in red, and a legend.
//!
//! The model's y axis points up; SVG's points down, so the picture is flipped. Everything
//! is drawn in pixels after fitting the geometry into [`RenderOptions::width`] ×
//! [`RenderOptions::height`]; glyphs and labels keep their size whatever the scale, and the
//! view box is fitted to everything drawn. The output depends only on the inputs.

pub(crate) mod command;
mod dimensions;
mod geometry;
mod glyphs;
mod labels;
mod style;
mod svg;
#[cfg(test)]
mod tests;
mod view;

use loci::{ConstraintId, Diagnosis, EntityId, GroupId, Member, System};
use std::collections::{BTreeMap, BTreeSet};
use std::fmt::Write;
use style::{Entry, Ink};
use svg::{escape, num, Svg};
use view::{ToPixels, View, P2};

/// How to draw.
#[derive(Clone, Debug, PartialEq)]
pub struct RenderOptions {
    /// Entities drawn as construction (reference) geometry: dashed, thinner.
    pub construction: BTreeSet<EntityId>,
    /// The other groups whose geometry is drawn, muted (it is fixed while the group
    /// solves). `None`: every group with a lower handle.
    pub earlier: Option<BTreeSet<GroupId>>,
    /// The box the geometry is fitted into, in pixels (glyphs, labels and the legend come
    /// on top of it).
    pub width: f64,
    /// See [`RenderOptions::width`].
    pub height: f64,
    /// Blank space around everything drawn, in pixels.
    pub margin: f64,
    /// The title above the legend; `None`: the group, and the diagnosis' verdict when given.
    pub title: Option<String>,
    /// Whether to draw the legend (and the title).
    pub legend: bool,
}

impl Default for RenderOptions {
    fn default() -> Self {
        Self {
            construction: BTreeSet::new(),
            earlier: None,
            width: 640.0,
            height: 480.0,
            margin: 16.0,
            title: None,
            legend: true,
        }
    }
}

/// Draws `group` of `sys` as it stands (solve it first for a solved picture). With a
/// `diagnosis` of the group, geometry that can still move is drawn in another colour than
/// geometry that cannot, and conflicting constraints are red.
#[must_use]
pub fn render_svg(
    sys: &System,
    group: GroupId,
    diagnosis: Option<&Diagnosis>,
    opts: &RenderOptions,
) -> String {
    let view = View::of_group(sys, group);
    let items = geometry::collect(&view, group, diagnosis, opts);

    // Fit the geometry (drawing-plane units) into the box.
    let mut lo = P2::new(f64::INFINITY, f64::INFINITY);
    let mut hi = P2::new(f64::NEG_INFINITY, f64::NEG_INFINITY);
    for p in items.iter().flat_map(|it| it.shape.extent()) {
        if p.is_finite() {
            lo = P2::new(lo.x.min(p.x), lo.y.min(p.y));
            hi = P2::new(hi.x.max(p.x), hi.y.max(p.y));
        }
    }
    if !lo.is_finite() || !hi.is_finite() {
        lo = P2::new(0.0, 0.0);
        hi = lo;
    }
    let width = if opts.width.is_finite() && opts.width > 1.0 {
        opts.width
    } else {
        640.0
    };
    let height = if opts.height.is_finite() && opts.height > 1.0 {
        opts.height
    } else {
        480.0
    };
    let px = ToPixels::fit(lo, hi, width, height);

    let mut svg = Svg::default();
    geometry::draw(&mut svg, &items, &px);
    // The mean of the group's points lies inside a closed profile (the middle of the box
    // need not: a triangle's hypotenuse runs through it), so dimensions set off away from
    // it land outside.
    let own: Vec<P2> = items
        .iter()
        .filter(|it| it.ink != Ink::Earlier)
        .filter_map(|it| match it.shape {
            geometry::Shape::Point(p) => Some(px.px(p)),
            _ => None,
        })
        .collect();
    let centre = if own.is_empty() {
        svg.bounds
            .rect
            .map_or(P2::new(0.0, 0.0), |r| r.lo.mid(r.hi))
    } else {
        own.iter()
            .fold(P2::new(0.0, 0.0), |a, p| a.plus(*p))
            .scale(1.0 / own.len() as f64)
    };

    let conflicts: BTreeSet<ConstraintId> = diagnosis
        .into_iter()
        .flat_map(|d| &d.conflicting)
        .flat_map(|s| &s.members)
        .filter_map(|m| match m {
            Member::Constraint(c) => Some(*c),
            Member::Entity(_) => None,
        })
        .collect();
    let measured: BTreeMap<ConstraintId, f64> = diagnosis
        .into_iter()
        .flat_map(|d| &d.measurements)
        .map(|m| (m.constraint, m.value))
        .collect();
    let mut ctx = glyphs::Ctx {
        view: &view,
        px,
        centre,
        labels: labels::Labels::default(),
        measured,
    };
    // Labels keep off the points and the curves.
    for it in &items {
        let pts: Vec<P2> = it.shape.samples().into_iter().map(|p| px.px(p)).collect();
        if let [p] = pts.as_slice() {
            ctx.labels.block(*p, 8.0);
        }
        for w in pts.windows(2) {
            let n = (w[1].minus(w[0]).norm() / 6.0).ceil().min(400.0) as usize;
            for i in 0..=n {
                let t = i as f64 / n.max(1) as f64;
                ctx.labels.block(w[0].plus(w[1].minus(w[0]).scale(t)), 3.0);
            }
        }
    }
    svg.open("id=\"constraints\"");
    for c in sys.constraints().iter().filter(|c| c.group == group) {
        glyphs::draw(&mut svg, &mut ctx, c, conflicts.contains(&c.h));
    }
    svg.close();

    if opts.legend {
        let title = opts.title.clone().unwrap_or_else(|| match diagnosis {
            Some(d) => format!("group {}: {}, {} dof", group.0, d.outcome, d.dof),
            None => format!("group {}", group.0),
        });
        let mut entries = Vec::new();
        let has = |ink: Ink| items.iter().any(|it| it.ink == ink);
        if diagnosis.is_some() {
            entries.push(Entry {
                ink: Ink::Fixed,
                construction: false,
            });
            entries.push(Entry {
                ink: Ink::Free,
                construction: false,
            });
        } else {
            entries.push(Entry {
                ink: Ink::Plain,
                construction: false,
            });
        }
        if has(Ink::Earlier) {
            entries.push(Entry {
                ink: Ink::Earlier,
                construction: false,
            });
        }
        if items.iter().any(|it| it.construction) {
            entries.push(Entry {
                ink: Ink::Plain,
                construction: true,
            });
        }
        entries.push(Entry {
            ink: Ink::Glyph,
            construction: false,
        });
        if !conflicts.is_empty() || has(Ink::Conflict) {
            entries.push(Entry {
                ink: Ink::Conflict,
                construction: false,
            });
        }
        let at = svg
            .bounds
            .rect
            .map_or(P2::new(0.0, 0.0), |r| P2::new(r.lo.x, r.hi.y + 18.0));
        let marks: BTreeSet<glyphs::Mark> = sys
            .constraints()
            .iter()
            .filter(|c| c.group == group)
            .filter_map(|c| glyphs::Mark::of(c.kind))
            .collect();
        let marks: Vec<glyphs::Mark> = marks.into_iter().collect();
        style::legend(&mut svg, at, &title, &entries, &marks);
    }

    let m = if opts.margin.is_finite() && opts.margin >= 0.0 {
        opts.margin
    } else {
        16.0
    };
    let r = svg.bounds.rect.unwrap_or(svg::Rect {
        lo: P2::new(0.0, 0.0),
        hi: P2::new(1.0, 1.0),
    });
    let (x0, y0) = (r.lo.x - m, r.lo.y - m);
    let (w, h) = (r.hi.x - r.lo.x + 2.0 * m, r.hi.y - r.lo.y + 2.0 * m);
    let mut out = String::new();
    out.push_str("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n");
    let _ = writeln!(
        out,
        "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{}\" height=\"{}\" viewBox=\"{} {} {} {}\" font-family=\"DejaVu Sans, Verdana, sans-serif\">",
        num(w.ceil()),
        num(h.ceil()),
        num(x0),
        num(y0),
        num(w.ceil()),
        num(h.ceil())
    );
    let title = opts
        .title
        .clone()
        .unwrap_or_else(|| format!("loci: group {}", group.0));
    let _ = writeln!(out, "  <title>{}</title>", escape(&title));
    let _ = writeln!(
        out,
        "  <rect x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\" fill=\"white\"/>",
        num(x0),
        num(y0),
        num(w.ceil()),
        num(h.ceil())
    );
    out.push_str(&svg.body);
    out.push_str("</svg>\n");
    out
}
