//! `viscoroll._core`: the Rust side of the Python package `viscoroll` (PyO3), a thin adaptor over
//! the library's own stage functions, the ones the CLI's subcommands call (src/cli/*.rs).
//!
//! Every value crosses the boundary as the library's own serde JSON (a `Measurement`, a
//! `MasterCurve`, a `CompoundFit`, a `CreepSpectrum`, a `RunSummary`; `serde_json` with
//! `float_roundtrip`, so every f64 comes back bit for bit), and options as a JSON object whose keys
//! are the CLI's flag names with `_` for `-`. The Python layer (python/viscoroll) turns them into
//! DataFrames with pyvisco's column names and raises the warnings. Errors are raised as one
//! exception class per stage, each a subclass of `ViscorollError`, with the CLI's message (the
//! error and its causes, each once: `viscoroll::cli::error_text`).

use pyo3::create_exception;
use pyo3::exceptions::PyException;
use pyo3::prelude::*;
use pyo3::types::PyTuple;
use pyo3::IntoPyObjectExt;

/// Export `|py, args| body` as the function `name` of module `m` (pyo3 without its proc macros:
/// they would switch on features of `syn` that the root crate's build does not use, so that every
/// proc macro, and every crate behind one, would be compiled twice in target/).
macro_rules! export {
    ($m:expr, $name:literal, |$py:ident, $args:ident| $body:expr) => {
        $m.add_function(pyo3::types::PyCFunction::new_closure(
            $m.py(),
            Some($name),
            None,
            |$args: &pyo3::Bound<'_, pyo3::types::PyTuple>,
             _kw: Option<&pyo3::Bound<'_, pyo3::types::PyDict>>|
             -> pyo3::PyResult<pyo3::Py<pyo3::PyAny>> {
                let $py = $args.py();
                $crate::ret($py, $body?)
            },
        )?)?
    };
}

mod opts;
mod scenes;
mod stages;

create_exception!(
    viscoroll,
    ViscorollError,
    PyException,
    "Base class of every error viscoroll raises."
);
create_exception!(
    viscoroll,
    IngestError,
    ViscorollError,
    "Reading DMA data failed."
);
create_exception!(
    viscoroll,
    MasterError,
    ViscorollError,
    "The master curve could not be built."
);
create_exception!(
    viscoroll,
    FitError,
    ViscorollError,
    "The fit (master curve, Prony series, creep spectrum) failed."
);
create_exception!(
    viscoroll,
    ConvertError,
    ViscorollError,
    "Relaxation → creep conversion failed."
);
create_exception!(
    viscoroll,
    RollError,
    ViscorollError,
    "A rolling-contact solve failed."
);
create_exception!(
    viscoroll,
    MapsError,
    ViscorollError,
    "Friction maps could not be computed."
);
create_exception!(viscoroll, RunError, ViscorollError, "The main job failed.");

/// The stage an error comes from, i.e. the Python exception class it is raised as.
#[derive(Clone, Copy)]
pub(crate) enum Stage {
    Ingest,
    Master,
    Fit,
    Convert,
    Roll,
    Maps,
    Run,
}

/// An error of `stage` as its Python exception, with the CLI's text of the error and its causes.
pub(crate) fn stage_err<E>(stage: Stage) -> impl Fn(E) -> PyErr
where
    E: Into<anyhow::Error>,
{
    move |e| {
        let text = viscoroll::cli::error_text(&e.into());
        match stage {
            Stage::Ingest => IngestError::new_err(text),
            Stage::Master => MasterError::new_err(text),
            Stage::Fit => FitError::new_err(text),
            Stage::Convert => ConvertError::new_err(text),
            Stage::Roll => RollError::new_err(text),
            Stage::Maps => MapsError::new_err(text),
            Stage::Run => RunError::new_err(text),
        }
    }
}

/// A serde value as JSON text (an error of `stage` if it cannot be written, e.g. a NaN).
pub(crate) fn to_json<T: serde::Serialize>(stage: Stage, v: &T) -> PyResult<String> {
    serde_json::to_string(v).map_err(stage_err(stage))
}

/// Argument `i` of a call (the Python layer passes every argument, positionally).
pub(crate) fn arg<'py, T>(args: &Bound<'py, PyTuple>, i: usize) -> PyResult<T>
where
    T: pyo3::conversion::FromPyObjectOwned<'py>,
{
    let item = args.get_item(i)?;
    item.extract::<T>().map_err(Into::into)
}

/// A result as a Python object.
pub(crate) fn ret<'py, T: IntoPyObject<'py>>(py: Python<'py>, v: T) -> PyResult<Py<PyAny>> {
    v.into_py_any(py)
}

/// The module's definition (CPython takes a module from a single-phase init only if it was made
/// from one).
static mut MODULE_DEF: pyo3::ffi::PyModuleDef = pyo3::ffi::PyModuleDef {
    m_base: pyo3::ffi::PyModuleDef_HEAD_INIT,
    m_name: c"_core".as_ptr(),
    m_doc: c"The Rust side of viscoroll's Python package.".as_ptr(),
    m_size: 0,
    m_methods: std::ptr::null_mut(),
    m_slots: std::ptr::null_mut(),
    m_traverse: None,
    m_clear: None,
    m_free: None,
};

/// The module's entry point (what `#[pymodule]` would generate: single-phase initialisation).
#[no_mangle]
pub extern "C" fn PyInit__core() -> *mut pyo3::ffi::PyObject {
    Python::attach(|py| match module(py) {
        Ok(m) => m.into_ptr(),
        Err(e) => {
            e.restore(py);
            std::ptr::null_mut()
        }
    })
}

fn module(py: Python<'_>) -> PyResult<Bound<'_, PyModule>> {
    // SAFETY: MODULE_DEF is only ever used here, by CPython's import (under the interpreter lock),
    // through a raw pointer; PyModule_Create returns a new reference or NULL with an exception set.
    let m = unsafe {
        let def = std::ptr::addr_of_mut!(MODULE_DEF);
        Bound::from_owned_ptr_or_err(py, pyo3::ffi::PyModule_Create(def))?
    }
    .cast_into::<PyModule>()?;
    add_all(&m)?;
    Ok(m)
}

fn add_all(m: &Bound<'_, PyModule>) -> PyResult<()> {
    let py = m.py();
    m.add("ViscorollError", py.get_type::<ViscorollError>())?;
    m.add("IngestError", py.get_type::<IngestError>())?;
    m.add("MasterError", py.get_type::<MasterError>())?;
    m.add("FitError", py.get_type::<FitError>())?;
    m.add("ConvertError", py.get_type::<ConvertError>())?;
    m.add("RollError", py.get_type::<RollError>())?;
    m.add("MapsError", py.get_type::<MapsError>())?;
    m.add("RunError", py.get_type::<RunError>())?;
    stages::register(m)?;
    scenes::register(m)?;
    Ok(())
}
