//! The native half of the `gartowen` Python package. The public API, its argument checks and
//! result classes live in `gartowen/__init__.py`; these functions take validated arguments,
//! release the GIL for the Rust work and return arrays or the JSON documents the CLI prints.

mod arrays;
mod pixels;
mod python_scrambler;

use arrays::{read_points, to_array, Element};
use gartowen::certificate::{CertVerdict, Certificate, InputRecord};
use gartowen::core::{BuildContext, Claim, PowerOfTwoBase, Radix, Scrambler};
use gartowen::discrepancy::choice::MethodChoice;
use gartowen::discrepancy::{Kind, Points};
use gartowen::generate::{GeneratePlan, GenerateRequest, PointCount, PointOrder, RequestError};
use gartowen::net_check::{check_points, NetQuery, Silent};
use gartowen::netcheck::CheckBase;
use gartowen::owen::registry::build_radix;
use gartowen::reports::{discrepancy_pairs, timed_discrepancy};
use gartowen::verify::{check_candidate, radix_seeds, registry_seeds, Candidate, Level};
use numpy::{ndarray::Array2, IntoPyArray};
use pyo3::exceptions::{PyRuntimeError, PyValueError};
use pyo3::prelude::*;
use serde_json::json;
use std::sync::Arc;
use std::time::Instant;

fn value_error(e: impl std::fmt::Display) -> PyErr {
    PyValueError::new_err(e.to_string())
}

/// Points of a built-in sequence, optionally scrambled: an (n, dims) array.
#[pyfunction]
#[pyo3(signature = (seq, dims, n, scramble, seed, base, bits, words, start, gray))]
#[allow(clippy::too_many_arguments)]
fn generate<'py>(
    py: Python<'py>,
    seq: &str,
    dims: usize,
    n: u64,
    scramble: &str,
    seed: u64,
    base: Option<u64>,
    bits: u32,
    words: bool,
    start: u64,
    gray: bool,
) -> PyResult<Bound<'py, PyAny>> {
    let request = GenerateRequest {
        seq: seq.into(),
        dims,
        count: PointCount::Exact(n),
        start,
        bits,
        scramble: scramble.into(),
        seed,
        scramble_base: base,
    };
    let order = if gray {
        PointOrder::Gray
    } else {
        PointOrder::Natural
    };
    let plan = py
        .detach(|| GeneratePlan::new(&request))
        .map_err(value_error)?;
    let width = plan.width();
    let (count, dims) = plan.shape();
    let rows = usize::try_from(count)
        .ok()
        .filter(|&r| {
            r.checked_mul(dims)
                .is_some_and(|t| t <= isize::MAX as usize / 8)
        })
        .ok_or_else(|| {
            value_error(format!(
                "{count} points × {dims} dimensions do not fit in memory"
            ))
        })?;
    // The NumPy array is allocated once and filled in place with the GIL released.
    fn filled<'py, T: numpy::Element + Send>(
        py: Python<'py>,
        plan: &GeneratePlan,
        order: PointOrder,
        shape: [usize; 2],
        convert: impl Fn(u64) -> T + Sync + Send,
    ) -> PyResult<Bound<'py, PyAny>> {
        // numpy.zeros raises MemoryError where the points do not fit (PyArray2::zeros would
        // panic instead).
        let array = py
            .import("numpy")?
            .getattr("zeros")?
            .call1((shape, numpy::dtype::<T>(py)))?
            .cast_into::<numpy::PyArray2<T>>()?;
        // SAFETY: the array was just created here, so no other reference to its data exists
        // while it is filled.
        let data = unsafe { numpy::PyArrayMethods::as_slice_mut(&array) }.map_err(value_error)?;
        py.detach(|| plan.fill_rows(0, order, data, convert));
        Ok(array.into_any())
    }
    let shape = [rows, dims];
    match (words, width.bits()) {
        (false, _) => filled(py, &plan, order, shape, move |x| {
            gartowen::core::word_to_f64(x, width)
        }),
        (true, 32) => filled(py, &plan, order, shape, |x| x as u32),
        (true, _) => filled(py, &plan, order, shape, |x| x),
    }
}

