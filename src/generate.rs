//! Generating points of a built-in sequence, optionally scrambled: one validated plan shared
//! by `gartowen generate` and the Python package, so both refuse the same requests with the
//! same messages and produce the same words.

use gartowen_core::{BuildContext, CoreError, PowerOfTwoBase, Scrambler, Width};
use gartowen_seq::{gray_code, DigitalSequence, SeqError, SequenceKind};
use std::fmt;

/// Why a request was refused; the message names the bad value.
#[derive(Debug, Clone, PartialEq)]
pub enum RequestError {
    /// A parameter out of range or inconsistent with another.
    Invalid(String),
    /// The sequence refused it (unknown name, too many dimensions, index out of range).
    Sequence(SeqError),
    /// The scrambler registry refused it (unknown name, bad option, bad base).
    Scrambler(CoreError),
}

impl fmt::Display for RequestError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            RequestError::Invalid(m) => write!(f, "{m}"),
            RequestError::Sequence(e) => write!(f, "{e}"),
            RequestError::Scrambler(e) => write!(f, "{e}"),
        }
    }
}

impl std::error::Error for RequestError {}

impl From<SeqError> for RequestError {
    fn from(e: SeqError) -> Self {
        RequestError::Sequence(e)
    }
}

impl From<CoreError> for RequestError {
    fn from(e: CoreError) -> Self {
        RequestError::Scrambler(e)
    }
}

/// The order points are produced in.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum PointOrder {
    /// Row i is index start + i.
    Natural,
    /// Row i is index gray(start + i) = n ⊕ (n ≫ 1): `scipy.stats.qmc.Sobol`'s row order.
    Gray,
}

/// How many points: N = 2^m, or N itself.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum PointCount {
    /// N = 2^m.
    Log2(u32),
    /// N.
    Exact(u64),
}

/// What to generate.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct GenerateRequest {
    /// Sequence name: `sobol`, `sz4`, `sz16`, `faure:base=B` or `faure-net:base=B:m=M`.
    pub seq: String,
    /// Number of dimensions.
    pub dims: usize,
    /// Number of points.
    pub count: PointCount,
    /// Index of the first point.
    pub start: u64,
    /// Word width in bits: 32 or 64.
    pub bits: u32,
    /// Registry scrambler `NAME[:OPTION…]` (`none` for the plain sequence).
    pub scramble: String,
    /// Seed of the scrambler.
    pub seed: u64,
    /// Base for scramblers whose base is a parameter (default: the sequence's own); a
    /// base that differs from the scrambler's own (fixed, or a `:base=B` option) is refused.
    pub scramble_base: Option<u64>,
}

/// A validated request: the sequence, the index range and the scrambler instance.
pub struct GeneratePlan {
    /// The sequence, truncated to the requested dimensions.
    pub seq: DigitalSequence,
    /// Index of the first point.
    pub start: u64,
    /// Number of points.
    pub count: u64,
    /// The scrambler (the identity for `none`).
    pub scrambler: Box<dyn Scrambler>,
}

/// The scrambler `request` with `seed`, in base `scramble_base` when given (else `fallback`)
/// unless the request fixes its own base. A given base that the scrambler does not scramble
/// in (a fixed-base scrambler, or a `:base=B` option saying otherwise) is refused, naming
/// both, rather than silently ignored.
pub fn build_scrambler(
    request: &str,
    seed: u64,
    scramble_base: Option<u64>,
    fallback: PowerOfTwoBase,
) -> Result<Box<dyn Scrambler>, RequestError> {
    let default_base = match scramble_base {
        Some(b) => PowerOfTwoBase::from_base(b)?,
        None => fallback,
    };
    let ctx = BuildContext { seed, default_base };
    let scrambler = crate::registry().build_with(request, &ctx)?;
    if scramble_base.is_some() && request != "none" && scrambler.base() != default_base {
        return Err(RequestError::Invalid(format!(
            "--scramble-base {} conflicts with {}, which scrambles in base {}: drop one",
            default_base.base(),
            scrambler.name(),
            scrambler.base().base()
        )));
    }
    Ok(scrambler)
}

