//! Equations: each constraint (and each entity with an implicit condition) becomes residuals
//! `r(x) = 0` written once over [`Scalar`], so that the same code gives values (`f64`) and
//! exact derivatives ([`Dual`]).
//!
//! Families: [`points`] (coincidence, distances to points and planes, symmetry, horizontal and
//! vertical), [`lines`] (distances to lines, lengths, angles), [`circles`] (radii, arcs,
//! tangency to arcs), [`curves`] (cubics), [`orientation`] (normals).

mod carried;
mod circles;
mod compile;
mod curves;
mod direct;
mod duplicates;
mod fast;
mod lines;
mod orientation;
mod planar;
mod points;
pub(crate) mod refs;
pub(crate) mod spatial;

pub(crate) use carried::{as_expressions, Carried};
pub(crate) use compile::{compile_group, compile_unmerged, compile_unmerged_only, Kernel, Link};
pub(crate) use duplicates::{duplicate_groups, still_duplicates};
use refs::{Ent, Frame, Geo, PointRef};

use crate::geom::{Dual, Scalar};
use crate::model::{ConstraintId, ConstraintKind, EntityId};

/// Who an equation belongs to: a constraint, or an entity's implicit condition.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub(crate) enum Owner {
    Constraint(ConstraintId),
    Entity(EntityId),
}

/// What an equation says.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum EqKind {
    Constraint(ConstraintKind),
    /// A quaternion has unit length.
    UnitQuaternion,
    /// An arc's start and end are equally far from its centre.
    ArcRadii,
    /// A translated point is at its base plus `times` (in `val`) the translation.
    Translated,
    /// A moved point (`ents[0]`) is at the translation (`ents[1]`) plus its base (in
    /// `target`) turned by the rotation (`ents[2]`, a normal).
    RotTranslated,
    /// A rotated normal (`ents[0]`) is the rotation (`ents[1]`) times its base (w in `val`,
    /// x, y, z in `target`).
    Rotated,
}

/// A constraint resolved against the model, ready to evaluate.
#[derive(Clone, Debug)]
pub(crate) struct Equation {
    pub kind: EqKind,
    pub wp: Option<Frame>,
    pub pts: [Option<PointRef>; 2],
    pub ents: Vec<Ent>,
    pub val: f64,
    pub other: bool,
    pub other2: bool,
    /// A 2D angle whose `val` is signed (see [`crate::model::Constraint::signed`]).
    pub signed: bool,
    /// A branch chosen from the starting configuration (which components of a cross product to
    /// keep, which sign an angle has ...), so that the equations stay well conditioned.
    pub choice: u8,
    /// For `where_dragged`: the position the point must keep. For a 2D angle: its signed
    /// target in radians with its sine and cosine, kept by [`Equation::prepare`].
    pub target: [f64; 3],
    /// The `val` (its bits), `choice` and `other` a 2D angle's `target` was computed for:
    /// evaluations read it while they are unchanged instead of computing it again (a
    /// rounding, a sine and a cosine each time, library calls in WebAssembly).
    pub prepared_for: Option<(u64, u8, bool)>,
    /// The bases of the carried entities it reads (see [`refs::Konst`]).
    pub consts: Vec<[f64; 4]>,
}

impl Equation {
    /// The equation of constraint `c` over its resolved workplane, points and entities, with
    /// no branch chosen yet.
    pub(crate) fn of_constraint(
        c: &crate::model::Constraint,
        wp: Option<Frame>,
        pts: [Option<PointRef>; 2],
        ents: Vec<Ent>,
    ) -> Self {
        Self {
            kind: EqKind::Constraint(c.kind),
            wp,
            pts,
            ents,
            val: c.val,
            other: c.other,
            other2: c.other2,
            signed: c.signed,
            choice: 0,
            target: [0.0; 3],
            prepared_for: None,
            consts: Vec::new(),
        }
    }

    /// An entity's implicit equation of `kind` over its resolved entities, with the constants
    /// it carries (`val`, `target`).
    pub(crate) fn of_entity(kind: EqKind, ents: Vec<Ent>, val: f64, target: [f64; 3]) -> Self {
        Self {
            kind,
            wp: None,
            pts: [None, None],
            ents,
            val,
            other: false,
            other2: false,
            signed: false,
            choice: 0,
            target,
            prepared_for: None,
            consts: Vec::new(),
        }
    }
}

