#!/usr/bin/env python3
"""Prints, second by second, how far two replay_agent.py traces of the same answers are apart: the torso's position
(mm, in the plane), height (mm) and yaw (deg), cycle by cycle in the order the perceptions came (the servers' clocks
may be offset). Usage: compare_traces.py A B LABEL_A LABEL_B"""
import math
import sys


def load(path):
    rows = []
    for line in open(path):
        t, x, y, z, w, qx, qy, qz = map(float, line.split())
        rows.append((t, x, y, z, math.degrees(math.atan2(2 * (w * qz + qx * qy), 1 - 2 * (qy * qy + qz * qz)))))
    return rows


a, b = load(sys.argv[1]), load(sys.argv[2])
print(f"| after s | plane mm | height mm | yaw deg | {sys.argv[3]} x, y m | {sys.argv[4]} x, y m |")
print("| --- | --- | --- | --- | --- | --- |")
for second in range(1, len(a) // 50 + 1):
    i = 2 + 50 * second  # the beam shows in the third perception; 50 cycles a second
    if i >= min(len(a), len(b)):
        break
    (_, xa, ya, za, yawa), (_, xb, yb, zb, yawb) = a[i], b[i]
    yaw = (yawa - yawb + 180) % 360 - 180
    print(f"| {second} | {1000 * math.hypot(xa - xb, ya - yb):.1f} | {1000 * (za - zb):+.1f} | {yaw:+.2f} | "
          f"{xa:.3f}, {ya:.3f} | {xb:.3f}, {yb:.3f} |")
