//! The certificate envelope shared by `gartowen verify`, `check` and `discrepancy`: one
//! versioned JSON schema, so a CI gate can archive and compare any of them.
//!
//! Schema `gartowen-certificate`, version 1 (documented in docs/certificates.md):
//!
//! | field            | meaning                                                              |
//! |------------------|----------------------------------------------------------------------|
//! | `schema`         | always `"gartowen-certificate"`                                      |
//! | `schema_version` | 1; readers reject other versions                                     |
//! | `tool`, `tool_version` | `"gartowen"` and the crate version that wrote it               |
//! | `command`        | `verify`, `check` or `discrepancy`                                   |
//! | `verdict`        | `pass`, `fail` or `measured` (a value with no claim to judge)        |
//! | `parameters`     | the command's settings (level, base, kind, …)                        |
//! | `seeds`          | every seed the command drew randomness from (empty if none)          |
//! | `inputs`         | what was examined: files with a checksum, programs, registry entries |
//! | `result`         | the command's own result object                                      |
//! | `digest`         | `sha256:` and the SHA-256 of the canonical JSON of every other field |
//!
//! No timestamps or host names: the same inputs give byte-identical certificates, except for
//! the wall-time fields inside `result`.
//!
//! ```
//! use gartowen_verify::certificate::{Certificate, CertVerdict};
//! let c = Certificate::new("check", CertVerdict::Pass, serde_json::json!({"base": 2}), vec![],
//!     vec![], serde_json::json!({"t": 0}));
//! let back = Certificate::parse(&c.to_json()).unwrap();
//! assert_eq!(back, c);
//! ```

use serde::{Deserialize, Serialize};
use serde_json::Value;
use std::fmt;

/// The schema name every certificate carries.
pub const SCHEMA: &str = "gartowen-certificate";
/// The schema version this build writes and reads.
pub const SCHEMA_VERSION: u32 = 1;

/// A certificate's overall verdict.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum CertVerdict {
    /// Every judged property holds.
    Pass,
    /// Some judged property fails.
    Fail,
    /// Values only; nothing was judged.
    Measured,
}

/// One examined input: a file (with its checksum), an external program or a registry entry.
#[derive(Debug, Clone, PartialEq, Eq, Serialize, Deserialize)]
pub struct InputRecord {
    /// `file`, `program` or `registry`.
    pub kind: String,
    /// Path, command line or registry request.
    pub name: String,
    /// 64-bit FNV-1a (hex) of the content: the words of a point file, the bytes of a program's
    /// executable where it can be read; absent for registry entries (named by version instead).
    pub checksum_fnv1a64: Option<String>,
    /// Shape and other facts about the input (points, dims, width).
    #[serde(default)]
    pub details: Value,
}

/// The versioned envelope.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Certificate {
    /// Always [`SCHEMA`].
    pub schema: String,
    /// Always [`SCHEMA_VERSION`] when written by this build.
    pub schema_version: u32,
    /// `"gartowen"`.
    pub tool: String,
    /// The writing tool's version.
    pub tool_version: String,
    /// The command that produced it.
    pub command: String,
    /// Overall verdict.
    pub verdict: CertVerdict,
    /// Settings.
    pub parameters: Value,
    /// Seeds used.
    pub seeds: Vec<u64>,
    /// Inputs examined.
    pub inputs: Vec<InputRecord>,
    /// The command's result.
    pub result: Value,
}

/// The prefix of the `digest` field's value.
pub const DIGEST_PREFIX: &str = "sha256:";

/// Why a document is not a certificate this build can read.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum CertificateError {
    /// Not JSON, or fields of the wrong type.
    Malformed(String),
    /// `schema` is not [`SCHEMA`].
    WrongSchema(String),
    /// `schema_version` is not [`SCHEMA_VERSION`].
    UnsupportedVersion(u64),
    /// The document has no `digest` field.
    NoDigest,
    /// The content does not match its `digest`: the file was edited after it was written.
    DigestMismatch {
        /// The digest the file carries.
        recorded: String,
        /// The digest of its content.
        computed: String,
    },
}

impl fmt::Display for CertificateError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            CertificateError::Malformed(e) => write!(f, "not a certificate: {e}"),
            CertificateError::WrongSchema(s) => {
                write!(f, "schema is '{s}', expected '{SCHEMA}'")
            }
            CertificateError::UnsupportedVersion(v) => write!(
                f,
                "schema version {v} is not supported (this build reads {SCHEMA_VERSION})"
            ),
            CertificateError::NoDigest => write!(
                f,
                "digest: missing (every certificate this build writes carries one)"
            ),
            CertificateError::DigestMismatch { recorded, computed } => write!(
                f,
                "digest: the file says {recorded}, its content gives {computed}: it was edited after it was written"
            ),
        }
    }
}

