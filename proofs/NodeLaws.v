(** * The law of an ART node, and where AGL(q,2) stops being S_{2^q}.

    An ART node applies ψ (drawn from a list [H] of digit maps: the identity for translation
    variants, GL(q,2) for the matrix variants, S_b for the permutation variants) and then an
    independent uniform translation: [art_law q H] lists every pair once.
    - [art_law_transitive]: that law is uniformly transitive for ANY [H], so (with
      [Laws.output_uniform]) every ART variant's output digit strings are uniform:
      [art_output_uniform].
    - [agl3_two_transitive], [s4_two_transitive]: AGL(3,2) = GL(3,2)·translations and S_4 are
      uniformly 2-transitive, so Owen's pair lemma ([Laws.pair_lemma]) holds exactly for trees
      of such nodes; [translations_not_two_transitive]: translations alone are not.
    - [affine_is_symmetric_q1], [affine_is_symmetric_q2]: every permutation of 2 or 4 digits is
      affine (AGL(q,2) = S_{2^q} for q ≤ 2); [transposition_not_affine]: for every q ≥ 3 the
      swap of 0 and 1 is not, so AGL(q,2) ≠ S_{2^q}. *)

From Coq Require Import List Arith Bool Lia.
From Gartowen Require Import Laws ArtWord.
Import ListNotations.

Definition art_law (q : nat) (H : list (nat -> nat)) : list (nat -> nat) :=
  flat_map (fun h => map (fun t d => Nat.lxor (h d) t) (seq 0 (2 ^ q))) H.

Lemma lxor_cancel : forall a t, Nat.lxor a (Nat.lxor a t) = t.
Proof. intros. rewrite <- Nat.lxor_assoc, Nat.lxor_nilpotent, Nat.lxor_0_l. reflexivity. Qed.

Lemma cnt_seq_above : forall n s v, v < s -> cnt (fun t => t =? v) (seq s n) = 0.
Proof.
  induction n as [|n IH]; intros s v H; unfold cnt; simpl; auto.
  destruct (Nat.eqb_spec s v); [lia|]. apply IH. lia.
Qed.

Lemma cnt_seq_in : forall n s v, s <= v < s + n -> cnt (fun t => t =? v) (seq s n) = 1.
Proof.
  induction n as [|n IH]; intros s v H; [lia|]. unfold cnt. simpl.
  destruct (Nat.eqb_spec s v).
  - subst. simpl. f_equal. apply cnt_seq_above. lia.
  - apply IH. lia.
Qed.

Lemma length_art_law : forall q H, length (art_law q H) = 2 ^ q * length H.
Proof.
  intros. unfold art_law. rewrite <- cnt_true, cnt_flat_map.
  rewrite (sumL_ext _ _ (fun _ => 2 ^ q)).
  - rewrite sumL_const. lia.
  - intros. rewrite cnt_map, cnt_true, seq_length. reflexivity.
Qed.

Definition maps_digits (q : nat) (h : nat -> nat) : Prop := forall d, d < 2 ^ q -> h d < 2 ^ q.

(** Whatever ψ's list, a uniform translation after it sends each digit to each digit under
    exactly [length H] of the [2^q · length H] node maps. *)
Theorem art_law_transitive : forall q H d e, (forall h, In h H -> maps_digits q h) ->
  d < 2 ^ q -> e < 2 ^ q -> cnt (fun g => g d =? e) (art_law q H) = length H.
Proof.
  intros q H d e HH Hd He. unfold art_law. rewrite cnt_flat_map.
  rewrite (sumL_ext _ _ (fun _ => 1)).
  - rewrite sumL_const. lia.
  - intros h Hin. rewrite cnt_map.
    rewrite (cnt_ext _ _ (fun t => t =? Nat.lxor (h d) e)).
    + apply cnt_seq_in. split; [lia|]. simpl. apply lxor_lt; [apply HH; auto|exact He].
    + intros t _. destruct (Nat.eqb_spec (Nat.lxor (h d) t) e) as [E|E];
        destruct (Nat.eqb_spec t (Nat.lxor (h d) e)) as [E'|E']; auto.
      * exfalso. apply E'. rewrite <- E, lxor_cancel. reflexivity.
      * exfalso. apply E. rewrite E', lxor_cancel. reflexivity.
