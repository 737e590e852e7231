"""LinkProxy: a TCP relay on loopback that carries each direction at a link's rate and one-way
delay (half the round trip), for the WebSocket stream that Chromium's DevTools network emulation
leaves unthrottled (it delays the upgrade request, not the messages after it)."""
import collections
import socket
import threading
import time


class _Direction:
    """Bytes from `source` reach `sink` `delay_s` later, no faster than `bits_per_s`."""

    def __init__(self, source, sink, bits_per_s, delay_s):
        self.source, self.sink, self.bits_per_s, self.delay_s = source, sink, bits_per_s, delay_s
        self.queue = collections.deque()
        self.ready = threading.Condition()
        self.closed = False
        threading.Thread(target=self.read, daemon=True).start()
        threading.Thread(target=self.write, daemon=True).start()

    def read(self):
        while True:
            try:
                data = self.source.recv(16384)
            except OSError:
                data = b""
            with self.ready:
                if data:
                    self.queue.append((time.monotonic() + self.delay_s, data))
                else:
                    self.closed = True
                self.ready.notify()
            if not data:
                return

    def write(self):
        free_at = 0.0  # when the link has sent what it was given
        while True:
            with self.ready:
                while not self.queue and not self.closed:
                    self.ready.wait()
                if not self.queue:
                    break
                due, data = self.queue.popleft()
            # A chunk leaves once it has crossed (the delay) and the link is free, then holds the
            # link for its bits; sent in 1500-byte pieces so the pace is a packet's.
            for start in range(0, len(data), 1500):
                piece = data[start:start + 1500]
                send_at = max(due, free_at)
                wait = send_at - time.monotonic()
                if wait > 0:
                    time.sleep(wait)
                free_at = send_at + len(piece) * 8 / self.bits_per_s
                try:
                    self.sink.sendall(piece)
                except OSError:
                    return
        try:
            self.sink.shutdown(socket.SHUT_WR)
        except OSError:
            pass


class LinkProxy:
    """Listens on an ephemeral loopback port (`port`) and relays every connection to `target_port`."""

    def __init__(self, target_port, down_kbps, up_kbps, rtt_ms):
        self.target_port = target_port
        self.down_bps, self.up_bps, self.one_way_s = down_kbps * 1000, up_kbps * 1000, rtt_ms / 2000
        self.listener = socket.socket()
        self.listener.bind(("127.0.0.1", 0))
        self.listener.listen(8)
        self.port = self.listener.getsockname()[1]
        threading.Thread(target=self.accept, daemon=True).start()

    def accept(self):
        while True:
            try:
                client, _ = self.listener.accept()
            except OSError:
                return
            server = socket.create_connection(("127.0.0.1", self.target_port))
            for s in (client, server):
                s.setsockopt(socket.IPPROTO_TCP, socket.TCP_NODELAY, 1)
            _Direction(client, server, self.up_bps, self.one_way_s)
            _Direction(server, client, self.down_bps, self.one_way_s)

    def close(self):
        self.listener.close()
