"""gartowen: generate, scramble and verify quasi-Monte Carlo point sets in bases b = 2^q.

Conventions (the same as the ``gartowen`` command line):

* A coordinate is a W-bit word x (W = 32 or 64) with value x * 2^-W in [0, 1). Arrays of
  words are ``uint32`` (W = 32) or ``uint64`` (W = 64), of shape (n, dims) or (n,) for one
  dimension.
* float64 values are read exactly as 64-bit words: NaN, values outside [0, 1) and values that
  are not multiples of 2^-64 are refused with ``ValueError``. Words become float64 by
  truncation to 53 bits, so a value is never 1.0.
* Base-b digit k (k = 0 most significant) of a W-bit word is bits [W - q(k+1), W - qk).
* Discrepancies are squared (D^2) unless ``root=True``. SciPy's ``qmc.discrepancy`` returns D
  for L2-star but D^2 for CD and WD: ``discrepancy(x, "L2-star", scipy_convention=True)``
  answers in SciPy's convention, so the numbers compare one to one.
* SciPy's spellings are accepted where they mean the same thing: ``d=`` for ``dims``,
  ``scramble=False``, the kinds ``"L2-star"``, ``"CD"``, ``"WD"`` (also as ``method=``).
  Where they do not (``scramble=True``, ``"MD"``), the error names the gartowen equivalent.

Bad arguments raise ``TypeError`` (wrong type or dtype) or ``ValueError`` (wrong value), with
the messages the command line prints. Long work runs with the GIL released.

>>> import gartowen
>>> x = gartowen.generate("sobol", 2, 4, words=True)
>>> [hex(int(w)) for w in x[:, 1]]
['0x0', '0x80000000', '0xc0000000', '0x40000000']
>>> gartowen.check(x, 2).t
0
"""

from __future__ import annotations

import json
import operator
from dataclasses import dataclass, field
from fractions import Fraction
from typing import Any, Callable, Dict, List, Optional, Sequence, Tuple, Union

import numpy as np

from . import _native

__version__: str = _native.__version__

__all__ = [
    "generate",
    "scramble",
    "scramble_per_key",
    "check",
    "discrepancy",
    "verify",
    "list_scramblers",
    "CheckResult",
    "DiscrepancyResult",
    "VerifyResult",
]

_U64_MAX = (1 << 64) - 1


def _integer(name: str, value: Any, low: int = 0, high: int = _U64_MAX) -> int:
    """``value`` as a Python int in [low, high], or TypeError/ValueError naming ``name``."""
    if isinstance(value, (bool, np.bool_)):
        raise TypeError(f"{name} must be an integer, not bool")
    try:
        v = operator.index(value)
    except TypeError:
        raise TypeError(f"{name} must be an integer, not {type(value).__name__}") from None
    if v < low or v > high:
        if v < 0 and low == 0:
            raise ValueError(f"{name} = {v} is negative: it must be an integer in [{low}, {high}]")
        raise ValueError(f"{name} = {v} is out of range: it must be an integer in [{low}, {high}]")
    return v


def _optional_integer(name: str, value: Any, low: int = 0, high: int = _U64_MAX) -> Optional[int]:
    return None if value is None else _integer(name, value, low, high)


def _either(allowed: Sequence[str]) -> str:
    """`a, b or c`, as the native vocabulary errors list choices."""
    return allowed[0] if len(allowed) == 1 else f"{', '.join(allowed[:-1])} or {allowed[-1]}"


def _choice(name: str, value: Any, allowed: Sequence[str]) -> str:
    if not isinstance(value, str):
        raise TypeError(f"{name} must be a string, one of {_either(allowed)}")
    if value not in allowed:
        raise ValueError(f"unknown {name} '{value}'; use {_either(allowed)}")
    return value


def _string(name: str, value: Any) -> str:
    if not isinstance(value, str):
        raise TypeError(f"{name} must be a string, not {type(value).__name__}")
    return value


