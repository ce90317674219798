(** * Discrepancy closed forms from their definitions: Warnock's formula, Hickernell's
    generalized L2 and centred forms.

    Points are words on the grid of step [h = 1/M]: coordinate [j] of point [p] is
    [x (nth j p 0) = a·h] with [a < M] ([M = 2^W] for W-bit words). A squared discrepancy is
    the integral, over a family of boxes, of the squared local discrepancy
    [(A/N − Π_j len_j)²]: [A] counts the points in the box and [len_j] is its side in
    coordinate [j]. Every family here is a product over coordinates, and each coordinate's box
    parameters split into finitely many pieces (grid cells) on which every point's membership
    is constant and the side is a polynomial. Over a product [c] of pieces [A] is constant and
    the integral of the integrand is [(A/N)²·Π_j μ0(c_j) − 2(A/N)·Π_j μ1(c_j) + Π_j μ2(c_j)],
    with [μk t] the integral of [len^k] over piece [t] (Fubini on a box); [integral] below sums
    these over all products of pieces. The [μk] of each family are the elementary integrals of
    [t^k] and [(1 − t)^k] over a cell (antiderivatives): those and Fubini on a box are the
    calculus taken by hand; the rest is proved.

    - [separable_closed_form]: any such family's integral is
      [(1/N²)·Σ_p Σ_q Π_j K2(p_j, q_j) − 2·(1/N)·Σ_p Π_j K1(p_j) + K0^s], the kernels being
      per-coordinate sums over the pieces.
    - [warnock_formula] (L2-star, boxes [[0, y)]):
      [3^-s − (2/N)·Σ_p Π_j (1 − x_pj²)/2 + (1/N²)·Σ_p Σ_q Π_j (1 − max(x_pj, x_qj))].
    - [gl2_formula] (generalized L2: the same boxes, summed over every coordinate projection;
      a coordinate left out of a projection is the piece "whole interval", which holds every
      point, has side 1 and weight 1): [(4/3)^s − (2/N)·Σ_p Π_j (3 − x_pj²)/2
      + (1/N²)·Σ_p Σ_q Π_j (2 − max(x_pj, x_qj))].
    - [centred_formula] (centred: in each coordinate the box between [y] and the nearer end of
      [[0, 1]], every projection; [M] even): [(13/12)^s − (2/N)·Σ_p Π_j (1 + |x_pj − ½|/2
      − |x_pj − ½|²/2) + (1/N²)·Σ_p Σ_q Π_j (1 + |x_pj − ½|/2 + |x_qj − ½|/2 − |x_pj − x_qj|/2)].

    These are the closed forms `crates/discrepancy/src/kinds.rs` evaluates; the wrap-around
    form is `WrapAround.wd_formula`. *)

From Coq Require Import Reals Lra Lia List Arith.
Import ListNotations.
Open Scope R_scope.

(** ** Finite sums and products *)

Definition sumR {A : Type} (f : A -> R) (l : list A) : R :=
  fold_right (fun a acc => f a + acc) 0 l.

Lemma sumR_app : forall A (f : A -> R) l l', sumR f (l ++ l') = sumR f l + sumR f l'.
Proof. intros A f l l'. induction l as [|a l IH]; simpl; [lra|]. rewrite IH. lra. Qed.

Lemma sumR_map : forall A B (f : B -> R) (g : A -> B) l,
  sumR f (map g l) = sumR (fun a => f (g a)) l.
Proof. intros A B f g l. induction l as [|a l IH]; simpl; [|rewrite IH]; reflexivity. Qed.

Lemma sumR_flat_map : forall A B (f : B -> R) (g : A -> list B) l,
  sumR f (flat_map g l) = sumR (fun a => sumR f (g a)) l.
Proof.
  intros A B f g l. induction l as [|a l IH]; simpl; [reflexivity|].
  rewrite sumR_app, IH. reflexivity.
Qed.

Lemma sumR_ext : forall A (f g : A -> R) l,
  (forall a, In a l -> f a = g a) -> sumR f l = sumR g l.
Proof.
  intros A f g l H. induction l as [|a l IH]; simpl; [reflexivity|].
  rewrite (H a (or_introl eq_refl)), IH by (intros b Hb; apply H; right; exact Hb).
  reflexivity.
Qed.

Lemma sumR_zero : forall A (l : list A), sumR (fun _ => 0) l = 0.
Proof. intros A l. induction l as [|a l IH]; simpl; lra. Qed.

Lemma sumR_lin : forall A (f g k : A -> R) l,
  sumR (fun a => f a - 2 * g a + k a) l = sumR f l - 2 * sumR g l + sumR k l.
Proof. intros A f g k l. induction l as [|a l IH]; simpl; lra. Qed.

Lemma sumR_scal : forall A (f : A -> R) c l, sumR (fun a => c * f a) l = c * sumR f l.
Proof. intros A f c l. induction l as [|a l IH]; simpl; lra. Qed.

