#!/usr/bin/env python3
"""Ipopt traces of every candidate solve of some scenarios, and the progress budget replayed on them.

    python3 scripts/solver_traces.py collect OUT_DIR SCENARIO.yaml...   # plan, then replay each request
    python3 scripts/solver_traces.py budget OUT_DIR [--budget 30 --extension 20 ...]

`collect` runs `stanceplan plan SCENARIO --threads 1 --verbose --requests OUT_DIR/NAME/` for each
scenario, then replays every request twice (`stanceplan replay --print-level 5`): as the search solved
it, and with `--progress-budget 0` (the solve run to its iteration limit), and writes one JSON line per
request to OUT_DIR/traces.jsonl: per Ipopt run its constraint violation (inf_pr), dual infeasibility
(inf_du) and restoration flags per iteration, and how each replay ended.

`budget` replays the progress budget (planner/solver/stall_monitor.h, StallMonitor::out_of_budget) on
the unbudgeted traces, with the rule's parameters given, and prints what it would do: successes it
stops (each changes the search's route), failures it stops and the Ipopt iterations left. With the
defaults it reproduces the search's own budget, which the "as searched" replays check (the count of
requests where the two disagree is printed: a few, from the 3 digits of Ipopt's printed inf_pr;
2 of the 1572 requests of the 23 untuned, paper and guide-free runs). A rule that stops no success cannot change a plan; one
that does must be judged by whole runs (`stanceplan plan`), not by iterations.

Run from the repository root, with build/app/stanceplan built.
"""

import argparse
import glob
import json
import math
import os
import re
import subprocess
import sys
from concurrent.futures import ThreadPoolExecutor

STANCEPLAN = os.path.join("build", "app", "stanceplan")
ROW = re.compile(r"^\s*(\d+)(r?)\s+(\S+)\s+(\S+)\s+(\S+)\s+(\S+)")
END = re.compile(r"bin: (\S+) after (\d+)")


def ipopt_runs(log):
    """The Ipopt runs of one replay's log (a solve may re-solve with more active rows)."""
    runs = []
    for line in log.splitlines():
        if line.startswith("This is Ipopt"):
            runs.append({"inf_pr": [], "inf_du": [], "restoration": []})
            continue
        m = ROW.match(line)
        if m and runs:
            try:
                pr, du = float(m.group(4)), float(m.group(5))
            except ValueError:
                continue
            runs[-1]["inf_pr"].append(pr)
            runs[-1]["inf_du"].append(du)
            runs[-1]["restoration"].append(m.group(2) == "r")
    return runs


def replay(job):
    name, scenario, request = job
    out = {"scenario": name, "request": os.path.basename(request)}
    for label, extra in (("searched", []), ("unbudgeted", ["--progress-budget", "0"])):
        p = subprocess.run([STANCEPLAN, "replay", scenario, request, "--print-level", "5"] + extra,
                           capture_output=True, text=True)
        ends = [line for line in p.stdout.splitlines() if line.startswith("replay ")]
        m = END.search(ends[-1]) if ends else None
        out[label] = {"runs": ipopt_runs(p.stdout), "status": m.group(1) if m else "?",
                      "iterations": int(m.group(2)) if m else 0}
    return out


def collect(args):
    jobs = []
    for scenario in args.scenarios:
        name = os.path.basename(os.path.dirname(scenario)) + "_" + os.path.splitext(
            os.path.basename(scenario))[0]
        folder = os.path.join(args.out, name)
        os.makedirs(folder, exist_ok=True)
        for old in glob.glob(os.path.join(folder, "request_*.bin")):
            os.remove(old)
        with open(os.path.join(folder, "plan.log"), "w") as log:
            subprocess.run([STANCEPLAN, "plan", scenario, "--threads", "1", "--verbose", "--out",
                            os.path.join(folder, "plan.json"), "--requests", folder],
                           stdout=subprocess.DEVNULL, stderr=log)
        for request in sorted(glob.glob(os.path.join(folder, "request_*.bin"))):
            jobs.append((name, scenario, request))
    with open(os.path.join(args.out, "traces.jsonl"), "w") as out, \
            ThreadPoolExecutor(args.jobs) as pool:
        for record in pool.map(replay, jobs):
            out.write(json.dumps(record) + "\n")
    print(f"{len(jobs)} requests traced into {os.path.join(args.out, 'traces.jsonl')}")


def budget_stop(inf_pr, rule):
    """The iteration at which the progress budget stops a run, or None (StallMonitor; 0: none)."""
    if rule.budget <= 0:
        return None
    allowed, mark = rule.budget, math.inf
    for i, v in enumerate(inf_pr):
        if not math.isfinite(mark):
            mark = v
        elif v * rule.progress_factor < mark:
            mark, allowed = v, max(allowed, i + rule.extension)
        if v < rule.near_feasible:
            allowed = max(allowed, i + rule.extension)
        if i > allowed:
            return i
    return None


def budget(args):
    with open(os.path.join(args.out, "traces.jsonl")) as f:
        records = [json.loads(line) for line in f]
    lost, stopped, total, left, disagree = [], 0, 0, 0, 0
    for r in records:
        raw = r["unbudgeted"]
        used, stop = 0, False
        for run in raw["runs"]:
            k = budget_stop(run["inf_pr"], args)
            total += len(run["inf_pr"])
            if stop:
                continue
            if k is None:
                used += len(run["inf_pr"])
            else:
                used, stop = used + k + 1, True
        left += used
        if stop and raw["status"] == "solved":
            lost.append(f"{r['scenario']}/{r['request']}")
        elif stop:
            stopped += 1
        searched_solved = r["searched"]["status"] == "solved"
        disagree += searched_solved != (raw["status"] == "solved" and not stop)
    print(f"{len(records)} requests, {total} Ipopt iterations without a budget, {left} with this "
          f"rule; it stops {stopped} failures and {len(lost)} successes")
    for name in lost:
        print("  success stopped:", name)
    print(f"requests where the rule and the search's own replay disagree: {disagree} "
          "(a few with the search's rule: Ipopt prints inf_pr to 3 digits)")


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    sub = parser.add_subparsers(dest="command", required=True)
    c = sub.add_parser("collect")
    c.add_argument("out")
    c.add_argument("scenarios", nargs="+")
    c.add_argument("--jobs", type=int, default=2)
    b = sub.add_parser("budget")
    b.add_argument("out")
    b.add_argument("--budget", type=int, default=30)
    b.add_argument("--extension", type=int, default=20)
    b.add_argument("--progress-factor", type=float, default=10.0)
    b.add_argument("--near-feasible", type=float, default=1e-2)
    args = parser.parse_args()
    if not os.path.exists(STANCEPLAN):
        sys.exit(f"{STANCEPLAN}: not built (run from the repository root after building)")
    (collect if args.command == "collect" else budget)(args)


if __name__ == "__main__":
    main()
