(** * ART as built: the marginal law of one node, whatever the table shares.

    [NodeLaws.art_law q H] is the law of a node that applies ψ drawn from [H] and then an
    independent uniform translation. ART as built is not a tree of such independent nodes:
    every node of one symbol shares that symbol's ψ and code, the grammar has self-loops (a
    node's ancestors can carry its own symbol, so the translations pending at the node can
    depend on its own ψ), art-owen-8p builds codes from ψ's entries, and the per-dimension
    shifts (input [a], output [d]; [crates/art/src/dims.rs]) are what restore uniformity.

    Digit [k] of the output is ψ_s(x_k ⊕ a_k) ⊕ c ⊕ d_k, where s is the node's symbol (fixed by
    the grammar and the input prefix), [c] the node's translation (its pending translations
    and its symbol's code field: ANY function of ψ_s and of the rest of the table) and
    [a_k], [d_k] the digits of the dimension's shifts. [node_law_as_built]: when [d_k] is
    uniform and independent of the table and of [a_k], the node map has exactly the law
    [art_law q (H ∘ τ_a)], ψ's law composed with the input shift and then a uniform
    translation, whatever [c] is. The output shift absorbs the shared, self-looped, reused
    parts ([shift_absorbs]). Marginal laws of each variant follow:

    - [translation_node_law]: ψ the identity (art-owen-2 and art-owen-t1 to -t8): uniform over the
      2^q translations; in base 2 that is all of S_2 ([art_owen_2_node_law]);
    - [q_art_4_node_law]: ψ uniform on GL(2,2) (q-art-4): uniform over S_4, every a;
    - [permutation_node_law]: ψ uniform over a list holding every bijection of the digits
      equally often: uniform over the bijections; [symmetric_node_law]: so with ψ uniform on
      [Symmetric.Sb] (art-owen-8p on S_8, art-owen-16p on S_16), which holds each bijection
      once ([Sb_lists_each_bijection_once]);
    - [affine_node_law]: ψ uniform over the linear bijections (art-owen-m1 … -m8): uniform
      over AGL(q,2), for every q.

    Joint laws across nodes are not covered (ART's nodes of one symbol are dependent), nor the
    partial tail digit (a translation only: [ArtWord.tail_translations_not_symmetric]). *)

From Coq Require Import List Arith Bool Lia.
From Gartowen Require Import Laws ArtWord NodeLaws Symmetric.
Import ListNotations.

Section Node.

Variable q : nat.

Local Notation D := (seq 0 (2 ^ q)).

(** Two maps agree on the digits. *)
Definition agree (f g : nat -> nat) : bool := forallb (fun x => f x =? g x) (seq 0 (2 ^ q)).

Lemma agree_spec : forall f g, agree f g = true <-> (forall x, x < 2 ^ q -> f x = g x).
Proof.
  intros f g. unfold agree. rewrite forallb_forall. split; intros H x Hx.
  - apply Nat.eqb_eq, H, in_seq. lia.
  - apply Nat.eqb_eq, H. apply in_seq in Hx. lia.
Qed.

Lemma digits_nonempty : 0 < 2 ^ q.
Proof. apply Nat.neq_0_lt_0, Nat.pow_nonzero. lia. Qed.

(** [f] and [g] differ by a translation: [f x ⊕ g x] is the same for every digit [x]. *)
Definition differ_by_translation (f g : nat -> nat) : bool :=
  agree (fun x => Nat.lxor (f x) (g x)) (fun _ => Nat.lxor (f 0) (g 0)).

Lemma lxor_solve : forall a d e, Nat.lxor a d = e <-> d = Nat.lxor a e.
Proof.
  intros a d e. split; intro H.
  - subst. rewrite lxor_cancel. reflexivity.
  - subst. apply lxor_cancel.
Qed.

Lemma agree_shift : forall f sigma d,
  agree (fun x => Nat.lxor (f x) d) sigma = true <->
  (forall x, x < 2 ^ q -> d = Nat.lxor (f x) (sigma x)).
Proof.
  intros f sigma d. rewrite agree_spec. split; intros H x Hx; apply lxor_solve; auto.
Qed.

Lemma cnt_false : forall A (l : list A), cnt (fun _ => false) l = 0.
Proof. intros A l. unfold cnt. induction l; simpl; auto. Qed.

