//! Plain Python values (dicts, lists, numbers, strings) to and from JSON values, so that
//! loci's serde types (entities, references, mates, reports) cross the boundary as the same
//! dictionaries their files hold.

use pyo3::exceptions::PyTypeError;
use pyo3::prelude::*;
use pyo3::types::{PyBool, PyDict, PyFloat, PyInt, PyList, PyString, PyTuple};
use serde_json::{Map, Number, Value};

/// A Python value as JSON: `None`, bools, ints, floats, strings, lists, tuples and dicts
/// with string keys.
pub fn to_json(v: &Bound<'_, PyAny>) -> PyResult<Value> {
    if v.is_none() {
        Ok(Value::Null)
    } else if let Ok(b) = v.downcast::<PyBool>() {
        Ok(Value::Bool(b.is_true()))
    } else if v.is_instance_of::<PyInt>() {
        if let Ok(i) = v.extract::<i64>() {
            Ok(Value::Number(i.into()))
        } else {
            Ok(Value::Number(v.extract::<u64>()?.into()))
        }
    } else if v.is_instance_of::<PyFloat>() {
        let f: f64 = v.extract()?;
        Number::from_f64(f)
            .map(Value::Number)
            .ok_or_else(|| crate::errors::model(format!("{f} is not a finite number")))
    } else if let Ok(s) = v.downcast::<PyString>() {
        Ok(Value::String(s.to_cow()?.into_owned()))
    } else if let Ok(d) = v.downcast::<PyDict>() {
        let mut m = Map::new();
        for (k, x) in d.iter() {
            let key: String = k
                .extract()
                .map_err(|_| PyTypeError::new_err("dictionary keys must be strings"))?;
            m.insert(key, to_json(&x)?);
        }
        Ok(Value::Object(m))
    } else if v.is_instance_of::<PyList>() || v.is_instance_of::<PyTuple>() {
        let mut out = Vec::new();
        for x in v.try_iter()? {
            out.push(to_json(&x?)?);
        }
        Ok(Value::Array(out))
    } else if let Ok(f) = v.extract::<f64>() {
        // NumPy scalars and other numbers.
        Number::from_f64(f)
            .map(Value::Number)
            .ok_or_else(|| crate::errors::model(format!("{f} is not a finite number")))
    } else {
        Err(PyTypeError::new_err(format!(
            "cannot pass a {} to loci; expected a number, string, list or dict",
            v.get_type().name()?
        )))
    }
}

/// A JSON value as plain Python objects.
pub fn to_py(py: Python<'_>, v: &Value) -> PyResult<PyObject> {
    Ok(match v {
        Value::Null => py.None(),
        Value::Bool(b) => PyBool::new(py, *b).to_owned().into_any().unbind(),
        Value::Number(n) => {
            if let Some(i) = n.as_i64() {
                i.into_pyobject(py)?.into_any().unbind()
            } else if let Some(u) = n.as_u64() {
                u.into_pyobject(py)?.into_any().unbind()
            } else {
                n.as_f64()
                    .unwrap_or(f64::NAN)
                    .into_pyobject(py)?
                    .into_any()
                    .unbind()
            }
        }
        Value::String(s) => PyString::new(py, s).into_any().unbind(),
        Value::Array(a) => {
            let l = PyList::empty(py);
            for x in a {
                l.append(to_py(py, x)?)?;
            }
            l.into_any().unbind()
        }
        Value::Object(m) => {
            let d = PyDict::new(py);
            for (k, x) in m {
                d.set_item(k, to_py(py, x)?)?;
            }
            d.into_any().unbind()
        }
    })
}

/// Any serializable loci value as plain Python objects.
pub fn ser_to_py<T: serde::Serialize>(py: Python<'_>, v: &T) -> PyResult<PyObject> {
    let value = serde_json::to_value(v).map_err(crate::errors::model)?;
    to_py(py, &value)
}
