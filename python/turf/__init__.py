"""turf in a Python process: the simulation kernels stepped in-process, Gymnasium-shaped environments and
VectorSim (worlds in worker processes). No DDS, no sockets.

    import turf
    sim = turf.Sim("ssl_div_a", seed=1, realism="realistic")
    obs = sim.step({"blue": commands}, n=8)   # commands: robots_per_team x 6 (turf.SSL_COMMAND_COLUMNS)
"""

from . import _turf
from ._turf import (LEGGED_JOINT_COLUMNS, SSL_BALL_COLUMNS, SSL_BALL_DETECTION_COLUMNS, SSL_CAMERA_FRAME_COLUMNS,
                    SSL_COMMAND_COLUMNS, SSL_ROBOT_COLUMNS, SSL_ROBOT_DETECTION_COLUMNS, LeggedSim, SslSim,
                    error_names, is_legged_scene, scene_path)
from .errors import TurfError


# The learning configuration of SSL scenes, for Sim(..., **FAST_SSL): the largest physics step at which every
# physics test of tests/core still passes, 2.5 ms against the scenes' 2 ms (3 ms and 4 ms fail
# Physics.GoalStopsTheBall: the ball sinks into the goal's back wall), and no boundary wall boxes, goals as static
# bodies of their own (core/mjcf.cpp: the walls' boxes are never touched, the containment stage keeping ball and
# robots at their inner faces; a 2 x 11 match runs the same to the bit with and without them; MuJoCo 2.2 tested
# them against every robot at every step). ctest runs the physics tests in this configuration too (core_tests'
# "learning." tests).
FAST_SSL_STEP = 0.0025
FAST_SSL = {"physics_step": FAST_SSL_STEP, "wall_segments": 0}


def Sim(scene="ssl_div_a", seed=None, realism=None, physics_step=None, robots_per_team=None, wall_segments=None):
    """A world of ``scene`` (a name in configs/scenes/ or a path to a scene file) stepped in this process.

    ``seed`` replaces the scene's seed (every random stream of the run derives from it); ``realism`` is a
    preset name (ideal, realistic, harsh), a YAML file or YAML text, or None for the scene's own.
    ``physics_step`` (s), ``robots_per_team`` (SSL: ids 0..n-1 exist; fewer parked robots, faster steps) and
    ``wall_segments`` (SSL: boxes per boundary wall, 0 for none) override the scene's and are checked as the file's are
    (``**turf.FAST_SSL``: the learning configuration). Returns an SslSim for SSL scenes and a
    LeggedSim for ``kind: legged`` scenes."""
    cls = LeggedSim if is_legged_scene(scene) else SslSim
    return cls(scene, seed=seed, realism=realism or "", physics_step=physics_step, robots_per_team=robots_per_team,
               wall_segments=wall_segments)


from .vector import VectorSim  # noqa: E402  (uses Sim)
from . import envs  # noqa: E402,F401

__all__ = ["Sim", "FAST_SSL", "FAST_SSL_STEP", "SslSim", "LeggedSim", "VectorSim", "TurfError", "envs", "error_names", "is_legged_scene",
           "scene_path", "SSL_COMMAND_COLUMNS", "SSL_BALL_COLUMNS", "SSL_ROBOT_COLUMNS",
           "SSL_BALL_DETECTION_COLUMNS", "SSL_ROBOT_DETECTION_COLUMNS", "SSL_CAMERA_FRAME_COLUMNS",
           "LEGGED_JOINT_COLUMNS"]
