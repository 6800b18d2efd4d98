//! Dragging: a shape follows the cursor as closely as the constraints allow while the rest
//! moves as little as possible, with soft constraints on, and never flips.
//!
//! A [`Drag`] writes the soft constraints once and keeps one [`Solver`]: consecutive steps
//! change values only, so they reuse the compiled equations, ordering and factorisation,
//! and components the drag does not touch are not solved. After each step the orientation
//! of every triangle of lines and point-to-point distances, the bend of every hinge of two
//! of them (see [`super::bars`]), the direction of every arc and the side of every tangency
//! (see [`super::sides`]) is compared with before; a step that would turn one over (or that
//! fails) is undone and taken in shorter pieces. A step that stops short, its cursor beyond
//! reach, then takes the grip toward the cursor as far as the constraints let it.

use super::bars::Bars;
use super::sides::Side;
use super::soft::SoftRec;
use super::{ArcId, PointId, ShapeId, ShapeKind, Sketch, SketchError};
use crate::solve::{Outcome, Solver};

/// The shortest piece of a step tried, as a fraction of it, before giving up.
const SHORTEST_PIECE: f64 = 1.0 / 64.0;

/// The most Newton iterations a piece of a step takes before it is taken shorter. Pieces of
/// random linkages dragged along random paths that solved took 3 to 15 iterations, a few up
/// to 64; shorter pieces take fewer.
const PIECE_ITERATIONS: usize = 50;

/// A hinge may bend the other way in one piece of a step only while it is this close to
/// straight (the change of the sine of its angle): passing through straight, it does so in
/// short pieces; further, it jumped to the linkage's other branch. Dragged by 3 in one step, a
/// two-link arm of 2.6 and 2.6 reached the cursor with its elbow the other way round (sines
/// 0.999 and -0.987) where the straight path there stays within reach (random drags, seed
/// 603). A free polyline's corner dragged across the line of its neighbours passes in pieces.
///
/// Only in the shortest piece tried may a hinge change branch: there no shorter piece would
/// keep it, because the place the grip can reach nearest the cursor itself jumps. A crank's
/// pin dragged straight across its pivot swings round to the other side as the cursor passes
/// the pivot, bending the coupler's hinge the other way (`loci drag four_bar.json --point B
/// --to=-1,0`). Triangles, arcs and tangent sides never turn over, in any piece.
const BENT: f64 = 0.1;

/// The relative step size of the dragged parameters (see [`crate::Config::dragged_scale`]).
const DRAGGED_SCALE: f64 = 1e-4;

/// How many times a step that stopped short tries to reach toward the cursor (see
/// [`Drag::reach`]), halving the way each time.
const REACH_TRIES: usize = 4;

/// How much the grip weighs in a solve of a drag: far more than the rest (a step), or as much
/// (reaching toward a cursor beyond reach, see [`Drag::reach`]).
#[derive(Clone, Copy)]
enum Grip {
    Heavy,
    Even,
}

/// What a drag keeps of the sketch's shape to compare after a piece of a step: signed areas
/// of triangles and sides of tangencies (`turns`), sines of hinges' bends, arcs' sweeps.
struct Senses {
    turns: Vec<f64>,
    bends: Vec<f64>,
    sweeps: Vec<f64>,
}

/// What one drag step did.
#[derive(Clone, Debug, PartialEq)]
pub struct DragStep {
    /// The outcome of the last solve (of the last piece tried).
    pub outcome: Outcome,
    /// Whether the whole step was taken; false when a piece of it could not be taken without a
    /// failure or a flip, however short (the grip then goes toward the cursor as far as the
    /// constraints let it, or stays where the last good piece left it).
    pub reached: bool,
    /// Pieces solved and kept.
    pub pieces: usize,
    /// Pieces undone because they failed or would have flipped something.
    pub refused: usize,
    /// Pieces undone because they would have flipped a triangle, a hinge's bend, an arc or a
    /// tangent side.
    pub flips_prevented: usize,
    /// Where the dragged shape's grip ended.
    pub at: [f64; 2],
    /// How far that is from the target.
    pub miss: f64,
}