/// Up to four residuals, written by an equation.
pub(crate) struct Rows<S> {
    pub v: [S; 4],
    pub n: usize,
}

impl<S: Scalar> Rows<S> {
    pub fn new() -> Self {
        Self {
            v: [S::cst(0.0); 4],
            n: 0,
        }
    }

    #[inline]
    pub fn push(&mut self, r: S) {
        if self.n < 4 {
            self.v[self.n] = r;
            self.n += 1;
        }
    }
}

impl Equation {
    pub fn pt(&self, i: usize) -> &PointRef {
        // Validation guarantees the fields a kind uses are present.
        self.pts[i]
            .as_ref()
            .expect("validated: point field present")
    }

    pub fn ent(&self, i: usize) -> &Ent {
        &self.ents[i]
    }

    pub fn line(&self, i: usize) -> &[PointRef; 2] {
        match &self.ents[i] {
            Ent::Line(l) => l,
            _ => unreachable!("validated: line field"),
        }
    }

    pub fn frame(&self, i: usize) -> &Frame {
        match &self.ents[i] {
            Ent::Workplane(f) => f,
            _ => unreachable!("validated: workplane field"),
        }
    }

    pub fn wp(&self) -> Option<&Frame> {
        self.wp.as_ref()
    }

    /// Writes the residuals at `x` (local slot values).
    pub fn eval<S: Scalar>(&self, x: &[S], out: &mut Rows<S>) {
        let g = Geo { x, k: &self.consts };
        use ConstraintKind as K;
        let k = match self.kind {
            EqKind::UnitQuaternion => return orientation::unit_quaternion(self, &g, out),
            EqKind::ArcRadii => return circles::arc_radii(self, &g, out),
            EqKind::Translated => return points::translated(self, &g, out),
            EqKind::RotTranslated => return points::rot_translated(self, &g, out),
            EqKind::Rotated => return orientation::rotated(self, &g, out),
            EqKind::Constraint(k) => k,
        };
        match k {
            K::PointsCoincident => points::coincident(self, &g, out),
            K::PtPtDistance => points::pt_pt_distance(self, &g, out),
            K::PtPlaneDistance | K::PtFaceDistance => points::pt_plane_distance(self, &g, out),
            K::PtInPlane | K::PtOnFace => points::pt_in_plane(self, &g, out),
            K::WhereDragged => points::where_dragged(self, &g, out),
            K::ProjPtDistance => points::proj_pt_distance(self, &g, out),
            K::Symmetric => points::symmetric(self, &g, out),
            K::SymmetricHoriz => points::symmetric_axis(self, &g, out, true),
            K::SymmetricVert => points::symmetric_axis(self, &g, out, false),
            K::SymmetricLine => points::symmetric_line(self, &g, out),
            K::AtMidpoint => points::at_midpoint(self, &g, out),
            K::Horizontal => points::horizontal_vertical(self, &g, out, true),
            K::Vertical => points::horizontal_vertical(self, &g, out, false),
            K::PtLineDistance => lines::pt_line_distance(self, &g, out),
            K::PtOnLine => lines::pt_on_line(self, &g, out),
            K::EqualLengthLines => lines::length_relation(self, &g, out, lines::Relation::Equal),
            K::LengthRatio => lines::length_relation(self, &g, out, lines::Relation::Ratio),
            K::LengthDifference => {
                lines::length_relation(self, &g, out, lines::Relation::Difference)
            }
            K::EqLenPtLineD => lines::eq_len_pt_line_d(self, &g, out),
            K::EqPtLnDistances => lines::eq_pt_ln_distances(self, &g, out),
            K::EqualAngle => lines::equal_angle(self, &g, out),
            K::Angle => lines::angle(self, &g, out),
            K::Parallel => lines::parallel(self, &g, out),
            K::Perpendicular => lines::perpendicular(self, &g, out),
            K::Diameter => circles::diameter(self, &g, out),
            K::PtOnCircle => circles::pt_on_circle(self, &g, out),
            K::EqualRadius => circles::equal_radius(self, &g, out),
            K::EqualLineArcLen => {
                circles::arc_length_relation(self, &g, out, circles::ArcRel::LineEqual)
            }
            K::ArcArcLenRatio => {
                circles::arc_length_relation(self, &g, out, circles::ArcRel::ArcArcRatio)
            }
            K::ArcLineLenRatio => {
                circles::arc_length_relation(self, &g, out, circles::ArcRel::ArcLineRatio)
            }
            K::ArcArcDifference => {
                circles::arc_length_relation(self, &g, out, circles::ArcRel::ArcArcDiff)
            }
            K::ArcLineDifference => {
                circles::arc_length_relation(self, &g, out, circles::ArcRel::ArcLineDiff)
            }
            K::ArcLineTangent => circles::arc_line_tangent(self, &g, out),
            K::CubicLineTangent => curves::cubic_line_tangent(self, &g, out),
            K::CurveCurveTangent => curves::curve_curve_tangent(self, &g, out),
            K::SameOrientation => orientation::same_orientation(self, &g, out),
        }
    }