def _array(points: Any, name: str = "points") -> np.ndarray:
    """An ndarray as given (any memory order), or a list converted by NumPy."""
    if isinstance(points, np.ndarray):
        return points
    if isinstance(points, (list, tuple)):
        return np.asarray(points)
    raise TypeError(
        f"{name} must be a NumPy array of float64 values in [0,1) or uint32/uint64 words, "
        f"not {type(points).__name__}"
    )


def generate(
    seq: str,
    dims: Optional[int] = None,
    n: Optional[int] = None,
    *,
    d: Optional[int] = None,
    scramble: Union[str, bool, None] = None,
    seed: int = 0,
    base: Optional[int] = None,
    bits: int = 32,
    words: bool = False,
    start: int = 0,
    order: str = "natural",
) -> np.ndarray:
    """Points ``start .. start + n - 1`` of a built-in digital sequence, optionally scrambled.

    Args:
        seq: ``"sobol"`` (base 2, Joe-Kuo new-joe-kuo-6.21201, 21201 dims), ``"sz4"`` (base 4,
            4 dims), ``"sz16"`` (base 16, 16 dims), ``"faure:base=B"`` (B = 2, 4, ..., 256;
            B dims) or ``"faure-net:base=B:m=M"`` (B + 1 dims, a net of its first B^M points).
        dims: number of dimensions (``d=`` as in SciPy is the same).
        n: number of points (at least 1).
        scramble: registry scrambler ``NAME[:OPTION...]`` (see :func:`list_scramblers`);
            None or False for the plain sequence. ``True`` is refused: name the scramble
            (``"owen-oracle"`` for Owen's nested uniform scramble; SciPy's
            ``Sobol(scramble=True)`` is a random linear matrix scramble with a digital shift,
            ``"lms-shift"`` here).
        seed: the scrambler's seed, an integer in [0, 2^64).
        base: scrambling base for scramblers whose base is a parameter (default: the
            sequence's own); a base the scrambler does not take (a fixed base, or its
            ``:base=B`` option) raises ValueError.
        bits: word width W, 32 or 64.
        words: return words (uint32 for 32 bits, uint64 for 64) instead of float64 values.
        start: index of the first point.
        order: ``"natural"`` (row i is index start + i) or ``"gray"`` (row i is index
            gray(start + i), the row order of ``scipy.stats.qmc.Sobol``).

    Returns:
        An (n, dims) array: float64 values in [0, 1), or words with ``words=True``. Bit for bit
        what ``gartowen generate`` writes for the same arguments.
    """
    seq = _string("seq", seq)
    if d is not None:
        if dims is not None:
            raise TypeError("give dims or d (SciPy's name for it), not both")
        dims = d
    if dims is None or n is None:
        raise TypeError("generate() needs dims (or d=) and n, e.g. generate('sobol', d=2, n=64)")
    dims = _integer("dims", dims, 1, 1 << 31)
    n = _integer("n", n)
    if scramble is True:
        raise ValueError(
            "scramble=True does not say which scramble: name it, e.g. scramble='owen-oracle' "
            "(Owen's nested uniform scramble) or scramble='lms-shift' (what SciPy's "
            "Sobol(scramble=True) does: a random linear matrix scramble with a digital shift); "
            "gartowen.list_scramblers() lists them all"
        )
    name = "none" if scramble is None or scramble is False else _string("scramble", scramble)
    seed = _integer("seed", seed)
    base = _optional_integer("base", base)
    bits = _integer("bits", bits)
    start = _integer("start", start)
    order = _choice("order", order, ("natural", "gray"))
    return _native.generate(
        seq, dims, n, name, seed, base, bits, bool(words), start, order == "gray"
    )


