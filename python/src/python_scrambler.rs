//! A vectorized Python function as a scrambler: `fn(words, dim, seed) -> words`, run through
//! the same battery as built-in scramblers and external programs.
//!
//! Every batch the battery asks for becomes one call with a uint32 (32-bit words) or uint64
//! array; a function that takes many seeds at once ([`PythonFunction::call_many`]) gets the
//! words of a run of seeds as one 2-D array, one row per seed. The first exception (raised by the function, or a reply of the wrong shape, type or
//! range) is kept; later batches return zeros without calling Python, the battery's health
//! check marks the checks after it, and `verify` re-raises the exception.

use gartowen::core::{Claim, PowerOfTwoBase, Scrambler, Width};
use numpy::{
    dtype, PyArray1, PyArrayDescrMethods, PyArrayMethods, PyUntypedArray, PyUntypedArrayMethods,
};
use pyo3::exceptions::{PyTypeError, PyValueError};
use pyo3::prelude::*;
use std::sync::atomic::{AtomicU64, Ordering};
use std::sync::{Arc, Mutex};
use std::time::Instant;

/// The Python function and what happened to it, shared by the instances of every seed.
pub struct PythonFunction {
    func: Py<PyAny>,
    /// The function's name, for messages.
    pub name: String,
    width: Width,
    error: Mutex<Option<PyErr>>,
    calls: AtomicU64,
    words: AtomicU64,
    nanos: AtomicU64,
}

impl PythonFunction {
    /// Wraps `func` for `width`-bit words.
    pub fn new(func: Py<PyAny>, name: String, width: Width) -> Self {
        PythonFunction {
            func,
            name,
            width,
            error: Mutex::new(None),
            calls: AtomicU64::new(0),
            words: AtomicU64::new(0),
            nanos: AtomicU64::new(0),
        }
    }

    /// The first error, taken (the caller re-raises it).
    pub fn take_error(&self) -> Option<PyErr> {
        self.error.lock().expect("error slot").take()
    }

    /// Whether an error stopped the function.
    pub fn failed(&self) -> Option<String> {
        self.error
            .lock()
            .expect("error slot")
            .as_ref()
            .map(|e| format!("the Python function raised {e}"))
    }

    /// Calls made, words scrambled and seconds spent inside the function (conversions
    /// excluded), summed over calls: calls on different threads can overlap while the
    /// function releases the GIL, so the sum is not bounded by the battery's wall time.
    pub fn usage(&self) -> (u64, u64, f64) {
        (
            self.calls.load(Ordering::Relaxed),
            self.words.load(Ordering::Relaxed),
            self.nanos.load(Ordering::Relaxed) as f64 * 1e-9,
        )
    }

    /// Scrambles `words` for `dim` and `seed` in one call; on any error the words become 0.
    fn call(&self, words: &mut [u64], dim: u32, seed: u64) {
        if words.is_empty() || self.error.lock().expect("error slot").is_some() {
            words.fill(0);
            return;
        }
        let result = Python::attach(|py| self.call_attached(py, words, 0, dim, seed));
        if let Err(e) = result {
            words.fill(0);
            let mut slot = self.error.lock().expect("error slot");
            if slot.is_none() {
                *slot = Some(e);
            }
        }
    }

    /// Scrambles `words` for seeds `first..first + count` in one call (`fn(words, dim, seeds)`
    /// with words of shape (count, n) and seeds a uint64 array of shape (count, 1)): row i of
    /// the result is seed `first + i`'s. On any error the words become 0.
    pub fn call_many(&self, words: &[u64], dim: u32, first: u64, count: u64) -> Vec<u64> {
        let mut out: Vec<u64> = (0..count).flat_map(|_| words.iter().copied()).collect();
        if out.is_empty() || self.error.lock().expect("error slot").is_some() {
            out.fill(0);
            return out;
        }
        let result =
            Python::attach(|py| self.call_attached(py, &mut out, count as usize, dim, first));
        if let Err(e) = result {
            out.fill(0);
            let mut slot = self.error.lock().expect("error slot");
            if slot.is_none() {
                *slot = Some(e);
            }
        }
        out
    }