/// A drag in progress; ends (taking its soft constraints out) when dropped.
///
/// [`Sketch::begin_drag`] borrows the sketch for the drag; [`Sketch::into_drag`] hands the
/// sketch to the drag, which gives it back from [`Drag::into_sketch`]: a drag that lives
/// between calls of another language (a browser's mouse events) cannot hold a borrow.
pub struct Drag<'a> {
    sketch: Held<'a>,
    points: Vec<PointId>,
    soft: Vec<SoftRec>,
    solver: Solver,
    /// The same solve with the grip weighing as much as the rest: where the cursor is beyond
    /// reach (see [`Drag::reach`]).
    reacher: Solver,
    /// Positions of the coordinates of the grip's points, x then y.
    grip_ix: Vec<[usize; 2]>,
    /// Positions of the coordinates of each triangle's corners.
    triangles: Vec<[[usize; 2]; 3]>,
    /// Positions of the coordinates of each hinge's points, `[a, b, c]` with bars `b`–`a`
    /// and `b`–`c`.
    hinges: Vec<[[usize; 2]; 3]>,
    /// Positions of the coordinates of each arc's centre, start and end.
    arcs: Vec<[[usize; 2]; 3]>,
    /// Tangencies whose side (of a line, or outside/inside another round) is kept.
    sides: Vec<Side>,
    /// Fixed points' coordinates: parameters, positions and values.
    fixed: Vec<(crate::ParamId, usize, f64)>,
    /// Every circle's radius parameter and its position, turned positive after each step
    /// ([`Sketch::positive_radii`]).
    radii: Vec<(crate::ParamId, usize)>,
    /// The system revision the solver compiled, once it has.
    compiled: Option<u64>,
}

/// The sketch a drag moves: borrowed from the caller or owned by the drag.
enum Held<'a> {
    Borrowed(&'a mut Sketch),
    Owned(Box<Sketch>),
    /// Between [`Drag::into_sketch`] taking the sketch out and the drag's end; never read.
    Gone,
}

impl std::ops::Deref for Held<'_> {
    type Target = Sketch;
    fn deref(&self) -> &Sketch {
        match self {
            Held::Borrowed(s) => s,
            Held::Owned(s) => s,
            Held::Gone => unreachable!("a drag's sketch is read only while the drag holds it"),
        }
    }
}

impl std::ops::DerefMut for Held<'_> {
    fn deref_mut(&mut self) -> &mut Sketch {
        match self {
            Held::Borrowed(s) => s,
            Held::Owned(s) => s,
            Held::Gone => unreachable!("a drag's sketch is read only while the drag holds it"),
        }
    }
}

