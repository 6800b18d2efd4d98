//! Writing SVG text: elements in pixels, numbers rounded to hundredths, and the box of
//! everything drawn so far (for the view box).

use super::view::P2;
use std::fmt::Write;

/// A number for SVG: at most two decimals, no trailing zeros, never `-0`.
pub(crate) fn num(v: f64) -> String {
    if !v.is_finite() {
        return "0".into();
    }
    let mut s = format!("{:.2}", v);
    if s.contains('.') {
        while s.ends_with('0') {
            s.pop();
        }
        if s.ends_with('.') {
            s.pop();
        }
    }
    if s == "-0" {
        s = "0".into();
    }
    s
}

/// A dimension's value for a label: integers as such, others with up to three decimals.
pub(crate) fn value(v: f64) -> String {
    if !v.is_finite() {
        return "?".into();
    }
    let mut s = format!("{:.3}", v);
    while s.ends_with('0') {
        s.pop();
    }
    if s.ends_with('.') {
        s.pop();
    }
    if s == "-0" {
        s = "0".into();
    }
    s
}

/// Escapes text for an element's content or an attribute.
pub(crate) fn escape(s: &str) -> String {
    let mut o = String::with_capacity(s.len());
    for c in s.chars() {
        match c {
            '&' => o.push_str("&amp;"),
            '<' => o.push_str("&lt;"),
            '>' => o.push_str("&gt;"),
            '"' => o.push_str("&quot;"),
            c => o.push(c),
        }
    }
    o
}

/// An axis-aligned box in pixels.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Rect {
    pub lo: P2,
    pub hi: P2,
}

impl Rect {
    /// The box of width `w` and height `h` centred on `c`.
    pub(crate) fn centred(c: P2, w: f64, h: f64) -> Self {
        Self {
            lo: P2::new(c.x - w / 2.0, c.y - h / 2.0),
            hi: P2::new(c.x + w / 2.0, c.y + h / 2.0),
        }
    }

    pub(crate) fn overlaps(&self, o: &Rect) -> bool {
        self.lo.x < o.hi.x && o.lo.x < self.hi.x && self.lo.y < o.hi.y && o.lo.y < self.hi.y
    }
}

/// The box of points seen so far.
#[derive(Clone, Copy, Debug, Default)]
pub(crate) struct Bounds {
    pub rect: Option<Rect>,
}

impl Bounds {
    pub(crate) fn add(&mut self, p: P2) {
        if !p.is_finite() {
            return;
        }
        self.rect = Some(match self.rect {
            None => Rect { lo: p, hi: p },
            Some(r) => Rect {
                lo: P2::new(r.lo.x.min(p.x), r.lo.y.min(p.y)),
                hi: P2::new(r.hi.x.max(p.x), r.hi.y.max(p.y)),
            },
        });
    }

    pub(crate) fn add_rect(&mut self, r: Rect) {
        self.add(r.lo);
        self.add(r.hi);
    }
}

/// Approximate size of a label in pixels: sans-serif glyphs average about 0.6 em wide.
pub(crate) fn text_size(s: &str, font: f64) -> (f64, f64) {
    (s.chars().count() as f64 * font * 0.6, font)
}

/// SVG elements being written, with their extent.
#[derive(Default)]
pub(crate) struct Svg {
    pub body: String,
    pub bounds: Bounds,
    depth: usize,
}

impl Svg {
    fn indent(&mut self) {
        for _ in 0..self.depth + 1 {
            self.body.push_str("  ");
        }
    }

    /// An empty writer for elements that go inside a group opened here (see [`Svg::append`]).
    pub(crate) fn child(&self) -> Svg {
        Svg {
            body: String::new(),
            bounds: Bounds::default(),
            depth: self.depth + 1,
        }
    }

    /// Adds what `child` wrote.
    pub(crate) fn append(&mut self, child: Svg) {
        self.body.push_str(&child.body);
        if let Some(r) = child.bounds.rect {
            self.bounds.add_rect(r);
        }
    }

    /// Opens `<g attrs>`.
    pub(crate) fn open(&mut self, attrs: &str) {
        self.indent();
        let _ = writeln!(self.body, "<g {attrs}>");
        self.depth += 1;
    }

