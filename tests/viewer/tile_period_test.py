#!/usr/bin/env python3
"""Does the sea repeat? ocean-server streams a profile of a 20 m/s JONSWAP storm; ocean-viewer
renders it headless from high up (default 400 m, looking 12 degrees down along +z, away from the
sun) and this script
measures how strongly the picture repeats at the projected period of the server's patch.

The camera has no roll and looks along the z axis, so each picture row is a line of constant world z on
the water, and a shift of one patch along x moves a pixel by L(v) = f * patch * sin(a) / (H cos(b))
along its row v: f the focal length in pixels, H the eye height, a the row's ray angle below the
horizon and b its angle from the optical axis. Per row of water within 2 km whose L lies in
[6, width / 3], each grey level less its mean over one period around it, then the correlation of
that detail at x and x + L (linear interpolation); the result is the mean over those rows (as
test_render_gl's period_correlation). A sea made of one repeating tile scores near 1; a sea that does not repeat at
that period scores near its own autocorrelation there.

Prints one JSON object. With --max-correlation C the exit status is 1 when the mean exceeds C.
Exit status: 0 pass (or measured only), 1 fail, 2 bad arguments."""

import argparse
import json
import math
import os
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "support"))
from png_decode import decode_png  # noqa: E402
from server_launch import start_server  # noqa: E402

STORM = ["--spectrum", "jonswap", "--wind-speed", "20", "--choppiness", "1.2"]


def row_lags(width, height, eye_height, pitch_deg, fov_deg, patch, max_distance):
    f = (height / 2) / math.tan(math.radians(fov_deg) / 2)
    lags = {}
    for v in range(height):
        b = math.atan((v + 0.5 - height / 2) / f)  # below the optical axis is positive
        a = math.radians(-pitch_deg) + b
        if a <= 0 or eye_height / math.tan(a) > max_distance:
            continue
        lag = f * patch * math.sin(a) / (eye_height * math.cos(b))
        if 6 <= lag <= width / 3:
            lags[v] = lag
    return lags


def repetition(png_path, lags):
    width, height, channels, rows = decode_png(open(png_path, "rb").read())
    total = 0.0
    for v, lag in lags.items():
        line = rows[v]
        g = [sum(line[x * channels:x * channels + 3]) / 3.0 for x in range(width)]
        # Less its mean over one period around each pixel: what repeats with the period stays,
        # the light's slow change across the row (sky, glitter) goes.
        half = int(lag / 2)
        detail = [g[x] - sum(g[x - half:x + half + 1]) / (2 * half + 1) for x in range(half, width - half)]
        whole, frac = int(lag), lag - int(lag)
        count = len(detail) - whole - 1
        cov = va = vb = 0.0
        for x in range(count):
            a0 = detail[x]
            b0 = detail[x + whole] * (1 - frac) + detail[x + whole + 1] * frac
            cov += a0 * b0
            va += a0 * a0
            vb += b0 * b0
        total += cov / math.sqrt(va * vb) if va > 0 and vb > 0 else 0.0
    return total / len(lags)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--build", required=True, help="the CMake build folder")
    parser.add_argument("--out", help="folder for the screenshot and logs (default: a temporary one)")
    parser.add_argument("--profile", default="desktop")
    parser.add_argument("--patch", type=float, default=256.0, help="the server's --patch, metres")
    parser.add_argument("--size", default="1280x720")
    parser.add_argument("--eye-height", type=float, default=400.0)
    parser.add_argument("--pitch", type=float, default=-12.0)
    parser.add_argument("--frames", type=int, default=30)
    parser.add_argument("--max-correlation", type=float, help="fail when the mean correlation exceeds this")
    args = parser.parse_args()
    width, height = (int(x) for x in args.size.split("x"))
    out_dir = args.out or tempfile.mkdtemp(prefix="ocean-period-")
    os.makedirs(out_dir, exist_ok=True)
    log_path = os.path.join(out_dir, "server.log")
    png = os.path.join(out_dir, "period.png")
    server, port = start_server(args.build, ["--profiles", args.profile, "--size", "256", "--patch", str(args.patch)] + STORM,
                                log_path)
    try:
        viewer = subprocess.run([os.path.join(build_dir := args.build, "client", "viewer", "ocean-viewer"),
                                 "--server", f"127.0.0.1:{port}", "--headless", "--profile", args.profile,
                                 "--size", args.size, "--frames", str(args.frames), "--yaw", "180",
                                 "--eye-height", str(args.eye_height), "--pitch", str(args.pitch),
                                 "--screenshot", png, "--json",
                                 "--first-frame-timeout", "60"], capture_output=True, text=True, timeout=300)
    finally:
        server.terminate()
        server.wait(timeout=30)
    if viewer.returncode != 0:
        sys.exit(f"FAIL: ocean-viewer ({build_dir}) exited {viewer.returncode}:\n{viewer.stderr[-2000:]}")
    lags = row_lags(width, height, args.eye_height, args.pitch, 60.0, args.patch, 2000.0)
    result = {"profile": args.profile, "patch_m": args.patch, "eye_height_m": args.eye_height, "pitch_deg": args.pitch,
              "screenshot": png, "rows": len(lags), "lag_px": [round(min(lags.values()), 1), round(max(lags.values()), 1)],
              "correlation": round(repetition(png, lags), 4)}
    if args.max_correlation is not None:
        result["max_correlation"] = args.max_correlation
        result["pass"] = result["correlation"] <= args.max_correlation
    print(json.dumps(result))
    return 0 if result.get("pass", True) else 1


if __name__ == "__main__":
    sys.exit(main())
