(** * Digit strings, boxes, and the overflow-only search: the ground the net checker stands on.

    - [scan]: a running histogram over any key function that returns the first element whose
      key's count passes [T] ([scan_none], [scan_some]), and the soundness of scanning a prefix
      first ([scan_firstn]);
    - [pigeonhole]: [length l] numbers none above [T] that sum to [length l · T] all equal [T];
    - [digit_value] of a digit string (most significant first) and [cut_prefix], the digit of a
      shape cut from a deeper prefix;
    - [strings], [boxes] of a shape and [box_of] a point, with the partition of the points by
      the boxes of one shape ([filter_boxes], [sum_counts]).
    [Checker.v] builds the checker on these. *)

From Coq Require Import List Arith Bool Lia.
Import ListNotations.
From Gartowen Require Import Nested.

Lemma filter_none : forall A (f : A -> bool) l, (forall z, In z l -> f z = false) -> filter f l = [].
Proof.
  induction l as [|a r IH]; intro H; simpl; auto.
  rewrite (H a (or_introl eq_refl)). apply IH. intros z I. apply H. right. exact I.
Qed.

Lemma in_firstn : forall A p (l : list A) x, In x (firstn p l) -> In x l.
Proof. intros A p l x I. rewrite <- (firstn_skipn p l). apply in_or_app. left. exact I. Qed.

(** ** The overflow-only search, for any key function. *)
Section Scan.

Variables (A : Type) (kf : A -> nat) (T : nat).

(** Points with key [k]. *)
Definition cnt_key (k : nat) (l : list A) : nat := length (filter (fun y => kf y =? k) l).

