#!/usr/bin/env python3
"""clang-tidy over the given sources, remembering the ones it found clean.

A file is analysed again only when something clang-tidy sees could have changed: its
preprocessed text with comments (so every header it includes, and NOLINT markers), its compile
command, the .clang-tidy configuration, the extra arguments and clang-tidy's version. The
checkout's own path is left out of that key, so another clone of the same commit (CI's) reuses
this one's results. Only clean results are remembered: a file with a finding is analysed, and
reported, every time.

With --since COMMIT, only the files a change since COMMIT can have affected are analysed: those
whose own text or any header they include (as the dependency log of the Ninja build --deps names
lists them) differs from COMMIT's. Every file is, when COMMIT is not in this clone's history, when the configuration
changed since (CONFIGURATION below) or when a file has no dependency record. CI passes the last
commit a full run found clean (.ci/clang_tidy_clean, written by --record-clean).

Usage: tools/clang_tidy.py -p BUILD_DIR [-j N] [--extra-arg ARG ...] [--cache-dir DIR]
                           [--since COMMIT [--deps BUILD_DIR]] [--record-clean FILE] FILE...
--record-clean FILE: after a clean run over every given file (no --since), write HEAD's commit
to FILE, for later runs' --since.
Exit status: 0 when every file is clean, 1 when any has a warning or an error, 2 on bad use.
"""

import argparse
import concurrent.futures
import hashlib
import json
import os
import re
import shlex
import subprocess
import sys

FINDING = re.compile(r"(warning|error):")

# A change to any of these since --since's commit can change any file's findings: all are analysed.
CONFIGURATION = (".clang-tidy", "tools/clang_tidy.py", "CMakePresets.json",
                 "cmake/CollidoWarnings.cmake")


def default_cache_dir():
    base = os.environ.get("XDG_CACHE_HOME") or os.path.join(os.path.expanduser("~"), ".cache")
    return os.path.join(base, "collido-clang-tidy")


def compile_arguments(entry):
    if "arguments" in entry:
        return list(entry["arguments"])
    return shlex.split(entry["command"])


def preprocess_command(arguments, compiler):
    """The compile command turned into clang's preprocessor run (comments kept) to stdout."""
    result = [compiler]
    skip = False
    for argument in arguments[1:]:
        if skip:
            skip = False
            continue
        if argument in ("-o", "-MF", "-MT", "-MQ"):
            skip = True
            continue
        if argument in ("-c", "-MD", "-MMD") or argument.startswith("-o"):
            continue
        result.append(argument)
    return result + ["-w", "-E", "-C", "-o", "-"]


class Tidy:
    def __init__(self, options, root):
        self.options = options
        self.root = root
        self.build = os.path.realpath(options.p)
        with open(os.path.join(self.build, "compile_commands.json"), encoding="utf-8") as f:
            self.commands = {os.path.realpath(os.path.join(e["directory"], e["file"])): e
                             for e in json.load(f)}
        version = subprocess.run([options.clang_tidy, "--version"], capture_output=True,
                                 text=True, check=True).stdout
        with open(os.path.join(root, ".clang-tidy"), "rb") as f:
            config = f.read()
        common = hashlib.sha256()
        for part in (version.encode(), config, json.dumps(options.extra_arg).encode()):
            common.update(len(part).to_bytes(8, "little") + part)
        self.common = common

    def neutral(self, data):
        """The text with the build folder's and the checkout's paths replaced by placeholders."""
        data = data.replace(self.build.encode(), b"@BUILD@")
        return data.replace(self.root.encode(), b"@SOURCE@")

    def key(self, path, entry):
        arguments = compile_arguments(entry)
        command = preprocess_command(arguments, self.options.clang)
        run = subprocess.run(command, cwd=entry["directory"], capture_output=True, check=False)
        if run.returncode != 0:
            return None  # clang-tidy will report why the file does not compile
        digest = self.common.copy()
        for part in (self.neutral(path.encode()), self.neutral(" ".join(arguments).encode()),
                     self.neutral(run.stdout)):
            digest.update(len(part).to_bytes(8, "little") + part)
        return digest.hexdigest()

    def check(self, path):
        """Returns (found a problem, remembered clean, what clang-tidy printed on a problem)."""
        entry = self.commands.get(path)
        if entry is None:
            return True, False, f"error: {path} is not in {self.build}/compile_commands.json\n"
        key = self.key(path, entry)
        marker = os.path.join(self.options.cache_dir, key[:2], key) if key else None
        if marker and os.path.exists(marker):
            return False, True, ""
        command = [self.options.clang_tidy, "-p", self.build, "-quiet"]
        command += [f"-extra-arg={a}" for a in self.options.extra_arg] + [path]
        run = subprocess.run(command, capture_output=True, text=True, check=False)
        output = run.stdout + run.stderr
        found = run.returncode != 0 or any(FINDING.search(line) for line in output.splitlines())
        if not found and marker:
            os.makedirs(os.path.dirname(marker), exist_ok=True)
            with open(marker, "w", encoding="utf-8") as f:
                f.write(os.path.relpath(path, self.root) + "\n")
        return found, False, output if found else ""