(** The output shift absorbs everything: among the [2^q] shift digits, exactly one turns [f]
    into [sigma] when the two differ by a translation, and none otherwise. *)
Lemma shift_absorbs : forall f sigma, maps_digits q f -> maps_digits q sigma ->
  cnt (fun d => agree (fun x => Nat.lxor (f x) d) sigma) D =
  if differ_by_translation f sigma then 1 else 0.
Proof.
  intros f sigma Hf Hs. pose proof digits_nonempty as B.
  destruct (differ_by_translation f sigma) eqn:E.
  - unfold differ_by_translation in E. rewrite agree_spec in E.
    rewrite (cnt_ext _ _ (fun d => d =? Nat.lxor (f 0) (sigma 0))).
    + apply cnt_seq_in. split; [lia|]. simpl. apply lxor_lt; [apply Hf|apply Hs]; lia.
    + intros d _. destruct (Nat.eqb_spec d (Nat.lxor (f 0) (sigma 0))) as [->|N].
      * apply agree_shift. intros x Hx. symmetry. apply E, Hx.
      * destruct (agree _ sigma) eqn:A; [|reflexivity].
        exfalso. apply N. apply (proj1 (agree_shift f sigma d) A 0 B).
  - rewrite (cnt_ext _ _ (fun _ => false)); [apply cnt_false|].
    intros d _. destruct (agree _ sigma) eqn:A; [|reflexivity].
    rewrite agree_shift in A. exfalso.
    assert (T : differ_by_translation f sigma = true).
    { apply agree_spec. intros x Hx. rewrite <- (A x Hx), <- (A 0 B). reflexivity. }
    rewrite T in E. discriminate.
Qed.

(** A constant translation after [f] does not change whether it differs from [sigma] by one. *)
Lemma differ_after_translation : forall f c sigma,
  differ_by_translation (fun x => Nat.lxor (f x) c) sigma = differ_by_translation f sigma.
Proof.
  intros f c sigma.
  assert (K : forall x, Nat.lxor (Nat.lxor (f x) c) (sigma x) =
                        Nat.lxor c (Nat.lxor (f x) (sigma x))).
  { intro x. rewrite (Nat.lxor_comm (f x) c), Nat.lxor_assoc. reflexivity. }
  unfold differ_by_translation.
  destruct (agree (fun x => Nat.lxor (Nat.lxor (f x) c) (sigma x))
                  (fun _ => Nat.lxor (Nat.lxor (f 0) c) (sigma 0))) eqn:E1;
  destruct (agree (fun x => Nat.lxor (f x) (sigma x))
                  (fun _ => Nat.lxor (f 0) (sigma 0))) eqn:E2; auto; exfalso.
  - assert (T : agree (fun x => Nat.lxor (f x) (sigma x))
                      (fun _ => Nat.lxor (f 0) (sigma 0)) = true).
    { apply agree_spec. intros x Hx. pose proof (proj1 (agree_spec _ _) E1 x Hx) as Ex.
      simpl in Ex. rewrite !K in Ex. apply (f_equal (Nat.lxor c)) in Ex.
      rewrite !lxor_cancel in Ex. exact Ex. }
    congruence.
  - assert (T : agree (fun x => Nat.lxor (Nat.lxor (f x) c) (sigma x))
                      (fun _ => Nat.lxor (Nat.lxor (f 0) c) (sigma 0)) = true).
    { apply agree_spec. intros x Hx. rewrite !K. f_equal.
      exact (proj1 (agree_spec _ _) E2 x Hx). }
    congruence.
Qed.

(** The input shift moves digits among the digits. *)
Lemma shifted_maps_digits : forall h a, maps_digits q h -> a < 2 ^ q ->
  maps_digits q (fun x => h (Nat.lxor x a)).
Proof. intros h a Hh Ha x Hx. apply Hh, lxor_lt; assumption. Qed.

(** ** The node law as built *)