    /// Calls the function on `words` with `dim` and stores its reply in `words`: for `rows` = 0
    /// a 1-D array and the seed `first`, else `rows` rows of equal length (row-major) and the
    /// seeds `first + i` as a (rows, 1) array.
    fn call_attached(
        &self,
        py: Python<'_>,
        words: &mut [u64],
        rows: usize,
        dim: u32,
        first: u64,
    ) -> PyResult<()> {
        let shape = [rows, words.len() / rows.max(1)];
        let seed = if rows == 0 {
            first.into_pyobject(py)?.into_any()
        } else {
            let seeds: Vec<u64> = (0..rows as u64).map(|i| first.wrapping_add(i)).collect();
            PyArray1::from_vec(py, seeds).reshape([rows, 1])?.into_any()
        };
        let input = match self.width {
            Width::W32 => {
                let v: Vec<u32> = words.iter().map(|&x| x as u32).collect();
                PyArray1::from_vec(py, v).into_any()
            }
            _ => PyArray1::from_slice(py, words).into_any(),
        };
        let input = if shape[0] == 0 {
            input
        } else {
            input.call_method1("reshape", (shape[0], shape[1]))?
        };
        let started = Instant::now();
        let reply = self.func.bind(py).call1((input, dim, seed));
        self.nanos
            .fetch_add(started.elapsed().as_nanos() as u64, Ordering::Relaxed);
        self.calls.fetch_add(1, Ordering::Relaxed);
        self.words.fetch_add(words.len() as u64, Ordering::Relaxed);
        let reply = reply?;
        let what = format!("{} returned", self.name);
        let array = reply.cast::<PyUntypedArray>().map_err(|_| {
            PyTypeError::new_err(format!(
                "{what} {}, not a NumPy array of words",
                reply
                    .get_type()
                    .name()
                    .map(|n| n.to_string())
                    .unwrap_or_else(|_| "?".into())
            ))
        })?;
        let want: Vec<usize> = if shape[0] == 0 {
            vec![words.len()]
        } else {
            shape.to_vec()
        };
        if array.shape() != want.as_slice() {
            return Err(PyValueError::new_err(format!(
                "{what} shape {:?} for an input of shape {:?}",
                array.shape(),
                want
            )));
        }
        // A C-ordered copy, so that the words read back in the order they were sent.
        let array = array.call_method1("ravel", ())?;
        let array = array.cast::<PyUntypedArray>()?;
        let dt = array.dtype();
        let mask = self.width.mask();
        // The seed word k was scrambled with: row k / n of a 2-D call, else the one seed.
        let seed_of = |k: usize| match rows {
            0 => first,
            _ => first.wrapping_add((k / shape[1]) as u64),
        };
        let mut store = |k: usize, y: u64| -> PyResult<()> {
            if y & !mask != 0 {
                return Err(PyValueError::new_err(format!(
                    "{what} {y:#x} for word {:#x} (dim {dim}, seed {}): not a {}-bit word",
                    words[k],
                    seed_of(k),
                    self.width.bits()
                )));
            }
            words[k] = y;
            Ok(())
        };
        if dt.is_equiv_to(&dtype::<u32>(py)) {
            let a = array.cast::<PyArray1<u32>>()?.readonly();
            for (k, &y) in a.as_array().iter().enumerate() {
                store(k, y as u64)?;
            }
        } else if dt.is_equiv_to(&dtype::<u64>(py)) {
            if self.width == Width::W32 {
                // The words went out as uint32: a uint64 reply is not what was sent back,
                // whatever its values (a silent widening hides a dtype bug in `fn`).
                return Err(PyTypeError::new_err(format!(
                    "{what} dtype uint64 at width 32: return uint32 words, the input's dtype"
                )));
            }
            let a = array.cast::<PyArray1<u64>>()?.readonly();
            for (k, &y) in a.as_array().iter().enumerate() {
                store(k, y)?;
            }
        } else {
            return Err(PyTypeError::new_err(format!(
                "{what} dtype {}: return uint32 or uint64 words",
                dt.str()
                    .map(|s| s.to_string())
                    .unwrap_or_else(|_| "?".into())
            )));
        }
        Ok(())
    }
}

/// One seed's instance of a [`PythonFunction`].
pub struct PythonScrambler {
    /// The shared function.
    pub function: Arc<PythonFunction>,
    /// The seed passed to every call.
    pub seed: u64,
    /// The scrambling base (base 2 when the candidate's base is not a power of two: the
    /// battery then reads the words as base-b digit integers and never asks this).
    pub base: PowerOfTwoBase,
    /// What the function claims.
    pub claim: Claim,
}

impl Scrambler for PythonScrambler {
    fn name(&self) -> String {
        format!("python:{}", self.function.name)
    }
    fn base(&self) -> PowerOfTwoBase {
        self.base
    }
    fn claim(&self) -> Claim {
        self.claim
    }
    fn supports_width(&self, width: Width) -> bool {
        width == self.function.width
    }
    fn scramble(&self, x: u64, _width: Width, dim: u32) -> u64 {
        let mut one = [x];
        self.function.call(&mut one, dim, self.seed);
        one[0]
    }
    fn scramble_batch(&self, words: &mut [u64], _width: Width, dim: u32) {
        self.function.call(words, dim, self.seed);
    }
}
