//! Assemblies: rigid components placed by poses, related by mates and joints, solved all at
//! once on the core solver.
//!
//! A component's pose is a translation and a unit quaternion; its references (faces, edges,
//! circular edges, vertices, axes, its frame) live in its own frame. Every mate is written
//! as core constraints between entities carried by the poses ([`build`]), so the core's
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
mod prim;
mod report;
mod stepped;

pub use angle::{AngleReading, ANGLE_TOLERANCE, MAX_ROTATION_PER_ITERATION};
pub use component::{Component, Pose, Reference, Shape};
pub use error::AssemblyError;
pub use mate::{AppliedRotation, Mate, MateKind, Persistent, Selection};
pub use report::{AssemblyReport, ComponentReport, MateReport, MateStatus};
pub use stepped::Iteration;

use crate::{diagnose, Config, GroupId, Member, Outcome, Solver};
use confirm::Checked;
use prim::{Prim, World};
use serde::{Deserialize, Serialize};

/// The largest error, in model units or radians, at which a mate missing the tolerance after
/// a solve that converged is taken for the rounding of reading the poses back (see
/// [`Assembly::solve`]) and solved on to [`POLISH`] times the tolerance.
const POLISH_UP_TO: f64 = 1e-6;

/// The tolerance, as a fraction of the assembly's, of the solve that goes on from the poses
/// read back.
const POLISH: f64 = 1e-3;