(** The running histogram [h]: each point adds one to its key's count, and the first point whose
    count passes [T] is returned (the Rust loop's [bad_key], found at that point). The key is
    bound once per point ([let]), so the extracted scan does not recompute it on every lookup. *)
Fixpoint scan (h : nat -> nat) (l : list A) : option A :=
  match l with
  | [] => None
  | x :: r =>
      let k := kf x in
      if T <? h k + 1 then Some x
      else scan (fun k' => if k' =? k then h k + 1 else h k') r
  end.

Lemma scan_none : forall l h,
  scan h l = None <-> forall x, In x l -> h (kf x) + cnt_key (kf x) l <= T.
Proof.
  unfold cnt_key. induction l as [|y r IH]; intro h; simpl; [split; [tauto | auto]|].
  destruct (T <? h (kf y) + 1) eqn:E.
  - split; [discriminate|]. intro H. specialize (H y (or_introl eq_refl)).
    rewrite Nat.eqb_refl in H. simpl in H. apply Nat.ltb_lt in E. lia.
  - apply Nat.ltb_ge in E. rewrite IH. split.
    + intros H x [<-|I].
      * rewrite Nat.eqb_refl. simpl.
        destruct (in_dec Nat.eq_dec (kf y) (map kf r)) as [M|M].
        -- apply in_map_iff in M as [z [Z I]]. specialize (H z I). cbv beta in H.
           rewrite Z, Nat.eqb_refl in H. lia.
        -- replace (length (filter (fun y0 => kf y0 =? kf y) r)) with 0; [lia|].
           rewrite filter_none; [reflexivity|].
           intros z I. apply Nat.eqb_neq. intro Z. apply M. rewrite <- Z. now apply in_map.
      * specialize (H x I). cbv beta in H. destruct (Nat.eq_dec (kf x) (kf y)) as [K|K].
        -- rewrite K in *. rewrite Nat.eqb_refl in *. simpl. lia.
        -- rewrite (proj2 (Nat.eqb_neq _ _) K) in H.
           rewrite (proj2 (Nat.eqb_neq _ _) (not_eq_sym K)). lia.
    + intros H x I. specialize (H x (or_intror I)). cbv beta.
      destruct (Nat.eq_dec (kf x) (kf y)) as [K|K].
      * rewrite K in *. rewrite Nat.eqb_refl in *. simpl in H. lia.
      * rewrite (proj2 (Nat.eqb_neq _ _) K).
        rewrite (proj2 (Nat.eqb_neq _ _) (not_eq_sym K)) in H. lia.
Qed.

Lemma scan_some : forall l h x, scan h l = Some x ->
  In x l /\ T < h (kf x) + cnt_key (kf x) l.
Proof.
  unfold cnt_key. induction l as [|y r IH]; intros h x H; simpl in H; [discriminate|].
  destruct (T <? h (kf y) + 1) eqn:E.
  - injection H as <-. apply Nat.ltb_lt in E. split; [left; auto|]. simpl.
    rewrite Nat.eqb_refl. simpl. lia.
  - apply IH in H as [I L]. split; [right; exact I|]. simpl. cbv beta in L.
    destruct (Nat.eq_dec (kf x) (kf y)) as [K|K].
    + rewrite K in *. rewrite Nat.eqb_refl in *. simpl. lia.
    + rewrite (proj2 (Nat.eqb_neq _ _) K) in L.
      rewrite (proj2 (Nat.eqb_neq _ _) (not_eq_sym K)). lia.
Qed.

Lemma cnt_key_firstn : forall k p l, cnt_key k (firstn p l) <= cnt_key k l.
Proof.
  unfold cnt_key. intros k p l. revert p.
  induction l as [|y r IH]; intros [|p]; simpl; try lia.
  destruct (kf y =? k); simpl; specialize (IH p); lia.
Qed.

(** A box that overflows among the first [p] points overflows among all (the probe's
    soundness: counts only grow with more points). *)
Lemma scan_firstn : forall p l x, scan (fun _ => 0) (firstn p l) = Some x ->
  exists y, scan (fun _ => 0) l = Some y.
Proof.
  intros p l x H. destruct (scan (fun _ => 0) l) as [y|] eqn:E; [eauto|].
  apply scan_some in H as [I L]. rewrite scan_none in E.
  specialize (E x (in_firstn _ p l x I)).
  pose proof (cnt_key_firstn (kf x) p l). lia.
Qed.

End Scan.

(** The first element of a list whose test fails, with its failure. *)
Fixpoint find_first {A B} (f : A -> option B) (l : list A) : option (A * B) :=
  match l with
  | [] => None
  | x :: r => match f x with Some y => Some (x, y) | None => find_first f r end
  end.

Lemma find_first_none : forall A B (f : A -> option B) l,
  find_first f l = None <-> forall x, In x l -> f x = None.
Proof.
  induction l as [|x r IH]; simpl; [split; [tauto | auto]|].
  destruct (f x) eqn:E; split.
  - discriminate.
  - intro H. rewrite H in E; [discriminate | left; auto].
  - intros H y [<-|I]; auto. apply IH; auto.
  - intro H. apply IH. auto.
Qed.

Lemma find_first_some : forall A B (f : A -> option B) l x y,
  find_first f l = Some (x, y) -> In x l /\ f x = Some y.
Proof.
  induction l as [|z r IH]; simpl; intros x y H; [discriminate|].
  destruct (f z) eqn:E.
  - injection H as <- <-. auto.
  - apply IH in H as [I F]. auto.
Qed.

(** Every element of a list of [length l] numbers summing to [length l · T] and none above [T]
    is [T]: the pigeonhole step that lets the checker search only for overflow. *)
Lemma pigeonhole : forall T l, Forall (fun c => c <= T) l -> list_sum l = length l * T ->
  Forall (fun c => c = T) l.
Proof.
  intros T l. induction l as [|c r IH]; intros F S; constructor; inversion F; subst; simpl in S.
  - assert (list_sum r <= length r * T); [|lia].
    clear -H2. induction r as [|d r IH]; simpl; [lia|]. inversion H2; subst. specialize (IH H3). lia.
  - apply IH; auto. assert (list_sum r <= length r * T); [|lia].
    clear -H2. induction r as [|d r IH]; simpl; [lia|]. inversion H2; subst. specialize (IH H3). lia.
Qed.

Section Digits.

Variable b : nat.

(** The value of a digit string, most significant first: [floor(x·b^K)] for the first [K]
    digits of a point's coordinate. *)
Definition digit_value (x : list nat) : nat := fold_left (fun a d => a * b + d) x 0.

Lemma fold_val : forall y a, fold_left (fun a d => a * b + d) y a = a * b ^ length y + digit_value y.
Proof.
  unfold digit_value. induction y as [|d y IH]; intro a; simpl; [lia|].
  rewrite (IH (a * b + d)), (IH d). nia.
Qed.

Lemma val_app : forall x y, digit_value (x ++ y) = digit_value x * b ^ length y + digit_value y.
Proof. intros x y. unfold digit_value at 1. rewrite fold_left_app. apply fold_val. Qed.

Lemma val_cons : forall d y, digit_value (d :: y) = d * b ^ length y + digit_value y.
Proof. intros d y. apply (val_app [d] y). Qed.

Lemma val_lt : forall y, valid b y -> digit_value y < b ^ length y.
Proof.
  induction y as [|d y IH]; intro H; [unfold digit_value; simpl; lia|].
  inversion H; subst. rewrite val_cons. simpl. specialize (IH H3). nia.
Qed.

Lemma val_inj : forall x y, valid b x -> valid b y -> length x = length y -> digit_value x = digit_value y -> x = y.
Proof.
  induction x as [|d x IH]; intros [|e y] Hx Hy L V; simpl in L; try discriminate; auto.
  inversion Hx; inversion Hy; subst. rewrite !val_cons in V. injection L as L.
  pose proof (val_lt x H2). pose proof (val_lt y H6). rewrite <- L in *.
  assert (d = e) by (destruct (Nat.lt_trichotomy d e) as [D|[D|D]]; auto; nia). subst.
  f_equal. apply IH; auto. lia.
Qed.

Lemma pow_nonzero : 1 < b -> forall k, b ^ k <> 0.
Proof. intros B k. apply Nat.pow_nonzero. lia. Qed.

(** The cut of [box_keys.rs]: the digit [a = floor(x·b^d)] of a shape is the prefix at depth
    [K] divided by [b^(K−d)]. *)
Lemma cut_prefix : forall x d K, 1 < b -> valid b x -> d <= K -> K <= length x ->
  digit_value (firstn K x) / b ^ (K - d) = digit_value (firstn d x).
Proof.
  intros x d K B V D L.
  replace (firstn K x) with (firstn d x ++ firstn (K - d) (skipn d x)).
  2:{ clear V L B. revert d K D. induction x as [|a x IH]; intros [|d] [|K] D; simpl; auto; try lia.
      - rewrite firstn_nil. reflexivity.
      - f_equal. rewrite (IH d K); auto. lia. }
  rewrite val_app, firstn_length, skipn_length. replace (Nat.min (K - d) (length x - d)) with (K - d) by lia.
  rewrite Nat.div_add_l by (apply pow_nonzero; auto).
  rewrite Nat.div_small; [lia|].
  replace (K - d) with (length (firstn (K - d) (skipn d x))) at 2
    by (rewrite firstn_length, skipn_length; lia).
  apply val_lt. apply valid_firstn. unfold valid in *. rewrite <- (firstn_skipn d x) in V.
  apply Forall_app in V. tauto.
Qed.

(** ** Boxes of a shape. *)

(** Every digit string of length [d]. *)
Fixpoint strings (d : nat) : list (list nat) :=
  match d with
  | 0 => [[]]
  | S d' => flat_map (fun c => map (cons c) (strings d')) (seq 0 b)
  end.

(** Every box of a shape: one string of length [d_j] per coordinate. *)
Fixpoint boxes (sh : list nat) : list (list (list nat)) :=
  match sh with
  | [] => [[]]
  | d :: sh' => flat_map (fun p => map (cons p) (boxes sh')) (strings d)
  end.

