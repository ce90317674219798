"""The rendering benchmark: gartowen samplers against Mitsuba's own inside Mitsuba 3, on scenes
that stress decorrelation, by RMSE against a converged reference over many seeds.

    python -m gartowen.render --quick --out out/render        # CI-sized, about a minute
    python -m gartowen.render --out record/render             # the full run

Writes ``render.json`` (every number), ``render.md`` (tables, verdicts, the fixed-table check)
and ``*.png`` images (reference and error maps). Each method is rendered at every N for every
seed; per N it reports RMSE ± SE over seeds, seconds per sample and efficiency 1 / (MSE ×
seconds per sample). Method pairs get a verdict on the ratio of mean MSEs (a delta-method
confidence interval at family-wise level 0.05, Bonferroni over the pairs × N): ``better``,
``worse``, ``equivalent`` (inside ±``margin``) or ``inconclusive``.

The fixed-table check asks whether one table shared by every pixel correlates the pixels'
errors: for disjoint pairs of horizontally adjacent pixels it correlates the two errors over
seeds, and tests the mean correlation against 0 (two-sided, level 0.001 per row, not corrected
across rows; under independent pixel keys it is ~N(0, 1/(pairs · (seeds − 1))), so it detects
|ρ̄| ≥ 4.57 / sqrt(pairs · (seeds − 1)) at power 0.9: 0.153 in the quick run). Keys shared by
every pixel (``keys=shared``, the deliberately broken control) must fail it.
"""

from __future__ import annotations

import argparse
import json
import math
import os
import sys
import time
import zlib
from dataclasses import asdict, dataclass
from statistics import NormalDist
from typing import Any, Dict, List, Optional, Sequence, Tuple

import numpy as np

from . import mitsuba as gm

#: Level of the fixed-table check (two-sided).
CORRELATION_ALPHA = 0.001
#: Family-wise level of the method-pair verdicts.
VERDICT_ALPHA = 0.05


@dataclass(frozen=True)
class Method:
    """A sampler as a Mitsuba sampler dict (``gartowen`` ones get the seed as a property), with
    the short key ``--methods`` names it by (default: its label)."""

    label: str
    sampler: Dict[str, Any]
    key: str = ""


def methods(quick: bool) -> List[Method]:
    """The methods of issue 58: Mitsuba's own, then gartowen's (the quick mode takes a subset)."""
    g = lambda key, label, **p: Method(label, dict(type="gartowen", **p), key)
    own = [Method("mitsuba independent", {"type": "independent"}, "independent"),
           Method("mitsuba stratified", {"type": "stratified"}, "stratified"),
           Method("mitsuba multijitter", {"type": "multijitter"}, "multijitter"),
           Method("mitsuba ldsampler", {"type": "ldsampler"}, "ldsampler")]
    ours = [g("sobol-owen", "sobol + owen (binary)", sequence="sobol",
              scramble="owen-oracle:base=2"),
            g("sobol-lk-hash", "sobol + lk-hash", sequence="sobol", scramble="lk-hash"),
            g("art-owen-2", "sz16 + art-owen-2 (fixed table)", sequence="sz16",
              scramble="art-owen-2"),
            g("art-owen-16p", "sz16 + art-owen-16p (fixed table)", sequence="sz16",
              scramble="art-owen-16p"),
            g("art-owen-16p-per-pixel", "sz16 + art-owen-16p (table per pixel)", sequence="sz16",
              scramble="art-owen-16p", table="per-pixel"),
            g("owen-16", "sz16 + owen (base 16)", sequence="sz16", scramble="owen-oracle:base=16"),
            g("control-shared-key", "control: sz16 + art-owen-16p, one key for every pixel",
              sequence="sz16", scramble="art-owen-16p", keys="shared")]
    if quick:
        return [own[0], ours[0], ours[3], ours[5], ours[6]]
    return own + ours


def select_methods(quick: bool, keys: Optional[List[str]]) -> List[Method]:
    """The methods ``keys`` names (in the benchmark's order), or all of the mode's.

    Raises:
        ValueError: a key that names no method.
    """
    every = methods(False)
    if not keys:
        return methods(quick)
    known = {m.key for m in every}
    unknown = [k for k in keys if k not in known]
    if unknown:
        raise ValueError(f"unknown method {unknown[0]!r}: the methods are "
                         f"{', '.join(m.key for m in every)}")
    return [m for m in every if m.key in keys]


