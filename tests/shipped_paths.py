#!/usr/bin/env python3
"""The shipped-path matrix (issue 37): every shipped model through every command a user takes, and
every command line of README.md run as written. Each command must end with its documented exit
code (README "exit code": 0 ok, 2 bad input, 3 diverged, 1 other), never by a signal, a sanitizer
report or a time-out, print no nan/inf, and write no nan/inf (nor a null where a number belongs)
into the JSON and CSV files it writes.

    shipped_paths.py model configs/3d-xy5.yaml   check, run --until T (histories on), modes,
                                                 isopound-pre, pushover (3D: default 0 deg, 90 deg,
                                                 30 deg); isopound-post plot, animate and
                                                 floor-spectra on the run, pushover on the
                                                 first push that succeeded
    shipped_paths.py model demo                  the same on the model.yaml `isopound demo` writes
                                                 (docs/animation.md: "start your own from it")
    shipped_paths.py study configs/studies/x.yaml  isopound sweep --dry-run: every case builds
    shipped_paths.py readme SECTION              the commands of one "## " section of README.md in
                                                 document order, in a scratch copy of the tree
    shipped_paths.py list                        the test names (CTest registers one per line)

Common options: --bin DIR (isopound, isopound-post, isopound-pre), --scratch DIR (emptied first),
--until T (default 5 s; the sanitizer tree passes a shorter one), --timeout S (per command).
Exit 0 when everything ends as documented (or as KNOWN_FAILURES records), 1 otherwise, 77
(skipped) when ../shared/records is absent and ISOPOUND_REQUIRE_SHARED is not set.
"""
import argparse
import fnmatch
import json
import os
import re
import shlex
import shutil
import signal
import subprocess
import sys
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SKIPPED = 77
DOCUMENTED_EXIT = "0"  # every command of the matrix and of the README is documented to succeed

# ---------------------------------------------------------------------------------------------
# Known failures, as (command, model or README command) -> the defect. The matrix lands green with
# these failing; each entry names its defect (issue 37 unless said otherwise). Remove an entry when
# its fix lands: a listed command that passes fails the test ("fixed: remove ..."), so the list
# cannot go stale. `fails_as` is what it does today; a listed command that starts to crash (signal,
# sanitizer report, time-out) where it did not is a failure too.
#   command: the matrix label (check, run, modes, pre, pushover, pushover 90 deg, pushover 30 deg,
#            post plot, post animate, post floor-spectra, post pushover, post pushover 90 deg, ...)
#            or "readme" for a README command line;
#   target:  a config name pattern (fnmatch, no .yaml; "demo" for the demo's model.yaml) or, for
#            "readme", the command line exactly as README.md writes it.
# ---------------------------------------------------------------------------------------------
class Known:
    def __init__(self, command, target, fails_as, defect, workaround=None, but=()):
        self.command, self.target, self.fails_as, self.defect = command, target, fails_as, defect
        self.workaround = workaround  # README only: a shell step after which the line is rerun
        self.but = but  # targets the pattern matches that do not fail

    def matches(self, command, target):
        if self.command != command:
            return False
        if command == "readme":
            return self.target == target
        return fnmatch.fnmatchcase(target, self.target) and target not in self.but


KNOWN_FAILURES = [
    # Empty: every failure the matrix found when it was written (the 3D mid-storey crash, the
    # first-mode pushover along an axis of symmetric 3D buildings, modes and isopound-pre of
    # yielding 2D storeys, floor-spectra and animate refusing their defaults, sweep --db into a
    # missing folder) is fixed, each with its regression test (issue 37).
]

# Run time caps per model (s): where the default T would cost minutes. 3d-floor-to-column's first
# struck-column contact is at 4.085 s; every further 0.01 s of contact costs 10-20 s in Release
# (to 4.2 s: 200 s), so the matrix stops just after contact begins.
UNTIL_CAP = {"3d-floor-to-column": 4.09}

# JSON keys whose null is a value, not a NaN (nlohmann::json writes a NaN as null): an event that
# never happened (first_yield_time_s, first_impact_time_s, first_bottoming_s, a pushover's
# first_yield or capping), no contact episode (max_episode_net_work_*), no --until
# (end_of_analysis.requested_end_s), no spread warning (ensemble.spread_warning), a rotation of
# round-off size without contacts (unobstructed_3d ... theta_amplification).
NULL_KEYS = re.compile(
    r"^(first_.*|.*_time_s|first_bottoming_s|max_episode_net_work_(J|relative)|capping|first_yield"
    r"|requested_end_s|spread_warning|theta_amplification)$")

