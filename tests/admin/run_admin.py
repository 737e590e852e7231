#!/usr/bin/python3
"""ocean-admin against a real ocean-server: an accepted change (its SceneUpdate, effective a lead
in the future, with the new wind, then seen by --show), a wrong token (exit 3, the server's
reason on stderr), an out-of-range value (refused by ocean-admin itself: exit 2, nothing sent),
an unreadable token file (exit 2) and no server (exit 4)."""
import argparse
import json
import os
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "../../client/loadtest"))
import local_server  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import admin_expect  # noqa: E402


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--server-bin", required=True)
    parser.add_argument("--admin-bin", required=True)
    args = parser.parse_args()
    failures = []

    def admin(*flags, env=None):
        r = subprocess.run([args.admin_bin, *flags, "--timeout", "5"], stdout=subprocess.PIPE,
                           stderr=subprocess.PIPE, text=True, timeout=20, env=env)
        return r.returncode, r.stdout, r.stderr

    def expect(name, got, code, stderr_has=None):
        return admin_expect.expect(failures, name, got, code, stderr_has)

    with tempfile.TemporaryDirectory() as work:
        token, wrong = os.path.join(work, "token"), os.path.join(work, "wrong")
        with open(token, "w") as f:
            f.write("test-admin-token\n")
        with open(wrong, "w") as f:
            f.write("not-the-token\n")
        port = local_server.free_port()
        server = local_server.start(args.server_bin, [
            "--listen", f"127.0.0.1:{port}", "--metrics-listen", "off", "--size", "64", "--patch", "64",
            "--profiles", "mobile", "--wind-speed", "10", "--admin-token-file", token, "--log-level", "warn"], port)
        addr = f"127.0.0.1:{port}"
        try:
            out = expect("change", admin("--server", addr, "--token-file", token, "--wind-speed", "17.5",
                                         "--spectrum", "jonswap"), 0)
            if out:
                u = json.loads(out.strip().splitlines()[-1])
                if not u["effective_tick"] > u["welcome_tick"]:
                    failures.append(f"change: effective_tick {u['effective_tick']} is not after the Welcome's "
                                    f"tick {u['welcome_tick']}")
                if u["scene"]["wind_speed_mps"] != 17.5 or u["scene"]["spectrum"] != "jonswap":
                    failures.append(f"change: the SceneUpdate's scene is not the change: {u['scene']}")
                if u["request_id"] == 0:
                    failures.append("change: request_id 0 is the broadcast's, not ours")
            out = expect("show", admin("--server", addr, "--show"), 0)
            if out:
                s = json.loads(out.strip().splitlines()[-1])
                winds = [s["scene"]["wind_speed_mps"]] + [a["scene"]["wind_speed_mps"] for a in s["announced"]]
                if 17.5 not in winds:
                    failures.append(f"show: the changed wind is neither in force nor announced: {s}")
                # Deep water as the wire says it (0), not a JSON null.
                if s["scene"]["depth_m"] != 0:
                    failures.append(f"show: a deep sea's depth_m is {s['scene']['depth_m']!r}, not 0")
            env = dict(os.environ, OCEAN_ADMIN_TOKEN="test-admin-token")
            expect("token from the environment", admin("--server", addr, "--amplitude", "1.5", env=env), 0)
            expect("wrong token", admin("--server", addr, "--token-file", wrong, "--wind-speed", "12"), 3,
                   "unauthorized")
            expect("out of range", admin("--server", addr, "--token-file", token, "--wind-speed", "500"), 2,
                   "--wind-speed")
            expect("unreadable token file", admin("--server", addr, "--token-file", os.path.join(work, "missing"),
                                                  "--wind-speed", "12"), 2, "--token-file")
            expect("no change asked", admin("--server", addr, "--token-file", token), 2, "nothing to do")
        finally:
            local_server.stop(server)
        # The server is gone: nothing listens on its port now.
        expect("no server", admin("--server", addr, "--token-file", token, "--wind-speed", "12"), 4, "cannot connect")

    for f in failures:
        print("FAIL:", f)
    print("ok" if not failures else f"{len(failures)} failure(s)")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
