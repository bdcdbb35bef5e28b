"""The Python side of publish_test.cpp: a Sim stepped here, published with sim.publish(); what step() returned is
written to a file for the C++ reader to compare with the samples it received.

    publish_child.py --domain D --prefix P --out FILE [--scene S] [--calls K] [--n N]

Waits for the test's reader to match, makes K step(commands, n=N) calls, waits for the reader to leave (the test
has seen the last state), then writes FILE: uint32 robot count, then per call uint64 frame, the ball's 6 doubles
and robots x 9 doubles, native byte order. Exit 0, or 3 if a wait ran out (with the reason on stderr)."""

import argparse
import struct
import sys
import time

import numpy as np

import turf


def wait_for(condition, seconds, what):
    deadline = time.monotonic() + seconds
    while not condition():
        if time.monotonic() > deadline:
            sys.stderr.write("publish_child: gave up waiting for " + what + "\n")
            sys.exit(3)
        time.sleep(0.01)


def main():
    p = argparse.ArgumentParser()
    p.add_argument("--domain", type=int, required=True)
    p.add_argument("--prefix", required=True)
    p.add_argument("--out", required=True)
    p.add_argument("--scene", default="ssl_div_a")
    p.add_argument("--calls", type=int, default=30)
    p.add_argument("--n", type=int, default=8)
    a = p.parse_args()

    sim = turf.Sim(a.scene, seed=1, realism="realistic")
    sim.publish(domain=a.domain, prefix=a.prefix)
    wait_for(lambda: sim.state_readers >= 1, 60, "the test's reader")
    commands = np.zeros((2, sim.robots_per_team, len(turf.SSL_COMMAND_COLUMNS)))
    commands[:, :, 0] = 1.0  # every robot drives forwards, turning
    commands[:, :, 2] = 0.5
    records = []
    for _ in range(a.calls):
        obs = sim.step(commands, n=a.n)
        records.append(struct.pack("=Q", obs["frame"]) + obs["ball"].tobytes() + obs["robots"].tobytes())
    wait_for(lambda: sim.state_readers == 0, 120, "the test's reader to leave")
    sim.unpublish()
    with open(a.out, "wb") as f:
        f.write(struct.pack("=I", sim.robot_count) + b"".join(records))


if __name__ == "__main__":
    main()