Qed.

(** Every ART variant: independent ART nodes give uniform output digit strings. *)
Theorem art_output_uniform : forall q H n x y, 1 <= q -> (forall h, In h H -> maps_digits q h) ->
  length x = n -> length y = n -> valid (2 ^ q) x -> valid (2 ^ q) y ->
  (2 ^ q) ^ n * cnt (fun t => leqb (act t x) y) (trees (2 ^ q) (art_law q H) n) =
  length (trees (2 ^ q) (art_law q H) n).
Proof.
  intros q H n x y Hq HH Lx Ly Vx Vy.
  assert (B2 : 2 <= 2 ^ q) by (replace 2 with (2 ^ 1) at 1 by reflexivity; apply Nat.pow_le_mono_r; lia).
  apply (output_uniform (2 ^ q) B2 (art_law q H) (length H)); auto.
  - intros d e Hd He. apply art_law_transitive; auto.
  - rewrite length_art_law. reflexivity.
Qed.

(** ** Instances by computation *)

Definition fn_of (tbl : list nat) : nat -> nat := fun d => nth d tbl 0.

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

Definition trans_check (b c1 : nat) (G : list (nat -> nat)) : bool :=
  forallb (fun d => forallb (fun e => cnt (fun g => g d =? e) G =? c1) (seq 0 b)) (seq 0 b).

Definition trans2_check (b c2 : nat) (G : list (nat -> nat)) : bool :=
  forallb (fun d => forallb (fun d' => forallb (fun e => forallb (fun e' =>
    (d =? d') || (e =? e') || (cnt (fun g => (g d =? e) && (g d' =? e')) G =? c2))
    (seq 0 b)) (seq 0 b)) (seq 0 b)) (seq 0 b).

Lemma in_seq0 : forall b d, d < b -> In d (seq 0 b).
Proof. intros. apply in_seq. lia. Qed.

Lemma trans_check_ok : forall b c1 G, trans_check b c1 G = true ->
  forall d e, d < b -> e < b -> cnt (fun g => g d =? e) G = c1.
Proof.
  intros b c1 G H d e Hd He. unfold trans_check in H.
  rewrite forallb_forall in H. specialize (H d (in_seq0 _ _ Hd)).
  rewrite forallb_forall in H. specialize (H e (in_seq0 _ _ He)).
  apply Nat.eqb_eq, H.
Qed.

Lemma trans2_check_ok : forall b c2 G, trans2_check b c2 G = true ->
  forall d d' e e', d < b -> d' < b -> e < b -> e' < b -> d <> d' -> e <> e' ->
  cnt (fun g => (g d =? e) && (g d' =? e')) G = c2.
Proof.
  intros b c2 G H d d' e e' Hd Hd' He He' N N'. unfold trans2_check in H.
  rewrite forallb_forall in H. specialize (H d (in_seq0 _ _ Hd)).
  rewrite forallb_forall in H. specialize (H d' (in_seq0 _ _ Hd')).
  rewrite forallb_forall in H. specialize (H e (in_seq0 _ _ He)).
  rewrite forallb_forall in H. specialize (H e' (in_seq0 _ _ He')).
  apply Nat.eqb_neq in N, N'. rewrite N, N' in H. simpl in H. apply Nat.eqb_eq, H.
Qed.

Definition S4 : list (nat -> nat) := map fn_of (perms [0; 1; 2; 3]).

(** Uniform node permutations over S_4 (= AGL(2,2)): the pair lemma holds exactly. *)
Theorem s4_two_transitive :
  length S4 = 24 /\
  (forall d e, d < 4 -> e < 4 -> cnt (fun g => g d =? e) S4 = 6) /\
  (forall d d' e e', d < 4 -> d' < 4 -> e < 4 -> e' < 4 -> d <> d' -> e <> e' ->
     cnt (fun g => (g d =? e) && (g d' =? e')) S4 = 2).
