#!/usr/bin/env python3
"""Run the hardening audit's cases against a `pendulum` binary.

    python3 tools/audit/run_cases.py BINARY [--only PREFIX] [--cases FILE]
                                     [--jobs N] [--results FILE.jsonl] [-v]

Each case (crates/pendulum-cli/tests/data/audit/cases.jsonl, made by
make_cases.py) runs in a fresh scratch folder holding a copy of fixtures/
and of the files of examples/, after its "setup" (symlink, hardlink, mkdir,
write, mkfifo). Every file and folder is snapshotted (path -> sha256; links
by their target, never followed) before the run. The binary runs with stdin
at end of file, a CPU limit of 10 s (RLIMIT_CPU), a wall timeout of 30 s,
and, to protect the machine, files of at most 1 GiB (RLIMIT_FSIZE) and 4 GiB
of address space (RLIMIT_AS).

A case fails (classes, several may apply):

  crash              exit status not 0 or 2 (101 panic, 134 abort, a signal:
                     SIGXCPU is the CPU limit, SIGXFSZ the file limit), or
                     the wall timeout
  panic-text         stderr says "panicked", "backtrace" or "please report"
  refusal-stdout     exit 2 with something on stdout
  refusal-format     exit 2 and stderr not exactly one line "error: ..."
  nan-inf-word       a word of stdout/stderr is nan/inf/infinity (any case)
                     that the user did not type in the arguments
  nan-inf-word-from-file   the same, but the word is in an input file the
                     arguments name (the message quotes the user's file)
  file-changed       a file that existed before the run changed or vanished
  new-file-on-refusal  exit 2 and a new file or folder appeared
  partial-left       a file whose name contains ".partial" remains
  long-digits        stdout or stderr holds a run of 40 or more digits
  accepted-refusal   (soft) "expect" is "refuse" but the exit status is 0
  refused-legitimate (soft, informational) "expect" is "ok" but exit 2
  nan-inf-in-output-file (soft, extra) a new text output file holds a
                     nan/inf word the user did not type

Prints one line per failing case (id, classes, exit status, the first 200
characters of stderr), then the totals per class and the number of cases.
Exit status: 0 when no case failed in a hard class, 1 otherwise.
"""

import argparse
import concurrent.futures
import hashlib
import json
import os
import re
import resource
import shutil
import signal
import stat
import subprocess
import sys
import tempfile
import threading
import time
from pathlib import Path

HERE = Path(__file__).resolve().parent
ROOT = HERE.parent.parent
AUDIT = ROOT / "crates" / "pendulum-cli" / "tests" / "data" / "audit"

CPU_SECONDS = 10
WALL_SECONDS = 30
FSIZE = 1 << 30
ADDRESS_SPACE = 4 << 30
MAX_CAPTURE = 16 << 20  # bytes of stdout/stderr examined

HARD = ["crash", "panic-text", "refusal-stdout", "refusal-format", "nan-inf-word", "nan-inf-word-from-file",
        "file-changed", "new-file-on-refusal", "partial-left", "long-digits"]
SOFT = ["accepted-refusal", "refused-legitimate", "nan-inf-in-output-file"]

BAD_WORDS = {"nan", "inf", "infinity", "-inf", "+inf", "-nan"}
SPLIT = re.compile(r"[^A-Za-z0-9._]+")
TEXT_OUTPUTS = (".csv", ".json", ".toml", ".svg", ".html", ".txt", ".htm")


def words(text):
    """The words of a text, lower case, dots at their ends removed."""
    out = set()
    for w in SPLIT.split(text):
        w = w.strip(".").lower()
        if w:
            out.add(w)
    return out


def typed_words(text):
    """The words a user typed: as `words`, and also split at dots, so that
    'nan..3' counts as typing 'nan'."""
    return words(text) | {w.lower() for w in re.split(r"[^A-Za-z0-9_]+", text) if w}


def bad_words(text, typed):
    return sorted(w for w in words(text) if w in BAD_WORDS and w not in typed)


