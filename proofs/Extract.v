(** Extraction of the ART word loop ([ArtWord.art_word]), the nested-scramble action
    ([Nested.scramble]), the box count ([Nested.count]) and the counting net checker
    ([Checker.check_net], [t_value], [check_sequence]) and the rank path's XOR basis
    ([RankBasis.independent]) to OCaml, for the differential tests against the Rust code
    ([tests/extracted_differential.rs], [extracted_checker.rs], [extracted_rank.rs]; driver in
    [extracted/driver.ml]).

    Trusted beyond Coq's extraction: [nat] is OCaml's [int] ([ExtrOcamlNatInt]; every value here
    is far below 2^62). [Nat.lxor] and [Nat.shiftr] are extracted from their Coq definitions (a
    mapping to OCaml's [lxor]/[lsr] was once declared here, on a name the code does not use, so
    it never took effect; it is gone rather than trusted). Words and codes stay in Coq's
    binary [N]. *)

From Coq Require Import Extraction ExtrOcamlBasic ExtrOcamlNatInt NArith.
From Gartowen Require Import Nested Boxes Checker ArtWord RankBasis.

(** The Rust scramble of dimension [j]: [ART_root(x ⊕ A_j) ⊕ D_j] on [W]-bit words. *)
Definition art_word_dim (q W : nat) (child psi : nat -> nat -> nat) (code64 : nat -> N)
  (root : nat) (a d x : N) : N :=
  N.lxor (art_word q W child psi code64 root (N.lxor x a)) d.

Extraction "gartowen_extracted.ml" art_word_dim scramble count
  check_net t_value check_sequence comps digit_value box_of independent
  N.of_nat N.eqb N.lor N.shiftl.
