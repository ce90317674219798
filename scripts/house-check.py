#!/usr/bin/env python3
"""Prints the import cycles between modules of one crate, the Rust files over the size limit,
the locked dependencies that need a newer Rust than the workspace's declared rust-version, and
the shared crates whose features differ between the test build and the Python package's.

Modules are files (src/a.rs and src/a/mod.rs are module `a`, src/a/b.rs is `a::b`). A file
depends on every module its `crate::`, `super::` and `self::` paths name (the longest prefix
that is a module; `#[cfg(test)] mod tests` blocks are skipped). A dependency between two
modules is counted between the children of their lowest common ancestor that contain them, so
a parent using its child (or a child its parent) is layering, not a cycle; a cycle is a set of
sibling modules that reach each other. The declared rust-version is the MSRV: clippy's
`incompatible_msrv` lint checks the standard library calls against it, this script the
dependencies of Cargo.lock. The test command builds the Python package with the feature
test-build so that it reuses the test build: a crate both builds compile with different
features is compiled twice, with everything above it. Exit status 1 when anything is found,
0 otherwise.

Usage: scripts/house-check.py [--max-lines N] [--skip-dependencies] [ROOT]
"""

import json
import os
import re
import subprocess
import sys
from collections import defaultdict

MAX_LINES = 700
# Generated tables may exceed the limit; they say so on their first line.
GENERATED_MARK = "@generated"


def crates(root):
    """Directories holding a Cargo.toml and a src/ folder (the workspace members)."""
    out = []
    for dirpath, dirnames, filenames in os.walk(root):
        dirnames[:] = [d for d in dirnames if d not in ("target", ".git", "node_modules", ".venv")]
        if "Cargo.toml" in filenames and os.path.isdir(os.path.join(dirpath, "src")):
            out.append(dirpath)
    return sorted(out)


def module_of(src, path):
    rel = os.path.relpath(path, src)[:-3].split(os.sep)
    if rel[-1] in ("lib", "main", "mod"):
        rel = rel[:-1]
    if rel and rel[0] == "bin":
        return None  # binaries are crates of their own
    return tuple(rel)


def strip_tests_and_comments(text):
    text = re.sub(r"#\[cfg\(test\)\]\s*mod\s+\w+\s*\{.*", "", text, flags=re.S)
    text = re.sub(r"//[^\n]*", "", text)
    return text


def expand_use(tree):
    """Expands a use tree such as `a::{b, c::{d, e}}` into paths."""
    tree = tree.strip()
    depth, start = 0, None
    for i, ch in enumerate(tree):
        if ch == "{":
            if depth == 0:
                start = i
            depth += 1
        elif ch == "}":
            depth -= 1
    if start is None:
        return [tree.split(" as ")[0].strip()]
    prefix = tree[:start]
    inner = tree[start + 1 : tree.rindex("}")]
    parts, depth, cur = [], 0, ""
    for ch in inner:
        if ch == "," and depth == 0:
            parts.append(cur)
            cur = ""
            continue
        depth += ch == "{"
        depth -= ch == "}"
        cur += ch
    parts.append(cur)
    out = []
    for p in parts:
        if p.strip():
            out.extend(prefix + q for q in expand_use(p))
    return out


def referenced_paths(text):
    paths = []
    for m in re.finditer(r"\buse\s+([^;]+);", text):
        paths.extend(expand_use(m.group(1)))
    paths.extend(re.findall(r"(?<![\w:])((?:crate|super|self)(?:::\w+)+)", text))
    return paths


def resolve(path, here, is_dir_module, modules):
    parts = [p for p in path.replace(" ", "").split("::") if p]
    if not parts:
        return None
    base = list(here)
    if parts[0] == "crate":
        base, parts = [], parts[1:]
    elif parts[0] in ("super", "self"):
        # In a.rs or a/mod.rs, `self` is module a and `super` its parent.
        while parts and parts[0] in ("super", "self"):
            if parts[0] == "super":
                base = base[:-1]
            parts = parts[1:]
    else:
        return None
    best = tuple(base)
    for k in range(1, len(parts) + 1):
        cand = tuple(base + parts[:k])
        if cand in modules:
            best = cand
    return best