# ---------------------------------------------------------------------------------------------
# README command lines
# ---------------------------------------------------------------------------------------------
COMMAND_START = re.compile(
    r"^(\./build/|bash |cmake |ctest |isopound|nice |paraview |pvpython |xvfb-run |mpirun )")
SUBCOMMANDS = {
    "isopound": {"run", "demo", "modes", "check", "geometry", "overlap", "pushover", "sweep",
                 "export"},
    "isopound-post": {"plot", "animate", "spectra", "floor-spectra", "polar", "sweep-plot",
                      "pushover"},
    "isopound-pre": set(),
}
# A synopsis, not a command: [options], ..., or an upper-case placeholder (MODEL, DIR, N).
SYNOPSIS = re.compile(r"\[|\.\.\.|…|<\w+>|(?:^|\s)[A-Z][A-Z0-9_]*(?:\.\w+)?(?=\s|$)")

# README lines that are not run as written, and why (exact text as in README.md).
NOT_RUN = {
    "bash .ci/setup --tests && ctest --test-dir build --output-on-failure -j2":
        "the whole test suite, of which this matrix is a part (.ci/setup installs packages)",
    "cmake --install build":
        "installs into the system; the build's binaries are put first on PATH instead",
    "paraview --script=isopound-out/animation/view.py": "the interactive ParaView GUI",
    "paraview --script=out/runs/kv/animation/view.py": "the interactive ParaView GUI",
    "paraview --script=view.py": "the interactive ParaView GUI",
    "pvpython view.py": "names the command, not a path; the xvfb-run pvpython line runs it",
    "./build/bench/isopound_bench": "benchmark (minutes; not built in the sanitizer tree)",
    "./build/bench/isopound_geometry_bench": "benchmark (not built in the sanitizer tree)",
    "nice ./build/bench/isopound_battery --gaps 10 --laws kelvin_voigt --cache /tmp/refs":
        "benchmark battery (minutes; not built in the sanitizer tree)",
}
# README lines run with a stated change: (text as written) -> (text run, why).
RUN_AS = {
    "bash .ci/setup && ./build/isopound demo":
        ("./build/isopound demo", ".ci/setup (package install and build) is done by CI before"),
    "isopound check model.yaml":
        ("isopound check model.yaml", "model.yaml: a copy of configs/tutorial.yaml (your model)"),
    # The whole 44 s record gives 1266 frames: the --render video line then takes over 5 minutes.
    "isopound run configs/chapter4-3storey-kelvin_voigt.yaml -o out/runs/kv":
        ("isopound run configs/chapter4-3storey-kelvin_voigt.yaml -o out/runs/kv --until 5",
         "the whole record's video takes minutes; 5 s holds the --preview time 4.805 s"),
    "isopound sweep configs/studies/<study>.yaml":
        ("isopound sweep configs/studies/tutorial-3d.yaml",
         "<study>: tutorial-3d, the study the README says runs in a second"),
}
# Commands that need ParaView's pvpython (skipped without it unless ISOPOUND_REQUIRE_PARAVIEW=1).
NEEDS_PVPYTHON = re.compile(r"--render|pvpython")
# A study too long to run whole (README: 3030 runs, 250 s on one core): run on the same study with
# every run stopped at T (`set: analysis.t_end`), into the same database; stated in the listing.
SHORTENED_STUDIES = {"configs/studies/chapter4-gap.yaml"}
# README commands that need the output of a command written later on the page.
NEEDS_FIRST = {
    "isopound-post sweep-plot out/studies/chapter4-gap.db --x gap --y drift_ratio --group "
    "variant --where record=RSN1084_NORTHR_SCS052":
        "isopound sweep configs/studies/chapter4-gap.yaml -j 1 --db out/studies/chapter4-gap.db",
}
# `study.db` of the polar and export lines is the reader's own study: a small one with the axes
# those lines name (angle, gap) and outputs (u_base, F_impact), made in the scratch copy first.
STUDY_DB_FIXTURE = """\
name: study
model: configs/3d-xy5.yaml
set:
  ground_motion:
    L: {pulse: {amplitude: 0.8 m/s, period: 2 s, duration: 3 s, dt: 0.01 s}}
    T: {pulse: {amplitude: 0.4 m/s, period: 2 s, duration: 3 s, dt: 0.01 s}}
axes:
  - {path: ground_motion.angle, range: {from: 0 deg, to: 360 deg, step: 90 deg}}
  - {path: "structures[0].walls.gap", values: [10 cm, 20 cm]}
outputs:
  u_base: base.displacement
  F_impact: contacts.normal_force
"""


