#!/usr/bin/env python3
"""A transparent TCP proxy between one RCSSServerMJ agent and turf's agent port that measures the agent's robot
from what the server sends it (issue 14's acceptance: RCSSServerMJ's own trained T1 client, run unchanged).

RCSSServerMJ's perceptions carry the torso's ground-truth pose, `(pos (n torso_pos) (p x y z))` and
`(quat (n torso_quat) (q w x y z))`, and the time, `(time (now t))` (shared/protocols/rcssservermj.md), so no
other channel is needed. Stdlib only. Prints one JSON line when the agent or the server closes, or when the
measured window (--seconds of simulation time after the first perception) is over:
  upright %   share of perceptions with the torso's z axis within 45 deg of vertical
  falls       times the tilt went from under 45 deg (held 0.5 s) to over 60 deg
  walked m    displacement of the torso in the field's x-y plane from the first perception after the beam
              (the first one whose position jumped by more than 1 m, or the first one if it never did) to the last
  forward m   the same projected on the robot's heading at that start
usage: measure_proxy.py LISTEN_PORT SERVER_PORT OUT.json [--seconds 60]
"""
import argparse, json, math, re, socket, struct, sys, threading

POS = re.compile(rb"\(pos \(n torso_pos\) \(p (\S+) (\S+) (\S+)\)\)")
QUAT = re.compile(rb"\(quat \(n torso_quat\) \(q (\S+) (\S+) (\S+) (\S+)\)\)")
TIME = re.compile(rb"\(time \(now (\S+)\)\)")
COS45, COS60 = math.cos(math.radians(45)), math.cos(math.radians(60))


def frames(sock):
    """Yields (header, payload) of each 4-byte big-endian framed message; ends when the socket closes."""
    buf = b""
    while True:
        while len(buf) >= 4 and len(buf) >= 4 + struct.unpack(">I", buf[:4])[0]:
            n = struct.unpack(">I", buf[:4])[0]
            yield buf[:4], buf[4:4 + n]
            buf = buf[4 + n:]
        data = sock.recv(65536)
        if not data:
            return
        buf += data


class Measure:
    def __init__(self, seconds):
        self.seconds = seconds
        self.t0 = None
        self.samples = 0
        self.upright = 0
        self.falls = 0
        self.state = "unknown"  # up (held 0.5 s), down, unknown
        self.up_since = None
        self.start = None  # (x, y, heading)
        self.last = None
        self.prev = None
        self.done = False

    def perception(self, payload):
        t, p, q = TIME.search(payload), POS.search(payload), QUAT.search(payload)
        if not (t and p and q):
            return
        t = float(t.group(1))
        x, y, z = (float(v) for v in p.groups())
        w, qx, qy, qz = (float(v) for v in q.groups())
        if self.t0 is None:
            self.t0 = t
        if t - self.t0 > self.seconds:
            self.done = True
            return
        if self.prev is not None and math.hypot(x - self.prev[0], y - self.prev[1]) > 1.0:
            self.start = None  # beamed: measure from here
        heading = math.atan2(2 * (w * qz + qx * qy), 1 - 2 * (qy * qy + qz * qz))
        if self.start is None:
            self.start = (x, y, heading)
        self.prev = (x, y)
        self.last = (x, y)
        zz = 1 - 2 * (qx * qx + qy * qy)  # the torso z axis' vertical component
        self.samples += 1
        self.upright += zz >= COS45
        if zz >= COS45:
            self.up_since = t if self.up_since is None else self.up_since
            if t - self.up_since >= 0.5:
                self.state = "up"
        else:
            self.up_since = None
        if zz < COS60 and self.state == "up":
            self.falls += 1
            self.state = "down"

    def result(self):
        walked = forward = 0.0
        if self.start and self.last:
            dx, dy = self.last[0] - self.start[0], self.last[1] - self.start[1]
            walked = math.hypot(dx, dy)
            forward = dx * math.cos(self.start[2]) + dy * math.sin(self.start[2])
        return {"perceptions": self.samples, "upright_pct": round(100.0 * self.upright / max(1, self.samples), 1),
                "falls": self.falls, "walked_m": round(walked, 2), "forward_m": round(forward, 2)}


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("listen", type=int)
    ap.add_argument("server", type=int)
    ap.add_argument("out")
    ap.add_argument("--seconds", type=float, default=60.0)
    a = ap.parse_args()
    lsock = socket.socket()
    lsock.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)
    lsock.bind(("127.0.0.1", a.listen))
    lsock.listen(1)
    agent, _ = lsock.accept()
    server = socket.create_connection(("127.0.0.1", a.server))
    for s in (agent, server):
        s.setsockopt(socket.IPPROTO_TCP, socket.TCP_NODELAY, 1)
    m = Measure(a.seconds)

    def upstream():  # agent -> server, unchanged
        try:
            for head, payload in frames(agent):
                server.sendall(head + payload)
        except OSError:
            pass
        try:
            server.shutdown(socket.SHUT_WR)
        except OSError:
            pass

    threading.Thread(target=upstream, daemon=True).start()
    try:
        for head, payload in frames(server):
            m.perception(payload)
            if m.done:
                break
            agent.sendall(head + payload)
    except OSError:
        pass
    with open(a.out, "w") as f:
        json.dump(m.result(), f)
    for s in (agent, server):
        try:
            s.close()
        except OSError:
            pass


if __name__ == "__main__":
    sys.exit(main())
