#!/usr/bin/env python3
"""A TCP proxy between one RCSSServerMJ agent and the server that watches the agent's torso in the perceptions
(pos, quat) and prints one table row at the end: simulated seconds, distance walked, falls (torso below
--fall-height, counted once per fall until it is up again above --up-height), lowest and mean torso height while
walking (the mean from --mean-from), final yaw. Bytes pass unchanged; --capture FILE also writes each of the agent's
messages, one a line (replay_agent.py sends them again).
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
parser.add_argument("--capture", default=None, help="file for the agent's messages, one a line")
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


def frames(buffer):
    """The whole frames at the start of buffer, and what is left of it."""
    out = []
    while len(buffer) >= 4 and len(buffer) >= 4 + int.from_bytes(buffer[:4], "big"):
        n = int.from_bytes(buffer[:4], "big")
        out.append(buffer[4:4 + n])
        buffer = buffer[4 + n:]
    return out, buffer


def to_server():
    capture = open(args.capture, "w") if args.capture else None
    sent = first
    try:
        while True:
            if capture:
                messages, sent = frames(sent)
                capture.writelines(m.decode(errors="replace") + "\n" for m in messages)
                capture.flush()
            data = client.recv(65536)
            if not data:
                break
            server.sendall(data)
            sent += data
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
        messages, buffer = frames(buffer + data)
        for m in messages:
            watch(m.decode(errors="replace"))
except OSError:
    pass
client.close()
server.close()
(x0, y0, t0), (x1, y1, t1) = state["start"] or (0, 0, 0), state["last"] or (0, 0, 0)
print(f"| {args.label} | {t1 - t0:.1f} | {math.hypot(x1 - x0, y1 - y0):.1f} | {x1 - x0:.1f} | {state['falls']} | "
      f"{state['lowest']:.2f} | {state['sum_z'] / max(1, state['n_z']):.3f} | {state['yaw']:.0f} |")
