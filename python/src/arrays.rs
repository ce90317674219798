//! NumPy arrays in and out: float64 values in [0,1) or uint32/uint64 words, 1-D (one
//! dimension) or 2-D (points × dimensions), in any memory order.

use gartowen::core::{word_to_f64, Width};
use gartowen::netcheck::PointSet;
use numpy::ndarray::Array2;
use numpy::{
    dtype, IntoPyArray, PyArrayDescrMethods, PyArrayDyn, PyArrayMethods, PyUntypedArray,
    PyUntypedArrayMethods,
};
use pyo3::exceptions::{PyMemoryError, PyTypeError, PyValueError};
use pyo3::prelude::*;

/// What the caller passed: the element type decides the width and the output type.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Element {
    /// float64 values, read as exact 64-bit words.
    F64,
    /// uint32 words.
    U32,
    /// uint64 words.
    U64,
}

/// Points as row-major words, with the element type they came in.
pub struct InputPoints {
    /// Element type of the array.
    pub element: Element,
    /// Number of points.
    pub n: usize,
    /// Coordinates per point.
    pub dims: usize,
    /// Row-major words: point i, dimension j at `words[i·dims + j]`.
    pub words: Vec<u64>,
}

impl InputPoints {
    /// The word width: 32 for uint32, else 64.
    pub fn width(&self) -> Width {
        match self.element {
            Element::U32 => Width::W32,
            Element::F64 | Element::U64 => Width::W64,
        }
    }

    /// The points as a net-checker point set.
    pub fn point_set(&self) -> PyResult<PointSet> {
        PointSet::from_flat(self.width(), self.dims, &self.words)
            .map_err(|e| PyValueError::new_err(e.to_string()))
    }
}

/// An empty vector with room for `len` elements, or `MemoryError` naming `what` (under a
/// memory cap an infallible allocation would abort the interpreter).
pub fn try_vec<T>(len: usize, what: &str) -> PyResult<Vec<T>> {
    let mut v = Vec::new();
    v.try_reserve_exact(len).map_err(|_| {
        PyMemoryError::new_err(format!(
            "cannot allocate {len} elements ({} MiB) for {what}",
            len.saturating_mul(std::mem::size_of::<T>()) >> 20
        ))
    })?;
    Ok(v)
}

/// Raises `MemoryError` unless `bytes` can be allocated now: checked before work whose
/// transient buffers are allocated where a failure cannot be caught.
pub fn ensure_room(bytes: usize, what: &str) -> PyResult<()> {
    try_vec::<u8>(bytes, what).map(drop)
}

/// Reads `obj` (named `what` in messages) as points, float64 values exactly.
pub fn read_points(obj: &Bound<'_, PyAny>, what: &str) -> PyResult<InputPoints> {
    read_points_as(obj, what, false)
}

/// Reads `obj` as points; with `floor`, a float64 value becomes the 64-bit word at or below it
/// (exact for every box of depth ≤ 64 bits: the net check), else it must be a multiple of 2^-64.
pub fn read_points_as(obj: &Bound<'_, PyAny>, what: &str, floor: bool) -> PyResult<InputPoints> {
    let py = obj.py();
    let array = obj.cast::<PyUntypedArray>().map_err(|_| {
        PyTypeError::new_err(format!(
            "{what} must be a NumPy array of float64 values in [0,1) or uint32/uint64 words, \
             not {}",
            obj.get_type()
                .name()
                .map(|n| n.to_string())
                .unwrap_or_else(|_| "?".into())
        ))
    })?;
    let shape = array.shape().to_vec();
    let (n, dims) = match shape.as_slice() {
        [n] => (*n, 1),
        [n, d] => (*n, *d),
        _ => {
            return Err(PyValueError::new_err(format!(
            "{what} must be 1-D (one dimension) or 2-D (points × dimensions), got shape {shape:?}"
        )))
        }
    };
    if n == 0 || dims == 0 {
        return Err(PyValueError::new_err(format!(
            "{what} is empty (shape {shape:?})"
        )));
    }
    let dt = array.dtype();
    let (element, words) = if dt.is_equiv_to(&dtype::<f64>(py)) {
        let a = array.cast::<PyArrayDyn<f64>>()?.readonly();
        let view = a.as_array();
        let mut words = try_vec(n.saturating_mul(dims), what)?;
        for (k, &v) in view.iter().enumerate() {
            let w = if floor {
                gartowen::core::word_from_f64_floor(v)
            } else {
                gartowen::core::word_from_f64(v, Width::W64)
            }
            .map_err(|e| {
                PyValueError::new_err(format!(
                    "{what}: point {}, dimension {}: {e}",
                    k / dims,
                    k % dims
                ))
            })?;
            words.push(w);
        }
        (Element::F64, words)
    } else if dt.is_equiv_to(&dtype::<u32>(py)) {
        let a = array.cast::<PyArrayDyn<u32>>()?.readonly();
        let mut words = try_vec(n.saturating_mul(dims), what)?;
        words.extend(a.as_array().iter().map(|&x| x as u64));
        (Element::U32, words)
    } else if dt.is_equiv_to(&dtype::<u64>(py)) {
        let a = array.cast::<PyArrayDyn<u64>>()?.readonly();
        let mut words = try_vec(n.saturating_mul(dims), what)?;
        match a.as_slice() {
            Ok(s) => words.extend_from_slice(s),
            Err(_) => words.extend(a.as_array().iter().copied()),
        }
        (Element::U64, words)
    } else {
        return Err(PyTypeError::new_err(format!(
            "{what} has dtype {}: use float64 values in [0,1) or uint32/uint64 words",
            dt.str()
                .map(|s| s.to_string())
                .unwrap_or_else(|_| "?".into())
        )));
    };
    Ok(InputPoints {
        element,
        n,
        dims,
        words,
    })
}

/// An (n, dims) array of `words` (row-major) as `element`: float64 values (truncated to 53
/// bits, never 1.0), uint32 or uint64 words.
pub fn to_array<'py>(
    py: Python<'py>,
    words: Vec<u64>,
    n: usize,
    dims: usize,
    width: Width,
    element: Element,
) -> PyResult<Bound<'py, PyAny>> {
    let shape = (n, dims);
    let bad = |e: numpy::ndarray::ShapeError| PyValueError::new_err(e.to_string());
    Ok(match element {
        Element::F64 => {
            let mut v: Vec<f64> = try_vec(words.len(), "the scrambled points")?;
            v.extend(words.iter().map(|&x| word_to_f64(x, width)));
            Array2::from_shape_vec(shape, v)
                .map_err(bad)?
                .into_pyarray(py)
                .into_any()
        }
        Element::U32 => {
            let mut v: Vec<u32> = try_vec(words.len(), "the scrambled words")?;
            v.extend(words.iter().map(|&x| x as u32));
            Array2::from_shape_vec(shape, v)
                .map_err(bad)?
                .into_pyarray(py)
                .into_any()
        }
        Element::U64 => Array2::from_shape_vec(shape, words)
            .map_err(bad)?
            .into_pyarray(py)
            .into_any(),
    })
}
