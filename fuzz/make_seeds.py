#!/usr/bin/env python3
"""Writes the fuzzers' seed corpora (fuzz/corpus/<target>/) and the model dictionary
(fuzz/dict/model.dict) from the repository's configs and readers. Seeds are small derived files:
configs without their comments, and record snippets written here (no recorded data is copied).
Run from anywhere: python3 fuzz/make_seeds.py. Inputs libFuzzer adds later (new coverage) sit
beside these in the same directories."""
import glob
import os
import re

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
CORPUS = os.path.join(ROOT, "fuzz", "corpus")


def strip_comments(text):
    out = []
    for line in text.splitlines():
        if not line.strip() or line.lstrip().startswith("#"):
            continue
        out.append(re.sub(r"\s+#\s.*$", "", line))
    return "\n".join(out) + "\n"


def write(target, name, data):
    os.makedirs(os.path.join(CORPUS, target), exist_ok=True)
    mode = "wb" if isinstance(data, bytes) else "w"
    with open(os.path.join(CORPUS, target, name), mode) as f:
        f.write(data)


def models():
    for path in sorted(glob.glob(os.path.join(ROOT, "configs", "*.yaml"))):
        name = os.path.basename(path)
        if name.startswith("geometry-"):
            continue
        write("model", "seed-" + name, strip_comments(open(path).read()))
    write("model", "seed-issue28-hang.yaml", "    b: 1\n,c: 2")


def studies():
    for path in sorted(glob.glob(os.path.join(ROOT, "configs", "studies", "*.yaml"))):
        text = strip_comments(open(path).read())
        # fuzz_study puts the two models it needs beside the study (fuzz_study.cpp).
        text = re.sub(r"^model: \.\./3d-.*$", "model: model3d.yaml", text, flags=re.M)
        text = re.sub(r"^model: \.\./.*$", "model: model.yaml", text, flags=re.M)
        write("study", "seed-" + os.path.basename(path), text)


def polygon_pairs():
    path = os.path.join(ROOT, "configs", "geometry-overlap-example.yaml")
    write("polygon_pairs", "seed-example.yaml", strip_comments(open(path).read()))
    write("polygon_pairs", "seed-clockwise.yaml",
          "pairs:\n  - a: [[0, 0], [0, 1], [1, 1], [1, 0]]\n"
          "    b: [[0.5 m, 0.5 m], [150 cm, 50 cm], [1.5, 1.5]]\n")


# The record target's first byte chooses how the file is read (fuzz_record.cpp): format
# (byte % 3: auto, PEER, columns), column ((byte >> 2) % 3), time column ((byte >> 4) % 4 - 1),
# dt 0.01 s (0x40), extension .AT2 (0x80).
PEER = ("PEER NGA STRONG MOTION DATABASE RECORD\n"
        "SYNTHETIC SEED, 2026, FUZZ, 000\n"
        "ACCELERATION TIME SERIES IN UNITS OF G\n"
        "NPTS=   12, DT=   .0050 SEC\n"
        "  .1000000E-02  .2000000E-02 -.3000000E-02  .4000000E-02 -.5000000E-02\n"
        "  .6000000E-02 -.7000000E-02  .8000000E-02 -.9000000E-02  .1000000E-01\n"
        " -.1100000E-01  .1200000E-01\n")
PEER_VALUES_FIRST = ("SYNTHETIC SEED\nNOTE\nACCELERATION IN G\n"
                     "    6    0.0100    NPTS, DT\n"
                     "  1.0E-3  -2.0E-3  3.0E-3\n  -4.0E-3  5.0E-3  -6.0E-3\n")
COLUMNS_TIME = "# t a\n0.00 0.001\n0.01 -0.002\n0.02 0.003\n0.03 -0.004\n"
COLUMNS_CSV = "0.001, 0.1\n-0.002, 0.2\n0.003; 0.3\n% end\n"


def records():
    write("record", "seed-peer-auto-at2", bytes([0x80]) + PEER.encode())
    write("record", "seed-peer-explicit", bytes([0x01]) + PEER.encode())
    write("record", "seed-peer-values-first", bytes([0x80]) + PEER_VALUES_FIRST.encode())
    write("record", "seed-columns-time", bytes([0x02 | (1 << 2) | (1 << 4)]) + COLUMNS_TIME.encode())
    write("record", "seed-columns-dt", bytes([0x02 | 0x40]) + COLUMNS_CSV.encode())
    write("record", "seed-auto-columns-dt", bytes([0x40]) + COLUMNS_CSV.encode())


def dictionary():
    keys = set()
    for rel in ["solver/io/model_input.cpp", "solver/io/model_input3d.cpp",
                "solver/io/friction_pendulum_input.h", "solver/study/study_spec.cpp"]:
        keys |= set(re.findall(r'"([a-zA-Z_][a-zA-Z_0-9]*)"', open(os.path.join(ROOT, rel)).read()))
    units = set(re.findall(r'\{"([^"\\]+)", [^,]+, dim::',
                           open(os.path.join(ROOT, "solver/io/units.cpp")).read()))
    syntax = ["---", "...", ": ", "- ", "[", "]", "{", "}", ", ", "&a ", "*a", "~", '"', "'", "|\n",
              ">\n", "? ", "!!str ", "%YAML 1.2", "#", "\n  ", "\n    ", "1e308", "-0", "nan",
              ".inf", "true", "false"]
    esc = lambda t: t.replace("\\", "\\\\").replace('"', '\\"').replace("\n", "\\x0A")
    with open(os.path.join(ROOT, "fuzz", "dict", "model.dict"), "w") as d:
        d.write("# libFuzzer dictionary for the model and study readers: their keys (the readers'\n"
                "# string literals), the units of units.cpp and YAML syntax. fuzz/make_seeds.py.\n")
        for k in sorted(keys):
            d.write('key_%s="%s:"\n' % (k, k))
        for i, u in enumerate(sorted(units)):
            d.write('unit_%d=" %s"\n' % (i, esc(u)))
        for i, t in enumerate(syntax):
            d.write('yaml_%d="%s"\n' % (i, esc(t)))


if __name__ == "__main__":
    models()
    studies()
    polygon_pairs()
    records()
    dictionary()
