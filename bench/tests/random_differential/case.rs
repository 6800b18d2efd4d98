//! One random system from one seed: its kind and variant follow from the seed, its geometry
//! from a PRNG seeded with it. The system is built at a true configuration (so every
//! constraint but a planted contradicting one holds there), then its start is perturbed.

use crate::gadgets::{self, Gadget};
use crate::rng::Rng;
use crate::sketch::{Dim, Sketch, GROUP};
use crate::steps;
use loci::{ConstraintId, ConstraintKind as K, EntityKind, ParamId, System};
use std::sync::OnceLock;

#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum Variant {
    /// Satisfiable, usually under-constrained.
    Base,
    /// Satisfiable, with constraints that follow from the others (with consistent values).
    Redundant,
    /// A constraint whose value contradicts the others.
    Conflicting,
}

impl Variant {
    pub fn name(self) -> &'static str {
        match self {
            Variant::Base => "base",
            Variant::Redundant => "redundant",
            Variant::Conflicting => "conflicting",
        }
    }
}

pub struct Case {
    pub seed: u64,
    pub dim: Dim,
    pub variant: Variant,
    /// The system at its (perturbed) start.
    pub system: System,
    /// The true value of every solved parameter.
    pub truth: Vec<(ParamId, f64)>,
    /// A second start, perturbed from the truth independently.
    pub restart: Vec<(ParamId, f64)>,
    /// The constraints the variant added: implied, or the contradicting one.
    pub planted: Vec<ConstraintId>,
    /// A dimension of a gadget, with a value that holds with the rest and one that
    /// contradicts it (in a conflicting case: the planted constraint, set contradicting).
    pub switch: Option<(ConstraintId, f64, f64)>,
    /// The gadgets built, in order.
    pub gadgets: Vec<Gadget>,
    /// The size of the drawing: the largest true coordinate or distance, at least its scale.
    pub size: f64,
    /// The scale it is drawn at (see [`drawing_scale`]).
    pub scale: f64,
}

impl Case {
    /// Whether the system can be solved (known by construction).
    pub fn satisfiable(&self) -> bool {
        self.variant != Variant::Conflicting
    }

    pub fn label(&self) -> String {
        let dim = match self.dim {
            Dim::Planar => "2D",
            Dim::Spatial => "3D",
        };
        let gadgets = if self.gadgets.is_empty() {
            String::new()
        } else {
            format!(" {:?}", self.gadgets)
        };
        format!(
            "{dim} {}{gadgets}, {} constraints, planted {:?}",
            self.variant.name(),
            self.system.constraints().len(),
            self.planted.iter().map(|h| h.0).collect::<Vec<_>>()
        )
    }
}

/// The kind and variant a seed stands for: the six combinations in turn.
pub fn kind_of(seed: u64) -> (Dim, Variant) {
    let dim = if seed % 2 == 0 {
        Dim::Planar
    } else {
        Dim::Spatial
    };
    let variant =
        [Variant::Base, Variant::Redundant, Variant::Conflicting][(seed / 2 % 3) as usize];
    (dim, variant)
}

/// Builds the case of `seed`, at the [`drawing_scale`].
pub fn case(seed: u64) -> Case {
    case_at(seed, drawing_scale())
}

/// Builds the case of `seed`, every length `scale` times its length at scale 1.
pub fn case_at(seed: u64, scale: f64) -> Case {
    let (dim, variant) = kind_of(seed);
    let mut s = Sketch::new(Rng::new(seed), dim);
    let planar = s.planar();
    // The gadgets, each flagged when it plants a contradiction.
    let mut plan: Vec<(Gadget, bool)> = Vec::new();
    let pick = |s: &mut Sketch, conflicting: bool| loop {
        let g = Gadget::REDUNDANT[s.rng.below(Gadget::REDUNDANT.len())];
        if g.fits(planar, conflicting) {
            return g;
        }
    };
    match variant {
        Variant::Base => {}
        Variant::Redundant => {
            for _ in 0..1 + s.rng.below(3) {
                plan.push((pick(&mut s, false), false));
            }
        }
        Variant::Conflicting => {
            plan.push((pick(&mut s, true), true));
            if s.rng.chance(0.3) {
                plan.push((pick(&mut s, false), false));
            }
        }
    }
    // Base constraints first, gadgets at random points among them, 5 to 40 in all (a gadget
    // adds up to 8).
    let reserve = 8 * plan.len();
    let target = 5usize.max(3 + s.rng.below(38 - reserve));
    let mut at: Vec<usize> = plan.iter().map(|_| s.rng.below(target + 1)).collect();
    at.sort_unstable();
    let mut planted = Vec::new();
    let mut switch = None;
    let mut next = 0;
    loop {
        while next < plan.len() && s.cons.len() >= at[next] {
            let (g, conflicting) = plan[next];
            let p = gadgets::build(&mut s, g, conflicting);
            planted.push(p.index);
            // The switch of a conflicting case is its contradiction's (if it has a value that
            // holds); of a redundant case, the first dimension planted.
            if let Some((good, bad)) = p.values {
                if conflicting || (variant == Variant::Redundant && switch.is_none()) {
                    switch = Some((p.index, good, bad));
                }
            }
            next += 1;
        }
        if s.cons.len() >= target && next == plan.len() {
            break;
        }
        steps::step(&mut s);
    }
    finish(s, seed, variant, plan, planted, switch, scale)
}

