#!/usr/bin/python3
"""ocean-server's TLS (--tls-cert, --tls-key) end to end: the page's listener speaks https and the
WebSocket's wss with the given certificate, a client speaking plain HTTP to them is refused and
logged while the server serves on, SIGHUP puts a renewed certificate in force for new connections,
and a SIGHUP that finds a broken file keeps the old one, says why and counts it. Bad pairs at start
are refused with exit status 2 and a message naming the file.

Exit status: 0 pass, 1 a check failed, 2 bad arguments or a tool missing.
"""
import argparse
import json
import os
import re
import shutil
import signal
import socket
import ssl
import subprocess
import sys
import tempfile
import time
import urllib.request


def make_pair(folder, name):
    cert, key = os.path.join(folder, f"{name}-cert.pem"), os.path.join(folder, f"{name}-key.pem")
    subprocess.run(["openssl", "req", "-x509", "-newkey", "rsa:2048", "-nodes", "-keyout", key, "-out", cert, "-days", "2",
                    "-subj", f"/CN={name}", "-addext", "subjectAltName=IP:127.0.0.1"], check=True, capture_output=True)
    return cert, key


def der_of(pem_file):
    return ssl.PEM_cert_to_DER_cert(open(pem_file).read())


def served_der(port):
    context = ssl.create_default_context()
    context.check_hostname, context.verify_mode = False, ssl.CERT_NONE
    with socket.create_connection(("127.0.0.1", port), timeout=10) as raw, context.wrap_socket(raw) as tls:
        return tls.getpeercert(binary_form=True)


def plain_answer(port, request):
    """What a client speaking in the clear to a TLS port gets back (b"" when it is cut off)."""
    with socket.create_connection(("127.0.0.1", port), timeout=10) as raw:
        raw.sendall(request)
        try:
            return raw.recv(4096)
        except (ConnectionResetError, socket.timeout):
            return b""


