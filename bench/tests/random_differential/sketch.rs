//! The builder the generator draws with: it adds entities at their true positions and
//! constraints to a [`loci::System`], and remembers the true geometry so that every value a
//! constraint carries is measured from it.
//!
//! Positions are kept in native coordinates: (u, v, 0) in the workplane for a planar system,
//! (x, y, z) for a spatial one. Fixed objects (the workplane or reference plane) are in group
//! [`FIXED`]; everything solved is in group [`GROUP`]. Circles and arcs are always in the
//! plane (SolveSpace's own API takes them only in a workplane, centred on a 2D point), so a
//! spatial system draws them there and ties them to its 3D points by distances and points on
//! their cylinders.

use crate::geom::{add, cross, dot, norm, quat_axes, scale, sub, unit, V3};
use crate::rng::Rng;
use loci::{Constraint, ConstraintKind as K, Entity, Param, System};

pub const FIXED: u32 = 1;
pub const GROUP: u32 = 2;

#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum Dim {
    /// 2D points and curves in a workplane; every constraint in that workplane.
    Planar,
    /// 3D points and curves free in space, with a fixed reference plane.
    Spatial,
}

pub struct Pt {
    pub h: u32,
    pub at: V3,
    /// A 2D point in the reference plane of a spatial system (a circle's centre or an arc's
    /// ends): SolveSpace's 3D lines cannot join it.
    pub flat: bool,
}

pub struct Ln {
    pub h: u32,
    pub a: usize,
    pub b: usize,
}

/// A circle or an arc: its centre point, true radius and the axes of its plane.
pub struct Circ {
    pub h: u32,
    pub center: usize,
    pub r: f64,
    pub u: V3,
    pub v: V3,
}

pub struct Sketch {
    pub rng: Rng,
    pub dim: Dim,
    pub sys: System,
    next_param: u32,
    next_entity: u32,
    /// The workplane (planar) or the reference plane (spatial).
    pub plane: u32,
    /// The plane's 3D normal entity; circles and arcs in the workplane name it.
    pub plane_normal: u32,
    /// The plane's origin and axes U, V, N in native coordinates.
    pub frame: (V3, V3, V3, V3),
    pub pts: Vec<Pt>,
    pub lines: Vec<Ln>,
    pub circles: Vec<Circ>,
    /// Constraints in order of creation, their handles still 0.
    pub cons: Vec<Constraint>,
    /// The constraints planted by gadgets (never copied by another).
    pub planted: Vec<usize>,
}