def readme_sections(readme_text):
    """[(section title, [(line number, kind, command text)])] in document order."""
    sections, title, commands = [], None, []
    lines = readme_text.split("\n")
    fence, fence_is_commands, i = False, False, 0
    while i < len(lines):
        line, number = lines[i], i + 1
        if line.startswith("```"):
            if not fence:
                first = lines[i + 1] if i + 1 < len(lines) else ""
                fence, fence_is_commands = True, line == "```" and bool(COMMAND_START.match(first))
            else:
                fence = False
            i += 1
            continue
        if fence:
            if fence_is_commands and COMMAND_START.match(line):
                text = line
                while text.rstrip().endswith("\\") and i + 1 < len(lines):  # continuation
                    i += 1
                    text = text.rstrip()[:-1].rstrip() + " " + lines[i].strip()
                commands.append((number, "block", strip_comment(text)))
            i += 1
            continue
        if line.startswith("## "):
            if title is not None:
                sections.append((title, commands))
            title, commands = line[3:].strip(), []
        m = re.match(r"<!-- begin:output [\w.-]+: (.+?) -->", line)
        if m:
            commands.append((number, "output block", m.group(1)))
        i += 1
    if title is not None:
        sections.append((title, commands))
    # Inline `code` spans (outside fences and comments), which may wrap lines.
    text = re.sub(r"^```.*?^```", lambda m: "\n" * m.group(0).count("\n"), readme_text,
                  flags=re.S | re.M)
    text = re.sub(r"<!--.*?-->", lambda m: "\n" * m.group(0).count("\n"), text, flags=re.S)
    starts = [0] + [m.start() for m in re.finditer(r"^## ", text, flags=re.M)]
    for m in re.finditer(r"`([^`]+)`", text):
        span = " ".join(m.group(1).split())
        if not COMMAND_START.match(span) or not has_arguments(span):
            continue
        number = text.count("\n", 0, m.start()) + 1
        index = sum(1 for s in starts[1:] if s <= m.start()) - 1
        if index >= 0:
            sections[index][1].append((number, "inline", span))
    return [(t, sorted(c)) for t, c in sections]


def strip_comment(text):
    """The command without its trailing '# comment' (quoting kept as written)."""
    cut = re.search(r"\s+#\s", text)
    return text[: cut.start()].strip() if cut else text.strip()


def has_arguments(span):
    words = span.split()
    if words[0] in SUBCOMMANDS:
        rest = [w for w in words[1:] if w not in SUBCOMMANDS[words[0]]]
        return bool(rest)
    return len(words) > 1


def section_slug(title):
    """'Post-processing: `isopound-post`' -> 'post-processing' (the title up to ( or :)."""
    return re.sub(r"[^a-z0-9]+", "-", re.split(r"[(:]", title)[0].lower()).strip("-")


# ---------------------------------------------------------------------------------------------
# Running one command
# ---------------------------------------------------------------------------------------------
SANITIZER = re.compile(r"ERROR: (AddressSanitizer|LeakSanitizer)|runtime error: |"
                       r"SUMMARY: (AddressSanitizer|UndefinedBehaviorSanitizer)")
NAN_WORD = re.compile(r"(?<![\w.])[-+]?(nan|inf|infinity)(?![\w])", re.I)
NAN_CELL = re.compile(r"(^|,)\s*[-+]?(nan|inf|infinity)\s*(?=,|$)", re.I | re.M)


class Result:
    def __init__(self, label, shown, outcome, seconds, problems, output, known=None, note=""):
        self.label, self.shown, self.outcome, self.seconds = label, shown, outcome, seconds
        self.problems, self.output, self.known, self.note = problems, output, known, note