Lemma length_flat_map_const : forall A B (f : A -> list B) l c,
  (forall x, In x l -> length (f x) = c) -> length (flat_map f l) = length l * c.
Proof.
  induction l as [|x r IH]; intros c H; simpl; auto.
  rewrite app_length, H by (left; auto). rewrite (IH c); auto. intros; apply H; right; auto.
Qed.

Lemma strings_length : forall d, length (strings d) = b ^ d.
Proof.
  induction d as [|d IH]; simpl; auto.
  rewrite (length_flat_map_const _ _ _ _ (b ^ d)); [rewrite seq_length; lia|].
  intros; rewrite map_length; auto.
Qed.

Lemma boxes_length : forall sh, length (boxes sh) = b ^ sum sh.
Proof.
  induction sh as [|d sh IH]; simpl; auto.
  rewrite (length_flat_map_const _ _ _ _ (b ^ sum sh)).
  - rewrite strings_length, Nat.pow_add_r. lia.
  - intros; rewrite map_length; auto.
Qed.

Lemma in_strings : forall d p, In p (strings d) <-> valid b p /\ length p = d.
Proof.
  induction d as [|d IH]; intro p; simpl.
  - split; [intros [<-|[]]; split; [constructor | auto] | intros [_ L]; left; destruct p; simpl in *; auto; discriminate].
  - rewrite in_flat_map. split.
    + intros [c [C M]]. apply in_map_iff in M as [r [<- R]]. apply IH in R as [V L].
      apply in_seq in C. split; [constructor; auto; lia | simpl; auto].
    + intros [V L]. destruct p as [|c r]; [discriminate|]. inversion V; subst.
      exists c. split; [apply in_seq; lia|]. apply in_map. apply IH. auto.
