//! The model behind `loci.slvs`, the drop-in for SolveSpace's `slvs` module: libslvs's
//! arrays of parameters, entities and constraints, solved by `loci_slvs::solve_arrays`, which
//! answers as libslvs does (its start for merged unknowns, the end of Newton's path for an
//! under-constrained sketch, its result codes). The Python side (`python/loci/slvs.py`)
//! keeps `slvs`'s functions and dictionaries.

use crate::errors;
use loci_slvs::abi::{
    Slvs_Constraint, Slvs_Entity, Slvs_Param, SLVS_E_LINE_SEGMENT, SLVS_E_POINT_IN_2D,
    SLVS_RESULT_INCONSISTENT,
};
use loci_slvs::convert::InputError;
use pyo3::prelude::*;

/// `slvs`'s REDUNDANT_OKAY: solved, with redundant constraints (libslvs 3.1, and so
/// `solve_arrays`, says INCONSISTENT but writes the values).
const REDUNDANT_OKAY: i32 = 4;

/// libslvs's arrays, with handles numbered from 1 in each, as SolveSpace's module gives them.
#[pyclass(module = "loci.slvs")]
#[derive(Default)]
pub struct SlvsModel {
    params: Vec<Slvs_Param>,
    entities: Vec<Slvs_Entity>,
    constraints: Vec<Slvs_Constraint>,
}

impl SlvsModel {
    fn param_index(&self, h: u32) -> Option<usize> {
        // Handles are consecutive from 1.
        let i = usize::try_from(h).ok()?.checked_sub(1)?;
        (self.params.get(i)?.h == h).then_some(i)
    }
}

#[pymethods]
impl SlvsModel {
    #[new]
    fn new() -> Self {
        Self::default()
    }

    /// Adds an entity with new parameters holding `values`; returns its handle and its
    /// parameters' handles.
    #[pyo3(signature = (group, r#type, wrkpl, points, normal, distance, values))]
    #[allow(clippy::too_many_arguments)]
    fn add_entity(
        &mut self,
        group: u32,
        r#type: i32,
        wrkpl: u32,
        points: [u32; 4],
        normal: u32,
        distance: u32,
        values: Vec<f64>,
    ) -> PyResult<(u32, [u32; 4])> {
        if values.len() > 4 {
            return Err(errors::model("an entity has at most 4 parameters"));
        }
        let mut param = [0u32; 4];
        for (slot, val) in param.iter_mut().zip(values) {
            let h = u32::try_from(self.params.len() + 1).map_err(errors::model)?;
            self.params.push(Slvs_Param { h, group, val });
            *slot = h;
        }
        let h = u32::try_from(self.entities.len() + 1).map_err(errors::model)?;
        self.entities.push(Slvs_Entity {
            h,
            group,
            r#type,
            wrkpl,
            point: points,
            normal,
            distance,
            param,
        });
        Ok((h, param))
    }

    /// Adds a point in workplane `wrkpl` at (u, v): the common case, without `add_entity`'s
    /// conversions of arrays. Returns its handle and its two parameters.
    fn add_point_2d(
        &mut self,
        group: u32,
        wrkpl: u32,
        u: f64,
        v: f64,
    ) -> PyResult<(u32, u32, u32)> {
        let (h, p) = self.add_entity(group, SLVS_E_POINT_IN_2D, wrkpl, [0; 4], 0, 0, vec![u, v])?;
        Ok((h, p[0], p[1]))
    }

    /// Adds a line from `a` to `b`; returns its handle.
    fn add_line(&mut self, group: u32, wrkpl: u32, a: u32, b: u32) -> PyResult<u32> {
        Ok(self
            .add_entity(
                group,
                SLVS_E_LINE_SEGMENT,
                wrkpl,
                [a, b, 0, 0],
                0,
                0,
                Vec::new(),
            )?
            .0)
    }

