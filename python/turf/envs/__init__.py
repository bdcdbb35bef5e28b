"""Gymnasium-shaped environments over turf's in-process kernels.

gymnasium is not a dependency (it is not in Debian): the environments have its reset/step signature and
observation_space/action_space (gymnasium.spaces when it is importable, else turf.envs.spaces' own Box and
Dict), and are registered with gymnasium when it is importable:

    turf/SslGoToBallKick-v0   SslGoToBallKickEnv  one robot, go to the ball and kick it into the goal
    turf/Ssl2x11-v0           SslMatchEnv         a 2 x 11 match, one action per team
    turf/T1Walk-v0            T1WalkEnv           a Booster T1 walks to a point (task="stand": stands)

check_env(env) checks an environment against Gymnasium's documented API contract (turf.envs.checker)."""

from .checker import check_env
from .spaces import HAVE_GYMNASIUM, Box, Dict
from .ssl_kick import SslGoToBallKickEnv
from .ssl_match import SslMatchEnv
from .t1_walk import T1WalkEnv

ENVIRONMENTS = {
    "turf/SslGoToBallKick-v0": ("turf.envs.ssl_kick:SslGoToBallKickEnv", 600),
    "turf/Ssl2x11-v0": ("turf.envs.ssl_match:SslMatchEnv", 3600),
    "turf/T1Walk-v0": ("turf.envs.t1_walk:T1WalkEnv", 1000),
}

if HAVE_GYMNASIUM:  # pragma: no cover - gymnasium is not in Debian
    import gymnasium

    for _id, (_entry, _steps) in ENVIRONMENTS.items():
        if _id not in gymnasium.registry:
            gymnasium.register(id=_id, entry_point=_entry, max_episode_steps=_steps)

__all__ = ["check_env", "Box", "Dict", "SslGoToBallKickEnv", "SslMatchEnv", "T1WalkEnv", "ENVIRONMENTS",
           "HAVE_GYMNASIUM"]
