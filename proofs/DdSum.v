(** * The error bound of the compensated discrepancy ([crates/discrepancy/src/compensated.rs]).

    Same model as [Float.v]: binary64 is FLT(−1074, 53) with ties to even and no overflow (the
    Rust code checks at run time that every value stays below 2^1000). The Rust double-double
    operations are written here operation for operation:
    - [dd_add_correct]: [Dd::add] of two non-negative normalized pairs (hi ≥ 0, |lo| ≤ 2u·hi,
      u = 2^-53: the invariant [Inv]) returns such a pair within 10u² of the exact sum;
    - [dd_mul_bound]: [Dd::mul] returns one within 20u² of the exact product when hi·hi is 0
      or at least 2^-900 ([dd_mul_correct], [dd_mul_zero]);
    - [tree_error] (any order of additions: a binary tree) and [chain_error] (a left-to-right
      product), for any operation with such a one-step bound, instantiated as [dd_sum_error],
      [f64_sum_error], [dd_product_error] and [f64_product_error];
    - [pow_gamma]: (1 + δ)^h ≤ 1/(1 − hδ), so the code evaluates the bound without powers;
    - [to_computed], [combine_error]: from bounds on the exact sums to the relative error of
      D² = c0 + c1·S1/N + S2/N², combined exactly from the computed double-doubles;
    - [wd_pair_f64_error] (WD's f64 pair factor) and [fixed_point_exact] (the exact
      ingredients of the other factors).
    [crates/discrepancy/src/bound.rs] evaluates exactly these formulas in rationals, with the
    depths and term counts of the code's summation order. *)

From Coq Require Import Reals Psatz ZArith List.
From Flocq Require Import Core Relative.
From Gartowen Require Import Float.
Open Scope R_scope.

Definition u : R := / 9007199254740992.

Lemma u_bpow : bpow radix2 (-53) = u.
Proof.
  unfold u. change (-53)%Z with (- (53))%Z. rewrite bpow_opp. f_equal.

Qed.

Lemma half_ulp_one : / 2 * bpow radix2 (- prec + 1) = u.
Proof.
  rewrite <- u_bpow. unfold prec. replace (- (53) + 1)%Z with (-52)%Z by lia.
  change (-53)%Z with (-1 + -52)%Z. rewrite (bpow_plus radix2 (-1) (-52)). f_equal.
Qed.

Lemma u_pos : 0 < u.
Proof. unfold u. lra. Qed.

Lemma abs_le : forall x y, Rabs x <= y <-> - y <= x <= y.
Proof.
  intros x y. unfold Rabs. destruct (Rcase_abs x); split; intro H; lra.
Qed.

Lemma fmt_rnd : forall x, fmt (rnd x).
Proof. intro x. unfold fmt, rnd. apply generic_format_round; auto with typeclass_instances. Qed.

Lemma rnd_nonneg : forall x, 0 <= x -> 0 <= rnd x.
Proof.
  intros x H. unfold rnd. apply round_ge_generic; auto with typeclass_instances.
  apply generic_format_0.
Qed.

Lemma add_err : forall a b, fmt a -> fmt b -> Rabs (rnd (a + b) - (a + b)) <= u * Rabs (a + b).
Proof. intros a b Fa Fb. rewrite <- u_bpow. apply add_error; assumption. Qed.

(** The same against any upper bound M of the exact sum's magnitude. *)
Lemma add_err_le : forall a b M, fmt a -> fmt b -> Rabs (a + b) <= M ->
  Rabs (rnd (a + b) - (a + b)) <= u * M.
Proof.
  intros a b M Fa Fb H. eapply Rle_trans; [apply add_err; assumption|].
  apply Rmult_le_compat_l; [unfold u; lra|exact H].
Qed.

(** Rounding of any real: relative error u plus an absolute 2^-1075 (subnormals). *)
Definition eta : R := / 2 * bpow radix2 emin.

Lemma rnd_err : forall x, Rabs (rnd x - x) <= u * Rabs x + eta.
Proof.
  intro x. destruct (error_N_FLT radix2 emin prec ltac:(unfold prec; lia) choice x)
    as (d & n & Hd & Hn & _ & E).
  unfold rnd. rewrite E. rewrite half_ulp_one in Hd. fold eta in Hn.
  replace (x * (1 + d) + n - x) with (x * d + n) by ring.
  eapply Rle_trans; [apply Rabs_triang|]. rewrite Rabs_mult.
  apply Rplus_le_compat; [|exact Hn]. rewrite Rmult_comm.
  apply Rmult_le_compat_r; [apply Rabs_pos|exact Hd].
Qed.

(** Rounding of a real at least 2^-1022 in magnitude: relative error u. *)
Lemma rnd_rel : forall x, bpow radix2 (-1022) <= Rabs x -> Rabs (rnd x - x) <= u * Rabs x.
Proof.
  intros x H. rewrite <- half_ulp_one. unfold rnd.
  apply (relative_error_N_FLT radix2 emin prec prec_gt_0 choice x). exact H.
Qed.

Lemma eta_small : eta <= u * u * u * bpow radix2 (-900).
Proof.
  unfold eta, emin. rewrite <- u_bpow. rewrite <- !bpow_plus.
  replace (/ 2) with (bpow radix2 (-1)) by (simpl; lra). rewrite <- bpow_plus.
  apply bpow_le. lia.
Qed.

(** ** Double-doubles: the Rust [Dd] with its invariant. *)

(** A pair (hi, lo) of doubles with hi ≥ 0 and |lo| ≤ 2u·hi: what [quick_two_sum] returns
    for a non-negative sum, and what an f64 (lo = 0) or a correctly split integer is. *)
Definition Inv (a : R * R) : Prop :=
  fmt (fst a) /\ fmt (snd a) /\ 0 <= fst a /\ Rabs (snd a) <= 2 * u * fst a.

Definition val (a : R * R) : R := fst a + snd a.

Lemma inv_val : forall a, Inv a -> (1 - 2 * u) * fst a <= val a <= (1 + 2 * u) * fst a.
Proof.
  intros [h l] (_ & _ & H0 & Hl). unfold val; cbn [fst snd] in *.
  apply abs_le in Hl. unfold u in *. lra.
Qed.

Lemma inv_nonneg : forall a, Inv a -> 0 <= val a.
Proof.
  intros a H. pose proof (inv_val a H). destruct H as (_ & _ & Hp & _).
  unfold u in *. nra.
Qed.

(** Fast2Sum of a non-negative sum returns an [Inv] pair worth exactly s + t. *)
Lemma quick_two_sum_inv : forall s t, fmt s -> fmt t -> Rabs t <= Rabs s -> 0 <= s + t ->
  Inv (quick_two_sum s t) /\ val (quick_two_sum s t) = s + t.
Proof.
  intros s t Fs Ft Hts Hp.
  pose proof (quick_two_sum_exact s t Fs Ft Hts) as E.
  assert (Fh : fst (quick_two_sum s t) = rnd (s + t)) by reflexivity.
  pose proof (add_err s t Fs Ft) as R. rewrite <- Fh in R.
  rewrite (Rabs_pos_eq (s + t) Hp) in R. apply abs_le in R.
  assert (Hn : 0 <= fst (quick_two_sum s t)) by (rewrite Fh; apply rnd_nonneg; exact Hp).
  split; [|exact E].
  split; [rewrite Fh; apply fmt_rnd|].
  split; [unfold quick_two_sum; cbn [snd]; apply fmt_rnd|].
  split; [exact Hn|].
  apply abs_le. unfold u in *. lra.
Qed.

(** Rust [Dd::add]: [let (s, e) = two_sum(self.hi, o.hi);
    let (hi, lo) = quick_two_sum(s, e + self.lo + o.lo)]. *)
Definition dd_add (a b : R * R) : R * R :=
  let st := two_sum (fst a) (fst b) in
  quick_two_sum (fst st) (rnd (rnd (snd st + snd a) + snd b)).

Theorem dd_add_correct : forall a b, Inv a -> Inv b ->
  Inv (dd_add a b) /\
  Rabs (val (dd_add a b) - (val a + val b)) <= 10 * (u * u) * (val a + val b).
Proof.
  intros [ah al] [bh bl] Ia Ib.
  pose proof (inv_val _ Ia) as Va. pose proof (inv_val _ Ib) as Vb.
  destruct Ia as (Fah & Fal & Pa & Ha). destruct Ib as (Fbh & Fbl & Pb & Hb).
  unfold dd_add, val in *; cbn [fst snd] in *.
  set (s := fst (two_sum ah bh)). set (e := snd (two_sum ah bh)).
  assert (Es : s = rnd (ah + bh)) by reflexivity.
  assert (Fs : fmt s) by (rewrite Es; apply fmt_rnd).
  assert (Fe : fmt e) by (unfold e, two_sum; cbn [snd]; apply fmt_rnd).
  assert (Se : s + e = ah + bh) by (apply two_sum_exact; assumption).
  pose proof (add_err ah bh Fah Fbh) as Re. rewrite <- Es in Re.
  rewrite (Rabs_pos_eq (ah + bh)) in Re by lra. apply abs_le in Re.
  apply abs_le in Ha. apply abs_le in Hb.
  set (t1 := rnd (e + al)).
  assert (Ft1 : fmt t1) by apply fmt_rnd.
  assert (A1 : Rabs (e + al) <= u * (ah + bh) + 2 * u * ah) by (apply abs_le; lra).
  assert (R1' : Rabs (t1 - (e + al)) <= u * (u * (ah + bh) + 2 * u * ah))
    by (apply add_err_le; assumption).
  apply abs_le in R1'.
  set (t := rnd (t1 + bl)).
  assert (A2 : Rabs (t1 + bl) <= (1 + u) * (u * (ah + bh) + 2 * u * ah) + 2 * u * bh).
  { apply abs_le. unfold u in *. lra. }
  assert (R2' : Rabs (t - (t1 + bl)) <=
                u * ((1 + u) * (u * (ah + bh) + 2 * u * ah) + 2 * u * bh))
    by (apply add_err_le; assumption).
  apply abs_le in R2'.
  assert (Ht : Rabs t <= Rabs s).
  { rewrite (Rabs_pos_eq s) by (unfold u in *; lra). apply abs_le. unfold u in *. lra. }
  assert (Hp : 0 <= s + t) by (unfold u in *; lra).
  destruct (quick_two_sum_inv s t Fs (fmt_rnd _) Ht Hp) as [I V].
  split; [exact I|]. unfold val in V. rewrite V.
  apply abs_le. unfold u in *. lra.
Qed.

(** Rust [Dd::mul]: [let (p, e) = two_prod(self.hi, o.hi);
    let (hi, lo) = quick_two_sum(p, e + (self.hi * o.lo + self.lo * o.hi))]
    (lo·lo is dropped). *)
Definition dd_mul (a b : R * R) : R * R :=
  let pe := two_prod (fst a) (fst b) in
  quick_two_sum (fst pe) (rnd (snd pe + rnd (rnd (fst a * snd b) + rnd (snd a * fst b)))).

Theorem dd_mul_correct : forall a b, Inv a -> Inv b ->
  bpow radix2 (-900) <= fst a * fst b ->
  Inv (dd_mul a b) /\
  Rabs (val (dd_mul a b) - val a * val b) <= 20 * (u * u) * (val a * val b).
Proof.
  intros [ah al] [bh bl] Ia Ib HP.
  destruct Ia as (Fah & Fal & Pa & Ha). destruct Ib as (Fbh & Fbl & Pb & Hb).
  unfold dd_mul, val in *; cbn [fst snd] in *.
  set (P := ah * bh) in *.
  set (p := fst (two_prod ah bh)). set (e := snd (two_prod ah bh)).
  assert (Ep : p = rnd P) by reflexivity.
  assert (Fp : fmt p) by (rewrite Ep; apply fmt_rnd).
  assert (Fe : fmt e) by (unfold e, two_prod; cbn [snd]; apply fmt_rnd).
  assert (P0 : 0 <= P) by (eapply Rle_trans; [apply bpow_ge_0|exact HP]).
  assert (B969 : bpow radix2 (-969) <= Rabs P).
  { rewrite Rabs_pos_eq by lra. eapply Rle_trans; [|exact HP]. apply bpow_le. lia. }
  assert (Pe : p + e = P) by (apply two_prod_exact; auto).
  assert (Rp : Rabs (p - P) <= u * P).
  { rewrite Ep. pose proof (rnd_rel P) as R. rewrite (Rabs_pos_eq P P0) in R at 2.
    apply R. eapply Rle_trans; [|exact B969]. apply bpow_le. lia. }
  apply abs_le in Rp.
  pose proof eta_small as Eta.
  assert (EtaP : eta <= u * u * u * P).
  { eapply Rle_trans; [exact Eta|]. apply Rmult_le_compat_l; [unfold u; lra|exact HP]. }
  assert (Eta0 : 0 <= eta) by (unfold eta; apply Rmult_le_pos; [lra|apply bpow_ge_0]).
  (* the three cross products *)
  assert (X1 : Rabs (ah * bl) <= 2 * u * P).
  { rewrite Rabs_mult, (Rabs_pos_eq ah) by lra. unfold P.
    replace (2 * u * (ah * bh)) with (ah * (2 * u * bh)) by ring.
    apply Rmult_le_compat_l; assumption. }
  assert (X2 : Rabs (al * bh) <= 2 * u * P).
  { rewrite Rabs_mult, (Rabs_pos_eq bh) by lra. unfold P.
    replace (2 * u * (ah * bh)) with ((2 * u * ah) * bh) by ring.
    apply Rmult_le_compat_r; assumption. }
  assert (X3 : Rabs (al * bl) <= 4 * (u * u) * P).
  { rewrite Rabs_mult. unfold P.
    replace (4 * (u * u) * (ah * bh)) with ((2 * u * ah) * (2 * u * bh)) by ring.
    apply Rmult_le_compat; try apply Rabs_pos; assumption. }
  set (c1 := rnd (ah * bl)). set (c2 := rnd (al * bh)).
  assert (R1 : Rabs (c1 - ah * bl) <= u * (2 * u * P) + eta).
  { eapply Rle_trans; [apply rnd_err|]. apply Rplus_le_compat_r.
    apply Rmult_le_compat_l; [unfold u; lra|exact X1]. }
  assert (R2 : Rabs (c2 - al * bh) <= u * (2 * u * P) + eta).
  { eapply Rle_trans; [apply rnd_err|]. apply Rplus_le_compat_r.
    apply Rmult_le_compat_l; [unfold u; lra|exact X2]. }
  apply abs_le in X1. apply abs_le in X2. apply abs_le in X3.
  apply abs_le in R1. apply abs_le in R2.
  set (c := rnd (c1 + c2)).
  assert (A3 : Rabs (c1 + c2) <= 4 * u * P + 2 * (u * (2 * u * P) + eta))
    by (apply abs_le; lra).
  assert (R3' : Rabs (c - (c1 + c2)) <= u * (4 * u * P + 2 * (u * (2 * u * P) + eta)))
    by (apply add_err_le; [apply fmt_rnd|apply fmt_rnd|exact A3]).
  apply abs_le in R3'.
  set (t := rnd (e + c)).
  assert (A4 : Rabs (e + c) <=
               u * P + (1 + u) * (4 * u * P + 2 * (u * (2 * u * P) + eta))).
  { apply abs_le. unfold u in *. lra. }
  assert (R4' : Rabs (t - (e + c)) <=
                u * (u * P + (1 + u) * (4 * u * P + 2 * (u * (2 * u * P) + eta))))
    by (apply add_err_le; [exact Fe|apply fmt_rnd|exact A4]).
  apply abs_le in R4'.
  assert (Ht : Rabs t <= Rabs p).
  { rewrite (Rabs_pos_eq p) by (unfold u in *; lra). apply abs_le. unfold u in *. lra. }
  assert (Hs : 0 <= p + t) by (unfold u in *; lra).
  destruct (quick_two_sum_inv p t Fp (fmt_rnd _) Ht Hs) as [I V].
  split; [exact I|]. unfold val in V. rewrite V.
  replace ((ah + al) * (bh + bl)) with (P + ah * bl + al * bh + al * bl) by (unfold P; ring).
  apply abs_le. unfold u in *. lra.
Qed.

(** The other case of [Dd::mul]'s precondition: hi·hi = 0 (a factor 0, as (a/2)(1 − a) at
    a = 0 or (|x − y| − ½)² at |x − y| = ½): the product is exactly 0. *)
Lemma rnd_0 : rnd 0 = 0.
Proof. unfold rnd. apply round_0. auto with typeclass_instances. Qed.

Lemma dd_mul_zero : forall a b, Inv a -> Inv b -> fst a * fst b = 0 ->
  Inv (dd_mul a b) /\ val (dd_mul a b) = 0 /\ val a * val b = 0.
Proof.
  intros [ah al] [bh bl] Ia Ib H0.
  destruct Ia as (Fah & Fal & Pa & Ha). destruct Ib as (Fbh & Fbl & Pb & Hb).
  unfold dd_mul, val, Inv in *; cbn [fst snd] in *.
  assert (Z : (ah = 0 /\ al = 0) \/ (bh = 0 /\ bl = 0)).
  { destruct (Rmult_integral _ _ H0) as [A|B]; [left|right]; split; try assumption.
    - subst. rewrite Rmult_0_r in Ha. pose proof (Rabs_pos al).
      destruct (Req_dec al 0) as [E|E]; [exact E|]. pose proof (Rabs_pos_lt al E). lra.
    - subst. rewrite Rmult_0_r in Hb. pose proof (Rabs_pos bl).
      destruct (Req_dec bl 0) as [E|E]; [exact E|]. pose proof (Rabs_pos_lt bl E). lra. }
  assert (Pe : fst (two_prod ah bh) + snd (two_prod ah bh) = 0).
  { rewrite two_prod_exact by (auto; left; exact H0). exact H0. }
  assert (P0 : fst (two_prod ah bh) = 0) by (change (rnd (ah * bh) = 0); rewrite H0; apply rnd_0).
  assert (E0 : snd (two_prod ah bh) = 0) by lra.
  rewrite P0, E0.
  assert (C0 : rnd (rnd (ah * bl) + rnd (al * bh)) = 0).
  { destruct Z as [[-> ->]|[-> ->]]; rewrite ?Rmult_0_l, ?Rmult_0_r, rnd_0, Rplus_0_r; apply rnd_0. }
  rewrite C0, Rplus_0_r, rnd_0.
  unfold quick_two_sum; cbn [fst snd]. rewrite Rplus_0_r, rnd_0, Rminus_0_r, rnd_0, Rminus_0_r, rnd_0.
  split; [|split; [ring|destruct Z as [[-> ->]|[-> ->]]; ring]].
  split; [apply generic_format_0|]. split; [apply generic_format_0|]. split; [lra|].
  rewrite Rabs_R0. lra.
Qed.

(** [Dd::mul]'s precondition: hi·hi is 0 or at least 2^-900. *)
Definition dd_mul_pre (a b : R * R) : Prop :=
  fst a * fst b = 0 \/ bpow radix2 (-900) <= fst a * fst b.

Theorem dd_mul_bound : forall a b, Inv a -> Inv b -> dd_mul_pre a b ->
  Inv (dd_mul a b) /\
  Rabs (val (dd_mul a b) - val a * val b) <= 20 * (u * u) * (val a * val b).
Proof.
  intros a b Ia Ib [Z|B].
  - destruct (dd_mul_zero a b Ia Ib Z) as (I & V & W). split; [exact I|].
    rewrite V, W, Rminus_0_r, Rabs_R0, Rmult_0_r. lra.
  - apply dd_mul_correct; assumption.
Qed.

(** The f64 pair factor of WD for d > 4, 5/4 + c² with c = ||x − y| − ½| (Rust
    [1.25 + c * c], two roundings): within 2u of its value, for any real c with c² ≤ 1
    (here c ≤ ½). *)
Theorem wd_pair_f64_error : forall c, c * c <= 1 ->
  Rabs (rnd (5 / 4 + rnd (c * c)) - (5 / 4 + c * c)) <= 2 * u * (5 / 4 + c * c).
Proof.
  intros c C1.
  assert (C : 0 <= c * c) by nra.
  pose proof (rnd_err (c * c)) as R1. rewrite (Rabs_pos_eq (c * c) C) in R1.
  pose proof (rnd_err (5 / 4 + rnd (c * c))) as R2.
  pose proof eta_small as Eta.
  assert (Eta0 : 0 <= eta) by (unfold eta; apply Rmult_le_pos; [lra|apply bpow_ge_0]).
  assert (Tiny : bpow radix2 (-900) <= 1) by (apply (bpow_le radix2 (-900) 0); lia).
  assert (EtaS : eta <= u * u * u).
  { eapply Rle_trans; [exact Eta|]. rewrite <- (Rmult_1_r (u * u * u)) at 2.
    apply Rmult_le_compat_l; [unfold u; lra|exact Tiny]. }
  apply abs_le in R1.
  assert (A : Rabs (5 / 4 + rnd (c * c)) <= 5 / 4 + c * c + (u * (c * c) + eta))
    by (apply abs_le; lra).
  assert (R2' : Rabs (rnd (5 / 4 + rnd (c * c)) - (5 / 4 + rnd (c * c)))
                <= u * (5 / 4 + c * c + (u * (c * c) + eta)) + eta).
  { eapply Rle_trans; [exact R2|]. apply Rplus_le_compat_r.
    apply Rmult_le_compat_l; [unfold u; lra|exact A]. }
  apply abs_le in R2'. apply abs_le. unfold u in *. lra.
Qed.

(** The exact ingredients: an integer m with |m| < 2^53 times 2^e (e ≥ −1074) is a double,
    so its rounding returns it; every f64 ingredient of a factor at ≤ 50-bit coordinates
    (1 − x, 1 + x, x − ½, |x − y|, 1 − max, 2 − max, CD's pair factor) is such a number with
    e = −51 and |m| < 2^53. *)
Theorem fixed_point_exact : forall m e, (Z.abs m < 2 ^ 53)%Z -> (emin <= e)%Z ->
  rnd (IZR m * bpow radix2 e) = IZR m * bpow radix2 e.
Proof.
  intros m e Hm He. unfold rnd. apply round_generic; [auto with typeclass_instances|].
  apply generic_format_FLT. exists (Float radix2 m e).
  - unfold F2R. reflexivity.
  - cbn. exact Hm.
  - cbn. exact He.
Qed.

(** ** Sums in any order: a binary tree of additions, each with relative error delta. *)
Section Tree.
Variable T : Type.
Variable value : T -> R.
Variable ok : T -> Prop.
Variable add : T -> T -> T.
Variable delta : R.
Hypothesis delta_nonneg : 0 <= delta.
Hypothesis ok_nonneg : forall a, ok a -> 0 <= value a.
Hypothesis add_ok : forall a b, ok a -> ok b ->
  ok (add a b) /\ Rabs (value (add a b) - (value a + value b)) <= delta * (value a + value b).

(** A leaf is a computed term with the exact real it approximates. *)
Inductive tree := Leaf (x : T) (exact : R) | Node (l r : tree).

Fixpoint eval (t : tree) : T :=
  match t with Leaf x _ => x | Node l r => add (eval l) (eval r) end.
Fixpoint exact (t : tree) : R :=
  match t with Leaf _ x => x | Node l r => exact l + exact r end.
Fixpoint depth (t : tree) : nat :=
  match t with Leaf _ _ => O | Node l r => S (Nat.max (depth l) (depth r)) end.
Fixpoint leaves_ok (rho : R) (t : tree) : Prop :=
  match t with
  | Leaf x e => ok x /\ 0 <= e /\ Rabs (value x - e) <= rho * e
  | Node l r => leaves_ok rho l /\ leaves_ok rho r
  end.

Lemma exact_nonneg : forall rho t, leaves_ok rho t -> 0 <= exact t.
Proof.
  intros rho t. induction t as [x e|l IHl r IHr]; cbn; intro H.
  - tauto.
  - destruct H as [Hl Hr]. specialize (IHl Hl). specialize (IHr Hr). lra.
Qed.

(** If every leaf is within rho of its term, the computed sum is within
    (1 + rho)(1 + delta)^depth − 1 of the exact sum, relatively. *)
Theorem tree_error : forall rho t, 0 <= rho -> leaves_ok rho t ->
  ok (eval t) /\
  Rabs (value (eval t) - exact t) <= ((1 + rho) * (1 + delta) ^ depth t - 1) * exact t.
Proof.
  intros rho t Hr. induction t as [x e|l IHl r IHr]; cbn - [pow]; intro H.
  - destruct H as (O & E & B). split; [exact O|]. rewrite pow_O. lra.
  - destruct H as [Hl Hr']. destruct (IHl Hl) as [Ol Bl]. destruct (IHr Hr') as [Or Br].
    pose proof (exact_nonneg _ _ Hl) as El. pose proof (exact_nonneg _ _ Hr') as Er.
    destruct (add_ok _ _ Ol Or) as [O B]. split; [exact O|].
    set (m := Nat.max (depth l) (depth r)).
    set (K := (1 + rho) * (1 + delta) ^ m).
    assert (K1 : 1 <= K).
    { unfold K. rewrite <- (Rmult_1_l 1). apply Rmult_le_compat; try lra.
      apply pow_R1_Rle. lra. }
    assert (Kl : (1 + rho) * (1 + delta) ^ depth l <= K).
    { apply Rmult_le_compat_l; [lra|]. apply Rle_pow; [lra|]. apply Nat.le_max_l. }
    assert (Kr : (1 + rho) * (1 + delta) ^ depth r <= K).
    { apply Rmult_le_compat_l; [lra|]. apply Rle_pow; [lra|]. apply Nat.le_max_r. }
    assert (Bl' : Rabs (value (eval l) - exact l) <= (K - 1) * exact l).
    { eapply Rle_trans; [exact Bl|]. apply Rmult_le_compat_r; lra. }
    assert (Br' : Rabs (value (eval r) - exact r) <= (K - 1) * exact r).
    { eapply Rle_trans; [exact Br|]. apply Rmult_le_compat_r; lra. }
    apply abs_le in Bl'. apply abs_le in Br'.
    replace ((1 + rho) * (1 + delta) ^ S m) with (K * (1 + delta)) by (unfold K; cbn [pow]; ring).
    assert (D : delta * (value (eval l) + value (eval r)) <= delta * (K * (exact l + exact r))).
    { apply Rmult_le_compat_l; [exact delta_nonneg|]. lra. }
    apply abs_le in B. apply abs_le. nra.
Qed.

End Tree.

(** (1 + δ)^h ≤ 1/(1 − hδ) when hδ < 1 (the γ_h of Higham's analyses), so the bound can be
    evaluated in exact rationals without the power. *)
Lemma pow_gamma : forall delta h, 0 <= delta -> INR h * delta < 1 ->
  (1 + delta) ^ h * (1 - INR h * delta) <= 1.
Proof.
  intros delta h Hd. induction h as [|h IH]; intro Hh.
  - cbn. lra.
  - rewrite S_INR in *. cbn [pow].
    assert (Hh' : INR h * delta < 1) by (pose proof (pos_INR h); nra).
    specialize (IH Hh').
    assert (P : 0 <= (1 + delta) ^ h) by (apply pow_le; lra).
    (* (1+δ)^(h+1)(1 − (h+1)δ) = (1+δ)^h [(1 − hδ) − δ(h+1)δ... ] ≤ (1+δ)^h (1 − hδ) *)
    assert (Q : 0 <= (INR h + 1) * (delta * delta))
      by (apply Rmult_le_pos; [pose proof (pos_INR h); lra|nra]).
    assert (E : (1 + delta) * (1 - (INR h + 1) * delta) <= 1 - INR h * delta).
    { replace ((1 + delta) * (1 - (INR h + 1) * delta))
        with ((1 - INR h * delta) - (INR h + 1) * (delta * delta)) by ring. lra. }
    replace ((1 + delta) * (1 + delta) ^ h * (1 - (INR h + 1) * delta))
      with ((1 + delta) ^ h * ((1 + delta) * (1 - (INR h + 1) * delta))) by ring.
    eapply Rle_trans; [|exact IH].
    apply Rmult_le_compat_l; [exact P|exact E].
Qed.

(** ** Products left to right: a chain of multiplications, each with relative error delta
    when its precondition holds (no underflow). *)
Section Chain.
Variable T : Type.
Variable value : T -> R.
Variable ok : T -> Prop.
Variable mul : T -> T -> T.
Variable pre : T -> T -> Prop.
Variable delta : R.
Hypothesis delta_nonneg : 0 <= delta.
Hypothesis ok_nonneg : forall a, ok a -> 0 <= value a.
Hypothesis mul_ok : forall a b, ok a -> ok b -> pre a b ->
  ok (mul a b) /\ Rabs (value (mul a b) - value a * value b) <= delta * (value a * value b).

Fixpoint chain (acc : T) (fs : list (T * R)) : T :=
  match fs with nil => acc | f :: r => chain (mul acc (fst f)) r end.
Fixpoint chain_exact (x : R) (fs : list (T * R)) : R :=
  match fs with nil => x | f :: r => chain_exact (x * snd f) r end.
Fixpoint chain_pre (acc : T) (fs : list (T * R)) : Prop :=
  match fs with nil => True | f :: r => pre acc (fst f) /\ chain_pre (mul acc (fst f)) r end.
Definition factors_ok (phi : R) (fs : list (T * R)) : Prop :=
  Forall (fun f => ok (fst f) /\ 0 <= snd f /\ Rabs (value (fst f) - snd f) <= phi * snd f) fs.

Lemma mul_step : forall a y x xf K phi, ok a -> ok y -> pre a y -> 0 <= x -> 0 <= xf ->
  0 <= phi -> 1 <= K ->
  Rabs (value a - x) <= (K - 1) * x -> Rabs (value y - xf) <= phi * xf ->
  ok (mul a y) /\
  Rabs (value (mul a y) - x * xf) <= (K * ((1 + phi) * (1 + delta)) - 1) * (x * xf).
Proof.
  intros a y x xf K phi Oa Oy Pr Hx Hxf Hphi HK Ba By.
  destruct (mul_ok a y Oa Oy Pr) as [O B]. split; [exact O|].
  pose proof (ok_nonneg a Oa) as Va. pose proof (ok_nonneg y Oy) as Vy.
  set (va := value a) in *. set (vy := value y) in *.
  assert (Ua : va <= K * x) by (apply abs_le in Ba; lra).
  assert (Uy : vy <= (1 + phi) * xf) by (apply abs_le in By; lra).
  assert (H1 : Rabs ((va - x) * vy) <= (K - 1) * x * ((1 + phi) * xf)).
  { rewrite Rabs_mult, (Rabs_pos_eq vy Vy).
    apply Rmult_le_compat; [apply Rabs_pos|exact Vy|exact Ba|exact Uy]. }
  assert (H2 : Rabs (x * (vy - xf)) <= x * (phi * xf)).
  { rewrite Rabs_mult, (Rabs_pos_eq x Hx). apply Rmult_le_compat_l; [exact Hx|exact By]. }
  assert (H3 : delta * (va * vy) <= delta * ((K * x) * ((1 + phi) * xf))).
  { apply Rmult_le_compat_l; [exact delta_nonneg|].
    apply Rmult_le_compat; [exact Va|exact Vy|exact Ua|exact Uy]. }
  replace (value (mul a y) - x * xf)
    with ((value (mul a y) - va * vy) + ((va - x) * vy + x * (vy - xf))) by (unfold va, vy; ring).
  eapply Rle_trans; [apply Rabs_triang|].
  eapply Rle_trans; [apply Rplus_le_compat; [exact B|apply Rabs_triang]|].
  replace ((K * ((1 + phi) * (1 + delta)) - 1) * (x * xf))
    with (delta * ((K * x) * ((1 + phi) * xf)) + ((K - 1) * x * ((1 + phi) * xf) + x * (phi * xf)))
    by ring.
  lra.
Qed.

Theorem chain_error : forall phi fs acc x K, 0 <= phi -> 1 <= K -> ok acc -> 0 <= x ->
  Rabs (value acc - x) <= (K - 1) * x -> factors_ok phi fs -> chain_pre acc fs ->
  ok (chain acc fs) /\
  Rabs (value (chain acc fs) - chain_exact x fs)
    <= (K * ((1 + phi) * (1 + delta)) ^ length fs - 1) * chain_exact x fs.
Proof.
  intros phi fs. induction fs as [|[y xf] r IH]; intros acc x K Hphi HK Oa Hx Ba Fs Pr.
  - cbn. rewrite Rmult_1_r. split; assumption.
  - inversion Fs as [|f' r' Hf Fr]; subst. cbn [fst snd] in Hf. destruct Hf as (Oy & Hxf & By).
    cbn [chain chain_pre fst snd] in *. destruct Pr as [Pr Prr].
    destruct (mul_step acc y x xf K phi Oa Oy Pr Hx Hxf Hphi HK Ba By) as [O B].
    assert (HK' : 1 <= K * ((1 + phi) * (1 + delta))).
    { rewrite <- (Rmult_1_l 1). apply Rmult_le_compat; try lra.
      rewrite <- (Rmult_1_l 1). apply Rmult_le_compat; lra. }
    destruct (IH (mul acc y) (x * xf) (K * ((1 + phi) * (1 + delta))) Hphi HK' O
                (Rmult_le_pos _ _ Hx Hxf) B Fr Prr) as [O' B'].
    split; [exact O'|]. cbn [chain_exact length pow].
    replace (K * ((1 + phi) * (1 + delta)) * ((1 + phi) * (1 + delta)) ^ length r)
      with (K * ((1 + phi) * (1 + delta) * ((1 + phi) * (1 + delta)) ^ length r)) in B' by ring.
    exact B'.
Qed.

End Chain.

(** ** The four instances the Rust code uses. *)

Definition f64_ok (x : R) : Prop := fmt x /\ 0 <= x.
Definition f64_add (a b : R) : R := rnd (a + b).
Definition f64_mul (a b : R) : R := rnd (a * b).
Definition f64_mul_pre (a b : R) : Prop := bpow radix2 (-1022) <= a * b.

Lemma f64_add_ok : forall a b, f64_ok a -> f64_ok b ->
  f64_ok (f64_add a b) /\ Rabs (f64_add a b - (a + b)) <= u * (a + b).
Proof.
  intros a b [Fa Pa] [Fb Pb]. unfold f64_ok, f64_add.
  split; [split; [apply fmt_rnd|apply rnd_nonneg; lra]|].
  pose proof (add_err a b Fa Fb) as R. rewrite (Rabs_pos_eq (a + b)) in R by lra. exact R.
Qed.

Lemma f64_mul_ok : forall a b, f64_ok a -> f64_ok b -> f64_mul_pre a b ->
  f64_ok (f64_mul a b) /\ Rabs (f64_mul a b - a * b) <= u * (a * b).
Proof.
  intros a b [Fa Pa] [Fb Pb] H. unfold f64_ok, f64_mul, f64_mul_pre in *.
  assert (P : 0 <= a * b) by (apply Rmult_le_pos; assumption).
  split; [split; [apply fmt_rnd|apply rnd_nonneg; exact P]|].
  pose proof (rnd_rel (a * b)) as R. rewrite (Rabs_pos_eq (a * b) P) in R. exact (R H).
Qed.

Lemma dd_delta_nonneg : 0 <= 10 * (u * u).
Proof. unfold u. lra. Qed.
Lemma dd_mul_delta_nonneg : 0 <= 20 * (u * u).
Proof. unfold u. lra. Qed.
Lemma u_nonneg : 0 <= u.
Proof. unfold u. lra. Qed.
Lemma f64_ok_nonneg : forall a, f64_ok a -> 0 <= a.
Proof. intros a [_ P]. exact P. Qed.

(** Double-double sums (Rust [Dd::add]) in any order: relative error
    (1 + rho)(1 + 10u²)^depth − 1 over terms known within rho. *)
Theorem dd_sum_error : forall rho t, 0 <= rho ->
  leaves_ok (R * R) val Inv rho t ->
  Inv (eval _ dd_add t) /\
  Rabs (val (eval _ dd_add t) - exact _ t)
    <= ((1 + rho) * (1 + 10 * (u * u)) ^ depth _ t - 1) * exact _ t.
Proof.
  intros rho t Hr H. apply (tree_error (R * R) val Inv dd_add (10 * (u * u)) dd_delta_nonneg
    dd_add_correct rho t Hr H).
Qed.

(** f64 sums (the pairwise block sums) in any order: (1 + rho)(1 + u)^depth − 1. *)
Theorem f64_sum_error : forall rho t, 0 <= rho ->
  leaves_ok R (fun x => x) f64_ok rho t ->
  f64_ok (eval _ f64_add t) /\
  Rabs (eval _ f64_add t - exact _ t) <= ((1 + rho) * (1 + u) ^ depth _ t - 1) * exact _ t.
Proof.
  intros rho t Hr H.
  apply (tree_error R (fun x => x) f64_ok f64_add u u_nonneg f64_add_ok rho t Hr H).
Qed.

(** Double-double products (Rust [Dd::mul], left to right): each factor within phi, the
    running product within K − 1: (K((1 + phi)(1 + 20u²))^n − 1). *)
Theorem dd_product_error : forall phi fs acc x K, 0 <= phi -> 1 <= K -> Inv acc -> 0 <= x ->
  Rabs (val acc - x) <= (K - 1) * x -> factors_ok (R * R) val Inv phi fs ->
  chain_pre (R * R) dd_mul dd_mul_pre acc fs ->
  Inv (chain _ dd_mul acc fs) /\
  Rabs (val (chain _ dd_mul acc fs) - chain_exact _ x fs)
    <= (K * ((1 + phi) * (1 + 20 * (u * u))) ^ length fs - 1) * chain_exact _ x fs.
Proof.
  intros. apply (chain_error (R * R) val Inv dd_mul dd_mul_pre (20 * (u * u))
    dd_mul_delta_nonneg inv_nonneg dd_mul_bound); assumption.
Qed.

(** f64 products (left to right from 1.0): (K((1 + phi)(1 + u))^n − 1). *)
Theorem f64_product_error : forall phi fs acc x K, 0 <= phi -> 1 <= K -> f64_ok acc -> 0 <= x ->
  Rabs (acc - x) <= (K - 1) * x -> factors_ok R (fun x => x) f64_ok phi fs ->
  chain_pre R f64_mul f64_mul_pre acc fs ->
  f64_ok (chain _ f64_mul acc fs) /\
  Rabs (chain _ f64_mul acc fs - chain_exact _ x fs)
    <= (K * ((1 + phi) * (1 + u)) ^ length fs - 1) * chain_exact _ x fs.
Proof.
  intros. apply (chain_error R (fun x => x) f64_ok f64_mul f64_mul_pre u u_nonneg f64_ok_nonneg
    f64_mul_ok); assumption.
Qed.

(** ** From the sums to D². An error bound relative to the exact sum S becomes one relative to
    the computed sum, which is what the code knows. *)
Lemma to_computed : forall S Sc eps, 0 <= S -> 0 <= eps < 1 -> Rabs (Sc - S) <= eps * S ->
  Rabs (Sc - S) <= eps / (1 - eps) * Sc.
Proof.
  intros S Sc eps HS He B. apply abs_le in B.
  assert (Q : S <= Sc / (1 - eps)).
  { apply Rmult_le_reg_r with (1 - eps); [lra|]. unfold Rdiv.
    rewrite Rmult_assoc, Rinv_l, Rmult_1_r by lra. nra. }
  apply abs_le. unfold Rdiv in *.
  assert (eps * S <= eps * (Sc * / (1 - eps))) by (apply Rmult_le_compat_l; lra).
  replace (eps * / (1 - eps) * Sc) with (eps * (Sc * / (1 - eps))) by ring. lra.
Qed.

(** D² = c0 + c1·S1/N + S2/N² from sums known within E1 and E2, and the f64 [value] of the
    computed combination Vq: the relative error is at most
    (|value − Vq| + |c1|·E1/N + E2/N²) / (|Vq| − |c1|·E1/N − E2/N²). *)
Theorem combine_error : forall c0 c1 n S1 S2 S1c S2c E1 E2 value,
  0 < n -> Rabs (S1c - S1) <= E1 -> Rabs (S2c - S2) <= E2 ->
  let V := c0 + c1 * S1 / n + S2 / (n * n) in
  let Vq := c0 + c1 * S1c / n + S2c / (n * n) in
  let E := Rabs c1 * E1 / n + E2 / (n * n) in
  E < Rabs Vq ->
  Rabs (value - V) / Rabs V <= (Rabs (value - Vq) + E) / (Rabs Vq - E).
Proof.
  intros c0 c1 n S1 S2 S1c S2c E1 E2 value Hn B1 B2 V Vq E HE.
  assert (D : Rabs (Vq - V) <= E).
  { unfold Vq, V, E.
    replace (c0 + c1 * S1c / n + S2c / (n * n) - (c0 + c1 * S1 / n + S2 / (n * n)))
      with (c1 * (S1c - S1) / n + (S2c - S2) / (n * n)) by (field; lra).
    eapply Rle_trans; [apply Rabs_triang|]. unfold Rdiv.
    rewrite !Rabs_mult, !Rabs_inv, (Rabs_pos_eq n), (Rabs_pos_eq (n * n)) by nra.
    apply Rplus_le_compat.
    - rewrite Rmult_assoc, (Rmult_assoc (Rabs c1)). apply Rmult_le_compat_l; [apply Rabs_pos|].
      apply Rmult_le_compat_r; [apply Rlt_le, Rinv_0_lt_compat; lra|exact B1].
    - apply Rmult_le_compat_r; [apply Rlt_le, Rinv_0_lt_compat; nra|exact B2]. }
  assert (LV : Rabs Vq - E <= Rabs V).
  { pose proof (Rabs_triang_inv Vq V). pose proof (Rabs_triang (Vq - V) V).
    replace (Vq - V + V) with Vq in H0 by ring. lra. }
  assert (UV : Rabs (value - V) <= Rabs (value - Vq) + E).
  { replace (value - V) with ((value - Vq) + (Vq - V)) by ring.
    eapply Rle_trans; [apply Rabs_triang|]. lra. }
  assert (P : 0 < Rabs Vq - E) by lra.
  assert (E0 : 0 <= E).
  { pose proof (Rabs_pos (S1c - S1)). pose proof (Rabs_pos (S2c - S2)).
    unfold E, Rdiv. apply Rplus_le_le_0_compat; apply Rmult_le_pos;
      try (apply Rlt_le, Rinv_0_lt_compat; nra); try apply Rmult_le_pos; try apply Rabs_pos; lra. }
  unfold Rdiv. apply Rle_trans with ((Rabs (value - Vq) + E) * / Rabs V).
  - apply Rmult_le_compat_r; [apply Rlt_le, Rinv_0_lt_compat; lra|exact UV].
  - apply Rmult_le_compat_l; [pose proof (Rabs_pos (value - Vq)); pose proof (Rabs_pos Vq); lra|].
    apply Rinv_le_contravar; assumption.
Qed.
