(** * T3: the ART-Owen loop (docs/design.md §3.3) defines a nested scramble, for any child table, any
    ψ table, any translation codes and any root.

    The loop keeps a symbol [s] and pending translations [F j] for the digit [j] levels below
    the current one. At each digit it merges the symbol's code into [F], outputs
    ψ_s(x_k) translated by [F 0], moves to [child s x_k] (by the ORIGINAL digit) and shifts [F].
    Translations act on digits through [add] with inverse [sub] (⊕ on q-bit digits is one such
    action); [comb] merges translations (⊕ of codes). *)

From Coq Require Import List Arith Lia.
From Gartowen Require Import Nested.
Import ListNotations.

Section ArtOwen.

Variable b : nat.
Variable add sub comb : nat -> nat -> nat.
Hypothesis add_lt : forall d u, d < b -> add d u < b.
Hypothesis sub_lt : forall d u, d < b -> sub d u < b.
Hypothesis sub_add : forall d u, d < b -> sub (add d u) u = d.
Hypothesis add_sub : forall d u, d < b -> add (sub d u) u = d.

Variable child : nat -> nat -> nat.
Variable psi psi_inv : nat -> nat -> nat.
Hypothesis psi_lt : forall s d, d < b -> psi s d < b.
Hypothesis psi_inv_lt : forall s d, d < b -> psi_inv s d < b.
Hypothesis psi_inv_psi : forall s d, d < b -> psi_inv s (psi s d) = d.
Hypothesis psi_psi_inv : forall s d, d < b -> psi s (psi_inv s d) = d.
Variable code : nat -> nat -> nat.

(** The loop of docs/design.md §3.3. *)
Fixpoint art (s : nat) (F : nat -> nat) (x : list nat) : list nat :=
  match x with
  | [] => []
  | d :: r =>
      let F' := fun j => comb (F j) (code s j) in
      add (psi s d) (F' 0) :: art (child s d) (fun j => F' (S j)) r
  end.

(** The loop's state after reading a prefix. *)
Fixpoint state (s : nat) (F : nat -> nat) (pre : list nat) : nat * (nat -> nat) :=
  match pre with
  | [] => (s, F)
  | d :: r => state (child s d) (fun j => comb (F (S j)) (code s (S j))) r
  end.

Lemma state_app : forall pre s F d,
  state s F (pre ++ [d]) =
  (child (fst (state s F pre)) d,
   fun j => comb (snd (state s F pre) (S j)) (code (fst (state s F pre)) (S j))).
Proof. induction pre as [|a r IH]; intros s F d; simpl; auto. Qed.

(** The node permutation at a prefix: ψ of the node's symbol, then its translation. *)
Definition node_sigma (s0 : nat) (F0 : nat -> nat) (pre : list nat) (d : nat) : nat :=
  let st := state s0 F0 pre in add (psi (fst st) d) (comb (snd st 0) (code (fst st) 0)).

Definition node_tau (s0 : nat) (F0 : nat -> nat) (pre : list nat) (e : nat) : nat :=
  let st := state s0 F0 pre in psi_inv (fst st) (sub e (comb (snd st 0) (code (fst st) 0))).

Definition art_scramble (s0 : nat) (F0 : nat -> nat) : nested_scramble b.
Proof.
  refine {| sigma := node_sigma s0 F0; tau := node_tau s0 F0 |}; intros p d H; unfold node_sigma, node_tau.
  - apply add_lt, psi_lt, H.
  - apply psi_inv_lt, sub_lt, H.
  - rewrite sub_add by (apply psi_lt, H). apply psi_inv_psi, H.
  - rewrite psi_psi_inv by (apply sub_lt, H). apply add_sub, H.
Defined.

Lemma art_from_prefix : forall s0 F0 x pre,
  art (fst (state s0 F0 pre)) (snd (state s0 F0 pre)) x = act b (art_scramble s0 F0) pre x.
Proof.
  intros s0 F0 x. induction x as [|d r IH]; intro pre; simpl; auto.
  f_equal. rewrite <- IH, state_app. reflexivity.
Qed.

(** T3: the ART-Owen loop from root [s0] is the action of the nested scramble [art_scramble]:
    every node's map is ψ_symbol followed by a translation, a bijection of the digits. *)
Theorem art_is_nested_scramble : forall s0 F0 x,
  art s0 F0 x = scramble b (art_scramble s0 F0) x.
Proof. intros s0 F0 x. exact (art_from_prefix s0 F0 x []). Qed.

(** Hence ART-Owen scrambling, one root per dimension, preserves nets and sequences (T2). *)
Theorem art_preserves_nets : forall (root : nat -> nat) F0 n m t s Ps,
  is_net b n m t s Ps -> is_net b n m t s (map (scr_from b (fun j => art_scramble (root j) F0) 0) Ps).
Proof. intros. apply net_preserved. assumption. Qed.

End ArtOwen.