class Runner:
    def __init__(self, args, target):
        self.args, self.target = args, target
        self.results = []
        self.env = dict(os.environ)
        self.logs = 0  # commands run (their outputs are logs/NN.log)

    def run(self, label, argv, cwd, shown, shell=False, scan=None, note="", expect=()):
        """Runs argv (or a shell line), classifies how it ended, scans what it wrote; `expect`:
        files it must have written when it succeeds."""
        before = file_times(scan or [])
        start = time.time()
        timed_out = False
        # Its own session, so that a time-out ends the command with everything it started
        # (pvpython, a private Xvfb) and nothing else.
        process = subprocess.Popen(argv, cwd=cwd, shell=shell,
                                   executable="/bin/bash" if shell else None,
                                   stdout=subprocess.PIPE, stderr=subprocess.STDOUT, env=self.env,
                                   text=True, errors="replace", start_new_session=True)
        try:
            output, _ = process.communicate(timeout=self.args.timeout)
            code = process.returncode
        except subprocess.TimeoutExpired:
            timed_out, code = True, None
            os.killpg(process.pid, signal.SIGKILL)
            output, _ = process.communicate()
        seconds = time.time() - start
        outcome = classify(code, output, timed_out, shell)
        problems = []
        left = [] if timed_out else session_alive(process.pid)
        if left:
            problems.append(f"left processes running after it exited (ended now): {left[:3]}")
            os.killpg(process.pid, signal.SIGKILL)
        for m in NAN_WORD.finditer(output):
            line = output[output.rfind("\n", 0, m.start()) + 1: output.find("\n", m.end())]
            problems.append(f"prints '{m.group(0)}': {line.strip()}")
            break
        if outcome == "exit 0":
            for path in expect:
                if not os.path.exists(path) or os.stat(path).st_mtime_ns < start * 1e9 - 1e7:
                    problems.append(f"exit 0 but did not write {path}")
            for path, mtime in file_times(scan or []).items():
                if before.get(path) != mtime:  # written by this command
                    problems += scan_file(path)
        result = Result(label, shown, outcome, seconds, problems, output, note=note)
        self.judge(result)
        self.results.append(result)
        # Every command's whole output, for reading after the test (the listing shows a tail).
        os.makedirs(os.path.join(self.args.scratch, "logs"), exist_ok=True)
        self.logs += 1
        log = os.path.join(self.args.scratch, "logs", f"{self.logs:02d}.log")
        with open(log, "w", encoding="utf-8") as f:
            f.write(f"$ {shown}\n# {outcome}, {seconds:.2f} s\n{output}")
        print(f"  {status_of(result):<7} {seconds:7.2f} s  {outcome:<14} {shown}"
              + (f"    [{note}]" if note else ""), flush=True)
        for p in result.problems:
            print(f"          {p}")
        if status_of(result) in ("FAIL", "XFAIL"):
            tail = "\n".join(result.output.rstrip().split("\n")[-6:])
            print("          | " + tail.replace("\n", "\n          | "))
        return result

    def judge(self, result):
        command, target = (("readme", result.shown) if self.target == "readme"
                           else (result.label, self.target))
        for k in KNOWN_FAILURES:
            if k.matches(command, target):
                result.known = k
                break
        failed = result.outcome != "exit " + DOCUMENTED_EXIT or result.problems
        k = result.known
        if k and not failed:
            result.problems.append(f"fixed: remove the KNOWN_FAILURES entry ({k.command}, "
                                   f"{k.target}): {k.defect}")
        elif k and is_crash(result.outcome) and not is_crash(k.fails_as):
            result.problems.append(f"known failure now crashes ({result.outcome}; recorded: "
                                   f"{k.fails_as}): {k.defect}")

    def skip(self, label, shown, why):
        print(f"  {'skip':<7} {'':>9}  {'':<14} {shown}    [{why}]", flush=True)

    def report(self, wall):
        failures = [r for r in self.results if status_of(r) == "FAIL"]
        known = [r for r in self.results if status_of(r) == "XFAIL"]
        print(f"{len(self.results)} commands in {wall:.1f} s: "
              f"{len(self.results) - len(failures) - len(known)} as documented, "
              f"{len(known)} known failures, {len(failures)} failures")
        for r in known:
            print(f"  known: {r.outcome}: {r.shown}  ({r.known.defect})")
        for r in failures:
            print(f"  FAILED: {r.outcome}: {r.shown}")
            for p in r.problems:
                print(f"    {p}")
        return 1 if failures else 0


def session_alive(session, grace=5.0):
    """Processes of the command's session still running (not exiting) after a grace time."""
    deadline = time.time() + grace
    while True:
        running = session_members(session)
        if not running or time.time() > deadline:
            return running
        time.sleep(0.2)


