#!/usr/bin/python3
"""The hand-written copies of the profile table follow protocol/profile.hpp, as the server reports
it (ocean-server --help-json): the web page's profile menu, PROTOCOL.md's profile table and
README-server.md's --profiles row. (--help against the option table: test_config_loader.)

  check_tables.py OCEAN_SERVER SOURCE_DIR    every mismatch on stderr; exit 1 if any
"""
import pathlib
import re
import sys

sys.dont_write_bytecode = True
sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[2] / "deploy"))
from checks.server_config import server_tables  # noqa: E402


def page_profiles(html):
    """{id: name} of the page's <select id="profile">, without 0 (the server's choice)."""
    select = re.search(r'<select id="profile"[^>]*>(.*?)</select>', html, re.S)
    if not select:
        return None
    options = re.findall(r'<option value="(\d+)">([^<]*)</option>', select.group(1))
    return {int(value): name for value, name in options if value != "0"}


def protocol_rows(markdown):
    """{id: (name, grid, rate_hz, normals, choppy)} of PROTOCOL.md's profile table."""
    rows = {}
    for match in re.finditer(r"^\| (\d+) \| ([a-z-]+) \| (\d+) \| (\d+) \| (yes|no) \| (yes|no) \|", markdown, re.M):
        rows[int(match.group(1))] = (match.group(2), int(match.group(3)), int(match.group(4)),
                                     match.group(5) == "yes", match.group(6) == "yes")
    return rows


def main(argv):
    if len(argv) != 3:
        print(__doc__, file=sys.stderr)
        return 2
    server, source = argv[1], pathlib.Path(argv[2])
    tables = server_tables(server)
    profiles = {p["id"]: p for p in tables["profiles"]}
    problems = []

    page = page_profiles((source / "client/web/page/index.html").read_text())
    want = {i: p["name"] for i, p in profiles.items()}
    if page is None:
        problems.append("client/web/page/index.html: no <select id=\"profile\">")
    elif page != want:
        problems.append(f"client/web/page/index.html: the profile menu offers {sorted(page.items())}, "
                        f"protocol/profile.hpp has {sorted(want.items())}")

    rows = protocol_rows((source / "protocol/PROTOCOL.md").read_text())
    want_rows = {i: (p["name"], p["grid"], p["rate_hz"], p["normals"], p["choppy"]) for i, p in profiles.items()}
    for i in sorted(set(rows) | set(want_rows)):
        if rows.get(i) != want_rows.get(i):
            problems.append(f"protocol/PROTOCOL.md: profile row {i} reads {rows.get(i)}, "
                            f"protocol/profile.hpp has {want_rows.get(i)}")

    readme = (source / "server/README-server.md").read_text()
    row = next((line for line in readme.splitlines() if line.startswith("| `--profiles")), None)
    missing = [p["name"] for p in profiles.values() if row is None or not re.search(rf"\b{re.escape(p['name'])}\b", row)]
    if missing:
        problems.append(f"server/README-server.md: the --profiles row does not name {missing}")

    for problem in problems:
        print(f"check_tables: {problem}", file=sys.stderr)
    print(f"check_tables: {'FAILED' if problems else 'OK'}; {len(profiles)} profiles")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
