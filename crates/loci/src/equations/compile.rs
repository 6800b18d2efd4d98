//! Turning the constraints of one group into equations.

use super::carried::Carried;
use super::refs::{Ent, Frame, Locals, PointRef, Resolver};
use super::{EqKind, Equation, Owner};
use crate::error::ModelError;
use crate::model::{
    Constraint, ConstraintId, ConstraintKind, EntityKind, GroupId, ObjectId, ParamId, PlaneRule,
    System,
};

/// An equation between parameters, removed from the solve by substitution.
#[derive(Clone, Copy, Debug)]
pub(crate) enum Link {
    /// Parameter `a` equals parameter `b` (positions in [`System::params`]).
    Equal { owner: Owner, a: usize, b: usize },
    /// Parameter `p` equals `value`.
    Fix { owner: Owner, p: usize, value: f64 },
}

/// The equations of one group: general residuals, and equalities for substitution.
#[derive(Clone, Debug, Default)]
pub(crate) struct Compiled {
    pub kernels: Vec<Kernel>,
    pub links: Vec<Link>,
    /// Constraints left out as copies of an earlier one: `(copy, first)`.
    pub duplicates: Vec<(ConstraintId, ConstraintId)>,
    /// The entities read as expressions of what carries them: their own parameters are no
    /// unknowns, their implicit equations are not among the kernels.
    pub carried: Carried,
}

/// General residuals over a few parameters.
#[derive(Clone, Debug)]
pub(crate) struct Kernel {
    pub owner: Owner,
    /// Positions in [`System::params`] of the local slots.
    pub locals: Vec<u32>,
    pub eq: Equation,
    pub rows: usize,
}

impl Kernel {
    /// Gathers the local slot values from all parameter values.
    pub fn gather(&self, values: &[f64], x: &mut Vec<f64>) {
        x.clear();
        x.extend(self.locals.iter().map(|&p| values[p as usize]));
    }
}

/// Compiles every constraint of `group` and the implicit equations of its entities, reading
/// `values` (one per parameter, in [`System::params`] order) to pick branches. With
/// `express`, carried entities are read as expressions (see [`Carried`]); `dragged`
/// parameters stay unknowns.
pub(crate) fn compile_group(
    sys: &System,
    group: GroupId,
    dragged: &[ParamId],
    express: bool,
    values: &[f64],
    drawn: &[f64],
) -> Result<Compiled, ModelError> {
    let carried = if express {
        Carried::of(sys, group, dragged)
    } else {
        Carried::default()
    };
    let r = Resolver::carrying(sys, &carried);
    let mut mine: Vec<&Constraint> = sys
        .constraints()
        .iter()
        .filter(|c| c.group == group && !c.reference)
        .collect();
    let duplicates = drop_duplicates(&mut mine);
    // Constraints compile independently; large groups in chunks on all cores, joined in order.
    // A small group compiles straight into the result, in the same order: the chunks, their
    // parts and the copies that join them cost a small solve more than its compilation.
    let mut out = Compiled::default();
    let mut x = Vec::new();
    if mine.len() < crate::par::MIN_PARALLEL {
        out.links.reserve(mine.len());
        for c in &mine {
            compile_constraint(&r, c, values, drawn, &mut x, &mut out)?;
        }
    } else {
        const CHUNK: usize = 1024;
        let chunks: Vec<&[&Constraint]> = mine.chunks(CHUNK).collect();
        let parts = crate::par::map_items(
            chunks,
            true,
            Vec::new,
            |x, _, chunk| -> Result<Compiled, ModelError> {
                let mut part = Compiled::default();
                part.links.reserve(chunk.len());
                for c in chunk {
                    compile_constraint(&r, c, values, drawn, x, &mut part)?;
                }
                Ok(part)
            },
        );
        let parts = parts.into_iter().collect::<Result<Vec<_>, _>>()?;
        out.kernels
            .reserve(parts.iter().map(|p| p.kernels.len()).sum());
        out.links.reserve(parts.iter().map(|p| p.links.len()).sum());
        for mut part in parts {
            out.kernels.append(&mut part.kernels);
            out.links.append(&mut part.links);
        }
    }
    let mut kernels = Vec::new();
    compile_entities(&r, group, values, &mut x, &mut kernels)?;
    out.kernels.append(&mut kernels);
    out.duplicates = duplicates;
    drop(r);
    out.carried = carried;
    Ok(out)
}

