#!/usr/bin/env python3
"""A TCP proxy between one RCSSServerMJ agent and the server that watches the agent's torso in the perceptions
(pos, quat) and prints one table row at the end: simulated seconds, distance walked, falls (torso below
--fall-height, counted once per fall until it is up again above --up-height), lowest and mean torso height while
walking (the mean from --mean-from), final yaw. Bytes pass unchanged.
Usage: pose_proxy.py --listen PORT --server PORT --seconds S --label TEXT"""
import argparse
import math
import re
import socket
import threading

parser = argparse.ArgumentParser()
parser.add_argument("--listen", type=int, required=True)
parser.add_argument("--server", type=int, required=True)
parser.add_argument("--seconds", type=float, default=60.0)
parser.add_argument("--walk-from", type=float, default=1.0, help="sim time from which the distance counts")
parser.add_argument("--mean-from", type=float, default=5.0, help="sim time from which the mean height counts")
parser.add_argument("--fall-height", type=float, default=0.45)
parser.add_argument("--up-height", type=float, default=0.5)
parser.add_argument("--label", default="")
args = parser.parse_args()

listener = socket.socket()
listener.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)
listener.bind(("127.0.0.1", args.listen))
listener.listen(1)
# The agent's connection is the first that sends something (a port probe's closes empty).
while True:
    client, _ = listener.accept()
    first = client.recv(65536)
    if first:
        break
    client.close()
server = socket.create_connection(("127.0.0.1", args.server))
server.sendall(first)
for s in (client, server):
    s.setsockopt(socket.IPPROTO_TCP, socket.TCP_NODELAY, 1)

NOW = re.compile(r"\(now ([-0-9.e]+)\)")
POS = re.compile(r"\(p ([-0-9.e]+) ([-0-9.e]+) ([-0-9.e]+)\)")
QUAT = re.compile(r"\(q ([-0-9.e]+) ([-0-9.e]+) ([-0-9.e]+) ([-0-9.e]+)\)")
state = {"start": None, "last": None, "t": 0.0, "falls": 0, "down": False, "yaw": 0.0, "lowest": 10.0, "sum_z": 0.0, "n_z": 0}


def watch(message):
    t, p, q = NOW.search(message), POS.search(message), QUAT.search(message)
    if not (t and p and q):
        return
    now = float(t.group(1))
    x, y, z = (float(v) for v in p.groups())
    w, qx, qy, qz = (float(v) for v in q.groups())
    state["t"] = now
    if now >= args.walk_from and state["start"] is None:
        state["start"] = (x, y, now)
    state["last"] = (x, y, now)
    state["yaw"] = math.degrees(math.atan2(2 * (w * qz + qx * qy), 1 - 2 * (qy * qy + qz * qz)))
    if state["start"] is not None:
        state["lowest"] = min(state["lowest"], z)
    if now >= args.mean_from:
        state["sum_z"] += z
        state["n_z"] += 1
    if not state["down"] and z < args.fall_height:
        state["down"] = True
        state["falls"] += 1
    elif state["down"] and z > args.up_height:
        state["down"] = False


def to_server():
    try:
        while True:
            data = client.recv(65536)
            if not data:
                break
            server.sendall(data)
    except OSError:
        pass
    server.close()


threading.Thread(target=to_server, daemon=True).start()
buffer = b""
try:
    while state["t"] < args.seconds:
        data = server.recv(65536)
        if not data:
            break
        client.sendall(data)
        buffer += data
        while len(buffer) >= 4:
            n = int.from_bytes(buffer[:4], "big")
            if len(buffer) < 4 + n:
                break
            watch(buffer[4:4 + n].decode(errors="replace"))
            buffer = buffer[4 + n:]
except OSError:
    pass
client.close()
server.close()
(x0, y0, t0), (x1, y1, t1) = state["start"] or (0, 0, 0), state["last"] or (0, 0, 0)
print(f"| {args.label} | {t1 - t0:.1f} | {math.hypot(x1 - x0, y1 - y0):.1f} | {x1 - x0:.1f} | {state['falls']} | "
      f"{state['lowest']:.2f} | {state['sum_z'] / max(1, state['n_z']):.3f} | {state['yaw']:.0f} |")
