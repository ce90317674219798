(** * The uniform law on S_b is uniformly 2-transitive, for every b ≥ 2, so Owen's pair lemma
    holds for the full-tree oracle's node law in every base.

    [Laws.pair_lemma] is stated for any finite law [G] of node maps with two counting
    hypotheses: every digit goes to every digit under the same number [c1] of maps, and every
    ordered pair of distinct digits to every such pair under the same number [c2]. Here [G] is
    the symmetric group S_b, listed as its tables: the lists of length b with distinct entries
    below b, among all b^b tuples. The counting argument: composing every table with a
    transposition of digits permutes the tuples and keeps the tables, so it moves the count of
    tables with t(d) = e to that with t(d) = f (and pairs to pairs, with two transpositions);
    the counts are therefore equal, and they sum to the number of tables. No enumeration of
    S_b is computed: the statement holds for every b. *)

From Coq Require Import List Arith Bool Lia Permutation FinFun.
Import ListNotations.
From Gartowen Require Import Laws.

Section Symmetric.

Variable b : nat.

Definition L : list nat := seq 0 b.

(** The transposition of digits e and f. *)
Definition swap (e f x : nat) : nat := if x =? e then f else if x =? f then e else x.

Lemma swap_involutive : forall e f x, swap e f (swap e f x) = x.
Proof.
  intros e f x. unfold swap.
  destruct (Nat.eqb_spec x e) as [->|H1]; [|destruct (Nat.eqb_spec x f) as [->|H2]];
  repeat match goal with
    | |- context [?a =? ?a] => rewrite Nat.eqb_refl
    | |- context [?a =? ?c] => destruct (Nat.eqb_spec a c)
  end; subst; auto; lia.
Qed.

Lemma swap_injective : forall e f, Injective (swap e f).
Proof.
  intros e f x y H. rewrite <- (swap_involutive e f x), <- (swap_involutive e f y), H. reflexivity.
Qed.

Lemma swap_lt : forall e f x, e < b -> f < b -> x < b -> swap e f x < b.
Proof. intros e f x He Hf Hx. unfold swap. destruct (x =? e), (x =? f); auto. Qed.

Lemma swap_to_f : forall e f x, swap e f x = f <-> x = e.
Proof.
  intros e f x. unfold swap. split; intro H.
  - destruct (Nat.eqb_spec x e); auto. destruct (Nat.eqb_spec x f); lia.
  - subst. now rewrite Nat.eqb_refl.
Qed.

Lemma swap_elsewhere : forall e f x, x <> e -> x <> f -> swap e f x = x.
Proof.
  intros e f x H1 H2. unfold swap.
  destruct (Nat.eqb_spec x e), (Nat.eqb_spec x f); lia.
Qed.

Lemma swap_permutes_digits : forall e f, e < b -> f < b -> Permutation (map (swap e f) L) L.
Proof.
  intros e f He Hf. apply NoDup_Permutation.
  - apply Injective_map_NoDup; [apply swap_injective | apply seq_NoDup].
  - apply seq_NoDup.
  - intro x. unfold L. rewrite in_map_iff. split.
    + intros [y [<- Hy]]. apply in_seq in Hy. apply in_seq. split; [lia|].
      apply swap_lt; lia.
    + intro Hx. exists (swap e f x). split; [apply swap_involutive|].
      apply in_seq in Hx. apply in_seq. split; [lia|]. apply swap_lt; lia.
Qed.

(** Sums over permuted lists, and counts under a digit permutation of every coordinate. *)
Lemma sumL_perm : forall A (f : A -> nat) l l', Permutation l l' -> sumL f l = sumL f l'.
Proof. intros A f l l' P. induction P; simpl; lia. Qed.

Lemma sumL_map : forall A B (f : B -> nat) (g : A -> B) l, sumL f (map g l) = sumL (fun x => f (g x)) l.
Proof. intros. induction l; simpl; auto. Qed.

Lemma sumL_plus : forall A (f g : A -> nat) l, sumL (fun x => f x + g x) l = sumL f l + sumL g l.
Proof. intros. induction l; simpl; lia. Qed.

Lemma cnt_digit_permutation : forall (s : nat -> nat), Permutation (map s L) L ->
  forall k (P : list nat -> bool),
  cnt (fun ks => P (map s ks)) (tuples nat k L) = cnt P (tuples nat k L).