#: The pairs judged: (method, against).
PAIRS = [("sz16 + art-owen-16p (fixed table)", "sobol + owen (binary)"),
         ("sz16 + art-owen-16p (fixed table)", "sz16 + owen (base 16)"),
         ("sz16 + art-owen-16p (fixed table)", "sz16 + art-owen-16p (table per pixel)"),
         ("sobol + owen (binary)", "mitsuba independent")]


def scenes(mi: Any, quick: bool, side: Optional[int] = None) -> Dict[str, Dict[str, Any]]:
    """Scene dicts: Mitsuba's Cornell box; a small area light over an occluder (penumbra, MIS);
    a rough conductor with deep paths and Russian roulette. Quick: the Cornell box alone."""
    side = side or (16 if quick else 32)

    def box(integrator: Dict[str, Any]) -> Dict[str, Any]:
        d = mi.cornell_box()
        d["sensor"]["film"]["width"] = side
        d["sensor"]["film"]["height"] = side
        # A box filter: each sample lands in its own pixel, so that pixels are estimated from
        # their own samples alone (the default Gaussian splats into neighbours and correlates
        # them whatever the sampler).
        d["sensor"]["film"]["rfilter"] = {"type": "box"}
        d["integrator"] = integrator
        return d

    out = {"cornell": box({"type": "path", "max_depth": 6})}
    if quick:
        return out
    penumbra = box({"type": "path", "max_depth": 3})
    light = penumbra["light"]
    light["to_world"] = light["to_world"] @ mi.ScalarTransform4f().scale([0.35, 0.35, 1.0])
    penumbra["occluder"] = {"type": "sphere", "radius": 0.35,
                            "to_world": mi.ScalarTransform4f().translate([0.0, 0.35, 0.0]),
                            "bsdf": {"type": "diffuse"}}
    out["penumbra"] = penumbra
    glossy = box({"type": "path", "max_depth": 12, "rr_depth": 2})
    glossy["ball"] = {"type": "sphere", "radius": 0.45,
                      "to_world": mi.ScalarTransform4f().translate([0.2, -0.55, 0.1]),
                      "bsdf": {"type": "roughconductor", "alpha": 0.15}}
    out["glossy"] = glossy
    return out


def render(mi: Any, scene: Dict[str, Any], method: Method, spp: int, seed: int) -> Tuple[np.ndarray, float]:
    """One render of ``scene`` with ``method`` at ``spp`` and ``seed``: the image and seconds."""
    image, seconds, _ = render_counted(mi, scene, method, spp, seed)
    return image, seconds


def render_counted(mi: Any, scene: Dict[str, Any], method: Method, spp: int,
                   seed: int) -> Tuple[np.ndarray, float, int]:
    """[`render`], with the samples per pixel the sampler really took: Mitsuba's ldsampler
    rounds to a square power of two (100 → 256), stratified and multijitter to a square."""
    sampler = dict(method.sampler, sample_count=spp)
    if sampler["type"] == "gartowen":
        sampler["seed"] = seed
    d = dict(scene)
    d["sensor"] = dict(scene["sensor"], sampler=sampler)
    loaded = mi.load_dict(d)
    taken = int(loaded.sensors()[0].sampler().sample_count())
    started = time.perf_counter()
    image = np.array(mi.render(loaded, spp=taken, seed=seed), dtype=np.float64)
    return image, time.perf_counter() - started, taken


#: Independent parts a reference is rendered in (their spread gives its own variance).
REFERENCE_PARTS = 16


