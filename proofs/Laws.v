(** * Laws of nested scrambles on a finite model: exact counting over every assignment of node
    permutations in a depth-n tree.

    A law of node permutations is a finite list [G] of maps (the uniform law on the list, with
    multiplicity). A tree of depth [n] carries one map per node; [trees n] lists every tree of
    depth [n] with maps from [G], each exactly once, so counting trees is computing
    probabilities under independent node permutations with law [G] (the count divided by
    [length (trees n)]).

    - [output_uniform]: when [G] is uniformly transitive (each [d] goes to each [e] under the
      same number of maps), every output digit string is uniform.
    - [pair_lemma]: when [G] is also uniformly 2-transitive, two inputs that first differ at
      digit [k] have outputs that agree on the first [k] digits, differ at digit [k] with every
      ordered pair of distinct digits equally likely, and are uniform and independent below:
      Owen's pair lemma, exactly.
    - [art_law_transitive]: the ART node law (ψ from any list [H] of digit maps, then an
      independent uniform translation) is always uniformly transitive, so every ART variant has
      uniform output strings whatever its ψ group; the pair lemma needs 2-transitivity, which
      AGL(q,2) has ([agl3_two_transitive], and S_4 = AGL(2,2)) and translations alone do not
      ([translations_not_two_transitive]). *)

From Coq Require Import List Arith Bool Lia.
Import ListNotations.

Definition cnt {A} (P : A -> bool) (l : list A) : nat := length (filter P l).

Fixpoint leqb (x y : list nat) : bool :=
  match x, y with
  | [], [] => true
  | a :: x', c :: y' => (a =? c) && leqb x' y'
  | _, _ => false
  end.

Fixpoint sumL {A} (f : A -> nat) (l : list A) : nat :=
  match l with [] => 0 | x :: r => f x + sumL f r end.

Lemma cnt_ext : forall A (P Q : A -> bool) l, (forall x, In x l -> P x = Q x) -> cnt P l = cnt Q l.
Proof.
  intros A P Q l H. unfold cnt. induction l as [|a r IH]; simpl; auto.
  rewrite (H a (or_introl eq_refl)). destruct (Q a); simpl; rewrite IH; auto; intros; apply H; right; auto.
Qed.

Lemma cnt_app : forall A (P : A -> bool) l l', cnt P (l ++ l') = cnt P l + cnt P l'.
Proof. intros. unfold cnt. rewrite filter_app, app_length. reflexivity. Qed.

Lemma cnt_map : forall A B (P : B -> bool) (f : A -> B) l, cnt P (map f l) = cnt (fun x => P (f x)) l.
Proof. intros. unfold cnt. induction l as [|a r IH]; simpl; auto. destruct (P (f a)); simpl; auto. Qed.

Lemma cnt_flat_map : forall A B (P : B -> bool) (f : A -> list B) l,
  cnt P (flat_map f l) = sumL (fun x => cnt P (f x)) l.
Proof. intros. induction l as [|a r IH]; simpl; auto. rewrite cnt_app, IH. reflexivity. Qed.

Lemma cnt_true : forall A (l : list A), cnt (fun _ => true) l = length l.
Proof. intros. unfold cnt. induction l; simpl; auto. Qed.

Lemma cnt_and_const : forall A (a : bool) (P : A -> bool) l,
  cnt (fun x => a && P x) l = if a then cnt P l else 0.
Proof. intros. destruct a; simpl; [reflexivity|]. unfold cnt. induction l; simpl; auto. Qed.

Lemma sumL_const_if : forall A (P : A -> bool) K l,
  sumL (fun x => if P x then K else 0) l = cnt P l * K.
Proof.
  intros. unfold cnt. induction l as [|a r IH]; simpl; auto. destruct (P a); simpl; lia.
Qed.

Lemma sumL_const : forall A K (l : list A), sumL (fun _ => K) l = length l * K.
Proof. intros. induction l; simpl; lia. Qed.

Lemma sumL_ext : forall A (f g : A -> nat) l, (forall x, In x l -> f x = g x) -> sumL f l = sumL g l.
Proof.
  intros A f g l H. induction l as [|a r IH]; simpl; auto.
  rewrite H by (left; auto). rewrite IH; auto. intros; apply H; right; auto.
Qed.

(** ** Tuples: every list of length [k] with entries from [L] *)

Section Tuples.
Variable A : Type.
Variable dflt : A.

Fixpoint tuples (k : nat) (L : list A) : list (list A) :=
  match k with
  | 0 => [[]]
  | S k' => flat_map (fun x => map (cons x) (tuples k' L)) L
  end.

