"""gartowen samplers inside Mitsuba 3: a ``mi.Sampler`` whose samples are a gartowen sequence,
scrambled per pixel.

Install with the extra (``pip install './python[mitsuba]'``, which brings Mitsuba 3 from PyPI);
the LLVM variants also need libLLVM 16 or newer (Debian: ``apt-get install libllvm19``), found
through ``DRJIT_LIBLLVM_PATH`` or the usual library folders.

    import gartowen.mitsuba as gm
    mi = gm.load_mitsuba()                      # imports Mitsuba, sets the variant, registers
    scene = mi.load_dict({... "sampler": {"type": "gartowen", "sequence": "sz16",
                                          "scramble": "art-owen-16p", "sample_count": 64}})

The sampler's properties:

* ``sequence``: a gartowen sequence (``sobol``, ``sz16``, …; default ``sobol``);
* ``scramble``: a registry scrambler (default ``owen-oracle:base=2``, binary Owen);
* ``table``: for ART variants, ``fixed`` (default: one table seeded once per render, as a
  renderer ships it; each pixel's seed picks every dimension's root symbol and shifts) or
  ``per-pixel`` (a fresh table per pixel);
* ``keys``: ``per-pixel`` (default) or ``shared`` (every pixel the same seed: a deliberately
  broken layout whose pixels are correlated, the control of the fixed-table check);
* ``seed``: the render seed (default 0), combined with the seed Mitsuba passes.

Lanes map to (pixel, sample) as Mitsuba's film orders them: lane ``i`` is sample ``i % spp`` of
pixel ``i // spp``. The path's ``d``-th dimension (in Mitsuba's consumption order) is sequence
dimension ``d mod S`` (S the sequence's dimensions, at most 64) scrambled as dimension ``d``, so
dimensions past the sequence's are padded by independently scrambled repeats.
"""

from __future__ import annotations

import glob
import os
from typing import Any, Dict, List, Optional

import numpy as np

from . import generate, scramble_per_key

#: What to run where Mitsuba is missing.
INSTALL_MITSUBA = "pip install 'gartowen[mitsuba]' (or: pip install mitsuba)"
#: What to run where libLLVM is missing (Debian's; any libLLVM ≥ 16 works).
INSTALL_LLVM = "apt-get install libllvm19 (or point DRJIT_LIBLLVM_PATH at a libLLVM ≥ 16)"

#: Dimensions scrambled per call of the native code (computed ahead, as the path needs them).
_BLOCK = 8
#: The most sequence dimensions used before padding.
_MOST_DIMS = 64


class MitsubaUnavailable(RuntimeError):
    """Mitsuba 3 or the libLLVM its LLVM variants need is missing; the message names the
    install line."""


def find_libllvm() -> Optional[str]:
    """A libLLVM of version 16 or newer in the usual folders (newest first), or None."""
    found = []
    for folder in ("/usr/lib/x86_64-linux-gnu", "/usr/lib/aarch64-linux-gnu", "/usr/lib64",
                   "/usr/lib", "/usr/local/lib"):
        for path in glob.glob(os.path.join(folder, "libLLVM*.so*")):
            digits = "".join(c if c.isdigit() else " " for c in os.path.basename(path)).split()
            if digits and 16 <= int(digits[0]) < 100:
                found.append((int(digits[0]), path))
    return max(found)[1] if found else None


_REGISTERED: Dict[str, Any] = {}


def load_mitsuba(variant: str = "llvm_ad_rgb") -> Any:
    """Imports Mitsuba 3, sets ``variant``, turns symbolic loops off (so that the path tracer
    calls a Python sampler once per bounce and dimension with the whole wavefront) and
    registers the ``gartowen`` sampler; returns the ``mitsuba`` module.

    Raises:
        MitsubaUnavailable: Mitsuba or libLLVM is missing, naming the install line.
    """
    if variant.startswith("llvm") and not os.environ.get("DRJIT_LIBLLVM_PATH"):
        path = find_libllvm()
        if path is None:
            raise MitsubaUnavailable(f"Mitsuba's {variant} variant needs libLLVM ≥ 16: {INSTALL_LLVM}")
        os.environ["DRJIT_LIBLLVM_PATH"] = path
    try:
        import drjit as dr
        import mitsuba as mi
    except ImportError as e:
        raise MitsubaUnavailable(f"Mitsuba 3 is not installed ({e}): {INSTALL_MITSUBA}") from None
    try:
        mi.set_variant(variant)
    except (ImportError, AttributeError, RuntimeError, ValueError) as e:
        raise MitsubaUnavailable(
            f"Mitsuba cannot set the {variant} variant ({e}); for LLVM variants: {INSTALL_LLVM}"
        ) from None
    dr.set_flag(dr.JitFlag.SymbolicLoops, False)
    if variant not in _REGISTERED:
        _REGISTERED[variant] = _register(mi)
    return mi


def _splitmix(x: np.ndarray) -> np.ndarray:
    """SplitMix64's finalizer on uint64 (wrapping arithmetic)."""
    with np.errstate(over="ignore"):
        z = x + np.uint64(0x9E3779B97F4A7C15)
        z = (z ^ (z >> np.uint64(30))) * np.uint64(0xBF58476D1CE4E5B9)
        z = (z ^ (z >> np.uint64(27))) * np.uint64(0x94D049BB133111EB)
        return z ^ (z >> np.uint64(31))


