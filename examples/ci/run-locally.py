#!/usr/bin/env python3
"""Runs a GitHub Actions workflow or a GitLab CI file on this machine, job by job, step by step.

Each job starts in an empty workspace and sees only what its steps put there: a checkout is a
fresh clone of USER_REPO (submodules only when the file asks for them), artifacts travel only
where the file sends them. So a job that forgets its checkout, a wrong path or a lost artifact
fails here as it would on the hosted runner, before anyone pushes. Jobs run one after another
in the order their dependencies allow; matrix and `parallel:` jobs run once per instance.

Emulated: actions/checkout (a clone), dtolnay/rust-toolchain (cargo must be on PATH),
actions/upload-artifact and actions/download-artifact (copies under WORK/artifacts),
mikepenz/action-junit-report (the report files must exist and parse). `cargo install --path P`
where P is the gartowen CLI's crate installs the binary given with --gartowen, so each job does
not spend minutes rebuilding it (any other cargo command, a wrong path included, runs cargo);
every command runs as written, with bash -eo pipefail. Anything else (other actions, `if:` expressions other than
always()/success()/failure(), matrix include/exclude, GitLab rules) is refused by name.

Usage: run-locally.py github|gitlab PIPELINE.yml USER_REPO --gartowen BIN --work DIR
           [--only JOB --artifacts-from DIR]
--only runs one job (every instance), taking the artifacts of the jobs it needs from the
artifacts folder of an earlier run, to rehearse a change to a late job without the early ones.
Exit: 0 every job passed, 1 a job failed (named), 2 the file uses something not emulated.
"""

import argparse
import glob
import itertools
import os
import re
import shutil
import subprocess
import sys
import xml.etree.ElementTree as ElementTree

import yaml


class NotEmulated(Exception):
    """The pipeline uses a feature this runner does not reproduce."""


def clone(repo, dest, submodules):
    """A fresh checkout of the user's repository (what actions/checkout and GitLab do)."""
    cmd = ["git", "-c", "protocol.file.allow=always", "clone", "-q"]
    if submodules:
        cmd.append("--recurse-submodules")
    subprocess.run(cmd + [repo, dest], check=True)


def cargo_shim(bindir, gartowen):
    """A `cargo` first on PATH: `install --path P` of the CLI crate installs the given binary."""
    real = shutil.which("cargo") or "cargo"
    shim = os.path.join(bindir, "cargo")
    with open(shim, "w") as f:
        f.write(f"""#!/usr/bin/env bash
# cargo install --path P where P is the gartowen CLI crate: installs {gartowen}. Any other
# command (a wrong path included, which cargo refuses at once) goes to cargo itself.
if [ "${{1:-}}" = install ]; then
  path=""; prev=""
  for a in "$@"; do [ "$prev" = --path ] && path="$a"; prev="$a"; done
  if [ -n "$path" ] && grep -q '^name = "gartowen-cli"' "$path/Cargo.toml" 2>/dev/null; then
    cp "{gartowen}" "{bindir}/gartowen" && echo "  Installed gartowen from $path (prebuilt)"
    exit $?
  fi
fi
exec "{real}" "$@"
""")
    os.chmod(shim, 0o755)


def run_shell(script, cwd, env, log):
    """Runs one step's script as the hosted runners do (bash -eo pipefail); returns its status."""
    log.write(f"$ {script.strip()}\n")
    log.flush()
    done = subprocess.run(["bash", "--noprofile", "--norc", "-eo", "pipefail", "-c", script],
                          cwd=cwd, env=env, stdout=log, stderr=subprocess.STDOUT)
    return done.returncode


def copy_matches(patterns, src, dest):
    """Copies the files under src matching the glob patterns to dest (relative paths kept)."""
    found = 0
    for pattern in patterns:
        for path in glob.glob(os.path.join(src, pattern), recursive=True):
            if os.path.isfile(path):
                rel = os.path.relpath(path, src)
                os.makedirs(os.path.dirname(os.path.join(dest, rel)) or dest, exist_ok=True)
                shutil.copy2(path, os.path.join(dest, rel))
                found += 1
    return found


def check_junit(paths, cwd, log):
    """JUnit reports must exist and parse (the reporting action fails or shows nothing otherwise)."""
    files = [p for pat in paths for p in glob.glob(os.path.join(cwd, pat))]
    if not files:
        log.write(f"no JUnit report matches {paths}\n")
        return 1
    for path in files:
        suites = ElementTree.parse(path).getroot()
        cases = suites.iter("testcase")
        log.write(f"JUnit {os.path.basename(path)}: {sum(1 for _ in cases)} testcase(s)\n")
    return 0