impl Sketch {
    /// Starts dragging a shape as [`Sketch::begin_drag`] does, handing the sketch to the drag
    /// (get it back with [`Drag::into_sketch`]).
    ///
    /// # Errors
    /// As [`Sketch::begin_drag`]; the sketch comes back unchanged with the error.
    pub fn into_drag(
        mut self,
        shape: impl Into<ShapeId>,
    ) -> Result<Drag<'static>, (Box<Sketch>, SketchError)> {
        match self.start_drag(shape.into()) {
            Ok(mut d) => {
                d.sketch = Held::Owned(Box::new(self));
                Ok(d)
            }
            Err(e) => Err((Box::new(self), e)),
        }
    }

    /// Starts dragging a shape: a point, or a whole line, circle, arc or cubic (its grip is its
    /// midpoint, centre or the mean of its control points).
    ///
    /// # Errors
    /// No such shape, or one with a fixed point.
    pub fn begin_drag(&mut self, shape: impl Into<ShapeId>) -> Result<Drag<'_>, SketchError> {
        let mut d: Drag<'_> = self.start_drag(shape.into())?;
        d.sketch = Held::Borrowed(self);
        Ok(d)
    }

    /// Everything of a drag but its hold on the sketch, which the caller gives it: the soft
    /// constraints are written, so the drag returned must be given the sketch.
    fn start_drag(&mut self, shape: ShapeId) -> Result<Drag<'static>, SketchError> {
        self.kind(shape).ok_or(SketchError::NoShape(shape))?;
        let points = self.defining_points(shape);
        let fixed = self.fixed_points();
        if points.iter().any(|p| fixed.contains(p)) {
            return Err(SketchError::Fixed(shape));
        }
        let params: Vec<_> = points.iter().flat_map(|p| self.point_params(*p)).collect();
        // The grip should reach the cursor wherever the constraints allow: its parameters
        // weigh far more than the rest. A drag step is short, so the minimum-norm Newton steps
        // from where the sketch is already land next to the nearest solution; sliding along the
        // solutions to the exact nearest one (`Config::nearest`) cost a chain of 1,000 hinged
        // triangles up to 3.9 ms on single steps for no visible difference.
        let scale = self.cfg.dragged_scale.min(DRAGGED_SCALE);
        // A piece that fails is taken again shorter, which is the drag's answer to a failure:
        // the solver's own (checking the verdict, building the solution up, starting from
        // further off) took 1,000 iterations and more a piece, 96% of the time of random
        // linkages dragged beyond their reach, where they stretch to a singular pose.
        let cfg = self
            .cfg
            .clone()
            .with_find_failed(false)
            .with_failure_checks(false)
            .with_max_iterations(self.cfg.max_iterations.min(PIECE_ITERATIONS))
            .with_nearest(false)
            .with_dragged_scale(scale);
        self.restore_fixed();
        let ix = |p: PointId| self.point_indexes(p);
        let bars = Bars::of(self);
        let triangles = bars.triangles().into_iter().map(|t| t.map(ix)).collect();
        let hinges = bars.hinges().into_iter().map(|t| t.map(ix)).collect();
        let arcs = self
            .shapes()
            .filter(|(_, k)| *k == ShapeKind::Arc)
            .map(|(s, _)| self.arc_points(ArcId(s.0)).map(ix))
            .collect();
        let sides = self.tangent_sides();
        let grip_ix = match self.kind(shape) {
            Some(ShapeKind::Circle | ShapeKind::Arc) => vec![ix(points[0])],
            _ => points.iter().map(|p| ix(*p)).collect(),
        };
        let fixed = self
            .fixed_points()
            .into_iter()
            .flat_map(|p| {
                let ([i, j], [pi, pj]) = (ix(p), self.point_params(p));
                let v = self.sys.params();
                [(pi, i, v[i].val), (pj, j, v[j].val)]
            })
            .collect();
        let soft = self.add_soft()?;
        Ok(Drag {
            sketch: Held::Gone,
            points,
            soft,
            reacher: Solver::new(Self::SHAPE_GROUP, &[], cfg.clone()),
            solver: Solver::new(Self::SHAPE_GROUP, &params, cfg),
            grip_ix,
            triangles,
            hinges,
            arcs,
            sides,
            fixed,
            radii: self.circle_radii(),
            compiled: None,
        })
    }

    /// Drags a shape's grip toward `target` in one step (see [`Sketch::begin_drag`]).
    ///
    /// # Errors
    /// As [`Sketch::begin_drag`] and [`Drag::step`].
    pub fn drag(
        &mut self,
        shape: impl Into<ShapeId>,
        target: [f64; 2],
    ) -> Result<DragStep, SketchError> {
        self.begin_drag(shape)?.step(target)
    }
}

/// The point a fraction `t` of the way from `a` to `b`.
fn toward(a: [f64; 2], b: [f64; 2], t: f64) -> [f64; 2] {
    [a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])]
}

fn area(p: [[f64; 2]; 3]) -> f64 {
    (p[1][0] - p[0][0]) * (p[2][1] - p[0][1]) - (p[1][1] - p[0][1]) * (p[2][0] - p[0][0])
}

