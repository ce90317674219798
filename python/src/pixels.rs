//! One point set scrambled once per key, for renderers: every pixel (or render) draws the same
//! unscrambled points and scrambles them with a seed of its own. With a table seed, an ART
//! variant's one table serves every key (the table a renderer ships, keys choosing each
//! dimension's root symbol and shifts); without, every key is a fresh instance (seed = key).

use crate::arrays::{read_points, try_vec, Element};
use gartowen::art::registry::{variant_of, DEFAULT_SYMBOLS, MAX_TABLE_SYMBOLS};
use gartowen::art::ArtOwen;
use gartowen::core::registry::ScramblerRequest;
use gartowen::core::{BuildContext, PowerOfTwoBase, Scrambler, Width};
use numpy::ndarray::Array3;
use numpy::IntoPyArray;
use pyo3::exceptions::{PyTypeError, PyValueError};
use pyo3::prelude::*;
use rayon::prelude::*;

/// How each key scrambles.
enum PerKey {
    /// One ART table; keys choose roots and shifts.
    FixedTable(Box<ArtOwen>),
    /// A fresh registry instance per key.
    Fresh { name: String, base: PowerOfTwoBase },
}

fn fixed_table(name: &str, table_seed: u64) -> PyResult<ArtOwen> {
    let req = ScramblerRequest::parse(name).map_err(|e| PyValueError::new_err(e.to_string()))?;
    let variant = variant_of(&req.name).ok_or_else(|| {
        PyValueError::new_err(format!(
            "table_seed: '{name}' has no table to fix (an ART variant has: art-owen-2, q-art-4, \
             art-owen-8p, art-owen-16p, art-owen-mQ, art-owen-tQ)"
        ))
    })?;
    req.allow_only(&["table"])
        .map_err(|e| PyValueError::new_err(e.to_string()))?;
    let symbols = match req.option("table") {
        None => DEFAULT_SYMBOLS,
        Some(t) => t
            .parse::<usize>()
            .ok()
            .filter(|&n| n <= MAX_TABLE_SYMBOLS)
            .ok_or_else(|| {
                PyValueError::new_err(format!("{name}: table={t} is not 1..={MAX_TABLE_SYMBOLS}"))
            })?,
    };
    ArtOwen::new(variant, symbols, table_seed).map_err(|e| PyValueError::new_err(e.to_string()))
}

/// `out[k, i, j]`: point i's coordinate j (uint32 words, a 2-D array) scrambled as dimension
/// `first_dim + j` by `name` keyed with `keys[k]`; a (keys, points, dims) uint32 array.
#[pyfunction]
#[pyo3(signature = (words, name, keys, table_seed, first_dim, base))]
pub fn scramble_per_key<'py>(
    py: Python<'py>,
    words: &Bound<'py, PyAny>,
    name: &str,
    keys: Vec<u64>,
    table_seed: Option<u64>,
    first_dim: u32,
    base: Option<u64>,
) -> PyResult<Bound<'py, PyAny>> {
    let input = read_points(words, "words")?;
    if input.element != Element::U32 {
        return Err(PyTypeError::new_err(
            "words: uint32 words (value word · 2^-32), as generate(..., words=True) gives",
        ));
    }
    let (n, dims) = (input.n, input.dims);
    if first_dim.checked_add(dims as u32).is_none() {
        return Err(PyValueError::new_err(format!(
            "first_dim {first_dim} + {dims} dimensions overflow"
        )));
    }
    let how = match table_seed {
        Some(t) => PerKey::FixedTable(Box::new(fixed_table(name, t)?)),
        None => {
            let base = match base {
                Some(b) => PowerOfTwoBase::from_base(b)
                    .map_err(|e| PyValueError::new_err(e.to_string()))?,
                None => PowerOfTwoBase::B2,
            };
            // Refused now, not once per key.
            build(name, base, 0)?;
            PerKey::Fresh {
                name: name.to_string(),
                base,
            }
        }
    };
    let total = keys
        .len()
        .checked_mul(n)
        .and_then(|x| x.checked_mul(dims))
        .ok_or_else(|| PyValueError::new_err("keys × points × dims overflow"))?;
    let mut out: Vec<u32> = try_vec(total, "the per-key scrambles")?;
    out.resize(total, 0);
    let columns: Vec<Vec<u64>> = (0..dims)
        .map(|j| (0..n).map(|i| input.words[i * dims + j]).collect())
        .collect();
    py.detach(|| {
        out.par_chunks_mut(n * dims)
            .zip(keys.par_iter())
            .try_for_each(|(block, &key)| -> Result<(), String> {
                let fresh = match &how {
                    PerKey::Fresh { name, base } => {
                        Some(build(name, *base, key).map_err(|e| e.to_string())?)
                    }
                    PerKey::FixedTable(_) => None,
                };
                let mut column = vec![0u64; n];
                for (j, source) in columns.iter().enumerate() {
                    column.copy_from_slice(source);
                    let dim = first_dim + j as u32;
                    match (&how, &fresh) {
                        (PerKey::FixedTable(art), _) => {
                            art.scramble_batch_keyed(&mut column, Width::W32, dim, key)
                        }
                        (_, Some(s)) => s.scramble_batch(&mut column, Width::W32, dim),
                        (PerKey::Fresh { .. }, None) => unreachable!("built above"),
                    }
                    for (i, &y) in column.iter().enumerate() {
                        block[i * dims + j] = y as u32;
                    }
                }
                Ok(())
            })
    })
    .map_err(PyValueError::new_err)?;
    let array = Array3::from_shape_vec((keys.len(), n, dims), out)
        .map_err(|e| PyValueError::new_err(e.to_string()))?;
    Ok(array.into_pyarray(py).into_any())
}

fn build(name: &str, base: PowerOfTwoBase, seed: u64) -> PyResult<Box<dyn Scrambler>> {
    let ctx = BuildContext {
        seed,
        default_base: base,
    };
    let s = gartowen::registry()
        .build_with(name, &ctx)
        .map_err(|e| PyValueError::new_err(e.to_string()))?;
    if !s.supports_width(Width::W32) {
        return Err(PyValueError::new_err(format!(
            "{}: no 32-bit words, which a renderer's samples are",
            s.name()
        )));
    }
    Ok(s)
}
