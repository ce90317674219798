(** * The rank path's XOR basis decides whether the stacked rows' key is onto.

    `crates/netcheck/src/rank.rs` stacks a shape's rows (masks over the [D] index bits) and
    inserts them one by one into an XOR basis ([XorBasis::insert]: while the vector is nonzero,
    look at the pivot slot of its top bit; store it there if the slot is empty, else XOR the
    pivot in). The shape is declared to hold iff every insertion succeeds. [insert] below is
    that loop (fuel [D] for [D]-bit vectors), and [independent_iff_onto] proves that every
    insertion succeeds exactly when the key map [i ↦ (row_j · i)_j] of the indices below
    [2^D] is onto. With [Rank.balanced_iff_onto] (a linear key balances the boxes iff it is
    onto) that is the rank path's verdict, both ways ([independent_iff_balanced]: every box of
    the shape holds [2^(D − k)] of the [2^D] indices). `NetRank.v` shows that a digital net's
    box is this key of the point's index, so the verdict is [is_net]; the depth-first search
    over shapes that shares a prefix's basis among its completions is not modelled.

    The proof follows the basis: XORing a pivot (an earlier row, reduced) into the row being
    inserted is a row operation, which keeps the key map onto or not onto ([add_row_onto_iff]);
    a row reduced to zero leaves keys unhit ([zero_row_not_onto]); rows whose top bits are
    distinct give an onto key map ([echelon_onto]: fix the index bit at each top, highest
    last). *)

From Coq Require Import List Arith Bool Lia.
From Gartowen Require Import ArtWord ArtMarginal Rank.
Import ListNotations.

(** ** Bits *)

Lemma small_no_bit : forall r n, r < 2 ^ n -> Nat.testbit r n = false.
Proof.
  intros r n H. destruct (Nat.eq_dec r 0) as [->|E]; [apply Nat.bits_0|].
  apply Nat.bits_above_log2. apply Nat.log2_lt_pow2; lia.
Qed.

Lemma below_top : forall r, r <> 0 -> r < 2 ^ S (Nat.log2 r).
Proof. intros r E. apply Nat.log2_spec. lia. Qed.

