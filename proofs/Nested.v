(** * Nested scrambles, elementary boxes, and net preservation (theorem T2).

    A digit in base [b] is a natural number below [b]; a digit string is a list of digits, most
    significant first. A nested scramble assigns to every prefix [p] (the ORIGINAL digits above a
    position) a bijection [sigma p] of the digits, with inverse [tau p]. Its action maps digit
    [d] at prefix [p] to [sigma p d]. An elementary box in [s] dimensions is a tuple of prefixes,
    one per coordinate; a point lies in it when each coordinate starts with its prefix. *)

From Coq Require Import List Arith Lia.
Import ListNotations.

Section Nested.

Variable b : nat.

Definition valid (x : list nat) : Prop := Forall (fun d => d < b) x.

Record nested_scramble := {
  sigma : list nat -> nat -> nat;
  tau : list nat -> nat -> nat;
  sigma_lt : forall p d, d < b -> sigma p d < b;
  tau_lt : forall p d, d < b -> tau p d < b;
  tau_sigma : forall p d, d < b -> tau p (sigma p d) = d;
  sigma_tau : forall p d, d < b -> sigma p (tau p d) = d
}.

Fixpoint act (S : nested_scramble) (pre x : list nat) : list nat :=
  match x with
  | [] => []
  | d :: r => sigma S pre d :: act S (pre ++ [d]) r
  end.

Fixpoint unact (S : nested_scramble) (pre y : list nat) : list nat :=
  match y with
  | [] => []
  | e :: r => tau S pre e :: unact S (pre ++ [tau S pre e]) r
  end.

Definition scramble S x := act S [] x.
Definition unscramble S y := unact S [] y.

Lemma act_length : forall S x pre, length (act S pre x) = length x.
Proof. induction x; simpl; auto. Qed.

Lemma unact_length : forall S y pre, length (unact S pre y) = length y.
Proof. induction y; simpl; auto. Qed.

Lemma act_valid : forall S x pre, valid x -> valid (act S pre x).
Proof.
  induction x as [|d r IH]; intros pre H; simpl; constructor; inversion H; subst.
  - apply sigma_lt; auto.
  - apply IH; auto.
Qed.

Lemma unact_valid : forall S y pre, valid y -> valid (unact S pre y).
Proof.
  induction y as [|e r IH]; intros pre H; simpl; constructor; inversion H; subst.
  - apply tau_lt; auto.
  - apply IH; auto.
Qed.

Lemma unact_act : forall S x pre, valid x -> unact S pre (act S pre x) = x.
Proof.
  induction x as [|d r IH]; intros pre H; simpl; auto.
  inversion H; subst. rewrite tau_sigma by auto. f_equal. apply IH; auto.
Qed.

Lemma act_unact : forall S y pre, valid y -> act S pre (unact S pre y) = y.
Proof.
  induction y as [|e r IH]; intros pre H; simpl; auto.
  inversion H; subst. rewrite sigma_tau by auto. f_equal. apply IH; auto.
Qed.

Lemma act_firstn : forall S x k pre, firstn k (act S pre x) = act S pre (firstn k x).
Proof.
  induction x as [|d r IH]; intros [|k] pre; simpl; auto.
  f_equal. apply IH.
Qed.

Lemma unact_firstn : forall S y k pre, firstn k (unact S pre y) = unact S pre (firstn k y).
Proof.
  induction y as [|e r IH]; intros [|k] pre; simpl; auto.
  f_equal. apply IH.
Qed.

Lemma valid_firstn : forall x k, valid x -> valid (firstn k x).
Proof.
  induction x as [|d r IH]; intros [|k] H; simpl; try constructor.
  - inversion H; auto.
  - apply IH. inversion H; auto.
Qed.

(** T2, level classes: x lies in the level-k class of p exactly when its image lies in the
    level-k class of p's image; and every point of the image class has a preimage in p's
    class. So each level-k prefix class is mapped bijectively onto a level-k prefix class. *)
Theorem prefix_class_image : forall S x p k,
  valid x -> valid p ->
  (firstn k x = p <-> firstn k (scramble S x) = scramble S p).
Proof.
  intros S x p k Hx Hp. unfold scramble. split; intro H.
  - rewrite act_firstn. now rewrite H.
  - rewrite act_firstn in H.
    assert (E : unact S [] (act S [] (firstn k x)) = unact S [] (act S [] p)) by now rewrite H.
    rewrite !unact_act in E; auto using valid_firstn.