(** [psi] ranges over [H] (ψ of the node's symbol), [r] over [rest] (everything else the table
    and the grammar's walk hold), [d] over the digits (the output shift's digit, uniform and
    independent of both). The node map is [x ↦ ψ(x ⊕ a) ⊕ c ψ r ⊕ d] with [c] arbitrary: the
    count of draws giving [sigma] ([node_count]) is [length rest] times the count of [sigma]
    in [art_law q (H ∘ τ_a)], so the node's law is [art_law q (H ∘ τ_a)] exactly. *)
Definition node_count (R : Type) (H : list (nat -> nat)) (rest : list R) (a : nat)
  (c : (nat -> nat) -> R -> nat) (sigma : nat -> nat) : nat :=
  sumL (fun h => sumL (fun r =>
      cnt (fun d => agree (fun x => Nat.lxor (Nat.lxor (h (Nat.lxor x a)) (c h r)) d) sigma) D)
    rest) H.

Theorem node_law_as_built : forall (R : Type) (H : list (nat -> nat)) (rest : list R)
  (a : nat) (c : (nat -> nat) -> R -> nat) (sigma : nat -> nat),
  (forall h, In h H -> maps_digits q h) -> a < 2 ^ q -> (forall h r, c h r < 2 ^ q) ->
  maps_digits q sigma ->
  node_count R H rest a c sigma =
  length rest * cnt (fun g => agree g sigma) (art_law q (map (fun h x => h (Nat.lxor x a)) H)).
Proof.
  intros R H rest a c sigma HH Ha Hc Hs. unfold node_count.
  induction H as [|h H IH]; [unfold art_law, cnt; simpl; lia|].
  unfold art_law in *. simpl. rewrite cnt_app, Nat.mul_add_distr_l.
  rewrite <- IH by (intros; apply HH; right; auto).
  f_equal. rewrite cnt_map.
  assert (Hh : maps_digits q (fun x => h (Nat.lxor x a))).
  { apply shifted_maps_digits; [apply HH; left|]; auto. }
  transitivity (length rest * (if differ_by_translation (fun x => h (Nat.lxor x a)) sigma
                               then 1 else 0)).
  - rewrite <- sumL_const. apply sumL_ext. intros r _.
    rewrite <- (differ_after_translation (fun x => h (Nat.lxor x a)) (c h r)).
    apply (shift_absorbs (fun x => Nat.lxor (h (Nat.lxor x a)) (c h r)) sigma); [|exact Hs].
    intros x Hx. apply lxor_lt; [apply Hh, Hx|apply Hc].
  - f_equal. symmetry. exact (shift_absorbs (fun x => h (Nat.lxor x a)) sigma Hh Hs).
Qed.


(** ** Counting the law [art_law]: a map [sigma] appears once for each ψ in [H] that differs
    from it by a translation. *)

Lemma art_law_count : forall H sigma, (forall h, In h H -> maps_digits q h) ->
  maps_digits q sigma ->
  cnt (fun g => agree g sigma) (art_law q H) = cnt (fun h => differ_by_translation h sigma) H.
Proof.
  intros H sigma HH Hs. induction H as [|h H IH]; [reflexivity|].
  unfold art_law in *. simpl. rewrite cnt_app, cnt_map, cnt_cons.
  rewrite IH by (intros; apply HH; right; auto). f_equal.
  exact (shift_absorbs h sigma (HH h (or_introl eq_refl)) Hs).
Qed.

(** ** ψ uniform over the bijections *)

Definition bijective_on_digits (g : nat -> nat) : Prop :=
  maps_digits q g /\ forall x y, x < 2 ^ q -> y < 2 ^ q -> g x = g y -> x = y.

Lemma lxor_twice : forall x a, Nat.lxor (Nat.lxor x a) a = x.
Proof. intros. rewrite Nat.lxor_assoc, Nat.lxor_nilpotent, Nat.lxor_0_r. reflexivity. Qed.

(** Moving the input shift and the translation to the other side. *)
Lemma agree_moved : forall h sigma a t, a < 2 ^ q ->
  agree (fun x => Nat.lxor (h (Nat.lxor x a)) t) sigma =
  agree h (fun y => Nat.lxor (sigma (Nat.lxor y a)) t).
Proof.
  intros h sigma a t Ha.
  destruct (agree (fun x => Nat.lxor (h (Nat.lxor x a)) t) sigma) eqn:E1;
  destruct (agree h (fun y => Nat.lxor (sigma (Nat.lxor y a)) t)) eqn:E2; auto; exfalso.
  - assert (T : agree h (fun y => Nat.lxor (sigma (Nat.lxor y a)) t) = true).
    { apply agree_spec. intros y Hy.
      pose proof (proj1 (agree_spec _ _) E1 (Nat.lxor y a) (lxor_lt _ _ _ Hy Ha)) as Ey.
      simpl in Ey. rewrite lxor_twice in Ey. rewrite <- Ey, lxor_twice. reflexivity. }
    congruence.
  - assert (T : agree (fun x => Nat.lxor (h (Nat.lxor x a)) t) sigma = true).
    { apply agree_spec. intros x Hx.
      rewrite (proj1 (agree_spec _ _) E2 (Nat.lxor x a) (lxor_lt _ _ _ Hx Ha)).
      rewrite !lxor_twice. reflexivity. }
    congruence.
Qed.

Lemma sumL_swap_cnt : forall A B (P : A -> B -> bool) (l : list A) (m : list B),
  sumL (fun x => cnt (P x) m) l = sumL (fun y => cnt (fun x => P x y) l) m.
Proof.
  intros A B P l m. induction l as [|x l IH]; simpl.
  - induction m as [|y m IHm]; simpl; auto.
  - rewrite IH. clear IH. induction m as [|y m IHm]; simpl; auto.
    rewrite !cnt_cons in *. unfold cnt in *. simpl in *.
    destruct (P x y); simpl; lia.
Qed.

(** When [H] holds every bijection of the digits [K] times, every bijection [sigma] differs
    by a translation from [2^q · K] of the maps [ψ ∘ τ_a]. *)
Theorem permutation_count : forall H K a sigma,
  (forall h, In h H -> maps_digits q h) ->
  (forall g, bijective_on_digits g -> cnt (fun h => agree h g) H = K) ->
  a < 2 ^ q -> bijective_on_digits sigma ->
  cnt (fun h => differ_by_translation (fun x => h (Nat.lxor x a)) sigma) H = 2 ^ q * K.
Proof.
  intros H K a sigma HH HK Ha [Ms Is].
  rewrite <- (Nat.mul_1_r (cnt _ H)), <- sumL_const_if.
  rewrite (sumL_ext _ _ (fun h => cnt (fun t => agree h
                                     (fun y => Nat.lxor (sigma (Nat.lxor y a)) t)) D)).
  - rewrite sumL_swap_cnt, (sumL_ext _ _ (fun _ => K)).
    + rewrite sumL_const, seq_length. reflexivity.
    + intros t Ht. apply in_seq in Ht. apply HK. split.
      * intros y Hy. apply lxor_lt; [apply Ms, lxor_lt|]; lia.
      * intros x y Hx Hy E. apply (f_equal (fun v => Nat.lxor v t)) in E.
        rewrite !lxor_twice in E. apply Is in E; try (apply lxor_lt; lia).
        rewrite <- (lxor_twice x a), E, lxor_twice. reflexivity.
  - intros h Hh. rewrite <- (shift_absorbs (fun x => h (Nat.lxor x a)) sigma).
    + apply cnt_ext. intros t _. apply agree_moved, Ha.
    + apply shifted_maps_digits; auto.
    + exact Ms.
Qed.

(** The node law as built, counted through ψ alone: [sigma] is drawn once per [r] and per ψ
    in [H] with [ψ ∘ τ_a] a translation away from [sigma]. *)
Corollary node_count_by_translation : forall R H rest a c sigma,
  (forall h, In h H -> maps_digits q h) -> a < 2 ^ q -> (forall h r, c h r < 2 ^ q) ->
  maps_digits q sigma ->
  node_count R H rest a c sigma =
  length rest * cnt (fun h => differ_by_translation (fun x => h (Nat.lxor x a)) sigma) H.
Proof.
  intros R H rest a c sigma HH Ha Hc Hs. rewrite node_law_as_built by assumption.
  rewrite art_law_count, cnt_map; [reflexivity| |exact Hs].
  intros g Hg. apply in_map_iff in Hg. destruct Hg as [h [<- Hh]].
  apply shifted_maps_digits; auto.
Qed.

(** Translation variants (ψ the identity: art-owen-2, art-owen-t1 … -t8): each of the [2^q]
    translations is drawn [length rest] times, so the node is uniform over the translations
    (and over nothing else: a map that is no translation is drawn 0 times). *)
Theorem translation_node_law : forall R rest a c e,
  a < 2 ^ q -> e < 2 ^ q -> (forall h r, c h r < 2 ^ q) ->
  node_count R [fun x => x] rest a c (fun x => Nat.lxor x e) = length rest /\
  (forall sigma, maps_digits q sigma -> differ_by_translation (fun x => x) sigma = false ->
     node_count R [fun x => x] rest a c sigma = 0).
Proof.
  intros R rest a c e Ha He Hc.
  assert (Id : forall h, In h [fun x : nat => x] -> maps_digits q h).
  { intros h [<-|[]] x Hx. exact Hx. }
  split.
  - rewrite node_count_by_translation by (auto; intros x Hx; apply lxor_lt; assumption).
    rewrite cnt_cons.
    replace (differ_by_translation _ _) with true; [unfold cnt; simpl; lia|].
    symmetry. apply agree_spec. intros x _.
    rewrite !Nat.lxor_0_l, Nat.lxor_assoc, <- (Nat.lxor_assoc a x e), (Nat.lxor_comm a x),
      Nat.lxor_assoc, lxor_cancel. reflexivity.
  - intros sigma Hs N. rewrite node_count_by_translation by auto.
    rewrite cnt_cons.
    replace (differ_by_translation _ _) with false; [unfold cnt; simpl; lia|].
    symmetry. destruct (differ_by_translation (fun x => Nat.lxor x a) sigma) eqn:E; auto.
    pose proof (differ_after_translation (fun x => x) a sigma) as T. cbv beta in T.
    congruence.
Qed.

(** Permutation variants (ψ uniform over the bijections: art-owen-8p on S_8, art-owen-16p on
    S_16): with [H] holding every bijection [K] times, every bijection is drawn
    [length rest · 2^q · K] times out of [length rest · 2^q · length H]: uniform. *)
Theorem permutation_node_law : forall R H rest K a c sigma,
  (forall h, In h H -> maps_digits q h) ->
  (forall g, bijective_on_digits g -> cnt (fun h => agree h g) H = K) ->
  a < 2 ^ q -> (forall h r, c h r < 2 ^ q) -> bijective_on_digits sigma ->
  node_count R H rest a c sigma = length rest * (2 ^ q * K).
Proof.
  intros R H rest K a c sigma HH HK Ha Hc Hs.
  rewrite node_count_by_translation by (auto; apply Hs).
  rewrite (permutation_count H K a sigma); auto.
Qed.

(** ** ψ uniform over the linear bijections (the matrix variants art-owen-m1 … -m8) *)

Definition linear_on_digits (h : nat -> nat) : Prop :=
  forall x y, x < 2 ^ q -> y < 2 ^ q -> h (Nat.lxor x y) = Nat.lxor (h x) (h y).

Lemma linear_zero : forall h, linear_on_digits h -> h 0 = 0.
Proof.
  intros h Lh. pose proof digits_nonempty as B.
  pose proof (Lh 0 0 B B) as E. rewrite Nat.lxor_0_l in E.
  rewrite Nat.lxor_nilpotent in E. exact E.
Qed.

(** For linear [h] and [ell] and [sigma = τ_{σ(0)} ∘ ell] (an affine map with linear part
    [ell]), [h ∘ τ_a] differs from [sigma] by a translation exactly when [h = ell]. *)
Lemma affine_differ : forall h ell sigma a, linear_on_digits h -> linear_on_digits ell ->
  (forall x, x < 2 ^ q -> sigma x = Nat.lxor (ell x) (sigma 0)) -> a < 2 ^ q ->
  differ_by_translation (fun x => h (Nat.lxor x a)) sigma = agree h ell.
Proof.
  intros h ell sigma a Lh Le Hs Ha. pose proof digits_nonempty as B.
  assert (K : forall x, x < 2 ^ q ->
    Nat.lxor (h (Nat.lxor x a)) (sigma x) =
    Nat.lxor (Nat.lxor (h x) (ell x)) (Nat.lxor (h a) (sigma 0))).
  { intros x Hx. rewrite Lh, Hs by assumption.
    rewrite !Nat.lxor_assoc. f_equal.
    rewrite <- !Nat.lxor_assoc. rewrite (Nat.lxor_comm (h a) (ell x)). reflexivity. }
  unfold differ_by_translation.
  destruct (agree h ell) eqn:E.
  - apply agree_spec. intros x Hx. rewrite (K x Hx), (K 0 B).
    rewrite (proj1 (agree_spec _ _) E x Hx), (proj1 (agree_spec _ _) E 0 B).
    rewrite !Nat.lxor_nilpotent. reflexivity.
  - destruct (agree (fun x => Nat.lxor (h (Nat.lxor x a)) (sigma x))
                    (fun _ => Nat.lxor (h (Nat.lxor 0 a)) (sigma 0))) eqn:F; [|reflexivity].
    exfalso. assert (T : agree h ell = true); [|congruence].
    apply agree_spec. intros x Hx.
    pose proof (proj1 (agree_spec _ _) F x Hx) as Fx. simpl in Fx.
    rewrite (K x Hx), (K 0 B), (linear_zero h Lh), (linear_zero ell Le),
      Nat.lxor_nilpotent, Nat.lxor_0_l in Fx.
    apply (f_equal (fun v => Nat.lxor v (Nat.lxor (h a) (sigma 0)))) in Fx.
    rewrite lxor_twice, Nat.lxor_nilpotent in Fx.
    rewrite <- (lxor_twice (h x) (ell x)), Fx, Nat.lxor_0_l. reflexivity.
Qed.

(** Matrix variants: with [H] linear and holding every linear bijection [K] times, every
    affine bijection is drawn [length rest · K] times out of
    [length rest · 2^q · length H]: uniform over AGL(q,2), the registry's marginal:affine. *)
Theorem affine_node_law : forall R H rest K a c ell sigma,
  (forall h, In h H -> maps_digits q h /\ linear_on_digits h) ->
  (forall g, bijective_on_digits g -> linear_on_digits g -> cnt (fun h => agree h g) H = K) ->
  a < 2 ^ q -> (forall h r, c h r < 2 ^ q) ->
  bijective_on_digits ell -> linear_on_digits ell -> maps_digits q sigma ->
  (forall x, x < 2 ^ q -> sigma x = Nat.lxor (ell x) (sigma 0)) ->
  node_count R H rest a c sigma = length rest * K.
Proof.
  intros R H rest K a c ell sigma HH HK Ha Hc Be Le Ms Hs.
  rewrite node_count_by_translation; auto; [|intros h Hh; apply HH, Hh].
  f_equal. rewrite <- (HK ell Be Le). apply cnt_ext. intros h Hh.
  apply affine_differ; auto. apply HH, Hh.
Qed.

End Node.

(** ** Instances by computation: art-owen-2 and q-art-4 *)

(** art-owen-2 (q = 1, ψ the identity): both permutations of a binary digit are drawn
    [length rest] times, for either input-shift digit: uniform on S_2. *)
Theorem art_owen_2_node_law : forall R (rest : list R) c p a,
  In p (perms [0; 1]) -> a < 2 -> (forall h r, c h r < 2) ->
  node_count 1 R [fun x => x] rest a c (fn_of p) = length rest.
Proof.
  intros R rest c p a Hp Ha Hc.
  assert (T : forallb (fun p => forallb (fun a =>
                 differ_by_translation 1 (fun x => Nat.lxor x a) (fn_of p)) (seq 0 2))
                (perms [0; 1]) = true) by (vm_compute; reflexivity).
  rewrite forallb_forall in T. specialize (T p Hp). rewrite forallb_forall in T.
  specialize (T a (in_seq0 _ _ Ha)).
  rewrite node_count_by_translation; auto.
  - rewrite cnt_cons, T. unfold cnt. simpl. lia.
  - intros h [<-|[]] x Hx. exact Hx.
  - assert (M : forallb (fun p => forallb (fun d => fn_of p d <? 2) (seq 0 2))
                  (perms [0; 1]) = true) by (vm_compute; reflexivity).
    rewrite forallb_forall in M. specialize (M p Hp). rewrite forallb_forall in M.
    intros d Hd. apply Nat.ltb_lt, M, in_seq0, Hd.
Qed.

(** GL(2,2): the six linear bijections of 2-bit digits. *)
Definition lin2 (v1 v2 : nat) : nat -> nat := fun x =>
  Nat.lxor (if Nat.testbit x 0 then v1 else 0) (if Nat.testbit x 1 then v2 else 0).

Definition GL2 : list (nat -> nat) :=
  flat_map (fun v1 => flat_map (fun v2 =>
    if nodupb (map (lin2 v1 v2) (seq 0 4)) then [lin2 v1 v2] else []) (seq 0 4)) (seq 0 4).

(** q-art-4 (ψ uniform on GL(2,2), 6 maps): each of the 24 permutations of a 2-bit digit is
    drawn [length rest] times out of [24 · length rest], for every input-shift digit: the node
    is uniform on S_4, as the registry's marginal:symmetric claim states. *)
Theorem q_art_4_node_law : length GL2 = 6 /\ forall R (rest : list R) c p a,
  In p (perms [0; 1; 2; 3]) -> a < 4 -> (forall h r, c h r < 4) ->
  node_count 2 R GL2 rest a c (fn_of p) = length rest.
Proof.
  split; [vm_compute; reflexivity|].
  intros R rest c p a Hp Ha Hc.
  assert (T : forallb (fun p => forallb (fun a =>
                 cnt (fun h => differ_by_translation 2 (fun x => h (Nat.lxor x a)) (fn_of p)) GL2
                 =? 1) (seq 0 4)) (perms [0; 1; 2; 3]) = true) by (vm_compute; reflexivity).
  rewrite forallb_forall in T. specialize (T p Hp). rewrite forallb_forall in T.
  specialize (T a (in_seq0 _ _ Ha)). apply Nat.eqb_eq in T.
  rewrite node_count_by_translation; auto.
  - rewrite T. lia.
  - assert (M : forallb (fun h => forallb (fun d => h d <? 4) (seq 0 4)) GL2 = true)
      by (vm_compute; reflexivity).
    rewrite forallb_forall in M. intros h Hh d Hd. specialize (M h Hh).
    rewrite forallb_forall in M. apply Nat.ltb_lt, M, in_seq0, Hd.
  - assert (M : forallb (fun p => forallb (fun d => fn_of p d <? 4) (seq 0 4))
                  (perms [0; 1; 2; 3]) = true) by (vm_compute; reflexivity).
    rewrite forallb_forall in M. specialize (M p Hp). rewrite forallb_forall in M.
    intros d Hd. apply Nat.ltb_lt, M, in_seq0, Hd.
Qed.

(** ** The list [Symmetric.Sb] holds every bijection of the digits once

    So [permutation_node_law] applies to ψ drawn uniformly from S_b with [K = 1]: the
    hypothesis is met by the uniform law itself, not only assumed. *)

Lemma leqb_eq : forall t u, leqb t u = true <-> t = u.
Proof.
  induction t as [|x t IH]; intros [|y u]; simpl.
  - split; auto.
  - split; discriminate.
  - split; discriminate.
  - rewrite andb_true_iff, Nat.eqb_eq, IH. split.
    + intros [-> ->]. reflexivity.
    + intro E. injection E as -> ->. split; reflexivity.
Qed.

Lemma tuples_in_length : forall k L t, In t (tuples nat k L) -> length t = k.
Proof.
  induction k as [|k IH]; intros L t H; simpl in H.
  - destruct H as [<-|[]]. reflexivity.
  - apply in_flat_map in H as [x [_ Hx]]. apply in_map_iff in Hx as [t' [<- Ht']].
    simpl. f_equal. apply (IH L), Ht'.
Qed.

(** Exactly one tuple of length [k] over the digits below [n] equals a given one. *)
Lemma tuples_exact : forall n k u, length u = k -> (forall x, In x u -> x < n) ->
  cnt (fun t => leqb t u) (tuples nat k (seq 0 n)) = 1.
Proof.
  intros n. induction k as [|k IH]; intros u Lu Hu.
  - destruct u; [reflexivity|discriminate].
  - destruct u as [|x u]; [discriminate|]. simpl tuples. rewrite cnt_flat_map.
    rewrite (sumL_ext _ _ (fun y => if y =? x then 1 else 0)).
    + rewrite sumL_const_if, Nat.mul_1_r. apply cnt_seq_in.
      split; [lia|]. simpl. apply Hu. left. reflexivity.
    + intros y _. rewrite cnt_map. cbn [leqb]. rewrite cnt_and_const.
      destruct (y =? x); [|reflexivity]. apply IH.
      * simpl in Lu. lia.
      * intros z Hz. apply Hu. right. exact Hz.
Qed.

Lemma NoDup_map_on : forall (g : nat -> nat) l,
  (forall x y, In x l -> In y l -> g x = g y -> x = y) -> NoDup l -> NoDup (map g l).
Proof.
  intros g l Ig Nl. revert Ig. induction Nl as [|x l Nx Nl IH]; intro Ig; simpl; constructor.
  - intro Hx. apply in_map_iff in Hx as [y [E Hy]].
    assert (y = x) as -> by (apply Ig; [right; exact Hy|left; reflexivity|exact E]).
    contradiction.
  - apply IH. intros y z Hy Hz. apply Ig; right; assumption.
Qed.

Theorem Sb_lists_each_bijection_once : forall n g,
  (forall x, x < n -> g x < n) -> (forall x y, x < n -> y < n -> g x = g y -> x = y) ->
  cnt (fun h => forallb (fun x => h x =? g x) (seq 0 n)) (Sb n) = 1.
Proof.
  intros n g Mg Ig. unfold Sb, tables. rewrite cnt_map, cnt_filter.
  set (u := map g (seq 0 n)).
  assert (Tu : is_table n u = true).
  { apply is_table_spec. split; [unfold u; rewrite map_length, seq_length; reflexivity|].
    split.
    - intros x Hx. unfold u in Hx. apply in_map_iff in Hx as [y [<- Hy]].
      apply in_seq in Hy. apply Mg. lia.
    - apply NoDup_map_on; [|apply seq_NoDup].
      intros x y Hx Hy. apply in_seq in Hx, Hy. apply Ig; lia. }
  rewrite <- (tuples_exact n n u); [|unfold u; rewrite map_length, seq_length; reflexivity|].
  - apply cnt_ext. intros t Ht. apply tuples_in_length in Ht.
    destruct (leqb t u) eqn:E.
    + apply leqb_eq in E. subst t. rewrite Tu. simpl. apply forallb_forall.
      intros x Hx. apply in_seq in Hx. apply Nat.eqb_eq. unfold u.
      apply (fn_of_table n g x). lia.
    + destruct (is_table n t && _) eqn:F; [|reflexivity]. exfalso.
      apply andb_true_iff in F as [_ F]. rewrite forallb_forall in F.
      assert (t = u) as ->; [|rewrite (proj2 (leqb_eq u u) eq_refl) in E; discriminate].
      apply (nth_ext t u 0 0); [unfold u; rewrite map_length, seq_length; exact Ht|].
      intros x Hx. rewrite Ht in Hx. unfold u. transitivity (g x).
      * apply Nat.eqb_eq, F, in_seq. lia.
      * symmetry. exact (fn_of_table n g x Hx).
  - intros x Hx. unfold u in Hx. apply in_map_iff in Hx as [y [<- Hy]].
    apply in_seq in Hy. apply Mg. lia.
Qed.

(** art-owen-8p and -16p with ψ uniform on S_8 and S_16 ([Sb]): every bijection of the
    digits is drawn [length rest · 2^q] times, for every q. *)
Corollary symmetric_node_law : forall q R (rest : list R) a c sigma,
  a < 2 ^ q -> (forall h r, c h r < 2 ^ q) -> bijective_on_digits q sigma ->
  node_count q R (Sb (2 ^ q)) rest a c sigma = length rest * (2 ^ q * 1).
Proof.
  intros q R rest a c sigma Ha Hc Hs. apply (permutation_node_law q); auto.
  - intros h Hh. unfold Sb in Hh. apply in_map_iff in Hh as [t [<- Ht]].
    unfold tables in Ht. apply filter_In in Ht as [_ Ht]. apply is_table_spec in Ht.
    destruct Ht as [Lt [Et _]]. intros d Hd. apply Et, nth_In. lia.
  - intros g [Mg Ig]. apply Sb_lists_each_bijection_once; auto.
Qed.
