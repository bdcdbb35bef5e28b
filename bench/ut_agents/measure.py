#!/usr/bin/env python3
"""Measures real SimSpark agents playing on turf (issue 12): upright share, falls, approach to the ball.
Run by bench/ut_agents/run_match.sh (bench/run.sh ut-agents); stdlib only.

Sources:
  * torso pose and ball: turf-viewer's WebSocket (/ws), which relays turf-sim's DDS topics robots/links (every
    body's world pose) and world_state (ball); turf-viewer must run on the launch's DDS domain and prefix.
  * play mode and the kick-off: the SimSpark bridge's trainer port: this script sends (kickOff Left).

Per robot on the field (torso |y| < 11 m when the window starts; parked Naos stand at y = -12):
  upright %  = share of samples with the torso z-axis within 45 deg of vertical (R[2][2] >= cos 45 deg)
  falls      = times the torso went from "up" (tilt < 45 deg, held 0.5 s) to "down" (tilt > 60 deg); the dips of a
               get-up routine that never reach 60 deg and a fall before the robot stood 0.5 s again count no fall
  closest    = min horizontal distance torso -> ball in the window; start = the same at window start
  ball moved = ball's max horizontal displacement from its position at window start (> 0.10 m: moved)
"""
import argparse, base64, csv, json, math, os, socket, struct, sys, threading, time

COS45 = math.cos(math.radians(45))
COS60 = math.cos(math.radians(60))


# ---------------- minimal WebSocket client (RFC 6455, text frames, no extensions) ----------------
class WS:
    def __init__(self, host, port, path="/ws"):
        self.s = socket.create_connection((host, port), timeout=10)
        key = base64.b64encode(os.urandom(16)).decode()
        req = (f"GET {path} HTTP/1.1\r\nHost: {host}:{port}\r\nUpgrade: websocket\r\nConnection: Upgrade\r\n"
               f"Sec-WebSocket-Key: {key}\r\nSec-WebSocket-Version: 13\r\n\r\n")
        self.s.sendall(req.encode())
        buf = b""
        while b"\r\n\r\n" not in buf:
            d = self.s.recv(4096)
            if not d:
                raise RuntimeError("viewer closed during handshake")
            buf += d
        head, self.rest = buf.split(b"\r\n\r\n", 1)
        if b" 101 " not in head.split(b"\r\n")[0]:
            raise RuntimeError("WebSocket upgrade refused: " + head.decode(errors="replace"))
        self.s.settimeout(30)

    def _read(self, n):
        while len(self.rest) < n:
            d = self.s.recv(1 << 16)
            if not d:
                raise EOFError
            self.rest += d
        out, self.rest = self.rest[:n], self.rest[n:]
        return out

    def _send(self, op, payload):
        mask = os.urandom(4)
        n = len(payload)
        hdr = bytes([0x80 | op])
        if n < 126:
            hdr += bytes([0x80 | n])
        elif n < 65536:
            hdr += bytes([0x80 | 126]) + struct.pack(">H", n)
        else:
            hdr += bytes([0x80 | 127]) + struct.pack(">Q", n)
        self.s.sendall(hdr + mask + bytes(b ^ mask[i % 4] for i, b in enumerate(payload)))

    def recv(self):
        data, first_op = b"", None
        while True:
            b0, b1 = self._read(2)
            op, fin, n = b0 & 0x0F, b0 & 0x80, b1 & 0x7F
            if n == 126:
                n = struct.unpack(">H", self._read(2))[0]
            elif n == 127:
                n = struct.unpack(">Q", self._read(8))[0]
            mask = self._read(4) if b1 & 0x80 else None
            p = self._read(n)
            if mask:
                p = bytes(b ^ mask[i % 4] for i, b in enumerate(p))
            if op == 9:
                self._send(10, p)
                continue
            if op == 10:
                continue
            if op == 8:
                raise EOFError
            if op != 0:
                first_op = op
            data += p
            if fin:
                return data.decode() if first_op == 1 else data