Proof.
  intros s Hs k. induction k as [|k IH]; intro P; [reflexivity|].
  simpl tuples. rewrite !cnt_flat_map.
  rewrite (sumL_ext _ _ (fun x => cnt (fun ks => P (s x :: ks)) (tuples nat k L))).
  - rewrite <- (sumL_map _ _ (fun y => cnt (fun ks => P (y :: ks)) (tuples nat k L)) s).
    rewrite (sumL_perm _ _ _ _ Hs). apply sumL_ext. intros x _. rewrite cnt_map. reflexivity.
  - intros x _. rewrite cnt_map. simpl. apply (IH (fun ks => P (s x :: ks))).
Qed.

(** Tables: the permutations of 0..b−1, as lists. *)
Fixpoint distinctb (l : list nat) : bool :=
  match l with [] => true | x :: r => negb (existsb (Nat.eqb x) r) && distinctb r end.

Lemma distinctb_nodup : forall l, distinctb l = true <-> NoDup l.
Proof.
  induction l as [|x r IH]; simpl; split; intro H.
  - constructor.
  - reflexivity.
  - apply andb_true_iff in H as [H1 H2]. constructor; [|apply IH, H2].
    intro I. apply negb_true_iff in H1.
    assert (existsb (Nat.eqb x) r = true) by (apply existsb_exists; exists x; split; auto;
      apply Nat.eqb_refl). congruence.
  - inversion H as [|? ? N D]; subst. apply andb_true_iff. split; [|apply IH, D].
    apply negb_true_iff. destruct (existsb (Nat.eqb x) r) eqn:E; auto.
    apply existsb_exists in E as [y [Y Exy]]. apply Nat.eqb_eq in Exy. subst. contradiction.
Qed.

Definition is_table (t : list nat) : bool :=
  (length t =? b) && forallb (fun x => x <? b) t && distinctb t.

Lemma is_table_spec : forall t, is_table t = true <->
  length t = b /\ (forall x, In x t -> x < b) /\ NoDup t.
Proof.
  intro t. unfold is_table. rewrite !andb_true_iff, Nat.eqb_eq, forallb_forall, distinctb_nodup.
  split; intros [[H1 H2] H3] || intros [H1 [H2 H3]]; repeat split; auto;
    intros x Hx; [apply Nat.ltb_lt, H2, Hx | apply Nat.ltb_lt, H2, Hx].
Qed.

Lemma is_table_swap : forall e f t, e < b -> f < b ->
  is_table (map (swap e f) t) = is_table t.
Proof.
  assert (One : forall e f t, e < b -> f < b -> is_table t = true ->
                is_table (map (swap e f) t) = true).
  { intros e f t He Hf H. apply is_table_spec in H as [H1 [H2 H3]]. apply is_table_spec.
    split; [rewrite map_length; auto|]. split.
    - intros x Hx. apply in_map_iff in Hx as [y [<- Hy]]. apply swap_lt; auto.
    - apply Injective_map_NoDup; auto. apply swap_injective. }
  intros e f t He Hf. destruct (is_table t) eqn:T; [apply One; auto|].
  destruct (is_table (map (swap e f) t)) eqn:T'; auto.
  apply (One e f) in T'; auto. rewrite map_map in T'.
  rewrite (map_ext _ _ (swap_involutive e f)), map_id in T'. congruence.
Qed.

Definition tables : list (list nat) := filter is_table (tuples nat b L).

(** The law S_b: each table read as a map of digits. *)
Definition Sb : list (nat -> nat) := map (fun t d => nth d t 0) tables.

Lemma cnt_filter : forall A (P Q : A -> bool) l, cnt P (filter Q l) = cnt (fun x => Q x && P x) l.
Proof.
  intros. unfold cnt. induction l as [|a l IH]; simpl; auto.
  destruct (Q a); simpl; auto. destruct (P a); simpl; auto.
Qed.

Lemma nth_map_swap : forall e f t d, d < length t ->
  nth d (map (swap e f) t) 0 = swap e f (nth d t 0).
Proof.
  intros e f t d H. rewrite (nth_indep _ 0 (swap e f 0)) by (rewrite map_length; auto).
  apply map_nth.
Qed.

(** Transitivity: the tables sending d to e are as many as those sending d to f. *)
Lemma count_one_swap : forall d e f, d < b -> e < b -> f < b ->
  cnt (fun t => is_table t && (nth d t 0 =? e)) (tuples nat b L) =
  cnt (fun t => is_table t && (nth d t 0 =? f)) (tuples nat b L).
