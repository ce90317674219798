(* Differential driver: reads vectors written by the Rust test (tests/extracted_differential.rs)
   on stdin, recomputes every output with the code extracted from the Coq theories
   (Extract.v) and compares bit for bit. Prints one summary line per section and
   "mismatches N" at the end; exits 1 when N > 0 or the input is malformed.

   Input (whitespace-separated tokens):
     art Q W SYMBOLS PSI         one ART table (PSI = 1 when psi tables follow, 0 = identity)
       child  SYMBOLS*2^Q ints   child(s, d) at s*2^Q + d
       psi    SYMBOLS*2^Q ints   (when PSI = 1)
       codes  SYMBOLS hex        top-aligned 64-bit codes
       word ROOT A D X Y Z       (hex A D X Y Z) Y, Z = Rust scalar and batch scrambles of X
       ...
       end
     act K  L_1 P_1 .. L_K P_K  X_1..X_K  Y_1..Y_K
                                 node maps along one word's path (L_i images each), the
                                 word's digits and the Rust output's digits
     net B S N NPTS              one point set (NPTS points, S coordinates of N digits)
       pt ...                    S*N digits
       shape L_1..L_S H  C_1 M_1 .. C_H M_H
                                 Rust's histogram: M_i boxes of the shape hold C_i points
       endnet
     done *)

open Gartowen_extracted

let token () = Scanf.scanf " %s" (fun s -> s)
let int_tok () = int_of_string (token ())

let fail msg = prerr_endline ("driver: " ^ msg); exit 1

let n_of_hex (s : string) : n =
  let acc = ref (N.of_nat 0) in
  String.iter
    (fun c ->
      let v =
        match c with
        | '0' .. '9' -> Char.code c - 48
        | 'a' .. 'f' -> Char.code c - 87
        | 'A' .. 'F' -> Char.code c - 55
        | _ -> fail ("bad hex digit in " ^ s)
      in
      acc := N.coq_lor (N.shiftl !acc (N.of_nat 4)) (N.of_nat v))
    s;
  !acc

let rec hex_of_n (x : n) : string =
  if N.eqb x (N.of_nat 0) then "0"
  else
    let low = N.to_nat (N.coq_land x (N.of_nat 15)) in
    let rest = N.shiftr x (N.of_nat 4) in
    (if N.eqb rest (N.of_nat 0) then "" else hex_of_n rest) ^ Printf.sprintf "%x" low

let mismatches = ref 0
let report_mismatch what =
  incr mismatches;
  if !mismatches <= 10 then prerr_endline ("driver: mismatch: " ^ what)

let read_array len = Array.init len (fun _ -> int_tok ())

let art_section () =
  let q = int_tok () in
  let w = int_tok () in
  let symbols = int_tok () in
  let has_psi = int_tok () = 1 in
  let b = 1 lsl q in
  if token () <> "child" then fail "expected child";
  let child_t = read_array (symbols * b) in
  let psi_t =
    if has_psi then (
      if token () <> "psi" then fail "expected psi";
      Some (read_array (symbols * b)))
    else None
  in
  if token () <> "codes" then fail "expected codes";
  let codes = Array.init symbols (fun _ -> n_of_hex (token ())) in
  let child s d = child_t.((s * b) + d) in
  let psi s d = match psi_t with None -> d | Some t -> t.((s * b) + d) in
  let code64 s = codes.(s) in
  let words = ref 0 in
  let rec loop () =
    match token () with
    | "end" -> ()
    | "word" ->
        let root = int_tok () in
        let a = n_of_hex (token ()) in
        let d = n_of_hex (token ()) in
        let xs = token () in
        let ys = token () in
        let zs = token () in
        let y = art_word_dim q w child psi code64 root a d (n_of_hex xs) in
        List.iter
          (fun (path, v) ->
            if not (N.eqb y (n_of_hex v)) then
              report_mismatch
                (Printf.sprintf "art q=%d W=%d root=%d x=%s: rust %s %s, extracted %s" q w root
                   xs path v (hex_of_n y)))
          [ ("scalar", ys); ("batch", zs) ];
        incr words;
        loop ()
    | t -> fail ("unexpected token in art section: " ^ t)
  in
  loop ();
  Printf.printf "art q=%d W=%d symbols=%d psi=%b: %d words\n" q w symbols has_psi !words

let acts = ref 0
let act_section () =
  let k = int_tok () in
  let maps = Array.init k (fun _ -> let l = int_tok () in read_array l) in
  let x = List.init k (fun _ -> int_tok ()) in
  let y = List.init k (fun _ -> int_tok ()) in
  let sigma p d = maps.(List.length p).(d) in
  let s = { sigma; tau = (fun _ d -> d) } in
  if scramble 0 s x <> y then report_mismatch "nested-scramble action";
  incr acts

let rec enumerate_boxes b lens =
  (* every tuple of prefixes with the given lengths *)
  match lens with
  | [] -> [ [] ]
  | l :: rest ->
      let rec prefixes l = if l = 0 then [ [] ] else
          List.concat_map (fun p -> List.init b (fun d -> p @ [ d ])) (prefixes (l - 1)) in
      let tails = enumerate_boxes b rest in
      List.concat_map (fun p -> List.map (fun t -> p :: t) tails) (prefixes l)

let net_section () =
  let b = int_tok () in
  let s = int_tok () in
  let n = int_tok () in
  let npts = int_tok () in
  let pts =
    List.init npts (fun _ ->
        if token () <> "pt" then fail "expected pt";
        List.init s (fun _ -> List.init n (fun _ -> int_tok ())))
  in
  let shapes = ref 0 in
  let rec loop () =
    match token () with
    | "endnet" -> ()
    | "shape" ->
        let lens = List.init s (fun _ -> int_tok ()) in
        let h = int_tok () in
        let rust = List.sort compare (List.init h (fun _ -> let c = int_tok () in (c, int_tok ()))) in
        let hist = Hashtbl.create 8 in
        List.iter
          (fun box ->
            let c = count box pts in
            Hashtbl.replace hist c (1 + try Hashtbl.find hist c with Not_found -> 0))
          (enumerate_boxes b lens);
        let ours = List.sort compare (Hashtbl.fold (fun c m acc -> (c, m) :: acc) hist []) in
        if ours <> rust then
          report_mismatch
            (Printf.sprintf "box counts of shape (%s) in base %d"
               (String.concat "," (List.map string_of_int lens)) b);
        incr shapes;
        loop ()
    | t -> fail ("unexpected token in net section: " ^ t)
  in
  loop ();
  Printf.printf "net b=%d s=%d N=%d: %d shapes\n" b s npts !shapes

let () =
  let rec sections () =
    match token () with
    | "art" -> art_section (); sections ()
    | "act" -> act_section (); sections ()
    | "net" -> net_section (); sections ()
    | "done" -> ()
    | t -> fail ("unexpected token: " ^ t)
  in
  (try sections () with Scanf.Scan_failure m | Failure m -> fail ("malformed input: " ^ m)
                     | End_of_file -> fail "input ends before done");
  Printf.printf "act: %d words\n" !acts;
  Printf.printf "mismatches %d\n" !mismatches;
  exit (if !mismatches = 0 then 0 else 1)