/// Removes from `cs` every constraint that repeats an earlier one; returns `(copy, first)`.
fn drop_duplicates(cs: &mut Vec<&Constraint>) -> Vec<(ConstraintId, ConstraintId)> {
    let dups = super::duplicates::duplicates(cs);
    if dups.is_empty() {
        return Vec::new();
    }
    let out: Vec<(ConstraintId, ConstraintId)> = dups.iter().map(|&(i, f)| (cs[i].h, f)).collect();
    let mut gone = dups.iter().map(|&(i, _)| i).peekable();
    let mut i = 0;
    cs.retain(|_| {
        let drop = gone.peek() == Some(&i);
        if drop {
            gone.next();
        }
        i += 1;
        !drop
    });
    out
}

/// The implicit equations of the entities of `group` (unit quaternions, equal arc radii).
fn compile_entities(
    r: &Resolver<'_>,
    group: GroupId,
    values: &[f64],
    x: &mut Vec<f64>,
    out: &mut Vec<Kernel>,
) -> Result<(), ModelError> {
    for (i, e) in r.sys.entities().iter().enumerate() {
        // A carried entity's condition holds by construction: it is no equation.
        if e.group != group || !implicit(&e.kind) || r.carries(i) {
            continue;
        }
        let me = ObjectId::Entity(e.h);
        // An arc of a workplane with a point of this group, read straight from the model.
        if let Some((eq, l)) = super::direct::arc_radii(r.sys, e).filter(|(_, l)| {
            l.params
                .iter()
                .any(|&p| r.sys.params()[p as usize].group == group)
        }) {
            out.push(kernel(Owner::Entity(e.h), l, eq, values, x));
            continue;
        }
        let mut l = Locals::default();
        // The constant a moved copy carries (its base), where the equation reads it.
        let mut target = [0.0; 3];
        let (kind, ents, val) = match &e.kind {
            EntityKind::NormalIn3d { .. } => (
                EqKind::UnitQuaternion,
                vec![r.entity(me, e.h, &mut l)?],
                0.0,
            ),
            EntityKind::ArcOfCircle { .. } => {
                (EqKind::ArcRadii, vec![r.entity(me, e.h, &mut l)?], 0.0)
            }
            EntityKind::PointNTrans {
                base,
                translation,
                times,
                ..
            } => {
                let own = r.entity(me, e.h, &mut l)?;
                let base = r.entity(me, *base, &mut l)?;
                if !matches!(base, Ent::Point(_)) {
                    return Err(ModelError::MissingField {
                        owner: me,
                        field: "base",
                        expected: "a point",
                    });
                }
                let t = PointRef::P3(r.params(e.h, translation, &mut l)?);
                (
                    EqKind::Translated,
                    vec![own, base, Ent::Point(t)],
                    f64::from(*times),
                )
            }
            EntityKind::PointNRotTrans {
                base,
                translation,
                rotation,
                ..
            } => {
                let own = r.entity(me, e.h, &mut l)?;
                let t = PointRef::P3(r.params(e.h, translation, &mut l)?);
                let q = r.entity(me, *rotation, &mut l)?;
                target = *base;
                (EqKind::RotTranslated, vec![own, Ent::Point(t), q], 0.0)
            }
            EntityKind::NormalNRot { base, rotation, .. } => {
                let own = r.entity(me, e.h, &mut l)?;
                let q = r.entity(me, *rotation, &mut l)?;
                // The base quaternion: w in `val`, x, y, z in `target`.
                target = [base[1], base[2], base[3]];
                (EqKind::Rotated, vec![own, q], base[0])
            }
            _ => continue,
        };
        // An entity of this group whose parameters all belong to earlier groups (a copy) has
        // nothing to solve: its condition holds or not, but it is no equation of this group.
        if !l
            .params
            .iter()
            .any(|&p| r.sys.params()[p as usize].group == group)
        {
            continue;
        }
        let mut eq = Equation::of_entity(kind, ents, val, target);
        eq.consts = std::mem::take(&mut l.consts);
        let l = super::planar::compact(&mut eq, &l).unwrap_or(l);
        out.push(kernel(Owner::Entity(e.h), l, eq, values, x));
    }
    Ok(())
}

/// Whether an entity of this kind carries an implicit equation of its own.
fn implicit(kind: &EntityKind) -> bool {
    matches!(
        kind,
        EntityKind::NormalIn3d { .. }
            | EntityKind::ArcOfCircle { .. }
            | EntityKind::PointNTrans { .. }
            | EntityKind::PointNRotTrans { .. }
            | EntityKind::NormalNRot { .. }
    )
}