def session_members(session):
    """Command lines of the live processes in process group `session` (from /proc)."""
    members = []
    for pid in filter(str.isdigit, os.listdir("/proc")):
        try:
            with open(f"/proc/{pid}/stat", encoding="utf-8", errors="replace") as f:
                fields = f.read().rsplit(")", 1)[1].split()
            with open(f"/proc/{pid}/cmdline", "rb") as f:
                command = f.read().replace(b"\0", b" ").decode(errors="replace").strip()
        except OSError:
            continue
        # fields[0] the state, fields[2] the process group; an exiting process has no cmdline.
        if int(fields[2]) == session and fields[0] not in "ZX" and command:
            members.append(command)
    return members


def classify(code, output, timed_out, shell):
    if timed_out:
        return "timeout"
    if SANITIZER.search(output):
        return "sanitizer"
    if code < 0:
        return "signal " + signal_name(-code)
    if shell and code > 128 and code - 128 in {s.value for s in signal.Signals}:
        return "signal " + signal_name(code - 128)  # bash reports a child's signal as 128 + n
    return f"exit {code}"


def signal_name(number):
    try:
        return signal.Signals(number).name
    except ValueError:
        return str(number)


def is_crash(outcome):
    return outcome.startswith(("signal", "sanitizer", "timeout"))


def status_of(result):
    failed = result.outcome != "exit " + DOCUMENTED_EXIT or result.problems
    if result.known and failed and not any(p.startswith(("fixed:", "known failure now"))
                                           for p in result.problems):
        return "XFAIL"
    return "FAIL" if failed else "ok"


def file_times(dirs):
    """{path: mtime} of the JSON and CSV files under dirs."""
    times = {}
    for d in dirs:
        for base, _, names in os.walk(d):
            for name in names:
                if name.endswith((".json", ".csv")):
                    path = os.path.join(base, name)
                    times[path] = os.stat(path).st_mtime_ns
    return times


def scan_file(path):
    """nan/inf in a CSV or JSON file; in JSON also nulls where a number belongs (nlohmann::json
    writes a NaN as null) and a file that does not parse."""
    with open(path, encoding="utf-8", errors="replace") as f:
        text = f.read()
    if path.endswith(".csv"):
        if not any(t in text for t in ("nan", "NaN", "NAN", "inf", "Inf", "INF")):
            return []  # the common case, fast (histories.csv runs to megabytes)
        m = NAN_CELL.search(text)
        if m:
            line = text.count("\n", 0, m.start()) + 1
            return [f"{path}: line {line}: '{m.group(0).strip(', ')}'"]
        return []
    if not text.strip():
        return [f"{path}: empty"]
    bad = []

    def constant(name):
        bad.append(f"{path}: {name}")
        return 0.0

    try:
        document = json.loads(text, parse_constant=constant)
    except json.JSONDecodeError as e:
        return [f"{path}: not JSON: {e}"]
    nulls = []

    def walk(x, where):
        if x is None and not NULL_KEYS.match(where[-1] if where else ""):
            nulls.append("/".join(where))
        elif isinstance(x, dict):
            for key, value in x.items():
                walk(value, where + [key])
        elif isinstance(x, list):
            for i, value in enumerate(x):
                walk(value, where[:-1] + [f"{where[-1] if where else ''}[{i}]"])

    walk(document, [])
    if nulls:
        bad.append(f"{path}: null (a NaN?) at {', '.join(nulls[:5])}"
                   + (f" and {len(nulls) - 5} more" if len(nulls) > 5 else ""))
    return bad