class Runner:
    def __init__(self, args):
        self.repo = os.path.abspath(args.user_repo)
        self.work = os.path.abspath(args.work)
        self.gartowen = os.path.abspath(args.gartowen)
        self.artifacts = os.path.join(self.work, "artifacts")
        self.only = args.only
        self.overrides = dict(v.split("=", 1) for v in args.variable)
        if args.artifacts_from:
            shutil.copytree(args.artifacts_from, self.artifacts)
        os.makedirs(self.artifacts, exist_ok=True)

    def job_env(self, label, extra):
        """A fresh workspace for one job instance, and its environment (the cargo shim first)."""
        home = os.path.join(self.work, "jobs", slug(label))
        bindir = os.path.join(home, "bin")
        workspace = os.path.join(home, "workspace")
        os.makedirs(bindir)
        os.makedirs(workspace)
        cargo_shim(bindir, self.gartowen)
        env = dict(os.environ, PATH=bindir + os.pathsep + os.environ["PATH"], CI="true")
        env.update({k: str(v) for k, v in extra.items()})
        return workspace, env


def slug(label):
    """A job's label as a folder name ("exhaustive 1/4" → "exhaustive_1_4")."""
    return re.sub(r"\W+", "_", label)


def expand(text, matrix):
    """${{ matrix.X }} substituted; any other expression is not emulated."""
    def sub(m):
        expr = m.group(1).strip()
        if expr.startswith("matrix.") and expr[7:] in matrix:
            return str(matrix[expr[7:]])
        raise NotEmulated(f"expression ${{{{ {expr} }}}}")
    return re.sub(r"\$\{\{(.*?)\}\}", sub, text)


def github_instances(name, job):
    matrix = (job.get("strategy") or {}).get("matrix")
    if not matrix:
        return [(name, {})]
    if "include" in matrix or "exclude" in matrix:
        raise NotEmulated(f"job {name}: matrix include/exclude")
    keys = list(matrix)
    out = []
    for values in itertools.product(*(matrix[k] for k in keys)):
        combo = dict(zip(keys, values))
        label = ", ".join(str(v) for v in values)
        out.append((f"{name} ({label})", combo))
    return out


def github_step(runner, step, workspace, env, log, matrix, job_name):
    uses = step.get("uses")
    given = step.get("with") or {}
    if "run" in step:
        return run_shell(expand(step["run"], matrix), workspace, env, log)
    action = uses.split("@")[0]
    if action == "actions/checkout":
        clone(runner.repo, workspace, bool(given.get("submodules")))
        return 0
    if action == "dtolnay/rust-toolchain":
        return 0 if shutil.which("cargo", path=env["PATH"]) else 1
    if action == "actions/upload-artifact":
        name = expand(str(given.get("name", "artifact")), matrix)
        paths = [expand(p, matrix) for p in str(given["path"]).split("\n") if p.strip()]
        found = copy_matches(paths, workspace, os.path.join(runner.artifacts, name))
        log.write(f"upload-artifact {name}: {found} file(s)\n")
        if found == 0:  # if-no-files-found defaults to warn
            log.write(f"warning: no files match {paths}\n")
        return 0
    if action == "actions/download-artifact":
        for name in sorted(os.listdir(runner.artifacts)):
            if "name" in given and given["name"] != name:
                continue
            dest = workspace if given.get("merge-multiple") else os.path.join(workspace, name)
            copy_matches(["**/*"], os.path.join(runner.artifacts, name), dest)
        return 0
    if action == "mikepenz/action-junit-report":
        return check_junit(str(given["report_paths"]).split(","), workspace, log)
    raise NotEmulated(f"job {job_name}: action {uses}")


def run_github(runner, doc, log):
    jobs = doc["jobs"]
    status = {}
    pending = list(jobs)
    while pending:
        ready = [j for j in pending if all(n in status for n in as_list(jobs[j].get("needs")))]
        if not ready:
            raise NotEmulated(f"jobs {pending}: their needs never finish")
        name = ready[0]
        pending.remove(name)
        job = jobs[name]
        if runner.only and name != runner.only:
            status[name] = "not run"
            continue
        if any(status[n] not in ("passed", "not run") for n in as_list(job.get("needs"))):
            status[name] = "skipped"
            continue
        failed_any = False
        for label, matrix in github_instances(name, job):
            workspace, env = runner.job_env(label, {})
            failed = False
            for step in job["steps"]:
                cond = str(step.get("if", "success()")).strip()
                if cond not in ("always()", "success()", "failure()"):
                    raise NotEmulated(f"job {label}: if: {cond}")
                if cond == "success()" and failed or cond == "failure()" and not failed:
                    continue
                rc = github_step(runner, step, workspace, env, log, matrix, label)
                if rc != 0:
                    log.write(f"job {label}: step failed (exit {rc}): {step_name(step)}\n")
                    failed = True
            failed_any |= failed
            log.write(f"job {label}: {'FAILED' if failed else 'passed'}\n")
        status[name] = "failed" if failed_any else "passed"
    return status


def step_name(step):
    return step.get("name") or step.get("uses") or str(step.get("run", "")).strip().split("\n")[0]


def as_list(x):
    if x is None:
        return []
    return x if isinstance(x, list) else [x]


GITLAB_KEYWORDS = {"stages", "variables", "default", "include", "workflow", "image", "services",
                   "before_script", "after_script", "cache"}


