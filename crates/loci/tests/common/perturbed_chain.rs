//! A deterministic, perturbed chain of line segments of random lengths and turns, shared by
//! the scale test and the `chain` bench (which includes this file with `#[path]`).
//!
//! Segment `i` has its own two points `a_i`, `b_i` in a workplane. `b_i` and `a_{i+1}` are
//! joined by `points_coincident`; every segment has a `pt_pt_distance` length; every
//! neighbour pair has an `angle`; `a_0` is pinned with `where_dragged` and the first segment
//! is `horizontal`.
//!
//! Why the `horizontal`: lengths, angles and coincidences are all invariant under rotating
//! the whole chain about `a_0`, so with only `where_dragged` on `a_0` one degree of freedom
//! is left. Fixing the direction of the first segment removes it, so the chain is fully
//! constrained (DOF 0) and its solution is unique near the start: the exact drawing the
//! generator perturbs, which the test can compare against.
//!
//! Counting: `4n` unknowns; equations `2` (`where_dragged`) `+ 1` (horizontal) `+ 2(n-1)`
//! (coincident) `+ n` (lengths) `+ (n-1)` (angles) `= 4n`.
#![allow(dead_code)]

use loci::{Constraint, ConstraintKind as K, Entity, GroupId, Param, System};

/// The workplane of the chain (the xy plane, in group 1).
pub const CHAIN_WP: u32 = 3;

/// The group the chain's geometry and constraints live in.
pub const CHAIN_GROUP: u32 = 2;

/// A generated chain: the perturbed system plus the exact drawing it was perturbed from.
pub struct Chain {
    /// The system, with every chain point moved off the exact drawing.
    pub system: System,
    /// The group to solve.
    pub group: GroupId,
    /// Segment lengths.
    pub lengths: Vec<f64>,
    /// The `angle` constraint values in degrees: `angles[i]` is between segments `i` and
    /// `i + 1`.
    pub angles: Vec<f64>,
    /// The exact joints: `joints[i]` is the start of segment `i`, `joints[n]` the end of the last.
    pub joints: Vec<[f64; 2]>,
    /// Per segment: the handles of its start point, end point and line.
    pub segments: Vec<[u32; 3]>,
}

/// SplitMix64: a tiny, well-mixed generator, so the chain does not depend on a `rand`
/// version.
pub struct SplitMix(pub u64);

impl SplitMix {
    /// The next 64 random bits.
    pub fn next_u64(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }

    /// Uniform in `[lo, hi)`.
    pub fn uniform(&mut self, lo: f64, hi: f64) -> f64 {
        let unit = (self.next_u64() >> 11) as f64 / (1u64 << 53) as f64;
        lo + (hi - lo) * unit
    }
}

/// A chain of `n >= 1` segments. Lengths are in [5, 15), turns of 15 to 45 degrees either
/// way, and every chain coordinate starts up to `perturb` away from the exact drawing.
pub fn chain(n: usize, seed: u64, perturb: f64) -> Chain {
    assert!(n >= 1, "a chain needs at least one segment");
    let mut rng = SplitMix(seed);
    let mut sys = System::new();
    // The xy workplane: origin (0, 0, 0), identity quaternion.
    for (h, v) in [1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0]
        .iter()
        .enumerate()
        .map(|(i, v)| (i as u32 + 1, if i == 3 { 1.0 } else { *v }))
    {
        sys.add_param(Param::new(h, 1, v)).expect("fresh handle");
    }
    sys.add_entity(Entity::point_3d(1, 1, [1, 2, 3]))
        .expect("fresh");
    sys.add_entity(Entity::normal_3d(2, 1, [4, 5, 6, 7]))
        .expect("fresh");
    sys.add_entity(Entity::workplane(CHAIN_WP, 1, 1, 2))
        .expect("fresh");

    let lengths: Vec<f64> = (0..n).map(|_| rng.uniform(5.0, 15.0)).collect();
    let turns: Vec<f64> = (1..n)
        .map(|_| {
            let t = rng.uniform(15.0, 45.0);
            if rng.next_u64() & 1 == 0 {
                t
            } else {
                -t
            }
        })
        .collect();
    let mut joints = Vec::with_capacity(n + 1);
    let (mut p, mut heading) = ([0.0f64, 0.0f64], 0.0f64);
    joints.push(p);
    for i in 0..n {
        if i > 0 {
            heading += turns[i - 1].to_radians();
        }
        p = [
            p[0] + lengths[i] * heading.cos(),
            p[1] + lengths[i] * heading.sin(),
        ];
        joints.push(p);
    }

    let g = CHAIN_GROUP;
    let mut segments = Vec::with_capacity(n);
    let mut ch = 0u32;
    let mut next_c = || {
        ch += 1;
        ch
    };
    for i in 0..n {
        let base = 100 + 4 * i as u32;
        let (ea, eb, el) = (10 + 3 * i as u32, 11 + 3 * i as u32, 12 + 3 * i as u32);
        for (k, q) in [joints[i], joints[i + 1]].into_iter().enumerate() {
            for (j, v) in q.into_iter().enumerate() {
                let h = base + 2 * k as u32 + j as u32;
                let v = v + rng.uniform(-perturb, perturb);
                sys.add_param(Param::new(h, g, v)).expect("fresh handle");
            }
        }
        sys.add_entity(Entity::point_2d(ea, g, CHAIN_WP, [base, base + 1]))
            .expect("fresh");
        sys.add_entity(Entity::point_2d(eb, g, CHAIN_WP, [base + 2, base + 3]))
            .expect("fresh");
        sys.add_entity(Entity::line(el, g, Some(CHAIN_WP), ea, eb))
            .expect("fresh");
        segments.push([ea, eb, el]);
    }
    let wp = Some(CHAIN_WP);
    let mut add = |c: Constraint| {
        sys.add_constraint(c.in_workplane(wp))
            .expect("fresh handle");
    };
    add(Constraint::new(next_c(), g, K::WhereDragged).with_points(segments[0][0], 0));
    add(Constraint::new(next_c(), g, K::Horizontal).with_entities([segments[0][2], 0, 0, 0]));
    for i in 0..n {
        let [a, b, _] = segments[i];
        add(Constraint::new(next_c(), g, K::PtPtDistance)
            .with_points(a, b)
            .with_val(lengths[i]));
        if i + 1 < n {
            let [a1, _, l1] = segments[i + 1];
            add(Constraint::new(next_c(), g, K::PointsCoincident).with_points(b, a1));
            add(Constraint::new(next_c(), g, K::Angle)
                .with_entities([segments[i][2], l1, 0, 0])
                .with_val(turns[i].abs()));
        }
    }
    // The where_dragged pins a_0 where it starts; start it on the exact origin so the exact
    // drawing is the solution. Its perturbation was drawn anyway to keep the stream simple.
    sys.set_value(100.into(), 0.0);
    sys.set_value(101.into(), 0.0);
    Chain {
        system: sys,
        group: GroupId(g),
        lengths,
        angles: turns.iter().map(|t| t.abs()).collect(),
        joints,
        segments,
    }
}
