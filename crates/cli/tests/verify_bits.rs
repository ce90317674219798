//! `verify --bits K`: a program that scrambles only the top K bits (the C example built with
//! -DSCRAMBLED_BITS=K keeps the input's lower bits) fails as a 32-bit Owen scramble, passes
//! when judged on its top K bits, fails again when asked for more bits than it scrambles, and
//! impossible K exit 2.

use crate::support::{build_c_example, gartowen};

fn verify(program: &str, extra: &[&str]) -> (i32, String, String) {
    let out = gartowen(&[&["verify", "--external", program, "--base", "2"][..], extra].concat());
    (
        out.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

#[test]
fn a_twelve_bit_scrambler_passes_on_its_top_twelve_bits_only() {
    let dir = tempfile::tempdir().unwrap();
    let twelve = build_c_example(dir.path(), "owen_per_bit", &["-DSCRAMBLED_BITS=12"]);
    let (code, out, err) = verify(&twelve, &[]);
    assert_eq!(code, 1, "{out}{err}");
    assert!(out.contains("FAIL node-law"), "{out}");
    let (code, out, err) = verify(&twelve, &["--bits", "12"]);
    assert_eq!(code, 0, "{out}{err}");
    assert!(out.contains("(top 12 bits)"), "{out}");
    // Twelve depths are tested, no more.
    assert!(out.contains("node-law ............  "), "{out}");
    let (code, out, _) = verify(&twelve, &["--bits", "16"]);
    assert_eq!(code, 1, "{out}");
    let (code, out, err) = verify(&twelve, &["--bits", "12", "--width", "64"]);
    assert_eq!(code, 0, "{out}{err}");
    for (bits, fragment) in [("0", "between 1"), ("33", "word width 32")] {
        let (code, _, err) = verify(&twelve, &["--bits", bits]);
        assert_eq!(code, 2, "{err}");
        assert!(err.contains(fragment), "{err}");
    }
    let (code, _, err) = verify(&twelve, &["--bits", "12", "--expect", "owen-per-bit-hash"]);
    assert_eq!(code, 2, "{err}");
}