# ---------------- trainer / monitor port ----------------
class Trainer:
    def __init__(self, host, port):
        self.s = socket.create_connection((host, port), timeout=10)
        self.s.settimeout(None)
        self.modes, self.mode, self.time, self.lock = [], None, None, threading.Lock()
        threading.Thread(target=self._loop, daemon=True).start()

    def send(self, text):
        b = text.encode()
        self.s.sendall(struct.pack(">I", len(b)) + b)

    def _recvn(self, n):
        out = b""
        while len(out) < n:
            d = self.s.recv(n - len(out))
            if not d:
                raise EOFError
            out += d
        return out

    def _loop(self):
        try:
            while True:
                (n,) = struct.unpack(">I", self._recvn(4))
                msg = self._recvn(n).decode(errors="replace")
                with self.lock:
                    if "(play_modes" in msg:
                        i = msg.index("(play_modes") + len("(play_modes")
                        self.modes = msg[i:msg.index(")", i)].split()
                    for key in ("time", "play_mode"):
                        k = "(" + key + " "
                        if k in msg:
                            j = msg.index(k) + len(k)
                            v = msg[j:msg.index(")", j)]
                            if key == "time":
                                self.time = float(v)
                            else:
                                self.mode = int(v)
        except (EOFError, OSError):
            pass

    def mode_name(self):
        with self.lock:
            if self.mode is None:
                return "?"
            return self.modes[self.mode] if self.mode < len(self.modes) else str(self.mode)


def up_z(q):  # q = (w, x, y, z): world z-component of the body z-axis
    w, x, y, z = q
    return 1.0 - 2.0 * (x * x + y * y)


