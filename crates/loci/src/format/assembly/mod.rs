//! The assembly JSON format (`docs/assembly-format.md`, schema `docs/assembly.schema.json`):
//! components with poses and named references, world references, mates and options.
//!
//! ```json
//! { "loci_assembly": 1,
//!   "components": [
//!     { "name": "frame", "grounded": true,
//!       "references": { "hinge": { "type": "axis", "point": [0, 0, 0], "direction": [0, 0, 1] } } },
//!     { "name": "door", "pose": { "translation": [0, 0, 0], "rotation": [1, 0, 0, 0] },
//!       "references": { "hinge": { "type": "axis", "point": [0, 0, 0], "direction": [0, 0, 1] } } } ],
//!   "mates": [ { "type": "revolute", "a": { "component": "frame", "reference": "hinge" },
//!                "b": { "component": "door", "reference": "hinge" } } ] }
//! ```

use crate::assembly::{Assembly, AssemblyError};
use serde::{Deserialize, Serialize};
use thiserror::Error;

/// The version this reader understands and the writer writes.
pub const VERSION: u32 = 1;

/// Why an assembly file cannot be read.
#[derive(Clone, Debug, Error, PartialEq)]
#[non_exhaustive]
pub enum AssemblyFormatError {
    /// Not JSON, or not an assembly's shape.
    #[error("line {line}, column {column}: {message}")]
    Json {
        /// 1-based line.
        line: usize,
        /// 1-based column.
        column: usize,
        /// What serde found wrong.
        message: String,
    },
    /// A version this reader does not know.
    #[error("loci_assembly version {0} is not supported; this reader knows version {VERSION}")]
    Version(u32),
    /// A component's rotation quaternion is zero or not finite.
    #[error("component `{0}`: the rotation must be a non-zero quaternion [w, x, y, z]")]
    Rotation(String),
    /// Well-formed JSON describing an assembly that is not valid.
    #[error(transparent)]
    Invalid(#[from] AssemblyError),
}

fn one() -> u32 {
    VERSION
}

#[derive(Deserialize)]
struct FileIn {
    #[serde(default = "one")]
    loci_assembly: u32,
    #[serde(flatten)]
    assembly: Assembly,
}

#[derive(Serialize)]
struct FileOut<'a> {
    loci_assembly: u32,
    #[serde(flatten)]
    assembly: &'a Assembly,
}

/// Reads an assembly: the JSON, then every component and mate through [`Assembly`]'s
/// checks (unique names and ids, finite poses and references). Rotations are normalised;
/// mates without an id are given one.
///
/// # Errors
/// Malformed JSON (with its line and column), an unknown version, a zero rotation, or an
/// invalid assembly.
pub fn read(text: &str) -> Result<Assembly, AssemblyFormatError> {
    let f: FileIn = serde_json::from_str(text).map_err(|e| AssemblyFormatError::Json {
        line: e.line(),
        column: e.column(),
        message: e.to_string(),
    })?;
    if f.loci_assembly != VERSION {
        return Err(AssemblyFormatError::Version(f.loci_assembly));
    }
    let raw = f.assembly;
    let mut asm = Assembly {
        options: raw.options,
        world: raw.world,
        ..Assembly::default()
    };
    for mut c in raw.components {
        let q = c.pose.rotation;
        let n = q.iter().map(|x| x * x).sum::<f64>().sqrt();
        if !(n > 1e-12 && n.is_finite()) {
            return Err(AssemblyFormatError::Rotation(c.name));
        }
        // A rotation already of unit length to rounding is kept as written, so that an
        // assembly read back from the file it was written to is the same to the last bit and
        // solves as it did (a failing solve's steps can part ways over a last bit: 9
        // iterations against 74 on one random assembly).
        if (n - 1.0).abs() > UNIT_TO_ROUNDING {
            c.pose.rotation = q.map(|x| x / n);
        }
        asm.add_component(c)?;
    }
    for m in raw.mates {
        asm.add_mate(m)?;
    }
    Ok(asm)
}