Proof.
  split; [vm_compute; reflexivity|]. split.
  - apply trans_check_ok. vm_compute. reflexivity.
  - apply trans2_check_ok. vm_compute. reflexivity.
Qed.

(** GL(3,2): the linear maps x ↦ ⊕ of the images of x's bits that are bijections. *)
Definition lin3 (v1 v2 v4 : nat) : nat -> nat := fun x =>
  Nat.lxor (if Nat.testbit x 0 then v1 else 0)
    (Nat.lxor (if Nat.testbit x 1 then v2 else 0) (if Nat.testbit x 2 then v4 else 0)).

Fixpoint nodupb (l : list nat) : bool :=
  match l with [] => true | x :: r => negb (existsb (Nat.eqb x) r) && nodupb r end.

Definition GL3 : list (nat -> nat) :=
  flat_map (fun v1 => flat_map (fun v2 => flat_map (fun v4 =>
    if nodupb (map (lin3 v1 v2 v4) (seq 0 8)) then [lin3 v1 v2 v4] else [])
    (seq 0 8)) (seq 0 8)) (seq 0 8).

Definition AGL3 := art_law 3 GL3.

(** The law of an art-owen-m3 node, AGL(3,2) (1344 maps): uniformly 2-transitive, so Owen's
    pair lemma holds exactly for independent such nodes. *)
Lemma fn_of_table : forall b g d, d < b -> fn_of (map g (seq 0 b)) d = g d.
Proof.
  intros b g d H. unfold fn_of. rewrite (nth_indep _ 0 (g 0)) by (rewrite map_length, seq_length; lia).
  rewrite map_nth, seq_nth by lia. reflexivity.
Qed.

Theorem agl3_two_transitive :
  length GL3 = 168 /\ length AGL3 = 1344 /\
  (forall d d' e e', d < 8 -> d' < 8 -> e < 8 -> e' < 8 -> d <> d' -> e <> e' ->
     cnt (fun g => (g d =? e) && (g d' =? e')) AGL3 = 24).
Proof.
  split; [vm_compute; reflexivity|]. split; [vm_compute; reflexivity|].
  (* Count over the maps' tables (computed once) instead of re-evaluating each map. *)
  intros d d' e e' Hd Hd' He He' N N'.
  rewrite (cnt_ext _ _ (fun g => (fn_of (map g (seq 0 8)) d =? e) && (fn_of (map g (seq 0 8)) d' =? e')))
    by (intros g _; rewrite !fn_of_table by assumption; reflexivity).
  rewrite <- (cnt_map _ _ (fun f => (f d =? e) && (f d' =? e')) (fun g => fn_of (map g (seq 0 8)))).
  revert d d' e e' Hd Hd' He He' N N'. apply trans2_check_ok.
  pose (tables := map (fun g => map g (seq 0 8)) AGL3).
  assert (T : map (fun g => fn_of (map g (seq 0 8))) AGL3 = map fn_of tables)
    by (unfold tables; rewrite map_map; reflexivity).
  rewrite T. vm_compute. reflexivity.
Qed.

(** Translations alone (art-owen-t2's node law on 4 digits): uniform marginals, but not
    2-transitive: (0, 1) goes to (1, 0) under one translation and to (1, 2) under none. *)
Theorem translations_not_two_transitive :
  cnt (fun g => (g 0 =? 1) && (g 1 =? 0)) (art_law 2 [fun d => d]) = 1 /\
  cnt (fun g => (g 0 =? 1) && (g 1 =? 2)) (art_law 2 [fun d => d]) = 0.
Proof. split; vm_compute; reflexivity. Qed.

(** ** AGL(q,2) against S_{2^q} *)

Definition affine (q : nat) (f : nat -> nat) : Prop :=
  exists (L : nat -> nat) (t : nat),
    (forall x y, x < 2 ^ q -> y < 2 ^ q -> L (Nat.lxor x y) = Nat.lxor (L x) (L y)) /\
    (forall x, x < 2 ^ q -> f x = Nat.lxor (L x) t).

Definition affine_check (q : nat) (f : nat -> nat) : bool :=
  let L := fun x => Nat.lxor (f x) (f 0) in
  forallb (fun x => forallb (fun y => L (Nat.lxor x y) =? Nat.lxor (L x) (L y))
    (seq 0 (2 ^ q))) (seq 0 (2 ^ q)).

Lemma affine_check_ok : forall q f, affine_check q f = true -> affine q f.
Proof.
  intros q f H. exists (fun x => Nat.lxor (f x) (f 0)), (f 0). split.
  - intros x y Hx Hy. unfold affine_check in H.
    rewrite forallb_forall in H. specialize (H x (in_seq0 _ _ Hx)).
    rewrite forallb_forall in H. specialize (H y (in_seq0 _ _ Hy)).
    apply Nat.eqb_eq, H.
  - intros x _. rewrite Nat.lxor_assoc, Nat.lxor_nilpotent, Nat.lxor_0_r. reflexivity.
Qed.

(** AGL(1,2) = S_2 and AGL(2,2) = S_4: every permutation of the digits is affine. *)
Theorem affine_is_symmetric_q1 : forall p, In p (perms [0; 1]) -> affine 1 (fn_of p).
Proof.
  intros p Hp. apply affine_check_ok. revert p Hp. apply Forall_forall.
  apply Forall_forall. intros p Hp. vm_compute in Hp.
  repeat destruct Hp as [<-|Hp]; [vm_compute; reflexivity..|contradiction].
Qed.

Theorem affine_is_symmetric_q2 : forall p, In p (perms [0; 1; 2; 3]) -> affine 2 (fn_of p).
Proof.
  intros p Hp. apply affine_check_ok.
  assert (C : forallb (affine_check 2) (map fn_of (perms [0; 1; 2; 3])) = true)
    by (vm_compute; reflexivity).
  rewrite forallb_forall in C. apply C, in_map, Hp.
Qed.

Lemma lxor_move : forall v a t, v = Nat.lxor a t -> a = Nat.lxor v t.
Proof. intros v a t ->. rewrite Nat.lxor_assoc, Nat.lxor_nilpotent, Nat.lxor_0_r. reflexivity. Qed.

(** For every q ≥ 3 the transposition of 0 and 1 is a permutation of the 2^q digits that is not
    affine, so AGL(q,2) is a proper subgroup of S_{2^q}: an affine f has
    f(7) ⊕ f(0) = (f(1) ⊕ f(0)) ⊕ (f(2) ⊕ f(0)) ⊕ (f(4) ⊕ f(0)), and the swap gives 6 ≠ 7. *)
Theorem transposition_not_affine : forall q, 3 <= q -> ~ affine q swap01.
Proof.
  intros q Hq [L [t [Add F]]].
  assert (P : 8 <= 2 ^ q) by (replace 8 with (2 ^ 3) by reflexivity; apply Nat.pow_le_mono_r; lia).
  assert (L0 : L 0 = 0).
  { pose proof (Add 0 0 ltac:(lia) ltac:(lia)) as E. rewrite Nat.lxor_nilpotent in E.
    rewrite E, Nat.lxor_nilpotent. reflexivity. }
  pose proof (F 0 ltac:(lia)) as F0. rewrite L0, Nat.lxor_0_l in F0. vm_compute in F0. subst t.
  pose proof (lxor_move _ _ _ (F 1 ltac:(lia))) as F1.
  pose proof (lxor_move _ _ _ (F 2 ltac:(lia))) as F2.
  pose proof (lxor_move _ _ _ (F 3 ltac:(lia))) as F3.
  pose proof (lxor_move _ _ _ (F 4 ltac:(lia))) as F4.
  pose proof (lxor_move _ _ _ (F 7 ltac:(lia))) as F7.
  pose proof (Add 3 4 ltac:(lia) ltac:(lia)) as A34.
  vm_compute in F1, F2, F3, F4, F7. change (Nat.lxor 3 4) with 7 in A34.
  rewrite F7, F3, F4 in A34. vm_compute in A34. discriminate.
Qed.