def heading(q):  # q = (w, x, y, z): degrees from world +x to the torso's forward axis (its y), in the ground plane
    w, x, y, z = q
    return math.degrees(math.atan2(1.0 - 2.0 * (x * x + z * z), 2.0 * (x * y - w * z)))


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--viewer-port", type=int, default=8077)
    ap.add_argument("--monitor-port", type=int, default=3200)
    ap.add_argument("--host", default="127.0.0.1")
    ap.add_argument("--duration", type=float, default=60.0, help="sim seconds measured")
    ap.add_argument("--expect", type=int, default=4, help="robots on the field to wait for")
    ap.add_argument("--settle", type=float, default=5.0, help="sim seconds after they are on the field before kick-off")
    ap.add_argument("--kickoff", default="Left", help="team for (kickOff X); 'none' to send nothing")
    ap.add_argument("--wait-timeout", type=float, default=120.0, help="wall seconds to wait for the robots")
    ap.add_argument("--csv", default=None, help="write every sample (t, robot, x, y, z, upz, ball, play mode, heading in deg) here")
    ap.add_argument("--json", default=None, help="write the result table as JSON here")
    ap.add_argument("--feet-csv", default=None,
                    help="write each measured robot's feet (and type 4's toes) here: t, robot, body, x, y, z")
    a = ap.parse_args()

    tr = Trainer(a.host, a.monitor_port)
    ws = WS(a.host, a.viewer_port)
    torso_idx = {}
    feet_idx = {}  # robot -> {body name: index in its links}
    fw = csv.writer(open(a.feet_csv, "w", newline="")) if a.feet_csv else None
    cw = csv.writer(open(a.csv, "w", newline="")) if a.csv else None
    if cw:
        cw.writerow(["t", "robot", "x", "y", "z", "upz", "ball_x", "ball_y", "ball_z", "play_mode", "heading"])

    def poses(msg):
        out = {}
        for name, p in msg.get("links", {}).items():
            i = torso_idx.get(name)
            if i is None or len(p) < 7 * (i + 1):
                continue
            out[name] = (p[7 * i:7 * i + 3], p[7 * i + 3:7 * i + 7])
        return out

    # 1. wait for the scene and for `expect` robots continuously on the field (|y| < 11 m, torso 0.15..0.6 m high)
    #    for `settle` s of sim time.  (Parked Naos at y = -12 are ignored; so are start-up transients.)
    t_wall = time.time()
    since, on_field = {}, set()
    while True:
        if time.time() - t_wall > a.wait_timeout:
            sys.exit(f"measure: only {len(on_field)} of {a.expect} robots on the field after {a.wait_timeout} s")
        m = json.loads(ws.recv())
        if m.get("type") == "legged":
            for r in m["robots"]:
                bodies = r["bodies"]
                idx = [i for i, b in enumerate(bodies) if b == "torso" or b.endswith("torso")]
                if idx:
                    torso_idx[r["name"]] = idx[0]
                for i, b in enumerate(bodies):
                    if b.split("/")[-1] in ("lfoot", "rfoot", "ltoe", "rtoe"):
                        feet_idx.setdefault(r["name"], {})[b.split("/")[-1]] = i
            continue
        if m.get("type") != "state" or not torso_idx:
            continue
        t = m["t"]
        for n, (p, q) in poses(m).items():
            if abs(p[1]) < 11.0 and 0.15 < p[2] < 0.6:
                since.setdefault(n, t)
            else:
                since.pop(n, None)
        on_field = {n for n, t1 in since.items() if t - t1 >= a.settle}
        if len(on_field) >= a.expect:
            print(f"measure: {sorted(on_field)} on the field for {a.settle} s at t={t:.2f}", flush=True)
            if len(on_field) > a.expect:
                print(f"measure: WARNING {len(on_field)} robots on the field, expected {a.expect}", flush=True)
            break

    robots = sorted(on_field, key=lambda n: int(n.split("_")[-1]) if n.split("_")[-1].isdigit() else n)
    if a.kickoff.lower() != "none":
        tr.send(f"(kickOff {a.kickoff})")
        print(f"measure: sent (kickOff {a.kickoff}); play mode was {tr.mode_name()}", flush=True)

    # 2. measure
    st = {n: dict(n=0, up=0, falls=0, state=None, cand=None, cand_t=None, start=None, closest=1e9, d0=None,
                  minz=1e9) for n in robots}
    ball0, ball_max, t_start, t_last, modes_seen = None, 0.0, None, None, []
    while True:
        m = json.loads(ws.recv())
        if m.get("type") != "state" or "ball" not in m:
            continue
        t = m["t"]
        if t_start is None:
            t_start = t
        if t - t_start > a.duration:
            break
        t_last = t
        bp = m["ball"]["p"]
        if ball0 is None:
            ball0 = bp
        ball_max = max(ball_max, math.hypot(bp[0] - ball0[0], bp[1] - ball0[1]))
        mode = tr.mode_name()
        if not modes_seen or modes_seen[-1][1] != mode:
            modes_seen.append((round(t - t_start, 2), mode))
        for n, (p, q) in poses(m).items():
            if n not in st:
                continue
            s = st[n]
            uz = up_z(q)
            upright = uz >= COS45
            s["n"] += 1
            s["up"] += upright
            s["minz"] = min(s["minz"], p[2])
            d = math.hypot(p[0] - bp[0], p[1] - bp[1])
            if s["d0"] is None:
                s["d0"], s["start"] = d, (p[0], p[1])
            s["closest"] = min(s["closest"], d)
            # falls, with hysteresis: "down" = tilt > 60 deg; "up" again needs tilt < 45 deg held 0.5 s
            if uz < COS60:
                if s["state"] in (None, "up"):
                    s["falls"] += s["state"] == "up"
                s["state"], s["cand_t"] = "down", None
            elif upright:
                if s["state"] is None:
                    s["state"] = "up"
                elif s["state"] == "down":
                    if s["cand_t"] is None:
                        s["cand_t"] = t
                    elif t - s["cand_t"] >= 0.5:
                        s["state"], s["cand_t"] = "up", None
            else:
                s["cand_t"] = None
            if cw:
                cw.writerow([f"{t:.3f}", n, p[0], p[1], p[2], f"{uz:.4f}", bp[0], bp[1], bp[2], mode, f"{heading(q):.1f}"])
            if fw:
                links = m.get("links", {}).get(n, [])
                for b, i in feet_idx.get(n, {}).items():
                    if len(links) >= 7 * (i + 1):
                        fw.writerow([f"{t:.3f}", n, b, links[7 * i], links[7 * i + 1], links[7 * i + 2]])

    span = (t_last or 0) - (t_start or 0)
    rows = []
    print(f"\nmeasured {span:.1f} s of sim time (viewer t {t_start:.2f} .. {t_last:.2f}); play modes: {modes_seen}")
    print(f"ball: start ({ball0[0]:.2f}, {ball0[1]:.2f}), max displacement {ball_max:.2f} m -> "
          f"{'MOVED' if ball_max > 0.10 else 'did not move'}")
    print(f"{'robot':8} {'start x,y':>14} {'upright%':>8} {'falls':>5} {'d0 ball':>8} {'closest':>8} {'min z':>6}")
    for n in robots:
        s = st[n]
        if not s["n"]:
            print(f"{n:8} no samples")
            continue
        r = dict(robot=n, start=s["start"], upright_pct=100.0 * s["up"] / s["n"], falls=s["falls"],
                 ball_dist_start=s["d0"], closest=s["closest"], samples=s["n"], min_torso_z=s["minz"])
        rows.append(r)
        print(f"{n:8} {s['start'][0]:6.2f},{s['start'][1]:6.2f} {r['upright_pct']:8.1f} {s['falls']:5d} "
              f"{s['d0']:8.2f} {s['closest']:8.2f} {s['minz']:6.3f}")
    if rows:
        print(f"mean upright {sum(r['upright_pct'] for r in rows) / len(rows):.1f} %, "
              f"falls {sum(r['falls'] for r in rows)}, "
              f"best approach {min(r['closest'] for r in rows):.2f} m")
    if a.json:
        json.dump(dict(span=span, ball_start=ball0, ball_max_disp=ball_max, ball_moved=ball_max > 0.10,
                       modes=modes_seen, robots=rows), open(a.json, "w"), indent=1)


if __name__ == "__main__":
    main()