/// How far from 1 a rotation's length may be for [`read`] to keep it as written: rounding in
/// the products that make a unit quaternion.
const UNIT_TO_ROUNDING: f64 = 8.0 * f64::EPSILON;

/// Writes an assembly (with its current poses) as pretty JSON that [`read`] reads back.
#[must_use]
pub fn write(asm: &Assembly) -> String {
    serde_json::to_string_pretty(&FileOut {
        loci_assembly: VERSION,
        assembly: asm,
    })
    .expect("an assembly always serialises")
}

#[cfg(test)]
mod tests {
    use super::*;

    const DOOR: &str = r#"{ "loci_assembly": 1,
      "components": [
        { "name": "frame", "grounded": true,
          "references": { "hinge": { "type": "axis", "point": [0, 0, 0], "direction": [0, 0, 1] },
                          "jamb": { "type": "face", "point": [0, 0, 0], "normal": [1, 0, 0] } } },
        { "name": "door", "pose": { "translation": [0.1, 0, 0], "rotation": [2, 0, 0, 0] },
          "references": { "hinge": { "type": "axis", "point": [0, 0, 0], "direction": [0, 0, 1] },
                          "face": { "type": "face", "point": [0, 0, 0], "normal": [1, 0, 0] } } } ],
      "mates": [ { "type": "revolute", "a": { "component": "frame", "reference": "hinge" },
                   "b": { "component": "door", "reference": "hinge" } },
                 { "type": "angle", "degrees": 30, "a": { "component": "frame", "reference": "jamb" },
                   "b": { "component": "door", "reference": "face" } } ] }"#;

    #[test]
    fn reads_solves_and_reads_back() {
        let mut asm = read(DOOR).unwrap();
        assert_eq!(asm.components[1].pose.rotation, [1.0, 0.0, 0.0, 0.0]);
        assert_eq!(asm.mates[1].id, "ANGL1");
        assert_eq!(asm.components[1].references[1].0, "face");
        let r = asm.solve().unwrap();
        assert!(r.all_hold(), "{r}");
        let again = read(&write(&asm)).unwrap();
        assert_eq!(again.components, asm.components);
        assert_eq!(again.mates.len(), 2);
    }

    #[test]
    fn a_rotation_of_unit_length_to_rounding_reads_back_as_written() {
        let mut asm = read(DOOR).unwrap();
        // Unit to rounding, not exactly: dividing by its length would change its last bits.
        let q = [0.6, 0.8 + 2.0 * f64::EPSILON, 0.0, 0.0];
        asm.components[1].pose.rotation = q;
        let text = write(&asm);
        let again = read(&text).unwrap();
        assert_eq!(again.components[1].pose.rotation, q);
        assert_eq!(write(&again), text);
        // A rotation further from unit length is still made one.
        asm.components[1].pose.rotation = [0.6, 0.8 + 1e-9, 0.0, 0.0];
        let scaled = read(&write(&asm)).unwrap().components[1].pose.rotation;
        let n = scaled.iter().map(|x| x * x).sum::<f64>().sqrt();
        assert!((n - 1.0).abs() <= UNIT_TO_ROUNDING, "{scaled:?}");
        assert_ne!(scaled[1], 0.8 + 1e-9);
    }

    #[test]
    fn errors_say_where_and_what() {
        match read("{ \"components\": [ { \"name\": 3 } ] }") {
            Err(AssemblyFormatError::Json { line: 1, .. }) => {}
            other => panic!("{other:?}"),
        }
        assert_eq!(
            read("{ \"loci_assembly\": 7 }"),
            Err(AssemblyFormatError::Version(7))
        );
        let zero = DOOR.replace("[2, 0, 0, 0]", "[0, 0, 0, 0]");
        assert_eq!(
            read(&zero),
            Err(AssemblyFormatError::Rotation("door".into()))
        );
        let twice = DOOR.replace("\"name\": \"door\"", "\"name\": \"frame\"");
        assert!(matches!(
            read(&twice),
            Err(AssemblyFormatError::Invalid(
                AssemblyError::DuplicateComponent(_)
            ))
        ));
    }
}
