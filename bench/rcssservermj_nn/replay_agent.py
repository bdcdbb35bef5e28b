#!/usr/bin/env python3
"""Open-loop replay for bench/rcssservermj_nn/run.sh --open-loop: sends an agent's captured messages (pose_proxy.py
--capture: the init, then one answer a line) to a server, each answer after the next perception as the agent did,
and writes the torso seen in every perception: "time x y z w qx qy qz" a line. Usage:
  replay_agent.py --port PORT --capture FILE --trace FILE"""
import argparse
import re
import socket

parser = argparse.ArgumentParser()
parser.add_argument("--port", type=int, required=True)
parser.add_argument("--capture", required=True)
parser.add_argument("--trace", required=True)
args = parser.parse_args()

messages = [line.rstrip("\n") for line in open(args.capture)]
sock = socket.create_connection(("127.0.0.1", args.port))
sock.setsockopt(socket.IPPROTO_TCP, socket.TCP_NODELAY, 1)
FIELDS = [re.compile(p) for p in (r"\(now ([-0-9.e]+)\)", r"\(p ([-0-9.e]+) ([-0-9.e]+) ([-0-9.e]+)\)",
                                  r"\(q ([-0-9.e]+) ([-0-9.e]+) ([-0-9.e]+) ([-0-9.e]+)\)")]


incoming = sock.makefile("rb")


def exactly(n):
    data = incoming.read(n)
    if len(data) < n:
        raise EOFError("the server closed")
    return data


def send(text):
    body = text.encode()
    sock.sendall(len(body).to_bytes(4, "big") + body)


with open(args.trace, "w") as trace:
    send(messages[0])
    for answer in messages[1:]:
        perception = exactly(int.from_bytes(exactly(4), "big")).decode(errors="replace")
        found = [f.search(perception) for f in FIELDS]
        if all(found):
            trace.write(" ".join(v for m in found for v in m.groups()) + "\n")
        send(answer)
sock.close()