Qed.

Theorem prefix_class_onto : forall S y p k,
  valid y -> valid p -> firstn k y = scramble S p ->
  exists x, valid x /\ firstn k x = p /\ scramble S x = y.
Proof.
  intros S y p k Hy Hp H. exists (unscramble S y). unfold scramble, unscramble in *.
  split; [apply unact_valid; auto|]. split.
  - rewrite unact_firstn, H. apply unact_act; auto.
  - apply act_unact; auto.
Qed.

(** Points, boxes and counts in s dimensions: one scramble per dimension. *)

Definition prefix_of (p x : list nat) : bool :=
  if list_eq_dec Nat.eq_dec (firstn (length p) x) p then true else false.

Fixpoint in_box (B P : list (list nat)) : bool :=
  match B, P with
  | [], [] => true
  | p :: B', x :: P' => prefix_of p x && in_box B' P'
  | _, _ => false
  end.

Definition count (B : list (list nat)) (Ps : list (list (list nat))) : nat :=
  length (filter (in_box B) Ps).

Fixpoint scr_from (Ss : nat -> nested_scramble) (j : nat) (P : list (list nat)) :=
  match P with
  | [] => []
  | x :: r => scramble (Ss j) x :: scr_from Ss (S j) r
  end.

Fixpoint unscr_from (Ss : nat -> nested_scramble) (j : nat) (P : list (list nat)) :=
  match P with
  | [] => []
  | x :: r => unscramble (Ss j) x :: unscr_from Ss (S j) r
  end.

Definition valid_point (P : list (list nat)) := Forall valid P.

Lemma prefix_of_scramble : forall S p x,
  valid p -> valid x -> prefix_of (scramble S p) (scramble S x) = prefix_of p x.
Proof.
  intros S p x Hp Hx. unfold prefix_of.
  replace (length (scramble S p)) with (length p) by (unfold scramble; rewrite act_length; auto).
  destruct (list_eq_dec Nat.eq_dec (firstn (length p) (scramble S x)) (scramble S p)) as [E|E];
  destruct (list_eq_dec Nat.eq_dec (firstn (length p) x) p) as [F|F]; auto.
  - exfalso. apply F. apply (prefix_class_image S x p (length p)); auto.
  - exfalso. apply E. apply (prefix_class_image S x p (length p)); auto.
Qed.

Lemma in_box_scr : forall Ss B P j,
  valid_point B -> valid_point P ->
  in_box (scr_from Ss j B) (scr_from Ss j P) = in_box B P.
Proof.
  induction B as [|p B IH]; intros [|x P] j HB HP; simpl; auto.
  inversion HB; inversion HP; subst. rewrite prefix_of_scramble by auto. f_equal. apply IH; auto.
Qed.

Lemma scr_unscr : forall Ss B j, valid_point B -> scr_from Ss j (unscr_from Ss j B) = B.
Proof.
  induction B as [|p B IH]; intros j H; simpl; auto.
  inversion H; subst. unfold scramble, unscramble. rewrite act_unact by auto. f_equal. auto.
Qed.

Lemma unscr_valid : forall Ss B j, valid_point B -> valid_point (unscr_from Ss j B).
Proof.
  induction B as [|p B IH]; intros j H; simpl; constructor; inversion H; subst.
  - apply unact_valid; auto.
  - apply IH; auto.
Qed.

Lemma scr_valid : forall Ss P j, valid_point P -> valid_point (scr_from Ss j P).
Proof.
  induction P as [|x P IH]; intros j H; simpl; constructor; inversion H; subst.
  - apply act_valid; auto.
  - apply IH; auto.
Qed.

Definition shape (B : list (list nat)) : list nat := map (@length nat) B.

Lemma shape_unscr : forall Ss B j, shape (unscr_from Ss j B) = shape B.
Proof.
  induction B as [|p B IH]; intro j; simpl; auto. unfold unscramble. rewrite unact_length. f_equal. auto.
Qed.

Lemma length_scr : forall Ss P j, length (scr_from Ss j P) = length P.
Proof. induction P; intros; simpl; auto. Qed.