    /// Adds a constraint; returns its handle.
    #[pyo3(signature = (group, r#type, wrkpl, val, pt_a, pt_b, e_a, e_b, e_c, e_d, other, other2))]
    #[allow(clippy::too_many_arguments)]
    fn add_constraint(
        &mut self,
        group: u32,
        r#type: i32,
        wrkpl: u32,
        val: f64,
        pt_a: u32,
        pt_b: u32,
        e_a: u32,
        e_b: u32,
        e_c: u32,
        e_d: u32,
        other: i32,
        other2: i32,
    ) -> PyResult<u32> {
        let h = u32::try_from(self.constraints.len() + 1).map_err(errors::model)?;
        self.constraints.push(Slvs_Constraint {
            h,
            group,
            r#type,
            wrkpl,
            valA: val,
            ptA: pt_a,
            ptB: pt_b,
            entityA: e_a,
            entityB: e_b,
            entityC: e_c,
            entityD: e_d,
            other,
            other2,
        });
        Ok(h)
    }

    /// The groups that own a parameter, an entity or a constraint.
    fn has_group(&self, group: u32) -> bool {
        self.params.iter().any(|p| p.group == group)
            || self.entities.iter().any(|e| e.group == group)
            || self.constraints.iter().any(|c| c.group == group)
    }

    /// Solves `group` with up to four dragged parameters; returns `(result, dof, failed)`
    /// with `slvs`'s result codes. The GIL is released while it runs.
    fn solve(
        &mut self,
        py: Python<'_>,
        group: u32,
        dragged: Vec<u32>,
        calculate_faileds: bool,
    ) -> PyResult<(i32, i32, Vec<u32>)> {
        if dragged.len() > 4 {
            return Err(errors::solve_msg(format!(
                "{} dragged parameters; libslvs takes at most 4 (two 2D points)",
                dragged.len()
            )));
        }
        let mut d = [0u32; 4];
        d[..dragged.len()].copy_from_slice(&dragged);
        let (params, entities, constraints) = (&self.params, &self.entities, &self.constraints);
        let answer = py
            .allow_threads(|| {
                loci_slvs::solve_arrays(params, entities, constraints, d, calculate_faileds, group)
            })
            .map_err(|e| match e {
                InputError::Model(m) => errors::model(m),
                other => errors::model(other),
            })?;
        let mut result = answer.result;
        if let Some(values) = answer.values {
            if result == SLVS_RESULT_INCONSISTENT {
                result = REDUNDANT_OKAY;
            }
            for (i, v) in values {
                self.params[i].val = v;
            }
        }
        Ok((result, answer.dof, answer.failed))
    }

    /// The value of parameter `h`.
    fn value(&self, h: u32) -> PyResult<f64> {
        self.param_index(h)
            .map(|i| self.params[i].val)
            .ok_or_else(|| errors::model(format!("param {h} does not exist")))
    }

    /// Sets the value of parameter `h`.
    fn set_value(&mut self, h: u32, v: f64) -> PyResult<()> {
        let i = self
            .param_index(h)
            .ok_or_else(|| errors::model(format!("param {h} does not exist")))?;
        self.params[i].val = v;
        Ok(())
    }

    /// The coordinates of point entity `h` (its parameters' values).
    fn point_values(&self, h: u32) -> PyResult<Vec<f64>> {
        let e = usize::try_from(h)
            .ok()
            .and_then(|h| h.checked_sub(1))
            .and_then(|i| self.entities.get(i))
            .ok_or_else(|| errors::model(format!("entity {h} does not exist")))?;
        e.param
            .iter()
            .filter(|&&p| p != 0)
            .map(|&p| self.value(p))
            .collect()
    }

    /// The model as a `loci.System` (a copy), to check it or save it as loci's JSON.
    fn to_system(&self) -> PyResult<crate::system::PySystem> {
        let sys = loci_slvs::convert::system(&self.params, &self.entities, &self.constraints)
            .map_err(errors::model)?;
        Ok(crate::system::PySystem::from_system(sys))
    }
}
