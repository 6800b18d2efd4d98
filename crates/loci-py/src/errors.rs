//! The exceptions: `LociError` and its subclasses, and the conversions from loci's typed
//! errors. Messages are loci's own, which name the offending object and what was expected.

use pyo3::create_exception;
use pyo3::exceptions::PyException;
use pyo3::PyErr;

create_exception!(
    loci,
    LociError,
    PyException,
    "The base of every error loci raises."
);
create_exception!(
    loci,
    ModelError,
    LociError,
    "An invalid model: the message names the offending object and what was expected."
);
create_exception!(
    loci,
    SolveError,
    LociError,
    "A solve that cannot start (an unknown group, a bad option, a problem too large). \
     An inconsistent system is not an error: it is a result naming the conflicting constraints."
);
create_exception!(
    loci,
    FileError,
    LociError,
    "A file that cannot be read as a loci JSON, sketch, assembly or .slvs file; the message \
     says where."
);

/// A model error as a Python exception.
pub fn model(e: impl std::fmt::Display) -> PyErr {
    ModelError::new_err(e.to_string())
}

/// A solve error: model errors inside it stay `ModelError`s.
pub fn solve(e: loci::SolveError) -> PyErr {
    match e {
        loci::SolveError::Model(m) => model(m),
        other => SolveError::new_err(other.to_string()),
    }
}

/// A file error.
pub fn file(e: impl std::fmt::Display) -> PyErr {
    FileError::new_err(e.to_string())
}

/// A solve error from a message.
pub fn solve_msg(msg: String) -> PyErr {
    SolveError::new_err(msg)
}