Qed.

Lemma in_boxes : forall sh B, In B (boxes sh) <-> valid_point b B /\ shape B = sh.
Proof.
  induction sh as [|d sh IH]; intro B; simpl.
  - split; [intros [<-|[]]; split; [constructor | auto] | intros [_ S]; left; destruct B; simpl in *; auto; discriminate].
  - rewrite in_flat_map. split.
    + intros [p [P M]]. apply in_map_iff in M as [B' [<- R]]. apply IH in R as [V S].
      apply in_strings in P as [VP L]. split; [constructor; auto | simpl; f_equal; auto].
    + intros [V S]. destruct B as [|p B']; [discriminate|]. inversion V; subst.
      injection S as L S. exists p. split; [apply in_strings; auto|]. apply in_map. apply IH. auto.
Qed.

(** The box of shape [sh] that holds point [P]: its first [d_j] digits in each coordinate. *)
Fixpoint box_of (sh : list nat) (P : list (list nat)) : list (list nat) :=
  match sh, P with
  | d :: sh', x :: P' => firstn d x :: box_of sh' P'
  | _, _ => []
  end.

(** A point has room for a shape when it has [length sh] coordinates, each valid and with at
    least [d_j] digits. *)
Fixpoint fits (sh : list nat) (P : list (list nat)) : Prop :=
  match sh, P with
  | [], [] => True
  | d :: sh', x :: P' => valid b x /\ d <= length x /\ fits sh' P'
  | _, _ => False
  end.

Lemma prefix_of_iff : forall p x, prefix_of p x = true <-> firstn (length p) x = p.
Proof.
  intros p x. unfold prefix_of. destruct (list_eq_dec Nat.eq_dec (firstn (length p) x) p); split;
  auto; discriminate.
Qed.

Lemma in_box_iff : forall sh B P, fits sh P -> shape B = sh ->
  (in_box B P = true <-> B = box_of sh P).
Proof.
  induction sh as [|d sh IH]; intros [|p B] [|x P] F S; simpl in *; try tauto; try discriminate.
  all: try (split; auto; fail).
  destruct F as [V [L F]]. injection S as Lp S. rewrite andb_true_iff, prefix_of_iff, (IH B P F S).
  rewrite Lp. split; [intros [-> ->]; auto | intro E; injection E as -> ->; auto].
Qed.

Lemma box_of_in_boxes : forall sh P, fits sh P -> In (box_of sh P) (boxes sh).
Proof.
  intros sh P F. apply in_boxes. revert P F. induction sh as [|d sh IH]; intros [|x P] F;
  simpl in *; try tauto.
  - split; [constructor | auto].
  - destruct F as [V [L F]]. destruct (IH P F) as [VB SB]. split.
    + constructor; auto. apply valid_firstn. exact V.
    + f_equal; auto. rewrite firstn_length. lia.
Qed.

Lemma prefix_of_cons : forall c r y x, prefix_of (c :: r) (y :: x) = (y =? c) && prefix_of r x.
Proof.
  intros. apply Bool.eq_iff_eq_true. rewrite andb_true_iff, !prefix_of_iff, Nat.eqb_eq. simpl.
  split; [intro E; injection E; auto | intros [-> ->]; auto].
Qed.

Lemma filter_flat_map_length : forall A B (f : B -> bool) (g : A -> list B) l,
  length (filter f (flat_map g l)) = list_sum (map (fun x => length (filter f (g x))) l).
Proof. induction l as [|x r IH]; simpl; auto. rewrite filter_app, app_length, IH. reflexivity. Qed.

Lemma indicator_seq_0 : forall n a y, y < a ->
  list_sum (map (fun c => if y =? c then 1 else 0) (seq a n)) = 0.
Proof.
  induction n as [|n IH]; intros a y H; simpl; auto.
  rewrite (proj2 (Nat.eqb_neq y a)) by lia. apply IH. lia.
Qed.

Lemma indicator_seq_1 : forall n a y, a <= y < a + n ->
  list_sum (map (fun c => if y =? c then 1 else 0) (seq a n)) = 1.
Proof.
  induction n as [|n IH]; intros a y H; simpl; [lia|].
  destruct (Nat.eq_dec y a) as [->|E].
  - rewrite Nat.eqb_refl, indicator_seq_0 by lia. reflexivity.
  - rewrite (proj2 (Nat.eqb_neq y a) E). apply IH. lia.
Qed.

Lemma strings_prefix : forall d x, valid b x -> d <= length x ->
  length (filter (fun p => prefix_of p x) (strings d)) = 1.
Proof.
  induction d as [|d IH]; intros x V L; [reflexivity|].
  destruct x as [|y x]; simpl in L; [lia|]. inversion V; subst. simpl.
  rewrite filter_flat_map_length.
  rewrite (map_ext_in _ (fun c => if y =? c then 1 else 0)).
  - apply indicator_seq_1. lia.
  - intros c _. transitivity (if y =? c then length (filter (fun p => prefix_of p x) (strings d)) else 0).
    + clear. induction (strings d) as [|p r IH]; simpl; [destruct (y =? c); auto|].
      rewrite prefix_of_cons. destruct (y =? c), (prefix_of p x); simpl; auto.
    + rewrite IH by (auto; lia). reflexivity.
Qed.

(** Each point that fits lies in exactly one box of the shape. *)
Lemma filter_boxes : forall sh P, fits sh P ->
  length (filter (fun B => in_box B P) (boxes sh)) = 1.
Proof.
  induction sh as [|d sh IH]; intros [|x P] F; simpl in F; try tauto; try reflexivity.
  destruct F as [V [L F]]. simpl. rewrite filter_flat_map_length.
  rewrite (map_ext_in _ (fun p => if prefix_of p x then 1 else 0)).
  - transitivity (length (filter (fun p => prefix_of p x) (strings d)));
      [|apply strings_prefix; auto].
    clear. induction (strings d) as [|p r IH]; simpl; auto.
    destruct (prefix_of p x); simpl; rewrite IH; auto.
  - intros p _. transitivity (if prefix_of p x then length (filter (fun B => in_box B P) (boxes sh)) else 0).
    + clear. induction (boxes sh) as [|B r IH]; simpl; [destruct (prefix_of p x); auto|].
      destruct (prefix_of p x), (in_box B P); simpl; auto.
    + rewrite IH by exact F. reflexivity.
Qed.

(** The boxes of a shape partition the points: their counts add up to N. *)
Lemma sum_counts : forall sh Ps, Forall (fits sh) Ps ->
  list_sum (map (fun B => count B Ps) (boxes sh)) = length Ps.
Proof.
  intros sh Ps F. induction Ps as [|P Ps IH]; simpl.
  - unfold count. simpl. clear. induction (boxes sh); simpl; auto.
  - inversion F; subst.
    transitivity (length (filter (fun B => in_box B P) (boxes sh)) +
                  list_sum (map (fun B => count B Ps) (boxes sh))).
    + unfold count. simpl. clear. induction (boxes sh) as [|B r IH]; simpl; auto.
      destruct (in_box B P); simpl; rewrite IH; lia.
    + rewrite filter_boxes, IH by auto. reflexivity.
Qed.

End Digits.
