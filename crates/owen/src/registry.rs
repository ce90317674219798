//! Registry entries of the oracle: `owen-oracle[:uniform|:cyclic|:xor|:affine][:base=B]`, and
//! its form in bases that are not powers of two ([`build_radix`]).

use crate::{FullTreeOwen, OwenVariant, RadixOwen, RadixVariant};
use gartowen_core::registry::BuildContext;
use gartowen_core::{CoreError, PowerOfTwoBase, Radix, Scrambler, ScramblerRequest, ScramblerSpec};

/// The variant flag of `req` among `all` (named by `name`), the first of `all` (uniform) when
/// none is given; two flags are refused.
fn one_variant<V: Copy>(
    req: &ScramblerRequest,
    all: &[V],
    name: fn(V) -> &'static str,
) -> Result<V, CoreError> {
    let flags: Vec<V> = all.iter().copied().filter(|&v| req.flag(name(v))).collect();
    match flags.as_slice() {
        [] => Ok(all[0]),
        [v] => Ok(*v),
        _ => Err(CoreError::InvalidOption {
            scrambler: req.name.clone(),
            option: "variant".into(),
            reason: format!(
                "give at most one of {}",
                all.iter().map(|&v| name(v)).collect::<Vec<_>>().join(", ")
            ),
        }),
    }
}

fn build(req: &ScramblerRequest, ctx: &BuildContext) -> Result<Box<dyn Scrambler>, CoreError> {
    req.allow_only(&["uniform", "cyclic", "xor", "affine", "base"])?;
    let variant = one_variant(req, &OwenVariant::ALL, OwenVariant::name)?;
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
        summary: "exact full-tree Owen scramble; options :uniform (default) | :cyclic | :xor | :affine, :base=B (B = 2^q; any other B ≥ 3 takes :uniform | :cyclic | :per-depth)",
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
    let variant = one_variant(&req, &RadixVariant::ALL, RadixVariant::name)?;
    Ok(RadixOwen::new(radix, variant, seed))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn variants_are_one_flag_and_the_base_must_agree() {
        let three = Radix::new(3).unwrap();
        let two = build_radix("owen-oracle:cyclic:per-depth", three, 0).unwrap_err();
        assert!(two
            .to_string()
            .ends_with("give at most one of uniform, cyclic, per-depth"));
        let base = build_radix("owen-oracle:base=5", three, 0).unwrap_err();
        assert!(
            base.to_string().contains("base 5 differs from base 3"),
            "{base}"
        );
        let per_depth = build_radix("owen-oracle:per-depth:base=3", three, 0).unwrap();
        assert_eq!(per_depth.variant(), RadixVariant::PerDepth);
        assert_eq!(
            build_radix("owen-oracle", three, 0).unwrap().variant(),
            RadixVariant::Uniform
        );
        assert_eq!(
            requested_radix("owen-oracle:base=6", 2).unwrap(),
            Radix::new(6).ok()
        );
        assert_eq!(requested_radix("owen-oracle:base=8", 3).unwrap(), None);
        assert_eq!(
            requested_radix("owen-oracle", 7).unwrap(),
            Radix::new(7).ok()
        );
        assert!(requested_radix("owen-oracle:base=x", 2).is_err());
        assert!(requested_radix("owen-oracle:base=1", 2).is_err());
        let ctx = BuildContext {
            seed: 0,
            default_base: PowerOfTwoBase::B2,
        };
        let req = ScramblerRequest::parse("owen-oracle:xor:affine").unwrap();
        let e = build(&req, &ctx).err().unwrap().to_string();
        assert!(
            e.ends_with("give at most one of uniform, cyclic, xor, affine"),
            "{e}"
        );
    }
}