    /// Whether this is an angle between two directions of a workplane.
    pub fn is_planar_angle(&self) -> bool {
        self.kind == EqKind::Constraint(ConstraintKind::Angle) && self.wp.is_some()
    }

    /// Whether this is a 2D angle in SolveSpace's unsigned cosine form, which holds turning
    /// either way.
    pub fn is_unsigned_angle(&self) -> bool {
        self.is_planar_angle() && self.choice == lines::COSINE_FORM
    }

    /// Whether this is a 2D angle of 0 or 180 degrees, which is the same turning either way.
    pub fn is_straight_angle(&self) -> bool {
        self.is_planar_angle() && lines::target(self).sin().abs() < 1e-15
    }

    /// Writes a 2D angle as SolveSpace does, `cos(angle) - cos(val)` (see
    /// [`crate::Config::solvespace_angles`]), where that form keeps its gradient; elsewhere
    /// the signed form, with its branch chosen at `x` (the equation's local values).
    /// A signed angle keeps the signed form: the cosine holds at its mirror image too.
    pub fn write_angle_as_solvespace(&mut self, x: &[f64]) {
        if !self.is_planar_angle() || self.signed {
            return;
        }
        if lines::target(self).cos().abs() <= lines::COSINE_FORM_LIMIT {
            self.choice = lines::COSINE_FORM;
        } else if self.choice == lines::COSINE_FORM {
            self.choice = 0;
            self.choose(x);
        }
    }

    /// Picks the branch for kinds whose equations depend on the starting configuration.
    pub fn choose(&mut self, x: &[f64]) {
        if self.is_unsigned_angle() {
            // SolveSpace's form has no branch.
            return;
        }
        let g = Geo { x, k: &self.consts };
        use ConstraintKind as K;
        self.choice = match self.kind {
            EqKind::Constraint(K::Angle) => lines::choose_angle(self, &g),
            EqKind::Constraint(K::EqualAngle) => lines::choose_equal_angle(self, &g),
            EqKind::Constraint(K::SameOrientation) => {
                orientation::choose_same_orientation(self, &g)
            }
            EqKind::Constraint(K::CurveCurveTangent) => curves::choose_curve_curve(self, &g),
            EqKind::Constraint(K::ArcLineTangent) => circles::choose_arc_line(self, &g),
            _ => 0,
        };
        self.prepare();
    }

    /// Brings what evaluations keep of the equation's value up to date; after `val` changes.
    pub fn prepare(&mut self) {
        fast::prepare(self);
    }

    /// Number of residuals.
    pub fn rows(&self, x: &[f64]) -> usize {
        if let Some(n) = self.scalar_rows() {
            return n;
        }
        let mut r = Rows::new();
        self.eval(x, &mut r);
        r.n
    }

    /// 1 for the kinds whose evaluation is one residual whatever the configuration (a
    /// distance, an angle, a diameter, a tangency, a perpendicularity, an arc's equal radii,
    /// a unit quaternion): counting them needs no evaluation (a tenth of compiling a sketch of
    /// distances and angles). `None` for the others.
    fn scalar_rows(&self) -> Option<usize> {
        use ConstraintKind as K;
        match self.kind {
            EqKind::UnitQuaternion
            | EqKind::ArcRadii
            | EqKind::Constraint(
                K::PtPtDistance | K::Angle | K::Diameter | K::ArcLineTangent | K::Perpendicular,
            ) => Some(1),
            _ => None,
        }
    }

