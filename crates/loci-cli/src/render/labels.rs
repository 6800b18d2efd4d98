//! Placing labels so that they do not cover each other or the points of the drawing.

use super::svg::{text_size, Rect};
use super::view::P2;

/// The boxes already taken, in pixels.
#[derive(Default)]
pub(crate) struct Labels {
    taken: Vec<Rect>,
}

impl Labels {
    /// Marks a small box around `p` (a point of the geometry) as taken.
    pub(crate) fn block(&mut self, p: P2, size: f64) {
        self.taken.push(Rect::centred(p, size, size));
    }

    /// Where to centre label `s` (font size `font`): at `want`, or the nearest free place
    /// found by stepping along `dir` (a unit vector) one way and then the other, then
    /// across it. The chosen box is taken.
    pub(crate) fn place(&mut self, want: P2, dir: P2, s: &str, font: f64) -> P2 {
        let (w, h) = text_size(s, font);
        let step = h * 0.9;
        let across = dir.perp();
        let mut chosen = want;
        'search: for k in 0..12 {
            let offsets: &[f64] = if k == 0 { &[0.0] } else { &[1.0, -1.0] };
            for &sign in offsets {
                for d in [dir, across] {
                    let c = want.plus(d.scale(sign * step * f64::from(k)));
                    let r = Rect::centred(c, w + 2.0, h + 2.0);
                    if !self.taken.iter().any(|t| t.overlaps(&r)) {
                        chosen = c;
                        break 'search;
                    }
                }
            }
        }
        self.taken.push(Rect::centred(chosen, w + 2.0, h + 2.0));
        chosen
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_second_label_at_the_same_place_moves_away() {
        let mut l = Labels::default();
        let a = l.place(P2::new(0.0, 0.0), P2::new(0.0, 1.0), "30", 13.0);
        let b = l.place(P2::new(0.0, 0.0), P2::new(0.0, 1.0), "40", 13.0);
        assert_eq!(a, P2::new(0.0, 0.0));
        assert!((b.y - a.y).abs() >= 13.0, "{b:?}");
    }
}
