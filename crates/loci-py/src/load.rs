//! `loci.load` and `loci.loads`: one entry point for every file loci reads, returning the
//! object of the layer the file describes.

use crate::assembly::PyAssembly;
use crate::errors;
use crate::sketch::PySketch;
use crate::system::PySystem;
use loci::format::slvs::SlvsFile;
use pyo3::prelude::*;
use std::path::PathBuf;

fn from_text(py: Python<'_>, text: &str) -> PyResult<PyObject> {
    if loci::format::sketch::is_sketch_json(text) {
        return Ok(Py::new(py, PySketch::from_json_text(text)?)?.into_any());
    }
    let probe: serde_json::Value =
        serde_json::from_str(text).map_err(|e| errors::file(format!("not JSON: {e}")))?;
    if probe.get("loci_assembly").is_some() || probe.get("components").is_some() {
        let a = loci::format::assembly::read(text).map_err(errors::file)?;
        return Ok(Py::new(py, PyAssembly { inner: a })?.into_any());
    }
    let p = loci::format::json::Problem::from_json(text).map_err(errors::file)?;
    Ok(Py::new(py, PySystem::from_system(p.system))?.into_any())
}

/// Reads a file: a ``.slvs`` SolveSpace file or a loci JSON problem gives a ``System``, a
/// sketch file a ``Sketch``, an assembly file an ``Assembly``.
#[pyfunction]
pub fn load(py: Python<'_>, path: PathBuf) -> PyResult<PyObject> {
    let bytes = std::fs::read(&path)?;
    let is_slvs = path
        .extension()
        .is_some_and(|e| e.eq_ignore_ascii_case("slvs"))
        || bytes.starts_with(b"\xb1\xb2\xb3SolveSpaceREVa");
    if is_slvs {
        let f = SlvsFile::parse(&bytes)
            .map_err(|e| errors::file(format!("{}: {e}", path.display())))?;
        return Ok(Py::new(py, PySystem::from_system(f.system))?.into_any());
    }
    let text = String::from_utf8(bytes)
        .map_err(|_| errors::file(format!("{}: not UTF-8 text", path.display())))?;
    from_text(py, &text).map_err(|e| {
        if e.is_instance_of::<errors::FileError>(py) {
            errors::file(format!("{}: {}", path.display(), e.value(py)))
        } else {
            e
        }
    })
}

/// Reads JSON text as ``load`` reads a file (a problem, a sketch or an assembly).
#[pyfunction]
pub fn loads(py: Python<'_>, text: &str) -> PyResult<PyObject> {
    from_text(py, text)
}