/// The base a `--scramble-base`/`:base=B` request asks for when it is not a power of two
/// (`None`: a power of two, served by the binary path). `none` takes the flag's base alone.
pub fn radix_of_request(
    request: &str,
    scramble_base: Option<u64>,
) -> Result<Option<gartowen_core::Radix>, RequestError> {
    let default = scramble_base.unwrap_or(2);
    if request == "none" {
        return match gartowen_core::PowerOfTwoBase::from_base(default) {
            Ok(_) => Ok(None),
            Err(_) => Ok(Some(gartowen_core::Radix::new(default)?)),
        };
    }
    if let Some(flag) = scramble_base {
        // A request that names its base and a flag that names another: refused, not one of
        // them silently preferred.
        let named = gartowen_core::registry::ScramblerRequest::parse(request)?
            .option("base")
            .map(str::to_string);
        if let Some(text) = named.filter(|t| t.parse::<u64>().ok() != Some(flag)) {
            return Err(RequestError::Invalid(format!(
                "--scramble-base {flag} conflicts with {request}, which names base {text}: \
                 drop one"
            )));
        }
    }
    Ok(gartowen_owen::registry::requested_radix(request, default)?)
}

/// The word width for `bits` (32 or 64).
pub fn width_from_bits(bits: u32) -> Result<Width, RequestError> {
    match bits {
        32 => Ok(Width::W32),
        64 => Ok(Width::W64),
        _ => Err(RequestError::Invalid(format!(
            "bits must be 32 or 64, not {bits}"
        ))),
    }
}

/// Rows per parallel task of [`GeneratePlan::fill_rows`]: the task's columns (8 KiB of words
/// per dimension) stay in the core's cache between being scrambled and written out as rows.
pub const TASK_ROWS: usize = 1024;

impl GeneratePlan {
    /// Validates `r`: sequence and dimensions, the index range, the scrambler and its support
    /// of the width.
    ///
    /// ```
    /// use gartowen::generate::{GeneratePlan, GenerateRequest, PointCount, PointOrder};
    /// let r = GenerateRequest {
    ///     seq: "sobol".into(), dims: 2, count: PointCount::Log2(2), start: 0, bits: 32,
    ///     scramble: "none".into(), seed: 0, scramble_base: None,
    /// };
    /// let words = GeneratePlan::new(&r).unwrap().words(PointOrder::Natural).unwrap();
    /// assert_eq!(words, vec![0, 0, 0x8000_0000, 0x8000_0000, 0x4000_0000, 0xc000_0000,
    ///                        0xc000_0000, 0x4000_0000]);
    /// ```
    pub fn new(r: &GenerateRequest) -> Result<GeneratePlan, RequestError> {
        let kind: SequenceKind = r.seq.parse()?;
        let width = width_from_bits(r.bits)?;
        let seq = kind.build(r.dims, width)?;
        let count = match r.count {
            PointCount::Log2(m) => {
                if m > seq.index_bits() || m >= 64 {
                    return Err(RequestError::Invalid(format!(
                        "log2(n) = {m} is past the {} index bits of {}",
                        seq.index_bits(),
                        kind.name()
                    )));
                }
                1u64 << m
            }
            PointCount::Exact(0) => {
                return Err(RequestError::Invalid("n must be at least 1".into()))
            }
            PointCount::Exact(n) => n,
        };
        seq.check_range(r.start, count)?;
        if let Some(radix) = radix_of_request(&r.scramble, r.scramble_base)? {
            return Err(RequestError::Invalid(format!(
                "a base-{b} scramble acts on base-{b} digits and {} is a base-{} sequence: \
                 generate faure:base={b} (b prime), or scramble base-{b} points with \
                 `gartowen scramble`",
                kind.name(),
                kind.base().base(),
                b = radix.get()
            )));
        }
        let scrambler = build_scrambler(&r.scramble, r.seed, r.scramble_base, kind.base())?;
        if !scrambler.supports_width(width) {
            return Err(RequestError::Invalid(format!(
                "scrambler {} does not support {}-bit words",
                scrambler.name(),
                width.bits()
            )));
        }
        Ok(GeneratePlan {
            seq,
            start: r.start,
            count,
            scrambler,
        })
    }