def pixel_keys(render_seed: int, pass_seed: int, pixels: int, shared: bool = False) -> List[int]:
    """The per-pixel keys of a render: a hash of (render seed, Mitsuba's seed, pixel); with
    ``shared`` every pixel gets the first one."""
    base = _splitmix(np.array([render_seed], dtype=np.uint64) ^ _splitmix(
        np.array([pass_seed], dtype=np.uint64)))
    index = np.zeros(pixels, dtype=np.uint64) if shared else np.arange(pixels, dtype=np.uint64)
    return _splitmix(base ^ _splitmix(index)).tolist()


def table_seed_of(render_seed: int) -> int:
    """The seed of a render's one fixed table."""
    return int(_splitmix(np.array([render_seed ^ 0x7AB1E], dtype=np.uint64))[0])


_SEQUENCE_DIMS: Dict[str, int] = {}


def sequence_dims(sequence: str) -> int:
    """The dimensions of ``sequence`` used before padding (its own, at most 64)."""
    if sequence not in _SEQUENCE_DIMS:
        for d in (_MOST_DIMS, 32, 16, 8, 4, 2, 1):
            try:
                generate(sequence, d, 1)
            except ValueError:
                continue
            _SEQUENCE_DIMS[sequence] = d
            break
        else:
            raise ValueError(f"sequence '{sequence}' makes no points")
    return _SEQUENCE_DIMS[sequence]


def _is_art(name: str) -> bool:
    base = name.split(":")[0]
    return base in ("art-owen-2", "q-art-4", "art-owen-8p", "art-owen-16p") or (
        base.startswith(("art-owen-m", "art-owen-t")) and base[10:].isdigit()
    )


class PixelSamples:
    """The sampler's state for one render pass: the unscrambled points of ``spp`` samples and
    their per-pixel scrambles, computed a block of dimensions at a time."""

    def __init__(self, sequence: str, scramble: str, table: str, spp: int, keys: List[int],
                 table_seed: Optional[int]):
        self.sequence, self.scramble, self.spp, self.keys = sequence, scramble, spp, keys
        self.table_seed = table_seed if (table == "fixed" and _is_art(scramble)) else None
        self.dims = sequence_dims(sequence)
        self.points = generate(sequence, self.dims, spp, bits=32, words=True)
        self.values: List[np.ndarray] = []

    def dimension(self, d: int) -> np.ndarray:
        """Path dimension ``d`` for every lane, float32 values in [0, 1)."""
        while d >= len(self.values):
            first = len(self.values)
            columns = [(first + k) % self.dims for k in range(_BLOCK)]
            words = np.ascontiguousarray(self.points[:, columns])
            out = scramble_per_key(words, self.scramble, self.keys,
                                   table_seed=self.table_seed, first_dim=first)
            # The top 24 bits: float32 holds them exactly and never rounds up to 1.
            values = ((out >> np.uint32(8)).astype(np.float32) * np.float32(2.0 ** -24))
            self.values.extend(values[:, :, k].reshape(-1) for k in range(_BLOCK))
        return self.values[d]


def _register(mi: Any) -> Any:
    """Defines the sampler class for the current variant and registers it as ``gartowen``."""

    class GartowenSampler(mi.Sampler):
        """A gartowen sequence scrambled per pixel (see the module doc)."""

        def __init__(self, props: Any = None):
            props = props if props is not None else mi.Properties()
            super().__init__(props)
            get = lambda key, default: props[key] if key in props else default
            self.sequence = str(get("sequence", "sobol"))
            self.scramble_name = str(get("scramble", "owen-oracle:base=2"))
            self.table = str(get("table", "fixed"))
            self.keys_mode = str(get("keys", "per-pixel"))
            self.render_seed = int(get("seed", 0))
            if self.table not in ("fixed", "per-pixel"):
                raise ValueError(f"gartowen sampler: table '{self.table}': fixed or per-pixel")
            if self.keys_mode not in ("per-pixel", "shared"):
                raise ValueError(f"gartowen sampler: keys '{self.keys_mode}': per-pixel or shared")
            sequence_dims(self.sequence)  # an unknown sequence is refused when the scene loads
            self.state: Optional[PixelSamples] = None
            self.next_dim = 0

        def seed(self, seed: Any = 0, wavefront_size: int = 1) -> None:
            spp = max(1, int(self.sample_count()))
            wavefront = max(1, int(wavefront_size))
            pass_seed = int(np.asarray(seed).reshape(-1)[0]) if np.size(seed) else 0
            # A wavefront that is not whole pixels (Mitsuba also seeds a sampler of one lane)
            # takes the first lanes of whole pixels.
            pixels = -(-wavefront // spp)
            keys = pixel_keys(self.render_seed, pass_seed, pixels,
                              shared=self.keys_mode == "shared")
            self.state = PixelSamples(self.sequence, self.scramble_name, self.table, spp, keys,
                                      table_seed_of(self.render_seed))
            self.lanes = wavefront
            self.next_dim = 0

        def _next(self) -> Any:
            if self.state is None:
                self.seed(0, self.sample_count())
            values = self.state.dimension(self.next_dim)[: self.lanes]
            self.next_dim += 1
            return mi.Float(values)

        def next_1d(self, active: Any = True) -> Any:
            return self._next()

        def next_2d(self, active: Any = True) -> Any:
            x = self._next()
            return mi.Point2f(x, self._next())

        def clone(self) -> Any:
            props = mi.Properties()
            props["sequence"] = self.sequence
            props["scramble"] = self.scramble_name
            props["table"] = self.table
            props["keys"] = self.keys_mode
            props["seed"] = self.render_seed
            props["sample_count"] = int(self.sample_count())
            return GartowenSampler(props)

        def fork(self) -> Any:
            return self.clone()

    mi.register_sampler("gartowen", lambda props: GartowenSampler(props))
    return GartowenSampler
