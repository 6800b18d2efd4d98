//! Colours, line styles and the legend that explains them.

use super::glyphs::Mark;
use super::svg::Svg;
use super::view::P2;

/// What a drawn thing is, for its colour.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub(crate) enum Ink {
    /// Geometry of the group that cannot move any more.
    Fixed,
    /// Geometry of the group that can still move.
    Free,
    /// Geometry of the group when no diagnosis says which is which.
    Plain,
    /// Geometry of earlier groups: constant while this group solves.
    Earlier,
    /// Constraint glyphs.
    Glyph,
    /// Constraints in a conflict set, and entities whose own condition is in one.
    Conflict,
}

impl Ink {
    /// The colour.
    pub(crate) fn colour(self) -> &'static str {
        match self {
            Ink::Fixed => "#1b7a3a",
            Ink::Free => "#1565c0",
            Ink::Plain => "#303030",
            Ink::Earlier => "#a0a0a0",
            Ink::Glyph => "#9c27b0",
            Ink::Conflict => "#d50000",
        }
    }

    /// Words for the legend.
    pub(crate) fn describe(self) -> &'static str {
        match self {
            Ink::Fixed => "fully constrained",
            Ink::Free => "can still move",
            Ink::Plain => "geometry",
            Ink::Earlier => "earlier groups (fixed)",
            Ink::Glyph => "constraint",
            Ink::Conflict => "conflicting",
        }
    }

    /// The word used in `class` attributes.
    pub(crate) fn class(self) -> &'static str {
        match self {
            Ink::Fixed => "fixed",
            Ink::Free => "free",
            Ink::Plain => "plain",
            Ink::Earlier => "earlier",
            Ink::Glyph => "glyph",
            Ink::Conflict => "conflict",
        }
    }
}

/// Dash pattern of construction geometry.
pub(crate) const DASH: &str = "7 4";
/// Dash pattern of thin helper lines (extensions of lines to a foot or a vertex).
pub(crate) const HELPER_DASH: &str = "2 3";
/// Font size of dimension values, in pixels.
pub(crate) const FONT: f64 = 13.0;
/// Font size of small markers (H, V, =, ...).
pub(crate) const SMALL_FONT: f64 = 11.0;
/// Arrowhead length.
pub(crate) const ARROW: f64 = 8.0;
/// How far a dimension line stands off the geometry it measures.
pub(crate) const DIM_OFFSET: f64 = 24.0;

/// Stroke attributes for geometry drawn in `ink`, dashed when `construction`.
pub(crate) fn stroke(ink: Ink, construction: bool) -> String {
    let width = match ink {
        Ink::Earlier => 1.5,
        _ if construction => 1.5,
        _ => 2.0,
    };
    let mut s = format!(
        "fill=\"none\" stroke=\"{}\" stroke-width=\"{width}\" stroke-linecap=\"round\"",
        ink.colour()
    );
    if construction {
        s.push_str(&format!(" stroke-dasharray=\"{DASH}\""));
    }
    s
}

/// Attributes for a thin glyph line in `ink`.
pub(crate) fn thin(ink: Ink) -> String {
    format!(
        "fill=\"none\" stroke=\"{}\" stroke-width=\"1\"",
        ink.colour()
    )
}

/// Attributes for a filled glyph shape in `ink`.
pub(crate) fn filled(ink: Ink) -> String {
    format!("fill=\"{}\" stroke=\"none\"", ink.colour())
}

/// Attributes for text in `ink`.
pub(crate) fn text(ink: Ink) -> String {
    format!("fill=\"{}\"", ink.colour())
}

/// One entry of the legend.
pub(crate) struct Entry {
    pub ink: Ink,
    pub construction: bool,
}

/// Draws the legend in one row with its top left corner at `at`, after `title` on a row
/// of its own. Returns nothing; the extent goes into `svg`'s bounds.
/// The point markers present get a second row.
pub(crate) fn legend(svg: &mut Svg, at: P2, title: &str, entries: &[Entry], marks: &[Mark]) {
    svg.open("id=\"legend\" font-family=\"sans-serif\"");
    let mut y = at.y + FONT / 2.0;
    if !title.is_empty() {
        svg.text_left(P2::new(at.x, y), title, FONT, &text(Ink::Plain));
        y += FONT + 8.0;
    }
    let mut x = at.x;
    for e in entries {
        let label = if e.construction {
            "construction"
        } else {
            e.ink.describe()
        };
        let attrs = if e.ink == Ink::Glyph || e.ink == Ink::Conflict {
            format!(
                "fill=\"none\" stroke=\"{}\" stroke-width=\"2\"",
                e.ink.colour()
            )
        } else {
            stroke(e.ink, e.construction)
        };
        svg.line(P2::new(x, y), P2::new(x + 24.0, y), &attrs);
        x += 30.0;
        svg.text_left(P2::new(x, y), label, SMALL_FONT, &text(Ink::Plain));
        x += super::svg::text_size(label, SMALL_FONT).0 + 18.0;
    }
    let mut x = at.x;
    let y = y + SMALL_FONT + 10.0;
    for m in marks {
        // The ground triangle hangs below its point: lift it onto the row.
        let lift = if *m == Mark::Dragged { 8.0 } else { 0.0 };
        super::glyphs::mark(svg, P2::new(x + 12.0, y - lift), *m, Ink::Glyph);
        x += 30.0;
        svg.text_left(P2::new(x, y), m.describe(), SMALL_FONT, &text(Ink::Plain));
        x += super::svg::text_size(m.describe(), SMALL_FONT).0 + 18.0;
    }
    svg.close();
}
