//! The SolveSpace model: a [`loci::System`] read from loci JSON or `.slvs`, or built call by
//! call, solved group by group and diagnosed.

use crate::error::{js, parse, to_json, Fault, Res};
use loci::format::json::{Options, Problem, SolveRequest};
use loci::format::slvs::{self, GroupResult, SlvsFile};
use loci::{Config, Constraint, ConstraintId, Entity, GroupId, Outcome, Param, ParamId, Report};
use serde::Serialize;
use wasm_bindgen::prelude::*;

/// A SolveSpace-model system: parameters, entities and constraints in groups.
#[wasm_bindgen(js_name = RawSystem)]
#[derive(Default)]
pub struct System {
    pub(crate) sys: loci::System,
    /// The solve request of the file it was read from, if any.
    request: Option<SolveRequest>,
    /// The `.slvs` file it was read from, to save back with its styles and solid.
    slvs: Option<SlvsFile>,
}

/// A group's line in the result of solving a whole `.slvs` file.
#[derive(Serialize)]
struct GroupLine {
    group: u32,
    name: String,
    kind: String,
    ok: bool,
    result: String,
    dof: Option<usize>,
    failed: Vec<ConstraintId>,
}

impl System {
    /// An empty system.
    #[must_use]
    pub fn empty() -> Self {
        Self::default()
    }

    /// Reads a loci JSON problem file.
    ///
    /// # Errors
    /// A file that is not a problem, naming the object and field at fault.
    pub fn read_json(text: &str) -> Res<Self> {
        let p = Problem::from_json(text)?;
        Ok(System {
            request: Some(p.request()),
            sys: p.system,
            slvs: None,
        })
    }

    /// Reads a SolveSpace `.slvs` file.
    ///
    /// # Errors
    /// A file that is not one, with the line at fault.
    pub fn read_slvs(bytes: &[u8]) -> Res<Self> {
        let f = SlvsFile::parse(bytes)?;
        Ok(System {
            sys: f.system.clone(),
            request: None,
            slvs: Some(f),
        })
    }

    /// The problem file: the model and the solve request it was read with.
    #[must_use]
    pub fn write_json(&self) -> String {
        Problem {
            system: self.sys.clone(),
            solve: self.request.clone(),
        }
        .to_json()
    }

    /// Solves one group with the dragged parameters and options given (JSON of the problem
    /// format's `options`, or empty for the defaults).
    ///
    /// # Errors
    /// An invalid model, an unknown group or dragged parameter, a bad option.
    pub fn solve_group(&mut self, group: u32, dragged: &[u32], options: &str) -> Res<String> {
        self.solve_group_report(group, dragged, options)
            .map(|r| to_json(&r))
    }

    /// Solves the group of the file's solve request (or the highest group with constraints).
    ///
    /// # Errors
    /// As [`System::solve_group`].
    pub fn solve_request(&mut self) -> Res<String> {
        self.solve_request_report().map(|r| to_json(&r))
    }

    /// [`System::solve_request`], the report itself.
    ///
    /// # Errors
    /// As [`System::solve_group`].
    pub fn solve_request_report(&mut self) -> Res<Report> {
        let r = match &self.request {
            Some(r) => loci::solve(&mut self.sys, r.group, &r.dragged, &r.config())?,
            None => {
                let g = self.sys.constraints().iter().map(|c| c.group).max();
                let g = g.unwrap_or(GroupId(1));
                loci::solve(&mut self.sys, g, &[], &Config::default())?
            }
        };
        self.sync_slvs();
        Ok(r)
    }

    /// [`System::solve_group`], the report itself.
    ///
    /// # Errors
    /// As [`System::solve_group`].
    pub fn solve_group_report(
        &mut self,
        group: u32,
        dragged: &[u32],
        options: &str,
    ) -> Res<Report> {
        let cfg = config(options)?;
        let dragged: Vec<ParamId> = dragged.iter().map(|h| ParamId(*h)).collect();
        let r = loci::solve(&mut self.sys, GroupId(group), &dragged, &cfg)?;
        self.sync_slvs();
        Ok(r)
    }

