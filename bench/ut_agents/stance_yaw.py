#!/usr/bin/env python3
"""How far each stance foot of a type-4 Nao turns about the vertical while it is on the ground.
usage: stance_yaw.py RUN_DIR [RUN_DIR ...]
RUN_DIR holds a kept run's samples.csv and samples_feet.csv (run_match.sh --keep; a reference harness writing the
same files). Only the robots that walk from 10 m to 4 m before the ball (the attackers' approach) are used, in that
stretch. A foot's heading is that of its toe seen from its centre (type 4 only: the other types have no toe), a
stance a run of at least three samples with the foot's centre below 13 mm. Prints per robot and foot: the stances,
their mean sampled length and the heading's mean change over a stance (deg, counter-clockwise positive seen from
above: a left foot turning its toe inwards turns clockwise). Samples should come every cycle (20 ms).
"""
import collections
import csv
import math
import sys

GROUND_Z = 0.013  # m: the foot's centre below this is on the ground (the sole's box is 20 mm high)


def approach(samples):
    """Per robot, the stretch (t_from, t_to) in which its torso went from 10 m to 4 m before the ball."""
    by_robot = collections.defaultdict(list)
    for r in samples:
        by_robot[r['robot']].append(r)
    out = {}
    for robot, rows in by_robot.items():
        t10 = t4 = None
        for r in rows:
            d = math.hypot(float(r['x']) - float(r['ball_x']), float(r['y']) - float(r['ball_y']))
            if t10 is None and d <= 10:
                t10 = float(r['t'])
            if t10 is not None and d <= 4:
                t4 = float(r['t'])
                break
        if t10 is not None and t4 is not None and t10 > float(rows[0]['t']):
            out[robot] = (t10, t4)
    return out


def stances(run_dir):
    """{(robot, side): [(heading change deg, sampled length s), ...]} over the approach."""
    window = approach(list(csv.DictReader(open(run_dir + '/samples.csv'))))
    parts = collections.defaultdict(dict)  # (robot, side) -> {(t, 'foot'|'toe'): (x, y, z)}
    for t, robot, part, x, y, z in csv.reader(open(run_dir + '/samples_feet.csv')):
        t = float(t)
        if robot in window and window[robot][0] <= t <= window[robot][1]:
            parts[(robot, part[0])][(t, part[1:])] = (float(x), float(y), float(z))
    out = {}
    for key, p in sorted(parts.items()):
        times = sorted(t for (t, part) in p if part == 'foot' and (t, 'toe') in p)
        runs, current = [], []
        for t in times:
            foot, toe = p[(t, 'foot')], p[(t, 'toe')]
            heading = math.degrees(math.atan2(toe[1] - foot[1], toe[0] - foot[0]))
            if foot[2] < GROUND_Z:
                current.append((t, heading))
            elif current:
                runs.append(current)
                current = []
        out[key] = [((r[-1][1] - r[0][1] + 180) % 360 - 180, r[-1][0] - r[0][0]) for r in runs if len(r) >= 3]
    return out


def main():
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    for run_dir in sys.argv[1:]:
        for (robot, side), changes in stances(run_dir).items():
            if not changes:
                continue
            n = len(changes)
            mean = sum(c for c, _ in changes) / n
            length = sum(s for _, s in changes) / n
            print(f"{run_dir} {robot} {side}: {n} stances, {length * 1000:.0f} ms, heading change {mean:+.2f} deg")


if __name__ == '__main__':
    main()