def preexec():
    os.setsid()
    resource.setrlimit(resource.RLIMIT_CPU, (CPU_SECONDS, CPU_SECONDS + 1))
    resource.setrlimit(resource.RLIMIT_FSIZE, (FSIZE, FSIZE))
    try:
        resource.setrlimit(resource.RLIMIT_AS, (ADDRESS_SPACE, ADDRESS_SPACE))
    except (ValueError, OSError):
        pass
    resource.setrlimit(resource.RLIMIT_CORE, (0, 0))
    signal.signal(signal.SIGPIPE, signal.SIG_DFL)


def do_setup(steps, work):
    for step in steps or []:
        op, name = step[0], step[1]
        path = os.path.join(work, name)
        if op == "symlink":
            os.symlink(step[2], path)
        elif op == "hardlink":
            os.link(os.path.join(work, step[2]), path)
        elif op == "mkdir":
            os.makedirs(path, exist_ok=True)
        elif op == "write":
            with open(path, "w", encoding="utf-8") as f:
                f.write(step[2])
        elif op == "mkfifo":
            os.mkfifo(path)
        else:
            raise ValueError(f"unknown setup step {step!r}")


def snapshot(work):
    """relative path -> a fingerprint: ('dir',), ('link', target),
    ('file', sha256), ('fifo',), ('other',). Links are not followed."""
    snap = {}
    for dirpath, dirnames, filenames in os.walk(work, followlinks=False):
        rel_dir = os.path.relpath(dirpath, work)
        for d in list(dirnames):
            full = os.path.join(dirpath, d)
            rel = os.path.normpath(os.path.join(rel_dir, d))
            if os.path.islink(full):
                snap[rel] = ("link", os.readlink(full))
                dirnames.remove(d)
            else:
                snap[rel] = ("dir",)
        for f in filenames:
            full = os.path.join(dirpath, f)
            rel = os.path.normpath(os.path.join(rel_dir, f))
            try:
                st = os.lstat(full)
            except OSError:
                continue
            if stat.S_ISLNK(st.st_mode):
                snap[rel] = ("link", os.readlink(full))
            elif stat.S_ISREG(st.st_mode):
                h = hashlib.sha256()
                try:
                    with open(full, "rb") as fh:
                        for chunk in iter(lambda: fh.read(1 << 20), b""):
                            h.update(chunk)
                    snap[rel] = ("file", h.hexdigest())
                except OSError as e:
                    snap[rel] = ("file", f"unreadable: {e}")
            elif stat.S_ISFIFO(st.st_mode):
                snap[rel] = ("fifo",)
            else:
                snap[rel] = ("other",)
    return snap


def read_capped(path):
    with open(path, "rb") as f:
        data = f.read(MAX_CAPTURE)
    return data.decode("utf-8", errors="replace")


def input_file_words(args, work):
    """The words of the files (in the scratch folder) that the arguments name."""
    out = set()
    for a in args:
        if not a or a.startswith("/dev/") or a.startswith("/proc/"):
            continue
        p = os.path.join(work, a)
        try:
            if os.path.isfile(p):
                with open(p, "rb") as f:
                    out |= typed_words(f.read(4 << 20).decode("utf-8", errors="replace"))
        except OSError:
            pass
    return out


def describe_signal(n):
    try:
        name = signal.Signals(n).name
    except ValueError:
        name = f"signal {n}"
    extra = {"SIGXCPU": " (CPU limit)", "SIGXFSZ": " (file size limit)", "SIGKILL": " (killed)"}.get(name, "")
    return name + extra