/// Compiles `group` with every equation as general residuals, parameter equalities included,
/// so that each row belongs to one constraint (or entity) that can be named: the diagnosis
/// works on these. With `references`, only the reference (driven) constraints are compiled
/// instead, to measure them; entities then add nothing.
pub(crate) fn compile_unmerged(
    sys: &System,
    group: GroupId,
    values: &[f64],
    references: bool,
) -> Result<Vec<Kernel>, ModelError> {
    compile_unmerged_only(sys, group, values, references, &|_| true)
}

/// [`compile_unmerged`] for the constraints and entities `keep` accepts.
pub(crate) fn compile_unmerged_only(
    sys: &System,
    group: GroupId,
    values: &[f64],
    references: bool,
    keep: &dyn Fn(Owner) -> bool,
) -> Result<Vec<Kernel>, ModelError> {
    let r = Resolver::new(sys);
    let mut out = Vec::new();
    let mut x = Vec::new();
    let mut mine: Vec<&Constraint> = sys
        .constraints()
        .iter()
        .filter(|c| c.group == group && c.reference == references && keep(Owner::Constraint(c.h)))
        .collect();
    if !references {
        // Copies are reported as redundant apart (see `duplicates`).
        drop_duplicates(&mut mine);
    }
    for c in mine {
        let (eq, l) = resolve_constraint(&r, c)?;
        out.push(kernel(Owner::Constraint(c.h), l, eq, values, &mut x));
    }
    if !references {
        let mut entities = Vec::new();
        compile_entities(&r, group, values, &mut x, &mut entities)?;
        // These equations read carried entities by their own parameters: a carried entity's
        // implicit equation, which the solve never saw and so never named, comes with the
        // constraints that read it, or they would seem free of each other.
        let carried = Carried::of(sys, group, &[]);
        let mut read = vec![
            false;
            if carried.is_empty() {
                0
            } else {
                sys.params().len()
            }
        ];
        if !read.is_empty() {
            for k in &out {
                k.locals.iter().for_each(|&p| read[p as usize] = true);
            }
        }
        let tied = |o: Owner| match o {
            Owner::Entity(h) => sys.entity_index(h).is_some_and(|i| {
                carried.entity(i)
                    && sys.entities()[i]
                        .kind
                        .params()
                        .iter()
                        .any(|p| sys.param_index(*p).is_some_and(|p| read[p]))
            }),
            Owner::Constraint(_) => false,
        };
        out.extend(
            entities
                .into_iter()
                .filter(|k| keep(k.owner) || (!read.is_empty() && tied(k.owner))),
        );
    }
    Ok(out)
}

pub(super) fn kernel(
    owner: Owner,
    l: Locals,
    mut eq: Equation,
    values: &[f64],
    x: &mut Vec<f64>,
) -> Kernel {
    x.clear();
    x.extend(l.params.iter().map(|&p| values[p as usize]));
    eq.choose(x);
    if eq.kind == EqKind::Constraint(ConstraintKind::WhereDragged) {
        let g = super::refs::Geo {
            x: &x[..],
            k: &eq.consts,
        };
        let p = g.at(eq.pt(0), eq.wp());
        eq.target = [p.x, p.y, p.z];
    }
    let rows = eq.rows(x);
    Kernel {
        owner,
        locals: l.params.to_vec(),
        eq,
        rows,
    }
}

/// Resolves a constraint without substitution: the equation and its locals.
pub(crate) fn resolve_constraint(
    r: &Resolver<'_>,
    c: &Constraint,
) -> Result<(Equation, Locals), ModelError> {
    let owner = ObjectId::Constraint(c.h);
    let mut l = Locals::default();
    let sig = c.kind.signature();
    let wp = match (sig.plane, c.workplane) {
        (PlaneRule::Ignored, _) | (_, None) => None,
        (_, Some(h)) => match r.entity(owner, h, &mut l)? {
            Ent::Workplane(f) => Some(f),
            _ => {
                return Err(ModelError::MissingField {
                    owner,
                    field: "workplane",
                    expected: "a workplane",
                });
            }
        },
    };
    if sig.plane == PlaneRule::Required && wp.is_none() {
        return Err(ModelError::NeedsWorkplane {
            constraint: c.h,
            kind: c.kind,
        });
    }
    // Fields the type does not use are ignored, as validation ignores them (and libslvs
    // never reads them): a stray handle there must not fail the solve.
    let wants = c.wants();
    let used = |i: usize| wants[i].is_some();
    let mut pts = [None, None];
    for (i, (slot, h)) in pts.iter_mut().zip([c.pt_a, c.pt_b]).enumerate() {
        if !used(i) {
            continue;
        }
        if let Some(h) = h {
            match r.entity(owner, h, &mut l)? {
                Ent::Point(p) => *slot = Some(p),
                _ => {
                    return Err(ModelError::MissingField {
                        owner,
                        field: "pt_a/pt_b",
                        expected: "a point",
                    });
                }
            }
        }
    }
    let handles = [c.entity_a, c.entity_b, c.entity_c, c.entity_d];
    let mut ents = Vec::with_capacity(
        (0..4)
            .filter(|&i| handles[i].is_some() && used(i + 2))
            .count(),
    );
    for (i, h) in handles.into_iter().enumerate() {
        if let (Some(h), true) = (h, used(i + 2)) {
            ents.push(r.entity(owner, h, &mut l)?);
        }
    }
    let mut eq = Equation::of_constraint(c, wp, pts, ents);
    eq.consts = std::mem::take(&mut l.consts);
    Ok((eq, l))
}

