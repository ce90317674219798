(** * Monotonicity of the net property: a (t,m,s)-net is a (t+1,m,s)-net.

    The t-value the checker prints is the least t for which the set is a net; "least" only means
    what users read it to mean if every larger t holds too. An elementary box of m − t − 1 digits
    that still has room in some coordinate (fewer than n digits there) is the disjoint union of
    the b boxes that refine that coordinate by one more digit, each of m − t digits, so it holds
    b · b^t points. Room exists whenever m − t ≤ s·n: below that the (t,m,s) condition asks about
    boxes of m − t digits, which have room, and the refinement step always applies. *)

From Coq Require Import List Arith Bool Lia.
Import ListNotations.
From Gartowen Require Import Laws Symmetric Nested Checker.

Section Monotone.

Variable b : nat.

(** Coordinate [j] of box [B] refined by digit [d]. *)
Fixpoint refine (j d : nat) (B : list (list nat)) : list (list nat) :=
  match B, j with
  | [], _ => []
  | p :: B', 0 => (p ++ [d]) :: B'
  | p :: B', S j' => p :: refine j' d B'
  end.

Definition sum_digits (f : nat -> nat) : nat := sumL f (seq 0 b).

Lemma firstn_S_nth : forall (x : list nat) k, k < length x ->
  firstn (S k) x = firstn k x ++ [nth k x 0].
Proof.
  induction x as [|a x IH]; intros k H; simpl in H; [lia|].
  destruct k; simpl; auto. f_equal. apply IH. lia.
Qed.

Lemma prefix_of_snoc : forall p x d, length p < length x ->
  prefix_of (p ++ [d]) x = prefix_of p x && (nth (length p) x 0 =? d).
Proof.
  intros p x d H. unfold prefix_of. rewrite app_length. simpl.
  rewrite Nat.add_1_r, firstn_S_nth by exact H.
  destruct (list_eq_dec Nat.eq_dec (firstn (length p) x ++ [nth (length p) x 0]) (p ++ [d]))
    as [E|E];
  destruct (list_eq_dec Nat.eq_dec (firstn (length p) x) p) as [F|F]; simpl.
  - apply app_inj_tail in E as [_ E]. symmetry. now apply Nat.eqb_eq.
  - apply app_inj_tail in E as [E _]. contradiction.
  - symmetry. apply Nat.eqb_neq. intro N. apply E. now rewrite F, N.
  - reflexivity.
Qed.

(** Where point [P] lies in a refined box: in the box, with digit [d] next in coordinate [j]. *)
Lemma in_box_refine : forall B P j d,
  length B = length P -> j < length B -> length (nth j B []) < length (nth j P []) ->
  in_box (refine j d B) P =
    in_box B P && (nth (length (nth j B [])) (nth j P []) 0 =? d).
Proof.
  induction B as [|p B IH]; intros [|x P] j d L J N; simpl in *; try lia.
  destruct j as [|j]; simpl.
  - rewrite prefix_of_snoc by exact N.
    destruct (prefix_of p x), (in_box B P), (nth (length p) x 0 =? d); reflexivity.
  - rewrite IH by lia. destruct (prefix_of p x); reflexivity.
Qed.

Lemma sum_digits_one : forall x, x < b -> sum_digits (fun d => if x =? d then 1 else 0) = 1.
Proof.
  intros x H. unfold sum_digits. rewrite sumL_eqb_seq.
  replace ((0 <=? x) && (x <? 0 + b)) with true; auto.
  symmetry. apply andb_true_intro. split; [apply Nat.leb_le | apply Nat.ltb_lt]; lia.
Qed.

Lemma sum_digits_const : forall c, sum_digits (fun _ => c) = b * c.
Proof. intro c. unfold sum_digits. rewrite sumL_const', seq_length. lia. Qed.

Lemma sum_digits_ext : forall f g, (forall d, d < b -> f d = g d) ->
  sum_digits f = sum_digits g.
Proof.
  intros f g H. unfold sum_digits. apply sumL_ext. intros d Hd.
  apply in_seq in Hd. apply H. lia.
Qed.

(** The points of a box are those of its b refinements in coordinate [j], for well-formed
    points of [n]-digit coordinates when the box has room there. *)
Lemma count_refine : forall n s B Ps j,
  Forall (well_formed b n s) Ps -> length B = s -> j < s -> length (nth j B []) < n ->
  count B Ps = sum_digits (fun d => count (refine j d B) Ps).