def scramble(
    words_or_points: Any, name: str, seed: int, *, base: Optional[int] = None,
    bits: Optional[int] = None,
) -> np.ndarray:
    """Scrambles a point set with a registry scrambler: column j as dimension j, rows kept.

    Args:
        words_or_points: uint32 words (scrambled at W = 32), uint64 words (W = 64) or float64
            values in [0, 1) (read exactly as 64-bit words), shape (n, dims) or (n,).
        name: registry scrambler ``NAME[:OPTION...]``, e.g. ``"owen-oracle"``,
            ``"art-owen-16p"``, ``"owen-oracle:xor"``.
        seed: the scrambler's seed, an integer in [0, 2^64).
        base: scrambling base for scramblers whose base is a parameter (default 2). A base
            that is not a power of two (3..65535, ``owen-oracle[:cyclic|:per-depth]``) reads
            float64 values as base-b digits, snapped to the base-b grid of ⌈log_b n⌉ digits
            (a float cannot hold 1/3; deeper when the values carry more digits, refused when
            no grid a float resolves holds them), and words as base-b digit integers (below
            b^m), as ``gartowen scramble --scramble-base B`` does.
        bits: in such a base, the width of the digit words float values are read into, 32 or
            64 (default 32, as ``generate``'s): the output then equals ``generate(...,
            bits=bits, scramble=name)`` of the same points.

    Returns:
        An array of the input's shape and dtype; equal to ``gartowen scramble`` on the same data.
    """
    array = _array(words_or_points, "words_or_points")
    name = _string("name", name)
    seed = _integer("seed", seed)
    base = _optional_integer("base", base)
    bits = _optional_integer("bits", bits)
    out = _native.scramble(array, name, seed, base, bits)
    return out.reshape(array.shape)


def scramble_per_key(
    words: Any,
    name: str,
    keys: Any,
    *,
    table_seed: Optional[int] = None,
    first_dim: int = 0,
    base: Optional[int] = None,
) -> np.ndarray:
    """One point set scrambled once per key, as a renderer scrambles per pixel.

    Args:
        words: uint32 words (value word · 2^-32), shape (n, dims) or (n,).
        name: registry scrambler ``NAME[:OPTION...]``.
        keys: the keys (one per pixel, say), integers in [0, 2^64).
        table_seed: with an ART variant: one table drawn from this seed serves every key,
            each key choosing every dimension's root symbol and shifts (the fixed table a
            renderer ships). Keyed by ``table_seed`` itself this is ``scramble(words, name,
            table_seed)``. None: a fresh instance per key, ``scramble(words, name, key)``.
        first_dim: the scramble dimension of column 0 (column j is ``first_dim + j``).
        base: scrambling base for scramblers whose base is a parameter (default 2).

    Returns:
        A uint32 array of shape (len(keys), n, dims): ``out[k]`` is the set keyed by
        ``keys[k]``.
    """
    array = _array(words, "words")
    if array.dtype != np.uint32:
        raise TypeError(f"words has dtype {array.dtype}: uint32 words, as generate(..., words=True)")
    two_d = array.reshape(array.shape[0], -1)
    # A uint64 array's tolist() gives Python ints; np.asarray of big ints would give floats.
    raw = keys.reshape(-1).tolist() if isinstance(keys, np.ndarray) else list(keys)
    key_list = [_integer("keys", k) for k in raw]
    if not key_list:
        raise ValueError("keys is empty")
    table_seed = _optional_integer("table_seed", table_seed)
    first_dim = _integer("first_dim", first_dim, 0, (1 << 32) - 1)
    base = _optional_integer("base", base)
    return _native.scramble_per_key(two_d, _string("name", name), key_list, table_seed, first_dim, base)


@dataclass(frozen=True)
class CheckResult:
    """The outcome of :func:`check`.

    Attributes:
        holds: whether the checked property holds (True when only t-values were asked).
        t: the t-value of the whole set, or of the first projection; None when a given ``t``
            was checked instead.
        t_values: the t-value of each projection (its dimensions as a tuple), when computed.
        first_failure: the first failing box: ``shape`` (d_j per dimension), ``box_index``
            (a_j: the box is the product of [a_j, a_j + 1) / b^d_j), ``count`` and ``expected``
            points, plus ``projection`` and ``description`` (in words). For a t-value it is
            the box that shows the set is not a (t-1, m, s)-net.
        text: the report ``gartowen check`` prints.
        result: the JSON ``result`` of ``gartowen check --json``.
        certificate: the whole certificate document.
    """

    holds: bool
    t: Optional[int]
    t_values: Dict[Tuple[int, ...], int]
    first_failure: Optional[Dict[str, Any]]
    text: str
    result: Any
    certificate: Dict[str, Any]

    def __str__(self) -> str:
        return self.text


