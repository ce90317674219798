(** * The counting net checker, as implemented, decides [is_net] and [is_sequence].

    This models the algorithm of [crates/netcheck/src/counting.rs] and [box_keys.rs] step by
    step and proves that its verdicts are the definitions of [Nested.v]:
    - digit prefixes [P = floor(x·b^K)] at a depth [K], cut to a shape's digit
      [a = P / b^(K−d)] ([Boxes.cut_prefix]);
    - the mixed-radix box key [Σ_j a_j · b^(Σ_{i>j} d_i)] ([key]), equal for two points exactly
      when they share the box ([key_eq_iff]);
    - shapes: the compositions of [K] into [s] parts in lexicographic order ([comps], exactly
      the shapes of [K] digits, [In_comps]);
    - per shape, a running histogram that searches only for overflow ([Boxes.scan], kept in a
      binary trie by [ScanMap.scan_map] so that the extracted model runs on 2^16 points): the
      pigeonhole step ([Boxes.pigeonhole]) shows that no box holding more than [b^t] points means every box holds
      exactly [b^t];
    - the quick probe of the t search, which scans a prefix of the points first ([level_any]);
    - the t search ([t_value], the least [t]) and the sequence blocks ([check_sequence]).
    The definitions are extracted ([Extract.v]) and run against the Rust checker on every case
    of [tests/extracted_checker.rs]. *)

From Coq Require Import List Arith Bool Lia FMapPositive.
Import ListNotations.
From Gartowen Require Import Nested Boxes ScanMap.

Section Checker.

Variable b : nat.

(* The base of [Boxes.v]'s definitions and lemmas is this section's [b]. *)
Local Notation fits := (fits b).
Local Notation boxes := (boxes b).
Local Notation boxes_length := (boxes_length b).
Local Notation in_boxes := (in_boxes b).
Local Notation in_box_iff := (in_box_iff b).
Local Notation box_of_in_boxes := (box_of_in_boxes b).
Local Notation sum_counts := (sum_counts b).
Local Notation pow_nonzero := (pow_nonzero b).
Local Notation cut_prefix := (cut_prefix b).

(** ** Box keys. *)

(** The mixed-radix number of a box: [Σ_j digit_value(p_j) · b^(Σ_{i>j} d_i)]. *)
Fixpoint box_number (B : list (list nat)) : nat :=
  match B with
  | [] => 0
  | p :: B' => digit_value b p * b ^ sum (shape B') + box_number B'
  end.

(** The key of [box_keys.rs] at depth [K]: each shape digit cut from the prefix at depth [K]. *)
Fixpoint key (K : nat) (sh : list nat) (P : list (list nat)) : nat :=
  match sh, P with
  | d :: sh', x :: P' => digit_value b (firstn K x) / b ^ (K - d) * b ^ sum sh' + key K sh' P'
  | _, _ => 0
  end.

Lemma box_number_lt : forall B, valid_point b B -> box_number B < b ^ sum (shape B).
Proof.
  induction B as [|p B IH]; intro V; simpl; [lia|]. inversion V; subst.
  pose proof (val_lt b p H1). specialize (IH H2). rewrite Nat.pow_add_r. nia.
Qed.

Lemma box_number_inj : forall B C, valid_point b B -> valid_point b C -> shape B = shape C ->
  box_number B = box_number C -> B = C.
Proof.
  induction B as [|p B IH]; intros [|r C] VB VC S E; simpl in *; try discriminate; auto.
  inversion VB; inversion VC; subst. injection S as L S. rewrite <- S in E.
  pose proof (box_number_lt B H2). pose proof (box_number_lt C H6). rewrite <- S in H0.
  assert (digit_value b p = digit_value b r) as V.
  { destruct (Nat.lt_trichotomy (digit_value b p) (digit_value b r)) as [D|[D|D]]; auto; nia. }
  assert (box_number B = box_number C) by (rewrite V in E; lia).
  f_equal; [apply (val_inj b); auto | apply IH; auto].