fn compile_constraint(
    r: &Resolver<'_>,
    c: &Constraint,
    values: &[f64],
    drawn: &[f64],
    x: &mut Vec<f64>,
    out: &mut Compiled,
) -> Result<(), ModelError> {
    // A point held where it is dragged is held where the drawing has it, whatever start the
    // solve begins from: a solve from a solution built another way, in which the point had
    // moved, held it there and read `okay` with the point off its place.
    let values = if c.kind == ConstraintKind::WhereDragged {
        drawn
    } else {
        values
    };
    if super::direct::links(r.sys, c, values, x, out) {
        return Ok(());
    }
    compile_resolved(r, c, values, x, out)
}

/// [`compile_constraint`] by resolving the constraint, whatever it is.
pub(super) fn compile_resolved(
    r: &Resolver<'_>,
    c: &Constraint,
    values: &[f64],
    x: &mut Vec<f64>,
    out: &mut Compiled,
) -> Result<(), ModelError> {
    let (eq, l) = resolve_constraint(r, c)?;
    let owner = Owner::Constraint(c.h);
    let p = |s: u16| l.params[s as usize] as usize;
    // Native coordinates: the parameters themselves are the coordinates the constraint is
    // written in, so `a = b` equations can be removed by merging parameters.
    let native = |pt: &PointRef, wp: Option<&Frame>| -> Option<([u16; 3], usize)> {
        match (pt, wp) {
            (PointRef::P3(s), None) => Some((*s, 3)),
            (PointRef::P2 { wp: own, uv }, Some(f)) if own.id == f.id => {
                Some(([uv[0], uv[1], 0], 2))
            }
            _ => None,
        }
    };
    use ConstraintKind as K;
    match c.kind {
        K::PointsCoincident => {
            if let (Some((a, n)), Some((b, _))) =
                (native(eq.pt(0), eq.wp()), native(eq.pt(1), eq.wp()))
            {
                for (&sa, &sb) in a[..n].iter().zip(&b[..n]) {
                    out.links.push(Link::Equal {
                        owner,
                        a: p(sa),
                        b: p(sb),
                    });
                }
                return Ok(());
            }
        }
        K::Horizontal | K::Vertical => {
            let (pa, pb) = match eq.ents.first() {
                Some(Ent::Line(line)) => (line[0], line[1]),
                _ => (*eq.pt(0), *eq.pt(1)),
            };
            if let (Some((a, _)), Some((b, _))) = (native(&pa, eq.wp()), native(&pb, eq.wp())) {
                let i = if c.kind == K::Horizontal { 1 } else { 0 };
                out.links.push(Link::Equal {
                    owner,
                    a: p(a[i]),
                    b: p(b[i]),
                });
                return Ok(());
            }
        }
        K::WhereDragged => {
            if let Some((a, n)) = native(eq.pt(0), eq.wp()) {
                for &s in &a[..n] {
                    out.links.push(Link::Fix {
                        owner,
                        p: p(s),
                        value: values[p(s)],
                    });
                }
                return Ok(());
            }
        }
        K::EqualRadius => {
            if let (Ent::Circle { radius: ra, .. }, Ent::Circle { radius: rb, .. }) =
                (eq.ent(0), eq.ent(1))
            {
                out.links.push(Link::Equal {
                    owner,
                    a: p(*ra),
                    b: p(*rb),
                });
                return Ok(());
            }
        }
        K::Diameter => {
            if let Ent::Circle { radius, .. } = eq.ent(0) {
                out.links.push(Link::Fix {
                    owner,
                    p: p(*radius),
                    value: c.val / 2.0,
                });
                return Ok(());
            }
        }
        _ => {}
    }
    let mut eq = eq;
    let l = super::planar::compact(&mut eq, &l).unwrap_or(l);
    out.kernels.push(kernel(owner, l, eq, values, x));
    Ok(())
}