def check_crate(crate_dir):
    src = os.path.join(crate_dir, "src")
    files = {}
    for dirpath, _, filenames in os.walk(src):
        for f in filenames:
            if f.endswith(".rs"):
                p = os.path.join(dirpath, f)
                m = module_of(src, p)
                if m is not None:
                    files[m] = p
    modules = set(files)
    # Edges between siblings: parent -> {child_a -> {child_b}}
    edges = defaultdict(lambda: defaultdict(set))
    witness = {}
    for mod, path in files.items():
        with open(path, encoding="utf-8") as fh:
            text = strip_tests_and_comments(fh.read())
        is_dir = os.path.basename(path) in ("mod.rs", "lib.rs", "main.rs")
        for ref in referenced_paths(text):
            target = resolve(ref, mod, is_dir, modules)
            if target is None or target == mod:
                continue
            k = 0
            while k < min(len(mod), len(target)) and mod[k] == target[k]:
                k += 1
            if k == len(mod) or k == len(target):
                continue  # ancestor and descendant: layering
            parent, a, b = mod[:k], mod[: k + 1], target[: k + 1]
            edges[parent][a].add(b)
            witness.setdefault((a, b), (os.path.relpath(path, crate_dir), ref))
    cycles = []
    for parent, graph in edges.items():
        for comp in strongly_connected(graph):
            if len(comp) > 1:
                cycles.append((parent, sorted(comp)))
    return cycles, witness, files


def strongly_connected(graph):
    index, low, stack, on, out = {}, {}, [], set(), []
    counter = [0]
    nodes = set(graph) | {v for vs in graph.values() for v in vs}

    def visit(v):
        index[v] = low[v] = counter[0]
        counter[0] += 1
        stack.append(v)
        on.add(v)
        for w in graph.get(v, ()):
            if w not in index:
                visit(w)
                low[v] = min(low[v], low[w])
            elif w in on:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            comp = []
            while True:
                w = stack.pop()
                on.discard(w)
                comp.append(w)
                if w == v:
                    break
            out.append(comp)

    for v in sorted(nodes):
        if v not in index:
            visit(v)
    return out


def main(argv):
    limit = MAX_LINES
    args = list(argv)
    if "--max-lines" in args:
        i = args.index("--max-lines")
        limit = int(args[i + 1])
        del args[i : i + 2]
    skip_dependencies = "--skip-dependencies" in args
    args = [a for a in args if a != "--skip-dependencies"]
    root = args[0] if args else os.path.join(os.path.dirname(__file__), "..")
    root = os.path.abspath(root)
    bad = 0
    print("import cycles between sibling modules of one crate:")
    for crate_dir in crates(root):
        cycles, witness, _ = check_crate(crate_dir)
        for parent, comp in cycles:
            bad += 1
            name = os.path.relpath(crate_dir, root)
            where = "::".join(parent) or "crate root"
            print(f"  {name} ({where}): " + " <-> ".join("::".join(m) for m in comp))
            for a in comp:
                for b in comp:
                    if (a, b) in witness:
                        f, ref = witness[(a, b)]
                        print(f"      {'::'.join(a)} -> {'::'.join(b)}: {f} names {ref}")
    if bad == 0:
        print("  none")
    print(f"Rust files over {limit} lines (generated files excepted):")
    over = 0
    for p in rust_files(root):
        with open(p, encoding="utf-8", errors="replace") as fh:
            lines = fh.read().split("\n")
        if lines and GENERATED_MARK in lines[0]:
            continue
        n = len(lines) - (1 if lines and lines[-1] == "" else 0)
        if n > limit:
            over += 1
            print(f"  {os.path.relpath(p, root)}: {n} lines")
    if over == 0:
        print("  none")
    untiered = ignored_outside_the_large_tier(root)
    newer = 0 if skip_dependencies else msrv_violations(root)
    unshared = 0 if skip_dependencies else unshared_python_build(root)
    return 1 if bad or over or untiered or newer or unshared else 0


def rust_files(root):
    """Every .rs file under root, build and environment folders left out, in a fixed order."""
    for dirpath, dirnames, filenames in os.walk(root):
        dirnames[:] = sorted(d for d in dirnames if d not in ("target", ".git", ".venv"))
        for f in sorted(filenames):
            if f.endswith(".rs"):
                yield os.path.join(dirpath, f)


