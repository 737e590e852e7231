"""Headless Chromium over WebDriver (chromedriver, plain HTTP + JSON) and an ocean-server that
serves the page (--web-listen) and its WebSocket (--ws-listen): what the browser tests share."""
import base64
import json
import os
import re
import shutil
import socket
import subprocess
import sys
import time
import urllib.error
import urllib.request


# The page's figures (WebViewer::report), once its runtime is up; null before.
REPORT = ("return (typeof Module !== 'undefined' && Module.calledRun) ? "
          "Module.UTF8ToString(Module.ccall('ocean_web_report', 'number', [], [])) : null;")


# What crossed the wire for the page and everything it loaded, from the browser's own Resource
# Timing of a same-origin page: per file its path, bytes on the wire (headers included), bytes
# decoded, and when its response ended (ms from navigation).
TRANSFERS = ("return [performance.getEntriesByType('navigation')[0]]"
             ".concat(performance.getEntriesByType('resource'))"
             ".map(e => [new URL(e.name).pathname, e.transferSize, e.decodedBodySize, Math.round(e.responseEnd)]);")


def free_port():
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def http(method, url, body=None, timeout=60):
    data = json.dumps(body).encode() if body is not None else None
    request = urllib.request.Request(url, data=data, method=method, headers={"Content-Type": "application/json"})
    try:
        with urllib.request.urlopen(request, timeout=timeout) as reply:
            return json.loads(reply.read().decode())
    except urllib.error.HTTPError as e:  # WebDriver's own message says what went wrong
        raise OSError(f"{method} {url}: HTTP {e.code}: {e.read().decode(errors='replace')[:500]}") from None


def start_server(build, log_path, profile, fleet, extra=()):
    # mobile-choppy (with a choppy sea) only when asked for: its sim and encoder would cost the
    # others' frame rate.
    choppy = ["--profiles", "mobile,lite,mobile-choppy", "--choppiness", "1.2"] if profile == 5 else []
    args = [os.path.join(build, "server", "ocean-server"), "--listen", "127.0.0.1:0", "--ws-listen", "127.0.0.1:0",
            "--web-listen", "127.0.0.1:0", "--metrics-listen", "127.0.0.1:0"] + (choppy or ["--profiles", "mobile,lite"])
    if fleet:
        args += ["--config", fleet]
    args += list(extra)
    log = open(log_path, "w")
    server = subprocess.Popen(args, stdout=log, stderr=subprocess.STDOUT)
    deadline = time.time() + 30
    while time.time() < deadline:
        text = open(log_path).read()
        match = re.search(r"listening tcp=\S+ udp=\S+ ws=\S+:(\d+) metrics=\S+ web=\S+:(\d+)", text)
        if match:
            return server, int(match.group(1)), int(match.group(2))
        if server.poll() is not None:
            break
        time.sleep(0.1)
    server.kill()
    sys.exit(f"FAIL: ocean-server did not report its ports:\n{open(log_path).read()}")


class Browser:
    """One headless Chromium session over chromedriver's WebDriver HTTP API."""

    def __init__(self, chromium, chromedriver, profile_dir, insecure_certs=False):
        self.profile_dir = profile_dir
        self.insecure_certs = insecure_certs  # a self-signed test certificate is let in
        self.port = free_port()
        self.driver = subprocess.Popen([chromedriver, f"--port={self.port}"], stdout=subprocess.DEVNULL,
                                       stderr=subprocess.DEVNULL)
        self.base = f"http://127.0.0.1:{self.port}"
        deadline = time.time() + 30
        while True:
            try:
                if http("GET", self.base + "/status", timeout=2)["value"]["ready"]:
                    break
            except OSError:
                pass
            if time.time() > deadline:
                self.driver.kill()
                sys.exit("FAIL: chromedriver did not start")
            time.sleep(0.2)
        try:
            self.session = self.start_session(chromium, profile_dir)
        except Exception:
            self.driver.kill()
            subprocess.run(["pkill", "-KILL", "-f", "--", f"--user-data-dir={profile_dir}"], check=False)
            raise

    def start_session(self, chromium, profile_dir):
        options = {"binary": chromium,
                   "args": ["--headless=new", "--no-sandbox", "--use-angle=swiftshader", "--enable-unsafe-swiftshader",
                            "--window-size=1280,720", "--disable-dev-shm-usage", f"--user-data-dir={profile_dir}",
                            "--autoplay-policy=no-user-gesture-required"]}
        if self.insecure_certs:
            options["args"].append("--ignore-certificate-errors")
        reply = http("POST", self.base + "/session",
                     {"capabilities": {"alwaysMatch": {"browserName": "chrome", "goog:chromeOptions": options,
                                                       "acceptInsecureCerts": self.insecure_certs}}})
        return f"{self.base}/session/{reply['value']['sessionId']}"

    def emulate_network(self, down_kbps, up_kbps, rtt_ms):
        """DevTools network emulation (chromedriver's Network.emulateNetworkConditions) for every
        request from now on: a phone's link on loopback. Throughputs in kbit/s, as links are quoted."""
        http("POST", self.session + "/chromium/network_conditions",
             {"network_conditions": {"offline": False, "latency": rtt_ms, "download_throughput": down_kbps * 1000 / 8,
                                     "upload_throughput": up_kbps * 1000 / 8}})

    def open(self, url):
        http("POST", self.session + "/url", {"url": url})

    def set_viewport(self, width, height):
        """--window-size sizes the window, whose frame takes some of it: grow it by that much."""
        frame_w, frame_h = self.run("return [window.outerWidth - window.innerWidth, window.outerHeight - window.innerHeight];")
        http("POST", self.session + "/window/rect", {"width": width + frame_w, "height": height + frame_h})
        return self.run("return [window.innerWidth, window.innerHeight];")

    def run(self, script):
        return http("POST", self.session + "/execute/sync", {"script": script, "args": []})["value"]

    def screenshot(self):
        return base64.b64decode(http("GET", self.session + "/screenshot")["value"])

    def close(self):
        try:
            http("DELETE", self.session, timeout=10)
        except OSError:
            pass
        self.driver.terminate()
        try:
            self.driver.wait(10)
        except subprocess.TimeoutExpired:
            self.driver.kill()
        # A browser that did not quit (a busy page, a timed-out DELETE) would keep its software
        # rasterizer spinning beside the tests that run next: its processes all name our profile.
        subprocess.run(["pkill", "-KILL", "-f", "--", f"--user-data-dir={self.profile_dir}"], check=False)


def stop_server(server):
    server.terminate()
    try:
        server.wait(10)
    except subprocess.TimeoutExpired:
        server.kill()


def verdict(failures, work):
    """The exit status: 0 and the work folder removed when nothing failed, else 1 after printing
    each failure and the end of the server's log."""
    if not failures:
        shutil.rmtree(work, ignore_errors=True)
        return 0
    for failure in failures:
        print("FAIL:", failure)
    print(open(os.path.join(work, "server.log")).read()[-3000:])
    return 1


def self_signed_certificate(work):
    """A certificate for 127.0.0.1 and its key, made by openssl: (cert, key) paths."""
    cert, key = os.path.join(work, "cert.pem"), os.path.join(work, "key.pem")
    subprocess.run(["openssl", "req", "-x509", "-newkey", "rsa:2048", "-nodes", "-keyout", key, "-out", cert, "-days", "2",
                    "-subj", "/CN=127.0.0.1", "-addext", "subjectAltName=IP:127.0.0.1,DNS:localhost"],
                   check=True, capture_output=True)
    return cert, key
