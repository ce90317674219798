# Type stubs of the native module. The public API is in gartowen/__init__.py; these take
# validated arguments (see there for units and conventions).
from typing import Callable, List, Optional, Tuple

import numpy as np

__version__: str

def generate(
    seq: str, dims: int, n: int, scramble: str, seed: int, base: Optional[int], bits: int,
    words: bool, start: int, gray: bool,
) -> np.ndarray: ...
def scramble(
    points: np.ndarray, name: str, seed: int, base: Optional[int], bits: Optional[int]
) -> np.ndarray: ...
def scramble_per_key(
    words: np.ndarray, name: str, keys: List[int], table_seed: Optional[int], first_dim: int,
    base: Optional[int],
) -> np.ndarray: ...
def check(
    points: np.ndarray, base: int, m: Optional[int], t: Optional[int],
    projections: Optional[str], sequence: bool, histograms: bool,
) -> Tuple[str, bool, str]: ...
def discrepancy(
    points: np.ndarray, kind: str, method: str, root: bool, pairs: Optional[str]
) -> str: ...
def verify(
    func: Callable[[np.ndarray, int, int], np.ndarray], name: str, base: int, width: int,
    level: str, claim: str, seed: int, expect: Optional[str], batch_seeds: bool,
    max_dims: Optional[int],
) -> Tuple[str, int, int, float, float]: ...
def list_scramblers() -> str: ...
def describe_box(
    shape: List[int], box_index: List[int], count: int, expected: int, base: int
) -> str: ...