def ignored_outside_the_large_tier(root):
    """Ignored tests must belong to the large tier that scripts/test-large.sh runs."""
    print('#[ignore] tests not marked "large tier (scripts/test-large.sh)":')
    found = 0
    for p in rust_files(root):
        with open(p, encoding="utf-8", errors="replace") as fh:
            for k, line in enumerate(fh, 1):
                s = line.strip()
                if s.startswith("#[ignore") and not s.startswith(
                    '#[ignore = "large tier (scripts/test-large.sh)'
                ):
                    found += 1
                    print(f"  {os.path.relpath(p, root)}:{k}: {s}")
    if found == 0:
        print("  none")
    return found


def version_key(v):
    parts = [int(x) for x in re.findall(r"\d+", v)[:3]]
    return tuple(parts + [0] * (3 - len(parts)))


def msrv_violations(root):
    """Locked dependencies whose rust-version exceeds the workspace's."""
    with open(os.path.join(root, "Cargo.toml"), encoding="utf-8") as fh:
        m = re.search(r'^rust-version\s*=\s*"([^"]+)"', fh.read(), re.M)
    if not m:
        print("no rust-version declared in Cargo.toml [workspace.package]")
        return 1
    msrv = m.group(1)
    print(f"locked dependencies needing a newer Rust than rust-version {msrv}:")
    # The host's dependencies only: those of other platforms (Windows consoles, wasm) are not
    # downloaded by a Linux build, and CI may have no network.
    host = subprocess.run(["rustc", "-vV"], capture_output=True, text=True)
    triple = re.search(r"^host: (\S+)", host.stdout, re.M)
    platform = ["--filter-platform", triple.group(1)] if triple else []
    meta = subprocess.run(
        ["cargo", "metadata", "--format-version", "1", "--locked", "--offline"] + platform,
        cwd=root, capture_output=True, text=True,
    )
    if meta.returncode != 0:
        print("  cannot read Cargo.lock's packages: " + meta.stderr.strip().splitlines()[-1])
        return 1
    found = 0
    for p in json.loads(meta.stdout)["packages"]:
        need = p.get("rust_version")
        if need and version_key(need) > version_key(msrv):
            found += 1
            print(f"  {p['name']} {p['version']} needs Rust {need}")
    if found == 0:
        print("  none")
    return found


def crate_features(root, args):
    """{(name, version): features} of the packages `cargo tree ARGS` resolves, or None."""
    tree = subprocess.run(
        ["cargo", "tree", "-q", "--locked", "--offline", "--prefix", "none",
         "-f", "{p} [{f}]", "-e", "features,normal,build"] + args,
        cwd=root, capture_output=True, text=True,
    )
    if tree.returncode != 0:
        print("  cargo tree failed: " + (tree.stderr.strip().splitlines() or ["?"])[-1])
        return None
    found = {}
    for line in tree.stdout.splitlines():
        m = re.match(r"(\S+) (v\S+)(?: \([^)]*\))?(?: \(\*\))? \[(.*)\]", line.strip())
        if m:
            found[(m.group(1), m.group(2))] = m.group(3)
    return found


def unshared_python_build(root):
    """Crates the Python package (with test-build) compiles with other features than the tests."""
    manifest = os.path.join(root, "python", "Cargo.toml")
    if not os.path.exists(manifest):
        return 0
    with open(manifest, encoding="utf-8") as fh:
        if "test-build" not in fh.read():
            return 0
    print("crates the test build and the Python package (feature test-build) compile differently:")
    tests = crate_features(root, ["--workspace", "-e", "dev"])
    package = crate_features(root, ["-p", "gartowen-python", "--features", "extension-module,test-build"])
    if tests is None or package is None:
        return 1
    # pyo3's family is the package's alone (the tests never link Python), and the package itself
    # has its own features.
    own = ("pyo3", "pyo3-ffi", "pyo3-build-config", "pyo3-macros", "pyo3-macros-backend",
           "gartowen-python")
    found = 0
    for key, features in sorted(package.items()):
        if key[0] in own or key not in tests or tests[key] == features:
            continue
        found += 1
        print(f"  {key[0]} {key[1]}: tests [{tests[key]}], Python package [{features}]"
              " (python/Cargo.toml's test-build)")
    if found == 0:
        print("  none")
    return found


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