Qed.

Lemma shape_box_of : forall sh P, fits sh P -> shape (box_of sh P) = sh.
Proof.
  induction sh as [|d sh IH]; intros [|x P] F; simpl in *; try tauto; auto.
  destruct F as [_ [L F]]. rewrite firstn_length, IH by exact F. f_equal. lia.
Qed.

Lemma valid_box_of : forall sh P, fits sh P -> valid_point b (box_of sh P).
Proof. intros sh P F. apply (in_boxes sh). apply box_of_in_boxes. exact F. Qed.

(** A point is deep enough for depth [K] when each coordinate is valid with at least [K]
    digits. *)
Definition deep (K : nat) (P : list (list nat)) : Prop :=
  Forall (fun x => valid b x /\ K <= length x) P.

Lemma key_box_number : forall K sh P, 1 < b -> deep K P -> length sh = length P ->
  Forall (fun d => d <= K) sh -> key K sh P = box_number (box_of sh P).
Proof.
  induction sh as [|d sh IH]; intros [|x P] B D L F; simpl in *; try discriminate; auto.
  inversion D; inversion F; subst. destruct H1 as [V Lx].
  rewrite cut_prefix by (auto; lia). rewrite IH by (auto; lia).
  f_equal. f_equal. f_equal. rewrite shape_box_of; auto.
  clear -H2 H6 L. revert P H2 L. induction sh as [|e sh IH]; intros [|y P] H2 L; simpl in *;
  try discriminate; auto. inversion H2; inversion H6; subst. split; [tauto|]. split; [lia|].
  apply IH; auto.
Qed.

Lemma deep_fits : forall K sh P, deep K P -> length sh = length P ->
  Forall (fun d => d <= K) sh -> fits sh P.
Proof.
  induction sh as [|d sh IH]; intros [|x P] D L F; simpl in *; try discriminate; auto.
  inversion D; inversion F; subst. split; [tauto|]. split; [lia|]. apply IH; auto.
Qed.

(** Two points get the same key exactly when they lie in the same box of the shape. *)
Theorem key_eq_iff : forall K sh P Q, 1 < b -> deep K P -> deep K Q ->
  length sh = length P -> length sh = length Q -> Forall (fun d => d <= K) sh ->
  (key K sh P = key K sh Q <-> box_of sh P = box_of sh Q).
Proof.
  intros K sh P Q B DP DQ LP LQ F. rewrite !key_box_number by auto.
  split; [|intros ->; auto]. intro E. apply box_number_inj; auto.
  - apply valid_box_of. apply (deep_fits K); auto.
  - apply valid_box_of. apply (deep_fits K); auto.
  - rewrite !shape_box_of; auto; apply (deep_fits K); auto.
Qed.

(** ** Shapes. *)

(** The compositions of [k] into [s] parts, in lexicographic order: the shapes of
    [shapes.rs]. *)
Fixpoint comps (k s : nat) : list (list nat) :=
  match s with
  | 0 => if k =? 0 then [[]] else []
  | S s' => flat_map (fun d => map (cons d) (comps (k - d) s')) (seq 0 (S k))
  end.

