(** * Digital nets in base 2^q: the rank path's verdict is [is_net].

    A digital net of [2^(q·m)] points in [s] dimensions with [n]-digit coordinates in base
    2^q is given by rows [G j r] (row [r] of coordinate [j]'s generator matrix, a mask over
    the [D = q·m] index bits): digit [k] of coordinate [j] of point [i] is the q-bit number
    whose bits, most significant first, are the GF(2) dot products of rows [q·k], …,
    [q·k + q − 1] with [i] ([net_points]; `rank.rs` reads row r as bit r from the top of the
    coordinate word). A box of shape [d] holds point [i] exactly when the first [q·d_j] rows of
    each coordinate, stacked, give [i] the key spelled by the bits of the box's digits
    ([in_box_iff_key]), so every box's count is that key's fibre ([count_is_fibre]). With
    [RankBasis.independent_iff_balanced]: the points are a [(t, m, s)]-net in base 2^q
    ([Nested.is_net]) exactly when the XOR basis accepts the stacked rows of every shape with
    [Σ d_j = m − t] ([rank_path_is_net]). The depth-first search of `rank.rs`, which shares a
    prefix's basis among its completions, is not modelled (it is tested by extraction). *)

From Coq Require Import List Arith Bool Lia.
From Gartowen Require Import Nested Laws ArtWord NodeLaws Symmetric ArtMarginal Rank RankBasis.
Import ListNotations.

(** ** Lists *)

Lemma app_eq_same_length : forall A (l1 l2 l1' l2' : list A), length l1 = length l1' ->
  l1 ++ l2 = l1' ++ l2' -> l1 = l1' /\ l2 = l2'.
Proof.
  induction l1 as [|a l1 IH]; intros l2 [|a' l1'] l2' L E; simpl in *; try lia; [auto|].
  injection E as <- E. destruct (IH l2 l1' l2' ltac:(lia) E) as [-> ->]. auto.
Qed.

Lemma firstn_seq0 : forall k n, k <= n -> firstn k (seq 0 n) = seq 0 k.
Proof.
  intros k n H. rewrite <- (Nat.sub_add k n H), Nat.add_comm, seq_app, firstn_app, seq_length,
    Nat.sub_diag, firstn_O, app_nil_r, firstn_all2 by (rewrite seq_length; lia). reflexivity.
Qed.

(** Cut a list into pieces of the given lengths. *)
Fixpoint cut {A} (d : list nat) (l : list A) : list (list A) :=
  match d with
  | [] => []
  | k :: d' => firstn k l :: cut d' (skipn k l)
  end.

Lemma cut_spec : forall A d (l : list A), length l = sum d ->
  concat (cut d l) = l /\ map (@length A) (cut d l) = d.
Proof.
  induction d as [|k d IH]; intros l L; simpl in *.
  - destruct l; [auto|discriminate].
  - destruct (IH (skipn k l)) as [C S]; [rewrite skipn_length; lia|].
    rewrite C, firstn_skipn, S, firstn_length. split; [reflexivity|]. f_equal. lia.
Qed.

Lemma cut_in : forall A d (l : list A) p x, In p (cut d l) -> In x p -> In x l.
Proof.
  intros A d. induction d as [|k d IH]; intros l p x Hp Hx; simpl in Hp; [contradiction|].
  destruct Hp as [<-|Hp].
  - rewrite <- (firstn_skipn k l). apply in_or_app. left. exact Hx.
  - apply (IH _ _ _ Hp) in Hx. rewrite <- (firstn_skipn k l). apply in_or_app. right. exact Hx.
Qed.

Lemma num_inj : forall l l', length l = length l' -> num l = num l' -> l = l'.
Proof.
  intros l l' L E. apply (nth_ext _ _ false false L). intros j _.
  rewrite <- !num_bits, E. reflexivity.
Qed.

Lemma num_of_bits : forall y k, y < 2 ^ k -> num (map (Nat.testbit y) (seq 0 k)) = y.
Proof.
  intros y k Hy. apply Nat.bits_inj. intro j. rewrite num_bits.
  destruct (Nat.lt_ge_cases j k) as [L|L].
  - rewrite (nth_indep _ false (Nat.testbit y 0)) by (rewrite map_length, seq_length; exact L).
    rewrite map_nth, seq_nth by exact L. reflexivity.
  - rewrite nth_overflow by (rewrite map_length, seq_length; exact L). symmetry.
    apply small_no_bit. apply (Nat.lt_le_trans _ (2 ^ k)); [exact Hy|apply Nat.pow_le_mono_r; lia].
Qed.

Section Digits.

Variable q : nat.

(** A digit from its q bits, most significant first, and back. *)
Definition digit_value (bs : list bool) : nat := num (rev bs).
Definition digit_bits (v : nat) : list bool := rev (map (Nat.testbit v) (seq 0 q)).

Lemma digit_bits_length : forall v, length (digit_bits v) = q.
Proof. intro v. unfold digit_bits. rewrite rev_length, map_length, seq_length. reflexivity. Qed.

Lemma digit_value_lt : forall bs, length bs = q -> digit_value bs < 2 ^ q.
Proof. intros bs L. unfold digit_value. rewrite <- L, <- rev_length. apply num_lt. Qed.

Lemma digit_iff : forall bs v, length bs = q -> v < 2 ^ q ->
  digit_value bs = v <-> bs = digit_bits v.
Proof.
  intros bs v L Hv. unfold digit_value, digit_bits. split; intro E.
  - rewrite <- (num_of_bits v q Hv) in E. apply num_inj in E.
    + rewrite <- E, rev_involutive. reflexivity.
    + rewrite rev_length, map_length, seq_length. exact L.
  - rewrite E, rev_involutive. apply num_of_bits, Hv.
Qed.

Lemma seq_groups : forall d, seq 0 (q * d) = flat_map (fun k => map (fun u => q * k + u) (seq 0 q)) (seq 0 d).
Proof.
  induction d as [|d IH]; [rewrite Nat.mul_0_r; reflexivity|].
  rewrite seq_S, flat_map_app, <- IH. simpl. rewrite app_nil_r.
  replace (q * S d) with (q * d + q) by lia. rewrite seq_app. f_equal.
  clear. simpl. generalize (q * d) as a. generalize q as len. intros len.
  induction len as [|len IH]; intro a; [reflexivity|].
  rewrite !seq_S, map_app, IH; simpl; repeat f_equal; lia.
Qed.

End Digits.

Section Net.

Variables q D s n : nat.
Variable G : nat -> nat -> nat.

Definition digit_rows_bits (j k i : nat) : list bool :=
  map (fun u => dot D (G j (q * k + u)) i) (seq 0 q).

Definition coord (j i : nat) : list nat :=
  map (fun k => digit_value (digit_rows_bits j k i)) (seq 0 n).
Definition point (i : nat) : list (list nat) := map (fun j => coord j i) (seq 0 s).
Definition net_points : list (list (list nat)) := map point (seq 0 (2 ^ D)).

Fixpoint rows_from (j : nat) (d : list nat) : list nat :=
  match d with
  | [] => []
  | k :: d' => map (G j) (seq 0 (q * k)) ++ rows_from (S j) d'
  end.

(** The stacked rows of a base-2^q shape [d]: the first [q·d_j] rows of each coordinate. *)
Definition shape_rows (d : list nat) : list nat := rows_from 0 d.

Lemma rows_from_length : forall d j, length (rows_from j d) = q * sum d.
Proof.
  induction d as [|k d IH]; intro j; simpl; [lia|].
  rewrite app_length, map_length, seq_length, IH. lia.
Qed.

(** The bits of a box's digits, in the order of the stacked rows. *)
Definition box_bits (B : list (list nat)) : list bool :=
  concat (map (fun p => concat (map (digit_bits q) p)) B).

Lemma concat_groups : forall (l l' : list (list bool)), Forall (fun g => length g = q) l ->
  Forall (fun g => length g = q) l' -> concat l = concat l' -> length l = length l' -> l = l'.
Proof.
  induction l as [|g l IH]; intros [|g' l'] F F' E L; simpl in *; try lia; [reflexivity|].
  inversion F; inversion F'; subst.
  apply app_eq_same_length in E as [<- E]; [|congruence].
  f_equal. apply IH; auto.
Qed.

Lemma prefix_coord : forall p j i, length p <= n -> Forall (fun x => x < 2 ^ q) p ->
  prefix_of p (coord j i) = true <->
  map (fun r => dot D r i) (map (G j) (seq 0 (q * length p))) = concat (map (digit_bits q) p).
Proof.
  intros p j i Lp Vp. unfold prefix_of, coord. rewrite firstn_map, firstn_seq0 by exact Lp.
  rewrite map_map, seq_groups, flat_map_concat_map, concat_map, map_map.
  assert (Groups : forall k, length (map (fun x => dot D (G j x) i)
                     (map (fun u => q * k + u) (seq 0 q))) = q)
    by (intro k; rewrite !map_length, seq_length; reflexivity).
  split.
  - intro H. destruct (list_eq_dec _ _ _) as [E|]; [|discriminate]. rewrite <- E at 2.
    rewrite map_map. f_equal. apply map_ext. intro k.
    symmetry. unfold digit_rows_bits. rewrite map_map. symmetry.
    apply (proj1 (digit_iff q _ _ ltac:(rewrite map_length, seq_length; reflexivity)
                   (digit_value_lt q _ ltac:(rewrite map_length, seq_length; reflexivity)))).
    reflexivity.
  - intro E. apply concat_groups in E.
    + destruct (list_eq_dec _ _ _) as [_|N]; [reflexivity|exfalso; apply N].
      transitivity (map digit_value (map (digit_bits q) p)).
      * rewrite <- E, map_map. apply map_ext. intro k. unfold digit_rows_bits.
        rewrite map_map. reflexivity.
      * rewrite map_map. rewrite <- (map_id p) at 2. apply map_ext_in. intros v Hv.
        rewrite Forall_forall in Vp.
        apply (proj2 (digit_iff q (digit_bits q v) v (digit_bits_length q v) (Vp v Hv))).
        reflexivity.
    + apply Forall_forall. intros g Hg. apply in_map_iff in Hg as [k [<- _]]. apply Groups.
    + apply Forall_forall. intros g Hg. apply in_map_iff in Hg as [v [<- _]]. apply digit_bits_length.
    + rewrite !map_length, seq_length. reflexivity.
Qed.

Lemma box_digits_length : forall p, length (concat (map (digit_bits q) p)) = q * length p.
Proof.
  induction p as [|v p IH]; simpl; [lia|]. rewrite app_length, IH, digit_bits_length. lia.
Qed.

Lemma box_bits_length : forall B, length (box_bits B) = q * sum (map (@length nat) B).
Proof.
  induction B as [|p B IH]; simpl; [lia|]. unfold box_bits in *. simpl.
  rewrite app_length, IH, box_digits_length. lia.
Qed.

Lemma in_box_from : forall B j i, Forall (fun p => length p <= n) B ->
  Forall (fun p => Forall (fun x => x < 2 ^ q) p) B ->
  in_box B (map (fun j' => coord j' i) (seq j (length B))) = true <->
  map (fun r => dot D r i) (rows_from j (map (@length nat) B)) = box_bits B.
Proof.
  induction B as [|p B IH]; intros j i Ln Lv; [simpl; split; reflexivity|].
  inversion Ln as [|? ? Lp LB]; inversion Lv as [|? ? Vp VB]; subst.
  simpl. rewrite andb_true_iff, IH by assumption. rewrite map_app.
  unfold box_bits. simpl. fold (box_bits B).
  rewrite (prefix_coord p j i Lp Vp), map_map. split.
  - intros [P Q]. rewrite P, Q. reflexivity.
  - intro E. apply app_eq_same_length in E as [E1 E2]; [split; assumption|].
    rewrite map_length, seq_length, box_digits_length. reflexivity.
Qed.

Theorem in_box_iff_key : forall B i, length B = s -> Forall (fun p => length p <= n) B ->
  Forall (fun p => Forall (fun x => x < 2 ^ q) p) B ->
  in_box B (point i) = true <->
  keynum D (shape_rows (map (@length nat) B)) i = num (box_bits B).
Proof.
  intros B i Ls Ln Lv. unfold point. rewrite <- Ls, (in_box_from B 0 i Ln Lv).
  unfold shape_rows, keynum. split; [intro E; rewrite E; reflexivity|].
  intro E. apply num_inj in E; [exact E|].
  rewrite map_length, rows_from_length, box_bits_length. reflexivity.
Qed.

Lemma count_is_fibre : forall B, length B = s -> Forall (fun p => length p <= n) B ->
  Forall (fun p => Forall (fun x => x < 2 ^ q) p) B ->
  count B net_points =
  fibre D (keynum D (shape_rows (map (@length nat) B))) (num (box_bits B)).
Proof.
  intros B Ls Ln Lv. unfold count, net_points, fibre.
  change (length (filter (in_box B) (map point (seq 0 (2 ^ D)))))
    with (cnt (in_box B) (map point (seq 0 (2 ^ D)))).
  rewrite cnt_map. apply cnt_ext. intros i _. apply eq_iff_eq_true. rewrite Nat.eqb_eq.
  apply in_box_iff_key; assumption.
Qed.

Lemma rows_small : (forall j k, G j k < 2 ^ D) -> forall d j r, In r (rows_from j d) -> r < 2 ^ D.
Proof.
  intros Small d. induction d as [|k d IH]; intros j r Hr; simpl in Hr; [contradiction|].
  apply in_app_or in Hr as [Hr|Hr]; [|apply (IH (S j)), Hr].
  apply in_map_iff in Hr as [k' [<- _]]. apply Small.
Qed.

End Net.

Lemma sum_repeat : forall q k, sum (repeat q k) = q * k.
Proof. intros q k. induction k as [|k IH]; simpl; [lia|]. unfold sum in *. simpl. rewrite IH. lia. Qed.

Lemma concat_map_concat : forall A B (f : A -> list B) (L : list (list A)),
  concat (map (fun p => concat (map f p)) L) = concat (map f (concat L)).
Proof.
  intros A B f L. induction L as [|p L IH]; simpl; [reflexivity|].
  rewrite IH, map_app, concat_app. reflexivity.
Qed.

(** The rank path decides [is_net] in base 2^q: the [2^(q·m)] points are a [(t, m, s)]-net
    in base 2^q exactly when the XOR basis accepts the stacked rows (the first [q·d_j] of each
    coordinate) of every shape of [s] parts (each at most [n]) summing to [m − t]. *)
Theorem rank_path_is_net : forall q D s n G m t, D = q * m -> t <= m ->
  (forall j k, G j k < 2 ^ D) ->
  is_net (2 ^ q) n m t s (net_points q D s n G) <->
  (forall d, length d = s -> Forall (fun k => k <= n) d -> sum d = m - t ->
     independent D (shape_rows q G d) = true).
Proof.
  intros q D s n G m t HD Ht Small. split.
  - intros [_ [_ Boxes]] d Ld Fd Sd.
    assert (Lr : length (shape_rows q G d) = q * (m - t))
      by (unfold shape_rows; rewrite rows_from_length, Sd; reflexivity).
    apply independent_iff_balanced;
      [intros r Hr; apply (rows_small q D G Small d 0 r Hr)|rewrite Lr, HD; nia|].
    intros y Hy. rewrite Lr in Hy |- *.
    set (bl := map (Nat.testbit y) (seq 0 (q * (m - t)))).
    set (groups := cut (repeat q (m - t)) bl).
    destruct (cut_spec bool (repeat q (m - t)) bl) as [Cg Sg];
      [unfold bl; rewrite map_length, seq_length, sum_repeat; reflexivity|].
    fold groups in Cg, Sg.
    assert (Gq : forall g, In g groups -> length g = q).
    { intros g Hg. assert (In (length g) (repeat q (m - t))) by (rewrite <- Sg; apply in_map, Hg).
      apply repeat_spec in H. exact H. }
    set (digits := map digit_value groups).
    assert (Ldig : length digits = sum d).
    { unfold digits. rewrite map_length, <- (map_length (@length bool)), Sg, repeat_length. lia. }
    set (B := cut d digits).
    destruct (cut_spec nat d digits Ldig) as [CB SB]. fold B in CB, SB.
    assert (Digits : Forall (fun p => Forall (fun x => x < 2 ^ q) p) B).
    { apply Forall_forall. intros p Hp. apply Forall_forall. intros x Hx.
      apply (cut_in _ _ _ _ _ Hp) in Hx. apply in_map_iff in Hx as [g [<- Hg]].
      apply digit_value_lt, Gq, Hg. }
    assert (LBs : length B = s) by (rewrite <- (map_length (@length nat) B), SB; exact Ld).
    assert (Ln : Forall (fun p => length p <= n) B).
    { apply Forall_forall. intros p Hp. rewrite Forall_forall in Fd. apply Fd.
      rewrite <- SB. apply in_map, Hp. }
    assert (Bits : box_bits q B = bl).
    { unfold box_bits. rewrite concat_map_concat, CB. unfold digits. rewrite map_map.
      rewrite <- Cg. f_equal. rewrite <- (map_id groups) at 2. apply map_ext_in.
      intros g Hg. symmetry.
      apply (proj1 (digit_iff q g _ (Gq g Hg) (digit_value_lt q g (Gq g Hg)))). reflexivity. }
    pose proof (Boxes B LBs Digits Ln) as C. unfold shape in C. rewrite SB in C.
    specialize (C Sd). rewrite count_is_fibre, SB, Bits in C by assumption.
    unfold bl in C. rewrite num_of_bits in C by exact Hy.
    rewrite C, <- Nat.pow_mul_r. f_equal. rewrite HD. nia.
  - intro I. split; [|split].
    + unfold net_points. rewrite map_length, seq_length, HD, Nat.pow_mul_r. reflexivity.
    + apply Forall_forall. intros P HP. unfold net_points in HP.
      apply in_map_iff in HP as [i [<- _]]. unfold point. split; [|split].
      * rewrite map_length, seq_length. reflexivity.
      * apply Forall_forall. intros x Hx. apply in_map_iff in Hx as [j [<- _]].
        apply Forall_forall. intros v Hv. unfold coord in Hv.
        apply in_map_iff in Hv as [k [<- _]]. apply digit_value_lt.
        unfold digit_rows_bits. rewrite map_length, seq_length. reflexivity.
      * apply Forall_forall. intros x Hx. apply in_map_iff in Hx as [j [<- _]].
        unfold coord. rewrite map_length, seq_length. reflexivity.
    + intros B LB VB LnB SB. unfold shape in SB.
      assert (Digits : Forall (fun p => Forall (fun x => x < 2 ^ q) p) B) by exact VB.
      rewrite count_is_fibre by assumption.
      set (d := map (@length nat) B) in *.
      assert (Lr : length (shape_rows q G d) = q * (m - t))
        by (unfold shape_rows; rewrite rows_from_length, SB; reflexivity).
      pose proof (I d ltac:(unfold d; rewrite map_length; exact LB)
                    ltac:(unfold d; apply Forall_forall; intros k Hk;
                          apply in_map_iff in Hk as [p [<- Hp]];
                          rewrite Forall_forall in LnB; apply LnB, Hp) SB) as Ind.
      pose proof (proj1 (independent_iff_balanced D (shape_rows q G d)
                      (fun r Hr => rows_small q D G Small d 0 r Hr)
                      ltac:(rewrite Lr, HD; nia)) Ind) as Bal.
      rewrite Lr in Bal. rewrite Bal.
      * rewrite <- Nat.pow_mul_r. f_equal. rewrite HD. nia.
      * assert (Lb : length (box_bits q B) = q * (m - t))
          by (rewrite box_bits_length; fold d; rewrite SB; reflexivity).
        rewrite <- Lb. apply num_lt.
Qed.