impl Drag<'_> {
    /// The grip of the dragged shape, where it is now.
    #[must_use]
    pub fn grip(&self) -> [f64; 2] {
        let v = self.sketch.sys.params();
        let n = self.grip_ix.len() as f64;
        let sum = self
            .grip_ix
            .iter()
            .fold([0.0, 0.0], |a, [i, j]| [a[0] + v[*i].val, a[1] + v[*j].val]);
        [sum[0] / n, sum[1] / n]
    }

    /// The sketch being dragged, to read coordinates between steps.
    #[must_use]
    pub fn sketch(&self) -> &Sketch {
        &self.sketch
    }

    /// Moves the grip toward `target`: the whole way in one solve when that flips nothing,
    /// else in shorter pieces.
    ///
    /// # Errors
    /// A target that is not finite, or a solver that cannot start.
    pub fn step(&mut self, target: [f64; 2]) -> Result<DragStep, SketchError> {
        for v in target {
            if !(v.is_finite() && v.abs() <= crate::MAX_MAGNITUDE) {
                return Err(SketchError::BadValue {
                    what: "drag target",
                    value: v,
                    expected: "a finite number of size at most 1e100",
                });
            }
        }
        let start = self.grip();
        let (mut done, mut piece) = (0.0f64, 1.0f64);
        let mut step = DragStep {
            outcome: Outcome::Okay,
            reached: false,
            pieces: 0,
            refused: 0,
            flips_prevented: 0,
            at: start,
            miss: 0.0,
        };
        while done < 1.0 {
            let next = (done + piece).min(1.0);
            let goal = toward(start, target, next);
            let (outcome, flipped) = self.attempt(goal, piece <= SHORTEST_PIECE, Grip::Heavy)?;
            step.outcome = outcome;
            if outcome.is_ok() && !flipped {
                done = next;
                step.pieces += 1;
                piece = (piece * 2.0).min(1.0);
            } else {
                step.refused += 1;
                step.flips_prevented += usize::from(flipped);
                piece /= 2.0;
                if piece < SHORTEST_PIECE {
                    break;
                }
            }
        }
        step.reached = done >= 1.0;
        if !step.reached {
            self.reach(target, &mut step)?;
        }
        // The grip's parameters weigh much more than the rest, but not infinitely: when the
        // target is within reach the grip stops a hair short of it (about 1e-8 of the step,
        // the square of their relative weight). Only when it stops further short than that
        // (a millionth of the step), one more solve from there closes the gap; a target out
        // of reach stays far and costs nothing more.
        let span = (target[0] - start[0]).hypot(target[1] - start[1]);
        let grip = self.grip();
        let miss = (grip[0] - target[0]).hypot(grip[1] - target[1]);
        if step.reached && miss > 1e-6 * span && miss < 1e-3 * span {
            let (outcome, flipped) = self.attempt(target, false, Grip::Heavy)?;
            if outcome.is_ok() && !flipped {
                step.pieces += 1;
            }
        }
        step.at = self.grip();
        step.miss = (step.at[0] - target[0]).hypot(step.at[1] - target[1]);
        Ok(step)
    }

    /// Where a step stopped short, a cursor beyond reach: the grip goes toward it as far as
    /// the constraints let it. With the grip weighing far more than the rest, a linkage
    /// stretched toward the cursor cannot follow it round: every solve from a grip put beyond
    /// reach fails (the rest cannot take up the stretch, and moving the grip costs 1e8 times
    /// more), and a two-link arm stopped where it first straightened. Solved with the grip
    /// weighing as much as the rest, the linkage comes to rest near the place of the drawing
    /// nearest the one asked for, its grip toward the cursor; the way is halved up to
    /// [`REACH_TRIES`] times, and a solve that fails or flips anything is undone as in a step.
    fn reach(&mut self, target: [f64; 2], step: &mut DragStep) -> Result<(), SketchError> {
        let from = self.grip();
        let mut part = 1.0;
        for _ in 0..REACH_TRIES {
            let goal = toward(from, target, part);
            let (outcome, flipped) = self.attempt(goal, false, Grip::Even)?;
            if outcome.is_ok() && !flipped {
                step.outcome = outcome;
                step.pieces += 1;
                return Ok(());
            }
            step.refused += 1;
            step.flips_prevented += usize::from(flipped);
            part /= 2.0;
        }
        Ok(())
    }

    /// One solve with the grip put at `goal`; undone when it fails or flips something (a hinge's
    /// bend counts unless `bends_may_turn`), solved with the grip weighing as `weight` says.
    fn attempt(
        &mut self,
        goal: [f64; 2],
        bends_may_turn: bool,
        weight: Grip,
    ) -> Result<(Outcome, bool), SketchError> {
        let snapshot: Vec<f64> = self.sketch.sys.params().iter().map(|p| p.val).collect();
        let soft_values = self.sketch.soft_values(&self.soft);
        let before = self.orientation();
        let grip = self.grip();
        let d = [goal[0] - grip[0], goal[1] - grip[1]];
        for p in &self.points {
            let [x, y] = self.sketch.point(*p);
            self.sketch.move_point(*p, [x + d[0], y + d[1]])?;
        }
        let compiling = self.compiled != Some(self.sketch.sys.revision());
        if compiling {
            self.sketch.restore_fixed();
        }
        for &(p, i, want) in &self.fixed {
            if self.sketch.sys.params()[i].val.to_bits() != want.to_bits() {
                self.sketch.sys.set_value(p, want);
            }
        }
        self.sketch.write_soft(&self.soft, &soft_values);
        let solver = match weight {
            Grip::Heavy => &mut self.solver,
            Grip::Even => &mut self.reacher,
        };
        let report = solver.solve(&mut self.sketch.sys)?;
        self.compiled = Some(self.sketch.sys.revision());
        let flipped = report.outcome.is_ok() && self.flipped(&before, bends_may_turn);
        if !report.outcome.is_ok() || flipped {
            for (v, s) in self.sketch.sys.values_mut().zip(&snapshot) {
                *v = *s;
            }
        } else {
            self.sketch.positive_radii(&self.radii);
        }
        Ok((report.outcome, flipped))
    }

    /// Signed areas of the triangles and signed sides of the tangencies, sines of the hinges'
    /// bends, and sweeps of the arcs.
    fn orientation(&self) -> Senses {
        let v = self.sketch.sys.params();
        let xy = |[i, j]: [usize; 2]| [v[i].val, v[j].val];
        let turns = self
            .triangles
            .iter()
            .map(|t| area(t.map(xy)))
            .chain(self.sides.iter().map(|s| s.measure(v)))
            .collect();
        let bends = self
            .hinges
            .iter()
            .map(|h| {
                let [a, b, c] = h.map(xy);
                let (u, w) = ([a[0] - b[0], a[1] - b[1]], [c[0] - b[0], c[1] - b[1]]);
                let arms = ((u[0] * u[0] + u[1] * u[1]) * (w[0] * w[0] + w[1] * w[1])).sqrt();
                if arms > 0.0 {
                    (u[0] * w[1] - u[1] * w[0]) / arms
                } else {
                    0.0
                }
            })
            .collect();
        let sweeps = self
            .arcs
            .iter()
            .map(|a| {
                let [c, s, e] = a.map(xy);
                let start = (s[1] - c[1]).atan2(s[0] - c[0]);
                let end = (e[1] - c[1]).atan2(e[0] - c[0]);
                (end - start).to_degrees().rem_euclid(360.0)
            })
            .collect();
        Senses {
            turns,
            bends,
            sweeps,
        }
    }

    /// Whether a triangle turned over, a tangency changed sides, a hinge bent the other way
    /// without passing through straight, or an arc's sweep jumped across a full turn.
    fn flipped(&self, before: &Senses, bends_may_turn: bool) -> bool {
        let now = self.orientation();
        let turned = before.turns.iter().zip(&now.turns).any(|(a, b)| {
            let scale = a.abs().max(b.abs());
            scale > 0.0 && a * b < 0.0 && a.abs() > 1e-9 * scale.max(1.0)
        });
        let bent = !bends_may_turn
            && before
                .bends
                .iter()
                .zip(&now.bends)
                .any(|(a, b)| a * b < 0.0 && (a - b).abs() > BENT);
        let swept = before
            .sweeps
            .iter()
            .zip(&now.sweeps)
            .any(|(a, b)| (a - b).abs() > 180.0);
        turned || bent || swept
    }

    /// Ends the drag, taking its soft constraints out (as dropping it does).
    pub fn end(self) {}

    /// Ends the drag, taking its soft constraints out, and gives back the sketch when the drag
    /// owns it ([`Sketch::into_drag`]); `None` for a drag that borrowed it.
    #[must_use]
    pub fn into_sketch(mut self) -> Option<Sketch> {
        self.sketch.remove_soft(&self.soft);
        match std::mem::replace(&mut self.sketch, Held::Gone) {
            Held::Owned(s) => Some(*s),
            Held::Borrowed(_) | Held::Gone => None,
        }
    }
}

impl Drop for Drag<'_> {
    fn drop(&mut self) {
        if !matches!(self.sketch, Held::Gone) {
            self.sketch.remove_soft(&self.soft);
        }
    }
}