Lemma tuples_length : forall k L, length (tuples k L) = length L ^ k.
Proof.
  induction k as [|k IH]; intro L; simpl; auto.
  rewrite <- (cnt_true _ (flat_map _ _)), cnt_flat_map.
  rewrite (sumL_ext _ _ (fun _ => length L ^ k)).
  - rewrite sumL_const. reflexivity.
  - intros. rewrite cnt_map, cnt_true. apply IH.
Qed.

(** One coordinate: the [d]-th entry is distributed like [L]. *)
Lemma tuples_one : forall k d (P : A -> bool) L, d < k ->
  cnt (fun ks => P (nth d ks dflt)) (tuples k L) = cnt P L * length L ^ (k - 1).
Proof.
  induction k as [|k IH]; intros d P L Hd; [lia|]. simpl tuples.
  rewrite cnt_flat_map. destruct d as [|d].
  - rewrite (sumL_ext _ _ (fun x => if P x then length L ^ k else 0)).
    + rewrite sumL_const_if. replace (S k - 1) with k by lia. reflexivity.
    + intros x _. rewrite cnt_map. simpl. destruct (P x).
      * rewrite cnt_true, tuples_length. reflexivity.
      * unfold cnt. induction (tuples k L); simpl; auto.
  - rewrite (sumL_ext _ _ (fun _ => cnt P L * length L ^ (k - 1))).
    + rewrite sumL_const. replace (S k - 1) with (S (k - 1)) by lia. simpl. lia.
    + intros x _. rewrite cnt_map. simpl. apply IH. lia.
Qed.

(** Two distinct coordinates are independent, each distributed like [L]. *)
Lemma tuples_two : forall k d d' (P Q : A -> bool) L, d < k -> d' < k -> d <> d' ->
  cnt (fun ks => P (nth d ks dflt) && Q (nth d' ks dflt)) (tuples k L) =
  cnt P L * cnt Q L * length L ^ (k - 2).
Proof.
  induction k as [|k IH]; intros d d' P Q L Hd Hd' N; [lia|]. simpl tuples.
  rewrite cnt_flat_map. destruct d as [|d], d' as [|d']; [lia| | |].
  - rewrite (sumL_ext _ _ (fun x => if P x then cnt Q L * length L ^ (k - 1) else 0)).
    + rewrite sumL_const_if. replace (S k - 2) with (k - 1) by lia. lia.
    + intros x _. rewrite cnt_map. simpl. rewrite cnt_and_const.
      destruct (P x); [apply tuples_one; lia|reflexivity].
  - rewrite (sumL_ext _ _ (fun x => if Q x then cnt P L * length L ^ (k - 1) else 0)).
    + rewrite sumL_const_if. replace (S k - 2) with (k - 1) by lia. lia.
    + intros x _. rewrite cnt_map. simpl.
      rewrite (cnt_ext _ _ (fun ks => Q x && P (nth d ks dflt))) by (intros; apply andb_comm).
      rewrite cnt_and_const. destruct (Q x); [apply tuples_one; lia|reflexivity].
  - rewrite (sumL_ext _ _ (fun _ => cnt P L * cnt Q L * length L ^ (k - 2))).
    + rewrite sumL_const. replace (S k - 2) with (S (k - 2)) by lia. simpl. lia.
    + intros x _. rewrite cnt_map. simpl. apply IH; lia.
Qed.

End Tuples.

(** ** Trees of node maps and their action *)

Section Trees.
Variable b : nat.
Hypothesis b_ge_2 : 2 <= b.
Variable G : list (nat -> nat).

Inductive tree := Leaf | Node (g : nat -> nat) (kids : list tree).

Fixpoint trees (n : nat) : list tree :=
  match n with
  | 0 => [Leaf]
  | S n' => flat_map (fun g => map (Node g) (tuples tree b (trees n'))) G
  end.

(** The nested action: the node at a prefix maps the next digit; the child is chosen by the
    ORIGINAL digit. *)
Fixpoint act (t : tree) (x : list nat) : list nat :=
  match t, x with
  | Node g ks, d :: r => g d :: act (nth d ks Leaf) r
  | _, _ => []
  end.

Lemma trees_length : forall n, length (trees (S n)) = length G * length (trees n) ^ b.
Proof.
  intro n. simpl. rewrite <- (cnt_true _ (flat_map _ _)), cnt_flat_map.
  rewrite (sumL_ext _ _ (fun _ => length (trees n) ^ b)).
  - rewrite sumL_const. reflexivity.
  - intros. rewrite cnt_map, cnt_true, tuples_length. reflexivity.
