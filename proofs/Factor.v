(** * Every permutation of GF(2)^q factors uniquely as ψ ⊕ B with ψ(0) = 0, B = π(0), and π is
    a bijection exactly when ψ is. (The laws built on this, and AGL(q,2) against S_{2^q}, are in
    [NodeLaws.v].) *)

From Coq Require Import List Arith Bool Lia.
Import ListNotations.

Section BooleanGroup.

(** Any commutative group in which every element is its own inverse, such as GF(2)^q under ⊕. *)
Variable A : Type.
Variable xor : A -> A -> A.
Variable zero : A.
Hypothesis xor_assoc : forall x y z, xor x (xor y z) = xor (xor x y) z.
Hypothesis xor_comm : forall x y, xor x y = xor y x.
Hypothesis xor_zero_r : forall x, xor x zero = x.
Hypothesis xor_self : forall x, xor x x = zero.

Definition translation_part (pi : A -> A) : A := pi zero.
Definition linear_part (pi : A -> A) : A -> A := fun x => xor (pi x) (pi zero).

Lemma xor_cancel_r : forall x y, xor (xor x y) y = x.
Proof. intros. rewrite <- xor_assoc, xor_self, xor_zero_r. reflexivity. Qed.

Theorem factorization : forall pi : A -> A,
  linear_part pi zero = zero /\ forall x, pi x = xor (linear_part pi x) (translation_part pi).
Proof.
  intro pi. unfold linear_part, translation_part. split.
  - apply xor_self.
  - intro x. symmetry. apply xor_cancel_r.
Qed.

Theorem factorization_unique : forall (pi psi : A -> A) (B : A),
  psi zero = zero -> (forall x, pi x = xor (psi x) B) ->
  B = translation_part pi /\ forall x, psi x = linear_part pi x.
Proof.
  intros pi psi B H0 H. unfold translation_part, linear_part.
  assert (EB : pi zero = B) by (rewrite H, H0, xor_comm, xor_zero_r; reflexivity).
  split; [auto|]. intro x. rewrite EB, H. symmetry. apply xor_cancel_r.
Qed.

(** π is a bijection exactly when its linear part is. *)
Theorem factorization_bijective : forall pi : A -> A,
  (exists inv, forall x, inv (pi x) = x /\ pi (inv x) = x) <->
  (exists inv, forall x, inv (linear_part pi x) = x /\ linear_part pi (inv x) = x).
Proof.
  intro pi. unfold linear_part. split; intros [inv H].
  - exists (fun y => inv (xor y (pi zero))). intro x. split.
    + rewrite xor_cancel_r. apply H.
    + destruct (H (xor x (pi zero))) as [_ E]. rewrite E. apply xor_cancel_r.
  - exists (fun y => inv (xor y (pi zero))). intro x. split.
    + destruct (H x) as [E _]. exact E.
    + destruct (H (xor x (pi zero))) as [_ E]. rewrite <- (xor_cancel_r (pi (inv (xor x (pi zero)))) (pi zero)).
      rewrite E. apply xor_cancel_r.
Qed.

End BooleanGroup.

(** GF(2)^q as natural numbers under bitwise xor (digits of q bits are closed under it). *)
Theorem factorization_gf2 : forall pi : nat -> nat,
  Nat.lxor (pi 0) (pi 0) = 0 /\ forall x, pi x = Nat.lxor (Nat.lxor (pi x) (pi 0)) (pi 0).
Proof.
  intro pi. destruct (factorization nat Nat.lxor 0
    (fun x y z => eq_sym (Nat.lxor_assoc x y z)) Nat.lxor_0_r Nat.lxor_nilpotent pi) as [A B].
  split; [exact A | exact B].
Qed.
