#!/usr/bin/python3
"""Finds the largest number of clients one ocean-server holds with >= --target % of frames on
time and none wrong, on this machine: a fresh server per try, N doubled from --start until a try
fails, then bisected to --resolution. Prints one JSON object per try and a summary last.

  client/loadtest/find_capacity.py --build build --profile mobile --start 250 --max 8000

Each try starts the clients at --join-rate per second, then measures --duration seconds. Passing
a try needs frames_ok_pct >= target and frames_bad == 0 (ground truth, every frame).

--scenario NAME runs an ocean-loadtest scenario instead of --profile/--transport/--link, with the
server started as the scenario needs (tick rate, epoch, weather schedule: local_server.py)."""
import argparse
import json
import os
import subprocess
import sys
import tempfile

import local_server


def run_once(args, clients):
    with tempfile.TemporaryDirectory() as workdir:
        return run_in(args, clients, workdir)


def run_in(args, clients, workdir):
    loadtest = os.path.join(args.build, "client/loadtest/ocean-loadtest")
    ramp = max(0.5, clients / args.join_rate)
    port = local_server.free_port()
    if args.scenario:
        entry = local_server.scenario(loadtest, args.scenario)
        server_args = local_server.scenario_server_args(entry, workdir, first_change_s=ramp + 2.0,
                                                        horizon_s=ramp + args.duration + 60)
        if "--profiles" not in server_args:
            server_args += ["--profiles", entry["profile"]]
        loadtest_args = ["--scenario", args.scenario]
    else:
        server_args = ["--profiles", args.profile]
        loadtest_args = ["--profile", args.profile, "--transport", args.transport] + (["--link", args.link] if args.link else [])
    server = local_server.start(
        os.path.join(args.build, "server/ocean-server"),
        ["--listen", f"127.0.0.1:{port}", "--metrics-listen", "off", "--max-clients", str(clients + 16),
         "--log-level", "warn"] + server_args + args.server_arg, port)
    try:
        cmd = [loadtest, "--server", f"127.0.0.1:{port}", "--clients", str(clients), "--ramp", f"{ramp:g}",
               "--duration", str(args.duration), "--json", "--quiet", "--server-pid", str(server.pid)] + loadtest_args
        run = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                             timeout=ramp + args.duration + 120)
        if run.returncode != 0:
            raise RuntimeError(f"ocean-loadtest exited {run.returncode}: {run.stderr[-2000:]}")
        summary = json.loads(run.stdout.strip().splitlines()[-1])
        summary["alive"] = server.poll() is None
        return summary
    finally:
        local_server.stop(server)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--build", default="build", help="build tree holding server/ and client/loadtest/")
    ap.add_argument("--profile", default="mobile")
    ap.add_argument("--transport", default="udp")
    ap.add_argument("--link", default="", help="ocean-loadtest --link, e.g. rate=256kbit,delay=80ms,loss=5%%")
    ap.add_argument("--scenario", default="", help="an ocean-loadtest scenario (replaces --profile/--transport/--link)")
    ap.add_argument("--start", type=int, default=250)
    ap.add_argument("--max", type=int, default=8000)
    ap.add_argument("--target", type=float, default=99.0, help="frames_ok_pct a try must reach")
    ap.add_argument("--duration", type=float, default=20.0, help="measured seconds after the ramp")
    ap.add_argument("--join-rate", type=float, default=100.0, help="clients started per second")
    ap.add_argument("--resolution", type=float, default=0.1, help="stop bisecting when hi/lo - 1 is below this")
    ap.add_argument("--server-arg", action="append", default=[], help="extra ocean-server argument (repeatable)")
    args = ap.parse_args()

    tries = []

    def attempt(n):
        s = run_once(args, n)
        ok = s["alive"] and s["frames_bad"] == 0 and s["frames_ok_pct"] >= args.target
        row = {"clients": n, "pass": ok, "frames_ok_pct": s["frames_ok_pct"], "frames_bad": s["frames_bad"],
               "server_cpu_pct": s.get("server_cpu_pct"), "loadtest_cpu_pct": s["loadtest_cpu_pct"],
               "latency_p99_ms": s["latency_p99_ms"], "kbps_mean": s["kbps_mean"], "keyframes": s["keyframes"],
               "clients_connected": s["clients_connected"]}
        print(json.dumps(row), flush=True)
        tries.append(row)
        return ok

    lo, hi = 0, None
    n = args.start
    while n <= args.max:
        if attempt(n):
            lo = n
            n *= 2
        else:
            hi = n
            break
    if hi is not None and lo > 0:
        while hi / lo - 1 > args.resolution:
            mid = (lo + hi) // 2
            if attempt(mid):
                lo = mid
            else:
                hi = mid
    best = next((t for t in tries if t["clients"] == lo), None)
    print(json.dumps({"largest_passing_clients": lo, "first_failing_clients": hi, "target_pct": args.target,
                      "scenario": args.scenario, "profile": args.profile, "transport": args.transport, "link": args.link,
                      "duration_s": args.duration, "server_cpu_pct_at_largest": best and best["server_cpu_pct"],
                      "tries": len(tries)}))
    return 0 if lo > 0 else 1


if __name__ == "__main__":
    sys.exit(main())
