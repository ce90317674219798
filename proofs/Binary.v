(** * T4: a binary nested scramble of depth q·n is a base-2^q nested scramble of depth n.

    A base-2^q digit is q bits, most significant first ([bits]); [value] reads them back. The
    binary scramble's action on the q bits of a digit, after the bits of the digits above it,
    is the induced base-2^q node map; acting on the concatenated bits equals acting digit by
    digit. *)

From Coq Require Import List Arith Lia.
From Gartowen Require Import Nested.
Import ListNotations.

Fixpoint bits (q d : nat) : list nat :=
  match q with
  | 0 => []
  | S q' => d / 2 ^ q' :: bits q' (d mod 2 ^ q')
  end.

Fixpoint value (l : list nat) : nat :=
  match l with
  | [] => 0
  | a :: r => a * 2 ^ length r + value r
  end.

Lemma bits_length : forall q d, length (bits q d) = q.
Proof. induction q; simpl; auto. Qed.

Lemma value_lt : forall l, valid 2 l -> value l < 2 ^ length l.
Proof.
  induction l as [|a r IH]; intro H; simpl; [lia|].
  inversion H; subst. specialize (IH H3). nia.
Qed.

Lemma bits_valid : forall q d, d < 2 ^ q -> valid 2 (bits q d).
Proof.
  induction q as [|q IH]; intros d H; simpl; constructor.
  - apply Nat.div_lt_upper_bound; [apply Nat.pow_nonzero; lia|]. simpl in H. lia.
  - apply IH, Nat.mod_upper_bound, Nat.pow_nonzero. lia.
Qed.

Lemma value_bits : forall q d, d < 2 ^ q -> value (bits q d) = d.
Proof.
  induction q as [|q IH]; intros d H; simpl in *; [lia|].
  rewrite bits_length, IH by (apply Nat.mod_upper_bound, Nat.pow_nonzero; lia).
  assert (P : 2 ^ q <> 0) by (apply Nat.pow_nonzero; lia).
  pose proof (Nat.div_mod d (2 ^ q) P). lia.
Qed.

Lemma bits_value : forall l, valid 2 l -> bits (length l) (value l) = l.
Proof.
  induction l as [|a r IH]; intro H; simpl; auto.
  inversion H; subst.
  assert (P : 2 ^ length r <> 0) by (apply Nat.pow_nonzero; lia).
  pose proof (value_lt r H3) as L.
  rewrite Nat.div_add_l, Nat.div_small, Nat.add_0_r by auto.
  rewrite Nat.add_comm, Nat.mod_add, Nat.mod_small by auto.
  f_equal. apply IH; auto.
Qed.

Lemma valid_app : forall l1 l2 (c : nat), valid c l1 -> valid c l2 -> valid c (l1 ++ l2).
Proof. intros. apply Forall_app. auto. Qed.

Lemma act_app : forall c S a x pre, act c S pre (a ++ x) = act c S pre a ++ act c S (pre ++ a) x.
Proof.
  induction a as [|d r IH]; intros x pre; simpl.
  - rewrite app_nil_r. reflexivity.
  - f_equal. rewrite IH, <- app_assoc. reflexivity.
Qed.

Definition all_bits (q : nat) (x : list nat) : list nat := concat (map (bits q) x).

Section Induced.

Variable q : nat.
Variable S2 : nested_scramble 2.

(** The induced base-2^q node map at digit prefix P. *)
Definition induced_sigma (P : list nat) (d : nat) : nat := value (act 2 S2 (all_bits q P) (bits q d)).
Definition induced_tau (P : list nat) (e : nat) : nat := value (unact 2 S2 (all_bits q P) (bits q e)).

Lemma induced_lt : forall P d, d < 2 ^ q -> induced_sigma P d < 2 ^ q.
Proof.
  intros P d H. unfold induced_sigma.
  pose proof (value_lt _ (act_valid 2 S2 (bits q d) (all_bits q P) (bits_valid q d H))) as V.
  rewrite act_length, bits_length in V. exact V.
Qed.

Lemma induced_tau_lt : forall P d, d < 2 ^ q -> induced_tau P d < 2 ^ q.
Proof.
  intros P d H. unfold induced_tau.
  pose proof (value_lt _ (unact_valid 2 S2 (bits q d) (all_bits q P) (bits_valid q d H))) as V.
  rewrite unact_length, bits_length in V. exact V.
Qed.

Lemma bits_act : forall P d, d < 2 ^ q ->
  bits q (induced_sigma P d) = act 2 S2 (all_bits q P) (bits q d).
Proof.
  intros P d H. unfold induced_sigma.
  pose proof (bits_value _ (act_valid 2 S2 (bits q d) (all_bits q P) (bits_valid q d H))) as B.
  rewrite act_length, bits_length in B. exact B.
Qed.

Lemma bits_unact : forall P d, d < 2 ^ q ->
  bits q (induced_tau P d) = unact 2 S2 (all_bits q P) (bits q d).
Proof.
  intros P d H. unfold induced_tau.
  pose proof (bits_value _ (unact_valid 2 S2 (bits q d) (all_bits q P) (bits_valid q d H))) as B.
  rewrite unact_length, bits_length in B. exact B.
Qed.

Definition induced : nested_scramble (2 ^ q).
Proof.
  refine {| sigma := induced_sigma; tau := induced_tau |}.
  - apply induced_lt.
  - apply induced_tau_lt.
  - intros p d H. unfold induced_tau at 1. rewrite bits_act by auto.
    rewrite unact_act by (apply bits_valid; auto). apply value_bits; auto.
  - intros p d H. unfold induced_sigma at 1. rewrite bits_unact by auto.
    rewrite act_unact by (apply bits_valid; auto). apply value_bits; auto.
Defined.

Lemma all_bits_app : forall P D, all_bits q (P ++ [D]) = all_bits q P ++ bits q D.
Proof. intros. unfold all_bits. rewrite map_app, concat_app. simpl. rewrite app_nil_r. reflexivity. Qed.

Lemma binary_action_is_digitwise : forall x P,
  valid (2 ^ q) x ->
  act 2 S2 (all_bits q P) (all_bits q x) = all_bits q (act (2 ^ q) induced P x).
Proof.
  induction x as [|d r IH]; intros P H; [reflexivity|].
  inversion H; subst.
  change (all_bits q (d :: r)) with (bits q d ++ all_bits q r).
  change (act (2 ^ q) induced P (d :: r)) with (induced_sigma P d :: act (2 ^ q) induced (P ++ [d]) r).
  change (all_bits q (induced_sigma P d :: act (2 ^ q) induced (P ++ [d]) r))
    with (bits q (induced_sigma P d) ++ all_bits q (act (2 ^ q) induced (P ++ [d]) r)).
  rewrite act_app, bits_act by auto. f_equal.
  rewrite <- all_bits_app. apply IH. auto.
Qed.

(** T4: acting with the binary nested scramble on the q·n bits of n base-2^q digits is the
    base-2^q nested scramble [induced] acting on the digits. *)
Theorem binary_is_base_2q_nested : forall x,
  valid (2 ^ q) x -> scramble 2 S2 (all_bits q x) = all_bits q (scramble (2 ^ q) induced x).
Proof. intros x H. apply (binary_action_is_digitwise x [] H). Qed.

End Induced.
