(** * Binary digital nets: the rank path's verdict is [is_net].

    A binary digital net of [2^D] points in [s] dimensions with [n]-bit coordinates is given by
    rows [G j k] (row [k] of coordinate [j]'s generator matrix, a mask over the [D] index
    bits): bit [k] of coordinate [j] of point [i] is the GF(2) dot product of [G j k] with [i]
    ([net_points]). A box of shape [d] (prefixes of [d_j] bits) holds point [i] exactly when
    the stacked rows [shape_rows d] (the first [d_j] rows of each coordinate) give [i] the key
    spelled by the box's bits ([in_box_iff_key]), so the box's count is that key's fibre
    ([count_is_fibre]). With [RankBasis.independent_iff_balanced]: the points are a
    [(t, m, s)]-net in base 2 ([Nested.is_net]) exactly when the XOR basis accepts the stacked
    rows of every shape with [Σ d_j = m − t] ([rank_path_is_net]). Base 2^q is the binary case
    of shape [q·d] (`rank.rs` stacks [q·d_j] rows); that step is not modelled here. *)

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

(** Cut a list into blocks of the given lengths. *)
Fixpoint blocks (d l : list nat) : list (list nat) :=
  match d with
  | [] => []
  | k :: d' => firstn k l :: blocks d' (skipn k l)
  end.

Lemma blocks_spec : forall d l, length l = sum d ->
  concat (blocks d l) = l /\ map (@length nat) (blocks d l) = d.
Proof.
  induction d as [|k d IH]; intros l L; simpl in *.
  - destruct l; [auto|discriminate].
  - destruct (IH (skipn k l)) as [C S]; [rewrite skipn_length; lia|].
    rewrite C, firstn_skipn, S, firstn_length. split; [reflexivity|]. f_equal. lia.
Qed.

Lemma blocks_in : forall d l p x, In p (blocks d l) -> In x p -> In x l.
Proof.
  induction d as [|k d IH]; intros l p x Hp Hx; simpl in Hp; [contradiction|].
  destruct Hp as [<-|Hp].
  - rewrite <- (firstn_skipn k l). apply in_or_app. left. exact Hx.
  - apply (IH _ _ _ Hp) in Hx. rewrite <- (firstn_skipn k l). apply in_or_app. right. exact Hx.
Qed.

Lemma num_inj : forall l l', length l = length l' -> num l = num l' -> l = l'.
Proof.
  intros l l' L E. apply (nth_ext _ _ false false L). intros j _.
  rewrite <- !num_bits, E. reflexivity.
Qed.

(** ** The net and its boxes *)

Section Net.

Variables D s n : nat.
Variable G : nat -> nat -> nat.

Definition coord (j i : nat) : list nat := map (fun k => Nat.b2n (dot D (G j k) i)) (seq 0 n).
Definition point (i : nat) : list (list nat) := map (fun j => coord j i) (seq 0 s).
Definition net_points : list (list (list nat)) := map point (seq 0 (2 ^ D)).

Fixpoint rows_from (j : nat) (d : list nat) : list nat :=
  match d with
  | [] => []
  | k :: d' => map (G j) (seq 0 k) ++ rows_from (S j) d'
  end.

(** The stacked rows of shape [d]: the first [d_j] rows of each coordinate. *)
Definition shape_rows (d : list nat) : list nat := rows_from 0 d.

Lemma rows_from_length : forall d j, length (rows_from j d) = sum d.
Proof.
  induction d as [|k d IH]; intro j; simpl; [reflexivity|].
  rewrite app_length, map_length, seq_length, IH. reflexivity.
Qed.

