//! Registry entries of the oracle: `owen-oracle[:uniform|:cyclic|:xor|:affine][:base=B]`, and
//! its form in bases that are not powers of two ([`build_radix`]).

use crate::{FullTreeOwen, OwenVariant, RadixOwen, RadixVariant};
use gartowen_core::registry::BuildContext;
use gartowen_core::{CoreError, PowerOfTwoBase, Radix, Scrambler, ScramblerRequest, ScramblerSpec};

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

/// The base a request asks for when it is not a power of two: its `:base=B` option, else
/// `default` (`--scramble-base`); `None` when that base is a power of two (the registry's
/// entries serve it). Errors name a base that is neither.
pub fn requested_radix(request: &str, default: u64) -> Result<Option<Radix>, CoreError> {
    let req = ScramblerRequest::parse(request)?;
    let b = match req.option("base") {
        None => default,
        Some(text) => text.parse().map_err(|_| CoreError::InvalidOption {
            scrambler: req.name.clone(),
            option: "base".into(),
            reason: format!("'{text}' is not a number"),
        })?,
    };
    if PowerOfTwoBase::from_base(b).is_ok() {
        return Ok(None);
    }
    Radix::new(b).map(Some)
}

/// The built-in scrambler of `request` in base `radix`, a base that is not a power of two:
/// `owen-oracle[:uniform|:cyclic|:per-depth][:base=B]` (B, when given, must be `radix`).
///
/// ```
/// use gartowen_core::{Radix, RadixScrambler};
/// use gartowen_owen::registry::build_radix;
/// let three = Radix::new(3).unwrap();
/// assert_eq!(build_radix("owen-oracle:cyclic", three, 1).unwrap().name(), "owen-oracle:cyclic:base=3");
/// assert!(build_radix("art-owen-2", three, 1).is_err());
/// ```
pub fn build_radix(request: &str, radix: Radix, seed: u64) -> Result<RadixOwen, CoreError> {
    let req = ScramblerRequest::parse(request)?;
    if req.name != "owen-oracle" {
        return Err(CoreError::InvalidOption {
            scrambler: req.name.clone(),
            option: "base".into(),
            reason: format!(
                "only owen-oracle is built in for base {} (a base that is not 2^q)",
                radix.get()
            ),
        });
    }
    req.allow_only(&["uniform", "cyclic", "per-depth", "base"])?;
    if let Some(b) = req.option("base") {
        if b != radix.get().to_string() {
            return Err(CoreError::InvalidOption {
                scrambler: req.name.clone(),
                option: "base".into(),
                reason: format!("base {b} differs from base {}", radix.get()),
            });
        }
    }
    let flags: Vec<RadixVariant> = RadixVariant::ALL
        .into_iter()
        .filter(|v| req.flag(v.name()))
        .collect();
    let variant = match flags.as_slice() {
        [] => RadixVariant::Uniform,
        [v] => *v,
        _ => {
            return Err(CoreError::InvalidOption {
                scrambler: req.name.clone(),
                option: "variant".into(),
                reason: "give at most one of uniform, cyclic, per-depth".into(),
            })
        }
    };
    Ok(RadixOwen::new(radix, variant, seed))
}