def git(root, *arguments):
    """git's output in `root`, or None when it fails."""
    run = subprocess.run(["git", "-C", root, *arguments], capture_output=True, text=True,
                         check=False)
    return run.stdout if run.returncode == 0 else None


def dependency_groups(build, root):
    """What each object of `build` was compiled from (its sources and every header they include),
    as sets of paths relative to `root`, from the Ninja dependency log. A batch of the unity build
    (cmake/CollidoUnity.cmake) is one object whose set holds all of its sources."""
    run = subprocess.run(["ninja", "-C", build, "-t", "deps"], capture_output=True, text=True,
                         check=False)
    if run.returncode != 0:
        return []
    groups = []
    for line in run.stdout.splitlines():
        if line and not line[0].isspace():
            groups.append(set())
        elif groups and line.strip():
            path = os.path.realpath(os.path.join(build, line.strip()))
            groups[-1].add(os.path.relpath(path, root))
    return groups


def affected(paths, options, root):
    """The subset of `paths` a change since options.since can have affected, with the reason."""
    if git(root, "cat-file", "-e", f"{options.since}^{{commit}}") is None:
        return paths, f"{options.since} is not in this clone's history: every file"
    changed = git(root, "diff", "--name-only", options.since)
    if changed is None:
        return paths, f"git diff against {options.since} failed: every file"
    changed = set(changed.split())
    configuration = sorted(changed.intersection(CONFIGURATION))
    if configuration:
        return paths, f"{', '.join(configuration)} changed since {options.since}: every file"
    groups = dependency_groups(os.path.realpath(options.deps or options.p), root)
    chosen = []
    for path in paths:
        relative = os.path.relpath(path, root)
        mine = [g for g in groups if relative in g]
        # A file the build has no record of is analysed: nothing says it is unaffected.
        if not mine or any(g & changed for g in mine):
            chosen.append(path)
    return chosen, (f"{len(chosen)} of {len(paths)} files include what changed since "
                    f"{options.since[:12]}")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("-p", required=True, help="build folder with compile_commands.json")
    parser.add_argument("-j", type=int, default=os.cpu_count() or 1)
    parser.add_argument("--extra-arg", action="append", default=[],
                        help="argument added to each compile command (as clang-tidy's)")
    parser.add_argument("--cache-dir", default=default_cache_dir())
    parser.add_argument("--clang-tidy", default="clang-tidy")
    parser.add_argument("--clang", default="clang++", help="the preprocessor for the cache key")
    parser.add_argument("--since", help="analyse only what changed since this commit")
    parser.add_argument("--deps", metavar="BUILD_DIR",
                        help="the Ninja build whose dependency log --since reads (default: -p)")
    parser.add_argument("--record-clean", metavar="FILE",
                        help="after a clean full run, write HEAD's commit to FILE")
    parser.add_argument("files", nargs="+")
    options = parser.parse_args()
    if options.since and options.record_clean:
        parser.error("--record-clean needs a full run, not --since")

    root = os.path.realpath(os.path.join(os.path.dirname(__file__), ".."))
    try:
        tidy = Tidy(options, root)
    except FileNotFoundError as e:
        print(f"clang_tidy.py: error: {e.filename}: not found (configure the build folder first, "
              "e.g. tools/configure.sh release; clang-tidy and clang++ must be installed)",
              file=sys.stderr)
        return 2
    paths = [os.path.realpath(f) for f in options.files]
    if options.since:
        paths, reason = affected(paths, options, root)
        print(f"clang-tidy: {reason}")
    problems = cached = 0
    with concurrent.futures.ThreadPoolExecutor(max_workers=max(1, options.j)) as pool:
        for found, remembered, output in pool.map(tidy.check, paths):
            sys.stdout.write(output)
            sys.stdout.flush()
            problems += found
            cached += remembered
    print(f"clang-tidy: {len(paths)} files, {problems} with findings, {cached} known clean "
          f"from an earlier run of the same text ({options.cache_dir})")
    if options.record_clean and not problems:
        head = git(root, "rev-parse", "HEAD")
        if head is None:
            print("clang_tidy.py: error: no commit to record", file=sys.stderr)
            return 2
        with open(options.record_clean, "w", encoding="utf-8") as f:
            f.write(head)
        print(f"clang-tidy: recorded {head.strip()} in {options.record_clean} as clean")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
