(** * The error-free transformations of the compensated discrepancy, exact in binary64.

    The model is Flocq's: binary64 is the format FLT(emin = −1074, prec = 53) with rounding to
    nearest, ties to even. It has no overflow; IEEE binary64 arithmetic equals this rounding
    whenever a result is finite (Flocq's [Bplus_correct], [Bmult_correct]), which the Rust code
    checks ([crates/discrepancy/src/dd.rs], [compensated.rs]). Each definition below is the
    Rust function of [dd.rs] operation for operation, every operation rounded:
    - [two_sum] (Knuth): [s + e = a + b] exactly, for any two doubles;
    - [quick_two_sum] (Dekker's Fast2Sum): [s + e = a + b] when [|b| <= |a|];
    - [split] (Veltkamp, constant 2^27 + 1) and [two_prod] (Dekker, no FMA): [p + e = a·b]
      when the product is 0 or at least 2^-969 in magnitude (no underflow);
    - [add_error]: one rounded addition of doubles errs by at most 2^-53 of the exact sum
      (subnormal sums are exact), the rounding fact a double-double error analysis rests on.

    Axioms: Flocq's real numbers are Coq's classical reals, so [Print Assumptions] lists the
    standard axioms of [Coq.Reals] (see README.md); nothing else. *)

From Coq Require Import Reals Psatz ZArith.
From Flocq Require Import Core Plus_error Relative Pff2Flocq.
Open Scope R_scope.

Definition prec : Z := 53.
Definition emin : Z := -1074.
Global Instance prec_gt_0 : Prec_gt_0 prec.
Proof. unfold Prec_gt_0, prec. lia. Qed.

Definition fmt (x : R) : Prop := generic_format radix2 (FLT_exp emin prec) x.
Definition choice (n : Z) : bool := negb (Z.even n).
Definition rnd (x : R) : R := round radix2 (FLT_exp emin prec) (Znearest choice) x.

Lemma choice_sym : forall x, choice x = negb (choice (- (x + 1))).
Proof.
  intro x. unfold choice. rewrite Z.even_opp. change (x + 1)%Z with (Z.succ x).
  rewrite Z.even_succ, <- Z.negb_even, Bool.negb_involutive. reflexivity.
Qed.

Lemma prec_gt_1 : (1 < prec)%Z.
Proof. unfold prec. lia. Qed.

Lemma emin_le_0 : (emin <= 0)%Z.
Proof. unfold emin. lia. Qed.

Lemma rnd_opp : forall x, rnd (- x) = - rnd x.
Proof. intro x. apply (round_N_opp_sym emin prec choice choice_sym). Qed.

(** Rust: [let s = a + b; let bb = s - a; (s, (a - (s - bb)) + (b - bb))]. *)
Definition two_sum (a b : R) : R * R :=
  let s := rnd (a + b) in
  let bb := rnd (s - a) in
  (s, rnd (rnd (a - rnd (s - bb)) + rnd (b - bb))).

Theorem two_sum_exact : forall a b, fmt a -> fmt b ->
  fst (two_sum a b) + snd (two_sum a b) = a + b.
Proof.
  intros a b Fa Fb. unfold two_sum, rnd. cbn [fst snd].
  exact (TwoSum_correct emin prec choice prec_gt_1 emin_le_0 choice_sym a b Fa Fb).
Qed.

(** Rust: [let s = a + b; (s, b - (s - a))]. *)
Definition quick_two_sum (a b : R) : R * R :=
  let s := rnd (a + b) in (s, rnd (b - rnd (s - a))).

Theorem quick_two_sum_exact : forall a b, fmt a -> fmt b -> Rabs b <= Rabs a ->
  fst (quick_two_sum a b) + snd (quick_two_sum a b) = a + b.
Proof.
  intros a b Fa Fb H. unfold quick_two_sum. cbn [fst snd].
  replace (rnd (b - rnd (rnd (a + b) - a))) with (rnd (b + rnd (a - rnd (a + b)))).
  - exact (Fast2Sum_correct emin prec choice prec_gt_1 emin_le_0 choice_sym a b Fa Fb H).
  - f_equal. replace (a - rnd (a + b)) with (- (rnd (a + b) - a)) by ring.
    rewrite rnd_opp. ring.
Qed.

(** Rust: [let t = 134_217_729.0 * a; let hi = t - (t - a); (hi, a - hi)]. *)
Definition split (a : R) : R * R :=
  let t := rnd (a * (bpow radix2 27 + 1)) in
  let hi := rnd (t - rnd (t - a)) in
  (hi, rnd (a - hi)).

(** Rust: [let p = a * b; (p, ((ah * bh - p) + ah * bl + al * bh) + al * bl)]. *)
Definition two_prod (a b : R) : R * R :=
  let p := rnd (a * b) in
  let ah := fst (split a) in let al := snd (split a) in
  let bh := fst (split b) in let bl := snd (split b) in
  (p, rnd (rnd (rnd (rnd (rnd (ah * bh) - p) + rnd (ah * bl)) + rnd (al * bh)) + rnd (al * bl))).

Lemma split_hi : forall a,
  fst (split a) = rnd (rnd (a - rnd (a * (bpow radix2 27 + 1))) + rnd (a * (bpow radix2 27 + 1))).
Proof.
  intro a. unfold split. cbn [fst snd]. f_equal.
  replace (rnd (a * (bpow radix2 27 + 1)) - a) with (- (a - rnd (a * (bpow radix2 27 + 1)))) by ring.
  rewrite rnd_opp. ring.
Qed.

Lemma split_lo : forall a, snd (split a) = rnd (a - fst (split a)).
Proof. reflexivity. Qed.

Theorem two_prod_exact : forall a b, fmt a -> fmt b ->
  (a * b = 0 \/ bpow radix2 (-969) <= Rabs (a * b)) ->
  fst (two_prod a b) + snd (two_prod a b) = a * b.
Proof.
  intros a b Fa Fb H.
  assert (P4 : (4 <= prec)%Z) by (unfold prec; lia).
  assert (E0 : (emin < 0)%Z) by (unfold emin; lia).
  destruct (Dekker radix2 emin prec choice P4 E0 a b Fa Fb (or_introl eq_refl)) as [D _].
  unfold two_prod. cbn [fst snd].
  rewrite !split_lo, !split_hi.
  replace (rnd (rnd (rnd (a - rnd (a * (bpow radix2 27 + 1))) + rnd (a * (bpow radix2 27 + 1))) *
                rnd (rnd (b - rnd (b * (bpow radix2 27 + 1))) + rnd (b * (bpow radix2 27 + 1))))
             - rnd (a * b))
    with (- rnd (a * b) +
          rnd (rnd (rnd (a - rnd (a * (bpow radix2 27 + 1))) + rnd (a * (bpow radix2 27 + 1))) *
               rnd (rnd (b - rnd (b * (bpow radix2 27 + 1))) + rnd (b * (bpow radix2 27 + 1)))))
    by ring.
  symmetry. apply D. exact H.
Qed.

(** One rounded addition of two doubles: |rnd(x + y) − (x + y)| ≤ 2^-53 · |x + y|. *)
Theorem add_error : forall x y, fmt x -> fmt y ->
  Rabs (rnd (x + y) - (x + y)) <= bpow radix2 (-53) * Rabs (x + y).
Proof.
  intros x y Fx Fy.
  destruct (Rle_or_lt (bpow radix2 (emin + prec - 1)) (Rabs (x + y))) as [Big|Small].
  - eapply Rle_trans; [apply (relative_error_N_FLT radix2 emin prec prec_gt_0 choice (x + y) Big)|].
    right. unfold prec. change (-53 + 1)%Z with (-52)%Z.
    replace (bpow radix2 (-53)) with (/ 2 * bpow radix2 (-52)); [reflexivity|].
    change (-53)%Z with (-1 + -52)%Z. rewrite bpow_plus. f_equal.
  - unfold rnd. rewrite round_generic.
    + rewrite Rminus_eq_0, Rabs_R0. apply Rmult_le_pos; [apply bpow_ge_0|apply Rabs_pos].
    + apply valid_rnd_N.
    + apply FLT_format_plus_small; try assumption; auto with typeclass_instances.
      left. eapply Rlt_le_trans; [exact Small|]. apply bpow_le. unfold emin, prec. lia.
Qed.
