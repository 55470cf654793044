#!/usr/bin/env python3
"""sepax mutation check: does the test suite catch small deliberate bugs?

Reads the mutations of tests/mutations.txt (format described there), and for
each one, on a private copy of the tree in build/mutate/tree (the working
tree is never written, so an interrupted or failing run leaves it as it
was): replaces the mutation's anchor text in its source file, rebuilds the
test programs, and runs them, the mutation's likely killers first and then
the rest of the suite, stopping at the first program that fails (or runs past
the time limit). A mutation that every program passes is a survivor.

tests/test_determinism is left out of the verdict: its pinned hashes change
with any change of the physics, so it would kill every mutation and say
nothing about whether the other tests check the behaviour. It runs after
the others for the survivors only, and the report says whether the pinned
hash noticed them.

An anchor must match exactly once (runs of white space in the anchor match
any run of white space, so re-wrapping the code does not break it); one that
matches nowhere or more than once, or a mutated tree that does not compile,
is an error of the list, reported as such: the list is kept up to date, never
silently skipped.

Usage: scripts/mutate.py [--list FILE] [--only NAME[,NAME...]] [--jobs N]
Exit status: 0 when every mutation was caught, 1 otherwise.
"""

import argparse
import os
import re
import shutil
import subprocess
import sys
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
WORK = os.path.join(ROOT, "build", "mutate")
TREE = os.path.join(WORK, "tree")
LOGS = os.path.join(WORK, "logs")
COPIED = ["Makefile", "src", "include", "tests", "scripts", "ecs", "fuzz", "samples"]
# The pinned hashes fail on any change of the physics (see the docstring).
HASH_TEST = "test_determinism"
# Per test program; the slowest program takes a few seconds unmutated, so
# this only stops mutations that make a step never end.
TIME_LIMIT = 120


class ListError(Exception):
    pass


def parse_list(path):
    """Mutation records: name, file, tests (killers to run first), find,
    replace, why."""
    muts = []
    cur = None
    block = None
    with open(path, encoding="utf-8") as f:
        for lineno, raw in enumerate(f, 1):
            line = raw.rstrip("\n")
            where = "%s:%d" % (os.path.relpath(path, ROOT), lineno)
            if line.startswith("=== "):
                cur = {"name": line[4:].strip(), "file": None, "tests": [], "why": "",
                       "find": [], "replace": [], "where": where}
                muts.append(cur)
                block = None
                continue
            if cur is None or line.startswith("#") and block is None:
                continue
            if line.startswith("|"):
                if block is None:
                    raise ListError("%s: code line outside find:/replace:" % where)
                cur[block].append(line[1:])
                continue
            block = None
            if not line.strip():
                continue
            key, _, value = line.partition(":")
            key, value = key.strip(), value.strip()
            if key == "file":
                cur["file"] = value
            elif key == "tests":
                cur["tests"] = value.split()
            elif key == "why":
                cur["why"] = value
            elif key in ("find", "replace"):
                block = key
            else:
                raise ListError("%s: unknown field %r" % (where, key))
    names = set()
    for m in muts:
        if not m["file"] or not m["find"]:
            raise ListError("%s: mutation %r needs file: and find:" % (m["where"], m["name"]))
        if m["name"] in names:
            raise ListError("%s: mutation name %r used twice" % (m["where"], m["name"]))
        names.add(m["name"])
    return muts


def anchor_regex(lines):
    """The anchor as a pattern: its tokens, any run of white space between."""
    tokens = "\n".join(lines).split()
    return re.compile(r"\s+".join(re.escape(t) for t in tokens))


def apply_mutation(m, text):
    """The mutated text, or ListError if the anchor is missing or ambiguous."""
    pattern = anchor_regex(m["find"])
    hits = [h for h in pattern.finditer(text)]
    if len(hits) != 1:
        raise ListError("%s: mutation %r: anchor found %d times in %s (must be once); update the "
                        "mutation to the current code:\n  %s"
                        % (m["where"], m["name"], len(hits), m["file"], "\n  ".join(m["find"])))
    h = hits[0]
    start = h.start()
    # the replacement carries its own indentation: replace the anchor's too
    line_start = text.rfind("\n", 0, start) + 1
    if not text[line_start:start].strip():
        start = line_start
    replacement = "\n".join(m["replace"])
    if replacement.strip() == "\n".join(m["find"]).strip():
        raise ListError("%s: mutation %r changes nothing" % (m["where"], m["name"]))
    return text[:start] + replacement + text[h.end():]


def copy_tree():
    os.makedirs(TREE, exist_ok=True)
    for item in COPIED:
        src, dst = os.path.join(ROOT, item), os.path.join(TREE, item)
        if not os.path.exists(src):
            continue
        if os.path.isdir(src):
            shutil.rmtree(dst, ignore_errors=True)
            # fresh modification times: an object built from a mutated file
            # by an interrupted run is never taken for an up-to-date one
            shutil.copytree(src, dst, copy_function=shutil.copy)
        else:
            shutil.copy(src, dst)
    # flecs sources fetched for test_ecs are reused, not fetched again
    deps = os.path.join(ROOT, "build", "deps")
    if os.path.isdir(deps) and not os.path.exists(os.path.join(TREE, "build", "deps")):
        os.makedirs(os.path.join(TREE, "build"), exist_ok=True)
        os.symlink(deps, os.path.join(TREE, "build", "deps"))


