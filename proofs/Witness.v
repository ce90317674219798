(** * Re-checking a net verdict from its witness, on the user's own words.

    [gartowen check --witness FILE] writes the points as the checker read them (words of [w]
    bits) and what its verdict rests on: for "fails at t", a shape, a box and the box's count;
    for "holds at t", the claim alone; for "the t-value is T", the claim that the set is a
    (T,m,s)-net and the failing box at [T − 1]. [revalidate] re-checks that witness with
    definitions extracted from here ([Extract.v], run by [extracted/revalidate.ml]):
    - the words become digits by [word_digits] (the first [m] base-b digits of [x / 2^w]:
      [word_digits_value]);
    - a failing box is counted directly ([Nested.count], the definition): O(N);
    - "holds" is re-decided by the proved counting checker ([Checker.check_net]) with its
      histogram in a trie ([ScanMap.scan_map], equal to [Boxes.scan]) and its box keys by
      Horner's rule ([keyh], equal to [Checker.key]);
    - the t-value needs one full level and one box: the net property is monotone in t
      ([NetMonotone.net_monotone_le]), so a failing box at [T − 1] rules out every t < T.
    [revalidate_sound] states what a [true] answer proves. *)

From Coq Require Import List Arith Bool Lia FMapPositive.
Import ListNotations.
From Gartowen Require Import Nested Boxes Checker NetMonotone ScanMap.

Section Witness.

Variable b : nat.

(** ** Digits of words. *)

(** The [n] base-b digits of [v mod b^n], most significant first. *)
Fixpoint digits (n v : nat) : list nat :=
  match n with
  | 0 => []
  | S n' => digits n' (v / b) ++ [v mod b]
  end.

Lemma digits_length : forall n v, length (digits n v) = n.
Proof.
  induction n as [|n IH]; intro v; simpl; auto. rewrite app_length, IH. simpl. lia.
Qed.

Lemma digits_valid : forall n v, 0 < b -> valid b (digits n v).
Proof.
  induction n as [|n IH]; intros v B; simpl; [constructor|].
  unfold valid. apply Forall_app. split; [apply IH; exact B|].
  constructor; [apply Nat.mod_upper_bound; lia | constructor].
Qed.

Lemma digits_value : forall n v, 0 < b -> digit_value b (digits n v) = v mod b ^ n.
Proof.
  induction n as [|n IH]; intros v B.
  { rewrite Nat.pow_0_r, Nat.mod_1_r. reflexivity. }
  simpl digits. rewrite val_app, IH by auto. rewrite Nat.pow_succ_r'.
  assert (b ^ n <> 0) by (apply Nat.pow_nonzero; lia).
  rewrite Nat.mod_mul_r by lia. simpl length.
  rewrite Nat.pow_1_r. change (digit_value b [v mod b]) with (0 * b + v mod b). lia.
Qed.

(** The first [n] base-b digits of the word [x] read as [x / 2^w]. *)
Definition word_digits (w n x : nat) : list nat := digits n (x * b ^ n / 2 ^ w).

