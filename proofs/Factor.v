(** * T1: every permutation of GF(2)^q factors uniquely as ψ ⊕ B with ψ(0) = 0, B = π(0);
    and AGL(2,2) = S_4, by computation. *)

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

(** Counting corollary: π ↦ (ψ, π(0)) is a bijection from S_b onto (permutations fixing 0) × b
    choices, so b! = b·(b − 1)!, here for b = 2^q. *)
Theorem count_factorization : forall q, fact (2 ^ q) = 2 ^ q * fact (2 ^ q - 1).
Proof.
  intro q. assert (H : 2 ^ q <> 0) by (apply Nat.pow_nonzero; lia).
  destruct (2 ^ q) as [|n] eqn:E; [lia|]. simpl. rewrite Nat.sub_0_r. reflexivity.
Qed.

(** AGL(2,2) = S_4. A digit d in 0..3 has bits (d mod 2, d / 2). *)
Definition bit0 d := Nat.odd d.
Definition bit1 d := Nat.odd (d / 2).
Definition of_bits (b0 b1 : bool) : nat := (if b0 then 1 else 0) + (if b1 then 2 else 0).

(** y = A·x ⊕ u with A = [[a, b], [c, e]] acting on (bit0, bit1). *)
Definition affine (a b c e : bool) (u d : nat) : nat :=
  Nat.lxor (of_bits (xorb (a && bit0 d) (b && bit1 d)) (xorb (c && bit0 d) (e && bit1 d))) u.

Definition bools := [false; true].
Definition invertible (a b c e : bool) := xorb (a && e) (b && c).

Definition agl22 : list (list nat) :=
  flat_map (fun a => flat_map (fun b => flat_map (fun c => flat_map (fun e =>
    if invertible a b c e then map (fun u => map (affine a b c e u) [0; 1; 2; 3]) [0; 1; 2; 3] else [])
  bools) bools) bools) bools.

Fixpoint insert_all (x : nat) (l : list nat) : list (list nat) :=
  match l with
  | [] => [[x]]
  | y :: r => (x :: y :: r) :: map (cons y) (insert_all x r)
  end.

Fixpoint perms (l : list nat) : list (list nat) :=
  match l with
  | [] => [[]]
  | x :: r => flat_map (insert_all x) (perms r)
  end.

Definition list_eqb (x y : list nat) : bool := if list_eq_dec Nat.eq_dec x y then true else false.

Fixpoint nodupb (l : list (list nat)) : bool :=
  match l with
  | [] => true
  | x :: r => negb (existsb (list_eqb x) r) && nodupb r
  end.

(** The 6 invertible matrices times 4 translations give 24 distinct maps, which are exactly the
    24 permutations of {0, 1, 2, 3}. *)
Theorem agl22_is_s4 :
  length agl22 = 24 /\ nodupb agl22 = true /\ length (perms [0; 1; 2; 3]) = 24 /\
  forallb (fun p => existsb (list_eqb p) agl22) (perms [0; 1; 2; 3]) = true /\
  forallb (fun p => existsb (list_eqb p) (perms [0; 1; 2; 3])) agl22 = true.
Proof. vm_compute. repeat split. Qed.