Theorem In_comps : forall s k sh, In sh (comps k s) <-> length sh = s /\ sum sh = k.
Proof.
  induction s as [|s IH]; intros k sh.
  - simpl. destruct (k =? 0) eqn:K; simpl.
    + apply Nat.eqb_eq in K. subst. split; [intros [<-|[]]; auto|].
      intros [L _]. left. destruct sh; simpl in *; auto; discriminate.
    + apply Nat.eqb_neq in K. split; [tauto|]. intros [L S]. destruct sh; simpl in *; try discriminate.
      unfold sum in S. simpl in S. lia.
  - change (comps k (S s)) with (flat_map (fun d => map (cons d) (comps (k - d) s)) (seq 0 (S k))).
    rewrite in_flat_map. split.
    + intros [d [D M]]. apply in_map_iff in M as [sh' [<- I]]. apply IH in I as [L S].
      apply in_seq in D. simpl. unfold sum in *. simpl. split; [auto|lia].
    + intros [L S]. destruct sh as [|d sh']; simpl in L; [discriminate|].
      unfold sum in S. simpl in S. exists d. split; [apply in_seq; lia|].
      apply in_map. apply IH. split; [lia|]. unfold sum. lia.
Qed.

(** ** The level check, the net check, the t search and the sequence check. *)

(** One shape: the overflow-only scan of the points' keys against [b^t]. *)
Definition check_shape (K t : nat) (Ps : list (list (list nat))) (sh : list nat) :=
  scan_map _ (key K sh) (b ^ t) (PositiveMap.empty nat) Ps.

(** Every shape of [m − t] digits, in order, over prefixes at depth [K]; the first failing
    shape and the point whose box overflowed, or [None] when the level holds. *)
Definition check_level (K m t s : nat) (Ps : list (list (list nat))) :=
  find_first (check_shape K t Ps) (comps (m - t) s).

(** [check_net]: prefixes at depth [m − t]. *)
Definition check_net (m t s : nat) Ps := check_level (m - t) m t s Ps.

(** The t search's level test: prefixes at depth [m]; when [N/64 ≥ 64], the first [N/64]
    points are scanned first (a quick rejection), then all. *)
Definition level_any (m t s : nat) Ps :=
  let probe := length Ps / 64 in
  if 64 <=? probe then
    match check_level m m t s (firstn probe Ps) with
    | Some f => Some f
    | None => check_level m m t s Ps
    end
  else check_level m m t s Ps.

Fixpoint t_search (m s : nat) Ps (ts : list nat) : nat :=
  match ts with
  | [] => m
  | t :: r => match level_any m t s Ps with None => t | Some _ => t_search m s Ps r end
  end.

(** The t-value: the first [t] in [0..=m] whose level holds. *)
Definition t_value (m s : nat) Ps := t_search m s Ps (seq 0 (S m)).

(** Block [i] of [b^k] consecutive points. *)
Definition block (k i : nat) (Ps : list (list (list nat))) := firstn (b ^ k) (skipn (i * b ^ k) Ps).

(** Every block of [b^k] points, [t ≤ k ≤ M], in (k, block, shape) order. *)
Definition check_sequence (t M s : nat) Ps :=
  find_first (fun k => find_first (fun i => check_net k t s (block k i Ps))
                                  (seq 0 (length Ps / b ^ k)))
             (seq t (S M - t)).

Lemma wf_deep : forall n s K P, K <= n -> well_formed b n s P -> deep K P.
Proof.
  intros n s K P KN [_ [V L]]. unfold deep, valid_point in *. rewrite Forall_forall in *. intros x I.
  split; [apply V; auto | rewrite (L x I); auto].
Qed.

Lemma comps_le : forall k s sh K, k <= K -> In sh (comps k s) -> Forall (fun d => d <= K) sh.
Proof.
  intros k s sh K KK I. apply In_comps in I as [_ S]. subst. rewrite Forall_forall. intros d D.
  enough (d <= sum sh) by lia. clear KK. unfold sum. induction sh as [|e sh IH]; simpl in *; [tauto|].
  destruct D as [<-|D]; [lia|]. specialize (IH D). lia.
Qed.

(** The scan's count of a point's key is the count of its box. *)
Lemma cnt_key_count : forall n s K sh P Ps, 1 < b -> K <= n -> well_formed b n s P ->
  Forall (well_formed b n s) Ps -> length sh = s -> Forall (fun d => d <= K) sh ->
  cnt_key _ (key K sh) (key K sh P) Ps = count (box_of sh P) Ps.
Proof.
  intros n s K sh P Ps B KN WP WPs L F. unfold cnt_key, count. f_equal. apply filter_ext_in.
  intros Q I. rewrite Forall_forall in WPs. specialize (WPs Q I).
  assert (LP : length sh = length P) by (destruct WP; lia).
  assert (LQ : length sh = length Q) by (destruct WPs; lia).
  apply Bool.eq_iff_eq_true. rewrite Nat.eqb_eq, (in_box_iff sh).
  - rewrite (key_eq_iff K) by (eauto using wf_deep). split; auto.
  - apply (deep_fits K); eauto using wf_deep.
  - apply shape_box_of, (deep_fits K); eauto using wf_deep.
Qed.

(** The level check decides [is_net]: no box of any shape overflows exactly when every box of
    every shape of [m − t] digits holds [b^t] points, for any depth [K] from [m − t] to the
    points' precision [n]. *)
Theorem check_level_correct : forall n m t s K Ps, 1 < b -> t <= m -> m - t <= K -> K <= n ->
  length Ps = b ^ m -> Forall (well_formed b n s) Ps ->
  (check_level K m t s Ps = None <-> is_net b n m t s Ps).
Proof.
  intros n m t s K Ps B TM TK KN LPs WPs. unfold check_level, check_shape.
  rewrite find_first_none. split.
  - intro H. split; [exact LPs|]. split; [exact WPs|].
    intros BX LB VB NB SB.
    set (sh := shape BX).
    assert (C : In sh (comps (m - t) s)) by (apply In_comps; unfold sh, shape; rewrite map_length; auto).
    assert (F : Forall (fun d => d <= K) sh) by (apply (comps_le (m - t) s); auto).
    assert (LS : length sh = s) by (unfold sh, shape; rewrite map_length; auto).
    specialize (H sh C). rewrite scan_map_empty, scan_none in H.
    assert (Le : Forall (fun c => c <= b ^ t) (map (fun B' => count B' Ps) (boxes sh))).
    { rewrite Forall_forall. intros c I. apply in_map_iff in I as [B' [<- I]].
      apply in_boxes in I as [VB' SB'].
      destruct (count B' Ps) eqn:E; [lia|].
      assert (exists P, In P Ps /\ in_box B' P = true) as [P [IP HP]].
      { unfold count in E. destruct (filter (in_box B') Ps) as [|P r] eqn:FL; [discriminate|].
        exists P. apply (filter_In (in_box B') P Ps). rewrite FL. left. auto. }
      pose proof (proj1 (Forall_forall _ _) WPs P IP) as WP.
      assert (FP : fits sh P) by (apply (deep_fits K); eauto using wf_deep; destruct WP; lia).
      apply (in_box_iff sh B' P FP SB') in HP. rewrite <- E, HP.
      rewrite <- (cnt_key_count n s K sh P Ps); auto. specialize (H P IP). simpl in H. lia. }
    apply pigeonhole in Le.
    + rewrite Forall_forall in Le. apply Le. apply (in_map (fun B' => count B' Ps)). apply in_boxes. auto.
    + rewrite sum_counts, map_length, boxes_length, LPs.
      * fold sh in SB. rewrite SB, <- Nat.pow_add_r. f_equal. lia.
      * rewrite Forall_forall. intros P I. pose proof (proj1 (Forall_forall _ _) WPs P I) as WP.
        apply (deep_fits K); eauto using wf_deep. destruct WP; lia.
  - intros [_ [_ H]] sh C. rewrite scan_map_empty. apply scan_none. intros P I. simpl.
    pose proof (proj1 (Forall_forall _ _) WPs P I) as WP.
    assert (F : Forall (fun d => d <= K) sh) by (apply (comps_le (m - t) s); auto).
    apply In_comps in C as [LS SS].
    assert (FP : fits sh P) by (apply (deep_fits K); eauto using wf_deep; destruct WP; lia).
    rewrite (cnt_key_count n s K sh P Ps); auto.
    rewrite H; auto.
    + rewrite <- LS. transitivity (length (shape (box_of sh P)));
        [unfold shape; rewrite map_length; auto | rewrite shape_box_of; auto].
    + apply valid_box_of. exact FP.
    + clear -FP F KN. revert P FP. induction sh as [|d sh IH]; intros [|x P] FP; simpl in *;
      try tauto; constructor; inversion F; subst.
      * rewrite firstn_length. lia.
      * destruct FP as [_ [_ FP]]. apply IH; auto.
    + rewrite shape_box_of; auto.
Qed.

Corollary check_net_correct : forall n m t s Ps, 1 < b -> t <= m -> m - t <= n ->
  length Ps = b ^ m -> Forall (well_formed b n s) Ps ->
  (check_net m t s Ps = None <-> is_net b n m t s Ps).
Proof. intros. apply check_level_correct; auto. Qed.

(** The probe changes no verdict: it rejects only levels that the full scan rejects. *)
Lemma level_any_none : forall m t s Ps,
  level_any m t s Ps = None <-> check_level m m t s Ps = None.
Proof.
  intros m t s Ps. unfold level_any. destruct (64 <=? length Ps / 64); [|tauto].
  destruct (check_level m m t s (firstn (length Ps / 64) Ps)) as [[sh P]|] eqn:E; [|tauto].
  split; [discriminate|]. intro N. exfalso.
  apply find_first_some in E as [I S]. unfold check_shape in S. rewrite scan_map_empty in S.
  apply scan_firstn in S as [y Y]. unfold check_level in N. rewrite find_first_none in N.
  specialize (N sh I). unfold check_shape in N. rewrite scan_map_empty in N. congruence.
Qed.

Lemma in_box_empty : forall B P, Forall (fun p => p = []) B -> length B = length P -> in_box B P = true.
Proof.
  induction B as [|p B IH]; intros [|x P] F L; simpl in *; try discriminate; auto.
  inversion F; subst. rewrite IH; auto.
Qed.

(** Every set of [b^m] points is an [(m,m,s)]-net: its one box of [0] digits holds them all. *)
Lemma net_full : forall n m s Ps, length Ps = b ^ m -> Forall (well_formed b n s) Ps ->
  is_net b n m m s Ps.
Proof.
  intros n m s Ps L W. split; [exact L|]. split; [exact W|]. intros B LB _ _ SB.
  rewrite Nat.sub_diag in SB. rewrite <- L. unfold count. f_equal.
  assert (All : forall A (f : A -> bool) l, (forall x, In x l -> f x = true) -> filter f l = l).
  { clear. induction l as [|a r IH]; intro H; simpl; auto.
    rewrite (H a (or_introl eq_refl)), IH; auto. intros; apply H; right; auto. }
  apply All. rewrite Forall_forall in W. intros P I. apply in_box_empty.
    + rewrite Forall_forall. intros p Ip. unfold shape, sum in SB. clear -SB Ip.
      induction B as [|q B IH]; simpl in *; [tauto|]. destruct Ip as [->|Ip]; [destruct p; simpl in *; auto; lia|].
      apply IH; auto; lia.
    + destruct (W P I) as [LP _]. lia.
Qed.

Lemma t_search_seq : forall m s Ps len a,
  (exists t, a <= t < a + len /\ level_any m t s Ps = None) ->
  let r := t_search m s Ps (seq a len) in
  a <= r < a + len /\ level_any m r s Ps = None /\
  forall t, a <= t < r -> level_any m t s Ps <> None.
Proof.
  intros m s Ps len. induction len as [|len IH]; intros a [t [T L]]; [lia|]. simpl.
  destruct (level_any m a s Ps) as [f|] eqn:E.
  - destruct (IH (S a)) as [R1 [R2 R3]].
    + exists t. split; auto. destruct (Nat.eq_dec t a) as [->|N]; [congruence | lia].
    + split; [lia|]. split; auto. intros t' T'. destruct (Nat.eq_dec t' a) as [->|N].
      * rewrite E. discriminate.
      * apply R3. lia.
  - split; [lia|]. split; auto. intros; lia.
Qed.

(** The t search returns the t-value: the set is a [(t,m,s)]-net for the [t] it returns and for
    no smaller [t]. *)
Theorem t_value_correct : forall n m s Ps, 1 < b -> m <= n -> length Ps = b ^ m ->
  Forall (well_formed b n s) Ps ->
  t_value m s Ps <= m /\ is_net b n m (t_value m s Ps) s Ps /\
  forall t, t < t_value m s Ps -> ~ is_net b n m t s Ps.
Proof.
  intros n m s Ps B MN L W. unfold t_value.
  destruct (t_search_seq m s Ps (S m) 0) as [R1 [R2 R3]].
  - exists m. split; [lia|]. apply level_any_none. apply (check_level_correct n); auto; try lia.
    apply net_full; auto.
  - split; [lia|]. split.
    + apply level_any_none in R2. apply (check_level_correct n m _ s m) in R2; auto; lia.
    + intros t T N. apply (R3 t); [lia|]. apply level_any_none.
      apply (check_level_correct n m t s m); auto; lia.
Qed.

Lemma Forall_block : forall A (f : A -> Prop) p q l, Forall f l -> Forall f (firstn p (skipn q l)).
Proof.
  intros A f p q l H. rewrite Forall_forall in *. intros x I. apply H.
  apply in_firstn in I. rewrite <- (firstn_skipn q l). apply in_or_app. right. exact I.
Qed.

Lemma div_bound : forall N B i, B <> 0 -> (i < N / B <-> (i + 1) * B <= N).
Proof.
  intros N B i H. split; intro E.
  - pose proof (Nat.mul_div_le N B H). nia.
  - assert (i + 1 <= N / B) by (apply Nat.div_le_lower_bound; auto; lia). lia.
Qed.

(** The sequence check decides the (t,s)-sequence property for every block of [b^k] points,
    [t ≤ k ≤ M]. *)
Theorem check_sequence_correct : forall n t M s Ps, 1 < b -> M <= n ->
  Forall (well_formed b n s) Ps ->
  (check_sequence t M s Ps = None <->
   forall k i, t <= k <= M -> (i + 1) * b ^ k <= length Ps -> is_net b n k t s (block k i Ps)).
Proof.
  intros n t M s Ps B MN W. unfold check_sequence. rewrite find_first_none. split.
  - intros H k i K I. specialize (H k). rewrite find_first_none in H.
    assert (BK : b ^ k <> 0) by (apply pow_nonzero; auto).
    apply (check_net_correct n); try lia.
    + unfold block. rewrite firstn_length, skipn_length. nia.
    + unfold block. apply Forall_block. exact W.
    + apply H; [apply in_seq; lia|]. apply in_seq. split; [lia|]. simpl. apply div_bound; auto.
  - intros H k K. apply in_seq in K. rewrite find_first_none. intros i I. apply in_seq in I.
    assert (BK : b ^ k <> 0) by (apply pow_nonzero; auto).
    assert (Fit : (i + 1) * b ^ k <= length Ps) by (apply div_bound; auto; lia).
    apply (check_net_correct n); try lia.
    + unfold block. rewrite firstn_length, skipn_length. nia.
    + unfold block. apply Forall_block. exact W.
    + apply H; auto. lia.
Qed.

(** When no block of [b^(M+1)] points fits, the sequence check decides [is_sequence]. *)
Corollary check_sequence_is_sequence : forall n t M s Ps, 1 < b -> M <= n ->
  length Ps < b ^ S M -> Forall (well_formed b n s) Ps ->
  (check_sequence t M s Ps = None <-> is_sequence b n t s Ps).
Proof.
  intros n t M s Ps B MN L W. rewrite (check_sequence_correct n); auto. unfold is_sequence, block.
  split; intros H k i T F.
  - destruct (Nat.le_gt_cases k M) as [K|K]; [apply H; auto|].
    exfalso. assert (b ^ S M <= b ^ k) by (apply Nat.pow_le_mono_r; lia). nia.
  - apply H; auto. lia.
Qed.

End Checker.
