(** The floating-point theorems rest on Coq's classical real numbers (through Flocq): their
    [Print Assumptions] may list exactly the four standard axioms that check.sh allows
    (ClassicalDedekindReals.sig_forall_dec, ClassicalDedekindReals.sig_not_dec,
    FunctionalExtensionality.functional_extensionality_dep, Classical_Prop.classic). *)
From Gartowen Require Import Float.

Print Assumptions two_sum_exact.
Print Assumptions quick_two_sum_exact.
Print Assumptions two_prod_exact.
Print Assumptions add_error.
