#!/usr/bin/env python3
"""Regenerates the example output blocks of README.md from the current build, or checks them.

A block is a fenced code block between two markers; the first marker holds the command:

    <!-- begin:output NAME: isopound run configs/x.yaml -o out/readme/x --no-histories -->
    ```
    (what the command prints on stdout)
    ```
    <!-- end:output -->

The command runs from the repository root with `isopound` replaced by the binary given with
--isopound (default build/isopound). Commands write under out/ (git-ignored), never over tracked
files. Only the wall time changes from run to run: the "Steps: ..., N ms" line is compared with
its number masked.

    docs/regenerate-readme.py            rewrite README.md in place
    docs/regenerate-readme.py --check    exit 1 (and show the difference) if a block is stale;
                                         exit 77 (skipped) if a command needs ../shared and it is
                                         absent, unless ISOPOUND_REQUIRE_SHARED=1
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
WALL_TIME = re.compile(r"^(Steps: .*, )[0-9.]+( ms)$", re.M)
SKIPPED = 77


def masked(text):
    return WALL_TIME.sub(r"\1<wall time>\2", text)


def needs_shared(command):
    return "../shared/" in command


def run(command, isopound):
    words = shlex.split(command)
    if words[0] == "isopound":
        words[0] = isopound
    elif words[0] == "isopound-pre":
        words[0] = os.path.join(os.path.dirname(isopound), "geometry", "pre", "isopound-pre")
    else:
        raise SystemExit(f"regenerate-readme: a block's command must start with isopound: {command}")
    os.makedirs(os.path.join(ROOT, "out", "readme"), exist_ok=True)
    done = subprocess.run(words, cwd=ROOT, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    if done.returncode != 0:
        raise SystemExit(
            f"regenerate-readme: '{command}' exited with {done.returncode}:\n{done.stderr}"
        )
    return done.stdout


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--check", action="store_true", help="compare, do not rewrite")
    parser.add_argument("--isopound", default=os.path.join(ROOT, "build", "isopound"))
    parser.add_argument("--readme", default=os.path.join(ROOT, "README.md"))
    args = parser.parse_args()

    with open(args.readme, encoding="utf-8") as f:
        text = f.read()
    blocks = list(BLOCK.finditer(text))
    if not blocks:
        raise SystemExit("regenerate-readme: no <!-- begin:output NAME: COMMAND --> blocks")
    shared = os.path.isdir(os.path.join(ROOT, "..", "shared", "records"))
    required = os.environ.get("ISOPOUND_REQUIRE_SHARED", "0") not in ("", "0")
    if not shared and any(needs_shared(b["command"]) for b in blocks):
        if required:
            raise SystemExit("regenerate-readme: ../shared/records is required but absent")
        print("regenerate-readme: ../shared/records absent: skipped")
        return SKIPPED

    stale = []
    pieces, last = [], 0
    for b in blocks:
        fresh = "```\n" + run(b["command"], args.isopound) + "```\n"
        if masked(fresh) != masked(b["body"]):
            stale.append((b["name"], b["body"], fresh))
        pieces += [text[last : b.start("body")], fresh]
        last = b.end("body")
    pieces.append(text[last:])

    if args.check:
        for name, old, new in stale:
            print(f"README block '{name}' differs from a fresh run:")
            sys.stdout.writelines(
                difflib.unified_diff(
                    masked(old).splitlines(True), masked(new).splitlines(True), "README", "fresh"
                )
            )
        if stale:
            print("Regenerate with: python3 docs/regenerate-readme.py")
        return 1 if stale else 0
    with open(args.readme, "w", encoding="utf-8") as f:
        f.write("".join(pieces))
    print(f"regenerate-readme: {len(blocks)} blocks, {len(stale)} changed")
    return 0


if __name__ == "__main__":
    sys.exit(main())
