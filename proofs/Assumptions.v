(** Every main theorem must be closed under the global context (no axioms, no admits). *)
From Gartowen Require Import Nested Factor Counterexample Art ArtWord Binary.

Print Assumptions factorization.
Print Assumptions factorization_unique.
Print Assumptions factorization_bijective.
Print Assumptions factorization_gf2.
Print Assumptions count_factorization.
Print Assumptions agl22_is_s4.
Print Assumptions prefix_class_image.
Print Assumptions prefix_class_onto.
Print Assumptions count_scrambled.
Print Assumptions net_preserved.
Print Assumptions sequence_preserved.
Print Assumptions art_is_nested_scramble.
Print Assumptions art_preserves_nets.
Print Assumptions art_word_is_nested.
Print Assumptions art_word_injective.
Print Assumptions tail_one_bit_is_symmetric.
Print Assumptions tail_translations_not_symmetric.
Print Assumptions binary_is_base_2q_nested.
Print Assumptions base4_scramble_breaks_binary_net.