impl std::error::Error for CertificateError {}

impl Certificate {
    /// A certificate from this build for `command`.
    pub fn new(
        command: &str,
        verdict: CertVerdict,
        parameters: Value,
        seeds: Vec<u64>,
        inputs: Vec<InputRecord>,
        result: Value,
    ) -> Certificate {
        Certificate {
            schema: SCHEMA.into(),
            schema_version: SCHEMA_VERSION,
            tool: "gartowen".into(),
            tool_version: env!("CARGO_PKG_VERSION").into(),
            command: command.into(),
            verdict,
            parameters,
            seeds,
            inputs,
            result,
        }
    }

    /// Pretty JSON text, ending with the `digest` field (see [`content_digest`]).
    pub fn to_json(&self) -> String {
        let body = serde_json::to_string_pretty(self).expect("certificates serialize");
        let value = serde_json::to_value(self).expect("certificates serialize");
        let open = body.strip_suffix('}').expect("a JSON object").trim_end();
        format!("{open},\n  \"digest\": \"{}\"\n}}", content_digest(&value))
    }

    /// Parses a certificate, checking the schema name and version before the fields.
    pub fn parse(text: &str) -> Result<Certificate, CertificateError> {
        let v: Value =
            serde_json::from_str(text).map_err(|e| CertificateError::Malformed(e.to_string()))?;
        match v.get("schema").and_then(Value::as_str) {
            Some(SCHEMA) => {}
            Some(other) => return Err(CertificateError::WrongSchema(other.into())),
            None => return Err(CertificateError::WrongSchema("(missing)".into())),
        }
        match v.get("schema_version").and_then(Value::as_u64) {
            Some(n) if n == SCHEMA_VERSION as u64 => {}
            Some(n) => return Err(CertificateError::UnsupportedVersion(n)),
            None => return Err(CertificateError::Malformed("schema_version missing".into())),
        }
        serde_json::from_value(v).map_err(|e| CertificateError::Malformed(e.to_string()))
    }
}

/// The digest of a certificate document: [`DIGEST_PREFIX`] and the SHA-256 (hex) of its
/// canonical JSON (keys sorted, no whitespace, numbers and strings as serde_json writes them)
/// without the `digest` field. It detects a file edited after it was written; anyone can
/// compute it, so it is not a signature.
pub fn content_digest(doc: &Value) -> String {
    let mut text = String::new();
    match doc {
        Value::Object(map) => {
            let mut content = map.clone();
            content.remove("digest");
            canonical(&Value::Object(content), &mut text);
        }
        other => canonical(other, &mut text),
    }
    format!(
        "{DIGEST_PREFIX}{}",
        gartowen_core::sha256::sha256_hex(text.as_bytes())
    )
}

/// Checks that the certificate text carries a `digest` that matches its content.
pub fn check_digest(text: &str) -> Result<(), CertificateError> {
    let doc: Value =
        serde_json::from_str(text).map_err(|e| CertificateError::Malformed(e.to_string()))?;
    let recorded = doc
        .get("digest")
        .and_then(Value::as_str)
        .ok_or(CertificateError::NoDigest)?;
    let computed = content_digest(&doc);
    if recorded != computed {
        return Err(CertificateError::DigestMismatch {
            recorded: recorded.into(),
            computed,
        });
    }
    Ok(())
}

/// Writes `v` as canonical JSON: object keys in byte order, no whitespace.
fn canonical(v: &Value, out: &mut String) {
    match v {
        Value::Object(map) => {
            let mut keys: Vec<&String> = map.keys().collect();
            keys.sort();
            out.push('{');
            for (k, key) in keys.into_iter().enumerate() {
                if k > 0 {
                    out.push(',');
                }
                out.push_str(&Value::String(key.clone()).to_string());
                out.push(':');
                canonical(&map[key], out);
            }
            out.push('}');
        }
        Value::Array(items) => {
            out.push('[');
            for (k, item) in items.iter().enumerate() {
                if k > 0 {
                    out.push(',');
                }
                canonical(item, out);
            }
            out.push(']');
        }
        scalar => out.push_str(&scalar.to_string()),
    }
}