    /// Residuals and the dense Jacobian with respect to every local slot (row-major,
    /// `rows x x.len()`).
    #[cfg_attr(not(test), allow(dead_code))]
    pub fn jacobian(&self, x: &[f64], res: &mut [f64], jac: &mut [f64]) {
        let all: Vec<u16> = (0..x.len() as u16).collect();
        self.jacobian_active(x, &all, res, jac);
    }

    /// The residuals into `res` (one per row) when `self` has a written-out form, which costs
    /// a fraction of the generic one; false (and nothing written) otherwise.
    pub fn residuals_fast(&self, x: &[f64], res: &mut [f64]) -> bool {
        fast::jacobian(self, x, &[], res, &mut [])
    }

    /// Residuals and the dense Jacobian with respect to the slots in `active` only
    /// (row-major, `rows x active.len()`); the other slots are constants.
    ///
    /// Derivatives are exact, by forward differentiation: one pass with `N >= active.len()`
    /// directions for up to 16 unknowns, or passes of 16 directions each beyond that.
    pub fn jacobian_active(&self, x: &[f64], active: &[u16], res: &mut [f64], jac: &mut [f64]) {
        if !fast::jacobian(self, x, active, res, jac) {
            self.jacobian_dual(x, active, res, jac);
        }
    }

    /// [`Equation::jacobian_active`] by dual numbers alone, for every kind.
    pub fn jacobian_dual(&self, x: &[f64], active: &[u16], res: &mut [f64], jac: &mut [f64]) {
        match (x.len(), active.len()) {
            (0..=8, 0..=4) => self.pass::<4, 8>(x, active, 0, res, jac),
            (0..=8, _) => self.pass::<8, 8>(x, active, 0, res, jac),
            (9..=16, 0..=4) => self.pass::<4, 16>(x, active, 0, res, jac),
            (9..=16, 5..=8) => self.pass::<8, 16>(x, active, 0, res, jac),
            (9..=16, _) => self.pass::<16, 16>(x, active, 0, res, jac),
            (9..=32, 0..=8) => self.pass::<8, 32>(x, active, 0, res, jac),
            (9..=32, _) => {
                let mut start = 0;
                while start < active.len() {
                    self.pass::<16, 32>(x, active, start, res, jac);
                    start += 16;
                }
            }
            _ => {
                let mut start = 0;
                while start < active.len() {
                    self.pass_heap::<16>(x, active, start, res, jac);
                    start += 16;
                }
            }
        }
    }

    /// One pass over directions `start..start + N` of `active`, with up to `M` slots on the stack.
    fn pass<const N: usize, const M: usize>(
        &self,
        x: &[f64],
        active: &[u16],
        start: usize,
        res: &mut [f64],
        jac: &mut [f64],
    ) {
        let mut xs = [Dual::<N>::cst(0.0); M];
        for (d, &v) in xs.iter_mut().zip(x) {
            *d = Dual::cst(v);
        }
        for (k, &s) in active.iter().enumerate().skip(start).take(N) {
            xs[s as usize] = Dual::var(x[s as usize], k - start);
        }
        self.scatter(&xs[..x.len()], active.len(), start, res, jac);
    }

    fn pass_heap<const N: usize>(
        &self,
        x: &[f64],
        active: &[u16],
        start: usize,
        res: &mut [f64],
        jac: &mut [f64],
    ) {
        let mut xs: Vec<Dual<N>> = x.iter().map(|&v| Dual::cst(v)).collect();
        for (k, &s) in active.iter().enumerate().skip(start).take(N) {
            xs[s as usize] = Dual::var(x[s as usize], k - start);
        }
        self.scatter(&xs, active.len(), start, res, jac);
    }

    fn scatter<const N: usize>(
        &self,
        xs: &[Dual<N>],
        na: usize,
        start: usize,
        res: &mut [f64],
        jac: &mut [f64],
    ) {
        let mut out = Rows::new();
        self.eval(xs, &mut out);
        let width = N.min(na - start.min(na));
        for r in 0..out.n {
            res[r] = out.v[r].v;
            jac[r * na + start..r * na + start + width].copy_from_slice(&out.v[r].d[..width]);
        }
    }
}

#[cfg(test)]
mod tests;
