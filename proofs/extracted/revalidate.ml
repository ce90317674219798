(* Re-checks a witness written by `gartowen check --witness FILE` with the code extracted from
   Witness.v (Extract.v): the points' digits from their words, a failing box counted directly,
   "holds" re-decided by the proved counting checker. Usage: revalidate FILE (or - for stdin).
   Exit 0 when the claim is re-checked (Witness.revalidate_sound states what that proves),
   1 when the re-check rejects it, 2 when the file is malformed or outside the checked range.

   The file (whitespace-separated tokens):
     gartowen-witness 1
     base B width W dims S m M points N
     claim holds T | claim fails T | claim tvalue T
     box D_1..D_S A_1..A_S count C      for fails, and for tvalue when T > 0 (the box at T-1)
     words X_1 .. X_{N*S}                hex words, point by point
     end
   Trusted here, beyond the extraction: this parser and the range guard below (every value
   the extracted code computes stays below 2^62 when W <= 32 and B^M <= 2^29). *)

open Gartowen_extracted

let bad msg = prerr_endline ("revalidate: " ^ msg); exit 2

let () =
  let path = if Array.length Sys.argv > 1 then Sys.argv.(1) else bad "usage: revalidate FILE" in
  let ic = if path = "-" then Scanf.Scanning.stdin else
      (try Scanf.Scanning.open_in path with Sys_error e -> bad e) in
  let token () = try Scanf.bscanf ic " %s" (fun s -> s) with _ -> bad "unexpected end of file" in
  let int_tok what =
    let t = token () in
    match int_of_string_opt t with Some v when v >= 0 -> v | _ -> bad (what ^ ": not a count: " ^ t) in
  let expect w = let t = token () in if t <> w then bad (Printf.sprintf "expected %s, found %s" w t) in
  expect "gartowen-witness"; expect "1";
  expect "base"; let b = int_tok "base" in
  expect "width"; let w = int_tok "width" in
  expect "dims"; let s = int_tok "dims" in
  expect "m"; let m = int_tok "m" in
  expect "points"; let npts = int_tok "points" in
  let rec pow b k = if k = 0 then 1 else b * pow b (k - 1) in
  if b < 2 || w < 1 || w > 32 || s < 1 then bad "base >= 2, width 1..32 and dims >= 1 are re-checked";
  let rec fits acc k = k = 0 || (acc * b <= 1 lsl 29 && fits (acc * b) (k - 1)) in
  if not (fits 1 m) then bad "b^m above 2^29 is outside the re-checked range";
  if npts <> pow b m then bad (Printf.sprintf "points %d is not b^m = %d" npts (pow b m));
  expect "claim";
  let kind = token () in
  let t = int_tok "t" in
  let read_box () =
    expect "box";
    let sh = List.init s (fun _ -> int_tok "shape digit") in
    let av = List.init s (fun _ -> int_tok "box index") in
    expect "count";
    (sh, av, int_tok "count")
  in
  let claim =
    match kind with
    | "holds" -> Holds t
    | "fails" -> let sh, av, c = read_box () in Fails (t, sh, av, c)
    | "tvalue" when t = 0 -> TValue (0, [], [], 0)
    | "tvalue" -> let sh, av, c = read_box () in TValue (t, sh, av, c)
    | k -> bad ("unknown claim " ^ k)
  in
  expect "words";
  let word () =
    let tk = token () in
    match int_of_string_opt ("0x" ^ tk) with
    | Some v when v >= 0 && String.length tk <= 8 -> v
    | _ -> bad ("not a 32-bit hex word: " ^ tk)
  in
  let words = List.init npts (fun _ -> List.init s (fun _ -> word ())) in
  expect "end";
  let ints l = String.concat "," (List.map string_of_int l) in
  let what =
    match claim with
    | Holds t -> Printf.sprintf "a (%d,%d,%d)-net in base %d" t m s b
    | Fails (t, sh, av, c) ->
        Printf.sprintf "not a (%d,%d,%d)-net in base %d: box %s of shape %s holds %d points" t m s b
          (ints av) (ints sh) c
    | TValue (t, sh, av, c) ->
        Printf.sprintf "t-value %d in base %d (m = %d, s = %d)%s" t b m s
          (if t = 0 then "" else
             Printf.sprintf "; at t = %d box %s of shape %s holds %d points" (t - 1) (ints av)
               (ints sh) c)
  in
  let verdict =
    try revalidate b w m s words claim
    with Stack_overflow ->
      bad "the re-check ran out of stack (its list functions recurse once per point): raise the \
           limit (ulimit -s unlimited), as proofs/revalidate.sh does"
  in
  if verdict then (
    Printf.printf "re-checked by the extracted checker (Witness.revalidate_sound): %s\n" what;
    exit 0)
  else (
    Printf.printf "REJECTED by the extracted checker: the witness does not show %s\n" what;
    exit 1)
