#!/usr/bin/env python3
"""Regenerates the example outputs of README.md and docs/animation.md from the current build, or
checks them.

A block is a fenced code block between two markers; the first marker holds the command:

    <!-- begin:output NAME: isopound run configs/x.yaml -o out/readme/x --no-histories -->
    ```
    (what the command prints on stdout)
    ```
    <!-- end:output -->

A number quoted in the prose is a value: the first group of a regular expression matched in the
output of a command, which an output block or a hidden `run` marker names (the same document,
earlier or later; each command runs once):

    <!-- run demo-animate: isopound-post animate out/readme/demo -->
    ... and reaches <!-- value demo-animate /slow motion up to x([0-9]+)/ -->544<!-- /value -->
    inside the demo's impacts.

A command ending in `2>&1` also reads its stderr (notes). Commands run from the repository root,
in the order of the document, with `isopound` replaced by the binary given with --isopound
(default build/isopound) and `isopound-post`, `isopound-pre` by the ones beside it. Commands write under out/ (git-ignored), never over tracked
files. Only the wall time changes from run to run: the "Steps: ..., N ms" line is compared with
its number masked.

    docs/regenerate-readme.py            rewrite README.md and docs/animation.md in place
    docs/regenerate-readme.py --check    exit 1 (and show the difference) if a block or a value is
                                         stale; a document whose commands need ../shared is
                                         skipped when it is absent (exit 77 when every one is),
                                         unless ISOPOUND_REQUIRE_SHARED=1
"""
import argparse
import difflib
import os
import re
import shlex
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
BLOCK = re.compile(
    r"(?P<begin><!-- begin:output (?P<name>[\w.-]+): (?P<command>.+?) -->\n)"
    r"(?P<body>.*?)"
    r"(?P<end><!-- end:output -->)",
    re.S,
)
RUN = re.compile(r"<!-- run (?P<name>[\w.-]+): (?P<command>.+?) -->")
VALUE = re.compile(
    r"(?P<begin><!-- value (?P<name>[\w.-]+) /(?P<pattern>.+?)/ -->)(?P<body>.*?)(?P<end><!-- /value -->)",
    re.S,
)
DOCUMENTS = ["README.md", os.path.join("docs", "animation.md")]
WALL_TIME = re.compile(r"^(Steps: .*, )[0-9.]+( ms)$", re.M)
SKIPPED = 77


def masked(text):
    return WALL_TIME.sub(r"\1<wall time>\2", text)


def needs_shared(command):
    return "../shared/" in command


OUTPUTS = {}  # command -> its output, each command run once


def run(command, isopound):
    if command in OUTPUTS:
        return OUTPUTS[command]
    words = shlex.split(command)
    merge = words[-1] == "2>&1"
    if merge:
        words.pop()
    binaries = {
        "isopound": isopound,
        "isopound-post": os.path.join(os.path.dirname(isopound), "isopound-post"),
        "isopound-pre": os.path.join(os.path.dirname(isopound), "geometry", "pre", "isopound-pre"),
    }
    if words[0] not in binaries:
        raise SystemExit(f"regenerate-readme: a command must start with isopound: {command}")
    words[0] = binaries[words[0]]
    os.makedirs(os.path.join(ROOT, "out", "readme"), exist_ok=True)
    done = subprocess.run(
        words,
        cwd=ROOT,
        stdout=subprocess.PIPE,
        stderr=subprocess.STDOUT if merge else subprocess.PIPE,
        text=True,
    )
    if done.returncode != 0:
        raise SystemExit(
            f"regenerate-readme: '{command}' exited with {done.returncode}:\n{done.stderr or done.stdout}"
        )
    OUTPUTS[command] = done.stdout
    return done.stdout


def regenerate(text, isopound):
    """The document with its blocks and values from fresh runs, and the stale ones."""
    blocks = list(BLOCK.finditer(text))
    commands = {}  # name -> command, in the document's order
    for m in sorted(list(blocks) + list(RUN.finditer(text)), key=lambda m: m.start()):
        commands[m["name"]] = m["command"]
    for command in commands.values():
        run(command, isopound)
    stale = []
    pieces, last = [], 0
    for b in blocks:
        fresh = "```\n" + run(b["command"], isopound) + "```\n"
        if masked(fresh) != masked(b["body"]):
            stale.append((b["name"], b["body"], fresh))
        pieces += [text[last : b.start("body")], fresh]
        last = b.end("body")
    pieces.append(text[last:])
    text = "".join(pieces)
    pieces, last = [], 0
    for v in VALUE.finditer(text):
        if v["name"] not in commands:
            raise SystemExit(f"regenerate-readme: value of an unknown command '{v['name']}'")
        found = re.search(v["pattern"], run(commands[v["name"]], isopound))
        if not found:
            raise SystemExit(
                f"regenerate-readme: /{v['pattern']}/ not in the output of {commands[v['name']]}"
            )
        if found.group(1) != v["body"]:
            stale.append((f"{v['name']} /{v['pattern']}/", v["body"] + "\n", found.group(1) + "\n"))
        pieces += [text[last : v.start("body")], found.group(1)]
        last = v.end("body")
    pieces.append(text[last:])
    return "".join(pieces), stale, commands


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--check", action="store_true", help="compare, do not rewrite")
    parser.add_argument("--isopound", default=os.path.join(ROOT, "build", "isopound"))
    parser.add_argument("--readme", action="append", help="a document (default: %s)" % DOCUMENTS)
    args = parser.parse_args()

    shared = os.path.isdir(os.path.join(ROOT, "..", "shared", "records"))
    required = os.environ.get("ISOPOUND_REQUIRE_SHARED", "0") not in ("", "0")
    checked, any_stale = 0, False
    for document in args.readme or [os.path.join(ROOT, d) for d in DOCUMENTS]:
        with open(document, encoding="utf-8") as f:
            text = f.read()
        if not BLOCK.search(text) and not VALUE.search(text):
            raise SystemExit(f"regenerate-readme: {document} has no blocks or values")
        names = [m["command"] for m in list(BLOCK.finditer(text)) + list(RUN.finditer(text))]
        if not shared and any(needs_shared(c) for c in names):
            if required:
                raise SystemExit("regenerate-readme: ../shared/records is required but absent")
            print(f"regenerate-readme: ../shared/records absent: {document} skipped")
            continue
        fresh, stale, _ = regenerate(text, args.isopound)
        checked += 1
        if args.check:
            for name, old, new in stale:
                print(f"{os.path.relpath(document, ROOT)}: '{name}' differs from a fresh run:")
                sys.stdout.writelines(
                    difflib.unified_diff(
                        masked(old).splitlines(True), masked(new).splitlines(True), "doc", "fresh"
                    )
                )
            any_stale = any_stale or bool(stale)
            continue
        with open(document, "w", encoding="utf-8") as f:
            f.write(fresh)
        print(f"regenerate-readme: {os.path.relpath(document, ROOT)}: {len(stale)} changed")
    if args.check and any_stale:
        print("Regenerate with: python3 docs/regenerate-readme.py")
        return 1
    return 0 if checked else SKIPPED


if __name__ == "__main__":
    sys.exit(main())
