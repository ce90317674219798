(** * The rank criterion's counting half: a linear box key balances the boxes iff it is onto.

    For a digital net over GF(2) the box of point [i] under a shape is read off [i] linearly:
    its key (the stacked top digits of each coordinate, [k] bits in all) is [K i] for a map
    [K] with [K (i ⊕ j) = K i ⊕ K j] on the [2^m] indices. The shape holds (every box holds the
    same number of points) exactly when [K] hits every key ([balanced_iff_onto]): each key's
    fibre is a coset of the kernel ([fibre_is_kernel_size]), so all nonempty fibres are equal,
    and the [2^k] fibres sum to [2^m] ([fibres_sum]). The rank path (`crates/netcheck`) decides
    "onto" by the rank of the stacked rows: dependent rows leave keys unhit
    ([dependent_rows_miss_keys], below), so its "fails" is sound. `RankBasis.v` proves both
    directions for the XOR basis as `rank.rs` runs it ([independent_iff_balanced]). *)

From Coq Require Import List Arith Bool Lia Permutation.
From Gartowen Require Import Laws ArtWord NodeLaws Symmetric ArtMarginal.
Import ListNotations.

Lemma cnt_perm : forall A (P : A -> bool) l l', Permutation l l' -> cnt P l = cnt P l'.
Proof.
  intros A P l l' H. induction H; rewrite ?cnt_cons; lia.
Qed.

Lemma cnt_pos_exists : forall A (P : A -> bool) l, 0 < cnt P l -> exists x, In x l /\ P x = true.
Proof.
  intros A P l. induction l as [|a l IH]; intro H; [unfold cnt in H; simpl in H; lia|].
  rewrite cnt_cons in H. destruct (P a) eqn:E.
  - exists a. split; [left|]; auto.
  - destruct (IH ltac:(lia)) as [x [Hx Px]]. exists x. split; [right|]; auto.
Qed.

Section Linear.

Variables m k : nat.
Variable K : nat -> nat.
Hypothesis K_lt : forall x, x < 2 ^ m -> K x < 2 ^ k.
Hypothesis K_lin : forall x y, x < 2 ^ m -> y < 2 ^ m -> K (Nat.lxor x y) = Nat.lxor (K x) (K y).

Local Notation I := (seq 0 (2 ^ m)).

(** The number of indices whose key is [y]: the points in the box [y]. *)
Definition fibre (y : nat) : nat := cnt (fun x => K x =? y) I.

Lemma pow2_pos : forall n, 0 < 2 ^ n.
Proof. intro n. apply Nat.neq_0_lt_0, Nat.pow_nonzero. lia. Qed.

Lemma translation_permutes : forall x0, x0 < 2 ^ m ->
  Permutation (map (fun x => Nat.lxor x x0) I) I.
Proof.
  intros x0 H0. apply NoDup_Permutation.
  - apply NoDup_map_on; [|apply seq_NoDup].
    intros x y _ _ E. rewrite <- (lxor_twice x x0), E, lxor_twice. reflexivity.
  - apply seq_NoDup.
  - intro y. rewrite in_map_iff. split.
    + intros [x [<- Hx]]. apply in_seq in Hx. apply in_seq. split; [lia|].
      simpl. apply lxor_lt; lia.
    + intro Hy. exists (Nat.lxor y x0). split; [apply lxor_twice|].
      apply in_seq in Hy. apply in_seq. split; [lia|]. simpl. apply lxor_lt; lia.
Qed.

(** Every key that is hit is hit as often as 0 is: its fibre is a coset of the kernel. *)
Lemma fibre_is_kernel_size : forall x0, x0 < 2 ^ m -> fibre (K x0) = fibre 0.
Proof.
  intros x0 H0. unfold fibre.
  rewrite <- (cnt_perm _ _ _ _ (translation_permutes x0 H0)), cnt_map.
  apply cnt_ext. intros x Hx. apply in_seq in Hx. rewrite K_lin by lia.
  destruct (Nat.eqb_spec (Nat.lxor (K x) (K x0)) (K x0)) as [E|E];
  destruct (Nat.eqb_spec (K x) 0) as [F|F]; auto; exfalso.
  - apply F. apply (f_equal (fun v => Nat.lxor v (K x0))) in E.
    rewrite lxor_twice, Nat.lxor_nilpotent in E. exact E.
  - apply E. rewrite F. apply Nat.lxor_0_l.
Qed.

(** The [2^k] boxes hold the [2^m] points between them. *)
Lemma fibres_sum : sumL fibre (seq 0 (2 ^ k)) = 2 ^ m.
Proof.
  unfold fibre.
  rewrite <- (sumL_swap_cnt _ _ (fun x y => K x =? y)).
  rewrite (sumL_ext _ _ (fun _ => 1)).
  - rewrite sumL_const, seq_length. lia.
  - intros x Hx. apply in_seq in Hx.
    rewrite (cnt_ext _ _ (fun y => y =? K x)) by (intros; apply Nat.eqb_sym).
    apply cnt_seq_in. split; [lia|]. simpl. apply K_lt. lia.
Qed.

(** The shape holds ([2^(m−k)] points in every box) exactly when the key map is onto. *)
Theorem balanced_iff_onto : k <= m ->
  (forall y, y < 2 ^ k -> fibre y = 2 ^ (m - k)) <->
  (forall y, y < 2 ^ k -> exists x, x < 2 ^ m /\ K x = y).