def check(
    points: Any,
    base: int,
    *,
    m: Optional[int] = None,
    t: Optional[int] = None,
    projections: Optional[str] = None,
    sequence: bool = False,
    histograms: bool = False,
    snap: bool = True,
) -> CheckResult:
    """Net properties of a point set by counting points in elementary intervals.

    A shape (d_1..d_s) with sum d_j = m - t splits [0,1)^s into boxes of side b^-d_j; a
    (t,m,s)-net in base b has exactly b^t of its b^m points in every box.

    Args:
        points: float64 values in [0, 1) or uint32/uint64 words, shape (n, dims) or (n,).
        base: base b >= 2 of the elementary intervals (powers of two use a fast path).
        m: N = b^m (default: implied by N; with ``sequence``, the largest block exponent).
        t: check this t (a verdict in ``holds``) instead of computing the t-value.
        projections: ``"pairs"``, ``"groups:G"``, ``"blocks:G"`` or lists like ``"0,1;2,3"``.
        sequence: check the (t,s)-sequence property over every block of b^k points, k <= m.
        histograms: include per-shape count histograms (with ``t``, nets only).
        snap: float64 input in a base that is not a power of two is snapped to the base's grid
            (``gartowen check`` without ``--no-snap``): a coordinate within 2^-46 of a multiple
            of b^-m counts as that multiple, one between 2^-46 and 2^-44 is refused
            (ValueError naming the point). ``False`` reads floats by floor.

    Returns:
        A :class:`CheckResult`, the same as ``gartowen check --json`` on the same points.
    """
    array = _array(points)
    base = _integer("base", base)
    m = _optional_integer("m", m, 0, (1 << 32) - 1)
    t = _optional_integer("t", t, 0, (1 << 32) - 1)
    if projections is not None:
        projections = _string("projections", projections)
    text, holds, report = _native.check(
        array, base, m, t, projections, bool(sequence), bool(histograms), bool(snap)
    )
    cert = json.loads(text)
    result = cert["result"]
    items = result if isinstance(result, list) else [result]
    t_values: Dict[Tuple[int, ...], int] = {}
    first_failure = None
    for item in items:
        projection = tuple(item.get("projection", []))
        if "witness_at_t_minus_1" in item:
            t_values[projection] = item["t"]
            witness = item["witness_at_t_minus_1"] or {}
            failure = witness.get("first_failure")
        elif sequence:
            ff = item.get("first_failure")
            failure = None if ff is None else dict(ff["failure"], block=ff["block"], block_m=ff["m"])
            if t is None:
                t_values[projection] = item["t"]
        else:
            failure = item.get("first_failure")
        if failure is not None and first_failure is None:
            first_failure = dict(failure, projection=projection)
            first_failure["description"] = _native.describe_box(
                failure["shape"], failure["box_index"], failure["count"], failure["expected"], base
            )
    first_t = next(iter(t_values.values()), None) if t is None else None
    return CheckResult(holds, first_t, t_values, first_failure, report, result, cert)


