//! Registry entries of the oracle: `owen-oracle[:uniform|:cyclic|:xor|:affine][:base=B]`.

use crate::{FullTreeOwen, OwenVariant};
use gartowen_core::registry::BuildContext;
use gartowen_core::{CoreError, PowerOfTwoBase, Scrambler, ScramblerRequest, ScramblerSpec};

fn build(req: &ScramblerRequest, ctx: &BuildContext) -> Result<Box<dyn Scrambler>, CoreError> {
    req.allow_only(&["uniform", "cyclic", "xor", "affine", "base"])?;
    let flags: Vec<OwenVariant> = OwenVariant::ALL
        .into_iter()
        .filter(|v| req.flag(v.name()))
        .collect();
    let variant = match flags.as_slice() {
        [] => OwenVariant::Uniform,
        [v] => *v,
        _ => {
            return Err(CoreError::InvalidOption {
                scrambler: req.name.clone(),
                option: "variant".into(),
                reason: "give at most one of uniform, cyclic, xor, affine".into(),
            })
        }
    };
    Ok(Box::new(FullTreeOwen::new(
        req.base_or(ctx.default_base)?,
        variant,
        ctx.seed,
    )))
}

/// The oracle's registry entry.
pub fn specs() -> Vec<ScramblerSpec> {
    vec![ScramblerSpec {
        name: "owen-oracle",
        default_base: PowerOfTwoBase::B2,
        claim: gartowen_core::Claim::OWEN,
        summary: "exact full-tree Owen scramble; options :uniform (default) | :cyclic | :xor | :affine, :base=B",
        build,
    }]
}
