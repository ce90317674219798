(** Every main theorem must be closed under the global context (no axioms, no admits), except
    the floating-point theorems of [Float.v], whose real numbers rest on the standard axioms of
    Coq's classical reals (listed in README.md; check.sh allows exactly those). *)
From Gartowen Require Import Nested Boxes Checker NetMonotone Factor Counterexample Art ArtWord Binary Laws Symmetric NodeLaws ArtMarginal.

Print Assumptions factorization_unique.
Print Assumptions factorization_bijective.
Print Assumptions output_uniform.
Print Assumptions pair_lemma.
Print Assumptions Sb_transitive.
Print Assumptions Sb_two_transitive.
Print Assumptions symmetric_pair_lemma.
Print Assumptions Sb_sizes_3_4.
Print Assumptions art_law_transitive.
Print Assumptions art_output_uniform.
Print Assumptions s4_two_transitive.
Print Assumptions agl3_two_transitive.
Print Assumptions translations_not_two_transitive.
Print Assumptions affine_is_symmetric_q1.
Print Assumptions affine_is_symmetric_q2.
Print Assumptions transposition_not_affine.
Print Assumptions shift_absorbs.
Print Assumptions node_law_as_built.
Print Assumptions node_count_by_translation.
Print Assumptions translation_node_law.
Print Assumptions permutation_node_law.
Print Assumptions affine_node_law.
Print Assumptions art_owen_2_node_law.
Print Assumptions q_art_4_node_law.
Print Assumptions Sb_lists_each_bijection_once.
Print Assumptions symmetric_node_law.
Print Assumptions prefix_class_image.
Print Assumptions prefix_class_onto.
Print Assumptions count_scrambled.
Print Assumptions net_preserved.
Print Assumptions sequence_preserved.
Print Assumptions net_monotone.
Print Assumptions pigeonhole.
Print Assumptions key_eq_iff.
Print Assumptions In_comps.
Print Assumptions level_any_none.
Print Assumptions check_level_correct.
Print Assumptions check_net_correct.
Print Assumptions t_value_correct.
Print Assumptions t_value_threshold.
Print Assumptions check_sequence_correct.
Print Assumptions check_sequence_is_sequence.
Print Assumptions net_monotone_le.
Print Assumptions art_is_nested_scramble.
Print Assumptions art_preserves_nets.
Print Assumptions art_word_is_nested.
Print Assumptions art_word_injective.
Print Assumptions tail_one_bit_is_symmetric.
Print Assumptions tail_translations_not_symmetric.
Print Assumptions binary_is_base_2q_nested.
Print Assumptions base4_scramble_breaks_binary_net.