Proof.
  intros d e f Hd He Hf.
  rewrite <- (cnt_digit_permutation (swap e f) (swap_permutes_digits e f He Hf) b
               (fun t => is_table t && (nth d t 0 =? f))).
  apply cnt_ext. intros t _. rewrite is_table_swap by auto.
  destruct (is_table t) eqn:T; auto. apply is_table_spec in T as [T _].
  rewrite nth_map_swap by lia. simpl.
  destruct (Nat.eqb_spec (nth d t 0) e), (Nat.eqb_spec (swap e f (nth d t 0)) f); auto.
  - exfalso. apply n. apply swap_to_f. auto.
  - exfalso. apply n. apply (proj1 (swap_to_f e f _)). auto.
Qed.

Lemma sumL_eqb_seq : forall x start len,
  sumL (fun e => if x =? e then 1 else 0) (seq start len) =
  if (start <=? x) && (x <? start + len) then 1 else 0.
Proof.
  intros x start len. revert start. induction len as [|len IH]; intro start; simpl.
  - rewrite Nat.add_0_r. destruct (start <=? x) eqn:F, (x <? start) eqn:G; simpl; auto.
    apply Nat.leb_le in F. apply Nat.ltb_lt in G. lia.
  - rewrite IH. destruct (Nat.eqb_spec x start).
    + subst. replace (S start <=? start) with false by (symmetry; apply Nat.leb_gt; lia).
      replace (start <=? start) with true by (symmetry; apply Nat.leb_le; lia).
      replace (start <? start + S len) with true by (symmetry; apply Nat.ltb_lt; lia).
      reflexivity.
    + destruct (S start <=? x) eqn:F1, (start <=? x) eqn:F2,
        (x <? S start + len) eqn:F3, (x <? start + S len) eqn:F4; simpl; auto;
      repeat match goal with
        | H : (_ <=? _) = true |- _ => apply Nat.leb_le in H
        | H : (_ <=? _) = false |- _ => apply Nat.leb_gt in H
        | H : (_ <? _) = true |- _ => apply Nat.ltb_lt in H
        | H : (_ <? _) = false |- _ => apply Nat.ltb_ge in H
      end; lia.
Qed.

Lemma sumL_eqb : forall x, x < b -> sumL (fun e => if x =? e then 1 else 0) L = 1.
Proof.
  intros x H. unfold L. rewrite sumL_eqb_seq.
  replace ((0 <=? x) && (x <? 0 + b)) with true; auto.
  symmetry. apply andb_true_intro. split; [apply Nat.leb_le | apply Nat.ltb_lt]; lia.
Qed.

Lemma cnt_cons : forall A (P : A -> bool) a l, cnt P (a :: l) = (if P a then 1 else 0) + cnt P l.
Proof. intros. unfold cnt. simpl. destruct (P a); reflexivity. Qed.

Lemma sumL_const' : forall A K (l : list A), sumL (fun _ => K) l = length l * K.
Proof. intros. induction l; simpl; lia. Qed.

(** Every table sends d somewhere: counts over the image e sum to the count without it. *)
Lemma sum_over_images_of : forall (Q : list nat -> bool) d T, d < b ->
  (forall t, Q t = true -> is_table t = true) ->
  sumL (fun e => cnt (fun t => Q t && (nth d t 0 =? e)) T) L = cnt Q T.
Proof.
  intros Q d T Hd HQ. induction T as [|t T IH].
  - unfold cnt. simpl. rewrite sumL_const'. lia.
  - rewrite cnt_cons. rewrite (sumL_ext _ _ (fun e =>
      (if Q t && (nth d t 0 =? e) then 1 else 0) +
      cnt (fun t => Q t && (nth d t 0 =? e)) T)) by (intros; apply cnt_cons).
    rewrite sumL_plus, IH. f_equal. destruct (Q t) eqn:Qt; simpl.
    + apply HQ, is_table_spec in Qt as [L1 [L2 _]]. apply sumL_eqb, L2, nth_In. lia.
    + rewrite sumL_const'. lia.
Qed.

Lemma sum_over_images : forall d T, d < b ->
  sumL (fun e => cnt (fun t => is_table t && (nth d t 0 =? e)) T) L = cnt is_table T.
Proof. intros d T Hd. apply sum_over_images_of; auto. Qed.

Definition c1 : nat := cnt (fun t => is_table t && (nth 0 t 0 =? 0)) (tuples nat b L).

Lemma per_image : forall d e, d < b -> e < b ->
  b * cnt (fun t => is_table t && (nth d t 0 =? e)) (tuples nat b L) = length tables.
Proof.
  intros d e Hd He. unfold tables. rewrite <- (cnt_true _ (filter _ _)), cnt_filter.
  rewrite (cnt_ext _ (fun x => is_table x && true) is_table) by (intros; apply andb_true_r).
  rewrite <- (sum_over_images d) by auto.
  rewrite (sumL_ext _ _ (fun _ => cnt (fun t => is_table t && (nth d t 0 =? e)) (tuples nat b L))).
  - rewrite sumL_const'. unfold L. rewrite seq_length. reflexivity.
  - intros f Hf. apply in_seq in Hf. apply count_one_swap; lia.
