#!/usr/bin/env python3
"""Replays one agent's recorded messages into a SimSpark server (rcssserver3d or turf), open loop, one cycle per
recorded cycle, and records what the server perceived, in proxy.py's format (JSON lines: dir, cyc, wall, msg).
usage: replay.py --port P --stream TRACE.jsonl --out OUT.jsonl [--host 127.0.0.1] [--grace 5]
The stream: the a2s messages of a proxy.py trace. The first message (the agent's `scene`) is sent at once; the
server then sends --grace perceptions without waiting for the agent (SimSpark's grace cycles), which are read and
answered with nothing; from then on the messages the agent sent in the next recorded cycle (grouped by the trace's
cyc; `(syn)` for a cycle in which it sent nothing), then the perception they step to. Both servers so take every message at
the same perception index, whatever the machine's speed; needs the server's sync mode. Prints the replay cycle of the
recorded kick-off (from there the agent walks), for make_replay.py --walk-from.
--reference-freezes: the stream was recorded on rcssserver3d, which skips a resting robot's step every tenth cycle
while it hovers (ODE's auto-disable: the perception reads GYR exactly 0 and no joint moved); the hinge commands that
stepped into such a perception are sent as 0, so another server's joints lose that step's motion too.
"""
import argparse, json, re, socket, struct, sys, time

ap = argparse.ArgumentParser()
ap.add_argument('--port', type=int, required=True)
ap.add_argument('--host', default='127.0.0.1')
ap.add_argument('--stream', required=True)
ap.add_argument('--out', required=True)
ap.add_argument('--grace', type=int, default=5)
ap.add_argument('--reference-freezes', action='store_true')
a = ap.parse_args()
GYR = re.compile(r'\(GYR \(n torso\) \(rt ([-\d.e]+) ([-\d.e]+) ([-\d.e]+)\)\)')
HINGE = re.compile(r'\(((?:he|lae|rae|lle|rle)\d+) [-\d.e]+\)')


def frozen(msg):
    """A hovering perception of a skipped step: before the kick-off, GYR exactly 0."""
    m = GYR.search(msg)
    return '(pm BeforeKickOff)' in msg and m is not None and all(float(v) == 0 for v in m.groups())

first, groups, kickoff, skipped = None, {}, None, set()
for line in open(a.stream):
    r = json.loads(line)
    if r['dir'] != 'a2s':
        if kickoff is None and '(pm ' in r['msg'] and '(pm BeforeKickOff)' not in r['msg']:
            kickoff = r['cyc']
        if a.reference_freezes and frozen(r['msg']):
            skipped.add(r['cyc'] - 1)  # the messages sent after the perception before it stepped into it
        continue
    if first is None:
        first = r['msg']
        continue
    groups.setdefault(r['cyc'], []).append(r['msg'])
for c in skipped:
    groups[c] = [HINGE.sub(r'(\1 0)', m) for m in groups.get(c, [])]
if a.reference_freezes:
    print(f'{len(skipped)} skipped steps of the reference: their hinge commands sent as 0', file=sys.stderr)
cycles = list(range(min(groups), max(groups) + 1))

s = socket.create_connection((a.host, a.port))
s.setsockopt(socket.IPPROTO_TCP, socket.TCP_NODELAY, 1)
out = open(a.out, 'w')
k = -1


def log(direction, msg):
    out.write(json.dumps({'dir': direction, 'cyc': k, 'wall': time.time(), 'msg': msg}) + '\n')


def send(msg):
    log('a2s', msg)
    b = msg.encode('latin-1')
    s.sendall(struct.pack('>I', len(b)) + b)


def recv():
    global k
    def exact(n):
        b = b''
        while len(b) < n:
            c = s.recv(n - len(b))
            if not c:
                raise EOFError('server closed the connection')
            b += c
        return b
    n = struct.unpack('>I', exact(4))[0]
    msg = exact(n).decode('latin-1')
    k += 1
    log('s2a', msg)
    return msg


send(first)
for _ in range(a.grace):
    recv()
for c in cycles:
    for m in groups.get(c, ['(syn)']):
        send(m)
    recv()
out.close()
print(f'replayed {len(cycles)} cycles into {a.host}:{a.port}; {k + 1} perceptions in {a.out}', file=sys.stderr)
if kickoff is not None:
    print(f'the recorded kick-off (perception {kickoff} of the stream) is replay cycle {a.grace - 1 + kickoff - cycles[0]}',
          file=sys.stderr)
