#!/usr/bin/env python3
"""Vessels on screen (issue 35), checked from what ocean-viewer draws and records.

wedge: a 30 m hull at 7 m/s on an otherwise flat sea, streamed on desktop-choppy and rendered
headless at 1280x720 from 60 m up (looking 30 degrees down, where the water's reflection shows
its slopes), and the same view of the same sea without the vessel. Their difference is the hull
and what it did to the water. From the viewer's own record of the hull's pose at the last frame,
every pixel is cast onto the sea and placed in the hull's frame: the hull's box must be drawn
(nearly every pixel changed, strongly), the 50 m ahead of the bow undisturbed, and behind the
stern, in each 10 m band from 25 to 75 m back, the lateral place where the water changed most
(the wake's cusps; the trail of churned foam right behind the hull left out) must lie on a line
whose half-angle is within [12, 24] degrees (Kelvin: 19.47).

heave: a 24 m hull on a circuit through a 12 m/s swell on mobile, 240 frames headless with
--record-hulls: every frame's heave follows the decoded sea under the hull within 10 % of the
swell's height (the range of the surface amidships over the run) - the sea under the hull being
its five sampled points as the hull weighs them (bow, stern, port, starboard and twice amidships):
a 24 m hull across a crest rides below the crest, and judged against amidships alone, where in
the swell the run fell decided the figure (4.6 % in one run, 11.9 % in CI's, 7.7 % against its
points) - and no keel point stands more than the hull's draft above the decoded surface there
(the wake's depression included).

Prints one JSON object; exit 0 pass, 1 fail."""

import argparse
import csv
import json
import math
import os
import subprocess
import sys
import tempfile
import time

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "support"))
from png_decode import decode_png  # noqa: E402
from server_launch import start_server  # noqa: E402

WEDGE_FLEET = """wake-size = 256
wake-origin-x = -128
wake-origin-z = -128
{vessel}"""
WEDGE_VESSEL = """
[[vessel]]
id = 7
length = 30
beam = 7
draft = 2.0
waypoints = [[0, -125, 0], [35.714286, 125, 0]]
"""
HEAVE_FLEET = """wake-size = 512
wake-origin-x = -256
wake-origin-z = -256

[[vessel]]
id = 3
length = 24
beam = 6
draft = 1.5
repeat = true
waypoints = [[0, -100, -60], [28.57, 100, -60], [57.14, 100, 60], [85.71, -100, 60], [114.28, -100, -60]]
"""
CAMERA = {"x": 0.0, "y": 60.0, "z": 100.0, "pitch_deg": -30.0, "yaw_deg": 0.0, "fov_deg": 60.0}
WIDTH, HEIGHT = 1280, 720


def render(build, work, name, fleet, server_args, viewer_args, frames, sea_time_s):
    path = os.path.join(work, f"{name}.toml")
    with open(path, "w") as f:
        f.write(fleet)
    epoch_ms = int(time.time() * 1000) - int(sea_time_s * 1000)
    server, port = start_server(build, ["--config", path, "--epoch", str(epoch_ms)] + server_args,
                                os.path.join(work, f"{name}-server.log"))
    png, hulls = os.path.join(work, f"{name}.png"), os.path.join(work, f"{name}.csv")
    try:
        viewer = subprocess.run([os.path.join(build, "client", "viewer", "ocean-viewer"), "--server", f"127.0.0.1:{port}",
                                 "--headless", "--size", f"{WIDTH}x{HEIGHT}", "--frames", str(frames), "--screenshot", png,
                                 "--record-hulls", hulls, "--first-frame-timeout", "60"] + viewer_args,
                                capture_output=True, text=True, timeout=90)
    finally:
        server.terminate()
        server.wait(timeout=30)
    if viewer.returncode != 0:
        sys.exit(f"FAIL: ocean-viewer exited {viewer.returncode} ({name}):\n{viewer.stderr[-2000:]}")
    with open(hulls) as f:
        return png, list(csv.DictReader(f))


def load_rgb(path):
    with open(path, "rb") as f:
        w, h, c, rows = decode_png(f.read())
    return np.frombuffer(b"".join(bytes(r) for r in rows), np.uint8).reshape(h, w, c)[:, :, :3].astype(np.int32)