    /// Closes the innermost group.
    pub(crate) fn close(&mut self) {
        self.depth = self.depth.saturating_sub(1);
        self.indent();
        self.body.push_str("</g>\n");
    }

    pub(crate) fn line(&mut self, a: P2, b: P2, attrs: &str) {
        self.bounds.add(a);
        self.bounds.add(b);
        self.indent();
        let _ = writeln!(
            self.body,
            "<line x1=\"{}\" y1=\"{}\" x2=\"{}\" y2=\"{}\" {attrs}/>",
            num(a.x),
            num(a.y),
            num(b.x),
            num(b.y)
        );
    }

    pub(crate) fn circle(&mut self, c: P2, r: f64, attrs: &str) {
        self.bounds.add(P2::new(c.x - r, c.y - r));
        self.bounds.add(P2::new(c.x + r, c.y + r));
        self.indent();
        let _ = writeln!(
            self.body,
            "<circle cx=\"{}\" cy=\"{}\" r=\"{}\" {attrs}/>",
            num(c.x),
            num(c.y),
            num(r)
        );
    }

    /// A path with data `d`; `extent` are points that bound it.
    pub(crate) fn path(&mut self, d: &str, extent: &[P2], attrs: &str) {
        for &p in extent {
            self.bounds.add(p);
        }
        self.indent();
        let _ = writeln!(self.body, "<path d=\"{d}\" {attrs}/>");
    }

    /// A closed polygon (arrowheads, markers).
    pub(crate) fn polygon(&mut self, pts: &[P2], attrs: &str) {
        let list: Vec<String> = pts
            .iter()
            .map(|p| format!("{},{}", num(p.x), num(p.y)))
            .collect();
        for &p in pts {
            self.bounds.add(p);
        }
        self.indent();
        let _ = writeln!(
            self.body,
            "<polygon points=\"{}\" {attrs}/>",
            list.join(" ")
        );
    }

    /// Text centred on `c` (horizontally and, roughly, vertically).
    pub(crate) fn text(&mut self, c: P2, s: &str, font: f64, attrs: &str) {
        let (w, h) = text_size(s, font);
        self.bounds.add_rect(Rect::centred(c, w, h));
        self.indent();
        // The baseline sits about 0.35 em below the middle of capitals and digits.
        let _ = writeln!(
            self.body,
            "<text x=\"{}\" y=\"{}\" font-size=\"{}\" text-anchor=\"middle\" {attrs}>{}</text>",
            num(c.x),
            num(c.y + font * 0.35),
            num(font),
            escape(s)
        );
    }

    /// Text starting at `p` (left aligned, `p` on the middle line).
    pub(crate) fn text_left(&mut self, p: P2, s: &str, font: f64, attrs: &str) {
        let (w, h) = text_size(s, font);
        self.bounds.add(P2::new(p.x, p.y - h / 2.0));
        self.bounds.add(P2::new(p.x + w, p.y + h / 2.0));
        self.indent();
        let _ = writeln!(
            self.body,
            "<text x=\"{}\" y=\"{}\" font-size=\"{}\" {attrs}>{}</text>",
            num(p.x),
            num(p.y + font * 0.35),
            num(font),
            escape(s)
        );
    }
}

/// An arrowhead with its tip at `tip`, pointing along `dir` (a unit vector).
pub(crate) fn arrowhead(tip: P2, dir: P2, len: f64) -> [P2; 3] {
    let back = tip.minus(dir.scale(len));
    let side = dir.perp().scale(len * 0.35);
    [tip, back.plus(side), back.minus(side)]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numbers_are_short_and_never_negative_zero() {
        assert_eq!(num(1.0), "1");
        assert_eq!(num(1.005_1), "1.01");
        assert_eq!(num(-0.001), "0");
        assert_eq!(num(12.5), "12.5");
        assert_eq!(value(30.0), "30");
        assert_eq!(value(2.0 / 3.0), "0.667");
        assert_eq!(value(-0.0001), "0");
    }

    #[test]
    fn text_is_escaped() {
        assert_eq!(escape("a<b & \"c\""), "a&lt;b &amp; &quot;c&quot;");
    }
}
