(** * AGL(q,2) and Owen's pair lemma: the reduction to GL(q,2) for every q, and q = 4.

    The matrix variants' node law is [art_law q H] with [H] linear (GL(q,2)): ψ, then a
    uniform translation. [affine_pair_count]: for every q and any list [H] of linear maps, the
    number of node maps sending the distinct digits (d, d') to the distinct digits (e, e') is
    the number of [h] in [H] with [h (d ⊕ d') = e ⊕ e'] (the translation is then fixed). So the
    law is uniformly 2-transitive, and [Laws.pair_lemma] holds for trees of such nodes, exactly
    when [H] sends every nonzero digit to every nonzero digit equally often
    ([affine_two_transitive]). For GL(q,2) that is the transitivity of GL on nonzero vectors,
    computed here for q = 4 (GL(4,2): 20,160 maps; [agl4_two_transitive], so art-owen-m4's node
    law); q ≤ 3 is in [NodeLaws.v] (S_4 = AGL(2,2), AGL(3,2)). For every q the count is
    proved in [GLTransitive.v] ([agl_two_transitive]). *)

From Coq Require Import List Arith Bool Lia.
From Gartowen Require Import Laws ArtWord NodeLaws Symmetric ArtMarginal.
Import ListNotations.

(* GL(4,2)'s size is written as a literal; Coq warns that it builds it with of_num_uint. *)
Set Warnings "-abstract-large-number".

(** Any identity of ⊕ over a few variables, bit by bit. *)
Ltac xor_bits :=
  apply Nat.bits_inj; let i := fresh "i" in intro i; rewrite ?Nat.lxor_spec;
  repeat match goal with |- context [Nat.testbit ?x ?j] => destruct (Nat.testbit x j) end;
  reflexivity.

Lemma affine_pair_count : forall q H d d' e e',
  (forall h, In h H -> maps_digits q h /\ linear_on_digits q h) ->
  d < 2 ^ q -> d' < 2 ^ q -> e < 2 ^ q ->
  cnt (fun g => (g d =? e) && (g d' =? e')) (art_law q H) =
  cnt (fun h => h (Nat.lxor d d') =? Nat.lxor e e') H.
Proof.
  intros q H d d' e e' HH Hd Hd' He.
  induction H as [|h H IH]; [reflexivity|].
  unfold art_law in *. simpl. rewrite cnt_app, cnt_map, cnt_cons.
  rewrite IH by (intros; apply HH; right; auto). f_equal.
  destruct (HH h (or_introl eq_refl)) as [Mh Lh]. rewrite (Lh d d' Hd Hd').
  rewrite (cnt_ext _ _ (fun t => (Nat.lxor (h d) (h d') =? Nat.lxor e e') &&
                                 (t =? Nat.lxor (h d) e))).
  - rewrite cnt_and_const. destruct (_ =? _); [|reflexivity].
    apply cnt_seq_in. split; [lia|]. simpl. apply lxor_lt; [apply Mh|]; assumption.
  - intros t _.
    destruct (Nat.eqb_spec t (Nat.lxor (h d) e)) as [->|N].
    + rewrite andb_true_r.
      replace (Nat.lxor (h d) (Nat.lxor (h d) e)) with e by (symmetry; apply lxor_cancel).
      rewrite Nat.eqb_refl. simpl. apply eq_iff_eq_true. rewrite !Nat.eqb_eq. split; intro E.
      * rewrite <- E. xor_bits.
      * apply (f_equal (Nat.lxor e)) in E. rewrite lxor_cancel in E. rewrite <- E. xor_bits.
    + rewrite andb_false_r. destruct (Nat.eqb_spec (Nat.lxor (h d) t) e) as [E|E]; [|reflexivity].
      exfalso. apply N. apply lxor_solve, E.
Qed.

(** The affine law of a linear list [H] is uniformly 2-transitive with count [c2] exactly when
    [H] sends every nonzero digit to every nonzero digit [c2] times. *)
Theorem affine_two_transitive : forall q H c2,
  (forall h, In h H -> maps_digits q h /\ linear_on_digits q h) ->
  (forall v w, 0 < v < 2 ^ q -> 0 < w < 2 ^ q -> cnt (fun h => h v =? w) H = c2) ->
  forall d d' e e', d < 2 ^ q -> d' < 2 ^ q -> e < 2 ^ q -> e' < 2 ^ q -> d <> d' -> e <> e' ->
  cnt (fun g => (g d =? e) && (g d' =? e')) (art_law q H) = c2.
Proof.
  intros q H c2 HH Hc d d' e e' Hd Hd' He He' N N'.
  rewrite affine_pair_count by assumption. apply Hc.
  - split; [|apply lxor_lt; assumption].
    apply Nat.neq_0_lt_0. intro Z. apply N. apply Nat.lxor_eq_0_iff, Z.
  - split; [|apply lxor_lt; assumption].
    apply Nat.neq_0_lt_0. intro Z. apply N'. apply Nat.lxor_eq_0_iff, Z.
Qed.

(** ** GL(4,2) by computation *)

Definition lin4 (v1 v2 v4 v8 : nat) : nat -> nat := fun x =>
  Nat.lxor (Nat.lxor (if Nat.testbit x 0 then v1 else 0) (if Nat.testbit x 1 then v2 else 0))
           (Nat.lxor (if Nat.testbit x 2 then v4 else 0) (if Nat.testbit x 3 then v8 else 0)).

Definition digits16 : list nat := seq 0 16.

(** [lin4 v1 v2 v4 v8] when it is a bijection of the 16 digits. *)
Definition gl4_of (v1 v2 v4 v8 : nat) : list (nat -> nat) :=
  if nodupb (map (lin4 v1 v2 v4 v8) digits16) then [lin4 v1 v2 v4 v8] else [].

Definition GL4 : list (nat -> nat) :=
  flat_map (fun v1 => flat_map (fun v2 => flat_map (fun v4 => flat_map (fun v8 =>
    gl4_of v1 v2 v4 v8) digits16) digits16) digits16) digits16.

Lemma if_xorb : forall (a c : bool) v,
  (if xorb a c then v else 0) = Nat.lxor (if a then v else 0) (if c then v else 0).
Proof.
  intros [|] [|] v; simpl; rewrite ?Nat.lxor_0_l, ?Nat.lxor_0_r, ?Nat.lxor_nilpotent; reflexivity.
Qed.

Lemma swap_mid : forall a b c d,
  Nat.lxor (Nat.lxor a b) (Nat.lxor c d) = Nat.lxor (Nat.lxor a c) (Nat.lxor b d).
Proof. intros. xor_bits. Qed.

Lemma lin4_linear : forall v1 v2 v4 v8, linear_on_digits 4 (lin4 v1 v2 v4 v8).
Proof.
  intros v1 v2 v4 v8 x y _ _. unfold lin4. rewrite !Nat.lxor_spec, !if_xorb.
  set (a1 := if Nat.testbit x 0 then v1 else 0). set (b1 := if Nat.testbit y 0 then v1 else 0).
  set (a2 := if Nat.testbit x 1 then v2 else 0). set (b2 := if Nat.testbit y 1 then v2 else 0).
  set (a4 := if Nat.testbit x 2 then v4 else 0). set (b4 := if Nat.testbit y 2 then v4 else 0).
  set (a8 := if Nat.testbit x 3 then v8 else 0). set (b8 := if Nat.testbit y 3 then v8 else 0).
  rewrite (swap_mid a1 b1 a2 b2), (swap_mid a4 b4 a8 b8), swap_mid. reflexivity.
Qed.

Lemma in_GL4 : forall h, In h GL4 ->
  exists v1 v2 v4 v8, v1 < 16 /\ v2 < 16 /\ v4 < 16 /\ v8 < 16 /\ h = lin4 v1 v2 v4 v8.
Proof.
  intros h Hh. unfold GL4 in Hh.
  (* [rewrite], not [apply ... in]: the latter unfolds GL4's enumeration while unifying. *)
  rewrite in_flat_map in Hh. destruct Hh as [v1 [H1 Hh]].
  rewrite in_flat_map in Hh. destruct Hh as [v2 [H2 Hh]].
  rewrite in_flat_map in Hh. destruct Hh as [v4 [H4 Hh]].
  rewrite in_flat_map in Hh. destruct Hh as [v8 [H8 Hh]].
  unfold digits16 in H1, H2, H4, H8. apply in_seq in H1, H2, H4, H8.
  unfold gl4_of in Hh. destruct (nodupb _); [destruct Hh as [<-|[]]|destruct Hh].
  exists v1, v2, v4, v8. repeat split; lia.
Qed.

Lemma GL4_linear : forall h, In h GL4 -> maps_digits 4 h /\ linear_on_digits 4 h.
Proof.
  intros h Hh. apply in_GL4 in Hh as [v1 [v2 [v4 [v8 [H1 [H2 [H4 [H8 ->]]]]]]]].
  split; [|apply lin4_linear].
  intros x _. unfold lin4.
  assert (I : forall (c : bool) v, v < 2 ^ 4 -> (if c then v else 0) < 2 ^ 4)
    by (intros [|] v Hv; simpl in *; lia).
  repeat apply lxor_lt; apply I; simpl; lia.
Qed.

(** GL(4,2) has 20,160 maps and sends each nonzero digit to each nonzero digit under 1,344 of
    them; so AGL(4,2) (322,560 maps, art-owen-m4's node law) is uniformly 2-transitive and
    Owen's pair lemma ([Laws.pair_lemma]) holds exactly for trees of its nodes. *)
Theorem agl4_two_transitive :
  length GL4 = 20160 /\ length (art_law 4 GL4) = 16 * length GL4 /\
  (forall d d' e e', d < 16 -> d' < 16 -> e < 16 -> e' < 16 -> d <> d' -> e <> e' ->
     cnt (fun g => (g d =? e) && (g d' =? e')) (art_law 4 GL4) = 1344).
Proof.
  assert (L : length GL4 = 20160) by (vm_compute; reflexivity).
  split; [exact L|]. split; [apply length_art_law|].
  apply (affine_two_transitive 4 GL4 1344 GL4_linear).
  (* Count over the maps' tables (computed once) instead of re-evaluating each map. *)
  intros v w Hv Hw.
  rewrite (cnt_ext _ _ (fun h => fn_of (map h (seq 0 16)) v =? w))
    by (intros h _; rewrite fn_of_table by (simpl in Hv; lia); reflexivity).
  rewrite <- (cnt_map _ _ (fun f => f v =? w) (fun h => fn_of (map h (seq 0 16)))).
  assert (C : forallb (fun v => forallb (fun w =>
                cnt (fun f => f v =? w) (map (fun h => fn_of (map h (seq 0 16))) GL4) =? 1344)
                (seq 1 15)) (seq 1 15) = true).
  { pose (tables := map (fun h => map h (seq 0 16)) GL4).
    assert (T : map (fun h => fn_of (map h (seq 0 16))) GL4 = map fn_of tables)
      by (unfold tables; rewrite map_map; reflexivity).
    rewrite T. vm_compute. reflexivity. }
  rewrite forallb_forall in C. specialize (C v (proj2 (in_seq 15 1 v) ltac:(simpl in Hv; lia))).
  rewrite forallb_forall in C. specialize (C w (proj2 (in_seq 15 1 w) ltac:(simpl in Hw; lia))).
  apply Nat.eqb_eq, C.
Qed.