Lemma cleared_top : forall x t, x < 2 ^ S t -> Nat.testbit x t = false -> x < 2 ^ t.
Proof.
  intros x t H B. pose proof (Nat.testbit_spec' x t) as S. rewrite B in S.
  change (Nat.b2n false) with 0 in S.
  assert (P : 2 ^ t <> 0) by (apply Nat.pow_nonzero; lia).
  assert (L : x / 2 ^ t < 2).
  { apply Nat.div_lt_upper_bound; [exact P|]. rewrite Nat.mul_comm, <- Nat.pow_succ_r'. exact H. }
  rewrite Nat.mod_small in S by exact L.
  apply (Nat.div_small_iff x (2 ^ t) P). lia.
Qed.

(** Two nonzero vectors with the same top bit XOR to a vector below that bit. *)
Lemma xor_same_top : forall v w, v <> 0 -> w <> 0 -> Nat.log2 v = Nat.log2 w ->
  Nat.lxor v w < 2 ^ Nat.log2 v.
Proof.
  intros v w Hv Hw E. apply cleared_top.
  - apply lxor_lt; [apply below_top, Hv|]. rewrite E. apply below_top, Hw.
  - rewrite Nat.lxor_spec, Nat.bit_log2 by exact Hv. rewrite E, Nat.bit_log2 by exact Hw.
    reflexivity.
Qed.

Lemma top_is : forall r n, 2 ^ n <= r -> r < 2 ^ S n -> Nat.log2 r = n.
Proof. intros r n L H. apply Nat.log2_unique; lia. Qed.

(** ** The dot product with an index *)

Lemma dot_lxor_r : forall D r i i', dot D r (Nat.lxor i i') = xorb (dot D r i) (dot D r i').
Proof.
  intros D r i i'. unfold dot. rewrite <- fold_xorb_map. f_equal. apply map_ext. intro c.
  rewrite Nat.lxor_spec. destruct (Nat.testbit r c), (Nat.testbit i c), (Nat.testbit i' c);
    reflexivity.
Qed.

Lemma fold_xorb_snoc : forall l b,
  fold_right xorb false (l ++ [b]) = xorb (fold_right xorb false l) b.
Proof.
  induction l as [|a l IH]; intro b; simpl; [destruct b; reflexivity|].
  rewrite IH. destruct a, b, (fold_right xorb false l); reflexivity.
Qed.

Lemma dot_S : forall D r i, dot (S D) r i = xorb (dot D r i) (Nat.testbit r D && Nat.testbit i D).
Proof. intros D r i. unfold dot. rewrite seq_S, map_app. apply fold_xorb_snoc. Qed.

(** The dot product with the index [2^n] reads bit [n] of the row. *)
Lemma dot_pow2 : forall D r n, dot D r (2 ^ n) = (n <? D) && Nat.testbit r n.
Proof.
  induction D as [|D IH]; intros r n; [reflexivity|].
  rewrite dot_S, IH, Nat.pow2_bits_eqb.
  destruct (Nat.ltb_spec n D), (Nat.ltb_spec n (S D)), (Nat.eqb_spec n D);
    subst; try lia; repeat destruct (Nat.testbit r _); reflexivity.
Qed.

(** ** Onto key maps *)

(** Every key (a bit per row [j < k]) is hit by an index below [2^n]. *)
Definition onto (D n k : nat) (rows : nat -> nat) : Prop :=
  forall y : nat -> bool, exists i, i < 2 ^ n /\ forall j, j < k -> dot D (rows j) i = y j.

Lemma onto_ext : forall D n k rows rows', (forall j, j < k -> rows j = rows' j) ->
  onto D n k rows -> onto D n k rows'.
Proof.
  intros D n k rows rows' E O y. destruct (O y) as [i [Hi F]]. exists i. split; [exact Hi|].
  intros j Hj. rewrite <- E by exact Hj. apply F, Hj.
Qed.

(** Rows with distinct top bits, below the [n] index bits, give an onto key map: find an
    index for the rows below bit [n − 1], then fix bit [n − 1] for the one row (if any) whose
    top it is. *)
Lemma echelon_onto_on : forall D n k (Sel : nat -> bool) rows, n <= D ->
  (forall j, j < k -> Sel j = true -> rows j <> 0 /\ rows j < 2 ^ n) ->
  (forall j j', j < k -> j' < k -> Sel j = true -> Sel j' = true ->
     Nat.log2 (rows j) = Nat.log2 (rows j') -> j = j') ->
  forall y, exists i, i < 2 ^ n /\ forall j, j < k -> Sel j = true -> dot D (rows j) i = y j.
Proof.
  intros D n. induction n as [|n IH]; intros k Sel rows HD R U y.
  - exists 0. split; [simpl; lia|]. intros j Hj Sj. destruct (R j Hj Sj). simpl in *. lia.
  - set (S' := fun j => Sel j && (rows j <? 2 ^ n)).
    destruct (IH k S' rows ltac:(lia)) with (y := y) as [i' [Hi' Ei']].
    + intros j Hj Sj. unfold S' in Sj. apply andb_true_iff in Sj as [Sj L].
      apply Nat.ltb_lt in L. split; [apply R; assumption|exact L].
    + intros j j' Hj Hj' Sj Sj'. unfold S' in *. apply andb_true_iff in Sj as [Sj _].
      apply andb_true_iff in Sj' as [Sj' _]. apply U; assumption.
    + assert (Pn : 2 ^ n < 2 ^ S n) by (apply Nat.pow_lt_mono_r; lia).
      (* The row whose top bit is n, if its key bit is wrong. *)
      destruct (existsb (fun j => Sel j && negb (rows j <? 2 ^ n)
                               && negb (Bool.eqb (dot D (rows j) i') (y j))) (seq 0 k)) eqn:Bad.
      * apply existsb_exists in Bad as [js [Hjs Bj]]. apply in_seq in Hjs.
        apply andb_true_iff in Bj as [Bj Wrong]. apply andb_true_iff in Bj as [Sjs Big].
        apply negb_true_iff, Nat.ltb_ge in Big. apply negb_true_iff in Wrong.
        destruct (R js ltac:(lia) Sjs) as [_ Ljs].
        assert (Tjs : Nat.log2 (rows js) = n) by (apply top_is; assumption).
        exists (Nat.lxor i' (2 ^ n)). split; [apply lxor_lt; lia|].
        intros j Hj Sj. rewrite dot_lxor_r, dot_pow2.
        replace (n <? D) with true by (symmetry; apply Nat.ltb_lt; lia). simpl.
        destruct (Nat.ltb_spec (rows j) (2 ^ n)) as [Lj|Lj].
        -- rewrite small_no_bit by exact Lj. rewrite xorb_false_r. apply Ei'; [exact Hj|].
           unfold S'. rewrite Sj. simpl. apply Nat.ltb_lt, Lj.
        -- destruct (R j Hj Sj) as [_ Hj2].
           assert (j = js) as ->.
           { apply U; try assumption; try lia. rewrite Tjs. apply top_is; assumption. }
           rewrite <- Tjs. rewrite Nat.bit_log2 by lia.
           destruct (dot D (rows js) i'), (y js); simpl in *; congruence.
      * exists i'. split; [lia|]. intros j Hj Sj.
        destruct (Nat.ltb_spec (rows j) (2 ^ n)) as [Lj|Lj].
        -- apply Ei'; [exact Hj|]. unfold S'. rewrite Sj. simpl. apply Nat.ltb_lt, Lj.
        -- assert (Nb : In j (seq 0 k)) by (apply in_seq; lia).
           assert (F : (Sel j && negb (rows j <? 2 ^ n)
                        && negb (Bool.eqb (dot D (rows j) i') (y j))) = false).
           { destruct (Sel j && negb (rows j <? 2 ^ n)
                        && negb (Bool.eqb (dot D (rows j) i') (y j))) eqn:T; [|reflexivity].
             rewrite <- Bad. symmetry. apply existsb_exists. exists j. split; assumption. }
           rewrite Sj in F. replace (rows j <? 2 ^ n) with false in F
             by (symmetry; apply Nat.ltb_ge; exact Lj).
           simpl in F. apply negb_false_iff in F.
           destruct (dot D (rows j) i'), (y j); simpl in F; congruence.
Qed.

Theorem echelon_onto : forall D n k rows, n <= D ->
  (forall j, j < k -> rows j <> 0 /\ rows j < 2 ^ n) ->
  (forall j j', j < k -> j' < k -> Nat.log2 (rows j) = Nat.log2 (rows j') -> j = j') ->
  onto D n k rows.
Proof.
  intros D n k rows HD R U y.
  destruct (echelon_onto_on D n k (fun _ => true) rows HD) with (y := y) as [i [Hi E]].
  - intros j Hj _. apply R, Hj.
  - intros j j' Hj Hj' _ _. apply U; assumption.
  - exists i. split; [exact Hi|]. intros j Hj. apply E; [exact Hj|reflexivity].
Qed.

(** Adding an earlier row to row [a]. *)
Definition add_row (rows : nat -> nat) (a b : nat) : nat -> nat :=
  fun j => if j =? a then Nat.lxor (rows a) (rows b) else rows j.

Lemma add_row_onto : forall D n k rows a b, b < a ->
  onto D n k rows -> onto D n k (add_row rows a b).
Proof.
  intros D n k rows a b Hba O y.
  destruct (O (fun j => if j =? a then xorb (y a) (y b) else y j)) as [i [Hi E]].
  exists i. split; [exact Hi|]. intros j Hj. unfold add_row.
  destruct (Nat.eqb_spec j a) as [->|Ne].
  - rewrite dot_lxor, (E a Hj), (E b ltac:(lia)), Nat.eqb_refl.
    replace (b =? a) with false by (symmetry; apply Nat.eqb_neq; lia).
    destruct (y a), (y b); reflexivity.
  - rewrite (E j Hj). apply Nat.eqb_neq in Ne. rewrite Ne. reflexivity.
Qed.

Lemma add_row_onto_iff : forall D n k rows a b, b < a ->
  onto D n k rows <-> onto D n k (add_row rows a b).
Proof.
  intros D n k rows a b Hba. split; [apply add_row_onto, Hba|].
  intro O. apply (onto_ext _ _ _ (add_row (add_row rows a b) a b)).
  - intros j _. unfold add_row. destruct (Nat.eqb_spec j a) as [->|_]; [|reflexivity].
    rewrite Nat.eqb_refl. replace (b =? a) with false by (symmetry; apply Nat.eqb_neq; lia).
    apply lxor_twice.
  - apply add_row_onto; assumption.
Qed.

Lemma zero_row_not_onto : forall D n k rows a, a < k -> rows a = 0 -> ~ onto D n k rows.
Proof.
  intros D n k rows a Ha Z O. destruct (O (fun _ => true)) as [i [_ E]].
  specialize (E a Ha). rewrite Z, dot_zero in E. discriminate.
Qed.

(** ** The XOR basis of `rank.rs` *)

(** Reduce [v] by the pivots [B] (slot [t] holds a vector with top bit [t], or 0) until it is
    zero or its top slot is empty. *)
Fixpoint reduce (fuel : nat) (B : nat -> nat) (v : nat) : nat :=
  match fuel with
  | O => v
  | S f => if v =? 0 then 0 else
           let p := B (Nat.log2 v) in if p =? 0 then v else reduce f B (Nat.lxor v p)
  end.

(** [XorBasis::insert] for [D]-bit vectors: the new basis, and whether [v] was independent. *)
Definition insert (D : nat) (B : nat -> nat) (v : nat) : (nat -> nat) * bool :=
  let r := reduce D B v in
  if r =? 0 then (B, false) else ((fun t => if t =? Nat.log2 r then r else B t), true).

Fixpoint insert_all (D : nat) (B : nat -> nat) (rs : list nat) : bool :=
  match rs with
  | [] => true
  | r :: rs' => let (B', ok) := insert D B r in ok && insert_all D B' rs'
  end.

(** The rank path's verdict for stacked rows: every insertion into an empty basis succeeds. *)
Definition independent (D : nat) (rs : list nat) : bool := insert_all D (fun _ => 0) rs.

Section Basis.

Variable D : nat.
Variable R : nat -> nat.
Hypothesis R_small : forall j, R j < 2 ^ D.

(** After [k] insertions: [C j] is the pivot row [j] became; every pivot is one of them,
    stored at its top bit, and their tops are distinct. *)
Definition inv (k : nat) (C B : nat -> nat) : Prop :=
  (forall j, j < k -> C j <> 0 /\ C j < 2 ^ D /\ B (Nat.log2 (C j)) = C j) /\
  (forall t, B t <> 0 -> (exists j, j < k /\ C j = B t) /\ Nat.log2 (B t) = t /\ B t < 2 ^ D) /\
  (forall j j', j < k -> j' < k -> Nat.log2 (C j) = Nat.log2 (C j') -> j = j').

(** The rows with the first [k] replaced by their pivots. *)
Definition mix (k : nat) (C : nat -> nat) : nat -> nat := fun j => if j <? k then C j else R j.

Definition update (f : nat -> nat) (k v : nat) : nat -> nat := fun j => if j =? k then v else f j.

Lemma reduce_rowops : forall k C B, inv k C B -> forall fuel v K,
  onto D D K (update (mix k C) k v) <-> onto D D K (update (mix k C) k (reduce fuel B v)).
Proof.
  intros k C B [_ [I2 _]] fuel. induction fuel as [|f IH]; intros v K; [reflexivity|].
  simpl. destruct (Nat.eqb_spec v 0) as [->|Hv]; [reflexivity|].
  destruct (Nat.eqb_spec (B (Nat.log2 v)) 0) as [Hp|Hp]; [reflexivity|].
  rewrite <- IH. destruct (proj1 (I2 _ Hp)) as [j [Hj Cj]].
  rewrite (add_row_onto_iff D D K (update (mix k C) k v) k j) by exact Hj.
  split; apply onto_ext; intros j' _; unfold add_row, update, mix;
    destruct (Nat.eqb_spec j' k); try reflexivity; rewrite Nat.eqb_refl;
    replace (j =? k) with false by (symmetry; apply Nat.eqb_neq; lia);
    replace (j <? k) with true by (symmetry; apply Nat.ltb_lt; exact Hj); congruence.
Qed.

Lemma reduce_result : forall k C B, inv k C B -> forall fuel v, v < 2 ^ fuel -> v < 2 ^ D ->
  reduce fuel B v < 2 ^ D /\
  (reduce fuel B v = 0 \/ B (Nat.log2 (reduce fuel B v)) = 0).
Proof.
  intros k C B [_ [I2 _]] fuel. induction fuel as [|f IH]; intros v Hf HD.
  - simpl in *. split; [exact HD|]. left. lia.
  - simpl. destruct (Nat.eqb_spec v 0) as [->|Hv]; [split; [lia|left; reflexivity]|].
    destruct (Nat.eqb_spec (B (Nat.log2 v)) 0) as [Hp|Hp]; [split; [exact HD|right; exact Hp]|].
    destruct (I2 _ Hp) as [_ [Tp Lp]].
    apply IH.
    + apply (Nat.lt_le_trans _ (2 ^ Nat.log2 v)).
      * apply xor_same_top; [exact Hv|exact Hp|symmetry; exact Tp].
      * apply Nat.pow_le_mono_r; [lia|]. apply Nat.lt_succ_r. apply Nat.log2_lt_pow2; lia.
    + apply lxor_lt; assumption.
Qed.

Lemma insert_all_correct : forall rest k C B,
  inv k C B ->
  (forall j, j < length rest -> nth j rest 0 = R (k + j)) ->
  (forall K, onto D D K R <-> onto D D K (mix k C)) ->
  (insert_all D B rest = true <-> onto D D (k + length rest) R).
Proof.
  induction rest as [|r rest IH]; intros k C B I Rest E.
  - simpl. rewrite Nat.add_0_r, E. split; [intros _|reflexivity].
    destruct I as [I1 [_ I3]].
    apply (onto_ext _ _ _ C); [intros j Hj; unfold mix; rewrite (proj2 (Nat.ltb_lt j k) Hj);
      reflexivity|].
    apply echelon_onto; [lia| |exact I3]. intros j Hj. destruct (I1 j Hj) as [? [? _]]. auto.
  - assert (Hr : r = R k).
    { pose proof (Rest 0 ltac:(simpl; lia)) as H0. simpl in H0.
      rewrite Nat.add_0_r in H0. exact H0. }
    assert (Back : forall K, onto D D K R <-> onto D D K (update (mix k C) k (reduce D B r))).
    { intro K. rewrite E, <- (reduce_rowops k C B I). split; apply onto_ext; intros j _;
        unfold update, mix; destruct (Nat.eqb_spec j k) as [->|]; try reflexivity;
        rewrite Nat.ltb_irrefl; first [exact Hr|symmetry; exact Hr]. }
    destruct (reduce_result k C B I D r) as [Small [Zero|Free]].
    + apply (Nat.lt_le_trans _ (2 ^ D)); [rewrite Hr; apply R_small|lia].
    + rewrite Hr. apply R_small.
    + simpl. unfold insert. rewrite Zero, Nat.eqb_refl. simpl. split; [discriminate|].
      intro O. apply Back in O. apply (zero_row_not_onto D D _ _ k) in O; [contradiction|lia|].
      unfold update. rewrite Nat.eqb_refl. exact Zero.
    + set (v := reduce D B r) in *.
      destruct (Nat.eqb_spec v 0) as [Z|Hv].
      { simpl. unfold insert. fold v. rewrite Z, Nat.eqb_refl. simpl. split; [discriminate|].
        intro O. apply Back in O. apply (zero_row_not_onto D D _ _ k) in O; [contradiction|lia|].
        unfold update. rewrite Nat.eqb_refl. exact Z. }
      simpl. unfold insert. fold v. replace (v =? 0) with false by (symmetry; apply Nat.eqb_neq; exact Hv).
      simpl. replace (k + S (length rest)) with (S k + length rest) by lia.
      destruct I as [I1 [I2 I3]].
      apply (IH (S k) (update C k v)).
      * split; [|split].
        -- intros j Hj. unfold update. destruct (Nat.eqb_spec j k) as [->|Ne].
           ++ rewrite Nat.eqb_refl. auto.
           ++ destruct (I1 j ltac:(lia)) as [Cj [Lj Bj]]. repeat split; try assumption.
              destruct (Nat.eqb_spec (Nat.log2 (C j)) (Nat.log2 v)) as [Eq|]; [|exact Bj].
              exfalso. apply Cj. rewrite <- Bj, Eq. exact Free.
        -- intros t Ht. destruct (Nat.eqb_spec t (Nat.log2 v)) as [Et|Ne].
           ++ rewrite Et in *. split; [exists k; split; [lia|unfold update; rewrite Nat.eqb_refl; reflexivity]|].
              split; [reflexivity|exact Small].
           ++ destruct (I2 t Ht) as [[j [Hj Cj]] Rest2]. split; [|exact Rest2].
              exists j. split; [lia|]. unfold update.
              replace (j =? k) with false by (symmetry; apply Nat.eqb_neq; lia). exact Cj.
        -- intros j j' Hj Hj' T. unfold update in T.
           destruct (Nat.eqb_spec j k), (Nat.eqb_spec j' k); subst.
           ++ reflexivity.
           ++ exfalso. destruct (I1 j' ltac:(lia)) as [Cj [_ Bj]]. apply Cj.
              rewrite <- Bj, <- T. exact Free.
           ++ exfalso. destruct (I1 j ltac:(lia)) as [Cj [_ Bj]]. apply Cj.
              rewrite <- Bj, T. exact Free.
           ++ apply I3; [lia|lia|exact T].
      * intros j Hj. rewrite Nat.add_succ_comm. apply (Rest (S j)). simpl. lia.
      * intro K. rewrite Back. split; apply onto_ext; intros j _; unfold update, mix;
          destruct (Nat.eqb_spec j k) as [Ej|Ne];
          destruct (Nat.ltb_spec j k), (Nat.ltb_spec j (S k)); try lia; reflexivity.
Qed.

End Basis.

(** The rank path's verdict: every insertion of the stacked rows succeeds exactly when their
    key map over the [2^D] indices is onto (so, by [balanced_iff_onto], when the shape's boxes
    all hold the same number of points). *)
Theorem independent_iff_onto : forall D rs, (forall r, In r rs -> r < 2 ^ D) ->
  independent D rs = true <-> onto D D (length rs) (fun j => nth j rs 0).
Proof.
  intros D rs Small. unfold independent.
  assert (SmallR : forall j, nth j rs 0 < 2 ^ D).
  { intro j. destruct (Nat.lt_ge_cases j (length rs)) as [L|L].
    + apply Small, nth_In, L.
    + rewrite nth_overflow by exact L. apply Nat.neq_0_lt_0, Nat.pow_nonzero. lia. }
  apply (insert_all_correct D (fun j => nth j rs 0) SmallR rs 0 (fun _ => 0) (fun _ => 0)).
  - split; [intros j Hj; lia|split; [intros t Ht; contradiction|intros j j' Hj; lia]].
  - intros j _. reflexivity.
  - intro K. split; apply onto_ext; intros j _; unfold mix; reflexivity.
Qed.

(** ** The verdict in terms of boxes

    Read as a number (bit [j] = row [j]'s dot product), the stacked rows' key is a linear map
    of the index, so [Rank.balanced_iff_onto] applies: every insertion succeeds exactly when
    every one of the [2^k] keys (boxes) holds [2^(D − k)] of the [2^D] indices. *)

(** A list of bits as a number, bit [j] first-to-last from the least significant. *)
Definition num (l : list bool) : nat := fold_right (fun v acc => Nat.b2n v + 2 * acc) 0 l.

Lemma num_bits : forall l j, Nat.testbit (num l) j = nth j l false.
Proof.
  induction l as [|v l IH]; intro j.
  { unfold num. simpl fold_right. rewrite Nat.bits_0. destruct j; reflexivity. }
  unfold num in *. cbn [fold_right nth]. destruct v, j; simpl Nat.b2n.
  - rewrite Nat.add_comm. apply Nat.testbit_odd_0.
  - rewrite Nat.add_comm, Nat.testbit_odd_succ by lia. apply IH.
  - rewrite Nat.add_0_l. apply Nat.testbit_even_0.
  - rewrite Nat.add_0_l, Nat.testbit_even_succ by lia. apply IH.
Qed.

Lemma num_lt : forall l, num l < 2 ^ length l.
Proof.
  induction l as [|v l IH]; simpl; [lia|]. destruct v; simpl; lia.
Qed.

(** The key of index [i] as a number. *)
Definition keynum (D : nat) (rs : list nat) (i : nat) : nat := num (map (fun r => dot D r i) rs).

Lemma keynum_bits : forall D rs i j,
  Nat.testbit (keynum D rs i) j = (j <? length rs) && dot D (nth j rs 0) i.
Proof.
  intros D rs i j. unfold keynum. rewrite num_bits.
  destruct (Nat.ltb_spec j (length rs)) as [L|L].
  - rewrite (nth_indep _ false ((fun r => dot D r i) 0)) by (rewrite map_length; exact L).
    rewrite (map_nth (fun r => dot D r i) rs 0 j). reflexivity.
  - apply nth_overflow. rewrite map_length. exact L.
Qed.

Lemma keynum_lt : forall D rs i, keynum D rs i < 2 ^ length rs.
Proof. intros D rs i. unfold keynum. rewrite <- (map_length (fun r => dot D r i) rs). apply num_lt. Qed.

Lemma keynum_lin : forall D rs i i',
  keynum D rs (Nat.lxor i i') = Nat.lxor (keynum D rs i) (keynum D rs i').
Proof.
  intros D rs i i'. apply Nat.bits_inj. intro j.
  rewrite Nat.lxor_spec, !keynum_bits, dot_lxor_r.
  destruct (j <? length rs); reflexivity.
Qed.

Lemma onto_iff_keys : forall D rs, (forall y : nat -> bool,
    exists i, i < 2 ^ D /\ forall j, j < length rs -> dot D (nth j rs 0) i = y j) <->
  (forall y, y < 2 ^ length rs -> exists x, x < 2 ^ D /\ keynum D rs x = y).
Proof.
  intros D rs. split.
  - intros O y Hy. destruct (O (Nat.testbit y)) as [i [Hi E]]. exists i. split; [exact Hi|].
    apply Nat.bits_inj. intro j. rewrite keynum_bits.
    destruct (Nat.ltb_spec j (length rs)) as [L|L].
    + simpl. apply E, L.
    + simpl. symmetry. apply small_no_bit.
      apply (Nat.lt_le_trans _ (2 ^ length rs)); [exact Hy|apply Nat.pow_le_mono_r; lia].
  - intros O y. destruct (O (num (map y (seq 0 (length rs))))) as [x [Hx E]].
    + pose proof (num_lt (map y (seq 0 (length rs)))) as N.
      rewrite map_length, seq_length in N. exact N.
    + exists x. split; [exact Hx|]. intros j Hj.
      pose proof (keynum_bits D rs x j) as B. rewrite E, num_bits in B.
      replace (j <? length rs) with true in B by (symmetry; apply Nat.ltb_lt, Hj).
      simpl in B. rewrite <- B.
      rewrite (nth_indep _ false (y 0)) by (rewrite map_length, seq_length; exact Hj).
      rewrite map_nth, seq_nth by exact Hj. reflexivity.
Qed.

(** The rank path's verdict for one shape: every stacked row is accepted by the XOR basis
    exactly when each of the [2^k] boxes (keys) holds [2^(D − k)] of the [2^D] indices. *)
Theorem independent_iff_balanced : forall D rs,
  (forall r, In r rs -> r < 2 ^ D) -> length rs <= D ->
  independent D rs = true <->
  (forall y, y < 2 ^ length rs -> fibre D (keynum D rs) y = 2 ^ (D - length rs)).
Proof.
  intros D rs Small L.
  rewrite (balanced_iff_onto D (length rs) (keynum D rs)).
  - rewrite independent_iff_onto by exact Small. unfold onto. apply onto_iff_keys.
  - intros x _. apply keynum_lt.
  - intros x y _ _. apply keynum_lin.
  - exact L.
Qed.
