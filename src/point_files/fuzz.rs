//! Fuzzing of the readers: arbitrary and mutated inputs must give a point set or a named
//! error, never a panic, an abort or an allocation the input does not justify.

use super::npy::{npy_declared_shape, read_npy};
use super::text::{read_csv, read_hex};
use super::*;
use proptest::prelude::*;

#[test]
fn signed_hex_words_are_refused() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("signed.hex");
    for (text, ok) in [
        ("00000001 00000002\n", true),
        ("+0000001 00000002\n", false),
        ("00000001 -0000002\n", false),
    ] {
        std::fs::write(&path, text).unwrap();
        match read_points(&path, Some(Format::Hex), FloatWords::Exact).map(|(p, _)| p) {
            Ok(p) => assert!(ok, "{text} was read: {:?}", p.point(0)),
            Err(e) => {
                assert!(!ok, "{text}: {e}");
                assert!(e.to_string().contains("is not hexadecimal"), "{e}");
            }
        }
    }
}

fn npy_header(descr: &str, fortran: bool, shape: &str) -> Vec<u8> {
    let dict = format!(
        "{{'descr': '{descr}', 'fortran_order': {}, 'shape': {shape}, }}",
        if fortran { "True" } else { "False" }
    );
    let mut header = dict.into_bytes();
    while (10 + header.len() + 1) % 64 != 0 {
        header.push(b' ');
    }
    header.push(b'\n');
    let mut out = b"\x93NUMPY\x01\x00".to_vec();
    out.extend_from_slice(&(header.len() as u16).to_le_bytes());
    out.extend_from_slice(&header);
    out
}

fn valid_npy(rows: usize, dims: usize, fortran: bool) -> Vec<u8> {
    let mut out = npy_header("<f8", fortran, &format!("({rows}, {dims})"));
    for k in 0..rows * dims {
        out.extend_from_slice(&((k as f64 + 0.5) / (rows * dims) as f64).to_le_bytes());
    }
    out
}

fn all_readers(bytes: &[u8]) {
    let p = Path::new("fuzz");
    for floats in [FloatWords::Exact, FloatWords::Floor] {
        let sets = [
            read_npy(p, bytes, floats).map(|(s, _)| s),
            read_csv(p, bytes, floats),
            read_hex(p, bytes),
        ];
        for set in sets.into_iter().flatten() {
            assert!(!set.is_empty() && set.dims() >= 1);
        }
    }
}

#[test]
fn deeply_nested_headers_are_refused_at_once() {
    // 23 nested braces took npyz's parser minutes; refused before it is called.
    let mut bytes = npy_header("<f8", false, "(3, 2)");
    let at = bytes.iter().position(|&b| b == b'{').unwrap();
    bytes.splice(at..at, std::iter::repeat_n(b'{', 23));
    let len = (bytes.len() - 10) as u16;
    bytes[8..10].copy_from_slice(&len.to_le_bytes());
    let e = npy_declared_shape(&bytes).unwrap_err();
    assert!(e.contains("nests brackets 25 deep"), "{e}");
    let mut ok = npy_header("<f8", false, "(3, 2)");
    ok.extend_from_slice(&[0u8; 48]);
    assert_eq!(npy_declared_shape(&ok).unwrap().0, vec![3, 2]);
}

#[test]
fn headers_that_claim_more_data_than_the_file_holds_are_refused() {
    // A shape of 2^40 rows over 16 data bytes must be an error, not an attempt to
    // allocate terabytes (npyz checks the data length against the shape; this pins it).
    for shape in [
        "(1099511627776, 1)",
        "(2, 9223372036854775807)",
        "(4611686018427387904,)",
    ] {
        let mut bytes = npy_header("<f8", false, shape);
        bytes.extend_from_slice(&[0u8; 16]);
        let e = read_npy(Path::new("big.npy"), &bytes, FloatWords::Exact).expect_err("refused");
        assert!(e.to_string().contains("big.npy"), "{e}");
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 2000, ..ProptestConfig::default() })]

    #[test]
    fn arbitrary_bytes_never_panic(bytes in proptest::collection::vec(any::<u8>(), 0..256)) {
        all_readers(&bytes);
    }

    #[test]
    fn mutated_npy_files_never_panic(
        rows in 1usize..6, dims in 1usize..4, fortran in any::<bool>(),
        edits in proptest::collection::vec((any::<u16>(), any::<u8>()), 1..6),
        cut in any::<u16>(),
    ) {
        let mut bytes = valid_npy(rows, dims, fortran);
        for (at, v) in edits {
            let i = at as usize % bytes.len();
            bytes[i] = v;
        }
        let keep = bytes.len() - (cut as usize % 8).min(bytes.len());
        bytes.truncate(keep);
        all_readers(&bytes);
    }

    #[test]
    fn text_from_the_format_alphabets_never_panics(
        text in "[0-9a-fA-Fx.,eE+\\- #\\n]{0,200}"
    ) {
        all_readers(text.as_bytes());
    }

    #[test]
    fn valid_files_read_back(rows in 1usize..20, dims in 1usize..5, fortran in any::<bool>()) {
        let (set, floats) =
            read_npy(Path::new("ok.npy"), &valid_npy(rows, dims, fortran), FloatWords::Exact)
                .unwrap();
        prop_assert!(floats);
        prop_assert_eq!((set.len(), set.dims()), (rows, dims));
    }
}