/// How an assembly solves. Every field has a documented default.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct Options {
    /// Positional tolerance: a mate holds when its relations are within this (model units).
    /// Default `1e-10`.
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

    /// Solves every mate at once and moves the free components; grounded ones never move.
    ///
    /// Directions more than a quarter turn from what their mates ask are first turned
    /// towards it with the stepped mode's rotations, so that Newton's least-movement steps
    /// then reach the requested branch (aligned or opposed, the signed angle), not its
    /// mirror. Poses are written back only when every mate that can hold does.
    ///
    /// # Errors
    /// A malformed assembly (duplicate names or ids, bad poses or options).
    pub fn solve(&mut self) -> Result<AssemblyReport, AssemblyError> {
        self.solve_checked(true)
    }

    /// [`Assembly::solve`]; a named conflict is checked by solving its mates alone
    /// ([`confirm`]) when `check`.
    fn solve_checked(&mut self, check: bool) -> Result<AssemblyReport, AssemblyError> {
        self.check()?;
        let o = &self.options;
        if !(o.tolerance > 0.0 && o.tolerance.is_finite()) {
            return Err(AssemblyError::BadOption {
                name: "tolerance",
                value: o.tolerance,
                expected: "a positive finite number",
            });
        }
        let compiled = self.compile_all();
        let start = self.poses();
        let movable = self.movable();
        let tol = self.options.tolerance;
        let atol = self.angle_tol();
        let within = |p: &Prim, e: f64| e <= if p.is_angular() { atol } else { tol };
        let err_of = |prims: &[Prim], poses: &[Pose]| -> (f64, bool) {
            let w = World { poses };
            let mut worst = 0.0f64;
            let mut ok = true;
            for p in prims {
                let e = p.error(&w);
                worst = worst.max(e);
                ok &= within(p, e);
            }
            (worst, ok)
        };
        let holds_before: Vec<bool> = compiled
            .iter()
            .map(|c| c.as_ref().is_ok_and(|p| err_of(p, &start).1))
            .collect();
        let active = |prims: &[Prim]| {
            prims.iter().any(|p| {
                let (a, b) = p.bodies();
                a.is_some_and(|i| movable[i]) || b.is_some_and(|i| movable[i])
            })
        };
        // The prims to solve, each with its mate.
        let mut prims: Vec<(usize, Prim)> = Vec::new();
        for (i, c) in compiled.iter().enumerate() {
            if let Ok(p) = c {
                if active(p) {
                    prims.extend(p.iter().map(|x| (i, *x)));
                }
            }
        }
        let mut aligned = start.clone();
        self.prealign(&prims, &mut aligned, &movable);
        let grounded: Vec<bool> = self.components.iter().map(|c| c.grounded).collect();
        let group = GroupId(build::FREE);
        let cfg = Config::default()
            .with_tolerance(tol)
            .with_max_iterations(self.options.max_iterations);
        // Signed angles are first written as one cheap perpendicularity, which also holds at
        // the angle's mirror about the axis and where B's direction lies along it. The answer
        // is then measured mate by mate; a solve that fails, or ends where some mate does not
        // hold, is done again with the angles written exactly, so that only an impossible
        // request is reported as one and its conflict is named between the mates that fight.
        let has_angles = prims
            .iter()
            .any(|(_, p)| matches!(p, Prim::SignedAngle { .. }));
        // With the diagnosis to follow, which names the conflicts of a failure again (and
        // builds the solution up when none is shown), the solve itself does not name them:
        // a conflict among a dozen mates took seconds to name, twice.
        let names_later = self.options.diagnose;
        let attempt = |exact: bool, name: bool| -> Result<_, AssemblyError> {
            let mut poses = aligned.clone();
            let built = build::build(&poses, &grounded, &prims, exact)?;
            let mut sys = built.sys;
            let has_free = sys.params().iter().any(|p| p.group == group);
            let mut report = crate::Report::empty();
            if has_free {
                // A failure of the quick form is solved again exactly, which names it.
                let mut cfg = cfg.clone();
                cfg.name_conflicts = name && (exact || !has_angles);
                report = Solver::new(group, &[], cfg.clone()).solve(&mut sys)?;
                if report.outcome.is_ok() {
                    build::read_poses(&sys, &built.poses, &mut poses);
                    // Poses are read as unit quaternions, which moves a point by the unit
                    // length's residual times its distance from the frame's origin, and a
                    // mate's error is a length where the solve bounds each row: a mate can
                    // read just over the tolerance at an answer the solve accepted. Newton
                    // goes on from the unit quaternions, to a tighter tolerance (a step or
                    // two from so close).
                    let w = World { poses: &poses };
                    let just_over = |p: &Prim| {
                        let e = p.error(&w);
                        !within(p, e) && e <= POLISH_UP_TO
                    };
                    if prims.iter().any(|(_, p)| just_over(p)) {
                        build::write_poses(&mut sys, &built.poses, &poses);
                        let tight = cfg.clone().with_tolerance(tol * POLISH);
                        let again = Solver::new(group, &[], tight).solve(&mut sys)?;
                        if again.outcome.is_ok() {
                            build::read_poses(&sys, &built.poses, &mut poses);
                            report.iterations += again.iterations;
                            report.residual = again.residual;
                        } else {
                            // The first answer stands, for the diagnosis too.
                            build::write_poses(&mut sys, &built.poses, &poses);
                        }
                    }
                } else {
                    poses = start.clone();
                }
            }
            Ok((sys, built.poses, built.owner, has_free, report, poses))
        };
        let mut solved = attempt(false, !names_later)?;
        if has_angles {
            let (_, _, _, _, report, poses) = &solved;
            let all_hold = report.outcome.is_ok()
                && prims
                    .iter()
                    .all(|(_, p)| within(p, p.error(&World { poses })));
            if !all_hold {
                solved = attempt(true, !names_later)?;
            }
        }
        let (sys, _, _, has_free, report, _) = &solved;
        let diag = if *has_free && self.options.diagnose {
            Some(diagnose(sys, group, &cfg)?)
        } else {
            None
        };
        // The diagnosis solved what the solve, not naming conflicts, gave up on (by building
        // it up one mate at a time): the solve again as it would have run alone, for the poses.
        if diag.as_ref().is_some_and(|d| d.outcome.is_ok()) && !report.outcome.is_ok() {
            solved = attempt(true, true)?;
        }
        let (sys, built_poses, owner, _, report, poses) = solved;
        let ids: Vec<String> = self.mates.iter().map(|m| m.id.clone()).collect();
        let sets = |members: &[Member]| mates_of(&owner, members);
        let (conflicts, redundant): (Vec<Vec<usize>>, Vec<Vec<usize>>) = match &diag {
            Some(d) => (
                d.conflicting
                    .iter()
                    .map(|c| conflict_mates(&sys, group, &owner, c, &cfg))
                    .collect::<Result<_, _>>()?,
                d.redundant.iter().map(|r| sets(&r.members)).collect(),
            ),
            None => {
                let failed: Vec<Member> = report
                    .failed
                    .iter()
                    .map(|&c| Member::Constraint(c))
                    .collect();
                match report.outcome {
                    Outcome::Inconsistent => (vec![sets(&failed)], Vec::new()),
                    Outcome::RedundantOkay => (Vec::new(), vec![sets(&failed)]),
                    _ => (Vec::new(), Vec::new()),
                }
            }
        };
        // A named set is checked by solving its mates alone, as an assembly of their own.
        let named = check
            && diag
                .as_ref()
                .is_some_and(|d| d.outcome == Outcome::Inconsistent)
            && !conflicts.is_empty();
        let mut disproved = false;
        let conflicts = if named {
            let solved: Vec<bool> = compiled
                .iter()
                .map(|c| c.as_ref().is_ok_and(|p| active(p)))
                .collect();
            match self.check_conflicts(conflicts, &solved) {
                Checked::Confirmed(sets) => sets,
                Checked::Disproved => {
                    disproved = true;
                    Vec::new()
                }
                Checked::Solved(found) => {
                    let (again, report) = *found;
                    *self = again;
                    return Ok(confirm::as_from_start(report, &holds_before));
                }
            }
        } else {
            conflicts
        };
        let in_conflict: Vec<bool> = (0..ids.len())
            .map(|i| conflicts.iter().any(|s| s.contains(&i)))
            .collect();
        let in_redundant: Vec<bool> = (0..ids.len())
            .map(|i| redundant.iter().any(|s| s.contains(&i)))
            .collect();

        // Mates, measured where the components end.
        let mut mates = Vec::new();
        for (i, c) in compiled.iter().enumerate() {
            let m = &self.mates[i];
            let mut r = MateReport {
                id: m.id.clone(),
                kind: m.kind.name().into(),
                status: MateStatus::Unsatisfied,
                value: None,
                error: 0.0,
                message: String::new(),
                limit_violated: false,
            };
            match c {
                Err(e) => {
                    r.status = match e {
                        AssemblyError::Unusable {
                            needed: "direction",
                            ..
                        } if matches!(m.kind, MateKind::Angle { .. }) => MateStatus::NoDirection,
                        AssemblyError::SameComponent { .. }
                            if matches!(m.kind, MateKind::Angle { .. }) =>
                        {
                            MateStatus::SameComponent
                        }
                        AssemblyError::NotAttached { .. }
                            if matches!(m.kind, MateKind::Angle { .. }) =>
                        {
                            MateStatus::NotAttached
                        }
                        _ => MateStatus::InvalidSelection,
                    };
                    r.error = f64::NAN;
                    r.message = e.to_string();
                }
                Ok(p) => {
                    let (e, ok) = err_of(p, &poses);
                    r.error = e;
                    r.status = if !active(p) {
                        if ok {
                            MateStatus::Satisfied
                        } else {
                            MateStatus::Blocked
                        }
                    } else if in_conflict[i] {
                        MateStatus::Conflicting
                    } else if !ok {
                        MateStatus::Unsatisfied
                    } else if in_redundant[i] {
                        MateStatus::Redundant
                    } else if holds_before[i] {
                        MateStatus::Satisfied
                    } else {
                        MateStatus::Adjusted
                    };
                    if r.status == MateStatus::Blocked {
                        r.message = "both components are grounded; unable to adjust".into();
                    }
                }
            }
            mates.push(r);
        }
        for (i, r) in mates.iter_mut().enumerate() {
            if let Ok(p) = &compiled[i] {
                measure(&mut self.mates[i], p, &poses, r);
            }
        }
        // Components.
        let mut components = Vec::new();
        for (i, c) in self.components.iter_mut().enumerate() {
            c.pose = poses[i];
            let (dof, motions) = match (&diag, built_poses[i]) {
                (Some(d), Some(pp)) => {
                    freedom::motions(d, &pp, poses[i].translation, poses[i].rotation)
                }
                _ => (0, Vec::new()),
            };
            components.push(ComponentReport {
                name: c.name.clone(),
                grounded: c.grounded,
                pose: poses[i],
                dof,
                motions,
            });
        }
        let name_sets = |s: Vec<Vec<usize>>| -> Vec<Vec<String>> {
            s.into_iter()
                .filter(|v| !v.is_empty())
                .map(|v| v.into_iter().map(|i| ids[i].clone()).collect())
                .collect()
        };
        Ok(AssemblyReport {
            outcome: if disproved {
                Outcome::DidNotConverge
            } else {
                diag.as_ref().map_or(report.outcome, |d| d.outcome)
            },
            dof: diag.as_ref().map_or(report.dof, |d| d.dof),
            iterations: report.iterations,
            residual: report.residual,
            mates,
            components,
            conflicts: name_sets(conflicts),
            redundant: name_sets(redundant),
        })
    }

    /// Turns directions that are more than a quarter turn from what their mates ask
    /// towards it, with the stepped mode's rotations (at most 200 passes).
    fn prealign(&self, prims: &[(usize, Prim)], poses: &mut [Pose], movable: &[bool]) {
        let directional: Vec<Prim> = prims
            .iter()
            .map(|p| p.1)
            .filter(|p| matches!(p, Prim::Parallel(..) | Prim::SignedAngle { .. }))
            .collect();
        let far = |poses: &[Pose]| {
            let w = World { poses };
            directional
                .iter()
                .any(|p| p.error(&w) > std::f64::consts::FRAC_PI_2 * 0.9)
        };
        if !far(poses) {
            return;
        }
        let names: Vec<String> = self.components.iter().map(|c| c.name.clone()).collect();
        let s = stepped::StepSettings {
            rotation_gain: 1.0,
            max_rotation: self.options.max_rotation_per_iteration.max(1e-3),
        };
        for _ in 0..200 {
            let w = World { poses };
            let worst = directional.iter().map(|p| p.error(&w)).fold(0.0, f64::max);
            if worst < std::f64::consts::FRAC_PI_4 {
                break;
            }
            stepped::step_prims(&directional, poses, movable, &names, &s);
        }
    }

    /// The seed's stepped relaxation: passes over the mates in order, each applying its
    /// capped, gain-scaled rotations and its translations, until every mate is within
    /// tolerance or [`Options::max_steps`] passes. Each pass is reported with the poses
    /// and every mate's error; each mate's rotations of the last pass are kept in its
    /// `persistent.last_applied_rotations`. The components end where the last pass left them.
    ///
    /// # Errors
    /// A malformed assembly.
    pub fn solve_stepped(&mut self) -> Result<SteppedRun, AssemblyError> {
        self.check()?;
        let compiled = self.compile_all();
        let movable = self.movable();
        let names: Vec<String> = self.components.iter().map(|c| c.name.clone()).collect();
        let mut poses = self.poses();
        let s = stepped::StepSettings {
            rotation_gain: self.options.rotation_gain.clamp(0.0, 1.0),
            max_rotation: self.options.max_rotation_per_iteration,
        };
        let tol = self.options.step_tolerance.max(self.options.tolerance);
        let atol = self.angle_tol().max(tol);
        let errors = |poses: &[Pose]| -> (Vec<f64>, bool) {
            let w = World { poses };
            let mut all = true;
            let e = compiled
                .iter()
                .map(|c| match c {
                    Ok(p) => p
                        .iter()
                        .map(|x| {
                            let e = x.error(&w);
                            let (a, b) = x.bodies();
                            let can =
                                a.is_some_and(|i| movable[i]) || b.is_some_and(|i| movable[i]);
                            if can && e > if x.is_angular() { atol } else { tol } {
                                all = false;
                            }
                            e
                        })
                        .fold(0.0, f64::max),
                    Err(_) => f64::NAN,
                })
                .collect();
            (e, all)
        };
        let mut iterations = Vec::new();
        let (_, mut converged) = errors(&poses);
        let mut index = 0;
        while !converged && index < self.options.max_steps {
            index += 1;
            for (i, c) in compiled.iter().enumerate() {
                if let Ok(p) = c {
                    self.mates[i].persistent.last_applied_rotations =
                        stepped::step_prims(p, &mut poses, &movable, &names, &s);
                }
            }
            let (e, ok) = errors(&poses);
            converged = ok;
            iterations.push(Iteration {
                index,
                poses: poses.clone(),
                errors: e,
            });
        }
        for (c, p) in self.components.iter_mut().zip(&poses) {
            c.pose = *p;
        }
        for (i, c) in compiled.iter().enumerate() {
            if let Ok(p) = c {
                let mut r = MateReport {
                    id: String::new(),
                    kind: String::new(),
                    status: MateStatus::Unsatisfied,
                    value: None,
                    error: 0.0,
                    message: String::new(),
                    limit_violated: false,
                };
                measure(&mut self.mates[i], p, &poses, &mut r);
            }
        }
        Ok(SteppedRun {
            iterations,
            converged,
        })
    }

    /// The seed's measurement of angle mate `id` at the current poses, also kept in its
    /// persistent data. `None` for an unknown id, a mate that is not an angle, or one whose
    /// selections are rejected.
    pub fn measure_angle(&mut self, id: &str) -> Option<AngleReading> {
        let poses = self.poses();
        let i = self.mates.iter().position(|m| m.id == id)?;
        let prims = self.compile_all().swap_remove(i).ok()?;
        let mut r = MateReport {
            id: String::new(),
            kind: String::new(),
            status: MateStatus::Unsatisfied,
            value: None,
            error: 0.0,
            message: String::new(),
            limit_violated: false,
        };
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

/// The mate a member of the core's system was written for, if any (`owner`: by constraint
/// handle, `usize::MAX` for none).
fn mate_of(owner: &[usize], m: &Member) -> Option<usize> {
    match m {
        Member::Constraint(c) => owner
            .get(c.0 as usize)
            .copied()
            .filter(|&m| m != usize::MAX),
        Member::Entity(_) => None,
    }
}

/// The mates `members` were written for, ascending, each once.
fn mates_of(owner: &[usize], members: &[Member]) -> Vec<usize> {
    let mut v: Vec<usize> = members.iter().filter_map(|m| mate_of(owner, m)).collect();
    v.sort_unstable();
    v.dedup();
    v
}

/// The mates of a conflict the core named among its constraints (`set`), minimal among
/// mates. A set minimal among constraints can hold a mate in part only, where that mate whole
/// stands in for others (a fastened joint's coincidence, with a concentric mate and a
/// distance, where the fastened joint and the distance conflict alone): the mates are then
/// shrunk whole ([`crate::minimal_groups`]). A set that holds each of its mates whole is
/// minimal among mates already, if the core verified it minimal among its constraints. One it
/// did not verify (the solver's own list, given when every set the core shrank was found to
/// hold alone) is shrunk among mates too: a random assembly's seven mates were named, yet six
/// of them, a perpendicular mate left out, could not hold either (loci named those six when
/// they were solved alone).
fn conflict_mates(
    sys: &crate::System,
    group: GroupId,
    owner: &[usize],
    set: &crate::ConflictSet,
    cfg: &Config,
) -> Result<Vec<usize>, AssemblyError> {
    let members = &set.members[..];
    let mates = mates_of(owner, members);
    if mates.len() <= 1 {
        return Ok(mates);
    }
    let mut of_mate = vec![Vec::new(); mates.len()];
    for c in sys.constraints().iter().filter(|c| c.group == group) {
        let member = Member::Constraint(c.h);
        if let Some(i) = mate_of(owner, &member).and_then(|m| mates.binary_search(&m).ok()) {
            of_mate[i].push(c.h);
        }
    }
    let whole = of_mate
        .iter()
        .flatten()
        .all(|&c| members.contains(&Member::Constraint(c)));
    if whole && set.verified {
        return Ok(mates);
    }
    Ok(match crate::minimal_groups(sys, group, &of_mate, cfg)? {
        Some(kept) => kept.into_iter().map(|i| mates[i]).collect(),
        None => mates,
    })
}
