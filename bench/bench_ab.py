#!/usr/bin/env python3
"""A/B of MeshEdit's own benchmark rows between two bench builds (bench/README.md).

Every MeshEdit configuration that build B's programs list (anchors left out) runs in a fresh
process in both builds, alternated A B A B ... for --rounds rounds, so a drift of the
machine's speed hits both alike. Both run at the same thread count: all cores by default, as
a build from before MESHEDIT_THREADS existed ignores it; --pin 0 runs both on one processor. A job is "slower" only when every one of A's medians
is above every one of B's and the ratio of their medians passes --noise. Usage:

    git worktree add /tmp/base 5072107 && (build its bench targets into /tmp/base/build-bench)
    python3 bench/bench_ab.py --a build-bench --b /tmp/base/build-bench --out /tmp/ab.md
"""

import argparse
import os
import statistics
import sys

from bench_machine import wait_for_quiet
from run_bench import PREPARE, PROGRAMS, list_configs, log, parse_output, run_process

# Rows of MeshEdit itself; the anchors' rows do not change between two MeshEdit builds.
OURS = ("meshedit", "all", "core", "viewer")


def median_ms(path, job, impl, runs, timeout, pin):
    """{impl: median ms} of one configuration in a fresh process; {} if it failed (a job one
    build's program does not have)."""
    cmd = [path, "--job", job, "--impl", impl, "--runs", str(runs)]
    if pin:
        cmd = ["taskset", "-c", pin] + cmd
    env = {k: v for k, v in os.environ.items() if k != "MESHEDIT_THREADS"}
    rc, out, _, _ = run_process(cmd, os.path.dirname(path), timeout, env)
    if rc != 0:
        return {}
    results, _ = parse_output(out)
    return {r["impl"]: r["median_ms"] for r in results if "median_ms" in r}


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--a", required=True, help="build folder A (the change)")
    parser.add_argument("--b", required=True, help="build folder B (the base)")
    parser.add_argument("--rounds", type=int, default=3, help="A B alternations per job")
    parser.add_argument("--runs", type=int, default=3, help="repetitions in each process")
    parser.add_argument("--timeout", type=float, default=120, help="seconds per process")
    parser.add_argument("--noise", type=float, default=0.05,
                        help="a ratio above 1 + NOISE, consistent in every round, is slower")
    parser.add_argument("--only", default="", help="comma-separated substrings of job names")
    parser.add_argument("--pin", default="", help="processors for both (taskset -c), e.g. 0")
    parser.add_argument("--out", default="", help="the Markdown table (else standard output)")
    args = parser.parse_args()
    only = [w for w in args.only.split(",") if w]

    wait_for_quiet(0.5, 180, log)
    rows = []
    for name in PROGRAMS:
        paths = [os.path.join(os.path.abspath(b), "bench", name) for b in (args.a, args.b)]
        if not all(os.access(p, os.X_OK) for p in paths):
            continue
        configs, _ = list_configs(paths[1], name)
        configs = [(job, impl) for job, impl in configs
                   if impl in OURS and (not only or any(w in job for w in only))]
        if not configs:
            continue
        for path in paths:
            if name in PREPARE:
                run_process([path] + PREPARE[name], os.path.dirname(path), 600)
        for job, impl in configs:
            times = {"a": {}, "b": {}}  # per result impl: list of medians
            for round_ in range(args.rounds):
                for side, path in (("a", paths[0]), ("b", paths[1])):
                    for result_impl, ms in median_ms(path, job, impl, args.runs,
                                                     args.timeout, args.pin).items():
                        times[side].setdefault(result_impl, []).append(ms)
            for result_impl in sorted(set(times["a"]) | set(times["b"])):
                a, b = times["a"].get(result_impl, []), times["b"].get(result_impl, [])
                if not a or not b:
                    rows.append((job, result_impl, a, b, None, "only in " + ("A" if a else "B")))
                    continue
                ratio = statistics.median(a) / statistics.median(b)
                verdict = ("slower" if min(a) > max(b) and ratio > 1 + args.noise
                           else "faster" if max(a) < min(b) and ratio < 1 - args.noise
                           else "same")
                rows.append((job, result_impl, a, b, ratio, verdict))
                log(f"{job} {result_impl}: A/B {ratio:.3f} ({verdict})")

    def cell(values):
        return ", ".join(f"{v:.3g}" for v in values) if values else "—"

    text = ["| job | row | A medians (ms) | B medians (ms) | A/B | verdict |",
            "|---|---|---|---|---|---|"]
    for job, impl, a, b, ratio, verdict in rows:
        shown = f"{ratio:.3f}" if ratio is not None else "—"
        text.append(f"| {job} | {impl} | {cell(a)} | {cell(b)} | {shown} | {verdict} |")
    slower = sum(1 for r in rows if r[5] == "slower")
    text.append("")
    where = f"pinned to processor(s) {args.pin}" if args.pin else "all cores"
    text.append(f"{len(rows)} rows, {slower} slower beyond noise ({where}, {args.rounds} "
                f"alternated rounds of {args.runs} runs, noise {args.noise:g}).")
    output = "\n".join(text) + "\n"
    if args.out:
        with open(args.out, "w") as f:
            f.write(output)
    else:
        sys.stdout.write(output)
    return 1 if slower else 0


if __name__ == "__main__":
    sys.exit(main())