def wait_for(predicate, seconds):
    deadline = time.time() + seconds
    while time.time() < deadline:
        if predicate():
            return True
        time.sleep(0.1)
    return False


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--server-bin", required=True)
    args = parser.parse_args()
    if not shutil.which("openssl"):
        print("tls_reload_test: the openssl tool is missing (apt install openssl)", file=sys.stderr)
        return 2
    work = tempfile.mkdtemp(prefix="ocean-tls-")
    failures = []
    first, renewed = make_pair(work, "first"), make_pair(work, "renewed")
    cert, key = os.path.join(work, "cert.pem"), os.path.join(work, "key.pem")
    shutil.copy(first[0], cert)
    shutil.copy(first[1], key)
    root = os.path.join(work, "web")  # a stand-in page: what is served matters here, not what it does
    os.mkdir(root)
    for name in ("index.html", "viewer.js", "ocean-web.js", "ocean-web.wasm"):
        with open(os.path.join(root, name), "w") as f:
            f.write(f"<!-- {name} -->\n")

    # Pairs refused at start: exit 2, the file named.
    wrong = os.path.join(work, "garbage.pem")
    with open(wrong, "w") as f:
        f.write("not a certificate\n")
    missing = os.path.join(work, "none.pem")
    for cert_file, key_file, says in ((wrong, key, f"--tls-cert '{wrong}': not a PEM certificate chain"),
                                      (cert, renewed[1], f"--tls-key '{renewed[1]}': not a PEM private key, or not the certificate's"),
                                      (missing, key, f"--tls-cert '{missing}': cannot read it")):
        run = subprocess.run([args.server_bin, "--listen", "127.0.0.1:0", "--ws-listen", "127.0.0.1:0", "--metrics-listen", "off",
                              "--tls-cert", cert_file, "--tls-key", key_file], capture_output=True, text=True, timeout=60)
        if run.returncode != 2 or says not in run.stderr:
            failures.append(f"--tls-cert {cert_file} --tls-key {key_file}: exit {run.returncode}, stderr {run.stderr.strip()[-300:]!r}")

    log_path = os.path.join(work, "server.log")
    log = open(log_path, "w")
    server = subprocess.Popen([args.server_bin, "--listen", "127.0.0.1:0", "--ws-listen", "127.0.0.1:0", "--web-listen", "127.0.0.1:0",
                               "--web-root", root, "--metrics-listen", "127.0.0.1:0", "--size", "64", "--profiles", "mobile",
                               "--tls-cert", cert, "--tls-key", key], stdout=log, stderr=subprocess.STDOUT)
    text = lambda: open(log_path).read()  # noqa: E731
    try:
        if not wait_for(lambda: "listening" in text() or server.poll() is not None, 30):
            raise RuntimeError("the server did not report its ports")
        match = re.search(r"ws=\S+:(\d+) metrics=\S+:(\d+) web=\S+:(\d+)", text())
        if not match:
            raise RuntimeError(f"no ports in the log: {text()[-500:]}")
        ws, metrics, web = (int(v) for v in match.groups())

        for port, what in ((web, "the page"), (ws, "the WebSocket")):
            if served_der(port) != der_of(first[0]):
                failures.append(f"{what} does not present --tls-cert")
        context = ssl.create_default_context()
        context.check_hostname, context.verify_mode = False, ssl.CERT_NONE
        with urllib.request.urlopen(f"https://127.0.0.1:{web}/ocean-web.json", context=context, timeout=10) as reply:
            if json.loads(reply.read()).get("ws_port") != ws:
                failures.append("https /ocean-web.json names another WebSocket port")
        # A wss upgrade: the WebSocket handshake inside TLS.
        with socket.create_connection(("127.0.0.1", ws), timeout=10) as raw, context.wrap_socket(raw) as tls:
            tls.sendall(f"GET / HTTP/1.1\r\nHost: 127.0.0.1:{ws}\r\nUpgrade: websocket\r\nConnection: Upgrade\r\n"
                        "Sec-WebSocket-Key: dGhlIHNhbXBsZSBub25jZQ==\r\nSec-WebSocket-Version: 13\r\n\r\n".encode())
            answer = tls.recv(4096).decode(errors="replace")
            if not answer.startswith("HTTP/1.1 101"):
                failures.append(f"a wss upgrade was answered {answer.splitlines()[0] if answer else 'with nothing'!r}")
        # Plain HTTP to the https page: refused and logged, nothing else.
        plain = plain_answer(web, b"GET / HTTP/1.1\r\nHost: x\r\n\r\n")
        if plain.startswith(b"HTTP/1.1 200"):
            failures.append("plain HTTP got the page from the https listener")
        if not wait_for(lambda: "transport=web peer=127.0.0.1 reason=tls_handshake_failed" in text(), 10):
            failures.append("a plain HTTP request to the https page was not logged as tls_handshake_failed")
        # A plain ws:// upgrade to the wss port: refused the same way, logged for the WebSocket.
        plain = plain_answer(ws, f"GET / HTTP/1.1\r\nHost: 127.0.0.1:{ws}\r\nUpgrade: websocket\r\nConnection: Upgrade\r\n"
                                 "Sec-WebSocket-Key: dGhlIHNhbXBsZSBub25jZQ==\r\nSec-WebSocket-Version: 13\r\n\r\n".encode())
        if plain.startswith(b"HTTP/1.1 101"):
            failures.append("a plain ws:// upgrade was taken by the wss listener")
        if not wait_for(lambda: re.search(r"transport=ws peer=127\.0\.0\.1:\d+ reason=tls_handshake_failed", text()), 10):
            failures.append("a plain ws:// upgrade to the wss port was not logged as tls_handshake_failed")

        # A renewal: new connections get the new certificate.
        shutil.copy(renewed[0], cert)
        shutil.copy(renewed[1], key)
        server.send_signal(signal.SIGHUP)
        if not wait_for(lambda: "read again, in force for new connections" in text(), 10):
            failures.append("SIGHUP did not say the certificate was read again")
        for port, what in ((web, "the page"), (ws, "the WebSocket")):
            if served_der(port) != der_of(renewed[0]):
                failures.append(f"after SIGHUP {what} does not present the renewed certificate")
        # A broken renewal: the one in force stays, the error is logged and counted.
        shutil.copy(wrong, cert)
        server.send_signal(signal.SIGHUP)
        if not wait_for(lambda: "the certificate in force stays" in text(), 10):
            failures.append("a SIGHUP with a broken --tls-cert was not logged")
        if served_der(web) != der_of(renewed[0]):
            failures.append("a broken renewal replaced the certificate in force")
        with urllib.request.urlopen(f"http://127.0.0.1:{metrics}/metrics", timeout=10) as reply:
            scraped = reply.read().decode()
        if not re.search(r"^ocean_tls_reload_failures_total 1(\.0)?$", scraped, re.M):
            failures.append("ocean_tls_reload_failures_total is not 1 after one broken renewal")
        if not re.search(r'^ocean_rejects_total\{reason="tls_handshake_failed"\} 2(\.0)?$', scraped, re.M):
            failures.append("ocean_rejects_total{reason=\"tls_handshake_failed\"} is not 2 (the page's and the socket's)")
        if server.poll() is not None:
            failures.append(f"the server stopped (exit {server.returncode})")
        server.send_signal(signal.SIGTERM)
        if server.wait(20) != 0:
            failures.append(f"SIGTERM: exit {server.returncode}, not 0")
    except Exception as e:  # noqa: BLE001 - said below with the server's log
        failures.append(f"{type(e).__name__}: {e}")
    finally:
        if server.poll() is None:
            server.kill()
    if failures:
        for failure in failures:
            print("FAIL:", failure)
        print(text()[-3000:])
        return 1
    print(json.dumps({"https": web, "wss": ws, "renewed_on_sighup": True, "broken_renewal_kept_old": True}))
    shutil.rmtree(work, ignore_errors=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
