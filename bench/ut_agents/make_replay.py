#!/usr/bin/env python3
"""Turns one agent's proxy trace (proxy.py JSON lines) into a replay file for turf's reference-replay test
(tests/simspark/reference_replay_test.cpp): the agent's messages, and what the server perceived for it, per cycle.
usage: make_replay.py TRACE.jsonl OUT.txt --walk-from K [--cycles N] [--note TEXT]
TRACE: replay.py's record of a replay into the reference server. Keeps the message sent before the first perception
(scene), then cycles 0..N-1 (default: all): for cycle k (the k-th perception, from 0) the perception's time, play
mode, GYR, ACC, each HJ angle and both FRP forces, and the messages sent after reading it. K: the first cycle of
the walk (the cycle replay.py printed for the recorded kick-off), from which the test compares. Format:
  # comment lines (provenance: --note, the trace's name)
  W <K>
  J <joint names in the order of the R lines' angles>
  M <k> <message>       sent after perception k (k = -1: before the first); one line per message
  R <k> <t> <pm> <gyr x y z> <acc x y z> <angles deg...> <lf fz> <rf fz>
"""
import argparse, json, os, sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from compare import parse_perc  # noqa: E402

ap = argparse.ArgumentParser()
ap.add_argument('trace')
ap.add_argument('out')
ap.add_argument('--walk-from', type=int, required=True)
ap.add_argument('--cycles', type=int, default=None)
ap.add_argument('--note', default='')
a = ap.parse_args()

rows, msgs, joints = [], [], None
k = -1
for line in open(a.trace):
    r = json.loads(line)
    if r['dir'] == 'a2s':
        msgs.append((k, r['msg'].replace('\n', ' ')))
        continue
    p = parse_perc(r['msg'])
    if 't' not in p:
        continue
    k += 1
    if a.cycles is not None and k >= a.cycles:
        k -= 1
        break
    if joints is None:
        joints = list(p['hj'].keys())
    frp = p.get('frp', {})
    fz = [frp[f][1][2] if f in frp else 0.0 for f in ('lf', 'rf')]
    rows.append((k, p['t'], p.get('pm', '?'), p.get('gyr', [0, 0, 0]), p.get('acc', [0, 0, 0]),
                 [p['hj'].get(j, float('nan')) for j in joints], fz))

with open(a.out, 'w') as f:
    f.write(f'# turf reference replay: {os.path.basename(a.trace)}, {len(rows)} cycles, the walk from cycle '
            f'{a.walk_from}. Made by bench/ut_agents/make_replay.py.\n')
    if a.note:
        for n in a.note.split('\\n'):
            f.write(f'# {n}\n')
    f.write(f'W {a.walk_from}\n')
    f.write('J ' + ' '.join(joints) + '\n')
    last = rows[-1][0] if rows else -1
    mi = 0
    for row in rows:
        while mi < len(msgs) and msgs[mi][0] < row[0]:
            f.write(f'M {msgs[mi][0]} {msgs[mi][1]}\n'); mi += 1
        kk, t, pm, g, acc, hj, fz = row
        f.write(f'R {kk} {t:.2f} {pm} ' + ' '.join(f'{x:g}' for x in g + acc + hj + fz) + '\n')
    while mi < len(msgs) and msgs[mi][0] <= last:
        f.write(f'M {msgs[mi][0]} {msgs[mi][1]}\n'); mi += 1
print(f'{a.out}: {len(rows)} cycles, {len(msgs)} messages in the trace', file=sys.stderr)