/// The points (or words) scrambled by a registry scrambler, column j as dimension j; the
/// result has the input's shape (2-D) and element type.
#[pyfunction]
#[pyo3(signature = (points, name, seed, base, bits))]
fn scramble<'py>(
    py: Python<'py>,
    points: &Bound<'py, PyAny>,
    name: &str,
    seed: u64,
    base: Option<u64>,
    bits: Option<u32>,
) -> PyResult<Bound<'py, PyAny>> {
    let input = read_points(points, "points")?;
    let width = input.width();
    let (n, dims, element) = (input.n, input.dims, input.element);
    // What the scramble allocates besides the words read: a column and the output array in
    // the binary path; the digit columns, their snapped copy and the rows in base b.
    let words_needed =
        if gartowen::generate::radix_of_request(name, base).is_ok_and(|r| r.is_some()) {
            n.saturating_mul(dims).saturating_mul(4)
        } else {
            n.saturating_add(n.saturating_mul(dims))
        };
    arrays::ensure_room(words_needed.saturating_mul(8), "scrambling the points")?;
    let mut flat = input.words;
    let radix = gartowen::generate::radix_of_request(name, base).map_err(value_error)?;
    if radix.is_none() && bits.is_some() {
        return Err(value_error(
            "bits applies to float values in a base that is not a power of two",
        ));
    }
    if let Some(radix) = radix {
        // Base-b digits, as `gartowen scramble --scramble-base B` reads and writes them:
        // floats into digit words of `bits` (default 32, as generate's), words as they are.
        let digit_width =
            match (element, bits) {
                (Element::F64, b) => {
                    gartowen::generate::width_from_bits(b.unwrap_or(32)).map_err(value_error)?
                }
                (_, None) => width,
                (_, Some(_)) => return Err(value_error(
                    "bits reads float values; words are base-b digit integers of their own width",
                )),
            };
        let out = py
            .detach(|| {
                scramble_in_radix(&flat, width, digit_width, dims, element, name, seed, radix)
            })
            .map_err(value_error)?;
        return match out {
            RadixOut::Values(v) => Ok(Array2::from_shape_vec((n, dims), v)
                .map_err(|e| PyValueError::new_err(e.to_string()))?
                .into_pyarray(py)
                .into_any()),
            RadixOut::Words(w) => to_array(py, w, n, dims, width, element),
        };
    }
    py.detach(|| {
        let ctx = BuildContext {
            seed,
            default_base: match base {
                Some(b) => PowerOfTwoBase::from_base(b)?,
                None => PowerOfTwoBase::B2,
            },
        };
        let s = gartowen::registry().build_with(name, &ctx)?;
        if !s.supports_width(width) {
            let hint = if element == Element::F64 {
                "; float64 points are read as 64-bit words: pass uint32 words for a 32-bit scrambler"
            } else {
                ""
            };
            return Err(RequestError::Invalid(format!(
                "scrambler {} does not support the {}-bit words of points{hint}",
                s.name(),
                width.bits()
            )));
        }
        let mut column = vec![0u64; n]; // room checked above
        for j in 0..dims {
            for (i, x) in column.iter_mut().enumerate() {
                *x = flat[i * dims + j];
            }
            s.scramble_batch(&mut column, width, j as u32);
            for (i, &x) in column.iter().enumerate() {
                flat[i * dims + j] = x;
            }
        }
        Ok::<(), RequestError>(())
    })
    .map_err(value_error)?;
    to_array(py, flat, n, dims, width, element)
}

/// The result of a base-b scramble: float values (float input) or digit words.
enum RadixOut {
    Values(Vec<f64>),
    Words(Vec<u64>),
}

