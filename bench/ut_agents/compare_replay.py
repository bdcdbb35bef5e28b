#!/usr/bin/env python3
"""Compares two replays of one message stream (replay.py's output, one per server), perception by perception.
usage: compare_replay.py REF.jsonl OTHER.jsonl [--from K] [--to K] [--window 50]
Prints, per window of cycles: the RMS difference of the leg joints' angles (deg), of GYR (deg/s, vector), how far
each torso turned about its z axis (GYR z summed over the window's 20 ms cycles, deg; counter-clockwise positive),
the mean ACC z of each (m/s^2) and whether each has stayed upright so far (the agent's low-pass of ACC z above 7 in
every cycle since --from).
"""
import argparse, json, math, os, sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from compare import parse_perc  # noqa: E402

ap = argparse.ArgumentParser()
ap.add_argument('ref')
ap.add_argument('other')
ap.add_argument('--from', dest='k0', type=int, default=0)
ap.add_argument('--to', dest='k1', type=int, default=None)
ap.add_argument('--window', type=int, default=50)
ap.add_argument('--offset', type=int, default=0, help='OTHER perception k+offset against REF perception k')
a = ap.parse_args()


def load(p):
    return [parse_perc(json.loads(l)['msg']) for l in open(p) if json.loads(l)['dir'] == 's2a']


R, O = load(a.ref), load(a.other)
O = O[a.offset:] if a.offset >= 0 else [O[0]] * -a.offset + O
n = min(len(R), len(O)) if a.k1 is None else min(a.k1, len(R), len(O))
legs = [j for j in R[0]['hj'] if 'lj' in j]
lp = {'r': None, 'o': None}
up = {'r': True, 'o': True}  # upright so far (the agent's low-pass of ACC z above 7 in every cycle)
print('| cycles | t ref | legs RMS deg | worst joint | GYR RMS deg/s | turn deg ref / other | ACC z ref / other '
      '| upright ref / other |')
print('| --- | --- | --- | --- | --- | --- | --- | --- |')
for w0 in range(a.k0, n, a.window):
    w1 = min(n, w0 + a.window)
    se, per, ge, az, turn = 0.0, {}, 0.0, [0.0, 0.0], [0.0, 0.0]
    for k in range(w0, w1):
        r, o = R[k], O[k]
        for j in legs:
            d = (r['hj'].get(j, 0) - o['hj'].get(j, 0)) ** 2
            se += d; per[j] = per.get(j, 0) + d
        ge += sum((x - y) ** 2 for x, y in zip(r.get('gyr', [0] * 3), o.get('gyr', [0] * 3)))
        for i, (key, p) in enumerate((('r', r), ('o', o))):
            z = p.get('acc', [0, 0, 0])[2]
            az[i] += z
            turn[i] += p.get('gyr', [0, 0, 0])[2] * 0.02
            lp[key] = z if lp[key] is None else 0.9 * lp[key] + 0.1 * z
            up[key] = up[key] and lp[key] > 7
    m = w1 - w0
    worst = max(per, key=per.get)
    print(f'| {w0}-{w1 - 1} | {R[w0].get("t", 0):.2f} | {math.sqrt(se / m / len(legs)):.2f} | '
          f'{worst} {math.sqrt(per[worst] / m):.1f} | {math.sqrt(ge / m):.1f} | {turn[0]:+.1f} / {turn[1]:+.1f} | '
          f'{az[0] / m:.1f} / {az[1] / m:.1f} | '
          f'{"yes" if up["r"] else "no"} / {"yes" if up["o"] else "no"} |')
