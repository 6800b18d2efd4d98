//! Bars: pairs of points (up to coincidence) joined by a line or by a distance between them.
//! A drag watches the figures they make (see [`super::drag`]): triangles, which must never
//! turn over, and hinges, two bars meeting at a point, which must not change the sense they
//! bend in without passing through straight.

use super::{PointId, ShapeKind, Sketch, Spec};
use std::collections::{BTreeMap, BTreeSet};

/// Every point's bars, keyed by the representative of its class of coincident points.
pub(super) struct Bars(BTreeMap<PointId, BTreeSet<PointId>>);

impl Bars {
    /// The bars of `s`: its lines, and its distances between points. A distance joins two
    /// points as rigidly as a line with a length: three points with a distance on every side
    /// are a rigid triangle, which turns over only by a jump to its mirror image (a point held
    /// by two distances, dragged away, jumped across the line of its two anchors). Reference
    /// dimensions hold nothing.
    pub fn of(s: &Sketch) -> Self {
        let mut parent: BTreeMap<PointId, PointId> = BTreeMap::new();
        fn find(parent: &mut BTreeMap<PointId, PointId>, p: PointId) -> PointId {
            let mut r = p;
            while let Some(&q) = parent.get(&r) {
                if q == r {
                    break;
                }
                r = q;
            }
            parent.insert(p, r);
            r
        }
        for (_, spec) in s.constraints() {
            if let Spec::Coincident { a, b } = spec {
                let (ra, rb) = (
                    find(&mut parent, PointId(a.0)),
                    find(&mut parent, PointId(b.0)),
                );
                if ra != rb {
                    parent.insert(ra.max(rb), ra.min(rb));
                }
            }
        }
        let mut pairs: Vec<(PointId, PointId)> = s
            .shapes()
            .filter(|(_, k)| *k == ShapeKind::Line)
            .map(|(l, _)| {
                let [a, b] = s.line_points(super::LineId(l.0));
                (a, b)
            })
            .collect();
        for (id, spec) in s.constraints() {
            if let Spec::Distance { a, b, .. } = spec {
                if !s.constraint(id).is_some_and(|(_, reference)| reference) {
                    pairs.push((PointId(a.0), PointId(b.0)));
                }
            }
        }
        let mut adj: BTreeMap<PointId, BTreeSet<PointId>> = BTreeMap::new();
        for (a, b) in pairs {
            let (a, b) = (find(&mut parent, a), find(&mut parent, b));
            if a != b {
                adj.entry(a).or_default().insert(b);
                adj.entry(b).or_default().insert(a);
            }
        }
        Bars(adj)
    }

    /// Triangles: three points joined pairwise by bars.
    pub fn triangles(&self) -> Vec<[PointId; 3]> {
        let adj = &self.0;
        let mut out = Vec::new();
        for (u, nu) in adj {
            for v in nu.range(*u..).filter(|v| *v != u) {
                for w in adj[v].range(*v..).filter(|w| *w != v) {
                    if nu.contains(w) {
                        out.push([*u, *v, *w]);
                    }
                }
            }
        }
        out
    }

    /// Hinges `[a, b, c]`: bars from `b` to `a` and to `c`, each pair once, but for those
    /// whose ends are joined by a bar too: the triangle they make is watched already, and it
    /// bends as it turns.
    pub fn hinges(&self) -> Vec<[PointId; 3]> {
        let mut out = Vec::new();
        for (b, nb) in &self.0 {
            for a in nb {
                for c in nb.range(*a..).filter(|c| *c != a) {
                    if !self.0[a].contains(c) {
                        out.push([*a, *b, *c]);
                    }
                }
            }
        }
        out
    }
}
