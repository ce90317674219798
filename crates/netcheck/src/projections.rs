//! Which projections to check: all pairs, sliding or aligned groups, or an explicit list.

use crate::NetError;
use std::str::FromStr;

/// The most projections one check expands to.
pub const MAX_PROJECTIONS: u128 = 1 << 20;

/// The most dimension indices all projections of one check hold together.
pub const MAX_PROJECTION_ENTRIES: u128 = 1 << 24;

/// A family of coordinate projections.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum ProjectionSpec {
    /// Every pair (i, j), i < j.
    Pairs,
    /// Every window of g consecutive dimensions: (0..g), (1..g+1), ….
    Groups(usize),
    /// Aligned disjoint blocks of g dimensions: (0..g), (g..2g), ….
    Blocks(usize),
    /// Explicit lists of dimensions.
    List(Vec<Vec<usize>>),
}

impl FromStr for ProjectionSpec {
    type Err = NetError;

    /// `pairs`, `groups:G`, `blocks:G`, or `0,1;2,3` (projections separated by `;`).
    fn from_str(s: &str) -> Result<Self, NetError> {
        let bad = |why: &str| NetError::BadProjection(format!("'{s}': {why}"));
        if s == "pairs" {
            return Ok(ProjectionSpec::Pairs);
        }
        for (prefix, make) in [
            (
                "groups:",
                ProjectionSpec::Groups as fn(usize) -> ProjectionSpec,
            ),
            ("blocks:", ProjectionSpec::Blocks),
        ] {
            if let Some(g) = s.strip_prefix(prefix) {
                let g: usize = g.parse().map_err(|_| bad("group size is not a number"))?;
                if g == 0 {
                    return Err(bad("group size must be at least 1"));
                }
                return Ok(make(g));
            }
        }
        let mut list = Vec::new();
        for part in s.split(';') {
            let dims: Result<Vec<usize>, _> = part.split(',').map(|d| d.trim().parse()).collect();
            let dims =
                dims.map_err(|_| bad("expected pairs, groups:G, blocks:G or lists like 0,1;2,3"))?;
            // A repeated dimension would make a projection that is no point set of its own
            // (every box of it is a box of the smaller one): refuse rather than judge it.
            if let Some(d) = dims
                .iter()
                .enumerate()
                .find_map(|(k, d)| dims[..k].contains(d).then_some(d))
            {
                return Err(bad(&format!("dimension {d} appears twice in '{part}'")));
            }
            list.push(dims);
        }
        Ok(ProjectionSpec::List(list))
    }
}

impl ProjectionSpec {
    /// The projections of an s-dimensional set; errors on dimensions past s or empty lists.
    pub fn expand(&self, s: usize) -> Result<Vec<Vec<usize>>, NetError> {
        // Count before allocating: `pairs` of 20,000 dimensions is 200 million projections.
        let (count, entries): (u128, u128) = match self {
            ProjectionSpec::Pairs => {
                let n = (s as u128) * (s as u128).saturating_sub(1) / 2;
                (n, 2 * n)
            }
            ProjectionSpec::Groups(g) => {
                let n = s.saturating_sub(g - 1) as u128;
                (n, n * *g as u128)
            }
            ProjectionSpec::Blocks(g) => ((s / g) as u128, (s / g * g) as u128),
            ProjectionSpec::List(l) => (l.len() as u128, l.iter().map(|p| p.len() as u128).sum()),
        };
        if count > MAX_PROJECTIONS || entries > MAX_PROJECTION_ENTRIES {
            return Err(NetError::BadProjection(format!(
                "{self:?} of {s} dimensions gives {count} projections ({entries} dimension \
                 indices); at most {MAX_PROJECTIONS} projections and {MAX_PROJECTION_ENTRIES} \
                 indices are checked in one run"
            )));
        }
        let out: Vec<Vec<usize>> = match self {
            ProjectionSpec::Pairs => (0..s)
                .flat_map(|i| (i + 1..s).map(move |j| vec![i, j]))
                .collect(),
            ProjectionSpec::Groups(g) => (0..s.saturating_sub(g - 1))
                .map(|i| (i..i + g).collect())
                .collect(),
            ProjectionSpec::Blocks(g) => {
                (0..s / g).map(|b| (b * g..(b + 1) * g).collect()).collect()
            }
            ProjectionSpec::List(l) => l.clone(),
        };
        if out.is_empty() {
            return Err(NetError::BadProjection(format!(
                "no projection of {self:?} fits {s} dimensions"
            )));
        }
        for p in &out {
            if p.is_empty() {
                return Err(NetError::BadProjection("an empty projection".into()));
            }
            if let Some(&d) = p.iter().find(|&&d| d >= s) {
                return Err(NetError::NoSuchDimension { dim: d, dims: s });
            }
        }
        Ok(out)
    }
}

#[cfg(test)]
mod bound_tests {
    use super::*;

    #[test]
    fn a_projection_naming_a_dimension_twice_is_refused() {
        let e = "0,0".parse::<ProjectionSpec>().unwrap_err().to_string();
        assert!(e.contains("dimension 0 appears twice in '0,0'"), "{e}");
        let e = "0,1;2,3,2"
            .parse::<ProjectionSpec>()
            .unwrap_err()
            .to_string();
        assert!(e.contains("dimension 2 appears twice"), "{e}");
        assert!(
            "0,1;1,0".parse::<ProjectionSpec>().is_ok(),
            "distinct within each"
        );
    }

    #[test]
    fn expansions_are_counted_before_they_are_built() {
        // 1449 dimensions: 1,049,076 pairs, just past the bound; 1448: 1,047,628, inside.
        assert!(ProjectionSpec::Pairs.expand(1449).is_err());
        assert_eq!(ProjectionSpec::Pairs.expand(1448).unwrap().len(), 1_047_628);
        // Sliding groups bounded by their indices: 8193 windows of 2048 > 2^24.
        assert!(ProjectionSpec::Groups(2048).expand(10_240).is_err());
        assert_eq!(ProjectionSpec::Groups(3).expand(10).unwrap().len(), 8);
        assert_eq!(ProjectionSpec::Blocks(4).expand(10).unwrap().len(), 2);
    }
}