/// `scramble` in a base that is not a power of two: floats snapped to the base-b grid, words
/// as base-b digit integers (the library path `gartowen scramble` takes).
#[allow(clippy::too_many_arguments)]
fn scramble_in_radix(
    flat: &[u64],
    width: gartowen::core::Width,
    digit_width: gartowen::core::Width,
    dims: usize,
    element: Element,
    name: &str,
    seed: u64,
    radix: gartowen::core::Radix,
) -> Result<RadixOut, RequestError> {
    use gartowen::core::RadixLayout;
    use gartowen::radix_points::{from_digit_words, from_floats, radix_scrambler};
    let scrambler = radix_scrambler(name, radix, seed)?;
    let set = gartowen::netcheck::PointSet::from_flat(width, dims, flat)
        .map_err(|e| RequestError::Invalid(e.to_string()))?;
    let mut points = if element == Element::F64 {
        from_floats(&set, RadixLayout::new(digit_width, radix)?, None)?
    } else {
        from_digit_words(&set, RadixLayout::new(width, radix)?)?
    };
    if let Some(s) = &scrambler {
        points.scramble(s);
    }
    let n = points.len();
    let row_major = |f: &dyn Fn(u64) -> u64| -> Vec<u64> {
        (0..n * dims)
            .map(|k| f(points.columns[k % dims][k / dims]))
            .collect()
    };
    Ok(if element == Element::F64 {
        let layout = points.layout;
        let words = row_major(&|y| y);
        RadixOut::Values(words.iter().map(|&y| layout.to_f64(y)).collect())
    } else {
        RadixOut::Words(row_major(&|y| y))
    })
}

/// `gartowen check --json` on an array: the certificate JSON text and whether it holds.
#[pyfunction]
#[pyo3(signature = (points, base, m, t, projections, sequence, histograms, snap))]
#[allow(clippy::too_many_arguments)]
fn check(
    py: Python<'_>,
    points: &Bound<'_, PyAny>,
    base: u64,
    m: Option<u32>,
    t: Option<u32>,
    projections: Option<String>,
    sequence: bool,
    histograms: bool,
    snap: bool,
) -> PyResult<(String, bool, String)> {
    let check_base = CheckBase::new(base).map_err(value_error)?;
    let input = arrays::read_points_as(points, "points", true)?;
    let floats = matches!(input.element, arrays::Element::F64);
    let read = input.point_set()?;
    let record = gartowen::reports::point_set_record("array", "points", &read);
    let coordinates = read.len() * read.dims();
    let query = NetQuery {
        m,
        t,
        sequence,
        projections: projections.clone(),
        histograms,
    };
    let (set, snapped) = if floats && snap {
        gartowen::net_check::snap_floats(read, check_base, &query).map_err(PyValueError::new_err)?
    } else {
        (read, None)
    };
    let mut outcome = py
        .detach(|| check_points(&set, check_base, &query, &Silent))
        .map_err(PyValueError::new_err)?;
    if let Some(s) = &snapped {
        outcome.text = gartowen::net_check::snap_note(s, coordinates) + &outcome.text;
    }
    let cert = Certificate::new(
        "check",
        if outcome.holds {
            CertVerdict::Pass
        } else {
            CertVerdict::Fail
        },
        json!({
            "base": base, "m": m, "t": t, "sequence": sequence,
            "projections": projections, "histograms": histograms,
            "snap": snapped, "no_snap": !snap,
        }),
        vec![],
        vec![record],
        outcome.result_json(),
    );
    Ok((cert.to_json(), outcome.holds, outcome.text))
}

