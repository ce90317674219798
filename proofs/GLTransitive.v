(** * GL(q,2) sends every nonzero digit to every nonzero digit equally often, for every q.

    [Affine.affine_two_transitive] reduces Owen's pair lemma for the matrix variants' node law
    (ψ uniform over the linear bijections, then a uniform translation: AGL(q,2)) to this count.
    It was computed for q ≤ 4; here it is proved for every q, for any list [H] of linear
    bijections that holds every linear bijection of the digits the same number [K] of times
    ([gl_nonzero_uniform]), so [agl_two_transitive] holds in every base 2^q.

    The argument: for invertible linear [P] and [Q], the list of the maps [Q ∘ h ∘ P] holds
    every linear bijection [K] times too, and two lists with the same multiplicities give the
    same counts ([same_classes_same_counts]); so the number of [h] with [h v = w] equals the
    number with [h (P v) = Q⁻¹ w]. Any nonzero digit is moved to any other by at most two
    transvections [x ↦ x ⊕ [bit t of x]·c] with bit [t] of [c] clear ([move_nonzero]). *)

From Coq Require Import List Arith Bool Lia.
From Gartowen Require Import Laws ArtWord NodeLaws Symmetric ArtMarginal Affine Rank.
Import ListNotations.

Section GL.

Variable q : nat.

(** Two maps agree on the digits: an equivalence. *)
Lemma agree_refl : forall f, agree q f f = true.
Proof. intro f. apply (agree_spec q). reflexivity. Qed.

Lemma agree_trans : forall f g k, agree q f g = true -> agree q f k = agree q g k.
Proof.
  intros f g k Efg. rewrite (agree_spec q) in Efg. apply eq_iff_eq_true. rewrite !agree_spec.
  split; intros E x Hx; [rewrite <- Efg by exact Hx|rewrite Efg by exact Hx]; apply E, Hx.
Qed.

(** Lists whose members fall into the agreement classes equally often give the same counts
    to every predicate that respects agreement. *)
Lemma same_classes_same_counts : forall (Pr : (nat -> nat) -> bool),
  (forall f g, agree q f g = true -> Pr f = Pr g) ->
  forall H H', (forall g, In g H \/ In g H' ->
                 cnt (fun h => agree q h g) H = cnt (fun h => agree q h g) H') ->
  cnt Pr H = cnt Pr H'.