Lemma sumR_plus : forall A (f g : A -> R) l,
  sumR (fun a => f a + g a) l = sumR f l + sumR g l.
Proof. intros A f g l. induction l as [|a l IH]; simpl; lra. Qed.

Lemma sumR_swap : forall A B (f : A -> B -> R) l l',
  sumR (fun a => sumR (fun b => f a b) l') l = sumR (fun b => sumR (fun a => f a b) l) l'.
Proof.
  intros A B f l l'. induction l as [|a l IH]; simpl.
  - symmetry. apply sumR_zero.
  - rewrite IH, <- (sumR_plus _ (fun b => f a b) (fun b => sumR (fun a0 => f a0 b) l)).
    reflexivity.
Qed.

Lemma sumR_mult : forall A B (f : A -> R) (g : B -> R) l l',
  sumR f l * sumR g l' = sumR (fun a => sumR (fun b => f a * g b) l') l.
Proof.
  intros A B f g l l'. induction l as [|a l IH]; simpl; [lra|].
  rewrite <- IH, sumR_scal. ring.
Qed.

(** [prodN n f = f 0 · f 1 ⋯ f (n−1)]. *)
Fixpoint prodN (n : nat) (f : nat -> R) : R :=
  match n with
  | O => 1
  | S n' => f O * prodN n' (fun j => f (S j))
  end.

Lemma prodN_mult : forall n f g, prodN n f * prodN n g = prodN n (fun j => f j * g j).
Proof. induction n as [|n IH]; intros f g; simpl; [lra|]. rewrite <- IH. ring. Qed.

Lemma prodN_ext : forall n f g,
  (forall j, (j < n)%nat -> f j = g j) -> prodN n f = prodN n g.
Proof.
  induction n as [|n IH]; intros f g H; simpl; [reflexivity|].
  rewrite (H O) by lia. f_equal. apply IH. intros j Hj. apply H. lia.
Qed.

Lemma prodN_const : forall n c, prodN n (fun _ => c) = c ^ n.
Proof. induction n as [|n IH]; intro c; simpl; [reflexivity|]. rewrite IH. reflexivity. Qed.

(** A boolean as 0 or 1. *)
Definition ind (b : bool) : R := if b then 1 else 0.

Lemma count_as_sum : forall A (f : A -> bool) l,
  INR (length (filter f l)) = sumR (fun a => ind (f a)) l.
Proof.
  intros A f l. induction l as [|a l IH]; [reflexivity|].
  unfold sumR in *. cbn [fold_right filter]. unfold ind at 1. destruct (f a).
  - cbn [length]. rewrite S_INR, IH. ring.
  - rewrite IH. ring.
Qed.

Lemma forallb_shift : forall (f : nat -> bool) l,
  forallb f (map S l) = forallb (fun j => f (S j)) l.
Proof. intros f l. induction l as [|a l IH]; simpl; [|rewrite IH]; reflexivity. Qed.

Lemma ind_forallb : forall n (f : nat -> bool),
  ind (forallb f (seq 0 n)) = prodN n (fun j => ind (f j)).
Proof.
  induction n as [|n IH]; intro f; simpl; [reflexivity|].
  rewrite <- seq_shift, forallb_shift, <- IH. unfold ind. destruct (f O); simpl; ring.
Qed.

(** ** Telescoping over a grid *)

Lemma telescope : forall (g : nat -> R) n p, (p <= n)%nat ->
  sumR (fun a => ind (p <=? a)%nat * (g (S a) - g a)) (seq 0 n) = g n - g p.
Proof.
  intros g n. induction n as [|n IH]; intros p Hp.
  - replace p with O by lia. simpl. lra.
  - rewrite seq_S, sumR_app. simpl.
    destruct (Nat.eq_dec p (S n)) as [E|E].
    + subst p. rewrite (sumR_ext _ _ (fun _ => 0)), sumR_zero.
      * replace (S n <=? n)%nat with false by (symmetry; apply Nat.leb_gt; lia).
        unfold ind. lra.
      * intros a Ha. apply in_seq in Ha.
        replace (S n <=? a)%nat with false by (symmetry; apply Nat.leb_gt; lia).
        unfold ind. ring.
    + rewrite IH by lia. replace (p <=? n)%nat with true by (symmetry; apply Nat.leb_le; lia).
      unfold ind. ring.
Qed.

Lemma telescope_eq : forall (g : nat -> R) n p (f : nat -> R), (p <= n)%nat ->
  (forall a, f a = ind (p <=? a)%nat * (g (S a) - g a)) -> sumR f (seq 0 n) = g n - g p.
Proof.
  intros g n p f Hp Hf. rewrite <- telescope by exact Hp. apply sumR_ext. intros a _. apply Hf.
Qed.