# ---------------------------------------------------------------------------------------------
# The model matrix
# ---------------------------------------------------------------------------------------------
def model_matrix(args, model_arg):
    scratch = fresh_dir(args.scratch)
    tool = {name: os.path.join(args.bin, name) for name in ("isopound", "isopound-post",
                                                             "isopound-pre")}
    name = os.path.splitext(os.path.basename(model_arg))[0]
    runner = Runner(args, name)
    print(f"Shipped-path matrix of {model_arg}. To repeat a command: cd {ROOT}; "
          f"S={scratch}; PATH={args.bin}:$PATH. Whole outputs: $S/logs/")
    start = time.time()

    def run(label, tool_name, words, scan=None, expect=()):
        if not os.path.exists(tool[tool_name]):  # the sanitizer tree builds no VTK/Gmsh program
            runner.skip(label, tool_name + " " + " ".join(words), f"{tool_name} is not built here")
            return None
        argv = [tool[tool_name]] + words
        shown = " ".join([tool_name] + [shlex.quote(w).replace(scratch, "$S") for w in words])
        return runner.run(label, argv, ROOT, shown, scan=scan,
                          expect=[os.path.join(scan[0], f) for f in expect])

    model = model_arg
    if model_arg == "demo":  # the model the demo writes as the start of one's own
        name = "demo"
        made = run("demo", "isopound", ["demo", "--no-pictures", "-q", "-o",
                                        os.path.join(scratch, "demo")])
        model = os.path.join(scratch, "demo", "model.yaml")
        if made.outcome != "exit 0":
            return runner.report(time.time() - start)
    elif is_polygon_pairs(model_arg):  # configs/geometry-overlap-example.yaml
        run("geometry overlap", "isopound", ["geometry", "overlap", model])
        run("geometry overlap --exact", "isopound", ["geometry", "overlap", model, "--exact"])
        return runner.report(time.time() - start)

    until = min(args.until, UNTIL_CAP.get(name, args.until))
    three_d = is_3d(model)
    run("check", "isopound", ["check", model])
    out = os.path.join(scratch, "run")
    ran = run("run", "isopound", ["run", model, "--until", f"{until:g}", "-o", out], scan=[out],
              expect=["summary.json", "histories.csv"])
    run("modes", "isopound", ["modes", model])
    pre = os.path.join(scratch, "pre")
    run("pre", "isopound-pre", [model, "-o", pre], scan=[pre],
        expect=["properties.json"] + (["plan.png"] if three_d else []))
    pushes = [("pushover", [])]
    if three_d:
        pushes += [("pushover 90 deg", ["--angle", "90 deg"]),
                   ("pushover 30 deg", ["--angle", "30 deg"])]
    pushed = []
    for label, extra in pushes:
        d = os.path.join(scratch, label.replace(" ", "-"))
        r = run(label, "isopound", ["pushover", model, "-o", d] + extra, scan=[d],
                expect=["pushover.csv", "pushover.json"])
        pushed.append((label, d, r))
    if ran.outcome == "exit 0":
        for command, written in (("plot", "time_histories.png"),
                                 ("animate", "animation/animation.pvd"),
                                 ("floor-spectra", "floor-spectra.csv")):
            run("post " + command, "isopound-post", [command, out], scan=[out], expect=[written])
    else:
        runner.skip("post", "isopound-post plot|animate|floor-spectra $S/run", "the run failed")
    # The capacity curve of the plainest push (the first that succeeded): the angle changes only
    # the figure's title, and each drawing costs 2 s (5 s under the sanitizers).
    drawn = [(label, d) for label, d, r in pushed if r.outcome == "exit 0"][:1]
    for label, d in drawn:
        run("post " + label, "isopound-post", ["pushover", d], scan=[d], expect=["pushover.png"])
    if not drawn:
        runner.skip("post pushover", "isopound-post pushover $S/pushover*", "every push failed")
    return runner.report(time.time() - start)


def study_matrix(args, study):
    """A shipped study: every case built and every output selector resolved (--dry-run)."""
    scratch = fresh_dir(args.scratch)
    runner = Runner(args, os.path.splitext(os.path.basename(study))[0])
    print(f"Shipped study {study}. To repeat: cd {ROOT}; PATH={args.bin}:$PATH. "
          f"Whole outputs: {scratch}/logs/")
    start = time.time()
    runner.run("sweep --dry-run", [os.path.join(args.bin, "isopound"), "sweep", study,
                                   "--dry-run"], ROOT, f"isopound sweep {study} --dry-run")
    return runner.report(time.time() - start)


def is_polygon_pairs(path):
    with open(os.path.join(ROOT, path), encoding="utf-8") as f:
        return re.search(r"^pairs:", f.read(), re.M) is not None


def is_3d(path):
    with open(path if os.path.isabs(path) else os.path.join(ROOT, path), encoding="utf-8") as f:
        return re.search(r"^structures:", f.read(), re.M) is not None


def fresh_dir(path):
    shutil.rmtree(path, ignore_errors=True)
    os.makedirs(path)
    return os.path.abspath(path)