def run_gitlab(runner, doc, log):
    for unsupported in ("include", "workflow"):
        if unsupported in doc:
            raise NotEmulated(unsupported)
    stages = doc.get("stages", ["build", "test", "deploy"])
    default = doc.get("default") or {}
    variables = {k: str(v) for k, v in (doc.get("variables") or {}).items()}
    jobs = {k: v for k, v in doc.items() if k not in GITLAB_KEYWORDS and not k.startswith(".")}
    status = {}
    artifacts_of = {}
    for stage in stages:
        for name, job in jobs.items():
            if job.get("stage", "test") != stage:
                continue
            if "rules" in job or "only" in job or "except" in job:
                raise NotEmulated(f"job {name}: rules/only/except")
            if runner.only and name != runner.only:
                # An earlier run's artifacts stand in for the jobs not run.
                status[name] = "not run"
                artifacts_of[name] = [os.path.join(runner.artifacts, d)
                                      for d in sorted(os.listdir(runner.artifacts))
                                      if re.match(slug(name) + r"(_|$)", d)]
                continue
            needs = as_list(job.get("needs"))
            earlier = [j for j in jobs if stages.index(jobs[j].get("stage", "test"))
                       < stages.index(stage)]
            sources = needs if "needs" in job else earlier
            if any(status.get(j) not in ("passed", "not run") for j in sources):
                status[name] = "skipped"
                continue
            # Variables given when the pipeline runs take precedence over the file's.
            env_vars = dict(variables, **{k: str(v) for k, v in (job.get("variables") or {}).items()},
                            **runner.overrides)
            count = int(job.get("parallel", 1))
            failed_any = False
            for index in range(1, count + 1):
                label = f"{name} {index}/{count}" if count > 1 else name
                extra = dict(env_vars)
                if count > 1:
                    extra.update(CI_NODE_INDEX=index, CI_NODE_TOTAL=count)
                workspace, env = runner.job_env(label, extra)
                if env_vars.get("GIT_STRATEGY", "fetch") != "none":
                    strategy = env_vars.get("GIT_SUBMODULE_STRATEGY", "none")
                    clone(runner.repo, workspace, strategy in ("normal", "recursive"))
                for source in sources:
                    for folder in artifacts_of.get(source, []):
                        copy_matches(["**/*"], folder, workspace)
                script = job.get("before_script", default.get("before_script", [])) + job["script"]
                rc = run_shell("\n".join(script), workspace, env, log)
                failed = rc != 0
                art = job.get("artifacts") or {}
                if art and (not failed or art.get("when") in ("always", "on_failure")):
                    dest = os.path.join(runner.artifacts, slug(label))
                    paths = list(art.get("paths", []))
                    junit = as_list((art.get("reports") or {}).get("junit"))
                    copy_matches(paths + junit, workspace, dest)
                    artifacts_of.setdefault(name, []).append(dest)
                    if junit and check_junit(junit, workspace, log) != 0:
                        failed = True
                log.write(f"job {label}: {'FAILED (exit %d)' % rc if failed else 'passed'}\n")
                failed_any |= failed
            status[name] = "failed" if failed_any else "passed"
    return status


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("kind", choices=["github", "gitlab"])
    p.add_argument("pipeline")
    p.add_argument("user_repo")
    p.add_argument("--gartowen", required=True, help="the gartowen binary `cargo install` gives")
    p.add_argument("--work", required=True, help="an empty folder for workspaces and artifacts")
    p.add_argument("--only", help="run this job alone")
    p.add_argument("--artifacts-from", help="the artifacts folder of an earlier run (with --only)")
    p.add_argument("--variable", action="append", default=[], metavar="NAME=VALUE",
                   help="GitLab: a variable given when the pipeline runs (overrides the file's)")
    args = p.parse_args()
    bad = [v for v in args.variable if not re.fullmatch(r"[A-Za-z_][A-Za-z0-9_]*=.*", v)]
    if bad:
        print(f"run-locally: --variable {bad[0]!r} is not NAME=VALUE", file=sys.stderr)
        return 2
    if args.variable and args.kind != "gitlab":
        print("run-locally: --variable is for GitLab pipelines (GitHub workflows take none here)",
              file=sys.stderr)
        return 2
    if os.path.exists(args.work) and os.listdir(args.work):
        print(f"run-locally: --work {args.work} is not empty", file=sys.stderr)
        return 2
    runner = Runner(args)
    with open(args.pipeline) as f:
        doc = yaml.safe_load(f)
    with open(os.path.join(runner.work, "log.txt"), "w") as log:
        try:
            status = (run_github if args.kind == "github" else run_gitlab)(runner, doc, log)
        except NotEmulated as e:
            print(f"run-locally: not emulated: {e}", file=sys.stderr)
            return 2
    for name, s in status.items():
        print(f"{s:8} {name}")
    if all(s in ("passed", "not run") for s in status.values()):
        return 0
    print(f"run-locally: a job failed; the steps and their output: {runner.work}/log.txt",
          file=sys.stderr)
    return 1


if __name__ == "__main__":
    sys.exit(main())