Lemma telescope_gen : forall (g : nat -> R) n p,
  sumR (fun a => ind (p <=? a)%nat * (g (S a) - g a)) (seq 0 n) =
  if (p <=? n)%nat then g n - g p else 0.
Proof.
  intros g n p. destruct (Nat.leb_spec p n) as [H|H]; [apply telescope, H|].
  rewrite (sumR_ext _ _ (fun _ => 0)); [apply sumR_zero|].
  intros a Ha. apply in_seq in Ha.
  replace (p <=? a)%nat with false by (symmetry; apply Nat.leb_gt; lia). unfold ind. ring.
Qed.

Lemma telescope_upper : forall (g : nat -> R) n r,
  sumR (fun a => ind (a <? r)%nat * (g (S a) - g a)) (seq 0 n) = g (Nat.min r n) - g O.
Proof.
  intros g n r. induction n as [|n IH].
  - simpl. rewrite Nat.min_0_r. ring.
  - rewrite seq_S, sumR_app, IH. simpl. unfold ind.
    destruct (Nat.ltb_spec n r) as [H|H].
    + rewrite Nat.min_r by lia. rewrite (Nat.min_r r (S n)) by lia. ring.
    + rewrite Nat.min_l by lia. rewrite (Nat.min_l r (S n)) by lia. ring.
Qed.

Lemma telescope_gen_eq : forall (g : nat -> R) n p (f : nat -> R),
  (forall a, f a = ind (p <=? a)%nat * (g (S a) - g a)) ->
  sumR f (seq 0 n) = if (p <=? n)%nat then g n - g p else 0.
Proof.
  intros g n p f Hf. rewrite <- telescope_gen. apply sumR_ext. intros a _. apply Hf.
Qed.

Lemma telescope_upper_eq : forall (g : nat -> R) n r (f : nat -> R),
  (forall a, f a = ind (a <? r)%nat * (g (S a) - g a)) ->
  sumR f (seq 0 n) = g (Nat.min r n) - g O.
Proof.
  intros g n r f Hf. rewrite <- telescope_upper. apply sumR_ext. intros a _. apply Hf.
Qed.

(** ** A box family that is a product over coordinates *)

Section Separable.

(** The pieces of one coordinate's box parameters, a default piece (never read), whether a
    word lies in the box throughout a piece, and the integrals of [len^k] over a piece. *)
Variable T : Type.
Variable Q : list T.
Variable t0 : T.
Variable inside : nat -> T -> bool.
Variables mu0 mu1 mu2 : T -> R.

(** Every product of pieces, one per coordinate. *)
Fixpoint tuples (s : nat) : list (list T) :=
  match s with
  | O => [[]]
  | S s' => flat_map (fun t => map (cons t) (tuples s')) Q
  end.

(** A sum over the products of pieces of a product over coordinates is the product of the
    per-coordinate sums. *)
Lemma sum_tuples_prod : forall s (F : nat -> T -> R),
  sumR (fun c => prodN s (fun j => F j (nth j c t0))) (tuples s) =
  prodN s (fun j => sumR (F j) Q).
Proof.
  induction s as [|s IH]; intro F; simpl; [lra|].
  rewrite sumR_flat_map.
  rewrite (sumR_ext _ _ (fun t => F O t * prodN s (fun j => sumR (F (S j)) Q))).
  - rewrite Rmult_comm, <- sumR_scal. apply sumR_ext. intros t _. ring.
  - intros t _. rewrite sumR_map. simpl. rewrite sumR_scal, (IH (fun j => F (S j))).
    reflexivity.
Qed.

(** Point [p] lies in the box for every parameter in the product of pieces [c]. *)
Definition in_box (s : nat) (p : list nat) (c : list T) : bool :=
  forallb (fun j => inside (nth j p O) (nth j c t0)) (seq 0 s).

(** The integral of [(A/N − Π_j len_j)²]: over each product of pieces, [A] is constant. *)
Definition integral (s : nat) (P : list (list nat)) : R :=
  sumR (fun c =>
    let f := INR (length (filter (fun p => in_box s p c) P)) / INR (length P) in
    f ^ 2 * prodN s (fun j => mu0 (nth j c t0))
    - 2 * (f * prodN s (fun j => mu1 (nth j c t0)))
    + prodN s (fun j => mu2 (nth j c t0)))
  (tuples s).

(** The per-coordinate kernels. *)
Definition pair_kernel (a b : nat) : R :=
  sumR (fun t => ind (inside a t) * ind (inside b t) * mu0 t) Q.
Definition single_kernel (a : nat) : R := sumR (fun t => ind (inside a t) * mu1 t) Q.
Definition square_kernel : R := sumR mu2 Q.

Section Points.

Variable s : nat.
Variable P : list (list nat).
Hypothesis P_nonempty : P <> [].

Let N := INR (length P).

Lemma N_nonzero : N <> 0.
Proof. unfold N. apply not_0_INR. destruct P; [contradiction|]. simpl. lia. Qed.