Proof.
  intros Pr HP H. induction H as [|h T IH]; intros H' E.
  - destruct H' as [|h' T']; [reflexivity|]. exfalso.
    specialize (E h' (or_intror (or_introl eq_refl))).
    rewrite cnt_cons, agree_refl in E. unfold cnt in E. simpl in E. lia.
  - assert (Pos : 0 < cnt (fun x => agree q x h) H').
    { rewrite <- (E h (or_introl (or_introl eq_refl))), cnt_cons, agree_refl. lia. }
    apply cnt_pos_exists in Pos as [h' [Hin Ag]].
    apply in_split in Hin as [A [B ->]].
    rewrite cnt_cons, cnt_app, cnt_cons, (HP h' h Ag).
    rewrite (IH (A ++ B)), cnt_app; [lia|].
    intros g Hg. assert (Ig : In g (h :: T) \/ In g (A ++ h' :: B)).
    { destruct Hg as [Hg|Hg]; [left; right; exact Hg|right].
      apply in_app_or in Hg as [Hg|Hg]; apply in_or_app; [left|right; right]; exact Hg. }
    specialize (E g Ig). rewrite cnt_cons, cnt_app, cnt_cons in E. rewrite cnt_app.
    rewrite (agree_trans h' h g Ag) in E. lia.
Qed.

(** A linear bijection of the digits with its inverse. *)
Definition invertible (P Pi : nat -> nat) : Prop :=
  maps_digits q P /\ maps_digits q Pi /\ linear_on_digits q P /\ linear_on_digits q Pi /\
  (forall x, x < 2 ^ q -> Pi (P x) = x) /\ (forall x, x < 2 ^ q -> P (Pi x) = x).

(** [Q ∘ h ∘ P]. *)
Definition conjugate (Q P h : nat -> nat) : nat -> nat := fun x => Q (h (P x)).

Lemma conjugate_agree : forall P Pi Q Qi h g, invertible P Pi -> invertible Q Qi ->
  maps_digits q h -> maps_digits q g ->
  agree q (conjugate Q P h) g = agree q h (conjugate Qi Pi g).
Proof.
  intros P Pi Q Qi h g [MP [MPi [_ [_ [PiP PPi]]]]] [MQ [MQi [_ [_ [QiQ QQi]]]]] Mh Mg.
  apply eq_iff_eq_true. rewrite !agree_spec. unfold conjugate. split; intros E x Hx.
  - rewrite <- (PPi x Hx) at 1. rewrite <- (E (Pi x) (MPi x Hx)). symmetry. apply QiQ, Mh.
    apply MP, MPi, Hx.
  - rewrite E by (apply MP, Hx). rewrite PiP by exact Hx. apply QQi, Mg, Hx.
Qed.

Lemma conjugate_linear_bijection : forall P Pi Q Qi h, invertible P Pi -> invertible Q Qi ->
  linear_on_digits q h -> bijective_on_digits q h ->
  linear_on_digits q (conjugate Q P h) /\ bijective_on_digits q (conjugate Q P h).
Proof.
  intros P Pi Q Qi h [MP [MPi [LP [_ [PiP _]]]]] [MQ [_ [LQ [_ [QiQ _]]]]] Lh [Mh Ih].
  unfold conjugate. split; [|split].
  - intros x y Hx Hy. rewrite LP, Lh, LQ by auto. reflexivity.
  - intros x Hx. apply MQ, Mh, MP, Hx.
  - intros x y Hx Hy E. apply (f_equal Qi) in E. rewrite !QiQ in E by (apply Mh, MP; auto).
    apply Ih in E; [|apply MP; auto|apply MP; auto].
    rewrite <- (PiP x Hx), <- (PiP y Hy), E. reflexivity.
Qed.

(** The number of [h] with [h v = w] is the number with [h (P v) = Q⁻¹ w]. *)
Theorem gl_counts_equal : forall H K,
  (forall h, In h H -> linear_on_digits q h /\ bijective_on_digits q h) ->
  (forall g, bijective_on_digits q g -> linear_on_digits q g -> cnt (fun h => agree q h g) H = K) ->
  forall P Pi Q Qi, invertible P Pi -> invertible Q Qi ->
  forall v w, v < 2 ^ q -> w < 2 ^ q ->
  cnt (fun h => h v =? w) H = cnt (fun h => h (P v) =? Qi w) H.
Proof.
  intros H K HH HK P Pi Q Qi IP IQ v w Hv Hw.
  assert (Members : forall h, In h (map (conjugate Q P) H) ->
            linear_on_digits q h /\ bijective_on_digits q h).
  { intros h Hh. apply in_map_iff in Hh as [h0 [<- H0]].
    destruct (HH h0 H0) as [L B]. apply (conjugate_linear_bijection P Pi Q Qi); assumption. }
  rewrite (same_classes_same_counts (fun h => h v =? w)) with (H' := map (conjugate Q P) H).
  - rewrite cnt_map. apply cnt_ext. intros h Hh. unfold conjugate.
    destruct IQ as [MQ [MQi [_ [_ [QiQ QQi]]]]]. destruct IP as [MP _].
    destruct (HH h Hh) as [_ [Mh _]].
    apply eq_iff_eq_true. rewrite !Nat.eqb_eq. split; intro E.
    + rewrite <- E. symmetry. apply QiQ, Mh, MP, Hv.
    + rewrite E. apply QQi, Hw.
  - intros f g Ag. rewrite (agree_spec q) in Ag. rewrite Ag by exact Hv. reflexivity.
  - intros g Hg.
    assert (Lg : linear_on_digits q g /\ bijective_on_digits q g)
      by (destruct Hg as [Hg|Hg]; [apply HH|apply Members]; exact Hg).
    destruct Lg as [Lg Bg]. rewrite (HK g Bg Lg), cnt_map.
    rewrite (cnt_ext _ _ (fun h => agree q h (conjugate Qi Pi g))).
    + symmetry. destruct (conjugate_linear_bijection Pi P Qi Q g) as [L' B'].
      * destruct IP as [? [? [? [? [? ?]]]]]. repeat split; assumption.
      * destruct IQ as [? [? [? [? [? ?]]]]]. repeat split; assumption.
      * exact Lg.
      * exact Bg.
      * apply HK; assumption.
    + intros h Hh. destruct (HH h Hh) as [_ [Mh _]].
      rewrite (conjugate_agree P Pi Q Qi h g IP IQ Mh (proj1 Bg)). reflexivity.
Qed.

(** ** Transvections: [x ↦ x ⊕ c] when bit [t] of [x] is set *)

Definition tv (t c x : nat) : nat := if Nat.testbit x t then Nat.lxor x c else x.

Lemma tv_invertible : forall t c, c < 2 ^ q -> Nat.testbit c t = false ->
  invertible (tv t c) (tv t c).
Proof.
  intros t c Hc Ct.
  assert (M : maps_digits q (tv t c)).
  { intros x Hx. unfold tv. destruct (Nat.testbit x t); [apply lxor_lt|]; assumption. }
  assert (L : linear_on_digits q (tv t c)).
  { intros x y _ _. unfold tv. rewrite Nat.lxor_spec.
    destruct (Nat.testbit x t), (Nat.testbit y t); simpl; xor_bits. }
  assert (I : forall x, tv t c (tv t c x) = x).
  { intro x. unfold tv. destruct (Nat.testbit x t) eqn:X.
    - rewrite Nat.lxor_spec, X, Ct. simpl. apply lxor_twice.
    - rewrite X. reflexivity. }
  repeat split; try assumption; intros x _; apply I.
Qed.

Lemma invertible_compose : forall P Pi R Ri, invertible P Pi -> invertible R Ri ->
  invertible (fun x => R (P x)) (fun x => Pi (Ri x)).
Proof.
  intros P Pi R Ri [MP [MPi [LP [LPi [PiP PPi]]]]] [MR [MRi [LR [LRi [RiR RRi]]]]].
  repeat split.
  - intros x Hx. apply MR, MP, Hx.
  - intros x Hx. apply MPi, MRi, Hx.
  - intros x y Hx Hy. rewrite LP, LR by auto. reflexivity.
  - intros x y Hx Hy. rewrite LRi, LPi by auto. reflexivity.
  - intros x Hx. rewrite RiR by (apply MP, Hx). apply PiP, Hx.
  - intros x Hx. rewrite PPi by (apply MRi, Hx). apply RRi, Hx.
Qed.

(** Any nonzero digit is sent to any nonzero digit by an invertible linear map. *)
Theorem move_nonzero : forall u u', 0 < u < 2 ^ q -> 0 < u' < 2 ^ q ->
  exists P Pi, invertible P Pi /\ P u = u'.
Proof.
  intros u u' Hu Hu'.
  destruct (Nat.eq_dec (Nat.land u u') 0) as [Dj|Cm].
  - (* No common bit: u ↦ u ⊕ u' ↦ u'. *)
    set (t := Nat.log2 u). set (t' := Nat.log2 u').
    assert (Ut : Nat.testbit u t = true) by (apply Nat.bit_log2; lia).
    assert (U't' : Nat.testbit u' t' = true) by (apply Nat.bit_log2; lia).
    assert (Dis : forall i, Nat.testbit u i && Nat.testbit u' i = false).
    { intro i. rewrite <- Nat.land_spec, Dj. apply Nat.bits_0. }
    assert (U't : Nat.testbit u' t = false)
      by (pose proof (Dis t) as X; rewrite Ut in X; exact X).
    assert (Ut' : Nat.testbit u t' = false)
      by (pose proof (Dis t') as X; rewrite U't', andb_true_r in X; exact X).
    exists (fun x => tv t' u (tv t u' x)), (fun x => tv t u' (tv t' u x)). split.
    + apply invertible_compose; apply tv_invertible; lia || assumption.
    + unfold tv. rewrite Ut, Nat.lxor_spec, Ut', U't'. simpl.
      rewrite (Nat.lxor_comm u u'). apply lxor_twice.
  - (* A common bit t: one transvection by u ⊕ u'. *)
    set (t := Nat.log2 (Nat.land u u')).
    assert (Both : Nat.testbit u t && Nat.testbit u' t = true)
      by (rewrite <- Nat.land_spec; apply Nat.bit_log2, Cm).
    apply andb_true_iff in Both as [Ut U't].
    exists (tv t (Nat.lxor u u')), (tv t (Nat.lxor u u')). split.
    + apply tv_invertible; [apply lxor_lt; lia|]. rewrite Nat.lxor_spec, Ut, U't. reflexivity.
    + unfold tv. rewrite Ut. apply lxor_cancel.
Qed.

(** GL(q,2), as any list holding every linear bijection [K] times, sends every nonzero digit
    to every nonzero digit equally often. *)
Theorem gl_nonzero_uniform : forall H K,
  (forall h, In h H -> linear_on_digits q h /\ bijective_on_digits q h) ->
  (forall g, bijective_on_digits q g -> linear_on_digits q g -> cnt (fun h => agree q h g) H = K) ->
  forall v w v' w', 0 < v < 2 ^ q -> 0 < w < 2 ^ q -> 0 < v' < 2 ^ q -> 0 < w' < 2 ^ q ->
  cnt (fun h => h v =? w) H = cnt (fun h => h v' =? w') H.
Proof.
  intros H K HH HK v w v' w' Hv Hw Hv' Hw'.
  destruct (move_nonzero v v' Hv Hv') as [P [Pi [IP Pv]]].
  destruct (move_nonzero w' w Hw' Hw) as [Q [Qi [IQ Qw]]].
  rewrite (gl_counts_equal H K HH HK P Pi Q Qi IP IQ v w) by lia.
  rewrite Pv, <- Qw. destruct IQ as [_ [_ [_ [_ [QiQ _]]]]]. rewrite QiQ by lia. reflexivity.
Qed.

(** Owen's pair lemma's hypothesis for the matrix variants' node law in every base 2^q: the
    affine law of GL(q,2) (every linear bijection [K] times) is uniformly 2-transitive. *)
Theorem agl_two_transitive : 1 <= q -> forall H K,
  (forall h, In h H -> linear_on_digits q h /\ bijective_on_digits q h) ->
  (forall g, bijective_on_digits q g -> linear_on_digits q g -> cnt (fun h => agree q h g) H = K) ->
  forall d d' e e', d < 2 ^ q -> d' < 2 ^ q -> e < 2 ^ q -> e' < 2 ^ q -> d <> d' -> e <> e' ->
  cnt (fun g => (g d =? e) && (g d' =? e')) (art_law q H) = cnt (fun h => h 1 =? 1) H.
Proof.
  intros Hq H K HH HK. apply affine_two_transitive.
  - intros h Hh. destruct (HH h Hh) as [L [M _]]. split; assumption.
  - intros v w Hv Hw. assert (One : 0 < 1 < 2 ^ q).
    { split; [lia|]. apply (Nat.lt_le_trans _ (2 ^ 1)); [simpl; lia|].
      apply Nat.pow_le_mono_r; lia. }
    apply (gl_nonzero_uniform H K HH HK); assumption.
Qed.

End GL.