def test_programs():
    names = []
    for d in ("tests", os.path.join("tests", "internal")):
        names += [f[:-2] for f in os.listdir(os.path.join(TREE, d))
                  if f.startswith("test_") and f.endswith(".c")]
    return sorted(names)


def build(jobs, log):
    targets = ["build/tests/" + t for t in test_programs()]
    with open(log, "a", encoding="utf-8") as out:
        r = subprocess.run(["make", "-j%d" % jobs, "OPT=-O2"] + targets, cwd=TREE, stdout=out,
                           stderr=subprocess.STDOUT)
    return r.returncode == 0


def run_test(name, log):
    """'pass', 'fail' or 'timeout'."""
    with open(log, "a", encoding="utf-8") as out:
        out.write("\n== %s\n" % name)
        out.flush()
        try:
            r = subprocess.run(["./build/tests/" + name], cwd=TREE, stdout=out,
                               stderr=subprocess.STDOUT, timeout=TIME_LIMIT)
        except subprocess.TimeoutExpired:
            return "timeout"
    return "pass" if r.returncode == 0 else "fail"


def run_suite(first, log):
    """The first failing program (and how), or None when all pass."""
    order = [t for t in first if t != HASH_TEST]
    order += [t for t in test_programs() if t not in order and t != HASH_TEST]
    for t in order:
        verdict = run_test(t, log)
        if verdict != "pass":
            return t, verdict
    return None


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--list", default=os.path.join(ROOT, "tests", "mutations.txt"))
    ap.add_argument("--only", default="", help="comma-separated mutation names")
    ap.add_argument("--jobs", type=int, default=2)
    args = ap.parse_args()

    try:
        muts = parse_list(args.list)
    except ListError as e:
        print("mutate: %s" % e)
        return 1
    if args.only:
        wanted = set(args.only.split(","))
        unknown = wanted - set(m["name"] for m in muts)
        if unknown:
            print("mutate: no mutation named %s" % ", ".join(sorted(unknown)))
            return 1
        muts = [m for m in muts if m["name"] in wanted]

    start = time.time()
    copy_tree()
    shutil.rmtree(LOGS, ignore_errors=True)
    os.makedirs(LOGS)
    # every anchor is checked before anything runs
    originals = {}
    try:
        for m in muts:
            if m["file"] not in originals:
                with open(os.path.join(TREE, m["file"]), encoding="utf-8") as f:
                    originals[m["file"]] = f.read()
            apply_mutation(m, originals[m["file"]])
    except (ListError, OSError) as e:
        print("mutate: %s" % e)
        return 1

    base_log = os.path.join(LOGS, "baseline.log")
    print("mutate: %d mutations; building and running the unmutated suite first" % len(muts))
    sys.stdout.flush()
    if not build(args.jobs, base_log):
        print("mutate: the unmutated tree does not build (see %s)" % base_log)
        return 1
    base = run_suite([], base_log)
    if base is None and run_test(HASH_TEST, base_log) != "pass":
        base = (HASH_TEST, "fail")
    if base is not None:
        print("mutate: the unmutated suite fails (%s: %s, see %s); fix that first"
              % (base[0], base[1], base_log))
        return 1

    survivors, broken = [], []
    for i, m in enumerate(muts, 1):
        t0 = time.time()
        log = os.path.join(LOGS, m["name"] + ".log")
        path = os.path.join(TREE, m["file"])
        with open(path, "w", encoding="utf-8") as f:
            f.write(apply_mutation(m, originals[m["file"]]))
        try:
            if not build(args.jobs, log):
                broken.append(m)
                verdict = "ERROR: the mutated tree does not compile (see %s)" % log
            else:
                killer = run_suite(m["tests"], log)
                if killer is None:
                    survivors.append(m)
                    hashed = run_test(HASH_TEST, log) != "pass"
                    verdict = "SURVIVED%s" % (" (only the pinned determinism hash noticed)"
                                              if hashed else "")
                else:
                    verdict = "caught by %s (%s)" % killer
        finally:
            with open(path, "w", encoding="utf-8") as f:
                f.write(originals[m["file"]])
        print("[%2d/%d] %-40s %s  %.0f s" % (i, len(muts), m["name"], verdict, time.time() - t0))
        sys.stdout.flush()

    print("mutate: %d mutations, %d caught, %d survived, %d broken; %.0f s in all"
          % (len(muts), len(muts) - len(survivors) - len(broken), len(survivors), len(broken),
             time.time() - start))
    for m in survivors:
        print("  survivor %s (%s, %s): %s" % (m["name"], m["file"], m["where"], m["why"]))
    for m in broken:
        print("  broken   %s (%s): fix the mutation in the list" % (m["name"], m["where"]))
    return 0 if not survivors and not broken else 1


if __name__ == "__main__":
    sys.exit(main())
