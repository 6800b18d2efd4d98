//! Python bindings of loci, built by maturin into the extension module `loci._loci`; the
//! pure-Python package `loci` (in `python/loci`) re-exports it and adds the `loci.slvs`
//! drop-in for SolveSpace's module.
//!
//! Three layers are bound: the SolveSpace model (`loci.System`, `system.rs`), the sketcher
//! (`loci.Sketch`, `sketch.rs`) and assemblies (`loci.Assembly`, `assembly.rs`). Every error crosses the
//! boundary as a `loci.LociError` subclass; nothing panics into Python; solves release the GIL.

mod assembly;
mod convert;
mod errors;
mod load;
mod result;
mod shapes;
mod sketch;
mod sketch_items;
mod slvs;
mod system;

use pyo3::prelude::*;

/// loci's own allocations (not Python's) go through mimalloc, as in `loci-bench`: with
/// glibc's malloc the large blocks of a big solve go back to the kernel when freed and are
/// faulted in again on the next, which cost a 10,000-segment chain a third of its solve time.
#[global_allocator]
static GLOBAL: mimalloc::MiMalloc = mimalloc::MiMalloc;

/// The native part of the `loci` package.
#[pymodule]
fn _loci(m: &Bound<'_, PyModule>) -> PyResult<()> {
    let py = m.py();
    m.add("LociError", py.get_type::<errors::LociError>())?;
    m.add("ModelError", py.get_type::<errors::ModelError>())?;
    m.add("SolveError", py.get_type::<errors::SolveError>())?;
    m.add("FileError", py.get_type::<errors::FileError>())?;
    m.add_class::<system::PySystem>()?;
    m.add_class::<result::SolveResult>()?;
    m.add_class::<result::CheckResult>()?;
    m.add_class::<sketch::PySketch>()?;
    m.add_class::<shapes::Point>()?;
    m.add_class::<shapes::Line>()?;
    m.add_class::<shapes::Circle>()?;
    m.add_class::<shapes::Arc>()?;
    m.add_class::<shapes::Cubic>()?;
    m.add_class::<sketch_items::SketchConstraint>()?;
    m.add_class::<sketch_items::SketchResult>()?;
    m.add_class::<sketch_items::DragResult>()?;
    m.add_class::<assembly::PyAssembly>()?;
    m.add_class::<assembly::AssemblyResult>()?;
    m.add_class::<slvs::SlvsModel>()?;
    m.add_function(wrap_pyfunction!(load::load, m)?)?;
    m.add_function(wrap_pyfunction!(load::loads, m)?)?;
    m.add("__version__", env!("CARGO_PKG_VERSION"))?;
    Ok(())
}