def reference(mi: Any, name: str, scene: Dict[str, Any], spp: int,
              cache: Optional[str]) -> Tuple[np.ndarray, np.ndarray]:
    """The converged image (Mitsuba's independent sampler at ``spp`` in all, in
    [`REFERENCE_PARTS`] independent parts) and the variance of each of its values (the parts'
    spread / parts), cached in ``cache``. A method's MSE is corrected by the mean variance:
    E|image − reference|² = MSE + Var(reference), so the reference's own noise does not
    flatten the comparison of methods whose error approaches it."""
    path = os.path.join(cache, f"reference-{name}-{spp}.npz") if cache else None
    if path and os.path.exists(path):
        saved = np.load(path)
        return saved["mean"], saved["variance"]
    part = max(1, spp // REFERENCE_PARTS)
    parts = np.stack([render(mi, scene, Method("reference", {"type": "independent"}), part,
                             0x5EED + k)[0] for k in range(REFERENCE_PARTS)])
    mean, variance = parts.mean(0), parts.var(0, ddof=1) / REFERENCE_PARTS
    if path:
        os.makedirs(cache, exist_ok=True)
        np.savez(path, mean=mean, variance=variance)
    return mean, variance


def pixel_correlation(errors: np.ndarray) -> Dict[str, float]:
    """The fixed-table check on ``errors`` (seeds × height × width × channels): the mean over
    disjoint horizontal pixel pairs of the correlation over seeds of their luminance errors,
    its z statistic under independence and the two-sided p-value."""
    lum = errors.mean(axis=-1) if errors.ndim == 4 else errors
    seeds = lum.shape[0]
    left, right = lum[:, :, 0:-1:2].reshape(seeds, -1), lum[:, :, 1::2].reshape(seeds, -1)
    left, right = left - left.mean(0), right - right.mean(0)
    norm = np.sqrt((left ** 2).sum(0) * (right ** 2).sum(0))
    keep = norm > 0
    r = (left * right).sum(0)[keep] / norm[keep]
    pairs = int(keep.sum())
    mean_r = float(r.mean()) if pairs else 0.0
    scale = math.sqrt(max(pairs * (seeds - 1), 1))
    z = mean_r * scale
    p = 2.0 * (1.0 - NormalDist().cdf(abs(z)))
    # The smallest |ρ̄| detected with power 0.9 at the check's level.
    normal = NormalDist()
    detects = (normal.inv_cdf(1 - CORRELATION_ALPHA / 2) + normal.inv_cdf(0.9)) / scale
    return {"mean_correlation": mean_r, "pairs": pairs, "seeds": seeds, "z": z, "p_value": p,
            "detects": detects, "passes": p >= CORRELATION_ALPHA}


def verdict(a: Sequence[float], b: Sequence[float], margin: float, alpha: float) -> Dict[str, Any]:
    """MSE ratio mean(a)/mean(b) with its confidence interval (delta method on the log) at
    level ``alpha``, and the verdict: better (< 1), worse (> 1), equivalent (inside [1/(1 +
    margin), 1 + margin]) or inconclusive; with the ratio the test detects at power 0.9
    (``detects``) and the seeds per method that would decide equivalence at this spread
    (``seeds_for_equivalence``, None when the observed ratio lies outside the margin)."""
    ma, mb = float(np.mean(a)), float(np.mean(b))
    if ma <= 0 or mb <= 0:
        # Errors below the reference's own noise: no ratio to judge.
        return {"ratio": float("nan"), "low": float("nan"), "high": float("nan"),
                "verdict": "inconclusive", "detects": float("nan"),
                "seeds_for_equivalence": None}
    se = math.sqrt(np.var(a, ddof=1) / len(a) / ma ** 2 + np.var(b, ddof=1) / len(b) / mb ** 2)
    z = NormalDist().inv_cdf(1 - alpha / 2)
    ratio = ma / mb
    low, high = ratio * math.exp(-z * se), ratio * math.exp(z * se)
    # Power: a true ratio of `detects` (or its inverse) is called different with probability
    # 0.9. Seeds: how many per method would put this spread's interval inside the margin, were
    # the ratio what was observed (none when it lies outside the margin).
    detects = math.exp((z + NormalDist().inv_cdf(0.9)) * se)
    room = math.log(1 + margin) - abs(math.log(ratio))
    seeds = max(len(a), len(b))
    needed = math.ceil(seeds * (z * se / room) ** 2) if room > 0 else None
    if 1 / (1 + margin) <= low and high <= 1 + margin:
        word = "equivalent"
    elif high < 1:
        word = "better"
    elif low > 1:
        word = "worse"
    else:
        word = "inconclusive"
    return {"ratio": ratio, "low": low, "high": high, "verdict": word, "detects": detects,
            "seeds_for_equivalence": needed}


def _png(path: str, image: np.ndarray) -> None:
    """Writes an RGB image in [0, 1] (gamma 2.2) as an 8-bit PNG (zlib only)."""
    rgb = np.clip(image[..., :3], 0, 1) ** (1 / 2.2)
    data = (rgb * 255 + 0.5).astype(np.uint8)
    h, w = data.shape[:2]
    raw = b"".join(b"\x00" + data[y].tobytes() for y in range(h))
    chunk = lambda tag, body: (len(body).to_bytes(4, "big") + tag + body
                               + zlib.crc32(tag + body).to_bytes(4, "big"))
    header = w.to_bytes(4, "big") + h.to_bytes(4, "big") + bytes([8, 2, 0, 0, 0])
    with open(path, "wb") as f:
        f.write(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", header) + chunk(b"IDAT", zlib.compress(raw))
                + chunk(b"IEND", b""))


#: The scenes, in order.
SCENES = ("cornell", "penumbra", "glossy")


def run(quick: bool, out: str, seeds: Optional[int] = None, sizes: Optional[List[int]] = None,
        margin: float = 0.2, reference_spp: Optional[int] = None, log: Any = sys.stderr,
        only: Optional[List[str]] = None, side: Optional[int] = None,
        method_keys: Optional[List[str]] = None) -> Dict[str, Any]:
    """Runs the benchmark (the scenes ``only`` names, else all of the mode's; the methods
    ``method_keys`` names, else all of the mode's) and writes its files into ``out``; returns
    the JSON document.

    Raises:
        ValueError: an unknown scene or method name.
        gartowen.mitsuba.MitsubaUnavailable: Mitsuba or libLLVM is missing.
    """
    unknown = [n for n in only or [] if n not in SCENES]
    if unknown:
        raise ValueError(f"unknown scene {unknown[0]!r}: the scenes are {', '.join(SCENES)}")
    chosen = select_methods(quick, method_keys)
    mi = gm.load_mitsuba()
    seeds = seeds or (8 if quick else 32)
    sizes = sizes or ([16, 64] if quick else [16, 32, 64, 100, 256, 1024])
    reference_spp = reference_spp or (4096 if quick else 65536)
    os.makedirs(out, exist_ok=True)
    doc: Dict[str, Any] = {"quick": quick, "seeds": seeds, "sizes": sizes, "margin": margin,
                           "resolution": side or (16 if quick else 32),
                           "reference_spp": reference_spp, "verdict_alpha": VERDICT_ALPHA,
                           "correlation_alpha": CORRELATION_ALPHA, "scenes": {}}
    pairs = [p for p in PAIRS if {p[0], p[1]} <= {m.label for m in chosen}]
    chosen_scenes = scenes(mi, quick and not only, side)
    for name, scene in chosen_scenes.items():
        if only and name not in only:
            continue
        ref, ref_variance = reference(mi, name, scene, reference_spp, os.path.join(out, "cache"))
        noise = float(ref_variance.mean())
        _png(os.path.join(out, f"{name}-reference.png"), ref)
        rows: Dict[str, Dict[int, Dict[str, Any]]] = {}
        for m in chosen:
            rows[m.label] = {}
            for n in sizes:
                mse, seconds, errors, taken = [], 0.0, [], n
                for s in range(seeds):
                    image, t, taken = render_counted(mi, scene, m, n, s)
                    errors.append(image - ref)
                    mse.append(float(((image - ref) ** 2).mean()) - noise)
                    seconds += t
                    if s == 0 and n == sizes[-1]:
                        err = np.abs(image - ref)
                        _png(os.path.join(out, f"{name}-error-{len(rows) - 1}.png"),
                             err / max(float(err.max()), 1e-12))
                rmse = np.sqrt(np.maximum(mse, 0.0))
                per_sample = seconds / (seeds * taken * ref.shape[0] * ref.shape[1])
                rows[m.label][n] = {
                    "spp_taken": taken,
                    "rmse": float(rmse.mean()), "rmse_se": float(rmse.std(ddof=1) / math.sqrt(seeds)),
                    "mse": mse, "seconds_per_sample": per_sample,
                    "efficiency": 1.0 / (float(np.mean(mse)) * per_sample),
                    "fixed_table_check": pixel_correlation(np.stack(errors)),
                }
                print(f"render: {name} {m.label} N={n}: RMSE {rows[m.label][n]['rmse']:.4g} "
                      f"± {rows[m.label][n]['rmse_se']:.2g}", file=log)
        alpha = VERDICT_ALPHA / max(1, len(pairs) * len(sizes))
        judged = [{"method": a, "against": b, "n": n,
                   **verdict(rows[a][n]["mse"], rows[b][n]["mse"], margin, alpha)}
                  for a, b in pairs for n in sizes]
        doc["scenes"][name] = {"methods": rows, "pairs": judged, "pair_alpha": alpha,
                               "error_maps": {str(k): m.label for k, m in enumerate(chosen)}}
    with open(os.path.join(out, "render.json"), "w") as f:
        json.dump(doc, f, indent=1)
    with open(os.path.join(out, "render.md"), "w") as f:
        f.write(markdown(doc))
    return doc


def markdown(doc: Dict[str, Any]) -> str:
    """The report in words and tables."""
    lines = [f"# Rendering benchmark ({'quick' if doc['quick'] else 'full'})", "",
             f"Mitsuba 3, {doc['resolution']}×{doc['resolution']} pixels, RMSE against a "
             f"{doc['reference_spp']}-spp reference of Mitsuba's independent sampler (MSE less "
             f"the reference's own variance), over {doc['seeds']} seeds per point. Verdicts: MSE ratio, "
             f"family-wise level {doc['verdict_alpha']} (Bonferroni over pairs × N), equivalent "
             f"within ±{doc['margin']:.0%}. Fixed-table check: mean correlation of adjacent "
             f"pixels' errors, two-sided level {doc['correlation_alpha']} per row, not "
             f"corrected across rows (each row's false-alarm rate is its level), with the "
             f"|ρ̄| it detects at power 0.9. A pair's `detects` is the MSE ratio (or its "
             f"inverse) called different at power 0.9; `seeds for ±margin` is how many seeds "
             f"per method would decide equivalence at the observed ratio and spread "
             f"(`outside`: the ratio lies outside the margin).", ""]
    for name, s in doc["scenes"].items():
        lines += [f"## {name}", "", "| method | N | RMSE ± SE | s/sample | efficiency | fixed-table check |",
                  "|---|---:|---|---:|---:|---|"]
        for label, by_n in s["methods"].items():
            for n, r in by_n.items():
                c = r["fixed_table_check"]
                power = f", detects |ρ̄| ≥ {c['detects']:.3f}" if "detects" in c else ""
                check = (f"{'pass' if c['passes'] else 'FAIL'} (ρ̄ = {c['mean_correlation']:.3f}, "
                         f"p = {c['p_value']:.2g}{power})")
                taken = r.get("spp_taken", int(n))
                shown = f"{n} (ran {taken})" if taken != int(n) else f"{n}"
                lines.append(f"| {label} | {shown} | {r['rmse']:.4g} ± {r['rmse_se']:.2g} | "
                             f"{r['seconds_per_sample']:.2e} | {r['efficiency']:.3g} | {check} |")
        lines += ["", "| method | against | N | MSE ratio [CI] | verdict | detects | seeds for ±margin |",
                  "|---|---|---:|---|---|---:|---:|"]
        for p in s["pairs"]:
            needed = p.get("seeds_for_equivalence")
            lines.append(f"| {p['method']} | {p['against']} | {p['n']} | {p['ratio']:.3f} "
                         f"[{p['low']:.3f}, {p['high']:.3f}] | {p['verdict']} | "
                         f"{p.get('detects', float('nan')):.2f}× | "
                         f"{needed if needed is not None else 'outside'} |")
        lines.append("")
    return "\n".join(lines)


def main(argv: Optional[List[str]] = None) -> int:
    """``python -m gartowen.render``: exit 0 when it ran, 2 on bad input or missing Mitsuba."""
    p = argparse.ArgumentParser(prog="gartowen-render", description=__doc__.split("\n\n")[0])
    p.add_argument("--quick", action="store_true", help="the CI-sized run (one scene, 5 methods)")
    p.add_argument("--out", default="out/render", help="output folder (default out/render)")
    p.add_argument("--seeds", type=int, help="seeds per point (default 8 quick, 32 full)")
    p.add_argument("--sizes", help="samples per pixel, comma-separated (default 16,64 quick)")
    p.add_argument("--margin", type=float, default=0.2, help="equivalence margin (default 0.2)")
    p.add_argument("--resolution", type=int, help="image side in pixels (default 16 quick, 32 full)")
    p.add_argument("--methods", help="methods to run, comma-separated keys ("
                                     + ", ".join(m.key for m in methods(False))
                                     + "; default: the mode's)")
    p.add_argument("--scenes", help=f"scenes to run, comma-separated ({', '.join(SCENES)}; "
                                    "default: cornell when --quick, all otherwise)")
    a = p.parse_args(argv)
    only = a.scenes.split(",") if a.scenes else None
    try:
        sizes = [int(x) for x in a.sizes.split(",")] if a.sizes else None
        if sizes is not None and (not sizes or min(sizes) < 1):
            raise ValueError
    except ValueError:
        print(f"gartowen-render: --sizes '{a.sizes}': positive integers, comma-separated", file=sys.stderr)
        return 2
    if a.seeds is not None and a.seeds < 2:
        print("gartowen-render: --seeds must be at least 2 (a standard error needs two)", file=sys.stderr)
        return 2
    try:
        if a.resolution is not None and not 2 <= a.resolution <= 1024:
            raise ValueError(f"--resolution {a.resolution}: 2 to 1024 pixels")
        keys = a.methods.split(",") if a.methods else None
        run(a.quick, a.out, a.seeds, sizes, a.margin, only=only, side=a.resolution,
            method_keys=keys)
    except (gm.MitsubaUnavailable, ValueError) as e:
        print(f"gartowen-render: {e}", file=sys.stderr)
        return 2
    print(f"render report in {a.out}/render.md")
    return 0


if __name__ == "__main__":
    sys.exit(main())