    /// Solves every group of a `.slvs` file in order, as SolveSpace does.
    ///
    /// # Errors
    /// A system not read from a `.slvs` file.
    pub fn solve_slvs(&mut self) -> Res<String> {
        let Some(f) = self.slvs.as_mut() else {
            return Err(Fault::input(
                None,
                "solveAll: this system was not read from a .slvs file; solve a group instead",
            ));
        };
        let lines: Vec<GroupLine> = slvs::solve_all(f, &Config::default())
            .into_iter()
            .map(|g| GroupLine {
                group: g.group.0,
                ok: g.is_ok(),
                name: g.name.clone(),
                kind: g.kind.name(),
                result: g.result.to_string(),
                dof: match &g.result {
                    GroupResult::Solved(r) => Some(r.dof),
                    _ => None,
                },
                failed: match &g.result {
                    GroupResult::Solved(r) => r.failed.clone(),
                    _ => Vec::new(),
                },
            })
            .collect();
        self.sys = f.system.clone();
        Ok(to_json(&lines))
    }

    /// After a solve of a system read from `.slvs`: the file saves the new values.
    fn sync_slvs(&mut self) {
        if let Some(f) = self.slvs.as_mut() {
            f.system = self.sys.clone();
        }
    }

    /// The system as a `.slvs` file: the file it was read from with the new values, or a
    /// new file SolveSpace opens.
    ///
    /// # Errors
    /// A system the writer cannot express.
    pub fn write_slvs(&self) -> Res<Vec<u8>> {
        match &self.slvs {
            Some(f) => Ok(f.to_bytes()),
            None => Ok(slvs::export(&self.sys)?.bytes),
        }
    }

    /// The diagnosis of a group: degrees of freedom, conflicts, redundancies, freedoms.
    ///
    /// # Errors
    /// An invalid model or unknown group.
    pub fn check_group(&self, group: u32) -> Res<String> {
        let d = loci::diagnose(&self.sys, GroupId(group), &Config::default())?;
        Ok(to_json(&d))
    }
}

/// A solve's report as numbers, which the JavaScript wrapper (`reportOf` in `js/loci.js`)
/// turns into the same object as the report's JSON: the outcome (0 `okay`, 1 `redundant_okay`,
/// 2 `inconsistent`, 3 `did_not_converge`), dof, iterations, residual, unknowns, equations,
/// components, then the number of failed constraints and their handles, then the number of
/// failed entities and their handles. A small solve spent a sixth of its time under node
/// writing, decoding and parsing the report's JSON; an array of numbers crosses as one copy.
#[must_use]
pub fn packed(r: &Report) -> Vec<f64> {
    let outcome = match r.outcome {
        Outcome::Okay => 0.0,
        Outcome::RedundantOkay => 1.0,
        Outcome::Inconsistent => 2.0,
        Outcome::DidNotConverge => 3.0,
    };
    let mut v = Vec::with_capacity(9 + r.failed.len() + r.failed_entities.len());
    v.extend([
        outcome,
        r.dof as f64,
        r.iterations as f64,
        r.residual,
        r.unknowns as f64,
        r.equations as f64,
        r.components as f64,
        r.failed.len() as f64,
    ]);
    v.extend(r.failed.iter().map(|c| f64::from(c.0)));
    v.push(r.failed_entities.len() as f64);
    v.extend(r.failed_entities.iter().map(|e| f64::from(e.0)));
    v
}

/// The solver settings of an `options` object in the problem format (empty: defaults).
fn config(options: &str) -> Res<Config> {
    if options.trim().is_empty() {
        return Ok(Config::default());
    }
    let o: Options = parse("options", options)?;
    let req = SolveRequest {
        group: GroupId(1),
        dragged: Vec::new(),
        calculate_failed: true,
        options: o,
    };
    Ok(req.config())
}

#[wasm_bindgen(js_class = RawSystem)]
impl System {
    /// An empty system.
    #[wasm_bindgen(constructor)]
    #[must_use]
    pub fn new() -> System {
        System::empty()
    }

    /// Reads a loci JSON problem file.
    #[wasm_bindgen(js_name = fromJson)]
    pub fn from_json(text: &str) -> Result<System, JsValue> {
        js(System::read_json(text))
    }

    /// Reads a SolveSpace `.slvs` file.
    #[wasm_bindgen(js_name = fromSlvs)]
    pub fn from_slvs(bytes: &[u8]) -> Result<System, JsValue> {
        js(System::read_slvs(bytes))
    }

    /// The loci JSON problem file.
    #[wasm_bindgen(js_name = toJson)]
    #[must_use]
    pub fn to_json(&self) -> String {
        self.write_json()
    }

    /// The `.slvs` file.
    #[wasm_bindgen(js_name = toSlvs)]
    pub fn to_slvs(&self) -> Result<Vec<u8>, JsValue> {
        js(self.write_slvs())
    }

    /// Adds a parameter.
    #[wasm_bindgen(js_name = addParam)]
    pub fn add_param(&mut self, h: u32, group: u32, value: f64) -> Result<u32, JsValue> {
        js(self
            .sys
            .add_param(Param::new(h, group, value))
            .map(|p| p.0)
            .map_err(Fault::from))
    }