def ground_points(plane_y=0.0):
    """World (x, z) where each pixel's centre ray meets the plane y = plane_y (the sea: 0), as
    the viewer's Camera projects (client/render/camera.cpp); NaN above the horizon."""
    pitch, yaw = math.radians(CAMERA["pitch_deg"]), math.radians(CAMERA["yaw_deg"])
    forward = np.array([-math.sin(yaw) * math.cos(pitch), math.sin(pitch), -math.cos(yaw) * math.cos(pitch)])
    right = np.array([math.cos(yaw), 0.0, -math.sin(yaw)])
    up = np.cross(right, forward)
    t = math.tan(math.radians(CAMERA["fov_deg"]) / 2)
    px = (2 * (np.arange(WIDTH) + 0.5) / WIDTH - 1) * t * WIDTH / HEIGHT
    py = (1 - 2 * (np.arange(HEIGHT) + 0.5) / HEIGHT) * t
    rays = forward[None, None, :] + px[None, :, None] * right[None, None, :] + py[:, None, None] * up[None, None, :]
    down = rays[:, :, 1] < -1e-3
    s = np.where(down, (CAMERA["y"] - plane_y) / -np.minimum(rays[:, :, 1], -1e-3), np.nan)
    return CAMERA["x"] + s * rays[:, :, 0], CAMERA["z"] + s * rays[:, :, 2]


def wedge(build, work, result, failures):
    common = ["--profiles", "desktop-choppy", "--amplitude", "0"]
    view = ["--profile", "desktop-choppy", "--eye-height", str(CAMERA["y"]), "--pitch", str(CAMERA["pitch_deg"]),
            "--camera-z", str(CAMERA["z"])]
    # 19 s into the run at the server's start, the hull is about 30 m past x = 0 at the picture (the
    # viewer draws 20 frames about 3 s later, 4 s on a loaded machine), 150 m of wake behind it.
    with_png, hulls = render(build, work, "wedge", WEDGE_FLEET.format(vessel=WEDGE_VESSEL), common, view, 20, 19)
    without_png, _ = render(build, work, "flat", WEDGE_FLEET.format(vessel=""), common + ["--wake", "on"], view, 20, 19)
    diff = np.abs(load_rgb(with_png) - load_rgb(without_png)).max(axis=2).astype(float)
    last = hulls[-1]
    hx, hz, heading = float(last["x_m"]), float(last["z_m"]), math.radians(float(last["heading_deg"]))
    length, beam = 30.0, 7.0
    x, z = ground_points()
    dx, dz = math.cos(heading), math.sin(heading)
    along = (x - hx) * dx + (z - hz) * dz
    across = np.abs(-(x - hx) * dz + (z - hz) * dx)
    behind = -along - length / 2
    # The hull as seen: its deck, about 1.5 m above the waterline, cast from the same pixels.
    deck_x, deck_z = ground_points(1.5)
    deck_along = (deck_x - hx) * dx + (deck_z - hz) * dz
    deck_across = np.abs(-(deck_x - hx) * dz + (deck_z - hz) * dx)
    hull_box = (np.abs(deck_along) < 0.3 * length) & (deck_across < 0.3 * beam)
    # The water the bow is about to enter: 50 m of it, 50 m to each side, and not the square's last
    # 40 m. The wake's region is periodic (sim/wake_field.hpp): the waves the hull's start 3 m from
    # its left edge sent backwards come in at its right edge (9 m in, 22 s into the run).
    ahead = (along > length / 2 + 10) & (along < length / 2 + 60) & (across < 50) & (x < 128 - 40)
    result["hull_x_m"] = round(hx, 2)
    result["hull_pixels_changed_pct"] = round(100 * float((diff[hull_box] >= 20).mean()), 1)
    result["ahead_pixels"] = int(ahead.sum())
    result["ahead_pixels_changed_pct"] = round(100 * float((diff[ahead] >= 3).mean()), 2)
    result["ahead_mean_change"] = round(float(diff[ahead].mean()), 3)
    if result["hull_pixels_changed_pct"] < 90:
        failures.append(f"the hull is not drawn where it is: {result['hull_pixels_changed_pct']} % of its box changed")
    if ahead.sum() < 5000:
        failures.append(f"too little water ahead of the bow to judge ({int(ahead.sum())} pixels): the viewer started late")
    elif result["ahead_pixels_changed_pct"] > 1.0:
        failures.append(f"the water ahead of the bow is disturbed: {result['ahead_pixels_changed_pct']} % changed")
    cusps = []
    trail = 0.4 * beam + 0.06 * 80 + 3  # the foam trail's half-width 80 m back, and a margin
    for near in range(25, 75, 10):
        band = (behind >= near) & (behind < near + 10) & (across > trail) & (across < 60)
        lateral = np.arange(trail, 60, 2.0)
        profile = [diff[band & (across >= a) & (across < a + 2)].mean() for a in lateral]
        peak = int(np.nanargmax(profile))
        cusps.append((near + 5, lateral[peak] + 1.0, profile[peak], float(np.nanmedian(profile))))
    slope, offset = np.polyfit([c[0] for c in cusps], [c[1] for c in cusps], 1)
    result["cusps"] = [[c[0], round(c[1], 1), round(c[2], 2)] for c in cusps]
    result["wedge_half_angle_deg"] = round(math.degrees(math.atan(slope)), 2)
    if not 12.0 <= result["wedge_half_angle_deg"] <= 24.0:
        failures.append(f"the wake's half-angle is {result['wedge_half_angle_deg']} deg, not within [12, 24]")
    if any(c[2] < 1.5 * c[3] for c in cusps):
        failures.append(f"a band behind the hull has no clear cusp (peak, median): {cusps}")


