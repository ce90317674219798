(** * T5: nested scrambling in base 4 need not preserve binary nets: an explicit base-4 nested
    scramble and a binary (0,2,2)-net whose image is not a binary (0,2,2)-net. *)

From Coq Require Import List Arith Bool Lia.
From Gartowen Require Import Nested.
Import ListNotations.

(** The root permutation 0 ↦ 0, 3 ↦ 1, 1 ↦ 2, 2 ↦ 3 of base-4 digits; identity below the root. *)
Definition perm4 (d : nat) : nat := match d with 1 => 2 | 2 => 3 | 3 => 1 | _ => d end.
Definition perm4_inv (d : nat) : nat := match d with 1 => 3 | 2 => 1 | 3 => 2 | _ => d end.
Definition root_sigma (p : list nat) (d : nat) : nat := match p with [] => perm4 d | _ => d end.
Definition root_tau (p : list nat) (d : nat) : nat := match p with [] => perm4_inv d | _ => d end.

Ltac digit4 := intros p d H; destruct p; do 4 (destruct d as [|d]; [simpl; lia|]); lia.

Definition S4 : nested_scramble 4.
Proof.
  refine {| sigma := root_sigma; tau := root_tau |}; digit4.
Defined.

Definition Id4 : nested_scramble 4.
Proof.
  refine {| sigma := fun _ d => d; tau := fun _ d => d |}; intros; auto.
Defined.

(** Scramble the first coordinate only. *)
Definition scramblers (j : nat) : nested_scramble 4 := match j with 0 => S4 | _ => Id4 end.

(** Four points, one base-4 digit per coordinate: (0,0), (2,2), (1,3), (3,1). *)
Definition net4 : list (list (list nat)) := [[[0]; [0]]; [[2]; [2]]; [[1]; [3]]; [[3]; [1]]].

(** The binary view: base-4 digit d is the two bits d / 2, d mod 2. *)
Definition to_bits (x : list nat) : list nat := flat_map (fun d => [d / 2; d mod 2]) x.
Definition binary (Ps : list (list (list nat))) := map (map to_bits) Ps.

Definition prefixes2 : list (list nat) := [[]; [0]; [1]; [0; 0]; [0; 1]; [1; 0]; [1; 1]].

Lemma small_prefix : forall p, valid 2 p -> length p <= 2 -> In p prefixes2.
Proof.
  intros p Hv Hl. unfold valid in Hv.
  destruct p as [|a [|c [|e r]]]; simpl in Hl; try lia;
    repeat match goal with H : Forall _ (_ :: _) |- _ => inversion H; subst; clear H end;
    repeat match goal with H : ?x < 2 |- _ => destruct x as [|[|?]]; [| | lia]; clear H end;
    unfold prefixes2; simpl; repeat (first [left; reflexivity | right]).
Qed.

(** Every box of two binary prefixes with lengths summing to 2 holds exactly [c] points. *)
Definition boxes_hold (Ps : list (list (list nat))) (c : nat) : bool :=
  forallb (fun p1 => forallb (fun p2 =>
    if length p1 + length p2 =? 2 then count [p1; p2] Ps =? c else true) prefixes2) prefixes2.

Lemma boxes_hold_net : forall Ps,
  length Ps = 4 -> Forall (well_formed 2 2 2) Ps -> boxes_hold Ps 1 = true -> is_net 2 2 2 0 2 Ps.
Proof.
  intros Ps Hlen Hwf Hb. split; [exact Hlen|]. split; [exact Hwf|].
  intros B HlB HvB HnB Hsum.
  destruct B as [|p1 [|p2 [|p3 B]]]; simpl in HlB; try discriminate.
  inversion HvB as [|? ? Hv1 Hv']; inversion Hv' as [|? ? Hv2 _]; subst.
  inversion HnB as [|? ? Hn1 Hn']; inversion Hn' as [|? ? Hn2 _]; subst.
  unfold boxes_hold in Hb. rewrite forallb_forall in Hb.
  specialize (Hb p1 (small_prefix p1 Hv1 Hn1)). rewrite forallb_forall in Hb.
  specialize (Hb p2 (small_prefix p2 Hv2 Hn2)).
  simpl in Hsum. rewrite Nat.add_0_r in Hsum. rewrite Hsum in Hb. simpl in Hb.
  apply Nat.eqb_eq in Hb. exact Hb.
Qed.

Lemma net_before : is_net 2 2 2 0 2 (binary net4).
Proof.
  apply boxes_hold_net.
  - reflexivity.
  - repeat constructor; simpl; lia.
  - vm_compute. reflexivity.
Qed.

Lemma not_net_after : ~ is_net 2 2 2 0 2 (binary (map (scr_from 4 scramblers 0) net4)).
Proof.
  intros [_ [_ H]].
  (* The box [0, 1/2) × [0, 1/2) now holds two points: (00, 00) and (01, 01). *)
  specialize (H [[0]; [0]]). vm_compute in H.
  assert (C : 2 = 1) by (apply H; auto; repeat constructor; lia). discriminate.
Qed.

Theorem base4_scramble_breaks_binary_net :
  exists Ss : nat -> nested_scramble 4,
    is_net 2 2 2 0 2 (binary net4) /\ ~ is_net 2 2 2 0 2 (binary (map (scr_from 4 Ss 0) net4)).
Proof. exists scramblers. split; [apply net_before | apply not_net_after]. Qed.
