(** Extraction to OCaml of the ART word loop ([ArtWord.art_word]), the nested-scramble action
    ([Nested.scramble]), the box count ([Nested.count]), the counting net checker
    ([Checker.check_net], [t_value], [check_sequence]) and the rank path's XOR basis
    ([RankBasis.independent]), for the differential tests against the Rust code
    ([tests/extracted_differential.rs], [extracted_checker.rs], [extracted_rank.rs]; driver in
    [extracted/driver.ml]); and of the witness re-check ([Witness.revalidate], run on the
    files of [gartowen check --witness] by [extracted/revalidate.ml]).

    Trusted beyond Coq's extraction: [nat] is OCaml's [int] ([ExtrOcamlNatInt]; every value here
    is far below 2^62). [Nat.lxor] and [Nat.shiftr] are extracted from their Coq definitions (a
    mapping to OCaml's [lxor]/[lsr] was once declared here, on a name the code does not use, so
    it never took effect; it is gone rather than trusted). Words and codes stay in Coq's
    binary [N].

    Also trusted: [Nat.add], [Nat.mul], [Nat.sub], [Nat.div], [Nat.modulo], [Nat.ltb] and
    [Nat.leb] are OCaml's [+], [*], truncated [-], [/], [mod], [<] and [<=] (with Coq's answers
    at a zero divisor: [n / 0 = 0], [n mod 0 = n]). Extracted from their Coq definitions they
    take time (and stack) linear in the value, which the re-checker of [Witness.v] cannot
    afford on 2^16 points of 32-bit words. *)

From Coq Require Import Extraction ExtrOcamlBasic ExtrOcamlNatInt NArith.
From Gartowen Require Import Nested Boxes Checker ArtWord RankBasis Witness.

(* Both names of each: Coq.Init.Nat's and the alias the theories use (PeanoNat.Nat's). *)
Extract Inlined Constant Coq.Init.Nat.add => "(+)".
Extract Inlined Constant Coq.Init.Nat.mul => "( * )".
Extract Constant Coq.Init.Nat.sub => "fun n m -> Stdlib.max 0 (n - m)".
Extract Inlined Constant Coq.Init.Nat.ltb => "(<)".
Extract Inlined Constant Coq.Init.Nat.leb => "(<=)".
Extract Constant Coq.Init.Nat.div => "fun n m -> if m = 0 then 0 else n / m".
Extract Constant Coq.Init.Nat.modulo => "fun n m -> if m = 0 then n else n mod m".
Extract Inlined Constant Coq.Arith.PeanoNat.Nat.add => "(+)".
Extract Inlined Constant Coq.Arith.PeanoNat.Nat.mul => "( * )".
Extract Constant Coq.Arith.PeanoNat.Nat.sub => "fun n m -> Stdlib.max 0 (n - m)".
Extract Inlined Constant Coq.Arith.PeanoNat.Nat.ltb => "(<)".
Extract Inlined Constant Coq.Arith.PeanoNat.Nat.leb => "(<=)".
Extract Constant Coq.Arith.PeanoNat.Nat.div => "fun n m -> if m = 0 then 0 else n / m".
Extract Constant Coq.Arith.PeanoNat.Nat.modulo => "fun n m -> if m = 0 then n else n mod m".

(** The Rust scramble of dimension [j]: [ART_root(x ⊕ A_j) ⊕ D_j] on [W]-bit words. *)
Definition art_word_dim (q W : nat) (child psi : nat -> nat -> nat) (code64 : nat -> N)
  (root : nat) (a d x : N) : N :=
  N.lxor (art_word q W child psi code64 root (N.lxor x a)) d.

Extraction "gartowen_extracted.ml" art_word_dim scramble count
  check_net t_value check_sequence comps digit_value box_of independent
  N.of_nat N.eqb N.lor N.shiftl revalidate.
