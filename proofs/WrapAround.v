(** * The wrap-around discrepancy's closed form from its definition.

    Each coordinate's box is the arc [[y, y + ℓ)] of the circle [[0, 1)], for every start [y]
    and length [ℓ] in [[0, 1)] (the usual parameters [(y, z)] with [z = y + ℓ mod 1], a shear
    of the square that keeps area: taken by hand), over every coordinate projection. On the
    grid of step [h = 1/M], with [y] in cell [a] and [ℓ] in cell [c], the word [p] lies in the
    arc iff the cell of [(p·h − y) mod 1], [offset p a], is below [c], or equal to [c] in the
    upper triangle of the cell (fractional parts summing above 1). So the pieces are the two
    triangles of every cell [(a, c)]; the moments of [ℓ^k] over them are the integrals of
    [(c + β)^k h^k] against the weights [β] and [1 − β] (by hand). [wd_formula]: the integral
    is `kinds.rs`'s [−(4/3)^s + (1/N²)·Σ_p Σ_q Π_j (3/2 − |x_pj − x_qj|·(1 − |x_pj − x_qj|))]. *)

From Coq Require Import Reals Lra Lia List Arith Bool.
From Gartowen Require Import Discrepancy.
Import ListNotations.
Open Scope R_scope.

Lemma sumR_cons : forall A (f : A -> R) a l, sumR f (a :: l) = f a + sumR f l.
Proof. reflexivity. Qed.

Lemma sumR_minus : forall A (f g : A -> R) l, sumR (fun a => f a - g a) l = sumR f l - sumR g l.
Proof. intros A f g l. induction l as [|a l IH]; [simpl; ring|]. rewrite !sumR_cons, IH. ring. Qed.

Lemma sumR_const : forall A (l : list A) k, sumR (fun _ => k) l = INR (length l) * k.
Proof.
  intros A l k. induction l as [|a l IH]; [simpl; ring|].
  rewrite sumR_cons, IH. cbn [length]. rewrite S_INR. ring.
Qed.

Lemma telescope_seq : forall (g : nat -> R) lo n,
  sumR (fun a => g (S a) - g a) (seq lo n) = g (lo + n)%nat - g lo.
Proof.
  intros g lo n. revert lo. induction n as [|n IH]; intro lo.
  - simpl. rewrite Nat.add_0_r. ring.
  - cbn [seq]. rewrite sumR_cons, IH. replace (S lo + n)%nat with (lo + S n)%nat by lia. ring.
Qed.

Lemma telescope_seq_eq : forall (g : nat -> R) lo n (f : nat -> R),
  (forall a, f a = g (S a) - g a) -> sumR f (seq lo n) = g (lo + n)%nat - g lo.
Proof. intros g lo n f E. rewrite <- telescope_seq. apply sumR_ext. intros a _. apply E. Qed.

(** Sums of [1], [a] and [a²] over [lo ≤ a < lo + n]. *)
Definition S1 (k : nat) : R := INR k * (INR k - 1) / 2.
Definition S2 (k : nat) : R := (INR k - 1) * INR k * (2 * INR k - 1) / 6.

Lemma sum_a : forall lo n, sumR (fun a => INR a) (seq lo n) = S1 (lo + n) - S1 lo.
Proof.
  intros lo n. rewrite <- telescope_seq. apply sumR_ext. intros a _.
  unfold S1. rewrite S_INR. field.
Qed.

Lemma sum_a2 : forall lo n, sumR (fun a => INR a ^ 2) (seq lo n) = S2 (lo + n) - S2 lo.
Proof.
  intros lo n. rewrite <- telescope_seq. apply sumR_ext. intros a _.
  unfold S2. rewrite S_INR. field.
Qed.

Lemma sum_quadratic : forall (u v w : R) lo n,
  sumR (fun a => u + v * INR a + w * INR a ^ 2) (seq lo n) =
  INR n * u + v * (S1 (lo + n) - S1 lo) + w * (S2 (lo + n) - S2 lo).
Proof.
  intros u v w lo n. rewrite !sumR_plus, !sumR_scal, sumR_const, seq_length, sum_a, sum_a2.
  reflexivity.
Qed.

Lemma seq_split3 : forall p q M, (p <= q <= M)%nat ->
  seq 0 M = seq 0 p ++ seq p (q - p) ++ seq q (M - q).
Proof.
  intros p q M H. replace M with (p + ((q - p) + (M - q)))%nat at 1 by lia.
  rewrite !seq_app. simpl. replace (p + (q - p))%nat with q by lia. reflexivity.
Qed.

Section Wrap.

Variable M : nat.
Hypothesis M_pos : (0 < M)%nat.

Local Notation h := (h M).
Local Notation x := (x M).

Lemma hM : h * INR M = 1.
Proof. unfold h. field. apply not_0_INR. lia. Qed.

(** The cell of [(p·h − y) mod 1] for [y] in cell [a]. *)
Definition offset (p a : nat) : nat := ((p + M - 1 - a) mod M)%nat.

Lemma offset_below : forall p a, (a < p)%nat -> (p < M)%nat -> offset p a = (p - 1 - a)%nat.
Proof.
  intros p a Ha Hp. unfold offset.
  replace (p + M - 1 - a)%nat with ((p - 1 - a) + 1 * M)%nat by lia.
  rewrite Nat.mod_add by lia. apply Nat.mod_small. lia.
Qed.

Lemma offset_above : forall p a, (p <= a)%nat -> (a < M)%nat -> offset p a = (p + M - 1 - a)%nat.
Proof. intros p a Ha Hm. unfold offset. apply Nat.mod_small. lia. Qed.

Lemma offset_lt : forall p a, (offset p a < M)%nat.
Proof. intros p a. unfold offset. apply Nat.mod_upper_bound. lia. Qed.

Definition wd_pieces : list (nat * nat * bool) :=
  flat_map (fun a => flat_map (fun c => [(a, c, false); (a, c, true)]) (seq 0 M)) (seq 0 M).

Definition wd_inside (p : nat) (t : nat * nat * bool) : bool :=
  let '(a, c, up) := t in orb (offset p a <? c)%nat (andb (offset p a =? c)%nat up).

Definition wd_mu0 (t : nat * nat * bool) : R := h ^ 2 / 2.

Definition wd_mu1 (t : nat * nat * bool) : R :=
  let '(_, c, up) := t in
  if up then h ^ 3 * (INR c / 2 + / 3) else h ^ 3 * (INR c / 2 + / 6).

Definition wd_mu2 (t : nat * nat * bool) : R :=
  let '(_, c, up) := t in
  if up then h ^ 4 * (INR c ^ 2 / 2 + 2 * INR c / 3 + / 4)
  else h ^ 4 * (INR c ^ 2 / 2 + INR c / 3 + / 12).

Lemma wd_sum : forall f, sumR f wd_pieces =
  sumR (fun a => sumR (fun c => f (a, c, false) + f (a, c, true)) (seq 0 M)) (seq 0 M).
Proof.
  intro f. unfold wd_pieces. rewrite sumR_flat_map. apply sumR_ext. intros a _.
  rewrite sumR_flat_map. apply sumR_ext. intros c _. rewrite !sumR_cons. simpl. ring.
Qed.
Lemma count_from : forall k, (k <= M)%nat ->
  sumR (fun c => ind (k <=? c)%nat) (seq 0 M) = INR M - INR k.
Proof.
  intros k Hk. rewrite (telescope_gen_eq INR M k).
  - replace (k <=? M)%nat with true by (symmetry; apply Nat.leb_le; lia). ring.
  - intro c. rewrite S_INR. ring.
Qed.

Lemma wd_square : square_kernel _ wd_pieces wd_mu2 = / 3.
Proof.
  unfold square_kernel. rewrite wd_sum.
  rewrite (sumR_ext _ _ (fun _ => h ^ 4 * (INR M ^ 3 / 3))).
  - rewrite sumR_const, seq_length. pose proof hM. replace (h ^ 4) with (h * h * h * h) by ring.
    replace (/ 3) with ((h * INR M) ^ 4 / 3) by (rewrite H; field). field.
  - intros a _. cbn [wd_mu2].
    rewrite (sumR_ext _ _ (fun c => h ^ 4 * (INR c ^ 2 + INR c + / 3))) by (intros c _; field).
    rewrite sumR_scal, (telescope_seq_eq (fun k => INR k ^ 3 / 3) 0 M).
    + simpl. field.
    + intro c. rewrite S_INR. field.
Qed.

(** Inner sum of the single kernel for the offset [e]. *)
Lemma count_eq : forall e, (e < M)%nat -> sumR (fun c => ind (c =? e)%nat) (seq 0 M) = 1.
Proof.
  intros e He.
  rewrite (sumR_ext _ _ (fun c => ind (e <=? c)%nat - ind (S e <=? c)%nat)).
  - rewrite sumR_minus, !count_from by lia. rewrite S_INR. ring.
  - intros c _. unfold ind.
    destruct (Nat.eqb_spec c e), (Nat.leb_spec e c), (Nat.leb_spec (S e) c); try lia; ring.
Qed.

(** Inner sum of the single kernel for the offset [e]. *)
Lemma wd_single_inner : forall e, (e < M)%nat ->
  sumR (fun c => ind (orb (e <? c)%nat (andb (e =? c)%nat false)) * (h ^ 3 * (INR c / 2 + / 6))
               + ind (orb (e <? c)%nat (andb (e =? c)%nat true)) * (h ^ 3 * (INR c / 2 + / 3)))
    (seq 0 M) =
  h ^ 3 * (INR M ^ 2 / 2 - INR e ^ 2 / 2 - INR e / 2 - / 6).
Proof.
  intros e He.
  rewrite (sumR_ext _ _ (fun c => h ^ 3 * (ind (S e <=? c)%nat * (INR c + / 2))
                                  + h ^ 3 * ((INR e / 2 + / 3) * ind (c =? e)%nat))).
  2: { intros c _. unfold ind.
       destruct (Nat.ltb_spec e c), (Nat.eqb_spec e c), (Nat.leb_spec (S e) c), (Nat.eqb_spec c e);
         simpl; try lia; subst; field. }
  rewrite sumR_plus, !sumR_scal.
  rewrite (telescope_gen_eq (fun k => INR k ^ 2 / 2) M (S e)) by (intro c; rewrite S_INR; field).
  replace (S e <=? M)%nat with true by (symmetry; apply Nat.leb_le; lia).
  rewrite count_eq by exact He. rewrite S_INR. field.
Qed.

Lemma seq_split2 : forall p, (p <= M)%nat -> seq 0 M = seq 0 p ++ seq p (M - p).
Proof.
  intros p H. replace M with (p + (M - p))%nat at 1 by lia. rewrite seq_app. reflexivity.
Qed.

Lemma INR_sub1 : forall p a, (a < p)%nat -> INR (p - 1 - a) = INR p - 1 - INR a.
Proof. intros p a H. rewrite !minus_INR by lia. simpl. ring. Qed.

Lemma INR_subM : forall p a, (a < M)%nat -> INR (p + M - 1 - a) = INR p + INR M - 1 - INR a.
Proof. intros p a H. rewrite !minus_INR, plus_INR by lia. simpl. ring. Qed.

Lemma wd_single : forall p, (p < M)%nat -> single_kernel _ wd_pieces wd_inside wd_mu1 p = / 3.
Proof.
  intros p Hp. unfold single_kernel. rewrite wd_sum.
  rewrite (sumR_ext _ _ (fun a => h ^ 3 * (INR M ^ 2 / 2 - INR (offset p a) ^ 2 / 2
                                           - INR (offset p a) / 2 - / 6))).
  2: { intros a _. cbn [wd_inside wd_mu1]. apply wd_single_inner, offset_lt. }
  rewrite (seq_split2 p) by lia. rewrite sumR_app.
  set (P := INR p). set (Mr := INR M).
  rewrite (sumR_ext _ _ (fun a => h ^ 3 * (Mr ^ 2 / 2 - (P - 1) ^ 2 / 2 - (P - 1) / 2 - / 6)
                                   + h ^ 3 * (P - 1 + / 2) * INR a + (- h ^ 3 / 2) * INR a ^ 2)
             (seq 0 p)).
  2: { intros a Ha. apply in_seq in Ha. rewrite offset_below, INR_sub1 by lia. unfold P, Mr. field. }
  rewrite (sumR_ext _ _
             (fun a => h ^ 3 * (Mr ^ 2 / 2 - (P + Mr - 1) ^ 2 / 2 - (P + Mr - 1) / 2 - / 6)
                       + h ^ 3 * (P + Mr - 1 + / 2) * INR a + (- h ^ 3 / 2) * INR a ^ 2)
             (seq p (M - p))).
  2: { intros a Ha. apply in_seq in Ha. rewrite offset_above, INR_subM by lia. unfold P, Mr. field. }
  rewrite !sum_quadratic. replace (p + (M - p))%nat with M by lia. rewrite Nat.add_0_l.
  unfold S1, S2. rewrite minus_INR by lia. fold P Mr. simpl (INR 0).
  assert (HM : Mr <> 0) by (unfold Mr; apply not_0_INR; lia).
  unfold h. fold Mr. field. exact HM.
Qed.

Lemma wd_pair_inner : forall e f, (e < M)%nat -> (f < M)%nat ->
  sumR (fun c => ind (orb (e <? c)%nat (andb (e =? c)%nat false))
                 * ind (orb (f <? c)%nat (andb (f =? c)%nat false)) * (h ^ 2 / 2)
               + ind (orb (e <? c)%nat (andb (e =? c)%nat true))
                 * ind (orb (f <? c)%nat (andb (f =? c)%nat true)) * (h ^ 2 / 2))
    (seq 0 M) = h ^ 2 * (INR M - / 2 - INR (Nat.max e f)).
Proof.
  intros e f He Hf.
  rewrite (sumR_ext _ _ (fun c => h ^ 2 / 2 * ind (S (Nat.max e f) <=? c)%nat
                                  + h ^ 2 / 2 * ind (Nat.max e f <=? c)%nat)).
  2: { intros c _. unfold ind.
       destruct (Nat.ltb_spec e c), (Nat.eqb_spec e c), (Nat.ltb_spec f c), (Nat.eqb_spec f c),
         (Nat.leb_spec (S (Nat.max e f)) c), (Nat.leb_spec (Nat.max e f) c);
         simpl; try lia; ring. }
  rewrite sumR_plus, !sumR_scal, !count_from by lia. rewrite S_INR. field.
Qed.

Lemma wd_pair_le : forall p q, (p <= q)%nat -> (q < M)%nat ->
  pair_kernel _ wd_pieces wd_inside wd_mu0 p q =
  / 2 - (INR q - INR p) * h + ((INR q - INR p) * h) ^ 2.
Proof.
  intros p q Hpq Hq. unfold pair_kernel. rewrite wd_sum.
  rewrite (sumR_ext _ _ (fun a => h ^ 2 * (INR M - / 2 - INR (Nat.max (offset p a) (offset q a))))).
  2: { intros a _. cbn [wd_inside wd_mu0]. apply wd_pair_inner; apply offset_lt. }
  rewrite (seq_split3 p q M) by lia. rewrite !sumR_app.
  set (P := INR p). set (Q := INR q). set (Mr := INR M).
  rewrite (sumR_ext _ _ (fun a => h ^ 2 * (Mr - / 2 - (Q - 1)) + h ^ 2 * INR a + 0 * INR a ^ 2)
             (seq 0 p)).
  2: { intros a Ha. apply in_seq in Ha. rewrite !offset_below by lia.
       rewrite Nat.max_r by lia. rewrite INR_sub1 by lia. unfold Q, Mr. ring. }
  rewrite (sumR_ext _ _ (fun a => h ^ 2 * (Mr - / 2 - (P + Mr - 1)) + h ^ 2 * INR a + 0 * INR a ^ 2)
             (seq p (q - p))).
  2: { intros a Ha. apply in_seq in Ha. rewrite offset_above, (offset_below q a) by lia.
       rewrite Nat.max_l by lia. rewrite INR_subM by lia. unfold P, Mr. ring. }
  rewrite (sumR_ext _ _ (fun a => h ^ 2 * (Mr - / 2 - (Q + Mr - 1)) + h ^ 2 * INR a + 0 * INR a ^ 2)
             (seq q (M - q))).
  2: { intros a Ha. apply in_seq in Ha. rewrite !offset_above by lia.
       rewrite Nat.max_r by lia. rewrite INR_subM by lia. unfold Q, Mr. ring. }
  rewrite !sum_quadratic. rewrite Nat.add_0_l.
  replace (p + (q - p))%nat with q by lia. replace (q + (M - q))%nat with M by lia.
  unfold S1, S2. rewrite !minus_INR by lia. fold P Q Mr. simpl (INR 0).
  assert (HM : Mr <> 0) by (unfold Mr; apply not_0_INR; lia).
  unfold h. fold Mr. field. exact HM.
Qed.

Lemma wd_pair : forall p q, (p < M)%nat -> (q < M)%nat ->
  pair_kernel _ wd_pieces wd_inside wd_mu0 p q =
  / 2 - Rabs (x p - x q) + Rabs (x p - x q) ^ 2.
Proof.
  intros p q Hp Hq. pose proof (h_pos M M_pos) as Hh. unfold Discrepancy.x.
  destruct (Nat.le_gt_cases p q) as [L|L].
  - rewrite wd_pair_le by assumption.
    assert (INR p <= INR q) by (apply le_INR, L).
    rewrite Rabs_left1 by nra. ring.
  - assert (Sym : pair_kernel _ wd_pieces wd_inside wd_mu0 p q =
                  pair_kernel _ wd_pieces wd_inside wd_mu0 q p)
      by (unfold pair_kernel; apply sumR_ext; intros; ring).
    rewrite Sym, wd_pair_le by lia.
    assert (INR q < INR p) by (apply lt_INR, L).
    rewrite Rabs_right by nra. ring.
Qed.

(** The squared wrap-around discrepancy as the integral of its definition. *)
Definition wd_integral (s : nat) (P : list (list nat)) : R :=
  integral _ (pieces_all _ wd_pieces) None (inside_all _ wd_inside)
    (with_whole _ wd_mu0) (with_whole _ wd_mu1) (with_whole _ wd_mu2) s P.

(** Hickernell's closed form (`kinds.rs`, [Kind::WrapAround]). *)
Definition wd (s : nat) (P : list (list nat)) : R :=
  let N := INR (length P) in
  - (4 / 3) ^ s
  + / N ^ 2 * sumR (fun p => sumR (fun q => prodN s (fun j =>
        3 / 2 - Rabs (x (nth j p O) - x (nth j q O))
                * (1 - Rabs (x (nth j p O) - x (nth j q O))))) P) P.

Theorem wd_formula : forall s P, P <> [] -> on_grid M s P -> wd_integral s P = wd s P.
Proof.
  intros s P HP G. unfold wd_integral, wd.
  rewrite separable_closed_form by exact HP.
  rewrite square_kernel_all, wd_square.
  assert (HN : INR (length P) <> 0).
  { apply not_0_INR. destruct P; [contradiction|]. simpl. lia. }
  assert (E1 : sumR (fun p => prodN s (fun j => single_kernel _ (pieces_all _ wd_pieces)
                 (inside_all _ wd_inside) (with_whole _ wd_mu1) (nth j p O))) P
               = INR (length P) * (4 / 3) ^ s).
  { rewrite (sumR_ext _ _ (fun _ => (4 / 3) ^ s)); [apply sumR_const|].
    intros p Hp. rewrite <- prodN_const. apply prodN_ext. intros j Hj.
    rewrite single_kernel_all, wd_single by (apply G; assumption). field. }
  assert (E2 : sumR (fun p => sumR (fun q => prodN s (fun j =>
                 pair_kernel _ (pieces_all _ wd_pieces) (inside_all _ wd_inside)
                   (with_whole _ wd_mu0) (nth j p O) (nth j q O))) P) P
             = sumR (fun p => sumR (fun q => prodN s (fun j =>
                 3 / 2 - Rabs (x (nth j p O) - x (nth j q O))
                         * (1 - Rabs (x (nth j p O) - x (nth j q O))))) P) P).
  { apply sumR_ext. intros p Hp. apply sumR_ext. intros q Hq.
    apply prodN_ext. intros j Hj.
    rewrite pair_kernel_all, wd_pair by (apply G; assumption). field. }
  rewrite E1, E2. replace (1 + / 3) with (4 / 3) by field. field. exact HN.
Qed.

End Wrap.