# ---------------------------------------------------------------------------------------------
# README commands
# ---------------------------------------------------------------------------------------------
def readme_section(args, slug):
    with open(os.path.join(ROOT, "README.md"), encoding="utf-8") as f:
        sections = readme_sections(f.read())
    chosen = [(t, c) for t, c in sections if section_slug(t) == slug]
    if not chosen:
        raise SystemExit(f"shipped_paths: no README section '{slug}'")
    title, commands = chosen[0]
    scratch = fresh_dir(args.scratch)
    tree = scratch_tree(args, scratch)
    runner = Runner(args, "readme")
    runner.env["PATH"] = os.path.join(scratch, "bin") + os.pathsep + runner.env.get("PATH", "")
    pvpython = shutil.which("pvpython") is not None
    pv_required = os.environ.get("ISOPOUND_REQUIRE_PARAVIEW", "0") not in ("", "0")
    print(f"README.md, \"{title}\": {len(commands)} command lines, run in {tree} (a scratch copy: "
          f"configs/ copied, docs/ linked, ../shared linked, {scratch}/bin first on PATH). "
          f"Whole outputs: {scratch}/logs/")
    start = time.time()
    done = {}

    def run_line(written, number):
        if written in done:
            print(f"  {'(again)':<7} {'':>9}  {done[written].outcome:<14} {written}    "
                  f"[line {number}: run above]")
            return done[written]
        for first in [NEEDS_FIRST[written]] if written in NEEDS_FIRST else []:
            run_line(first, f"{number} (needed first)")
        text, note = written, f"line {number}"
        if written in RUN_AS:
            text, why = RUN_AS[written]
            note += f"; run as '{text}': {why}" if text != written else f"; {why}"
        if re.search(r"(?<![\w/.-])study\.db\b", text):
            make_study_db(runner, tree)
            note += "; study.db: a small angle x gap study made first (the reader's own)"
        if written == "isopound check model.yaml":
            shutil.copy(os.path.join(tree, "configs", "tutorial.yaml"),
                        os.path.join(tree, "model.yaml"))
        for study in SHORTENED_STUDIES:
            if study in text:
                shorten_study(os.path.join(tree, study), args.until)
                note += f"; {study} with every run stopped at {args.until:g} s (README: long)"
        if (args.readme_until is not None and re.match(r"isopound run\b", text)
                and "--until" not in text and not re.search(r"[|;&<>]", text)):
            # The sanitizer tree: the line's own options, a shorter analysis (ensembles of whole
            # records took 30-40 s each there; the Release tree runs the line as written).
            text += f" --until {args.readme_until:g}"
            note += f"; stopped at {args.readme_until:g} s (--readme-until: sanitizer tree)"
        if (re.search(r"isopound demo\b", text) and "--2d" not in text
                and "--no-pictures" not in text
                and not os.path.exists(os.path.join(args.bin, "isopound-post"))):
            # The demo draws through isopound-post; where it is not built, its analysis alone.
            text += " --no-pictures"
            note += "; run with --no-pictures: isopound-post is not built here"
        absent = [t for t in ("isopound-post", "isopound-pre")
                  if re.search(r"(?<![\w/.-])" + t + r"\b", text)
                  and not os.path.exists(os.path.join(args.bin, t))]
        if NEEDS_PVPYTHON.search(text) and not os.path.exists(os.path.join(args.bin,
                                                                          "isopound-post")):
            absent.append("isopound-post")  # ParaView reads what isopound-post writes
        if absent:  # the sanitizer tree builds no VTK/Gmsh program (ISOPOUND_BUILD_POST=OFF)
            runner.skip("readme", written, f"line {number}: {absent[0]} is not built here")
            return None
        if NEEDS_PVPYTHON.search(text) and not pvpython and not pv_required:
            runner.skip("readme", written, f"line {number}: needs pvpython (ParaView), absent")
            return None
        r = runner.run("readme", text, tree, written, shell=True, scan=[tree], note=note)
        if NEEDS_PVPYTHON.search(text) and status_of(r) == "FAIL" and r.outcome != "sanitizer":
            # ParaView's pvpython, started under ctest -j2 on a loaded machine, failed twice in
            # six runs at start-up, in its own X and MPI set-up ("X connection to :0 broken" then
            # MPI_Init "Unable to start a daemon", exit 1; "vtkXOpenGLRenderWindow: bad X server
            # connection. DISPLAY=:99. Aborting.", SIGABRT): one retry, the first failure listed
            # but not counted. A failure that repeats, or a sanitizer report, fails.
            runner.results.remove(r)
            r = runner.run("readme", text, tree, written, shell=True, scan=[tree],
                           note=note + "; retried once: pvpython start-up failed")
        if r.known and r.known.workaround and status_of(r) == "XFAIL":
            # The known failure worked around, so that what follows on the page is still checked.
            fix = r.known.workaround
            r = runner.run("readme", f"{fix} && {text}", tree, f"{fix} && {written}", shell=True,
                           scan=[tree], note=f"{note}; known failure worked around")
        done[written] = r
        return r

    for number, kind, written in commands:
        if written in NOT_RUN:
            runner.skip("readme", written, f"line {number}: {NOT_RUN[written]}")
        elif written not in RUN_AS and SYNOPSIS.search(written):
            runner.skip("readme", written, f"line {number}: a synopsis (placeholders)")
        else:
            run_line(written, number)
    return runner.report(time.time() - start)