/// 64-bit FNV-1a of a byte string (the checksum certificates use for files and programs).
pub fn fnv1a64(bytes: &[u8]) -> u64 {
    bytes.iter().fold(0xcbf2_9ce4_8422_2325u64, |h, &b| {
        (h ^ b as u64).wrapping_mul(0x0000_0100_0000_01b3)
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use serde_json::json;

    fn sample() -> Certificate {
        Certificate::new(
            "verify",
            CertVerdict::Fail,
            json!({"level": "quick"}),
            vec![0, 7],
            vec![InputRecord {
                kind: "file".into(),
                name: "p.npy".into(),
                checksum_fnv1a64: Some(format!("{:016x}", fnv1a64(b"abc"))),
                details: json!({"points": 4}),
            }],
            json!({"implementations": []}),
        )
    }

    #[test]
    fn round_trips_and_rejects_other_schemas_and_versions() {
        let c = sample();
        assert_eq!(Certificate::parse(&c.to_json()).unwrap(), c);
        let mut v: Value = serde_json::from_str(&c.to_json()).unwrap();
        v["schema_version"] = json!(2);
        assert_eq!(
            Certificate::parse(&v.to_string()),
            Err(CertificateError::UnsupportedVersion(2))
        );
        v["schema_version"] = json!(1);
        v["schema"] = json!("other");
        assert_eq!(
            Certificate::parse(&v.to_string()),
            Err(CertificateError::WrongSchema("other".into()))
        );
        v["schema"] = json!(SCHEMA);
        v["verdict"] = json!("maybe");
        assert!(matches!(
            Certificate::parse(&v.to_string()),
            Err(CertificateError::Malformed(_))
        ));
    }

    #[test]
    fn floats_read_back_bit_for_bit() {
        // Found by the certificate fuzz target: without correctly rounded parsing these read
        // back one ULP off after a write, so a merged certificate drifted from its shards.
        let mut c = sample();
        for text in [
            "0.011111111111111113",
            "1.1111111111111111e33",
            "2.2250738585072014e-308",
        ] {
            let x: f64 = text.parse().unwrap();
            c.result = json!({ "seconds": x });
            let text = c.to_json();
            let back = Certificate::parse(&text).unwrap();
            assert_eq!(
                back.result["seconds"].as_f64().unwrap().to_bits(),
                x.to_bits()
            );
            assert_eq!(back, c);
            assert_eq!(back.to_json(), text);
        }
    }

    #[test]
    fn the_digest_detects_any_edit_and_ignores_layout() {
        let text = sample().to_json();
        assert_eq!(check_digest(&text), Ok(()));
        // The same content, laid out differently (keys reordered, compact): still valid.
        let doc: Value = serde_json::from_str(&text).unwrap();
        let mut keys: Vec<(String, Value)> = doc.as_object().unwrap().clone().into_iter().collect();
        keys.reverse();
        let relaid = format!(
            "{{{}}}",
            keys.iter()
                .map(|(k, v)| format!("{}:{}", Value::String(k.clone()), v))
                .collect::<Vec<_>>()
                .join(",")
        );
        assert_eq!(check_digest(&relaid), Ok(()));
        // One edited value, one added field, one removed field: each detected.
        let edits: [fn(&mut Value); 4] = [
            |d| d["seeds"][1] = json!(8),
            |d| d["result"]["extra"] = json!(true),
            |d| {
                d.as_object_mut().unwrap().remove("inputs");
            },
            |d| d["inputs"][0]["details"]["points"] = json!(4.0),
        ];
        for edit in edits {
            let mut d = doc.clone();
            edit(&mut d);
            assert!(
                matches!(
                    check_digest(&d.to_string()),
                    Err(CertificateError::DigestMismatch { .. })
                ),
                "{d}"
            );
        }
        let mut d = doc.clone();
        d.as_object_mut().unwrap().remove("digest");
        assert_eq!(
            check_digest(&d.to_string()),
            Err(CertificateError::NoDigest)
        );
        // The digest is the SHA-256 of the canonical form: sorted keys, no whitespace.
        assert_eq!(
            content_digest(&json!({"b": [1, 2.5, "x"], "a": {"d": null, "c": false}})),
            format!(
                "sha256:{}",
                gartowen_core::sha256::sha256_hex(br#"{"a":{"c":false,"d":null},"b":[1,2.5,"x"]}"#)
            )
        );
    }

    #[test]
    fn fnv1a64_matches_the_published_test_vectors() {
        // FNV-1a 64 reference values for "" and "a" (Fowler, Noll, Vo).
        assert_eq!(fnv1a64(b""), 0xcbf2_9ce4_8422_2325);
        assert_eq!(fnv1a64(b"a"), 0xaf63_dc4c_8601_ec8c);
    }
}
