//! JSON records shared by the CLI and the Python package, so both describe one input and one
//! result identically.

use gartowen_discrepancy::choice::{compute, MethodChoice};
use gartowen_discrepancy::{Discrepancy, Kind, Points};
use gartowen_netcheck::PointSet;
use gartowen_verify::certificate::InputRecord;
use serde_json::{json, Value};
use std::time::Instant;

/// The certificate record of a point set: its kind (`file`, `array`), its name (a path, or
/// the argument's name), the FNV-1a checksum of its words (row-major, little-endian) and its
/// shape.
pub fn point_set_record(kind: &str, name: &str, points: &PointSet) -> InputRecord {
    InputRecord {
        kind: kind.into(),
        name: name.into(),
        checksum_fnv1a64: Some(format!("{:016x}", points.checksum())),
        details: json!({
            "points": points.len(), "dims": points.dims(), "width_bits": points.width().bits(),
        }),
    }
}

/// A discrepancy result as `gartowen discrepancy --json` reports it: kind, method, value (D²,
/// or D with `root`), the exact rational D² as decimal `p/q` where computed (and in hex as
/// `exact_hex`), the relative error bound and the seconds it took.
pub fn discrepancy_json(d: &Discrepancy, seconds: f64, root: bool) -> Value {
    let value = if root { d.value.sqrt() } else { d.value };
    json!({
        "kind": d.kind.name(),
        "method": d.method,
        "value": value,
        "squared": !root,
        "exact": d.exact.as_ref().map(|r| r.to_string()),
        // The same rational in hex, which readers convert without decimal digit limits
        // (Python refuses decimal integers past 4300 digits).
        "exact_hex": d.exact.as_ref().map(|r| {
            format!("{}/{}", r.numer().to_str_radix(16), r.denom().to_str_radix(16))
        }),
        "rel_error_bound": d.rel_error_bound,
        "seconds": seconds,
    })
}

/// D² of `points` by `method`, with the seconds it took.
pub fn timed_discrepancy(
    points: Points,
    kind: Kind,
    method: MethodChoice,
) -> Result<(Discrepancy, f64), String> {
    let started = Instant::now();
    let d = compute(points, kind, method)?;
    Ok((d, started.elapsed().as_secs_f64()))
}

/// The 2-D results of pairs of dimensions (`all`: every pair, else dimension 0 with each
/// other), each as [`discrepancy_json`] with its `pair`, as `gartowen discrepancy --pairs`
/// reports them.
pub fn discrepancy_pairs(
    points: Points,
    kind: Kind,
    method: MethodChoice,
    root: bool,
    all: bool,
) -> Result<Vec<Value>, String> {
    let (n, d) = (points.len(), points.dims);
    gartowen_discrepancy::curves::pair_list(d, all)
        .into_iter()
        .map(|[i, j]| {
            let two: Vec<u64> = (0..n)
                .flat_map(|k| [points.words[k * d + i], points.words[k * d + j]])
                .collect();
            let pair = Points {
                words: &two,
                dims: 2,
                width: points.width,
            };
            let (r, seconds) = timed_discrepancy(pair, kind, method)?;
            let mut v = discrepancy_json(&r, seconds, root);
            v["pair"] = json!([i, j]);
            Ok(v)
        })
        .collect()
}
