#!/usr/bin/python3
"""ocean-loadtest --merge end to end: two load-test processes (as two machines of a Kubernetes
Indexed Job would be) run side by side on loopback against one real ocean-server, each writing its
--json summary; `ocean-loadtest --merge` combines them. The merged summary must carry the sums of
the parts' counts and the percentiles of the union of their latency samples (recomputed here from
the histograms in the parts, with the same nearest-rank rule), and match one process that ran both
halves (--threads 2) in everything that does not depend on timing."""
import argparse
import json
import math
import os
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "../../client/loadtest"))
import local_server  # noqa: E402

SUMMED = ["clients", "clients_connected", "clients_welcomed", "frames_expected", "frames_received", "frames_ok",
          "frames_late", "frames_lost", "frames_bad", "keyframes", "stalls", "clients_without_frame"]


def percentile(histogram, p):
    """Nearest rank over sparse [bin, count] pairs: the bin's upper edge, capped at the max."""
    total = sum(c for _, c in histogram["bins"])
    if total == 0:
        return 0.0
    rank = max(1, math.ceil(p / 100.0 * total))
    seen = 0
    for b, c in sorted(histogram["bins"]):
        seen += c
        if seen >= rank:
            return min(histogram["max"], (b + 1) * histogram["bin"])
    return histogram["max"]


def union(parts, name):
    bins = {}
    for p in parts:
        for b, c in p["parts"][name]["bins"]:
            bins[b] = bins.get(b, 0) + c
    return {"bin": parts[0]["parts"][name]["bin"], "max": max(p["parts"][name]["max"] for p in parts),
            "bins": sorted([b, c] for b, c in bins.items())}


def check(parts, merged, single):
    failures = []
    for key in SUMMED:
        if merged[key] != sum(p[key] for p in parts):
            failures.append(f"{key}: merged {merged[key]} != sum of parts {[p[key] for p in parts]}")
    if merged["processes"] != 2 or merged["frames_bad"] != 0 or merged["frames_expected"] <= 0:
        failures.append(f"processes {merged['processes']}, frames_bad {merged['frames_bad']}, expected {merged['frames_expected']}")
    latency = union(parts, "latency_s")
    for p in (50, 99):
        want = round(percentile(latency, p) * 1e3, 6)
        if not math.isclose(merged[f"latency_p{p}_ms"], want, rel_tol=1e-5):
            failures.append(f"latency_p{p}_ms: merged {merged[f'latency_p{p}_ms']} != union of the parts {want}")
    if merged["parts"]["latency_s"]["bins"] != latency["bins"]:
        failures.append("the merged latency histogram is not the union of the parts'")
    ok_pct = 100.0 * merged["frames_ok"] / merged["frames_expected"]
    if not math.isclose(merged["frames_ok_pct"], ok_pct, rel_tol=1e-5):
        failures.append(f"frames_ok_pct {merged['frames_ok_pct']} != frames_ok / frames_expected {ok_pct}")
    # One process with both halves: the same clients; frames owed within the spread of start times.
    for key in ("clients", "clients_welcomed"):
        if merged[key] != single[key]:
            failures.append(f"{key}: merged {merged[key]} != one process with both halves {single[key]}")
    if abs(merged["frames_expected"] - single["frames_expected"]) > 0.1 * single["frames_expected"]:
        failures.append(f"frames_expected: merged {merged['frames_expected']} vs one process {single['frames_expected']}")
    return failures


def run_loadtests(args, port, seeds, extra):
    procs = [subprocess.Popen([args.loadtest_bin, "--server", f"127.0.0.1:{port}", "--clients", str(args.clients),
                               "--ramp", "0.5", "--duration", str(args.duration), "--seed", str(seed), "--json",
                               "--quiet"] + extra, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
             for seed in seeds]
    outs = [p.communicate(timeout=args.duration + 40) for p in procs]
    for p, (_, err) in zip(procs, outs):
        if p.returncode != 0:
            raise RuntimeError(f"ocean-loadtest exited {p.returncode}: {err[-2000:]}")
    return [out for out, _ in outs]


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--server-bin", required=True)
    ap.add_argument("--loadtest-bin", required=True)
    ap.add_argument("--clients", type=int, default=6, help="per process")
    ap.add_argument("--duration", type=float, default=3.0)
    args = ap.parse_args()
    port = local_server.free_port()
    server = local_server.start(args.server_bin, ["--listen", f"127.0.0.1:{port}", "--metrics-listen", "off",
                                                  "--profiles", "mobile", "--log-level", "warn"], port)
    try:
        with tempfile.TemporaryDirectory() as work:
            texts = run_loadtests(args, port, [1, 1 + args.clients], [])
            paths = []
            for i, text in enumerate(texts):
                paths.append(os.path.join(work, f"part-{i}.json"))
                with open(paths[-1], "w") as f:
                    f.write(text)
            merge = subprocess.run([args.loadtest_bin, "--merge", *paths, "--json"], stdout=subprocess.PIPE,
                                   stderr=subprocess.PIPE, text=True, timeout=30)
            if merge.returncode != 0:
                print("ocean-loadtest --merge failed:", merge.stderr, file=sys.stderr)
                return 1
            merged = json.loads(merge.stdout.strip().splitlines()[-1])
            parts = [json.loads(t.strip().splitlines()[-1]) for t in texts]
            args.clients *= 2
            single = json.loads(run_loadtests(args, port, [1], ["--threads", "2"])[0].strip().splitlines()[-1])
    finally:
        local_server.stop(server)
    print(json.dumps({k: merged[k] for k in SUMMED + ["processes", "latency_p50_ms", "latency_p99_ms", "frames_ok_pct"]}))
    failures = check(parts, merged, single)
    for f in failures:
        print("FAIL:", f, file=sys.stderr)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