@dataclass(frozen=True)
class DiscrepancyResult:
    """The outcome of :func:`discrepancy`.

    Attributes:
        kind: ``l2star``, ``cd``, ``wd`` or ``gl2``.
        method: the method that computed it (``fast``, ``compensated``, ``exact``, ``naive``).
        value: D^2 as a float (D with ``root=True``); correctly rounded for exact and fast.
        squared: whether ``value`` is D^2.
        exact: the exact rational D^2 where computed (exact and fast methods), else None.
        rel_error_bound: a proven bound on |value - D^2| / D^2 where known: 0 when ``value``
            is D^2 exactly, 2^-53 for a correctly rounded exact value; None when no bound is
            proven for this input (64-bit words with more than 50 significant bits, values
            outside the float range: ``value`` is then inf or 0 and ``exact`` holds D^2).
        seconds: time of the computation.
        pair: the two dimensions of a pair result, else None.
        pairs: the pair results requested with ``pairs=``.
        certificate: the whole certificate document (joint result only).
    """

    kind: str
    method: str
    value: float
    squared: bool
    exact: Optional[Fraction]
    rel_error_bound: Optional[float]
    seconds: float
    pair: Optional[Tuple[int, int]] = None
    pairs: List["DiscrepancyResult"] = field(default_factory=list)
    certificate: Optional[Dict[str, Any]] = field(default=None, repr=False)

    def __float__(self) -> float:
        return float(self.value)


def _discrepancy_result(r: Dict[str, Any], cert: Optional[Dict[str, Any]] = None) -> DiscrepancyResult:
    value = r["value"]
    exact = None
    if r.get("exact_hex") is not None:
        # Hex, not decimal: Python limits decimal integer conversion to 4300 digits.
        num, den = r["exact_hex"].split("/")
        exact = Fraction(int(num, 16), int(den, 16))
    if value is None:
        # JSON has no infinity: a value past f64's range comes as null, its exact rational
        # (when computed) tells the sign.
        value = float("nan") if exact is None else (float("inf") if exact > 0 else float("-inf"))
    return DiscrepancyResult(
        kind=r["kind"],
        method=r["method"],
        value=float(value),
        squared=r["squared"],
        exact=exact,
        rel_error_bound=r["rel_error_bound"],
        seconds=r["seconds"],
        pair=None if r.get("pair") is None else tuple(r["pair"]),
        pairs=[_discrepancy_result(p) for p in r.get("pairs", [])],
        certificate=cert,
    )


# SciPy's names of the discrepancy kinds (``qmc.discrepancy(method=...)``), and gartowen's.
_SCIPY_KINDS = {"l2-star": "l2star", "cd": "cd", "wd": "wd"}
_KINDS = ("l2star", "cd", "wd", "gl2")


def _kind(kind: str) -> str:
    """gartowen's name of a discrepancy kind given in gartowen's or SciPy's spelling."""
    lowered = kind.lower()
    if lowered in _KINDS:
        return lowered
    if lowered in _SCIPY_KINDS:
        return _SCIPY_KINDS[lowered]
    if lowered == "md":
        raise ValueError(
            "the mixture discrepancy (SciPy's 'MD') is not implemented; use 'l2star', 'cd' "
            "(SciPy's 'CD'), 'wd' (SciPy's 'WD') or 'gl2'"
        )
    return kind  # unknown: the native layer names the choices


