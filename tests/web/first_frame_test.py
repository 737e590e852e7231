#!/usr/bin/python3
"""The browser viewer's first frame on a phone's link: headless Chromium with DevTools network
emulation opens the page a real ocean-server serves and connects at once; the page reports when
its socket opened, its Welcome came and its first decoded frame was drawn, in milliseconds from
navigation (performance.now()). Fails when that first frame comes later than --within seconds,
or when the emulation did not hold the page's own transfer to the link's rate (then the figure
would say nothing about the link). Prints the figures as JSON.

Exit status: 0 pass, 1 a check failed, 2 bad arguments or a tool missing.
"""
import argparse
import json
import os
import shutil
import sys
import tempfile
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from chromium_driver import REPORT, TRANSFERS, Browser, start_server, stop_server, verdict  # noqa: E402
from link_proxy import LinkProxy  # noqa: E402

STAGES = "return window.oceanStages || {};"


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--build", required=True, help="the native build tree (with web/ from -DOCEAN_BUILD_WEB=ON)")
    parser.add_argument("--chromium", default="chromium")
    parser.add_argument("--chromedriver", default="chromedriver")
    parser.add_argument("--down-kbps", type=float, default=1600.0)
    parser.add_argument("--up-kbps", type=float, default=750.0)
    parser.add_argument("--rtt-ms", type=float, default=150.0)
    parser.add_argument("--within", type=float, default=5.0, help="seconds from navigation to the first frame")
    parser.add_argument("--profile", type=int, default=1)
    args = parser.parse_args()
    for tool in (args.chromium, args.chromedriver):
        if not shutil.which(tool):
            print(f"first_frame_test: {tool} not found", file=sys.stderr)
            return 2
    if min(args.down_kbps, args.up_kbps) <= 0 or args.rtt_ms < 0 or args.within <= 0:
        print("first_frame_test: --down-kbps and --up-kbps must be > 0, --rtt-ms >= 0, --within > 0", file=sys.stderr)
        return 2

    work = tempfile.mkdtemp(prefix="ocean-first-frame-")
    failures = []
    server, ws_port, web_port = start_server(args.build, os.path.join(work, "server.log"), args.profile, "")
    # The stream through a relay at the same link: the emulation delays the WebSocket's upgrade
    # but not its messages. (So the upgrade pays the round trip twice: a pessimistic figure.)
    proxy = LinkProxy(ws_port, args.down_kbps, args.up_kbps, args.rtt_ms)
    browser = None
    try:
        browser = Browser(shutil.which(args.chromium), shutil.which(args.chromedriver), os.path.join(work, "chromium"))
        browser.emulate_network(args.down_kbps, args.up_kbps, args.rtt_ms)
        browser.open(f"http://127.0.0.1:{web_port}/index.html?connect=1&profile={args.profile}"
                     f"&ws=ws://127.0.0.1:{proxy.port}/")
        deadline, report = time.time() + max(60.0, 4 * args.within), None
        while time.time() < deadline:
            text = browser.run(REPORT)
            report = json.loads(text) if text else None
            if report and (report.get("first_frame_ms", -1) >= 0 or report["state"] in ("closed", "failed")):
                break
            time.sleep(0.2)
        transfers = browser.run(TRANSFERS)
        stages = browser.run(STAGES)
        if not report or report.get("first_frame_ms", -1) < 0:
            failures.append(f"no frame drawn within {max(60.0, 4 * args.within):.0f} s of navigation: {report}")
            raise RuntimeError
        first_s = report["first_frame_ms"] / 1000.0
        if first_s > args.within:
            failures.append(f"the first frame came {first_s:.2f} s after navigation, over {args.within} s")
        # The emulation held: the page's bytes cannot have arrived faster than the link carries them.
        page_bytes = sum(t[1] for t in transfers)
        loaded_s = max(t[3] for t in transfers) / 1000.0
        floor_s = page_bytes * 8 / (args.down_kbps * 1000)
        if loaded_s < 0.9 * floor_s:
            failures.append(f"{page_bytes} bytes loaded in {loaded_s:.2f} s, faster than {args.down_kbps} kbit/s allows "
                            f"({floor_s:.2f} s): the network emulation did not apply")
        print(json.dumps({"down_kbps": args.down_kbps, "up_kbps": args.up_kbps, "rtt_ms": args.rtt_ms,
                          "first_frame_s": round(first_s, 3), "within_s": args.within,
                          "page_loaded_s": round(loaded_s, 3), "page_bytes": page_bytes,
                          "module_loaded_s": round(stages.get("module", -1) / 1000.0, 3),
                          "runtime_ready_s": round(stages.get("ready", -1) / 1000.0, 3),
                          "socket_open_s": round(report["open_ms"] / 1000.0, 3),
                          "welcome_s": round(report["welcome_ms"] / 1000.0, 3),
                          "profile": report.get("profile"), "transfers": transfers, "stages": stages}))
    except RuntimeError:
        pass
    except Exception as e:  # WebDriver refused something, the page threw: say what, with the server's log
        failures.append(f"{type(e).__name__}: {e}")
    finally:
        if browser:
            browser.close()
        proxy.close()
        stop_server(server)
    return verdict(failures, work)


if __name__ == "__main__":
    sys.exit(main())
