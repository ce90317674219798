(** The floating-point theorems and the discrepancy closed forms rest on Coq's classical real
    numbers (which Flocq uses too): their
    [Print Assumptions] may list exactly the four standard axioms that check.sh allows
    (ClassicalDedekindReals.sig_forall_dec, ClassicalDedekindReals.sig_not_dec,
    FunctionalExtensionality.functional_extensionality_dep, Classical_Prop.classic). *)
From Gartowen Require Import Float DdSum Discrepancy WrapAround.

Print Assumptions two_sum_exact.
Print Assumptions quick_two_sum_exact.
Print Assumptions two_prod_exact.
Print Assumptions add_error.
Print Assumptions dd_add_correct.
Print Assumptions dd_mul_bound.
Print Assumptions dd_sum_error.
Print Assumptions f64_sum_error.
Print Assumptions dd_product_error.
Print Assumptions f64_product_error.
Print Assumptions pow_gamma.
Print Assumptions to_computed.
Print Assumptions combine_error.
Print Assumptions wd_pair_f64_error.
Print Assumptions fixed_point_exact.
Print Assumptions separable_closed_form.
Print Assumptions warnock_formula.
Print Assumptions gl2_formula.
Print Assumptions centred_formula.
Print Assumptions wd_formula.