Proof.
  intro Hkm. split.
  - intros B y Hy. pose proof (pow2_pos (m - k)) as P. rewrite <- (B y Hy) in P.
    apply cnt_pos_exists in P as [x [Hx E]]. apply in_seq in Hx. apply Nat.eqb_eq in E.
    exists x. split; [lia|exact E].
  - intros O y Hy.
    assert (All : forall z, z < 2 ^ k -> fibre z = fibre 0).
    { intros z Hz. destruct (O z Hz) as [x [Hx <-]]. apply fibre_is_kernel_size, Hx. }
    pose proof fibres_sum as S.
    rewrite (sumL_ext _ _ (fun _ => fibre 0)) in S
      by (intros z Hz; apply in_seq in Hz; apply All; lia).
    rewrite sumL_const, seq_length in S.
    rewrite All by exact Hy.
    replace (2 ^ m) with (2 ^ k * 2 ^ (m - k)) in S
      by (rewrite <- Nat.pow_add_r; f_equal; lia).
    apply (Nat.mul_cancel_l _ _ (2 ^ k)); [apply Nat.pow_nonzero; lia|exact S].
Qed.

End Linear.

(** ** Dependent rows leave keys unhit: the rank path's "fails" is sound

    Rows are masks over [n] index bits; bit j of a key is the GF(2) dot product of row j with
    the index. When a nonempty subset of the stacked rows XORs to zero (the rank path's XOR
    basis rejects a row), the key bits of that subset always XOR to zero, so every key whose
    bits there XOR to one is hit by no index: the key map is not onto and the shape fails
    ([dependent_rows_miss_keys]; with keys read as numbers, [balanced_iff_onto]). The converse
    (independent rows make the key onto) is `RankBasis.independent_iff_onto`. *)

Definition dot (n r i : nat) : bool :=
  fold_right xorb false (map (fun c => Nat.testbit r c && Nat.testbit i c) (seq 0 n)).

Lemma fold_xorb_map : forall (f g : nat -> bool) l,
  fold_right xorb false (map (fun c => xorb (f c) (g c)) l) =
  xorb (fold_right xorb false (map f l)) (fold_right xorb false (map g l)).
Proof.
  intros f g l. induction l as [|c l IH]; simpl; [reflexivity|]. rewrite IH.
  destruct (f c), (g c), (fold_right xorb false (map f l)), (fold_right xorb false (map g l));
    reflexivity.
Qed.

Lemma dot_lxor : forall n r r' i, dot n (Nat.lxor r r') i = xorb (dot n r i) (dot n r' i).
Proof.
  intros n r r' i. unfold dot. rewrite <- fold_xorb_map. f_equal. apply map_ext. intro c.
  rewrite Nat.lxor_spec. destruct (Nat.testbit r c), (Nat.testbit r' c), (Nat.testbit i c);
    reflexivity.
Qed.

Lemma dot_zero : forall n i, dot n 0 i = false.
Proof.
  intros n i. unfold dot. induction (seq 0 n) as [|c l IH]; simpl; [reflexivity|].
  rewrite IH, Nat.bits_0. reflexivity.
Qed.

(** The key of index [i]: one bit per row. *)
Definition key (n : nat) (rows : list nat) (i : nat) : list bool := map (fun r => dot n r i) rows.

(** The XOR of the selected rows, and the parity of a key's selected bits. *)
Fixpoint xor_sel (sel : list bool) (rows : list nat) : nat :=
  match sel, rows with
  | b :: sel', r :: rows' => if b then Nat.lxor r (xor_sel sel' rows') else xor_sel sel' rows'
  | _, _ => 0
  end.

Fixpoint parity (sel y : list bool) : bool :=
  match sel, y with
  | b :: sel', v :: y' => xorb (b && v) (parity sel' y')
  | _, _ => false
  end.

Lemma parity_key : forall n sel rows i, parity sel (key n rows i) = dot n (xor_sel sel rows) i.
Proof.
  intros n sel. induction sel as [|b sel IH]; intros rows i; simpl.
  - symmetry. apply dot_zero.
  - destruct rows as [|r rows]; simpl; [symmetry; apply dot_zero|].
    rewrite IH. destruct b; simpl.
    + rewrite dot_lxor. reflexivity.
    + destruct (dot n (xor_sel sel rows) i); reflexivity.
Qed.

(** The key with one bit set, at the first selected row. *)
Fixpoint first_one (sel : list bool) : list bool :=
  match sel with
  | [] => []
  | true :: r => true :: map (fun _ => false) r
  | false :: r => false :: first_one r
  end.

Lemma parity_zeros : forall sel (l : list bool), parity sel (map (fun _ => false) l) = false.
Proof.
  induction sel as [|b sel IH]; intros [|x l]; simpl; auto. rewrite IH, andb_false_r. reflexivity.
Qed.

Lemma first_one_spec : forall sel, existsb (fun b => b) sel = true ->
  length (first_one sel) = length sel /\ parity sel (first_one sel) = true.
Proof.
  induction sel as [|b sel IH]; simpl; [discriminate|]. intro H. destruct b; simpl.
  - rewrite map_length, parity_zeros. split; reflexivity.
  - destruct (IH H) as [L P]. rewrite L, P. split; reflexivity.
Qed.

Theorem dependent_rows_miss_keys : forall n rows sel,
  length sel = length rows -> existsb (fun b => b) sel = true -> xor_sel sel rows = 0 ->
  exists y, length y = length rows /\ forall i, key n rows i <> y.
Proof.
  intros n rows sel L S Z. destruct (first_one_spec sel S) as [Ly Py].
  exists (first_one sel). split; [congruence|].
  intros i E. rewrite <- E, parity_key, Z, dot_zero in Py. discriminate.
Qed.