/// `gartowen discrepancy --json` on an array: the certificate JSON text.
#[pyfunction]
#[pyo3(signature = (points, kind, method, root, pairs))]
fn discrepancy(
    py: Python<'_>,
    points: &Bound<'_, PyAny>,
    kind: &str,
    method: &str,
    root: bool,
    pairs: Option<&str>,
) -> PyResult<String> {
    let kind_value: Kind = kind
        .parse()
        .map_err(|e| PyValueError::new_err(format!("{e}")))?;
    let choice: MethodChoice = method
        .parse()
        .map_err(|e| PyValueError::new_err(format!("{e}")))?;
    let all_pairs = match pairs {
        None => None,
        Some("first") => Some(false),
        Some("all") => Some(true),
        Some(other) => {
            return Err(PyValueError::new_err(format!(
                "unknown pairs '{other}'; use 'first' or 'all'"
            )))
        }
    };
    let input = read_points(points, "points")?;
    let set = input.point_set()?;
    let width = input.width();
    let (dims, words) = (input.dims, input.words);
    let result = py.detach(|| {
        let points = Points {
            words: &words,
            dims,
            width,
        };
        let (joint, seconds) = timed_discrepancy(points, kind_value, choice)?;
        let mut result = gartowen::reports::discrepancy_json(&joint, seconds, root);
        let pairs = match all_pairs {
            Some(all) => discrepancy_pairs(points, kind_value, choice, root, all)?,
            None => Vec::new(),
        };
        result["pairs"] = json!(pairs);
        Ok::<_, String>(result)
    });
    let result = result.map_err(PyValueError::new_err)?;
    let doc = Certificate::new(
        "discrepancy",
        CertVerdict::Measured,
        json!({ "kind": kind_value.name(), "method": choice.name(), "pairs": pairs, "root": root }),
        vec![],
        vec![gartowen::reports::point_set_record("array", "points", &set)],
        result,
    );
    Ok(doc.to_json())
}

/// The verify battery on a Python function; returns the certificate JSON text, the calls,
/// words and seconds spent in the function, and the battery's wall seconds. Re-raises the
/// function's first exception.
#[pyfunction]
#[pyo3(signature = (func, name, base, width, level, claim, seed, expect, batch_seeds, max_dims))]
#[allow(clippy::too_many_arguments)]
fn verify(
    py: Python<'_>,
    func: Py<PyAny>,
    name: String,
    base: u64,
    width: u32,
    level: &str,
    claim: &str,
    seed: u64,
    expect: Option<String>,
    batch_seeds: bool,
    max_dims: Option<u32>,
) -> PyResult<(String, u64, u64, f64, f64)> {
    if max_dims == Some(0) {
        return Err(PyValueError::new_err(
            "max_dims 0: a scrambler serves at least dimension 0",
        ));
    }
    // A base 2^q keeps binary words; any other base b ≥ 3 passes base-b digit integers.
    let (base_value, radix) = match PowerOfTwoBase::from_base(base) {
        Ok(b) => (b, None),
        Err(_) => match Radix::new(base) {
            Ok(r) => (PowerOfTwoBase::B2, Some(r)),
            Err(e) => return Err(PyValueError::new_err(format!("base {base}: {e}"))),
        },
    };
    let width_value = match width {
        32 => gartowen::core::Width::W32,
        64 => gartowen::core::Width::W64,
        w => {
            return Err(PyValueError::new_err(format!(
                "width {w}: the battery passes 32- or 64-bit words"
            )))
        }
    };
    let level_value: Level = level
        .parse()
        .map_err(|e| PyValueError::new_err(format!("{e}")))?;
    let claim_value = Claim::parse(claim)
        .and_then(|c| c.in_base(base as u32))
        .map_err(|e| PyValueError::new_err(e.to_string()))?;
    let registry = gartowen::registry();
    if let (Some(twin), Some(r)) = (&expect, radix) {
        build_radix(twin, r, 0)
            .map_err(|e| PyValueError::new_err(format!("expect {twin}: {e}")))?;
    } else if let Some(twin) = &expect {
        let s = registry
            .build_with(
                twin,
                &BuildContext {
                    seed: 0,
                    default_base: base_value,
                },
            )
            .map_err(|e| PyValueError::new_err(format!("expect {twin}: {e}")))?;
        if s.base() != base_value {
            return Err(PyValueError::new_err(format!(
                "expect {twin} scrambles in base {}, the function in base {base}",
                s.base().base()
            )));
        }
    }
    let function = Arc::new(python_scrambler::PythonFunction::new(
        func,
        name.clone(),
        width_value,
    ));
    let started = Instant::now();
    let report = py.detach(|| {
        let for_seed = function.clone();
        let watched = function.clone();
        let build = move |s: u64| {
            Ok(Box::new(python_scrambler::PythonScrambler {
                function: for_seed.clone(),
                seed: s,
                base: base_value,
                claim: claim_value,
            }) as Box<dyn Scrambler>)
        };
        let mut candidate =
            Candidate::from_builder(format!("python:{name}"), claim_value, Box::new(build))?;
        // The structural checks use the caller's seed; the laws use seeds 0, 1, 2, ….
        candidate.probe = (candidate.with_seed)(seed)?;
        candidate.health = Box::new(move || watched.failed());
        if batch_seeds {
            let many = function.clone();
            candidate.many = Some(Box::new(move |words: &[u64], _width, dim, first, count| {
                Ok(many.call_many(words, dim, first, count))
            }));
        }
        candidate.radix = radix;
        candidate.max_dims = max_dims;
        candidate.twin = expect.as_deref().map(|twin| {
            let seeds = match radix {
                Some(r) => radix_seeds(twin, r),
                None => registry_seeds(&registry, twin, base_value),
            };
            (twin.to_string(), seeds)
        });
        Ok::<_, String>(check_candidate(&candidate, level_value, 1))
    });
    let seconds = started.elapsed().as_secs_f64();
    if let Some(e) = function.take_error() {
        return Err(e);
    }
    let report = report.map_err(PyRuntimeError::new_err)?;
    let failed = report.failed();
    let (calls, words, python_seconds) = function.usage();
    let cert = Certificate::new(
        "verify",
        if failed {
            CertVerdict::Fail
        } else {
            CertVerdict::Pass
        },
        json!({
            "level": level_value,
            "node_law_seeds": level_value.plan().law_seeds,
            "family_alpha": gartowen::verify::stats::FAMILY_ALPHA,
            "claim_override": claim,
            "python": { "function": name, "base": base, "width": width, "seed": seed,
                        "expect": expect, "claim": report.claim, "batch_seeds": batch_seeds,
                        "max_dims": max_dims },
        }),
        gartowen::verify::seeds_used(seed),
        vec![InputRecord {
            kind: "python".into(),
            name: name.clone(),
            checksum_fnv1a64: None,
            details: json!({ "calls": calls, "words": words, "python_seconds": python_seconds }),
        }],
        json!({ "implementations": [report] }),
    );
    Ok((cert.to_json(), calls, words, python_seconds, seconds))
}