Lemma count_as_product : forall c,
  INR (length (filter (fun p => in_box s p c) P)) =
  sumR (fun p => prodN s (fun j => ind (inside (nth j p O) (nth j c t0)))) P.
Proof.
  intro c. rewrite count_as_sum. apply sumR_ext. intros p _. apply ind_forallb.
Qed.

Lemma volume_term :
  sumR (fun c => (INR (length (filter (fun p => in_box s p c) P)) / N) ^ 2
                 * prodN s (fun j => mu0 (nth j c t0))) (tuples s) =
  / N ^ 2 * sumR (fun p => sumR (fun q =>
        prodN s (fun j => pair_kernel (nth j p O) (nth j q O))) P) P.
Proof.
  pose proof N_nonzero as HN.
  rewrite (sumR_ext _ _ (fun c => / N ^ 2 * sumR (fun p => sumR (fun q =>
      prodN s (fun j => ind (inside (nth j p O) (nth j c t0))
                        * ind (inside (nth j q O) (nth j c t0)) * mu0 (nth j c t0))) P) P)).
  - rewrite sumR_scal. f_equal.
    rewrite sumR_swap. apply sumR_ext. intros p _.
    rewrite sumR_swap. apply sumR_ext. intros q _.
    apply (sum_tuples_prod s (fun j t =>
      ind (inside (nth j p O) t) * ind (inside (nth j q O) t) * mu0 t)).
  - intros c _. rewrite count_as_product.
    set (S := sumR (fun p => prodN s (fun j => ind (inside (nth j p O) (nth j c t0)))) P).
    replace ((S / N) ^ 2 * prodN s (fun j => mu0 (nth j c t0)))
      with (/ N ^ 2 * (S * S) * prodN s (fun j => mu0 (nth j c t0))) by (field; exact HN).
    unfold S. rewrite sumR_mult, Rmult_assoc. f_equal.
    rewrite Rmult_comm, <- sumR_scal. apply sumR_ext. intros p _.
    rewrite <- sumR_scal. apply sumR_ext. intros q _.
    rewrite !prodN_mult. apply prodN_ext. intros j _. ring.
Qed.

Lemma cross_term :
  sumR (fun c => INR (length (filter (fun p => in_box s p c) P)) / N
                 * prodN s (fun j => mu1 (nth j c t0))) (tuples s) =
  / N * sumR (fun p => prodN s (fun j => single_kernel (nth j p O))) P.
Proof.
  rewrite (sumR_ext _ _ (fun c => / N * sumR (fun p =>
      prodN s (fun j => ind (inside (nth j p O) (nth j c t0)) * mu1 (nth j c t0))) P)).
  - rewrite sumR_scal. f_equal. rewrite sumR_swap. apply sumR_ext. intros p _.
    apply (sum_tuples_prod s (fun j t => ind (inside (nth j p O) t) * mu1 t)).
  - intros c _. rewrite count_as_product. unfold Rdiv.
    rewrite (Rmult_comm (sumR _ P) (/ N)), Rmult_assoc. f_equal.
    rewrite Rmult_comm, <- sumR_scal. apply sumR_ext. intros p _.
    rewrite prodN_mult. apply prodN_ext. intros j _. ring.
Qed.

Lemma square_term :
  sumR (fun c => prodN s (fun j => mu2 (nth j c t0))) (tuples s) = square_kernel ^ s.
Proof.
  rewrite (sum_tuples_prod s (fun _ t => mu2 t)), <- prodN_const. reflexivity.
Qed.

(** The integral of a separable family in closed form. *)
Theorem separable_closed_form :
  integral s P =
  / N ^ 2 * sumR (fun p => sumR (fun q =>
      prodN s (fun j => pair_kernel (nth j p O) (nth j q O))) P) P
  - 2 * (/ N * sumR (fun p => prodN s (fun j => single_kernel (nth j p O))) P)
  + square_kernel ^ s.
Proof.
  unfold integral. fold N. rewrite sumR_lin, volume_term, cross_term, square_term. ring.
Qed.

End Points.

End Separable.

(** Adding to each coordinate the piece "whole interval" (every point inside, side 1, weight
    1) sums the integrals over every coordinate projection; each kernel gains 1. *)
Section Projections.

Variable T : Type.
Variable Q : list T.
Variable inside : nat -> T -> bool.
Variables mu0 mu1 mu2 : T -> R.

Definition inside_all (a : nat) (t : option T) : bool :=
  match t with None => true | Some t => inside a t end.
Definition with_whole (mu : T -> R) (t : option T) : R :=
  match t with None => 1 | Some t => mu t end.
Definition pieces_all : list (option T) := None :: map Some Q.

Lemma pair_kernel_all : forall a b,
  pair_kernel _ pieces_all inside_all (with_whole mu0) a b =
  1 + pair_kernel _ Q inside mu0 a b.