def discrepancy(
    points: Any,
    kind: str = "l2star",
    method: str = "auto",
    *,
    root: bool = False,
    pairs: Optional[str] = None,
    scipy_convention: bool = False,
) -> DiscrepancyResult:
    """The squared discrepancy D^2 of a point set: L2-star, centered, wrap-around or generalized L2.

    Plain float sums cancel catastrophically (terms near 3^-d against D^2 near 1e-10), so
    ``"auto"`` picks the fastest method whose relative error bound is at most 1e-12: the
    O(N log N) exact method for 2-D L2-star, else compensated (double-double) sums, else exact
    rational arithmetic.

    Args:
        points: float64 values in [0, 1) or uint32/uint64 words, shape (n, dims) or (n,).
        kind: ``"l2star"``, ``"cd"``, ``"wd"`` or ``"gl2"`` (SciPy's ``"L2-star"``, ``"CD"``
            and ``"WD"`` too, in any case).
        method: ``"auto"``, ``"naive"``, ``"compensated"``, ``"exact"`` or ``"fast"`` (2-D
            L2-star only). A SciPy kind name here (``method="CD"``, as in
            ``qmc.discrepancy``) is read as the kind. ``"compensated"`` reports the error bound proved in the project's
            Coq theory ``proofs/DdSum.v``; where its hypotheses (coordinates of at most 50
            bits, no overflow or underflow) fail, it computes exactly instead.
        root: report D instead of D^2.
        scipy_convention: report what ``scipy.stats.qmc.discrepancy`` reports: D for L2-star,
            D^2 for CD and WD (overrides ``root``).
        pairs: also report 2-D values of pairs of dimensions: ``"first"`` (0 with each other)
            or ``"all"``.

    Returns:
        A :class:`DiscrepancyResult`; ``exact`` is a :class:`fractions.Fraction` where computed.
    """
    array = _array(points)
    # The native layer names unknown kinds and methods with the choices (one vocabulary).
    kind = _string("kind", kind)
    method = _string("method", method)
    if method.lower() in _SCIPY_KINDS or method.lower() == "md":
        if kind != "l2star":
            raise ValueError(
                f"method={method!r} is SciPy's name of a kind, and kind={kind!r} is given too; "
                "give the kind once (kind=...), and method= for the algorithm"
            )
        kind, method = method, "auto"
    kind = _kind(kind)
    if scipy_convention:
        root = kind == "l2star"
    if pairs is not None:
        pairs = _choice("pairs", pairs, ("first", "all"))
    cert = json.loads(_native.discrepancy(array, kind, method, bool(root), pairs))
    return _discrepancy_result(cert["result"], cert)


@dataclass(frozen=True)
class VerifyResult:
    """The outcome of :func:`verify`.

    Attributes:
        passed: no check failed.
        report: the implementation's report: ``claim``, ``checks`` (each with ``check``,
            ``verdict``, ``detail``, p-value, level and sub-tests) and the per-depth ``profile``.
        certificate: the certificate document (``gartowen verify --json`` format).
        python_calls: calls made to the function.
        python_words: words passed to it.
        python_seconds: seconds spent inside the function, summed over calls. Calls from
            the battery's worker threads can overlap while the function releases the GIL
            (NumPy does), so this sum can exceed ``seconds``.
        seconds: wall seconds of the whole battery.
    """

    passed: bool
    report: Dict[str, Any]
    certificate: Dict[str, Any]
    python_calls: int
    python_words: int
    python_seconds: float
    seconds: float

    @property
    def failures(self) -> List[Dict[str, Any]]:
        """The failing checks."""
        return [c for c in self.report["checks"] if c["verdict"] == "fail"]

    def verdicts(self) -> Dict[str, str]:
        """Check name -> verdict (``pass``, ``fail``, ``measured``, ``skipped``, ``not-run``)."""
        return {c["check"]: c["verdict"] for c in self.report["checks"]}

    def __str__(self) -> str:
        lines = [f"{self.report['name']} (claim {self.report['claim']}): "
                 f"{'pass' if self.passed else 'FAIL'}"]
        for c in self.report["checks"]:
            lines.append(f"  {c['check']:<11} {c['verdict']:<8} {c['detail']}")
        for family, row in self.report.get("profile", []):
            lines.append(f"  profile {family:<11} depth 0-> {row}")
        lines.append(
            f"  {self.seconds:.2f} s in all, {self.python_seconds:.2f} s in the function "
            f"({self.python_calls} calls, {self.python_words} words)"
        )
        return "\n".join(lines)


