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
     checker B S N NPTS          one point set for the counting net checker (Checker.v)
       pt ...                    S*N digits
       net M T | tval M | seq T MAXM    queries, each answered on a line of its own:
         answer net M T holds SHAPES
         answer net M T fails POS shape D,.. box A,.. count C
         answer tval M T
         answer seq T MAXM holds BLOCKS SHAPES
         answer seq T MAXM fails BLOCKS SHAPES at K block I shape D,.. box A,.. count C
       endchecker
     rank D NR R_1..R_NR         one shape's stacked rows (masks over D index bits), answered
                                 "answer rank 1" when the XOR basis accepts every row, else 0
     done
   The checker's answers are compared by the Rust test, not here; POS, BLOCKS and SHAPES are
   the report's counters (failing shape's position, blocks and shapes examined), derived from
   the extracted shape list. *)

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

let checkers = ref 0
let ints l = String.concat "," (List.map string_of_int l)
let rec pow b k = if k = 0 then 1 else b * pow b (k - 1)
let rec position x = function
  | [] -> fail "a failing shape is not among the shapes"
  | y :: r -> if y = x then 0 else 1 + position x r

(* Shape, box index (the value of each coordinate's box digits) and count of a failure. *)
let failure_text b pts (sh, p) =
  let bx = box_of sh p in
  Printf.sprintf "shape %s box %s count %d" (ints sh) (ints (List.map (digit_value b) bx)) (count bx pts)

let checker_section () =
  let b = int_tok () in
  let s = int_tok () in
  let n = int_tok () in
  let npts = int_tok () in
  let pts =
    List.init npts (fun _ ->
        if token () <> "pt" then fail "expected pt";
        List.init s (fun _ -> List.init n (fun _ -> int_tok ())))
  in
  let rec loop () =
    match token () with
    | "endchecker" -> ()
    | "net" ->
        let m = int_tok () in
        let t = int_tok () in
        let shapes = comps (m - t) s in
        (match check_net b m t s pts with
         | None -> Printf.printf "answer net %d %d holds %d\n" m t (List.length shapes)
         | Some (sh, p) ->
             Printf.printf "answer net %d %d fails %d %s\n" m t (position sh shapes + 1)
               (failure_text b pts (sh, p)));
        loop ()
    | "tval" ->
        let m = int_tok () in
        Printf.printf "answer tval %d %d\n" m (t_value b m s pts);
        loop ()
    | "seq" ->
        let t = int_tok () in
        let maxm = int_tok () in
        let blocks m = npts / pow b m in
        let shapes m = List.length (comps (m - t) s) in
        (* blocks and block-shapes of every level below k, all of which passed *)
        let rec below k acc_b acc_s =
          if k <= t then (acc_b, acc_s)
          else below (k - 1) (acc_b + blocks (k - 1)) (acc_s + blocks (k - 1) * shapes (k - 1))
        in
        (match check_sequence b t maxm s pts with
         | None ->
             let bs, ss = below (maxm + 1) 0 0 in
             Printf.printf "answer seq %d %d holds %d %d\n" t maxm bs ss
         | Some (k, (i, (sh, p))) ->
             let bs, ss = below k 0 0 in
             let pos = position sh (comps (k - t) s) in
             Printf.printf "answer seq %d %d fails %d %d at %d block %d %s\n" t maxm
               (bs + i + 1) (ss + i * shapes k + pos + 1) k i
               (failure_text b (block b k i pts) (sh, p)));
        loop ()
    | t -> fail ("unexpected token in checker section: " ^ t)
  in
  loop ();
  incr checkers

let ranks = ref 0

let rank_section () =
  let d = int_tok () in
  let nr = int_tok () in
  let rows = List.init nr (fun _ -> int_tok ()) in
  incr ranks;
  Printf.printf "answer rank %d\n" (if independent d rows then 1 else 0)

let () =
  let rec sections () =
    match token () with
    | "art" -> art_section (); sections ()
    | "act" -> act_section (); sections ()
    | "net" -> net_section (); sections ()
    | "checker" -> checker_section (); sections ()
    | "rank" -> rank_section (); sections ()
    | "done" -> ()
    | t -> fail ("unexpected token: " ^ t)
  in
  (try sections () with Scanf.Scan_failure m | Failure m -> fail ("malformed input: " ^ m)
                     | End_of_file -> fail "input ends before done");
  Printf.printf "act: %d words\n" !acts;
  Printf.printf "checker: %d point sets\n" !checkers;
  Printf.printf "rank: %d shapes\n" !ranks;
  Printf.printf "mismatches %d\n" !mismatches;
  exit (if !mismatches = 0 then 0 else 1)