Proof.
  intros n s B Ps j WF LB J N. induction Ps as [|P Ps IH].
  - unfold count. simpl. symmetry. rewrite sum_digits_const. lia.
  - inversion WF as [|P' Ps' WP WPs]; subst.
    destruct WP as [LP [VP NP]].
    assert (Lj : length (nth j P []) = n).
    { rewrite Forall_forall in NP. apply NP, nth_In. lia. }
    assert (Dj : nth (length (nth j B [])) (nth j P []) 0 < b).
    { unfold valid_point in VP. rewrite Forall_forall in VP.
      assert (Hin : In (nth j P []) P) by (apply nth_In; lia).
      assert (V := VP _ Hin).
      unfold valid in V. rewrite Forall_forall in V. apply V, nth_In. lia. }
    unfold count in *. simpl.
    rewrite (sum_digits_ext _
      (fun d => (if in_box (refine j d B) P then 1 else 0) +
                length (filter (in_box (refine j d B)) Ps))).
    2: { intros d _. simpl. destruct (in_box (refine j d B) P); reflexivity. }
    unfold sum_digits in *. rewrite sumL_plus, <- IH by assumption. fold (sum_digits
      (fun d => if in_box (refine j d B) P then 1 else 0)).
    rewrite (sum_digits_ext _ (fun d => if in_box B P then
              (if nth (length (nth j B [])) (nth j P []) 0 =? d then 1 else 0) else 0)).
    2: { intros d _. rewrite in_box_refine by lia.
         destruct (in_box B P), (_ =? d); reflexivity. }
    destruct (in_box B P); simpl.
    + rewrite sum_digits_one by exact Dj. reflexivity.
    + rewrite sum_digits_const. lia.
Qed.

Lemma refine_length : forall B j d, length (refine j d B) = length B.
Proof. induction B; intros [|j] d; simpl; auto. Qed.

Lemma refine_valid : forall B j d, d < b -> valid_point b B -> valid_point b (refine j d B).
Proof.
  unfold valid_point. induction B as [|p B IH]; intros [|j] d H V; simpl; auto;
    inversion V; subst; constructor; auto.
  unfold valid in *. apply Forall_app. split; auto.
Qed.

Lemma refine_room : forall B j d n, j < length B -> length (nth j B []) < n ->
  Forall (fun p => length p <= n) B -> Forall (fun p => length p <= n) (refine j d B).
Proof.
  induction B as [|p B IH]; intros [|j] d n J N F; simpl in *; try lia;
    inversion F; subst; constructor; auto.
  - rewrite app_length. simpl. lia.
  - apply IH; auto. lia.
Qed.

Lemma refine_sum : forall B j d, j < length B -> sum (shape (refine j d B)) = S (sum (shape B)).
Proof.
  unfold sum, shape. induction B as [|p B IH]; intros [|j] d J; simpl in *; try lia.
  - rewrite app_length. simpl. lia.
  - rewrite IH by lia. lia.
Qed.

(** A box whose digit count is below s·n has room in some coordinate. *)
Lemma room : forall B n, Forall (fun p => length p <= n) B ->
  sum (shape B) < length B * n -> exists j, j < length B /\ length (nth j B []) < n.
Proof.
  unfold sum, shape. induction B as [|p B IH]; intros n F H; simpl in *; [lia|].
  inversion F; subst. destruct (Nat.lt_ge_cases (length p) n) as [L|L].
  - exists 0. split; [lia | exact L].
  - destruct (IH n) as [j [J N]]; auto; [lia|]. exists (S j). split; [lia | exact N].
Qed.

(** Monotonicity: a (t,m,s)-net in base b of n-digit points is a (t+1,m,s)-net, whenever
    t < m and m − t ≤ s·n (so that its boxes of m − t − 1 digits have room to refine). *)
Theorem net_monotone : forall n m t s Ps, t < m -> m - t <= s * n ->
  is_net b n m t s Ps -> is_net b n m (S t) s Ps.
Proof.
  intros n m t s Ps T R [L [WF Box]]. split; [exact L|]. split; [exact WF|].
  intros B LB VB NB SB.
  destruct (room B n NB) as [j [J N]]; [rewrite LB; nia|].
  rewrite (count_refine n s B Ps j) by (auto; lia).
  rewrite (sum_digits_ext _ (fun _ => b ^ t)).
  - rewrite sum_digits_const. simpl. reflexivity.
  - intros d D. apply Box.
    + rewrite refine_length. exact LB.
    + apply refine_valid; auto.
    + apply refine_room; auto.
    + rewrite refine_sum by exact J. lia.
Qed.

(** Hence every t' between t and m (with m − t ≤ s·n): the least t of a net is a threshold. *)
Theorem net_monotone_le : forall n m t t' s Ps, t <= t' -> t' <= m -> m - t <= s * n ->
  is_net b n m t s Ps -> is_net b n m t' s Ps.
Proof.
  intros n m t t' s Ps H1 H2 R N. revert H2. induction H1 as [|t' H1 IH]; intro H2; auto.
  apply net_monotone; [lia | lia | apply IH; lia].
Qed.

(** The checker's t-value is a threshold: the set is a [(t,m,s)]-net for every [t] from the
    value [t_value] returns up to [m], and for none below it ([Checker.t_value_correct]). *)
Theorem t_value_threshold : forall n m s Ps, 1 < b -> 0 < s -> m <= n -> length Ps = b ^ m ->
  Forall (well_formed b n s) Ps ->
  forall t, t <= m -> (is_net b n m t s Ps <-> t_value b m s Ps <= t).
Proof.
  intros n m s Ps B S M L W t T.
  destruct (t_value_correct b n m s Ps B M L W) as [R1 [R2 R3]]. split.
  - intro N. destruct (Nat.le_gt_cases (t_value b m s Ps) t) as [G|G]; auto.
    exfalso. exact (R3 t G N).
  - intro G. apply (net_monotone_le n m (t_value b m s Ps) t s Ps); auto. nia.
Qed.

End Monotone.