def verify(
    fn: Callable[[np.ndarray, int, int], np.ndarray],
    base: int,
    width: int,
    *,
    level: str = "quick",
    claims: str = "owen",
    seed: int = 0,
    expect: Optional[str] = None,
    name: Optional[str] = None,
    batch_seeds: bool = False,
    max_dims: Optional[int] = None,
) -> VerifyResult:
    """Runs the ``gartowen verify`` battery on a vectorized Python scrambler.

    ``fn(words, dim, seed)`` gets a 1-D array of ``width``-bit words (uint32 for 32, uint64 for
    64), a dimension index and a seed (an int in [0, 2^64)), and returns the scrambled words as
    an array of the same shape (uint32 or uint64). It must be a pure function of its arguments.

    With ``batch_seeds=True`` the law checks call ``fn`` once for many seeds: ``words`` is a
    2-D array with one row per seed and ``seed`` a uint64 array of shape ``(rows, 1)``, so
    NumPy code that combines ``seed`` with ``words`` elementwise broadcasts it unchanged; the
    reply has the words' shape. The structural checks still pass one seed as an int. The
    verdicts are the same as without it, in far fewer calls (the quick level makes about 2,000
    calls per dimension and pass otherwise).
    The battery checks structure exactly (injectivity, nestedness in base ``base``, nets kept)
    and randomness by marginal and joint laws over seeds 0, 1, 2, ... (node laws, pairs of
    nodes, GF(2) flip relations, subtree collisions, Owen's pair lemma, dimensions), judged on
    ``claims`` at a family-wise false-alarm rate of 1e-3.

    Args:
        fn: the scrambler.
        base: its scrambling base: a power of two 2..256 (binary words, value word·2^-W), or
            any other base 3..65535, whose words are integers below b^m (m base-b digits, the
            most with b^m ≤ 2^width, most significant first; value word·b^-m). Base 3 in
            32-bit words: 20 digits, words below 3^20. ``flip-rank`` is not applicable there.
        width: 32 or 64.
        level: ``"quick"``, ``"full"`` or ``"exhaustive"``.
        claims: what it claims: ``"owen"``, ``"nested"``, ``"marginal[:GROUP]"`` or
            ``"independent:GROUP"`` (GROUP: symmetric, affine, translation, cyclic).
        seed: the seed of the main instance (structural checks).
        expect: a registry scrambler it must equal bit for bit (e.g. ``"owen-per-bit-hash"``).
        name: the name in the report (default: the function's ``__qualname__``).
        batch_seeds: whether ``fn`` takes many seeds per call (above).
        max_dims: the dimensions ``fn`` serves, 0..max_dims-1 (a sampler with N dimensions
            per domain); ``fn`` is never called with another, and a sub-test that needs one
            reports "not run: needs dimension D" (as ``verify --max-dims``).

    Returns:
        A :class:`VerifyResult`. An exception raised by ``fn`` (or a reply of the wrong shape,
        dtype or range) stops the battery and is re-raised.
    """
    if not callable(fn):
        raise TypeError(f"fn must be callable, not {type(fn).__name__}")
    base = _integer("base", base, 2, 65535)
    width = _integer("width", width)
    level = _string("level", level)
    claims = _string("claims", claims)
    seed = _integer("seed", seed)
    if expect is not None:
        expect = _string("expect", expect)
    if name is None:
        name = getattr(fn, "__qualname__", None) or type(fn).__name__
    name = _string("name", name)
    if not isinstance(batch_seeds, bool):
        raise TypeError(f"batch_seeds must be True or False, not {batch_seeds!r}")
    if max_dims is not None:
        max_dims = _integer("max_dims", max_dims, 1, 2**32 - 1)
    text, calls, words, python_seconds, seconds = _native.verify(
        fn, name, base, width, level, claims, seed, expect, batch_seeds, max_dims
    )
    cert = json.loads(text)
    report = cert["result"]["implementations"][0]
    passed = not any(c["verdict"] == "fail" for c in report["checks"])
    return VerifyResult(passed, report, cert, calls, words, python_seconds, seconds)


def list_scramblers() -> List[Dict[str, Any]]:
    """Every registered scrambler: ``name``, ``base``, ``table_bytes`` (default configuration),
    ``claim`` (``nested``, ``marginal:GROUP``, ``independent:GROUP`` or ``owen``),
    ``claims_nested_uniform`` and ``summary`` (with its options), as ``gartowen list --json``.
    """
    return json.loads(_native.list_scramblers())
