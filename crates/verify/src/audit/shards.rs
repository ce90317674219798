//! What one shard of a verify run must hold: its members of the implementation list, in
//! order, and nothing else.

use super::{refuse, AuditError};
use crate::verdict::ImplReport;

/// A shard holds implementations k with k mod N = I − 1, each once, in order: all of them
/// and no other. A shard past the list (N above the number of implementations, as a fixed CI
/// matrix gives) holds none and records an empty list; the whole run records at least one.
pub(super) fn shard_members(
    reports: &[ImplReport],
    (index, count): (u64, u64),
    total: usize,
    external: bool,
) -> Result<(), AuditError> {
    if external && count != 1 {
        return Err(refuse(
            "parameters.shard",
            format!("shard {index}/{count} of an external program: its battery is not sharded"),
        ));
    }
    // Counted, not listed: `total` and `count` are the file's numbers, possibly huge.
    let first = index - 1;
    let members = if first < total as u64 {
        (total as u64 - 1 - first) / count + 1
    } else {
        0
    };
    let in_place = reports
        .iter()
        .enumerate()
        .all(|(j, r)| Some(r.index as u64) == first.checked_add(j as u64 * count));
    if reports.len() as u64 != members || !in_place {
        let got: Vec<usize> = reports.iter().map(|r| r.index).collect();
        return Err(refuse(
            "result.implementations",
            format!(
                "indices {got:?}, but shard {index}/{count} of {total} implementations holds \
                 the {members} with k mod {count} = {first}, in order"
            ),
        ));
    }
    if reports.is_empty() && count == 1 {
        return Err(refuse("result.implementations", "empty"));
    }
    Ok(())
}