/// One failing box in words, as `gartowen check` prints it.
#[pyfunction]
#[pyo3(signature = (shape, box_index, count, expected, base))]
fn describe_box(
    shape: Vec<u32>,
    box_index: Vec<u64>,
    count: u64,
    expected: u64,
    base: u64,
) -> String {
    gartowen::net_check::describe_failure(
        &gartowen::netcheck::BoxFailure {
            shape,
            box_index,
            count,
            expected,
        },
        base,
    )
}

/// `gartowen list --json`: the registry as JSON text.
#[pyfunction]
fn list_scramblers() -> PyResult<String> {
    let rows = gartowen::registry_listing().map_err(value_error)?;
    Ok(serde_json::to_string(&rows).expect("json"))
}

/// The native module.
#[pymodule]
fn _native(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(generate, m)?)?;
    m.add_function(wrap_pyfunction!(scramble, m)?)?;
    m.add_function(wrap_pyfunction!(check, m)?)?;
    m.add_function(wrap_pyfunction!(discrepancy, m)?)?;
    m.add_function(wrap_pyfunction!(verify, m)?)?;
    m.add_function(wrap_pyfunction!(list_scramblers, m)?)?;
    m.add_function(wrap_pyfunction!(describe_box, m)?)?;
    m.add_function(wrap_pyfunction!(pixels::scramble_per_key, m)?)?;
    m.add("__version__", env!("CARGO_PKG_VERSION"))?;
    Ok(())
}
