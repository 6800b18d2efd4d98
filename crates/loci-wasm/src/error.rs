//! Errors as they cross into JavaScript: a class (which `Error` subclass the JavaScript
//! wrapper throws), the object at fault as loci names it, and the message.

use loci::assembly::AssemblyError;
use loci::format::assembly::AssemblyFormatError;
use loci::format::json::JsonError;
use loci::format::sketch::SketchFileError;
use loci::format::slvs::{ExportError, SlvsError};
use loci::sketch::SketchError;
use loci::{ModelError, SolveError};
use wasm_bindgen::JsValue;

/// The error classes of the package, one per layer and one for input that is not usable at
/// all. The JavaScript wrapper throws the `Error` subclass of the same name.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Class {
    /// The SolveSpace model: dangling or wrong references, bad handles, bad numbers.
    Model,
    /// A solve that cannot start: an unknown group, a bad option.
    Solve,
    /// The sketcher: unknown shapes, wrong shape kinds, bad values.
    Sketch,
    /// Assemblies: unknown components, references or mates.
    Assembly,
    /// A file that cannot be read: JSON or `.slvs`.
    Format,
    /// An argument of the wrong shape (a handle that is not a handle, a missing drag).
    Input,
}

impl Class {
    /// The name of the JavaScript class.
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            Class::Model => "ModelError",
            Class::Solve => "SolveError",
            Class::Sketch => "SketchError",
            Class::Assembly => "AssemblyError",
            Class::Format => "FormatError",
            Class::Input => "InputError",
        }
    }
}

/// An error on its way to JavaScript.
#[derive(Clone, Debug, PartialEq)]
pub struct Fault {
    /// Which class.
    pub class: Class,
    /// The object at fault as loci names it (`entity 12`, `point 104`, `mate revolute1`,
    /// `component door`), when there is one.
    pub object: Option<String>,
    /// The whole message, naming the object and what was expected.
    pub message: String,
}

impl Fault {
    /// An argument that is not usable.
    pub fn input(object: Option<String>, message: impl Into<String>) -> Self {
        Fault {
            class: Class::Input,
            object,
            message: message.into(),
        }
    }

    /// The JavaScript `Error` thrown: its `name` is the class, with `object` and
    /// `lociClass` properties that the wrapper reads to throw the subclass.
    #[must_use]
    pub fn into_js(self) -> JsValue {
        let e = js_sys::Error::new(&self.message);
        e.set_name(self.class.name());
        let v: JsValue = e.into();
        let object = self.object.map_or(JsValue::NULL, |o| JsValue::from_str(&o));
        // Setting a property on a fresh Error cannot fail.
        let _ = js_sys::Reflect::set(&v, &JsValue::from_str("object"), &object);
        let _ = js_sys::Reflect::set(
            &v,
            &JsValue::from_str("lociClass"),
            &JsValue::from_str(self.class.name()),
        );
        v
    }
}

/// The result type of the bindings' inner functions.
pub type Res<T> = Result<T, Fault>;

/// Converts an inner result for a `#[wasm_bindgen]` function.
pub fn js<T>(r: Res<T>) -> Result<T, JsValue> {
    r.map_err(Fault::into_js)
}

fn model_object(e: &ModelError) -> Option<String> {
    Some(match e {
        ModelError::ZeroHandle { what, index } => format!("{what} #{index}"),
        ModelError::DuplicateHandle { object } | ModelError::InUse { object, .. } => {
            object.to_string()
        }
        ModelError::Dangling { owner, .. }
        | ModelError::WrongKind { owner, .. }
        | ModelError::MissingField { owner, .. }
        | ModelError::NonFinite { owner, .. }
        | ModelError::OutOfRange { owner, .. } => owner.to_string(),
        ModelError::NeedsWorkplane { constraint, .. } => constraint.to_string(),
        ModelError::Cycle { entity } => entity.to_string(),
        _ => return None,
    })
}

impl From<ModelError> for Fault {
    fn from(e: ModelError) -> Self {
        Fault {
            class: Class::Model,
            object: model_object(&e),
            message: e.to_string(),
        }
    }
}

impl From<SolveError> for Fault {
    fn from(e: SolveError) -> Self {
        let object = match &e {
            SolveError::Model(m) => return m.clone().into(),
            SolveError::UnknownGroup { group, .. } => Some(group.to_string()),
            SolveError::UnknownDragged(h) => Some(format!("param {h}")),
            SolveError::BadOption { name, .. } => Some(format!("option {name}")),
            _ => None,
        };
        Fault {
            class: Class::Solve,
            object,
            message: e.to_string(),
        }
    }
}

