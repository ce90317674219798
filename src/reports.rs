//! JSON records shared by the CLI and the Python package, so both describe one input and one
//! result identically.

use gartowen_discrepancy::Discrepancy;
use gartowen_netcheck::PointSet;
use gartowen_verify::certificate::InputRecord;
use serde_json::{json, Value};

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