impl Sketch {
    pub fn new(rng: Rng, dim: Dim) -> Self {
        let mut s = Sketch {
            rng,
            dim,
            sys: System::new(),
            next_param: 0,
            next_entity: 0,
            plane: 0,
            plane_normal: 0,
            frame: ([0.0; 3], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]),
            pts: Vec::new(),
            lines: Vec::new(),
            circles: Vec::new(),
            cons: Vec::new(),
            planted: Vec::new(),
        };
        // A fixed plane through a random origin with a random orientation.
        let origin = [0, 1, 2].map(|_| s.rng.range(-5.0, 5.0));
        let q = s.random_quaternion();
        let o = origin.map(|v| s.param_in(FIXED, v));
        let qp = q.map(|v| s.param_in(FIXED, v));
        let (pe, ne, we) = (s.entity(), s.entity(), s.entity());
        s.add(Entity::point_3d(pe, FIXED, o));
        s.add(Entity::normal_3d(ne, FIXED, qp));
        s.add(Entity::workplane(we, FIXED, pe, ne));
        s.plane = we;
        s.plane_normal = ne;
        if dim == Dim::Spatial {
            let (u, v, n) = quat_axes(q);
            s.frame = (origin, u, v, n);
        }
        s
    }

    pub fn entity(&mut self) -> u32 {
        self.next_entity += 1;
        self.next_entity
    }

    fn param_in(&mut self, group: u32, v: f64) -> u32 {
        self.next_param += 1;
        let h = self.next_param;
        self.sys
            .add_param(Param::new(h, group, v))
            .expect("fresh param handle");
        h
    }

    pub fn param(&mut self, v: f64) -> u32 {
        self.param_in(GROUP, v)
    }

    fn add(&mut self, e: Entity) {
        self.sys.add_entity(e).expect("a valid entity");
    }

    pub fn planar(&self) -> bool {
        self.dim == Dim::Planar
    }

    /// The workplane every constraint of a planar system is in.
    pub fn wp(&self) -> Option<u32> {
        self.planar().then_some(self.plane)
    }

    pub fn random_quaternion(&mut self) -> [f64; 4] {
        let q = [0, 1, 2, 3].map(|_| self.rng.normal());
        let m = q.iter().map(|c| c * c).sum::<f64>().sqrt();
        q.map(|c| c / m)
    }

    pub fn random_point(&mut self) -> V3 {
        let z = if self.planar() {
            0.0
        } else {
            self.rng.range(-10.0, 10.0)
        };
        [self.rng.range(-10.0, 10.0), self.rng.range(-10.0, 10.0), z]
    }

    pub fn random_dir(&mut self) -> V3 {
        if self.planar() {
            let t = self.rng.range(0.0, std::f64::consts::TAU);
            [t.cos(), t.sin(), 0.0]
        } else {
            loop {
                let d = [0, 1, 2].map(|_| self.rng.normal());
                if norm(d) > 1e-3 {
                    return unit(d);
                }
            }
        }
    }

    /// A unit direction perpendicular to the unit direction `d`.
    pub fn perp_dir(&mut self, d: V3) -> V3 {
        if self.planar() {
            scale([-d[1], d[0], 0.0], self.rng.sign())
        } else {
            loop {
                let c = cross(d, self.random_dir());
                if norm(c) > 0.1 {
                    return unit(c);
                }
            }
        }
    }

    /// A unit direction at `deg` degrees from the unit direction `d`.
    pub fn dir_at_angle(&mut self, d: V3, deg: f64) -> V3 {
        let w = self.perp_dir(d);
        let t = deg.to_radians();
        add(scale(d, t.cos()), scale(w, t.sin()))
    }

    /// A new point entity at `at`; its index. In a spatial system a 3D point.
    pub fn point(&mut self, at: V3) -> usize {
        self.point_as(at, false)
    }

    /// A new point entity at `at`: a 2D point in the plane when `flat` (`at` must lie in the
    /// plane) or in a planar system, else a 3D point.
    pub fn point_as(&mut self, at: V3, flat: bool) -> usize {
        let e = self.entity();
        let flat = flat || self.planar();
        if flat {
            let (o, u, v, _) = self.frame;
            let (x, y) = (dot(sub(at, o), u), dot(sub(at, o), v));
            let (pu, pv) = (self.param(x), self.param(y));
            self.add(Entity::point_2d(e, GROUP, self.plane, [pu, pv]));
        } else {
            let p = at.map(|c| self.param(c));
            self.add(Entity::point_3d(e, GROUP, p));
        }
        self.pts.push(Pt {
            h: e,
            at,
            flat: flat && !self.planar(),
        });
        self.pts.len() - 1
    }

    /// The points lines may join: every point of a planar system, the 3D points of a
    /// spatial one (SolveSpace's 3D lines take 3D points only).
    pub fn joinable(&self) -> Vec<usize> {
        (0..self.pts.len()).filter(|&i| !self.pts[i].flat).collect()
    }

    /// An existing joinable point (with probability `p_existing`) or a new random one.
    pub fn some_point(&mut self, p_existing: f64) -> usize {
        let ok = self.joinable();
        if !ok.is_empty() && self.rng.chance(p_existing) {
            ok[self.rng.below(ok.len())]
        } else {
            let at = self.random_point();
            self.point(at)
        }
    }

    pub fn line(&mut self, a: usize, b: usize) -> usize {
        let e = self.entity();
        let (ha, hb) = (self.pts[a].h, self.pts[b].h);
        self.add(Entity::line(e, GROUP, self.wp(), ha, hb));
        self.lines.push(Ln { h: e, a, b });
        self.lines.len() - 1
    }

    /// A line's end minus its start, in native coordinates.
    pub fn dir(&self, l: usize) -> V3 {
        let ln = &self.lines[l];
        sub(self.pts[ln.b].at, self.pts[ln.a].at)
    }

    /// A circle about `center` (a point in the plane) in the plane, whose normal it names.
    pub fn circle(&mut self, center: usize, r: f64) -> usize {
        let rp = self.param(r);
        let (d, c) = (self.entity(), self.entity());
        self.add(Entity::distance(d, GROUP, Some(self.plane), rp));
        let ch = self.pts[center].h;
        self.add(Entity::circle(
            c,
            GROUP,
            Some(self.plane),
            ch,
            self.plane_normal,
            d,
        ));
        self.circles.push(Circ {
            h: c,
            center,
            r,
            u: self.frame.1,
            v: self.frame.2,
        });
        self.circles.len() - 1
    }

    /// An arc in the plane, counter-clockwise from `t0` to `t1` about `center` (a point in
    /// the plane).
    pub fn arc(&mut self, center: usize, r: f64, t0: f64, t1: f64) -> usize {
        let (_, u, v, _) = self.frame;
        let c = self.pts[center].at;
        let at = |t: f64| add(c, add(scale(u, r * t.cos()), scale(v, r * t.sin())));
        let start = self.point_as(at(t0), true);
        let end = self.point_as(at(t1), true);
        let e = self.entity();
        let (hc, hs, he) = (self.pts[center].h, self.pts[start].h, self.pts[end].h);
        self.add(Entity::arc(
            e,
            GROUP,
            self.plane,
            self.plane_normal,
            hc,
            hs,
            he,
        ));
        self.circles.push(Circ {
            h: e,
            center,
            r,
            u,
            v,
        });
        self.circles.len() - 1
    }

    /// A centre for a circle or arc: a point in the plane, existing (with probability
    /// `p_existing`) or new.
    pub fn center(&mut self, p_existing: f64) -> usize {
        let flat: Vec<usize> = (0..self.pts.len())
            .filter(|&i| self.planar() || self.pts[i].flat)
            .collect();
        if !flat.is_empty() && self.rng.chance(p_existing) {
            return flat[self.rng.below(flat.len())];
        }
        let (o, u, v, _) = self.frame;
        let (x, y) = (self.rng.range(-10.0, 10.0), self.rng.range(-10.0, 10.0));
        self.point_as(add(o, add(scale(u, x), scale(v, y))), true)
    }

    /// A point on circle `c` at angle `t` (off its plane by `lift` along the axis).
    pub fn on_circle(&self, c: usize, t: f64, lift: f64) -> V3 {
        let ci = &self.circles[c];
        let n = cross(ci.u, ci.v);
        let p = add(
            add(self.pts[ci.center].at, scale(ci.u, ci.r * t.cos())),
            scale(ci.v, ci.r * t.sin()),
        );
        add(p, scale(n, lift))
    }

    /// A constraint of `kind` in the system's workplane (none for spatial systems).
    pub fn con(&self, kind: K) -> Constraint {
        Constraint::new(0, GROUP, kind).in_workplane(self.wp())
    }

    /// Pushes a constraint; its index.
    pub fn push(&mut self, c: Constraint) -> usize {
        self.cons.push(c);
        self.cons.len() - 1
    }

    pub fn pt_h(&self, p: usize) -> u32 {
        self.pts[p].h
    }

    pub fn distance(&mut self, a: usize, b: usize) -> usize {
        let d = norm(sub(self.pts[a].at, self.pts[b].at));
        let c = self
            .con(K::PtPtDistance)
            .with_points(self.pt_h(a), self.pt_h(b))
            .with_val(d);
        self.push(c)
    }

    /// The angle in degrees between lines `l1` and `l2` (0 to 180).
    pub fn angle_between(&self, l1: usize, l2: usize) -> f64 {
        let (a, b) = (self.dir(l1), self.dir(l2));
        (dot(a, b) / (norm(a) * norm(b)))
            .clamp(-1.0, 1.0)
            .acos()
            .to_degrees()
    }

    pub fn angle(&mut self, l1: usize, l2: usize, deg: f64) -> usize {
        let c = self
            .con(K::Angle)
            .with_entities([self.lines[l1].h, self.lines[l2].h, 0, 0])
            .with_val(deg);
        self.push(c)
    }

    /// A constraint between two lines with no value (parallel, perpendicular, equal length).
    pub fn between_lines(&mut self, kind: K, l1: usize, l2: usize) -> usize {
        let c = self
            .con(kind)
            .with_entities([self.lines[l1].h, self.lines[l2].h, 0, 0]);
        self.push(c)
    }

    pub fn coincident(&mut self, a: usize, b: usize) -> usize {
        let c = self
            .con(K::PointsCoincident)
            .with_points(self.pt_h(a), self.pt_h(b));
        self.push(c)
    }

    pub fn midpoint(&mut self, p: usize, l: usize) -> usize {
        let c = self
            .con(K::AtMidpoint)
            .with_points(self.pt_h(p), 0)
            .with_entities([self.lines[l].h, 0, 0, 0]);
        self.push(c)
    }

    pub fn on_line(&mut self, p: usize, l: usize) -> usize {
        let c = self
            .con(K::PtOnLine)
            .with_points(self.pt_h(p), 0)
            .with_entities([self.lines[l].h, 0, 0, 0]);
        self.push(c)
    }

    /// Horizontal or vertical in the plane (spatial systems: projected onto it).
    pub fn axis_aligned(&mut self, kind: K, l: usize) -> usize {
        let c = Constraint::new(0, GROUP, kind)
            .in_workplane(Some(self.plane))
            .with_entities([self.lines[l].h, 0, 0, 0]);
        self.push(c)
    }

    /// A constraint whose workplane field SolveSpace ignores (point and plane, circles).
    pub fn unplaned(&mut self, kind: K, p: Option<usize>, e: [u32; 2], val: f64) -> usize {
        let c = Constraint::new(0, GROUP, kind)
            .with_points(p.map_or(0, |p| self.pt_h(p)), 0)
            .with_entities([e[0], e[1], 0, 0])
            .with_val(val);
        self.push(c)
    }

    /// Signed distance of a native point from the plane.
    pub fn plane_height(&self, p: V3) -> f64 {
        dot(sub(p, self.frame.0), self.frame.3)
    }
}