/// The scale every case is drawn at: 1, or `LOCI_DIFF_SCALE`. Each length of a case (a
/// coordinate, a distance, a diameter, a difference of lengths, how far a start is moved off)
/// is that many times its length at scale 1; angles and ratios are the same. The same systems
/// drawn in other units: metres (`0.001`) or microns (`1000`) instead of millimetres.
pub fn drawing_scale() -> f64 {
    static SCALE: OnceLock<f64> = OnceLock::new();
    *SCALE.get_or_init(|| {
        let Ok(v) = std::env::var("LOCI_DIFF_SCALE") else {
            return 1.0;
        };
        match v.trim().parse::<f64>() {
            Ok(k) if k > 0.0 && k.is_finite() => k,
            _ => panic!("LOCI_DIFF_SCALE={v}: expected a positive number"),
        }
    })
}

/// Whether a constraint's value is a length (scaled with the drawing) rather than an angle
/// or a ratio.
fn value_is_length(kind: K) -> bool {
    matches!(
        kind,
        K::PtPtDistance
            | K::PtPlaneDistance
            | K::PtLineDistance
            | K::PtFaceDistance
            | K::LengthDifference
            | K::Diameter
            | K::ProjPtDistance
            | K::ArcArcDifference
            | K::ArcLineDifference
    )
}

/// The parameters that are lengths: points' coordinates and distance entities (not a
/// normal's quaternion).
fn length_params(sys: &System) -> Vec<ParamId> {
    sys.entities()
        .iter()
        .filter(|e| {
            matches!(
                e.kind,
                EntityKind::PointIn3d { .. }
                    | EntityKind::PointIn2d { .. }
                    | EntityKind::Distance { .. }
            )
        })
        .flat_map(|e| e.kind.params().to_vec())
        .collect()
}

/// Scales every length of `sys` (points' coordinates, distance entities, length values) by
/// `k`, and the values of `switch` with its constraint's.
fn scale_lengths(
    sys: &mut System,
    k: f64,
    switch: &mut Option<(usize, f64, f64)>,
    handles: &[u32],
) {
    for p in length_params(sys) {
        let v = sys.value(p).expect("an entity's parameter");
        sys.set_value(p, v * k);
    }
    let kinds: Vec<(ConstraintId, K)> = sys.constraints().iter().map(|c| (c.h, c.kind)).collect();
    for (h, kind) in kinds {
        if value_is_length(kind) {
            sys.constraint_mut(h)
                .expect("a constraint of the system")
                .val *= k;
        }
    }
    if let Some((i, good, bad)) = switch {
        let h = ConstraintId(handles[*i]);
        if sys.constraint(h).is_some_and(|c| value_is_length(c.kind)) {
            *good *= k;
            *bad *= k;
        }
    }
}

fn finish(
    mut s: Sketch,
    seed: u64,
    variant: Variant,
    plan: Vec<(Gadget, bool)>,
    planted: Vec<usize>,
    mut switch: Option<(usize, f64, f64)>,
    k: f64,
) -> Case {
    // Constraints in a random order, numbered 1.. in that order.
    let n = s.cons.len();
    let mut order: Vec<usize> = (0..n).collect();
    for i in (1..n).rev() {
        order.swap(i, s.rng.below(i + 1));
    }
    let mut handle = vec![0u32; n];
    for (k, &i) in order.iter().enumerate() {
        handle[i] = k as u32 + 1;
        let mut c = s.cons[i].clone();
        c.h = ConstraintId(k as u32 + 1);
        s.sys.add_constraint(c).expect("a valid constraint");
    }
    if k != 1.0 {
        scale_lengths(&mut s.sys, k, &mut switch, &handle);
    }
    let truth: Vec<(ParamId, f64)> = s
        .sys
        .params()
        .iter()
        .filter(|p| p.group.0 == GROUP)
        .map(|p| (p.h, p.val))
        .collect();
    // Lengths only: a normal's quaternion has entries up to 1 at every scale.
    let size = length_params(&s.sys)
        .into_iter()
        .map(|p| s.sys.value(p).expect("an entity's parameter").abs())
        .fold(k, f64::max);
    let start = perturb(&mut s, &truth, k);
    let restart = perturb(&mut s, &truth, k);
    for &(p, v) in &start {
        s.sys.set_value(p, v);
    }
    Case {
        seed,
        dim: s.dim,
        variant,
        system: s.sys,
        truth,
        restart,
        planted: planted.iter().map(|&i| ConstraintId(handle[i])).collect(),
        switch: switch.map(|(i, good, bad)| (ConstraintId(handle[i]), good, bad)),
        gadgets: plan.into_iter().map(|(g, _)| g).collect(),
        size,
        scale: k,
    }
}

/// A start near the truth: every coordinate moved by a normal deviate of a drawn size (from
/// a nudge to a tenth of the drawing).
fn perturb(s: &mut Sketch, truth: &[(ParamId, f64)], scale: f64) -> Vec<(ParamId, f64)> {
    let sigma = [0.02, 0.1, 0.3, 1.0][s.rng.below(4)] * scale;
    truth
        .iter()
        .map(|&(p, v)| (p, v + sigma * s.rng.normal()))
        .collect()
}