def run_case(case, binary, fixtures, examples):
    args = case["args"]
    tmp = tempfile.mkdtemp(prefix="pendulum-audit-")
    work = os.path.join(tmp, "work")
    try:
        shutil.copytree(fixtures, work, symlinks=True)
        for p in sorted(Path(examples).iterdir()):
            if p.is_file():
                shutil.copy2(p, os.path.join(work, p.name))
        do_setup(case.get("setup"), work)
        before = snapshot(work)
        out_path = os.path.join(tmp, "stdout")
        err_path = os.path.join(tmp, "stderr")
        timed_out = False
        started = time.monotonic()
        proc = None
        for attempt in range(10):  # the binary may be replaced by a build meanwhile
            try:
                with open(out_path, "wb") as out, open(err_path, "wb") as err:
                    r, w = os.pipe()
                    os.close(w)  # stdin: at end of file at once
                    try:
                        proc = subprocess.Popen([binary] + args, cwd=work, stdin=r, stdout=out, stderr=err,
                                                preexec_fn=preexec, close_fds=True)
                    finally:
                        os.close(r)
                    try:
                        proc.wait(timeout=WALL_SECONDS)
                    except subprocess.TimeoutExpired:
                        timed_out = True
                        try:
                            os.killpg(proc.pid, signal.SIGKILL)
                        except ProcessLookupError:
                            pass
                        proc.wait()
                break
            except OSError as e:
                if attempt == 9:
                    return {"id": case["id"], "classes": ["runner-error"], "code": None,
                            "stderr": f"could not run the binary: {e}", "seconds": 0.0}
                time.sleep(3)
        seconds = time.monotonic() - started
        # wait for any process the binary left behind in its group to end
        try:
            os.killpg(proc.pid, signal.SIGKILL)
        except (ProcessLookupError, PermissionError):
            pass
        code = proc.returncode
        stdout = read_capped(out_path)
        stderr = read_capped(err_path)
        after = snapshot(work)
        classes = []
        notes = []
        if timed_out:
            classes.append("crash")
            notes.append(f"wall timeout {WALL_SECONDS} s")
        elif code not in (0, 2):
            classes.append("crash")
            if code < 0:
                notes.append(describe_signal(-code))
            elif code == 101:
                notes.append("exit 101 (panic)")
            elif code == 134:
                notes.append("exit 134 (abort)")
            else:
                notes.append(f"exit {code}")
        low = stderr.lower()
        if "panicked" in low or "backtrace" in low or "please report" in low:
            classes.append("panic-text")
        if code == 2 and not timed_out:
            if stdout != "":
                classes.append("refusal-stdout")
            lines = stderr.split("\n")
            if lines and lines[-1] == "":
                lines = lines[:-1]
            if len(lines) != 1 or not lines[0].startswith("error: "):
                classes.append("refusal-format")
        typed = set()
        for a in args:
            typed |= typed_words(a)
        bad = bad_words(stdout + "\n" + stderr, typed)
        if bad:
            file_words = input_file_words(args, work)
            if all(w in file_words for w in bad):
                classes.append("nan-inf-word-from-file")
            else:
                classes.append("nan-inf-word")
            notes.append("words " + ",".join(bad))
        changed = []
        for path, fp in before.items():
            now = after.get(path)
            if now is None:
                changed.append(f"{path} deleted")
            elif now != fp:
                changed.append(f"{path} changed")
        if changed:
            classes.append("file-changed")
            notes.append("; ".join(changed[:5]))
        new = sorted(set(after) - set(before))
        if code == 2 and new:
            classes.append("new-file-on-refusal")
            notes.append("new: " + ", ".join(new[:5]))
        partial = sorted(p for p in after if ".partial" in os.path.basename(p))
        if partial:
            classes.append("partial-left")
            notes.append("partial: " + ", ".join(partial[:5]))
        if re.search(r"\d{40,}", stdout) or re.search(r"\d{40,}", stderr):
            classes.append("long-digits")
        if case["expect"] == "refuse" and code == 0 and not timed_out:
            classes.append("accepted-refusal")
        if case["expect"] == "ok" and code == 2 and not timed_out:
            classes.append("refused-legitimate")
        if code == 0 and not timed_out:
            for path in new:
                if after[path][0] != "file" or not path.lower().endswith(TEXT_OUTPUTS):
                    continue
                try:
                    with open(os.path.join(work, path), "rb") as f:
                        text = f.read(8 << 20).decode("utf-8", errors="replace")
                except OSError:
                    continue
                fb = bad_words(text, typed)
                if fb:
                    classes.append("nan-inf-in-output-file")
                    notes.append(f"{path}: words {','.join(fb)}")
                    break
        return {"id": case["id"], "classes": classes, "code": None if timed_out else code,
                "stderr": stderr, "stdout_head": stdout[:300], "notes": notes, "seconds": round(seconds, 3),
                "expect": case["expect"], "args": args}
    finally:
        shutil.rmtree(tmp, ignore_errors=True)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("binary")
    ap.add_argument("--only", default="", help="run only the cases whose id starts with this")
    ap.add_argument("--cases", default=str(AUDIT / "cases.jsonl"))
    ap.add_argument("--fixtures", default=str(AUDIT / "fixtures"))
    ap.add_argument("--examples", default=str(ROOT / "examples"))
    ap.add_argument("--jobs", type=int, default=2, help="parallel cases, at most 2")
    ap.add_argument("--results", help="write every case's result to this JSON-lines file")
    ap.add_argument("-v", "--verbose", action="store_true", help="progress on stderr")
    opts = ap.parse_args()
    binary = os.path.abspath(opts.binary)
    jobs = max(1, min(2, opts.jobs))
    with open(opts.cases, encoding="utf-8") as f:
        cases = [json.loads(line) for line in f if line.strip()]
    # A private copy of fixtures and examples, so that regenerating them
    # (make_cases.py) while the audit runs does not disturb it.
    source = tempfile.mkdtemp(prefix="pendulum-audit-source-")
    shutil.copytree(opts.fixtures, os.path.join(source, "fixtures"), symlinks=True)
    os.makedirs(os.path.join(source, "examples"))
    for p in sorted(Path(opts.examples).iterdir()):
        if p.is_file():
            shutil.copy2(p, os.path.join(source, "examples", p.name))
    opts.fixtures = os.path.join(source, "fixtures")
    opts.examples = os.path.join(source, "examples")
    cases = [c for c in cases if c["id"].startswith(opts.only)]
    order = {c["id"]: i for i, c in enumerate(cases)}
    results = []
    lock = threading.Lock()
    done = [0]

    def one(case):
        r = run_case(case, binary, opts.fixtures, opts.examples)
        with lock:
            done[0] += 1
            if opts.verbose and (done[0] % 100 == 0 or r["classes"]):
                print(f"[{done[0]}/{len(cases)}] {r['id']} {','.join(r['classes']) or 'pass'} ({r['seconds']} s)",
                      file=sys.stderr, flush=True)
        return r

    try:
        with concurrent.futures.ThreadPoolExecutor(max_workers=jobs) as pool:
            for r in pool.map(one, cases):
                results.append(r)
    finally:
        shutil.rmtree(source, ignore_errors=True)
    results.sort(key=lambda r: order[r["id"]])
    if opts.results:
        with open(opts.results, "w", encoding="utf-8") as f:
            for r in results:
                f.write(json.dumps(r, ensure_ascii=False) + "\n")
    totals = {}
    for r in results:
        if not r["classes"]:
            continue
        for c in r["classes"]:
            totals[c] = totals.get(c, 0) + 1
        err = r["stderr"].replace("\n", "\\n")[:200]
        note = f" [{'; '.join(r.get('notes', []))}]" if r.get("notes") else ""
        print(f"{r['id']}\t{','.join(r['classes'])}\texit={r['code']}{note}\t{err}")
    print()
    print("Totals per class (cases):")
    for c in HARD + SOFT + ["runner-error"]:
        if c in totals:
            print(f"  {c:28s} {totals[c]}")
    failing = sum(1 for r in results if any(c in HARD or c == "runner-error" for c in r["classes"]))
    soft = sum(1 for r in results if r["classes"] and not any(c in HARD for c in r["classes"]))
    print(f"Cases: {len(results)}; failing (hard): {failing}; soft only: {soft}; passing: "
          f"{sum(1 for r in results if not r['classes'])}")
    sys.exit(1 if failing else 0)


if __name__ == "__main__":
    main()
