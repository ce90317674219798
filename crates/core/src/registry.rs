//! The registry: one list of every scrambler by name, so that every cross-check runs over
//! every implementation. Crates contribute [`ScramblerSpec`]s; the `gartowen` facade
//! assembles the full registry.

use crate::{Claim, CoreError, Identity, PowerOfTwoBase, Scrambler};

/// A parsed scrambler request `NAME[:OPTION[:OPTION…]]`, where an option is `key=value` or a
/// bare word (e.g. `owen-oracle:xor`, `art-owen-16p:table=256`).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct ScramblerRequest {
    /// The registry name.
    pub name: String,
    /// Options in order: `(key, Some(value))` or `(word, None)`.
    pub options: Vec<(String, Option<String>)>,
}

impl ScramblerRequest {
    /// Parses `NAME[:OPTION…]`.
    ///
    /// ```
    /// use gartowen_core::ScramblerRequest;
    /// let r = ScramblerRequest::parse("art-owen-16p:table=256").unwrap();
    /// assert_eq!(r.name, "art-owen-16p");
    /// assert_eq!(r.option("table"), Some("256"));
    /// // An option given twice is refused rather than letting the last one win.
    /// assert!(ScramblerRequest::parse("owen-oracle:base=4:base=8").is_err());
    /// ```
    pub fn parse(text: &str) -> Result<Self, CoreError> {
        let mut parts = text.split(':');
        let name = parts.next().unwrap_or("").trim().to_string();
        if name.is_empty() {
            return Err(CoreError::UnknownScrambler {
                name: text.to_string(),
                known: vec![],
            });
        }
        let mut options = Vec::new();
        for part in parts {
            let (k, v) = match part.split_once('=') {
                Some((k, v)) => (k.trim().to_string(), Some(v.trim().to_string())),
                None => (part.trim().to_string(), None),
            };
            if k.is_empty() {
                return Err(CoreError::InvalidOption {
                    scrambler: name,
                    option: part.to_string(),
                    reason: "empty option".into(),
                });
            }
            if options.iter().any(|(seen, _)| *seen == k) {
                return Err(CoreError::InvalidOption {
                    scrambler: name,
                    option: k,
                    reason: "given twice".into(),
                });
            }
            options.push((k, v));
        }
        Ok(ScramblerRequest { name, options })
    }

    /// The value of option `key=value`, if given.
    pub fn option(&self, key: &str) -> Option<&str> {
        self.options
            .iter()
            .find(|(k, v)| k == key && v.is_some())
            .and_then(|(_, v)| v.as_deref())
    }

    /// Whether the bare-word option `word` is present.
    pub fn flag(&self, word: &str) -> bool {
        self.options.iter().any(|(k, v)| k == word && v.is_none())
    }

    /// Errors on any option outside `allowed` (keys and bare words alike).
    pub fn allow_only(&self, allowed: &[&str]) -> Result<(), CoreError> {
        for (k, _) in &self.options {
            if !allowed.contains(&k.as_str()) {
                return Err(CoreError::InvalidOption {
                    scrambler: self.name.clone(),
                    option: k.clone(),
                    reason: if allowed.is_empty() {
                        "this scrambler takes no options".into()
                    } else {
                        format!("expected one of: {}", allowed.join(", "))
                    },
                });
            }
        }
        Ok(())
    }
}

/// What a constructor gets besides the request: the seed, and the base to use when the
/// scrambler takes one and the request does not say (the sequence's own base).
#[derive(Debug, Clone, Copy)]
pub struct BuildContext {
    /// The seed.
    pub seed: u64,
    /// Base for scramblers whose base is a parameter (`:base=B` overrides it).
    pub default_base: PowerOfTwoBase,
}

/// How to build a scrambler from a request and its context.
pub type BuildFn = fn(&ScramblerRequest, &BuildContext) -> Result<Box<dyn Scrambler>, CoreError>;

/// A registry entry: name, what it is, and how to build it.
#[derive(Clone)]
pub struct ScramblerSpec {
    /// Kebab-case name used on the command line.
    pub name: &'static str,
    /// Its base when built without options (options such as `:base=` may change it).
    pub default_base: PowerOfTwoBase,
    /// What it claims when built without options (options such as `:xor` may change it).
    pub claim: Claim,
    /// One line on what it is; options are listed here too.
    pub summary: &'static str,
    /// The constructor.
    pub build: BuildFn,
}

/// An ordered list of scrambler specs, looked up by name.
#[derive(Clone, Default)]
pub struct Registry {
    specs: Vec<ScramblerSpec>,
}

fn build_identity(
    req: &ScramblerRequest,
    _ctx: &BuildContext,
) -> Result<Box<dyn Scrambler>, CoreError> {
    req.allow_only(&[])?;
    Ok(Box::new(Identity))
}

impl Registry {
    /// A registry with the core's own entry: `none` (the identity, unscrambled reference).
    pub fn with_core() -> Self {
        let mut r = Registry::default();
        r.add(ScramblerSpec {
            name: "none",
            default_base: PowerOfTwoBase::B2,
            claim: Claim::NESTED,
            summary: "identity (unscrambled reference)",
            build: build_identity,
        });
        r
    }

    /// Adds an entry. Panics on a duplicate name: a registry bug, not an input error.
    pub fn add(&mut self, spec: ScramblerSpec) {
        assert!(
            self.get(spec.name).is_none(),
            "duplicate scrambler name {}",
            spec.name
        );
        self.specs.push(spec);
    }

    /// The entries in registration order.
    pub fn specs(&self) -> &[ScramblerSpec] {
        &self.specs
    }

    /// The entry called `name`.
    pub fn get(&self, name: &str) -> Option<&ScramblerSpec> {
        self.specs.iter().find(|s| s.name == name)
    }

    /// Builds the scrambler described by `request` (`NAME[:OPTION…]`) with `seed`, in base 2
    /// where the base is a parameter.
    pub fn build(&self, request: &str, seed: u64) -> Result<Box<dyn Scrambler>, CoreError> {
        self.build_with(
            request,
            &BuildContext {
                seed,
                default_base: PowerOfTwoBase::B2,
            },
        )
    }

    /// Builds the scrambler described by `request` in the given context.
    pub fn build_with(
        &self,
        request: &str,
        ctx: &BuildContext,
    ) -> Result<Box<dyn Scrambler>, CoreError> {
        let req = ScramblerRequest::parse(request)?;
        let spec = self
            .get(&req.name)
            .ok_or_else(|| CoreError::UnknownScrambler {
                name: req.name.clone(),
                known: self.specs.iter().map(|s| s.name.to_string()).collect(),
            })?;
        (spec.build)(&req, ctx)
    }
}

impl ScramblerRequest {
    /// The `base=B` option as a power-of-two base, or `default` when absent.
    pub fn base_or(&self, default: PowerOfTwoBase) -> Result<PowerOfTwoBase, CoreError> {
        match self.option("base") {
            None => Ok(default),
            Some(text) => {
                let b: u64 = text.parse().map_err(|_| CoreError::InvalidOption {
                    scrambler: self.name.clone(),
                    option: "base".into(),
                    reason: format!("'{text}' is not a number"),
                })?;
                PowerOfTwoBase::from_base(b)
            }
        }
    }
}