    /// Adds an entity given as the JSON of the problem format.
    #[wasm_bindgen(js_name = addEntity)]
    pub fn add_entity(&mut self, json: &str) -> Result<u32, JsValue> {
        js(parse::<Entity>("entity", json)
            .and_then(|e| self.sys.add_entity(e).map(|h| h.0).map_err(Fault::from)))
    }

    /// Adds a constraint given as the JSON of the problem format.
    #[wasm_bindgen(js_name = addConstraint)]
    pub fn add_constraint(&mut self, json: &str) -> Result<u32, JsValue> {
        js(parse::<Constraint>("constraint", json)
            .and_then(|c| self.sys.add_constraint(c).map(|h| h.0).map_err(Fault::from)))
    }

    /// Removes a constraint; whether it existed.
    #[wasm_bindgen(js_name = removeConstraint)]
    pub fn remove_constraint(&mut self, h: u32) -> bool {
        self.sys.remove_constraint(ConstraintId(h)).is_some()
    }

    /// A parameter's value.
    #[must_use]
    pub fn value(&self, h: u32) -> Option<f64> {
        self.sys.value(ParamId(h))
    }

    /// Sets a parameter's value; whether it exists.
    #[wasm_bindgen(js_name = setValue)]
    pub fn set_value(&mut self, h: u32, v: f64) -> bool {
        self.sys.set_value(ParamId(h), v)
    }

    /// Every parameter's handle, in the order of `values`.
    #[wasm_bindgen(js_name = paramHandles)]
    #[must_use]
    pub fn param_handles(&self) -> Vec<u32> {
        self.sys.params().iter().map(|p| p.h.0).collect()
    }

    /// Every parameter's value, in the order of `paramHandles`.
    #[must_use]
    pub fn values(&self) -> Vec<f64> {
        self.sys.params().iter().map(|p| p.val).collect()
    }

    /// Sets every parameter's value, in the order of `paramHandles`.
    #[wasm_bindgen(js_name = setValues)]
    pub fn set_values(&mut self, values: &[f64]) -> Result<(), JsValue> {
        if values.len() != self.sys.params().len() {
            return Err(Fault::input(
                Some("values".into()),
                format!(
                    "setValues: {} values given for {} parameters",
                    values.len(),
                    self.sys.params().len()
                ),
            )
            .into_js());
        }
        for (v, x) in self.sys.values_mut().zip(values) {
            *v = *x;
        }
        Ok(())
    }

    /// Every group that has objects, in increasing order.
    #[must_use]
    pub fn groups(&self) -> Vec<u32> {
        self.sys.groups().iter().map(|g| g.0).collect()
    }

    /// The model as JSON (`params`, `entities`, `constraints`).
    #[wasm_bindgen(js_name = modelJson)]
    #[must_use]
    pub fn model_json(&self) -> String {
        to_json(&self.sys)
    }

    /// Solves a group; the report as JSON.
    #[wasm_bindgen(js_name = solve)]
    pub fn solve(&mut self, group: u32, dragged: &[u32], options: &str) -> Result<String, JsValue> {
        js(self.solve_group(group, dragged, options))
    }

    /// Solves as the file's request says; the report as JSON.
    #[wasm_bindgen(js_name = solveRequest)]
    pub fn solve_req(&mut self) -> Result<String, JsValue> {
        js(self.solve_request())
    }

    /// Solves a group; the report as numbers (see [`packed`]).
    #[wasm_bindgen(js_name = solvePacked)]
    pub fn solve_packed(
        &mut self,
        group: u32,
        dragged: &[u32],
        options: &str,
    ) -> Result<Vec<f64>, JsValue> {
        js(self
            .solve_group_report(group, dragged, options)
            .map(|r| packed(&r)))
    }

    /// Solves as the file's request says; the report as numbers (see [`packed`]).
    #[wasm_bindgen(js_name = solveRequestPacked)]
    pub fn solve_req_packed(&mut self) -> Result<Vec<f64>, JsValue> {
        js(self.solve_request_report().map(|r| packed(&r)))
    }

    /// Solves every group of a `.slvs` file; one line per group, as JSON.
    #[wasm_bindgen(js_name = solveAll)]
    pub fn solve_all(&mut self) -> Result<String, JsValue> {
        js(self.solve_slvs())
    }

    /// The diagnosis of a group, as JSON.
    pub fn check(&self, group: u32) -> Result<String, JsValue> {
        js(self.check_group(group))
    }
}