    /// The word width.
    pub fn width(&self) -> Width {
        self.seq.width()
    }

    /// The sequence index of row `i`.
    pub fn index(&self, i: u64, order: PointOrder) -> u64 {
        let position = self.start + i;
        match order {
            PointOrder::Natural => position,
            PointOrder::Gray => gray_code(position),
        }
    }

    /// Fills `row` (one word per dimension) with the scrambled point of row `i`.
    pub fn row(&self, i: u64, order: PointOrder, row: &mut [u64]) {
        let index = self.index(i, order);
        let width = self.width();
        for (j, x) in row.iter_mut().enumerate() {
            *x = self
                .scrambler
                .scramble(self.seq.point(index, j), width, j as u32);
        }
    }

    /// Rows `first..first + out.len() / dims` (row-major words) into `out`, as
    /// [`GeneratePlan::fill_rows`] without conversion.
    pub fn block(&self, first: u64, order: PointOrder, out: &mut [u64]) {
        self.fill_rows(first, order, out, |x| x);
    }

    /// Rows `first..first + out.len() / dims` into `out` (row-major), each word passed through
    /// `convert` (to f64 values, say). Tasks of [`TASK_ROWS`] rows run in parallel; in each,
    /// every dimension's column is filled incrementally and scrambled in one batch, then the
    /// rows are written out, so memory beyond `out` is one task's columns per worker, and the
    /// values do not depend on the thread count.
    pub fn fill_rows<T: Send>(
        &self,
        first: u64,
        order: PointOrder,
        out: &mut [T],
        convert: impl Fn(u64) -> T + Sync,
    ) {
        use rayon::prelude::*;
        let dims = self.seq.dims();
        let width = self.width();
        out.par_chunks_mut(TASK_ROWS * dims)
            .enumerate()
            .for_each_init(
                || vec![0u64; TASK_ROWS * dims],
                |columns, (task, chunk)| {
                    let rows = chunk.len() / dims;
                    let position = self.start + first + (task * TASK_ROWS) as u64;
                    for (j, column) in columns.chunks_exact_mut(TASK_ROWS).enumerate() {
                        let column = &mut column[..rows];
                        match order {
                            PointOrder::Natural => self.seq.fill_points(j, position, column),
                            PointOrder::Gray => self.seq.fill_points_gray(j, position, column),
                        }
                        self.scrambler.scramble_batch(column, width, j as u32);
                    }
                    // Rows written in order (sequential stores), reading the columns across.
                    for (i, row) in chunk.chunks_exact_mut(dims).enumerate() {
                        for (j, v) in row.iter_mut().enumerate() {
                            *v = convert(columns[j * TASK_ROWS + i]);
                        }
                    }
                },
            );
    }

    /// Every point, row-major (`N × dims` words), each dimension scrambled in one batch.
    /// Refuses a size whose element count overflows or exceeds the address space.
    pub fn words(&self, order: PointOrder) -> Result<Vec<u64>, RequestError> {
        let dims = self.seq.dims();
        let n = usize::try_from(self.count)
            .ok()
            .filter(|&n| {
                n.checked_mul(dims)
                    .is_some_and(|t| t <= isize::MAX as usize / 8)
            })
            .ok_or_else(|| {
                RequestError::Invalid(format!(
                    "{} points × {dims} dimensions do not fit in memory",
                    self.count
                ))
            })?;
        let mut out = vec![0u64; n * dims];
        self.block(0, order, &mut out);
        Ok(out)
    }

    /// The number of points and the dimensions: the (rows, columns) of [`Self::words`].
    pub fn shape(&self) -> (u64, usize) {
        (self.count, self.seq.dims())
    }
}
