//! Assemblies: rigid components placed by poses, related by mates and joints, solved all at
//! once on the core solver.
//!
//! A component's pose is a translation and a unit quaternion; its references (faces, edges,
//! circular edges, vertices, axes, its frame) live in its own frame. Every mate is written
//! as core constraints between entities carried by the poses (`build.rs`), so the core's
//! solve, degrees of freedom and conflict diagnosis apply unchanged: grounded components are
//! constants and never move, Newton's least-movement steps keep every part near where it
//! was, and [`Assembly::solve`] reports each mate's status and each component's remaining
//! motions. [`Assembly::solve_stepped`] runs the seed's one-mate-at-a-time relaxation
//! instead, reporting each iteration, for animation.
//!
//! ```
//! use loci::assembly::{Assembly, Component, Mate, MateKind, Pose, Reference, Selection};
//!
//! let mut asm = Assembly::new();
//! let axis = Reference::Axis { point: [0.0; 3], direction: [0.0, 0.0, 1.0] };
//! asm.add_component(Component::new("frame", Pose::IDENTITY).grounded().with("hinge", axis.clone()))?;
//! asm.add_component(Component::new("door", Pose::new([0.1, 0.0, 0.2], [1.0, 0.0, 0.0, 0.0])).with("hinge", axis))?;
//! asm.add_mate(Mate::new(MateKind::Revolute, Selection::on("frame", "hinge"), Selection::on("door", "hinge")))?;
//! let report = asm.solve()?;
//! assert!(report.all_hold());
//! assert_eq!(report.dof, 1);
//! assert_eq!(report.component("door").unwrap().motions, ["rotates about axis (0, 0, 1) through (0, 0, 0)"]);
//! # Ok::<(), loci::assembly::AssemblyError>(())
//! ```

pub mod angle;
mod build;
mod compile;
mod component;
mod confirm;
mod error;
mod freedom;
mod mate;
mod math;
mod place;
mod prim;
mod report;
mod solve;
mod stepped;

pub use angle::{AngleReading, ANGLE_TOLERANCE, MAX_ROTATION_PER_ITERATION};
pub use component::{Component, Pose, Reference, Shape};
pub use error::AssemblyError;
pub use mate::{AppliedRotation, Mate, MateKind, Persistent, Selection};
pub use report::{AssemblyReport, ComponentReport, MateReport, MateStatus};
pub use stepped::Iteration;

use prim::{Prim, World};
use serde::{Deserialize, Serialize};
/// How an assembly solves. Every field has a documented default.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct Options {
    /// Positional tolerance: a mate holds when its relations are within this (model units),
    /// or within the rounding of world positions for components far from the origin
    /// ([`crate::Config::tolerance_at`]). Default `1e-10`.
    pub tolerance: f64,
    /// Angular tolerance in radians for reporting angle mates; without it, ten times
    /// `tolerance`, never below [`ANGLE_TOLERANCE`]. Default none.
    pub angle_tolerance: Option<f64>,
    /// The stepped mode's gain on each rotation, in `[0, 1]`. Default `1`.
    pub rotation_gain: f64,
    /// The stepped mode's cap on one rotation, radians. Default
    /// [`MAX_ROTATION_PER_ITERATION`].
    pub max_rotation_per_iteration: f64,
    /// The stepped mode's largest number of passes. Default `2000`.
    pub max_steps: usize,
    /// The stepped mode stops when every mate is within this (lengths; angles use the
    /// angular tolerance, never below this). Default `1e-6`.
    pub step_tolerance: f64,
    /// Whether the report names conflicts and redundancies as minimal sets and describes every
    /// component's motions (a diagnosis after the solve). Default `true`.
    pub diagnose: bool,
    /// Newton iterations at most. Default `100`.
    pub max_iterations: usize,
}

impl Default for Options {
    fn default() -> Self {
        Self {
            tolerance: 1e-10,
            angle_tolerance: None,
            rotation_gain: 1.0,
            max_rotation_per_iteration: MAX_ROTATION_PER_ITERATION,
            max_steps: 2000,
            step_tolerance: 1e-6,
            diagnose: true,
            max_iterations: 100,
        }
    }
}

/// Components, world references and mates.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct Assembly {
    /// The components, in order.
    #[serde(default)]
    pub components: Vec<Component>,
    /// References fixed in the world, attached to no component.
    #[serde(
        default,
        with = "component::named",
        skip_serializing_if = "Vec::is_empty"
    )]
    pub world: Vec<(String, Reference)>,
    /// The mates and joints, in order.
    #[serde(default)]
    pub mates: Vec<Mate>,
    /// How it solves.
    #[serde(default)]
    pub options: Options,
}

/// What the stepped mode did.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct SteppedRun {
    /// Every pass, in order.
    pub iterations: Vec<Iteration>,
    /// Whether every mate came within tolerance.
    pub converged: bool,
}

impl Assembly {
    /// An empty assembly.
    #[must_use]
    pub fn new() -> Self {
        Self::default()
    }

