#!/usr/bin/env python3
# A class of generated submissions for the exercise pull-with-a-weight, graded in one run of
# `isoparm check` on all cores: answers that pass (the weight of P2,2 near 16/3), too light or
# too heavy weights, a moved control point, a negative weight, and unreadable files. Each file
# is graded as its making says, the summary counts them, and the CSV and JSON agree.
import argparse
import csv
import json
import os
import random
import re
import shutil
import subprocess
import sys


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--isoparm", required=True)
    ap.add_argument("--source", required=True)
    ap.add_argument("--work", required=True)
    ap.add_argument("--count", type=int, default=300)
    args = ap.parse_args()
    exercise = os.path.join(args.source, "assets/exercises/pull-with-a-weight.json")
    with open(os.path.join(args.source, "assets/exercises/solutions/pull-with-a-weight.json")) as f:
        solution = json.load(f)
    shutil.rmtree(args.work, ignore_errors=True)
    folder = os.path.join(args.work, "class")
    os.makedirs(folder)
    rng = random.Random(31)
    expected = {}

    def write(name, scene, passes):
        path = os.path.join(folder, name)
        with open(path, "w") as f:
            json.dump(scene, f)
        expected[path] = passes

    n = args.count
    kinds = (["pass"] * (n // 2) + ["light"] * (n // 6) + ["heavy"] * (n // 6) + ["moved"] * (n // 15)
             + ["negative"] * (n // 30) + ["broken"] * (n // 60))
    kinds += ["pass"] * (n - len(kinds))
    for k, kind in enumerate(kinds):
        scene = json.loads(json.dumps(solution))
        hill = scene["objects"][0]["surface"]
        # At (0.5, 0.5) the hill is (0.275 + 0.3 w) / (0.75 + 0.25 w) high: 0.9 at w = 16/3,
        # within 0.005 of it for w in [5.28, 5.42]; 0.8875 at w = 5, 0.928 at w = 7.
        if kind == "pass":
            hill["weights"][2][2] = rng.uniform(5.28, 5.42)
        elif kind == "light":
            hill["weights"][2][2] = rng.uniform(1.0, 4.5)
        elif kind == "heavy":
            hill["weights"][2][2] = rng.uniform(7.0, 12.0)
        elif kind == "moved":
            hill["weights"][2][2] = 1.0
            hill["points"][2][2] = [0, 0, 2.5]  # the top reaches 0.9 by a moved point
        elif kind == "negative":
            hill["weights"][0][rng.randrange(5)] = -rng.uniform(0.1, 2.0)
        name = f"student-{k:03d}-{kind}.json"
        if kind == "broken":
            path = os.path.join(folder, name)
            with open(path, "w") as f:
                f.write(json.dumps(scene)[: rng.randrange(10, 200)])  # cut off mid-file
            expected[path] = False
        else:
            write(name, scene, kind == "pass")

    out_csv = os.path.join(args.work, "grades.csv")
    out_json = os.path.join(args.work, "grades.json")
    done = subprocess.run([args.isoparm, "check", exercise, folder, "--csv", out_csv,
                           "--json", out_json], capture_output=True, text=True, timeout=240)
    print(done.stdout.splitlines()[-1] if done.stdout else done.stderr)
    problems = []
    if done.returncode != 1:
        problems.append(f"exit {done.returncode}, expected 1 (some submissions fail): {done.stderr}")
    passed = sum(expected.values())
    broken = kinds.count("broken")
    summary = f"{n} submissions: {passed} passed, {n - passed} failed ({broken} could not be read)"
    if summary not in done.stdout:
        problems.append(f"the summary is not '{summary}':\n{done.stdout[-500:]}")
    lines = {}
    for line in done.stdout.splitlines():
        m = re.match(r"(PASS|FAIL)  (\S+)  ", line)
        if m:
            lines[m.group(2)] = m.group(1) == "PASS"
    for path, passes in expected.items():
        if lines.get(path) is not passes:
            problems.append(f"{path}: graded {lines.get(path)}, expected {passes}")
    with open(out_csv) as f:
        rows = list(csv.DictReader(f))
    if len(rows) != n or any((r["result"] == "pass") != expected[r["file"]] for r in rows):
        problems.append("the CSV does not agree with the lines")
    with open(out_json) as f:
        grades = json.load(f)
    if grades["summary"] != {"submissions": n, "passed": passed, "failed": n - passed,
                             "unreadable": broken}:
        problems.append(f"the JSON summary: {grades['summary']}")
    for p in problems[:20]:
        print("class_test:", p, file=sys.stderr)
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