(** The box's bits as booleans. *)
Definition box_bits (B : list (list nat)) : list bool := map (fun x => x =? 1) (concat B).

Lemma in_box_from : forall B j i, Forall (fun p => length p <= n) B ->
  in_box B (map (fun j' => coord j' i) (seq j (length B))) = true <->
  map (fun r => Nat.b2n (dot D r i)) (rows_from j (map (@length nat) B)) = concat B.
Proof.
  induction B as [|p B IH]; intros j i Ln; [simpl; split; reflexivity|].
  inversion Ln as [|? ? Lp LB]; subst.
  simpl. rewrite andb_true_iff, IH by exact LB. rewrite map_app, map_map.
  unfold prefix_of, coord. rewrite firstn_map, firstn_seq0 by exact Lp.
  split.
  - intros [P Q]. destruct (list_eq_dec _ _ _) as [E|]; [|discriminate]. rewrite E, Q. reflexivity.
  - intro E. apply app_eq_same_length in E as [E1 E2];
      [|rewrite map_length, seq_length; reflexivity].
    split; [|exact E2]. destruct (list_eq_dec _ _ _) as [_|N]; [reflexivity|contradiction].
Qed.

(** A box of [s] prefixes of at most [n] bits holds point [i] exactly when the stacked rows of
    its shape give [i] the key its bits spell. *)
Theorem in_box_iff_key : forall B i, length B = s -> Forall (fun p => length p <= n) B ->
  Forall (fun p => Forall (fun x => x < 2) p) B ->
  in_box B (point i) = true <->
  keynum D (shape_rows (map (@length nat) B)) i = num (box_bits B).
Proof.
  intros B i Ls Ln Lv. unfold point. rewrite <- Ls, (in_box_from B 0 i Ln).
  unfold shape_rows, keynum, box_bits.
  assert (Len : length (map (fun r => dot D r i) (rows_from 0 (map (@length nat) B))) =
                length (map (fun x => x =? 1) (concat B))).
  { rewrite !map_length, rows_from_length. clear. induction B as [|p B IH]; simpl; [reflexivity|].
    rewrite app_length, IH. reflexivity. }
  assert (Bits : concat B = map Nat.b2n (map (fun x => x =? 1) (concat B))).
  { rewrite map_map. symmetry. rewrite <- (map_id (concat B)) at 2. apply map_ext_in.
    intros x Hx. apply in_concat in Hx as [p [Hp Hx]]. rewrite Forall_forall in Lv.
    pose proof (proj1 (Forall_forall _ _) (Lv p Hp) x Hx). destruct x as [|[|x]]; simpl; lia. }
  split.
  - intro E. f_equal. rewrite Bits, <- map_map in E. clear Bits.
    apply (f_equal (map (fun v => v =? 1))) in E. rewrite !map_map in E.
    rewrite (map_ext (fun x => Nat.b2n (dot D x i) =? 1) (fun x => dot D x i)) in E
      by (intro x; destruct (dot D x i); reflexivity).
    rewrite (map_ext (fun x => Nat.b2n (x =? 1) =? 1) (fun x => x =? 1)) in E
      by (intro x; destruct (x =? 1); reflexivity).
    exact E.
  - intro E. apply num_inj in E; [|exact Len]. rewrite Bits, <- E, map_map. reflexivity.
Qed.

Lemma count_is_fibre : forall B, length B = s -> Forall (fun p => length p <= n) B ->
  Forall (fun p => Forall (fun x => x < 2) p) B ->
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

Lemma concat_length_sum : forall (B : list (list nat)), length (concat B) = sum (map (@length nat) B).
Proof. induction B as [|p B IH]; simpl; [reflexivity|]. rewrite app_length, IH. reflexivity. Qed.

Lemma num_of_bits : forall y k, y < 2 ^ k -> num (map (Nat.testbit y) (seq 0 k)) = y.
Proof.
  intros y k Hy. apply Nat.bits_inj. intro j. rewrite num_bits.
  destruct (Nat.lt_ge_cases j k) as [L|L].
  - rewrite (nth_indep _ false (Nat.testbit y 0)) by (rewrite map_length, seq_length; exact L).
    rewrite map_nth, seq_nth by exact L. reflexivity.
  - rewrite nth_overflow by (rewrite map_length, seq_length; exact L). symmetry.
    apply small_no_bit. apply (Nat.lt_le_trans _ (2 ^ k)); [exact Hy|apply Nat.pow_le_mono_r; lia].
Qed.

(** The rank path decides [is_net] for binary digital nets: the [2^m] points are a
    [(t, m, s)]-net in base 2 exactly when the XOR basis accepts the stacked rows of every
    shape of [s] parts (each at most [n]) summing to [m − t]. *)
Theorem rank_path_is_net : forall m t, D = m -> t <= m -> (forall j k, G j k < 2 ^ D) ->
  is_net 2 n m t s net_points <->
  (forall d, length d = s -> Forall (fun k => k <= n) d -> sum d = m - t ->
     independent D (shape_rows d) = true).
Proof.
  intros m t HD Ht Small. split.
  - intros [_ [_ Boxes]] d Ld Fd Sd.
    assert (Lr : length (shape_rows d) = m - t) by (unfold shape_rows; rewrite rows_from_length; exact Sd).
    apply independent_iff_balanced; [intros r Hr; apply (rows_small Small d 0 r Hr)|lia|].
    intros y Hy. rewrite Lr in Hy |- *.
    set (bl := map (Nat.testbit y) (seq 0 (m - t))).
    set (B := blocks d (map Nat.b2n bl)).
    assert (LB : length (map Nat.b2n bl) = sum d) by (unfold bl; rewrite !map_length, seq_length; lia).
    destruct (blocks_spec d _ LB) as [CB SB]. fold B in CB, SB.
    assert (Digits : Forall (fun p => Forall (fun x => x < 2) p) B).
    { apply Forall_forall. intros p Hp. apply Forall_forall. intros x Hx.
      apply (blocks_in _ _ _ _ Hp) in Hx. apply in_map_iff in Hx as [v [<- _]].
      destruct v; simpl; lia. }
    assert (LBs : length B = s) by (rewrite <- (map_length (@length nat) B), SB; exact Ld).
    assert (Ln : Forall (fun p => length p <= n) B).
    { apply Forall_forall. intros p Hp. rewrite Forall_forall in Fd. apply Fd.
      rewrite <- SB. apply in_map, Hp. }
    pose proof (Boxes B LBs Digits Ln) as C. unfold shape in C. rewrite SB in C.
    specialize (C Sd). rewrite count_is_fibre, SB in C by assumption.
    unfold box_bits in C. rewrite CB, map_map in C.
    rewrite (map_ext (fun x => Nat.b2n x =? 1) (fun x => x)) in C by (intros [|]; reflexivity).
    rewrite map_id in C. unfold bl in C. rewrite num_of_bits in C by exact Hy.
    rewrite C. f_equal. lia.
  - intro I. split; [|split].
    + unfold net_points. rewrite map_length, seq_length, HD. reflexivity.
    + apply Forall_forall. intros P HP. unfold net_points in HP.
      apply in_map_iff in HP as [i [<- _]]. unfold point. split; [|split].
      * rewrite map_length, seq_length. reflexivity.
      * apply Forall_forall. intros x Hx. apply in_map_iff in Hx as [j [<- _]].
        apply Forall_forall. intros v Hv. unfold coord in Hv.
        apply in_map_iff in Hv as [k [<- _]]. destruct (dot D (G j k) i); simpl; lia.
      * apply Forall_forall. intros x Hx. apply in_map_iff in Hx as [j [<- _]].
        unfold coord. rewrite map_length, seq_length. reflexivity.
    + intros B LB VB LnB SB. unfold shape in SB.
      assert (Digits : Forall (fun p => Forall (fun x => x < 2) p) B) by exact VB.
      rewrite count_is_fibre by assumption.
      set (d := map (@length nat) B) in *.
      assert (Lr : length (shape_rows d) = m - t)
        by (unfold shape_rows; rewrite rows_from_length; exact SB).
      pose proof (I d ltac:(unfold d; rewrite map_length; exact LB)
                    ltac:(unfold d; apply Forall_forall; intros k Hk;
                          apply in_map_iff in Hk as [p [<- Hp]];
                          rewrite Forall_forall in LnB; apply LnB, Hp) SB) as Ind.
      pose proof (proj1 (independent_iff_balanced D (shape_rows d)
                      (fun r Hr => rows_small Small d 0 r Hr) ltac:(lia)) Ind) as Bal.
      rewrite Lr in Bal. rewrite Bal.
      * f_equal. lia.
      * assert (Lb : length (box_bits B) = m - t)
          by (unfold box_bits; rewrite map_length, concat_length_sum; exact SB).
        rewrite <- Lb. apply num_lt.
Qed.

End Net.
