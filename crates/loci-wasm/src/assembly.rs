//! Assemblies: rigid components placed by poses and related by mates, read from the assembly
//! format or built call by call, solved at once or step by step.

use crate::error::{js, parse, to_json, Fault, Res};
use loci::assembly::{Assembly, Component, Mate, Pose};
use loci::format::assembly as file;
use wasm_bindgen::prelude::*;

/// An assembly.
#[wasm_bindgen(js_name = RawAssembly)]
#[derive(Default)]
pub struct AssemblyBinding {
    asm: Assembly,
}

impl AssemblyBinding {
    /// Reads an assembly file.
    ///
    /// # Errors
    /// Malformed JSON (with its line and column) or an invalid assembly, naming the
    /// component, reference or mate at fault.
    pub fn read(text: &str) -> Res<Self> {
        Ok(AssemblyBinding {
            asm: file::read(text)?,
        })
    }

    /// The assembly.
    #[must_use]
    pub fn assembly(&self) -> &Assembly {
        &self.asm
    }

    /// Solves all mates at once; the report as JSON.
    ///
    /// # Errors
    /// An assembly whose constraint system cannot be built.
    pub fn solve_all(&mut self) -> Res<String> {
        Ok(to_json(&self.asm.solve()?))
    }

    fn component_index(&self, name: &str) -> Res<usize> {
        self.asm
            .components
            .iter()
            .position(|c| c.name == name)
            .ok_or_else(|| Fault {
                class: crate::error::Class::Assembly,
                object: Some(format!("component {name}")),
                message: format!("component `{name}` does not exist"),
            })
    }
}

#[wasm_bindgen(js_class = RawAssembly)]
impl AssemblyBinding {
    /// An empty assembly.
    #[wasm_bindgen(constructor)]
    #[must_use]
    pub fn new() -> AssemblyBinding {
        AssemblyBinding::default()
    }

    /// Reads an assembly file (`loci_assembly` JSON).
    #[wasm_bindgen(js_name = fromJson)]
    pub fn from_json(text: &str) -> Result<AssemblyBinding, JsValue> {
        js(AssemblyBinding::read(text))
    }

    /// The assembly file, with the current poses.
    #[wasm_bindgen(js_name = toJson)]
    #[must_use]
    pub fn to_json(&self) -> String {
        file::write(&self.asm)
    }

    /// Adds a component given as the JSON of the assembly format; its index.
    #[wasm_bindgen(js_name = addComponent)]
    pub fn add_component(&mut self, json: &str) -> Result<u32, JsValue> {
        js(parse::<Component>("component", json).and_then(|c| {
            self.asm
                .add_component(c)
                .map(|i| u32::try_from(i).unwrap_or(u32::MAX))
                .map_err(Fault::from)
        }))
    }

    /// Adds a mate given as the JSON of the assembly format; its id.
    #[wasm_bindgen(js_name = addMate)]
    pub fn add_mate(&mut self, json: &str) -> Result<String, JsValue> {
        js(parse::<Mate>("mate", json).and_then(|m| self.asm.add_mate(m).map_err(Fault::from)))
    }

    /// Solves every mate at once; the report as JSON.
    pub fn solve(&mut self) -> Result<String, JsValue> {
        js(self.solve_all())
    }

    /// Solves one mate at a time, pass after pass; every pass as JSON, for animation.
    #[wasm_bindgen(js_name = solveStepped)]
    pub fn solve_stepped(&mut self) -> Result<String, JsValue> {
        js(self
            .asm
            .solve_stepped()
            .map(|r| to_json(&r))
            .map_err(Fault::from))
    }

    /// The components' names, as JSON, in the order of `poses`.
    #[wasm_bindgen(js_name = componentNames)]
    #[must_use]
    pub fn component_names(&self) -> String {
        let v: Vec<&str> = self
            .asm
            .components
            .iter()
            .map(|c| c.name.as_str())
            .collect();
        to_json(&v)
    }

    /// The components, as JSON (name, pose, grounded, references).
    #[must_use]
    pub fn components(&self) -> String {
        to_json(&self.asm.components)
    }

    /// Every component's pose: seven numbers each, translation x, y, z then rotation
    /// quaternion w, x, y, z.
    #[must_use]
    pub fn poses(&self) -> Vec<f64> {
        self.asm
            .components
            .iter()
            .flat_map(|c| {
                let (t, q) = (c.pose.translation, c.pose.rotation);
                [t[0], t[1], t[2], q[0], q[1], q[2], q[3]]
            })
            .collect()
    }

    /// Places a component: translation x, y, z then rotation quaternion w, x, y, z.
    #[wasm_bindgen(js_name = setPose)]
    pub fn set_pose(&mut self, name: &str, pose: &[f64]) -> Result<(), JsValue> {
        js((|| {
            let i = self.component_index(name)?;
            if pose.len() != 7 {
                return Err(Fault::input(
                    Some(format!("component {name}")),
                    format!(
                        "setPose: {} numbers given; 7 are expected (x, y, z, w, qx, qy, qz)",
                        pose.len()
                    ),
                ));
            }
            let p = Pose::new(
                [pose[0], pose[1], pose[2]],
                [pose[3], pose[4], pose[5], pose[6]],
            );
            if !p.is_valid() {
                return Err(loci::assembly::AssemblyError::BadPose(name.to_string()).into());
            }
            self.asm.components[i].pose = p;
            Ok(())
        })())
    }

    /// Reads an angle mate's angle as the solver sees it, as JSON (null for no such mate).
    #[wasm_bindgen(js_name = measureAngle)]
    pub fn measure_angle(&mut self, id: &str) -> String {
        to_json(&self.asm.measure_angle(id))
    }
}