(** Their value is [⌊x·b^n / 2^w⌋]: the point [x / 2^w] lies in the digit string's cell. *)
Theorem word_digits_value : forall w n x, 1 < b -> x < 2 ^ w ->
  digit_value b (word_digits w n x) = x * b ^ n / 2 ^ w.
Proof.
  intros w n x B X. unfold word_digits. rewrite digits_value by lia.
  apply Nat.mod_small. apply Nat.div_lt_upper_bound; [apply Nat.pow_nonzero; lia|].
  pose proof (pow_nonzero b ltac:(lia) n). nia.
Qed.

Definition point_of_words (w n : nat) (xs : list nat) : list (list nat) :=
  map (word_digits w n) xs.

Lemma point_of_words_wf : forall w n s xs, 1 < b -> length xs = s ->
  well_formed b n s (point_of_words w n xs).
Proof.
  intros w n s xs B L. unfold well_formed, point_of_words, valid_point.
  rewrite map_length. split; [exact L|]. split; rewrite Forall_forall; intros x I;
  apply in_map_iff in I as [y [<- _]]; [apply digits_valid; lia | apply digits_length].
Qed.

(** ** The counting checker, fast. *)

(** [Checker.key] by Horner's rule: [keyh K sh P acc = acc · b^(Σ sh) + key K sh P]. *)
Fixpoint keyh (K : nat) (sh : list nat) (P : list (list nat)) (acc : nat) : nat :=
  match sh, P with
  | d :: sh', x :: P' => keyh K sh' P' (acc * b ^ d + digit_value b (firstn K x) / b ^ (K - d))
  | _, _ => acc
  end.

Lemma keyh_key : forall K sh P acc, length sh = length P ->
  keyh K sh P acc = acc * b ^ sum sh + key b K sh P.
Proof.
  induction sh as [|d sh IH]; intros [|x P] acc L; simpl in *; try discriminate.
  - unfold sum. simpl. lia.
  - rewrite IH by lia. unfold sum. simpl. fold (sum sh). rewrite Nat.pow_add_r. lia.
Qed.

(** Each coordinate's prefix value at depth [K], computed once per point for every shape. *)
Definition vals (K : nat) (P : list (list nat)) : list nat :=
  map (fun x => digit_value b (firstn K x)) P.

(** [keyh] on the prefix values. *)
Fixpoint keyv (K : nat) (sh : list nat) (V : list nat) (acc : nat) : nat :=
  match sh, V with
  | d :: sh', v :: V' => keyv K sh' V' (acc * b ^ d + v / b ^ (K - d))
  | _, _ => acc
  end.

Lemma keyv_vals : forall K sh P acc, keyv K sh (vals K P) acc = keyh K sh P acc.
Proof. induction sh as [|d sh IH]; intros [|x P] acc; simpl; auto. Qed.

Definition is_none {A} (o : option A) : bool := match o with None => true | Some _ => false end.

Definition check_shape_fast (K t : nat) (Vs : list (list nat)) (sh : list nat) :=
  scan_map _ (fun V => keyv K sh V 0) (b ^ t) (PositiveMap.empty nat) Vs.

(** The counting checker on the points' prefix values: [None] when the net holds. *)
Definition check_net_fast (m t s : nat) (Ps : list (list (list nat))) :=
  let Vs := map (vals (m - t)) Ps in
  find_first (check_shape_fast (m - t) t Vs) (comps (m - t) s).

Lemma find_first_none_ext : forall A B C (f : A -> option B) (g : A -> option C) l,
  (forall x, In x l -> is_none (f x) = is_none (g x)) ->
  is_none (find_first f l) = is_none (find_first g l).
Proof.
  induction l as [|x r IH]; intro H; simpl; auto. pose proof (H x (or_introl eq_refl)) as Hx.
  destruct (f x), (g x); simpl in Hx; try discriminate; auto.
  apply IH. intros; apply H; right; auto.
Qed.

Lemma scan_map_map : forall A B (g : A -> B) kf T h l,
  is_none (scan_map B kf T h (map g l)) = is_none (scan_map A (fun x => kf (g x)) T h l).
Proof.
  intros A B g kf T h l. revert h. induction l as [|x r IH]; intro h; simpl; auto.
  destruct (T <? get h (kf (g x)) + 1); auto.
Qed.

Lemma scan_map_ext : forall A (f g : A -> nat) T h l, (forall x, In x l -> f x = g x) ->
  scan_map A f T h l = scan_map A g T h l.
Proof.
  intros A f g T h l. revert h. induction l as [|x r IH]; intros h H; simpl; auto.
  rewrite H by (left; auto). destruct (T <? get h (g x) + 1); auto.
  apply IH. intros; apply H; right; auto.
Qed.

Lemma scan_ext : forall A (f g : A -> nat) T h l, (forall x, In x l -> f x = g x) ->
  scan A f T h l = scan A g T h l.
Proof.
  intros A f g T h l. revert h. induction l as [|x r IH]; intros h H; simpl; auto.
  rewrite H by (left; auto). destruct (T <? h (g x) + 1); auto.
  apply IH. intros; apply H; right; auto.
Qed.

(** The fast checker answers what the proved checker answers, on well-formed points. *)
Theorem check_net_fast_eq : forall n m t s Ps, Forall (well_formed b n s) Ps ->
  is_none (check_net_fast m t s Ps) = is_none (check_net b m t s Ps).
Proof.
  intros n m t s Ps W. unfold check_net_fast, check_net, check_level.
  apply find_first_none_ext. intros sh I. apply In_comps in I as [L _].
  unfold check_shape_fast, check_shape. rewrite scan_map_map.
  rewrite (scan_map_ext _ _ (fun P => keyh (m - t) sh P 0)) by (intros; apply keyv_vals).
  rewrite !scan_map_empty. f_equal. apply scan_ext.
  intros P IP. rewrite Forall_forall in W. destruct (W P IP) as [LP _].
  rewrite keyh_key by lia. lia.
Qed.

Corollary check_net_fast_correct : forall n m t s Ps, 1 < b -> t <= m -> m - t <= n ->
  length Ps = b ^ m -> Forall (well_formed b n s) Ps ->
  (is_none (check_net_fast m t s Ps) = true <-> is_net b n m t s Ps).
Proof.
  intros n m t s Ps B T K L W. rewrite (check_net_fast_eq n) by exact W.
  rewrite <- (check_net_correct b n m t s Ps); auto.
  destruct (check_net b m t s Ps); simpl; split; congruence.
Qed.

(** ** A failing box, re-counted. *)

(** The box of a witness: shape [sh], coordinate [j]'s prefix the [sh_j] digits of [av_j]. *)
Definition box_of_index (sh av : list nat) : list (list nat) :=
  map (fun da => digits (fst da) (snd da)) (combine sh av).

Lemma box_of_index_shape : forall sh av, length sh = length av ->
  shape (box_of_index sh av) = sh.
Proof.
  induction sh as [|d sh IH]; intros [|a av] L; simpl in *; try discriminate; auto.
  unfold shape in *. simpl. rewrite digits_length. f_equal. apply IH. lia.
Qed.

(** The witness box is a box of [m − t] digits (each index below [b^(sh_j)], each prefix at
    most [n] digits) that holds [c ≠ b^t] points. *)
Definition recheck_fail (n m t s : nat) (Ps : list (list (list nat))) (sh av : list nat)
  (c : nat) : bool :=
  (length sh =? s) && (length av =? s) && (sum sh =? m - t) &&
  forallb (fun d => d <=? n) sh &&
  forallb (fun da => snd da <? b ^ fst da) (combine sh av) &&
  (count (box_of_index sh av) Ps =? c) && negb (c =? b ^ t).

Theorem recheck_fail_sound : forall n m t s Ps sh av c, 1 < b ->
  recheck_fail n m t s Ps sh av c = true -> ~ is_net b n m t s Ps.
Proof.
  intros n m t s Ps sh av c B R [_ [_ Box]]. unfold recheck_fail in R.
  repeat rewrite andb_true_iff in R.
  destruct R as [[[[[[Ls La] Sm] Dn] _] Cnt] Ne].
  apply Nat.eqb_eq in Ls, La, Sm, Cnt. apply negb_true_iff, Nat.eqb_neq in Ne.
  apply Ne. rewrite <- Cnt. apply Box.
  - unfold box_of_index. rewrite map_length, combine_length. lia.
  - unfold valid_point, box_of_index. rewrite Forall_forall. intros p I.
    apply in_map_iff in I as [da [<- _]]. apply digits_valid. lia.
  - unfold box_of_index. rewrite Forall_forall. intros p I.
    apply in_map_iff in I as [[d a] [<- I]]. simpl. rewrite digits_length.
    apply in_combine_l in I. rewrite forallb_forall in Dn. apply Nat.leb_le, Dn, I.
  - rewrite box_of_index_shape by lia. exact Sm.
Qed.

(** ** The t-value from one level and one box. *)

Theorem t_value_witness : forall n m s T Ps sh av c, 1 < b -> 0 < s -> m <= n -> T <= m ->
  length Ps = b ^ m -> Forall (well_formed b n s) Ps ->
  is_none (check_net_fast m T s Ps) = true ->
  (T = 0 \/ recheck_fail n m (T - 1) s Ps sh av c = true) ->
  forall t, t <= m -> (is_net b n m t s Ps <-> T <= t).
Proof.
  intros n m s T Ps sh av c B S MN TM L W H F t TM'.
  assert (NT : is_net b n m T s Ps) by (apply (check_net_fast_correct n); auto; lia).
  split.
  - intro N. destruct (Nat.le_gt_cases T t) as [G|G]; auto. exfalso.
    destruct F as [F|F]; [lia|]. apply (recheck_fail_sound n m (T - 1) s Ps sh av c B F).
    apply (net_monotone_le b n m t (T - 1) s Ps); auto; nia.
  - intro G. apply (net_monotone_le b n m T t s Ps); auto. nia.
Qed.

(** ** The re-check of a witness. *)

(** What a witness claims of the set at [m] digits: the net property at [t] holds, or fails in
    box [(sh, av)] holding [c] points, or the t-value is [t] (with the failing box at [t − 1]
    when [t > 0]). *)
Inductive claim :=
  | Holds (t : nat)
  | Fails (t : nat) (sh av : list nat) (c : nat)
  | TValue (t : nat) (sh av : list nat) (c : nat).

Definition revalidate (w m s : nat) (words : list (list nat)) (cl : claim) : bool :=
  let Ps := map (point_of_words w m) words in
  (1 <? b) && (0 <? s) && (length words =? b ^ m) &&
  forallb (fun xs => (length xs =? s) && forallb (fun x => x <? 2 ^ w) xs) words &&
  match cl with
  | Holds t => (t <=? m) && is_none (check_net_fast m t s Ps)
  | Fails t sh av c => (t <=? m) && recheck_fail m m t s Ps sh av c
  | TValue t sh av c =>
      (t <=? m) && is_none (check_net_fast m t s Ps) &&
      ((t =? 0) || recheck_fail m m (t - 1) s Ps sh av c)
  end.

(** A re-check that answers [true] proves the claim of the points whose digits the words
    give ([word_digits_value]), at precision [m]. *)
Theorem revalidate_sound : forall w m s words cl, revalidate w m s words cl = true ->
  let Ps := map (point_of_words w m) words in
  match cl with
  | Holds t => is_net b m m t s Ps
  | Fails t _ _ _ => ~ is_net b m m t s Ps
  | TValue t _ _ _ => forall t', t' <= m -> (is_net b m m t' s Ps <-> t <= t')
  end.
Proof.
  intros w m s words cl R Ps. unfold revalidate in R. fold Ps in R.
  repeat rewrite andb_true_iff in R. destruct R as [[[[B S] L] Wd] R].
  apply Nat.ltb_lt in B, S. apply Nat.eqb_eq in L.
  assert (LP : length Ps = b ^ m) by (unfold Ps; rewrite map_length; exact L).
  assert (W : Forall (well_formed b m s) Ps).
  { unfold Ps. rewrite Forall_forall. intros P I. apply in_map_iff in I as [xs [<- I]].
    rewrite forallb_forall in Wd. specialize (Wd xs I). apply andb_true_iff in Wd as [Lx _].
    apply point_of_words_wf; auto. apply Nat.eqb_eq, Lx. }
  destruct cl as [t|t sh av c|t sh av c]; repeat rewrite andb_true_iff in R.
  - destruct R as [T N]. apply Nat.leb_le in T. apply (check_net_fast_correct m); auto; lia.
  - destruct R as [_ F]. apply (recheck_fail_sound m m t s Ps sh av c); auto.
  - destruct R as [[T N] F]. apply Nat.leb_le in T. apply orb_true_iff in F.
    apply (t_value_witness m m s t Ps sh av c); auto.
    + destruct F as [F|F]; [left; apply Nat.eqb_eq, F | right; exact F].
Qed.

End Witness.