def heave(build, work, result, failures):
    sea = ["--profiles", "mobile", "--spectrum", "jonswap", "--wind-speed", "12", "--small-wave", "3"]
    _, rows = render(build, work, "swell", HEAVE_FLEET, sea, ["--profile", "mobile", "--eye-height", "30"], 240, 40)
    mid = np.array([float(r["surface_mid_m"]) for r in rows])
    points = [np.array([float(r[f"surface_{p}_m"]) for r in rows]) for p in ("bow", "stern", "port", "starboard")]
    under = (sum(points) + 2.0 * mid) / 6.0  # the sea under the hull, weighed as hull_motion.cpp does
    heaves = np.array([float(r["heave_m"]) for r in rows])
    keel = np.array([float(r["keel_above_m"]) for r in rows])
    swell = float(mid.max() - mid.min())
    worst = float(np.abs(heaves - under).max())
    result.update({"heave_frames": len(rows), "swell_height_m": round(swell, 3), "heave_worst_m": round(worst, 4),
                   "heave_worst_pct_of_swell": round(100 * worst / swell, 2) if swell > 0 else None,
                   "heave_worst_vs_amidships_m": round(float(np.abs(heaves - mid).max()), 4),
                   "keel_above_surface_max_m": round(float(keel.max()), 3), "draft_m": float(rows[0]["draft_m"])})
    if len(rows) < 200 or swell < 0.5:
        failures.append(f"too little to judge: {len(rows)} frames posed, a swell of {swell:.2f} m")
    elif worst > 0.1 * swell:
        failures.append(f"the heave leaves the sea under the hull by {worst:.3f} m, over 10 % of the {swell:.2f} m swell")
    if keel.max() >= float(rows[0]["draft_m"]):
        failures.append(f"a keel point stands {keel.max():.2f} m above the surface, more than the draft")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--build", required=True)
    parser.add_argument("--out", help="folder for the pictures, records and logs (default: a temporary one)")
    parser.add_argument("--only", choices=["wedge", "heave"])
    args = parser.parse_args()
    work = args.out or tempfile.mkdtemp(prefix="ocean-vessels-")
    os.makedirs(work, exist_ok=True)
    result, failures = {"out": work}, []
    if args.only in (None, "wedge"):
        wedge(args.build, work, result, failures)
    if args.only in (None, "heave"):
        heave(args.build, work, result, failures)
    print(json.dumps(result))
    for f in failures:
        print("FAIL:", f, file=sys.stderr)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