impl From<SketchError> for Fault {
    fn from(e: SketchError) -> Self {
        let object = match &e {
            SketchError::Model(m) => return m.clone().into(),
            SketchError::Solve(s) => return s.clone().into(),
            SketchError::NoShape(s) | SketchError::Fixed(s) => Some(s.to_string()),
            SketchError::WrongShape { shape, .. } | SketchError::SameShape { shape, .. } => {
                Some(shape.to_string())
            }
            SketchError::NoConstraint(c) => Some(c.to_string()),
            SketchError::BadValue { what, .. } => Some((*what).to_string()),
            SketchError::NotADimension(kind) => Some((*kind).to_string()),
            _ => None,
        };
        Fault {
            class: Class::Sketch,
            object,
            message: e.to_string(),
        }
    }
}

impl From<SketchFileError> for Fault {
    fn from(e: SketchFileError) -> Self {
        let (class, object) = match &e {
            SketchFileError::Json(_) => (Class::Format, None),
            SketchFileError::DuplicateName(n) => (Class::Format, Some(n.clone())),
            SketchFileError::UnknownName { owner, .. } | SketchFileError::Sketch { owner, .. } => {
                (Class::Sketch, Some(owner.clone()))
            }
            _ => (Class::Format, None),
        };
        Fault {
            class,
            object,
            message: e.to_string(),
        }
    }
}

impl From<AssemblyError> for Fault {
    fn from(e: AssemblyError) -> Self {
        let object = match &e {
            AssemblyError::Solve(s) => return s.clone().into(),
            AssemblyError::Model(m) => return m.clone().into(),
            AssemblyError::DuplicateComponent(c) | AssemblyError::BadPose(c) => {
                Some(format!("component {c}"))
            }
            AssemblyError::BadReference { component, .. } => Some(format!("component {component}")),
            AssemblyError::UnknownComponent { mate, .. }
            | AssemblyError::UnknownReference { mate, .. }
            | AssemblyError::Unusable { mate, .. }
            | AssemblyError::SameComponent { mate, .. }
            | AssemblyError::NotAttached { mate, .. }
            | AssemblyError::BadValue { mate, .. } => Some(format!("mate {mate}")),
            AssemblyError::DuplicateMate(m) => Some(format!("mate {m}")),
            AssemblyError::BadOption { name, .. } => Some(format!("option {name}")),
            _ => None,
        };
        Fault {
            class: Class::Assembly,
            object,
            message: e.to_string(),
        }
    }
}

impl From<AssemblyFormatError> for Fault {
    fn from(e: AssemblyFormatError) -> Self {
        match e {
            AssemblyFormatError::Invalid(a) => a.into(),
            AssemblyFormatError::Rotation(c) => Fault {
                class: Class::Format,
                object: Some(format!("component {c}")),
                message: AssemblyFormatError::Rotation(c).to_string(),
            },
            other => Fault {
                class: Class::Format,
                object: None,
                message: other.to_string(),
            },
        }
    }
}

impl From<JsonError> for Fault {
    fn from(e: JsonError) -> Self {
        let message = e.to_string();
        if let Some(m) = &e.model {
            // Valid JSON describing an invalid model: a model error, with the file's place.
            return Fault {
                message,
                ..(**m).clone().into()
            };
        }
        Fault {
            class: Class::Format,
            object: (!e.object.is_empty()).then(|| e.object.clone()),
            message,
        }
    }
}

impl From<SlvsError> for Fault {
    fn from(e: SlvsError) -> Self {
        Fault {
            class: Class::Format,
            object: Some(format!("line {}", e.line())),
            message: e.to_string(),
        }
    }
}

impl From<ExportError> for Fault {
    fn from(e: ExportError) -> Self {
        match e {
            ExportError::Model(m) => m.into(),
            other => Fault {
                class: Class::Format,
                object: None,
                message: other.to_string(),
            },
        }
    }
}

/// Reads JSON of a Rust type, naming what was being read when it does not fit.
pub fn parse<T: serde::de::DeserializeOwned>(what: &str, text: &str) -> Res<T> {
    serde_json::from_str(text).map_err(|e| Fault {
        class: Class::Input,
        object: Some(what.to_string()),
        message: format!("{what}: {e}"),
    })
}

/// Writes a value as JSON (the report types always serialise).
pub fn to_json<T: serde::Serialize>(v: &T) -> String {
    serde_json::to_string(v).unwrap_or_else(|e| format!("{{\"error\":\"{e}\"}}"))
}