def scratch_tree(args, scratch):
    tree = os.path.join(scratch, "repo")
    os.makedirs(tree)
    shutil.copytree(os.path.join(ROOT, "configs"), os.path.join(tree, "configs"))
    os.symlink(os.path.join(ROOT, "docs"), os.path.join(tree, "docs"))
    shutil.copy(os.path.join(ROOT, "README.md"), tree)
    os.symlink(shared_dir(), os.path.join(scratch, "shared"))  # ../shared beside the tree
    os.makedirs(os.path.join(scratch, "bin"))
    os.makedirs(os.path.join(tree, "build"))
    for name in ("isopound", "isopound-post", "isopound-pre"):
        os.symlink(os.path.join(args.bin, name), os.path.join(scratch, "bin", name))
        os.symlink(os.path.join(args.bin, name), os.path.join(tree, "build", name))
    return tree


def make_study_db(runner, tree):
    if os.path.exists(os.path.join(tree, "study.db")):
        return
    with open(os.path.join(tree, "study.yaml"), "w", encoding="utf-8") as f:
        f.write(STUDY_DB_FIXTURE)
    runner.run("fixture", "isopound sweep study.yaml -j 2 -q --db study.db", tree,
               "isopound sweep study.yaml -j 2 -q --db study.db", shell=True,
               note="fixture for study.db")


def shorten_study(path, until):
    with open(path, encoding="utf-8") as f:
        text = f.read()
    if "analysis.t_end" in text:
        return
    if re.search(r"^set:\n", text, re.M):
        text = re.sub(r"^set:\n", f"set:\n  analysis.t_end: {until:g} s\n", text, count=1,
                      flags=re.M)
    else:
        text = re.sub(r"^(model: .*\n)", rf"\1set:\n  analysis.t_end: {until:g} s\n", text,
                      count=1, flags=re.M)
    with open(path, "w", encoding="utf-8") as f:
        f.write(text)


def shared_dir():
    return os.environ.get("ISOPOUND_SHARED", os.path.join(os.path.dirname(ROOT), "shared"))


# ---------------------------------------------------------------------------------------------
def test_names():
    """README sections first: CTest starts tests in this order on a fresh tree, and the longest
    (post-processing, the demos) should not start last."""
    names = []
    with open(os.path.join(ROOT, "README.md"), encoding="utf-8") as f:
        for title, commands in readme_sections(f.read()):
            if commands:
                names.append(("readme", section_slug(title)))
    for f in sorted(os.listdir(os.path.join(ROOT, "configs"))):
        if f.endswith(".yaml"):
            names.append(("model", "configs/" + f))
    names.append(("model", "demo"))
    for f in sorted(os.listdir(os.path.join(ROOT, "configs", "studies"))):
        if f.endswith(".yaml"):
            names.append(("study", "configs/studies/" + f))
    return names


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("what", choices=["model", "study", "readme", "list"])
    parser.add_argument("target", nargs="?")
    parser.add_argument("--bin", default=os.path.join(ROOT, "build"))
    parser.add_argument("--scratch", default=os.path.join(ROOT, "out", "shipped-paths"))
    parser.add_argument("--until", type=float, default=5.0, help="run --until T (s)")
    parser.add_argument("--timeout", type=float, default=300.0, help="per command (s)")
    parser.add_argument("--readme-until", type=float, default=None,
                        help="README lines `isopound run ...` stopped at T (s); default: as written")
    args = parser.parse_args()
    if args.what == "list":
        for kind, target in test_names():
            print(f"{kind} {target}")
        return 0
    if not os.path.isdir(os.path.join(shared_dir(), "records")):
        if os.environ.get("ISOPOUND_REQUIRE_SHARED", "0") not in ("", "0"):
            raise SystemExit("shipped_paths: ../shared/records is required but absent")
        print("shipped_paths: ../shared/records absent: skipped")
        return SKIPPED
    args.bin, args.scratch = os.path.abspath(args.bin), os.path.abspath(args.scratch)
    if args.what == "model":
        return model_matrix(args, args.target)
    if args.what == "study":
        return study_matrix(args, args.target)
    return readme_section(args, args.target)


if __name__ == "__main__":
    sys.exit(main())