(** T2, boxes: the count of the scrambled set in any box equals the count of the original set
    in the box's preimage, a box of the same shape. So the counts per box are permuted. *)
Theorem count_scrambled : forall Ss B Ps,
  valid_point B -> Forall valid_point Ps ->
  count B (map (scr_from Ss 0) Ps) = count (unscr_from Ss 0 B) Ps.
Proof.
  intros Ss B Ps HB HPs. unfold count.
  induction Ps as [|P Ps IH]; simpl; auto.
  inversion HPs; subst.
  rewrite <- (scr_unscr Ss B 0) at 1 by auto.
  rewrite in_box_scr by (auto using unscr_valid).
  destruct (in_box (unscr_from Ss 0 B) P); simpl; rewrite IH; auto.
Qed.

(** Nets at precision n: b^m points of s coordinates, each a valid string of length n; every
    box with prefixes of length ≤ n whose lengths sum to m − t holds exactly b^t points. *)

Definition sum (l : list nat) : nat := fold_right plus 0 l.

Definition well_formed (n s : nat) (P : list (list nat)) : Prop :=
  length P = s /\ valid_point P /\ Forall (fun x => length x = n) P.

Definition is_net (n m t s : nat) (Ps : list (list (list nat))) : Prop :=
  length Ps = b ^ m /\ Forall (well_formed n s) Ps /\
  forall B, length B = s -> valid_point B -> Forall (fun p => length p <= n) B ->
            sum (shape B) = m - t -> count B Ps = b ^ t.

Lemma scr_well_formed : forall Ss n s P j, well_formed n s P -> well_formed n s (scr_from Ss j P).
Proof.
  intros Ss n s P j [Hl [Hv Hn]]. split; [|split].
  - rewrite length_scr; auto.
  - apply scr_valid; auto.
  - clear Hl Hv. revert j. induction P as [|x P IH]; intro j; simpl; constructor; inversion Hn; subst.
    + unfold scramble. rewrite act_length. auto.
    + apply IH; auto.
Qed.

Lemma length_unscr : forall Ss B j, length (unscr_from Ss j B) = length B.
Proof. induction B; intros; simpl; auto. Qed.

Lemma unscr_lengths : forall Ss B j n,
  Forall (fun p => length p <= n) B -> Forall (fun p => length p <= n) (unscr_from Ss j B).
Proof.
  induction B as [|p B IH]; intros j n H; simpl; constructor; inversion H; subst.
  - unfold unscramble. rewrite unact_length. auto.
  - apply IH; auto.
Qed.

(** T2, nets: a coordinate-wise nested scramble maps a (t,m,s)-net to a (t,m,s)-net, for any
    base b and precision n. *)
Theorem net_preserved : forall Ss n m t s Ps,
  is_net n m t s Ps -> is_net n m t s (map (scr_from Ss 0) Ps).
Proof.
  intros Ss n m t s Ps [Hlen [Hwf Hbox]]. split; [|split].
  - rewrite map_length. auto.
  - rewrite Forall_map. eapply Forall_impl; [|exact Hwf]. intros P HP. apply scr_well_formed; auto.
  - intros B HlB HvB HnB Hsum.
    rewrite count_scrambled; auto.
    + apply Hbox.
      * rewrite length_unscr; auto.
      * apply unscr_valid; auto.
      * apply unscr_lengths; auto.
      * rewrite shape_unscr; auto.
    + eapply Forall_impl; [|exact Hwf]. intros P [_ [HP _]]. exact HP.
Qed.

(** (t,s)-sequences (finite prefix of one): every block of b^k consecutive points, k ≥ t, that
    fits in the list is a (t,k,s)-net. *)
Definition is_sequence (n t s : nat) (Ps : list (list (list nat))) : Prop :=
  forall k i, t <= k -> (i + 1) * b ^ k <= length Ps ->
    is_net n k t s (firstn (b ^ k) (skipn (i * b ^ k) Ps)).

Theorem sequence_preserved : forall Ss n t s Ps,
  is_sequence n t s Ps -> is_sequence n t s (map (scr_from Ss 0) Ps).
Proof.
  intros Ss n t s Ps H k i Htk Hfit.
  rewrite map_length in Hfit.
  rewrite skipn_map, firstn_map. apply net_preserved. apply H; auto.
Qed.

End Nested.