Proof.
  intros a b. unfold pair_kernel, pieces_all. simpl. rewrite sumR_map. unfold ind. simpl. ring.
Qed.

Lemma single_kernel_all : forall a,
  single_kernel _ pieces_all inside_all (with_whole mu1) a = 1 + single_kernel _ Q inside mu1 a.
Proof.
  intro a. unfold single_kernel, pieces_all. simpl. rewrite sumR_map. unfold ind. simpl. ring.
Qed.

Lemma square_kernel_all :
  square_kernel _ pieces_all (with_whole mu2) = 1 + square_kernel _ Q mu2.
Proof. unfold square_kernel, pieces_all. simpl. rewrite sumR_map. reflexivity. Qed.

End Projections.

(** ** The grid *)

Section Grid.

Variable M : nat.
Hypothesis M_pos : (0 < M)%nat.

(** The grid step and the coordinate of word [a]. *)
Definition h : R := / INR M.
Definition x (a : nat) : R := INR a * h.

Lemma h_pos : 0 < h.
Proof. apply Rinv_0_lt_compat, lt_0_INR. exact M_pos. Qed.

Lemma x_M : x M = 1.
Proof. unfold x, h. field. apply not_0_INR. lia. Qed.

Lemma x_0 : x O = 0.
Proof. unfold x. simpl. ring. Qed.

Lemma x_step : forall a, x (S a) - x a = h.
Proof. intro a. unfold x. rewrite S_INR. ring. Qed.

Lemma x_le : forall a b, (a <= b)%nat -> x a <= x b.
Proof.
  intros a b H. unfold x. apply Rmult_le_compat_r; [left; exact h_pos|]. apply le_INR, H.
Qed.

Lemma x_lt : forall a b, (a < b)%nat -> x a < x b.
Proof.
  intros a b H. unfold x. apply Rmult_lt_compat_r; [exact h_pos|]. apply lt_INR, H.
Qed.

Lemma x_max : forall a b, Rmax (x a) (x b) = x (Nat.max a b).
Proof.
  intros a b. unfold Rmax. destruct (Rle_dec (x a) (x b)) as [H|H].
  - destruct (Nat.le_gt_cases a b) as [L|L].
    + rewrite Nat.max_r by exact L. reflexivity.
    + pose proof (x_lt b a L). lra.
  - destruct (Nat.le_gt_cases a b) as [L|L].
    + pose proof (x_le a b L). lra.
    + rewrite Nat.max_l by lia. reflexivity.
Qed.

(** The integrals of [t] and [t²] over the cell [[x a, x (a+1)]]. *)
Definition m1 (a : nat) : R := (x (S a) ^ 2 - x a ^ 2) / 2.
Definition m2 (a : nat) : R := (x (S a) ^ 3 - x a ^ 3) / 3.

(** *** L2-star: the boxes [[0, y)]; in cell [a], word [p] is inside iff [p ≤ a], side [y]. *)

Definition anchored (p a : nat) : bool := (p <=? a)%nat.

Lemma anchored_pair : forall p q, (p <= M)%nat -> (q <= M)%nat ->
  pair_kernel _ (seq 0 M) anchored (fun _ => h) p q = 1 - Rmax (x p) (x q).
Proof.
  intros p q Hp Hq. unfold pair_kernel.
  rewrite x_max, <- x_M, <- (telescope x M (Nat.max p q)) by lia.
  apply sumR_ext. intros a _. rewrite x_step. unfold ind, anchored.
  destruct (Nat.leb_spec p a), (Nat.leb_spec q a), (Nat.leb_spec (Nat.max p q) a);
    try ring; lia.
Qed.

Lemma anchored_single : forall p, (p <= M)%nat ->
  single_kernel _ (seq 0 M) anchored m1 p = (1 - x p ^ 2) / 2.
Proof.
  intros p Hp. unfold single_kernel.
  rewrite (telescope_eq (fun b => x b ^ 2 / 2) M p).
  - cbv beta. rewrite x_M. field.
  - exact Hp.
  - intro a. unfold m1, anchored. field.
Qed.

Lemma anchored_square : square_kernel _ (seq 0 M) m2 = / 3.
Proof.
  unfold square_kernel. rewrite (telescope_eq (fun b => x b ^ 3 / 3) M O).
  - cbv beta. rewrite x_M, x_0. field.
  - lia.
  - intro a. unfold m2, ind. simpl. field.
Qed.

(** The squared L2-star discrepancy as the integral of its definition. *)
Definition l2star_integral (s : nat) (P : list (list nat)) : R :=
  integral _ (seq 0 M) O anchored (fun _ => h) m1 m2 s P.

