#!/usr/bin/env python3
"""Writes the book's generated pages and figures with the `pendulum` binary.

    python3 book/generate.py PENDULUM

- `src/reference/`: the index (`pendulum --help`) and one page a command,
  `pendulum <command> --help` as the binary prints it (`fit decay` is
  `fit-decay.md`). The commands the binary lists and the reference pages
  SUMMARY.md lists must be the same set, or nothing is written and the
  difference is named.
- `src/gallery/`: every figure of the gallery, made by running the
  commands of `src/gallery.md`'s `sh` blocks in order, in a scratch folder
  that sees the repository's `examples/` and `crates/`. The figures the
  commands write (`.svg`, in any folder below the scratch one) and the
  images the page shows (`gallery/…`) must be the same set.

Neither folder is committed (book/.gitignore): they are the binary's own
words and drawings, made again at every build.
"""

import os
import re
import shutil
import subprocess
import sys
import tempfile

BOOK = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(BOOK)
SRC = os.path.join(BOOK, "src")


def fail(message):
    print(f"error: {message}", file=sys.stderr)
    sys.exit(1)


def help_text(pendulum, path):
    out = subprocess.run(
        [pendulum, *path, "--help"], capture_output=True, text=True, check=False
    )
    if out.returncode != 0:
        fail(f"`pendulum {' '.join(path)} --help` failed: {out.stderr}")
    return out.stdout


def subcommands(text):
    """The (name, summary) pairs of a help text's `Commands:` list."""
    found, inside = [], False
    for line in text.splitlines():
        if line.startswith("Commands:"):
            inside = True
            continue
        if inside:
            if not line.strip():
                break
            if line.startswith("  ") and not line.startswith("   "):
                name, _, summary = line.strip().partition(" ")
                if name != "help":
                    found.append((name, summary.strip()))
    return found


def commands(pendulum):
    """Every command path the binary lists, depth first, with its summary
    and help text."""
    listed = []

    def walk(path):
        for name, summary in subcommands(help_text(pendulum, path)):
            sub = path + [name]
            listed.append((sub, summary, help_text(pendulum, sub)))
            walk(sub)

    walk([])
    return listed


def page(path):
    return "-".join(path) + ".md"


def fenced(text):
    return "```text\n" + text.rstrip("\n") + "\n```\n"


def write_reference(pendulum):
    listed = commands(pendulum)
    summary = open(os.path.join(SRC, "SUMMARY.md"), encoding="utf-8").read()
    in_summary = set(re.findall(r"\(reference/([^)#]+\.md)\)", summary)) - {"index.md"}
    from_binary = {page(path) for path, _, _ in listed}
    if in_summary != from_binary:
        missing = sorted(from_binary - in_summary)
        stale = sorted(in_summary - from_binary)
        fail(
            "the commands the binary lists and the reference pages SUMMARY.md lists differ:"
            + (f"\n  commands without a page in SUMMARY.md: {missing}" if missing else "")
            + (f"\n  pages in SUMMARY.md of no command: {stale}" if stale else "")
        )
    out = os.path.join(SRC, "reference")
    shutil.rmtree(out, ignore_errors=True)
    os.makedirs(out)
    note = "*Written at the book's build from the binary's own help (`{}`).*\n"
    lines = [
        "# The commands\n",
        "Every command's help, as the binary prints it: `pendulum COMMAND --help`.",
        "The same text is what a terminal shows; this book's chapters say what the",
        "commands are for and how to read their output.\n",
    ]
    for path, summary_line, _ in listed:
        indent = "  " * (len(path) - 1)
        lines.append(f"{indent}- [`pendulum {' '.join(path)}`]({page(path)}): {summary_line}")
    lines.append("")
    lines.append(fenced(help_text(pendulum, [])))
    lines.append(note.format("pendulum --help"))
    with open(os.path.join(out, "index.md"), "w", encoding="utf-8") as f:
        f.write("\n".join(lines))
    for path, _, text in listed:
        name = "pendulum " + " ".join(path)
        with open(os.path.join(out, page(path)), "w", encoding="utf-8") as f:
            f.write(f"# {name}\n\n{fenced(text)}\n{note.format(name + ' --help')}")
    return len(listed) + 1


def sh_commands(markdown):
    """The commands of a page's `sh` blocks (continuation lines joined, `#`
    comments dropped), as the CLI tests read them."""
    found, inside, pending = [], False, ""
    for line in markdown.splitlines():
        if line.startswith("```"):
            inside = line == "```sh"
            continue
        if not inside or line.lstrip().startswith("#") or not line.strip():
            continue
        if line.rstrip().endswith("\\"):
            pending += line.rstrip()[:-1]
            continue
        command = pending + line
        pending = ""
        cut = command.find(" #")
        if cut >= 0:
            command = command[:cut]
        found.append(" ".join(command.split()))
    return found


def write_gallery(pendulum):
    gallery = open(os.path.join(SRC, "gallery.md"), encoding="utf-8").read()
    shown = set(re.findall(r"\]\(gallery/([^)]+)\)", gallery))
    out = os.path.join(SRC, "gallery")
    with tempfile.TemporaryDirectory() as scratch:
        bin_dir = os.path.join(scratch, ".bin")
        work = os.path.join(scratch, "work")
        os.makedirs(bin_dir)
        os.makedirs(work)
        os.symlink(os.path.abspath(pendulum), os.path.join(bin_dir, "pendulum"))
        for name in ["examples", "crates"]:
            os.symlink(os.path.join(ROOT, name), os.path.join(work, name))
        env = dict(os.environ, PATH=bin_dir + os.pathsep + os.environ.get("PATH", ""))
        for command in sh_commands(gallery):
            ran = subprocess.run(
                ["bash", "-o", "pipefail", "-c", command],
                cwd=work,
                env=env,
                capture_output=True,
                text=True,
                check=False,
            )
            if ran.returncode != 0:
                fail(f"the gallery's `{command}` failed:\n{ran.stderr}")
        drawn = set()
        for folder, dirs, files in os.walk(work):
            dirs[:] = [d for d in dirs if not os.path.islink(os.path.join(folder, d))]
            for f in files:
                if f.endswith(".svg"):
                    drawn.add(os.path.relpath(os.path.join(folder, f), work))
        if drawn != shown:
            fail(
                "the figures the gallery's commands draw and the images gallery.md shows differ:"
                + f"\n  drawn, not shown: {sorted(drawn - shown)}"
                + f"\n  shown, not drawn: {sorted(shown - drawn)}"
            )
        shutil.rmtree(out, ignore_errors=True)
        for name in sorted(drawn):
            target = os.path.join(out, name)
            os.makedirs(os.path.dirname(target), exist_ok=True)
            shutil.copyfile(os.path.join(work, name), target)
    return len(drawn)


def main():
    if len(sys.argv) != 2:
        fail("usage: python3 book/generate.py PENDULUM")
    pendulum = os.path.abspath(sys.argv[1])
    if not os.access(pendulum, os.X_OK):
        fail(f"no pendulum binary at {pendulum}")
    pages = write_reference(pendulum)
    figures = write_gallery(pendulum)
    print(f"generate.py: {pages} reference pages, {figures} gallery figures")


if __name__ == "__main__":
    main()