    /// Adds a component; returns its index.
    ///
    /// # Errors
    /// A name already used, a pose that is not finite with a unit rotation, or a reference
    /// with a number that is not finite.
    pub fn add_component(&mut self, c: Component) -> Result<usize, AssemblyError> {
        check_component(&c)?;
        if self.components.iter().any(|x| x.name == c.name) {
            return Err(AssemblyError::DuplicateComponent(c.name));
        }
        self.components.push(c);
        Ok(self.components.len() - 1)
    }

    /// Adds a reference fixed in the world.
    pub fn add_world_reference(&mut self, name: &str, r: Reference) {
        self.world.push((name.into(), r));
    }

    /// Adds a mate; an empty id is given one (`ANGL3` for the third angle mate). Returns the id.
    ///
    /// # Errors
    /// An id already used.
    pub fn add_mate(&mut self, mut m: Mate) -> Result<String, AssemblyError> {
        if m.id.is_empty() {
            let prefix = m.kind.id_prefix();
            let n = self
                .mates
                .iter()
                .filter(|x| x.kind.id_prefix() == prefix)
                .count();
            let mut k = n + 1;
            loop {
                let id = format!("{prefix}{k}");
                if !self.mates.iter().any(|x| x.id == id) {
                    m.id = id;
                    break;
                }
                k += 1;
            }
        }
        if self.mates.iter().any(|x| x.id == m.id) {
            return Err(AssemblyError::DuplicateMate(m.id));
        }
        let id = m.id.clone();
        self.mates.push(m);
        Ok(id)
    }

    /// The component named `name`.
    #[must_use]
    pub fn component(&self, name: &str) -> Option<&Component> {
        self.components.iter().find(|c| c.name == name)
    }

    /// The mate with id `id`.
    #[must_use]
    pub fn mate(&self, id: &str) -> Option<&Mate> {
        self.mates.iter().find(|m| m.id == id)
    }

    fn check(&mut self) -> Result<(), AssemblyError> {
        let mut names = rustc_hash::FxHashSet::default();
        for c in &self.components {
            check_component(c)?;
            if !names.insert(c.name.as_str()) {
                return Err(AssemblyError::DuplicateComponent(c.name.clone()));
            }
        }
        let mut counts = rustc_hash::FxHashMap::default();
        for m in &mut self.mates {
            let n = counts.entry(m.kind.id_prefix()).or_insert(0usize);
            *n += 1;
            if m.id.is_empty() {
                m.id = format!("{}{}", m.kind.id_prefix(), n);
            }
        }
        // Borrowed, not copied: every solve checks them.
        let mut ids = rustc_hash::FxHashSet::default();
        ids.reserve(self.mates.len());
        for m in &self.mates {
            if !ids.insert(m.id.as_str()) {
                return Err(AssemblyError::DuplicateMate(m.id.clone()));
            }
        }
        Ok(())
    }

    fn poses(&self) -> Vec<Pose> {
        self.components.iter().map(|c| c.pose).collect()
    }

    fn movable(&self) -> Vec<bool> {
        self.components.iter().map(|c| !c.grounded).collect()
    }

    /// Every mate's relations, or why it has none.
    fn compile_all(&mut self) -> Vec<Result<Vec<Prim>, AssemblyError>> {
        let poses = self.poses();
        let (components, world) = (&self.components, &self.world);
        let index: rustc_hash::FxHashMap<&str, usize> = components
            .iter()
            .enumerate()
            .map(|(i, c)| (c.name.as_str(), i))
            .collect();
        let is_angle = |m: &Mate| matches!(m.kind, MateKind::Angle { .. });
        let mut out: Vec<Result<Vec<Prim>, AssemblyError>> = self
            .mates
            .iter_mut()
            .map(|m| {
                if is_angle(m) {
                    Ok(Vec::new())
                } else {
                    compile::compile(components, &index, world, &poses, m, &Default::default())
                }
            })
            .collect();
        // Angle mates last: a hinge's axis is the natural reference axis of an angle about it.
        let mut hints: rustc_hash::FxHashMap<(prim::Body, prim::Body), Vec<_>> =
            rustc_hash::FxHashMap::default();
        for p in out.iter().flatten().flatten() {
            if let Prim::Parallel(a, b, _) = p {
                let key = if a.body <= b.body {
                    (a.body, b.body)
                } else {
                    (b.body, a.body)
                };
                hints.entry(key).or_default().push((*a, *b));
            }
        }
        for (m, o) in self.mates.iter_mut().zip(out.iter_mut()) {
            if is_angle(m) {
                *o = compile::compile(components, &index, world, &poses, m, &hints);
            }
        }
        out
    }

    fn angle_tol(&self) -> f64 {
        angle::angle_tolerance(self.options.angle_tolerance, self.options.tolerance)
    }

