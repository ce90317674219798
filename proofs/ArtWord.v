(** * T3 with the real pieces: the Rust ART-Owen loop on W-bit words.

    The loop of [crates/art/src/engine/mod.rs] ([run_from]): a word of [W] bits is [W / q] full
    digits of [q] bits, most significant first, and a partial tail digit of [r = W mod q < q]
    bits (the lowest bits). Each symbol has one 64-bit translation code, top-aligned; field [j]
    of it (bits 64 − q(j+1) .. 64 − qj, zeros below bit 0) lands on the digit [j] levels below the
    symbol's node, and fields that fall past the word are never read: this is the truncation of
    the codes to the word. A full digit gets ψ of its node's symbol, then the translation; the
    tail digit gets the top [r] bits of its translation only.

    [art_loop] is that loop on digit lists; [art_word] adds the word <-> digits glue and is what
    [Extract.v] extracts to OCaml for the differential test against the Rust code. *)

From Coq Require Import List Arith NArith Lia.
From Gartowen Require Import Nested Art.
Import ListNotations.

Lemma lxor_lt : forall q a b, a < 2 ^ q -> b < 2 ^ q -> Nat.lxor a b < 2 ^ q.
Proof.
  intros q a b Ha Hb.
  destruct (Nat.eq_dec (Nat.lxor a b) 0) as [E|E].
  { rewrite E. apply Nat.neq_0_lt_0, Nat.pow_nonzero. lia. }
  destruct q as [|q'].
  { simpl in *. assert (a = 0) by lia. assert (b = 0) by lia. subst. vm_compute in E. lia. }
  apply Nat.log2_lt_pow2; [lia|].
  eapply Nat.le_lt_trans; [apply Nat.log2_lxor|].
  apply Nat.max_lub_lt.
  - destruct (Nat.eq_dec a 0) as [->|Na]; [change (Nat.log2 0) with 0; lia|].
    rewrite <- Nat.log2_lt_pow2 by lia. exact Ha.
  - destruct (Nat.eq_dec b 0) as [->|Nb]; [change (Nat.log2 0) with 0; lia|].
    rewrite <- Nat.log2_lt_pow2 by lia. exact Hb.
Qed.

Lemma shiftr_lt : forall q r a, r <= q -> a < 2 ^ q -> Nat.shiftr a (q - r) < 2 ^ r.
Proof.
  intros q r a Hr Ha. rewrite Nat.shiftr_div_pow2.
  apply Nat.div_lt_upper_bound; [apply Nat.pow_nonzero; lia|].
  rewrite <- Nat.pow_add_r. replace (q - r + r) with q by lia. exact Ha.
Qed.

Section Word.

(** [q] bits per full digit, [r < q] bits in the tail digit (0: no tail). *)
Variable q r : nat.
Hypothesis r_lt_q : r < q.

(** The grammar as a child function on symbols (any function), ψ tables that are bijections of
    the [2^q] digits, and codes given by their [q]-bit fields. *)
Variable child : nat -> nat -> nat.
Variable psi psi_inv : nat -> nat -> nat.
Hypothesis psi_lt : forall s d, d < 2 ^ q -> psi s d < 2 ^ q.
Hypothesis psi_inv_lt : forall s d, d < 2 ^ q -> psi_inv s d < 2 ^ q.
Hypothesis psi_inv_psi : forall s d, d < 2 ^ q -> psi_inv s (psi s d) = d.
Hypothesis psi_psi_inv : forall s d, d < 2 ^ q -> psi s (psi_inv s d) = d.
Variable code : nat -> nat -> nat.
Hypothesis code_lt : forall s j, code s j < 2 ^ q.

(** The loop: [F j] is the translation pending for the digit [j] levels below. *)
Fixpoint art_loop (s : nat) (F : nat -> nat) (x : list nat) (t : nat) : list nat * nat :=
  let F' := fun j => Nat.lxor (F j) (code s j) in
  match x with
  | [] => ([], Nat.lxor t (Nat.shiftr (F' 0) (q - r)))
  | d :: rest =>
      let (ys, yt) := art_loop (child s d) (fun j => F' (S j)) rest t in
      (Nat.lxor (psi s d) (F' 0) :: ys, yt)
  end.

Definition F_ok (F : nat -> nat) : Prop := forall j, F j < 2 ^ q.

(** The translation of a digit: ⊕ on q-bit digits ([mod] only makes the map total). *)
Definition tr (d u : nat) : nat := Nat.lxor d (u mod 2 ^ q).

Lemma mod_lt_q : forall u, u mod 2 ^ q < 2 ^ q.
Proof. intro u. apply Nat.mod_upper_bound, Nat.pow_nonzero. lia. Qed.

Lemma tr_lt : forall d u, d < 2 ^ q -> tr d u < 2 ^ q.
Proof. intros. apply lxor_lt; [assumption|apply mod_lt_q]. Qed.

Lemma tr_tr : forall d u, tr (tr d u) u = d.
Proof.
  intros. unfold tr. rewrite Nat.lxor_assoc, Nat.lxor_nilpotent, Nat.lxor_0_r. reflexivity.
Qed.

(** The digit-level part is Art.v's loop with ⊕ for translations. *)
Definition art_scramble_q (s0 : nat) (F0 : nat -> nat) : nested_scramble (2 ^ q) :=
  art_scramble (2 ^ q) tr tr Nat.lxor tr_lt tr_lt (fun d u _ => tr_tr d u) (fun d u _ => tr_tr d u)
    child psi psi_inv psi_lt psi_inv_lt psi_inv_psi psi_psi_inv code s0 F0.

(** The tail's translation: the top [r] bits of the pending translation after the full digits. *)
Definition tail_shift (s0 : nat) (F0 : nat -> nat) (x : list nat) : nat :=
  let st := state Nat.lxor child code s0 F0 x in
  Nat.shiftr (Nat.lxor (snd st 0) (code (fst st) 0)) (q - r).

Lemma F_ok_step : forall s F, F_ok F -> F_ok (fun j => Nat.lxor (F (S j)) (code s (S j))).
Proof. intros s F H j. apply lxor_lt; auto. Qed.

Lemma state_ok : forall x s F, F_ok F -> F_ok (snd (state Nat.lxor child code s F x)).
Proof.
  induction x as [|d rest IH]; intros s F H; simpl; [assumption|].
  apply IH, F_ok_step, H.
Qed.

Lemma art_loop_eq : forall x s F t, F_ok F ->
  art_loop s F x t = (art tr Nat.lxor child psi code s F x, Nat.lxor t (tail_shift s F x)).
Proof.
  induction x as [|d rest IH]; intros s F t H.
  - reflexivity.
  - cbn [art_loop art]. rewrite IH by (apply F_ok_step, H). unfold tr.
    rewrite (Nat.mod_small (Nat.lxor (F 0) (code s 0))) by (apply lxor_lt; auto). reflexivity.
Qed.

(** T3 (real pieces): for any grammar, ψ tables, codes and root, and any start translations
    below [2^q], the loop maps the full digits by the nested scramble [art_scramble_q] (each
    node: ψ of its symbol, then a translation) and the tail digit by a translation that depends
    only on the full digits above it: a nested scramble of the mixed-radix tree whose last level
    has [2^r] symbols and translation-only nodes. The tail stays below [2^r]. *)
Theorem art_word_is_nested : forall s0 F0 x t, F_ok F0 ->
  art_loop s0 F0 x (t : nat) =
    (scramble (2 ^ q) (art_scramble_q s0 F0) x, Nat.lxor t (tail_shift s0 F0 x)) /\
  tail_shift s0 F0 x < 2 ^ r.
Proof.
  intros s0 F0 x t H. split.
  - rewrite art_loop_eq by exact H. f_equal.
    exact (art_is_nested_scramble (2 ^ q) tr tr Nat.lxor tr_lt tr_lt (fun d u _ => tr_tr d u)
             (fun d u _ => tr_tr d u) child psi psi_inv psi_lt psi_inv_lt psi_inv_psi psi_psi_inv
             code s0 F0 x).
  - unfold tail_shift. apply shiftr_lt; [lia|].
    apply lxor_lt; [apply state_ok, H|apply code_lt].
Qed.

(** Hence the word map is a bijection: two valid inputs of one length with tails below [2^r]
    that give the same output are equal. *)
Theorem art_word_injective : forall s0 F0 x x' t t', F_ok F0 ->
  valid (2 ^ q) x -> valid (2 ^ q) x' -> length x = length x' ->
  art_loop s0 F0 x t = art_loop s0 F0 x' t' -> x = x' /\ t = t'.
Proof.
  intros s0 F0 x x' t t' H Vx Vx' L E.
  destruct (art_word_is_nested s0 F0 x t H) as [Ex _].
  destruct (art_word_is_nested s0 F0 x' t' H) as [Ex' _].
  rewrite Ex, Ex' in E. injection E as Es Et.
  assert (Xeq : x = x').
  { rewrite <- (unact_act _ (art_scramble_q s0 F0) x [] Vx),
            <- (unact_act _ (art_scramble_q s0 F0) x' [] Vx').
    unfold scramble in Es. rewrite Es. reflexivity. }
  subst x'. split; [reflexivity|].
  apply (f_equal (fun v => Nat.lxor v (tail_shift s0 F0 x))) in Et.
  rewrite !Nat.lxor_assoc, Nat.lxor_nilpotent, !Nat.lxor_0_r in Et. exact Et.
Qed.

End Word.

(** What the tail does to the law: its node maps are translations, a group of order [2^r].
    For [r = 1] that is every permutation of the two symbols, so the tail keeps Owen's law;
    for [r >= 2] it is not: the swap of 0 and 1 is no translation. *)
Theorem tail_one_bit_is_symmetric : forall f : nat -> nat,
  f 0 < 2 -> f 1 < 2 -> f 0 <> f 1 -> exists c, forall t, t < 2 -> f t = Nat.lxor t c.
Proof.
  intros f H0 H1 N. exists (f 0). intros t Ht.
  destruct t as [|[|t]]; [rewrite Nat.lxor_0_l; reflexivity| |lia].
  destruct (f 0) as [|[|]] eqn:E0; destruct (f 1) as [|[|]] eqn:E1; try lia; reflexivity.
Qed.

Definition swap01 (t : nat) : nat := if t =? 0 then 1 else if t =? 1 then 0 else t.

Theorem tail_translations_not_symmetric : forall r, 2 <= r ->
  ~ exists c, forall t, t < 2 ^ r -> swap01 t = Nat.lxor t c.
Proof.
  intros r Hr [c Hc].
  assert (P : 4 <= 2 ^ r) by (replace 4 with (2 ^ 2) by reflexivity; apply Nat.pow_le_mono_r; lia).
  pose proof (Hc 0 ltac:(lia)) as E0. rewrite Nat.lxor_0_l in E0. simpl in E0. subst c.
  pose proof (Hc 2 ltac:(lia)) as E2. vm_compute in E2. discriminate.
Qed.

(** ** The word glue (extracted with the loop; the differential test exercises it) *)

(** Digit [k] of a [W]-bit word (most significant first) and the tail digit. *)
Definition digit_at (q W k : nat) (x : N) : nat :=
  N.to_nat (N.land (N.shiftr x (N.of_nat (W - q * S k))) (N.ones (N.of_nat q))).
Definition word_digits (q W : nat) (x : N) : list nat :=
  map (fun k => digit_at q W k x) (seq 0 (W / q)).
Definition word_tail (q W : nat) (x : N) : nat :=
  N.to_nat (N.land x (N.ones (N.of_nat (W mod q)))).
Definition join (q r : nat) (ys : list nat) (yt : nat) : N :=
  N.lor (N.shiftl (fold_left (fun acc d => N.lor (N.shiftl acc (N.of_nat q)) (N.of_nat d)) ys 0%N)
                  (N.of_nat r)) (N.of_nat yt).

(** Field [j] of a top-aligned 64-bit code: bits 64 − q(j+1) .. 64 − qj, zeros below bit 0. *)
Definition code_field (q : nat) (c : N) (j : nat) : nat :=
  N.to_nat (N.land (N.shiftr (N.shiftl c (N.of_nat (q * S j))) 64) (N.ones (N.of_nat q))).

(** The ART-Owen scramble of a [W]-bit word from symbol [root], as [run_from] computes it. *)
Definition art_word (q W : nat) (child psi : nat -> nat -> nat) (code64 : nat -> N) (root : nat)
  (x : N) : N :=
  let '(ys, yt) := art_loop q (W mod q) child psi (fun s => code_field q (code64 s)) root
                     (fun _ => 0) (word_digits q W x) (word_tail q W x) in
  join q (W mod q) ys yt.
