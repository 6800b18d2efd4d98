//! Helpers shared by the integration tests: a small sketch builder over the public API.
#![allow(dead_code)]

pub mod perturbed_chain;
pub mod rng;

use loci::{Constraint, ConstraintKind, Entity, Param, System};

/// The workplane every 2D helper sketches in (the xy plane, defined in group 1).
pub const WP: u32 = 200;

/// Builds systems through the public API, handing out parameter and constraint handles.
pub struct Sketch {
    /// The system being built.
    pub sys: System,
    next_param: u32,
    next_constraint: u32,
}

impl Sketch {
    /// A system holding the xy workplane in group 1: params 1..=7, entities 101, 102 and
    /// [`WP`].
    pub fn new() -> Self {
        let mut sys = System::new();
        sys.add_xy_workplane(1, 1, [101, 102, WP]).unwrap();
        Self {
            sys,
            next_param: 1000,
            next_constraint: 1,
        }
    }

    /// A fresh parameter in `group` starting at `v`.
    pub fn param(&mut self, group: u32, v: f64) -> u32 {
        let h = self.next_param;
        self.next_param += 1;
        self.sys.add_param(Param::new(h, group, v)).unwrap();
        h
    }

    /// A point in the workplane with handle `h`, in `group`, at `uv`.
    pub fn point(&mut self, h: u32, group: u32, uv: [f64; 2]) -> u32 {
        let u = self.param(group, uv[0]);
        let v = self.param(group, uv[1]);
        self.sys
            .add_entity(Entity::point_2d(h, group, WP, [u, v]))
            .unwrap();
        h
    }

    /// A line segment in the workplane.
    pub fn line(&mut self, h: u32, group: u32, a: u32, b: u32) -> u32 {
        self.sys
            .add_entity(Entity::line(h, group, Some(WP), a, b))
            .unwrap();
        h
    }

    /// Adds `c` (built with any handle) under the next constraint handle, in the workplane.
    pub fn constrain(&mut self, c: Constraint) -> u32 {
        let h = self.next_constraint;
        self.next_constraint += 1;
        let c = Constraint { h: h.into(), ..c }.in_workplane(Some(WP));
        self.sys.add_constraint(c).unwrap();
        h
    }

    /// A constraint of `kind` in `group` with points `a`, `b` (0 = none).
    pub fn on_points(&mut self, group: u32, kind: ConstraintKind, a: u32, b: u32, val: f64) -> u32 {
        self.constrain(
            Constraint::new(0, group, kind)
                .with_points(a, b)
                .with_val(val),
        )
    }

    /// A constraint of `kind` in `group` on entities `a`, `b` (0 = none).
    pub fn on_entities(
        &mut self,
        group: u32,
        kind: ConstraintKind,
        a: u32,
        b: u32,
        val: f64,
    ) -> u32 {
        self.constrain(
            Constraint::new(0, group, kind)
                .with_entities([a, b, 0, 0])
                .with_val(val),
        )
    }

    /// The workplane coordinates of 2D point `h`.
    pub fn uv(&self, h: u32) -> [f64; 2] {
        uv(&self.sys, h)
    }
}

/// The workplane coordinates of 2D point `h` of `sys`.
pub fn uv(sys: &System, h: u32) -> [f64; 2] {
    match &sys.entity(h.into()).expect("point exists").kind {
        loci::EntityKind::PointIn2d { params } => {
            [sys.value(params[0]).unwrap(), sys.value(params[1]).unwrap()]
        }
        other => panic!("entity {h} is not a 2D point: {other:?}"),
    }
}

/// Euclidean distance between two points of the plane.
pub fn dist(a: [f64; 2], b: [f64; 2]) -> f64 {
    (a[0] - b[0]).hypot(a[1] - b[1])
}

/// Every parameter value of `sys`, as bits, for exact comparisons.
pub fn value_bits(sys: &System) -> Vec<(u32, u64)> {
    sys.params()
        .iter()
        .map(|p| (p.h.0, p.val.to_bits()))
        .collect()
}

/// Constraint handles as the report lists them.
pub fn ids(hs: &[u32]) -> Vec<loci::ConstraintId> {
    let mut v: Vec<loci::ConstraintId> = hs.iter().map(|&h| h.into()).collect();
    v.sort_unstable();
    v
}
