(** * The running histogram on a binary trie, equal to the function-map [Boxes.scan].

    [Boxes.scan] keeps its histogram as a function, so each lookup in the extracted code walks
    every earlier update: quadratic in the number of points. [scan_map] keeps it in Coq's
    [PositiveMap] (a binary trie, logarithmic lookups) and returns exactly what [scan] returns
    ([scan_map_empty]), so every theorem about [scan] holds for it. The re-checker of
    [Witness.v] uses it on sets of 2^16 points. *)

From Coq Require Import List Arith Lia PArith FMapPositive.
Import ListNotations.
From Gartowen Require Import Boxes.

(** The binary number [m ≥ 1] as a [positive], by halving: logarithmic in the extracted code
    (unlike [Pos.of_succ_nat], which counts up). [fuel ≥ m] suffices. *)
Fixpoint bin (fuel m : nat) : positive :=
  match fuel with
  | 0 => xH
  | S f =>
      if m <=? 1 then xH
      else if m mod 2 =? 0 then xO (bin f (m / 2)) else xI (bin f (m / 2))
  end.

Lemma bin_spec : forall fuel m, 1 <= m <= fuel -> Pos.to_nat (bin fuel m) = m.
Proof.
  induction fuel as [|f IH]; intros m [M1 M2]; [lia|].
  change (bin (S f) m) with
    (if m <=? 1 then xH else if m mod 2 =? 0 then xO (bin f (m / 2)) else xI (bin f (m / 2))).
  destruct (m <=? 1) eqn:E; [apply Nat.leb_le in E; rewrite Pos2Nat.inj_1; lia|]. apply Nat.leb_gt in E.
  pose proof (Nat.div_mod m 2 ltac:(lia)) as D. pose proof (Nat.mod_upper_bound m 2 ltac:(lia)).
  assert (1 <= m / 2 <= f).
  { split; [apply Nat.div_le_lower_bound; lia | apply Nat.div_le_upper_bound; lia]. }
  destruct (m mod 2 =? 0) eqn:P; [apply Nat.eqb_eq in P | apply Nat.eqb_neq in P].
  - rewrite Pos2Nat.inj_xO. rewrite IH by lia. lia.
  - rewrite Pos2Nat.inj_xI. rewrite IH by lia. lia.
Qed.

(** The trie key of a histogram key [k]: the positive [k + 1]. *)
Definition pkey (k : nat) : positive := bin (S k) (S k).

Lemma pkey_inj : forall k k', pkey k = pkey k' -> k = k'.
Proof.
  intros k k' E. assert (Pos.to_nat (pkey k) = Pos.to_nat (pkey k')) as H by congruence.
  unfold pkey in H. rewrite !bin_spec in H by lia. lia.
Qed.

Section ScanMap.

Variables (A : Type) (kf : A -> nat) (T : nat).

(** A key's count in the trie (absent = 0). *)
Definition get (h : PositiveMap.t nat) (k : nat) : nat :=
  match PositiveMap.find (pkey k) h with Some c => c | None => 0 end.

(** [Boxes.scan] with the histogram in the trie. *)
Fixpoint scan_map (h : PositiveMap.t nat) (l : list A) : option A :=
  match l with
  | [] => None
  | x :: r =>
      let k := kf x in
      let c := get h k in
      if T <? c + 1 then Some x else scan_map (PositiveMap.add (pkey k) (c + 1) h) r
  end.

Lemma scan_map_scan : forall l h f, (forall k, get h k = f k) ->
  scan_map h l = scan A kf T f l.
Proof.
  induction l as [|x r IH]; intros h f H; simpl; auto.
  rewrite !H. destruct (T <? f (kf x) + 1); auto. apply IH. intro k. unfold get.
  destruct (k =? kf x) eqn:E.
  - apply Nat.eqb_eq in E. subst. rewrite PositiveMap.gss. reflexivity.
  - apply Nat.eqb_neq in E. rewrite PositiveMap.gso by (intro P; apply pkey_inj in P; auto).
    apply H.
Qed.

(** From the empty trie, [scan_map] is [scan] from the zero histogram. *)
Theorem scan_map_empty : forall l,
  scan_map (PositiveMap.empty nat) l = scan A kf T (fun _ => 0) l.
Proof.
  intro l. apply scan_map_scan. intro k. unfold get. rewrite PositiveMap.gempty. reflexivity.
Qed.

End ScanMap.