(** Warnock's closed form (`kinds.rs`, [Kind::L2Star]). *)
Definition warnock (s : nat) (P : list (list nat)) : R :=
  let N := INR (length P) in
  (/ 3) ^ s
  - 2 * (/ N * sumR (fun p => prodN s (fun j => (1 - x (nth j p O) ^ 2) / 2)) P)
  + / N ^ 2 * sumR (fun p => sumR (fun q =>
        prodN s (fun j => 1 - Rmax (x (nth j p O)) (x (nth j q O)))) P) P.

(** Words on the grid: every coordinate below [M]. *)
Definition on_grid (s : nat) (P : list (list nat)) : Prop :=
  forall p, In p P -> forall j, (j < s)%nat -> (nth j p O < M)%nat.

Theorem warnock_formula : forall s P, P <> [] -> on_grid s P ->
  l2star_integral s P = warnock s P.
Proof.
  intros s P HP G. unfold l2star_integral, warnock.
  rewrite separable_closed_form by exact HP. rewrite anchored_square.
  assert (E1 : sumR (fun p => prodN s (fun j => single_kernel _ (seq 0 M) anchored m1 (nth j p O))) P
             = sumR (fun p => prodN s (fun j => (1 - x (nth j p O) ^ 2) / 2)) P).
  { apply sumR_ext. intros p Hp. apply prodN_ext. intros j Hj.
    apply anchored_single. pose proof (G p Hp j Hj). lia. }
  assert (E2 : sumR (fun p => sumR (fun q => prodN s (fun j =>
                 pair_kernel _ (seq 0 M) anchored (fun _ => h) (nth j p O) (nth j q O))) P) P
             = sumR (fun p => sumR (fun q => prodN s (fun j =>
                 1 - Rmax (x (nth j p O)) (x (nth j q O)))) P) P).
  { apply sumR_ext. intros p Hp. apply sumR_ext. intros q Hq.
    apply prodN_ext. intros j Hj. pose proof (G p Hp j Hj). pose proof (G q Hq j Hj).
    apply anchored_pair; lia. }
  rewrite E1, E2. ring.
Qed.

(** *** Generalized L2: the boxes [[0, y)] over every coordinate projection. *)

Definition gl2_integral (s : nat) (P : list (list nat)) : R :=
  integral _ (pieces_all _ (seq 0 M)) None (inside_all _ anchored)
    (with_whole _ (fun _ => h)) (with_whole _ m1) (with_whole _ m2) s P.

(** Hickernell's closed form (`kinds.rs`, [Kind::GeneralizedL2]). *)
Definition gl2 (s : nat) (P : list (list nat)) : R :=
  let N := INR (length P) in
  (4 / 3) ^ s
  - 2 * (/ N * sumR (fun p => prodN s (fun j => (3 - x (nth j p O) ^ 2) / 2)) P)
  + / N ^ 2 * sumR (fun p => sumR (fun q =>
        prodN s (fun j => 2 - Rmax (x (nth j p O)) (x (nth j q O)))) P) P.

Theorem gl2_formula : forall s P, P <> [] -> on_grid s P -> gl2_integral s P = gl2 s P.
Proof.
  intros s P HP G. unfold gl2_integral, gl2.
  rewrite separable_closed_form by exact HP.
  rewrite square_kernel_all, anchored_square.
  assert (E1 : sumR (fun p => prodN s (fun j => single_kernel _ (pieces_all _ (seq 0 M))
                 (inside_all _ anchored) (with_whole _ m1) (nth j p O))) P
             = sumR (fun p => prodN s (fun j => (3 - x (nth j p O) ^ 2) / 2)) P).
  { apply sumR_ext. intros p Hp. apply prodN_ext. intros j Hj.
    rewrite single_kernel_all, anchored_single by (pose proof (G p Hp j Hj); lia). field. }
  assert (E2 : sumR (fun p => sumR (fun q => prodN s (fun j =>
                 pair_kernel _ (pieces_all _ (seq 0 M)) (inside_all _ anchored)
                   (with_whole _ (fun _ => h)) (nth j p O) (nth j q O))) P) P
             = sumR (fun p => sumR (fun q => prodN s (fun j =>
                 2 - Rmax (x (nth j p O)) (x (nth j q O)))) P) P).
  { apply sumR_ext. intros p Hp. apply sumR_ext. intros q Hq.
    apply prodN_ext. intros j Hj. pose proof (G p Hp j Hj). pose proof (G q Hq j Hj).
    rewrite pair_kernel_all, anchored_pair by lia. ring. }
  rewrite E1, E2. replace (1 + / 3) with (4 / 3) by field. ring.
Qed.

(** *** Centred: the box between [y] and the nearer end of [[0, 1]], every projection.

    [M = 2K]: the left cells [a < K] (box [[0, y]], side [y], word [p] inside iff [p ≤ a]) and
    the right cells [K + i] (box [[y, 1]], side [1 − y], inside iff [p > K + i]). *)

Section Centred.

Variable K : nat.
Hypothesis M_even : M = (2 * K)%nat.

Lemma x_K : x K = / 2.
Proof.
  unfold x, h. rewrite M_even, mult_INR. simpl (INR 2).
  field. apply not_0_INR. lia.
Qed.

Lemma x_KK : x (K + K) = 1.
Proof. replace (K + K)%nat with M by lia. apply x_M. Qed.

Definition centred_pieces : list (bool * nat) :=
  map (pair false) (seq 0 K) ++ map (pair true) (seq 0 K).

Definition centred_inside (p : nat) (t : bool * nat) : bool :=
  let (right, a) := t in if right then (K + a <? p)%nat else (p <=? a)%nat.

Definition centred_mu1 (t : bool * nat) : R :=
  let (right, a) := t in
  if right then ((1 - x (K + a)) ^ 2 - (1 - x (S (K + a))) ^ 2) / 2 else m1 a.

Definition centred_mu2 (t : bool * nat) : R :=
  let (right, a) := t in
  if right then ((1 - x (K + a)) ^ 3 - (1 - x (S (K + a))) ^ 3) / 3 else m2 a.

Lemma right_inside : forall p i, ind (K + i <? p)%nat = ind (i <? p - K)%nat.
Proof.
  intros p i. unfold ind. destruct (Nat.ltb_spec (K + i) p), (Nat.ltb_spec i (p - K));
    reflexivity || lia.
Qed.

Lemma centred_square : square_kernel _ centred_pieces centred_mu2 = / 12.
Proof.
  unfold square_kernel, centred_pieces. rewrite sumR_app, !sumR_map. cbn [centred_mu2].
  rewrite (telescope_gen_eq (fun b => x b ^ 3 / 3) K O);
    [|intro a; cbv beta; unfold m2, ind; simpl; field].
  rewrite (telescope_gen_eq (fun b => - (1 - x (K + b)) ^ 3 / 3) K O);
    [|intro a; cbv beta; rewrite <- plus_n_Sm; unfold ind; simpl; field].
  cbv beta. replace (0 <=? K)%nat with true by reflexivity.
  rewrite Nat.add_0_r, x_KK, x_K, x_0. field.
Qed.

Lemma centred_single : forall p, (p < M)%nat ->
  single_kernel _ centred_pieces centred_inside centred_mu1 p =
  / 2 * Rabs (x p - / 2) - / 2 * Rabs (x p - / 2) ^ 2.
Proof.
  intros p Hp. unfold single_kernel, centred_pieces. rewrite sumR_app, !sumR_map.
  cbn [centred_inside centred_mu1].
  rewrite (telescope_gen_eq (fun b => x b ^ 2 / 2) K p);
    [|intro a; cbv beta; unfold m1; field].
  rewrite (telescope_upper_eq (fun b => - (1 - x (K + b)) ^ 2 / 2) K (p - K));
    [|intro a; cbv beta; rewrite right_inside, <- plus_n_Sm; field].
  cbv beta. rewrite Nat.add_0_r, x_K.
  destruct (Nat.ltb_spec p K) as [L|L].
  - replace (p - K)%nat with O by lia. rewrite Nat.min_0_l, Nat.add_0_r, x_K.
    replace (p <=? K)%nat with true by (symmetry; apply Nat.leb_le; lia).
    pose proof (x_lt p K L) as X. rewrite x_K in X.
    rewrite Rabs_left by lra. field.
  - rewrite Nat.min_l by lia. replace (K + (p - K))%nat with p by lia.
    pose proof (x_le K p L) as X. rewrite x_K in X.
    rewrite (Rabs_pos_eq (x p - / 2)) by lra.
    destruct (Nat.leb_spec p K) as [E|E].
    + replace p with K by lia. rewrite x_K. field.
    + field.
Qed.

Lemma centred_pair : forall p q, (p < M)%nat -> (q < M)%nat ->
  pair_kernel _ centred_pieces centred_inside (fun _ => h) p q =
  / 2 * Rabs (x p - / 2) + / 2 * Rabs (x q - / 2) - / 2 * Rabs (x p - x q).
Proof.
  intros p q Hp Hq. unfold pair_kernel, centred_pieces. rewrite sumR_app, !sumR_map.
  cbn [centred_inside].
  rewrite (telescope_gen_eq x K (Nat.max p q)).
  2: { intro a. rewrite x_step. unfold ind.
       destruct (Nat.leb_spec p a), (Nat.leb_spec q a), (Nat.leb_spec (Nat.max p q) a);
         try ring; lia. }
  rewrite (telescope_upper_eq (fun b => x (K + b)) K (Nat.min p q - K)).
  2: { intro i. cbv beta. rewrite <- plus_n_Sm, x_step, !right_inside. unfold ind.
       destruct (Nat.ltb_spec i (p - K)), (Nat.ltb_spec i (q - K)),
         (Nat.ltb_spec i (Nat.min p q - K)); try ring; lia. }
  cbv beta. rewrite Nat.add_0_r.
  rewrite (Nat.min_l (Nat.min p q - K) K) by lia.
  assert (L : (if (Nat.max p q <=? K)%nat then x K - x (Nat.max p q) else 0)
             = Rmax 0 (/ 2 - Rmax (x p) (x q))).
  { rewrite x_max, <- x_K. destruct (Nat.leb_spec (Nat.max p q) K) as [E|E].
    - pose proof (x_le _ _ E). unfold Rmax. destruct (Rle_dec _ _); lra.
    - pose proof (x_lt _ _ E). unfold Rmax. destruct (Rle_dec _ _); lra. }
  assert (R : x (K + (Nat.min p q - K)) - x K = Rmax 0 (Rmin (x p) (x q) - / 2)).
  { assert (Em : Rmin (x p) (x q) = x (Nat.min p q)).
    { unfold Rmin. destruct (Nat.le_ge_cases p q) as [O|O].
      - rewrite (Nat.min_l p q O). pose proof (x_le _ _ O). destruct (Rle_dec _ _); lra.
      - rewrite (Nat.min_r p q O). pose proof (x_le _ _ O). destruct (Rle_dec _ _); lra. }
    rewrite Em, <- x_K. destruct (Nat.le_gt_cases K (Nat.min p q)) as [E|E].
    - replace (K + (Nat.min p q - K))%nat with (Nat.min p q) by lia.
      pose proof (x_le _ _ E). unfold Rmax. destruct (Rle_dec _ _); lra.
    - replace (Nat.min p q - K)%nat with O by lia. rewrite Nat.add_0_r.
      pose proof (x_lt _ _ E). unfold Rmax. destruct (Rle_dec _ _); lra. }
  rewrite L, R. unfold Rmax, Rmin, Rabs.
  repeat (destruct (Rle_dec _ _) || destruct (Rcase_abs _)); lra.
Qed.

(** The squared centred discrepancy as the integral of its definition. *)
Definition centred_integral (s : nat) (P : list (list nat)) : R :=
  integral _ (pieces_all _ centred_pieces) None (inside_all _ centred_inside)
    (with_whole _ (fun _ => h)) (with_whole _ centred_mu1) (with_whole _ centred_mu2) s P.

(** Hickernell's closed form (`kinds.rs`, [Kind::Centered]). *)
Definition centred (s : nat) (P : list (list nat)) : R :=
  let N := INR (length P) in
  (13 / 12) ^ s
  - 2 * (/ N * sumR (fun p => prodN s (fun j =>
        1 + / 2 * Rabs (x (nth j p O) - / 2) - / 2 * Rabs (x (nth j p O) - / 2) ^ 2)) P)
  + / N ^ 2 * sumR (fun p => sumR (fun q => prodN s (fun j =>
        1 + / 2 * Rabs (x (nth j p O) - / 2) + / 2 * Rabs (x (nth j q O) - / 2)
          - / 2 * Rabs (x (nth j p O) - x (nth j q O)))) P) P.

Theorem centred_formula : forall s P, P <> [] -> on_grid s P ->
  centred_integral s P = centred s P.
Proof.
  intros s P HP G. unfold centred_integral, centred.
  rewrite separable_closed_form by exact HP.
  rewrite square_kernel_all, centred_square.
  assert (E1 : sumR (fun p => prodN s (fun j => single_kernel _ (pieces_all _ centred_pieces)
                 (inside_all _ centred_inside) (with_whole _ centred_mu1) (nth j p O))) P
             = sumR (fun p => prodN s (fun j =>
                 1 + / 2 * Rabs (x (nth j p O) - / 2)
                   - / 2 * Rabs (x (nth j p O) - / 2) ^ 2)) P).
  { apply sumR_ext. intros p Hp. apply prodN_ext. intros j Hj.
    rewrite single_kernel_all, centred_single by exact (G p Hp j Hj). ring. }
  assert (E2 : sumR (fun p => sumR (fun q => prodN s (fun j =>
                 pair_kernel _ (pieces_all _ centred_pieces) (inside_all _ centred_inside)
                   (with_whole _ (fun _ => h)) (nth j p O) (nth j q O))) P) P
             = sumR (fun p => sumR (fun q => prodN s (fun j =>
                 1 + / 2 * Rabs (x (nth j p O) - / 2) + / 2 * Rabs (x (nth j q O) - / 2)
                   - / 2 * Rabs (x (nth j p O) - x (nth j q O)))) P) P).
  { apply sumR_ext. intros p Hp. apply sumR_ext. intros q Hq.
    apply prodN_ext. intros j Hj.
    rewrite pair_kernel_all, centred_pair by (apply G; assumption). ring. }
  rewrite E1, E2. replace (1 + / 12) with (13 / 12) by field. ring.
Qed.

End Centred.

End Grid.