Qed.

Theorem Sb_transitive : 2 <= b -> forall d e, d < b -> e < b ->
  cnt (fun g => g d =? e) Sb = c1.
Proof.
  intros Hb d e Hd He. unfold Sb. rewrite cnt_map. unfold tables. rewrite cnt_filter.
  assert (A := per_image d e Hd He). assert (B := per_image 0 0 ltac:(lia) ltac:(lia)).
  unfold c1. apply (Nat.mul_cancel_l _ _ b); lia.
Qed.

Theorem Sb_size : 2 <= b -> b * c1 = length Sb.
Proof. intro Hb. unfold Sb. rewrite map_length. apply per_image; lia. Qed.

(** Two-transitivity. [pair d d' e e' t]: t is a table sending d to e and d' to e'. *)
Definition pair (d d' e e' : nat) (t : list nat) : bool :=
  is_table t && ((nth d t 0 =? e) && (nth d' t 0 =? e')).

Lemma swap_eqb : forall e f x y, (swap e f x =? swap e f y) = (x =? y).
Proof.
  intros e f x y. destruct (Nat.eqb_spec x y) as [->|N]; [apply Nat.eqb_refl|].
  apply Nat.eqb_neq. intro E. apply N. exact (swap_injective e f x y E).
Qed.

Lemma count_pair_swap : forall d d' x y e f, d < b -> d' < b -> e < b -> f < b ->
  cnt (pair d d' x y) (tuples nat b L) =
  cnt (pair d d' (swap e f x) (swap e f y)) (tuples nat b L).
Proof.
  intros d d' x y e f Hd Hd' He Hf.
  rewrite <- (cnt_digit_permutation (swap e f) (swap_permutes_digits e f He Hf) b
               (pair d d' (swap e f x) (swap e f y))).
  apply cnt_ext. intros t _. unfold pair. rewrite is_table_swap by auto.
  destruct (is_table t) eqn:T; auto. apply is_table_spec in T as [T _].
  rewrite !nth_map_swap by lia. rewrite !swap_eqb. reflexivity.
Qed.

Lemma count_pair_equal : forall d d' e e' f f', d < b -> d' < b -> e < b -> e' < b ->
  f < b -> f' < b -> e <> e' -> f <> f' ->
  cnt (pair d d' e e') (tuples nat b L) = cnt (pair d d' f f') (tuples nat b L).
Proof.
  intros d d' e e' f f' Hd Hd' He He' Hf Hf' N N'.
  set (g := swap e f e').
  assert (Hg : g < b) by (apply swap_lt; auto).
  assert (Gf : g <> f).
  { intro E. apply N. apply (swap_injective e f). unfold g in E. rewrite E.
    unfold swap. now rewrite Nat.eqb_refl. }
  rewrite (count_pair_swap d d' e e' e f) by auto.
  replace (swap e f e) with f by (unfold swap; now rewrite Nat.eqb_refl).
  fold g. rewrite (count_pair_swap d d' f g g f') by auto.
  rewrite (swap_elsewhere g f' f) by auto.
  replace (swap g f' g) with f' by (unfold swap; now rewrite Nat.eqb_refl).
  reflexivity.
Qed.

Lemma pair_diagonal : forall d d' e t, d < b -> d' < b -> d <> d' -> pair d d' e e t = false.
Proof.
  intros d d' e t Hd Hd' N. unfold pair. destruct (is_table t) eqn:T; auto.
  apply is_table_spec in T as [L1 [_ D]]. simpl.
  destruct (Nat.eqb_spec (nth d t 0) e), (Nat.eqb_spec (nth d' t 0) e); auto.
  exfalso. apply N. apply (proj1 (NoDup_nth t 0) D); lia.
Qed.

Lemma sumL_scale : forall A (f : A -> nat) K l, sumL (fun x => K * f x) l = K * sumL f l.
Proof. intros. induction l; simpl; lia. Qed.

Lemma sum_off_diagonal : forall e v, e < b ->
  sumL (fun e' => if e =? e' then 0 else v) L = (b - 1) * v.
Proof.
  intros e v He.
  assert (S : sumL (fun e' => if e =? e' then 0 else v) L +
              sumL (fun e' => v * (if e =? e' then 1 else 0)) L = b * v).
  { rewrite <- sumL_plus. rewrite (sumL_ext _ _ (fun _ => v)).
    - rewrite sumL_const'. unfold L. rewrite seq_length. lia.
    - intros x _. destruct (e =? x); lia. }
  rewrite sumL_scale, sumL_eqb in S by exact He. destruct b; lia.
Qed.

Definition c2 : nat := cnt (pair 0 1 0 1) (tuples nat b L).

Lemma per_pair : forall d d', d < b -> d' < b -> d <> d' ->
  b * (b - 1) * cnt (pair d d' 0 1) (tuples nat b L) = length tables.
Proof.
  intros d d' Hd Hd' N.
  assert (b2 : 2 <= b) by lia.
  unfold tables. rewrite <- (cnt_true _ (filter _ _)), cnt_filter.
  rewrite (cnt_ext _ (fun x => is_table x && true) is_table) by (intros; apply andb_true_r).
  rewrite <- (sum_over_images d) by auto.
  set (v := cnt (pair d d' 0 1) (tuples nat b L)).
  rewrite (sumL_ext _ _ (fun _ => (b - 1) * v)).
  - rewrite sumL_const'. unfold L. rewrite seq_length. lia.
  - intros e He. apply in_seq in He.
    rewrite <- (sum_over_images_of (fun t => is_table t && (nth d t 0 =? e)) d')
      by (auto; intros t T; apply andb_true_iff in T; tauto).
    rewrite <- (sum_off_diagonal e v) by lia. apply sumL_ext. intros e' He'.
    apply in_seq in He'.
    rewrite (cnt_ext _ _ (pair d d' e e'))
      by (intros t _; unfold pair; rewrite andb_assoc; reflexivity).
    destruct (Nat.eqb_spec e e') as [<-|Ne].
    + rewrite (cnt_ext _ _ (fun _ => false)) by (intros t _; apply pair_diagonal; auto).
      rewrite ?Nat.eqb_refl. unfold cnt. clear. induction (tuples nat b L); auto.
    + apply count_pair_equal; lia.
Qed.

Theorem Sb_two_transitive : 2 <= b -> forall d d' e e', d < b -> d' < b -> e < b -> e' < b ->
  d <> d' -> e <> e' ->
  cnt (fun g => (g d =? e) && (g d' =? e')) Sb = c2.
Proof.
  intros Hb d d' e e' Hd Hd' He He' N N'. unfold Sb. rewrite cnt_map. unfold tables.
  rewrite cnt_filter.
  rewrite (cnt_ext _ _ (pair d d' e e')) by reflexivity.
  rewrite (count_pair_equal d d' e e' 0 1) by lia.
  assert (A := per_pair d d' Hd Hd' N). assert (B := per_pair 0 1 ltac:(lia) ltac:(lia) ltac:(lia)).
  unfold c2. apply (Nat.mul_cancel_l _ _ (b * (b - 1))); [nia|]. lia.
Qed.

Theorem Sb_size2 : 2 <= b -> b * (b - 1) * c2 = length Sb.
Proof. intro Hb. unfold Sb. rewrite map_length. apply per_pair; lia. Qed.

End Symmetric.

(** Owen's pair lemma for the full-tree oracle's node law, uniform over S_b, in every base
    b ≥ 2 (2, 4, 8, 16, 256 among them, and the bases that are not powers of two). *)
Theorem symmetric_pair_lemma : forall b, 2 <= b ->
  forall k m p d d' r r' q e e' s s',
  length p = k -> length q = k -> length r = m -> length r' = m -> length s = m ->
  length s' = m -> valid b p -> valid b q -> valid b r -> valid b r' -> valid b s ->
  valid b s' -> d < b -> d' < b -> e < b -> e' < b -> d <> d' -> e <> e' ->
  b ^ k * (b * (b - 1)) * b ^ (2 * m) *
    cnt (fun t => leqb (act t (p ++ d :: r)) (q ++ e :: s) &&
                  leqb (act t (p ++ d' :: r')) (q ++ e' :: s')) (trees b (Sb b) (k + S m)) =
  length (trees b (Sb b) (k + S m)).
Proof.
  intros b Hb. apply (pair_lemma b Hb (Sb b) (c1 b) (Sb_transitive b Hb) (Sb_size b Hb)
                       (c2 b) (Sb_two_transitive b Hb) (Sb_size2 b Hb)).
Qed.

(** Not vacuous: the law is the whole symmetric group (3! and 4! tables, by computation). *)
Theorem Sb_sizes_3_4 : length (Sb 3) = 6 /\ length (Sb 4) = 24.
Proof. split; vm_compute; reflexivity. Qed.
