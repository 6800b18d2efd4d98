//! Placing labels so that they do not cover each other or the points of the drawing.

use super::svg::{text_size, Rect};
use super::view::P2;
use std::collections::HashMap;

/// The side of the grid cells that index the taken boxes, in pixels.
const CELL: f64 = 32.0;

/// The boxes already taken, in pixels, indexed by a grid so that a sketch with thousands
/// of labels places each in time independent of the others.
#[derive(Default)]
pub(crate) struct Labels {
    taken: Vec<Rect>,
    /// Grid cell -> the boxes that reach into it. Only looked up, never iterated, so the
    /// output does not depend on its order.
    grid: HashMap<(i64, i64), Vec<usize>>,
}

fn cells(r: &Rect) -> impl Iterator<Item = (i64, i64)> {
    let c = |v: f64| (v / CELL).floor().clamp(-1e9, 1e9) as i64;
    let (x0, x1, y0, y1) = (c(r.lo.x), c(r.hi.x), c(r.lo.y), c(r.hi.y));
    (x0..=x1).flat_map(move |x| (y0..=y1).map(move |y| (x, y)))
}

impl Labels {
    fn take(&mut self, r: Rect) {
        if !(r.lo.is_finite() && r.hi.is_finite()) {
            return;
        }
        let i = self.taken.len();
        self.taken.push(r);
        for k in cells(&r) {
            self.grid.entry(k).or_default().push(i);
        }
    }

    fn is_free(&self, r: &Rect) -> bool {
        cells(r).all(|k| {
            self.grid
                .get(&k)
                .is_none_or(|v| v.iter().all(|&i| !self.taken[i].overlaps(r)))
        })
    }

    /// Marks a small box around `p` (a point of the geometry) as taken.
    pub(crate) fn block(&mut self, p: P2, size: f64) {
        self.take(Rect::centred(p, size, size));
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
                    if self.is_free(&Rect::centred(c, w + 2.0, h + 2.0)) {
                        chosen = c;
                        break 'search;
                    }
                }
            }
        }
        self.take(Rect::centred(chosen, w + 2.0, h + 2.0));
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

    #[test]
    fn a_label_keeps_off_a_blocked_point_across_cells() {
        let mut l = Labels::default();
        // A point on a cell corner blocks labels in all four cells.
        l.block(P2::new(CELL, CELL), 8.0);
        let a = l.place(P2::new(CELL, CELL), P2::new(1.0, 0.0), "8", 13.0);
        let r = Rect::centred(a, 8.0, 13.0);
        assert!(
            !r.overlaps(&Rect::centred(P2::new(CELL, CELL), 8.0, 8.0)),
            "{a:?}"
        );
    }
}