Qed.

Definition valid (x : list nat) : Prop := Forall (fun d => d < b) x.

(** Counting over a level: a predicate that looks at the root map and one child. *)
Lemma level_one : forall n (A : (nat -> nat) -> bool) d (P : tree -> bool), d < b ->
  cnt (fun t => match t with Node g ks => A g && P (nth d ks Leaf) | Leaf => false end) (trees (S n)) =
  cnt A G * (cnt P (trees n) * length (trees n) ^ (b - 1)).
Proof.
  intros n A d P Hd. simpl trees. rewrite cnt_flat_map.
  rewrite (sumL_ext _ _ (fun g => if A g then cnt P (trees n) * length (trees n) ^ (b - 1) else 0)).
  - apply sumL_const_if.
  - intros g _. rewrite cnt_map. rewrite cnt_and_const.
    destruct (A g); [apply tuples_one; lia|reflexivity].
Qed.

Lemma level_two : forall n (A : (nat -> nat) -> bool) d d' (P Q : tree -> bool),
  d < b -> d' < b -> d <> d' ->
  cnt (fun t => match t with
                | Node g ks => A g && (P (nth d ks Leaf) && Q (nth d' ks Leaf))
                | Leaf => false end) (trees (S n)) =
  cnt A G * (cnt P (trees n) * cnt Q (trees n) * length (trees n) ^ (b - 2)).
Proof.
  intros n A d d' P Q Hd Hd' N. simpl trees. rewrite cnt_flat_map.
  rewrite (sumL_ext _ _ (fun g => if A g then
             cnt P (trees n) * cnt Q (trees n) * length (trees n) ^ (b - 2) else 0)).
  - apply sumL_const_if.
  - intros g _. rewrite cnt_map. rewrite cnt_and_const.
    destruct (A g); [apply tuples_two; lia|reflexivity].
Qed.

(** [G] is uniformly transitive with [c1] maps taking any digit to any digit. *)
Variable c1 : nat.
Hypothesis G_trans : forall d e, d < b -> e < b -> cnt (fun g => g d =? e) G = c1.
Hypothesis G_size : b * c1 = length G.

Lemma pow_split : forall L k, 1 <= k -> L * L ^ (k - 1) = L ^ k.
Proof. intros L k H. replace k with (S (k - 1)) at 2 by lia. reflexivity. Qed.

(** Every output string is uniform: exactly [1/b^n] of the trees map [x] to [y]. *)
Theorem output_uniform : forall n x y, length x = n -> length y = n -> valid x -> valid y ->
  b ^ n * cnt (fun t => leqb (act t x) y) (trees n) = length (trees n).
Proof.
  induction n as [|n IH]; intros x y Lx Ly Vx Vy.
  - destruct x, y; try discriminate. reflexivity.
  - destruct x as [|d r]; [discriminate|]. destruct y as [|e s]; [discriminate|].
    inversion Vx; inversion Vy; subst.
    rewrite (cnt_ext _ _ (fun t => match t with
                 | Node g ks => (fun g => g d =? e) g && (fun t => leqb (act t r) s) (nth d ks Leaf)
                 | Leaf => false end)) by (intros [|g ks] _; reflexivity).
    rewrite (level_one n (fun g => g d =? e) d (fun t => leqb (act t r) s)) by assumption. rewrite G_trans by assumption.
    rewrite trees_length. simpl in Lx, Ly.
    specialize (IH r s ltac:(lia) ltac:(lia) ltac:(assumption) ltac:(assumption)).
    rewrite <- G_size, <- (pow_split (length (trees n)) b) by lia. rewrite <- IH.
    rewrite Nat.pow_succ_r'. ring.
Qed.

Lemma pow_split2 : forall L k, 2 <= k -> L * L * L ^ (k - 2) = L ^ k.
Proof. intros L k H. replace k with (S (S (k - 2))) at 2 by lia. simpl. ring. Qed.

(** [G] is uniformly 2-transitive: [c2] maps take any two distinct digits to any two distinct
    digits. *)
Variable c2 : nat.
Hypothesis G_trans2 : forall d d' e e', d < b -> d' < b -> e < b -> e' < b -> d <> d' -> e <> e' ->
  cnt (fun g => (g d =? e) && (g d' =? e')) G = c2.
Hypothesis G_size2 : b * (b - 1) * c2 = length G.

(** Owen's pair lemma, exactly: inputs [p ++ d :: r] and [p ++ d' :: r'] (first difference at
    digit [k = length p]) go to [q ++ e :: s] and [q ++ e' :: s'] (common prefix, distinct
    digits [e], [e'], any tails) for exactly [1 / (b^k · b(b−1) · b^(2m))] of the trees, [m] the
    tails' length. These pairs of outputs number [b^k · b(b−1) · b^(2m)], so every other pair
    of outputs has probability 0: the outputs agree above digit [k] and differ at it. *)
Theorem pair_lemma : forall k m p d d' r r' q e e' s s',
  length p = k -> length q = k -> length r = m -> length r' = m -> length s = m -> length s' = m ->
  valid p -> valid q -> valid r -> valid r' -> valid s -> valid s' ->
  d < b -> d' < b -> e < b -> e' < b -> d <> d' -> e <> e' ->
  b ^ k * (b * (b - 1)) * b ^ (2 * m) *
    cnt (fun t => leqb (act t (p ++ d :: r)) (q ++ e :: s) &&
                  leqb (act t (p ++ d' :: r')) (q ++ e' :: s')) (trees (k + S m)) =
  length (trees (k + S m)).
Proof.
  induction k as [|k IH]; intros m p d d' r r' q e e' s s' Lp Lq Lr Lr' Ls Ls'
    Vp Vq Vr Vr' Vs Vs' Hd Hd' He He' Nd Ne.
  - destruct p; [|discriminate]. destruct q; [|discriminate]. simpl app.
    rewrite (cnt_ext _ _ (fun t => match t with
                 | Node g ks => (fun g => (g d =? e) && (g d' =? e')) g &&
                     ((fun t => leqb (act t r) s) (nth d ks Leaf) &&
                      (fun t => leqb (act t r') s') (nth d' ks Leaf))
                 | Leaf => false end)).
    2: { intros [|g ks] _; [reflexivity|]. simpl.
         destruct (g d =? e), (g d' =? e'), (leqb (act (nth d ks Leaf) r) s),
                  (leqb (act (nth d' ks Leaf) r') s'); reflexivity. }
    simpl plus.
    rewrite (level_two m (fun g => (g d =? e) && (g d' =? e')) d d' (fun t => leqb (act t r) s)
               (fun t => leqb (act t r') s')) by assumption. rewrite G_trans2 by assumption.
    rewrite trees_length.
    pose proof (output_uniform m r s Lr Ls Vr Vs) as U1.
    pose proof (output_uniform m r' s' Lr' Ls' Vr' Vs') as U2.
    rewrite <- G_size2.
    rewrite <- (pow_split2 (length (trees m)) b) by lia.
    remember (length (trees m) ^ (b - 2)) as P eqn:HP.
    rewrite <- U1 at 1. rewrite <- U2.
    replace (2 * m) with (m + m) by lia. rewrite Nat.pow_add_r. simpl Nat.pow. ring.
  - destruct p as [|a p]; [discriminate|]. destruct q as [|c q]; [discriminate|].
    pose proof (Forall_inv Vp) as Ha. apply Forall_inv_tail in Vp.
    pose proof (Forall_inv Vq) as Hc. apply Forall_inv_tail in Vq. simpl in Lp, Lq.
    rewrite (cnt_ext _ _ (fun t => match t with
                 | Node g ks => (fun g => g a =? c) g &&
                     (fun t => leqb (act t (p ++ d :: r)) (q ++ e :: s) &&
                               leqb (act t (p ++ d' :: r')) (q ++ e' :: s')) (nth a ks Leaf)
                 | Leaf => false end)).
    2: { intros [|g ks] _; [reflexivity|]. simpl.
         destruct (g a =? c), (leqb (act (nth a ks Leaf) (p ++ d :: r)) (q ++ e :: s)),
                  (leqb (act (nth a ks Leaf) (p ++ d' :: r')) (q ++ e' :: s')); reflexivity. }
    simpl plus.
    rewrite (level_one (k + S m) (fun g => g a =? c) a (fun t =>
               leqb (act t (p ++ d :: r)) (q ++ e :: s) &&
               leqb (act t (p ++ d' :: r')) (q ++ e' :: s'))) by assumption.
    rewrite G_trans by assumption. rewrite trees_length.
    specialize (IH m p d d' r r' q e e' s s' ltac:(lia) ltac:(lia) Lr Lr' Ls Ls'
                  ltac:(assumption) ltac:(assumption) Vr Vr' Vs Vs' Hd Hd' He He' Nd Ne).
    rewrite <- G_size, <- (pow_split (length (trees (k + S m))) b) by lia.
    rewrite <- IH. rewrite Nat.pow_succ_r'. ring.
Qed.

End Trees.