    /// The tolerance a mate's positional error is held to: [`Options::tolerance`], or,
    /// for components so far from the origin that world positions cannot be stored that
    /// finely, their rounding, as the solver holds its residuals to it
    /// ([`crate::Config::tolerance_at`]; a coincident mate 1e7 from the origin is met to
    /// 9.3e-10 at best). Angles are measured between unit directions, whose rounding does not
    /// grow with the distance.
    fn position_tol(&self) -> f64 {
        let largest = |v: [f64; 3]| v.iter().fold(0.0f64, |m, x| m.max(x.abs()));
        let size = self
            .components
            .iter()
            .map(|c| {
                let reach = c
                    .references
                    .iter()
                    .fold(0.0f64, |m, (_, r)| m.max(largest(r.point())));
                largest(c.pose.translation) + reach
            })
            .fold(0.0f64, f64::max);
        crate::Config::default()
            .with_tolerance(self.options.tolerance)
            .tolerance_at(size)
    }

    /// The seed's measurement of angle mate `id` at the current poses, also kept in its
    /// persistent data. `None` for an unknown id, a mate that is not an angle, or one whose
    /// selections are rejected.
    pub fn measure_angle(&mut self, id: &str) -> Option<AngleReading> {
        let poses = self.poses();
        let i = self.mates.iter().position(|m| m.id == id)?;
        let prims = self.compile_all().swap_remove(i).ok()?;
        let mut r = MateReport::unmeasured(String::new(), String::new());
        measure(&mut self.mates[i], &prims, &poses, &mut r);
        angle_reading(&prims, &poses)
    }
}

fn check_component(c: &Component) -> Result<(), AssemblyError> {
    if !c.pose.is_valid() {
        return Err(AssemblyError::BadPose(c.name.clone()));
    }
    for (n, r) in &c.references {
        if !r.is_finite() {
            return Err(AssemblyError::BadReference {
                component: c.name.clone(),
                reference: n.clone(),
            });
        }
    }
    Ok(())
}

fn angle_reading(prims: &[Prim], poses: &[Pose]) -> Option<AngleReading> {
    let w = World { poses };
    prims.iter().find_map(|p| match *p {
        Prim::SignedAngle { a, b, axis, target } => {
            let (da, db) = (w.dir(&a), w.dir(&b));
            let n = w.pose(a.body).direction(axis);
            let signed = prim::signed_angle(da, db, n);
            let angle = math::angle_between(da, db);
            Some(AngleReading {
                angle,
                angle_deg: angle.to_degrees(),
                signed,
                signed_deg: signed.to_degrees(),
                error: prim::wrap(signed - target),
            })
        }
        _ => None,
    })
}

/// A mate's value where the components are, kept in its persistent data; joint limits.
fn measure(m: &mut Mate, prims: &[Prim], poses: &[Pose], r: &mut MateReport) {
    let w = World { poses };
    let value = match m.kind {
        MateKind::Angle { .. } => angle_reading(prims, poses).map(|a| {
            m.persistent.angle_rad = Some(a.signed);
            m.persistent.angle_deg = Some(a.signed_deg);
            a.signed_deg
        }),
        MateKind::Distance { .. } => prims.iter().rev().find_map(|p| match p {
            Prim::PtPtDistance(a, b, _) => Some(math::norm(math::sub(w.point(b), w.point(a)))),
            Prim::PtPlaneDistance(p, l, _) => Some(prim::plane_offset(&w, p, l)),
            Prim::PtLineDistance(p, l, _) => Some(prim::line_offset(&w, p, l)),
            Prim::Coincident(a, b) => Some(math::norm(math::sub(w.point(b), w.point(a)))),
            Prim::OnLine(p, l) => Some(prim::line_offset(&w, p, l)),
            Prim::InPlane(p, l) => Some(prim::plane_offset(&w, p, l)),
            _ => None,
        }),
        MateKind::Revolute => match (
            prims.first(),
            prims.get(1),
            m.persistent.axis,
            m.persistent.axis_b,
        ) {
            (Some(Prim::Coincident(..)), Some(Prim::Parallel(da, db, _)), Some(ua), Some(ub)) => {
                let n = w.dir(da);
                let ua = w.pose(da.body).direction(ua);
                let ub = w.pose(db.body).direction(ub);
                let a = prim::signed_angle(ua, ub, n);
                m.persistent.angle_rad = Some(a);
                m.persistent.angle_deg = Some(a.to_degrees());
                Some(a.to_degrees())
            }
            _ => None,
        },
        MateKind::Slider => match prims.get(1) {
            Some(Prim::OnLine(p, l)) => {
                let d = w.dir(&l.dir());
                Some(math::dot(math::sub(w.point(p), w.point(&l.point())), d))
            }
            _ => None,
        },
        _ => None,
    };
    m.persistent.measured = value;
    r.value = value;
    if let (Some(v), Some([lo, hi])) = (value, m.limits) {
        if v < lo - 1e-9 || v > hi + 1e-9 {
            r.limit_violated = true;
            r.message = format!("joint limit [{lo}, {hi}] violated: {}", report::round(v));
        }
    }
}
