(** * ART's pair law as built: sibling subtrees with one symbol are one map.

    Owen's pair lemma (L2, [Laws.pair_lemma]) needs independent node maps: two inputs that
    first differ at digit [k] then have independent, uniform digits below [k]. In the ART-Owen
    loop ([Art.art]) the pending translations a node hands to its children depend on the node
    alone (its symbol and its own pending translations), not on the digit that chose the child.
    So two children of one node that get the same symbol ([child s a = child s a']) carry the
    same state, and the whole subtrees below them are the same map ([art_shared_child]): inputs
    [pre ++ a :: r] and [pre ++ a' :: r] get the same output digits below [k], for every suffix
    [r], every table, every ψ and every code. Under Owen these digits agree with probability
    [b^-(length r)]; under ART with probability at least that of a shared child symbol, which
    [crates/art/src/pair_law.rs] computes exactly for the grammar as built. *)

From Coq Require Import List Arith Lia.
From Gartowen Require Import Nested Art.
Import ListNotations.

Section ArtPair.

Variable add comb : nat -> nat -> nat.
Variable child : nat -> nat -> nat.
Variable psi : nat -> nat -> nat.
Variable code : nat -> nat -> nat.

(* [Art.art] does not use the section's hypotheses (bijectivity, ranges): only its operations. *)
Local Notation art := (art add comb child psi code).
Local Notation state := (state comb child code).

Lemma art_app : forall pre s F x,
  art s F (pre ++ x) = art s F pre ++ art (fst (state s F pre)) (snd (state s F pre)) x.
Proof. induction pre as [|d r IH]; intros s F x; simpl; auto. f_equal. apply IH. Qed.

Lemma art_length : forall x s F, length (art s F x) = length x.
Proof. induction x as [|d r IH]; intros s F; simpl; auto. Qed.

(** Digit [k]'s node hands the same state to the children of [a] and [a'] when they share a
    symbol: below digit [k] the outputs of [pre ++ a :: r] and [pre ++ a' :: r] agree. *)
Theorem art_shared_child : forall s0 F0 pre a a' r,
  child (fst (state s0 F0 pre)) a = child (fst (state s0 F0 pre)) a' ->
  skipn (S (length pre)) (art s0 F0 (pre ++ a :: r)) =
  skipn (S (length pre)) (art s0 F0 (pre ++ a' :: r)).
Proof.
  intros s0 F0 pre a a' r E. rewrite !art_app.
  assert (Skip : forall l1 l2 : list nat, length l1 = length pre ->
    skipn (S (length pre)) (l1 ++ l2) = skipn 1 l2).
  { intros l1 l2 L. rewrite <- L. clear L. induction l1 as [|x l1 IH]; simpl; auto. }
  rewrite !Skip by apply art_length. simpl. rewrite E. reflexivity.
Qed.

(** And the node at digit [k] itself is one map for both: the outputs agree above [k] and
    differ at [k] exactly as ψ of the node's symbol, translated by one translation, sends [a]
    and [a'] ([Art.art] is nested: [art_is_nested_scramble]). So for inputs whose digits
    below [k] agree, the output digits below [k] agree: ART's pair law differs from Owen's
    whenever the grammar gives two children of a node one symbol. *)
Corollary art_pair_agrees_below : forall s0 F0 pre a a' r j,
  child (fst (state s0 F0 pre)) a = child (fst (state s0 F0 pre)) a' ->
  length pre < j ->
  nth j (art s0 F0 (pre ++ a :: r)) 0 = nth j (art s0 F0 (pre ++ a' :: r)) 0.
Proof.
  intros s0 F0 pre a a' r j E J.
  assert (NS : forall n i (l : list nat), nth (n + i) l 0 = nth i (skipn n l) 0).
  { induction n as [|n IH]; intros i [|x l]; simpl; auto. destruct i; auto. }
  pose proof (art_shared_child s0 F0 pre a a' r E) as Sh.
  replace j with (S (length pre) + (j - S (length pre))) by lia.
  rewrite !NS, Sh. reflexivity.
Qed.

End ArtPair.
