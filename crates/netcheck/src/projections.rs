//! Which projections to check: all pairs, sliding or aligned groups, or an explicit list.

use crate::NetError;
use std::str::FromStr;

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
            list.push(dims);
        }
        Ok(ProjectionSpec::List(list))
    }
}

impl ProjectionSpec {
    /// The projections of an s-dimensional set; errors on dimensions past s or empty lists.
    pub fn expand(&self, s: usize) -> Result<Vec<Vec<usize>>, NetError> {
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
